//! Exact evaluation without a gcd per operation: homogeneous integer arithmetic.
//!
//! A rational point `λ = (a_0, …, a_m)/D` (common denominator `D`) and a control net whose
//! coordinate `c` is brought to a common denominator `L_c` (`c_α = z_α / L_c`, `z_α ∈ ℤ`) give
//!
//! `p_c(λ) = Σ_α z_α C(n;α) a^α / (L_c · D^n)`,
//!
//! an integer computation followed by one division (one gcd) per coordinate. Both de Casteljau
//! and the Bernstein form run on the integers through the same generic code as everything else
//! ([`crate::casteljau`], [`crate::bernstein`]), and agree exactly.
//!
//! ```
//! use tribez::exact::{Algorithm, ExactEvaluator};
//! use tribez::number::parse_rational as q;
//! use tribez::patch::ControlNet;
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let eval = ExactEvaluator::new(&ControlNet::from_points(2, 2, &pts));
//! let u = [q("1/2").unwrap(), q("1/3").unwrap(), q("1/6").unwrap()];
//! for alg in [Algorithm::Casteljau, Algorithm::Bernstein] {
//!     let p: Vec<String> = eval.evaluate(&u, alg).iter().map(|x| x.to_string()).collect();
//!     assert_eq!(p, ["4/9", "5/9", "29/36"]);
//! }
//! ```

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed};

use crate::patch::ControlNet;
use crate::simplex::multinomial;
use crate::{bernstein, casteljau};

/// Which exact algorithm to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Algorithm {
    /// The tetrahedral de Casteljau scheme on integers.
    Casteljau,
    /// The direct Bernstein form `Σ C(n;α) z_α a^α` on integers.
    Bernstein,
}

/// Bring rationals to a common (least) denominator: `(numerators, D)` with `x_k = a_k / D`.
pub fn common_denominator(xs: &[BigRational]) -> (Vec<BigInt>, BigInt) {
    let d = xs.iter().fold(BigInt::one(), |acc, x| acc.lcm(x.denom()));
    let nums = xs.iter().map(|x| x.numer() * (&d / x.denom())).collect();
    (nums, d)
}

/// A control net prepared once for many exact evaluations.
#[derive(Clone, Debug)]
pub struct ExactEvaluator {
    /// `z_α` per coordinate: the control points times `L_c`.
    integer_net: ControlNet<BigInt>,
    /// `C(n;α) z_α`: the Bernstein form's integer coefficients.
    scaled_net: ControlNet<BigInt>,
    /// `L_c`, the least common denominator of coordinate `c`.
    denominators: Vec<BigInt>,
}

impl ExactEvaluator {
    /// Prepare `net`: one least common denominator per coordinate.
    pub fn new(net: &ControlNet<BigRational>) -> Self {
        let dim = net.dim();
        let denominators: Vec<BigInt> = (0..dim)
            .map(|c| {
                net.points()
                    .fold(BigInt::one(), |acc, p| acc.lcm(p[c].denom()))
            })
            .collect();
        let coords: Vec<BigInt> = net
            .points()
            .flat_map(|p| {
                p.iter()
                    .zip(&denominators)
                    .map(|(x, l)| x.numer() * (l / x.denom()))
            })
            .collect();
        let integer_net = ControlNet::new(net.simplex().clone(), dim, coords);
        let scaled: Vec<BigInt> = integer_net
            .entries()
            .flat_map(|(alpha, p)| {
                let k = BigInt::from(multinomial(alpha));
                p.iter().map(move |z| z * &k).collect::<Vec<_>>()
            })
            .collect();
        let scaled_net = ControlNet::new(net.simplex().clone(), dim, scaled);
        ExactEvaluator {
            integer_net,
            scaled_net,
            denominators,
        }
    }

    /// The homogeneous form `P(λ)` at a rational point (which need not sum to one).
    pub fn evaluate(&self, lambda: &[BigRational], algorithm: Algorithm) -> Vec<BigRational> {
        let (a, d) = common_denominator(lambda);
        let n = self.integer_net.degree();
        let numer = match algorithm {
            Algorithm::Casteljau => casteljau::evaluate(&self.integer_net, &a),
            Algorithm::Bernstein => monomial_sum(&self.scaled_net, &a),
        };
        let dn = num_traits::pow(d, n);
        numer
            .into_iter()
            .zip(&self.denominators)
            .map(|(z, l)| BigRational::new(z, l * &dn))
            .collect()
    }

    /// The integer net `z_α` and its per-coordinate denominators `L_c`.
    pub fn integer_net(&self) -> (&ControlNet<BigInt>, &[BigInt]) {
        (&self.integer_net, &self.denominators)
    }
}

/// `Σ_α s_α a^α` per coordinate, the integer Bernstein sum with the multinomials already folded
/// into `s_α` (so `bernstein::basis` is called with unit coefficients avoided).
fn monomial_sum(scaled: &ControlNet<BigInt>, a: &[BigInt]) -> Vec<BigInt> {
    let n = scaled.degree();
    let pw: Vec<Vec<BigInt>> = a
        .iter()
        .map(|x| {
            let mut v = vec![BigInt::one()];
            for e in 1..=n {
                let next = &v[e - 1] * x;
                v.push(next);
            }
            v
        })
        .collect();
    let monomials: Vec<BigInt> = scaled
        .simplex()
        .iter()
        .map(|alpha| {
            alpha
                .iter()
                .enumerate()
                .fold(BigInt::one(), |acc, (k, &e)| acc * &pw[k][e as usize])
        })
        .collect();
    (0..scaled.dim())
        .map(|c| {
            monomials
                .iter()
                .zip(scaled.points())
                .map(|(mono, p)| mono * &p[c])
                .sum()
        })
        .collect()
}

/// Exact evaluation of a rational net by the generic algorithms on rationals (gcd after every
/// operation). The reference the fast paths are tested against; slow.
pub fn evaluate_rational(
    net: &ControlNet<BigRational>,
    lambda: &[BigRational],
    algorithm: Algorithm,
) -> Vec<BigRational> {
    match algorithm {
        Algorithm::Casteljau => casteljau::evaluate(net, lambda),
        Algorithm::Bernstein => bernstein::evaluate(net, lambda),
    }
}

/// Sum of |x| over a slice (used for condition numbers).
pub fn abs_sum(xs: &[BigRational]) -> BigRational {
    xs.iter().map(Signed::abs).sum()
}
