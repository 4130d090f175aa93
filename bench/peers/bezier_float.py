"""Float evaluation of a Bézier triangle by the Python package `bezier` (its compiled
Triangle.evaluate_barycentric_multi), the closest float peer of tribez.

    python bezier_float.py CASE.json                 # bezier's f64 values at the case's points
    python bezier_float.py CASE.json --time 100000   # microseconds per point, M random points

The case's exact numbers are rounded once to the nearest double. `bezier` evaluates
Σ C(n; α) λ^α c_α by a Horner-like scheme per row (not de Casteljau). The timing is the one
call on all M points (best of --repeat), without input conversion.
"""

import argparse
import json
import math
import sys
import time

import bezier
import numpy as np

from workload import read_case


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--time", type=int, metavar="M", help="time M random points")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()

    n, nodes, points = read_case(args.case)
    # bezier wants the nodes as a (dim, N) Fortran array; x.numerator / x.denominator is the
    # correctly rounded double of a Fraction.
    arr = np.asfortranarray([[x.numerator / x.denominator for x in col] for col in zip(*nodes)])
    triangle = bezier.Triangle(arr, degree=n, copy=False, verify=False)

    if args.time:
        rng = np.random.default_rng(args.seed)
        st = rng.random((args.time, 2))
        flip = st.sum(axis=1) > 1.0
        st[flip] = 1.0 - st[flip]
        pts = np.asfortranarray(np.column_stack([1.0 - st[:, 0] - st[:, 1], st[:, 0], st[:, 1]]))
        triangle.evaluate_barycentric_multi(np.asfortranarray(pts[:8]), verify=False)  # warm-up
        best = math.inf
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            triangle.evaluate_barycentric_multi(pts, verify=False)
            best = min(best, time.perf_counter() - t0)
        print(json.dumps({
            "tool": "bezier", "version": bezier.__version__, "degree": n, "points": args.time,
            "seconds": best, "us_per_point": best / args.time * 1e6,
        }))
        return
    pts = np.asfortranarray([[x.numerator / x.denominator for x in p] for p in points])
    values = triangle.evaluate_barycentric_multi(pts, verify=False)
    json.dump({"tool": "bezier", "version": bezier.__version__, "results": values.T.tolist()}, sys.stdout)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
