#![no_main]
//! Fuzz target `mesh`: see `tribez::hazmat::io::fuzz::mesh`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::mesh(data));
