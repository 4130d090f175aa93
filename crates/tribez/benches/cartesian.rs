//! Per-row cost of `--cartesian` batches against barycentric ones (issue 16: within 2×).
//!
//! The same 100,000 points of a cubic triangle over the domain (0,0), (3,0), (1,2), given once
//! as barycentric floats and once as Cartesian floats (computed from them in f64), judged in
//! memory by the batch checker on one thread (`BatchChecker::check_rows`: the float filter
//! first, exact arithmetic when it cannot decide) at `cond=1000`. The claims: the f64 de
//! Casteljau values at the barycentric floats, and for the Cartesian rows the exact values at
//! the Cartesian floats rounded to f64 (an f64 code's values there, converted to barycentric
//! coordinates in floats, fail `cond=1000` on about 25 rows in 100,000 where the condition
//! number is small, and a failing row is computed exactly for its report). So every row passes
//! on both sides: the figure is the cost of the filter, not of failure reports. Both sides run in the same process, interleaved by criterion; the number of
//! rows that fell back to exact arithmetic is printed once per side.
//! `cargo bench -p tribez --bench cartesian`.

use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use tribez::batch::{BatchChecker, BatchOptions};
use tribez::hazmat::domain::Domain;
use tribez::hazmat::exact::{Algorithm, ExactEvaluator};
use tribez::hazmat::number::{exact_f64, round_f64};
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
    let (mut bary, mut cart, mut values, mut cart_values) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let exact = ExactEvaluator::new(&net);
    for _ in 0..ROWS {
        let u = unit();
        let v = unit() * (1.0 - u);
        let l = [1.0 - u - v, u, v];
        let x = [
            l[0] * vertices[0][0] + l[1] * vertices[1][0] + l[2] * vertices[2][0],
            l[0] * vertices[0][1] + l[1] * vertices[1][1] + l[2] * vertices[2][1],
        ];
        let y = tribez::hazmat::float::casteljau(&fnet, &l);
        let at_x = domain.barycentric(&[q(x[0]), q(x[1])]).unwrap();
        let yc = exact
            .evaluate_fast(&at_x)
            .iter()
            .map(round_f64)
            .collect::<Vec<_>>();
        bary.extend(l);
        cart.extend(x);
        values.extend(y);
        cart_values.extend(yc);
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
    for (name, ch, pts, ys) in [
        ("barycentric", &cb, &bary, &values),
        ("cartesian", &cc, &cart, &cart_values),
    ] {
        let r = pool.install(|| ch.check_rows(pts, ys, 0, "<memory>", "cubic").unwrap().0);
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
                cc.check_rows(&cart, &cart_values, 0, "<memory>", "cubic")
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
