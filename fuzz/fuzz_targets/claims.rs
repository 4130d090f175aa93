#![no_main]
//! Fuzz target `claims`: see `tribez::io::fuzz::claims`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::io::fuzz::claims(data));
