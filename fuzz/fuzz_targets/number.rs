#![no_main]
//! Fuzz target `number`: see `tribez::hazmat::io::fuzz::number`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::number(data));
