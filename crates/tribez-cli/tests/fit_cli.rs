//! `tribez fit` and `tribez check --mesh FITTED --fit DATA` as a user runs them.
//!
//! Expected values come from outside tribez: fixtures/fit/small/expected.json (SymPy's exact
//! solution of the normal equations, derive.py, with the C1 conditions derived from gradients
//! rather than the μ rule), fixtures/fit/numpy (numpy's lstsq, fit_numpy.py), and hand
//! derivations in the comments.

mod common;

use std::path::{Path, PathBuf};

use common::{fails, fixtures, listing, tribez, write};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use serde_json::Value as Json;

fn fx(rel: &str) -> String {
    fixtures().join(rel).display().to_string()
}

fn q(s: &str) -> BigRational {
    tribez::parse_rational(s).unwrap_or_else(|e| panic!("{s}: {e}"))
}

/// Run tribez with `args`, expect exit status `code`, parse standard output as JSON.
fn json(args: &[&str], code: i32) -> Json {
    let out = tribez()
        .args(args)
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(code),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn text(args: &[&str], code: i32) -> String {
    let out = tribez().args(args).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(code),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn expected() -> Json {
    let text = std::fs::read_to_string(fixtures().join("fit/small/expected.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The 17-significant-digit decimal of a report is within half a unit of its 17th digit of
/// the exact value.
fn decimal_agrees(decimal: &str, exact: &BigRational) {
    let d = q(decimal);
    if exact.is_zero() {
        assert!(d.is_zero(), "{decimal}");
        return;
    }
    // |d − exact| ≤ |exact|·10^-16 is a generous form of "17 significant digits".
    let tol = exact.abs() * q("1e-16");
    assert!((&d - exact).abs() <= tol, "{decimal} vs {exact}");
}

#[test]
fn small_fits_match_sympy() {
    let e = expected();
    for case in e["cases"].as_array().unwrap() {
        let n = case["degree"].to_string();
        let s = case["smoothness"].as_str().unwrap();
        let j = json(
            &[
                "fit",
                &fx("fit/small/data.csv"),
                "--mesh",
                &fx("fit/small/mesh.toml"),
                "--degree",
                &n,
                "--smoothness",
                s,
            ],
            0,
        );
        let what = format!("degree {n} {s}");
        assert_eq!(j["degree"].to_string(), n, "{what}");
        assert_eq!(j["smoothness"], s, "{what}");
        assert_eq!(j["rows"], 49);
        assert_eq!(j["triangles"], 4);
        let want: Vec<&str> = case["ordinates"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap())
            .collect();
        let fitted = j["fitted"].as_array().unwrap();
        assert_eq!(fitted.len(), want.len(), "{what}");
        for (f, w) in fitted.iter().zip(&want) {
            assert_eq!(q(f["value"]["exact"].as_str().unwrap()), q(w), "{what} {f}");
            decimal_agrees(f["value"]["decimal"].as_str().unwrap(), &q(w));
        }
        let rss = &j["residual_sum_of_squares"];
        let want_rss = q(case["rss"].as_str().unwrap());
        assert_eq!(q(rss["exact"].as_str().unwrap()), want_rss, "{what}");
        decimal_agrees(rss["decimal"].as_str().unwrap(), &want_rss);
        let m = &j["max_abs_residual"];
        let want_m = q(case["max_abs_residual"].as_str().unwrap());
        assert_eq!(q(m["exact"].as_str().unwrap()), want_m, "{what}");
        decimal_agrees(m["decimal"].as_str().unwrap(), &want_m);
        assert_eq!(
            j["max_abs_residual_line"], case["max_abs_residual_line"],
            "{what}"
        );
        assert!(j["fitted_mesh_file"].is_null());
        assert!(j["undetermined"].as_array().unwrap().is_empty());
    }
}

#[test]
fn the_small_mesh_file_is_derive_py_s_mesh() {
    let e = expected();
    let mesh = tribez::mesh::Mesh::from_file(fixtures().join("fit/small/mesh.toml")).unwrap();
    let vertices: Vec<[BigRational; 2]> = e["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| [q(v[0].as_str().unwrap()), q(v[1].as_str().unwrap())])
        .collect();
    assert_eq!(mesh.vertices(), vertices.as_slice());
    let triangles: Vec<[usize; 3]> = serde_json::from_value(e["triangles"].clone()).unwrap();
    assert_eq!(mesh.triangles(), triangles.as_slice());
}

#[test]
fn the_text_report_shows_the_residuals() {
    let e = expected();
    let case = &e["cases"][0];
    assert_eq!(
        (case["degree"].as_u64(), case["smoothness"].as_str()),
        (Some(2), Some("c0"))
    );
    let out = text(
        &[
            "fit",
            &fx("fit/small/data.csv"),
            "--mesh",
            &fx("fit/small/mesh.toml"),
        ],
        0,
    );
    assert!(out.contains("(49 rows)"), "{out}");
    assert!(out.contains("degree 2), C0: 13 ordinates"), "{out}");
    assert!(
        out.contains("rank 13: every ordinate determined by the data"),
        "{out}"
    );
    let line = format!(" at line {} (exact", case["max_abs_residual_line"]);
    assert!(out.contains("largest absolute residual: "), "{out}");
    assert!(out.contains(&line), "{out}");
    assert!(out.contains("residual sum of squares: "), "{out}");
    // the exact numbers are too long for a line: their sizes are shown instead
    assert!(out.contains("digits)"), "{out}");
    assert!(out.contains("vertex 4"), "{out}");
    assert!(out.contains("give -o FITTED"), "{out}");
}

/// The ordinates of a mesh file, exact.
fn ordinates(path: &Path) -> Vec<BigRational> {
    tribez::mesh::Mesh::from_file(path)
        .unwrap()
        .ordinates()
        .iter()
        .map(|o| o.clone().expect("every ordinate"))
        .collect()
}

#[test]
fn the_fitted_mesh_file_reads_back() {
    let e = expected();
    let dir = tempfile::tempdir().unwrap();
    for (name, case) in [
        ("fitted.toml", &e["cases"][1]),
        ("fitted.json", &e["cases"][3]),
    ] {
        let out = dir.path().join(name);
        let o = out.display().to_string();
        let j = json(
            &[
                "fit",
                &fx("fit/small/data.csv"),
                "--mesh",
                &fx("fit/small/mesh.toml"),
                "--degree",
                &case["degree"].to_string(),
                "--smoothness",
                case["smoothness"].as_str().unwrap(),
                "-o",
                &o,
            ],
            0,
        );
        assert_eq!(j["fitted_mesh_file"], o.as_str());
        // a valid mesh, every ordinate present
        let check = json(&["mesh", "check", &o], 0);
        assert_eq!(check["valid"], true);
        assert_eq!(check["degree"].to_string(), case["degree"].to_string());
        let want: Vec<BigRational> = case["ordinates"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| q(v.as_str().unwrap()))
            .collect();
        assert_eq!(ordinates(&out), want, "{name}");
        if name.ends_with(".json") {
            let raw: Json = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
            assert!(raw["ordinates"].is_object());
        }
    }
    assert_eq!(listing(dir.path()), ["fitted.json", "fitted.toml"]);
}

/// Triangle `t` of `mesh` as a patch file in `dir`.
fn triangle_patch(mesh: &str, t: usize, dir: &Path) -> PathBuf {
    let p = dir.join(format!("t{t}.toml"));
    tribez()
        .args(["mesh", "patch", mesh, "--triangle", &t.to_string(), "-o"])
        .arg(&p)
        .assert()
        .code(0);
    p
}

#[test]
fn a_c1_fit_is_c1_across_its_interior_edges() {
    // The square cut by its diagonals: the interior edges are the spokes k–4, each shared by
    // triangles k and k+1 (mod 4) (triangle k = (k, k+1, 4)). Each pair is judged by
    // `tribez join`, which compares the two patches' derivatives across the common edge.
    let dir = tempfile::tempdir().unwrap();
    for (s, smooth) in [("c1", true), ("c0", false)] {
        let fitted = dir.path().join(format!("{s}.toml"));
        tribez()
            .args([
                "fit",
                &fx("fit/small/data.csv"),
                "--mesh",
                &fx("fit/small/mesh.toml"),
                "--smoothness",
                s,
                "-o",
            ])
            .arg(&fitted)
            .assert()
            .code(0);
        let m = fitted.display().to_string();
        let patches: Vec<String> = (0..4)
            .map(|t| triangle_patch(&m, t, dir.path()).display().to_string())
            .collect();
        let mut c1 = Vec::new();
        for k in 0..4 {
            let j = json(&["join", &patches[k], &patches[(k + 1) % 4]], 0);
            assert_eq!(j["c0"], true, "{s} {k}");
            c1.push(j["c1"] == true);
        }
        if smooth {
            assert!(c1.iter().all(|&c| c), "{s}: {c1:?}");
        } else {
            // these noisy data are not fitted C1 by the C0 fit
            assert!(!c1.iter().all(|&c| c), "{s}: {c1:?}");
        }
    }
}

#[test]
fn the_numpy_fit_passes_and_the_perturbed_one_fails() {
    let data = fx("fit/numpy/data.csv");
    let good = json(
        &[
            "check",
            "--mesh",
            &fx("fit/numpy/fitted_numpy.toml"),
            "--fit",
            &data,
        ],
        0,
    );
    assert_eq!(good["passed"], true);
    assert_eq!(good["tolerance"], "cond");
    assert_eq!(good["precision"], "f64");
    assert_eq!(good["rows"], 400);
    // 16 vertices and 33 edges of the 3 × 3 grid: 49 ordinates
    assert_eq!(good["ordinates"], 49);
    assert_eq!(good["rank"], 49);
    assert!(good["error_ratio"].as_f64().unwrap() < 1.0, "{good}");
    // numpy's float fit leaves a residual at least the exact minimum
    assert!(q(good["rss_excess"]["exact"].as_str().unwrap()) >= BigRational::zero());
    let bad = json(
        &[
            "check",
            "--mesh",
            &fx("fit/numpy/fitted_numpy_perturbed.toml"),
            "--fit",
            &data,
        ],
        1,
    );
    assert_eq!(bad["passed"], false);
    assert!(bad["error_ratio"].as_f64().unwrap() > 1.0, "{bad}");
    // the perturbation: 1e-6 in the ordinate of vertex 0
    let worst = q(bad["max_abs_error"]["exact"].as_str().unwrap());
    assert!(worst > q("9e-7") && worst < q("11e-7"), "{worst}");
    assert_eq!(bad["per_ordinate"][0]["id"], "the ordinate of vertex 0");
    // an absolute tolerance above the perturbation accepts it; exact accepts neither
    let abs = json(
        &[
            "check",
            "--mesh",
            &fx("fit/numpy/fitted_numpy_perturbed.toml"),
            "--fit",
            &data,
            "--tolerance",
            "abs=2e-6",
        ],
        0,
    );
    assert_eq!(abs["passed"], true);
    let exact = json(
        &[
            "check",
            "--mesh",
            &fx("fit/numpy/fitted_numpy.toml"),
            "--fit",
            &data,
            "--tolerance",
            "exact",
        ],
        1,
    );
    assert_eq!(exact["passed"], false);
}

#[test]
fn the_float_fit_text_and_junit() {
    let dir = tempfile::tempdir().unwrap();
    let junit = dir.path().join("fit.xml");
    let out = tribez()
        .args([
            "check",
            "--mesh",
            &fx("fit/numpy/fitted_numpy_perturbed.toml"),
            "--fit",
            &fx("fit/numpy/data.csv"),
            "--junit",
        ])
        .arg(&junit)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let t = String::from_utf8(out.stdout).unwrap();
    assert!(t.contains("tolerance cond: FAIL"), "{t}");
    assert!(t.contains("condition number κ₂(A) ≤"), "{t}");
    assert!(t.contains("the ordinate of vertex 0: claimed"), "{t}");
    let xml = std::fs::read_to_string(&junit).unwrap();
    let doc = roxmltree::Document::parse(&xml).unwrap();
    let failures: Vec<_> = doc
        .descendants()
        .filter(|n| n.has_tag_name("failure"))
        .collect();
    assert_eq!(failures.len(), 1, "{xml}");
}

/// The unit square cut along 0–2, quadratic, geometry only.
const SQUARE: &str = "degree = 2\nvertices = [[\"0\", \"0\"], [\"1\", \"0\"], [\"1\", \"1\"], [\"0\", \"1\"]]\ntriangles = [[0, 1, 2], [0, 2, 3]]\n";

#[test]
fn bad_inputs_are_one_line_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = write(d, "square.toml", SQUARE);
    let m = mesh.display().to_string();
    // line 3 (after a header and a comment... here: header, one row, then the outside one)
    let outside = write(d, "outside.csv", "x,y,value\n1/2,1/4,1\n2,1/2,0\n");
    let malformed = write(d, "malformed.csv", "x,y,value\n1,1,1\n1/2,1/3\n");
    let clockwise = write(
        d,
        "clockwise.toml",
        "degree = 1\nvertices = [[\"0\", \"0\"], [\"1\", \"0\"], [\"0\", \"1\"]]\ntriangles = [[0, 2, 1]]\n",
    );
    let out = d.join("fitted.toml");
    let o = out.display().to_string();
    let before = listing(d);
    fails(
        tribez().args([
            "fit",
            &outside.display().to_string(),
            "--mesh",
            &m,
            "-o",
            &o,
        ]),
        &["outside.csv:3:", "(2, 1/2) lies outside the mesh"],
    );
    fails(
        tribez().args([
            "fit",
            &malformed.display().to_string(),
            "--mesh",
            &m,
            "-o",
            &o,
        ]),
        &["malformed.csv:3:", "2 fields, expected 3"],
    );
    fails(
        tribez().args([
            "fit",
            &d.join("absent.csv").display().to_string(),
            "--mesh",
            &m,
            "-o",
            &o,
        ]),
        &["absent.csv"],
    );
    fails(
        tribez().args([
            "fit",
            &fx("fit/small/data.csv"),
            "--mesh",
            &d.join("absent.toml").display().to_string(),
        ]),
        &["absent.toml"],
    );
    // a clockwise triangle in the mesh: its line and key
    fails(
        tribez().args([
            "fit",
            &fx("fit/small/data.csv"),
            "--mesh",
            &clockwise.display().to_string(),
        ]),
        &["clockwise.toml:3", "triangles[0]", "clockwise"],
    );
    fails(
        tribez().args([
            "fit",
            &fx("fit/small/data.csv"),
            "--mesh",
            &m,
            "--degree",
            "0",
        ]),
        &["--degree"],
    );
    fails(
        tribez().args([
            "fit",
            &fx("fit/small/data.csv"),
            "--mesh",
            &m,
            "--smoothness",
            "c2",
        ]),
        &["c2", "c0 or c1"],
    );
    assert_eq!(listing(d), before);
}

#[test]
fn rank_deficiency_names_the_ordinates_and_regularize_resolves_it() {
    // Data only in triangle 0 = (0, 1, 2) of the square: the ordinate of vertex 3 and those of
    // edges 0–3 and 2–3 touch no data. The values are x·y, a quadratic, so the minimum-norm fit
    // reproduces them exactly (residual 0) and leaves the three free ordinates at 0.
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = write(d, "square.toml", SQUARE);
    let data = write(
        d,
        "tri0.csv",
        "# x, y, x*y, all with x > y (triangle 0)\n1/2,1/4,1/8\n3/4,1/4,3/16\n3/4,1/2,3/8\n1/4,1/8,1/32\n7/8,1/8,7/64\n7/8,3/4,21/32\n1/2,1/8,1/16\n",
    );
    let out = d.join("fitted.toml");
    let args = |extra: &[&str]| -> Vec<String> {
        let mut a = vec![
            "fit".to_string(),
            data.display().to_string(),
            "--mesh".into(),
            mesh.display().to_string(),
            "-o".into(),
            out.display().to_string(),
        ];
        a.extend(extra.iter().map(ToString::to_string));
        a
    };
    fails(
        tribez().args(args(&[])),
        &[
            "tri0.csv: the data do not determine 3 of the 9 ordinates",
            "the ordinate of vertex 3; edge 0–3, ordinate 1; edge 2–3, ordinate 1",
            "--regularize",
        ],
    );
    assert!(!out.exists());
    let j = json(
        &args(&["--regularize"])
            .iter()
            .map(String::as_str)
            .collect::<Vec<_>>(),
        0,
    );
    assert_eq!(j["regularized"], true);
    assert_eq!(
        j["undetermined"],
        serde_json::json!([
            "the ordinate of vertex 3",
            "edge 0–3, ordinate 1",
            "edge 2–3, ordinate 1"
        ])
    );
    assert_eq!(j["residual_sum_of_squares"]["exact"], "0");
    // x·y on triangle 0 = (0,0), (1,0), (1,1): its blossom gives b(vertex 2) = 1,
    // b(edge 1–2) = (1·1 + 0·1)/2 = 1/2, the other ordinates of the triangle 0.
    let o = ordinates(&out);
    let want = ["0", "0", "1", "0", "0", "0", "0", "1/2", "0"];
    // the numbering: vertices 0–3, then edges 0–1, 0–2, 0–3, 1–2, 2–3
    assert_eq!(o, want.iter().map(|s| q(s)).collect::<Vec<_>>());
}

#[test]
fn check_fit_usage_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let data = fx("fit/numpy/data.csv");
    let fitted = fx("fit/numpy/fitted_numpy.toml");
    // --fit needs --mesh
    fails(tribez().args(["check", "--fit", &data]), &["--mesh"]);
    // --mesh needs --results or --fit, and takes only one of them
    fails(
        tribez().args(["check", "--mesh", &fitted]),
        &["--results", "--fit"],
    );
    fails(
        tribez().args([
            "check",
            "--mesh",
            &fitted,
            "--fit",
            &data,
            "--results",
            &data,
        ]),
        &["--fit", "--results"],
    );
    fails(
        tribez().args([
            "check",
            "--mesh",
            &fitted,
            "--fit",
            &data,
            "--tolerance",
            "ulps=1",
        ]),
        &["--tolerance", "ulps=1", "does not apply to fits"],
    );
    // the options of evaluation batches are refused, each by name
    for extra in [
        &["--plot", "map.svg"][..],
        &["--html", "r.html"],
        &["--cartesian"],
        &["--baseline", "b.json"],
        &["--record-baseline", "b.json"],
    ] {
        fails(
            tribez()
                .args(["check", "--mesh", &fitted, "--fit", &data])
                .args(extra),
            &[extra[0], "is not available with --fit"],
        );
    }
    fails(
        tribez().args([
            "check",
            "--mesh",
            &fitted,
            "--fit",
            &data,
            "--precision",
            "f16",
        ]),
        &["--precision"],
    );
    // a mesh without ordinates is no fit to judge
    fails(
        tribez().args([
            "check",
            "--mesh",
            &fx("fit/numpy/mesh.toml"),
            "--fit",
            &data,
        ]),
        &["mesh.toml", "has no value for the ordinate of vertex 0"],
    );
    let before = listing(d);
    let junit = d.join("j.xml").display().to_string();
    fails(
        tribez().args([
            "check",
            "--mesh",
            &fitted,
            "--fit",
            &d.join("absent.csv").display().to_string(),
            "--junit",
            &junit,
        ]),
        &["absent.csv"],
    );
    assert_eq!(listing(d), before);
}

/// Issue 35 §5: the `cond` tolerance at any scale, and at `x* = 0`. The verdicts come from
/// fixtures/fit/scale/derive.py (Python `fractions`, with tribez's bound of κ only known to lie
/// in an interval; a verdict is recorded only if it holds over the whole interval).
#[test]
fn cond_verdicts_at_any_scale_match_the_fractions_reference() {
    let raw = std::fs::read_to_string(fixtures().join("fit/scale/expected.json")).unwrap();
    let e: Json = serde_json::from_str(&raw).unwrap();
    let cases = e["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 9);
    for c in cases {
        let mesh = fx(&format!("fit/scale/{}", c["mesh"].as_str().unwrap()));
        let data = fx(&format!("fit/scale/{}", c["data"].as_str().unwrap()));
        for (tol, want) in c["verdicts"].as_object().unwrap() {
            let want = want.as_bool().unwrap();
            let args = ["check", "--mesh", &mesh, "--fit", &data, "--tolerance", tol];
            let j = json(&args, if want { 0 } else { 1 });
            assert_eq!(j["passed"], want, "{args:?}: {j}");
            // the allowed error is finite, positive and inside derive.py's bracket
            let (lo, hi) = (
                c["allowed_low"].as_f64().unwrap(),
                c["allowed_high"].as_f64().unwrap(),
            );
            let a = j["allowed_error"].as_f64().unwrap_or(f64::NAN);
            assert!(
                a >= lo * (1.0 - 1e-12) && a <= hi * (1.0 + 1e-12),
                "{args:?}: {j}"
            );
            let exact = q(j["allowed_error_exact"]["exact"].as_str().unwrap());
            assert!(exact.is_positive(), "{args:?}: {j}");
            // the error norm: √(error_sq) of derive.py
            let err_sq = q(c["error_sq"].as_str().unwrap());
            let en = j["error_norm"].as_f64().unwrap();
            let en_q = tribez::parse_rational(&format!("f64:{en:e}")).unwrap();
            if err_sq.is_zero() {
                assert_eq!(en, 0.0);
            } else {
                // within 1e-12 relative: (en²/err_sq) in (1 − 3e-12, 1 + 3e-12)
                let r = &en_q * &en_q / &err_sq;
                assert!(
                    r > q("0.999999999997") && r < q("1.000000000003"),
                    "{en} {err_sq}"
                );
            }
        }
    }
    // The zero solution: the allowed error is the residual term alone, 2√3·ε/(1 − ε) with
    // κ = 1, ‖r*‖ = √6, ‖A‖ = √2 (derive.py): 3.846e-16, shown in the text.
    let t = text(
        &[
            "check",
            "--mesh",
            &fx("fit/scale/zero_small.toml"),
            "--fit",
            &fx("fit/scale/zero_data.csv"),
        ],
        0,
    );
    assert!(t.contains("allows ‖Δx‖₂ ≤ 3.846e-16"), "{t}");
    assert!(t.contains(": PASS"), "{t}");
}

/// Issue 35 §7: fewer distinct points than ordinates. Without `--regularize` the error names
/// the undetermined ordinates (found from the rows, not the normal equations); with it, the minimum-norm fit is fixtures/fit/fewpoints'
/// (derive.py: Python `fractions`, `x = G w` with `G² w = h`, the undetermined ordinates those
/// whose `e_i` is outside the range of `G`).
#[test]
fn few_points_minimum_norm_matches_the_fractions_reference() {
    let raw = std::fs::read_to_string(fixtures().join("fit/fewpoints/expected.json")).unwrap();
    let e: Json = serde_json::from_str(&raw).unwrap();
    let data = fx("fit/fewpoints/data.csv");
    let mesh = fx("fit/fewpoints/mesh.toml");
    // 8 distinct points (derive.py): rank 8, 24 of the 25 ordinates undetermined
    fails(
        tribez().args(["fit", &data, "--mesh", &mesh, "--degree", "4"]),
        &[
            "data.csv: the data do not determine 24 of the 25 ordinates (rank 8 of 25)",
            "--regularize",
        ],
    );
    let j = json(
        &[
            "fit",
            &data,
            "--mesh",
            &mesh,
            "--degree",
            "4",
            "--regularize",
        ],
        0,
    );
    assert_eq!(j["ordinates"], e["ordinates"]);
    assert_eq!(j["rank"], e["rank"]);
    let fitted = j["fitted"].as_array().unwrap();
    let want: Vec<&str> = e["x"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(fitted.len(), want.len());
    for (f, w) in fitted.iter().zip(&want) {
        assert_eq!(
            q(f["value"]["exact"].as_str().unwrap()),
            q(w),
            "{}",
            f["id"]
        );
    }
    assert_eq!(
        q(j["residual_sum_of_squares"]["exact"].as_str().unwrap()),
        q(e["rss"].as_str().unwrap())
    );
    let und: Vec<Json> = e["undetermined"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| fitted[i.as_u64().unwrap() as usize]["id"].clone())
        .collect();
    assert_eq!(j["undetermined"], Json::Array(und));
}

/// Issue 35 §7: `fit --degree 30` with 20 points on one triangle (496 ordinates) took past 20 s
/// without `--regularize` and over 10 minutes with it. Both must now finish well within 10 s.
/// (Interpolation: 20 distinct points in general position and 496 ordinates, so the
/// minimum-norm fit meets every value, residual 0.)
#[test]
fn degree_30_with_20_points_is_quick() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mesh = write(
        d,
        "tri.toml",
        "degree = 1\nvertices = [[\"0\", \"0\"], [\"1\", \"0\"], [\"0\", \"1\"]]\ntriangles = [[0, 1, 2]]\n",
    );
    // 20 points with 3-digit coordinates inside the triangle (a fixed sequence)
    let mut s = String::from("x,y,value\n");
    let mut seed: u64 = 12345;
    let mut next = || {
        seed = (seed * 1_103_515_245 + 12_345) % (1 << 31);
        seed
    };
    let mut count = 0;
    while count < 20 {
        let (a, b) = (next() % 1000, next() % 1000);
        if a + b >= 1000 {
            continue;
        }
        let v = next() % 2001;
        s += &format!("{a}/1000,{b}/1000,{v}/1000\n");
        count += 1;
    }
    let data = write(d, "d.csv", &s);
    let (data, mesh) = (data.display().to_string(), mesh.display().to_string());
    let t = std::time::Instant::now();
    fails(
        tribez().args(["fit", &data, "--mesh", &mesh, "--degree", "30"]),
        &["the data do not determine 496 of the 496 ordinates (rank 20 of 496)"],
    );
    assert!(t.elapsed().as_secs_f64() < 60.0, "{:?}", t.elapsed()); // a hang guard (debug build)
    let t = std::time::Instant::now();
    let j = json(
        &[
            "fit",
            &data,
            "--mesh",
            &mesh,
            "--degree",
            "30",
            "--regularize",
        ],
        0,
    );
    assert!(t.elapsed().as_secs_f64() < 60.0, "{:?}", t.elapsed()); // a hang guard (debug build)
    assert_eq!(j["rank"], 20);
    assert_eq!(j["residual_sum_of_squares"]["exact"], "0");
}
