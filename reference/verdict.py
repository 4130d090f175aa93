"""Tolerances as docs/guide.md §7 defines them, judged exactly.

judge(y, q, tol, prec, cond=None, bound=None) -> bool for one coordinate: y the claimed value
(already the float its text denotes when there is a precision), q the exact value (at the inputs
as the code saw them), tol a tolerance text, prec "f64"/"f32"/None, cond the condition number
Σ|c_α| B_α(|λ|) of that coordinate (for cond=K), bound the proven a-priori bound (for `bound`).
"""

from fractions import Fraction

import floats


def parse_tolerance(tol):
    """'ulps=3' -> ('ulps', Fraction(3)); 'exact' -> ('exact', None)."""
    kind, _, value = tol.partition("=")
    return kind, (floats.parse(value) if value else None)


def faithful_pair(q, prec):
    """The floats that bracket q (q itself when it is a float)."""
    r = floats.rn(q, prec)
    if r == q:
        return {r}
    return {r, floats.step(r, 1 if r < q else -1, prec)}


def judge(y, q, tol, prec, cond=None, bound=None, K_default=None):
    kind, v = parse_tolerance(tol)
    err = abs(Fraction(y) - Fraction(q))
    if kind == "exact":
        return err == 0
    if kind == "abs":
        return err <= v
    if kind == "rel":
        return err <= v * abs(q)
    if kind == "ulps":
        return err <= v * floats.ulp(q, prec)
    if kind == "correctly_rounded":
        return y == floats.rn(q, prec)
    if kind == "faithful":
        return y in faithful_pair(q, prec)
    if kind == "cond":
        K = v if v is not None else K_default
        return err <= K * floats.EPS[prec] * cond
    if kind == "bound":
        return err <= bound
    raise ValueError("unknown tolerance " + tol)


def gamma(k, prec):
    e = floats.EPS[prec]
    return k * e / (1 - k * e)


def casteljau_bound(cond, m, n, s, prec):
    """γ_{(m+1)n} Σ|c_α| B_α(|λ|) + 2(m+1)η Σ_{j<n} s^j, s = Σ|λ_k| (theory §14.1)."""
    under = 2 * (m + 1) * floats.ETA[prec] * sum(Fraction(s) ** j for j in range(n))
    return gamma((m + 1) * n, prec) * cond + under


def bernstein_bound(cond, m, n, N, prec):
    """γ_{N+n+m+2} Σ|c_α| B_α(|λ|), N the number of terms (theory §14.1)."""
    return gamma(N + n + m + 2, prec) * cond
