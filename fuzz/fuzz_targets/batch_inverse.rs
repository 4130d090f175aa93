#![no_main]
//! Fuzz target `batch_inverse`: see `tribez::hazmat::io::fuzz::batch_inverse`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::batch_inverse(data));
