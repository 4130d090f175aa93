//! **Unstable**: the low-level building blocks of tribez (as the Python package `bezier` keeps
//! its `hazmat`). Everything here may change or go in any release; the stable API is what the
//! crate root re-exports.
//!
//! * exact core: [`number`] (exact numbers, correctly rounded conversions, ULPs),
//!   [`simplex`] (multi-indices), [`patch`] (control nets, [`patch::BezierPatch`]),
//!   [`domain`], [`bernstein`], [`casteljau`], [`blossom`], [`subdivide`], [`elevate`],
//!   [`derivative`], [`symbolic`], [`scalar`], [`exact`] (the exact evaluation kernel);
//! * the kinds: [`rational`], [`functional`], [`spatch`], [`any_patch`], [`join`];
//! * floats: [`float`] (the float programs, glam kernels);
//! * certification: [`certify`] (bounds, measures, the float filter, certifiers);
//! * files: [`io`] (the document tree, patch files, point files);
//! * errors: [`error`].

macro_rules! hazmat {
    ($($(#[$doc:meta])* $name:ident),* $(,)?) => {
        $(
            $(#[$doc])*
            pub mod $name {
                pub use crate::$name::*;
            }
        )*
    };
}

/// Files in: the document tree, patch files, point files; and the entry points of the fuzz
/// targets.
pub mod io {
    pub use crate::io::*;

    /// The entry points of the fuzz targets (they read claim files and batches too, so they sit
    /// above the file layer: [`crate::hazmat::io`] only re-exports them here).
    pub mod fuzz {
        pub use crate::fuzz::*;
    }
}

hazmat!(
    /// `AnyPatch`: the representation of a [`crate::Patch`] by kind.
    any_patch,
    /// Bernstein polynomials and the direct Bernstein form.
    bernstein,
    /// Blossoms and subpatches.
    blossom,
    /// de Casteljau's algorithm, generic.
    casteljau,
    /// Certification: bounds, measures, the float filter and the certifiers.
    certify,
    /// Derivatives, tangent frames and normals.
    derivative,
    /// Domain simplices and Cartesian ↔ barycentric conversion.
    domain,
    /// Degree elevation.
    elevate,
    /// The core's error type.
    error,
    /// The exact evaluation kernel.
    exact,
    /// Float types, precisions and the float programs.
    float,
    /// Functional (nonparametric) patches.
    functional,
    /// Joins: continuity between patches.
    join,
    /// Exact linear algebra for least-squares fits: normal equations, a certified solver
    /// (Dixon's p-adic lifting), null spaces, minimum-norm solutions.
    linalg,
    /// Exact numbers: parsing, printing, correctly rounded conversions, ULPs.
    number,
    /// Control nets and polynomial patches.
    patch,
    /// Rational Bézier simplices.
    rational,
    /// The scalar trait of the generic algorithms.
    scalar,
    /// Multi-indices of Bézier simplices.
    simplex,
    /// S-patches over convex polygons.
    spatch,
    /// Subdivision.
    subdivide,
    /// Polynomials in barycentric and Cartesian form.
    symbolic,
);
