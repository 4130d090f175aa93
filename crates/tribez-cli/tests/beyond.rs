//! Issue 5 on the command line: rational patches, Bézier curves and tetrahedra, functional
//! patches and S-patches; and every kind of bad input they add (exit status 2, one line on
//! stderr naming the file and key or point, nothing on stdout).

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use predicates::prelude::*;

fn tribez() -> Command {
    Command::cargo_bin("tribez").expect("binary built")
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/beyond")
        .join(name)
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write temp file");
    p
}

/// Run `tribez ARGS PATCH` on a temporary patch file and expect exit 2 with every fragment on
/// stderr and nothing on stdout.
fn fails(text: &str, args: &[&str], fragments: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "p.toml", text);
    let mut cmd = tribez();
    cmd.arg(args[0]).arg(&p).args(&args[1..]);
    let mut a = cmd.assert().code(2).stdout(predicate::str::is_empty());
    for f in fragments {
        a = a.stderr(predicate::str::contains(*f));
    }
}

const RATIONAL: &str = r#"degree = 1
[control_points]
"1,0,0" = ["1", "0"]
"0,1,0" = ["0", "1"]
"0,0,1" = ["0", "0"]
[weights]
"1,0,0" = 1
"0,1,0" = 2
"0,0,1" = 3
"#;

#[test]
fn eval_rational_octant_exactly_and_in_floats() {
    tribez()
        .args(["eval"])
        .arg(fixture("octant_quartic.toml"))
        .args(["--at", "1/3,1/4,5/12", "--float", "all"])
        .assert()
        .success()
        .stdout(predicate::str::contains("rational, degree 4"))
        .stdout(predicate::str::contains("(1020/1681, 969/1681, 920/1681)"))
        .stdout(predicate::str::contains("f32 homogeneous de Casteljau"))
        .stdout(predicate::str::contains("ulp from the exact value"));
}

#[test]
fn eval_s_patch_at_cartesian_points() {
    tribez()
        .args(["eval"])
        .arg(fixture("pentagon_depth2.toml"))
        .args([
            "--cartesian",
            "--at",
            "2,2",
            "--float",
            "f64",
            "--format",
            "json",
        ])
        .assert()
        .success()
        .stdout(predicate::str::contains("\"81/358\""))
        .stdout(predicate::str::contains("\"63147/128164\""))
        .stdout(predicate::str::contains("ulps_vs_exact_at_inputs"));
    // without --cartesian: usage error
    tribez()
        .args(["eval"])
        .arg(fixture("pentagon_depth2.toml"))
        .args(["--at", "1/5,1/5,1/5,1/5,1/5"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--cartesian"));
    // outside the polygon
    tribez()
        .args(["eval"])
        .arg(fixture("pentagon_depth2.toml"))
        .args(["--cartesian", "--at", "10,0"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("--at 10,0"))
        .stderr(predicate::str::contains("outside the polygon"));
}

#[test]
fn graph_of_a_functional_patch_is_a_patch_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("graph.toml");
    tribez()
        .args(["graph"])
        .arg(fixture("functional_linear.toml"))
        .arg("-o")
        .arg(&out)
        .assert()
        .success();
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(
        text.contains("\"1,1,1\" = [\"8/3\", \"3\", \"-5/6\"]"),
        "{text}"
    );
    // the graph evaluates to (x, y, ℓ(x, y))
    tribez()
        .args(["eval"])
        .arg(&out)
        .args(["--cartesian", "--at", "2,3"])
        .assert()
        .success()
        .stdout(predicate::str::contains(": (2, 3, 1/2)"));
    // and its symbolic form is (x, y, 3 − 2x + y/2)
    tribez()
        .args(["symbolic", "--cartesian"])
        .arg(&out)
        .assert()
        .success()
        .stdout(predicate::str::contains("-2*x + 1/2*y + 3"));
    // graph of a non-functional patch
    tribez()
        .args(["graph"])
        .arg(fixture("cubic_curve.toml"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("takes a functional patch"));
}

#[test]
fn curves_and_tetrahedra_on_the_command_line() {
    tribez()
        .args(["eval"])
        .arg(fixture("cubic_curve.toml"))
        .args(["--at", "1/2,1/2"])
        .assert()
        .success()
        .stdout(predicate::str::contains(": (2, 15/8)"));
    tribez()
        .args(["eval"])
        .arg(fixture("tetra_quadratic.toml"))
        .args(["--at", "1/5,1/4,1/3,13/60", "--float", "f64"])
        .assert()
        .success()
        .stdout(predicate::str::contains("(1969/3600, 2569/3600, 173/180)"));
    tribez()
        .args(["symbolic"])
        .arg(fixture("cubic_curve.toml"))
        .assert()
        .success()
        .stdout(predicate::str::contains("3*u^2*v + 9*u*v^2 + 4*v^3"));
}

#[test]
fn rational_zero_denominator_at_the_queried_point() {
    let zero_corner = RATIONAL.replace("\"1,0,0\" = 1", "\"1,0,0\" = 0");
    fails(
        &zero_corner,
        &["eval", "--at", "1,0,0"],
        &["--at 1,0,0", "undefined at (1, 0, 0)", "denominator"],
    );
    // negative weights: the denominator u − v vanishes on the line u = v
    let negative = RATIONAL
        .replace("\"0,1,0\" = 2", "\"0,1,0\" = -1")
        .replace("\"0,0,1\" = 3", "\"0,0,1\" = 0");
    fails(
        &negative,
        &["eval", "--at", "1/2,1/2,0"],
        &["undefined at (1/2, 1/2, 0)"],
    );
    // elsewhere it evaluates
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "p.toml", &zero_corner);
    tribez()
        .arg("eval")
        .arg(&p)
        .args(["--at", "0,1/2,1/2"])
        .assert()
        .success()
        .stdout(predicate::str::contains(": (0, 2/5)"));
}

#[test]
fn bad_weights() {
    let missing = RATIONAL.replace("\"0,0,1\" = 3\n", "");
    fails(
        &missing,
        &["eval", "--at", "1,0,0"],
        &["p.toml", "weights", "missing weight \"0,0,1\""],
    );
    let duplicated = RATIONAL.replace("\"0,0,1\" = 3", "\"0,0,1\" = 3\n\"0, 0,1\" = 4");
    fails(
        &duplicated,
        &["eval", "--at", "1,0,0"],
        &["weights.\"0, 0,1\"", "duplicated weight"],
    );
    let extra = RATIONAL.replace("\"0,0,1\" = 3", "\"0,0,1\" = 3\n\"2,0,0\" = 4");
    fails(
        &extra,
        &["eval", "--at", "1,0,0"],
        &["weights.\"2,0,0\"", "no control point \"2,0,0\""],
    );
    let all_zero = RATIONAL
        .replace("\" = 1\n", "\" = 0\n")
        .replace("\" = 2\n", "\" = 0\n")
        .replace("\" = 3\n", "\" = 0\n");
    fails(
        &all_zero,
        &["eval", "--at", "1,0,0"],
        &["every weight is zero"],
    );
    let not_a_number = RATIONAL.replace("\" = 2\n", "\" = \"two\"\n");
    fails(
        &not_a_number,
        &["eval", "--at", "1,0,0"],
        &["weights.\"0,1,0\""],
    );
    // weights where the kind says otherwise
    let contradiction = format!("kind = \"bezier\"\n{RATIONAL}");
    fails(
        &contradiction,
        &["eval", "--at", "1,0,0"],
        &["has no weights"],
    );
}

#[test]
fn symbolic_rational_prints_numerators_and_denominator() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "p.toml", RATIONAL);
    tribez()
        .arg("symbolic")
        .arg(&p)
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "[0] u\n[1] 2*v\ndenominator u + 2*v + 3*w",
        ));
}

#[test]
fn a_claim_op_that_takes_polynomial_patches_rejects_a_rational_one() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "p.toml", RATIONAL);
    write(
        dir.path(),
        "x.claims.toml",
        "patch = \"p.toml\"\n[[claim]]\nid = \"s\"\nop = \"symbolic\"\nexpect = [\"u\", \"v\"]\n",
    );
    tribez()
        .arg("reproduce")
        .arg(dir.path())
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "operation `symbolic` does not take a rational patch",
        ));
}

const SQUARE: &str = r#"degree = 1
polygon = [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]]
[control_points]
"1,0,0,0" = ["0"]
"0,1,0,0" = ["1"]
"0,0,1,0" = ["2"]
"0,0,0,1" = ["3"]
"#;

#[test]
fn s_patch_over_a_square() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "p.toml", SQUARE);
    // Wachspress on the unit square is bilinear: λ(1/2, 1/4) = (3/8, 3/8, 1/8, 1/8)
    tribez()
        .arg("eval")
        .arg(&p)
        .args(["--cartesian", "--at", "1/2,1/4"])
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "(Wachspress (3/8, 3/8, 1/8, 1/8)): (1)",
        ));
}

#[test]
fn bad_polygons() {
    let nonconvex = SQUARE.replace("[\"1\", \"1\"]", "[\"1/4\", \"1/4\"]");
    fails(
        &nonconvex,
        &["eval", "--cartesian", "--at", "0,0"],
        &["p.toml:2", "polygon", "not strictly convex"],
    );
    let crossing = SQUARE.replace(
        "[[\"0\", \"0\"], [\"1\", \"0\"], [\"1\", \"1\"], [\"0\", \"1\"]]",
        "[[\"0\", \"0\"], [\"1\", \"1\"], [\"1\", \"0\"], [\"0\", \"1\"]]",
    );
    fails(
        &crossing,
        &["eval", "--cartesian", "--at", "0,0"],
        &["polygon", "self-intersecting"],
    );
    let clockwise = SQUARE.replace(
        "[[\"0\", \"0\"], [\"1\", \"0\"], [\"1\", \"1\"], [\"0\", \"1\"]]",
        "[[\"0\", \"0\"], [\"0\", \"1\"], [\"1\", \"1\"], [\"1\", \"0\"]]",
    );
    fails(
        &clockwise,
        &["eval", "--cartesian", "--at", "0,0"],
        &["polygon", "clockwise"],
    );
    let collinear = SQUARE.replace(
        "[\"1\", \"1\"], [\"0\", \"1\"]",
        "[\"1\", \"1\"], [\"1\", \"2\"]",
    );
    fails(
        &collinear,
        &["eval", "--cartesian", "--at", "0,0"],
        &["polygon", "on the line"],
    );
    let wrong_parts = SQUARE.replace("polygon = [[\"0\", \"0\"], ", "polygon = [");
    fails(
        &wrong_parts,
        &["eval", "--cartesian", "--at", "1,1/2"],
        &["control_points", "3 vertices"],
    );
    let with_domain = format!("domain = [[\"0\",\"0\"],[\"1\",\"0\"],[\"0\",\"1\"]]\n{SQUARE}");
    fails(
        &with_domain,
        &["eval", "--cartesian", "--at", "0,0"],
        &["domain", "cannot have `domain`"],
    );
    let three_d = SQUARE.replace("[\"0\", \"1\"]]", "[\"0\", \"1\", \"0\"]]");
    fails(
        &three_d,
        &["eval", "--cartesian", "--at", "0,0"],
        &["polygon", "vertex 4 has 3 coordinates"],
    );
}

const FUNCTIONAL: &str = r#"kind = "functional"
degree = 1
domain = [["0", "0"], ["2", "0"], ["0", "2"]]
[control_points]
"1,0,0" = ["1"]
"0,1,0" = ["2"]
"0,0,1" = ["3"]
"#;

#[test]
fn functional_patches() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "p.toml", FUNCTIONAL);
    tribez()
        .arg("eval")
        .arg(&p)
        .args(["--cartesian", "--at", "1,1"])
        .assert()
        .success()
        .stdout(predicate::str::contains(": (5/2)"));
    let two = FUNCTIONAL.replace("[\"2\"]", "[\"2\", \"0\"]");
    fails(
        &two,
        &["eval", "--at", "1,0,0"],
        &["p.toml", "control_points", "different dimensions"],
    );
    let all_two = FUNCTIONAL
        .replace("[\"1\"]", "[\"1\", \"0\"]")
        .replace("[\"2\"]", "[\"2\", \"0\"]")
        .replace("[\"3\"]", "[\"3\", \"0\"]");
    fails(
        &all_two,
        &["eval", "--at", "1,0,0"],
        &[
            "control_points",
            "functional patch has one control ordinate",
            "2 coordinates",
        ],
    );
    fails(
        &all_two,
        &["graph"],
        &["functional patch has one control ordinate"],
    );
    let unknown = FUNCTIONAL.replace("functional", "funtional");
    fails(
        &unknown,
        &["eval", "--at", "1,0,0"],
        &["kind", "unknown kind `funtional`"],
    );
}

#[test]
fn derivative_of_a_rational_patch() {
    tribez()
        .args(["derivative"])
        .arg(fixture("octant_quartic.toml"))
        .args(["--at", "1,0,0", "--dir", "-1,1,0"])
        .assert()
        .success()
        .stdout(predicate::str::contains("at (1, 0, 0): (0, 2, 0)"));
    // second order: fixtures/beyond/derive.py, the closed-form second quotient rule
    tribez()
        .args(["derivative"])
        .arg(fixture("octant_quartic.toml"))
        .args(["--at", "1/3,1/4,5/12", "--dir", "-1,1,0", "--dir", "-1,1,0"])
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "(-16565330304/4750104241, -22730325024/4750104241, -16409296800/4750104241)",
        ));
    // orders above 12 are refused (the work grows as 3^order)
    let mut many = vec!["derivative", "--at", "1/3,1/4,5/12"];
    for _ in 0..13 {
        many.extend(["--dir", "-1,1,0"]);
    }
    tribez()
        .args(&many[..1])
        .arg(fixture("octant_quartic.toml"))
        .args(&many[1..])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("at most 12 directions"));
    // the tangent frame: the normal is radial (each component 12132288/2825761 times p's) and
    // equals the one from the projected intermediate points
    tribez()
        .args(["tangent"])
        .arg(fixture("octant_quartic.toml"))
        .args(["--at", "1/3,1/4,5/12"])
        .assert()
        .success()
        .stdout(predicate::str::contains(
            "normal p_x × p_y = (12374933760/4750104241, 11756187072/4750104241, 11161704960/4750104241)",
        ))
        .stdout(predicate::str::contains("(equal)"));
    let zero_corner = RATIONAL.replace("\"1,0,0\" = 1", "\"1,0,0\" = 0");
    fails(
        &zero_corner,
        &["derivative", "--at", "1,0,0", "--dir", "-1,1,0"],
        &["--at 1,0,0", "undefined at (1, 0, 0)"],
    );
    tribez()
        .args(["derivative"])
        .arg(fixture("pentagon_depth2.toml"))
        .args(["--at", "2,2", "--dir", "-1,1"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("does not take S-patches"));
}

/// The rational blossom X[..]/W[..] of the octant; expected values from fixtures/beyond/derive.py
/// (X and W blossoms by the multi-affine de Casteljau, Python fractions).
#[test]
fn blossom_of_a_rational_patch() {
    let blossom = |args: &[&str]| {
        let mut cmd = tribez();
        cmd.arg("blossom").arg(fixture("octant_quartic.toml"));
        for a in args {
            cmd.args(["--arg", a]);
        }
        cmd.assert()
    };
    let u = "1/3,1/4,5/12";
    // the diagonal is the patch: p(1/3,1/4,5/12) = (1020, 969, 920)/1681 (docs/theory.md §10)
    blossom(&[u, u, u, u])
        .success()
        .stdout(predicate::str::contains(
            "= (1020/1681, 969/1681, 920/1681)",
        ));
    // four different arguments, in two orders (symmetry)
    let args = [u, "1/2,1/2,0", "0,1/3,2/3", "1/5,2/5,2/5"];
    for order in [[0, 1, 2, 3], [3, 2, 0, 1], [1, 3, 0, 2]] {
        blossom(&order.map(|i| args[i]))
            .success()
            .stdout(predicate::str::contains(
                "= (857/1871, 2917/3742, 907/1871)",
            ));
    }
    // W[e1, e1, e1, x] = 12 x0 + 12 x1 + 9 x2 (the weights w400, w310, w301) is 0 at x = (-3, 0, 4)
    blossom(&["1,0,0", "1,0,0", "1,0,0", "-3,0,4"])
        .code(2)
        .stdout(predicate::str::is_empty())
        .stderr(predicate::str::contains(
            "tribez: --arg: the rational blossom b[(1, 0, 0), (1, 0, 0), (1, 0, 0), (-3, 0, 4)] is undefined: the weight blossom W[(1, 0, 0), (1, 0, 0), (1, 0, 0), (-3, 0, 4)]",
        ));
    blossom(&["1,0,0"])
        .code(2)
        .stderr(predicate::str::contains("takes exactly 4 arguments, got 1"));
    // the same in a claim file: a located error naming the claim's `args`
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(fixture("octant_quartic.toml"), dir.path().join("o.toml")).unwrap();
    write(
        dir.path(),
        "x.claims.toml",
        "patch = \"o.toml\"\n[[claim]]\nid = \"w0\"\nop = \"blossom\"\nargs = [[\"1\", \"0\", \"0\"], [\"1\", \"0\", \"0\"], [\"1\", \"0\", \"0\"], [\"-3\", \"0\", \"4\"]]\nexpect = [\"0\", \"0\", \"0\"]\n",
    );
    tribez()
        .arg("reproduce")
        .arg(dir.path())
        .assert()
        .code(2)
        .stderr(
            predicate::str::contains("x.claims.toml:5: w0.args")
                .and(predicate::str::contains("w0.args"))
                .and(predicate::str::contains("weight blossom W[")),
        );
    // S-patches are refused
    tribez()
        .args(["blossom"])
        .arg(fixture("pentagon_depth2.toml"))
        .args(["--arg", "1,0,0,0,0", "--arg", "1,0,0,0,0"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains("does not take S-patches"));
}

#[test]
fn elevate_and_subpatch_a_rational_patch() {
    let dir = tempfile::tempdir().unwrap();
    let up = dir.path().join("up.toml");
    tribez()
        .args(["elevate", "--by", "2"])
        .arg(fixture("octant_quartic.toml"))
        .arg("-o")
        .arg(&up)
        .assert()
        .success();
    let text = std::fs::read_to_string(&up).unwrap();
    assert!(
        text.contains("degree = 6") && text.contains("[weights]"),
        "{text}"
    );
    tribez()
        .arg("eval")
        .arg(&up)
        .args(["--at", "1/3,1/4,5/12"])
        .assert()
        .success()
        .stdout(predicate::str::contains("(1020/1681, 969/1681, 920/1681)"));
    // the elevated patch is still on the sphere, identically
    write(
        dir.path(),
        "up.claims.toml",
        "patch = \"up.toml\"\n[[claim]]\nid = \"s\"\nop = \"implicit\"\nequation = \"x^2 + y^2 + z^2 - 1\"\nexpect = \"0\"\n",
    );
    tribez().arg("reproduce").arg(dir.path()).assert().success();
    // subpatch over [a1, midpoint of a1 a2, centroid]: its corner 3 is the parent's centroid,
    // (80, 100, 59)/141 (80² + 100² + 59² = 141²)
    let sub = dir.path().join("sub.toml");
    tribez()
        .arg("subpatch")
        .arg(fixture("octant_quartic.toml"))
        .args([
            "--vertex",
            "1,0,0",
            "--vertex",
            "1/2,1/2,0",
            "--vertex",
            "1/3,1/3,1/3",
            "-o",
        ])
        .arg(&sub)
        .assert()
        .success();
    tribez()
        .arg("eval")
        .arg(&sub)
        .args(["--at", "0,0,1"])
        .assert()
        .success()
        .stdout(predicate::str::contains("(80/141, 100/141, 59/141)"));
    tribez()
        .arg("eval")
        .arg(fixture("octant_quartic.toml"))
        .args(["--at", "1/3,1/3,1/3"])
        .assert()
        .success()
        .stdout(predicate::str::contains("(80/141, 100/141, 59/141)"));
    // a weight that becomes 0 on elevation
    fails(
        "degree = 1\n[control_points]\n\"1,0\" = [\"0\"]\n\"0,1\" = [\"1\"]\n[weights]\n\"1,0\" = 1\n\"0,1\" = -1\n",
        &["elevate"],
        &["weight 0"],
    );
}

#[test]
fn subdivide_a_rational_patch() {
    let out = tribez()
        .args(["subdivide", "--format", "json", "--at", "1/3,1/3,1/3"])
        .arg(fixture("octant_quartic.toml"))
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let pieces = j["pieces"].as_array().unwrap();
    assert_eq!(pieces.len(), 3);
    let dir = tempfile::tempdir().unwrap();
    for (s, piece) in pieces.iter().enumerate() {
        let p = write(
            dir.path(),
            &format!("piece{s}.json"),
            &piece["patch"].to_string(),
        );
        // corner s of piece s is the split point, the parent's centroid (80, 100, 59)/141
        let mut at = ["0"; 3];
        at[s] = "1";
        tribez()
            .arg("eval")
            .arg(&p)
            .args(["--at", &at.join(",")])
            .assert()
            .success()
            .stdout(predicate::str::contains("(80/141, 100/141, 59/141)"));
        write(
            dir.path(),
            &format!("piece{s}.claims.toml"),
            &format!(
                "patch = \"piece{s}.json\"\n[[claim]]\nid = \"s\"\nop = \"implicit\"\nequation = \"x^2 + y^2 + z^2 - 1\"\nexpect = \"0\"\n"
            ),
        );
    }
    tribez().arg("reproduce").arg(dir.path()).assert().success();
    tribez()
        .args(["subdivide", "--midpoints"])
        .arg(fixture("octant_quartic.toml"))
        .assert()
        .success()
        .stdout(predicate::str::contains("[pieces.patch.weights]"));
}

#[test]
fn halve_a_rational_patch() {
    // The octant halved on edge 1,2. The new corner is the parent at (1/2, 1/2, 0), by hand on
    // the edge w = 0 (weights 12, 12, 16, 24, 48; B_i = C(4,i)/16):
    // x = (12 + 12·4 + 16·(3/4)·6 + 24·(1/2)·4)/(12 + 12·4 + 16·6 + 24·4 + 48) = 180/300 = 3/5,
    // y = (12·(1/2)·4 + 16·(3/4)·6 + 24·4 + 48)/300 = 240/300 = 4/5.
    let out = tribez()
        .args(["halve", "--format", "json", "--edge", "1,2"])
        .arg(fixture("octant_quartic.toml"))
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let j: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let pieces = j["pieces"].as_array().unwrap();
    assert_eq!(pieces.len(), 2);
    let dir = tempfile::tempdir().unwrap();
    for (s, (piece, corner)) in pieces.iter().zip(["0,1,0", "1,0,0"]).enumerate() {
        assert!(piece["patch"]["weights"].is_object(), "a rational half");
        let p = write(
            dir.path(),
            &format!("half{s}.json"),
            &piece["patch"].to_string(),
        );
        tribez()
            .arg("eval")
            .arg(&p)
            .args(["--at", corner])
            .assert()
            .success()
            .stdout(predicate::str::contains("(3/5, 4/5, 0)"));
        // each half still lies on the unit sphere, as a polynomial identity
        write(
            dir.path(),
            &format!("half{s}.claims.toml"),
            &format!(
                "patch = \"half{s}.json\"\n[[claim]]\nid = \"s\"\nop = \"implicit\"\nequation = \"x^2 + y^2 + z^2 - 1\"\nexpect = \"0\"\n"
            ),
        );
    }
    tribez().arg("reproduce").arg(dir.path()).assert().success();
    // the Wikipedia article's add-and-halve gives the same halves
    let again = tribez()
        .args([
            "halve",
            "--format",
            "json",
            "--edge",
            "1,2",
            "--add-and-halve",
        ])
        .arg(fixture("octant_quartic.toml"))
        .output()
        .unwrap();
    let k: serde_json::Value = serde_json::from_slice(&again.stdout).unwrap();
    assert_eq!(k["pieces"], j["pieces"]);
    // S-patches are refused with a one-line usage error
    tribez()
        .args(["halve", "--edge", "1,2"])
        .arg(fixture("pentagon_depth2.toml"))
        .assert()
        .code(2)
        .stderr(predicate::str::contains("does not take S-patches"));
}

#[test]
fn float_claims_on_rational_and_s_patches() {
    tribez()
        .arg("check")
        .arg(fixture("float.claims.toml"))
        .assert()
        .success()
        .stdout(predicate::str::contains("octant-f64-python"))
        .stdout(predicate::str::contains("4 passed"));
    // a claimed value 1000 ulps off fails (exit 1)
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(fixture("octant_quartic.toml"), dir.path().join("o.toml")).unwrap();
    write(
        dir.path(),
        "bad.claims.toml",
        "patch = \"o.toml\"\n[[claim]]\nid = \"b\"\nop = \"eval\"\nat = [\"1/3\", \"1/4\", \"5/12\"]\nprecision = \"f64\"\ntolerance = \"ulps=8\"\nexpect = [\"0.60678167757298\", \"0.5764425936942295\", \"0.5472932778108268\"]\n",
    );
    tribez()
        .arg("check")
        .arg(dir.path().join("bad.claims.toml"))
        .assert()
        .code(1);
    // rational patches have a proven bound (src/certify/bound.rs): a value far off fails it (exit 1)
    write(
        dir.path(),
        "bound.claims.toml",
        "patch = \"o.toml\"\n[[claim]]\nid = \"b\"\nop = \"eval\"\nat = [\"1/3\", \"1/4\", \"5/12\"]\nprecision = \"f64\"\ntolerance = \"bound\"\nexpect = [\"0.6\", \"0.5\", \"0.5\"]\n",
    );
    tribez()
        .arg("check")
        .arg(dir.path().join("bound.claims.toml"))
        .assert()
        .code(1);
}
