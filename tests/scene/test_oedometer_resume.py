#!/usr/bin/python3
"""Scene test: a run longer than a job goes on from a checkpoint
(`-var checkpoint N`, then `-var resume 1`), on the scene of
test_oedometer.py (side 2.75, Cu 2.5 DA, linear springs kn 2e7 N/m).

1. A job with `checkpoint 3` ends after three blocks of loading: exit code
   0, a CHECKPOINT line naming the step (6,000), checkpoint.restart and
   checkpoint.in written, no final state (no final.dump, no STOP line).
2. The same command with `resume 1`, on 2 ranks (the restart holds the
   whole state; the ranks may change between jobs), runs to the stop: no
   second specimen (the final state holds the grains of the first job),
   fabric_series.txt one row per check from step 0 to the stop step, every
   `every` steps, none twice and none missing, and the STOP line and the
   thermo's loading time count from the beginning of the loading.
3. A resume changes the state only in what LIGGGHTS' restart cannot carry
   (the walls' tangential springs, the servo's integral): the run resumed
   after every eight blocks by tools/oedometer_runs.py (the study's driver)
   ends at rest, its steps and wall time those of all its jobs, with a
   primary fraction within 5 points of the run without checkpoints (this
   specimen's block-to-block scatter is about 4 points; a resume that lost
   the contacts or the specimen would be far off); it prints a progress
   line per checkpoint.
4. The servo gets its integral back: a job resumed after the first
   block, with the lid still rising, prints a RESUME line with the lid's
   speed from checkpoint.in (its displacement over the last block / the
   block's time), and over the next block holds the lid stress as the run
   without checkpoints does: mean within 2 kPa of that run's, rms error at
   most 1.2 times that run's + 0.01 (0.1 kPa off, rms 0.064 against 0.068;
   with the integral restarted from zero: 6.8 kPa below, rms 0.134).
5. Bad values: `resume 2` and `checkpoint -1` stop with an ERROR naming the
   value; `resume 1` without a checkpoint stops with LIGGGHTS' ERROR naming
   the file it cannot open (no crash).
"""
import contextlib
import io
import os
import re
import sys

import scene_util as su

VARS = {"every": 2000, "side": 2.75, "kn": 2e7}


def series_steps(path):
    return [int(x) for x in su.outputs.read_series(path)["step"]]


def fabric(text):
    m = re.search(r"^FABRIC: loose \S+ % by number, primary fabric ([0-9.eE+-]+) % by mass",
                  text, re.M)
    return float(m.group(1)) if m else None


def thermo_column(text, name):
    """(step, value) of thermo column `name` in every row LIGGGHTS printed
    under a header line 'Step ... name ...', by the header's words."""
    rows, header = [], None
    for line in text.splitlines():
        w = line.split()
        if w[:1] == ["Step"]:
            header = w if name in w else None
        elif header is not None and len(w) == len(header) and re.match(r"^\d+$", w[0]):
            rows.append((int(w[0]), float(w[header.index(name)])))
        else:
            header = None
    return rows


def runner(args):
    """run(out, extra, nprocs, log): the scene with VARS, out and `extra`."""
    scene = os.path.join(args.source, "input_scripts", "in.oedometer")

    def run(out, extra, nprocs=None, log="job"):
        v = dict(VARS, out=out, **extra)
        return su.run_launcher(args, scene, nprocs=nprocs, variables=v,
                               log=os.path.join(args.work, log + ".log"),
                               cwd=args.source, timeout=600)
    return run


def check_checkpoint(chk, run, out):
    """1. A job that ends with a checkpoint."""
    first = run(out, {"checkpoint": 3}, log="first")
    ck = [l for l in first.output.splitlines() if l.startswith("CHECKPOINT:")]
    chk.check("checkpoint 3: the job ends with exit code 0 and a CHECKPOINT line at step 6000",
              first.returncode == 0 and ck and "step 6000" in ck[0]
              and "CHECKPOINT: written" in first.output, first.describe())
    chk.check("checkpoint.restart and checkpoint.in written, no final state, no STOP",
              os.path.isfile(os.path.join(out, "checkpoint.restart"))
              and os.path.isfile(os.path.join(out, "checkpoint.in"))
              and not os.path.exists(os.path.join(out, "final.dump"))
              and "STOP:" not in first.output)


def check_resume(chk, run, out):
    """2. Resumed on 2 ranks, to the stop: the first job's grains, one
    series row per check, the loading time from the start."""
    second = run(out, {"resume": 1}, nprocs=2, log="second")
    stop = [l for l in second.output.splitlines() if l.startswith("STOP:")]
    chk.check("resume 1 on 2 ranks runs to the stop", second.returncode == 0 and stop
              and stop[0].startswith("STOP: at rest"), second.describe())
    final = os.path.join(out, "final.dump")
    if not chk.check("the resumed job writes the final state", os.path.isfile(final)):
        chk.finish()
    snap = su.last_snapshot(final)
    with open(os.path.join(out, "grains_0.vtk")) as f:
        n0 = re.search(r"POINTS (\d+)", f.read())
    chk.check("no second specimen: the final state holds the %s grains of the first job (got %d)"
              % (n0.group(1) if n0 else "?", snap.natoms),
              n0 and snap.natoms == int(n0.group(1)))
    steps = series_steps(os.path.join(out, "fabric_series.txt"))
    n_stop = int(re.search(r"after (\d+) steps", stop[0]).group(1)) if stop else -1
    want = list(range(0, n_stop + 1, VARS["every"]))
    chk.check("fabric_series.txt: one row per check from 0 to the stop step %d, none twice "
              "or missing (%d rows)" % (n_stop, len(steps)), steps == want,
              "got %s" % steps)
    chk.check("no fabric_series.part left", not os.path.exists(os.path.join(out, "fabric_series.part")))
    dt = re.search(r"^TIMESTEP: .*; dt = (\S+) s", second.output, re.M)
    rows = thermo_column(second.output, "t_load")
    bad = [(st, t) for st, t in rows
           if dt and abs(t - st * float(dt.group(1))) > 1e-6 * st * float(dt.group(1))]
    chk.check("the resumed job's loading time (thermo t_load) is steps x dt from the start of "
              "the loading (%d rows)" % len(rows), dt and rows and not bad, bad[:5])


def check_driver(args, chk, run):
    """3. The driver: a checkpoint every 8 blocks, against the run without
    (folder 'whole', which part 4 compares with too)."""
    sys.path.insert(0, os.path.join(args.source, "tools"))
    import oedometer_runs
    whole = run(os.path.join(args.work, "whole"), {}, log="whole")
    p_whole = fabric(whole.output)
    rundir = os.path.join(args.work, "driver")
    progress = io.StringIO()
    with contextlib.redirect_stdout(progress):
        row = oedometer_runs.run_scene(rundir, dict(VARS, checkpoint=8))
    with open(os.path.join(rundir, "screen.txt")) as f:
        text = f.read()
    jobs = text.count("CHECKPOINT: written")
    lines = [l for l in progress.getvalue().splitlines() if "going on from the checkpoint" in l]
    chk.check("the driver prints a progress line per checkpoint (%d lines, %d checkpoints)"
              % (len(lines), jobs), len(lines) == jobs and jobs > 0
              and all("steps of loading" in l and "primary" in l for l in lines),
              progress.getvalue())
    p_split = float(row["primary_mass_pct"]) if row else None
    chk.check("the driver goes on from each checkpoint to the stop (%d checkpoints), at rest"
              % jobs, row and row["at_rest"] == "yes" and jobs >= 2, text[-2000:])
    with open(os.path.join(rundir, "wall_s.txt")) as f:
        wall = float(f.read())
    chk.check("the row's wall time is that of all the jobs (%.1f s)" % wall,
              row and abs(float(row["wall_s"]) - wall) < 0.2 and wall > 0)
    chk.check("primary %% by mass resumed every 8 blocks %s, without checkpoints %s: within 5 points"
              % (p_split, p_whole), p_split is not None and p_whole is not None
              and abs(p_split - p_whole) <= 5.0)


def block(path, step):
    """(lid stress, rms stress error) of the series row at `step`, or None."""
    s = su.outputs.read_series(path)
    hit = [i for i, st in enumerate(s["step"]) if int(st) == step]
    return (s["lid_stress"][hit[0]], s["stress_error_rms"][hit[0]]) if hit else None


def check_early_resume(args, chk, run):
    """4. An early resume: the lid's speed handed to the servo."""
    early = os.path.join(args.work, "early")
    e1 = run(early, {"checkpoint": 1, "t_max": 0.004}, log="early1")
    ck_path = os.path.join(early, "checkpoint.in")
    ck_in = open(ck_path).read() if os.path.isfile(ck_path) else ""
    e2 = run(early, {"checkpoint": 1, "t_max": 0.004, "resume": 1}, log="early2")
    v_ck = re.search(r"^variable lid_v_ck equal (\S+)", ck_in, re.M)
    line = re.search(r"^RESUME: the lid moved (\S+) m/s", e2.output, re.M)
    chk.check("the resumed job prints the lid's speed of checkpoint.in (%s, %s m/s), above zero"
              % (v_ck.group(1) if v_ck else None, line.group(1) if line else None),
              e1.returncode == 0 and e2.returncode == 0 and v_ck and line
              and float(v_ck.group(1)) > 0
              and abs(float(line.group(1)) - float(v_ck.group(1))) <= 1e-9 * float(v_ck.group(1)),
              e2.describe())
    after = block(os.path.join(early, "fabric_series.txt"), 2 * VARS["every"])
    ref = block(os.path.join(args.work, "whole", "fabric_series.txt"), 2 * VARS["every"])
    chk.check("over the block after the resume the lid stress averages %s Pa, rms error %s; "
              "without checkpoints %s Pa, %s: within 2 kPa, rms at most 1.2 times + 0.01"
              % (after and after[0], after and after[1], ref and ref[0], ref and ref[1]),
              after and ref and abs(after[0] - ref[0]) <= 2000.0
              and after[1] <= 1.2 * ref[1] + 0.01)


def check_bad_values(args, chk, run):
    """5. Bad values stop with an ERROR naming them; no checkpoint to
    resume from, with LIGGGHTS' ERROR naming checkpoint.in."""
    for extra, value in (({"resume": 2}, "2"), ({"checkpoint": -1}, "-1")):
        key = list(extra)[0]
        r = run(os.path.join(args.work, "bad_%s" % key), extra, log="bad_" + key)
        errs = r.errors()
        chk.check("%s %s: an ERROR naming it" % (key, value),
                  r.returncode != 0 and not r.crashed() and errs
                  and ("%s %s" % (key, value)) in errs[0], r.describe())
    none = os.path.join(args.work, "nothing")
    os.makedirs(none, exist_ok=True)
    r = run(none, {"resume": 1}, log="no_checkpoint")
    errs = [l for l in r.output.splitlines() if l.startswith("ERROR")]
    chk.check("resume 1 without a checkpoint: an ERROR naming checkpoint.in",
              r.returncode != 0 and not r.crashed() and errs and "checkpoint.in" in errs[0],
              r.describe())


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    run = runner(args)
    out = os.path.join(args.work, "split")
    check_checkpoint(chk, run, out)
    check_resume(chk, run, out)
    check_driver(args, chk, run)
    check_early_resume(args, chk, run)
    check_bad_values(args, chk, run)
    chk.finish()


if __name__ == "__main__":
    main()
