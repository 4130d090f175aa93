//! Exact least-squares fits (issue 14's target: a quadratic C0 fit of 10,000 data points on a
//! 50-triangle mesh within 10 s), and how the time grows with triangles and points.
//! `cargo bench --bench fit`; `FIT_BENCH=quick` runs only the target case.
//!
//! The meshes are grids of the unit square, `kx × ky` cells cut along a diagonal (`2·kx·ky`
//! triangles); the data are points with 4-digit decimal coordinates from a fixed linear
//! congruential sequence, with 6-digit decimal values of a smooth function.

use criterion::{Criterion, criterion_group, criterion_main};
use tribez::fit::{DataPoint, FitOptions, Smoothness, fit};
use tribez::mesh::Mesh;
use tribez::{Rational, parse_rational};

fn grid(kx: usize, ky: usize, n: usize) -> Mesh {
    let q = |a: usize, b: usize| Rational::new(a.into(), b.into());
    let mut v = Vec::new();
    for j in 0..=ky {
        for i in 0..=kx {
            v.push([q(i, kx), q(j, ky)]);
        }
    }
    let id = |i: usize, j: usize| j * (kx + 1) + i;
    let mut t = Vec::new();
    for j in 0..ky {
        for i in 0..kx {
            t.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            t.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    Mesh::new(v, t, n).unwrap()
}

fn data(count: usize) -> Vec<DataPoint> {
    let mut seed: u64 = 2024;
    let mut next = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) % 10_001
    };
    (0..count)
        .map(|i| {
            let (a, b) = (next(), next());
            let (x, y) = (a as f64 / 1e4, b as f64 / 1e4);
            let v = (3.0 * x).sin() * (2.0 * y).cos() + x * y;
            DataPoint {
                line: i + 1,
                x: parse_rational(&format!("{a}/10000")).unwrap(),
                y: parse_rational(&format!("{b}/10000")).unwrap(),
                value: parse_rational(&format!("{v:.6}")).unwrap(),
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let quick = std::env::var("FIT_BENCH").is_ok_and(|v| v == "quick");
    let mut cases = vec![((5, 5), 10_000usize, 2usize, Smoothness::C0)];
    if !quick {
        cases.extend([
            ((5, 1), 10_000, 2, Smoothness::C0),
            ((10, 10), 10_000, 2, Smoothness::C0),
            ((5, 5), 1_000, 2, Smoothness::C0),
            ((5, 5), 100_000, 2, Smoothness::C0),
            ((5, 5), 10_000, 3, Smoothness::C0),
            ((5, 5), 10_000, 2, Smoothness::C1),
            ((5, 5), 10_000, 3, Smoothness::C1),
        ]);
    }
    let mut group = c.benchmark_group("fit");
    group.sample_size(10);
    for ((kx, ky), points, n, smoothness) in cases {
        let mesh = grid(kx, ky, n);
        let d = data(points);
        let options = FitOptions {
            smoothness,
            regularize: true,
            ..FitOptions::default()
        };
        let name = format!(
            "{} triangles, {points} points, degree {n}, {smoothness} ({} ordinates)",
            2 * kx * ky,
            mesh.ordinate_count()
        );
        group.bench_function(&name, |b| {
            b.iter(|| fit(&mesh, &d, "bench", &options).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
