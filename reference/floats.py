"""Exact floats for the reference (named floats.py, not numbers.py, which would shadow the standard
library module `numbers` that `fractions` imports): rounding a Fraction to f64/f32 (ties to even), binade ULPs,
stepping between neighbouring floats, and the texts tribez reads (docs/guide.md §2).

Written from docs/theory.md §14.3-§14.4 with integers only: no value passes through a Python
float on its way to a verdict (Python floats are used only to print a double's shortest text,
and that text is checked to read back exactly).
"""

from fractions import Fraction

# precision name -> (significand bits p, least exponent emin, greatest exponent emax)
FORMATS = {"f64": (53, -1022, 1023), "f32": (24, -126, 127)}
# unit roundoff ε_p (docs/guide.md §7) and the underflow unit η (docs/theory.md §14)
EPS = {"f64": Fraction(1, 2**53), "f32": Fraction(1, 2**24)}
ETA = {"f64": Fraction(1, 2**1075), "f32": Fraction(1, 2**150)}


def floor_log2(q):
    """⌊log2 q⌋ for a Fraction q > 0, from bit lengths (theory §14.4)."""
    a, b = q.numerator, q.denominator
    e = a.bit_length() - b.bit_length()
    if a * 2 ** max(0, -e) < b * 2 ** max(0, e):
        e -= 1
    return e


def ulp(q, prec):
    """Binade ULP of the rational q: 2^(e-p+1) with 2^e <= |q| < 2^(e+1), e clamped to emin;
    ulp(0) is the smallest subnormal."""
    p, emin, _ = FORMATS[prec]
    if q == 0:
        return Fraction(1, 2 ** (p - 1 - emin))
    e = max(floor_log2(abs(Fraction(q))), emin)
    return Fraction(2) ** (e - p + 1)


def rn(q, prec):
    """The float of precision `prec` nearest the rational q, ties to even, as a Fraction
    (theory §14.4, with integers only). Raises OverflowError when it rounds to infinity."""
    q = Fraction(q)
    if q == 0:
        return Fraction(0)
    p, emin, emax = FORMATS[prec]
    a, b = abs(q.numerator), q.denominator
    e = max(floor_log2(Fraction(a, b)), emin)
    # scaled = a / b / 2^(e-p+1) = num / den, split into m + r with 0 <= r < 1
    shift = e - p + 1
    num, den = (a, b << shift) if shift >= 0 else (a << -shift, b)
    m, rem = divmod(num, den)
    if 2 * rem > den or (2 * rem == den and m % 2 == 1):
        m += 1
    if m == 2**p:
        m = 2 ** (p - 1)
        e += 1
        shift += 1
    if e > emax:
        raise OverflowError("rounds to infinity")
    v = Fraction(m << shift) if shift >= 0 else Fraction(m, 1 << -shift)
    return v if q > 0 else -v


def is_float(q, prec):
    try:
        return rn(q, prec) == q
    except OverflowError:
        return False


def key(x, prec):
    """Ordered integer key of a float x (a Fraction that is a float of `prec`): consecutive
    floats have consecutive keys, ±0 maps to 0 (theory §14.4, step distance)."""
    p, emin, _ = FORMATS[prec]
    if x == 0:
        return 0
    a = abs(x)
    tiny = Fraction(2) ** (emin - p + 1)
    if a < Fraction(2) ** emin:
        k = a / tiny
    else:
        e = floor_log2(a)
        f = a / Fraction(2) ** (e - p + 1) - 2 ** (p - 1)
        k = (e - emin) * 2 ** (p - 1) + f + 2 ** (p - 1)
    assert k.denominator == 1, "not a float"
    return int(k) if x > 0 else -int(k)


def from_key(k, prec):
    p, emin, emax = FORMATS[prec]
    if k == 0:
        return Fraction(0)
    a = abs(k)
    if a < 2 ** (p - 1):
        x = a * Fraction(2) ** (emin - p + 1)
    else:
        e = (a - 2 ** (p - 1)) // 2 ** (p - 1) + emin
        f = a - 2 ** (p - 1) - (e - emin) * 2 ** (p - 1)
        if e > emax:
            raise OverflowError("beyond the largest float")
        x = (2 ** (p - 1) + f) * Fraction(2) ** (e - p + 1)
    return x if k > 0 else -x


def step(x, k, prec):
    """The float k steps (nextafter) from the float x."""
    return from_key(key(x, prec) + k, prec)


def frac_text(q):
    """A rational in lowest terms as tribez prints it: "p" or "p/q"."""
    q = Fraction(q)
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


def exact_decimal(q):
    """The exact decimal text of a dyadic rational (every float has one)."""
    q = Fraction(q)
    d = q.denominator
    k = d.bit_length() - 1
    assert d == 2**k, "not dyadic"
    n = abs(q.numerator) * 5**k
    s = str(n).rjust(k + 1, "0")
    text = s if k == 0 else s[:-k] + "." + s[-k:]
    return ("-" if q < 0 else "") + text


def hex_text(q, prec):
    """A C99 hexadecimal float text of the float q (exact)."""
    q = Fraction(q)
    if q == 0:
        return "0x0p+0"
    a = abs(q)
    e = floor_log2(a)
    m = a / Fraction(2) ** e  # in [1, 2)
    bits = 0
    while m.denominator != 1:
        m *= 2
        bits += 1
    # m = integer significand with `bits` fraction bits; write as hex with fraction digits
    mi = m.numerator
    nibbles = (bits + 3) // 4
    mi <<= nibbles * 4 - bits
    head = mi >> (nibbles * 4)
    tail = mi - (head << (nibbles * 4))
    text = "0x%x" % head
    if nibbles:
        text += "." + ("%0*x" % (nibbles, tail))
    return ("-" if q < 0 else "") + text + "p%+d" % e


def float_text(x, prec, style):
    """A text that denotes the float x of `prec` under that precision: 'short' (Python's shortest
    round-trip repr, f64 only), 'hex', 'exact' (exact decimal) or 'frac' (p/q)."""
    x = Fraction(x)
    if style == "short" and prec == "f64":
        t = repr(float(x))
        assert rn(Fraction(t), "f64") == x  # the text denotes x under the precision
        return t
    if style == "hex":
        return hex_text(x, prec)
    if style == "frac":
        return frac_text(x)
    return exact_decimal(x)


def parse(text):
    """The exact value of a number text of docs/guide.md §2 (the forms this program writes:
    integers, p/q, decimals, hex floats)."""
    t = text.strip()
    if t.lower().lstrip("+-").startswith("0x"):
        neg = t.startswith("-")
        body = t.lstrip("+-")[2:]
        mant, _, exp = body.partition("p")
        ip, _, fp = mant.partition(".")
        v = Fraction(int(ip or "0", 16)) + (Fraction(int(fp, 16), 16 ** len(fp)) if fp else 0)
        v *= Fraction(2) ** int(exp or "0")
        return -v if neg else v
    return Fraction(t)
