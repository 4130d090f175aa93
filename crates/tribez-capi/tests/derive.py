#!/usr/bin/env python3
"""Independent expected values for the C ABI tests (src/tests.rs, examples/c): Python's exact
fractions and float(Fraction) (correctly rounded, ties to even), no tribez.

Finn's quadratic triangle in R^3, control points in the canonical order 200, 110, 020, 101,
011, 002: (0,0,0), (1,0,2), (0,2,0), (0,1,0), (1,1,1), (0,2,1). Its homogeneous form at
(u, v, w): sum over |a| = 2 of 2!/(a0! a1! a2!) u^a0 v^a1 w^a2 P_a.

Run: python3 crates/tribez-capi/tests/derive.py
"""
from fractions import Fraction as F
import random

NET = {(2, 0, 0): (0, 0, 0), (1, 1, 0): (1, 0, 2), (0, 2, 0): (0, 2, 0),
       (1, 0, 1): (0, 1, 0), (0, 1, 1): (1, 1, 1), (0, 0, 2): (0, 2, 1)}
COEF = {(2, 0, 0): 1, (1, 1, 0): 2, (0, 2, 0): 1, (1, 0, 1): 2, (0, 1, 1): 2, (0, 0, 2): 1}


def exact(u, v, w):
    u, v, w = F(u), F(v), F(w)
    out = [F(0)] * 3
    for a, p in NET.items():
        b = COEF[a] * u ** a[0] * v ** a[1] * w ** a[2]
        for c in range(3):
            out[c] += b * p[c]
    return out


def casteljau(u, v, w):
    """A double de Casteljau, as examples/c does it (level by level, u*b_i+1 + v*b_j+1 + w*b_k+1)."""
    b = dict(NET)
    for r in (2, 1):
        nb = {}
        for k in range(r):
            for j in range(r - k):
                i = r - 1 - j - k
                nb[(i, j, k)] = tuple(u * b[(i + 1, j, k)][c] + v * b[(i, j + 1, k)][c] + w * b[(i, j, k + 1)][c]
                                      for c in range(3))
        b = nb
    return b[(0, 0, 0)]


if __name__ == "__main__":
    print("(1/2, 1/3, 1/6):", [str(x) for x in exact(F(1, 2), F(1, 3), F(1, 6))])
    print("(0.5, 0.25, 0.25):", [str(x) for x in exact(0.5, 0.25, 0.25)])
    p = (0.5, 0.1, 0.4)
    print("(0.5, 0.1, 0.4) as doubles, correctly rounded:", [float(x).hex() for x in exact(*p)])
    # a point where the double de Casteljau is not correctly rounded in some coordinate
    rng = random.Random(7)
    for _ in range(10000):
        u = rng.random(); v = rng.random() * (1 - u); w = 1 - u - v
        e = exact(u, v, w)
        cr = [float(x) for x in e]
        dc = casteljau(u, v, w)
        if dc != tuple(cr):
            print("point", [x.hex() for x in (u, v, w)])
            print("  correctly rounded", [x.hex() for x in cr])
            print("  de Casteljau     ", [x.hex() for x in dc])
            break
