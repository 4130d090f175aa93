//! [`AnyPatch`]: every kind of patch a patch file describes, as one enum of the kinds' own types.
//!
//! This is the representation behind the public [`crate::Patch`]; the kinds' capabilities
//! (exact evaluation, the float program, its error bound, the constructions) are implemented
//! per kind in [`crate::capability`], one file per kind.

use crate::patch::BezierPatch;
use crate::rational::RationalPatch;
use crate::spatch::SPatch;

/// Any kind of patch a patch file can describe (docs/guide.md §3: `[weights]`, `polygon`,
/// `kind = "functional"`). Plain Bézier simplices are [`BezierPatch`]; the other kinds wrap one
/// or carry their own net.
#[derive(Clone, Debug, PartialEq)]
pub enum AnyPatch {
    /// A polynomial Bézier simplex.
    Bezier(BezierPatch),
    /// A rational Bézier simplex (`[weights]`).
    Rational(RationalPatch),
    /// A functional (nonparametric) patch: one ordinate per control point (`d = 1`) over a
    /// domain simplex (`kind = "functional"`).
    Functional(BezierPatch),
    /// An S-patch over a convex polygon (`polygon = [...]`).
    SPatch(SPatch),
}

impl AnyPatch {
    /// `"a rational patch"`, `"an S-patch"`, …: the kind with its article, for messages.
    pub fn described(&self) -> &'static str {
        match self {
            AnyPatch::Bezier(_) => "a Bézier patch",
            AnyPatch::Rational(_) => "a rational patch",
            AnyPatch::Functional(_) => "a functional patch",
            AnyPatch::SPatch(_) => "an S-patch",
        }
    }

    /// `"Bézier"`, `"rational"`, `"functional"` or `"S-patch"`.
    pub fn kind_name(&self) -> &'static str {
        match self {
            AnyPatch::Bezier(_) => "Bézier",
            AnyPatch::Rational(_) => "rational",
            AnyPatch::Functional(_) => "functional",
            AnyPatch::SPatch(_) => "S-patch",
        }
    }

    /// Its name, to change (an S-patch's too).
    pub fn name_mut(&mut self) -> &mut Option<String> {
        match self {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => &mut p.name,
            AnyPatch::Rational(r) => &mut r.patch.name,
            AnyPatch::SPatch(s) => &mut s.name,
        }
    }

    /// The polynomial patch, for the kinds that are one (Bézier and functional).
    pub fn polynomial(&self) -> Option<&BezierPatch> {
        match self {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => Some(p),
            _ => None,
        }
    }
}
