"""Exact numbers a + b·√D (a, b rational, D a positive integer that is not a square): the
irrational answers of the reference's quadratic locate claims, with exact signs and
comparisons, and the verdicts of guide §6's tolerances against them. Standard library only."""

from fractions import Fraction as F
from math import isqrt

import floats


class Quad:
    """a + b·√D, exactly; D > 0 is not a perfect square, so the number is rational only when
    b = 0."""

    __slots__ = ("a", "b", "D")

    def __init__(self, a, b, D):
        assert D > 0 and isqrt(D) ** 2 != D, "D must not be a square"
        self.a, self.b, self.D = F(a), F(b), D

    def _lift(self, x):
        if isinstance(x, Quad):
            assert x.D == self.D, "numbers of two fields"
            return x
        return Quad(x, 0, self.D)

    def __add__(self, x):
        x = self._lift(x)
        return Quad(self.a + x.a, self.b + x.b, self.D)

    __radd__ = __add__

    def __neg__(self):
        return Quad(-self.a, -self.b, self.D)

    def __sub__(self, x):
        return self + (-self._lift(x))

    def __rsub__(self, x):
        return self._lift(x) - self

    def __mul__(self, x):
        x = self._lift(x)
        return Quad(self.a * x.a + self.b * x.b * self.D, self.a * x.b + self.b * x.a, self.D)

    __rmul__ = __mul__

    def sign(self):
        """The sign of a + b√D, exactly: when a and b disagree in sign, compare a² with b²D."""
        sa = (self.a > 0) - (self.a < 0)
        sb = (self.b > 0) - (self.b < 0)
        if sb == 0:
            return sa
        if sa == 0 or sa == sb:
            return sb
        return sa if self.a * self.a > self.b * self.b * self.D else sb

    def __eq__(self, x):
        return (self - x).sign() == 0

    def __lt__(self, x):
        return (self - x).sign() < 0

    def __le__(self, x):
        return (self - x).sign() <= 0

    def __gt__(self, x):
        return (self - x).sign() > 0

    def __ge__(self, x):
        return (self - x).sign() >= 0

    __hash__ = None

    def bracket(self, bits=240):
        """Rationals lo < self < hi with hi - lo ≤ |b|·2^-bits·2 (√D between two integers over
        2^bits)."""
        r = isqrt(self.D << (2 * bits))  # r ≤ √D·2^bits < r + 1
        lo_root, hi_root = F(r, 2**bits), F(r + 1, 2**bits)
        ends = [self.a + self.b * lo_root, self.a + self.b * hi_root]
        return min(ends), max(ends)

    def approx(self):
        """A rational within 2^-239·|b| of the number (the midpoint of its bracket)."""
        lo, hi = self.bracket()
        return (lo + hi) / 2

    def __repr__(self):
        return "Quad(%s + %s√%d)" % (self.a, self.b, self.D)


def abs_q(x):
    return x if x.sign() >= 0 else -x


def within(y, x, v):
    """|y - x| ≤ v exactly, for a rational y and v ≥ 0."""
    return x >= F(y) - v and x <= F(y) + v


def binade_ulp(x, prec):
    """ulp(x) in `prec` for an irrational x: the binade of both ends of its bracket (they agree
    unless x is within 2^-239 of a power of two; then None)."""
    lo, hi = x.bracket()
    ul, uh = floats.ulp(lo, prec), floats.ulp(hi, prec)
    return ul if ul == uh else None


def rounded(x, prec):
    """RN(x) in `prec`: the rounding of both ends of the bracket (RN is monotone, so RN(x) is
    theirs when they agree; an irrational is never a midpoint, so they agree unless x is within
    2^-239 of one: then None)."""
    lo, hi = x.bracket()
    a, b = floats.rn(lo, prec), floats.rn(hi, prec)
    return a if a == b else None


def faithful(x, prec):
    """The two floats of `prec` around the irrational x (it is never a float), or None when
    the bracket straddles a float."""
    lo, hi = x.bracket()
    below = floats.rn(lo, prec)
    if below > lo:
        below = floats.step(below, -1, prec)
    above = floats.step(below, 1, prec)
    if not (below < lo and hi < above):
        return None
    return (below, above)


def judge(y, x, kind, v, prec):
    """The verdict of claimed rational y against the irrational x at tolerance `kind` (with
    parameter v), decided exactly; None where the bracket of x cannot decide (x within 2^-239
    of a binade edge or a rounding boundary: the caller draws another case)."""
    y = F(y)
    if kind == "exact":
        return False  # a rational is never irrational
    if kind == "abs":
        return within(y, x, v)
    if kind == "rel":
        # |y - x| ≤ v|x| ⟺ x(1 - v s) ≤ y ≤ x(1 + v s) for s the sign of x
        s = x.sign()
        return (x * (1 - v * s) - y).sign() <= 0 and (x * (1 + v * s) - y).sign() >= 0
    if kind == "ulps":
        u = binade_ulp(x, prec)
        return None if u is None else within(y, x, v * u)
    if kind == "correctly_rounded":
        r = rounded(x, prec)
        return None if r is None else y == r
    if kind == "faithful":
        pair = faithful(x, prec)
        return None if pair is None else y in pair
    raise ValueError("tolerance %s against an irrational value" % kind)
