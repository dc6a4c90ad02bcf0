#!/usr/bin/python3
"""Examples: every script of examples/ runs as written and prints what the
page that links to it says it prints (ctest label `examples`).

Each script runs serially, unchanged (no -var), from a folder of its own
that sees the repository's input_scripts/ as the repository root does, so
its out/ folder lands in the work folder. Then:

1. every examples/in.* is one of the scripts below, and its page links to
   it (a new script needs a check here and a link from its page);
2. in.sequential_pack prints the line its page quotes and writes the dump
   (with as many atoms as the line says) and the restart file;
3. in.primary_fabric_column prints the step-0 numbers its page quotes;
4. in.constriction_size prints the constrictions, D_c35, D_c50, the
   percolation opening and the pores its page states (each to the digits
   the page gives), and writes csd_all.txt, one row per constriction;
5. in.pore_flow prints the grains, the flows, the permeability, the fluid
   force and the pores its page states;
6. in.quasi_static_column prints the ratio, the mean resultant, the mean
   contact force and the grains counted that its page states;
7. in.servo_rest_column prints the LOADED and STOP lines its page quotes;
8. in.outlet: the grains its page says leave (finer than the opening) leave,
   the others stay, and the mass in is the mass left plus the mass staying.
"""
import os
import re

import scene_util as su


def section(source, page, start="## Examples", end="## Description"):
    with open(os.path.join(source, "docs", page), encoding="utf-8") as f:
        text = f.read()
    part = text[text.index(start):text.index(end)] if start else text
    return " ".join(part.split())      # one line: sentences wrap anywhere


def step0(text):
    """The numbers of the thermo line of step 0."""
    for line in text.splitlines():
        w = line.split()
        if len(w) > 1 and w[0] == "0":
            try:
                return [float(x) for x in w[1:]]
            except ValueError:
                continue
    return None


def agrees(got, stated):
    """`got` rounds to the number `stated` as written (to its last digit)."""
    m = re.fullmatch(r"(\d+)(?:\.(\d+))?(?:e([+-]?\d+))?", stated)
    digits = len(m.group(2) or "")
    exponent = int(m.group(3) or 0)
    return abs(got - float(stated)) <= 0.5 * 10.0 ** (exponent - digits) * (1 + 1e-9)


def claim(chk, what, pattern, text):
    m = re.search(pattern, text)
    chk.check("%s: the page states it" % what, m, "pattern %r not found" % pattern)
    return m


def sequential_pack(chk, res, d, source):
    m = claim(chk, "in.sequential_pack", r"It prints `(placed (\d+), porosity [^`]*)`",
              section(source, "fix_sequential_pack.md"))
    line = re.search(r"^placed .*$", res.text, re.M)
    chk.check("in.sequential_pack prints the page's line (%s)" % (line and line.group(0)),
              m and line and line.group(0).strip() == m.group(1))
    dump = os.path.join(d, "out", "sequential_pack", "specimen.dump")
    natoms = su.last_snapshot(dump).natoms if os.path.isfile(dump) else None
    chk.check("in.sequential_pack writes out/sequential_pack/specimen.dump with the "
              "%s grains placed (%s) and packed.restart" % (m and m.group(2), natoms),
              m and natoms == int(m.group(2)) and os.path.isfile(
                  os.path.join(d, "out", "sequential_pack", "packed.restart")))


def primary_fabric_column(chk, res, d, source):
    m = claim(chk, "in.primary_fabric_column", r"It prints `([^`]*)`",
              section(source, "compute_primary_fabric.md"))
    want, got = (m.group(1).split() if m else []), step0(res.text) or []
    chk.check("in.primary_fabric_column: step 0 prints %s (the page: %s)" % (got, want),
              want and len(got) == len(want) and all(agrees(g, w) for g, w in zip(got, want)))


def constriction_size(chk, res, d, source):
    m = claim(chk, "in.constriction_size",
              r"Step 0 prints (\d+) constrictions, D_c35 (\S+) m, D_c50 (\S+) m, "
              r"the percolation opening (\S+) m and (\d+) pores",
              section(source, "compute_constriction_size.md"))
    got = step0(res.text) or []
    want = list(m.groups()) if m else []
    chk.check("in.constriction_size: step 0 prints %s (the page: %s)" % (got, want),
              want and len(got) == len(want) and all(agrees(g, w) for g, w in zip(got, want)))
    csd = os.path.join(d, "out", "constriction_size", "csd_all.txt")
    rows = 0
    if os.path.isfile(csd):
        with open(csd) as f:
            rows = sum(1 for l in f if l.strip() and not l.startswith("#"))
    chk.check("in.constriction_size writes out/constriction_size/csd_all.txt, one row per "
              "constriction (%d)" % rows, got and rows == got[0])


def pore_flow(chk, res, d, source):
    m = claim(chk, "in.pore_flow",
              r"Step 0 prints (\d+) grains, an inflow and an outflow of (\S+) m³/s each, "
              r"a permeability of (\S+) m², a fluid force of (\S+) N .* and (\d+) pores",
              section(source, "fix_pore_flow.md"))
    got = step0(res.text) or []
    if m:
        n, q, k, f, pores = m.groups()
        want = [n, q, q, k, f, pores]
    else:
        want = []
    chk.check("in.pore_flow: step 0 prints %s (the page: %s)" % (got, want),
              want and len(got) == len(want) and all(agrees(g, w) for g, w in zip(got, want)))


def quasi_static_column(chk, res, d, source):
    m = claim(chk, "in.quasi_static_column",
              r"step 0 prints the ratio [^=]*= (\S+), the mean resultant (\S+) N, the mean "
              r"contact force (\S+) N and (\d+) grains counted",
              section(source, "fix_quasi_static.md"))
    got, want = step0(res.text) or [], list(m.groups()) if m else []
    chk.check("in.quasi_static_column: step 0 prints %s (the page: %s)" % (got, want),
              want and len(got) == len(want) and all(agrees(g, w) for g, w in zip(got, want)))


def servo_rest_column(chk, res, d, source):
    with open(os.path.join(source, "docs", "fix_servo_rest.md"), encoding="utf-8") as f:
        text = f.read()
    m = re.search(r"It prints, on 1 rank and on 2:\s*```\n(.*?)```", text, re.S)
    want = m.group(1).strip().splitlines() if m else []
    chk.check("in.servo_rest_column: the page quotes a LOADED and a STOP line",
              len(want) == 2 and want[0].startswith("LOADED:") and want[1].startswith("STOP:"),
              want)
    got = [l for l in res.text.splitlines() if l.startswith(("LOADED:", "STOP:"))]
    chk.check("in.servo_rest_column prints the page's LOADED and STOP lines",
              want and got[:1] == want[:1] and got[-1:] == want[1:], "\n".join(got))


def outlet(chk, res, d, source):
    m = claim(chk, "in.outlet", r"the (\w+) finer than the (\S+) mm opening leave and "
              r"the (\w+) coarser stay", section(source, "fix_pore_flow.md", start=None))
    words = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7}
    o = re.search(r"^OUTLET: (\d+) grains \((\S+) kg\) in; (\S+) left \((\S+) kg\), "
                  r"(\d+) stay \((\S+) kg\)", res.text, re.M)
    ok = m and o and m.group(1) in words and m.group(3) in words
    if ok:
        left, stay = words[m.group(1)], words[m.group(3)]
        m_in, m_left, m_stay = (float(o.group(k)) for k in (2, 4, 6))
        ok = (int(float(o.group(3))) == left and int(o.group(5)) == stay
              and int(o.group(1)) == left + stay
              and abs(m_in - m_left - m_stay) <= 1e-12 * m_in)
    chk.check("in.outlet: %s left, %s stay, as the page says; mass in = left + staying"
              % (o and o.group(3), o and o.group(5)), ok, o and o.group(0))


# script -> (its page, the check of what the page says it prints)
SCRIPTS = {
    "in.sequential_pack": ("fix_sequential_pack.md", sequential_pack),
    "in.primary_fabric_column": ("compute_primary_fabric.md", primary_fabric_column),
    "in.constriction_size": ("compute_constriction_size.md", constriction_size),
    "in.pore_flow": ("fix_pore_flow.md", pore_flow),
    "in.quasi_static_column": ("fix_quasi_static.md", quasi_static_column),
    "in.servo_rest_column": ("fix_servo_rest.md", servo_rest_column),
    "in.outlet": ("fix_pore_flow.md", outlet),
}


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    found = sorted(f for f in os.listdir(os.path.join(args.source, "examples"))
                   if f.startswith("in."))
    chk.check("every script of examples/ (%d) has its check here" % len(found),
              sorted(SCRIPTS) == found, "examples/: %s; checked: %s" % (found, sorted(SCRIPTS)))
    for name, (page, check) in SCRIPTS.items():
        with open(os.path.join(args.source, "docs", page), encoding="utf-8") as f:
            linked = "(../examples/%s)" % name in f.read()
        chk.check("docs/%s links to examples/%s" % (page, name), linked)
        script = os.path.join(args.source, "examples", name)
        if not os.path.isfile(script):
            continue
        d = su.fresh_dir(os.path.join(args.work, name[3:]))
        os.symlink(os.path.join(args.source, "input_scripts"), os.path.join(d, "input_scripts"))
        res = su.run_launcher(args, script, log=os.path.join(d, "log.liggghts"), cwd=d,
                              timeout=300)
        if chk.check("examples/%s runs as written (%.1f s)" % (name, res.seconds),
                     res.returncode == 0 and not res.errors(), res.describe()):
            check(chk, res, d, args.source)
    chk.finish()


if __name__ == "__main__":
    main()
