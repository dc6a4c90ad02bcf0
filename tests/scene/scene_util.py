"""Shared helpers of the scene tests (tests/scene/test_*.py).

A scene test writes a small LIGGGHTS input into its work folder, runs the
launcher (build/liggghts-fabric) on it, serially or under mpirun, and checks
the output and the dumps. CTest runs every test as

    /usr/bin/python3 tests/scene/test_X.py --launcher PATH --source REPO_ROOT
                                           --work WORKDIR

and the test passes iff it exits 0. Only the standard library and numpy.
The outputs of our styles (their positions and names) come from tools/
(tools/outputs.py, the tables of the C++ headers), as do the soils
(tools/soils.py).
"""

import argparse
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DATA_DIR = os.path.join(HERE, "data")
# the tools of the repository these tests belong to (the --source of CTest)
TOOLS_DIR = os.path.join(HERE, os.pardir, os.pardir, "tools")
sys.path.insert(0, os.path.abspath(TOOLS_DIR))
import outputs  # noqa: E402
import soils  # noqa: E402


# ---- the oedometer scene -------------------------------------------------

def oedometer_text(source):
    """input_scripts/in.oedometer and the parts it includes
    (input_scripts/oedometer/*.in), as one text: what the scene runs."""
    scripts = os.path.join(source, "input_scripts")
    parts = sorted(os.path.join(scripts, "oedometer", f)
                   for f in os.listdir(os.path.join(scripts, "oedometer")) if f.endswith(".in"))
    text = ""
    for path in [os.path.join(scripts, "in.oedometer")] + parts:
        with open(path) as f:
            text += f.read() + "\n"
    return text


# ---- command line --------------------------------------------------------

def parse_args(description):
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--launcher", required=True,
                   help="the liggghts-fabric executable")
    p.add_argument("--source", required=True, help="the repository root")
    p.add_argument("--work", required=True,
                   help="a folder for inputs, logs and dumps (created)")
    p.add_argument("--mpirun", default=shutil.which("mpirun") or "mpirun",
                   help="mpirun to use for multi-rank runs")
    p.add_argument("--timeout", type=float, default=120.0,
                   help="seconds allowed for one launcher run")
    a = p.parse_args()
    a.launcher = os.path.abspath(a.launcher)
    a.source = os.path.abspath(a.source)
    a.work = os.path.abspath(a.work)
    os.makedirs(a.work, exist_ok=True)
    return a


def fresh_dir(path):
    """An empty folder at `path` (only ever a folder inside WORKDIR)."""
    if os.path.isdir(path):
        shutil.rmtree(path)
    os.makedirs(path)
    return path


# ---- pass/fail bookkeeping -----------------------------------------------

class Checker:
    """Prints one line per check and the final 'N passed, M failed'."""

    def __init__(self):
        self.passed = 0
        self.failed = 0
        self.t0 = time.time()

    def check(self, what, ok, detail=""):
        ok = bool(ok)
        if ok:
            self.passed += 1
        else:
            self.failed += 1
        line = "[%s] %s" % ("PASS" if ok else "FAIL", what)
        if detail and not ok:
            line += "\n       " + str(detail).replace("\n", "\n       ")
        print(line, flush=True)
        return ok

    def note(self, text):
        print("       " + text, flush=True)

    def finish(self):
        print("%d passed, %d failed (%.1f s)"
              % (self.passed, self.failed, time.time() - self.t0), flush=True)
        sys.exit(0 if self.failed == 0 else 1)


# ---- running the launcher ------------------------------------------------

class Result:
    def __init__(self, cmd, returncode, output, seconds, timed_out, log):
        self.cmd = cmd
        self.returncode = returncode
        self.output = output          # stdout and stderr together
        self.seconds = seconds
        self.timed_out = timed_out
        self.log = log                # text of the -log file ('' if none)

    @property
    def text(self):
        """Everything the run printed: its output and its log file."""
        return self.output + "\n" + self.log

    def errors(self):
        """The lines that carry 'ERROR:' (LIGGGHTS error->all / one)."""
        return [l for l in self.text.splitlines() if "ERROR:" in l]

    def crashed(self):
        """True for a death by signal (negative code, 128+N from a shell or
        mpirun) or the usual crash messages."""
        if self.timed_out:
            return False
        if self.returncode < 0 or self.returncode >= 128:
            return True
        return bool(re.search(r"Segmentation fault|signal \d+|core dumped|"
                              r"terminate called|Aborted|free\(\): |"
                              r"double free|corrupted",
                              self.output))

    def describe(self):
        tail = "\n".join(self.output.strip().splitlines()[-15:])
        return ("command: %s\nexit code %s%s after %.1f s\n--- last output "
                "lines ---\n%s" % (" ".join(self.cmd), self.returncode,
                                   " (timed out)" if self.timed_out else "",
                                   self.seconds, tail))


def mpirun_prefix(args, nprocs):
    cmd = [args.mpirun]
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    # (ranks yield the core while they wait: more ranks than cores, or a
    # second job beside them, no longer spin against each other)
    cmd += ["--oversubscribe", "--mca", "mpi_yield_when_idle", "1", "-np", str(nprocs)]
    return cmd


def run_launcher(args, input_path, nprocs=None, variables=None, log=None,
                 cwd=None, timeout=None):
    """Runs the launcher on `input_path` (nprocs None: without mpirun).

    The run's stdout and stderr are captured together (never -screen none);
    its log goes to `log` (default: next to the input, .log). On a timeout the
    whole process group (mpirun and its ranks) is killed."""
    if log is None:
        log = os.path.splitext(input_path)[0] + ".log"
    if cwd is None:
        cwd = os.path.dirname(os.path.abspath(input_path))
    cmd = [] if nprocs is None else mpirun_prefix(args, nprocs)
    cmd += [args.launcher, "-in", input_path, "-log", log, "-echo", "both"]
    for name, value in (variables or {}).items():
        # a list: an index variable of several values (-var name v1 v2 ...)
        values = value if isinstance(value, (list, tuple)) else [value]
        cmd += ["-var", name] + [str(v) for v in values]
    timeout = args.timeout if timeout is None else timeout
    t0 = time.time()
    try:
        proc = subprocess.Popen(cmd, cwd=cwd, stdin=subprocess.DEVNULL,
                                stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT,
                                start_new_session=True)
    except OSError as e:   # no launcher or no mpirun
        return Result(cmd, 127, "cannot start %s: %s" % (cmd[0], e), 0.0,
                      False, "")
    timed_out = False
    try:
        out, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, _ = proc.communicate()
    seconds = time.time() - t0
    text = out.decode("utf-8", errors="replace")
    logtext = ""
    if os.path.isfile(log):
        with open(log, errors="replace") as f:
            logtext = f.read()
    with open(os.path.splitext(log)[0] + ".out", "w") as f:
        f.write(text)   # kept for a look after a failure
    return Result(cmd, proc.returncode, text, seconds, timed_out, logtext)


# ---- input scripts -------------------------------------------------------

def write_file(path, text):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    return path


def num(v):
    """A number for an input script, exactly as Python holds it."""
    return repr(float(v))


# Contact model and material of in.pack: needed so that `run` sets up pair
# gran (its cut-off comes from the fix's max_rad) and the material checks pass.
MATERIALS = """\
pair_style      gran model hooke tangential history
pair_coeff      * *
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
fix m5 all property/global characteristicVelocity scalar 0.1
neigh_modify    delay 0
timestep        1e-7
"""


def preamble(atom_style="granular", processors=None):
    """The settings every granular scene here starts with (newton off and an
    atom map: compute primary/fabric needs both)."""
    lines = ["units           si",
             "atom_style      %s" % atom_style,
             "atom_modify     map array",
             "boundary        f f f",
             "newton          off",
             "communicate     single vel yes"]
    if processors:
        lines.append("processors      %s" % processors)
    return "\n".join(lines) + "\n"


def header(box, atom_style="granular", processors=None):
    """units .. create_box for a box [0, box]^3 (box: edge or (x, y, z))."""
    if not isinstance(box, (tuple, list)):
        box = (box, box, box)
    return preamble(atom_style, processors) + (
        "region          box block 0 %s 0 %s 0 %s units box\n"
        % tuple(num(b) for b in box) + "create_box      1 box\n")


def block_region(rid, lo, hi, extra=""):
    return ("region          %s block %s %s %s %s %s %s units box%s\n"
            % (rid, num(lo[0]), num(hi[0]), num(lo[1]), num(hi[1]),
               num(lo[2]), num(hi[2]), " " + extra if extra else ""))


def dump_lines(dump_id, path, fix_id, every=1):
    """A sorted `dump custom` with full precision (%.17g round-trips)."""
    return ("dump            %s all custom %d %s id type x y z radius f_%s\n"
            "dump_modify     %s sort id format \"%%d %%d %%.17g %%.17g %%.17g "
            "%%.17g %%.17g\"\n" % (dump_id, every, path, fix_id, dump_id))


def pack_scene(psd, edge, porosity=0.4, arrangement="discrete", seed=1,
               fix_id="pack", extra_fix="", processors=None, dump=None,
               run="run 0"):
    """A cube container [0, edge]^3 filling the box, packed by the fix."""
    text = header(edge, processors=processors)
    text += block_region("container", (0, 0, 0), (edge, edge, edge))
    text += ("fix             %s all sequential/pack psd %s porosity %s "
             "arrangement %s region container seed %d%s\n"
             % (fix_id, psd, num(porosity), arrangement, seed,
                " " + extra_fix if extra_fix else ""))
    text += MATERIALS
    if dump:
        text += dump_lines("d1", dump, fix_id)
    text += run + "\n"
    text += vector_print(fix_id)
    return text


def vector_print(fix_id):
    """Input lines that print the fix's global vector as one line
    (positions from fix_sequential_pack/pack_outputs.h)."""
    return outputs.pack_vector_print(fix_id)


def pack_vector(text):
    """The fix's global vector as printed by vector_print(): a dict by name
    of pack_outputs.h (the last such line), or None."""
    return outputs.pack_vector_values(text)


# ---- reading results -----------------------------------------------------

# LAMMPS text dumps: tools/outputs.py reads them (columns by the names of
# the dump's ITEM: ATOMS / ITEM: ENTRIES line: snap.col("c_pf[2]"))
Snapshot = outputs.Snapshot
read_dump = outputs.read_dump
last_snapshot = outputs.last_snapshot


def nlocal_stats(text):
    """(ave, max, min) of the last 'Nlocal: A ave M max m min' line."""
    found = re.findall(r"^Nlocal:\s+(\S+) ave (\S+) max (\S+) min", text,
                       re.M)
    if not found:
        return None
    return tuple(float(v) for v in found[-1])


def pack_summary(text):
    """From the fix's summary: (in the list, placed, not placed) or None."""
    m = re.search(r"particles: (\d+) in the list, (\d+) placed .*?, (\d+) "
                  r"not placed", text)
    return tuple(int(v) for v in m.groups()) if m else None


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def numbers_in(text):
    return [float(t) for t in NUMBER.findall(text)]


def mentions_number(text, value, rel=1e-9):
    """Whether `text` prints `value` (in any format, to `rel`)."""
    for v in numbers_in(text):
        if v == value or (value != 0 and abs(v - value) <= rel * abs(value)):
            return True
    return False


def warnings_of(text, style):
    """The WARNING lines that LIGGGHTS printed for our style `style` (e.g.
    'sequential/pack'), each once: the facts a test reads from them are
    their numbers (numbers_in), not their wording."""
    seen = []
    for line in text.splitlines():
        if "WARNING:" in line and style in line and line not in seen:
            seen.append(line)
    return seen


def names_value(text, value, tol):
    """Whether `text` prints a number within `tol` of `value` (a value
    printed rounded, e.g. to 3 decimals: tol 6e-4)."""
    return any(abs(v - value) <= tol for v in numbers_in(text))


def max_overlap(x, r, block=512):
    """Largest (r_i + r_j - |x_i - x_j|) / (r_i + r_j) over pairs i != j."""
    n = len(r)
    worst = -math.inf
    for s in range(0, n, block):
        e = min(s + block, n)
        d = np.sqrt(((x[s:e, None, :] - x[None, :, :]) ** 2).sum(-1))
        rs = r[s:e, None] + r[None, :]
        ov = (rs - d) / rs
        ov[np.arange(e - s), np.arange(s, e)] = -math.inf
        worst = max(worst, float(ov.max()))
    return worst
