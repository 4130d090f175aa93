//! `tribez check --patch PATCH --locate-results FILE` and `--ray-results FILE` as a user runs
//! them. Expected verdicts: the rows of fixtures/inverse/batch/ say theirs (SymPy values from
//! fixtures/inverse/expected_surfaces.json, and hand derivations written beside each row); the
//! peer rows (bezier's `Triangle.locate`) are judged in crates/tribez/tests/inverse_peer.rs.

mod common;

use common::{fails, fixtures, listing, tribez, write};

fn fx(name: &str) -> String {
    fixtures().join(name).display().to_string()
}

fn json(args: &[&str], code: i32) -> serde_json::Value {
    let out = tribez()
        .args(args)
        .args(["--format", "json"])
        .output()
        .expect("run tribez");
    assert_eq!(
        out.status.code(),
        Some(code),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// The linear triangle with nodes (0, 0), (1, 0), (0, 1), written to `dir`: the identity on the
/// whole plane, so (x, y) has the parameters (s, t) = (x, y) and no others.
fn identity_triangle(dir: &std::path::Path) -> std::path::PathBuf {
    write(
        dir,
        "identity.toml",
        "degree = 1\n[control_points]\n\"1,0,0\" = [0, 0]\n\"0,1,0\" = [1, 0]\n\"0,0,1\" = [0, 1]\n",
    )
}

fn failed_lines(j: &serde_json::Value) -> Vec<u64> {
    j["failures"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["line"].as_u64().unwrap())
        .collect()
}

#[test]
fn ray_rows_first_hits_corners_grazing_and_misses() {
    let j = json(
        &[
            "check",
            "--patch",
            &fx("inverse/dome.toml"),
            "--ray-results",
            &fx("inverse/batch/dome.rays.csv"),
            "--tolerance",
            "abs=1e-15",
        ],
        1,
    );
    assert_eq!(j["kind"], "ray");
    assert_eq!(
        (j["checked"].as_u64(), j["failed"].as_u64()),
        (Some(12), Some(4))
    );
    assert_eq!(failed_lines(&j), vec![21, 23, 25, 27]);
    let f = j["failures"].as_array().unwrap();
    // the second hit claimed as the first: extra, and the first hit (τ = 5/8) missed
    let kinds = |i: usize| -> Vec<String> {
        f[i]["mismatches"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| m["kind"].as_str().unwrap().to_string())
            .collect()
    };
    assert_eq!(kinds(0), ["extra", "missed"]);
    assert!(
        f[0]["mismatches"][1]["reason"]
            .as_str()
            .unwrap()
            .contains("tau = 5/8")
    );
    // `none` for a ray that hits: the hit τ = 11/8 is shown exactly
    assert_eq!(kinds(1), ["missed"]);
    assert!(
        f[1]["mismatches"][0]["reason"]
            .as_str()
            .unwrap()
            .contains("tau = 11/8")
    );
    assert_eq!(kinds(2), ["extra"]);
    assert_eq!(kinds(3), ["coordinate"]);
    assert_eq!(
        (j["missed"].as_u64(), j["extra"].as_u64()),
        (Some(2), Some(2))
    );
}

#[test]
fn locate_rows_edges_corners_and_wrong_counts() {
    let args = [
        "check",
        "--patch",
        &fx("inverse/quad_triangle.toml"),
        "--locate-results",
        &fx("inverse/batch/quad.locate.csv"),
        "--tolerance",
        "abs=1e-15",
    ];
    let j = json(&args, 1);
    assert_eq!(
        (j["checked"].as_u64(), j["failed"].as_u64()),
        (Some(8), Some(3))
    );
    assert_eq!(failed_lines(&j), vec![15, 17, 19]);
    // the missed solution is shown exactly: its polynomial 4x^2 + 2x - 1, interval and decimal
    let reason = j["failures"][0]["mismatches"][0]["reason"]
        .as_str()
        .unwrap();
    assert!(reason.contains("missed"), "{reason}");
    assert!(reason.contains("4x^2 + 2x - 1"), "{reason}");
    assert!(reason.contains("0.3090169943749474"), "{reason}");
    assert_eq!(j["failures"][0]["exact"][0][0]["polynomial"][2], "4");
    // text: the counts and each failed line
    let out = tribez().args(args).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("8 locate rows checked"), "{text}");
    assert!(text.contains("passed 5, failed 3"), "{text}");
    assert!(
        text.contains(
            "line 17: (1/2, 1/2) claimed (0.30901699437494745, 0.30901699437494745) (0.5, 0.5)"
        ),
        "{text}"
    );
}

#[test]
fn a_functional_patch_takes_rays_in_json_lines_and_junit() {
    let dir = tempfile::tempdir().unwrap();
    let junit = dir.path().join("j.xml");
    let j = json(
        &[
            "check",
            "--patch",
            &fx("inverse/hill.toml"),
            "--ray-results",
            &fx("inverse/batch/hill.rays.jsonl"),
            "--precision",
            "f64",
            "--tolerance",
            "correctly_rounded",
            "--junit",
            junit.to_str().unwrap(),
        ],
        1,
    );
    assert_eq!(failed_lines(&j), vec![2]);
    assert_eq!(j["precision"], "f64");
    let xml = std::fs::read_to_string(&junit).unwrap();
    assert!(xml.contains("line 2:"), "{xml}");
}

#[test]
fn passing_rows_exit_0() {
    let dir = tempfile::tempdir().unwrap();
    let rows = write(
        dir.path(),
        "r.csv",
        "1/4,1/4,2,0,0,-1,11/8,1/4,1/4\n2,2,1,0,0,-1\n",
    );
    let j = json(
        &[
            "check",
            "--patch",
            &fx("inverse/dome.toml"),
            "--ray-results",
            rows.to_str().unwrap(),
        ],
        0,
    );
    assert_eq!(
        (j["passed"].as_u64(), j["tolerance"].as_str()),
        (Some(2), Some("exact"))
    );
}

#[test]
fn bad_rows_and_arguments_exit_2_naming_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let dome = fx("inverse/dome.toml");
    let quad = fx("inverse/quad_triangle.toml");
    let cases: [(&str, &str, &str, &[&str]); 5] = [
        (
            "--locate-results",
            "l1.csv",
            "1/2,1/2,0.3,0.3\n1,2,3\n",
            &["l1.csv:2", "3 columns"],
        ),
        (
            "--locate-results",
            "l2.csv",
            "# c\n1/2,1/2,x,0.3\n",
            &["l2.csv:2", "malformed number"],
        ),
        (
            "--ray-results",
            "r1.csv",
            "0,0,1,0,0,0,none\n",
            &["r1.csv:1", "direction is zero"],
        ),
        (
            "--ray-results",
            "r2.jsonl",
            "[0,0,1,0,0,-1,1,0]\n",
            &["r2.jsonl:1", "8 columns"],
        ),
        (
            "--ray-results",
            "r3.csv",
            "# nothing\n",
            &["r3.csv", "no result rows"],
        ),
    ];
    for (flag, name, text, words) in cases {
        let rows = write(dir.path(), name, text);
        let patch = if flag == "--ray-results" {
            &dome
        } else {
            &quad
        };
        let before = listing(dir.path());
        fails(
            tribez().args(["check", "--patch", patch, flag, rows.to_str().unwrap()]),
            words,
        );
        assert_eq!(listing(dir.path()), before);
    }
    let rows = write(dir.path(), "ok.csv", "1/2,1/2,none\n");
    let rows = rows.to_str().unwrap();
    fails(
        tribez().args(["check", "--patch", &dome, "--locate-results", rows]),
        &["dome.toml", "ℝ^2"],
    );
    fails(
        tribez().args([
            "check",
            "--patch",
            &quad,
            "--locate-results",
            rows,
            "--tolerance",
            "ulps=1",
        ]),
        &["needs --precision"],
    );
    fails(
        tribez().args([
            "check",
            "--patch",
            &quad,
            "--locate-results",
            rows,
            "--precision",
            "f64",
            "--tolerance",
            "cond",
        ]),
        &["inverse batches take"],
    );
    fails(
        tribez().args([
            "check",
            "--patch",
            &quad,
            "--locate-results",
            rows,
            "--cartesian",
        ]),
        &["--cartesian is not available with --locate-results"],
    );
    fails(
        tribez().args(["check", "--patch", &quad]),
        &["--patch needs"],
    );
}

#[test]
fn anywhere_judges_locate_rows_over_the_whole_plane() {
    // The linear triangle with nodes (0, 0), (1, 0), (0, 1) is the identity on the whole plane:
    // (x, y) has the parameters (s, t) = (x, y), inside the closed triangle or not (hand-derived).
    let dir = tempfile::tempdir().unwrap();
    let patch = identity_triangle(dir.path());
    let rows = write(
        dir.path(),
        "r.csv",
        "2,2,none\n2,2,2,2\n-1/2,1/4,-1/2,1/4\n1/4,1/2,1/4,1/2\n",
    );
    let (patch, rows) = (patch.to_str().unwrap(), rows.to_str().unwrap());
    let args = ["check", "--patch", patch, "--locate-results", rows];
    // in the closed triangle: rows 2 and 3 claim parameters outside it, which are extra
    let j = json(&args, 1);
    assert_eq!(failed_lines(&j), vec![2, 3]);
    assert_eq!(
        (j["extra"].as_u64(), j["anywhere"].as_bool()),
        (Some(2), Some(false))
    );
    // anywhere: they hold, and row 1's "none" misses (2, 2)
    let j = json(&[&args[..], &["--anywhere"]].concat(), 1);
    assert_eq!(failed_lines(&j), vec![1]);
    assert_eq!(
        (j["missed"].as_u64(), j["anywhere"].as_bool()),
        (Some(1), Some(true))
    );
    let out = tribez().args(args).arg("--anywhere").output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("parameters anywhere in the plane"), "{text}");
    // only locate rows take it
    let ray_rows = write(dir.path(), "ray.csv", "0,0,1,0,0,-1,none\n");
    fails(
        tribez().args([
            "check",
            "--patch",
            &fx("inverse/dome.toml"),
            "--ray-results",
            ray_rows.to_str().unwrap(),
            "--anywhere",
        ]),
        &["cannot be used with '--anywhere'"],
    );
    fails(
        tribez().args(["check", &fx("finn_day30.claims.toml"), "--anywhere"]),
        &["--locate-results"],
    );
}

#[test]
fn a_missing_or_directory_results_file_is_named_plainly() {
    let dir = tempfile::tempdir().unwrap();
    let quad = fx("inverse/quad_triangle.toml");
    let missing = dir.path().join("nosuch.csv");
    for (flag, patch) in [("--locate-results", &quad), ("--results", &quad)] {
        let err = fails(
            tribez().args(["check", "--patch", patch, flag, missing.to_str().unwrap()]),
            &["nosuch.csv: cannot read: No such file or directory"],
        );
        assert!(!err.contains("os error"), "{err}");
        fails(
            tribez().args([
                "check",
                "--patch",
                patch,
                flag,
                dir.path().to_str().unwrap(),
            ]),
            &["a directory, not a regular file"],
        );
    }
}

#[test]
fn rows_can_come_from_a_pipe() {
    // the identity triangle: (x, y) has (s, t) = (x, y) (hand-derived)
    let dir = tempfile::tempdir().unwrap();
    let patch = identity_triangle(dir.path());
    let out = tribez()
        .args(["check", "--patch", patch.to_str().unwrap()])
        .args(["--locate-results", "/dev/stdin", "--format", "json"])
        .write_stdin("1/4,1/2,1/4,1/2\n1/3,1/3,none\n")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        (j["checked"].as_u64(), j["missed"].as_u64()),
        (Some(2), Some(1))
    );
    assert_eq!(failed_lines(&j), vec![2]);
}
