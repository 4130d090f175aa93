#!/usr/bin/env python3
"""Run tribez on random cases and compare its verdicts with the reference's (reference/README.md).

  python3 reference/run.py --seed S --claims N [--tribez PATH] [--out DIR]

Generates about N claims (claim files of every covered operation, and `check --results` batches
whose rows count as claims) into a temporary directory, runs `tribez check ... --format json` on
them, and compares every verdict, every exact value tribez reports for `eval`, every claimed value as
tribez read it, and every exit status. Prints one line per disagreement, the seed, and a summary
`N agreed, N disagreed (N expected failures)`; exits 1 on any disagreement that is not listed in
reference/expected_failures.json, 0 otherwise. Each disagreement is written to DIR (default
reference-disagreements/ in the current directory) as a small case: the patch, a claim file with
that one claim (or the batch), and expected.json with the reference's verdict.
"""

import argparse
import json
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from fractions import Fraction  # noqa: E402

import floats  # noqa: E402
import selftest  # noqa: E402
from gen import BatchGen, InverseBatchGen, InverseGen, OpsGen  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

CHUNK = 200  # claim files per `tribez check` run (bounds the size of one JSON report)
OPS = ["blossom", "subpatch", "elevate", "derivative", "edge_curve", "tangent", "halve", "subdivide"]


def write_json(path, obj):
    with open(path, "w") as f:
        json.dump(obj, f, indent=1)


def generate(seed, nclaims, workdir):
    """Write the cases; return (claim cases, batch cases)."""
    rng = random.Random(seed)
    ops, inv, bat, ibat = OpsGen(rng), InverseGen(rng), BatchGen(rng), InverseBatchGen(rng)
    claims = []  # dicts: file, id, claim, patches {name: file dict}, expected
    batches = []
    budget_batch = nclaims // 5
    budget_claims = nclaims - budget_batch
    nfile = 0
    while len(claims) < budget_claims:
        nfile += 1
        name = "f%04d" % nfile
        c = rng.random()
        file_claims, patches = [], {}
        if c < 0.55:  # eval claims on one patch
            P, pf = ops.patch()
            patches["p"] = pf
            for k in range(rng.randint(4, 10)):
                got = ops.eval_claim(P, "eval-%d" % k)
                if got:
                    file_claims.append(got)
        elif c < 0.8:  # constructions and derivatives on one polynomial (or rational) patch
            P, pf = ops.patch(kind=rng.choice(["bezier", "bezier", "bezier", "rational"]))
            patches["p"] = pf
            for k in range(rng.randint(3, 8)):
                op = rng.choice(OPS if P["weights"] is None else ["blossom", "derivative", "tangent"])
                if op == "tangent" and (P["m"] != 2 or P["d"] != 3):
                    op = "blossom"
                try:
                    file_claims.append(ops.op_claim(P, "%s-%d" % (op, k), op))
                except ZeroDivisionError:  # a rational value undefined there: tribez refuses it (exit 2)
                    pass
            for k in range(rng.randint(0, 2)):
                op = rng.choice(["barycentric", "direction"])
                file_claims.append(ops.free_claim("%s-x%d" % (op, k), op))
        else:  # inverse problems: each claim with its own patches
            for k in range(rng.randint(3, 8)):
                kind = rng.choice(["intersect", "parabola", "locate", "quad_locate", "ray", "join", "height"])
                files, claim, exp = getattr(inv, kind + "_case")("%s-%d" % (kind, k))
                for pname, pfile in files.items():
                    pn = "%s%d" % (pname, k)
                    patches[pn] = pfile
                    if "patches" in claim:
                        claim["patches"] = ["a%d" % k, "b%d" % k]
                    else:
                        claim["patch"] = pn
                file_claims.append((claim, exp))
        if not file_claims:
            continue
        # claim files in chunks of CHUNK files, one `tribez check` run per chunk
        chunk = "c%04d" % ((nfile - 1) // CHUNK)
        cdir = os.path.join(workdir, "claims", chunk)
        os.makedirs(cdir, exist_ok=True)
        pnames = {}
        for pname, pfile in patches.items():
            fn = "%s.%s.json" % (name, pname)
            write_json(os.path.join(cdir, fn), pfile)
            pnames[pname] = fn
        doc = {"source": "reference/run.py, seed %d" % seed}
        if list(patches) == ["p"]:
            doc["patch"] = pnames["p"]
        else:
            doc["patches"] = pnames
        doc["claim"] = [cl for cl, _ in file_claims]
        write_json(os.path.join(cdir, name + ".claims.json"), doc)
        for cl, exp in file_claims:
            claims.append({"chunk": chunk, "file": name + ".claims.json", "id": cl["id"], "claim": cl, "doc": doc, "patches": patches, "expected": exp})
    rows = 0
    nb = 0
    while rows < budget_batch:
        nb += 1
        n = rng.randint(5, 40)
        bdir = os.path.join(workdir, "batch%03d" % nb)
        os.makedirs(bdir)
        if rng.random() < 0.7:  # check --patch P --results FILE
            pf, text, ext, opts, exp = bat.batch(n)
            rowsfile = "rows" + ext
            opts = ["--results", rowsfile] + opts
        else:  # check --patch P --locate-results / --ray-results FILE
            pf, text, opts, exp = ibat.batch(rng.choice(["locate", "ray"]), n)
            rowsfile = "rows.csv"
        write_json(os.path.join(bdir, "patch.json"), pf)
        with open(os.path.join(bdir, rowsfile), "w") as f:
            f.write(text)
        batches.append({"dir": bdir, "rows": rowsfile, "opts": opts, "expected": exp, "n": n})
        rows += n
    return claims, batches


def run_chunk(tribez, cdir):
    """`tribez check DIR --format json` on one chunk of claim files. If that exits 2 (bad input
    somewhere), every file is run alone, so that one refused file costs only its own claims.
    Returns (exit status, {(file, id): report of the claim}, {file: error line})."""
    p = subprocess.run([tribez, "check", ".", "--format", "json"], cwd=cdir, capture_output=True, text=True)
    got, errors = {}, {}
    if p.returncode != 2:
        for c in json.loads(p.stdout)["claims"]:
            got[(os.path.basename(c["file"]), c["id"])] = c
        return p.returncode, got, errors
    for fn in sorted(os.listdir(cdir)):
        if not fn.endswith(".claims.json"):
            continue
        q = subprocess.run([tribez, "check", fn, "--format", "json"], cwd=cdir, capture_output=True, text=True)
        if q.returncode == 2:
            errors[fn] = q.stderr.strip()
            continue
        for c in json.loads(q.stdout)["claims"]:
            got[(os.path.basename(c["file"]), c["id"])] = c
    return 2, got, errors


def run_claims(tribez, workdir, jobs):
    """Every chunk, `jobs` at a time; returns ({chunk: exit status}, reports, errors)."""
    from concurrent.futures import ThreadPoolExecutor
    root = os.path.join(workdir, "claims")
    chunks = sorted(os.listdir(root))
    with ThreadPoolExecutor(max_workers=jobs) as ex:
        results = list(ex.map(lambda c: run_chunk(tribez, os.path.join(root, c)), chunks))
    rcs, got, errors = {}, {}, {}
    for c, (rc, g, e) in zip(chunks, results):
        rcs[c] = rc
        got.update(g)
        errors.update(e)
    return rcs, got, errors


def load_xfail():
    with open(os.path.join(HERE, "expected_failures.json")) as f:
        return json.load(f)


def run_regressions(tribez):
    """Every case of reference/regressions/: a directory with one claim file (case.claims.*) and
    expected.json {"issue", "claims": {id: {"verdict", "exact"}}}, or a batch (command.json
    {"args": [...]} and expected.json {"exit", "passed", "failed"}). Returns [(name, reasons)]."""
    out = []
    rdir = os.path.join(HERE, "regressions")
    for name in sorted(os.listdir(rdir)):
        d = os.path.join(rdir, name)
        if not os.path.isdir(d):
            continue
        with open(os.path.join(d, "expected.json")) as f:
            exp = json.load(f)
        reasons = []
        if os.path.exists(os.path.join(d, "command.json")):
            with open(os.path.join(d, "command.json")) as f:
                args = json.load(f)["args"]
            p = subprocess.run([tribez] + args + ["--format", "json"], cwd=d, capture_output=True, text=True)
            if p.returncode != exp["exit"]:
                reasons.append("exit status: tribez %d, expected %d" % (p.returncode, exp["exit"]))
            if p.returncode in (0, 1):
                rep = json.loads(p.stdout)
                s = rep.get("summary", rep)
                if (s.get("passed"), s.get("failed")) != (exp["passed"], exp["failed"]):
                    reasons.append("counts: tribez %s/%s, expected %d/%d" % (s.get("passed"), s.get("failed"), exp["passed"], exp["failed"]))
        else:
            case = [fn for fn in os.listdir(d) if ".claims." in fn][0]
            p = subprocess.run([tribez, "check", case, "--format", "json"], cwd=d, capture_output=True, text=True)
            if p.returncode == 2:
                reasons.append("tribez exited 2: " + p.stderr.strip())
            else:
                got = {c["id"]: c for c in json.loads(p.stdout)["claims"]}
                for cid, e in exp["claims"].items():
                    g = got.get(cid)
                    if g is None:
                        reasons.append("%s: no verdict" % cid)
                        continue
                    if g["verdict"] != e["verdict"]:
                        reasons.append("%s: verdict: tribez %s, expected %s" % (cid, g["verdict"], e["verdict"]))
                    if e.get("exact") is not None and g.get("exact") != e["exact"]:
                        reasons.append("%s: exact value: tribez %s, expected %s" % (cid, g.get("exact"), e["exact"]))
        out.append((name, reasons))
    return out


def xfail_reason(info, xfails):
    for x in xfails:
        if all(info.get(k) in (v if isinstance(v, list) else [v]) for k, v in x["match"].items()):
            return x["issue"]
    return None


def compare_claim(case, got):
    """The reasons tribez's report of one claim disagrees with the reference (empty: agrees)."""
    exp = case["expected"]
    out = []
    if got is None:
        return ["no verdict in tribez's report"]
    if got["verdict"] != exp["verdict"]:
        out.append("verdict: tribez %s, reference %s" % (got["verdict"], exp["verdict"]))
    if exp.get("exact") is not None and got.get("exact") != exp["exact"]:
        out.append("exact value: tribez %s, reference %s" % (got.get("exact"), exp["exact"]))
    if exp.get("claimed") is not None and got.get("claimed") != exp["claimed"]:
        out.append("claimed value as read: tribez %s, reference %s" % (got.get("claimed"), exp["claimed"]))
    return out


def save_case(outdir, label, files, expected):
    d = os.path.join(outdir, label)
    os.makedirs(d, exist_ok=True)
    for name, content in files.items():
        path = os.path.join(d, name)
        if isinstance(content, str):
            with open(path, "w") as f:
                f.write(content)
        else:
            write_json(path, content)
    write_json(os.path.join(d, "expected.json"), expected)
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seed", type=int, default=None, help="random when omitted (printed)")
    ap.add_argument("--claims", type=int, default=2000)
    ap.add_argument("--tribez", default=os.path.join(ROOT, "target", "debug", "tribez"))
    ap.add_argument("--out", default="reference-disagreements", help="where disagreements are written")
    ap.add_argument("--keep", action="store_true", help="keep the generated files (printed)")
    ap.add_argument("--verbose", action="store_true", help="print every expected failure, not the first 3 of each issue")
    ap.add_argument("--jobs", type=int, default=2, help="tribez processes at a time (default 2)")
    a = ap.parse_args()
    seed = a.seed if a.seed is not None else random.SystemRandom().randrange(2**32)
    print("reference: seed %d, %d claims, tribez %s" % (seed, a.claims, a.tribez), flush=True)
    t0 = time.time()
    selftest.run(seed)  # the reference checks itself first (floats against the platform, theory's examples)
    workdir = tempfile.mkdtemp(prefix="tribez-reference-")
    try:
        claims, batches = generate(seed, a.claims, workdir)
        t1 = time.time()
        xf = load_xfail()
        xfails = xf["expected_failures"]
        agreed = disagreed = xfailed = 0
        problems = []
        xfail_chunks = set()  # chunks whose exit status an expected failure may change
        xfail_by = {}  # issue -> count (only the first 3 of each are printed without --verbose)

        def disagree(label, reasons, files, expected, info):
            nonlocal disagreed, xfailed
            why = xfail_reason(info, xfails)
            d = save_case(a.out, label, files, expected)
            if why:
                xfailed += 1
                xfail_by[why] = xfail_by.get(why, 0) + 1
                if info.get("chunk"):
                    xfail_chunks.add(info["chunk"])
                tag = "expected failure (%s)" % why
                if not a.verbose and xfail_by[why] > 3:
                    return
            else:
                disagreed += 1
                tag = "DISAGREEMENT"
            cat = ",".join("%s=%s" % (k, info[k]) for k in sorted(info) if info[k] is not None and k != "chunk")
            problems.append("%s %s (%s): %s [%s]" % (tag, label, cat, "; ".join(reasons), d))

        rcs, got, errors = run_claims(a.tribez, workdir, a.jobs)
        for c in claims:
            g = got.get((c["file"], c["id"]))
            reasons = ["tribez exited 2 on its file: " + errors[c["file"]]] if c["file"] in errors else compare_claim(c, g)
            if not reasons:
                agreed += 1
                continue
            doc = dict(c["doc"])
            doc["claim"] = [c["claim"]]
            files = {"case.claims.json": doc}
            used = c["claim"].get("patches") or ([c["claim"]["patch"]] if "patch" in c["claim"] else list(c["patches"]))
            if "patches" in doc:
                doc["patches"] = {pn: doc["patches"][pn] for pn in used}
            for pname in used:
                fn = doc["patch"] if "patch" in doc else doc["patches"][pname]
                files[fn] = c["patches"][pname]
            info = dict(c["expected"]["info"], chunk=c["chunk"])
            expected = {"issue": None, "found_by": "reference/run.py --seed %d" % seed, "category": info,
                        "claims": {c["id"]: {"verdict": c["expected"]["verdict"], "exact": c["expected"]["exact"]}},
                        "tribez_said": g and {"verdict": g["verdict"], "exact": g.get("exact")}}
            disagree("%s-%s" % (c["file"].split(".")[0], c["id"]), reasons, files, expected, info)
        for chunk, rc in sorted(rcs.items()):
            expected_rc = 0 if all(c["expected"]["verdict"] == "passed" for c in claims if c["chunk"] == chunk) else 1
            if rc != expected_rc and chunk in xfail_chunks:
                xfailed += 1
            elif rc != expected_rc:
                disagreed += 1
                problems.append("DISAGREEMENT exit status of `tribez check` on the claim files of %s: %d, reference %d" % (chunk, rc, expected_rc))
        nrows = 0
        for b in batches:
            cmd = [a.tribez, "check", "--patch", "patch.json", "--format", "json"] + b["opts"]
            p = subprocess.run(cmd, cwd=b["dir"], capture_output=True, text=True)
            exp = b["expected"]
            nrows += b["n"]
            reasons = []
            if p.returncode != exp["exit"]:
                reasons.append("exit status: tribez %d, reference %d %s" % (p.returncode, exp["exit"], p.stderr.strip()[:200]))
            if p.returncode in (0, 1):
                rep = json.loads(p.stdout)
                s = rep.get("summary", rep)  # inverse batches give their counts at the top level
                if (s.get("passed"), s.get("failed")) != (exp["passed"], exp["failed"]):
                    reasons.append("counts: tribez passed %s failed %s, reference passed %d failed %d" % (s.get("passed"), s.get("failed"), exp["passed"], exp["failed"]))
                lines = sorted(f.get("line") for f in rep.get("failures", []))
                if exp["info"].get("format") != "json" and not rep.get("failures_not_listed") and lines != exp["failed_lines"]:
                    reasons.append("failed lines: tribez %s, reference %s" % (lines, exp["failed_lines"]))
            if reasons:
                with open(os.path.join(b["dir"], b["rows"])) as f:
                    text = f.read()
                with open(os.path.join(b["dir"], "patch.json")) as f:
                    pf = json.load(f)
                files = {"patch.json": pf, b["rows"]: text, "command.json": {"args": ["check", "--patch", "patch.json"] + b["opts"]}}
                disagree(os.path.basename(b["dir"]), reasons, files, exp, exp["info"])
            else:
                agreed += b["n"]
        regs = run_regressions(a.tribez)
        for name, reasons in regs:
            if not reasons:
                agreed += 1
            elif name in xf.get("regressions", {}):
                xfailed += 1
                problems.append("expected failure (%s) regression %s: %s" % (xf["regressions"][name], name, "; ".join(reasons)))
            else:
                disagreed += 1
                problems.append("DISAGREEMENT regression %s: %s" % (name, "; ".join(reasons)))
        t2 = time.time()
        for line in problems:
            print(line)
        for why, k in sorted(xfail_by.items()):
            print("expected failures: %d of %s (listed in reference/expected_failures.json)" % (k, why))
        ops = {}
        for c in claims:
            info = c["expected"]["info"]
            key = info["op"] + (" " + info["patch_kind"] if info["op"] == "locate" else "")
            ops[key] = ops.get(key, 0) + 1
        npass = sum(1 for c in claims if c["expected"]["verdict"] == "passed")
        print("covered: " + ", ".join("%s %d" % kv for kv in sorted(ops.items())) + ", batch rows %d in %d batches" % (nrows, len(batches)))
        print("reference verdicts: %d claims passed, %d failed; batches: %d rows; %d regression cases" % (npass, len(claims) - npass, nrows, len(regs)))
        print("%d agreed, %d disagreed, %d expected failures (seed %d; generated in %.1f s, checked in %.1f s)" % (agreed, disagreed, xfailed, seed, t1 - t0, t2 - t1))
        if a.keep:
            print("generated files kept in " + workdir)
        return 1 if disagreed else 0
    finally:
        if not a.keep:
            shutil.rmtree(workdir, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
