#!/usr/bin/env python3
"""Run the command examples of the documentation and compare their output with the text shown.

    python3 docs/check_examples.py [TRIBEZ]        # default: target/debug/tribez

Every fenced block of README.md and docs/*.md that contains lines starting with `$ ` is a
session: each `$ ` line (with `\\` continuations) is run by bash in a scratch directory where
`fixtures/` is the repository's and `tribez` is the binary under test; the lines after it, up to
the next `$ ` line, are its expected output (standard output, then standard error). In the
expected text a line `...` stands for any number of lines, and `...` inside a line (or a
trailing `…`) for any text; trailing spaces are ignored. `$ cat FILE` of a file that does not
exist yet creates FILE from the expected text, so a session can show its input files. A command
may exit non-zero; `$ echo $?` checks the exit status of the command before it. A `$ cc ...`
line (docs/c.md: compile a C example against libtribez and run it) is run when pkg-config finds
tribez (PKG_CONFIG_PATH), and counted as not run otherwise; with CI set it must be found.

Prints one line per command that differs, and a summary; exits 1 if any differs.
"""

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def sessions(path):
    """(first line number, [(command, expected lines)]) for every block with `$ ` lines."""
    lines = path.read_text(encoding="utf-8").splitlines()
    out, block, start = [], None, 0
    for no, line in enumerate(lines, 1):
        if line.startswith("```"):
            if block is None:
                block, start = [], no
            else:
                if any(b.startswith("$ ") for b in block):
                    out.append((start, parse(block)))
                block = None
        elif block is not None:
            block.append(line)
    return out


def parse(block):
    cmds, i = [], 0
    while i < len(block):
        if not block[i].startswith("$ "):
            i += 1
            continue
        cmd = block[i][2:]
        while cmd.endswith("\\") and i + 1 < len(block):
            i += 1
            cmd = cmd[:-1] + " " + block[i].strip()
        i += 1
        expected = []
        while i < len(block) and not block[i].startswith("$ "):
            expected.append(block[i])
            i += 1
        cmds.append((cmd, expected))
    return cmds


def line_pattern(expected):
    parts = re.split(r"\.\.\.|…", expected.rstrip())
    return re.compile("^" + ".*".join(re.escape(p) for p in parts) + ("" if len(parts) == 1 else ".*") + "$")


def matches(expected, actual):
    """Does `actual` (lines) match `expected` (lines, with `...` wildcards)?"""
    def go(e, a):
        if e == len(expected):
            return a == len(actual)
        if expected[e].strip() == "...":
            return any(go(e + 1, k) for k in range(a, len(actual) + 1))
        return a < len(actual) and bool(line_pattern(expected[e]).match(actual[a].rstrip())) and go(e + 1, a + 1)

    sys.setrecursionlimit(100000)
    return go(0, 0)


def main():
    binary = Path(sys.argv[1] if len(sys.argv) > 1 else ROOT / "target/debug/tribez").resolve()
    if not binary.is_file():
        sys.exit(f"{binary}: no such binary (cargo build first)")
    docs = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
    failed = ran = not_run = 0
    have_c = subprocess.run(["pkg-config", "--exists", "tribez"], capture_output=True).returncode == 0 \
        if shutil.which("pkg-config") else False
    for doc in docs:
        for start, cmds in sessions(doc):
            with tempfile.TemporaryDirectory() as tmp:
                bindir = Path(tmp, ".bin")
                bindir.mkdir()
                os.symlink(binary, bindir / "tribez")
                os.symlink(ROOT / "fixtures", Path(tmp, "fixtures"))
                env = dict(os.environ, PATH=f"{bindir}:{os.environ['PATH']}")
                status = 0
                for cmd, expected in cmds:
                    if cmd.strip() == "echo $?":
                        ran += 1
                        if expected != [str(status)]:
                            failed += 1
                            print(f"{doc.relative_to(ROOT)}:{start}: exit status {status}, the text shows {expected}")
                        continue
                    if cmd.split()[0] not in ("tribez", "cat", "python3", "cc"):
                        continue  # only tribez sessions (and their cat/python3 set-up) are run
                    if cmd.split()[0] == "cc" and not have_c:
                        not_run += 1
                        if os.environ.get("CI"):
                            failed += 1
                            print(f"{doc.relative_to(ROOT)}:{start}: `cc` example, but pkg-config finds no tribez")
                        continue
                    m = re.fullmatch(r"cat (\S+)", cmd)
                    if m and not Path(tmp, m.group(1)).exists():
                        Path(tmp, m.group(1)).write_text("\n".join(expected) + "\n", encoding="utf-8")
                        continue
                    ran += 1
                    r = subprocess.run(["bash", "-c", cmd], cwd=tmp, env=env, capture_output=True, text=True, timeout=600)
                    status = r.returncode
                    actual = (r.stdout + r.stderr).splitlines()
                    if not matches(expected, actual):
                        failed += 1
                        print(f"{doc.relative_to(ROOT)}:{start}: `{cmd}` differs; actual output:")
                        print("\n".join("    " + a for a in actual[:40]))
    if not_run:
        print(f"{not_run} C examples not run: pkg-config finds no tribez (docs/c.md: install.sh, PKG_CONFIG_PATH)")
    print(f"{ran} commands run, {failed} differ")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
