"""The exceptions of tribez (raised by the native module too)."""


class TribezError(Exception):
    """Base class of every exception tribez raises."""


class InputError(TribezError, ValueError):
    """Bad input: a patch, a number, a point, a tolerance or an array that tribez cannot use.

    The message is the one line the command line prints after ``tribez: `` for the same input
    (file, line, key and what is wrong).
    """


class CertificationError(TribezError):
    """Raised by :meth:`Report.raise_if_failed` when some row or claim fails.

    ``report`` is the :class:`Report`; the message is its failure summary.
    """

    def __init__(self, message, report=None):
        super().__init__(message)
        self.report = report


class InternalError(TribezError, RuntimeError):
    """A bug in tribez (a Rust panic, caught before it could cross into Python)."""
