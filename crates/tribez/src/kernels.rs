//! The evaluation kernels behind [`crate::Patch::evaluate`] and the float programs tribez
//! certifies, for front ends that evaluate many points themselves: the exact evaluator of a
//! control net (prepared once, [`ExactEvaluator`]), the float de Casteljau algorithm
//! ([`casteljau`], on a net rounded by [`net_to`]), float Wachspress coordinates, and the machine
//! floats tribez rounds to and judges ([`Float`]: `f64`, `f32`) (docs/theory.md §3, §12, §14.1).
//!
//! ```
//! use tribez::kernels::*;
//! use tribez::parse_rational as q;
//! let q = |s: &str| q(s).unwrap();
//! // the quadratic curve with control points 0, 1, 0: p(λ) = 2 λ_0 λ_1, so p(1/2, 1/2) = 1/2
//! let p = tribez::Patch::from_toml(
//!     "degree = 2\n[control_points]\n\"2,0\" = [\"0\"]\n\"1,1\" = [\"1\"]\n\"0,2\" = [\"0\"]\n",
//! )
//! .unwrap();
//! let exact = ExactEvaluator::new(p.control_net());
//! assert_eq!(exact.evaluate_fast(&[q("1/2"), q("1/2")]), [q("1/2")]);
//! // in f64 every step of de Casteljau is exact here: (0 + 1)/2 = 1/2, (1 + 0)/2 = 1/2, 1/2
//! assert_eq!(casteljau(&net_to::<f64>(p.control_net()), &[0.5, 0.5]), [0.5]);
//! // (a, D) with λ_k = a_k / D on machine words
//! assert_eq!(word_point(&[q("1/2"), q("1/4"), q("1/4")]), Some((vec![2, 1, 1], 4)));
//! assert_eq!(<f64 as Float>::round(&q("1/10")), 0.1);
//! ```

pub use crate::exact::{ExactEvaluator, word_point};
pub use crate::float::{Float, casteljau, net_to};
pub use crate::spatch::wachspress_float;
