#!/usr/bin/python3
"""Scene test: an error raised through LIGGGHTS' error->one reaches a
redirected output, and the log file keeps everything up to the error.

error->one prints "ERROR on proc N: ..." to the screen and calls MPI_Abort,
which kills the processes without flushing their stdio buffers. Stock
liggghts, with its output redirected to a file as in a batch job, leaves
only Open MPI's abort notice there and a 0-byte log. The launcher
line-buffers its streams and flushes them in an MPI_Abort hook
(launcher/main.cpp). Checked without mpirun and with mpirun -np 2, output
redirected to a file (not a pipe, not a terminal):

1. a missing `include` file (error->one on rank 0, from input.cpp);
2. the same error after a short run, so that thermo output and the run's
   summary are pending when the abort comes.
"""
import os
import subprocess
import time

import scene_util as su

SCRIPT = """\
units           si
print           "MARK BEFORE THE ERROR"
{run}include         {missing}
print           "MARK AFTER THE ERROR"
"""

RUN = """\
atom_style      atomic
atom_modify     sort 0 0
region          box block 0 1 0 1 0 1 units box
create_box      1 box
mass            1 1.0
thermo_style    custom step atoms
thermo          1
run             3
"""


def run_to_file(args, name, text, nprocs):
    work = su.fresh_dir(os.path.join(args.work, name))
    inp = su.write_file(os.path.join(work, "in.bad"), text)
    out_path = os.path.join(work, "output.txt")
    log_path = os.path.join(work, "log.bad")
    cmd = [] if nprocs is None else su.mpirun_prefix(args, nprocs)
    cmd += [args.launcher, "-in", inp, "-log", log_path, "-echo", "both"]
    t0 = time.time()
    with open(out_path, "w") as out:
        try:
            rc = subprocess.call(cmd, cwd=work, stdin=subprocess.DEVNULL,
                                 stdout=out, stderr=subprocess.STDOUT,
                                 timeout=120)
        except subprocess.TimeoutExpired:
            rc = None
    with open(out_path, errors="replace") as f:
        output = f.read()
    log = ""
    if os.path.isfile(log_path):
        with open(log_path, errors="replace") as f:
            log = f.read()
    return rc, output, log, time.time() - t0


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    missing = os.path.join(args.work, "no_such_file.in")
    for case, run in (("include", ""), ("include_after_run", RUN)):
        for nprocs in (None, 2):
            name = "%s_%s" % (case, "serial" if nprocs is None else "np%d" % nprocs)
            rc, output, log, secs = run_to_file(
                args, name, SCRIPT.format(run=run, missing=missing), nprocs)
            where = "%s (%s, %.1f s)" % (case, "no mpirun" if nprocs is None
                                         else "mpirun -np %d" % nprocs, secs)
            chk.check("%s: the run fails (exit code %s)" % (where, rc),
                      rc not in (0, None), output[-2000:])
            err = [l for l in output.splitlines()
                   if l.startswith("ERROR") and "no_such_file.in" in l]
            chk.check("%s: the redirected output holds the ERROR line" % where,
                      bool(err), output[-2000:])
            chk.check("%s: the output holds what came before the error" % where,
                      "MARK BEFORE THE ERROR" in output, output[-2000:])
            chk.check("%s: the log file is not empty and reaches the failing "
                      "command" % where,
                      "MARK BEFORE THE ERROR" in log and "include" in log
                      and "MARK AFTER" not in log.replace('print           "MARK AFTER', ""),
                      "log (%d bytes):\n%s" % (len(log), log[-1500:]))
            if run:
                chk.check("%s: the log keeps the run's thermo output" % where,
                          "Loop time" in log, log[-1500:])
    chk.finish()


if __name__ == "__main__":
    main()
