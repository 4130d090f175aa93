"""tribez: exact Bézier triangles and simplices, to certify floating-point code.

tribez computes with Bézier triangles (and Bézier simplices of any dimension, rational patches,
functional patches and S-patches) exactly, in rational arithmetic, and judges floating-point
results against those exact values.

>>> import tribez
>>> from fractions import Fraction as F
>>> p = tribez.Patch.from_nodes([[0, 1, 0, 0, 1, 0], [0, 0, 2, 1, 1, 2], [0, 2, 0, 0, 1, 1]])
>>> p.evaluate([[F(1, 2), F(1, 3), F(1, 6)]])
[(Fraction(4, 9), Fraction(5, 9), Fraction(29, 36))]

The main entry points: :class:`Patch` (from files, text or ``bezier``-style node arrays; exact
and float evaluation), :func:`check` (judge many float results at once, from numpy arrays),
:class:`Report` (its verdict, the command line's report),
:func:`tribez.testing.assert_certified` (for pytest), :func:`check_locate` and :func:`check_ray`
(another implementation's answers to the inverse problems), :func:`hunt` (search for the inputs
where a function evaluating a patch is least accurate). Bad input raises :class:`InputError`,
a ``ValueError`` whose message is the one line the command line prints.
"""

from __future__ import annotations

import os
import textwrap
from fractions import Fraction
from typing import Optional, Sequence

import numpy as np

from . import _native
from ._convert import float_rows, fraction, matrix_texts, number_text
from ._errors import CertificationError, InputError, InternalError, TribezError
from ._report import CertifyReport, ClaimsReport, InverseReport, Report
from ._hunt import MAX_HUNT_BATCH, MAX_HUNT_BUDGET, MAX_HUNT_TOP, HuntReport, HuntRow, hunt

__all__ = [
    "Patch",
    "Report",
    "ClaimsReport",
    "CertifyReport",
    "InverseReport",
    "check",
    "check_claims",
    "check_locate",
    "check_ray",
    "certify",
    "hunt",
    "HuntReport",
    "HuntRow",
    "threads",
    "TribezError",
    "InputError",
    "CertificationError",
    "InternalError",
    "parse_number",
]

# the version of the native module (python/Cargo.toml), which is the package's (pyproject.toml
# takes it from there)
__version__: str = _native.__version__

MAX_DEGREE: int = _native.MAX_DEGREE
MAX_CONTROL_POINTS: int = _native.MAX_CONTROL_POINTS
MAX_SIMPLEX_DIMENSION: int = _native.MAX_SIMPLEX_DIMENSION
MAX_RANDOM_POINTS: int = _native.MAX_RANDOM_POINTS
MAX_INVERSE_ROWS: int = _native.MAX_INVERSE_ROWS


def parse_number(x) -> Fraction:
    """The exact value of a number: an int, a float (the exact value of the double), a
    ``Fraction``, or a string in tribez's number syntax (``"7"``, ``"4/9"``, ``"-1.5e-3"`` =
    -3/2000, ``"0x1.8p-3"``, ``"f64:0.1"`` = the double nearest 0.1, ``"f32:0.1"``).

    >>> parse_number("0.1"), parse_number(0.1) == Fraction(0.1)
    (Fraction(1, 10), True)
    """
    return fraction(_native.parse_number(number_text(x, "number")))


class Patch:
    """A Bézier patch of any kind, with exact rational control points.

    Build one with :meth:`from_file`, :meth:`from_toml`, :meth:`from_json` or
    :meth:`from_nodes`. Attributes: ``degree`` (n), ``dimension`` (d, coordinates of a value),
    ``simplex`` (m: 1 curves, 2 triangles, 3 tetrahedra, ...), ``kind`` (``"bezier"``,
    ``"rational"``, ``"functional"`` or ``"s-patch"``), ``name``, ``nodes`` (exact, in
    ``bezier``'s layout) and ``weights`` (rational patches).

    A value is ``p(λ) = Σ_{|α|=n} c_α B^n_α(λ)``, ``B^n_α(λ) = n!/(α_0!⋯α_m!) λ_0^{α_0}⋯λ_m^{α_m}``,
    at barycentric coordinates ``λ = (λ_0, …, λ_m)`` (``(u, v, w)`` on a triangle); corner ``k``
    interpolates ``c_{n e_k}``.
    """

    __slots__ = ("_native", "_path")

    def __init__(self, native, _path: Optional[str] = None):
        if not isinstance(native, _native.NativePatch):
            raise TypeError(
                "use Patch.from_file, Patch.from_toml, Patch.from_json or Patch.from_nodes"
            )
        self._native = native
        self._path = _path

    # -- construction -------------------------------------------------------------------

    @classmethod
    def from_file(cls, path) -> "Patch":
        """Read a patch file (``.toml`` or ``.json``, by extension; the layout of README.md,
        "Patch files"). Errors name the file, line and key."""
        try:
            path = os.fspath(path)
        except TypeError:
            raise InputError(f"path: expected a str or os.PathLike, got {type(path).__name__}") from None
        if isinstance(path, bytes):
            path = os.fsdecode(path)
        return cls(_native.NativePatch.from_file(path), path)

    @classmethod
    def from_toml(cls, text: str, name: str = "<toml>") -> "Patch":
        """Parse a patch from TOML text; ``name`` stands for the file in error messages."""
        _check_str(text, "text")
        return cls(_native.NativePatch.from_toml(text, name))

    @classmethod
    def from_json(cls, text: str, name: str = "<json>") -> "Patch":
        """Parse a patch from JSON text; ``name`` stands for the file in error messages."""
        _check_str(text, "text")
        return cls(_native.NativePatch.from_json(text, name))

    @classmethod
    def from_nodes(cls, nodes, degree: Optional[int] = None, weights=None, simplex: int = 2) -> "Patch":
        """A Bézier simplex from control points in the layout of the Python package ``bezier``.

        ``nodes``: a numpy array or nested lists of shape ``(dimension, number of control
        points)``: column ``j`` is control point ``j`` in the canonical order (the same as
        ``bezier``'s: sorted by the last index, then the one before, …; for a quadratic
        triangle ``200 110 020 101 011 002``). ``degree`` is inferred from the number of
        columns when omitted (``C(n + m, m)`` of them on the m-simplex). ``weights`` (one per
        control point) makes a rational patch. ``simplex``: m (1 curves, 2 triangles, 3
        tetrahedra, ...).

        Numbers may be ints, floats (taken as the exact value of the double: ``0.1`` is
        3602879701896397/36028797018963968), ``fractions.Fraction``, or strings in tribez's number
        syntax (``"1/10"``, ``"0.1"`` = 1/10 exactly, ``"0x1.8p-3"``).
        """
        if isinstance(nodes, np.ndarray) and nodes.ndim == 1:
            raise InputError(
                "nodes: a 1-dimensional array; expected shape (dimension, number of control points)"
            )
        rows = matrix_texts(nodes, "nodes")
        if not rows:
            raise InputError("nodes: no rows (expected shape (dimension, number of control points))")
        points = [list(col) for col in zip(*rows)]
        if not points:
            raise InputError("nodes: no control points (nodes has 0 columns)")
        w = None
        if weights is not None:
            if isinstance(weights, np.ndarray):
                weights = weights.reshape(-1).tolist() if weights.dtype.kind in "fiu" else list(weights.reshape(-1))
            elif not isinstance(weights, (list, tuple)):
                raise InputError(f"weights: expected a sequence of numbers, got {type(weights).__name__}")
            w = [number_text(x, f"weights[{i}]") for i, x in enumerate(weights)]
        if degree is not None:
            degree = _count(degree, "degree", (MAX_DEGREE, f"{{x}} is above the limit of {MAX_DEGREE}"))
        simplex = _count(simplex, "simplex", (
            MAX_SIMPLEX_DIMENSION,
            f"{{x}} is not a simplex dimension from 1 to {MAX_SIMPLEX_DIMENSION} "
            "(1 for curves, 2 for triangles, 3 for tetrahedra)"))
        return cls(_native.NativePatch.from_nodes(simplex, degree, points, w))

    # -- attributes ---------------------------------------------------------------------

    @property
    def degree(self) -> int:
        """The degree n."""
        return self._native.degree

    @property
    def dimension(self) -> int:
        """The number of coordinates d of a control point (and of a value)."""
        return self._native.dimension

    @property
    def simplex(self) -> int:
        """The simplex dimension m (2 for triangles); N - 1 for an S-patch over an N-gon."""
        return self._native.simplex

    @property
    def kind(self) -> str:
        """``"bezier"``, ``"rational"``, ``"functional"`` or ``"s-patch"``."""
        return self._native.kind

    @property
    def name(self) -> Optional[str]:
        """The ``name`` of the patch file, if any."""
        return self._native.name

    @property
    def nodes(self) -> list:
        """The control points, exact, in ``bezier``'s layout: ``dimension`` lists of Fractions,
        one entry per control point in canonical order."""
        pts = self._native.control_points()
        return [[fraction(p[i]) for p in pts] for i in range(self.dimension)]

    @property
    def weights(self) -> Optional[list]:
        """The weights of a rational patch (Fractions, canonical order), else None."""
        w = self._native.weights()
        return None if w is None else [fraction(x) for x in w]

    def to_toml(self) -> str:
        """The patch as a TOML patch file (exact numbers as strings)."""
        return self._native.to_toml()

    def to_json(self) -> str:
        """The patch as a JSON patch file (exact numbers as strings)."""
        return self._native.to_json()

    def __eq__(self, other):
        if not isinstance(other, Patch):
            return NotImplemented
        return self._native == other._native

    __hash__ = None

    def __repr__(self) -> str:
        return repr(self._native)

    def __reduce__(self):
        # pickled as its JSON patch file (exact), e.g. to send it to Dask workers
        return (_patch_from_json, (self.to_json(),))

    # -- evaluation ---------------------------------------------------------------------

    def evaluate(self, points, cartesian: bool = False) -> list:
        """Exact values at points: a list with one tuple of ``fractions.Fraction`` per point.

        ``points``: rows of barycentric coordinates (m + 1 numbers summing to exactly 1), or of
        Cartesian coordinates in the patch's domain with ``cartesian=True`` (S-patches: always
        Cartesian). One flat sequence is one point. Numbers as in :meth:`from_nodes` (a float is
        its exact value, so ``[1/3, 1/3, 1/3]`` in floats does not sum to 1: use Fractions or
        strings). Rational patches: the quotient, exactly.
        """
        rows = matrix_texts(points, "points", allow_vector=True)
        values = self._native.evaluate(rows, bool(cartesian))
        return [tuple(fraction(x) for x in v) for v in values]

    def evaluate_float(self, points, precision: str = "f64") -> np.ndarray:
        """tribez's own float path at float points: a numpy array of shape (rows, dimension),
        dtype float64 (``precision="f64"``) or float32 (``"f32"``).

        The control net and the points are rounded to the precision (the points are floats
        already: float64, or float32 which widens exactly), then de Casteljau runs in it
        (rational patches: homogeneous de Casteljau then one division; S-patches: Cartesian
        points, float Wachspress coordinates then de Casteljau). Its error is within the bound
        that ``certify`` reports (``docs/theory.md §14``).
        """
        width = self._native.point_width
        arr = float_rows(points, "points", width)
        raw = self._native.evaluate_float(arr.tobytes(), width, _precision_name(precision))
        dtype = np.float64 if precision == "f64" else np.float32
        return np.frombuffer(raw, dtype=dtype).reshape(arr.shape[0], self.dimension).copy()


def _patch_from_json(text: str) -> Patch:
    return Patch.from_json(text)


def _check_str(x, where):
    if not isinstance(x, str):
        raise InputError(f"{where}: expected a str, got {type(x).__name__}")


#: The largest row index (the report's ``row`` arrays are int64).
_MAX_ROW = 2**63 - 1


def _count(x, where, above: Optional[tuple] = None) -> int:
    """A non-negative int; ``above = (limit, message)``: an int above ``limit`` is an InputError
    with that message (``{x}`` in it is the value), so that no int reaches the native module
    beyond the machine word it is read into (an OverflowError there)."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        raise InputError(f"{where}: expected a non-negative int, got {x!r}")
    x = int(x)
    if x < 0:
        raise InputError(f"{where}: {x} is negative")
    if above is not None and x > above[0]:
        raise InputError(f"{where}: " + above[1].format(x=x))
    return x


def _precision_name(precision) -> str:
    if precision in ("f64", "f32"):
        return precision
    raise InputError(f"precision: unknown precision `{precision}` (expected \"f64\" or \"f32\")")


TOLERANCES = """\
Tolerances (the strings of the command line's --tolerance; y claimed, q exact, per coordinate):

    exact               y = q
    ulps=N              |y - q| <= N ulp(q)  (the ulp of q's binade in the precision)
    abs=E               |y - q| <= E
    rel=E               |y - q| <= E |q|
    correctly_rounded   y is the float nearest q (ties to even)
    faithful            y is one of the two floats bracketing q (q itself if it is a float)
    cond=K              |y - q| <= K eps sum_i |c_i| B_i(|lambda|)   (eps = 2^-53 in f64, 2^-24 in
                        f32): for code whose algorithm is unknown; K = 3n accepts anything as
                        accurate as de Casteljau (the default cond=9 is 3n for cubics)
    bound               within the proven a-priori bound of `algorithm` ("casteljau":
                        gamma_{(m+1)n} sum|c_i| B_i(|lambda|); "bernstein": the direct form's)

N, E and K are exact numbers ("1e-12", "1/3"). The exact value q is taken at the inputs as the code
saw them (the floats in `points`, which need not sum to 1: the homogeneous form is evaluated there),
so the verdict measures the algorithm's own error; the error at the intended inputs is reported too.
"""


def threads() -> int:
    """The number of threads judging uses (rayon's pool: one per core; RAYON_NUM_THREADS)."""
    return _native.threads()


def _precision_of(values, precision):
    if precision is not None:
        return _precision_name(precision)
    dtype = getattr(values, "dtype", None)
    if dtype is not None and np.dtype(dtype) == np.float32:
        return "f32"
    return "f64"


def check(patch: Patch, points, values, tolerance: str = "cond=9", precision: Optional[str] = None,
          cartesian: bool = False, *, algorithm: str = "casteljau", first_row: int = 0) -> Report:
    """Judge float results of another implementation against the exact values of ``patch``.

    ``points``: a numpy array (or nested lists) of floats, one row per result: m + 1 barycentric
    coordinates (or, with ``cartesian=True``, the m Cartesian coordinates in the patch's domain).
    ``values``: the claimed results, one row of ``patch.dimension`` floats per point.
    ``precision``: ``"f64"`` or ``"f32"``; by default that of ``values`` (float32 -> "f32",
    otherwise "f64"). float32 arrays widen exactly; every number denotes the float it is.
    ``tolerance``: see below. ``algorithm``: the algorithm whose bound ``tolerance="bound"``
    uses (``"casteljau"`` or ``"bernstein"``). ``first_row``: the index of the first row in a
    larger set (for partitions whose reports are merged; row indices in the report count from it).

    Returns a :class:`Report`: the library's batch report, the same as the command line's
    ``tribez check --patch P --results FILE`` on the same rows (its text is ``str(report)``).
    NaN and infinite values are failed rows, not errors. The GIL is released while judging,
    which runs on every core (rayon).

    Rows are judged by a float filter first (an f64 de Casteljau with a rigorous error bound,
    then a compensated stage); only rows it cannot decide fall back to exact big-integer
    arithmetic (``report.fell_back``).

    C-contiguous float64 arrays are read in place, without a copy (others are converted first):
    do not write to them from another thread while ``check`` runs.

    """
    if not isinstance(patch, Patch):
        raise InputError(f"patch: expected a tribez.Patch, got {type(patch).__name__}")
    prec = _precision_of(values, precision)
    if not isinstance(tolerance, str):
        raise InputError(f"tolerance: expected a str such as \"cond=9\", got {tolerance!r}")
    if algorithm not in ("casteljau", "bernstein"):
        raise InputError(f"algorithm: unknown algorithm `{algorithm}` (expected casteljau or bernstein)")
    first_row = _count(first_row, "first_row")
    width = _native_width(patch, cartesian)
    pts = float_rows(points, "points", width)
    vals = float_rows(values, "values", patch.dimension)
    if pts.shape[0] != vals.shape[0]:
        raise InputError(f"{pts.shape[0]} rows of points but {vals.shape[0]} rows of values")
    if pts.shape[0] == 0:
        raise InputError("points: no rows")
    if first_row + pts.shape[0] - 1 > _MAX_ROW:
        # row indices are int64 in the report's arrays (and machine words in the library)
        raise InputError(
            f"first_row: {first_row} + {pts.shape[0]} rows passes the largest row index 2^63 - 1"
        )
    # the arrays are read in place (float_rows: C-contiguous float64), not copied
    native = _native.check_rows(patch._native, pts, vals, width, patch.dimension,
                                tolerance, prec, bool(cartesian), algorithm, first_row)
    return Report(native)


check.__doc__ = (check.__doc__ or "") + textwrap.indent(TOLERANCES, "    ")


def _native_width(patch: Patch, cartesian: bool) -> int:
    if patch.kind == "s-patch":
        return 2
    return patch.simplex if cartesian else patch.simplex + 1


def check_claims(path) -> ClaimsReport:
    """Check a claim file, or every claim file under a directory (``*.claims.toml``,
    ``*.claims.json``, searched recursively): the library's report of ``tribez check PATH``.

    Every claim is recomputed exactly and compared with the value its source printed, within the
    claim's tolerance. Returns a :class:`ClaimsReport` (a :class:`Report`): ``passed``,
    ``failed``, ``errata`` (claims wrong as printed, recorded as known errata: they do not fail),
    ``claims``, ``ok``, ``str(report)`` (the command line's text), ``to_json()``, per-claim
    ``results`` and ``rows``; ``raise_if_failed()``. Bad claim files raise :class:`InputError`
    with the command line's message (file, line, key).
    """
    try:
        path = os.fspath(path)
    except TypeError:
        raise InputError(f"path: expected a str or os.PathLike, got {type(path).__name__}") from None
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    return ClaimsReport(_native.check_claims(path))


def certify(patch: Patch, points=None, random: Optional[int] = None, seed: Optional[int] = None,
            precision: str = "all", algorithm: str = "all") -> CertifyReport:
    """Certify tribez's own float evaluation of ``patch``: run its float program (de Casteljau
    and the direct Bernstein form for polynomial patches; homogeneous de Casteljau and one
    division for rational ones; float Wachspress coordinates then de Casteljau for S-patches) in
    f64 and f32 and judge every result against the exact value and the proven a-priori error
    bound (docs/theory.md §14): the library's report of ``tribez certify``.

    ``points``: rows of points in the patch's coordinates (m + 1 barycentric coordinates; (x, y)
    in the polygon of an S-patch), numbers as in :meth:`Patch.from_nodes` (each is rounded to
    the precision as a float program would round it). Otherwise ``random`` reproducible random
    points (1000 when neither is given; at most ``MAX_RANDOM_POINTS``) from ``seed`` (1 when
    omitted, as the command line; the report gives it back as ``report.seed`` with the command
    that reproduces the run). ``precision``: ``"f64"``, ``"f32"`` or ``"all"``; ``algorithm``:
    ``"casteljau"``, ``"bernstein"`` or ``"all"``.

    Returns a :class:`CertifyReport` (a :class:`Report`): ``ok`` when every result is within its
    bound, per algorithm and precision ``results`` and ``rows``, ``max_ulps``, ``worst``,
    ``seed``, ``str(report)``, ``to_json()``; ``raise_if_failed()``.
    """
    if not isinstance(patch, Patch):
        raise InputError(f"patch: expected a tribez.Patch, got {type(patch).__name__}")
    if points is not None and random is not None:
        raise InputError("give points or random (a number of random points), not both")
    rows = None
    if points is not None:
        rows = matrix_texts(points, "points", allow_vector=True)
        if not rows:
            raise InputError("points: no rows")
    elif random is None:
        random = 1000
    if random is not None:
        random = _count(random, "random", (
            _native.MAX_RANDOM_POINTS,
            f"{{x}}: expected a whole number from 1 to {_native.MAX_RANDOM_POINTS}"))
    seed = 1 if seed is None else _count(seed, "seed")
    if seed >= 2**64:
        raise InputError(f"seed: {seed} is above the limit of 2^64 - 1")
    if not isinstance(precision, str) or precision not in ("f64", "f32", "all"):
        raise InputError(f"precision: unknown precision `{precision}` (expected \"f64\", \"f32\" or \"all\")")
    if not isinstance(algorithm, str):
        raise InputError(f"algorithm: expected a str, got {type(algorithm).__name__}")
    # the report names the patch as the command line does: by its file, when it came from one
    label = patch._path or (f"<{patch.name}>" if patch.name else "<patch>")
    return CertifyReport(_native.certify(patch._native, rows, random, seed, precision, algorithm, label))


def _inverse_rows(queries, claimed, qwhere: str, cwhere: str, qwidth: int, twidth: int,
                  most: Optional[int]) -> list:
    """The rows of an inverse batch as number texts: the query, then the claimed tuples."""
    try:
        count = len(queries)
    except TypeError:
        count = 0  # not a sequence: matrix_texts says so
    if count > MAX_INVERSE_ROWS:
        raise InputError(f"{qwhere}: {count} rows, more than the {MAX_INVERSE_ROWS} one call judges "
                         "(split them, or write a results file for tribez check)")
    qs = matrix_texts(queries, qwhere)
    if not qs:
        raise InputError(f"{qwhere}: no rows")
    if len(qs[0]) != qwidth:
        raise InputError(f"{qwhere}: rows of {len(qs[0])} numbers, expected {qwidth}")
    if isinstance(claimed, np.ndarray) and claimed.ndim >= 1:
        claimed = list(claimed)
    if not isinstance(claimed, (list, tuple)):
        raise InputError(f"{cwhere}: expected a list with one entry per row, got {type(claimed).__name__}")
    if len(claimed) != len(qs):
        raise InputError(f"{len(qs)} rows of {qwhere} but {len(claimed)} entries of {cwhere}")
    rows = []
    for i, (q, c) in enumerate(zip(qs, claimed)):
        where = f"{cwhere}[{i}]"
        if c is None or (isinstance(c, (list, tuple, np.ndarray)) and len(c) == 0):
            rows.append(q + ["none"])
            continue
        tuples = matrix_texts(c, where, allow_vector=True)
        if tuples and len(tuples[0]) != twidth:
            raise InputError(f"{where}: tuples of {len(tuples[0])} numbers, expected {twidth}")
        if most is not None and len(tuples) > most:
            raise InputError(f"{where}: {len(tuples)} tuples, expected at most {most}")
        rows.append(q + [x for t in tuples for x in t])
    return rows


def _check_inverse(kind: str, patch: Patch, rows: list, tolerance: str, precision,
                   anywhere: bool = False) -> "InverseReport":
    if not isinstance(tolerance, str):
        raise InputError(f"tolerance: expected a str such as \"exact\" or \"ulps=16\", got {tolerance!r}")
    if precision is not None:
        precision = _precision_name(precision)
    label = patch._path or (f"<{patch.name}>" if patch.name else "<patch>")
    return InverseReport(_native.check_inverse(patch._native, kind, rows, tolerance, precision,
                                               bool(anywhere), label))


def check_locate(patch: Patch, points, claimed, tolerance: str = "exact",
                 precision: Optional[str] = None, anywhere: bool = False) -> "InverseReport":
    """Judge another implementation's answers to *locate*: the parameters ``(s, t)`` at which a
    planar triangle patch (Bézier or rational) passes through a point.

    ``points``: one row ``(x, y)`` per query (a numpy array or nested lists). ``claimed``: one
    entry per query, the parameter pairs the code found there: a pair ``(s, t)``, several pairs
    (a list of pairs or a ``(k, 2)`` array), or ``None`` (or an empty list) for none. Every
    ``(s, t)`` of the closed triangle ``s, t >= 0``, ``s + t <= 1`` (of the whole plane with
    ``anywhere=True``, for code that extrapolates) that maps to the point is an exact solution;
    each claimed pair is paired with the nearest exact one within
    ``2**-20 * max(1, |value|)`` and judged with ``tolerance`` (``"exact"``, ``"ulps=N"``,
    ``"abs=E"``, ``"rel=E"``, ``"correctly_rounded"``, ``"faithful"``); an exact solution left
    unpaired is *missed*, a claimed pair left unpaired is *extra*.

    Numbers are as in :meth:`Patch.from_nodes`: a float is the value it is, a string is read
    exactly (``"0.1"`` is 1/10). With ``precision`` (``"f64"`` or ``"f32"``) every number denotes
    the float of that precision nearest it, the patch is rounded likewise, and the exact answer is
    that of the query and patch as the code saw them.

    Returns an :class:`InverseReport`, the report of ``tribez check --patch P --locate-results
    FILE`` on the same rows (row ``i`` is line ``i + 1`` there).
    """
    if not isinstance(patch, Patch):
        raise InputError(f"patch: expected a tribez.Patch, got {type(patch).__name__}")
    if not isinstance(anywhere, (bool, np.bool_)):
        raise InputError(f"anywhere: expected a bool, got {anywhere!r}")
    rows = _inverse_rows(points, claimed, "points", "claimed", 2, 2, None)
    return _check_inverse("locate", patch, rows, tolerance, precision, anywhere)


def check_ray(patch: Patch, rays, hits, tolerance: str = "exact",
              precision: Optional[str] = None) -> "InverseReport":
    """Judge another implementation's first hits of rays on a triangle patch in R^3 (Bézier or
    rational, or a functional patch as its graph).

    ``rays``: one row ``(ox, oy, oz, dx, dy, dz)`` per ray (origin, then direction). ``hits``:
    one entry per ray, the claimed first hit ``(tau, s, t)`` (the point ``o + tau * d`` at the
    parameters ``(s, t)``), or ``None`` for a ray that misses. The exact answer is the hit with
    the smallest ``tau >= 0`` over the closed triangle, a grazing touch included; a later hit
    claimed as the first fails (it is extra, and the first is missed). ``tolerance`` and
    ``precision`` as in :func:`check_locate`.

    Returns an :class:`InverseReport`, the report of ``tribez check --patch P --ray-results
    FILE`` on the same rows (row ``i`` is line ``i + 1`` there).
    """
    if not isinstance(patch, Patch):
        raise InputError(f"patch: expected a tribez.Patch, got {type(patch).__name__}")
    rows = _inverse_rows(rays, hits, "rays", "hits", 6, 3, 1)
    return _check_inverse("ray", patch, rows, tolerance, precision)
