#![no_main]
//! Fuzz target `batch_csv`: see `tribez::io::fuzz::batch_csv`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::io::fuzz::batch_csv(data));
