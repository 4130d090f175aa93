#![no_main]
//! Fuzz target `certify`: see `tribez::hazmat::io::fuzz::certify`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::certify(data));
