#![no_main]
//! Fuzz target `number`: see `tribez::io::fuzz::number`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::io::fuzz::number(data));
