//! Reading input files is linear in their size (issue 10): the largest patch file allowed
//! (`MAX_CONTROL_POINTS` = 250,000 control points: a 3-simplex of degree 112 has 246,905) read
//! from TOML and from JSON, parsed and turned into a patch, must take at most 2 s; a JSON points
//! file of 100,000 points likewise. The files are written to a temporary directory first (not
//! measured); each iteration is the library's whole read (`read_patch`, `read_points`).
//! `cargo bench -p tribez --bench read`.

use std::fmt::Write;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use tribez::hazmat::io::patch_file::{MAX_CONTROL_POINTS, read_patch};
use tribez::hazmat::io::points::read_points;

const DEGREE: usize = 112;

/// Every multi-index (i, j, k, l) of degree `n` on the 3-simplex.
fn indices(n: usize) -> Vec<[usize; 4]> {
    let mut out = Vec::new();
    for i in 0..=n {
        for j in 0..=n - i {
            for k in 0..=n - i - j {
                out.push([i, j, k, n - i - j - k]);
            }
        }
    }
    out
}

fn coords(a: &[usize; 4]) -> [String; 3] {
    [
        format!("{}/{}", a[0] * 7 + 1, a[1] + 3),
        format!("-{}.{}", a[2], a[3]),
        format!("{}e-3", a[0] + a[3]),
    ]
}

fn toml_patch() -> String {
    let mut s = format!("name = \"largest\"\ndegree = {DEGREE}\n\n[control_points]\n");
    for a in indices(DEGREE) {
        let [x, y, z] = coords(&a);
        writeln!(
            s,
            "\"{},{},{},{}\" = [\"{x}\", \"{y}\", \"{z}\"]",
            a[0], a[1], a[2], a[3]
        )
        .unwrap();
    }
    s
}

fn json_patch() -> String {
    let mut s = format!(
        "{{\n  \"name\": \"largest\",\n  \"degree\": {DEGREE},\n  \"control_points\": {{\n"
    );
    let all = indices(DEGREE);
    for (n, a) in all.iter().enumerate() {
        let [x, y, z] = coords(a);
        let comma = if n + 1 < all.len() { "," } else { "" };
        writeln!(
            s,
            "    \"{},{},{},{}\": [\"{x}\", \"{y}\", \"{z}\"]{comma}",
            a[0], a[1], a[2], a[3]
        )
        .unwrap();
    }
    s + "  }\n}\n"
}

fn json_points(n: usize) -> String {
    let mut s = String::from("[\n");
    for i in 0..n {
        let comma = if i + 1 < n { "," } else { "" };
        writeln!(s, "  [{}e-6, 0.25, {}]{comma}", i % 1000, i % 7).unwrap();
    }
    s + "]\n"
}

fn bench(c: &mut Criterion) {
    assert!(indices(DEGREE).len() <= MAX_CONTROL_POINTS);
    assert!(indices(DEGREE + 1).len() > MAX_CONTROL_POINTS);
    let mut g = c.benchmark_group("read");
    g.sample_size(10).measurement_time(Duration::from_secs(20));
    let dir = tempfile::tempdir().unwrap();
    let toml = dir.path().join("largest.toml");
    std::fs::write(&toml, toml_patch()).unwrap();
    let json = dir.path().join("largest.json");
    std::fs::write(&json, json_patch()).unwrap();
    let points = dir.path().join("points.json");
    std::fs::write(&points, json_points(100_000)).unwrap();
    g.bench_function("patch TOML 246,905 control points", |b| {
        b.iter(|| read_patch(&toml).unwrap())
    });
    g.bench_function("patch JSON 246,905 control points", |b| {
        b.iter(|| read_patch(&json).unwrap())
    });
    g.bench_function("points JSON 100,000", |b| {
        b.iter(|| read_points(&points, 3).unwrap())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
