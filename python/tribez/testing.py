"""pytest-friendly assertions: ``from tribez.testing import assert_certified``."""

from __future__ import annotations

from . import check


def assert_certified(patch, points, values, tolerance: str = "cond=9", precision=None,
                     cartesian: bool = False, **kwargs):
    """Assert that every row of ``values`` is within ``tolerance`` of the exact value of
    ``patch`` at ``points`` (see :func:`tribez.check` for the arguments and the tolerances).

    On failure raises ``AssertionError`` whose message is the report's failure text (the
    failed rows with their claimed and exact values and errors, the worst row, the summary), so
    pytest shows it. Returns the :class:`tribez.Report` otherwise.
    """
    report = check(patch, points, values, tolerance=tolerance, precision=precision,
                   cartesian=cartesian, **kwargs)
    if not report.ok:
        raise AssertionError(
            f"tribez: {report.failed} of {report.passed + report.failed} rows fail "
            f"tolerance {tolerance}\n{report.failure_text()}"
        )
    return report
