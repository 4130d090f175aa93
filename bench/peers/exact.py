"""Exact evaluation of a Bézier triangle by the exact-arithmetic peers of tribez.

Backends: gmpy2 (GMP), flint (python-flint, FLINT), fractions (the standard library), sympy.
Algorithms, all exact and all giving the same values:

  horner     integer homogeneous Horner: the point (a, b, c)/q with one common denominator q,
             the control values of each coordinate scaled to integers X_α by the lcm L of their
             denominators and multiplied by the multinomials C(n; α) once per patch; then
             H = Σ_α C(n; α) X_α a^i b^j c^k, each row k (a polynomial in a, b) by Horner and
             the rows combined by Horner in c, and one division at the end: p = H / (q^n L).
             O(n^2) integer operations per point.
  casteljau  rational de Casteljau, n levels of c' = u c1 + v c2 + w c3 on rationals
             (O(n^3) rational operations, each reducing a fraction).

    python exact.py CASE.json --backend gmpy2 --algo horner          # the values, as JSON
    python exact.py CASE.json --backend gmpy2 --algo horner --time   # microseconds per point

The values are printed {"results": [["p/q", ...], ...]} in lowest terms ("p" for integers), the
way tribez prints them, so the two can be compared as text. --time prints one JSON line; the
timing covers the per-point work only (best of --repeat runs), not reading or preparing the patch.
"""

import argparse
import json
import math
import sys
import time
from fractions import Fraction

from workload import canonical_indices, read_case, text


class Backend:
    """Integers and rationals of one library."""

    def __init__(self, name):
        self.name = name
        if name == "gmpy2":
            import gmpy2

            self.version = gmpy2.version()
            self.integer, self.rational = gmpy2.mpz, gmpy2.mpq
        elif name == "flint":
            import flint

            self.version = flint.__version__
            self.integer, self.rational = flint.fmpz, flint.fmpq
        elif name == "fractions":
            self.version = sys.version.split()[0]
            self.integer, self.rational = int, Fraction
        elif name == "sympy":
            import sympy

            self.version = sympy.__version__
            self.integer, self.rational = sympy.Integer, sympy.Rational
        else:
            raise SystemExit(f"unknown backend {name} (gmpy2, flint, fractions, sympy)")

    def q(self, fr):
        return self.rational(self.integer(fr.numerator), self.integer(fr.denominator))

    def as_fraction(self, x):
        if isinstance(x, Fraction):
            return x
        if self.name == "flint":
            return Fraction(int(x.p), int(x.q))
        if self.name == "sympy":
            return Fraction(int(x.p), int(x.q))
        return Fraction(int(x.numerator), int(x.denominator))


class Horner:
    """Integer homogeneous Horner, prepared once per patch."""

    def __init__(self, backend, n, nodes):
        self.b, self.n = backend, n
        idx = canonical_indices(n)
        z = backend.integer
        self.rows = []  # per coordinate: rows k = 0..n of scaled integers s_α = C(n; α) X_α
        self.scale = []
        for c in range(len(nodes[0])):
            L = math.lcm(*(p[c].denominator for p in nodes))
            mult = [math.factorial(n) // (math.factorial(i) * math.factorial(j) * math.factorial(k)) for i, j, k in idx]
            s = [z(m * p[c].numerator * (L // p[c].denominator)) for m, p in zip(mult, nodes)]
            rows, start = [], 0
            for k in range(n + 1):
                rows.append(s[start:start + n - k + 1])
                start += n - k + 1
            self.rows.append(rows)
            self.scale.append(L)

    def __call__(self, lam):
        b, n = self.b, self.n
        q = math.lcm(*(x.denominator for x in lam))
        a1, a2, a3 = (b.integer(x.numerator * (q // x.denominator)) for x in lam)
        den = b.integer(q) ** n
        out = []
        for rows, L in zip(self.rows, self.scale):
            acc = rows[n][0]
            for k in range(n - 1, -1, -1):
                row = rows[k]
                t, vp = row[0], 1
                for j in range(1, len(row)):
                    vp = vp * a2
                    t = t * a1 + row[j] * vp
                acc = acc * a3 + t
            out.append(b.rational(acc, den * L))
        return out


class Casteljau:
    """Rational de Casteljau, prepared once per patch."""

    def __init__(self, backend, n, nodes):
        self.b, self.n = backend, n
        self.cols = [[backend.q(p[c]) for p in nodes] for c in range(len(nodes[0]))]
        # plan[r]: for each index of degree n-r-1, the ranks of its three parents in degree n-r
        rank = lambda i, j, k, d: k * (2 * d + 3 - k) // 2 + j  # noqa: E731
        self.plan = [
            [(rank(i + 1, j, k, d), rank(i, j + 1, k, d), rank(i, j, k + 1, d)) for i, j, k in canonical_indices(d - 1)]
            for d in range(n, 0, -1)
        ]

    def __call__(self, lam):
        u, v, w = (self.b.q(x) for x in lam)
        out = []
        for col in self.cols:
            vals = col
            for level in self.plan:
                vals = [u * vals[x] + v * vals[y] + w * vals[z] for x, y, z in level]
            out.append(vals[0])
        return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--backend", default="gmpy2")
    ap.add_argument("--algo", choices=["horner", "casteljau"], default="horner")
    ap.add_argument("--time", action="store_true", help="print the time per point instead of the values")
    ap.add_argument("--repeat", type=int, default=5, help="best of this many timed runs")
    ap.add_argument("--points", type=int, help="use only the first POINTS points")
    args = ap.parse_args()

    n, nodes, points = read_case(args.case)
    if args.points is not None:
        points = points[: args.points]
    if not points:
        raise SystemExit(f"{args.case}: no points")
    backend = Backend(args.backend)
    evaluate = (Horner if args.algo == "horner" else Casteljau)(backend, n, nodes)

    if not args.time:
        values = [[text(backend.as_fraction(x)) for x in evaluate(p)] for p in points]
        json.dump({"backend": backend.name, "algo": args.algo, "results": values}, sys.stdout)
        sys.stdout.write("\n")
        return
    best = math.inf
    for _ in range(args.repeat):
        t0 = time.perf_counter()
        for p in points:
            evaluate(p)
        best = min(best, time.perf_counter() - t0)
    print(json.dumps({
        "tool": args.backend, "version": backend.version, "algo": args.algo, "degree": n,
        "points": len(points), "seconds": best, "us_per_point": best / len(points) * 1e6,
    }))


if __name__ == "__main__":
    main()
