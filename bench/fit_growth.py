#!/usr/bin/env python3
"""Inputs for timing `tribez fit` as the mesh and the data grow (issue 14's speed figures).

    python3 bench/fit_growth.py OUT_DIR
    for f in OUT_DIR/*.sh; do bash "$f"; done      # or time each command line by hand

Writes meshes of the unit square as kx × ky cells cut along a diagonal (2·kx·ky triangles, the
same grids as `cargo bench --bench fit`), data files of N points with 4-digit decimal coordinates
from the same linear congruential sequence and 6-decimal values of sin(3x)·cos(2y) + x·y, and one
line per case to run. Python's standard library only; tribez is not used to make its inputs.
"""
import math
import sys
from pathlib import Path

CASES = [  # (kx, ky, points, degree)
    (5, 1, 10_000, 2),
    (5, 5, 1_000, 2),
    (5, 5, 10_000, 2),
    (10, 10, 10_000, 2),
    (5, 5, 100_000, 2),
]


def mesh(kx, ky, n):
    lines = [f"degree = {n}", "vertices = ["]
    for j in range(ky + 1):
        for i in range(kx + 1):
            lines.append(f'  ["{i}/{kx}", "{j}/{ky}"],')
    lines.append("]")
    lines.append("triangles = [")
    vid = lambda i, j: j * (kx + 1) + i
    for j in range(ky):
        for i in range(kx):
            lines.append(f"  [{vid(i, j)}, {vid(i + 1, j)}, {vid(i + 1, j + 1)}],")
            lines.append(f"  [{vid(i, j)}, {vid(i + 1, j + 1)}, {vid(i, j + 1)}],")
    lines.append("]")
    return "\n".join(lines) + "\n"


def data(count):
    seed = 2024
    mask = (1 << 64) - 1
    out = ["x,y,value"]
    for _ in range(count):
        seed = (seed * 6364136223846793005 + 1442695040888963407) & mask
        a = (seed >> 33) % 10_001
        seed = (seed * 6364136223846793005 + 1442695040888963407) & mask
        b = (seed >> 33) % 10_001
        x, y = a / 1e4, b / 1e4
        v = math.sin(3 * x) * math.cos(2 * y) + x * y
        out.append(f"{a}/10000,{b}/10000,{v:.6f}")
    return "\n".join(out) + "\n"


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else "fit_growth")
    out.mkdir(parents=True, exist_ok=True)
    for kx, ky, points, n in CASES:
        m = out / f"grid_{kx}x{ky}_n{n}.toml"
        m.write_text(mesh(kx, ky, n))
        d = out / f"data_{points}.csv"
        if not d.exists():
            d.write_text(data(points))
        name = f"{2 * kx * ky}tri_{points}pts_n{n}"
        (out / f"{name}.sh").write_text(
            f"tribez fit {d} --mesh {m} --regularize > /dev/null\n"
        )
        print(name, m, d)


if __name__ == "__main__":
    main()
