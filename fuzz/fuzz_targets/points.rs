#![no_main]
//! Fuzz target `points`: see `tribez::hazmat::io::fuzz::points`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::points(data));
