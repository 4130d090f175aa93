"""Python numbers and arrays -> what the native module takes (exact number texts, f64 bytes)."""

from __future__ import annotations

import numbers
from fractions import Fraction

import numpy as np

from ._errors import InputError

_KINDS = "int, float, fractions.Fraction or str"


def number_text(x, where: str) -> str:
    """The exact text of one number in tribez's syntax.

    ints as decimal, floats (Python or numpy) as their exact value (hex form), Fractions (any
    ``numbers.Rational``) as ``p/q``, strings as written (tribez parses them: ``"1/3"``,
    ``"0.1"`` = 1/10, ``"0x1.8p-3"``, ``"f64:0.1"``); anything else is an InputError.
    ``nan`` and infinities pass through as text, and the library rejects them with its message.
    """
    if isinstance(x, str):
        return x
    if isinstance(x, (bool, np.bool_)):
        raise InputError(f"{where}: {x!r} is a bool, not a number ({_KINDS})")
    if isinstance(x, float):
        return x.hex()
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, numbers.Rational):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, np.floating):
        if np.isfinite(x):
            p, q = x.as_integer_ratio()
            return f"{p}/{q}"
        return repr(float(x))
    if isinstance(x, numbers.Real) and hasattr(x, "as_integer_ratio"):
        # decimal.Decimal and friends: their exact value
        try:
            p, q = x.as_integer_ratio()
        except (ValueError, OverflowError):
            return str(x)
        return f"{p}/{q}"
    raise InputError(f"{where}: {x!r} is not a number ({_KINDS})")


def _is_sequence(x) -> bool:
    return isinstance(x, (list, tuple, np.ndarray))


def matrix_texts(a, where: str, *, allow_vector: bool = False) -> list[list[str]]:
    """Rows of number texts from a 2-D numpy array or nested sequences (rectangular).

    With ``allow_vector``, one flat sequence is one row.
    """
    if isinstance(a, np.ndarray):
        if a.ndim == 1 and allow_vector:
            a = a.reshape(1, -1)
        if a.ndim != 2:
            raise InputError(f"{where}: an array of {a.ndim} dimensions, expected 2 (rows)")
        if a.dtype.kind in "fiub" and a.dtype.itemsize <= 8:
            rows = a.tolist()
        else:
            rows = [list(r) for r in a]
    else:
        if not _is_sequence(a):
            raise InputError(
                f"{where}: expected a 2-D numpy array or a list of lists, got {type(a).__name__}"
            )
        rows = list(a)
        if allow_vector and rows and not any(_is_sequence(r) for r in rows):
            rows = [rows]
        for i, r in enumerate(rows):
            if not _is_sequence(r):
                raise InputError(
                    f"{where}[{i}]: expected a row (a list or array of numbers), got {type(r).__name__}"
                )
    out = []
    width = None
    for i, r in enumerate(rows):
        r = list(r)
        if width is None:
            width = len(r)
        elif len(r) != width:
            raise InputError(
                f"{where}[{i}]: a row of {len(r)} numbers, but row 0 has {width} (rows of different lengths)"
            )
        out.append([number_text(x, f"{where}[{i}][{j}]") for j, x in enumerate(r)])
    return out


def float_rows(a, where: str, width: int | None = None) -> np.ndarray:
    """A C-contiguous float64 2-D array of a float (or integer) array or nested lists.

    float32 input widens exactly. Exact numbers (Fractions, strings) are not floats: they are an
    InputError here (round them yourself, deliberately).
    """
    if isinstance(a, np.ndarray) and a.dtype.kind == "f":
        if a.dtype.itemsize > 8:
            raise InputError(
                f"{where}: {a.dtype} values are not f64 or f32 (convert them deliberately)"
            )
        arr = a
    else:
        try:
            arr = np.asarray(a)
        except (ValueError, TypeError) as e:
            raise InputError(f"{where}: not a rectangular array of floats ({e})") from None
        if arr.dtype.kind not in "fiu":
            raise InputError(
                f"{where}: an array of {arr.dtype} values; expected floats (float64 or float32)"
            )
    if arr.ndim == 1 and width is not None and arr.size == width:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2:
        raise InputError(f"{where}: an array of {arr.ndim} dimensions, expected 2 (one row per point)")
    if width is not None and arr.shape[1] != width:
        raise InputError(f"{where}: rows of {arr.shape[1]} numbers, expected {width}")
    return np.ascontiguousarray(arr, dtype=np.float64)


def fraction(text: str) -> Fraction:
    """A Fraction from the library's exact text (``p/q`` or ``p``)."""
    return Fraction(text)
