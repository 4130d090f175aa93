//! Joining two patches across a common domain edge (facet): C0, C1 by the μ rule, C^r by the
//! blossom, G1 as an exact polynomial identity, and Finn's quadrilateral condition
//! (Floater's notes §5, Finn's notes §30.1; docs/theory.md §8).
//!
//! Setting (Floater's notes): `A` is given over `T = [a_1, a_2, a_3]` with net `c`, `B` over
//! `U = [a_1, a_2, a_4]` with net `c̃`, where `c̃`'s third index belongs to `a_4`. Here the common
//! edge is found from the two domains, with the vertices listed in any order: `B`'s index that
//! belongs to its fourth vertex is its *row index* `ρ`, and `B`'s other indices are matched to
//! `A`'s through the common vertices. With `μ` the barycentric coordinates of `a_4` with respect
//! to `T`:
//!
//! * **C0** (Floater's notes eq. 12) ⇔ `c̃_{i,j,0} = c_{i,j,0}`, `i + j = n`;
//! * **C1** ⇔ C0 and `c̃_{i,j,1} = μ_1 c_{i+1,j,0} + μ_2 c_{i,j+1,0} + μ_3 c_{i,j,1}` (the μ rule);
//! * **C^r** ⇔ for `ρ = 0..=r`: `c̃_{i,j,ρ} = b_A[e_1^i, e_2^j, μ^ρ]`, i.e. the first `r + 1` rows of
//!   `B` agree with the subpatch of `A` over `U` (its C^n extension).
//!
//! The same holds for two `m`-simplices with a common facet (`m` indices instead of `i, j`).
//!
//! **G1** (triangles in `ℝ^d`, `d >= 3`): along the edge `λ(t) = (1−t) e_i + t e_j`, let `E(t)` be the
//! edge tangent, `X_A(t)` and `X_B(t)` the cross-boundary derivatives of `A` and `B` (barycentric
//! directions `e_j − e_i` and `e_opp − e_i`). The tangent planes agree at every edge point iff C0 holds
//! and `X_B(t) ∈ span(E(t), X_A(t))`, i.e. iff every `3×3` minor of `[E X_A X_B]` (for `d = 3` the
//! determinant `E · (X_A × X_B)`) is the zero polynomial in `t`; both patches must also be regular
//! along the edge (`E ∧ X_A ≢ 0`, `E ∧ X_B ≢ 0`). This is decided symbolically, never by sampling.
//!
//! **Degree 0 (constant patches).** `B` has rows `ρ = 0..=n` only, so C^r means "rows
//! `0..=min(r, n)` agree" ([`Join::c1`] and [`Join::max_smoothness`] read it so). When all
//! `n + 1` rows agree, `B` is the C^n extension of `A`: both are pieces of one polynomial, hence
//! C^r for every `r`. For `n = 0` that single row is C0, so two equal constants are C1, C2, …
//! (and `c1_neighbour` of a constant is that constant, a pair `analyse` accepts as C1). G1 is
//! still decided, and it fails: G1 asks for a common *tangent plane* along the edge, and a
//! constant patch has none (its edge tangent and cross-boundary derivative vanish, so the
//! regularity condition `E ∧ X_A ≢ 0` fails, exactly as for a higher-degree patch that is
//! singular along the whole edge). C1 implies G1 only where the surface is regular. Finn's
//! condition has no quadrilaterals at `n = 0` (`i + j = n − 1` has no solutions): it holds
//! vacuously.
//!
//! **Finn's condition:** each quadrilateral `c_{i+1,j,0}, c_{i,j+1,0}, c_{i,j,1}, c̃_{i,j,1}`
//! (`i + j = n − 1`) is planar. Finn's notes claims this suffices for G1; it does not (docs/theory.md §8).
//!
//! ```
//! use tribez::hazmat::domain::Domain;
//! use tribez::hazmat::join::analyse;
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::{BezierPatch, ControlNet};
//! let pts = |v: &[[&str; 3]]| v.iter().map(|p| p.iter().map(|s| q(s).unwrap()).collect()).collect::<Vec<Vec<_>>>();
//! let tri = |v: [[&str; 2]; 3]| Domain::new(v.iter().map(|p| p.iter().map(|s| q(s).unwrap()).collect()).collect()).unwrap();
//! // docs/theory.md §8: planar quadrilaterals, C0, yet not G1
//! let p = BezierPatch { name: None, domain: Some(tri([["0", "0"], ["1", "0"], ["0", "1"]])), net: ControlNet::from_points(2, 2,
//!     &pts(&[["0", "0", "0"], ["1", "0", "0"], ["2", "0", "0"], ["1/2", "1", "0"], ["3/2", "1", "1"], ["1", "2", "1"]])) };
//! let b = BezierPatch { name: None, domain: Some(tri([["0", "0"], ["1", "0"], ["0", "-1"]])), net: ControlNet::from_points(2, 2,
//!     &pts(&[["0", "0", "0"], ["1", "0", "0"], ["2", "0", "0"], ["1/2", "-2", "0"], ["3/2", "-1", "-1"], ["1", "-2", "-1"]])) };
//! let j = analyse(&p, &b).unwrap();
//! assert!(j.c0 && !j.c1);
//! assert_eq!((j.coplanarity, j.g1), (Some(true), Some(false)));
//! assert_eq!(j.g1_minors[0].to_text(&["t"]), "-8*t^2 + 8*t");
//! ```

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::casteljau;
use crate::domain::{Domain, determinant};
use crate::error::CoreError;
use crate::patch::{BezierPatch, ControlNet};
use crate::simplex::Simplex;
use crate::symbolic::Polynomial;
#[cfg(test)]
use crate::symbolic::barycentric_form;

type Q = BigRational;

/// The common facet (edge, for triangles) of two domain simplices.
#[derive(Clone, Debug, PartialEq)]
pub struct SharedFacet {
    /// `A`'s vertex indices (0-based) of the facet, ascending.
    pub a: Vec<usize>,
    /// `B`'s vertex indices of the same vertices, in the same order.
    pub b: Vec<usize>,
    /// `A`'s vertex off the facet.
    pub a_opposite: usize,
    /// `B`'s vertex off the facet (its index is `B`'s row index `ρ`).
    pub b_opposite: usize,
    /// The facet's vertices, in `A`'s order.
    pub vertices: Vec<Vec<Q>>,
}

fn facet_word(m: usize) -> &'static str {
    if m == 2 { "edge" } else { "facet" }
}

/// Find the facet two domains share (vertices compared exactly, in any order).
pub fn shared_facet(da: &Domain, db: &Domain) -> Result<SharedFacet, CoreError> {
    let m = da.m();
    if db.m() != m {
        return Err(CoreError::DomainDimensions { a: m, b: db.m() });
    }
    let mut a = Vec::new();
    let mut b = Vec::new();
    for (i, va) in da.vertices().iter().enumerate() {
        if let Some(j) = db.vertices().iter().position(|vb| vb == va) {
            a.push(i);
            b.push(j);
        }
    }
    if a.len() == m + 1 {
        return Err(CoreError::SameDomain {
            vertices: da.vertices().to_vec(),
            m,
        });
    }
    if a.len() < m {
        return Err(CoreError::NoSharedFacet {
            a: da.vertices().to_vec(),
            b: db.vertices().to_vec(),
            m,
            common: a.len(),
        });
    }
    let a_opposite = (0..=m)
        .find(|k| !a.contains(k))
        .expect("one vertex is off the facet");
    let b_opposite = (0..=m)
        .find(|k| !b.contains(k))
        .expect("one vertex is off the facet");
    let vertices = a.iter().map(|&i| da.vertices()[i].clone()).collect();
    Ok(SharedFacet {
        a,
        b,
        a_opposite,
        b_opposite,
        vertices,
    })
}

/// The rows of the C^n extension of `A` across a facet: `rows[ρ] = b_A[μ^ρ, ·^{n−ρ}]`, a net of
/// degree `n − ρ` whose control point at `α` (with `α_opp = 0`) is `b_A[e^α, μ^ρ]`.
pub struct Extension {
    rows: Vec<ControlNet<Q>>,
}

impl Extension {
    /// The rows for `A`'s net and the fourth vertex `μ` (barycentric w.r.t. `A`'s domain).
    pub fn new(net: &ControlNet<Q>, mu: &[Q]) -> Self {
        // Row ρ is level ρ of the de Casteljau pyramid at μ.
        Extension {
            rows: casteljau::levels(net, mu),
        }
    }

    /// The extension's control point at `B`'s multi-index `beta`.
    pub fn point(&self, facet: &SharedFacet, beta: &[u32]) -> Vec<Q> {
        let rho = beta[facet.b_opposite] as usize;
        let alpha = a_index(facet, beta, 0);
        self.rows[rho].at(&alpha).to_vec()
    }
}

/// `A`'s multi-index with `B`'s facet entries moved to `A`'s positions and `extra` at `A`'s
/// opposite vertex.
fn a_index(facet: &SharedFacet, beta: &[u32], extra: u32) -> Vec<u32> {
    let mut alpha = vec![0u32; beta.len()];
    for (&ia, &ib) in facet.a.iter().zip(&facet.b) {
        alpha[ia] = beta[ib];
    }
    alpha[facet.a_opposite] = extra;
    alpha
}

/// Floater's μ rule for one point of `B`'s row 1: `Σ_k μ_k c_{α+e_k}` where `α` is `B`'s index
/// moved to `A` with the row entry removed (`|α| = n − 1`).
pub fn mu_rule(net: &ControlNet<Q>, facet: &SharedFacet, mu: &[Q], beta: &[u32]) -> Vec<Q> {
    assert_eq!(beta[facet.b_opposite], 1, "the μ rule is about row 1");
    let base = a_index(facet, beta, 0);
    let mut out = vec![Q::zero(); net.dim()];
    for (k, mk) in mu.iter().enumerate() {
        let mut alpha = base.clone();
        alpha[k] += 1;
        for (o, x) in out.iter_mut().zip(net.at(&alpha)) {
            *o += mk * x;
        }
    }
    out
}

/// A condition that fails, with the control points concerned and the exact amount.
#[derive(Clone, Debug, PartialEq)]
pub enum Violation {
    /// Row `ρ` of `B` differs from the extension at `index` (B's multi-index): C^ρ fails.
    Row {
        /// The row (`0` for C0, `1` for C1, …).
        rho: usize,
        /// `B`'s multi-index.
        index: Vec<u32>,
        /// `B`'s control point.
        actual: Vec<Q>,
        /// What C^ρ requires (A's edge point, the μ rule, or the blossom).
        required: Vec<Q>,
        /// `actual − required`.
        difference: Vec<Q>,
    },
    /// Finn's quadrilateral at `B`'s row-1 index `index` is not planar.
    Coplanarity {
        /// `B`'s multi-index of the quadrilateral's point `c̃_{i,j,1}`.
        index: Vec<u32>,
        /// The four points `c_{i+1,j,0}, c_{i,j+1,0}, c_{i,j,1}, c̃_{i,j,1}` with their indices (A, A, A, B).
        points: Vec<(Vec<u32>, Vec<Q>)>,
        /// `det[P2 − P1, P3 − P1, P4 − P1]` (6 × the signed volume; for `d > 3` the first non-zero minor).
        volume: Q,
    },
    /// The tangent planes differ somewhere on the edge.
    G1 {
        /// Why.
        reason: String,
        /// The non-zero minor `det[E, X_A, X_B](t)` (for `d = 3` the determinant), if that is why.
        determinant: Option<Polynomial>,
        /// An edge parameter `t` where it is not zero, with its value, and both normals there (`d = 3`).
        witness: Option<G1Witness>,
    },
}

/// Where the G1 determinant is provably non-zero.
#[derive(Clone, Debug, PartialEq)]
pub struct G1Witness {
    /// Edge parameter: `λ = (1−t) e_i + t e_j`.
    pub t: Q,
    /// `A`'s barycentric coordinates of that edge point.
    pub at: Vec<Q>,
    /// The determinant's value there.
    pub value: Q,
    /// `E × X_A` there (`d = 3`).
    pub normal_a: Option<Vec<Q>>,
    /// `E × X_B` there (`d = 3`).
    pub normal_b: Option<Vec<Q>>,
}

/// The analysis of a pair.
#[derive(Clone, Debug, PartialEq)]
pub struct Join {
    /// The common facet.
    pub facet: SharedFacet,
    /// Barycentric coordinates of `B`'s fourth vertex with respect to `A`'s domain.
    pub mu: Vec<Q>,
    /// `μ_opp < 0`: the domains lie on opposite sides of the common facet (else they overlap).
    pub opposite_sides: bool,
    /// `rows_agree[ρ]`: row `ρ` of `B` agrees with the extension of `A`.
    pub rows_agree: Vec<bool>,
    /// C0.
    pub c0: bool,
    /// C1: C0 and row 1 agrees (for `n = 0`, where there is no row 1, C0 alone: see the module doc).
    pub c1: bool,
    /// The highest `r` with C^r (`−1` when not C0). `n` means every row agrees: `B` is the
    /// extension of `A`, one polynomial, so the pair is C^r for *every* `r` (for `n = 0`, two equal
    /// constants: `0` here, yet C1).
    pub max_smoothness: i64,
    /// G1 (`None` unless triangles in `ℝ^d`, `d >= 3`; decided for every degree, `false` for
    /// constant patches, which have no tangent plane).
    pub g1: Option<bool>,
    /// The minors of `[E X_A X_B]` as polynomials in the edge parameter `t` (`d = 3`: one).
    pub g1_minors: Vec<Polynomial>,
    /// Finn's quadrilateral condition (`None` unless triangles in `ℝ^d`, `d >= 3`).
    pub coplanarity: Option<bool>,
    /// Every failed condition.
    pub violations: Vec<Violation>,
    /// Remarks (overlapping domains, singular edges, why G1 is not decided).
    pub notes: Vec<String>,
}

fn sub(a: &[Q], b: &[Q]) -> Vec<Q> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

fn det3_poly(a: &[Polynomial; 3], b: &[Polynomial; 3], c: &[Polynomial; 3]) -> Polynomial {
    let m = |x: &Polynomial, y: &Polynomial, z: &Polynomial| x.mul(y).mul(z);
    m(&a[0], &b[1], &c[2])
        .add(&m(&a[1], &b[2], &c[0]))
        .add(&m(&a[2], &b[0], &c[1]))
        .sub(&m(&a[2], &b[1], &c[0]))
        .sub(&m(&a[1], &b[0], &c[2]))
        .sub(&m(&a[0], &b[2], &c[1]))
}

/// All `k×k` minors (`k = 2, 3`) of the `d×k` matrix whose columns are `cols`, rows chosen in
/// lexicographic order.
fn minors(cols: &[Vec<Polynomial>]) -> Vec<Polynomial> {
    let d = cols[0].len();
    let k = cols.len();
    let mut out = Vec::new();
    let row = |r: usize| -> Vec<Polynomial> { cols.iter().map(|c| c[r].clone()).collect() };
    if k == 2 {
        for i in 0..d {
            for j in i + 1..d {
                let (ri, rj) = (row(i), row(j));
                out.push(ri[0].mul(&rj[1]).sub(&ri[1].mul(&rj[0])));
            }
        }
    } else {
        for i in 0..d {
            for j in i + 1..d {
                for l in j + 1..d {
                    let (ri, rj, rl) = (row(i), row(j), row(l));
                    let a = [ri[0].clone(), rj[0].clone(), rl[0].clone()];
                    let b = [ri[1].clone(), rj[1].clone(), rl[1].clone()];
                    let c = [ri[2].clone(), rj[2].clone(), rl[2].clone()];
                    out.push(det3_poly(&a, &b, &c));
                }
            }
        }
    }
    out
}

/// `Σ_k d_k ∂P/∂λ_k` for each coordinate, restricted to the edge `λ(t) = (1−t) e_i + t e_j`:
/// polynomials in `t`. The derivative net (one de Casteljau step with `d`, times `n`) restricted to
/// the edge is the Bézier curve of its face `[i, j]`: `Σ_k b_k C(n−1, k) (1−t)^{n−1−k} t^k`.
/// A constant net (degree 0) has the zero derivative.
fn edge_derivative(net: &ControlNet<Q>, dir: &[Q], i: usize, j: usize) -> Vec<Polynomial> {
    if net.degree() == 0 {
        return vec![Polynomial::zero(1); net.dim()];
    }
    let dn = crate::derivative::derivative_net(net, &[dir]);
    let face = dn.face(&[i, j]);
    let q = face.degree();
    let t = Polynomial::variable(1, 0);
    let s = Polynomial::constant(1, Q::one()).sub(&t);
    let basis: Vec<Polynomial> = (0..=q)
        .map(|k| {
            s.pow((q - k) as u32)
                .mul(&t.pow(k as u32))
                .scale(&Q::from_integer(
                    crate::simplex::binomial_exact(q as u64, k as u64).into(),
                ))
        })
        .collect();
    (0..net.dim())
        .map(|c| {
            face.points()
                .zip(&basis)
                .fold(Polynomial::zero(1), |acc, (p, b)| acc.add(&b.scale(&p[c])))
        })
        .collect()
}

/// The same, from the symbolic form (`Σ_k d_k ∂P/∂λ_k` composed with `λ(t)`): the independent check.
#[cfg(test)]
fn edge_derivative_symbolic(net: &ControlNet<Q>, dir: &[Q], i: usize, j: usize) -> Vec<Polynomial> {
    let edge = edge_param(net.m(), i, j);
    barycentric_form(net)
        .iter()
        .map(|p| {
            let d = dir
                .iter()
                .enumerate()
                .fold(Polynomial::zero(p.nvars()), |acc, (k, dk)| {
                    acc.add(&p.derivative(k).scale(dk))
                });
            d.compose(&edge)
        })
        .collect()
}

fn unit_diff(m: usize, to: usize, from: usize) -> Vec<Q> {
    let mut v = vec![Q::zero(); m + 1];
    v[to] += Q::one();
    v[from] -= Q::one();
    v
}

fn edge_param(m: usize, i: usize, j: usize) -> Vec<Polynomial> {
    let t = Polynomial::variable(1, 0);
    let one = Polynomial::constant(1, Q::one());
    let mut out = vec![Polynomial::zero(1); m + 1];
    out[i] = one.sub(&t);
    out[j] = t;
    out
}

fn cross(a: &[Q], b: &[Q]) -> Vec<Q> {
    crate::derivative::cross(a, b)
}

/// Analyse the pair `(A, B)`: the domains must share one facet, the degrees, simplex dimensions
/// and point dimensions must agree.
pub fn analyse(a: &BezierPatch, b: &BezierPatch) -> Result<Join, CoreError> {
    let (na, nb) = (&a.net, &b.net);
    same_shape(na, nb)?;
    let (da, db) = (a.domain_or_reference(), b.domain_or_reference());
    let facet = shared_facet(&da, &db)?;
    let m = na.m();
    let n = na.degree();
    let d = na.dim();
    let mu = da.barycentric(&db.vertices()[facet.b_opposite])?;
    let opposite_sides = mu[facet.a_opposite].is_negative();
    let mut notes = Vec::new();
    if !opposite_sides {
        notes.push(format!(
            "the domains overlap: B's fourth vertex lies on the same side of the common {} as A's (μ_{} = {} >= 0); the conditions below still compare B with the extension of A",
            facet_word(m),
            facet.a_opposite + 1,
            mu[facet.a_opposite]
        ));
    }
    let mut violations = Vec::new();
    let rows_agree = rows_agreeing(na, nb, &facet, &mu, &mut violations);
    let max_smoothness = rows_agree
        .iter()
        .position(|&ok| !ok)
        .map_or(n as i64, |r| r as i64 - 1);
    // C^r ⇔ rows 0..=min(r, n) agree: B has no row beyond n, so once all n + 1 rows agree the
    // pair is one polynomial and C^r for every r (degree 0 included: two equal constants are C1).
    let c_r = |r: usize| rows_agree[..=r.min(n)].iter().all(|&ok| ok);
    let c0 = c_r(0);
    let c1 = c_r(1);

    let (mut g1, mut g1_minors, mut coplanarity) = (None, Vec::new(), None);
    if m == 2 && d >= 3 {
        coplanarity = Some(finn_coplanarity(na, nb, &facet, &mut violations));
        if n == 0 {
            notes.push("degree 0: Finn's condition has no quadrilaterals (it holds vacuously); constant patches have no tangent plane, so G1 fails although the pair is C^r for every r".into());
        }
        let (holds, minors) = g1_identity(na, nb, &facet, c0, &mut violations);
        g1 = Some(holds);
        g1_minors = minors;
    } else if m == 2 {
        notes.push(format!("G1 and Finn's coplanarity are decided for surfaces in R^d with d >= 3; these points have d = {d}"));
    } else {
        notes.push(format!(
            "G1 is decided for triangles (m = 2) only; this is a join of {m}-simplices"
        ));
    }
    Ok(Join {
        facet,
        mu,
        opposite_sides,
        rows_agree,
        c0,
        c1,
        max_smoothness,
        g1,
        g1_minors,
        coplanarity,
        violations,
        notes,
    })
}

/// Two nets of one simplex dimension, degree and point dimension, or the error naming which
/// differs.
fn same_shape(na: &ControlNet<Q>, nb: &ControlNet<Q>) -> Result<(), CoreError> {
    if na.m() != nb.m() {
        return Err(CoreError::SimplexDimensions {
            a: na.m(),
            b: nb.m(),
        });
    }
    if na.degree() != nb.degree() {
        return Err(CoreError::Degrees {
            a: na.degree(),
            b: nb.degree(),
        });
    }
    if na.dim() != nb.dim() {
        return Err(CoreError::PointDimensions {
            a: na.dim(),
            b: nb.dim(),
        });
    }
    Ok(())
}

/// C^r by rows (theory §8): row ρ of B (its control points at distance ρ from the common facet)
/// must be the ρ-th row of A's extension across the facet: row 0 A's facet net, row 1 the μ
/// rule, rows beyond by the blossom of A at μ. Whether each row agrees; every differing control
/// point is a [`Violation::Row`].
fn rows_agreeing(
    na: &ControlNet<Q>,
    nb: &ControlNet<Q>,
    facet: &SharedFacet,
    mu: &[Q],
    violations: &mut Vec<Violation>,
) -> Vec<bool> {
    let n = na.degree();
    let ext = Extension::new(na, mu);
    let mut rows_agree = vec![true; n + 1];
    for (beta, actual) in nb.entries() {
        let rho = beta[facet.b_opposite] as usize;
        let required = match rho {
            0 => na.at(&a_index(facet, beta, 0)).to_vec(),
            1 => mu_rule(na, facet, mu, beta),
            _ => ext.point(facet, beta),
        };
        if actual != required.as_slice() {
            rows_agree[rho] = false;
            violations.push(Violation::Row {
                rho,
                index: beta.to_vec(),
                actual: actual.to_vec(),
                difference: sub(actual, &required),
                required,
            });
        }
    }
    rows_agree
}

/// Finn's coplanarity condition for triangles in R^d, d >= 3: each quadrilateral of A's two
/// control points beside the edge, A's point across it and B's point across it spans no volume.
/// Every quadrilateral that does is a [`Violation::Coplanarity`]; true when none does.
fn finn_coplanarity(
    na: &ControlNet<Q>,
    nb: &ControlNet<Q>,
    facet: &SharedFacet,
    violations: &mut Vec<Violation>,
) -> bool {
    let mut all_planar = true;
    for (beta, qb) in nb.entries().filter(|(beta, _)| beta[facet.b_opposite] == 1) {
        let base = a_index(facet, beta, 0);
        let mut p1 = base.clone();
        p1[facet.a[0]] += 1;
        let mut p2 = base.clone();
        p2[facet.a[1]] += 1;
        let mut p3 = base;
        p3[facet.a_opposite] += 1;
        let pts = [
            na.at(&p1).to_vec(),
            na.at(&p2).to_vec(),
            na.at(&p3).to_vec(),
            qb.to_vec(),
        ];
        let vecs = [
            sub(&pts[1], &pts[0]),
            sub(&pts[2], &pts[0]),
            sub(&pts[3], &pts[0]),
        ];
        let volume = first_nonzero_minor3(&vecs);
        if !volume.is_zero() {
            all_planar = false;
            violations.push(Violation::Coplanarity {
                index: beta.to_vec(),
                points: vec![
                    (p1, pts[0].clone()),
                    (p2, pts[1].clone()),
                    (p3, pts[2].clone()),
                    (beta.to_vec(), pts[3].clone()),
                ],
                volume,
            });
        }
    }
    all_planar
}

/// G1 along the common edge as a polynomial identity in the edge parameter t (theory §8): the
/// patches meet (C0), both are regular along the edge, and every 3×3 minor of
/// `[E, X_A, X_B](t)` (edge tangent, A's and B's cross-boundary derivatives) is the zero
/// polynomial. Whether G1 holds, and the minors; each failure is a [`Violation::G1`], a
/// non-zero minor with a parameter where it does not vanish.
fn g1_identity(
    na: &ControlNet<Q>,
    nb: &ControlNet<Q>,
    facet: &SharedFacet,
    c0: bool,
    violations: &mut Vec<Violation>,
) -> (bool, Vec<Polynomial>) {
    let (m, n, d) = (na.m(), na.degree(), na.dim());
    let (ia, ja, ka) = (facet.a[0], facet.a[1], facet.a_opposite);
    let (ib, jb, kb) = (facet.b[0], facet.b[1], facet.b_opposite);
    let la = edge_param(m, ia, ja);
    let e = edge_derivative(na, &unit_diff(m, ja, ia), ia, ja);
    let xa = edge_derivative(na, &unit_diff(m, ka, ia), ia, ja);
    let xb = edge_derivative(nb, &unit_diff(m, kb, ib), ib, jb);
    let g1_minors = minors(&[e.clone(), xa.clone(), xb.clone()]);
    let regular_a = minors(&[e.clone(), xa.clone()])
        .iter()
        .any(|p| !p.is_zero());
    let regular_b = minors(&[e.clone(), xb.clone()])
        .iter()
        .any(|p| !p.is_zero());
    let mut holds = c0 && regular_a && regular_b;
    if !c0 {
        violations.push(Violation::G1 {
            reason: "the patches do not meet along the edge (not C0)".into(),
            determinant: None,
            witness: None,
        });
    }
    for (who, ok) in [("A", regular_a), ("B", regular_b)] {
        if !ok {
            violations.push(Violation::G1 {
                reason: if n == 0 {
                    format!("{who} is constant (degree 0): its derivatives vanish, it has no tangent plane")
                } else {
                    format!("{who} is singular along the whole edge (its edge tangent and cross-boundary derivative are parallel): no tangent plane")
                },
                determinant: None,
                witness: None,
            });
        }
    }
    if let Some(bad) = g1_minors.iter().find(|p| !p.is_zero()) {
        holds = false;
        let deg = bad.degree().unwrap_or(0).max(1);
        // a non-zero polynomial of degree `deg` has at most `deg` roots: one of these is not one
        let witness = (0..=deg).find_map(|k| {
            let t = Q::new(k.into(), deg.into());
            let value = bad.evaluate(std::slice::from_ref(&t));
            if value.is_zero() {
                return None;
            }
            let at: Vec<Q> = la
                .iter()
                .map(|p| p.evaluate(std::slice::from_ref(&t)))
                .collect();
            let ev = |v: &[Polynomial]| {
                v.iter()
                    .map(|p| p.evaluate(std::slice::from_ref(&t)))
                    .collect::<Vec<_>>()
            };
            let (normal_a, normal_b) = if d == 3 {
                (
                    Some(cross(&ev(&e), &ev(&xa))),
                    Some(cross(&ev(&e), &ev(&xb))),
                )
            } else {
                (None, None)
            };
            Some(G1Witness {
                t,
                at,
                value,
                normal_a,
                normal_b,
            })
        });
        violations.push(Violation::G1 {
            reason: "B's cross-boundary derivative leaves the span of A's edge tangent and cross-boundary derivative: det[E, X_A, X_B](t) is not the zero polynomial".into(),
            determinant: Some(bad.clone()),
            witness,
        });
    }
    (holds, g1_minors)
}

/// The first non-zero `3×3` minor of the `d×3` matrix with the given columns (`d >= 3`), else 0.
fn first_nonzero_minor3(cols: &[Vec<Q>; 3]) -> Q {
    let d = cols[0].len();
    for i in 0..d {
        for j in i + 1..d {
            for l in j + 1..d {
                let mat = [i, j, l]
                    .iter()
                    .map(|&r| cols.iter().map(|c| c[r].clone()).collect())
                    .collect();
                let v = determinant(mat);
                if !v.is_zero() {
                    return v;
                }
            }
        }
    }
    Q::zero()
}

/// A neighbour of `A` across the facet with `A`'s vertices `facet` (for triangles an edge
/// `a_i a_j`), over the simplex `facet` vertices (in that order) + `new_vertex` (last), such that
/// the pair is C1: rows 0 and 1 are forced (C0 and the μ rule); the other rows are free and are
/// filled here with the C^n extension `c̃_α = b_A[e^α, μ^{α_last}]` (so the pair is in fact C^n).
pub fn c1_neighbour(
    a: &BezierPatch,
    facet: &[usize],
    new_vertex: Vec<Q>,
) -> Result<BezierPatch, CoreError> {
    let net = &a.net;
    let m = net.m();
    let da = a.domain_or_reference();
    let mut sorted = facet.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    if facet.len() != m || sorted.len() != m || sorted.iter().any(|&k| k > m) {
        return Err(CoreError::FacetVertices { m });
    }
    let mut vertices: Vec<Vec<Q>> = facet.iter().map(|&k| da.vertices()[k].clone()).collect();
    vertices.push(new_vertex);
    let db = Domain::new(vertices)?;
    let a_opposite = (0..=m)
        .find(|k| !facet.contains(k))
        .expect("one vertex is off the facet");
    let mu = da.barycentric(&db.vertices()[m])?;
    if !mu[a_opposite].is_negative() {
        return Err(CoreError::Overlap {
            vertex: db.vertices()[m].clone(),
            m,
            opposite: a_opposite + 1,
            mu,
        });
    }
    let sf = SharedFacet {
        a: facet.to_vec(),
        b: (0..m).collect(),
        a_opposite,
        b_opposite: m,
        vertices: db.vertices()[..m].to_vec(),
    };
    let ext = Extension::new(net, &mu);
    let simplex = Simplex::new(m, net.degree());
    let points: Vec<Vec<Q>> = simplex.iter().map(|beta| ext.point(&sf, beta)).collect();
    let out = ControlNet::from_points(m, net.degree(), &points);
    let what = facet
        .iter()
        .map(|k| format!("a{}", k + 1))
        .collect::<String>();
    Ok(BezierPatch {
        name: Some(format!(
            "C1 neighbour of {} across {what}: rows 0 and 1 (last index 0, 1) forced by C0 and the mu rule; rows >= 2 are free, filled with the C^n extension (blossom)",
            a.name.clone().unwrap_or_else(|| "A".into())
        )),
        net: out,
        domain: Some(db),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational;
    use crate::symbolic::cartesian_form;
    use proptest::prelude::*;

    fn r(v: &[&str]) -> Vec<Q> {
        v.iter().map(|s| parse_rational(s).unwrap()).collect()
    }

    fn patch(n: usize, pts: &[&[&str]], domain: &[&[&str]]) -> BezierPatch {
        let points: Vec<Vec<Q>> = pts.iter().map(|p| r(p)).collect();
        BezierPatch {
            name: None,
            net: ControlNet::from_points(2, n, &points),
            domain: Some(Domain::new(domain.iter().map(|v| r(v)).collect()).unwrap()),
        }
    }

    /// docs/theory.md §8: planar quadrilaterals, yet not G1 (normals not parallel at the midpoint).
    #[test]
    fn seed_002_g1_counterexample() {
        let t: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "1"]];
        let u: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "-1"]];
        let p = patch(
            2,
            &[
                &["0", "0", "0"],
                &["1", "0", "0"],
                &["2", "0", "0"],
                &["1/2", "1", "0"],
                &["3/2", "1", "1"],
                &["1", "2", "1"],
            ],
            t,
        );
        let q = patch(
            2,
            &[
                &["0", "0", "0"],
                &["1", "0", "0"],
                &["2", "0", "0"],
                &["1/2", "-2", "0"],
                &["3/2", "-1", "-1"],
                &["1", "-2", "-1"],
            ],
            u,
        );
        let j = analyse(&p, &q).unwrap();
        assert!(j.c0);
        assert_eq!(j.coplanarity, Some(true));
        assert_eq!(j.g1, Some(false));
        // E = (2,0,0); X_A = (1/2 + t, 2, 2t) ... the determinant is a non-zero multiple of t(1−t)
        let det = &j.g1_minors[0];
        let tt = |s: &str| det.evaluate(&r(&[s]));
        assert!(tt("0").is_zero() && tt("1").is_zero() && !tt("1/2").is_zero());
    }

    /// docs/theory.md §8: row 1 from a common λ ≠ μ (Σλ = 1, λ_3 < 0) is G1 but not C1.
    #[test]
    fn common_lambda_gives_g1_without_c1() {
        let t: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "1"]];
        let a = patch(
            3,
            &[
                &["0", "0", "0"],
                &["1", "0", "1"],
                &["2", "1", "0"],
                &["3", "0", "1"],
                &["0", "1", "1"],
                &["1", "2", "3"],
                &["3", "1", "2"],
                &["1", "3", "0"],
                &["2", "3", "1"],
                &["1", "4", "2"],
            ],
            t,
        );
        let lambda = r(&["2/5", "4/5", "-1/5"]);
        let facet = SharedFacet {
            a: vec![0, 1],
            b: vec![0, 1],
            a_opposite: 2,
            b_opposite: 2,
            vertices: vec![],
        };
        let mut pts = Vec::new();
        for beta in Simplex::new(2, 3).iter() {
            pts.push(match beta[2] {
                0 => a.net.at(beta).to_vec(),
                1 => mu_rule(&a.net, &facet, &lambda, beta),
                _ => r(&["5", "-7", "1"]),
            });
        }
        let b = BezierPatch {
            name: None,
            net: ControlNet::from_points(2, 3, &pts),
            domain: Some(
                Domain::new(vec![r(&["0", "0"]), r(&["1", "0"]), r(&["1", "-1"])]).unwrap(),
            ),
        };
        let j = analyse(&a, &b).unwrap();
        assert!(j.c0 && !j.c1);
        assert_eq!(j.g1, Some(true));
        assert_eq!(j.coplanarity, Some(true));
    }

    #[test]
    fn shared_edge_in_any_order_and_errors() {
        let t = Domain::new(vec![r(&["0", "0"]), r(&["1", "0"]), r(&["0", "1"])]).unwrap();
        let u = Domain::new(vec![r(&["1", "0"]), r(&["1", "-1"]), r(&["0", "0"])]).unwrap();
        let f = shared_facet(&t, &u).unwrap();
        assert_eq!(
            (f.a.clone(), f.b.clone(), f.a_opposite, f.b_opposite),
            (vec![0, 1], vec![2, 0], 2, 1)
        );
        let far = Domain::new(vec![r(&["5", "5"]), r(&["6", "5"]), r(&["5", "6"])]).unwrap();
        assert!(
            shared_facet(&t, &far)
                .unwrap_err()
                .to_string()
                .contains("share no edge")
        );
        assert!(
            shared_facet(&t, &t)
                .unwrap_err()
                .to_string()
                .contains("same simplex")
        );
    }

    #[test]
    fn mu_rule_is_row_one_of_the_blossom_extension() {
        let a = patch(
            3,
            &[
                &["0"],
                &["1"],
                &["5"],
                &["2"],
                &["7"],
                &["-3"],
                &["4"],
                &["1/2"],
                &["9"],
                &["6"],
            ],
            &[&["0", "0"], &["3", "1"], &["1", "2"]],
        );
        let mu = r(&["3/4", "11/12", "-2/3"]);
        let facet = SharedFacet {
            a: vec![0, 1],
            b: vec![0, 1],
            a_opposite: 2,
            b_opposite: 2,
            vertices: vec![],
        };
        let ext = Extension::new(&a.net, &mu);
        for beta in Simplex::new(2, 3).iter().filter(|b| b[2] == 1) {
            assert_eq!(mu_rule(&a.net, &facet, &mu, beta), ext.point(&facet, beta));
        }
    }

    fn small() -> impl Strategy<Value = Q> {
        (-9i64..=9, 1i64..=4).prop_map(|(a, b)| Q::new(a.into(), b.into()))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(16))]

        /// The C^n extension is C^r for every r (max_smoothness = n); perturbing row ρ of it
        /// gives exactly C^{ρ−1}.
        #[test]
        fn extension_is_cn_and_perturbation_lowers_it(
            n in 1usize..=4,
            coords in proptest::collection::vec(small(), 45),
            x in 1i64..=5, y in 1i64..=5, rho_pick in 0usize..10, delta in 1i64..=3,
        ) {
            let len = crate::simplex::count(2, n) * 3;
            let net = ControlNet::new(Simplex::new(2, n), 3, coords[..len].to_vec());
            let a = BezierPatch { name: None, net, domain: Some(Domain::new(vec![r(&["0", "0"]), r(&["4", "1"]), r(&["1", "3"])]).unwrap()) };
            // a new vertex below the edge a1a2 (the line y = x/4)
            let v = vec![Q::from_integer(x.into()), Q::from_integer((-y).into())];
            let b = c1_neighbour(&a, &[0, 1], v).unwrap();
            let j = analyse(&a, &b).unwrap();
            prop_assert_eq!(j.max_smoothness, n as i64);
            prop_assert!(j.c0 && j.c1);
            // independent check: the C^n extension is the same polynomial in x, y (symbolic.rs)
            let (ca, cb) = (cartesian_form(&a.net, a.domain.as_ref().unwrap()), cartesian_form(&b.net, b.domain.as_ref().unwrap()));
            prop_assert_eq!(&ca, &cb);
            prop_assert_eq!(j.g1, Some(j.g1_minors.iter().all(Polynomial::is_zero) && j.violations.is_empty()));
            // the edge polynomials from the derivative net equal those of the symbolic form
            for (i, jj, k) in [(0, 1, 2), (1, 2, 0), (2, 0, 1)] {
                let d = unit_diff(2, k, i);
                prop_assert_eq!(edge_derivative(&a.net, &d, i, jj), edge_derivative_symbolic(&a.net, &d, i, jj));
            }
            let rho = rho_pick % (n + 1);
            let mut pts: Vec<Vec<Q>> = b.net.points().map(<[Q]>::to_vec).collect();
            let k = b.net.simplex().iter().position(|beta| beta[2] as usize == rho).unwrap();
            pts[k][0] += Q::from_integer(delta.into());
            let b2 = BezierPatch { net: ControlNet::from_points(2, n, &pts), ..b };
            let j2 = analyse(&a, &b2).unwrap();
            prop_assert_eq!(j2.max_smoothness, rho as i64 - 1);
            // independent check: the difference of the Cartesian forms has transversal derivatives of
            // order < ρ that vanish on the edge line, and one of order ρ that does not
            let diff = cartesian_form(&b2.net, b2.domain.as_ref().unwrap())[0].sub(&ca[0]);
            let (a1, a2, a4) = (r(&["0", "0"]), r(&["4", "1"]), b2.domain.as_ref().unwrap().vertices()[2].clone());
            let tpar = Polynomial::variable(1, 0);
            let line: Vec<Polynomial> = (0..2).map(|c| Polynomial::constant(1, a1[c].clone()).add(&tpar.scale(&(&a2[c] - &a1[c])))).collect();
            let mut dk = diff;
            for k in 0..=rho {
                let on_edge = dk.compose(&line);
                prop_assert_eq!(on_edge.is_zero(), k < rho, "order {} of {}", k, rho);
                dk = dk.derivative(0).scale(&(&a4[0] - &a1[0])).add(&dk.derivative(1).scale(&(&a4[1] - &a1[1])));
            }
            prop_assert_eq!(j2.violations.iter().filter(|v| matches!(v, Violation::Row { .. })).count(), 1);
        }
    }

    #[test]
    fn g1_undecided_below_d3_and_tetrahedra_join() {
        // scalar patches (d = 1): C^r decided, G1 and coplanarity not
        let t: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "1"]];
        let a = patch(2, &[&["0"], &["1"], &["2"], &["3"], &["1/2"], &["7"]], t);
        let b = c1_neighbour(&a, &[1, 0], r(&["1", "-1"])).unwrap();
        let j = analyse(&a, &b).unwrap();
        assert_eq!((j.max_smoothness, j.g1, j.coplanarity), (2, None, None));
        assert!(j.notes[0].contains("d >= 3"));
        // two tetrahedra sharing a facet: the C^n extension, then a perturbed row 2
        let pts: Vec<Vec<Q>> = (0..crate::simplex::count(3, 2))
            .map(|k| vec![Q::from_integer((k as i64 * 7 % 5 - 2).into())])
            .collect();
        let tet = BezierPatch {
            name: None,
            net: ControlNet::from_points(3, 2, &pts),
            domain: Some(
                Domain::new(vec![
                    r(&["0", "0", "0"]),
                    r(&["2", "0", "0"]),
                    r(&["0", "3", "0"]),
                    r(&["1", "1", "4"]),
                ])
                .unwrap(),
            ),
        };
        let nb = c1_neighbour(&tet, &[0, 1, 2], r(&["1", "1", "-2"])).unwrap();
        let jt = analyse(&tet, &nb).unwrap();
        assert_eq!((jt.max_smoothness, jt.g1), (2, None));
        assert_eq!(jt.facet.a_opposite, 3);
        let mut p2: Vec<Vec<Q>> = nb.net.points().map(<[Q]>::to_vec).collect();
        let last = p2.len() - 1; // the corner 0,0,0,2 (row 2)
        p2[last][0] += Q::one();
        let jt2 = analyse(
            &tet,
            &BezierPatch {
                net: ControlNet::from_points(3, 2, &p2),
                ..nb
            },
        )
        .unwrap();
        assert_eq!(jt2.max_smoothness, 1);
    }

    /// Degree 0 (module doc): equal constants are C^r for every r, and not G1 (no tangent plane);
    /// `c1_neighbour` of a constant is that constant, and `analyse` accepts the pair as C1.
    #[test]
    fn degree_zero_joins_are_decided() {
        let t: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "1"]];
        let u: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "-1"]];
        let a = patch(0, &[&["2", "-1", "5"]], t);
        let b = patch(0, &[&["2", "-1", "5"]], u);
        let j = analyse(&a, &b).unwrap();
        assert!(j.c0 && j.c1);
        assert_eq!(j.max_smoothness, 0);
        assert_eq!((j.g1, j.coplanarity), (Some(false), Some(true)));
        assert!(j.g1_minors.iter().all(Polynomial::is_zero));
        assert_eq!(
            j.violations
                .iter()
                .filter(|v| matches!(v, Violation::G1 { reason, .. } if reason.contains("constant (degree 0)")))
                .count(),
            2
        );
        // the neighbour --make-c1 builds is the same constant, and it is accepted as C1
        let nb = c1_neighbour(&a, &[0, 1], r(&["1", "-1"])).unwrap();
        assert_eq!(
            nb.net.points().next().unwrap(),
            r(&["2", "-1", "5"]).as_slice()
        );
        let jn = analyse(&a, &nb).unwrap();
        assert!(jn.c0 && jn.c1 && jn.max_smoothness == 0);
        // different constants: not even C0
        let c = patch(0, &[&["2", "-1", "6"]], u);
        let jc = analyse(&a, &c).unwrap();
        assert!(!jc.c0 && !jc.c1 && jc.max_smoothness == -1 && jc.g1 == Some(false));
        // scalar constants (d = 1): C^r decided, G1 not (d < 3)
        let s = analyse(&patch(0, &[&["7"]], t), &patch(0, &[&["7"]], u)).unwrap();
        assert!(s.c1 && s.g1.is_none());
    }

    #[test]
    fn mismatches_are_errors() {
        let t: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "1"]];
        let u: &[&[&str]] = &[&["0", "0"], &["1", "0"], &["0", "-1"]];
        let p1 = patch(1, &[&["0"], &["1"], &["2"]], t);
        let p2 = patch(2, &[&["0"], &["1"], &["2"], &["0"], &["1"], &["2"]], u);
        assert!(
            analyse(&p1, &p2)
                .unwrap_err()
                .to_string()
                .contains("degrees 1 and 2")
        );
        // overlapping domains (fourth vertex on the same side): analysed, with a note
        let over = patch(
            1,
            &[&["0"], &["1"], &["5"]],
            &[&["0", "0"], &["1", "0"], &["1", "1"]],
        );
        let j = analyse(&p1, &over).unwrap();
        assert!(
            !j.opposite_sides && j.notes[0].contains("the domains overlap"),
            "{:?}",
            j.notes
        );
        let p3 = patch(1, &[&["0", "1"], &["1", "1"], &["2", "1"]], u);
        assert!(
            analyse(&p1, &p3)
                .unwrap_err()
                .to_string()
                .contains("coordinates")
        );
        // same side: an error for --make-c1
        assert!(
            c1_neighbour(&p1, &[0, 1], r(&["1", "1"]))
                .unwrap_err()
                .to_string()
                .contains("same side")
        );
        // collinear new vertex: degenerate domain
        assert!(matches!(
            c1_neighbour(&p1, &[0, 1], r(&["3", "0"])).unwrap_err(),
            CoreError::DegenerateDomain(_)
        ));
    }
}
