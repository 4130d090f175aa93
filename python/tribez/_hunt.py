"""tribez.hunt: search for the inputs where a Python function evaluating a patch is least
accurate (the library's hunt, what ``tribez hunt`` runs), and its report."""

from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass
from typing import Optional

import numpy as np

from . import _native
from ._convert import fraction
from ._errors import InputError

#: The most rows a hunt may be given as its budget (2^40).
MAX_HUNT_BUDGET: int = _native.MAX_HUNT_BUDGET
#: The most rows given to the function in one call.
MAX_HUNT_BATCH: int = _native.MAX_HUNT_BATCH
#: The most rows a report lists.
MAX_HUNT_TOP: int = _native.MAX_HUNT_TOP


@dataclass(frozen=True)
class HuntRow:
    """One of the worst rows a hunt found.

    ``row``: its number (from 1, in the order rows were given to the function); ``input``: the
    row given (floats of the precision); ``claimed``: the function's answer (as the judge reads
    it: the nearest float of the precision); ``exact``: the exact value the row was judged
    against (``fractions.Fraction``): at the input as the function saw it, with the control
    points rounded to the precision, as :func:`tribez.check` judges (barycentric rows: the
    homogeneous form at those floats, which need not sum to 1); ``ulps``: the error in ULPs
    against it, the largest over the coordinates, computed exactly, ``inf`` for a non-finite
    answer; ``passed``: it meets the
    tolerance; ``reason``: why it breaks the tolerance, else None.
    """

    row: int
    input: tuple
    claimed: tuple
    exact: tuple
    ulps: float
    passed: bool
    reason: Optional[str]


def _hunt_from_state(cls, state, patch):
    return HuntReport(cls.from_state(state), patch)


class HuntReport:
    """What :func:`tribez.hunt` found.

    Attributes: ``evaluated`` (rows given to the function and judged), ``broke`` (rows that broke
    the tolerance), ``ok`` (none did), ``seed`` (give it again to repeat the hunt), ``budget``,
    ``precision``, ``tolerance``, ``cartesian``, ``by_kind`` (rows per kind: ``uniform``,
    ``special`` (at the places floats fail), ``local`` (moves around the worst rows)),
    ``max_ulps`` (the largest error found, in ULPs) and ``worst`` (the worst rows, worst first:
    a list of :class:`HuntRow`).

    ``text()`` (also ``str(report)``) and ``json()`` are the report ``tribez hunt`` prints for the
    same hunt, but for the names: the function's name stands for the program, and the last line
    (JSON: ``reproduce``, a string) is the Python call that repeats the hunt.
    :meth:`to_claims` writes the worst rows as a claim file that ``tribez check`` judges again.
    """

    __slots__ = ("_native", "_patch", "_worst")

    def __init__(self, native, patch):
        self._native = native
        self._patch = patch
        self._worst = [
            HuntRow(row, tuple(inp), tuple(claimed), tuple(fraction(q) for q in exact), ulps, passed, reason)
            for (row, inp, claimed, exact, ulps, passed, reason) in native.worst()
        ]

    def __reduce__(self):
        # pickled as plain values (exact values as p/q texts) and the patch, e.g. for Dask
        return (_hunt_from_state, (type(self._native), self._native.state(), self._patch))

    @property
    def evaluated(self) -> int:
        """Rows given to the function and judged."""
        return self._native.evaluated

    @property
    def broke(self) -> int:
        """Rows that broke the tolerance."""
        return self._native.broke

    @property
    def ok(self) -> bool:
        """True when no row broke the tolerance."""
        return self._native.broke == 0

    @property
    def seed(self) -> int:
        """The seed of the search (drawn at random when none was given)."""
        return self._native.seed

    @property
    def budget(self) -> int:
        return self._native.budget

    @property
    def precision(self) -> str:
        return self._native.precision

    @property
    def tolerance(self) -> str:
        return self._native.tolerance

    @property
    def cartesian(self) -> bool:
        return self._native.cartesian

    @property
    def by_kind(self) -> dict:
        """Rows of each kind: ``{"uniform": ..., "special": ..., "local": ...}``."""
        return dict(zip(("uniform", "special", "local"), self._native.by_kind))

    @property
    def max_ulps(self) -> Optional[float]:
        """The largest error found, in ULPs (that of ``worst[0]``)."""
        return self._native.max_ulps

    @property
    def worst(self) -> list:
        """The worst rows (:class:`HuntRow`), worst first (ties: the earlier row), distinct
        inputs, at most ``top``."""
        return list(self._worst)

    def text(self) -> str:
        """The text report, as ``tribez hunt`` prints it."""
        return self._native.text()

    def json(self) -> str:
        """The JSON report, as ``tribez hunt --format json`` writes it."""
        return self._native.json()

    def __str__(self) -> str:
        return self.text()

    def __repr__(self) -> str:
        return (f"<tribez.HuntReport evaluated={self.evaluated} broke={self.broke} "
                f"max_ulps={self.max_ulps} seed={self.seed}>")

    def to_claims(self, path) -> None:
        """Write the worst rows as a claim file (as ``tribez hunt --claims-out``): one ``eval``
        claim per row, at the row's input with the function's answer as ``expect``, in the hunt's
        precision and tolerance, so that ``tribez check FILE`` (or :func:`tribez.check_claims`)
        judges them again with the same verdicts. A patch read from a file is named by its path
        relative to the claim file's directory; a patch built in memory is written into the claim
        file (an inline ``[patch]`` table)."""
        try:
            path = os.fspath(path)
        except TypeError:
            raise InputError(f"path: expected a str or os.PathLike, got {type(path).__name__}") from None
        if isinstance(path, bytes):
            path = os.fsdecode(path)
        directory = os.path.dirname(os.path.abspath(path))
        reference = None
        if self._patch._path is not None:
            target = os.path.realpath(self._patch._path)
            try:
                reference = os.path.relpath(target, os.path.realpath(directory))
            except ValueError:  # another drive (Windows)
                reference = target
            reference = reference.replace(os.sep, "/")
        text = self._native.claims_text(reference, self._patch._native)
        if os.path.isdir(path):
            raise InputError(f"{path}: is a directory")
        fd, tmp = tempfile.mkstemp(dir=directory, prefix=".tribez-", suffix=".tmp")
        try:
            with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as f:
                f.write(text)
            os.replace(tmp, path)
        except BaseException:
            try:
                os.unlink(tmp)
            except OSError:
                pass
            raise


def _name_of(fn) -> str:
    """The function's qualified name (``Triangle.evaluate_barycentric``), without the enclosing
    functions of a local function; an object without a name: its type's name."""
    name = getattr(fn, "__qualname__", None) or getattr(fn, "__name__", None)
    if not isinstance(name, str):
        return type(fn).__name__
    return name.rsplit("<locals>.", 1)[-1]


def _caller(fn, width: int, dimension: int, precision: str):
    """The target the native hunt calls: ``call(rows, n, first)`` gives the function the ``n``
    rows from row ``first`` as a (n, width) array of the precision's dtype and answers the bytes of
    its (n, dimension) answer as float64 (an f32 hunt's answers rounded to float32 first)."""
    dtype = np.float32 if precision == "f32" else np.float64

    def call(rows: bytes, n: int, first: int) -> bytes:
        # a fresh, writable array (rows of the precision: float32 holds them exactly)
        points = np.frombuffer(rows, dtype=np.float64).reshape(n, width).astype(dtype)
        answer = fn(points)
        where = f"fn: its answer for rows {first} to {first + n - 1}"
        try:
            out = np.asarray(answer)
        except (ValueError, TypeError) as e:
            raise InputError(f"{where} is not an array of numbers ({e})") from None
        if out.dtype not in (np.dtype(np.float64), np.dtype(np.float32)):
            raise InputError(f"{where} has dtype {out.dtype}, expected float64 or float32")
        if out.shape != (n, dimension):
            raise InputError(
                f"{where} has shape {out.shape}, expected ({n}, {dimension}): "
                f"one row of the patch's {dimension} coordinates per row given"
            )
        # the f32 judge reads an answer as the nearest float32 (numpy rounds to nearest, ties to
        # even), as the command line reads an answer line
        return np.ascontiguousarray(out.astype(dtype), dtype=np.float64).tobytes()

    return call


def _whole(x, where: str, lo: int, hi: int) -> int:
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        raise InputError(f"{where}: expected a whole number from {lo} to {hi}, got {x!r}")
    x = int(x)
    if not lo <= x <= hi:
        raise InputError(f"{where}: {x}: expected a whole number from {lo} to {hi}")
    return x


def hunt(patch, fn, *, precision: str = "f64", tolerance: str = "cond", budget: int = 10_000,
         seed: Optional[int] = None, cartesian: bool = False, batch: int = 4096,
         top: int = 10) -> HuntReport:
    """Search for the inputs where ``fn`` evaluates ``patch`` least accurately: the library's
    hunt, what ``tribez hunt PATCH -- PROGRAM`` runs, with a Python function as the program.

    ``fn`` is given a numpy array of shape ``(B, m + 1)`` (barycentric coordinates
    ``λ_0, …, λ_m``; with ``cartesian=True`` ``(B, m)``, Cartesian points of the patch's domain),
    dtype float64 (float32 with ``precision="f32"``), and answers an array-like of shape
    ``(B, patch.dimension)``, float64 or float32 (an f32 hunt reads each number as the nearest
    float32). ``B`` is at most ``batch``. A result of another shape or dtype raises
    :class:`InputError` naming the rows; an exception ``fn`` raises ends the hunt and propagates
    unchanged. Ctrl-C is honoured between calls.

    The search (deterministic for a ``seed``; a random one is drawn and reported when ``seed`` is
    None): about 15% of ``budget`` on uniform points, 25% on the places floats fail (corners and
    edges, coordinates ``2^-k r`` at every scale, binade boundaries, near zeros of a coordinate of
    the value, points of large condition number), then local search around the worst rows found.
    Every row is judged as :func:`tribez.check` judges it with the same ``tolerance`` (``"cond"``
    without ``K``: ``K = (m + 1) n``), exactly: the error is that of the answer against the
    exact value at the inputs as ``fn`` saw them. The patch must be a polynomial Bézier patch.

    Returns a :class:`HuntReport`.
    """
    from . import Patch, _precision_name

    if not isinstance(patch, Patch):
        raise InputError(f"patch: expected a tribez.Patch, got {type(patch).__name__}")
    if not callable(fn):
        raise InputError(f"fn: expected a function, got {type(fn).__name__}")
    precision = _precision_name(precision)
    if not isinstance(tolerance, str):
        raise InputError(f"tolerance: expected a str such as \"cond\" or \"ulps=4\", got {tolerance!r}")
    if not isinstance(cartesian, (bool, np.bool_)):
        raise InputError(f"cartesian: expected a bool, got {cartesian!r}")
    budget = _whole(budget, "budget", 1, MAX_HUNT_BUDGET)
    batch = _whole(batch, "batch", 1, MAX_HUNT_BATCH)
    top = _whole(top, "top", 1, MAX_HUNT_TOP)
    if seed is None:
        seed = int.from_bytes(os.urandom(8), "little")
    seed = _whole(seed, "seed", 0, 2**64 - 1)
    cartesian = bool(cartesian)
    name = _name_of(fn)
    label = patch._path or (f"<{patch.name}>" if patch.name else "<patch>")
    call = [f"tribez.hunt(patch, {name}", f"precision={json.dumps(precision)}",
            f"tolerance={json.dumps(tolerance)}", f"budget={budget}", f"seed={seed}"]
    if cartesian:
        call.append("cartesian=True")
    if batch != 4096:
        call.append(f"batch={batch}")
    if top != 10:
        call.append(f"top={top}")
    reproduce = ", ".join(call) + ")"
    width = patch.simplex if cartesian else patch.simplex + 1
    target = _caller(fn, width, patch.dimension, precision)
    native = _native.hunt(patch._native, target, precision, tolerance, budget, seed, cartesian, batch,
                          top, label, name, reproduce)
    return HuntReport(native, patch)


__all__ = ["hunt", "HuntReport", "HuntRow"]
