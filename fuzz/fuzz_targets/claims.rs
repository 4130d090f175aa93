#![no_main]
//! Fuzz target `claims`: see `tribez::hazmat::io::fuzz::claims`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::claims(data));
