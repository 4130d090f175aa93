//! Per-row cost of `--cartesian` batches against barycentric ones (issue 16: within 2×).
//!
//! The same 100,000 points of a cubic triangle over the domain (0,0), (3,0), (1,2), given once
//! as barycentric floats and once as Cartesian floats (computed from them in f64), with the f64
//! de Casteljau values as the claims, judged in memory by the batch checker on one thread
//! (`BatchChecker::check_rows`: the float filter first, exact arithmetic when it cannot decide)
//! at `cond=1000` (every row decided by the filter and passing on both sides: the cost of the
//! filter, not of failure reports). Both sides run in the same process, interleaved by criterion; the number of
//! rows that fell back to exact arithmetic is printed once per side.
//! `cargo bench -p tribez --bench cartesian`.

use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use tribez::batch::{BatchChecker, BatchOptions};
use tribez::hazmat::domain::Domain;
use tribez::hazmat::exact::Algorithm;
use tribez::hazmat::number::exact_f64;
use tribez::hazmat::patch::{BezierPatch, ControlNet};
use tribez::hazmat::simplex::Simplex;
use tribez::{Precision, Rational, Tolerance};

const ROWS: usize = 100_000;

fn bench(c: &mut Criterion) {
    let q = |x: f64| exact_f64(x).unwrap();
    let simplex = Simplex::new(2, 3);
    let coords: Vec<Rational> = (0..simplex.len() * 3)
        .map(|i| Rational::new(((i * 37 % 23) as i64 - 11).into(), 8.into()))
        .collect();
    let net = ControlNet::new(simplex.clone(), 3, coords);
    let fnet = net.map(tribez::hazmat::number::round_f64);
    let _ = &simplex;
    let vertices = [[0.0, 0.0], [3.0, 0.0], [1.0, 2.0]];
    let domain = Domain::new(vertices.iter().map(|v| vec![q(v[0]), q(v[1])]).collect()).unwrap();
    let mut s = 1u64;
    let mut unit = || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut bary, mut cart, mut values) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..ROWS {
        let u = unit();
        let v = unit() * (1.0 - u);
        let l = [1.0 - u - v, u, v];
        let x = [
            l[0] * vertices[0][0] + l[1] * vertices[1][0] + l[2] * vertices[2][0],
            l[0] * vertices[0][1] + l[1] * vertices[1][1] + l[2] * vertices[2][1],
        ];
        let y = tribez::hazmat::float::casteljau(&fnet, &l);
        bary.extend(l);
        cart.extend(x);
        values.extend(y);
    }
    let mut patch = BezierPatch::new(net);
    patch.domain = Some(domain);
    let checker = |cartesian: bool| {
        let options = BatchOptions {
            tolerance: Tolerance::parse("cond=1000").unwrap(),
            precision: Some(Precision::F64),
            algorithm: Algorithm::Casteljau,
            cartesian,
            ..BatchOptions::default()
        };
        BatchChecker::new(patch.clone(), &options).unwrap()
    };
    let (cb, cc) = (checker(false), checker(true));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    for (name, ch, pts) in [("barycentric", &cb, &bary), ("cartesian", &cc, &cart)] {
        let r = pool.install(|| {
            ch.check_rows(pts, &values, 0, "<memory>", "cubic")
                .unwrap()
                .0
        });
        eprintln!(
            "{name}: {} rows, {} passed, {} fell back to exact arithmetic",
            r.checked, r.passed, r.fell_back
        );
    }
    let mut g = c.benchmark_group("batch_100k_rows_n3_cond1000");
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(4));
    g.throughput(Throughput::Elements(ROWS as u64));
    g.bench_function("barycentric", |b| {
        b.iter(|| {
            pool.install(|| {
                cb.check_rows(&bary, &values, 0, "<memory>", "cubic")
                    .unwrap()
                    .0
                    .passed
            })
        })
    });
    g.bench_function("cartesian", |b| {
        b.iter(|| {
            pool.install(|| {
                cc.check_rows(&cart, &values, 0, "<memory>", "cubic")
                    .unwrap()
                    .0
                    .passed
            })
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
