//! What a kind of patch can do: the capability traits ([`traits`]) and their implementations,
//! one file per kind (`bezier`: Bézier simplices and functional patches; `rational`; `spatch`).
//! A new kind is one new file here implementing the traits, and a variant of
//! [`crate::any_patch::AnyPatch`].

pub mod bezier;
pub mod rational;
pub mod spatch;
pub mod traits;

pub use traits::{
    BoundText, Constructions, CoordinateCase, CoordinateText, ErrorBound, ExactEval, FloatCase,
    FloatEval, FloatProgram, InputSpace, PointEvaluator, Seen, Shape, SymbolicForm,
};
