//! Inverse problems, exactly (issue 13's targets): all intersections of two cubics (≤ 10 ms) and
//! of two quintics (≤ 100 ms), locate on a cubic triangle (≤ 100 ms), a ray against a cubic patch
//! (≤ 10 ms). `cargo bench --bench inverse`.

use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};
use tribez::algebraic::{Curve, intersect_curves, locate, ray_hits};
use tribez::{Patch, parse_rational};

fn fixture(name: &str) -> Patch {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse");
    Patch::from_file(dir.join(name)).unwrap()
}

fn curve(name: &str) -> Curve {
    Curve::from_patch(&fixture(name), name).unwrap()
}

fn inverse(c: &mut Criterion) {
    let q = |s: &str| parse_rational(s).unwrap();
    let (a, b) = (curve("cubic_a.toml"), curve("cubic_b.toml"));
    assert_eq!(intersect_curves(&a, &b).unwrap().points.len(), 3);
    c.bench_function("intersect two cubics (3 points)", |x| {
        x.iter(|| intersect_curves(&a, &b).unwrap())
    });
    let (a5, b5) = (curve("random/r02_a.toml"), curve("random/r01_b.toml"));
    assert_eq!((a5.degree(), b5.degree()), (5, 5));
    let n5 = intersect_curves(&a5, &b5).unwrap().points.len();
    c.bench_function(&format!("intersect two quintics ({n5} points)"), |x| {
        x.iter(|| intersect_curves(&a5, &b5).unwrap())
    });
    let tri = fixture("cubic_triangle.toml");
    let p = [q("1"), q("1")];
    assert_eq!(locate(&tri, &p, false).unwrap().points.len(), 1);
    c.bench_function("locate on a cubic triangle", |x| {
        x.iter(|| locate(&tri, &p, false).unwrap())
    });
    let surf = fixture("cubic_surface.toml");
    let (o, d) = (
        [q("1/5"), q("1/5"), q("3")],
        [q("1/10"), q("1/20"), q("-1")],
    );
    assert_eq!(ray_hits(&surf, &o, &d).unwrap().hits.len(), 1);
    c.bench_function("ray against a cubic patch", |x| {
        x.iter(|| ray_hits(&surf, &o, &d).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = inverse
}
criterion_main!(benches);
