//! Patch files: TOML or JSON (chosen by extension), documented in docs/guide.md (§3).
//!
//! ```toml
//! name = "Finn, day 30, worked example"
//! degree = 2
//! # domain = [["1","0"], ["0","1"], ["0","0"]]   # optional: m+1 vertices in R^m
//! [control_points]
//! "2,0,0" = ["0", "0", "0"]
//! "1,1,0" = ["1", "0", "2"]
//! # … every multi-index of degree 2 exactly once
//! ```
//!
//! Keys are multi-indices with `m + 1` comma-separated parts (`m = 1` curves, `2` triangles,
//! `3` tetrahedra, …), summing to `degree`; values are arrays of `d >= 1` numbers, written as
//! strings in the number syntax of [`crate::number::parse_rational`] or as plain numbers (taken
//! from their text, exactly).
//!
//! Three optional additions make the other kinds of [`AnyPatch`] (docs/guide.md §3,
//! "Rational patches, S-patches and functional patches"):
//!
//! * `[weights]`, keyed like `control_points`, one number per control point: a **rational**
//!   patch. Every control point needs exactly one weight; zero and negative weights are
//!   accepted (evaluating where the denominator vanishes is an error).
//! * `polygon = [["x", "y"], …]`: an **S-patch** over that convex polygon (counter-clockwise);
//!   the control-point keys then have one part per polygon vertex, summing to `degree` (the
//!   depth). No `domain` and no `weights` with a polygon.
//! * `kind = "functional"`: a **functional** (nonparametric) patch: one control ordinate per
//!   control point (`d = 1`) over `domain` (default: the reference simplex).
//!
//! `kind` may also be written `"bezier"`, `"rational"` or `"s-patch"`; it must then agree with
//! the keys present. [`read_patch`] returns plain and functional patches as a [`BezierPatch`] and
//! rejects the other kinds with a located error; [`read_any_patch`] returns every kind.
//!
//! Reading is `read.rs` (with the located [`PatchFileProblem`]s of `problem.rs`), writing (TOML and
//! JSON in the same layout) is `write.rs`; every item is re-exported here.

mod problem;
mod read;
mod write;

pub use problem::PatchFileProblem;
pub use read::{any_patch_from_document, domain, patch_from_document, read_any_patch, read_patch};
pub use write::{any_patch_to_json, any_patch_to_toml, patch_to_json, patch_to_toml};

#[cfg(doc)]
use crate::{any_patch::AnyPatch, patch::BezierPatch};

/// The largest degree a patch file may have. Exact evaluation at degree 200 costs tens of
/// milliseconds per point (docs/performance.md, "Scaling"); beyond that, results run to many kilobits.
pub const MAX_DEGREE: usize = 200;
/// The largest number of control points a patch file may have.
pub const MAX_CONTROL_POINTS: usize = 250_000;
/// The largest simplex dimension `m` (number of barycentric coordinates minus one).
pub const MAX_SIMPLEX_DIMENSION: usize = 16;

/// The keys a patch file may have.
pub const PATCH_KEYS: &[&str] = &[
    "name",
    "degree",
    "domain",
    "control_points",
    "domain_in_parent",
    "weights",
    "polygon",
    "kind",
];

/// `"1,0,2"` for a multi-index.
pub fn index_key(alpha: &[u32]) -> String {
    alpha
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(",")
}

#[cfg(test)]
mod tests;
