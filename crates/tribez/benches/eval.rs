//! `cargo bench`: exact and float evaluation, subdivision and degree elevation.
//!
//! Workloads (ratios against the peers come from `bench/compare.sh`, which runs the peers of
//! `bench/peers/` on the same input files; docs/performance.md):
//! - "reference" (`bench/peers/workload.py`): dimension 3, control points `p/q` with
//!   `|p| ≤ 2^16`, `1 ≤ q ≤ 2^16`, barycentric points `(a, b, c)/q` with `q ≤ 2^16`;
//! - "dyadic": the exact values of random f64 control points in `[−1, 1]` and of random f64
//!   barycentric points (`w = 1 − u − v` rounded, so the exact sum may differ from 1: the
//!   homogeneous form is evaluated, as certification sees it).
//!
//! Measurement times are short so that the whole `cargo bench` takes a few minutes.
//!
//! `check` of 1,000,000 f64 claims against plain f64 evaluation is in benches/check.rs.

use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use num_bigint::BigInt;
use num_rational::BigRational;
use tribez::hazmat::casteljau;
use tribez::hazmat::exact::{Algorithm, ExactEvaluator, evaluate_rational};
use tribez::hazmat::float::{
    casteljau_dvec3, casteljau_vec3, dvec3_points, horner_dvec3_many, horner_points_dvec3,
    horner_points_vec3, horner_vec3_many, net_f32, net_f64, vec3_points,
};
use tribez::hazmat::number::exact_f64;
use tribez::hazmat::patch::ControlNet;
use tribez::hazmat::simplex::Simplex;

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 16
    }
    fn below(&mut self, k: u64) -> u64 {
        self.next() % k
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 5) as f64 / (1u64 << 43) as f64
    }
}

fn reference_net(n: usize, rng: &mut Rng) -> ControlNet<BigRational> {
    let s = Simplex::new(2, n);
    let coords = (0..s.len() * 3)
        .map(|_| {
            BigRational::new(
                BigInt::from(rng.below(2 * 65_536 + 1) as i64 - 65_536),
                BigInt::from(rng.below(65_536) + 1),
            )
        })
        .collect();
    ControlNet::new(s, 3, coords)
}

fn reference_points(m: usize, rng: &mut Rng) -> Vec<Vec<BigRational>> {
    (0..m)
        .map(|_| {
            let q = rng.below(65_536) + 1;
            let a = rng.below(q + 1);
            let b = rng.below(q - a + 1);
            [a, b, q - a - b]
                .iter()
                .map(|&x| BigRational::new(x.into(), q.into()))
                .collect()
        })
        .collect()
}

fn dyadic_net(n: usize, rng: &mut Rng) -> ControlNet<BigRational> {
    let s = Simplex::new(2, n);
    let coords = (0..s.len() * 3)
        .map(|_| exact_f64(2.0 * rng.unit() - 1.0).unwrap())
        .collect();
    ControlNet::new(s, 3, coords)
}

fn float_points(m: usize, rng: &mut Rng) -> Vec<[f64; 3]> {
    (0..m)
        .map(|_| {
            let (mut a, mut b) = (rng.unit(), rng.unit());
            if a + b > 1.0 {
                (a, b) = (1.0 - a, 1.0 - b);
            }
            [1.0 - a - b, a, b]
        })
        .collect()
}

fn config(g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>) {
    g.sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
}

fn exact(c: &mut Criterion) {
    let mut g = c.benchmark_group("exact");
    config(&mut g);
    for n in [3, 10, 20, 30] {
        let mut rng = Rng(1000 + n as u64);
        let m = if n <= 10 { 200 } else { 50 };
        let net = reference_net(n, &mut rng);
        let pts = reference_points(m, &mut rng);
        let eval = ExactEvaluator::new(&net);
        g.throughput(Throughput::Elements(m as u64));
        g.bench_function(BenchmarkId::new("reference_horner", n), |b| {
            b.iter(|| {
                pts.iter()
                    .map(|p| eval.evaluate_fast(p))
                    .collect::<Vec<_>>()
            })
        });
        if n <= 10 {
            let few = &pts[..5];
            g.throughput(Throughput::Elements(5));
            g.bench_function(BenchmarkId::new("reference_rational_casteljau", n), |b| {
                b.iter(|| {
                    few.iter()
                        .map(|p| evaluate_rational(&net, p, Algorithm::Casteljau))
                        .collect::<Vec<_>>()
                })
            });
        }
        let dnet = dyadic_net(n, &mut rng);
        let dpts: Vec<Vec<BigRational>> = float_points(m, &mut rng)
            .iter()
            .map(|p| p.iter().map(|&x| exact_f64(x).unwrap()).collect())
            .collect();
        let deval = ExactEvaluator::new(&dnet);
        g.throughput(Throughput::Elements(m as u64));
        g.bench_function(BenchmarkId::new("dyadic_horner", n), |b| {
            b.iter(|| {
                dpts.iter()
                    .map(|p| deval.evaluate_fast(p))
                    .collect::<Vec<_>>()
            })
        });
    }
    g.finish();
}

fn float(c: &mut Criterion) {
    let mut g = c.benchmark_group("float");
    config(&mut g);
    let m = 10_000;
    for n in [3, 10, 20, 30] {
        let mut rng = Rng(2000 + n as u64);
        let net = reference_net(n, &mut rng);
        let pts = float_points(m, &mut rng);
        let pts32: Vec<[f32; 3]> = pts.iter().map(|p| p.map(|x| x as f32)).collect();
        let (n64, n32) = (net_f64(&net), net_f32(&net));
        let (d64, h64, d32, h32) = (
            dvec3_points(&n64),
            horner_points_dvec3(&n64),
            vec3_points(&n32),
            horner_points_vec3(&n32),
        );
        g.throughput(Throughput::Elements(m as u64));
        let mut out64 = Vec::new();
        g.bench_function(BenchmarkId::new("f64_horner", n), |b| {
            b.iter(|| horner_dvec3_many(&h64, n, &pts, &mut out64))
        });
        g.bench_function(BenchmarkId::new("f64_casteljau", n), |b| {
            b.iter(|| {
                pts.iter()
                    .map(|&u| casteljau_dvec3(&d64, n, u))
                    .collect::<Vec<_>>()
            })
        });
        let mut out32 = Vec::new();
        g.bench_function(BenchmarkId::new("f32_horner", n), |b| {
            b.iter(|| horner_vec3_many(&h32, n, &pts32, &mut out32))
        });
        g.bench_function(BenchmarkId::new("f32_casteljau", n), |b| {
            b.iter(|| {
                pts32
                    .iter()
                    .map(|&u| casteljau_vec3(&d32, n, u))
                    .collect::<Vec<_>>()
            })
        });
    }
    g.finish();
}

fn structure(c: &mut Criterion) {
    let mut g = c.benchmark_group("n30");
    config(&mut g);
    let mut rng = Rng(30);
    let net = reference_net(30, &mut rng);
    let at = reference_points(1, &mut rng).remove(0);
    // Subdivision at a point into three sub-triangles and elevation n → n + 1, exactly, on the
    // reference workload (tribez::hazmat::subdivide / tribez::hazmat::elevate; `cargo bench --bench
    // constructions` measures more constructions on small rationals).
    g.bench_function("split_at_point_exact", |b| {
        b.iter(|| {
            tribez::hazmat::subdivide::split_at_pieces(&net, &at)
                .unwrap()
                .len()
        })
    });
    g.bench_function("elevate_by_1_exact", |b| {
        b.iter(|| tribez::hazmat::elevate::elevate(&net, 1).len())
    });
    let n64 = net_f64(&net);
    let at64: Vec<f64> = at.iter().map(tribez::hazmat::number::round_f64).collect();
    g.bench_function("subdivision_levels_f64", |b| {
        b.iter(|| casteljau::levels(&n64, &at64).len())
    });
    g.finish();
}

criterion_group!(benches, exact, float, structure);
criterion_main!(benches);
