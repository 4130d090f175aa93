//! Reading and writing patch files.

use super::write::strings;
use super::*;
use crate::io::InputError;
use crate::io::Problem;
use crate::io::tree::Document;
use crate::patch::BezierPatch;

const FINN: &str = r#"
name = "Finn"
degree = 2
[control_points]
"2,0,0" = ["0", "0", "0"]
"1,1,0" = ["1", "0", "2"]
"0,2,0" = ["0", "2", "0"]
"1,0,1" = ["0", "1", "0"]
"0,1,1" = ["1", "1", "1"]
"0,0,2" = ["0", "2", "1"]
"#;

fn parse(text: &str) -> Result<BezierPatch, InputError> {
    let doc = Document::parse_toml("p.toml", text)?;
    patch_from_document(&doc, &doc.root, "")
}

#[test]
fn reads_the_worked_example() {
    let p = parse(FINN).unwrap();
    assert_eq!(p.net.degree(), 2);
    assert_eq!(p.net.dim(), 3);
    assert_eq!(strings(p.net.at(&[1, 1, 0])), ["1", "0", "2"]);
}

/// Errors are data: the variant, the key and the line, with the figures of the message
/// as fields (the sentence is the `Display` of the variant).
#[test]
fn errors_carry_the_problem_as_data() {
    let problem = |text: &str| {
        let e = parse(text).unwrap_err();
        (*e.problem, e.key, e.line)
    };
    let missing = FINN.replace("\"0,0,2\" = [\"0\", \"2\", \"1\"]\n", "");
    assert_eq!(
        problem(&missing),
        (
            Problem::Patch(PatchFileProblem::MissingControlPoint {
                index: "0,0,2".into(),
                degree: 2
            }),
            Some("control_points".into()),
            Some(4)
        )
    );
    let wrong_sum = FINN.replace("\"0,0,2\"", "\"0,0,3\"");
    assert_eq!(
        problem(&wrong_sum).0,
        Problem::Patch(PatchFileProblem::MultiIndexSum { sum: 3, degree: 2 })
    );
    let mixed = FINN.replace("[\"0\", \"2\", \"1\"]", "[\"0\", \"2\"]");
    assert_eq!(
        problem(&mixed),
        (
            Problem::Patch(PatchFileProblem::PointDimension {
                dim: 2,
                other: "2,0,0".into(),
                expected: 3
            }),
            Some("control_points.\"0,0,2\"".into()),
            Some(10)
        )
    );
    let big = FINN.replace("degree = 2", "degree = 100000");
    assert_eq!(
        problem(&big).0,
        Problem::Patch(PatchFileProblem::DegreeTooLarge {
            degree: 100_000,
            limit: MAX_DEGREE
        })
    );
}

#[test]
fn round_trips_through_toml_and_json() {
    let p = parse(FINN).unwrap();
    let again = parse(&patch_to_toml(&p)).unwrap();
    assert_eq!(p, again);
    let json = patch_to_json(&p).to_string();
    let doc = Document::parse_json("p.json", &json).unwrap();
    assert_eq!(patch_from_document(&doc, &doc.root, "").unwrap(), p);
}

fn err(text: &str) -> String {
    parse(text).unwrap_err().to_string()
}

#[test]
fn bad_patches_name_the_place() {
    let missing = FINN.replace("\"0,1,1\" = [\"1\", \"1\", \"1\"]\n", "");
    assert!(
        err(&missing).contains("missing control point \"0,1,1\""),
        "{}",
        err(&missing)
    );
    let dup = FINN
        .replace("\"0,1,1\"", "\"0, 1,1\"")
        .replace("\"0,0,2\"", "\"0,1,1\"");
    assert!(
        err(&dup).contains("duplicated multi-index"),
        "{}",
        err(&dup)
    );
    let sum = FINN.replace("\"0,0,2\"", "\"0,0,3\"");
    assert!(
        err(&sum).starts_with("p.toml:10: control_points.\"0,0,3\": multi-index sums to 3"),
        "{}",
        err(&sum)
    );
    let len = FINN.replace("\"0,0,2\"", "\"0,0,0,2\"");
    assert!(err(&len).contains("has 4 parts"), "{}", err(&len));
    let dim = FINN.replace("[\"0\", \"2\", \"1\"]", "[\"0\", \"2\"]");
    assert!(err(&dim).contains("different dimensions"), "{}", err(&dim));
    let num = FINN.replace("\"1\", \"1\", \"1\"", "\"1\", \"x\", \"1\"");
    assert!(
        err(&num).contains("control_points.\"0,1,1\"[1]"),
        "{}",
        err(&num)
    );
    let zero = FINN.replace("\"1\", \"1\", \"1\"", "\"1\", \"1/0\", \"1\"");
    assert!(err(&zero).contains("zero denominator"), "{}", err(&zero));
    let big = FINN.replace("degree = 2", "degree = 201");
    assert!(
        err(&big).contains("above the limit of 200"),
        "{}",
        err(&big)
    );
    let degenerate = FINN.replace(
        "degree = 2",
        "degree = 2\ndomain = [[\"0\",\"0\"],[\"1\",\"1\"],[\"2\",\"2\"]]",
    );
    assert!(
        err(&degenerate).contains("degenerate domain"),
        "{}",
        err(&degenerate)
    );
    let unknown = FINN.replace("degree = 2", "degree = 2\ndegre = 3");
    assert!(
        err(&unknown).contains("degre: unknown key"),
        "{}",
        err(&unknown)
    );
}

#[test]
fn every_kind_round_trips_through_toml_and_json() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/beyond");
    for f in [
        "octant_quartic.toml",
        "pentagon_depth2.toml",
        "functional_linear.toml",
        "tetra_quadratic.toml",
    ] {
        let p = read_any_patch(&dir.join(f)).unwrap();
        let doc = Document::parse_toml("p.toml", &any_patch_to_toml(&p)).unwrap();
        assert_eq!(
            any_patch_from_document(&doc, &doc.root, "").unwrap(),
            p,
            "{f}"
        );
        let doc = Document::parse_json("p.json", &any_patch_to_json(&p).to_string()).unwrap();
        assert_eq!(
            any_patch_from_document(&doc, &doc.root, "").unwrap(),
            p,
            "{f}"
        );
    }
}
