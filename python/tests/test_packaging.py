"""The package as installed: its version (the same in every place that states it), its metadata,
the README's example, and arrays of every layout judged alike (the C-contiguous float64 ones are
read in place, the others converted first)."""

import contextlib
import io
import json
import re
from importlib import metadata

import numpy as np

import tribez


def _version_in(path, section):
    """The `version = "..."` line of a TOML section (Python 3.9 has no tomllib)."""
    text = path.read_text()
    body = text.split(f"[{section}]", 1)[1].split("\n[", 1)[0]
    return re.search(r'^version\s*=\s*"([^"]+)"', body, re.M).group(1)


def test_one_version_everywhere(root):
    workspace = _version_in(root / "Cargo.toml", "workspace.package")
    assert workspace == "0.3.0"
    assert _version_in(root / "python" / "Cargo.toml", "package") == workspace
    dependency = re.search(r'^tribez\s*=\s*\{[^}]*version\s*=\s*"([^"]+)"',
                           (root / "Cargo.toml").read_text(), re.M).group(1)
    assert dependency == workspace
    assert tribez.__version__ == workspace
    assert metadata.version("tribez") == workspace
    assert f"## {workspace} " in (root / "CHANGELOG.md").read_text()


def test_installed_metadata():
    meta = metadata.metadata("tribez")
    assert meta["Requires-Python"] == ">=3.9"
    assert (meta.get("License-Expression") or meta.get("License")) == "MIT OR Apache-2.0"
    urls = dict(u.split(", ", 1) for u in meta.get_all("Project-URL"))
    assert {"Homepage", "Documentation", "Repository", "Changelog"} <= set(urls)
    assert "Programming Language :: Python :: 3 :: Only" in meta.get_all("Classifier")
    assert "numpy>=1.21" in meta.get_all("Requires-Dist")
    # the long description: python/README.md
    assert "tribez for Python" in metadata.distribution("tribez").read_text("METADATA")
    files = {str(f) for f in metadata.files("tribez")}
    assert any(f.endswith("LICENSE-MIT") for f in files) and any(f.endswith("LICENSE-APACHE") for f in files)


def test_readme_example_runs(root):
    text = (root / "python" / "README.md").read_text()
    code = text.split("```python\n", 1)[1].split("```", 1)[0]
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, "python/README.md", "exec"), {})
    # Finn's worked example at (1/2, 1/3, 1/6): (4/9, 5/9, 29/36), as the comment says
    first = out.getvalue().splitlines()[0]
    assert first == "[(Fraction(4, 9), Fraction(5, 9), Fraction(29, 36))]"
    assert re.search(r"#\s*" + re.escape(first), code)


def test_arrays_of_every_layout_are_judged_alike(finn):
    rng = np.random.default_rng(11)
    u = rng.random(500)
    v = (1 - u) * rng.random(500)
    pts = np.column_stack([u, v, 1.0 - u - v])
    vals = finn.evaluate_float(pts)
    vals[17, 1] += 1e-3  # about 4.5e12 ulps off
    vals[18, 0] = np.nan
    want = tribez.check(finn, pts, vals, tolerance="cond=9")
    assert want.passed > 400 and want.failed >= 2  # row 18 (NaN) and row 17 (moved) among them
    assert not want.rows["passed"][18] and not want.rows["passed"][17]

    def unaligned(a):
        raw = bytearray(a.nbytes + 1)
        b = np.frombuffer(raw, dtype=np.float64, offset=1, count=a.size).reshape(a.shape)
        b[...] = a
        assert not b.flags.aligned
        return b

    layouts = {
        "Fortran order": np.asfortranarray,
        "a strided view": lambda a: np.repeat(a, 2, axis=0)[::2],
        "big-endian": lambda a: a.astype(">f8"),
        "unaligned": unaligned,
        "nested lists": lambda a: a.tolist(),
    }
    for name, layout in layouts.items():
        got = tribez.check(finn, layout(pts), layout(vals), tolerance="cond=9")
        assert json.loads(got.to_json()) == json.loads(want.to_json()), name
        assert np.array_equal(got.rows["ulps_seen"], want.rows["ulps_seen"]), name
