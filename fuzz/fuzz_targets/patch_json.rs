#![no_main]
//! Fuzz target `patch_json`: see `tribez::hazmat::io::fuzz::patch_json`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::patch_json(data));
