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
        return _integer_text(int(x), 1, where)
    if isinstance(x, numbers.Rational):
        return _integer_text(int(x.numerator), int(x.denominator), where)
    if isinstance(x, np.floating):
        if np.isfinite(x):
            p, q = x.as_integer_ratio()
            return _integer_text(p, q, where)
        return repr(float(x))
    if isinstance(x, numbers.Real) and hasattr(x, "as_integer_ratio"):
        # decimal.Decimal and friends: their exact value
        try:
            p, q = x.as_integer_ratio()
        except (ValueError, OverflowError):
            return str(x)
        return _integer_text(p, q, where)
    raise InputError(f"{where}: {x!r} is not a number ({_KINDS})")


#: The most digits tribez reads in one number (numerator and denominator together; the library's
#: ``MAX_DIGITS``).
MAX_DIGITS = 100_000

#: Digits per piece of a long integer's decimal text: below Python's smallest limit on int-to-str
#: conversion (640 digits), so that no setting of ``sys.set_int_max_str_digits`` refuses a piece.
_PIECE = 600


def _digits(n: int) -> int:
    """Decimal digits of ``n >= 0`` (1 for 0), without converting it to text."""
    if n == 0:
        return 1
    d = (n.bit_length() * 30103) // 100000  # floor(bits log10 2) <= digits
    while n >= 10**d:
        d += 1
    return max(d, 1)


def _decimal(n: int) -> str:
    """The decimal text of ``n >= 0`` in pieces of ``_PIECE`` digits (Python's own ``str`` of a
    long int is refused beyond ``sys.get_int_max_str_digits()``, 4300 by default)."""
    base = 10**_PIECE
    pieces = []
    while n >= base:
        n, r = divmod(n, base)
        pieces.append(str(r).zfill(_PIECE))
    pieces.append(str(n))
    return "".join(reversed(pieces))


def _integer_text(p: int, q: int, where: str) -> str:
    """``p`` (``q == 1``) or ``p/q`` in decimal, whatever their length up to tribez's limit of
    ``MAX_DIGITS`` digits; a longer number is an InputError with the library's message."""
    # bits first: an int of a billion bits is refused before any digit is counted
    if (p.bit_length() + q.bit_length()) * 30103 // 100000 > 2 * MAX_DIGITS:
        digits = (p.bit_length() + q.bit_length()) * 30103 // 100000
        raise InputError(
            f"{where}: about {digits} digits, above the limit of {MAX_DIGITS} digits for a number"
        )
    digits = _digits(abs(p)) + (0 if q == 1 else _digits(q))
    if digits > MAX_DIGITS:
        raise InputError(f"{where}: {digits} digits, above the limit of {MAX_DIGITS} digits for a number")
    text = ("-" if p < 0 else "") + _decimal(abs(p))
    return text if q == 1 else f"{text}/{_decimal(q)}"


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


def _int_of(digits: str) -> int:
    """The int of a decimal text of any length, in pieces of ``_PIECE`` digits (Python's own
    ``int`` of a long text is refused beyond ``sys.get_int_max_str_digits()``)."""
    neg = digits.startswith("-")
    digits = digits.lstrip("+-")
    n = 0
    for i in range(0, len(digits), _PIECE):
        piece = digits[i:i + _PIECE]
        n = n * 10**len(piece) + int(piece)
    return -n if neg else n


def fraction(text: str) -> Fraction:
    """A Fraction from the library's exact text (``p/q`` or ``p``), of any length (an exact value
    of many digits is not refused by Python's limit on int-from-text conversion)."""
    if len(text) < 4000:
        return Fraction(text)
    p, _, q = text.partition("/")
    return Fraction(_int_of(p), _int_of(q) if q else 1)
