//! `tribez mesh check`, `tribez mesh patch` and `tribez lookup` as a user runs them. Expected
//! values: fixtures/mesh/derive.py (pure Python fractions: the fixture's ordinates are blossoms
//! of f = x³ − 2xy + y²/3 + 1/2, and a cubic mesh reproduces f exactly).

use std::path::{Path, PathBuf};

use assert_cmd::Command;

fn tribez() -> Command {
    Command::cargo_bin("tribez").expect("binary built")
}

fn fx(name: &str) -> String {
    let p: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures")
        .join(name);
    p.display().to_string()
}

const HEX: &str = "mesh/hexagon_cubic.toml";

/// Exit status 2, nothing on standard output, one line on standard error containing `words`.
fn fails_with(args: &[&str], words: &[&str]) {
    let out = tribez().args(args).assert().code(2).get_output().clone();
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(err.lines().count(), 1, "{err}");
    for w in words {
        assert!(err.contains(w), "{args:?}: {w:?} not in {err:?}");
    }
}

fn json(args: &[&str], code: i32) -> serde_json::Value {
    let out = tribez()
        .args(args)
        .args(["--format", "json"])
        .assert()
        .code(code)
        .get_output()
        .stdout
        .clone();
    serde_json::from_slice(&out).unwrap()
}

#[test]
fn the_hexagon_is_valid() {
    let j = json(&["mesh", "check", &fx(HEX)], 0);
    assert_eq!(j["valid"], true);
    // 7 vertices, 12 edges (6 spokes, 6 rim) × 2, 6 interiors: 7 + 24 + 6 = 37.
    assert_eq!(j["ordinates"], 37);
    assert_eq!(j["edges"], 12);
}

#[test]
fn lookups_reproduce_the_cubic_and_agree_on_shared_edges() {
    let j = json(
        &["lookup", &fx(HEX), "--points", &fx("mesh/points.csv")],
        1, // the last point, (2, 0), is outside
    );
    let r = j["results"].as_array().unwrap();
    // derive.py: f at each point of points.csv.
    let expected = ["563/1350", "5/8", "1/2", "157/192", "163/192", "49/192"];
    for (row, e) in r.iter().zip(expected) {
        assert_eq!(row["value"], e, "{row}");
        // every containing triangle gives the same value (C0)
        for t in row["triangles"].as_array().unwrap() {
            assert_eq!(t["value"], e, "{row}");
        }
    }
    // (1/2, 0) is the midpoint of spoke 0–1: triangles 0 and 5; (0, 0) is in all six;
    // (3/4, 1/2) is on the rim edge 1–2: triangle 0 only.
    let tris = |i: usize| -> Vec<u64> {
        r[i]["triangles"]
            .as_array()
            .unwrap()
            .iter()
            .map(|t| t["triangle"].as_u64().unwrap())
            .collect()
    };
    assert_eq!(tris(1), [0, 5]);
    assert_eq!(tris(2), [0, 1, 2, 3, 4, 5]);
    assert_eq!(tris(3), [1, 2]);
    assert_eq!(tris(5), [0]);
    assert_eq!(r[1]["triangles"][0]["where"], "edge 0–1");
    // (1/3, 1/5) in triangle 0 = (0,0), (1,0), (1/2,1): λ2 = y = 1/5, λ1 = x − λ2/2 = 7/30.
    assert_eq!(
        r[0]["triangles"][0]["barycentric"],
        serde_json::json!(["17/30", "7/30", "1/5"])
    );
    assert_eq!(r[6]["inside"], false);
    assert!(r[6]["value"].is_null());
}

#[test]
fn float_lookup_shows_its_errors() {
    // (1/2, 0) is exact in floats and so is every step there (λ = (1/2, 1/2, 0), ordinates
    // 1/2, 1/2, 1/2, 3/2 on the edge): 5/8 exactly, no error.
    let j = json(&["lookup", &fx(HEX), "--at", "1/2,0", "--float", "f32"], 0);
    let f = &j["results"][0]["float"];
    assert_eq!(f["precision"], "f32");
    assert_eq!(f["value"], "5/8");
    assert_eq!(f["ulps_vs_exact_at_inputs"], "0");
    // At (1/3, 1/5) the float point is not the exact one: the errors are small but there, and
    // the exact value at the point as seen is the cubic at the rounded point.
    let j = json(
        &["lookup", &fx(HEX), "--at", "1/3,1/5", "--float", "f64"],
        0,
    );
    let f = &j["results"][0]["float"];
    let ulps: f64 = ratio(f["ulps_vs_exact_at_inputs"].as_str().unwrap());
    assert!(ulps > 0.0 && ulps < 8.0, "{f}");
    // x, y as seen: the f64 nearest 1/3 = 6004799503160661/2^54, nearest 1/5 = 3602879701896397/2^54
    assert_eq!(
        f["point_as_seen"],
        serde_json::json!([
            "6004799503160661/18014398509481984",
            "3602879701896397/18014398509481984"
        ])
    );
}

fn ratio(s: &str) -> f64 {
    match s.split_once('/') {
        Some((p, q)) => p.parse::<f64>().unwrap() / q.parse::<f64>().unwrap(),
        None => s.parse().unwrap(),
    }
}

#[test]
fn mesh_patch_writes_a_functional_patch_every_command_reads() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t2.toml");
    tribez()
        .args(["mesh", "patch", &fx(HEX), "--triangle", "2", "-o"])
        .arg(&out)
        .assert()
        .code(0);
    // Triangle 2 = (0,0), (-1/2,1), (-1,0); the point λ = (1/2, 1/4, 1/4) is (-3/8, 1/4):
    // f = -27/512 + 3/16 + 1/48 + 1/2 = (-81 + 288 + 32 + 768)/1536 = 1007/1536.
    let o = tribez()
        .args(["eval"])
        .arg(&out)
        .args(["--at", "1/2,1/4,1/4", "--format", "json"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&o).unwrap();
    assert_eq!(j["results"][0]["point"][0], "1007/1536");
    fails_with(
        &["mesh", "patch", &fx(HEX), "--triangle", "6"],
        &["--triangle 6", "triangles 0 to 5"],
    );
}

/// Issue 35 §8: `mesh patch -o t.json` wrote TOML into t.json. The extension chooses the format,
/// as `fit -o` does; `--format json` with a `.toml` name is refused.
#[test]
fn mesh_patch_chooses_the_format_by_the_extension() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.JSON");
    tribez()
        .args(["mesh", "patch", &fx(HEX), "--triangle", "2", "-o"])
        .arg(&out)
        .assert()
        .code(0);
    let text = std::fs::read_to_string(&out).unwrap();
    let j: serde_json::Value = serde_json::from_str(&text).expect("JSON in a .json file");
    assert_eq!(j["kind"], "functional", "{text}");
    // the JSON file is a patch file every command reads: the same value as the TOML test above
    let o = tribez()
        .args(["eval"])
        .arg(&out)
        .args(["--at", "1/2,1/4,1/4", "--format", "json"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let v: serde_json::Value = serde_json::from_slice(&o).unwrap();
    assert_eq!(v["results"][0]["point"][0], "1007/1536");
    // .toml gets TOML (not JSON) even with --format text spelled out
    let toml = dir.path().join("t.toml");
    tribez()
        .args([
            "mesh",
            "patch",
            &fx(HEX),
            "--triangle",
            "2",
            "--format",
            "text",
            "-o",
        ])
        .arg(&toml)
        .assert()
        .code(0);
    assert!(
        std::fs::read_to_string(&toml)
            .unwrap()
            .contains("kind = \"functional\"")
    );
    let bad = dir.path().join("u.toml");
    fails_with(
        &[
            "mesh",
            "patch",
            &fx(HEX),
            "--triangle",
            "2",
            "--format",
            "json",
            "-o",
            bad.to_str().unwrap(),
        ],
        &["u.toml", "--format json"],
    );
    assert!(!bad.exists());
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn mesh_check_lists_located_problems() {
    let dir = tempfile::tempdir().unwrap();
    // 0=(0,0) 1=(2,0) 2=(1,2) 3=(1,-2) 4=(1,0): triangle 0 above the x axis, two below split at
    // 4, the midpoint of edge 0–1 (a T-junction); triangle 2 clockwise.
    let m = write(
        dir.path(),
        "t.toml",
        "degree = 1\nvertices = [[0, 0], [2, 0], [1, 2], [1, -2], [1, 0]]\ntriangles = [\n  [0, 1, 2],\n  [0, 3, 4],\n  [4, 1, 3],\n]\n",
    );
    let out = tribez()
        .args(["mesh", "check", &m])
        .assert()
        .code(1)
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    // clockwise, T-junction, and the 5 vertex ordinates of a degree-1 mesh without ordinates
    assert!(text.contains("INVALID: 7 problems"), "{text}");
    assert!(
        text.contains(":6: triangles[2]: triangle 2 (vertices [4, 1, 3]) is clockwise"),
        "{text}"
    );
    assert!(
        text.contains(":4: triangles[0]: T-junction: vertex 4 lies inside edge 0–1 of triangle 0"),
        "{text}"
    );
    assert!(
        text.contains(": ordinates: the ordinate of vertex 0 is missing"),
        "{text}"
    );
    // Any other command refuses the mesh with its first problem.
    fails_with(
        &["lookup", &m, "--at", "1,1"],
        &["t.toml:6: triangles[2]:", "clockwise"],
    );
}

#[test]
fn bad_input_is_one_line_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let bad = write(
        dir.path(),
        "b.toml",
        "degree = 2\nvertices = [[0, 0], [1, 0]]\ntriangles = [[0, 1, 2]]\n",
    );
    fails_with(
        &["mesh", "check", &bad],
        &["b.toml:2: vertices: vertices: 2, expected 3"],
    );
    let txt = write(dir.path(), "m.txt", "degree = 2\n");
    fails_with(&["mesh", "check", &txt], &["m.txt", "unknown file type"]);
    fails_with(&["lookup", &fx(HEX)], &["give at least one point"]);
    fails_with(
        &["lookup", &fx(HEX), "--at", "1,2,3"],
        &["--at 1,2,3", "expected 2 coordinates"],
    );
    fails_with(
        &["lookup", &fx(HEX), "--at", "1/0,2"],
        &["--at `1/0,2`", "zero denominator"],
    );
    // A point inside a mesh but beyond f32's range.
    let huge = write(
        dir.path(),
        "h.toml",
        "degree = 1\nvertices = [[0, 0], [1e40, 0], [0, 1e40]]\ntriangles = [[0, 1, 2]]\n[ordinates]\nvertex = [0, 1, 2]\n",
    );
    fails_with(
        &["lookup", &huge, "--at", "1e39,0", "--float", "f32"],
        &["the point (1000000000000000000000000000000000000000, 0) overflows f32"],
    );
}

#[test]
fn check_mesh_results_judges_other_codes_lookups() {
    // fixtures/mesh/results.py: 200 rows correctly rounded at the inputs as seen (computed with
    // fractions), line 202 off by 2^-40 relative, line 203 outside the mesh.
    let dir = tempfile::tempdir().unwrap();
    let junit = dir.path().join("j.xml");
    let args = |t: &str| {
        vec![
            "check".to_string(),
            "--mesh".into(),
            fx(HEX),
            "--results".into(),
            fx("mesh/lookups.csv"),
            "--precision".into(),
            "f64".into(),
            "--tolerance".into(),
            t.into(),
        ]
    };
    let mut a = args("correctly_rounded");
    a.extend(["--junit".into(), junit.display().to_string()]);
    let a: Vec<&str> = a.iter().map(String::as_str).collect();
    let j = json(&a, 1);
    assert_eq!(j["summary"]["claims"], 202, "{j}");
    assert_eq!(j["summary"]["passed"], 200, "{j}");
    let lines: Vec<u64> = j["failures"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["line"].as_u64().unwrap())
        .collect();
    assert_eq!(lines, [202, 203]);
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(
        xml.contains("line 203: the point (2, 0) is outside the mesh"),
        "{xml}"
    );
    // Every tolerance: 2^-40 relative is about 2^12 = 4096 ulp at 0.47 (binade [1/4, 1/2)):
    // 7706 ulp, so ulps=4096 still fails it; abs=1e-12 passes it (4.3e-13).
    for (t, passed) in [
        ("ulps=4096", 200),
        ("abs=1e-12", 201),
        ("rel=1e-12", 201),
        ("cond", 200),
        ("bound", 200),
    ] {
        let a = args(t);
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        let j = json(&a, 1);
        assert_eq!(j["summary"]["passed"], passed, "{t}: {j}");
    }
    fails_with(
        &[
            "check",
            "--mesh",
            &fx(HEX),
            "--results",
            &fx("mesh/lookups.csv"),
            "--tolerance",
            "ulps=1",
        ],
        &["needs --precision"],
    );
    fails_with(
        &[
            "check",
            "--mesh",
            &fx(HEX),
            "--results",
            &fx("mesh/lookups.csv"),
            "--cartesian",
        ],
        &["--cartesian is not available with --mesh"],
    );
    fails_with(
        &["check", "--results", &fx("mesh/lookups.csv")],
        &["--results needs --patch PATCH or --mesh MESH"],
    );
}
