//! What a kind of patch can do: the capability traits ([`traits`]) and their implementations,
//! one file per kind (`bezier`: Bézier simplices and functional patches; `rational`; `spatch`).
//! A new kind is one new file here implementing the traits, and a variant of
//! `crate::any_patch::AnyPatch`.

pub mod bezier;
pub mod rational;
pub mod spatch;
pub mod traits;

pub use traits::{
    BoundText, Constructions, CoordinateCase, CoordinateText, ErrorBound, ExactEval, FloatCase,
    FloatEval, FloatProgram, InputSpace, PointEvaluator, Seen, Shape, Split, SubPatch,
    SymbolicForm,
};

/// The constructions of a patch (Bézier, functional and rational patches; not S-patches): its
/// kind's [`Constructions`], results of the same kind.
pub fn constructions(any: &crate::any_patch::AnyPatch) -> Option<Box<dyn Constructions + '_>> {
    use crate::any_patch::AnyPatch;
    match any {
        AnyPatch::Bezier(p) => Some(Box::new(bezier::Polynomial {
            patch: p,
            wrap: AnyPatch::Bezier,
            functional: false,
        })),
        AnyPatch::Functional(p) => Some(Box::new(bezier::Polynomial {
            patch: p,
            wrap: AnyPatch::Functional,
            functional: true,
        })),
        AnyPatch::Rational(r) => Some(Box::new(r)),
        AnyPatch::SPatch(_) => None,
    }
}

#[cfg(test)]
mod tests;
