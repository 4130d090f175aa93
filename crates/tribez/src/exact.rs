//! Exact evaluation without a gcd per operation: homogeneous integer arithmetic.
//!
//! A rational point `λ = (a_0, …, a_m)/D` (common denominator `D`) and a control net whose
//! coordinate `c` is brought to a common denominator `L_c` (`c_α = z_α / L_c`, `z_α ∈ ℤ`) give
//!
//! `p_c(λ) = Σ_α z_α C(n;α) a^α / (L_c · D^n)`,
//!
//! an integer computation followed by one division (one gcd) per coordinate. Both de Casteljau
//! and the Bernstein form run on the integers through the same generic code as everything else
//! ([`crate::casteljau`], [`crate::bernstein`]), and agree exactly. [`ExactEvaluator::evaluate_fast`] is the
//! fast kernel (nested homogeneous Horner on machine-word limbs, row-scaled for triangles, a
//! gcd-free reduction; see `src/exact/kernel.rs`), property-tested equal to
//! [`evaluate_rational`]; it is what `tribez eval` and the claims use.
//!
//! ```
//! use tribez::hazmat::exact::{Algorithm, ExactEvaluator};
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::ControlNet;
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let eval = ExactEvaluator::new(&ControlNet::from_points(2, 2, &pts));
//! let u = [q("1/2").unwrap(), q("1/3").unwrap(), q("1/6").unwrap()];
//! assert_eq!(eval.evaluate_fast(&u).iter().map(|x| x.to_string()).collect::<Vec<_>>(), ["4/9", "5/9", "29/36"]);
//! for alg in [Algorithm::Casteljau, Algorithm::Bernstein] {
//!     let p: Vec<String> = eval.evaluate(&u, alg).iter().map(|x| x.to_string()).collect();
//!     assert_eq!(p, ["4/9", "5/9", "29/36"]);
//! }
//! ```

use std::sync::OnceLock;

use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed};
use rayon::prelude::*;

use crate::patch::ControlNet;
use crate::simplex::multinomial;
use crate::{bernstein, casteljau};

mod kernel;
mod limbs;

pub use kernel::word_point;

/// Which exact algorithm to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Algorithm {
    /// The tetrahedral de Casteljau scheme on integers.
    Casteljau,
    /// The direct Bernstein form `Σ C(n;α) z_α a^α` on integers.
    Bernstein,
}

impl Algorithm {
    /// The name written in claim files and on the command line: `"casteljau"`, `"bernstein"`.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Casteljau => "casteljau",
            Algorithm::Bernstein => "bernstein",
        }
    }
}

/// A text that is not an algorithm's name (`"casteljau"` or `"bernstein"`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown algorithm `{text}` (known: casteljau, bernstein)")]
pub struct ParseAlgorithmError {
    /// The text.
    pub text: String,
}

/// `"casteljau"` or `"bernstein"`, and [`Display`](std::fmt::Display) writes them back.
///
/// ```
/// use tribez::Algorithm;
/// assert_eq!("bernstein".parse::<Algorithm>().unwrap(), Algorithm::Bernstein);
/// assert_eq!(Algorithm::Casteljau.to_string(), "casteljau");
/// assert_eq!(
///     "horner".parse::<Algorithm>().unwrap_err().to_string(),
///     "unknown algorithm `horner` (known: casteljau, bernstein)"
/// );
/// ```
impl std::str::FromStr for Algorithm {
    type Err = ParseAlgorithmError;
    fn from_str(s: &str) -> Result<Self, ParseAlgorithmError> {
        match s {
            "casteljau" => Ok(Algorithm::Casteljau),
            "bernstein" => Ok(Algorithm::Bernstein),
            _ => Err(ParseAlgorithmError { text: s.into() }),
        }
    }
}

impl std::fmt::Display for Algorithm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
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
    /// The control net as given (the integer nets are built from it when first needed).
    net: ControlNet<BigRational>,
    /// `z_α` and `C(n;α) z_α`, built on first use by the generic paths when the fast kernel did
    /// not need them (a triangle at high degree needs neither: its row form is built from the
    /// rational net directly).
    nets: OnceLock<IntegerNets>,
    /// `L_c`, the least common denominator of coordinate `c`.
    denominators: Vec<BigInt>,
    /// The per-patch data of the fast Horner kernel.
    fast: kernel::FastNet,
}

/// The integer forms of a control net over its denominators `L_c`.
#[derive(Clone, Debug)]
struct IntegerNets {
    /// `z_α` per coordinate: the control points times `L_c`.
    integer: ControlNet<BigInt>,
    /// `C(n;α) z_α`: the Bernstein form's integer coefficients.
    scaled: ControlNet<BigInt>,
    /// `C(n;α)` by rank.
    multinomials: Vec<BigUint>,
}

impl IntegerNets {
    /// `z_α = c_α L_c` and `C(n;α) z_α`, point by point on all cores (the serial part of a whole
    /// run at high degrees otherwise).
    fn new(net: &ControlNet<BigRational>, denominators: &[BigInt]) -> Self {
        let dim = net.dim();
        let alphas: Vec<&[u32]> = net.simplex().iter().collect();
        let points: Vec<&[BigRational]> = net.points().collect();
        let multinomials: Vec<BigUint> = alphas.par_iter().map(|a| multinomial(a)).collect();
        let (coords, scaled): (Vec<Vec<BigInt>>, Vec<Vec<BigInt>>) = points
            .par_iter()
            .zip(&multinomials)
            .map(|(p, mult)| {
                let k = BigInt::from(mult.clone());
                p.iter()
                    .zip(denominators)
                    .map(|(x, l)| {
                        let z = x.numer() * kernel::div_exact(l, x.denom());
                        let s = &z * &k;
                        (z, s)
                    })
                    .unzip()
            })
            .unzip();
        IntegerNets {
            integer: ControlNet::new(
                net.simplex().clone(),
                dim,
                coords.into_iter().flatten().collect(),
            ),
            scaled: ControlNet::new(
                net.simplex().clone(),
                dim,
                scaled.into_iter().flatten().collect(),
            ),
            multinomials,
        }
    }

    fn as_kernel_input(&self) -> kernel::IntegerNetsRef<'_> {
        (&self.scaled, &self.integer, &self.multinomials)
    }
}

impl ExactEvaluator {
    /// Prepare `net`: one least common denominator per coordinate.
    pub fn new(net: &ControlNet<BigRational>) -> Self {
        let dim = net.dim();
        let factored: Vec<Option<kernel::Factors>> = (0..dim)
            .into_par_iter()
            .map(|c| kernel::Factors::of(net.points().map(|p| p[c].denom())))
            .collect();
        let denominators: Vec<BigInt> = factored
            .iter()
            .enumerate()
            .map(|(c, f)| match f {
                Some(f) => BigInt::from(f.product()),
                None => kernel::lcm_fold(&BigInt::one(), net.points().map(|p| p[c].denom())),
            })
            .collect();
        let nets = if kernel::FastNet::needs_integer_nets(net, &denominators) {
            OnceLock::from(IntegerNets::new(net, &denominators))
        } else {
            OnceLock::new()
        };
        let fast = kernel::FastNet::new(
            net,
            nets.get().map(IntegerNets::as_kernel_input),
            &denominators,
            factored,
        );
        ExactEvaluator {
            net: net.clone(),
            nets,
            denominators,
            fast,
        }
    }

    /// The integer nets, built now if the kernel did not need them.
    fn nets(&self) -> &IntegerNets {
        self.nets
            .get_or_init(|| IntegerNets::new(&self.net, &self.denominators))
    }

    /// The homogeneous form `P(λ)` at a rational point (which need not sum to one), by the fast
    /// kernel: nested homogeneous Horner on machine-word limbs with the multinomial-scaled integer
    /// control points precomputed once per patch (row by row for triangles), and a reduction to
    /// lowest terms that uses the known prime factors of the denominators (src/exact/kernel.rs).
    /// Points whose homogeneous coordinates are negative or do not fit a machine word fall back
    /// to [`Algorithm::Bernstein`]. Equal to `evaluate_rational` (property-tested).
    pub fn evaluate_fast(&self, lambda: &[BigRational]) -> Vec<BigRational> {
        match word_point(lambda) {
            Some((a, d)) => self.fast.evaluate(&a, d),
            None => self.evaluate(lambda, Algorithm::Bernstein),
        }
    }

    /// The homogeneous form `P(λ)` at a rational point (which need not sum to one).
    pub fn evaluate(&self, lambda: &[BigRational], algorithm: Algorithm) -> Vec<BigRational> {
        let (a, d) = common_denominator(lambda);
        let n = self.net.degree();
        let nets = self.nets();
        let numer = match algorithm {
            Algorithm::Casteljau => casteljau::evaluate(&nets.integer, &a),
            Algorithm::Bernstein => monomial_sum(&nets.scaled, &a),
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
        (&self.nets().integer, &self.denominators)
    }
}

/// `[1, x, x², …, xⁿ]`.
pub(crate) fn powers(x: &BigInt, n: usize) -> Vec<BigInt> {
    let mut v = Vec::with_capacity(n + 1);
    v.push(BigInt::one());
    for e in 1..=n {
        let next = &v[e - 1] * x;
        v.push(next);
    }
    v
}

/// `Σ_α s_α a^α` per coordinate, the integer Bernstein sum with the multinomials already folded
/// into `s_α` (so `bernstein::basis` is called with unit coefficients avoided).
fn monomial_sum(scaled: &ControlNet<BigInt>, a: &[BigInt]) -> Vec<BigInt> {
    let n = scaled.degree();
    let pw: Vec<Vec<BigInt>> = a.iter().map(|x| powers(x, n)).collect();
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simplex::Simplex;
    use proptest::prelude::*;

    /// A rational from a numerator and one of several denominator shapes: 16-bit, powers of
    /// two (dyadic), a prime above 2^32, a product with a large odd part (unfactorable: the
    /// fallback gcd path).
    fn rational(p: i64, q: u64, shape: u8) -> BigRational {
        let q = match shape % 4 {
            0 => BigInt::from(q % 65_536 + 1),
            1 => BigInt::from(1u8) << (q % 90),
            2 => BigInt::from(4_294_967_311u64) * BigInt::from(q % 7 + 1),
            _ => BigInt::from(q | 1) * BigInt::from(u64::MAX),
        };
        BigRational::new(BigInt::from(p), q)
    }

    fn net_strategy() -> impl Strategy<Value = ControlNet<BigRational>> {
        (1usize..=3, 0usize..=8, 1usize..=3, any::<u8>()).prop_flat_map(|(m, n, dim, shape)| {
            let len = crate::simplex::count(m, n) * dim;
            proptest::collection::vec((any::<i64>(), any::<u64>(), 0u8..4), len).prop_map(
                move |v| {
                    let coords = v
                        .into_iter()
                        .map(|(p, q, s)| {
                            rational(p >> (shape % 40), q, if shape < 128 { 0 } else { s })
                        })
                        .collect();
                    ControlNet::new(Simplex::new(m, n), dim, coords)
                },
            )
        })
    }

    proptest! {
        /// The word paths of `lcm_big` and `div_exact` (shift, Hensel remainder and division)
        /// against num-integer's lcm and num-bigint's division: multi-limb and word operands,
        /// either sign, many trailing zeros, divisors `2^t · odd`.
        #[test]
        fn lcm_and_exact_division_agree_with_num_integer(
            limbs in proptest::collection::vec(any::<u64>(), 0..6),
            zeros in 0u32..200,
            neg: bool,
            w in any::<u64>(),
            t in 0u32..64,
            other in proptest::collection::vec(any::<u64>(), 1..4),
        ) {
            use num_integer::Integer;
            use num_traits::Zero;
            let mut x = BigInt::zero();
            for &l in &limbs {
                x = (x << 64u32) + BigInt::from(l);
            }
            x <<= zeros;
            if neg {
                x = -x;
            }
            let word = ((w >> t) | 1) << t;
            let b = BigInt::from(word);
            prop_assert_eq!(kernel::lcm_big(&x, &b), x.lcm(&b));
            prop_assert_eq!(kernel::lcm_big(&b, &x), x.lcm(&b));
            prop_assert_eq!(kernel::div_exact(&(&x * &b), &b), x.clone());
            let mut y = BigInt::zero();
            for &l in &other {
                y = (y << 64u32) + BigInt::from(l);
            }
            if !y.is_zero() {
                prop_assert_eq!(kernel::lcm_big(&x, &y), x.lcm(&y));
                prop_assert_eq!(kernel::div_exact(&(&x * &y), &y), x.clone());
            }
        }

        /// `lcm_fold` (on limbs while the operands are nonzero words) against num-integer's
        /// lcm folded step by step, on sequences of words, multi-limb numbers and zeros.
        #[test]
        fn lcm_fold_agrees_with_num_integer(
            start in proptest::collection::vec(any::<u64>(), 0..4),
            xs in proptest::collection::vec(
                (any::<u64>(), 0u32..64, 0u8..10, any::<u64>()), 0..12),
        ) {
            use num_integer::Integer;
            use num_traits::Zero;
            let big = |limbs: &[u64]| {
                limbs.iter().fold(BigInt::zero(), |x, &l| (x << 64u32) + BigInt::from(l))
            };
            let start = big(&start);
            let xs: Vec<BigInt> = xs
                .iter()
                .map(|&(w, t, kind, hi)| match kind {
                    0 => BigInt::zero(),
                    1 => big(&[hi, w]),
                    // small words share factors often
                    2..=5 => BigInt::from((w % 1000 + 1) << (t % 8)),
                    _ => BigInt::from(((w >> t) | 1) << t),
                })
                .collect();
            let expected = xs.iter().fold(start.clone(), |acc, x| acc.lcm(x));
            prop_assert_eq!(kernel::lcm_fold(&start, xs.iter()), expected);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The fast kernel equals the rational de Casteljau (gcd after every operation), at
        /// barycentric points, homogeneous points, points with zeros, negative and huge coordinates.
        #[test]
        fn horner_kernel_equals_rational_de_casteljau(
            net in net_strategy(),
            raw in proptest::collection::vec((0u64..70_000, 1u64..70_000, any::<bool>()), 4),
            kind in 0u8..7,
        ) {
            let m = net.m();
            let lambda: Vec<BigRational> = raw.iter().take(m + 1).map(|&(a, q, neg)| {
                let (a, q) = match kind {
                    0 => (a, q),
                    1 => (a * u64::from(a % 3 != 0), 1),
                    2 => (a << 40, 1u64 << 50),
                    3 => (a, (q % 8192 + 1) << 50), // lcm may overflow a word: fallback
                    // Coordinates below 2^16 and 2^8: the triangle rows run in blocks of 4 and
                    // 8 coordinates per word (17-bit coordinates above: blocks of 3; 57-bit: 1).
                    5 => (a % 65_536, q % 65_536 + 1),
                    6 => (a % 256, q % 256 + 1),
                    _ => (a, q),
                };
                let x = BigRational::new(BigInt::from(a), BigInt::from(q));
                if kind == 4 && neg { -x } else { x }
            }).collect();
            let eval = ExactEvaluator::new(&net);
            let expected = evaluate_rational(&net, &lambda, Algorithm::Casteljau);
            // Ratio's `==` compares values; the kernel must also return lowest terms (the
            // reference reduces after every operation), so compare the parts.
            let parts = |v: &[BigRational]| -> Vec<(BigInt, BigInt)> {
                v.iter().map(|x| (x.numer().clone(), x.denom().clone())).collect()
            };
            prop_assert_eq!(parts(&eval.evaluate_fast(&lambda)), parts(&expected));
            prop_assert_eq!(parts(&eval.evaluate(&lambda, Algorithm::Casteljau)), parts(&expected));
        }
    }

    /// Primes of a denominator met at only one control point are decided from the point
    /// (`p | C(n;α)` or `p | a_k`) rather than from residues: 7 at `α = (6, 1, 0)`, where
    /// `C(7; 6, 1, 0) = 7`; 11 at `(2, 2, 3)` (`C = 210`); 13 at two points (read off residues).
    /// Points whose coordinates are multiples of 11 or 13, or zero, make those primes divide the
    /// numerator; the results must still be in lowest terms and equal the reference. The second
    /// coordinate has lone primes of its own (17, 19; 11 at `(2, 2, 3)` too), so that a point's
    /// gcds, shared by the coordinates, carry primes that are lone in one coordinate only.
    #[test]
    fn horner_kernel_lone_primes_against_the_reference() {
        let simplex = Simplex::new(2, 7);
        let alphas: Vec<Vec<u32>> = simplex.iter().map(<[u32]>::to_vec).collect();
        let coords: Vec<BigRational> = alphas
            .iter()
            .enumerate()
            .flat_map(|(r, alpha)| {
                let den: i64 = match alpha.as_slice() {
                    [6, 1, 0] => 7,
                    [2, 2, 3] => 11 * 2,
                    [1, 3, 3] | [0, 0, 7] => 13,
                    _ => 1,
                };
                let den1: i64 = match alpha.as_slice() {
                    [6, 1, 0] => 17,
                    [2, 2, 3] => 11,
                    [0, 7, 0] => 19 * 4,
                    _ => 1,
                };
                let r = r as i64;
                [
                    BigRational::new(BigInt::from(r - 7), BigInt::from(den)),
                    BigRational::new(BigInt::from(3 * r + 1), BigInt::from(den1)),
                ]
            })
            .collect();
        let net = ControlNet::new(simplex, 2, coords);
        let eval = ExactEvaluator::new(&net);
        let parts = |v: &[BigRational]| -> Vec<(BigInt, BigInt)> {
            v.iter()
                .map(|x| (x.numer().clone(), x.denom().clone()))
                .collect()
        };
        for a in [
            [1, 1, 1],
            [11, 22, 33],
            [1, 11, 5],
            [13, 2, 26],
            [0, 5, 8],
            [7, 0, 0],
            [77, 143, 1],
            [3, 5, 0],
            [17, 19, 1],
            [19 * 7, 0, 17],
            [1, 17 * 11, 19 * 13],
        ] {
            let d: i64 = a.iter().sum();
            let lambda: Vec<BigRational> = a
                .iter()
                .map(|&x| BigRational::new(BigInt::from(x), BigInt::from(d)))
                .collect();
            let expected = evaluate_rational(&net, &lambda, Algorithm::Casteljau);
            assert_eq!(
                parts(&eval.evaluate_fast(&lambda)),
                parts(&expected),
                "at {a:?}"
            );
        }
    }

    /// A triangle of degree 20 with 16-bit denominators has results far beyond four limbs:
    /// its kernel is the row form alone and the integer nets are left unbuilt, until a generic
    /// path asks for them; a quadratic, a curve and a tetrahedron build them at once. Every
    /// path agrees with rational de Casteljau on the net as given.
    #[test]
    fn integer_nets_are_built_when_a_path_needs_them() {
        let n = 20;
        let count = crate::simplex::count(2, n);
        let coords: Vec<BigRational> = (0..3 * count as u64)
            .map(|i| rational((i * 7919 % 20011) as i64 - 10_000, i * 104_729 + 3, 0))
            .collect();
        let net = ControlNet::new(Simplex::new(2, n), 3, coords);
        let eval = ExactEvaluator::new(&net);
        assert!(eval.nets.get().is_none(), "degree 20: the row form alone");
        let (u, v) = (
            BigRational::new(BigInt::from(3), BigInt::from(11)),
            BigRational::new(BigInt::from(5), BigInt::from(13)),
        );
        let w = BigRational::one() - &u - &v;
        let lambda = [u, v, w];
        let expected = evaluate_rational(&net, &lambda, Algorithm::Casteljau);
        assert_eq!(eval.evaluate_fast(&lambda), expected);
        assert!(eval.nets.get().is_none());
        assert_eq!(eval.evaluate(&lambda, Algorithm::Bernstein), expected);
        assert!(eval.nets.get().is_some(), "built by the generic path");
        assert_eq!(eval.evaluate(&lambda, Algorithm::Casteljau), expected);
        let (integer, denominators) = eval.integer_net();
        assert_eq!(
            BigRational::new(integer.point(0)[1].clone(), denominators[1].clone()),
            net.point(0)[1]
        );
        for (m, n) in [(2, 2), (1, 5), (3, 3)] {
            let count = crate::simplex::count(m, n);
            let coords = (0..2 * count as u64)
                .map(|i| rational(i as i64 - 4, i + 2, 0))
                .collect();
            let small = ExactEvaluator::new(&ControlNet::new(Simplex::new(m, n), 2, coords));
            assert!(small.nets.get().is_some(), "m = {m}, n = {n}");
        }
    }

    /// A prime of `L_c` found dividing the numerator by its residue is divided out without a
    /// check, and its higher powers with one. By hand, the linear triangle with control values
    /// `(1/9, 17/9, 1)` and `(1/9, 2/9, 4/9)`: at `(1/2, 1/2, 0)`, `(1/9 + 17/9)/2 = 1` (both
    /// factors 3 of `L_c = 9` out) and `(1/9 + 2/9)/2 = 1/6` (one); at `(1/2, 0, 1/2)`,
    /// `(1/9 + 1)/2 = 5/9` and `(1/9 + 4/9)/2 = 5/18` (none); at `(1/4, 3/4, 0)`,
    /// `(1 + 51)/36 = 13/9` and `(1 + 6)/36 = 7/36`.
    #[test]
    fn shared_primes_and_their_powers_leave_the_numerator() {
        let q = |s: &str| crate::number::parse_rational(s).unwrap();
        let pts: Vec<Vec<BigRational>> = [["1/9", "1/9"], ["17/9", "2/9"], ["1", "4/9"]]
            .iter()
            .map(|p| p.iter().map(|s| q(s)).collect())
            .collect();
        let net = ControlNet::from_points(2, 1, &pts);
        let eval = ExactEvaluator::new(&net);
        for (at, expected) in [
            (["1/2", "1/2", "0"], ["1", "1/6"]),
            (["1/2", "0", "1/2"], ["5/9", "5/18"]),
            (["1/4", "3/4", "0"], ["13/9", "7/36"]),
        ] {
            let lambda = at.map(q);
            let got: Vec<String> = eval
                .evaluate_fast(&lambda)
                .iter()
                .map(ToString::to_string)
                .collect();
            assert_eq!(got, expected, "{at:?}");
            assert_eq!(
                eval.evaluate_fast(&lambda),
                evaluate_rational(&net, &lambda, Algorithm::Casteljau)
            );
        }
    }

    #[test]
    fn horner_kernel_on_a_known_quadratic() {
        // The module doc example, plus the reduced-denominator case: at a corner the value is
        // the corner control point exactly.
        let q = |s: &str| crate::number::parse_rational(s).unwrap();
        let pts: Vec<Vec<BigRational>> = [
            ["1/3", "-5/6", "7"],
            ["2", "0", "1/9"],
            ["-1/4", "3/8", "0"],
            ["5", "1", "1"],
            ["0", "0", "0"],
            ["1/12", "-2", "4/3"],
        ]
        .iter()
        .map(|p| p.iter().map(|s| q(s)).collect())
        .collect();
        let eval = ExactEvaluator::new(&ControlNet::from_points(2, 2, &pts));
        let at = |u: [&str; 3]| {
            eval.evaluate_fast(&u.map(q))
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
        };
        assert_eq!(at(["1", "0", "0"]), ["1/3", "-5/6", "7"]);
        assert_eq!(at(["0", "0", "1"]), ["1/12", "-2", "4/3"]);
        // (1/2, 1/2, 0): (c200 + 2 c110 + c020)/4 = (1/3 + 4 - 1/4)/4 = 49/48, (-5/6 + 3/8)/4 = -11/96, (7 + 2/9)/4 = 65/36.
        assert_eq!(at(["1/2", "1/2", "0"]), ["49/48", "-11/96", "65/36"]);
    }
}
