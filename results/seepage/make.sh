#!/bin/bash
# Regenerates results/seepage from scratch: Cu 2.0, 2.5 and 3.0, both
# rules, side 3.3, seed 1, at the scene's defaults, then the seepage test at
# gradient 300 (-var gradients 300, the flow solved every 1,000 steps); the verdict of compute
# constriction/size on the same specimens at rest; the eroded volume per
# run, stage and size interval; the size study (Cu 2.0 up to side 7.7);
# the positive control (a gap-graded soil). Run
# from the repository root. About 4
# core-hours (Cu 3.0 and the side-7.7 runs most of it; the gap-graded
# control 0.7).
set -euo pipefail
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
$py tools/oedometer_study.py --sides 3.3 --soils cu2.0 cu2.5 cu3.0 --rules discrete layerwise \
    --seeds 1 --jobs 2 --ranks 1 --var gradients=300 flow_every=1000 --out out/seepage
cp out/seepage/study.csv results/seepage/study.csv
$py tools/constriction_verdict.py --study out/seepage --dest results/seepage/verdict
$py tools/suffusion_report.py out/seepage/runs/* --out results/seepage
$py results/seepage/score.py results/seepage
# how often the flow must be solved: DA Cu 2.0, one scene run per interval
rm -f results/seepage/flow_every.csv
echo "flow_every,steps,eroded_pct_of_specimen,eroded_pct_of_loose,grains_eroded,wall_s" > results/seepage/flow_every.csv
for fe in 50 100 200 500 1000 2000; do
  start=$(date +%s)
  build/liggghts-fabric -in input_scripts/in.oedometer -var psd input_scripts/psd/cu2.0.txt -var side 3.3 \
      -var gradients 300 -var flow_every $fe -var out out/seepage_fe$fe -log out/seepage_fe$fe.log \
      | grep "^SEEPAGE: gradient" | head -1 > out/seepage_fe$fe.line
  wall=$(( $(date +%s) - start ))
  sed -E "s/.* for ([0-9]+) steps: eroded ([0-9.]+) % of the specimen, ([0-9.]+) % of its loose grains \(([0-9]+) grains.*/$fe,\1,\2,\3,\4,$wall/" \
      out/seepage_fe$fe.line >> results/seepage/flow_every.csv
done
# 1 and 2 ranks: DA Cu 2.0 twice on 2 ranks beside the study's run and the sweep's every 1,000
root=""; [ "$(id -u)" -eq 0 ] && root="--allow-run-as-root"
for k in 1 2; do
  mpirun $root -np 2 build/liggghts-fabric -in input_scripts/in.oedometer -var psd input_scripts/psd/cu2.0.txt \
      -var side 3.3 -var gradients 300 -var out out/seepage_ranks2_$k -log out/seepage_ranks2_$k.log > /dev/null
done
$py - <<'PY'
import sys
sys.path.insert(0, "tools")
import outputs
runs = [(1, "campaign (study.csv)", "out/seepage/runs/DA_cu2.0_side3.3_seed1"),
        (1, "flow_every sweep", "out/seepage_fe1000"), (2, "first", "out/seepage_ranks2_1"),
        (2, "second", "out/seepage_ranks2_2")]
with open("results/seepage/ranks.csv", "w") as f:
    f.write("ranks,run,primary_pct_at_rest,eroded_pct_of_specimen,eroded_pct_of_loose\n")
    for ranks, name, run in runs:
        g = outputs.read_global(run + "/fabric_global.txt")
        pos = outputs.index(outputs.fabric_vector())
        s = outputs.read_suffusion(run + "/suffusion.txt")
        f.write("%d,%s,%.4f,%.3f,%.3f\n" % (ranks, name, g[pos["primary_percent_by_mass"]],
                                             s["eroded_pct"][-1], s["eroded_loose_pct"][-1]))
PY
# the gradient in stages: DA and LA Cu 2.0 (about 30 minutes each)
for a in discrete layerwise; do
  build/liggghts-fabric -in input_scripts/in.oedometer -var psd input_scripts/psd/cu2.0.txt -var side 3.3 \
      -var arrangement $a -var gradients 3 10 30 100 300 -var out out/seepage_grad_$a \
      -log out/seepage_grad_$a.log > /dev/null || true
done
$py - <<'PY'
import sys
sys.path.insert(0, "tools")
import outputs
with open("results/seepage/gradients.csv", "w") as f:
    f.write("run,gradient,steps_total,eroded_pct_of_specimen,eroded_pct_of_loose,grains_eroded,"
            "lid_stress_Pa_at_stage_end\n")
    for a, r in (("discrete", "DA"), ("layerwise", "LA")):
        s = outputs.read_suffusion("out/seepage_grad_%s/suffusion.txt" % a)
        for k in range(len(s["gradient"])):
            f.write("%s_cu2.0_side3.3_seed1,%s,%d,%.3f,%.3f,%d,%.0f\n" % (
                r, s["gradient_text"][k], s["steps"][k], s["eroded_pct"][k],
                s["eroded_loose_pct"][k], s["grains_eroded"][k], s["lid_stress"][k]))
PY
# the size study: Cu 2.0, both rules, side 3.3 seeds 1-3, sides 5.5 and 7.7
# seed 1 (about 1.5 core-hours, side 7.7 most of it)
$py tools/oedometer_study.py --sides 3.3 --soils cu2.0 --rules discrete layerwise \
    --seeds 1 2 3 --jobs 2 --ranks 1 --var gradients=300 flow_every=1000 --out out/seepage_size
$py tools/oedometer_study.py --sides 5.5 7.7 --soils cu2.0 --rules discrete layerwise \
    --seeds 1 --jobs 2 --ranks 1 --var gradients=300 flow_every=1000 --out out/seepage_size
mkdir -p results/seepage/size
cp out/seepage_size/study.csv results/seepage/size/study.csv
$py tools/constriction_verdict.py --study out/seepage_size --dest results/seepage/size/verdict
rm -f results/seepage/size/verdict/csd_*.txt     # the CSDs of side 7.7 run to megabytes: out/ keeps them
$py tools/suffusion_report.py out/seepage_size/runs/* --out results/seepage/size
$py results/seepage/score.py results/seepage/size
# the positive control: a gap-graded soil (input_scripts/psd/gap10.txt, 10 %
# of fines 0.12-0.15 mm in grains 0.75-1.0 mm), unstable by Kezdi and
# Kenney & Lau. Packed at porosity 0.40 (the packer leaves 46-60 coarse
# grains unplaced: the specimen holds 11.3-11.5 % fines), loaded from there
# (t_max 1 s; overlap_max 0.1 for the lid's first impact on the loose DA
# packing), the same seepage test with the filter of every skeleton grain
# at the floor (opening 0.7 mm, in the gap; at the default d60, 0.88 mm,
# the skeleton's own grains fall through); about 20 minutes a run alone
$py tools/oedometer_study.py --sides 6 --soils gap10 --rules discrete layerwise --seeds 1 \
    --jobs 2 --ranks 1 --var porosity=0.40 t_max=1.0 overlap_max=0.1 opening=0.7e-3 gradients=300 flow_every=1000 \
    --out out/seepage_control
mkdir -p results/seepage/control
cp out/seepage_control/study.csv results/seepage/control/study.csv
$py tools/constriction_verdict.py --study out/seepage_control --dest results/seepage/control/verdict
rm -f results/seepage/control/verdict/csd_*.txt  # 2 MB: out/ keeps them
$py tools/suffusion_report.py out/seepage_control/runs/* --out results/seepage/control
$py results/seepage/score.py results/seepage/control
