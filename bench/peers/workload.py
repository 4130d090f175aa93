"""Benchmark cases for tribez and its peers: one JSON file per case.

A case is {"degree": n, "dim": d, "nodes": [[x, y, z], ...], "points": [[l1, l2, l3], ...]}:
the control points of a Bézier triangle in tribez's canonical order (rows k = 0..n, j ascending
inside a row; the node order of the Python package `bezier` too) and barycentric points, every
number an exact rational written "p/q" (or "p").

The reference workload: control values p/q with |p| <= 2^16 and 1 <= q <= 2^16, drawn
independently; barycentric points (a/q, b/q, c/q) with one common denominator 1 <= q <= 2^16 and
a + b + c = q, so every point sums to 1 exactly; dimension 3.

    python workload.py --degree 10 --points 1000 --seed 1010 > case.json
"""

import argparse
import json
import random
import sys
from fractions import Fraction


def text(q):
    """'p/q' in lowest terms, or 'p' for an integer (tribez's own printing)."""
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def canonical_indices(n):
    """(i, j, k) with i + j + k = n in canonical order: k ascending, then j ascending."""
    return [(n - j - k, j, k) for k in range(n + 1) for j in range(n - k + 1)]


def make_case(degree, dim, points, seed, bits=16):
    rng = random.Random(seed)
    top = 1 << bits

    def value():
        return Fraction(rng.randint(-top, top), rng.randint(1, top))

    nodes = [[value() for _ in range(dim)] for _ in canonical_indices(degree)]
    pts = []
    for _ in range(points):
        q = rng.randint(1, top)
        a = rng.randint(0, q)
        b = rng.randint(0, q - a)
        pts.append([Fraction(a, q), Fraction(b, q), Fraction(q - a - b, q)])
    return {
        "degree": degree,
        "dim": dim,
        "nodes": [[text(x) for x in p] for p in nodes],
        "points": [[text(x) for x in p] for p in pts],
    }


def read_case(path):
    """The case as Fractions: (degree, nodes, points)."""
    with open(path) as f:
        case = json.load(f)
    nodes = [[Fraction(x) for x in p] for p in case["nodes"]]
    points = [[Fraction(x) for x in p] for p in case.get("points", [])]
    n = case["degree"]
    if len(nodes) != (n + 1) * (n + 2) // 2:
        raise SystemExit(f"{path}: degree {n} needs {(n + 1) * (n + 2) // 2} nodes, got {len(nodes)}")
    return n, nodes, points


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--degree", type=int, required=True)
    ap.add_argument("--dim", type=int, default=3)
    ap.add_argument("--points", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    json.dump(make_case(args.degree, args.dim, args.points, args.seed), sys.stdout)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
