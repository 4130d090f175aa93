//! Subdivision, halving, subpatches and degree elevation of a degree-30 triangle, exactly.
//! `cargo bench --bench constructions`.

use criterion::{Criterion, criterion_group, criterion_main};
use num_rational::BigRational;
use tribez::hazmat::blossom::subpatch_exact;
use tribez::hazmat::elevate::elevate_exact;
use tribez::hazmat::patch::ControlNet;
use tribez::hazmat::simplex::Simplex;
use tribez::hazmat::subdivide::{halve_exact, midpoint_split_exact, split_at_pieces_exact};

fn q(a: i64, b: i64) -> BigRational {
    BigRational::new(a.into(), b.into())
}

/// A degree-n triangle in R^3 with small pseudo-random rational coordinates.
fn net(n: usize) -> ControlNet<BigRational> {
    let sx = Simplex::new(2, n);
    let mut state: u64 = 12345;
    let coords = (0..sx.len() * 3)
        .map(|_| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            q(
                ((state >> 33) % 199) as i64 - 99,
                ((state >> 20) % 16) as i64 + 1,
            )
        })
        .collect();
    ControlNet::new(sx, 3, coords)
}

fn constructions(c: &mut Criterion) {
    let n30 = net(30);
    let t = [q(1, 3), q(1, 5), q(7, 15)];
    let f = [
        vec![q(1, 3), q(1, 3), q(1, 3)],
        vec![q(2, 1), q(-1, 1), q(0, 1)],
        vec![q(1, 7), q(3, 7), q(3, 7)],
    ];
    c.bench_function("degree 30: split at a point", |b| {
        b.iter(|| split_at_pieces_exact(&n30, &t).unwrap())
    });
    c.bench_function("degree 30: four-way midpoint split", |b| {
        b.iter(|| midpoint_split_exact(&n30).unwrap())
    });
    c.bench_function("degree 30: halve", |b| b.iter(|| halve_exact(&n30, 0, 1)));
    c.bench_function("degree 30: subpatch", |b| {
        b.iter(|| subpatch_exact(&n30, &f).unwrap())
    });
    c.bench_function("degree 30: elevate by 1", |b| {
        b.iter(|| elevate_exact(&n30, 1))
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = constructions
}
criterion_main!(benches);
