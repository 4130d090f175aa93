#![no_main]
//! Fuzz target `batch_jsonl`: see `tribez::hazmat::io::fuzz::batch_jsonl`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::batch_jsonl(data));
