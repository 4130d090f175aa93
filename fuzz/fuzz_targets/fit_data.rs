#![no_main]
//! Fuzz target `fit_data`: see `tribez::hazmat::io::fuzz::fit_data`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::fit_data(data));
