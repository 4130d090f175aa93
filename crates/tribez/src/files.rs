//! Files in, beyond patch files (which [`crate::Patch::from_file`] reads): points files, the
//! polynomial patch files that the joins and the batch checker take, and the multi-index keys
//! of patch files. Every error is an [`InputError`] naming the file, line and key.
//!
//! ```
//! // a points file of barycentric points, one per line (CSV), 3 coordinates each
//! let dir = tempfile::tempdir().unwrap();
//! let path = dir.path().join("points.csv");
//! std::fs::write(&path, "1/2,1/4,1/4\n0,0,1\n").unwrap();
//! let points = tribez::files::read_points(&path, 3).unwrap();
//! let q = |s: &str| tribez::parse_rational(s).unwrap();
//! assert_eq!(points, [vec![q("1/2"), q("1/4"), q("1/4")], vec![q("0"), q("0"), q("1")]]);
//! // a row of the wrong width is an error naming the file
//! assert!(tribez::files::read_points(&path, 2).unwrap_err().to_string().contains("points.csv"));
//! assert_eq!(tribez::files::index_key(&[2, 0, 1]), "2,0,1");
//! ```

use std::path::Path;

use crate::io::InputError;
use crate::patch::BezierPatch;

pub use crate::io::patch_file::index_key;
pub use crate::io::points::read_points;

/// Read a polynomial patch file (`.toml` or `.json`): a Bézier simplex, as the joins
/// ([`crate::constructions::analyse_join`]) and the batch checker take; a file of another kind
/// (weights, a polygon, `kind = "functional"`) is an error naming it.
pub fn read_bezier_patch(path: &Path) -> Result<BezierPatch, InputError> {
    crate::io::patch_file::read_patch(path)
}
