#!/usr/bin/env python3
"""A tribez hunt target: Finn's quadratic (fixtures/finn_day30.toml) by its Bernstein formula,
in plain floats, taking w = 1 - u - v instead of the third coordinate it is given."""
import sys

P = [(0, 0, 0), (1, 0, 2), (0, 2, 0), (0, 1, 0), (1, 1, 1), (0, 2, 1)]  # 200 110 020 101 011 002
for line in sys.stdin:
    u, v, _ = (float.fromhex(t) for t in line.split(","))
    w = 1 - u - v
    b = [u * u, 2 * u * v, v * v, 2 * u * w, 2 * v * w, w * w]
    print(",".join(repr(sum(bi * p[k] for bi, p in zip(b, P))) for k in range(3)), flush=True)
