//! The exact constructions that are not (yet) methods of [`crate::Patch`] or its
//! [`crate::Constructions`]: multi-indices and control nets, domains, subdivision matrices,
//! joins of two patches (C0, C1, C^r, G1), the C1 neighbour, tangent frames and the
//! polynomial (symbolic) form, for the command line and other front ends (docs/theory.md §1–§9).
//!
//! A curated list: the types the [`crate::Constructions`] trait returns ([`ControlNet`],
//! [`Domain`], [`TangentFrame`]) and the functions the commands call.
//!
//! ```
//! use tribez::constructions::*;
//! use tribez::parse_rational as q;
//! let q = |s: &str| q(s).unwrap();
//! // multi-indices: C(4, 2) = 6 control points of a quadratic triangle; 3!/(2! 0! 1!) = 3
//! assert_eq!(binomial(4, 2), 6);
//! assert_eq!(multinomial(&[2, 0, 1]).to_string(), "3");
//! let s = Simplex::new(2, 2);
//! assert_eq!(s.iter().map(|a| a.to_vec()).collect::<Vec<_>>()[..3], [[2, 0, 0], [1, 1, 0], [0, 2, 0]]);
//! // the subpatch matrix of a line (m = 1, n = 1) over [e_0, (e_0 + e_1)/2]: c′_10 = b[e_0] = c_10,
//! // c′_01 = b[(e_0 + e_1)/2] = c_10/2 + c_01/2
//! let f = [vec![q("1"), q("0")], vec![q("1/2"), q("1/2")]];
//! assert_eq!(subpatch_matrix(1, 1, &f).unwrap(), [[q("1"), q("0")], [q("1/2"), q("1/2")]]);
//! // halving a line at its midpoint: [e_0, mid] and [mid, e_1]
//! let [a, b] = halve_domains::<tribez::Rational>(1, 0, 1);
//! assert_eq!((a[1].clone(), b[0].clone()), (vec![q("1/2"), q("1/2")], vec![q("1/2"), q("1/2")]));
//! // corners are numbered from 1 on the command line: edge 1,3 of a triangle is (0, 2)
//! assert_eq!(check_edge(2, 1, 3).unwrap(), (0, 2));
//! assert!(check_edge(2, 1, 4).is_err());
//! assert_eq!(cartesian_names(2), ["x", "y"]);
//! ```

pub use crate::blossom::subpatch_matrix;
pub use crate::derivative::TangentFrame;
pub use crate::domain::{Domain, check_barycentric, check_direction};
pub use crate::join::{Join, SharedFacet, Violation, analyse as analyse_join, c1_neighbour};
pub use crate::patch::{BezierPatch, ControlNet};
pub use crate::rational::RationalPatch;
pub use crate::simplex::{Simplex, binomial, multinomial};
pub use crate::subdivide::{check_edge, halve_domains};
pub use crate::symbolic::{Polynomial, cartesian_names};
