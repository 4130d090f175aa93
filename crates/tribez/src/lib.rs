//! # tribez: exact Bézier triangles (and simplices), to certify floating-point code
//!
//! tribez computes with triangular Bézier patches — and Bézier simplices of any dimension —
//! **exactly**, in rational arithmetic, and uses those exact answers to judge floating-point
//! results.
//!
//! ```
//! use tribez::casteljau::evaluate;
//! use tribez::number::parse_rational as q;
//! use tribez::patch::ControlNet;
//! // Finn's notes (Finn, day 30), worked example (a): the point is exactly [4/9, 5/9, 29/36].
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let net = ControlNet::from_points(2, 2, &pts);
//! let u = [q("1/2").unwrap(), q("1/3").unwrap(), q("1/6").unwrap()];
//! let p: Vec<String> = evaluate(&net, &u).iter().map(|x| x.to_string()).collect();
//! assert_eq!(p, ["4/9", "5/9", "29/36"]);
//! ```
//!
//! ## Layers
//! The exact core ([`number`], [`simplex`], [`bernstein`], [`domain`], [`patch`],
//! [`casteljau`], [`exact`], [`float`]) never depends on the outer layers: files ([`io`]) and the
//! command line.

pub mod any_patch;
pub mod api_error;
pub mod batch;
pub mod bernstein;
pub mod blossom;
pub mod capability;
pub mod casteljau;
pub mod certify;
pub mod claims;
pub mod derivative;
pub mod domain;
pub mod elevate;
pub mod error;
pub mod exact;
pub mod float;
pub mod functional;
pub mod io;
pub mod join;
pub mod judge;
pub mod number;
pub mod patch;
pub mod patch_type;
pub mod rational;
pub mod scalar;
pub mod simplex;
pub mod spatch;
pub mod subdivide;
pub mod symbolic;
#[cfg(test)]
mod testing;

pub use api_error::Error;
pub use capability::{Constructions, ErrorBound, ExactEval, FloatEval, FloatProgram};
pub use certify::measures::Tolerance;
pub use exact::Algorithm;
pub use float::Precision;
pub use judge::{CoordinateJudgement, Judgement, judge, judge_algorithm, judge_with};
pub use num_rational::BigRational as Rational;
pub use number::parse_rational;
pub use patch_type::{Degree, Patch, PatchKind, SimplexDim};
