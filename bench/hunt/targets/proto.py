"""The pipe protocol of `tribez hunt` for the benchmark's Python targets (bench/hunt/README.md),
the same as proto.h: rows of comma-separated hex floats on standard input, one answer line per
row (hex floats, exact) on standard output, every answer to a block written before the next read.
"""
import math
import os
import sys


def read_net(path):
    """(degree, dimension, [((i, j, k), [c_1, ..., c_d])]) from a .net file."""
    with open(path) as f:
        n, d = map(int, f.readline().split())
        points = []
        for line in f:
            parts = line.split()
            if parts:
                points.append((tuple(map(int, parts[:3])), [float(x) for x in parts[3:3 + d]]))
    return n, d, points


def multinomial(n, idx):
    return math.factorial(n) // math.prod(math.factorial(i) for i in idx)


def casteljau(n, points, lam):
    """de Casteljau in f64, as casteljau.h: b^{l-1}_{ijk} = u b_{i+1,j,k} + v b_{i,j+1,k} + w b_{i,j,k+1}."""
    u, v, w = lam
    b = {idx: list(c) for idx, c in points}
    for level in range(n, 0, -1):
        nxt = {}
        for k in range(level):
            for j in range(level - k):
                i = level - 1 - j - k
                a, bb, c = b[(i + 1, j, k)], b[(i, j + 1, k)], b[(i, j, k + 1)]
                nxt[(i, j, k)] = [u * x + v * y + w * z for x, y, z in zip(a, bb, c)]
        b = nxt
    return b[(0, 0, 0)]


def serve(evaluate):
    """Answer every row of standard input with evaluate([u, v, w]) -> [values]."""
    pending = b""
    while True:
        block = os.read(0, 1 << 20)
        if not block:
            break
        pending += block
        *lines, pending = pending.split(b"\n")
        out = []
        for line in lines:
            lam = [float.fromhex(x.decode()) for x in line.split(b",")]
            out.append(",".join(float.hex(y) for y in evaluate(lam)))
        if out:
            sys.stdout.write("\n".join(out) + "\n")
            sys.stdout.flush()
