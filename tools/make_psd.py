#!/usr/bin/python3
"""Write a sieve-analysis PSD file with a chosen coefficient of uniformity.

The curve is a log-normal distribution by mass, truncated at +-2 standard
deviations of ln(d) and renormalised to 0..100 %, sampled at 16 sieve sizes
spaced evenly in log(d). For an untruncated log-normal
Cu = d60/d10 = exp(sigma (z60 - z10)); sigma is found by bisection so that
the truncated curve has the requested Cu, and the curve is scaled so that
d10 is the requested value.

    /usr/bin/python3 tools/make_psd.py CU D10_METRES > file.txt
"""
import math
import sys


def phi(z):
    return 0.5 * (1.0 + math.erf(z / math.sqrt(2.0)))


def curve(sigma, d50, n=16, cut=2.0):
    lo, hi = phi(-cut), phi(cut)
    pts = []
    for i in range(n):
        z = -cut + 2.0 * cut * i / (n - 1)
        d = d50 * math.exp(sigma * z)
        pts.append((d, 100.0 * (phi(z) - lo) / (hi - lo)))
    pts[0] = (pts[0][0], 0.0)
    pts[-1] = (pts[-1][0], 100.0)
    return pts


def d_at(pts, p):
    for (d0, p0), (d1, p1) in zip(pts, pts[1:]):
        if p1 >= p and p1 > p0:
            t = (p - p0) / (p1 - p0)
            return math.exp(math.log(d0) + t * (math.log(d1) - math.log(d0)))
    return pts[-1][0]


def main():
    cu, d10 = float(sys.argv[1]), float(sys.argv[2])
    a, b = 0.01, 3.0
    for _ in range(100):
        s = 0.5 * (a + b)
        pts = curve(s, 1.0)
        if d_at(pts, 60) / d_at(pts, 10) < cu:
            a = s
        else:
            b = s
    pts = curve(s, 1.0)
    scale = d10 / d_at(pts, 10)
    print(f"# Cu = {cu:g} soil: log-normal by mass, sigma(ln d) = {s:.4f},")
    print(f"# truncated at +-2 sigma, d10 = {d10:g} m; made by")
    print(f"#   /usr/bin/python3 tools/make_psd.py {cu:g} {d10:g}")
    print("# diameter(m)  percent_passing")
    for d, p in pts:
        print(f"{d * scale:.6e}  {p:.3f}")


main()
