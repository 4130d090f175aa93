"""Ctrl-C (SIGINT) during a long tribez.check or tribez.certify raises KeyboardInterrupt within
a moment (issue 35 §7): the library asks Python for pending signals between slabs of rows or
points, instead of ignoring them until the call ends."""

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


@pytest.mark.parametrize("script", [CHECK, CERTIFY], ids=["check", "certify"])
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
