"""Random cases from a seed: patch files, claim files and `check --results` batches, each with the
answer and the verdict the reference computes for it (docs/guide.md §3, §6, §7, §8).

Every generated claim carries `expected`: {"verdict": "passed"|"FAILED", "exact": [...] or None,
"kind": a short category used by the expected-failures list}.
"""

import random
from fractions import Fraction as F

import bezier as bz
import floats
import quadratic
from quadratic import Quad
from verdict import bernstein_bound, casteljau_bound, judge, parse_tolerance


def rational_parts(sols):
    """Solutions with every irrational coordinate (quadratic.Quad) that has no irrational part
    written as the rational it is."""
    return [tuple(F(q.a) if isinstance(q, Quad) and q.b == 0 else q for q in s) for s in sols]


def paired(y, q):
    """A claimed coordinate y pairs with the exact q when |y - q| ≤ 2^-20 max(1, |q|) (guide
    §6), decided exactly for a rational or an irrational q."""
    if not isinstance(q, Quad):
        return abs(y - q) <= F(1, 2**20) * max(1, abs(q))
    if quadratic.abs_q(q) >= 1:
        return quadratic.judge(y, q, "rel", F(1, 2**20), None)
    return quadratic.within(y, q, F(1, 2**20))


def judge_any(y, q, tol, prec):
    """`judge` for a rational q; for an irrational one (quadratic.Quad), its exact verdict."""
    if not isinstance(q, Quad):
        return judge(y, q, tol, prec)
    kind, v = parse_tolerance(tol)
    verdict = quadratic.judge(y, q, kind, v, prec)
    assert verdict is not None, "the bracket of %r cannot decide %s" % (q, tol)
    return verdict

PRECS = ["f64", "f32"]

# Domains whose vertices are floats in both precisions, so that "the Cartesian point rounded,
# then converted exactly" is the only rounding a Cartesian input sees. The first one is the
# domain of issue 35 §1, where most points have barycentric coordinates that are not floats.
DOMAINS2 = [
    [[0, 0], [3, 0], [0, 3]],
    [[1, 2], [7, 3], [2, 8]],  # Floater's triangle, theory §2
    [[0, 0], [5, 0], [0, 7]],
    [[-1, 0], [2, -1], [1, 3]],
    [[0, 0], [1, 0], [0, 1]],
]
DOMAINS1 = [[[0], [3]], [[-1], [6]], [[2], [-5]]]
DOMAINS3 = [[[0, 0, 0], [3, 0, 0], [0, 3, 0], [0, 0, 3]], [[1, 0, 0], [0, 5, 0], [0, 0, 7], [1, 1, 1]]]
# strictly convex, counter-clockwise, integer vertices (S-patches, theory §12)
POLYGONS = [
    [[0, 0], [4, 0], [5, 3], [2, 5], [-1, 3]],
    [[0, 0], [3, 0], [3, 3], [0, 3]],
    [[0, 0], [5, 1], [1, 4]],
    [[1, 0], [1, 1], [0, 1], [-1, 0], [-1, -1], [0, -1]],
]


class Gen:
    def __init__(self, rng):
        self.r = rng
        self.good = False  # when set, every claimed value is the exact or correctly rounded one

    def new_claim(self):
        """Start a claim: about 40% of claims claim only correct values (exact or correctly
        rounded), the rest mix correct, nearly correct and wrong values."""
        self.good = self.r.random() < 0.4

    # --- numbers -------------------------------------------------------------------------
    def num_text(self, big=False):
        """A random number text and its exact value: integers, p/q, short decimals, exponents."""
        r = self.r
        c = r.random()
        if c < 0.3:
            t = str(r.randint(-9, 9))
        elif c < 0.6:
            t = "%d/%d" % (r.randint(-20, 20), r.choice([2, 3, 4, 5, 6, 7, 9, 10, 11, 12]))
        elif c < 0.85:
            t = "%s%d.%s" % (r.choice(["", "-"]), r.randint(0, 5), "".join(r.choice("0123456789") for _ in range(r.randint(1, 4))))
        elif c < 0.95:
            t = "%s%de-%d" % (r.choice(["", "-"]), r.randint(1, 99), r.randint(1, 3))
        else:
            x = F(r.randint(-2**20, 2**20), 2 ** r.randint(0, 20))
            t = floats.hex_text(x, "f64") if x != 0 else "0"
        return t, floats.parse(t)

    def float_text(self, x, prec):
        styles = ["hex", "exact", "frac"] + (["short"] * 4 if prec == "f64" else [])
        return floats.float_text(x, prec, self.r.choice(styles))

    # --- patches -------------------------------------------------------------------------
    def patch(self, kind=None, m=None, d=None):
        """A random patch: (reference dict, file dict). kind: bezier, rational, spatch."""
        r = self.r
        kind = kind or r.choice(["bezier"] * 6 + ["rational"] * 2 + ["spatch", "functional"])
        f = {}
        if kind == "functional":  # one ordinate per control point over a triangle (theory §13)
            m, d = 2, 1
            f["kind"] = "functional"
        if kind == "spatch":
            poly = r.choice(POLYGONS)
            n = r.randint(1, 2)
            m = len(poly) - 1
            f["polygon"] = [[str(x) for x in v] for v in poly]
        else:
            m = m if m is not None else r.choice([1, 2, 2, 2, 2, 3])
            n = r.randint(1, 4 if m < 3 else 3)
            if kind == "rational":
                n = min(n, 3)
        d = d if d is not None else r.choice([1, 2, 3])
        pts, texts = {}, {}
        for alpha in bz.indices(n, m):
            vals = [self.num_text() for _ in range(d)]
            texts[alpha] = [t for t, _ in vals]
            pts[alpha] = [v for _, v in vals]
        f["degree"] = n
        f["control_points"] = {bz.key_text(a): texts[a] for a in bz.indices(n, m)}
        P = {"n": n, "m": m, "d": d, "kind": kind, "points": pts, "texts": texts, "weights": None, "domain": None, "polygon": None}
        if kind == "rational":
            wt = {}
            for alpha in bz.indices(n, m):
                t = r.choice(["1", "2", "3", "1/2", "3/2", "0.3", "5/3", "7"])
                wt[alpha] = floats.parse(t)
                f.setdefault("weights", {})[bz.key_text(alpha)] = t
            P["weights"] = wt
        if kind == "spatch":
            P["polygon"] = [[F(x) for x in v] for v in poly]
        elif r.random() < 0.6 or kind == "functional":
            dom = r.choice({1: DOMAINS1, 2: DOMAINS2, 3: DOMAINS3}[m])
            if r.random() < 0.3:  # vertices in another order
                dom = dom[:]
                r.shuffle(dom)
            P["domain"] = [[F(x) for x in v] for v in dom]
            f["domain"] = [[str(x) for x in v] for v in dom]
        return P, f

    def rounded(self, P, prec):
        """The patch as float code saw it: control points (for a rational patch the homogeneous
        net (w c, w)) rounded once to prec (guide §5 eval --float, §7)."""
        Q = dict(P)
        if P["weights"] is None:
            Q["points"] = {a: [floats.rn(x, prec) for x in v] for a, v in P["points"].items()}
        else:
            # keep the rounded homogeneous net as the net; evaluate() takes weights*points
            Q["weights"] = {a: floats.rn(w, prec) for a, w in P["weights"].items()}
            Q["points"] = {a: [floats.rn(P["weights"][a] * x, prec) / Q["weights"][a] for x in v] for a, v in P["points"].items()}
        return Q

    # --- points --------------------------------------------------------------------------
    def bary_exact(self, m, inside=True):
        """Random rational barycentric coordinates summing to 1."""
        r = self.r
        while True:
            den = r.choice([2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 30, 100])
            parts = [r.randint(0 if inside else -den // 2, den) for _ in range(m)]
            last = den - sum(parts)
            if inside and last < 0:
                continue
            return [F(p, den) for p in parts] + [F(last, den)]

    def dec_text(self, x, digits):
        """x written as a decimal with `digits` significant digits (rounded half even by str)."""
        return "%.*g" % (digits, float(x)) if x != 0 else "0"

    def point_text(self, x, prec):
        """A text for an input coordinate x: exact (p/q), a short decimal, or 17 digits."""
        c = self.r.random()
        if prec is None or c < 0.3:
            return floats.frac_text(x)
        if c < 0.6:
            return self.dec_text(x, self.r.choice([1, 2, 3]))
        return self.dec_text(x, 17 if prec == "f64" else 9)

    def cart_point(self, P):
        """A Cartesian point (exact) inside the domain / polygon."""
        if P["polygon"] is not None:
            poly = P["polygon"]
            while True:
                ws = [F(self.r.randint(1, 9)) for _ in poly]
                s = sum(ws)
                p = [sum(w * v[i] for w, v in zip(ws, poly)) / s for i in range(2)]
                if bz.inside_polygon(poly, p):
                    return p
        dom = bz.domain_of(P)
        lam = self.bary_exact(P["m"], inside=P["weights"] is not None or self.r.random() < 0.8)
        if self.r.random() < 0.3:  # a simple point: small integers or halves
            lam = self.bary_exact(P["m"])
        return [sum(l * v[i] for l, v in zip(lam, dom)) for i in range(P["m"])]

    # --- claimed values ------------------------------------------------------------------
    def claimed_float(self, q, prec):
        """A claimed float near q: correctly rounded, the other neighbour, k steps off, or wrong."""
        r = self.r
        c = 0 if self.good else r.random()
        rq = floats.rn(q, prec)
        if c < 0.35:
            y = rq
        elif c < 0.5:
            y = floats.step(rq, 1 if rq < q else -1, prec) if rq != q else floats.step(rq, r.choice([-1, 1]), prec)
        elif c < 0.8:
            y = floats.step(rq, r.choice([-3, -2, -1, 1, 2, 3]), prec)
        elif c < 0.9:
            y = floats.step(rq, r.choice([-1, 1]) * r.randint(4, 300), prec)
        else:
            y = floats.rn(q + F(r.randint(-100, 100), r.choice([7, 100, 1000])), prec)
        if r.random() < 0.15:  # written as a longer decimal or as p/q, rounded by the reader
            t = floats.frac_text(q) if r.random() < 0.5 else self.dec_text(y, 17 if prec == "f64" else 9)
            return t, floats.rn(floats.parse(t), prec)
        return self.float_text(y, prec), y

    def claimed_exact(self, q):
        r = self.r
        c = 0 if self.good else r.random()
        if c < 0.5:
            y = q
        elif c < 0.7:
            y = q + F(r.choice([-1, 1]), r.choice([10**6, 10**12, 3 * 10**9, 2**40]))
        elif c < 0.85:
            t = self.dec_text(q, r.choice([6, 12, 17]))
            return t, floats.parse(t)
        else:
            y = q + F(r.randint(-50, 50), r.choice([1, 7, 100]))
        return floats.frac_text(y), y

    def tolerance(self, prec, ys, qs, conds=None, bound=None, kinds=None):
        """A tolerance text: a random kind, with a parameter that is either typical or exactly at
        (or just inside) the largest error of the claimed values, so both sides of a boundary are
        exercised."""
        r = self.r
        if kinds is None:
            kinds = ["exact", "abs", "rel"] + (["ulps", "correctly_rounded", "faithful"] * 2 if prec else [])
            if prec and conds is not None:
                kinds += ["cond", "condK", "condK"]
            if prec and bound is not None:
                kinds += ["bound", "bound"]
        kind = r.choice(kinds)
        errs = [abs(y - q) for y, q in zip(ys, qs)]
        at_edge = r.random() < 0.5
        shrink = F(1) if r.random() < 0.5 else F(2**30 - 1, 2**30)

        def edge(vals, typical):
            vals = [v for v in vals if v is not None]
            if at_edge and vals and max(vals) > 0:
                return floats.frac_text(max(vals) * shrink)
            return typical

        if kind in ("exact", "correctly_rounded", "faithful", "bound", "cond"):
            return kind
        if kind == "abs":
            return "abs=" + edge(errs, r.choice(["1e-15", "1e-6", "1/1000", "0", "1e-300"]))
        if kind == "rel":
            return "rel=" + edge([e / abs(q) if q != 0 else None for e, q in zip(errs, qs)], r.choice(["1e-16", "1e-7", "2e-16", "0"]))
        if kind == "ulps":
            return "ulps=" + edge([e / floats.ulp(q, prec) for e, q in zip(errs, qs)], r.choice(["0", "1/2", "1", "2", "3", "16", "0.75"]))
        if kind == "condK":
            eps = floats.EPS[prec]
            return "cond=" + edge([e / (eps * c) if c else None for e, c in zip(errs, conds)], r.choice(["0", "1", "3", "9", "1/2"]))
        raise AssertionError(kind)

    # --- eval claims ---------------------------------------------------------------------
    def eval_claim(self, P, cid):
        r = self.r
        prec = r.choice([None, "f64", "f64", "f32"])
        self.new_claim()
        claim = {"id": cid, "op": "eval", "source": "reference"}
        spatch = P["polygon"] is not None
        use_cart = spatch or r.random() < 0.5
        info = {"op": "eval", "input": "cartesian" if use_cart else "at", "precision": prec, "patch_kind": P["kind"]}
        if use_cart:
            p = self.cart_point(P)
            texts = [self.point_text(x, prec) for x in p]
            claim["cartesian"] = texts
            seen_p = [floats.parse(t) for t in texts]
            if prec:
                seen_p = [floats.rn(x, prec) for x in seen_p]
        else:
            lam = self.bary_exact(P["m"], inside=P["weights"] is not None or r.random() < 0.8)
            texts = [self.point_text(x, prec) for x in lam]
            vals = [floats.parse(t) for t in texts]
            if prec is None and sum(vals) != 1:
                texts = [floats.frac_text(x) for x in lam]
                vals = lam
            claim["at"] = texts
            seen_lam = [floats.rn(x, prec) for x in vals] if prec else vals
        Q = self.rounded(P, prec) if prec else P
        if spatch:
            if prec and not bz.inside_polygon(P["polygon"], seen_p):
                return None
            seen_lam = bz.wachspress(P["polygon"], seen_p)
        elif use_cart:
            seen_lam = bz.barycentric(bz.domain_of(P), seen_p)
        info["lam_floats"] = all(floats.is_float(x, prec) for x in seen_lam) if prec else None
        qs = bz.evaluate(Q, seen_lam)
        conds, bound = None, None
        algorithm = None
        if prec and not spatch:
            al = [abs(x) for x in seen_lam]
            if P["weights"] is None:
                conds = [sum(abs(Q["points"][a][i]) * bz.bernstein(a, al) for a in bz.indices(P["n"], P["m"])) for i in range(P["d"])]
                algorithm = r.choice([None, "casteljau", "bernstein"])
                if algorithm == "bernstein":
                    N = len(bz.indices(P["n"], P["m"]))
                    bound = [bernstein_bound(c, P["m"], P["n"], N, prec) for c in conds]
                else:
                    bound = [casteljau_bound(c, P["m"], P["n"], sum(al), prec) for c in conds]
            else:
                # rational: homogeneous net (w c, w) as seen; theory §14.1: de Casteljau's bound
                # (γ_K Σ|·|B(|λ|) plus its underflow term) on numerator and denominator, then
                # |ŷ − q| ≤ E_1 + ε(|q| + E_1) + η with E_1 = (e_N + |q| e_D)/(|D| − e_D)
                hn = {a: [Q["weights"][a] * x for x in Q["points"][a]] for a in Q["points"]}
                SW = sum(abs(Q["weights"][a]) * bz.bernstein(a, al) for a in hn)
                D = sum(Q["weights"][a] * bz.bernstein(a, seen_lam) for a in hn)
                eps = floats.EPS[prec]
                conds, bound = [], []
                for i in range(P["d"]):
                    SX = sum(abs(hn[a][i]) * bz.bernstein(a, al) for a in hn)
                    conds.append((SX + abs(qs[i]) * SW) / abs(D))
                    # e_N, e_D: de Casteljau's bound on each net, with its underflow term
                    eN = casteljau_bound(SX, P["m"], P["n"], sum(al), prec)
                    eD = casteljau_bound(SW, P["m"], P["n"], sum(al), prec)
                    if abs(D) <= eD:
                        bound = None
                        break
                    E1 = (eN + abs(qs[i]) * eD) / (abs(D) - eD)
                    bound.append(E1 + eps * (abs(qs[i]) + E1) + floats.ETA[prec])
        ys, ytexts = [], []
        for q in qs:
            t, y = self.claimed_float(q, prec) if prec else self.claimed_exact(q)
            ytexts.append(t)
            ys.append(y)
        if bound is not None:
            # a bound is per coordinate; for the edge parameter use the bound itself
            pass
        tol = self.tolerance(prec, ys, qs, conds=conds, bound=bound)
        if tol == "bound" and algorithm:
            claim["algorithm"] = algorithm
        if prec:
            claim["precision"] = prec
        if tol != "exact" or r.random() < 0.5:
            claim["tolerance"] = tol
        claim["expect"] = ytexts
        K_default = (P["m"] + 1) * P["n"]
        ok = all(judge(y, q, tol, prec, cond=conds[i] if conds else None, bound=bound[i] if bound else None, K_default=K_default) for i, (y, q) in enumerate(zip(ys, qs)))
        info["tolerance"] = tol.split("=")[0]
        return claim, {"verdict": "passed" if ok else "FAILED", "exact": [floats.frac_text(q) for q in qs],
                       "claimed": [floats.frac_text(y) for y in ys], "info": info}


# --- the other claim operations (exact values; guide §6) ------------------------------------

def rational_derivative(P, lam, dirs):
    """D_S p by Leibniz's rule on X = p W (theory §10): D_S p = (D_S X - Σ_{T ⊊ S} D_T p D_{S∖T} W)/W,
    over subsets in increasing size; D_T of the nets by the blossom (theory §4, §7)."""
    n, m = P["n"], P["m"]
    hn = bz.homogeneous_net(P)
    r = len(dirs)

    def dnet(T):  # D_T of the homogeneous polynomial (X, W), |T| <= n, else 0
        k = len(T)
        if k > n:
            return [F(0)] * (P["d"] + 1)
        from math import factorial
        v = bz.blossom_net(hn, n, m, [dirs[i] for i in T] + [lam] * (n - k))
        f = factorial(n) // factorial(n - k)
        return [f * x for x in v]

    from itertools import combinations
    W = dnet(())[-1]
    memo = {}
    for size in range(r + 1):
        for S in combinations(range(r), size):
            XS = dnet(S)[:-1]
            acc = list(XS)
            for tsize in range(size):
                for T in combinations(S, tsize):
                    rest = tuple(i for i in S if i not in T)
                    dw = dnet(rest)[-1]
                    acc = [a - memo[T][i] * dw for i, a in enumerate(acc)]
            memo[S] = [a / W for a in acc]
    return memo[tuple(range(r))]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


class OpsGen(Gen):
    """Claims of the operations other than eval, judged with exact, abs= or rel= tolerances on
    exact inputs (a precision is given only where every input is a float already)."""

    def numbers_claim(self, claim, qs, info, prec=None):
        """Claimed values for a flat list of exact numbers qs, a tolerance, and the verdict."""
        ys, texts = [], []
        for q in qs:
            t, y = self.claimed_float(q, prec) if prec else self.claimed_exact(q)
            ys.append(y)
            texts.append(t)
        tol = self.tolerance(prec, ys, qs)
        if prec:
            claim["precision"] = prec
        if tol != "exact" or self.r.random() < 0.5:
            claim["tolerance"] = tol
        ok = all(judge(y, q, tol, prec) for y, q in zip(ys, qs))
        info["tolerance"] = tol.split("=")[0]
        return texts, ok

    def shape(self, texts, lengths):
        out, i = [], 0
        for L in lengths:
            out.append(texts[i:i + L])
            i += L
        return out

    def op_claim(self, P, cid, op):
        r = self.r
        n, m, d = P["n"], P["m"], P["d"]
        self.new_claim()
        claim = {"id": cid, "op": op, "source": "reference"}
        info = {"op": op, "patch_kind": P["kind"], "precision": None}
        rational = P["weights"] is not None
        if op == "blossom":
            # outside the simplex only for polynomial patches: a rational blossom is undefined
            # where the weight blossom W vanishes, which positive weights exclude only inside
            args = [self.bary_exact(m, inside=rational or r.random() < 0.7) for _ in range(n)]
            claim["args"] = [[floats.frac_text(x) for x in a] for a in args]
            qs = bz.blossom(P, args)
            texts, ok = self.numbers_claim(claim, qs, info)
            claim["expect"] = texts
        elif op == "subpatch":
            while True:
                verts = [self.bary_exact(m, inside=r.random() < 0.8) for _ in range(m + 1)]
                if bz.det([[F(1)] + v[1:] for v in verts]) != 0:
                    break
            claim["vertices"] = [[floats.frac_text(x) for x in v] for v in verts]
            net = bz.subpatch(P, verts)
            keys = bz.indices(n, m)
            texts, ok = self.numbers_claim(claim, [x for a in keys for x in net[a]], info)
            claim["expect"] = {bz.key_text(a): t for a, t in zip(keys, self.shape(texts, [d] * len(keys)))}
            qs = [x for a in keys for x in net[a]]
        elif op == "elevate":
            by = r.randint(1, 2)
            claim["by"] = by
            net = bz.elevate(P, by)
            keys = bz.indices(n + by, m)
            qs = [x for a in keys for x in net[a]]
            texts, ok = self.numbers_claim(claim, qs, info)
            claim["expect"] = {bz.key_text(a): t for a, t in zip(keys, self.shape(texts, [d] * len(keys)))}
        elif op in ("halve", "subdivide"):
            # pieces as subpatches (guide §5 halve/subdivide, theory §5): halve edge I,J gives the
            # parent with corner J replaced by the midpoint, then with corner I replaced; subdivide
            # at U gives piece k = the parent with corner k replaced by U (U inside, on no facet);
            # midpoints (triangles) gives [a1,m12,m13], [m12,a2,m23], [m13,m23,a3], [m23,m13,m12]
            E = [list(bz.unit(m, k)) for k in range(m + 1)]
            if op == "halve":
                i, j = r.sample(range(1, m + 2), 2)
                claim["edge"] = [i, j]
                mid = [F(a + b, 2) for a, b in zip(E[i - 1], E[j - 1])]
                pieces = [E[:j - 1] + [mid] + E[j:], E[:i - 1] + [mid] + E[i:]]
            elif m == 2 and r.random() < 0.4:
                claim["midpoints"] = True
                mp = lambda a, b: [F(x + y, 2) for x, y in zip(E[a], E[b])]
                pieces = [[E[0], mp(0, 1), mp(0, 2)], [mp(0, 1), E[1], mp(1, 2)], [mp(0, 2), mp(1, 2), E[2]], [mp(1, 2), mp(0, 2), mp(0, 1)]]
            else:
                while True:
                    U = self.bary_exact(m, inside=True)
                    if min(U) > 0:
                        break
                claim["at"] = [floats.frac_text(x) for x in U]
                pieces = [E[:k] + [U] + E[k + 1:] for k in range(m + 1)]
            keys = bz.indices(n, m)
            nets = [bz.subpatch(P, v) for v in pieces]
            qs = [x for net in nets for a in keys for x in net[a]]
            texts, ok = self.numbers_claim(claim, qs, info)
            per = len(keys) * d
            claim["expect"] = [{bz.key_text(a): t for a, t in zip(keys, self.shape(texts[i * per:(i + 1) * per], [d] * len(keys)))} for i in range(len(nets))]
        elif op == "derivative":
            k = r.randint(1, min(n, 3) if not rational else 2)
            dom = bz.domain_of(P)
            if r.random() < 0.5:
                lam = self.bary_exact(m, inside=True)
                claim["at"] = [floats.frac_text(x) for x in lam]
            else:
                lam = self.bary_exact(m, inside=True)
                p = [sum(l * v[i] for l, v in zip(lam, dom)) for i in range(m)]
                claim["cartesian"] = [floats.frac_text(x) for x in p]
            dirs = []
            for _ in range(k):
                if r.random() < 0.5:
                    a, b = self.bary_exact(m, False), self.bary_exact(m, False)
                    dv = [x - y for x, y in zip(a, b)]
                    claim.setdefault("dirs", []).append([floats.frac_text(x) for x in dv])
                else:
                    vec = [F(r.randint(-5, 5), r.choice([1, 2, 3])) for _ in range(m)]
                    dv = bz.directional(dom, vec)
                    claim.setdefault("vectors", []).append([floats.frac_text(x) for x in vec])
                dirs.append(dv)
            # derivatives along directions commute, so dirs and vectors may come in any order
            qs = rational_derivative(P, lam, dirs) if rational else bz.derivative(P, lam, dirs)
            texts, ok = self.numbers_claim(claim, qs, info)
            claim["expect"] = texts
        elif op == "edge_curve":
            i, j = r.sample(range(1, m + 2), 2)
            claim["from"], claim["to"] = i, j
            pts = bz.edge_curve(P, i, j)
            qs = [x for p in pts for x in p]
            texts, ok = self.numbers_claim(claim, qs, info)
            claim["expect"] = self.shape(texts, [d] * len(pts))
        elif op == "tangent":
            lam = self.bary_exact(m, inside=True)
            claim["at"] = [floats.frac_text(x) for x in lam]
            dom = bz.domain_of(P)
            ex = bz.directional(dom, [1, 0])
            ey = bz.directional(dom, [0, 1])
            der = (lambda ds: rational_derivative(P, lam, ds)) if rational else (lambda ds: bz.derivative(P, lam, ds))
            part = r.choice(["point", "normal"])
            claim["part"] = part
            qs = bz.evaluate(P, lam) if part == "point" else cross(der([ex]), der([ey]))
            texts, ok = self.numbers_claim(claim, qs, info)
            claim["expect"] = texts
        else:
            raise AssertionError(op)
        return claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}

    def free_claim(self, cid, op):
        """`barycentric` and `direction`: claims with their own domain (no patch needed)."""
        r = self.r
        m = r.choice([1, 2, 2, 3])
        dom = r.choice({1: DOMAINS1, 2: DOMAINS2, 3: DOMAINS3}[m])
        self.new_claim()
        claim = {"id": cid, "op": op, "source": "reference", "domain": [[str(x) for x in v] for v in dom]}
        info = {"op": op, "patch_kind": None, "precision": None}
        vec = [F(r.randint(-20, 20), r.choice([1, 2, 3, 7])) for _ in range(m)]
        if op == "barycentric":
            claim["point"] = [floats.frac_text(x) for x in vec]
            qs = bz.barycentric([[F(x) for x in v] for v in dom], vec)
        else:
            claim["vector"] = [floats.frac_text(x) for x in vec]
            qs = bz.directional([[F(x) for x in v] for v in dom], vec)
        texts, ok = self.numbers_claim(claim, qs, info)
        claim["expect"] = texts
        return claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}


# --- inverse problems with rational answers (guide §5 intersect/locate/ray, §6) -------------

def ipoint(r, d, lo=-8, hi=8):
    return [F(r.randint(lo, hi)) for _ in range(d)]


def linear_file(pts, keys):
    return {"degree": 1, "control_points": {k: [floats.frac_text(x) for x in p] for k, p in zip(keys, pts)}}


class InverseGen(Gen):
    """intersect of two segments, locate on a linear triangle, ray on a flat triangle in R^3: cases
    whose exact answers are rational (Cramer's rule), with integer data so that a precision rounds
    nothing but the claimed values. Claims list parameter tuples (or a bare count)."""

    def tuples_claim(self, claim, sols, info, prec, dim):
        r = self.r
        self.new_claim()
        if prec:
            claim["precision"] = prec
        info["precision"] = prec
        mode = r.random()
        if mode < 0.1:
            claim["expect"] = len(sols) + (r.choice([-1, 1]) if r.random() < 0.4 else 0)
            claim["expect"] = max(claim["expect"], 0)
            ok = claim["expect"] == len(sols)
            info["tolerance"] = "count"
            return ok
        sols = rational_parts(sols)
        tuples = [list(s) for s in sols]
        if r.random() < 0.15 and tuples:
            tuples = []  # a missed solution
        elif r.random() < 0.1:
            tuples = tuples + [[F(r.randint(0, 8), 8) for _ in range(dim)]]  # an extra tuple
        qs_all, ys_all, texts_all = [], [], []
        for tup in tuples:
            texts, ys = [], []
            for q in tup:
                # an irrational value is claimed near a rational within 2^-239 of it
                qa = q.approx() if isinstance(q, Quad) else q
                t, y = self.claimed_float(qa, prec) if prec else self.claimed_exact(qa)
                texts.append(t)
                ys.append(y)
            texts_all.append(texts)
            ys_all.append(ys)
            qs_all.append(tup)
        flat_y = [y for ys in ys_all for y in ys]
        flat_q = [q.approx() if isinstance(q, Quad) else q for qs in qs_all for q in qs]
        kinds = ["exact", "abs", "rel"] + (["ulps", "correctly_rounded", "faithful"] if prec else [])
        tol = self.tolerance(prec, flat_y, flat_q, kinds=kinds) if flat_y else r.choice(["exact", "abs=1e-9"])
        if tol != "exact" or r.random() < 0.5:
            claim["tolerance"] = tol
        info["tolerance"] = tol.split("=")[0]
        claim["expect"] = texts_all
        # pairing (guide §6): a tuple pairs with the exact solution nearest it when every
        # coordinate is within 2^-20 max(1, |value|); with at most one exact solution, the claim
        # holds when it lists exactly one tuple per solution, paired, each coordinate in tolerance
        if len(ys_all) != len(sols):
            return False
        # claimed tuples in the order of the exact ones: pair each with its own solution (the
        # solutions here are far apart compared with 2^-20, so nearest pairing gives the same)
        for ys, s in zip(ys_all, sols):
            if any(not paired(y, q) for y, q in zip(ys, s)):
                return False
            if not all(judge_any(y, q, tol, prec) for y, q in zip(ys, s)):
                return False
        return True

    def intersect_case(self, cid):
        r = self.r
        while True:
            P0, P1, Q0, Q1 = (ipoint(r, 2) for _ in range(4))
            a = [P1[i] - P0[i] for i in range(2)]
            b = [Q1[i] - Q0[i] for i in range(2)]
            D = -a[0] * b[1] + a[1] * b[0]
            if D != 0:
                break
        c = [Q0[i] - P0[i] for i in range(2)]
        s = (-c[0] * b[1] + c[1] * b[0]) / D
        t = (a[0] * c[1] - a[1] * c[0]) / D
        sols = [(s, t)] if 0 <= s <= 1 and 0 <= t <= 1 else []
        files = {"a": linear_file([P0, P1], ["1,0", "0,1"]), "b": linear_file([Q0, Q1], ["1,0", "0,1"])}
        claim = {"id": cid, "op": "intersect", "source": "reference", "patches": ["a", "b"]}
        info = {"op": "intersect", "patch_kind": "segment"}
        ok = self.tuples_claim(claim, sols, info, r.choice([None, "f64", "f32"]), 2)
        return files, claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}

    def parabola_case(self, cid):
        """A quadratic curve A (a parabola: control points not collinear) and a segment B on the line
        through A(s1) and A(s2), or on the tangent at A(s1) (s1 = s2, a tangential point). A line
        meets a parabola in at most two points, so the exact answer is {(s_i, t_i)} restricted to
        [0, 1]^2, all rational; every coordinate is dyadic, so a precision rounds nothing."""
        r = self.r
        while True:
            C = [ipoint(r, 2) for _ in range(3)]
            if bz.det([[1, 1, 1], [C[0][0], C[1][0], C[2][0]], [C[0][1], C[1][1], C[2][1]]]) != 0:
                break
        A = {"n": 2, "m": 1, "points": {(2, 0): C[0], (1, 1): C[1], (0, 2): C[2]}, "weights": None}
        at = lambda s: bz.evaluate(A, [1 - s, s])
        s1 = F(r.randint(-2, 10), 8)
        tangent = r.random() < 0.25
        s2 = s1 if tangent else F(r.choice([k for k in range(-2, 11) if F(k, 8) != s1]), 8)
        p1 = at(s1)
        if tangent:
            dvec = bz.derivative(A, [1 - s1, s1], [[-1, 1]])
        else:
            dvec = [x - y for x, y in zip(at(s2), p1)]
        while True:
            a, b = F(r.randint(-6, 6), 4), F(r.randint(-6, 6), 4)
            if a != b:
                break
        B0 = [p + a * v for p, v in zip(p1, dvec)]
        B1 = [p + b * v for p, v in zip(p1, dvec)]
        cands = {(s1, -a / (b - a))}
        if not tangent:
            cands.add((s2, (1 - a) / (b - a)))
        sols = sorted(c for c in cands if 0 <= c[0] <= 1 and 0 <= c[1] <= 1)
        files = {"a": linear_file(C, ["2,0", "1,1", "0,2"]), "b": linear_file([B0, B1], ["1,0", "0,1"])}
        files["a"]["degree"] = 2
        claim = {"id": cid, "op": "intersect", "source": "reference", "patches": ["a", "b"]}
        info = {"op": "intersect", "patch_kind": "parabola-tangent" if tangent else "parabola"}
        ok = self.tuples_claim(claim, sols, info, r.choice([None, "f64", "f32"]), 2)
        return files, claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}

    def join_case(self, cid):
        """Two triangle patches over triangles sharing an edge (guide §5 join, theory §8): A over
        [a1, a2, a3], B over [a1, a2, v] with v across the edge; B is the extension of A (the
        subpatch of A over B's triangle) with one control point of row ρ (last index ρ) changed,
        or none. B's first r+1 rows agree with the extension exactly for r < ρ, so max_smoothness
        is ρ - 1 (-1: not C0), or n when nothing changed; c0 and c1 follow."""
        r = self.r
        n = r.randint(1, 3)
        d = r.choice([1, 2, 3])
        dom = [[F(x) for x in v] for v in r.choice(DOMAINS2)]
        a1, a2, a3 = dom
        # v: a3 reflected through the edge midpoint, moved along the edge: across the edge
        mid = [(a1[i] + a2[i]) / 2 for i in range(2)]
        shift = F(r.randint(-2, 2), 2)
        v = [2 * mid[i] - a3[i] + shift * (a2[i] - a1[i]) for i in range(2)]
        A = {"n": n, "m": 2, "d": d, "points": {}, "weights": None, "domain": dom}
        for alpha in bz.indices(n, 2):
            A["points"][alpha] = [F(r.randint(-9, 9), r.choice([1, 2, 3])) for _ in range(d)]
        verts = [bz.barycentric(dom, p) for p in (a1, a2, v)]
        Bnet = bz.subpatch(A, verts)
        rho = r.choice([None] + list(range(n + 1)))
        if rho is not None:
            alpha = r.choice([a for a in bz.indices(n, 2) if a[2] == rho])
            Bnet[alpha] = [x + (F(r.randint(1, 5), r.choice([1, 7])) if i == 0 else 0) for i, x in enumerate(Bnet[alpha])]
        ms = n if rho is None else rho - 1
        cp = lambda net: {bz.key_text(a): [floats.frac_text(x) for x in net[a]] for a in bz.indices(n, 2)}
        files = {"a": {"degree": n, "control_points": cp(A["points"]), "domain": [[floats.frac_text(x) for x in p] for p in dom]},
                 "b": {"degree": n, "control_points": cp(Bnet), "domain": [[floats.frac_text(x) for x in p] for p in (a1, a2, v)]}}
        part = r.choice(["max_smoothness", "c0", "c1"])
        truth = {"max_smoothness": ms, "c0": ms >= 0, "c1": ms >= 1}[part]
        self.new_claim()
        if self.good or r.random() < 0.4:
            claimed = truth
        elif part == "max_smoothness":
            claimed = r.choice([x for x in range(-1, n + 1) if x != ms])
        else:
            claimed = not truth
        claim = {"id": cid, "op": "join", "source": "reference", "patches": ["a", "b"], "part": part, "expect": claimed}
        info = {"op": "join", "patch_kind": "bezier", "tolerance": "exact"}
        return files, claim, {"verdict": "passed" if claimed == truth else "FAILED", "exact": None, "info": info}

    def height_case(self, cid):
        """`ray` with `height` (x, y) on a functional patch: (z, s, t) with z = f(x, y) and (s, t) the
        last two barycentric coordinates of (x, y) (the parameters, as for locate); none outside
        the domain (guide §6)."""
        r = self.r
        P, pf = self.patch(kind="functional")
        prec = r.choice([None, "f64", "f32"])
        dom = P["domain"]
        lam = self.bary_exact(2, inside=r.random() < 0.75)
        pt = [sum(l * v[i] for l, v in zip(lam, dom)) for i in range(2)]
        texts = [self.point_text(x, prec) for x in pt]
        seen = [floats.rn(floats.parse(t), prec) if prec else floats.parse(t) for t in texts]
        Q = self.rounded(P, prec) if prec else P
        lam = bz.barycentric(dom, seen)
        sols = [(bz.evaluate(Q, lam)[0], lam[1], lam[2])] if min(lam) >= 0 else []
        claim = {"id": cid, "op": "ray", "source": "reference", "height": texts}
        info = {"op": "ray-height", "patch_kind": "functional"}
        ok = self.tuples_claim(claim, sols, info, prec, 3)
        return {"hill": pf}, claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}

    def locate_case(self, cid):
        r = self.r
        while True:
            A, B, C = (ipoint(r, 2) for _ in range(3))
            if bz.det([[1, 1, 1], [A[0], B[0], C[0]], [A[1], B[1], C[1]]]) != 0:
                break
        prec = r.choice([None, "f64", "f32"])
        lam = self.bary_exact(2, inside=r.random() < 0.7)
        pt = [sum(l * v[i] for l, v in zip(lam, [A, B, C])) for i in range(2)]
        texts = [self.point_text(x, prec) for x in pt]
        seen = [floats.rn(floats.parse(t), prec) if prec else floats.parse(t) for t in texts]
        lam = bz.barycentric([A, B, C], seen)  # the query as the code saw it
        claim = {"id": cid, "op": "locate", "source": "reference", "point": texts}
        anywhere = r.random() < 0.2
        if anywhere:
            claim["anywhere"] = True
        sols = [(lam[1], lam[2])] if anywhere or min(lam) >= 0 else []
        files = {"tri": linear_file([A, B, C], ["1,0,0", "0,1,0", "0,0,1"])}
        info = {"op": "locate", "patch_kind": "linear"}
        ok = self.tuples_claim(claim, sols, info, prec, 2)
        return files, claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}

    def quad_patch(self):
        """A quadratic triangle whose preimages are known by construction (guide §5 locate, §6).
        With (s, t) = (λ1, λ2), P(s, t) = M (x(s), y(s, t)) + o where x(s) = k s^2 - k σ s + e,
        y(s, t) = c t + h(s) with h quadratic, and M an invertible 2x2 integer matrix. After M
        mixes the coordinates both depend on s, s^2 and t, so the exact engine sees a general
        quadratic system. The control points are the blossom's values at the corners (theory §4).
        Returns (P, file, query) where query(sa, ta) gives the point q = P(sa, ta) and all its
        preimages in the plane: x(s) = x(sa) has the roots sa and σ - sa (one, on the fold line
        s = σ/2, where the Jacobian vanishes), and t = (y - h(s)) / c. Data are dyadic with small
        denominators, so every q is a float of either precision."""
        r = self.r
        sigma = F(r.randint(-2, 18), 8)
        k = F(r.randint(1, 4), r.choice([1, 2])) * r.choice([-1, 1])
        e = F(r.randint(-6, 6))
        h = [F(r.randint(-4, 4), r.choice([1, 2, 4])) for _ in range(3)]  # h0 + h1 s + h2 s^2
        c = r.choice([F(1), F(2), F(-1), F(1, 2)])
        while True:
            M = [[F(r.randint(-3, 3)) for _ in range(2)] for _ in range(2)]
            if M[0][0] * M[1][1] - M[0][1] * M[1][0] != 0:
                break
        o = [F(r.randint(-4, 4)) for _ in range(2)]
        # power-form coefficients {(i, j): coefficient of s^i t^j} of x and y, then of P
        xc = {(0, 0): e, (1, 0): -k * sigma, (2, 0): k}
        yc = {(0, 0): h[0], (1, 0): h[1], (2, 0): h[2], (0, 1): c}
        monos = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)]
        pc = [{m: M[i][0] * xc.get(m, 0) + M[i][1] * yc.get(m, 0) + (o[i] if m == (0, 0) else 0) for m in monos} for i in range(2)]

        def blossom2(f, a, b):
            (sa, ta), (sb, tb) = a, b
            return (f[(0, 0)] + f[(1, 0)] * (sa + sb) / 2 + f[(0, 1)] * (ta + tb) / 2 + f[(2, 0)] * sa * sb
                    + f[(1, 1)] * (sa * tb + sb * ta) / 2 + f[(0, 2)] * ta * tb)

        corner = [(F(0), F(0)), (F(1), F(0)), (F(0), F(1))]  # λ0, λ1 = s, λ2 = t
        points = {}
        for alpha in bz.indices(2, 2):
            args = [corner[i] for i in range(3) for _ in range(alpha[i])]
            points[alpha] = [blossom2(pc[i], args[0], args[1]) for i in range(2)]
        P = {"n": 2, "m": 2, "d": 2, "points": points, "weights": None}
        hs = lambda s: h[0] + h[1] * s + h[2] * s * s

        def query(sa, ta):
            X = k * sa * sa - k * sigma * sa + e
            Y = c * ta + hs(sa)
            q = [M[i][0] * X + M[i][1] * Y + o[i] for i in range(2)]
            pre = [(s, (Y - hs(s)) / c) for s in sorted({sa, sigma - sa})]
            for s, t in pre:  # the reference checks its own construction
                assert bz.evaluate(P, [1 - s - t, s, t]) == q, "quad_patch: a planted preimage does not map to q"
            return q, pre

        def query_irrational(j, Y):
            """The point with x = X and y = Y, X chosen so that x(s) = X has the irrational roots
            s = σ/2 ± √j/8 (j not a square): the discriminant σ²/4 - (e - X)/k is j/64. Then
            s² = σ s - (e - X)/k, so h(s) = A + B s and t = (Y - h(s))/c lie in Q(√j) too. The
            point itself is dyadic (a float of either precision)."""
            X = e - k * (sigma * sigma / 4 - F(j, 64))
            q = [M[i][0] * X + M[i][1] * Y + o[i] for i in range(2)]
            A = h[0] - h[2] * (e - X) / k
            B = h[1] + h[2] * sigma
            pre = []
            for sign in (-1, 1):
                s_ = Quad(sigma / 2, F(sign, 8), j)
                t_ = (Y - A - B * s_) * (1 / c)
                # the reference checks its own algebra: P's power form at (s, t) in Q(√j) is q
                for i in range(2):
                    val = Quad(0, 0, j)
                    for (pi, pj), coef in pc[i].items():
                        term = Quad(coef, 0, j)
                        for _ in range(pi):
                            term = term * s_
                        for _ in range(pj):
                            term = term * t_
                        val = val + term
                    assert val == q[i], "quad_patch: an irrational preimage does not map to q"
                pre.append((s_, t_))
            return q, pre

        pf = {"degree": 2, "control_points": {bz.key_text(a): [floats.frac_text(x) for x in v] for a, v in points.items()}}
        return P, pf, query, sigma, query_irrational

    def quad_locate_case(self, cid):
        """`locate` on a quad_patch at a point with one or two planted preimages (one when the
        query's preimage lies on the fold)."""
        r = self.r
        P, pf, query, sigma, query_irrational = self.quad_patch()
        irrational = r.random() < 0.3
        fold = not irrational and r.random() < 0.25
        if irrational:
            j = r.choice([2, 3, 5, 6, 7, 8, 10, 11, 12, 13, 17, 20, 28, 45])
            q, pre = query_irrational(j, F(r.randint(-16, 16), 8))
        else:
            sa = sigma / 2 if fold else F(r.randint(-2, 9), 8)
            q, pre = query(sa, F(r.randint(-1, 8), 8))
        prec = r.choice([None, "f64", "f32"])
        claim = {"id": cid, "op": "locate", "source": "reference", "point": [floats.frac_text(x) for x in q]}
        anywhere = r.random() < 0.2
        if anywhere:
            claim["anywhere"] = True
        sols = [(s, t) for s, t in pre if anywhere or (s >= 0 and t >= 0 and s + t <= 1)]
        info = {"op": "locate", "patch_kind": "quadratic-irrational" if irrational else "quadratic-fold" if len(pre) == 1 else "quadratic"}
        ok = self.tuples_claim(claim, sols, info, prec, 2)
        return {"quad": pf}, claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}

    def ray_case(self, cid):
        r = self.r
        while True:
            A, B, C = (ipoint(r, 3) for _ in range(3))
            d = ipoint(r, 3, -3, 3)
            e1 = [B[i] - A[i] for i in range(3)]
            e2 = [C[i] - A[i] for i in range(3)]
            M = [[e1[i], e2[i], -d[i]] for i in range(3)]
            D = bz.det(M)
            if D != 0:
                break
        lam = self.bary_exact(2, inside=r.random() < 0.7)
        tau0 = F(r.randint(-2, 6), r.choice([1, 2, 4]))
        target = [sum(l * v[i] for l, v in zip(lam, [A, B, C])) for i in range(3)]
        o = [target[i] - tau0 * d[i] for i in range(3)]
        prec = r.choice([None, "f64", "f32"])
        texts = [self.point_text(x, prec) for x in o]
        o = [floats.rn(floats.parse(t), prec) if prec else floats.parse(t) for t in texts]
        # solve o + tau d = A + s (B - A) + t (C - A) for the query as the code saw it
        rhs = [o[i] - A[i] for i in range(3)]
        sol = bz.cramer_3(M, rhs)
        tau, s_, t_ = sol[2], sol[0], sol[1]
        sols = [(tau, s_, t_)] if tau >= 0 and s_ >= 0 and t_ >= 0 and s_ + t_ <= 1 else []
        claim = {"id": cid, "op": "ray", "source": "reference", "origin": texts, "direction": [floats.frac_text(x) for x in d]}
        files = {"tri3": linear_file([A, B, C], ["1,0,0", "0,1,0", "0,0,1"])}
        info = {"op": "ray", "patch_kind": "linear"}
        ok = self.tuples_claim(claim, sols, info, prec, 3)
        return files, claim, {"verdict": "passed" if ok else "FAILED", "exact": None, "info": info}


# --- `check --patch P --results FILE` batches (guide §8) ------------------------------------

class BatchGen(Gen):
    """A batch of results of another implementation, one row per point: barycentric (m+1) or
    Cartesian (m, `--cartesian`) coordinates, then the d claimed values. Returns the file text,
    the options, and the expected verdict of every row."""

    def batch(self, nrows):
        r = self.r
        P, pf = self.patch(kind="bezier")
        prec = r.choice([None, "f64", "f64", "f32"])
        cart = r.random() < 0.5
        fmt = r.choice(["csv", "csv", "jsonl", "json"])
        Q = self.rounded(P, prec) if prec else P
        dom = bz.domain_of(P)
        rows = []
        all_good = r.random() < 0.35  # a batch of correct (exact or correctly rounded) values
        for _ in range(nrows):
            self.new_claim()
            self.good = self.good or all_good
            if cart:
                p = self.cart_point(P)
                texts = [self.point_text(x, prec) for x in p]
                seen = [floats.parse(t) for t in texts]
                if prec:
                    seen = [floats.rn(x, prec) for x in seen]
                lam = bz.barycentric(dom, seen)
            else:
                lam0 = self.bary_exact(P["m"], inside=r.random() < 0.8)
                texts = [self.point_text(x, prec) for x in lam0]
                lam = [floats.parse(t) for t in texts]
                if prec:
                    lam = [floats.rn(x, prec) for x in lam]
                elif sum(lam) != 1:
                    texts = [floats.frac_text(x) for x in lam0]
                    lam = lam0
            qs = bz.evaluate(Q, lam)
            al = [abs(x) for x in lam]
            conds = [sum(abs(Q["points"][a][i]) * bz.bernstein(a, al) for a in bz.indices(P["n"], P["m"])) for i in range(P["d"])]
            ys, yt = [], []
            for q in qs:
                t, y = self.claimed_float(q, prec) if prec else self.claimed_exact(q)
                ys.append(y)
                yt.append(t)
            bad = not all_good and r.random() < 0.02  # a nan or an empty field fails the row (guide §8)
            if bad:
                yt[r.randrange(len(yt))] = r.choice(["nan", "inf", ""])
            rows.append({"texts": texts + yt, "ys": ys, "qs": qs, "conds": conds, "lam": lam, "bad": bad})
        kinds = ["exact", "abs", "rel"] + (["ulps", "correctly_rounded", "faithful", "cond", "condK", "bound"] if prec else [])
        pick = r.choice(rows)
        tol = self.tolerance(prec, pick["ys"], pick["qs"], conds=pick["conds"], kinds=kinds)
        algorithm = r.choice(["casteljau", "bernstein"]) if tol == "bound" else None
        N = len(bz.indices(P["n"], P["m"]))
        K_default = (P["m"] + 1) * P["n"]
        for row in rows:
            if row["bad"]:
                row["ok"] = False
                continue
            if tol == "bound":
                if algorithm == "bernstein":
                    bounds = [bernstein_bound(c, P["m"], P["n"], N, prec) for c in row["conds"]]
                else:
                    bounds = [casteljau_bound(c, P["m"], P["n"], sum(abs(x) for x in row["lam"]), prec) for c in row["conds"]]
            else:
                bounds = [None] * len(row["qs"])
            row["ok"] = all(judge(y, q, tol, prec, cond=c, bound=b, K_default=K_default) for y, q, c, b in zip(row["ys"], row["qs"], row["conds"], bounds))
        opts = []
        if prec:
            opts += ["--precision", prec]
        if tol != "exact" or r.random() < 0.5:
            opts += ["--tolerance", tol]
        if algorithm:
            opts += ["--algorithm", algorithm]
        if cart:
            opts += ["--cartesian"]
        # the file; each row's line number
        lines, row_lines = [], []
        if fmt == "csv":
            if r.random() < 0.3:
                lines.append("# rows written by the reference")
            for row in rows:
                lines.append(",".join(row["texts"]))
                row_lines.append(len(lines))
            text = "\n".join(lines) + "\n"
        elif fmt == "jsonl":
            import json
            for row in rows:
                lines.append(json.dumps(row["texts"]))
                row_lines.append(len(lines))
            text = "\n".join(lines) + "\n"
        else:
            import json
            text = "[\n" + ",\n".join("  " + json.dumps(row["texts"]) for row in rows) + "\n]\n"
            row_lines = [i + 2 for i in range(len(rows))]
        expected = {
            "passed": sum(1 for row in rows if row["ok"]),
            "failed": sum(1 for row in rows if not row["ok"]),
            "failed_lines": [ln for ln, row in zip(row_lines, rows) if not row["ok"]],
            "exit": 0 if all(row["ok"] for row in rows) else 1,
            "info": {"op": "batch", "format": fmt, "cartesian": cart, "precision": prec, "tolerance": tol.split("=")[0],
                     "lam_floats": all(floats.is_float(x, prec) for row in rows for x in row["lam"]) if prec else None},
        }
        return pf, text, "." + fmt, opts, expected


# --- `check --locate-results` / `--ray-results` batches (guide §8) ---------------------------

class InverseBatchGen(InverseGen):
    """Rows of another implementation's answers to locate (x, y, then pairs or `none`) on a linear
    triangle, or to ray (origin, direction, then the first hit or `none`) on a flat triangle in R^3.
    Each row is judged like a locate/ray claim with the batch's tolerance."""

    def row_claim(self, sols, prec, tol, dim):
        """Claimed tuples for a row and whether the row holds."""
        r = self.r
        self.new_claim()
        self.good = self.good or self.all_good
        sols = rational_parts(sols)
        tuples = [list(s) for s in sols]
        if not self.good:
            c = r.random()
            if c < 0.1 and tuples:
                tuples = []
            elif c < 0.2 and (dim == 2 or not tuples):  # a ray row claims one hit at most
                tuples = tuples + [[F(r.randint(0, 8), 8) for _ in range(dim)]]
        texts, ok = [], len(tuples) == len(sols)
        for tup, s in zip(tuples, sols + [None] * len(tuples)):
            for q in tup:
                qa = q.approx() if isinstance(q, Quad) else q
                t, y = self.claimed_float(qa, prec) if prec else self.claimed_exact(qa)
                texts.append(t)
            ys = [floats.rn(floats.parse(t), prec) if prec else floats.parse(t) for t in texts[-dim:]]
            if s is not None and ok:
                if any(not paired(y, q) for y, q in zip(ys, s)):
                    ok = False
                elif not all(judge_any(y, q, tol, prec) for y, q in zip(ys, s)):
                    ok = False
        return (texts if texts else [r.choice(["none", "none", ""])]), ok

    def batch(self, kind, nrows):
        r = self.r
        prec = r.choice([None, "f64", "f32"])
        tol = r.choice(["exact", "abs=1e-9", "rel=1e-12"] + (["ulps=1", "ulps=4", "correctly_rounded", "faithful"] if prec else []))
        quad = kind == "locate" and r.random() < 0.4
        if quad:
            _, quad_pf, query, sigma, query_irrational = self.quad_patch()
        while True:
            A, B, C = (ipoint(r, 3 if kind == "ray" else 2) for _ in range(3))
            if kind == "locate" and bz.det([[1, 1, 1], [A[0], B[0], C[0]], [A[1], B[1], C[1]]]) != 0:
                break
            if kind == "ray" and any(cross([B[i] - A[i] for i in range(3)], [C[i] - A[i] for i in range(3)])):
                break
        rows = []
        self.all_good = r.random() < 0.35
        for _ in range(nrows):
            if quad:
                if r.random() < 0.3:  # irrational preimages (quadratic.Quad)
                    j = r.choice([2, 3, 5, 6, 7, 10, 11, 13, 17])
                    q, pre = query_irrational(j, F(r.randint(-16, 16), 8))
                else:
                    sa = sigma / 2 if r.random() < 0.2 else F(r.randint(-2, 9), 8)
                    q, pre = query(sa, F(r.randint(-1, 8), 8))
                qtexts = [floats.frac_text(x) for x in q]
                sols = [(s_, t_) for s_, t_ in pre if s_ >= 0 and t_ >= 0 and s_ + t_ <= 1]
                dim = 2
            elif kind == "locate":
                lam = self.bary_exact(2, inside=r.random() < 0.7)
                pt = [sum(l * v[i] for l, v in zip(lam, [A, B, C])) for i in range(2)]
                qtexts = [self.point_text(x, prec) for x in pt]
                seen = [floats.rn(floats.parse(t), prec) if prec else floats.parse(t) for t in qtexts]
                lam = bz.barycentric([A, B, C], seen)
                sols = [(lam[1], lam[2])] if min(lam) >= 0 else []
                dim = 2
            else:
                while True:
                    d = ipoint(r, 3, -3, 3)
                    e1 = [B[i] - A[i] for i in range(3)]
                    e2 = [C[i] - A[i] for i in range(3)]
                    M = [[e1[i], e2[i], -d[i]] for i in range(3)]
                    if bz.det(M) != 0:
                        break
                lam = self.bary_exact(2, inside=r.random() < 0.7)
                tau0 = F(r.randint(-2, 6), r.choice([1, 2, 4]))
                target = [sum(l * v[i] for l, v in zip(lam, [A, B, C])) for i in range(3)]
                o = [target[i] - tau0 * d[i] for i in range(3)]
                otexts = [self.point_text(x, prec) for x in o]
                o = [floats.rn(floats.parse(t), prec) if prec else floats.parse(t) for t in otexts]
                s_, t_, tau = bz.cramer_3(M, [o[i] - A[i] for i in range(3)])
                sols = [(tau, s_, t_)] if tau >= 0 and s_ >= 0 and t_ >= 0 and s_ + t_ <= 1 else []
                qtexts = otexts + [floats.frac_text(x) for x in d]
                dim = 3
            ctexts, ok = self.row_claim(sols, prec, tol, dim)
            rows.append((qtexts + ctexts, ok))
        text = "\n".join(",".join(t) for t, _ in rows) + "\n"
        pf = quad_pf if quad else linear_file([A, B, C], ["1,0,0", "0,1,0", "0,0,1"])
        opts = ["--" + kind + "-results", "rows.csv"]
        if prec:
            opts += ["--precision", prec]
        if tol != "exact" or r.random() < 0.5:
            opts += ["--tolerance", tol]
        failed_lines = [i + 1 for i, (_, ok) in enumerate(rows) if not ok]
        return pf, text, opts, {"passed": nrows - len(failed_lines), "failed": len(failed_lines), "failed_lines": failed_lines,
                                "exit": 1 if failed_lines else 0,
                                "info": {"op": kind + "-batch", "patch_kind": "quadratic" if quad else "linear", "format": "csv", "precision": prec, "tolerance": tol.split("=")[0]}}
