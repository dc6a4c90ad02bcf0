#!/bin/bash
# Regenerates results/rest from scratch. Run from the repository root.
# About 6 core-hours; each part's README names what it writes.
set -euo pipefail
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
L=build/liggghts-fabric
root=""; [ "$(id -u)" -eq 0 ] && root="--allow-run-as-root"
# force_balance: the rules side by side (sixteen rows, about 30 minutes on 2 cores)
$py bench/hold_diagnosis/run.py --study kinetic --side 7.7 --hold 0 --out out/rest_force_balance \
    --rows energy_rule_zeta0.6_seed1 energy_rule_zeta0.6_seed2 energy_rule_zeta0.6_seed3 \
           dt_gain1_tol1e-3_seed1 dt_gain1_tol1e-3_seed2 dt_gain1_tol1e-3_seed3 \
           dt_gain4_tol1e-3_seed1 dt_gain4_tol1e-3_seed2 dt_gain4_tol1e-3_seed3 \
           dt_gain4_every1000_seed1 dt_gain4_every1000_seed2 dt_gain4_every1000_seed3 \
           dt_gain8_tol1e-3_seed1 dt_gain8_tol1e-3_seed2 dt_gain8_tol1e-3_seed3 dt_gain16_tol1e-3_seed1
cp out/rest_force_balance/kinetic_table.csv results/rest/force_balance/rest_table.csv
cp out/rest_force_balance/rest_chart.png results/rest/force_balance/rest_chart.png
# force_balance: relaxed towards 1e-4 with the lid held (relaxation_tol1e-4.csv: the thermo
# rows after LOADED in each run's screen output)
$py bench/hold_diagnosis/run.py --study kinetic --side 7.7 --hold 0 --out out/rest_force_balance \
    --rows dt_gain4_tol1e-4_seed1 dt_gain4_tol1e-4_seed2 balance_tol1e-4_seed1 balance_tol1e-4_seed2
# force_balance: the wide soil and the side-3.3 hold
$L -in input_scripts/in.oedometer -var side 3.3 -var psd results/rest/force_balance/fuller4.5.txt -var out out/rest_wide
$L -in input_scripts/in.oedometer -var side 3.3 -var hold 20000 -var out out/rest_hold33
cp out/rest_hold33/hold_series.txt results/rest/force_balance/hold33_series.txt
$L -in input_scripts/in.oedometer -var relax_lid servo -var hold 20000 -var out out/rest_servo_hold
cp out/rest_servo_hold/hold_series.txt results/rest/force_balance/hold_after_servo_rest_side7.7.txt
# the main job and seed 2 (one rank) held 20,000 steps (hold_side7.7.csv: the HOLD lines), and the main job damped instead of zeroed
# (results/rest/README quotes its 39 % as measured when a reload waited for the end of its block)
root=""; [ "$(id -u)" -eq 0 ] && root="--allow-run-as-root"
mpirun $root -np 2 $L -in input_scripts/in.oedometer -var hold 20000 -var out out/rest_hold77 | grep "^HOLD"
$L -in input_scripts/in.oedometer -var seed 2 -var hold 20000 -var out out/rest_hold77_seed2 | grep "^HOLD"
mpirun $root -np 2 $L -in input_scripts/in.oedometer -var hold 20000 -var hold_zero 0 -var hold_damping 0.7 \
    -var out out/rest_hold77_damped | grep "^HOLD"
# force_balance: the protocol, tolerance and damping tables, one scene run per row (about 2.5 hours on 2 cores)
$py bench/rest_protocol/run.py --out results/rest/force_balance --runs out/rest_protocol
cp out/rest_protocol/protocol_DA_cu2.5_seed1_relax_lidservo_relax_max40000_rest_tol1e-4/fabric_series.txt \
    results/rest/force_balance/servo_relaxation_tol1e-4_series.txt
# ... the damping table's chart (damping_table.csv: bench/rest_protocol/run.py above, about 40 minutes of it)
$py bench/rest_protocol/damping_chart.py results/rest/force_balance/damping_table.csv
# creep_diagnosis: the former rest held, one setting moved at a time (about 30 minutes on 2 cores)
$py bench/hold_diagnosis/run.py --out out/rest_creep
cp out/rest_creep/hold_table.csv out/rest_creep/hold_series.csv out/rest_creep/hold_diagnosis.png \
    results/rest/creep_diagnosis/
# stop_rule: replays the former rule's runs of results/paper, results/stress and results/settings
# (their study folders under out/, made by those folders' make.sh)
$py bench/stop_rule/replay.py out/paper_la out/paper_n038 out/settings_hertz out/settings_k3957 \
    out/settings_dt02 out/stress/s1e4 out/stress/s3e4 out/stress/s1e5 out/stress/s3e5 out/stress/s1e6 \
    --csv results/rest/stop_rule/replay.csv
# resume_handover (about 1 h 45 min on 2 cores)
bash bench/resume_handover/run.sh
cp out/resume_handover/blocks.csv results/rest/resume_handover/
bash bench/resume_handover/la35_side5.sh
cp out/resume_la35/la35_side5.csv results/rest/resume_handover/
