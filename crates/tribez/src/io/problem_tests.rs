//! The typed errors: bad input gives the variant with its figures, and `Display` the message.
//! Expected messages are written here by hand from the checks' definitions.

use std::path::Path;

use super::tree::Document;
use super::{ClaimProblem, InputError, Problem, RowsProblem};
use crate::batch::ResultsChecker;
use crate::claims::ClaimFile;
use crate::error::CoreError;

/// The degree-1 triangle used below: its three corners.
const PATCH: &str = r#"
[patch]
degree = 1
[patch.control_points]
"1,0,0" = ["0", "0"]
"0,1,0" = ["1", "0"]
"0,0,1" = ["0", "1"]
"#;

/// The first error of judging the claim file `PATCH` + `claim`.
fn claim_error(claim: &str) -> InputError {
    let text = format!("{PATCH}\n[[claim]]\n{claim}");
    let doc = Document::parse_toml("t.claims.toml", &text).expect("TOML");
    let file = match ClaimFile::from_document(doc, Path::new("t.claims.toml")) {
        Ok(file) => file,
        Err(e) => return e,
    };
    file.judge_all().expect_err("the claim is bad input")
}

#[test]
fn a_corner_out_of_range_names_the_corner_and_the_count() {
    let e =
        claim_error("id = \"c\"\nop = \"edge_curve\"\nfrom = 1\nto = 5\nexpect = [[\"0\", \"0\"]]");
    assert!(matches!(
        *e.problem,
        Problem::Claim(ClaimProblem::NoSuchCorner {
            corner: 5,
            corners: 3
        })
    ));
    assert_eq!(e.key.as_deref(), Some("c.to"));
    assert_eq!(
        e.problem.to_string(),
        "corner 5 does not exist: corners are numbered 1 to 3"
    );
}

#[test]
fn an_unknown_method_lists_the_choices() {
    let e =
        claim_error("id = \"h\"\nop = \"halve\"\nedge = [1, 2]\nmethod = \"bisect\"\nexpect = []");
    let Problem::Claim(ClaimProblem::NotOneOf { text, choices }) = &*e.problem else {
        panic!("{e:?}")
    };
    assert_eq!(text, "bisect");
    assert_eq!(choices.len(), 3);
    assert_eq!(
        e.problem.to_string(),
        "`bisect`: expected \"blossom\", \"add-and-halve\" or \"add-and-halve-bottom-first\""
    );
}

#[test]
fn a_missing_input_and_an_unknown_operation() {
    let e = claim_error("id = \"e\"\nop = \"elevate\"\nby = 0\nexpect = []");
    assert!(matches!(
        *e.problem,
        Problem::Claim(ClaimProblem::ElevateBy {
            most: 199,
            limit: 200
        })
    ));
    let e = claim_error("id = \"x\"\nop = \"no-such-op\"\nexpect = 1");
    let Problem::Claim(ClaimProblem::UnknownOp { op, known }) = &*e.problem else {
        panic!("{e:?}")
    };
    assert_eq!(op, "no-such-op");
    assert!(known.contains(&"eval") && known.contains(&"edge_curve"));
    let e = claim_error("id = \"d\"\nop = \"derivative\"\nat = [\"1\", \"0\", \"0\"]\nexpect = []");
    assert!(matches!(
        *e.problem,
        Problem::Claim(ClaimProblem::NoDirections)
    ));
}

#[test]
fn a_core_error_keeps_its_figures() {
    let e = crate::subdivide::check_edge(2, 1, 4).unwrap_err();
    assert_eq!(
        e,
        CoreError::BadEdge {
            i: 1,
            j: 4,
            corners: 3
        }
    );
    assert_eq!(
        e.to_string(),
        "edge 1,4: an edge is two distinct corners numbered 1 to 3"
    );
    let q = |x: i64| num_rational::BigRational::from_integer(x.into());
    let clockwise = vec![vec![q(0), q(0)], vec![q(0), q(1)], vec![q(1), q(0)]];
    assert_eq!(
        crate::spatch::Polygon::new(clockwise).unwrap_err(),
        CoreError::Clockwise
    );
}

#[test]
fn a_row_with_the_wrong_width() {
    let problem = RowsProblem::ColumnCount {
        found: 4,
        width: 3,
        dim: 3,
    };
    assert_eq!(
        problem.to_string(),
        "4 columns, expected 6 (3 input coordinates, then the 3 claimed coordinates of the point)"
    );
    let e = crate::batch::BatchChecker::new(
        crate::patch::BezierPatch::new(crate::testing::finn()),
        &crate::batch::BatchOptions::default(),
    )
    .expect("checker")
    .check_reader(
        "0.5,0.5,0,1\n".as_bytes(),
        crate::batch::Format::Csv,
        "r.csv",
        "finn",
        &mut |_, _| {},
    )
    .unwrap_err();
    let crate::batch::BatchError::Input(e) = e else {
        panic!("{e:?}")
    };
    assert_eq!(e.line, Some(1));
    assert_eq!(
        *e.problem,
        Problem::Rows(RowsProblem::ColumnCount {
            found: 4,
            width: 3,
            dim: 3
        })
    );
}
