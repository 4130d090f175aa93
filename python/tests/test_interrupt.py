"""Ctrl-C (SIGINT) during a long tribez.check, tribez.certify or tribez.hunt raises
KeyboardInterrupt within a moment (issue 35 §7): the library asks Python for pending signals
between slabs of rows or points (the hunt: between calls of the function), instead of ignoring
them until the call ends."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import pytest

pytestmark = pytest.mark.skipif(os.name != "posix", reason="SIGINT to a child process")

# Each script prints "go" just before its long call, which would run for a minute or more.
CHECK = textwrap.dedent("""
    import numpy as np, tribez
    n = 100
    cols = (n + 1) * (n + 2) // 2
    rng = np.random.default_rng(1)
    nodes = rng.integers(-1000, 1000, size=(3, cols)).tolist()
    patch = tribez.Patch.from_nodes(nodes)
    pts = rng.dirichlet([1, 1, 1], size=400_000)
    vals = np.zeros((400_000, 3))
    print("go", flush=True)
    tribez.check(patch, pts, vals, tolerance="ulps=4")
    print("finished", flush=True)
""")

CERTIFY = textwrap.dedent("""
    import tribez
    n = 30
    cols = (n + 1) * (n + 2) // 2
    nodes = [[(7 * j + 3 * c) % 11 - 5 for j in range(cols)] for c in range(3)]
    patch = tribez.Patch.from_nodes(nodes)
    print("go", flush=True)
    tribez.certify(patch, random=1_000_000)
    print("finished", flush=True)
""")

HUNT = textwrap.dedent("""
    import numpy as np, tribez
    patch = tribez.Patch.from_nodes([[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]])
    print("go", flush=True)
    # a function in C (numpy's ufunc): (B, 3) rows -> (B, 3) answers; 2^40 rows would take days
    tribez.hunt(patch, np.negative, budget=2**40, batch=1000, seed=1)
    print("finished", flush=True)
""")


@pytest.mark.parametrize("script", [CHECK, CERTIFY, HUNT], ids=["check", "certify", "hunt"])
def test_sigint_raises_keyboard_interrupt_promptly(script):
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stdout.readline().strip() == "go"
        time.sleep(1.5)
        assert proc.poll() is None, "the call ended before the signal: make it longer"
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=20)
        waited = time.monotonic() - sent
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert "finished" not in out
    assert "KeyboardInterrupt" in err, err
    assert proc.returncode != 0
    # between slabs: well under the minute the whole call takes (generous for a loaded machine)
    assert waited < 5, f"{waited:.1f} s after SIGINT"
