#![no_main]
//! Fuzz target `batch_csv`: see `tribez::hazmat::io::fuzz::batch_csv`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::batch_csv(data));
