#![no_main]
//! Fuzz target `batch_json_array`: see `tribez::hazmat::io::fuzz::batch_json_array`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::batch_json_array(data));
