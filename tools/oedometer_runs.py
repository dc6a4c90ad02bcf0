#!/usr/bin/python3
"""Run input_scripts/in.oedometer with settings and read back its result:
the one runner of the oedometer chart (bench/oedometer_chart/run.py) and the
study of the paper's models (tools/oedometer_study.py).

run_scene(rundir, variables, ranks) runs a copy of the scene (LIGGGHTS reads
its script as it goes: a copy keeps the run safe from edits) from the
repository root with `-var out rundir`, and returns one row: wall time,
steps, whether the run stopped at rest, the lid stress, primary % by mass,
loose % by number, the OZ % (the paper's rule and oz_tolerance), the
anisotropies a_c and a_n, and the grains; None if the run failed (its
output is in rundir/screen.txt). With `checkpoint` N among the variables,
each job ends after N blocks with a checkpoint and the next job goes on
from it (`resume` 1) until the run stops; a folder that already holds a
checkpoint (a job cut off, e.g. by a session's or a queue's time limit)
goes on from it with its own copy of the scene, and the wall time adds up
over the jobs (rundir/wall_s.txt).

run_all(todo, jobs, one, csv_path, fields, order) runs `one(item)` for each
item, `jobs` at a time, and appends each row to csv_path as it comes
(resumable: the callers skip the names the CSV already holds).
"""
import csv
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import outputs  # noqa: E402  (the compute's output tables)

RESULT_FIELDS = ["wall_s", "steps", "at_rest", "lid_stress_Pa", "primary_mass_pct",
                 "loose_number_pct", "oz_mass_pct", "oz_tolerant_mass_pct",
                 "fabric_anisotropy", "force_anisotropy", "grains"]


def run_scene(rundir, variables, ranks=1):
    os.makedirs(rundir, exist_ok=True)
    scene = os.path.join(rundir, "in.oedometer")
    screen = os.path.join(rundir, "screen.txt")
    wall_file = os.path.join(rundir, "wall_s.txt")
    resume = (os.path.exists(os.path.join(rundir, "checkpoint.restart"))
              and os.path.exists(scene) and os.path.exists(screen))
    # the scene and its parts are copied, so that a resumed job runs the
    # scene it began with
    parts = os.path.join(rundir, "oedometer")
    if not resume:
        shutil.copyfile(os.path.join(ROOT, "input_scripts", "in.oedometer"), scene)
        shutil.rmtree(parts, ignore_errors=True)
        shutil.copytree(os.path.join(ROOT, "input_scripts", "oedometer"), parts)
        if os.path.exists(wall_file):
            os.remove(wall_file)
    wall = float(open(wall_file).read()) if resume and os.path.exists(wall_file) else 0.0
    while True:
        cmd = [os.path.join(ROOT, "build", "liggghts-fabric"), "-in", scene,
               "-log", os.path.join(rundir, "log.lammps"), "-var", "out", rundir,
               "-var", "parts", parts]
        for k, val in variables.items():
            cmd += ["-var", k, str(val)]
        cmd += ["-var", "resume", "1" if resume else "0"]
        if ranks > 1:
            root = ["--allow-run-as-root"] if os.geteuid() == 0 else []
            cmd = ["mpirun"] + root + ["--oversubscribe", "-np", str(ranks)] + cmd
        t0 = time.perf_counter()
        with open(screen, "a" if resume else "w") as f:
            start = f.tell()
            rc = subprocess.call(cmd, stdout=f, stderr=subprocess.STDOUT, cwd=ROOT)
        wall += time.perf_counter() - t0
        with open(wall_file, "w") as f:
            f.write("%.1f\n" % wall)
        with open(screen, errors="replace") as f:
            f.seek(start)
            job = f.read()
        if rc != 0:
            sys.stderr.write("exit %d: see %s/screen.txt\n" % (rc, rundir))
            return None
        if "CHECKPOINT: written" in job and not re.search(r"^STOP: ", job, re.M):
            line = re.search(r"^CHECKPOINT: after .*?(\d+ steps of loading).*?unbalanced-force ratio (\S+) "
                             r"\(rest_tol (\S+)\), kinetic energy (\S+) J"
                             r".*?primary fabric (\S+) %", job, re.M)
            if line:
                ratio, tol, ke = (float(line.group(k)) for k in (2, 3, 4))
                where = ("unbalanced-force ratio %.3g (rest below %g)" % (ratio, tol) if tol > 0
                         else "kinetic energy %.3g J (the energy rule)" % ke)
                print("%s: %s, %s, primary %.2f %% by mass; %.0f s so far, going on from the checkpoint"
                      % (os.path.basename(rundir), line.group(1), where, float(line.group(5)), wall),
                      flush=True)
            resume = True
            continue
        break
    # the result by name: the protocol's (rest.txt) and the compute's
    # (fabric_global.txt), as tools/outputs.py reads them
    rest = outputs.read_rest(os.path.join(rundir, "rest.txt"))
    v = outputs.read_global(os.path.join(rundir, "fabric_global.txt"))
    if rest is None or v is None or not rest["ended"]:
        sys.stderr.write("no result (rest.txt, fabric_global.txt): see %s/screen.txt\n" % rundir)
        return None
    pos = outputs.index(outputs.fabric_vector())
    row = {"wall_s": "%.1f" % wall, "steps": "%d" % rest["steps"],
           "at_rest": "yes" if rest["phase_name"] == "at rest" else "no",
           "lid_stress_Pa": "%.0f" % rest["rest_stress"],
           "grains": "%d" % v[pos["particles"]]}
    for field, name, fmt in (("primary_mass_pct", "primary_percent_by_mass", "%.2f"),
                             ("loose_number_pct", "loose_percent_by_number", "%.2f"),
                             ("oz_mass_pct", "overlapping_zone_percent", "%.2f"),
                             ("oz_tolerant_mass_pct", "overlapping_zone_tolerant_percent", "%.2f"),
                             ("fabric_anisotropy", "fabric_anisotropy", "%.4f"),
                             ("force_anisotropy", "force_anisotropy", "%.4f")):
        row[field] = fmt % v[pos[name]]
    return row


def read_rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def run_all(todo, jobs, one, csv_path, fields, order):
    """one(item) -> row or None; rows go to csv_path as they come, sorted by
    order (a list of names)."""
    def write(rows):
        rows.sort(key=lambda r: order.index(r["name"]) if r["name"] in order else len(order))
        with open(csv_path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
            w.writeheader()
            w.writerows(rows)
    with ThreadPoolExecutor(max_workers=jobs) as ex:
        for fut in as_completed([ex.submit(one, item) for item in todo]):
            row = fut.result()
            if row:
                write(read_rows(csv_path) + [row])
