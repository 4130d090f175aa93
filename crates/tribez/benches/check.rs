//! Judging float evaluation claims against plain float evaluation (issue 4's target: checking
//! 1,000,000 f64 claims of a degree-3 patch costs at most 10× evaluating them in f64).
//!
//! Both sides run on one thread over the same 1,000,000 points, with the numbers already in
//! memory: `f64 de Casteljau` is the glam kernel writing into a preallocated buffer; `judge/TOL`
//! is [`Filter::judge`], the row judgement `tribez check --patch P --results FILE` runs per row
//! (the plain running-error stage and the compensated stage, in the order the tolerance calls
//! for: tight tolerances go straight to the compensated one), deciding every claim at tolerance
//! TOL. Rows left open by both stages would go to exact arithmetic; the bench asserts there are
//! none, so it measures the filter alone. `judge+report/TOL` is what the command runs per row:
//! its report (histogram, worst row) wants tight ULP figures for every row, so it judges
//! compensated-first whatever the tolerance. `cargo bench --bench check`.

use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use num_rational::BigRational;
use tribez::hazmat::certify::filter::{Decision, Enclosure, Filter, Scratch, Thresholds};
use tribez::hazmat::certify::measures::Tolerance;
use tribez::hazmat::exact::Algorithm;
use tribez::hazmat::float::{Precision, casteljau_dvec3, dvec3_points, net_f64};
use tribez::hazmat::patch::ControlNet;
use tribez::hazmat::simplex::Simplex;

const N: usize = 3;
const CLAIMS: usize = 1_000_000;

fn workload() -> (ControlNet<f64>, Vec<[f64; 3]>) {
    let simplex = Simplex::new(2, N);
    let coords: Vec<BigRational> = (0..simplex.len() * 3)
        .map(|i| BigRational::new(((i * 37 % 23) as i64 - 11).into(), 7.into()))
        .collect();
    let net = net_f64(&ControlNet::new(simplex, 3, coords));
    let mut s = 1u64;
    let mut unit = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let pts = (0..CLAIMS)
        .map(|_| {
            let u = unit();
            let v = unit() * (1.0 - u);
            [u, v, 1.0 - u - v]
        })
        .collect();
    (net, pts)
}

fn check(c: &mut Criterion) {
    let (net, pts) = workload();
    let dpts = dvec3_points(&net);
    let mut out = vec![[0.0f64; 3]; CLAIMS];
    let mut g = c.benchmark_group("check_1M_f64_claims_n3");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3));
    g.throughput(Throughput::Elements(CLAIMS as u64));
    g.bench_function("f64 de Casteljau (plain evaluation)", |b| {
        b.iter(|| {
            for (p, o) in pts.iter().zip(out.iter_mut()) {
                let v = casteljau_dvec3(&dpts, N, *p);
                *o = [v.x, v.y, v.z];
            }
        })
    });
    let claimed = out.clone();
    let filter = Filter::new(&net);
    for tol in ["cond=9", "bound", "ulps=4", "correctly_rounded"] {
        let th = Thresholds::new(
            &Tolerance::parse(tol).expect("known tolerance"),
            Precision::F64,
            Algorithm::Casteljau,
            2,
            N,
        );
        let mut scratch = Scratch::default();
        let mut enc = vec![Enclosure::default(); 3];
        // the row judgement of `tribez check --results` (src/commands/batch.rs)
        let judge = |scratch: &mut Scratch, enc: &mut [Enclosure]| -> usize {
            let mut open = 0;
            for (p, y) in pts.iter().zip(&claimed) {
                if filter.judge(&th, p, y, scratch, enc).decision == Decision::Undecided {
                    open += 1;
                }
            }
            open
        };
        assert_eq!(
            judge(&mut scratch, &mut enc),
            0,
            "{tol}: some claims would need exact arithmetic"
        );
        g.bench_function(format!("judge/{tol}"), |b| {
            b.iter(|| judge(&mut scratch, &mut enc))
        });
        // what the command does per row (src/commands/batch/judge.rs): its report (histogram,
        // worst row) wants every row's tight ULP figures, so it judges compensated-first
        // whatever the tolerance ([`Filter::judge_tight`]), then tightens the rare rows only the
        // plain stage could decide
        let with_report = |scratch: &mut Scratch, enc: &mut [Enclosure]| -> f64 {
            let mut worst = 0f64;
            for (p, y) in pts.iter().zip(&claimed) {
                let r = filter.judge_tight(&th, p, y, scratch, enc);
                let hi = if r.tight {
                    r.ulps
                } else {
                    filter.ulps_bounds(&th, p, y, scratch, enc).1
                };
                worst = worst.max(hi);
            }
            worst
        };
        g.bench_function(format!("judge+report/{tol}"), |b| {
            b.iter(|| with_report(&mut scratch, &mut enc))
        });
    }
    g.finish();
}

criterion_group!(benches, check);
criterion_main!(benches);
