//! The `derivative`, `tangent` and `join` commands, run as a user runs them.

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;

fn tribez() -> Command {
    Command::cargo_bin("tribez").unwrap()
}

fn fixture(p: &str) -> String {
    format!("{}/../../fixtures/{p}", env!("CARGO_MANIFEST_DIR"))
}

fn json(args: &[&str]) -> Value {
    let out = tribez()
        .args(args)
        .args(["--format", "json"])
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    serde_json::from_slice(&out).unwrap()
}

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap().to_string())
        .collect()
}

fn fails_with(args: &[&str], message: &str) {
    tribez()
        .args(args)
        .assert()
        .code(2)
        .stdout("")
        .stderr(predicate::str::contains(message));
}

const FINN: &str = "finn_day30.toml";
const FLOATER: &str = "derivatives/finn_floater.toml";

#[test]
fn derivative_floater_example_cartesian_vectors() {
    // docs/theory.md §7
    let v = json(&[
        "derivative",
        &fixture(FLOATER),
        "--at",
        "3,4",
        "--cartesian",
        "--vector",
        "1,-2",
    ]);
    assert_eq!(strings(&v["value"]), ["48/245", "-118/245", "64/245"]);
    let v = json(&[
        "derivative",
        &fixture(FLOATER),
        "--at",
        "3,4",
        "--cartesian",
        "--vector",
        "1,-2",
        "--vector",
        "1,-2",
    ]);
    assert_eq!(strings(&v["value"]), ["-256/1225", "256/1225", "242/1225"]);
    assert_eq!(v["order"], 2);
}

#[test]
fn derivative_barycentric_direction() {
    let v = json(&[
        "derivative",
        &fixture(FINN),
        "--at",
        "1/2,1/3,1/6",
        "--dir",
        "1,0,-1",
    ]);
    assert_eq!(strings(&v["value"]), ["0", "-2", "1/3"]);
}

#[test]
fn derivative_errors() {
    let f = fixture(FINN);
    fails_with(
        &["derivative", &f, "--at", "1/2,1/3,1/6", "--dir", "1,0,0"],
        "sums to 1, not 0",
    );
    fails_with(
        &[
            "derivative",
            &f,
            "--at",
            "1/2,1/3,1/6",
            "--dir",
            "1,0,-1",
            "--dir",
            "1,0,-1",
            "--dir",
            "0,1,-1",
        ],
        "order 3",
    );
    fails_with(
        &["derivative", &f, "--at", "1/2,1/3,1/6"],
        "at least one direction",
    );
    fails_with(
        &["derivative", &f, "--at", "1/2,1/3,1/3", "--dir", "1,0,-1"],
        "not 1",
    );
    fails_with(
        &["derivative", &f, "--at", "1/2,1/3,1/6", "--vector", "1,2,3"],
        "expected 2",
    );
}

#[test]
fn tangent_finn_worked_example() {
    let v = json(&["tangent", &fixture(FINN), "--at", "1/2,1/3,1/6"]);
    assert_eq!(strings(&v["point"]), ["4/9", "5/9", "29/36"]);
    assert_eq!(strings(&v["intermediate"]["1,0,0"]), ["1/3", "1/6", "2/3"]);
    assert_eq!(strings(&v["intermediate"]["0,1,0"]), ["2/3", "5/6", "7/6"]);
    assert_eq!(strings(&v["intermediate"]["0,0,1"]), ["1/3", "7/6", "1/2"]);
    assert_eq!(strings(&v["partials"]["x"]), ["0", "-2", "1/3"]);
    assert_eq!(strings(&v["partials"]["y"]), ["2/3", "-2/3", "4/3"]);
    assert_eq!(strings(&v["normal"]), ["-22/9", "2/9", "4/3"]);
    assert_eq!(v["normal"], v["normal_from_intermediate"]);
}

#[test]
fn tangent_flags_a_singular_point() {
    // c200 = c110 = c101: at the corner (1,0,0) both partials vanish (hand derivation: the
    // level-1 de Casteljau points there are exactly those three control points).
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("pinched.toml");
    std::fs::write(
        &p,
        "degree = 2\n[control_points]\n\"2,0,0\" = [\"0\", \"0\", \"0\"]\n\"1,1,0\" = [\"0\", \"0\", \"0\"]\n\
         \"0,2,0\" = [\"1\", \"0\", \"0\"]\n\"1,0,1\" = [\"0\", \"0\", \"0\"]\n\
         \"0,1,1\" = [\"0\", \"1\", \"1\"]\n\"0,0,2\" = [\"0\", \"1\", \"0\"]\n",
    )
    .unwrap();
    let path = p.to_str().unwrap();
    let v = json(&["tangent", path, "--at", "1,0,0"]);
    assert_eq!(v["regular"], false);
    assert_eq!(strings(&v["normal"]), ["0", "0", "0"]);
    assert_eq!(
        json(&["tangent", path, "--at", "0,1/2,1/2"])["regular"],
        true
    );
    let text = tribez()
        .args(["tangent", path, "--at", "1,0,0"])
        .output()
        .unwrap();
    assert!(text.status.success());
    assert!(String::from_utf8_lossy(&text.stdout).contains("SINGULAR point"));
}

#[test]
fn tangent_of_a_constant_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("c.toml");
    std::fs::write(
        &p,
        "degree = 0\n[control_points]\n\"0,0,0\" = [\"1\", \"2\", \"3\"]\n",
    )
    .unwrap();
    fails_with(
        &["tangent", p.to_str().unwrap(), "--at", "1,0,0"],
        "degree 0",
    );
}

#[test]
fn join_g1_counterexample() {
    let v = json(&[
        "join",
        &fixture("joins/g1_counter_p.toml"),
        &fixture("joins/g1_counter_q.toml"),
    ]);
    assert_eq!(v["c0"], true);
    assert_eq!(v["c1"], false);
    assert_eq!(v["g1"], false);
    assert_eq!(v["coplanarity"], true);
    assert_eq!(v["max_smoothness"], 0);
    assert_eq!(strings(&v["mu"]), ["2", "0", "-1"]);
    let g1 = v["violations"]
        .as_array()
        .unwrap()
        .iter()
        .find(|x| x["condition"] == "G1")
        .unwrap();
    assert_eq!(g1["determinant"], "-8*t^2 + 8*t");
    assert_eq!(strings(&g1["witness"]["normal_a"]), ["0", "-2", "4"]);
    assert_eq!(strings(&g1["witness"]["normal_b"]), ["0", "2", "-6"]);
}

#[test]
fn join_finds_the_edge_in_any_vertex_order() {
    let v = json(&[
        "join",
        &fixture("joins/cubic_a.toml"),
        &fixture("joins/cubic_b_c1.toml"),
    ]);
    assert_eq!(v["shared_edge"]["a_vertices"], serde_json::json!([1, 2]));
    assert_eq!(v["shared_edge"]["b_vertices"], serde_json::json!([3, 2]));
    assert_eq!(v["c1"], true);
    assert_eq!(v["max_smoothness"], 1);
}

#[test]
fn make_c1_builds_a_cn_neighbour() {
    let dir = tempfile::tempdir().unwrap();
    let b = dir.path().join("b.toml");
    tribez()
        .args([
            "join",
            &fixture("joins/cubic_a.toml"),
            "--make-c1",
            "--domain",
            "2,-2",
            "-o",
            b.to_str().unwrap(),
        ])
        .assert()
        .success();
    let v = json(&["join", &fixture("joins/cubic_a.toml"), b.to_str().unwrap()]);
    assert_eq!(v["c1"], true);
    assert_eq!(v["g1"], true);
    assert_eq!(v["max_smoothness"], 3);
    // rows 0 and 1 equal those of the independently built C1 neighbour (make_fixtures.py)
    let built = tribez::Patch::from_file(&b).unwrap();
    let python = tribez::Patch::from_file(fixture("joins/cubic_b_c1.toml")).unwrap();
    for (idx, p) in built.control_net().entries().filter(|(idx, _)| idx[2] <= 1) {
        assert_eq!(
            p,
            python.control_net().at(&[idx[2], idx[1], idx[0]]),
            "at {idx:?}"
        );
    }
    // another edge
    let out = tribez()
        .args([
            "join",
            &fixture("joins/cubic_a.toml"),
            "--make-c1",
            "--edge",
            "2,3",
            "--domain",
            "4,4",
            "--format",
            "json",
        ])
        .assert()
        .success();
    let p: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
    assert_eq!(
        p["domain"],
        serde_json::json!([["3", "1"], ["1", "2"], ["4", "4"]])
    );
}

/// issue 10: `--make-c1` on a constant (degree 0) builds the same constant, and `join` accepts
/// the pair as C1 (equal constants are C^r for every r); G1 is decided: no (no tangent plane).
#[test]
fn make_c1_of_a_constant_is_accepted_as_c1() {
    let dir = tempfile::tempdir().unwrap();
    let b = dir.path().join("b.toml");
    tribez()
        .args([
            "join",
            &fixture("joins/const_a.toml"),
            "--make-c1",
            "--domain",
            "5,-3",
            "-o",
            b.to_str().unwrap(),
        ])
        .assert()
        .success();
    let v = json(&["join", &fixture("joins/const_a.toml"), b.to_str().unwrap()]);
    assert_eq!(v["c0"], true);
    assert_eq!(v["c1"], true);
    assert_eq!(v["g1"], false);
    assert_eq!(v["coplanarity"], true);
    let v = json(&[
        "join",
        &fixture("joins/const_a.toml"),
        &fixture("joins/const_b.toml"),
    ]);
    assert_eq!(
        (v["c1"].clone(), v["g1"].clone()),
        (true.into(), false.into())
    );
}

#[test]
fn join_errors() {
    let a = fixture("joins/quad_a.toml");
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p.to_str().unwrap().to_string()
    };
    // different degree
    let lin = write(
        "lin.toml",
        "degree = 1\ndomain = [[\"1\",\"2\"],[\"7\",\"3\"],[\"5\",\"-3\"]]\n[control_points]\n\"1,0,0\" = [\"0\",\"0\",\"0\"]\n\"0,1,0\" = [\"0\",\"2\",\"0\"]\n\"0,0,1\" = [\"1\",\"1\",\"1\"]\n",
    );
    fails_with(&["join", &a, &lin], "degrees 2 and 1");
    // different dimension
    let flat = std::fs::read_to_string(fixture("joins/quad_b_c1.toml")).unwrap();
    let flat = flat
        .lines()
        .map(|l| {
            if l.starts_with('"') {
                format!("{}]", &l[..l.rfind(',').unwrap()])
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let flat = write("flat.toml", &flat);
    fails_with(&["join", &a, &flat], "3 and 2 coordinates");
    // domains sharing no edge
    let far = std::fs::read_to_string(fixture("joins/quad_b_c1.toml"))
        .unwrap()
        .replace("[\"7\", \"3\"]", "[\"7\", \"4\"]");
    let far = write("far.toml", &far);
    fails_with(&["join", &a, &far], "share no edge");
    // no domains: the same (reference) triangle
    fails_with(&["join", &fixture(FINN), &fixture(FINN)], "same simplex");
    // degenerate domain (in the file, and for --make-c1)
    let degen = std::fs::read_to_string(&a)
        .unwrap()
        .replace("[\"2\", \"8\"]", "[\"13\", \"4\"]");
    let degen = write("degen.toml", &degen);
    fails_with(&["join", &degen, &a], "degenerate domain");
    fails_with(
        &["join", &a, "--make-c1", "--domain", "13,4"],
        "degenerate domain",
    );
    fails_with(&["join", &a, "--make-c1", "--domain", "3,7"], "same side");
    fails_with(
        &["join", &a, "--make-c1", "--domain", "5,-3", "--edge", "1,4"],
        "--edge 1,4",
    );
    fails_with(&["join", &a], "give two patches");
    // the options of --make-c1 are refused when a pair is checked (they would do nothing)
    let b = fixture("joins/quad_b_c1.toml");
    fails_with(
        &["join", &a, &b, "--domain", "5,-3"],
        "the argument '[B]' cannot be used with '--domain <X,Y>'",
    );
    fails_with(
        &["join", &a, &b, "--edge", "1,3"],
        "the argument '[B]' cannot be used with '--edge <I,J>'",
    );
    fails_with(
        &["join", &a, "--domain", "5,-3"],
        "the following required arguments were not provided: --make-c1",
    );
    fails_with(
        &["join", &a, "--edge", "1,3"],
        "the following required arguments were not provided: --domain <X,Y> --make-c1",
    );
}

#[test]
fn reproduce_derivative_and_join_fixtures() {
    for d in ["derivatives", "joins"] {
        tribez()
            .args(["reproduce", &fixture(d)])
            .assert()
            .success()
            .stdout(predicate::str::contains("0 failed"));
    }
}

#[test]
fn derivative_of_a_tetrahedron_and_a_curve() {
    let dir = tempfile::tempdir().unwrap();
    // p = Σ λ_k c_k (degree 1) over the tetrahedron (0,0,0),(2,0,0),(0,3,0),(1,1,4) with values 1, 2, 5, 11:
    // the affine function 1 + x/2 + 4y/3 + ... ; D_v p for v = (2,0,0) is c_1 - c_0 = 1 (moving to vertex 2)
    let t = dir.path().join("t.toml");
    std::fs::write(
        &t,
        "degree = 1\ndomain = [[\"0\",\"0\",\"0\"],[\"2\",\"0\",\"0\"],[\"0\",\"3\",\"0\"],[\"1\",\"1\",\"4\"]]\n[control_points]\n\"1,0,0,0\" = [\"1\"]\n\"0,1,0,0\" = [\"2\"]\n\"0,0,1,0\" = [\"5\"]\n\"0,0,0,1\" = [\"11\"]\n",
    )
    .unwrap();
    let v = json(&[
        "derivative",
        t.to_str().unwrap(),
        "--at",
        "1/4,1/4,1/4,1/4",
        "--vector",
        "2,0,0",
    ]);
    assert_eq!(strings(&v["value"]), ["1"]);
    let v = json(&[
        "derivative",
        t.to_str().unwrap(),
        "--at",
        "1/4,1/4,1/4,1/4",
        "--dir",
        "-1,0,0,1",
    ]);
    assert_eq!(strings(&v["value"]), ["10"]);
    // a quadratic curve 0, 1, 4 over [0, 1]: p(x) = 2x(1-x) + 4x^2 = 2x + 2x^2 with the reference
    // domain (1), (0) (u = x): p'(1/2) = 4, p'' = 4
    let c = dir.path().join("c.toml");
    std::fs::write(
        &c,
        "degree = 2\n[control_points]\n\"2,0\" = [\"4\"]\n\"1,1\" = [\"1\"]\n\"0,2\" = [\"0\"]\n",
    )
    .unwrap();
    let v = json(&[
        "derivative",
        c.to_str().unwrap(),
        "--at",
        "1/2",
        "--cartesian",
        "--vector",
        "1",
        "--vector",
        "1",
    ]);
    assert_eq!(strings(&v["value"]), ["4"]);
    let v = json(&[
        "derivative",
        c.to_str().unwrap(),
        "--at",
        "1/2",
        "--cartesian",
        "--vector",
        "1",
    ]);
    assert_eq!(strings(&v["value"]), ["4"]);
}

#[test]
fn bad_claims_of_the_new_ops_are_located_errors() {
    let dir = tempfile::tempdir().unwrap();
    let quad = fixture("joins/quad_a.toml");
    let cases = [
        (
            "op = \"join\"\npatches = [\"a\"]\npart = \"c1\"\nexpect = true",
            "a join needs two patches",
        ),
        (
            "op = \"join\"\npatches = [\"a\", \"nope\"]\npart = \"c1\"\nexpect = true",
            "no patch named `nope`",
        ),
        (
            "op = \"join\"\npatches = [\"a\", \"a\"]\npart = \"c1\"\nexpect = true",
            "same simplex",
        ),
        (
            "op = \"tangent\"\npatch = \"a\"\nat = [\"1\", \"0\", \"0\"]\npart = \"curvature\"\nexpect = true",
            "`curvature` is not available",
        ),
        (
            "op = \"derivative\"\npatch = \"a\"\nat = [\"1\", \"0\", \"0\"]\ndirs = [[\"1\", \"0\", \"0\"]]\nexpect = [\"0\"]",
            "sums to 1, not 0",
        ),
        (
            "op = \"derivative\"\npatch = \"a\"\nat = [\"1\", \"0\", \"0\"]\ndirs = [[\"1\", \"0\", \"-1\"], [\"1\", \"0\", \"-1\"], [\"1\", \"0\", \"-1\"]]\nexpect = [\"0\"]",
            "order 3",
        ),
        (
            "op = \"edge_curve\"\npatch = \"a\"\nfrom = 1\nto = 4\nexpect = []",
            "corner 4 does not exist",
        ),
    ];
    for (i, (claim, message)) in cases.iter().enumerate() {
        let sub = dir.path().join(format!("case{i}"));
        std::fs::create_dir(&sub).unwrap();
        std::fs::write(
            sub.join("x.claims.toml"),
            format!("[patches]\na = \"{quad}\"\n\n[[claim]]\nid = \"c\"\n{claim}\n"),
        )
        .unwrap();
        tribez()
            .args(["reproduce", sub.to_str().unwrap()])
            .assert()
            .code(2)
            .stderr(
                predicate::str::contains(*message).and(predicate::str::contains("x.claims.toml:")),
            );
    }
}
