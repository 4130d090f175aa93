//! Machine-readable timings for `bench/compare.sh`, on a case file of the peers' format
//! (`bench/peers/workload.py`: `{"degree", "dim", "nodes": [[x, y, z], …], "points": …}`, nodes in
//! `bezier`'s order, which is tribez's canonical order). One JSON object per line.
//!
//! ```text
//! cargo run --release --example speed -- exact CASE.json [--expect PEER_RESULTS.json]
//! cargo run --release --example speed -- float CASE.json M
//! ```

use std::time::Instant;

use num_rational::BigRational;
use serde_json::{Value, json};
use tribez::hazmat::exact::{Algorithm, ExactEvaluator};
use tribez::hazmat::float::{
    casteljau_dvec3, casteljau_vec3, dvec3_points, horner_dvec3, horner_dvec3_many,
    horner_points_dvec3, horner_points_vec3, horner_vec3_many, net_f32, net_f64, vec3_points,
};
use tribez::hazmat::number::{format_rational, parse_rational};
use tribez::hazmat::patch::ControlNet;

fn scalar(v: &Value) -> BigRational {
    let text = match v {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    parse_rational(&text).unwrap_or_else(|e| panic!("bad number {text}: {e}"))
}

fn best_of<T>(repeat: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..repeat {
        let t0 = Instant::now();
        let r = f();
        best = best.min(t0.elapsed().as_secs_f64());
        out = Some(r);
    }
    (best, out.expect("repeat >= 1"))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mode, path) = (args[0].as_str(), &args[1]);
    let case: Value = serde_json::from_str(&std::fs::read_to_string(path).expect("read case"))
        .expect("case JSON");
    let n = case["degree"].as_u64().expect("degree") as usize;
    let nodes: Vec<Vec<BigRational>> = case["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_array().unwrap().iter().map(scalar).collect())
        .collect();
    let net = ControlNet::from_points(2, n, &nodes);
    match mode {
        "exact" => {
            let points: Vec<Vec<BigRational>> = case["points"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| p.as_array().unwrap().iter().map(scalar).collect())
                .collect();
            let t0 = Instant::now();
            let eval = ExactEvaluator::new(&net);
            let prepare = t0.elapsed().as_secs_f64();
            let repeat = std::env::var("SPEED_REPEAT")
                .ok()
                .and_then(|r| r.parse().ok())
                .unwrap_or(3);
            let (secs, results) = best_of(repeat, || {
                points
                    .iter()
                    .map(|p| eval.evaluate_fast(p))
                    .collect::<Vec<_>>()
            });
            let bits: Vec<u64> = results
                .iter()
                .flatten()
                .map(|q| q.numer().bits() + q.denom().bits())
                .collect();
            let mut out = json!({
                "tool": "tribez", "what": "exact", "algo": "horner", "degree": n, "points": points.len(),
                "seconds": secs, "us_per_point": secs / points.len() as f64 * 1e6, "prepare_seconds": prepare,
                "mean_result_bits": bits.iter().sum::<u64>() as f64 / bits.len() as f64,
                "max_result_bits": bits.iter().max(),
            });
            if std::env::var_os("SPEED_NO_CHECK").is_some() {
                println!("{out}");
                return;
            }
            if n <= 10 {
                let few = &points[..points.len().min(50)];
                let (s, generic) = best_of(1, || {
                    few.iter()
                        .map(|p| {
                            tribez::hazmat::exact::evaluate_rational(&net, p, Algorithm::Casteljau)
                        })
                        .collect::<Vec<_>>()
                });
                assert!(
                    generic.iter().zip(&results).all(|(a, b)| a == b),
                    "fast kernel differs from rational de Casteljau"
                );
                out["us_per_point_rational_casteljau"] = json!(s / few.len() as f64 * 1e6);
            }
            let t1 = Instant::now();
            let text: usize = results
                .iter()
                .flatten()
                .map(|q| format_rational(q).len())
                .sum();
            out["print_us_per_point"] =
                json!(t1.elapsed().as_secs_f64() / points.len() as f64 * 1e6);
            out["printed_chars"] = json!(text);
            if let Some(i) = args.iter().position(|a| a == "--expect") {
                let peer: Value = serde_json::from_str(
                    &std::fs::read_to_string(&args[i + 1]).expect("read peer results"),
                )
                .expect("peer JSON");
                let theirs = peer["results"].as_array().unwrap();
                let identical = theirs.len() == results.len()
                    && theirs.iter().zip(&results).all(|(t, r)| {
                        t.as_array()
                            .unwrap()
                            .iter()
                            .zip(r)
                            .all(|(a, b)| a.as_str() == Some(format_rational(b).as_str()))
                    });
                out["identical_to_peer"] = json!(identical);
            }
            println!("{out}");
        }
        "float" => {
            let m: usize = args[2].parse().expect("number of points");
            // Uniform-ish barycentric float points, as peer_eval.py draws them (a simple LCG).
            let mut s = 0x9E37_79B9_7F4A_7C15u64;
            let mut next = || {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (s >> 11) as f64 / (1u64 << 53) as f64
            };
            let pts: Vec<[f64; 3]> = (0..m)
                .map(|_| {
                    let (mut a, mut b) = (next(), next());
                    if a + b > 1.0 {
                        (a, b) = (1.0 - a, 1.0 - b);
                    }
                    [1.0 - a - b, a, b]
                })
                .collect();
            let pts32: Vec<[f32; 3]> = pts.iter().map(|p| p.map(|x| x as f32)).collect();
            let n64 = net_f64(&net);
            let n32 = net_f32(&net);
            let (d64, h64, d32, h32) = (
                dvec3_points(&n64),
                horner_points_dvec3(&n64),
                vec3_points(&n32),
                horner_points_vec3(&n32),
            );
            let report = |what: &str, secs: f64, sink: f64| {
                println!(
                    "{}",
                    json!({"tool": "tribez", "what": what, "degree": n, "points": m, "seconds": secs, "us_per_point": secs / m as f64 * 1e6, "checksum": sink})
                );
            };
            let mut out64 = Vec::new();
            let (t, v) = best_of(5, || {
                horner_dvec3_many(&h64, n, &pts, &mut out64);
                out64.iter().map(|p| p.element_sum()).sum::<f64>()
            });
            report("f64_horner", t, v);
            let (t, v) = best_of(5, || {
                pts.iter()
                    .map(|&u| horner_dvec3(&h64, n, u).element_sum())
                    .sum::<f64>()
            });
            report("f64_horner_one_point_calls", t, v);
            let (t, v) = best_of(5, || {
                pts.iter()
                    .map(|&u| casteljau_dvec3(&d64, n, u).element_sum())
                    .sum::<f64>()
            });
            report("f64_casteljau", t, v);
            let mut out32 = Vec::new();
            let (t, v) = best_of(5, || {
                horner_vec3_many(&h32, n, &pts32, &mut out32);
                out32
                    .iter()
                    .map(|p| f64::from(p.element_sum()))
                    .sum::<f64>()
            });
            report("f32_horner", t, v);
            let (t, v) = best_of(5, || {
                pts32
                    .iter()
                    .map(|&u| f64::from(casteljau_vec3(&d32, n, u).element_sum()))
                    .sum::<f64>()
            });
            report("f32_casteljau", t, v);
        }
        "csv" => {
            // M random float points and their f64 Horner values, as rows for
            // `tribez check --results FILE --precision f64` (f64 Display is the shortest round trip).
            let m: usize = args[2].parse().expect("number of points");
            let mut s = 0x2545_F491_4F6C_DD1Du64;
            let mut next = || {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                (s >> 11) as f64 / (1u64 << 53) as f64
            };
            let pts: Vec<[f64; 3]> = (0..m)
                .map(|_| {
                    let (mut a, mut b) = (next(), next());
                    if a + b > 1.0 {
                        (a, b) = (1.0 - a, 1.0 - b);
                    }
                    [1.0 - a - b, a, b]
                })
                .collect();
            let h64 = horner_points_dvec3(&net_f64(&net));
            let mut out = Vec::new();
            let t0 = Instant::now();
            horner_dvec3_many(&h64, n, &pts, &mut out);
            let secs = t0.elapsed().as_secs_f64();
            let mut text = String::with_capacity(m * 120);
            for (p, v) in pts.iter().zip(&out) {
                text += &format!("{},{},{},{},{},{}\n", p[0], p[1], p[2], v.x, v.y, v.z);
            }
            std::fs::write(&args[3], text).expect("write csv");
            eprintln!(
                "{}",
                json!({"tool": "tribez", "what": "f64_horner_for_csv", "degree": n, "points": m, "seconds": secs})
            );
        }
        "read-eval" => {
            // The end-to-end baseline of `tribez check --results FILE` on a `csv` file: read the
            // file, parse the six numbers of each row (Rust's correctly rounded `str::parse`),
            // evaluate the patch at the first three by f64 de Casteljau and compare with the last
            // three. One thread; best of 3 (one pass with --once, to be timed as a process).
            let path = &args[2];
            let d64 = dvec3_points(&net_f64(&net));
            let passes = if args.iter().any(|a| a == "--once") {
                1
            } else {
                3
            };
            let (secs, differ) = best_of(passes, || {
                let text = std::fs::read_to_string(path).expect("read csv");
                let mut differ = 0usize;
                for line in text.lines().filter(|l| !l.starts_with('#')) {
                    let mut x = [0f64; 6];
                    for (slot, t) in x.iter_mut().zip(line.split(',')) {
                        *slot = t.trim().parse().expect("a number");
                    }
                    let v = casteljau_dvec3(&d64, n, [x[0], x[1], x[2]]);
                    differ += usize::from([v.x, v.y, v.z] != [x[3], x[4], x[5]]);
                }
                differ
            });
            println!(
                "{}",
                json!({"tool": "tribez", "what": "read_parse_f64_casteljau", "degree": n, "seconds": secs, "rows_differing": differ})
            );
        }
        other => panic!("unknown mode {other}"),
    }
}
