#!/usr/bin/env python3
"""The hunt benchmark of issue 33 (bench/hunt/README.md): `tribez hunt` against uniform random
points on four float implementations with known weaknesses, and the hunt's own cost.

For each target and seed: `tribez hunt` with --budget 10000 (--tolerance cond) gives its largest
error in ULPs and whether a row broke `cond`; the same target answers 10,000 and 1,000,000 uniform
random points of the triangle, judged by `tribez check --results` at the same tolerance. Then the
hunt's own cost per row (a hunt whose target answers a constant without reading its rows, against
`check --results` on those same rows and answers) and its rows per second through the pipe.

Needs python3, a C compiler (`cc`) and a release build of tribez (`cargo build --release -p
tribez-cli`, and for the cost `cargo build --release -p tribez --example hunt_cost`).
Usage: python3 bench/hunt/run.py [--seeds 10] [--quick] [--python] [--only cost|search]
"""
import argparse
import json
import math
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# (label, program, patch, precision, python version or None)
TARGETS = [
    ("(1) Bernstein sum, f32, n=5", "bernstein_f32", "quintic_signed", "f32", "bernstein_f32.py"),
    ("(2) power basis, f64, n=8", "power_f64", "octic_signed", "f64", None),
    ("(3) band fault, f64, n=3", "band_fault", "cubic_positive", "f64", "band_fault.py"),
    ("(4) f32 near a corner, f64, n=3", "corner_f32", "cubic_positive", "f64", "corner_f32.py"),
]
HELPERS = ["constant", "uniform", "casteljau"]


def build(out):
    for name in [t[1] for t in TARGETS] + HELPERS:
        src = os.path.join(HERE, "targets", name + ".c")
        subprocess.run(["cc", "-O2", "-o", os.path.join(out, name), src, "-lm"], check=True)


def patch(name, ext):
    return os.path.join(HERE, "patches", f"{name}.{ext}")


def ulps(x):
    return math.inf if x is None else float(x)


def timed(cmd, **kw):
    """Run cmd; (CompletedProcess, wall seconds, CPU seconds of it and everything it waited for)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run(cmd, **kw)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return p, wall, cpu


def run_hunt(tribez, target_cmd, patch_toml, precision, budget, seed, tolerance="cond"):
    cmd = [tribez, "hunt", patch_toml, "--precision", precision, "--tolerance", tolerance,
           "--budget", str(budget), "--seed", str(seed), "--format", "json"]
    cmd += ["--"] + target_cmd
    p, wall, cpu = timed(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 1):
        sys.exit(f"hunt failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr}")
    r = json.loads(p.stdout)
    top = ulps(r["worst"][0]["ulps"]) if r["worst"] else 0.0
    return top, r["broke"], wall, cpu


def check_csv(tribez, patch_toml, precision, csv, tolerance="cond"):
    cmd = [tribez, "check", "--patch", patch_toml, "--results", csv, "--precision", precision,
           "--tolerance", tolerance, "--format", "json"]
    p, wall, cpu = timed(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 1):
        sys.exit(f"check failed ({p.returncode}): {' '.join(cmd)}\n{p.stderr}")
    return json.loads(p.stdout), wall, cpu


def check_summary(report):
    """(largest error in ULPs, rows that broke the tolerance) from check --results --format json."""
    worst = report.get("worst") or {}
    return (ulps(worst.get("ulps")) if worst else 0.0), report["summary"]["failed"]


def run_uniform(tribez, tmp, bindir, target_cmd, patch_name, precision, seed, n):
    rows = os.path.join(tmp, "rows.txt")
    answers = os.path.join(tmp, "answers.txt")
    csv = os.path.join(tmp, "uniform.csv")
    with open(rows, "w") as f:
        subprocess.run([os.path.join(bindir, "uniform"), str(seed), str(n), precision], stdout=f,
                       check=True)
    with open(rows) as fin, open(answers, "w") as fout:
        subprocess.run(target_cmd, stdin=fin, stdout=fout, check=True)
    with open(csv, "w") as f:
        subprocess.run(["paste", "-d,", rows, answers], stdout=f, check=True)
    report, _, _ = check_csv(tribez, patch(patch_name, "toml"), precision, csv)
    return check_summary(report)


def fmt(x):
    if math.isinf(x):
        return "inf"
    return f"{x:.3g}"


def search(args, tribez, bindir, tmp):
    seeds = range(args.seeds)
    sizes = [10_000] if args.quick else [10_000, 1_000_000]
    rows = []
    for number, (label, prog, pname, prec, py) in enumerate(TARGETS, 1):
        if args.target and number not in args.target:
            continue
        if args.python and py:
            cmd = [sys.executable, os.path.join(HERE, "targets", py), patch(pname, "net")]
        else:
            cmd = [os.path.join(bindir, prog), patch(pname, "net")]
        hunt_max, hunt_broke, uni = [], 0, {n: ([], 0) for n in sizes}
        for s in seeds:
            top, broke, wall, _ = run_hunt(tribez, cmd, patch(pname, "toml"), prec, args.budget, s)
            hunt_max.append(top)
            hunt_broke += broke > 0
            line = f"{label} seed {s}: hunt {fmt(top)} ulp, {broke} broke ({wall:.2f} s)"
            for k, n in enumerate(sizes):
                # independent points for each size: seed 2s for 10k, 2s+1 for 1M
                m, failed = run_uniform(tribez, tmp, bindir, [os.path.join(bindir, prog),
                                        patch(pname, "net")], pname, prec, 2 * s + k, n)
                uni[n][0].append(m)
                uni[n] = (uni[n][0], uni[n][1] + (failed > 0))
                line += f"; uniform {n}: {fmt(m)} ulp, {failed} broke"
            print(line, flush=True)
        rows.append((label, hunt_max, hunt_broke, uni))
    n_big = sizes[-1]
    print()
    print(f"| target | hunt {args.budget}: median max ulp | uniform {n_big}: median max ulp | "
          f"hunt ≥ uniform (seeds) | seeds hunt broke cond | "
          + " | ".join(f"seeds uniform {n} broke cond / median max ulp" for n in sizes) + " |")
    print("|---" * (5 + len(sizes)) + "|")
    for label, hunt_max, hunt_broke, uni in rows:
        wins = sum(h >= u for h, u in zip(hunt_max, uni[n_big][0]))
        print(f"| {label} | {fmt(statistics.median(hunt_max))} | "
              f"{fmt(statistics.median(uni[n_big][0]))} | {wins}/{len(hunt_max)} | "
              f"{hunt_broke}/{len(hunt_max)} | "
              + " | ".join(f"{uni[n][1]}/{len(hunt_max)}, {fmt(statistics.median(uni[n][0]))}"
                           for n in sizes) + " |")


def cost_case(args, tribez, tmp, label, pname, tolerance, target, answers, in_memory=None):
    """One line of the cost table: a hunt of args.cost_rows rows (seed 1, f64) against `check
    --results` on the same rows and answers (and, given `in_memory`, the same hunt run in memory
    by the example hunt_cost). `target` is the target's command line; `answers(rows_file,
    csv_file)` writes the CSV of the recorded rows and their answers."""
    n = args.cost_rows
    toml = patch(pname, "toml")
    record = os.path.join(tmp, "hunt_rows.txt")
    # the rows the hunt gives (the same seed gives the same rows), recorded once through tee
    tee = ["sh", "-c", 'tee "$0" | "$@"', record] + target
    run_hunt(tribez, tee, toml, "f64", n, 1, tolerance)
    csv = os.path.join(tmp, "hunt_rows.csv")
    answers(record, csv)
    runs = {}
    for _ in range(args.repeat):
        _, _, hw, hc = run_hunt(tribez, target, toml, "f64", n, 1, tolerance)
        with open(record) as fin:
            _, tw, tc = timed(target, stdin=fin, stdout=subprocess.DEVNULL)
        _, cw, cc = check_csv(tribez, toml, "f64", csv, tolerance)
        got = {"hw": hw, "hc": hc, "tc": tc, "cw": cw, "cc": cc}
        if in_memory:
            p, mw, mc = timed(in_memory + [toml, "f64", tolerance, str(n), "1", in_memory_value],
                              capture_output=True, text=True, check=True)
            got["mw"], got["mc"] = mw, mc
        for k, v in got.items():
            runs.setdefault(k, []).append(v)
    med = {k: statistics.median(v) for k, v in runs.items()}
    own = med["hc"] - med["tc"]
    line = (f"| {label} | {n:,} | {med['hw']:.2f} / {med['hc']:.2f} | {med['tc']:.2f} | "
            f"{med['cw']:.2f} / {med['cc']:.2f} | **{own / med['cc']:.2f}** | "
            f"{med['hw'] / med['cw']:.2f} | {n / med['hw']:,.0f} |")
    if in_memory:
        # the pipe's time: the hunt's less the same hunt's in memory, by the wall clock and by
        # CPU (the hunt process's own, its target's taken off; steadier on a loaded machine)
        pipe_wall = med["hw"] - med["mw"]
        pipe_cpu = own - med["mc"]
        rate = lambda t: f"{n / t:,.0f}" if t > 0 else "(no difference)"  # noqa: E731
        line += (f" {med['mw']:.2f} / {med['mc']:.2f} | {rate(pipe_wall)} / "
                 f"**{rate(pipe_cpu)}** |")
    else:
        line += " | |"
    print(line, flush=True)


in_memory_value = "1.5000000000000007"  # 3/2 + 3 * 2^-52, 3 ulps off the exact 3/2


def cost(args, tribez, bindir, tmp):
    """The hunt's own cost per row, its rows per second, and the pipe's."""
    const = os.path.join(bindir, "constant")

    def with_answer(text):
        def write(rows, csv):
            with open(rows) as fin, open(csv, "w") as f:
                for line in fin:
                    f.write(line.rstrip("\n") + "," + text + "\n")
        return write

    def answered_by(prog):
        def write(rows, csv):
            answers = os.path.join(tmp, "hunt_answers.txt")
            with open(rows) as fin, open(answers, "w") as fout:
                subprocess.run(prog, stdin=fin, stdout=fout, check=True)
            with open(csv, "w") as f:
                subprocess.run(["paste", "-d,", rows, answers], stdout=f, check=True)
        return write

    example = os.path.join(ROOT, "target", "release", "examples", "hunt_cost")
    if not os.access(example, os.X_OK):
        sys.exit(f"{example}: not found; build it with cargo build --release --example hunt_cost")
    print(f"medians of {args.repeat} runs, wall / CPU seconds; a process's CPU includes its "
          "target's, whose own CPU on the same rows alone (target) is taken off for the ratio")
    print()
    print("| patch, tolerance, target | rows | hunt | target | check --results, same rows | "
          "CPU ratio (hunt − target) / check | wall ratio | hunt rows/s | in memory | "
          "pipe rows/s by wall / by CPU |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    cost_case(args, tribez, tmp, "constant_three_halves, abs=1e-10, answers 3/2 + 3 ulps",
              "constant_three_halves", "abs=1e-10", [const, in_memory_value, "1"],
              with_answer(in_memory_value), in_memory=[example])
    casteljau = [os.path.join(bindir, "casteljau"), patch("cubic_positive", "net")]
    cost_case(args, tribez, tmp, "cubic_positive, cond, de Casteljau (every row passes)",
              "cubic_positive", "cond", casteljau, answered_by(casteljau))
    if args.cost_rows_failing:
        rows = args.cost_rows
        args.cost_rows = args.cost_rows_failing
        cost_case(args, tribez, tmp, "cubic_positive, cond, answers 0 (every row fails)",
                  "cubic_positive", "cond", [const, "0", "2"], with_answer("0,0"))
        args.cost_rows = rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tribez", default=os.path.join(ROOT, "target", "release", "tribez"))
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--budget", type=int, default=10_000)
    ap.add_argument("--quick", action="store_true", help="uniform 10,000 points only")
    ap.add_argument("--python", action="store_true",
                    help="hunt the Python versions of the targets that have one")
    ap.add_argument("--only", choices=["search", "cost"])
    ap.add_argument("--target", type=int, action="append", choices=[1, 2, 3, 4],
                    help="run this target only (repeatable; default all four)")
    ap.add_argument("--cost-rows", type=int, default=1_000_000)
    ap.add_argument("--cost-rows-failing", type=int, default=100_000,
                    help="rows of the cost run whose answers all fail (0: none)")
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    if not os.access(args.tribez, os.X_OK):
        sys.exit(f"{args.tribez}: not found; build it with cargo build --release -p tribez-cli")
    with tempfile.TemporaryDirectory(prefix="tribez-hunt-bench-") as tmp:
        bindir = os.path.join(tmp, "bin")
        os.mkdir(bindir)
        build(bindir)
        if args.only != "cost":
            search(args, args.tribez, bindir, tmp)
        if args.only != "search":
            print()
            cost(args, args.tribez, bindir, tmp)


if __name__ == "__main__":
    main()
