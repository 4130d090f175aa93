#![no_main]
//! Fuzz target `hunt_answer`: see `tribez::hazmat::io::fuzz::hunt_answer`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| tribez::hazmat::io::fuzz::hunt_answer(data));
