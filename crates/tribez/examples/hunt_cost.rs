//! The hunt without its pipe (bench/hunt/run.py): `tribez::hunt::hunt` in memory, with a target
//! that answers the same constant to every row, timed. Against `tribez hunt` on the same patch,
//! seed, budget and constant (the same rows, answers and verdicts), the difference in time is
//! the pipe's: writing the rows to a program and reading its answers.
//!
//! ```text
//! cargo run --release --example hunt_cost -- PATCH PRECISION TOLERANCE BUDGET SEED VALUE
//! ```
//!
//! prints `rows seconds broke` on one line (VALUE: a decimal, each coordinate's answer).

use std::time::Instant;

use tribez::hunt::{HuntOptions, hunt};
use tribez::{Patch, Precision, Tolerance};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() != 6 {
        eprintln!("usage: hunt_cost PATCH PRECISION TOLERANCE BUDGET SEED VALUE");
        std::process::exit(2);
    }
    let patch = Patch::from_file(&args[0]).unwrap_or_else(|e| panic!("{}: {e}", args[0]));
    let precision: Precision = args[1].parse().expect("f64 or f32");
    let tolerance = Tolerance::parse(&args[2]).expect("a tolerance");
    let mut options = HuntOptions::new(precision, tolerance);
    options.budget = args[3].parse().expect("a budget");
    options.seed = args[4].parse().expect("a seed");
    let value: f64 = args[5].parse().expect("a decimal value");
    let dim = patch.dimension();
    let width = patch.simplex_dim() + 1;
    let mut target = |rows: &[f64]| -> Result<Vec<f64>, std::convert::Infallible> {
        Ok(vec![value; rows.len() / width * dim])
    };
    let start = Instant::now();
    let report = hunt(&patch, &options, &mut target).expect("the hunt runs");
    println!(
        "{} {:.6} {}",
        report.evaluated,
        start.elapsed().as_secs_f64(),
        report.broke
    );
}
