#!/usr/bin/env python3
"""Target (3) in Python, as band_fault.c: de Casteljau in f64, the result multiplied by 1 + 2^-20
when the smallest barycentric coordinate lies in [1e-9, 2e-9]. Usage: band_fault.py PATCH.net"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from proto import casteljau, read_net, serve  # noqa: E402


def main():
    n, _, points = read_net(sys.argv[1])

    def evaluate(lam):
        out = casteljau(n, points, lam)
        if 1e-9 <= min(lam) <= 2e-9:
            out = [x * (1.0 + 2.0**-20) for x in out]
        return out

    serve(evaluate)


if __name__ == "__main__":
    main()
