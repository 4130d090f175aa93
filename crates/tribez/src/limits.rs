//! The limits every input is checked against before anything is allocated: the sizes a patch
//! file may have and the largest subdivision matrix (docs/guide.md §13). The command line
//! and the Python package check their own inputs against the same constants.
//!
//! ```
//! use tribez::limits::*;
//! assert_eq!((MAX_DEGREE, MAX_CONTROL_POINTS, MAX_SIMPLEX_DIMENSION), (200, 250_000, 16));
//! // the number text limits: digits of one number, and the magnitude of a written exponent
//! assert_eq!((MAX_DIGITS, MAX_EXPONENT), (100_000, 100_000));
//! assert_eq!((MAX_MATRIX_ROWS, MAX_POINTS), (1000, 1_000_000));
//! ```

pub use crate::blossom::MAX_MATRIX_ROWS;
pub use crate::io::patch_file::{MAX_CONTROL_POINTS, MAX_DEGREE, MAX_SIMPLEX_DIMENSION};
pub use crate::io::points::MAX_POINTS;
pub use crate::number::{MAX_DIGITS, MAX_EXPONENT};
