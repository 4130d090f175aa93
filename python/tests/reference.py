"""An independent exact reference in plain Python fractions (no tribez): multi-indices in the
canonical order, the Bernstein form of a Bézier simplex, and ULP measures of floats.

Used by the tests to derive expected values without the program under test.
"""

from fractions import Fraction
from math import factorial, prod
import math


def multi_indices(m, n):
    """Multi-indices (a_0, ..., a_m), |a| = n, in the canonical order: sorted by the last
    coordinate ascending, then the one before it, and so on (bezier's node order)."""
    if m == 0:
        return [(n,)]
    out = []
    for last in range(n + 1):
        for head in multi_indices(m - 1, n - last):
            out.append(head + (last,))
    return out


def bernstein_value(nodes, degree, lam):
    """p(lam) = sum_a c_a n!/(a_0!...a_m!) prod lam_i^a_i, exactly; nodes in bezier's layout
    (dimension rows, one column per control point in canonical order)."""
    lam = [Fraction(x) for x in lam]
    m = len(lam) - 1
    idx = multi_indices(m, degree)
    dim = len(nodes)
    out = [Fraction(0)] * dim
    for col, a in enumerate(idx):
        b = Fraction(factorial(degree), prod(factorial(x) for x in a)) * prod(
            l**e for l, e in zip(lam, a)
        )
        for i in range(dim):
            out[i] += Fraction(nodes[i][col]) * b
    return out


def ulp(q, mant_bits=53, emin=-1022):
    """ulp of the binade of the exact value q (2^(e - p + 1), e = floor(log2|q|), at least the
    subnormal spacing)."""
    q = abs(Fraction(q))
    if q == 0:
        return Fraction(2) ** (emin - mant_bits + 1)
    e = q.numerator.bit_length() - q.denominator.bit_length()
    if Fraction(2) ** e > q:
        e -= 1
    e = max(e, emin)
    return Fraction(2) ** (e - mant_bits + 1)


def ulps_error(x, q):
    """|x - q| / ulp(q)."""
    return abs(Fraction(x) - Fraction(q)) / ulp(q)


def correctly_rounded(q):
    """The double nearest q (ties to even), computed with fractions only."""
    q = Fraction(q)
    x = float(q)  # Fraction.__float__ is correctly rounded (integer division, round-half-even)
    return x


def next_up(x):
    return math.nextafter(x, math.inf)
