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
        if not isinstance(other, Report):
            raise InputError(f"merge: expected a tribez.Report, got {type(other).__name__}")
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
