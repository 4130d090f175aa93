#!/usr/bin/env python3
"""Target (1) in Python, the same arithmetic as bernstein_f32.c: the direct Bernstein sum in f32,
each operation done in f64 and rounded to binary32 (exact emulation: an f64 product or sum of two
binary32 numbers rounded to binary32 is the binary32 operation's result, as f64 has more than
2 * 24 + 2 bits). Usage: bernstein_f32.py PATCH.net"""
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from proto import multinomial, read_net, serve  # noqa: E402

_f = struct.Struct("f")


def f32(x):
    return _f.unpack(_f.pack(x))[0]


def main():
    n, d, points = read_net(sys.argv[1])
    coef = [(idx, [f32(multinomial(n, idx) * c) for c in cs]) for idx, cs in points]

    def evaluate(lam):
        u, v, w = (f32(x) for x in lam)
        pu, pv, pw = [1.0], [1.0], [1.0]
        for _ in range(n):
            pu.append(f32(pu[-1] * u))
            pv.append(f32(pv[-1] * v))
            pw.append(f32(pw[-1] * w))
        out = []
        for e in range(d):
            s = 0.0
            for (i, j, k), cs in coef:
                t = f32(cs[e] * pu[i])
                t = f32(t * pv[j])
                t = f32(t * pw[k])
                s = f32(s + t)
            out.append(s)
        return out

    serve(evaluate)


if __name__ == "__main__":
    main()
