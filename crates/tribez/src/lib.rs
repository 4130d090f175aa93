//! # tribez: exact Bézier triangles (and simplices), to certify floating-point code
//!
//! tribez computes with Bézier triangles — and Bézier simplices of any dimension, rational and
//! functional patches, and S-patches — **exactly**, in rational arithmetic, and uses those exact
//! answers to judge what floating-point code computes.
//!
//! Start from a [`Patch`] (built with its constructors or read from a patch file), evaluate it
//! exactly, and [`judge`] a float result:
//!
//! ```
//! use tribez::{Degree, Patch, Precision, SimplexDim, Tolerance, judge, parse_rational};
//! let q = |s: &str| parse_rational(s).unwrap();
//! // Finn's worked example: degree 2 over the triangle (m = 2), points in R³, control points
//! // in the canonical order 200, 110, 020, 101, 011, 002
//! let pts = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]];
//! let net = pts.iter().map(|p| p.iter().map(|x| q(&x.to_string())).collect()).collect();
//! let patch = Patch::bezier(SimplexDim(2), Degree(2), net).unwrap();
//! let p = patch.evaluate(&[q("1/2"), q("1/3"), q("1/6")]).unwrap();
//! assert_eq!(p, [q("4/9"), q("5/9"), q("29/36")]);
//!
//! // A float program saw (0.5, fl(1/3), fl(1/6)), which sums to 1 − 2^-55, and returned the
//! // nearest floats of 4/9, 5/9 and 29/36: within one ULP of the exact values at what it saw
//! let claimed = [4.0 / 9.0, 5.0 / 9.0, 29.0 / 36.0];
//! let input = [0.5, 1.0 / 3.0, 1.0 / 6.0];
//! let ulps = Tolerance::parse("ulps=1").unwrap();
//! assert!(judge(&patch, &input, &claimed, &ulps, Precision::F64).unwrap().passed);
//! // but not all correctly rounded there (fixtures/judge/derive.py)
//! let cr = Tolerance::parse("correctly_rounded").unwrap();
//! let j = judge(&patch, &input, &claimed, &cr, Precision::F64).unwrap();
//! assert!(!j.passed && j.coordinates[0].correctly_rounded);
//! ```
//!
//! ## What is here
//!
//! * [`Patch`], [`PatchKind`], [`SimplexDim`], [`Degree`]: one type for every kind of patch;
//! * [`capability`]: what a kind can do ([`ExactEval`], [`FloatEval`], [`ErrorBound`],
//!   [`Constructions`]), implemented per kind, one file per kind;
//! * [`judge`], [`judge_with`], [`judge_algorithm`], [`judge_cartesian`], [`judge_input`]
//!   ([`JudgeInput`]: barycentric or Cartesian points), [`Judgement`]: one call that judges a
//!   float result (docs/theory.md §14);
//! * [`Rational`], [`parse_rational`], [`Precision`], [`Tolerance`], [`Algorithm`]: exact
//!   numbers, precisions and tolerances, parsed from the same strings as the command line;
//! * [`mesh`]: meshes of functional Bézier triangles sharing their ordinates (C0), exact
//!   point location and lookup;
//! * [`claims`]: claim files, read and checked; [`batch`]: batches of another implementation's
//!   results, judged in parallel, by a [`ResultsChecker`] (a patch's values, a mesh's lookups,
//!   inverse answers: each from a reader or a file);
//! * [`hunt`]: search for the inputs where another implementation is least accurate
//!   (`tribez hunt`);
//! * [`algebraic`]: real algebraic numbers ([`RealAlgebraic`]) and the inverse problems they
//!   answer exactly: [`intersect_curves`] for two planar curves ([`Curve`]);
//! * [`format`](mod@format): numbers in and out (parsing, exact and float printing, correct
//!   rounding, ULPs); [`limits`]: the sizes every input is checked against; [`files`]: points
//!   files and polynomial patch files;
//! * [`constructions`]: multi-indices, control nets, subdivision matrices, joins, symbolic
//!   forms; [`kernels`]: the exact and float evaluation kernels;
//! * [`ordered`]: work rendered in parallel and written in order (a long report streamed);
//! * [`Error`] (with [`InputError`] and [`CoreError`]): errors carrying data;
//! * `hazmat`: the low-level building blocks, **unstable**, only with the cargo feature
//!   `unstable-internals` (off by default; the fuzz targets use it).
//!
//! The exact core never depends on the outer layers (files, claims, the command line, which is
//! the separate `tribez-cli` crate).

#![warn(missing_docs)]
// Without the feature `unstable-internals`, the building blocks that only `hazmat` re-exports,
// and the fuzz targets' helpers, have no caller in the crate: they are not dead, only unexported.
#![cfg_attr(not(feature = "unstable-internals"), allow(dead_code, unused_imports))]

pub mod algebraic;
mod any_patch;
mod api_error;
pub mod batch;
mod bernstein;
mod blossom;
pub mod capability;
mod casteljau;
mod certification;
mod certify;
pub mod claims;
pub mod constructions;
mod derivative;
mod domain;
mod elevate;
mod error;
mod exact;
pub mod files;
pub mod fit;
mod float;
pub mod format;
mod functional;
#[cfg(any(fuzzing, feature = "unstable-internals"))]
mod fuzz;
#[cfg(feature = "unstable-internals")]
pub mod hazmat;
pub mod hunt;
mod io;
mod join;
mod judge;
mod judge_inverse;
mod judge_refusal;
pub mod kernels;
pub mod limits;
mod linalg;
pub mod mesh;
mod number;
pub mod ordered;
mod patch;
mod patch_type;
mod rational;
pub mod report;
mod scalar;
mod simplex;
mod spatch;
mod subdivide;
mod symbolic;
#[cfg(test)]
mod testing;

pub use algebraic::{AlgebraicError, Curve, CurveIntersections, RealAlgebraic, intersect_curves};
pub use api_error::Error;
pub use batch::ResultsChecker;
pub use capability::{
    Constructions, ErrorBound, ExactEval, FloatEval, FloatProgram, Split, SubPatch,
};
pub use certification::{
    CertifyOptions, CertifyPoints, CertifyReport, CertifyRow, PointResult, RandomPoints, certify,
    certify_until,
};
pub use certify::measures::Tolerance;
pub use error::CoreError;
pub use exact::Algorithm;
pub use float::Precision;
pub use io::{ClaimProblem, InputError, NeededKind, Problem, RowsProblem};
pub use judge::{
    CoordinateJudgement, JudgeInput, Judgement, judge, judge_algorithm, judge_cartesian,
    judge_input, judge_with,
};
pub use judge_refusal::{Lacks, Refusal};
pub use num_rational::BigRational as Rational;
pub use number::parse_rational;
pub use patch_type::{Degree, FloatEvaluator, Patch, PatchKind, SimplexDim};
pub use subdivide::HalvingOrder;
