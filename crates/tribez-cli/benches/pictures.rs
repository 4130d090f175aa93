//! Pictures (issue 15's targets): an error map of 100,000 rows within 1 s, a degree-20 surface
//! sampled at 10,000 points within 1 s. Both are timed end to end, as a user runs them (the
//! `tribez` binary, reading the files, writing the SVG):
//!
//! * `check 100k rows` is `tribez check --patch P --results R --precision f64 --tolerance
//!   ulps=4` over 100,000 rows of a cubic (claimed values from plain f64 de Casteljau here);
//!   `check 100k rows + map` adds `--plot map.svg`, and `+ map + html` adds `--html`: their
//!   difference is what drawing costs.
//! * `plot degree 20, 10011 points` is `tribez plot P -o surface.svg --samples 140`: 10,011
//!   exact evaluations of a degree-20 triangle in R^3 (231 control points), 19,600 shaded
//!   triangles, the net on top.
//!
//! `cargo bench -p tribez-cli --bench pictures`.

use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};

const ROWS: usize = 100_000;

/// A small deterministic generator (numbers in [0, 1)).
struct Lcg(u64);

impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

type Net = HashMap<[usize; 3], [f64; 3]>;

/// Write a patch file of degree `n` in R^3 (x, y on the abscissae, z small integers over 7) and
/// return its net in f64.
fn patch(dir: &Path, n: usize) -> Net {
    let mut text = format!("degree = {n}\n[control_points]\n");
    let mut net = Net::new();
    let mut k = 0usize;
    for i in (0..=n).rev() {
        for j in (0..=n - i).rev() {
            let l = n - i - j;
            let z = (k * 37 % 23) as i64 - 11;
            k += 1;
            text += &format!("\"{i},{j},{l}\" = [\"{i}/{n}\", \"{j}/{n}\", \"{z}/7\"]\n");
            net.insert(
                [i, j, l],
                [i as f64 / n as f64, j as f64 / n as f64, z as f64 / 7.0],
            );
        }
    }
    std::fs::write(dir.join(format!("degree{n}.toml")), text).unwrap();
    net
}

/// de Casteljau in f64 at `(u, v, w)` (the float code whose results are checked).
fn casteljau(n: usize, net: &Net, l: [f64; 3]) -> [f64; 3] {
    let mut b = net.clone();
    for r in (0..n).rev() {
        let mut next = Net::new();
        for i in 0..=r {
            for j in 0..=r - i {
                let k = r - i - j;
                let (p, q, s) = (b[&[i + 1, j, k]], b[&[i, j + 1, k]], b[&[i, j, k + 1]]);
                let mut c = [0.0; 3];
                for t in 0..3 {
                    c[t] = l[0] * p[t] + l[1] * q[t] + l[2] * s[t];
                }
                next.insert([i, j, k], c);
            }
        }
        b = next;
    }
    b[&[0, 0, 0]]
}

fn pictures(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let net = patch(d, 3);
    let mut rng = Lcg(7);
    let mut rows = String::with_capacity(ROWS * 100);
    for _ in 0..ROWS {
        let u = rng.unit();
        let v = rng.unit() * (1.0 - u);
        let l = [u, v, 1.0 - u - v];
        let y = casteljau(3, &net, l);
        rows += &format!(
            "{:?},{:?},{:?},{:?},{:?},{:?}\n",
            l[0], l[1], l[2], y[0], y[1], y[2]
        );
    }
    std::fs::write(d.join("rows.csv"), rows).unwrap();
    patch(d, 20);
    let tribez = env!("CARGO_BIN_EXE_tribez");
    let run = |args: &[&str]| {
        let out = Command::new(tribez)
            .current_dir(d)
            .args(args)
            .output()
            .unwrap();
        assert!(
            matches!(out.status.code(), Some(0 | 1)),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    };
    let check = [
        "check",
        "--patch",
        "degree3.toml",
        "--results",
        "rows.csv",
        "--precision",
        "f64",
        "--tolerance",
        "ulps=4",
    ];
    let mut g = c.benchmark_group("pictures");
    g.sample_size(10).measurement_time(Duration::from_secs(8));
    g.bench_function("check 100k rows", |b| b.iter(|| run(&check)));
    let with = |extra: &[&'static str]| [&check[..], extra].concat();
    let map = with(&["--plot", "map.svg"]);
    g.bench_function("check 100k rows + map", |b| b.iter(|| run(&map)));
    let both = with(&["--plot", "map.svg", "--html", "report.html"]);
    g.bench_function("check 100k rows + map + html", |b| b.iter(|| run(&both)));
    let plot = [
        "plot",
        "degree20.toml",
        "-o",
        "surface.svg",
        "--samples",
        "140",
    ];
    g.bench_function("plot degree 20, 10011 points", |b| b.iter(|| run(&plot)));
    g.finish();
}

criterion_group!(benches, pictures);
criterion_main!(benches);
