//! A-priori forward error bounds of tribez's float algorithms, and the condition number.
//!
//! **Model** (\[Higham02\] §2.2): round to nearest, unit roundoff ε (2^-53 for f64, 2^-24 for
//! f32), `fl(x op y) = (x op y)(1 + δ)`, `|δ| ≤ ε`, without underflow or overflow;
//! `γ_k = kε / (1 − kε)`, and a product of `k` factors `(1 + δ)^{±1}` is `1 + θ_k` with
//! `|θ_k| ≤ γ_k` (\[Higham02\] Lemma 3.1).
//!
//! **de Casteljau** on the m-simplex (FORMULAS.md §14.1, derived as in \[MP99\] Cor. 3.2; \[MP06\]
//! §3 for the simplex): every step computes `((λ_0 A_0 + λ_1 A_1) + …) + λ_m A_m` left to right,
//! so a term collects at most `m + 1` roundings per level and at most `(m + 1) n` along its path
//! to the apex. The computed value is `Σ_paths c_i · (product of the path's weights) · (1 + θ)`,
//! hence, for any signs of `λ` (the weights' absolute values sum to `B_i(|λ|)`),
//!
//! `|fl(p) − P(λ)| ≤ γ_{(m+1)n} Σ_i |c_i| B^n_i(|λ_0|, …, |λ_m|)`,
//!
//! with `P` the homogeneous form at the exact values of the float inputs (they need not sum to 1).
//! For `λ ≥ 0` this is FORMULAS' `γ_{3n} Σ|c_i|B_i(u,v,w)` on the triangle. Underflow adds at most
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
        assert_eq!(roundings(Algorithm::Casteljau, 2, 3), 9); // γ_{3n}, FORMULAS §14.1
        assert_eq!(roundings(Algorithm::Casteljau, 1, 4), 8); // curves: γ_{2n} \[MP99\]
        assert_eq!(roundings(Algorithm::Bernstein, 2, 3), 10 + 3 + 2 + 2);
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
