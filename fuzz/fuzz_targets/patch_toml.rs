#![no_main]
//! Fuzz target `patch_toml`: see `tribez::hazmat::io::fuzz::patch_toml`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::patch_toml(data));
