//! Command-line tests of the constructions: blossom, subpatch, subdivide, halve, elevate, matrix.

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;

const FINN: &str = r#"name = "Finn"
degree = 2
[control_points]
"2,0,0" = ["0", "0", "0"]
"1,1,0" = ["1", "0", "2"]
"0,2,0" = ["0", "2", "0"]
"1,0,1" = ["0", "1", "0"]
"0,1,1" = ["1", "1", "1"]
"0,0,2" = ["0", "2", "1"]
"#;

const CURVE: &str = r#"degree = 3
[control_points]
"3,0" = ["0", "0"]
"2,1" = ["1", "2"]
"1,2" = ["3", "2"]
"0,3" = ["4", "0"]
"#;

fn write(dir: &tempfile::TempDir, name: &str, text: &str) -> String {
    let p = dir.path().join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn tribez() -> Command {
    Command::cargo_bin("tribez").unwrap()
}

fn json(args: &[&str]) -> Value {
    let out = tribez()
        .args(args)
        .args(["--format", "json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// A one-line error naming what is wrong, exit status 2, nothing on stdout.
fn fails(args: &[&str], needle: &str) {
    let out = tribez().args(args).output().unwrap();
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    assert!(out.stdout.is_empty(), "{args:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains(needle), "{err} does not contain {needle}");
}

#[test]
fn blossom_value() {
    let d = tempfile::tempdir().unwrap();
    let f = write(&d, "finn.toml", FINN);
    let v = json(&["blossom", &f, "--arg", "1/2,1/2,0", "--arg", "0,1/2,1/2"]);
    assert_eq!(v, serde_json::json!({"point": ["1/2", "1", "3/4"]}));
    tribez()
        .args(["blossom", &f, "--arg", "1/2,1/2,0", "--arg", "0,0,1"])
        .assert()
        .success()
        .stdout("b[(1/2, 1/2, 0), (0, 0, 1)] = (1/2, 1, 1/2)\n");
}

#[test]
fn subpatch_composes_with_eval() {
    let d = tempfile::tempdir().unwrap();
    let f = write(&d, "finn.toml", FINN);
    let v = json(&[
        "subpatch",
        &f,
        "--vertex",
        "0,1/2,1/2",
        "--vertex",
        "1/2,0,1/2",
        "--vertex",
        "1/2,1/2,0",
    ]);
    assert_eq!(
        v["domain_in_parent"],
        serde_json::json!([
            ["0", "1/2", "1/2"],
            ["1/2", "0", "1/2"],
            ["1/2", "1/2", "0"]
        ])
    );
    assert_eq!(
        v["control_points"]["0,2,0"],
        serde_json::json!(["0", "1", "1/4"])
    );
    // the TOML output is a patch file: the centre of the sub-triangle is the centre of the parent
    let out = d.path().join("sub.toml");
    tribez()
        .args([
            "subpatch",
            &f,
            "--vertex",
            "0,1/2,1/2",
            "--vertex",
            "1/2,0,1/2",
            "--vertex",
            "1/2,1/2,0",
            "-o",
        ])
        .arg(&out)
        .assert()
        .success();
    let sub = json(&["eval", out.to_str().unwrap(), "--at", "1/3,1/3,1/3"]);
    let parent = json(&["eval", &f, "--at", "1/3,1/3,1/3"]);
    assert_eq!(sub["results"][0]["point"], parent["results"][0]["point"]);
}

#[test]
fn elevate_composes_with_eval() {
    let d = tempfile::tempdir().unwrap();
    let f = write(&d, "finn.toml", FINN);
    let up = tribez()
        .args(["elevate", &f, "--by", "3", "--format", "json"])
        .output()
        .unwrap();
    assert!(up.status.success());
    let g = write(&d, "up.json", std::str::from_utf8(&up.stdout).unwrap());
    let v: Value = json(&["eval", &g, "--at", "1/2,1/3,1/6"]);
    assert_eq!(
        v["results"][0]["point"],
        serde_json::json!(["4/9", "5/9", "29/36"])
    );
    let e = json(&["elevate", &f]);
    assert_eq!(e["degree"], 3);
    assert_eq!(
        e["control_points"]["1,1,1"],
        serde_json::json!(["2/3", "2/3", "1"])
    );
}

#[test]
fn subdivide_and_halve_pieces() {
    let d = tempfile::tempdir().unwrap();
    let f = write(&d, "finn.toml", FINN);
    let v = json(&["subdivide", &f, "--at", "1/2,1/3,1/6"]);
    let pieces = v["pieces"].as_array().unwrap();
    assert_eq!(pieces.len(), 3);
    assert_eq!(
        pieces[0]["domain_in_parent"][0],
        serde_json::json!(["1/2", "1/3", "1/6"])
    );
    assert_eq!(
        pieces[0]["patch"]["control_points"]["2,0,0"],
        serde_json::json!(["4/9", "5/9", "29/36"])
    );
    let v = json(&["subdivide", &f, "--midpoints"]);
    assert_eq!(v["pieces"].as_array().unwrap().len(), 4);
    assert_eq!(
        v["pieces"][3]["patch"]["control_points"]["2,0,0"],
        serde_json::json!(["1/2", "3/2", "3/4"])
    );
    let h = json(&["halve", &f, "--edge", "1,2"]);
    assert_eq!(
        h["pieces"][0]["domain_in_parent"],
        serde_json::json!([["1", "0", "0"], ["1/2", "1/2", "0"], ["0", "0", "1"]])
    );
    assert_eq!(
        h["pieces"][1]["domain_in_parent"],
        serde_json::json!([["1/2", "1/2", "0"], ["0", "1", "0"], ["0", "0", "1"]])
    );
    assert_eq!(
        h["pieces"][0]["patch"]["control_points"]["0,2,0"],
        serde_json::json!(["1/2", "1/2", "1"])
    );
    let a = json(&["halve", &f, "--edge", "1,2", "--add-and-halve"]);
    assert_eq!(a, h);
    // text output of the pieces is a TOML document
    tribez()
        .args(["subdivide", &f, "--midpoints"])
        .assert()
        .success()
        .stdout(predicate::str::contains("[[pieces]]"));
}

#[test]
fn curves_work_too() {
    let d = tempfile::tempdir().unwrap();
    let f = write(&d, "curve.toml", CURVE);
    let v = json(&["subdivide", &f, "--at", "1/3,2/3"]);
    assert_eq!(
        v["pieces"][1]["patch"]["control_points"]["1,2"],
        serde_json::json!(["16/9", "16/9"])
    );
    let b = json(&[
        "blossom", &f, "--arg", "1,0", "--arg", "1,0", "--arg", "0,1",
    ]);
    assert_eq!(b["point"], serde_json::json!(["1", "2"]));
    let h = json(&["halve", &f, "--edge", "2,1"]);
    // corner 1 replaced by the midpoint p(1/2,1/2) = (0 + 3·1 + 3·3 + 4, 0 + 3·2 + 3·2 + 0)/8; corner 2 kept
    assert_eq!(
        h["pieces"][0]["patch"]["control_points"]["3,0"],
        serde_json::json!(["2", "3/2"])
    );
    assert_eq!(
        h["pieces"][0]["patch"]["control_points"]["0,3"],
        serde_json::json!(["4", "0"])
    );
    fails(
        &["subdivide", &f, "--midpoints"],
        "four-way midpoint split is defined for triangles",
    );
}

#[test]
fn matrices() {
    let v = json(&["matrix", "halve", "--degree", "3"]);
    assert_eq!(v["order"][1], serde_json::json!([2, 1, 0]));
    assert_eq!(
        v["rows"][3],
        serde_json::json!(["1/8", "3/8", "3/8", "1/8", "0", "0", "0", "0", "0", "0"])
    );
    let s = json(&[
        "matrix",
        "subpatch",
        "--degree",
        "1",
        "--vertex",
        "1,0,0",
        "--vertex",
        "1/2,1/2,0",
        "--vertex",
        "0,0,1",
    ]);
    assert_eq!(
        s["rows"],
        serde_json::json!([["1", "0", "0"], ["1/2", "1/2", "0"], ["0", "0", "1"]])
    );
    tribez()
        .args(["matrix", "halve", "--degree", "2", "--format", "latex"])
        .assert()
        .success()
        .stdout(predicate::str::contains("\\frac{1}{2}"));
}

#[test]
fn errors() {
    let d = tempfile::tempdir().unwrap();
    let f = write(&d, "finn.toml", FINN);
    fails(
        &["blossom", &f, "--arg", "1,0,0"],
        "takes exactly 2 arguments, got 1",
    );
    fails(
        &[
            "blossom", &f, "--arg", "1,0,0", "--arg", "1,0,0", "--arg", "1,0,0",
        ],
        "got 3",
    );
    fails(
        &["blossom", &f, "--arg", "1,0,0", "--arg", "1/2,1/2,1/2"],
        "sum to 3/2, not 1",
    );
    fails(
        &[
            "subpatch",
            &f,
            "--vertex",
            "1,0,0",
            "--vertex",
            "0,1,0",
            "--vertex",
            "1/2,1/2,0",
        ],
        "affinely dependent",
    );
    fails(
        &["subpatch", &f, "--vertex", "1,0,0", "--vertex", "0,1,0"],
        "expected 3",
    );
    fails(
        &[
            "subpatch", &f, "--vertex", "1,0,0", "--vertex", "0,1,0", "--vertex", "0,0,2",
        ],
        "not 1",
    );
    fails(
        &[
            "matrix", "subpatch", "--degree", "2", "--vertex", "1,0,0", "--vertex", "2,-1,0",
            "--vertex", "0,1,0",
        ],
        "affinely dependent",
    );
    fails(&["subdivide", &f, "--at", "1/2,1/2,1/2"], "not 1");
    // a point on an edge gives two pieces (tests/cli_usage.rs); a corner splits nothing
    fails(
        &["subdivide", &f, "--at", "0,0,1"],
        "the point is corner 3 of the domain",
    );
    for bad in ["1,1", "0,2", "1,4", "1", "1,2,3", "a,b"] {
        fails(&["halve", &f, "--edge", bad], "--edge");
    }
    fails(
        &["halve", &f, "--edge", "3,3"],
        "two distinct corners numbered 1 to 3",
    );
    fails(
        &["matrix", "halve", "--degree", "2", "--edge", "2,2"],
        "two distinct corners",
    );
    fails(&["elevate", &f, "--by", "0"], "at least 1");
    fails(
        &["matrix", "halve", "--degree", "2", "--vertex", "1,0,0"],
        "--vertex belongs to `matrix subpatch`",
    );
    fails(
        &[
            "matrix", "subpatch", "--degree", "2", "--edge", "1,2", "--vertex", "1,0,0",
            "--vertex", "0,1,0", "--vertex", "0,0,1",
        ],
        "--edge and --piece belong to `matrix halve`",
    );
    fails(
        &["matrix", "halve", "--degree", "60"],
        "above the limit of 1000",
    );
    fails(
        &["elevate", &f, "--by", "199"],
        "above the patch-file limits",
    );
}

#[test]
fn the_construction_fixtures_reproduce() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
    tribez()
        .arg("reproduce")
        .arg(&dir)
        .assert()
        .success()
        .stdout(
            predicate::str::contains("wiki-halving-matrix")
                .and(predicate::str::contains("add-and-halve-bottom-row-first"))
                .and(predicate::str::contains(" 0 failed")),
        );
}

#[test]
fn a_subpatch_of_a_patch_with_a_domain_has_the_image_domain() {
    let d = tempfile::tempdir().unwrap();
    let with_domain = FINN.replace(
        "degree = 2",
        "degree = 2\ndomain = [[\"1\", \"2\"], [\"7\", \"3\"], [\"2\", \"8\"]]",
    );
    let f = write(&d, "finn.toml", &with_domain);
    let out = d.path().join("sub.json");
    tribez()
        .args([
            "subpatch",
            &f,
            "--vertex",
            "1,0,0",
            "--vertex",
            "1/2,1/2,0",
            "--vertex",
            "1/3,1/3,1/3",
            "--format",
            "json",
            "-o",
        ])
        .arg(&out)
        .assert()
        .success();
    let sub: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    // vertices a1 = (1,2), (a1+a2)/2 = (4, 5/2), (a1+a2+a3)/3 = (10/3, 13/3)
    assert_eq!(
        sub["domain"],
        serde_json::json!([["1", "2"], ["4", "5/2"], ["10/3", "13/3"]])
    );
    // the same Cartesian point gives the same value in both
    let a = json(&["eval", &f, "--cartesian", "--at", "3,3"]);
    let b = json(&["eval", out.to_str().unwrap(), "--cartesian", "--at", "3,3"]);
    assert_eq!(a["results"][0]["point"], b["results"][0]["point"]);
}

/// A functional patch stays functional through every construction (its ordinates over the same
/// Cartesian points), so the pieces are again data a lookup or a functional claim takes.
#[test]
fn constructions_of_a_functional_patch_stay_functional() {
    let d = tempfile::tempdir().unwrap();
    // f(x, y) = x + 2y over the triangle (0,0), (2,0), (0,2): ordinates at the Bézier
    // abscissae of a linear patch are the corner values 0, 2, 4
    let f = write(
        &d,
        "plane.toml",
        "kind = \"functional\"\ndegree = 1\ndomain = [[0, 0], [2, 0], [0, 2]]\n\n[control_points]\n\"1,0,0\" = [0]\n\"0,1,0\" = [2]\n\"0,0,1\" = [4]\n",
    );
    let runs: [&[&str]; 4] = [
        &["elevate", &f, "--by", "2"],
        &[
            "subpatch",
            &f,
            "--vertex",
            "1,0,0",
            "--vertex",
            "1/2,1/2,0",
            "--vertex",
            "0,0,1",
        ],
        &["halve", &f, "--edge", "1,3"],
        &["subdivide", &f, "--midpoints"],
    ];
    for args in runs {
        let out = json(args);
        let patches: Vec<Value> = match out.get("pieces") {
            Some(p) => p
                .as_array()
                .unwrap()
                .iter()
                .map(|p| p["patch"].clone())
                .collect(),
            None => vec![out],
        };
        for (k, p) in patches.iter().enumerate() {
            assert_eq!(p["kind"], "functional", "{args:?}");
            // read back: at the Cartesian point (1/2, 1/4), in this piece's domain or not,
            // the value is x + 2y = 1 (a linear function, exactly reproduced everywhere)
            let file = write(&d, &format!("piece{k}.json"), &p.to_string());
            let v = json(&["eval", &file, "--cartesian", "--at", "1/2,1/4"]);
            assert_eq!(
                v["results"][0]["point"],
                serde_json::json!(["1"]),
                "{args:?}"
            );
        }
    }
}
