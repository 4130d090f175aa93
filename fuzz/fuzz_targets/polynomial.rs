#![no_main]
//! Fuzz target `polynomial`: see `tribez::hazmat::io::fuzz::polynomial`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::polynomial(data));
