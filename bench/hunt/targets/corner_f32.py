#!/usr/bin/env python3
"""Target (4) in Python, as corner_f32.c: de Casteljau in f64 on the inputs rounded to f32 when a
coordinate is above 0.999. Usage: corner_f32.py PATCH.net"""
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from proto import casteljau, read_net, serve  # noqa: E402

_f = struct.Struct("f")


def main():
    n, _, points = read_net(sys.argv[1])

    def evaluate(lam):
        if max(lam) > 0.999:
            lam = [_f.unpack(_f.pack(x))[0] for x in lam]
        return casteljau(n, points, lam)

    serve(evaluate)


if __name__ == "__main__":
    main()
