"""Benchmark: judging 1,000,000 f64 rows of a degree-3 patch from numpy arrays (tribez.check)
against the command line's `tribez check --results` on the same rows (a CSV this script writes);
then, on fewer rows, tribez.check_locate and tribez.check_ray against `--locate-results` and
`--ray-results`.

    python python/bench/bench_check.py [--rows N] [--inverse-rows M] [--cli PATH] [--repeat K]

Needs the package installed in release mode (`pip install ./python`, which maturin builds with
optimisations) and a release build of the command line (`cargo build --release -p tribez-cli`;
default path target/release/tribez). The rows: random barycentric points (u, v in [0, 1),
w = 1 - u - v in f64, some outside the triangle), values from the patch's own f64 de Casteljau
(`Patch.evaluate_float`), printed in the CSV with Python's shortest round-trip repr, which the
CLI reads back to the same doubles (--precision f64). Both sides judge at cond=9.

The inverse batches (M rows, default 1,000; 0 skips them): locate on
fixtures/inverse/peer/triangle.toml (a planar cubic) at the points P(1 - s - t, s, t) of random
(s, t) in the triangle, claiming (s, t); rays straight down onto fixtures/inverse/cubic_surface.toml
from 1 above P(1 - s - t, s, t), claiming the hit (1, s, t); both at tolerance abs=1e-9. Their
rows pass to Python as numbers and reach the library as text either way, and each row costs
exact algebraic work (milliseconds), so the ratio there is about 1: the figure shows that the
Python call adds nothing to the engine's time.

Prints the best of K wall-clock times of each side and their ratio (Python / CLI), the same
ratio of CPU times (user + system over all threads: steadier on a machine shared with other
work), and for
`tribez.check` its CPU time over its wall time (about the number of cores busy: the GIL is
released and rayon judges on every core). The Python
time includes the conversion of the arrays; the CLI time includes reading and parsing the CSV
(which is the point: numpy arrays need no text).
"""

from __future__ import annotations

import argparse
import os
import pathlib
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

import tribez

ROOT = pathlib.Path(__file__).resolve().parents[2]
PATCH = ROOT / "fixtures" / "peers" / "peer_cubic.toml"
LOCATE_PATCH = ROOT / "fixtures" / "inverse" / "peer" / "triangle.toml"
RAY_PATCH = ROOT / "fixtures" / "inverse" / "cubic_surface.toml"


def rows(patch: tribez.Patch, n: int, seed: int = 3):
    rng = np.random.default_rng(seed)
    u = rng.random(n) * 1.1 - 0.05
    v = (1 - u) * rng.random(n)
    w = 1.0 - u - v
    points = np.column_stack([u, v, w])
    values = patch.evaluate_float(points)
    return points, values


def write_csv(path: pathlib.Path, points: np.ndarray, values: np.ndarray) -> None:
    data = np.hstack([points, values])
    with open(path, "w") as f:
        f.write("# u, v, w, x, y, z (f64, shortest round-trip)\n")
        for row in data.tolist():
            f.write(",".join(map(repr, row)))
            f.write("\n")


def parameters(n: int, seed: int = 5) -> np.ndarray:
    """n random (s, t) strictly inside the triangle s, t >= 0, s + t <= 1."""
    rng = np.random.default_rng(seed)
    s = rng.uniform(0.05, 0.9, n)
    t = (0.95 - s) * rng.uniform(0.05, 0.95, n)
    return np.column_stack([s, t])


def at(patch: tribez.Patch, st: np.ndarray) -> np.ndarray:
    """The patch's f64 values at the barycentric points (1 - s - t, s, t)."""
    return patch.evaluate_float(np.column_stack([1.0 - st[:, 0] - st[:, 1], st[:, 0], st[:, 1]]))


def write_rows(path: pathlib.Path, rows: np.ndarray) -> None:
    with open(path, "w") as f:
        for row in rows.tolist():
            f.write(",".join(map(repr, row)))
            f.write("\n")


def inverse(args) -> None:
    """check_locate and check_ray against --locate-results and --ray-results on the same rows."""
    n = args.inverse_rows
    st = parameters(n)
    tri = tribez.Patch.from_file(LOCATE_PATCH)
    xy = at(tri, st)
    surface = tribez.Patch.from_file(RAY_PATCH)
    p = at(surface, st)
    rays = np.column_stack([p[:, 0], p[:, 1], p[:, 2] + 1.0, np.zeros(n), np.zeros(n), -np.ones(n)])
    hits = np.column_stack([np.ones(n), st])
    tol = "abs=1e-9"
    cases = [
        ("check_locate", "--locate-results", LOCATE_PATCH,
         lambda: tribez.check_locate(tri, xy, st, tolerance=tol, precision="f64"),
         np.hstack([xy, st])),
        ("check_ray", "--ray-results", RAY_PATCH,
         lambda: tribez.check_ray(surface, rays, hits, tolerance=tol, precision="f64"),
         np.hstack([rays, hits])),
    ]
    with tempfile.TemporaryDirectory() as d:
        for name, flag, patch_file, call, rows_ in cases:
            try:
                report = call()
            except tribez.InputError as e:  # a query the exact engine refuses (its caps)
                print(f"tribez.{name} ({n} rows): refused: {e}")
                continue
            t_py = best(call, args.repeat)
            csv = pathlib.Path(d) / f"{name}.csv"
            write_rows(csv, rows_)
            cmd = [args.cli, "check", "--patch", str(patch_file), flag, str(csv),
                   "--precision", "f64", "--tolerance", tol]
            out = subprocess.run(cmd, capture_output=True, text=True)
            if out.returncode not in (0, 1):
                print(out.stderr, file=sys.stderr)
                raise SystemExit(2)
            t_cli = best(lambda: subprocess.run(cmd, capture_output=True), args.repeat)
            last = out.stdout.strip().splitlines()[-1]
            print(f"tribez.{name} ({n} rows):  {t_py:.3f} s   passed {report.passed}, failed {report.failed}")
            print(f"tribez check {flag} (CSV): {t_cli:.3f} s   {last}")
            print(f"ratio Python / CLI: {t_py / t_cli:.3f} (wall-clock time)")


def best(f, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def best_cpu(f, repeat: int, children: bool = False) -> float:
    """The least CPU time (user + system, every thread) of `repeat` calls of f: of this process,
    or with `children` of the subprocesses it waited for. Less sensitive than wall-clock time to
    other work on a shared machine."""
    who = resource.RUSAGE_CHILDREN if children else resource.RUSAGE_SELF
    times = []
    for _ in range(repeat):
        r0 = resource.getrusage(who)
        f()
        r1 = resource.getrusage(who)
        times.append((r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime))
    return min(times)


def thread_cpu() -> dict:
    """CPU ticks (user + system) of each thread of this process, from /proc (Linux; {} elsewhere)."""
    out = {}
    base = pathlib.Path("/proc/self/task")
    if not base.is_dir():
        return out
    for t in base.iterdir():
        try:
            fields = (t / "stat").read_text().rsplit(")", 1)[1].split()
            out[t.name] = int(fields[11]) + int(fields[12])  # utime, stime (fields 14, 15)
        except (OSError, IndexError, ValueError):
            pass
    return out


def threads_busy(f) -> str:
    """Which threads did the work of f: their share of its CPU time (Linux only)."""
    before = thread_cpu()
    f()
    after = thread_cpu()
    deltas = sorted((after[t] - before.get(t, 0) for t in after), reverse=True)
    total = sum(deltas)
    if not total:
        return "per-thread CPU time unavailable"
    shares = [d / total for d in deltas if d / total >= 0.05]
    return f"{len(shares)} threads did it (" + ", ".join(f"{x:.0%}" for x in shares) + " of its CPU time)"


def cpu_per_wall(f) -> float:
    """CPU time of this process (all its threads) over wall-clock time for one call of f: about
    the number of cores busy meanwhile (2 when both cores judge)."""
    c0, t0 = time.process_time(), time.perf_counter()
    f()
    return (time.process_time() - c0) / (time.perf_counter() - t0)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--cli", default=str(ROOT / "target" / "release" / "tribez"))
    ap.add_argument("--tolerance", default="cond=9")
    ap.add_argument("--inverse-rows", type=int, default=1000)
    args = ap.parse_args()

    patch = tribez.Patch.from_file(PATCH)
    assert patch.degree == 3
    points, values = rows(patch, args.rows)
    print(f"{args.rows} rows of {PATCH.relative_to(ROOT)} (degree {patch.degree}), tolerance {args.tolerance}, "
          f"{tribez.threads()} threads")

    report = tribez.check(patch, points, values, tolerance=args.tolerance)
    t_py = best(lambda: tribez.check(patch, points, values, tolerance=args.tolerance), args.repeat)
    busy = cpu_per_wall(lambda: tribez.check(patch, points, values, tolerance=args.tolerance))
    c_py = best_cpu(lambda: tribez.check(patch, points, values, tolerance=args.tolerance), args.repeat)
    spread = threads_busy(lambda: tribez.check(patch, points, values, tolerance=args.tolerance))
    print(f"tribez.check (numpy arrays):   {t_py:.3f} s   passed {report.passed}, failed {report.failed}, "
          f"fell back {report.fell_back}; CPU time / wall time {busy:.2f}; {spread}")

    if not os.path.exists(args.cli):
        print(f"no CLI at {args.cli}: build it with `cargo build --release -p tribez-cli`", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory() as d:
        csv = pathlib.Path(d) / "rows.csv"
        write_csv(csv, points, values)
        cmd = [args.cli, "check", "--patch", str(PATCH), "--results", str(csv),
               "--precision", "f64", "--tolerance", args.tolerance]
        out = subprocess.run(cmd, capture_output=True, text=True)
        if out.returncode not in (0, 1):
            print(out.stderr, file=sys.stderr)
            return 2
        last = out.stdout.strip().splitlines()[-1]
        t_cli = best(lambda: subprocess.run(cmd, capture_output=True), args.repeat)
        c_cli = best_cpu(lambda: subprocess.run(cmd, capture_output=True), args.repeat, children=True)
    print(f"tribez check --results (CSV):  {t_cli:.3f} s   {last}")
    print(f"ratio Python / CLI: {t_py / t_cli:.3f} (wall-clock time); "
          f"{c_py / c_cli:.3f} (CPU time: {c_py:.3f} s / {c_cli:.3f} s)")
    if args.inverse_rows > 0:
        inverse(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
