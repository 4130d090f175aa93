//! Rough timing (not a benchmark; `cargo bench` has those): judging 1,000,000 f64 evaluation
//! claims of a cubic with the float filter, against evaluating the same points in f64 alone.
//!
//! `cargo run --release --example filter_ratio`

use std::time::Instant;

use num_rational::BigRational;
use tribez::hazmat::certify::filter::{Decision, Enclosure, Filter, Scratch, Thresholds};
use tribez::hazmat::certify::measures::Tolerance;
use tribez::hazmat::exact::Algorithm;
use tribez::hazmat::float::net_f64;
use tribez::hazmat::patch::ControlNet;
use tribez::hazmat::simplex::Simplex;

fn main() {
    let n = 3;
    let simplex = Simplex::new(2, n);
    let coords: Vec<BigRational> = (0..simplex.len() * 3)
        .map(|i| BigRational::new(((i * 37 % 23) as i64 - 11).into(), 7.into()))
        .collect();
    let net = net_f64(&ControlNet::new(simplex, 3, coords));
    let count = 1_000_000;
    let mut s = 1u64;
    let mut unit = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let pts: Vec<[f64; 3]> = (0..count)
        .map(|_| {
            let u = unit();
            let v = unit() * (1.0 - u);
            [u, v, 1.0 - u - v]
        })
        .collect();
    // plain f64 evaluation: the glam kernel (no allocation per point), as a renderer would run it
    let dpts = tribez::hazmat::float::dvec3_points(&net);
    let t = Instant::now();
    let claimed: Vec<Vec<f64>> = pts
        .iter()
        .map(|p| {
            let v = tribez::hazmat::float::casteljau_dvec3(&dpts, n, *p);
            vec![v.x, v.y, v.z]
        })
        .collect();
    let eval = t.elapsed();
    let filter = Filter::new(&net);
    for tol in ["ulps=4", "cond=9", "correctly_rounded", "bound"] {
        let th = Thresholds::new(
            &Tolerance::parse(tol).unwrap(),
            tribez::hazmat::float::Precision::F64,
            Algorithm::Casteljau,
            2,
            n,
        );
        let mut scratch = Scratch::default();
        let mut enc = vec![Enclosure::default(); 3];
        let t = Instant::now();
        let mut undecided = 0;
        // the row judgement of `tribez check --results` (plain and compensated stages, in the
        // order the tolerance calls for)
        for (p, y) in pts.iter().zip(&claimed) {
            if filter.judge(&th, p, y, &mut scratch, &mut enc).decision == Decision::Undecided {
                undecided += 1;
            }
        }
        let check = t.elapsed();
        println!(
            "{tol}: f64 evaluation {:?}, filter check {:?}: ratio {:.2}; {undecided} of {count} undecided (these go to the exact path)",
            eval,
            check,
            check.as_secs_f64() / eval.as_secs_f64()
        );
    }
}
