"""Exact Bézier simplices in Fractions, written from docs/theory.md §0-§12.

A patch is a dict with keys
  n        the degree (the depth of an S-patch)
  m        the simplex dimension (N-1 for an S-patch over an N-gon)
  points   {multi-index tuple: [Fraction, ...]}   (d coordinates each)
  weights  {multi-index tuple: Fraction} or None  (a rational patch, theory §10)
  domain   [[Fraction]*m]*(m+1) or None            (default: the reference simplex)
  polygon  [[x, y]]*N or None                      (an S-patch, theory §12)
Multi-index part k belongs to vertex k; barycentric points have m+1 coordinates.
"""

from fractions import Fraction
from math import factorial


def indices(n, m):
    """All multi-indices of degree n in N^(m+1), in canonical order (theory §1): ascending in the
    last part, then the one before it, ...; the first part is implied."""
    if m == 0:
        return [(n,)]
    out = []
    for last in range(n + 1):
        for head in indices(n - last, m - 1):
            out.append(head + (last,))
    return out


def key_text(alpha):
    return ",".join(str(a) for a in alpha)


_MULTI = {}


def multinomial(alpha):
    if alpha in _MULTI:
        return _MULTI[alpha]
    r = factorial(sum(alpha))
    for a in alpha:
        r //= factorial(a)
    _MULTI[alpha] = r
    return r


def bernstein(alpha, lam):
    """B^n_alpha(lam) = n!/(alpha!) prod lam_k^alpha_k (the homogeneous form)."""
    r = Fraction(multinomial(alpha))
    for a, x in zip(alpha, lam):
        r *= Fraction(x) ** a
    return r


def unit(m, k):
    return tuple(1 if i == k else 0 for i in range(m + 1))


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def blossom_net(net, n, m, args):
    """de Casteljau with argument args[r] at level r (theory §4) on a net {alpha: vector};
    returns the apex vector. With every argument equal it is the homogeneous evaluation (§3)."""
    level = dict(net)
    for r, x in enumerate(args):
        deg = n - r - 1
        new = {}
        for alpha in indices(deg, m):
            acc = None
            for k in range(m + 1):
                v = level[add(alpha, unit(m, k))]
                term = [x[k] * c for c in v]
                acc = term if acc is None else [p + q for p, q in zip(acc, term)]
            new[alpha] = acc
        level = new
    return level[tuple([0] * (m + 1))]


def homogeneous_net(patch):
    """(w c, w) for a rational patch, c for a polynomial one."""
    if patch.get("weights") is None:
        return patch["points"]
    return {a: [patch["weights"][a] * c for c in v] + [patch["weights"][a]] for a, v in patch["points"].items()}


def project(v, rational):
    if not rational:
        return v
    w = v[-1]
    if w == 0:
        raise ZeroDivisionError("weight blossom vanishes")
    return [x / w for x in v[:-1]]


def evaluate(patch, lam):
    """p(lam), lam barycentric (homogeneous form: lam need not sum to 1)."""
    lam = [Fraction(x) for x in lam]
    net = homogeneous_net(patch)
    v = blossom_net(net, patch["n"], patch["m"], [lam] * patch["n"]) if patch["n"] > 0 else net[tuple([0] * (patch["m"] + 1))]
    return project(v, patch.get("weights") is not None)


def blossom(patch, args):
    net = homogeneous_net(patch)
    return project(blossom_net(net, patch["n"], patch["m"], [[Fraction(x) for x in a] for a in args]), patch.get("weights") is not None)


def det(rows):
    """Determinant of a square matrix of Fractions (Gaussian elimination)."""
    a = [list(map(Fraction, r)) for r in rows]
    n = len(a)
    d = Fraction(1)
    for i in range(n):
        p = next((r for r in range(i, n) if a[r][i] != 0), None)
        if p is None:
            return Fraction(0)
        if p != i:
            a[i], a[p] = a[p], a[i]
            d = -d
        d *= a[i][i]
        for r in range(i + 1, n):
            f = a[r][i] / a[i][i]
            for c in range(i, n):
                a[r][c] -= f * a[i][c]
    return d


def reference_domain(m):
    """Default domain: for triangles (1,0), (0,1), (0,0) (so u = x, v = y, w = 1 - x - y); in
    general the unit vectors then the origin."""
    return [[Fraction(1 if i == k else 0) for i in range(m)] for k in range(m)] + [[Fraction(0)] * m]


def cramer(domain, rhs_head, point):
    """Solve sum_k u_k = rhs_head, sum_k u_k a_k = point by Cramer's rule (theory §2)."""
    m = len(domain) - 1
    cols = [[Fraction(1)] + list(v) for v in domain]
    b = [Fraction(rhs_head)] + [Fraction(x) for x in point]
    mat = lambda cs: [[cs[c][r] for c in range(m + 1)] for r in range(m + 1)]
    D = det(mat(cols))
    if D == 0:
        raise ValueError("degenerate domain")
    return [det(mat(cols[:k] + [b] + cols[k + 1:])) / D for k in range(m + 1)]


def barycentric(domain, point):
    return cramer(domain, 1, point)


def directional(domain, vector):
    return cramer(domain, 0, vector)


def domain_of(patch):
    return patch.get("domain") or reference_domain(patch["m"])


# --- S-patches (theory §12) ---

def signed_area(a, b, c):
    return ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2


def wachspress(polygon, p):
    """λ_i = ω_i/Σω, ω_i = C_i Π_{j ∉ {i-1, i}} A_j(p) (theory §12)."""
    N = len(polygon)
    A = [signed_area(p, polygon[j], polygon[(j + 1) % N]) for j in range(N)]
    C = [signed_area(polygon[i - 1], polygon[i], polygon[(i + 1) % N]) for i in range(N)]
    w = []
    for i in range(N):
        r = C[i]
        for j in range(N):
            if j != (i - 1) % N and j != i:
                r *= A[j]
        w.append(r)
    s = sum(w)
    return [x / s for x in w]


def inside_polygon(polygon, p):
    N = len(polygon)
    return all(signed_area(p, polygon[j], polygon[(j + 1) % N]) > 0 for j in range(N))


# --- constructions ---

def subpatch(patch, verts):
    """c'_alpha = b[f_0^alpha_0, ..., f_m^alpha_m] (theory §4); polynomial patches."""
    n, m = patch["n"], patch["m"]
    out = {}
    for alpha in indices(n, m):
        args = []
        for k, a in enumerate(alpha):
            args += [verts[k]] * a
        out[alpha] = blossom(patch, args) if n > 0 else patch["points"][alpha]
    return out


def elevate(patch, by):
    """Degree elevation by `by` steps: the subpatch identity c'_beta = sum over alpha <= beta of
    C(n; alpha) C(r; beta - alpha) / C(n + r; beta) c_alpha (theory §6, all steps at once)."""
    n, m = patch["n"], patch["m"]
    out = {}
    for beta in indices(n + by, m):
        acc = None
        for alpha in indices(n, m):
            gamma = tuple(b - a for a, b in zip(alpha, beta))
            if min(gamma) < 0:
                continue
            f = Fraction(multinomial(alpha) * multinomial(gamma), multinomial(beta))
            term = [f * c for c in patch["points"][alpha]]
            acc = term if acc is None else [x + y for x, y in zip(acc, term)]
        out[beta] = acc
    return out


def derivative(patch, lam, dirs):
    """n!/(n-r)! b[d_1, ..., d_r, lam^(n-r)] (theory §7), polynomial patches."""
    n, r = patch["n"], len(dirs)
    if r > n:
        return [Fraction(0)] * len(next(iter(patch["points"].values())))
    v = blossom_net(patch["points"], n, patch["m"], [list(map(Fraction, d)) for d in dirs] + [list(map(Fraction, lam))] * (n - r))
    f = factorial(n) // factorial(n - r)
    return [f * x for x in v]


def edge_curve(patch, i, j):
    """Control points of t -> p((1-t) e_i + t e_j), corners 1-based: c_{(n-q) e_i + q e_j}."""
    n, m = patch["n"], patch["m"]
    out = []
    for q in range(n + 1):
        alpha = [0] * (m + 1)
        alpha[i - 1] += n - q
        alpha[j - 1] += q
        out.append(patch["points"][tuple(alpha)])
    return out


def cramer_3(M, rhs):
    """Solve the square system M x = rhs (rows of M) by Cramer's rule."""
    n = len(M)
    D = det(M)
    return [det([[rhs[i] if c == k else M[i][c] for c in range(n)] for i in range(n)]) / D for k in range(n)]
