#![no_main]
//! Fuzz target `patch_toml`: see `tribez::io::fuzz::patch_toml`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::io::fuzz::patch_toml(data));
