#!/usr/bin/env python3
"""Write the benchmark's patches: patches/NAME.toml (what tribez reads) and patches/NAME.net (the
same control points as plain integers, what the target programs read).

A .net file: a first line `degree dimension`, then one line per control point `i j k c_1 ... c_d`,
the control point of multi-index (i, j, k), i.e. of the Bernstein polynomial
n!/(i! j! k!) u^i v^j w^k with (u, v, w) the row's barycentric coordinates in order.

Every control value is a small integer, so the targets read them exactly in f32 and f64 and the
only errors are those of the evaluation itself. Run with no arguments from anywhere.
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def indices(n):
    """Multi-indices (i, j, k) of degree n in tribez's canonical order (k ascending, then j)."""
    return [(n - j - k, j, k) for k in range(n + 1) for j in range(n + 1 - k)]


def lcg_values(n, count, seed):
    """`count` integers in [-9, 9] from a fixed linear congruential generator (reproducible)."""
    x = seed
    out = []
    for _ in range(count):
        x = (6364136223846793005 * x + 1442695040888963407) % 2**64
        out.append((x >> 33) % 19 - 9)
    return out


def write(name, comment, n, points):
    dim = len(points[0][1])
    lines = [f"# {line}" for line in comment] + [f'name = "{name}"', f"degree = {n}", "", "[control_points]"]
    for (i, j, k), c in points:
        lines.append(f'"{i},{j},{k}" = [' + ", ".join(f'"{v}"' for v in c) + "]")
    with open(os.path.join(HERE, "patches", name + ".toml"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(HERE, "patches", name + ".net"), "w") as f:
        f.write(f"{n} {dim}\n")
        for (i, j, k), c in points:
            f.write(f"{i} {j} {k} " + " ".join(str(v) for v in c) + "\n")


def main():
    # (1) degree 5, scalar, signs mixed: the value crosses zero inside the triangle, where the
    # direct Bernstein sum in f32 cancels
    idx = indices(5)
    vals = lcg_values(5, len(idx), 33)
    write(
        "quintic_signed",
        ["Benchmark patch for target (1), the direct Bernstein sum in f32 (bench/hunt/README.md).",
         "Written by bench/hunt/make_patches.py: integers in [-9, 9] of mixed signs."],
        5,
        [(a, [v]) for a, v in zip(idx, vals)],
    )
    # (2) degree 8, scalar, signs mixed: the power basis's coefficients are large (multinomials
    # times binomials of (1 - u - v)^k) and cancel
    idx = indices(8)
    vals = lcg_values(8, len(idx), 8)
    write(
        "octic_signed",
        ["Benchmark patch for target (2), the power basis in f64 (bench/hunt/README.md).",
         "Written by bench/hunt/make_patches.py: integers in [-9, 9] of mixed signs."],
        8,
        [(a, [v]) for a, v in zip(idx, vals)],
    )
    # (3), (4) a cubic in R^2 with positive control points (1 + r, 2 + r + r mod 3), r the
    # multi-index's rank: positive values, condition number 1, so de Casteljau in f64 is within
    # `cond` everywhere and only the planted faults break it
    idx = indices(3)
    write(
        "cubic_positive",
        ["Benchmark patch for targets (3) and (4), correct f64 de Casteljau with a planted fault",
         "(bench/hunt/README.md). Written by bench/hunt/make_patches.py: control point r (canonical",
         "order) is (1 + r, 2 + r + r mod 3), positive, so the condition number is 1."],
        3,
        [(a, [1 + r, 2 + r + r % 3]) for r, a in enumerate(idx)],
    )


if __name__ == "__main__":
    main()
