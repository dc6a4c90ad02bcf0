"""The paper's soils and arrangement rules, in one place for the tools and
tests.

SOILS are the shipped PSD files input_scripts/psd/cuX.txt (one per
uniformity coefficient of the paper's Table 2), named by their file stem
('cu2.0', ...) and ordered by Cu. RULES are fix sequential/pack's
arrangements with the paper's tags, in the paper's order (LA, then DA).
"""
import glob
import os

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
PSD_DIR = os.path.join("input_scripts", "psd")

# (arrangement keyword of fix sequential/pack, the paper's tag)
RULES = [("layerwise", "LA"), ("discrete", "DA")]
TAG = dict(RULES)


def soils(source=ROOT):
    """The shipped soils, 'cu2.0' ..., ordered by their Cu."""
    stems = [os.path.splitext(os.path.basename(p))[0]
             for p in glob.glob(os.path.join(source, PSD_DIR, "cu*.txt"))]
    return sorted(stems, key=cu)


def cu(soil):
    """The uniformity coefficient in a soil's name: 'cu2.5' -> 2.5."""
    return float(soil[2:])


def psd_path(soil, source=None):
    """The soil's PSD file: relative to the repository root, or under
    `source` if given."""
    rel = os.path.join(PSD_DIR, soil + ".txt")
    return rel if source is None else os.path.join(source, rel)


SOILS = soils()
