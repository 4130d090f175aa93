"""tribez.Report: the library's report of a batch check (or of claim files), seen from Python."""

from __future__ import annotations

import json
from typing import Optional

import numpy as np

from ._errors import CertificationError, InputError


class Report:
    """The verdict of :func:`check`: the library's batch report, as the
    command line prints it (``str(report)``) and exports it (``report.to_json()``).

    Attributes: ``passed`` and ``failed`` (counts of rows), ``ok`` (nothing failed),
    ``fell_back`` (rows the float filter left open, computed in exact arithmetic),
    ``max_ulps`` (the largest error in ULPs, of the worst row, computed exactly; None without a
    precision), ``worst`` (a dict: ``row`` (its index in the whole set), ``ulps``, and per
    coordinate the claimed value, the exact values and the errors at the inputs as seen and as
    intended), ``histogram`` (a dict from bucket label to count), ``rows`` (per-row numpy
    arrays; see :attr:`rows`), ``tolerance``, ``precision``.

    Reports of disjoint row sets combine with :meth:`merge`; :meth:`raise_if_failed` raises
    :class:`CertificationError` with the failure summary.
    """

    __slots__ = ("_native", "_rows")

    def __init__(self, native):
        self._native = native
        self._rows = None

    @property
    def passed(self) -> int:
        """Rows that hold."""
        return self._native.passed

    @property
    def failed(self) -> int:
        """Rows that fail."""
        return self._native.failed

    @property
    def ok(self) -> bool:
        """True when nothing failed."""
        return self._native.failed == 0

    @property
    def fell_back(self) -> int:
        """Rows the float filter could not decide, judged in exact big-integer arithmetic."""
        return self._native.fell_back

    @property
    def tolerance(self) -> str:
        return self._native.tolerance

    @property
    def precision(self) -> Optional[str]:
        return self._native.precision

    @property
    def max_ulps(self) -> Optional[float]:
        """The largest error in ULPs (of the worst row, computed exactly), None if unknown."""
        return self._native.max_ulps

    @property
    def worst(self) -> Optional[dict]:
        """The worst row: ``{"row": index, "ulps": error, "coordinates": [...]}`` (the JSON
        report's ``worst``, its ``line`` named ``row``), or None."""
        w = self._native.worst_json()
        return None if w is None else json.loads(w)

    @property
    def histogram(self) -> dict:
        """Errors in ULPs, counted per bucket (``"0"``, ``"(0, 1/2]"``, ..., ``"> 256"``)."""
        return dict(self._native.histogram())

    @property
    def rows(self) -> dict:
        """Per-row results, numpy arrays indexed like the rows (after a merge: by row index):

        * ``row`` (int64): the row's index (counted from ``first_row``);
        * ``passed`` (bool): within the tolerance;
        * ``ulps_seen`` (float64): the error in ULPs at the inputs as the code saw them (the
          floats of the precision, the control points rounded to it), the largest over the
          coordinates; exact for rows computed exactly, otherwise the upper end of a compensated
          enclosure a small fraction of an ULP wide (never across the 0 and 1/2 boundaries);
          infinite for a NaN or infinite number;
        * ``ulps_intended`` (float64): the same error at the inputs as intended: the float64
          numbers given and the patch's exact control points. It differs from ``ulps_seen`` only
          where those differ from what the code saw (``precision="f32"`` rounds the inputs; a
          control point such as 1/3 is not a float): those rows are computed exactly;
        * ``correctly_rounded`` (bool): every coordinate is the float nearest the exact value at
          the inputs as seen (ties to even);
        * ``fell_back`` (bool): the float filter left the row to exact arithmetic.

        A report merged or unpickled before its rows were read has ``ulps_intended`` NaN (unknown)
        where the intended inputs differ from those seen: read ``rows`` first to keep them.

        The arrays are read-only (copy them to change them). Computed on first access (exact arithmetic only where the inputs as intended differ
        from those as seen); until then the report keeps the rows' numbers.
        """
        cached = getattr(self, "_rows", None)
        if cached is None:
            cached = {}
            for name, dtype, data in self._native.row_arrays():
                a = np.frombuffer(data, dtype=dtype).copy()
                a.flags.writeable = False
                cached[name] = a
            self._rows = cached
        return dict(cached)

    def to_json(self) -> str:
        """The report as JSON: the command line's ``--format json`` output."""
        return self._native.json()

    def __str__(self) -> str:
        """The command line's text report."""
        return self._native.text()

    def __repr__(self) -> str:
        return (f"<tribez.Report passed={self.passed} failed={self.failed} "
                f"fell_back={self.fell_back} max_ulps={self.max_ulps}>")

    def merge(self, other: "Report") -> "Report":
        """The report of the union of two disjoint row sets (e.g. partitions checked on different
        machines, each with its ``first_row``): counts and histograms add, the worst row is the
        larger error (ties: the smaller row index), the listed failures are the first ones by
        row index. Equal to the report of one run over all the rows."""
        if not isinstance(other, Report) or isinstance(other, _DocumentReport):
            raise InputError(
                f"merge: expected a report of tribez.check, got {type(other).__name__} "
                "(claims, certification and inverse reports do not merge)"
            )
        return Report(self._native.merge(other._native))

    def raise_if_failed(self) -> None:
        """Raise :class:`CertificationError` (carrying this report) if any row failed."""
        if not self.ok:
            raise CertificationError(self.failure_text(), self)

    def failure_text(self) -> str:
        """The failure summary: the text report's failures, worst row and summary lines."""
        return self._native.text()

    def __reduce__(self):
        return (_from_state, (type(self._native), self._native.state()))


def _from_state(cls, state):
    return Report(cls.from_state(state))


class _DocumentReport(Report):
    """A report the library renders whole (claim files, certification runs): its JSON and text."""

    __slots__ = ("_data",)

    def __init__(self, native):
        super().__init__(native)
        self._data = json.loads(native.json)

    @property
    def ok(self) -> bool:
        return bool(self._native.success)

    @property
    def fell_back(self) -> None:
        """None: every claim and every certified point is computed in exact arithmetic."""
        return None

    @property
    def histogram(self) -> Optional[dict]:
        return None

    @property
    def tolerance(self) -> Optional[str]:
        return None

    @property
    def precision(self) -> Optional[str]:
        return None

    def to_json(self) -> str:
        """The report as JSON: the command line's ``--format json`` output."""
        return self._native.json

    def __str__(self) -> str:
        """The command line's text report."""
        return self._native.text

    def failure_text(self) -> str:
        return self._native.text

    def merge(self, other: "Report") -> "Report":
        raise InputError(
            f"merge: {type(self).__name__}s do not merge (only reports of tribez.check do); "
            "check the claim files together (a directory) or certify at all the points at once"
        )

    def __reduce__(self):
        n = self._native
        return (_document_from_parts, (n.kind, n.json, n.text, n.success))


def _document_from_parts(kind, json_text, text, success):
    from . import _native

    native = _native.NativeDocument.from_parts(kind, json_text, text, success)
    cls = {"claims": ClaimsReport, "certify": CertifyReport, "inverse": InverseReport}[kind]
    return cls(native)


def _ulps(measure) -> Optional[float]:
    """The float value of a JSON error measure's ``ulps`` (an exact ``p/q`` string), if any."""
    if not measure or not measure.get("ulps"):
        return None
    from fractions import Fraction

    return float(Fraction(measure["ulps"]["exact"]))


class ClaimsReport(_DocumentReport):
    """The report of claim files (:func:`tribez.check_claims`): what ``tribez check PATH`` prints
    (``str(report)``) and exports (``report.to_json()``), a :class:`Report`.

    ``passed`` (claims that hold), ``failed`` (claims that fail the run: wrong values, and known
    errata that no longer reproduce), ``errata`` (claims wrong as their source printed them,
    recorded as errata: they do not fail), ``claims`` (all of them), ``files``, ``ok`` (nothing
    failed), ``histogram`` (float claims' errors in ULPs per bucket), ``max_ulps`` and ``worst``
    (the float coordinate with the largest error at the inputs as seen), ``results`` (one dict
    per claim: the JSON report's ``claims``), ``rows`` (per-claim numpy arrays).
    """

    __slots__ = ()

    @property
    def summary(self) -> dict:
        """The JSON report's ``summary``."""
        return dict(self._data["summary"])

    @property
    def passed(self) -> int:
        """Claims that hold."""
        return self._data["summary"]["passed"]

    @property
    def failed(self) -> int:
        """Claims that fail the run (wrong values; errata that no longer reproduce)."""
        return self._data["summary"]["failed"]

    @property
    def errata(self) -> int:
        """Claims wrong as printed in their source, recorded as known errata (not failures)."""
        return self._data["summary"]["errata"]

    @property
    def claims(self) -> int:
        """All claims judged."""
        return self._data["summary"]["claims"]

    @property
    def files(self) -> int:
        """Claim files read."""
        return self._data["summary"]["files"]

    @property
    def histogram(self) -> dict:
        """Float claims' errors in ULPs (at the inputs as seen), counted per bucket."""
        return dict(self._data["summary"]["ulp_histogram"])

    @property
    def results(self) -> list:
        """One dict per claim, in order: ``file``, ``id``, ``op``, ``source``, ``erratum``,
        ``tolerance``, ``precision``, ``verdict`` (``"passed"``, ``"FAILED"``, ``"erratum"``,
        ...), ``exact``, ``claimed``, ``mismatches``, ``float`` (per float coordinate its errors
        at the inputs as seen and as intended)."""
        return json.loads(json.dumps(self._data["claims"]))

    def _float_errors(self):
        for c in self._data["claims"]:
            for k, f in enumerate(c.get("float") or []):
                u = _ulps(f.get("error_at_inputs_as_seen"))
                yield (float("inf") if u is None else u), c, k, f

    @property
    def max_ulps(self) -> Optional[float]:
        """The largest error in ULPs of a float claim's coordinate (None without float claims)."""
        return max((e[0] for e in self._float_errors()), default=None)

    @property
    def worst(self) -> Optional[dict]:
        """The float coordinate with the largest error (ties: the last, as in the text report):
        ``file``, ``id``, ``coordinate``, ``ulps``, ``ulps_intended`` and its JSON entry
        ``float`` (None without float claims)."""
        best = None
        for e in self._float_errors():
            if best is None or e[0] >= best[0]:  # ties: the last, as the text report's "worst"
                best = e
        if best is None:
            return None
        u, c, k, f = best
        return {"file": c["file"], "id": c["id"], "coordinate": k, "ulps": u,
                "ulps_intended": _ulps(f.get("error_at_intended_inputs")), "float": f}

    @property
    def rows(self) -> dict:
        """Per-claim numpy arrays: ``file``, ``id``, ``op``, ``verdict`` (object arrays of str),
        ``passed`` (bool: the claim holds), ``erratum`` (bool: a known erratum)."""
        cs = self._data["claims"]
        obj = lambda key: np.array([c[key] for c in cs], dtype=object)
        return {
            "file": obj("file"),
            "id": obj("id"),
            "op": obj("op"),
            "verdict": obj("verdict"),
            "passed": np.array([c["verdict"] in ("passed", "reproduced") for c in cs], dtype=bool),
            "erratum": np.array([c["verdict"] == "erratum" for c in cs], dtype=bool),
        }

    def __repr__(self) -> str:
        return (f"<tribez.ClaimsReport claims={self.claims} passed={self.passed} "
                f"errata={self.errata} failed={self.failed}>")


class CertifyReport(_DocumentReport):
    """The report of a certification run (:func:`tribez.certify`): what ``tribez certify``
    prints (``str(report)``) and exports (``report.to_json()``), a :class:`Report`.

    One result per algorithm and precision (``results``; ``rows`` as numpy arrays): the largest
    error in ULPs and where, the share correctly rounded, the largest condition numbers, the
    proven a-priori bound and the largest error over it, the points that broke it
    (``violations``). ``passed`` / ``failed`` count the results within / beyond their bound;
    ``ok`` is every result within its bound. ``seed`` and ``reproduce`` (the command line that
    reproduces the run) for random points.
    """

    __slots__ = ()

    @property
    def results(self) -> list:
        """One dict per algorithm and precision (the JSON report's ``results``)."""
        return json.loads(json.dumps(self._data["results"]))

    @property
    def passed(self) -> int:
        """Results (algorithm, precision) within their proven bound."""
        return sum(1 for r in self._data["results"] if r["within_bound"])

    @property
    def failed(self) -> int:
        """Results with some error beyond the proven bound."""
        return sum(1 for r in self._data["results"] if not r["within_bound"])

    @property
    def points(self) -> int:
        """The number of points evaluated."""
        return self._data["points"]

    @property
    def seed(self) -> Optional[int]:
        """The seed of the random points (None for given points)."""
        r = self._data.get("random")
        return None if r is None else r["seed"]

    @property
    def reproduce(self) -> Optional[str]:
        """The ``tribez certify`` command that reproduces a random run."""
        r = self._data.get("random")
        return None if r is None else r["reproduce"]

    @property
    def max_ulps(self) -> Optional[float]:
        """The largest error in ULPs over every algorithm and precision."""
        return max((r["max_ulps"] for r in self._data["results"]), default=None)

    @property
    def worst(self) -> Optional[dict]:
        """The result with the largest error: ``algorithm``, ``precision``, ``ulps`` and
        ``point`` (a tuple of Fractions: where, as the float program saw it)."""
        from fractions import Fraction

        rs = self._data["results"]
        if not rs:
            return None
        r = max(rs, key=lambda r: r["max_ulps"])
        point = r.get("worst_point")
        return {"algorithm": r["algorithm"], "precision": r["precision"], "ulps": r["max_ulps"],
                "point": None if point is None else tuple(Fraction(x) for x in point)}

    @property
    def rows(self) -> dict:
        """Per-result numpy arrays: ``algorithm``, ``precision``, ``bound`` (object arrays of
        str), ``coordinates``, ``correctly_rounded``, ``outside_hypothesis``, ``violations``
        (int64 counts), ``max_ulps``, ``max_condition``, ``max_relative_condition``,
        ``max_error_over_bound`` (float64), ``within_bound`` (bool)."""
        rs = self._data["results"]
        col = lambda key, dtype: np.array([r[key] for r in rs], dtype=dtype)
        return {
            "algorithm": col("algorithm", object),
            "precision": col("precision", object),
            "bound": col("bound", object),
            "coordinates": col("coordinates", np.int64),
            "correctly_rounded": col("correctly_rounded", np.int64),
            "outside_hypothesis": col("outside_hypothesis", np.int64),
            "violations": np.array([len(r["violations"]) for r in rs], dtype=np.int64),
            "max_ulps": col("max_ulps", np.float64),
            "max_condition": col("max_condition", np.float64),
            "max_relative_condition": col("max_relative_condition", np.float64),
            "max_error_over_bound": col("max_error_over_bound", np.float64),
            "within_bound": col("within_bound", bool),
        }

    def __repr__(self) -> str:
        return (f"<tribez.CertifyReport points={self.points} results={len(self._data['results'])} "
                f"within_bound={self.passed} max_ulps={self.max_ulps}>")


class InverseReport(_DocumentReport):
    """The report of a batch of inverse answers (:func:`tribez.check_locate`,
    :func:`tribez.check_ray`): what ``tribez check --patch P --locate-results FILE`` (or
    ``--ray-results``) prints (``str(report)``) and exports (``report.to_json()``), a
    :class:`Report`.

    ``kind`` (``"locate"`` or ``"ray"``), ``checked``, ``passed`` and ``failed`` (rows),
    ``missed`` (exact solutions no claimed tuple was paired with), ``extra`` (claimed tuples
    paired with no exact solution), ``out_of_tolerance`` (paired coordinates beyond the
    tolerance), ``infinite`` (queries with infinitely many solutions), ``not_finite`` (rows with
    a number that is not finite), ``failures`` (the first 100 failed rows in full, each with its
    ``row`` index), ``tolerance``, ``precision``.
    """

    __slots__ = ()

    def _count(self, key: str) -> int:
        return int(self._data[key])

    @property
    def kind(self) -> str:
        """``"locate"`` or ``"ray"``."""
        return self._data["kind"]

    @property
    def anywhere(self) -> bool:
        """Locate rows judged over the whole plane (``check_locate(..., anywhere=True)``)."""
        return bool(self._data["anywhere"])

    @property
    def checked(self) -> int:
        """Rows judged."""
        return self._count("checked")

    @property
    def passed(self) -> int:
        """Rows whose claim holds."""
        return self._count("passed")

    @property
    def failed(self) -> int:
        """Rows whose claim fails."""
        return self._count("failed")

    @property
    def missed(self) -> int:
        """Exact solutions no claimed tuple was paired with (over all rows)."""
        return self._count("missed")

    @property
    def extra(self) -> int:
        """Claimed tuples paired with no exact solution."""
        return self._count("extra")

    @property
    def out_of_tolerance(self) -> int:
        """Paired coordinates that break the tolerance."""
        return self._count("out_of_tolerance")

    @property
    def infinite(self) -> int:
        """Rows whose query has infinitely many solutions."""
        return self._count("infinite")

    @property
    def not_finite(self) -> int:
        """Rows with a number that is not finite."""
        return self._count("not_finite")

    @property
    def tolerance(self) -> str:
        return self._data["tolerance"]

    @property
    def precision(self) -> Optional[str]:
        return self._data["precision"]

    @property
    def failures(self) -> list:
        """The first failed rows (at most 100), in row order: dicts with ``row`` (the row's
        index), ``query`` and ``claimed`` (number texts as handed over), ``exact`` (the exact
        solutions) and ``mismatches`` (``kind``, ``path``, ``reason``, …)."""
        out = []
        for f in self._data["failures"]:
            f = json.loads(json.dumps(f))
            f["row"] = f.pop("line") - 1
            out.append(f)
        return out

    @property
    def max_ulps(self) -> Optional[float]:
        """The largest error in ULPs of a failed coordinate listed (None when none has one)."""
        errs = [_ulps(m.get("measures")) for f in self._data["failures"] for m in f["mismatches"]]
        errs = [e for e in errs if e is not None]
        return max(errs, default=None)

    @property
    def worst(self) -> None:
        """None: an inverse batch lists its failures (:attr:`failures`), not a worst row."""
        return None

    @property
    def rows(self) -> dict:
        """Per listed failure numpy arrays: ``row`` (int64), ``missed``, ``extra``,
        ``out_of_tolerance`` (int64 counts of its mismatches of each kind)."""
        fs = self._data["failures"]
        count = lambda kind: np.array([sum(1 for m in f["mismatches"] if m["kind"] == kind) for f in fs],
                                      dtype=np.int64)
        return {
            "row": np.array([f["line"] - 1 for f in fs], dtype=np.int64),
            "missed": count("missed"),
            "extra": count("extra"),
            "out_of_tolerance": count("coordinate"),
        }

    def __repr__(self) -> str:
        return (f"<tribez.InverseReport kind={self.kind} checked={self.checked} "
                f"passed={self.passed} failed={self.failed}>")
