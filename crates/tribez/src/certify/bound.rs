//! A-priori forward error bounds of tribez's float algorithms, and the condition number.
//!
//! **Model** (\[Higham02\] §2.2): round to nearest, unit roundoff ε (2^-53 for f64, 2^-24 for
//! f32), `fl(x op y) = (x op y)(1 + δ)`, `|δ| ≤ ε`, without underflow or overflow;
//! `γ_k = kε / (1 − kε)`, and a product of `k` factors `(1 + δ)^{±1}` is `1 + θ_k` with
//! `|θ_k| ≤ γ_k` (\[Higham02\] Lemma 3.1).
//!
//! **de Casteljau** on the m-simplex (docs/theory.md §14.1, derived as in \[MP99\] Cor. 3.2; \[MP06\]
//! §3 for the simplex): every step computes `((λ_0 A_0 + λ_1 A_1) + …) + λ_m A_m` left to right,
//! so a term collects at most `m + 1` roundings per level and at most `(m + 1) n` along its path
//! to the apex. The computed value is `Σ_paths c_i · (product of the path's weights) · (1 + θ)`,
//! hence, for any signs of `λ` (the weights' absolute values sum to `B_i(|λ|)`),
//!
//! `|fl(p) − P(λ)| ≤ γ_{(m+1)n} Σ_i |c_i| B^n_i(|λ_0|, …, |λ_m|)`,
//!
//! with `P` the homogeneous form at the exact values of the float inputs (they need not sum to 1).
//! For `λ ≥ 0` this is the theory reference's `γ_{3n} Σ|c_i|B_i(u,v,w)` on the triangle. Underflow adds at most
//! `η` (2^-1075 or 2^-150) per product (\[Higham02\] (2.8)); those absolute errors are carried to
//! the apex by the later steps with weight at most `s = Σ|λ_k|` per level, so we add
//! `2 (m+1) η Σ_{j<n} s^j` (the factor 2 covers the roundings of the carrying steps).
//!
//! **Direct Bernstein form** ([`crate::bernstein::evaluate`]): `b_α = C(n;α)` rounded once (exact
//! below 2^53 resp. 2^24), multiplied by `λ_0^{α_0}, …, λ_m^{α_m}` (`m + 1` products; the power
//! `λ^e` is computed by `e − 1` roundings), times `c_α` (one product), then the `N = C(n+m, m)`
//! terms are added left to right (recursive summation: the first term sees `N − 1` roundings,
//! \[Higham02\] §4.2). Every term is therefore `c_α B_α(λ)(1 + θ_K)` with
//! `K = 1 + (m + 1) + n + 1 + (N − 1) = N + n + m + 2`, and
//!
//! `|fl(p) − P(λ)| ≤ γ_{N+n+m+2} Σ_α |c_α| B_α(|λ|)`   (no underflow or overflow).
//!
//! We derived this bound ourselves from the standard model (it is not quoted from a paper); the
//! certification test checks it numerically. Underflow is **not** covered for this form: a
//! product chain can underflow and then be multiplied by a large control value, so a case whose
//! terms come near the underflow threshold is reported as outside the bound's hypothesis rather
//! than judged.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::exact::{Algorithm, ExactEvaluator};
use crate::float::Precision;
use crate::number::pow2;
use crate::patch::ControlNet;
use crate::simplex::count;

/// `γ_k = kε/(1 − kε)` exactly; `None` when `kε ≥ 1` (no bound).
pub fn gamma(k: usize, p: Precision) -> Option<BigRational> {
    let ke = BigRational::from_integer(k.into()) * pow2(i64::from(p.unit_roundoff_log2()));
    (ke < BigRational::one()).then(|| &ke / (BigRational::one() - &ke))
}

/// The number of roundings `K` in the bound `γ_K Σ|c_i|B_i(|λ|)` of `algorithm` on a degree-`n`
/// patch over the m-simplex: `(m+1)n` for de Casteljau, `N + n + m + 2` for the Bernstein form.
pub fn roundings(algorithm: Algorithm, m: usize, n: usize) -> usize {
    match algorithm {
        Algorithm::Casteljau => (m + 1) * n,
        Algorithm::Bernstein => count(m, n) + n + m + 2,
    }
}

/// The condition number of each coordinate: `Σ_i |c_i| B_i(|λ_0|, …, |λ_m|)` (exact; \[FR87\]).
pub fn condition(net: &ControlNet<BigRational>, lambda: &[BigRational]) -> Vec<BigRational> {
    let abs_net = net.map(Signed::abs);
    let abs_lambda: Vec<BigRational> = lambda.iter().map(Signed::abs).collect();
    ExactEvaluator::new(&abs_net).evaluate_fast(&abs_lambda)
}

/// The a-priori absolute error bound of `algorithm` in precision `p` at one coordinate with
/// condition number `condition` (see the module documentation). `lambda` are the exact values
/// of the float inputs. `None` when `Kε ≥ 1`.
pub fn a_priori(
    algorithm: Algorithm,
    p: Precision,
    m: usize,
    n: usize,
    condition: &BigRational,
    lambda: &[BigRational],
) -> Option<BigRational> {
    let g = gamma(roundings(algorithm, m, n), p)?;
    let mut b = g * condition;
    if algorithm == Algorithm::Casteljau && n > 0 {
        let eta = match p {
            Precision::F64 => pow2(-1075),
            Precision::F32 => pow2(-150),
        };
        let s: BigRational = lambda.iter().map(Signed::abs).sum();
        let mut geometric = BigRational::zero();
        let mut power = BigRational::one();
        for _ in 0..n {
            geometric += &power;
            power *= &s;
        }
        b += BigRational::from_integer((2 * (m + 1)).into()) * eta * geometric;
    }
    Some(b)
}

/// The double rounding threshold `η` (2^-1075 for f64, 2^-150 for f32): the largest absolute
/// error of one rounding in the subnormal range (\[Higham02\] (2.8)).
pub fn eta(p: Precision) -> BigRational {
    match p {
        Precision::F64 => pow2(-1075),
        Precision::F32 => pow2(-150),
    }
}

/// The unit roundoff `ε` exactly.
pub fn epsilon(p: Precision) -> BigRational {
    pow2(i64::from(p.unit_roundoff_log2()))
}

/// **Rational patches** (homogeneous de Casteljau, one division): the a-posteriori bound of
/// `tribez certify`.
///
/// *Inputs as the code saw them.* The float code ([`crate::rational::RationalPatch::evaluate_float`])
/// rounds the homogeneous net once: `â_i = RN(w_i c_i)` (each coordinate of the exact product
/// rounded) and `ŵ_i = RN(w_i)`, and takes the float point `λ̂`. Everything below is about the
/// exact values of these floats: `N(λ̂) = Σ â_i B_i(λ̂)` (per coordinate), `D(λ̂) = Σ ŵ_i B_i(λ̂)`,
/// and `q = N/D`, the exact value the code should produce.
///
/// *Numerator and denominator.* The code runs de Casteljau on the `(d+1)`-dimensional net
/// `(â_i, ŵ_i)`, so §14.1 (module documentation, [`a_priori`]) bounds each computed coordinate:
/// `|N̂ − N| ≤ e_N = γ_K Σ|â_i| B_i(|λ̂|)` and `|D̂ − D| ≤ e_D = γ_K Σ|ŵ_i| B_i(|λ̂|)`,
/// `K = (m+1)n` (plus the underflow term of [`a_priori`]).
///
/// *The quotient.* If `|D̂| > e_D`, then `D ≠ 0` and has the sign of `D̂`, and the identity
/// `N̂/D̂ − N/D = (N̂ − N)/D̂ − q (D̂ − D)/D̂` gives
///
/// `|N̂/D̂ − q| ≤ (e_N + |q| e_D) / |D̂|`.
///
/// *The division.* `ŷ = fl(N̂/D̂)` is `x(1 + δ)` with `|δ| ≤ ε`, or (subnormal result) `x + η'`
/// with `|η'| ≤ η`, where `x = N̂/D̂`. In the first case `x = ŷ/(1 + δ)`, so
/// `|ŷ − x| = |δ| |ŷ| / |1 + δ| ≤ ε |ŷ| / (1 − ε)`; in the second `|ŷ − x| ≤ η`. Hence
///
/// `|ŷ − q| ≤ (e_N + |q| e_D)/|D̂| + ε|ŷ|/(1 − ε) + η`.
///
/// Returns `None` when `|D̂| ≤ e_D` (the sign of the denominator is not certain: outside the
/// hypothesis) or when `Kε ≥ 1`. `e_num` are the bounds `e_N` per coordinate, `e_den` is `e_D`,
/// `q` the exact values, `d_hat` the computed denominator and `y_hat` the computed quotients.
pub fn rational_a_posteriori(
    p: Precision,
    e_num: &[BigRational],
    e_den: &BigRational,
    q: &[BigRational],
    d_hat: &BigRational,
    y_hat: &[BigRational],
) -> Option<Vec<BigRational>> {
    let dabs = d_hat.abs();
    if dabs <= *e_den {
        return None;
    }
    let eps = epsilon(p);
    let div = &eps / (BigRational::one() - &eps);
    let eta = eta(p);
    Some(
        e_num
            .iter()
            .zip(q)
            .zip(y_hat)
            .map(|((en, qc), yc)| (en + qc.abs() * e_den) / &dabs + &div * yc.abs() + &eta)
            .collect(),
    )
}

/// **Rational patches**: the a-priori form of the same bound, for claims (which give the
/// quotient `ŷ` but not the computed denominator `D̂`). With `D = D(λ̂)` exact and `|D| > e_D`,
/// `|D̂| ≥ |D| − e_D > 0`, so `E_1 = (e_N + |q| e_D)/(|D| − e_D)` bounds `|N̂/D̂ − q|`, hence
/// `|N̂/D̂| ≤ |q| + E_1` and the division adds at most `ε(|q| + E_1) + η`:
///
/// `|ŷ − q| ≤ E_1 + ε(|q| + E_1) + η`.
///
/// `None` when `|D| ≤ e_D`.
pub fn rational_a_priori(
    p: Precision,
    e_num: &[BigRational],
    e_den: &BigRational,
    q: &[BigRational],
    d: &BigRational,
) -> Option<Vec<BigRational>> {
    let gap = d.abs() - e_den;
    if !gap.is_positive() {
        return None;
    }
    let eps = epsilon(p);
    let eta = eta(p);
    Some(
        e_num
            .iter()
            .zip(q)
            .map(|(en, qc)| {
                let e1 = (en + qc.abs() * e_den) / &gap;
                &e1 + &eps * (qc.abs() + &e1) + &eta
            })
            .collect(),
    )
}

/// The condition number of a rational patch's coordinate `c` at `λ` (with respect to relative
/// perturbations of the homogeneous net, the analogue of `Σ|c_i|B_i(|λ|)`):
///
/// `κ_c = (Σ|â_{i,c}| B_i(|λ|) + |q_c| Σ|ŵ_i| B_i(|λ|)) / |D(λ)|`,
///
/// so that the bound above is `γ_K κ_c · |D|/|D̂|` plus the division's rounding; `cond=K` on a
/// rational claim means `|ŷ − q| ≤ K ε κ_c`. `None` when `D(λ) = 0`. `homogeneous` is the net
/// `(â_i, ŵ_i)` (weight last).
pub fn rational_condition(
    homogeneous: &ControlNet<BigRational>,
    lambda: &[BigRational],
) -> Option<Vec<BigRational>> {
    let h = ExactEvaluator::new(homogeneous).evaluate(lambda, Algorithm::Casteljau);
    let (d, n) = h.split_last()?;
    if d.is_zero() {
        return None;
    }
    let cond = condition(homogeneous, lambda);
    let (cd, cn) = cond.split_last()?;
    Some(
        n.iter()
            .zip(cn)
            .map(|(nc, cc)| (cc + (nc / d).abs() * cd) / d.abs())
            .collect(),
    )
}

/// **S-patches, the float Wachspress coordinates** ([`crate::spatch::wachspress_float`]): a
/// relative bound `θ` with `|λ̂_i − λ_i| ≤ θ λ_i` for every `i`, where `λ_i` are the exact
/// Wachspress coordinates of the float point `p̂` in the float polygon (the inputs as the code saw
/// them), and the term it adds to a polynomial evaluated at `λ̂` instead of `λ`.
///
/// *Areas.* `cross(a, b, c) = (b_0 − a_0)(c_1 − a_1) − (b_1 − a_1)(c_0 − a_0)` passes each of its
/// two products `t_1, t_2` through four roundings (two differences, the product, the final
/// subtraction), so `|x̂ − x| ≤ γ_4 (|t_1| + |t_2|)` and the relative error is `ρ = γ_4(|t_1| + |t_2|)/x`
/// for `x > 0`: the areas `A_j = cross(p̂, v_j, v_{j+1})` (positive strictly inside) and
/// `C_i = cross(v_{i−1}, v_i, v_{i+1})` (positive for a strictly convex counter-clockwise polygon).
///
/// *Weights.* `ω̂_i = C_i Π_{j ∉ {i−1, i}} A_j` by `N − 2` more products: `ω̂_i = ω_i (1 + r_i)` with
/// `|r_i| ≤ R_i = (1 + ρ_{C_i}) Π_j (1 + ρ_{A_j}) (1 + ε)^{N−2} − 1`.
///
/// *Sum and quotients.* The sum of the `N` positive weights, left to right, is
/// `Ŝ = S (1 + r_S)` with `|r_S| ≤ R_S = (1 + max R_i)(1 + γ_{N−1}) − 1`, and
/// `λ̂_i = fl(ω̂_i / Ŝ) = λ_i (1 + r_i)(1 + δ)/(1 + r_S)`, so `λ̂_i/λ_i` lies in
/// `[(1 − R_i)(1 − ε)/(1 + R_S), (1 + R_i)(1 + ε)/(1 − R_S)]`; `θ` is the largest distance of these
/// ends from 1.
///
/// *Hypotheses, checked here.* `p̂` strictly inside (every `A_j > 0`), no underflow: every exact
/// product, partial product, weight and coordinate is 0 or at least `4 · 2^{e_min}` (the smallest
/// normal), which with every `R < 1/2` keeps each rounded operation's exact result normal.
/// `None` otherwise, or when `θ ≥ 1/2`.
pub fn wachspress_relative(
    p: Precision,
    vertices: &[[BigRational; 2]],
    point: &[BigRational; 2],
) -> Option<BigRational> {
    let eps = epsilon(p);
    let one = BigRational::one();
    let half = BigRational::new(1.into(), 2.into());
    let tiny = pow2(match p {
        Precision::F64 => -1020,
        Precision::F32 => -124,
    });
    let normal = |x: &BigRational| x.is_zero() || x.abs() >= tiny;
    let g4 = gamma(4, p)?;
    // (value, relative bound) of cross(a, b, c), None if not positive or underflowing
    let cross = |a: &[BigRational; 2], b: &[BigRational; 2], c: &[BigRational; 2]| {
        let t1 = (&b[0] - &a[0]) * (&c[1] - &a[1]);
        let t2 = (&b[1] - &a[1]) * (&c[0] - &a[0]);
        let x = &t1 - &t2;
        (x.is_positive() && normal(&t1) && normal(&t2))
            .then(|| (g4.clone() * (t1.abs() + t2.abs()) / &x, x))
    };
    let n = vertices.len();
    let areas: Vec<(BigRational, BigRational)> = (0..n)
        .map(|j| cross(point, &vertices[j], &vertices[(j + 1) % n]).map(|(r, x)| (x, r)))
        .collect::<Option<_>>()?;
    let mut weights = Vec::with_capacity(n);
    let mut rel = Vec::with_capacity(n);
    for i in 0..n {
        let prev = (i + n - 1) % n;
        let (rc, c) = cross(&vertices[prev], &vertices[i], &vertices[(i + 1) % n])?;
        let mut w = c;
        let mut factor = &one + rc;
        for j in (0..n).filter(|&j| j != prev && j != i) {
            w *= &areas[j].0;
            if !normal(&w) {
                return None;
            }
            factor *= &one + &areas[j].1;
            factor *= &one + &eps;
        }
        let r = factor - &one;
        if r >= half {
            return None;
        }
        weights.push(w);
        rel.push(r);
    }
    let sum: BigRational = weights.iter().sum();
    let r_max = rel.iter().max()?.clone();
    let r_sum = (&one + &r_max) * (&one + gamma(n - 1, p)?) - &one;
    if r_sum >= half {
        return None;
    }
    let mut theta = BigRational::zero();
    for (w, r) in weights.iter().zip(&rel) {
        if !normal(&(w / &sum)) {
            return None;
        }
        let hi = (&one + r) * (&one + &eps) / (&one - &r_sum) - &one;
        let lo = &one - (&one - r) * (&one - &eps) / (&one + &r_sum);
        theta = theta.max(hi).max(lo);
    }
    (theta < half).then_some(theta)
}

/// The extra error of a degree-`n` polynomial evaluated at coordinates `λ̂` with
/// `|λ̂_i − λ_i| ≤ θ λ_i` (`λ ≥ 0`), as a multiple of `Σ|P_α| B_α(λ̂)`:
/// `|P(λ̂) − P(λ)| ≤ Σ|P_α| C(n;α) λ^α |Π(1 + θ_i)^{α_i} − 1| ≤ ((1 + θ)^n − 1) Σ|P_α|B_α(λ)`, and
/// `B_α(λ) ≤ B_α(λ̂)/(1 − θ)^n`, so the factor is `((1 + θ)^n − 1)/(1 − θ)^n`.
pub fn coordinate_factor(theta: &BigRational, n: usize) -> BigRational {
    let one = BigRational::one();
    let up = num_traits::pow(&one + theta, n);
    let down = num_traits::pow(&one - theta, n);
    (up - &one) / down
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational as q;

    #[test]
    fn gamma_values() {
        // γ_1 = ε/(1-ε) = 1/(2^53 - 1)
        assert_eq!(
            gamma(1, Precision::F64).unwrap(),
            q("1/9007199254740991").unwrap()
        );
        assert_eq!(gamma(9, Precision::F32).unwrap(), q("9/16777207").unwrap());
        assert!(gamma(1 << 24, Precision::F32).is_none());
    }

    #[test]
    fn rounding_counts() {
        assert_eq!(roundings(Algorithm::Casteljau, 2, 3), 9); // γ_{3n}, docs/theory.md §14.1
        assert_eq!(roundings(Algorithm::Casteljau, 1, 4), 8); // curves: γ_{2n} \[MP99\]
        assert_eq!(roundings(Algorithm::Bernstein, 2, 3), 10 + 3 + 2 + 2);
    }

    #[test]
    fn wachspress_bound_holds_and_needs_the_interior() {
        // The unit triangle (N = 3): Wachspress coordinates are the barycentric ones
        // (1 − x − y, x, y). At float points the float coordinates lie within θ of the exact ones.
        let r = |t: &str| q(t).unwrap();
        let tri = [[r("0"), r("0")], [r("1"), r("0")], [r("0"), r("1")]];
        let tri_f = [[0.0f64, 0.0], [1.0, 0.0], [0.0, 1.0]];
        for (x, y) in [
            (0.1f64, 0.2f64),
            (1e-3, 0.7),
            (0.333, 0.333),
            (1e-12, 1e-12),
        ] {
            let p = [
                crate::number::exact_f64(x).unwrap(),
                crate::number::exact_f64(y).unwrap(),
            ];
            let theta = wachspress_relative(Precision::F64, &tri, &p).unwrap();
            let got = crate::spatch::wachspress_float(&tri_f, &[x, y]);
            let exact = [
                BigRational::one() - &p[0] - &p[1],
                p[0].clone(),
                p[1].clone(),
            ];
            for (g, e) in got.iter().zip(&exact) {
                let err = (crate::number::exact_f64(*g).unwrap() - e).abs();
                assert!(err <= &theta * e, "at ({x}, {y}): {err} > θ {theta} · {e}");
            }
        }
        // on an edge a coordinate is 0 and no relative bound exists; outside the polygon neither
        assert!(wachspress_relative(Precision::F64, &tri, &[r("1/2"), r("0")]).is_none());
        assert!(wachspress_relative(Precision::F64, &tri, &[r("1"), r("1")]).is_none());
        // the polynomial factor: ((1+θ)^n − 1)/(1−θ)^n, e.g. θ = 1/10, n = 2: (21/100)/(81/100)
        assert_eq!(coordinate_factor(&r("1/10"), 2), r("7/27"));
    }

    #[test]
    fn rational_bounds_by_hand() {
        let r = |t: &str| q(t).unwrap();
        // (e_N + |q| e_D)/|D̂| + ε|ŷ|/(1−ε) + η with e_N = 1/100, e_D = 1/1000, q = −2, D̂ = −1/2, ŷ = 3
        let b = rational_a_posteriori(
            Precision::F64,
            &[r("1/100")],
            &r("1/1000"),
            &[r("-2")],
            &r("-1/2"),
            &[r("3")],
        )
        .unwrap();
        assert_eq!(
            b[0],
            r("24/1000") + r("3/9007199254740991") + crate::number::pow2(-1075)
        );
        // |D̂| ≤ e_D: the denominator's sign is not certain, no bound
        assert!(
            rational_a_posteriori(
                Precision::F64,
                &[r("1")],
                &r("1"),
                &[r("0")],
                &r("1"),
                &[r("0")]
            )
            .is_none()
        );
        // a priori: E1 = (1/100 + 2/1000)/(1/2 − 1/1000), then + ε(2 + E1) + η
        let e1 = r("12/1000") / r("499/1000");
        let a = rational_a_priori(
            Precision::F32,
            &[r("1/100")],
            &r("1/1000"),
            &[r("2")],
            &r("1/2"),
        )
        .unwrap();
        assert_eq!(
            a[0],
            &e1 + crate::number::pow2(-24) * (r("2") + &e1) + crate::number::pow2(-150)
        );
        assert!(
            rational_a_priori(Precision::F32, &[r("0")], &r("1"), &[r("0")], &r("-1")).is_none()
        );
    }

    #[test]
    fn rational_condition_by_hand() {
        // m = 1, n = 1: (w c, w) = (1, 1), (−4, 2) at λ = (1/2, 1/2): N = −3/2, D = 3/2, q = −1,
        // Σ|wc|B = 5/2, Σ|w|B = 3/2, κ = (5/2 + 3/2)/(3/2) = 8/3
        let net = ControlNet::from_points(
            1,
            1,
            &[
                vec![q("1").unwrap(), q("1").unwrap()],
                vec![q("-4").unwrap(), q("2").unwrap()],
            ],
        );
        let half = q("1/2").unwrap();
        assert_eq!(
            rational_condition(&net, &[half.clone(), half]).unwrap(),
            vec![q("8/3").unwrap()]
        );
        // D = 0 at λ = (2, −1): 2·1 − 1·2 = 0
        assert!(rational_condition(&net, &[q("2").unwrap(), q("-1").unwrap()]).is_none());
    }

    #[test]
    fn condition_uses_absolute_values() {
        // Linear patch with c = (1, -2, 3) at λ = (2, -1/2, -1/2): Σ|c_i||λ_i| = 2 + 1 + 3/2.
        let net = ControlNet::from_points(
            2,
            1,
            &[
                vec![q("1").unwrap()],
                vec![q("-2").unwrap()],
                vec![q("3").unwrap()],
            ],
        );
        let lam = [q("2").unwrap(), q("-1/2").unwrap(), q("-1/2").unwrap()];
        assert_eq!(condition(&net, &lam), vec![q("9/2").unwrap()]);
    }
}
