//! `lookup` claims (`op = "lookup"`): a mesh's value at a point as another implementation
//! found it. Expected values: fixtures/mesh/derive.py (pure Python fractions: the hexagon mesh
//! reproduces f = x³ − 2xy + y²/3 + 1/2, and its float lookup is simulated in Python doubles),
//! which wrote fixtures/mesh/lookup.claims.toml.

mod common;

use std::path::{Path, PathBuf};

use common::{fails, fixtures, tribez, write};
use serde_json::Value as Json;

fn check_json(file: &Path, code: i32) -> Json {
    let out = tribez()
        .args(["check", "--format", "json"])
        .arg(file)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(code),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn the_fixture_s_lookup_claims_hold() {
    let j = check_json(&fixtures().join("mesh/lookup.claims.toml"), 0);
    let claims = j["claims"].as_array().unwrap();
    assert_eq!(claims.len(), 7);
    for c in claims {
        assert_eq!(c["op"], "lookup");
        assert_eq!(c["verdict"], "passed", "{c}");
    }
    // f(1/3, 1/5) = 1/27 − 2/15 + 1/75 + 1/2 = 563/1350 (derive.py)
    assert_eq!(claims[0]["exact"]["value"], "563/1350");
    // (1/2, 0) is on the spoke shared by triangles 0 and 5: the claimed 5 is accepted
    assert_eq!(claims[1]["exact"]["triangle"], 5);
    // `cond` on a cubic: K = 3n = 9
    assert_eq!(claims[6]["tolerance"], "cond=9");
}

/// A claim file beside a copy of the hexagon mesh, with `body` as its one claim.
fn claim_file(dir: &Path, body: &str) -> PathBuf {
    std::fs::copy(
        fixtures().join("mesh/hexagon_cubic.toml"),
        dir.join("hexagon_cubic.toml"),
    )
    .unwrap();
    write(
        dir,
        "l.claims.toml",
        format!("[[claim]]\nid = \"c\"\nop = \"lookup\"\nmesh = \"hexagon_cubic.toml\"\n{body}"),
    )
}

#[test]
fn wrong_lookups_fail() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // the value of a neighbouring point
    let j = check_json(
        &claim_file(d, "at = [\"1/3\", \"1/5\"]\nexpect = \"5/8\"\n"),
        1,
    );
    assert_eq!(j["claims"][0]["verdict"], "FAILED");
    assert_eq!(j["claims"][0]["exact"], "563/1350");
    // the right value in a triangle that does not contain the point: (1/3, 1/5) is in
    // triangle 0 = (0, 1, 2) only
    let j = check_json(
        &claim_file(
            d,
            "at = [\"1/3\", \"1/5\"]\nexpect = \"563/1350\"\ntriangle = 1\n",
        ),
        1,
    );
    let c = &j["claims"][0];
    assert_eq!(c["exact"]["triangle"], 0);
    let m = c["mismatches"].as_array().unwrap();
    assert_eq!(m.len(), 1, "{c}");
    assert!(
        m[0]["reason"]
            .as_str()
            .unwrap()
            .contains("not in triangle 1; it is in triangle 0"),
        "{c}"
    );
    // the simulated float lookup is 1.32 ulp from the exact value at the inputs as seen
    // (derive.py): not exact, and not within ulps=1
    for tolerance in ["exact", "ulps=1"] {
        let j = check_json(
            &claim_file(
                d,
                &format!(
                    "at = [\"1/7\", \"3/11\"]\nexpect = \"0.4497867624027178\"\nprecision = \"f64\"\ntolerance = \"{tolerance}\"\n"
                ),
            ),
            1,
        );
        assert_eq!(j["claims"][0]["verdict"], "FAILED", "{tolerance}");
    }
}

#[test]
fn bad_lookup_claims_are_located() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bad = [
        (
            "at = [\"2\", \"0\"]\nexpect = \"1\"\n",
            &["l.claims.toml:5", "c.at", "(2, 0) lies outside the mesh"][..],
        ),
        (
            "at = [\"1/3\", \"1/5\", \"0\"]\nexpect = \"1\"\n",
            &["c.at", "3 fields, expected 2"],
        ),
        (
            "at = [\"1/3\", \"1/5\"]\nexpect = \"1\"\ntriangle = 6\n",
            &["c.triangle", "no triangle 6", "0 to 5"],
        ),
        (
            "at = [\"1/3\", \"1/5\"]\nexpect = \"1\"\nprecision = \"f64\"\ntolerance = \"bound\"\n",
            &["c.tolerance", "`bound` does not apply to `lookup`"],
        ),
        ("at = [\"1/3\", \"1/5\"]\n", &["missing key `expect`"]),
        (
            "at = [\"1/3\", \"1/5\"]\nexpect = \"1\"\npoint = [\"0\", \"0\"]\n",
            &["c.point"],
        ),
    ];
    for (body, words) in bad {
        let f = claim_file(d, body);
        fails(tribez().arg("check").arg(&f), words);
    }
    // a mesh file that is not there: the claim naming it
    let f = write(
        d,
        "m.claims.toml",
        "[[claim]]\nid = \"c\"\nop = \"lookup\"\nmesh = \"absent.toml\"\nat = [\"0\", \"0\"]\nexpect = \"1\"\n",
    );
    fails(tribez().arg("check").arg(&f), &["absent.toml", "c.mesh"]);
    // an invalid mesh: its own file and line
    write(
        d,
        "clockwise.toml",
        "degree = 1\nvertices = [[\"0\", \"0\"], [\"1\", \"0\"], [\"0\", \"1\"]]\ntriangles = [[0, 2, 1]]\n\n[ordinates]\nvertex = [\"0\", \"0\", \"0\"]\n",
    );
    let f = write(
        d,
        "cw.claims.toml",
        "[[claim]]\nid = \"c\"\nop = \"lookup\"\nmesh = \"clockwise.toml\"\nat = [\"0\", \"0\"]\nexpect = \"0\"\n",
    );
    fails(
        tribez().arg("check").arg(&f),
        &["clockwise.toml:3", "clockwise"],
    );
}
