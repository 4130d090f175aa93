//! Parsing each operation (good and bad input), and the issue-10 regressions of the claims:
//! inputs as the float code saw them, homogenised `implicit`, size caps before allocation.
//! Expected values are derived by hand in the comments.

use std::path::Path;

use num_rational::BigRational;

use super::*;
use crate::claims::Verdict;
use crate::io::tree::Document;
use crate::number::parse_rational;

/// Finn's worked example (degree 2): 200:(0,0,0) 110:(1,0,2) 020:(0,2,0) 101:(0,1,0)
/// 011:(1,1,1) 002:(0,2,1).
const FINN: &str = r#"[patch]
degree = 2
[patch.control_points]
"2,0,0" = ["0", "0", "0"]
"1,1,0" = ["1", "0", "2"]
"0,2,0" = ["0", "2", "0"]
"1,0,1" = ["0", "1", "0"]
"0,1,1" = ["1", "1", "1"]
"0,0,2" = ["0", "2", "1"]
"#;

fn q(s: &str) -> BigRational {
    parse_rational(s).unwrap()
}

fn qs(v: &[&str]) -> Vec<BigRational> {
    v.iter().map(|s| q(s)).collect()
}

fn file(text: &str) -> ClaimFile {
    let doc = Document::parse_toml("t.claims.toml", text).expect("valid TOML");
    ClaimFile::from_document(doc, Path::new("t.claims.toml")).expect("a claim file")
}

/// The claim file `head` + one claim `id = "c"` with `body` and `expect = 0`.
fn one(head: &str, body: &str) -> ClaimFile {
    file(&format!(
        "{head}\n[[claim]]\nid = \"c\"\n{body}\nexpect = 0\n"
    ))
}

/// Parse the claim and hand the result to `f`.
fn parsed<R>(head: &str, body: &str, f: impl FnOnce(ClaimOp<'_>) -> R) -> R {
    let cf = one(head, body);
    let inputs = Inputs::new(&cf, &cf.claims[0]).unwrap();
    f(ClaimOp::parse(&inputs).unwrap_or_else(|e| panic!("{e}")))
}

/// The one-line parse error of the claim.
fn parse_error(head: &str, body: &str) -> String {
    let cf = one(head, body);
    let inputs = Inputs::new(&cf, &cf.claims[0]).unwrap();
    match ClaimOp::parse(&inputs) {
        Ok(op) => panic!("parsed: {op:?}"),
        Err(e) => {
            let text = e.to_string();
            assert!(!text.contains('\n'), "one line: {text}");
            assert!(text.starts_with("t.claims.toml:"), "names the file: {text}");
            text
        }
    }
}

fn assert_error(head: &str, body: &str, fragments: &[&str]) {
    let e = parse_error(head, body);
    for f in fragments {
        assert!(e.contains(f), "{f:?} not in {e:?}");
    }
}

#[test]
fn op_names_keys_and_lookup_agree() {
    for op in OpName::ALL {
        assert_eq!(OpName::from_name(op.name()), Some(*op));
        assert!(!op.keys().is_empty());
    }
    assert_eq!(OpName::ALL.len(), 25);
    assert_eq!(OpName::from_name("evaluate"), None);
    assert_error(
        FINN,
        "op = \"evaluate\"",
        &["c.op", "unknown operation `evaluate`", "eval, symbolic"],
    );
    // a typo of a key is an error naming it, never ignored
    assert_error(
        FINN,
        "op = \"eval\"\nat = [\"1\", \"0\", \"0\"]\nalgoritm = \"bernstein\"",
        &["c.algoritm"],
    );
}

#[test]
fn eval_parses_points_and_algorithm() {
    parsed(
        FINN,
        "op = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/6\"]\nalgorithm = \"bernstein\"",
        |op| {
            let ClaimOp::Point(PointOp::Eval {
                point, algorithm, ..
            }) = op
            else {
                panic!()
            };
            assert_eq!(point.at, qs(&["1/2", "1/3", "1/6"]));
            assert_eq!(point.cartesian, None);
            assert_eq!(algorithm, crate::exact::Algorithm::Bernstein);
        },
    );
    // the reference triangle (1,0), (0,1), (0,0): (x, y) ↦ (u, v, w) = (x, y, 1 − x − y)
    parsed(
        FINN,
        "op = \"eval\"\ncartesian = [\"1/4\", \"1/2\"]",
        |op| {
            let ClaimOp::Point(PointOp::Eval { point, .. }) = op else {
                panic!()
            };
            assert_eq!(point.at, qs(&["1/4", "1/2", "1/4"]));
            assert_eq!(point.cartesian, Some(qs(&["1/4", "1/2"])));
        },
    );
    assert_error(
        FINN,
        "op = \"eval\"\nat = [\"1/2\", \"1/3\", \"1/3\"]",
        &["c.at"],
    );
    assert_error(FINN, "op = \"eval\"", &["c.at", "give exactly one of `at`"]);
    assert_error(
        FINN,
        "op = \"eval\"\nat = [\"1\", \"0\", \"0\"]\nalgorithm = \"horner\"",
        &["c.algorithm", "unknown algorithm `horner`"],
    );
    assert_error(
        FINN,
        "op = \"eval\"\nat = [\"1\", \"0\", \"x\"]",
        &["c.at[2]"],
    );
    // with `precision`, a point need not sum to one (the homogeneous form), but has m + 1 parts
    parsed(
        FINN,
        "op = \"eval\"\nat = [\"0.1\", \"0.2\", \"0.7\"]\nprecision = \"f64\"",
        |op| {
            assert!(op.is_eval());
        },
    );
    assert_error(
        FINN,
        "op = \"eval\"\nat = [\"1\", \"0\"]\nprecision = \"f64\"",
        &["c.at", "2 coordinates, expected 3"],
    );
}

#[test]
fn derivative_and_tangent_parse() {
    parsed(
        FINN,
        "op = \"derivative\"\nat = [\"1\", \"0\", \"0\"]\ndirs = [[\"-1\", \"1\", \"0\"]]\nvectors = [[\"0\", \"1\"]]",
        |op| {
            let ClaimOp::Point(PointOp::Derivative { dirs, vectors, .. }) = op else {
                panic!()
            };
            assert_eq!(dirs, vec![qs(&["-1", "1", "0"])]);
            assert_eq!(vectors, vec![qs(&["0", "1"])]);
        },
    );
    assert_error(
        FINN,
        "op = \"derivative\"\nat = [\"1\", \"0\", \"0\"]",
        &["c.dirs", "at least one direction"],
    );
    assert_error(
        FINN,
        "op = \"derivative\"\nat = [\"1\", \"0\", \"0\"]\ndirs = [[\"1\", \"1\", \"0\"]]",
        &["c.dirs", "direction 1"],
    );
    // order 3 of a degree-2 patch
    assert_error(
        FINN,
        "op = \"derivative\"\nat = [\"1\", \"0\", \"0\"]\ndirs = [[\"-1\", \"1\", \"0\"], [\"-1\", \"1\", \"0\"], [\"-1\", \"1\", \"0\"]]",
        &["c.dirs"],
    );
    parsed(
        FINN,
        "op = \"tangent\"\nat = [\"1\", \"0\", \"0\"]\npart = \"normal\"",
        |op| {
            let ClaimOp::Point(PointOp::Tangent { part, .. }) = op else {
                panic!()
            };
            assert_eq!(part.as_deref(), Some("normal"));
        },
    );
    assert_error(
        FINN,
        "op = \"tangent\"\npart = \"normal\"",
        &["c.at", "give exactly one"],
    );
}

#[test]
fn coordinates_parse() {
    parsed(
        "",
        "op = \"barycentric\"\ndomain = [[\"0\", \"0\"], [\"2\", \"0\"], [\"0\", \"2\"]]\npoint = [\"1\", \"1\"]",
        |op| {
            let ClaimOp::Point(PointOp::Coordinates {
                domain,
                x,
                direction,
            }) = op
            else {
                panic!()
            };
            assert_eq!((domain.m(), x, direction), (2, qs(&["1", "1"]), false));
        },
    );
    parsed(
        "",
        "op = \"direction\"\ndomain = [[\"0\", \"0\"], [\"2\", \"0\"], [\"0\", \"2\"]]\nvector = [\"1\", \"1\"]",
        |op| {
            let ClaimOp::Point(PointOp::Coordinates { direction, .. }) = op else {
                panic!()
            };
            assert!(direction);
        },
    );
    assert_error(
        "",
        "op = \"barycentric\"\ndomain = [[\"0\", \"0\"], [\"2\", \"0\"], [\"0\", \"2\"]]",
        &["c.point", "missing input `point`"],
    );
    assert_error(
        "",
        "op = \"barycentric\"\npoint = [\"1\", \"1\"]",
        &["c.domain", "missing input `domain`"],
    );
    assert_error(
        "",
        "op = \"barycentric\"\ndomain = [[\"0\", \"0\"], [\"2\", \"0\"], [\"4\", \"0\"]]\npoint = [\"1\", \"1\"]",
        &["c.domain"],
    );
}

#[test]
fn forms_parse() {
    parsed(
        FINN,
        "op = \"symbolic\"\nvariables = \"cartesian\"\nnames = [\"s\", \"t\"]\ncomponent = 2",
        |op| {
            let ClaimOp::Form(Form::Symbolic {
                cartesian,
                names,
                component,
                ..
            }) = op
            else {
                panic!()
            };
            assert_eq!(
                (cartesian, names, component),
                (true, vec!["s".to_string(), "t".into()], Some(2))
            );
        },
    );
    assert_error(
        FINN,
        "op = \"symbolic\"\ncomponent = 3",
        &["c.component", "component 3 does not exist"],
    );
    assert_error(
        FINN,
        "op = \"symbolic\"\nvariables = \"polar\"",
        &["c.variables", "`polar`"],
    );
    assert_error(
        FINN,
        "op = \"symbolic\"\nnames = [\"a\", \"b\"]",
        &["c.names", "2 names given, 3 variables needed"],
    );
    parsed(
        "",
        "op = \"basis_sum\"\ndegree = 3\nsimplex = 1\nat = [\"1/3\", \"2/3\"]",
        |op| {
            let ClaimOp::Form(Form::Basis(b)) = op else {
                panic!()
            };
            assert!(b.sum && b.m == 1 && b.degree == 3 && !b.cartesian);
            assert_eq!(b.at, Some(qs(&["1/3", "2/3"])));
        },
    );
    assert_error(
        "",
        "op = \"basis\"",
        &["c.degree", "missing input `degree`"],
    );
    assert_error(
        "",
        "op = \"basis\"\ndegree = 2\nsimplex = 17",
        &["c.degree", "simplex dimension 1 to 16"],
    );
    assert_error(
        "",
        "op = \"basis\"\ndegree = 201",
        &["c.degree", "degree at most 200"],
    );
    assert_error(
        "",
        "op = \"basis\"\ndegree = -1",
        &["c.degree", "not a non-negative integer"],
    );
    assert_error(
        "",
        "op = \"basis\"\ndegree = 2\nat = [\"1\", \"0\"]",
        &["c.at", "2 coordinates, expected 3"],
    );
    // C(216, 16) control points: refused before the simplex is enumerated
    assert_error(
        "",
        "op = \"basis\"\ndegree = 200\nsimplex = 16",
        &["c.degree", "above the limit of 250000"],
    );
    parsed(
        FINN,
        "op = \"implicit\"\nequation = \"x^2 - y\"\ncoordinates = [\"x\", \"y\", \"z\"]",
        |op| {
            let ClaimOp::Form(Form::Implicit {
                equation, names, ..
            }) = op
            else {
                panic!()
            };
            assert_eq!(equation.to_text(&["x", "y", "z"]), "x^2 - y");
            assert_eq!(names, vec!["u", "v", "w"]);
        },
    );
    assert_error(
        FINN,
        "op = \"implicit\"",
        &["c.equation", "missing input `equation`"],
    );
    assert_error(
        FINN,
        "op = \"implicit\"\nequation = \"x + q\"",
        &["c.equation", "`x + q`"],
    );
    assert_error(
        FINN,
        "op = \"implicit\"\nequation = \"x\"\ncoordinates = [\"x\", \"y\"]",
        &[
            "c.coordinates",
            "2 names given, the points have 3 coordinates",
        ],
    );
    parsed(FINN, "op = \"abscissae\"", |op| {
        assert!(matches!(op, ClaimOp::Form(Form::Abscissae { .. })))
    });
    assert_error(
        FINN,
        "op = \"graph\"",
        &["c.patch", "needs a functional patch"],
    );
    parsed(
        "",
        "op = \"ordinates\"\ndomain = [[\"0\", \"0\"], [\"1\", \"0\"], [\"0\", \"1\"]]\ndegree = 2\nfunction = \"x*y\"",
        |op| {
            let ClaimOp::Form(Form::Ordinates {
                degree, function, ..
            }) = op
            else {
                panic!()
            };
            assert_eq!(
                (degree, function.to_text(&["x", "y"])),
                (2, "x*y".to_string())
            );
        },
    );
    assert_error(
        "",
        "op = \"ordinates\"\ndomain = [[\"0\", \"0\"], [\"1\", \"0\"], [\"0\", \"1\"]]\ndegree = 201\nfunction = \"x\"",
        &["c.degree", "above the limit of 200"],
    );
}

#[test]
fn constructions_parse() {
    parsed(
        FINN,
        "op = \"blossom\"\nargs = [[\"1\", \"0\", \"0\"], [\"0\", \"1\", \"0\"]]",
        |op| {
            let ClaimOp::Construction(Construction::Blossom { args, .. }) = op else {
                panic!()
            };
            assert_eq!(args.len(), 2);
        },
    );
    assert_error(
        FINN,
        "op = \"blossom\"\nargs = [[\"1\", \"1\", \"0\"]]",
        &["c.args[0]"],
    );
    parsed(
        FINN,
        "op = \"subpatch\"\nvertices = [[\"1\", \"0\", \"0\"], [\"0\", \"1\", \"0\"], [\"1/3\", \"1/3\", \"1/3\"]]",
        |op| {
            let ClaimOp::Construction(Construction::Subpatch { vertices, .. }) = op else {
                panic!()
            };
            assert_eq!(vertices[2], qs(&["1/3", "1/3", "1/3"]));
        },
    );
    assert_error(
        FINN,
        "op = \"subpatch\"",
        &["c.vertices", "missing input `vertices`"],
    );
    parsed(FINN, "op = \"subdivide\"\nmidpoints = true", |op| {
        assert!(matches!(
            op,
            ClaimOp::Construction(Construction::Subdivide {
                mode: SubdivideMode::Midpoints,
                ..
            })
        ));
    });
    parsed(
        FINN,
        "op = \"subdivide\"\nat = [\"1/3\", \"1/3\", \"1/3\"]",
        |op| {
            let ClaimOp::Construction(Construction::Subdivide {
                mode: SubdivideMode::At(t),
                ..
            }) = op
            else {
                panic!()
            };
            assert_eq!(t, qs(&["1/3", "1/3", "1/3"]));
        },
    );
    assert_error(
        FINN,
        "op = \"subdivide\"\nmidpoints = \"yes\"",
        &["c.midpoints", "expected true or false"],
    );
    assert_error(
        FINN,
        "op = \"subdivide\"\nmidpoints = true\nat = [\"1/3\", \"1/3\", \"1/3\"]",
        &["c.at", "give exactly one"],
    );
    parsed(
        FINN,
        "op = \"halve\"\nedge = [3, 1]\nmethod = \"add-and-halve-bottom-first\"",
        |op| {
            let ClaimOp::Construction(Construction::Halve { edge, method, .. }) = op else {
                panic!()
            };
            assert_eq!(edge, (2, 0));
            assert_eq!(
                method,
                HalveMethod::AddAndHalve(crate::subdivide::HalvingOrder::BottomFirst)
            );
        },
    );
    assert_error(FINN, "op = \"halve\"\nedge = [1, 1]", &["c.edge"]);
    assert_error(
        FINN,
        "op = \"halve\"\nedge = [1, 2, 3]",
        &["c.edge", "two corner numbers"],
    );
    assert_error(
        FINN,
        "op = \"halve\"\nedge = [1, 2]\nmethod = \"bisect\"",
        &["c.method", "`bisect`"],
    );
    parsed(FINN, "op = \"elevate\"\nby = 3", |op| {
        let ClaimOp::Construction(Construction::Elevate { by, .. }) = op else {
            panic!()
        };
        assert_eq!(by, 3);
    });
    assert_error(
        FINN,
        "op = \"elevate\"\nby = 0",
        &["c.by", "elevate by 1 to 198", "capped at 200"],
    );
    // degree + by wrapped before the sum was checked (an abort): now the limit
    assert_error(
        FINN,
        "op = \"elevate\"\nby = \"18446744073709551615\"",
        &["c.by", "capped at 200"],
    );
    parsed(
        "",
        "op = \"matrix\"\nkind = \"halve\"\ndegree = 2\nsimplex = 3\nedge = [2, 4]\npiece = 2",
        |op| {
            let ClaimOp::Construction(Construction::Matrix { degree, kind }) = op else {
                panic!()
            };
            assert_eq!(degree, 2);
            assert_eq!(
                kind,
                MatrixKind::Halve {
                    m: 3,
                    edge: (1, 3),
                    piece: 2
                }
            );
        },
    );
    assert_error(
        "",
        "op = \"matrix\"\nkind = \"halve\"",
        &["c.degree", "missing input `degree`"],
    );
    assert_error(
        "",
        "op = \"matrix\"\ndegree = 2\nkind = \"split\"",
        &["c.kind"],
    );
    assert_error(
        "",
        "op = \"matrix\"\ndegree = 2\nkind = \"halve\"\npiece = 3",
        &["c.piece", "1 or 2"],
    );
    assert_error(
        "",
        "op = \"matrix\"\ndegree = 2\nkind = \"subpatch\"\nvertices = [[\"1\"]]",
        &["c.vertices", "give m+1 vertices"],
    );
    // n + m wrapped and bypassed the row limit: now refused first; C(44 + 2, 2) = 1035 > 1000
    assert_error(
        "",
        "op = \"matrix\"\nkind = \"halve\"\ndegree = \"18446744073709551615\"",
        &["c.degree", "at most 1000 rows"],
    );
    assert_error(
        "",
        "op = \"matrix\"\nkind = \"halve\"\ndegree = 44",
        &["c.degree", "at most 1000 rows"],
    );
    parsed("", "op = \"matrix\"\nkind = \"halve\"\ndegree = 43", |_| ());
    parsed(FINN, "op = \"edge_curve\"\nfrom = 3\nto = 2", |op| {
        let ClaimOp::Construction(Construction::EdgeCurve { from, to, .. }) = op else {
            panic!()
        };
        assert_eq!((from, to), (2, 1));
    });
    assert_error(
        FINN,
        "op = \"edge_curve\"\nfrom = 4\nto = 1",
        &["c.from", "corner 4 does not exist"],
    );
    assert_error(
        FINN,
        "op = \"edge_curve\"\nfrom = 1\nto = 1",
        &["c.to", "different corners"],
    );
    assert_error(
        FINN,
        "op = \"edge_curve\"\nfrom = 1",
        &["c.to", "missing input `to`"],
    );
}

const PAIR: &str = r#"[patches.a]
degree = 0
domain = [["0", "0"], ["1", "0"], ["0", "1"]]
[patches.a.control_points]
"0,0,0" = ["2", "-1", "5"]
[patches.b]
degree = 0
domain = [["0", "0"], ["1", "0"], ["0", "-1"]]
[patches.b.control_points]
"0,0,0" = ["2", "-1", "5"]
"#;

#[test]
fn join_parses_and_decides_degree_zero() {
    parsed(
        PAIR,
        "op = \"join\"\npatches = [\"a\", \"b\"]\npart = \"c1\"",
        |op| {
            let ClaimOp::Join(j) = op else { panic!() };
            assert_eq!(j.part.as_deref(), Some("c1"));
        },
    );
    assert_error(
        PAIR,
        "op = \"join\"\npatches = [\"a\"]",
        &["c.patches", "two patches, 1 named"],
    );
    assert_error(
        PAIR,
        "op = \"join\"\npatches = [\"a\", \"z\"]",
        &["c.patches", "no patch named `z`"],
    );
    assert_error(
        PAIR,
        "op = \"join\"",
        &["c.patches", "missing input `patches`"],
    );
    // two equal constants: C^r for every r, no tangent plane (crate::join module doc)
    let cf = file(&format!(
        "{PAIR}\n[[claim]]\nid = \"c1\"\nop = \"join\"\npatches = [\"a\", \"b\"]\npart = \"c1\"\nexpect = true\n[[claim]]\nid = \"g1\"\nop = \"join\"\npatches = [\"a\", \"b\"]\npart = \"g1\"\nexpect = false\n"
    ));
    for c in &cf.claims {
        assert_eq!(cf.judge(c).unwrap().verdict, Verdict::Holds, "{}", c.id);
    }
}

#[test]
fn implicit_homogenises_a_polynomial_patch() {
    // the flat triangle (0,0,1), (1,0,2), (0,1,1) lies on z = x + 1: X = v, Z = u + 2v + w,
    // W = u + v + w, so W (z − x − 1)(X/W) = Z − X − W = 0 (not u + v + w − 1)
    let flat = "[patch]\ndegree = 1\n[patch.control_points]\n\"1,0,0\" = [\"0\", \"0\", \"1\"]\n\"0,1,0\" = [\"1\", \"0\", \"2\"]\n\"0,0,1\" = [\"0\", \"1\", \"1\"]\n";
    let cf = file(&format!(
        "{flat}\n[[claim]]\nid = \"on\"\nop = \"implicit\"\nequation = \"z - x - 1\"\nexpect = \"0\"\n[[claim]]\nid = \"sq\"\nop = \"implicit\"\nequation = \"x^2 - y\"\nexpect = \"v^2 - uw - vw - w^2\"\n"
    ));
    for c in &cf.claims {
        assert_eq!(cf.judge(c).unwrap().verdict, Verdict::Holds, "{}", c.id);
    }
}

/// The control point 1/5 as the float code saw it, RN(1/5), copied by every construction:
/// with `precision` and `ulps=0` the copy holds (it failed: the exact value was computed from
/// the text 1/5, which RN(1/5) is not).
#[test]
fn every_op_computes_from_the_inputs_as_seen() {
    let fifth = "[patch]\ndegree = 1\n[patch.control_points]\n\"1,0,0\" = [\"0.2\"]\n\"0,1,0\" = [\"0.6\"]\n\"0,0,1\" = [\"1\"]\n";
    let claims = [
        // the edge from corner 1 to corner 2: the two control points, copied
        "op = \"edge_curve\"\nfrom = 1\nto = 2\nexpect = [[\"0.2\"], [\"0.6\"]]",
        // the subpatch over the parent's own corners: the net itself
        "op = \"subpatch\"\nvertices = [[\"1\", \"0\", \"0\"], [\"0\", \"1\", \"0\"], [\"0\", \"0\", \"1\"]]\nexpect = { \"1,0,0\" = [\"0.2\"], \"0,1,0\" = [\"0.6\"], \"0,0,1\" = [\"1\"] }",
        // the symbolic form: 0.2 u + 0.6 v + w, with RN(1/5) = 3602879701896397/2^54 and
        // RN(3/5) = 5404319552844595/2^53 (the text of the claimed polynomial is exact)
        "op = \"symbolic\"\nexpect = [\"3602879701896397/18014398509481984 u + 5404319552844595/9007199254740992 v + w\"]",
        // the blossom at the corner e_1: c_100
        "op = \"blossom\"\nargs = [[\"1\", \"0\", \"0\"]]\nexpect = [\"0.2\"]",
        // the value at corner 1 (eval keeps its own float view)
        "op = \"eval\"\nat = [\"1\", \"0\", \"0\"]\nexpect = [\"0.2\"]",
    ];
    let mut text = fifth.to_string();
    for (k, c) in claims.iter().enumerate() {
        text += &format!(
            "\n[[claim]]\nid = \"c{k}\"\nprecision = \"f64\"\ntolerance = \"ulps=0\"\n{c}\n"
        );
    }
    let cf = file(&text);
    for c in &cf.claims {
        let j = cf.judge(c).unwrap();
        assert_eq!(j.verdict, Verdict::Holds, "{}: {:?}", c.id, j.verdict);
    }
    // and without `precision` the same claims compare with the exact text (1/5 ≠ RN(1/5))
    let exact = text.replace("precision = \"f64\"\ntolerance = \"ulps=0\"\n", "");
    let cf = file(&exact);
    assert!(matches!(
        cf.judge(&cf.claims[0]).unwrap().verdict,
        Verdict::Holds
    ));
}

/// Rounding that overflows the precision is a located error.
#[test]
fn inputs_that_overflow_the_precision_are_errors() {
    let big =
        "[patch]\ndegree = 1\n[patch.control_points]\n\"1,0\" = [\"1e400\"]\n\"0,1\" = [\"0\"]\n";
    let cf = file(&format!(
        "{big}\n[[claim]]\nid = \"c\"\nop = \"edge_curve\"\nfrom = 1\nto = 2\nprecision = \"f64\"\nexpect = [[\"0\"], [\"0\"]]\n"
    ));
    let e = cf.judge(&cf.claims[0]).expect_err("an error").to_string();
    assert!(e.contains("c.patch") && e.contains("overflows f64"), "{e}");
}

/// The rational subpatch carries its place in the parent, as the polynomial one's file does.
#[test]
fn rational_subpatch_value_has_domain_in_parent() {
    // weights 1, 2, 3 on the corners; the subpatch over the parent's corners in reverse order
    // is the same net reversed: points c_001, c_010, c_100 and weights 3, 2, 1
    let r = "[patch]\ndegree = 1\n[patch.control_points]\n\"1,0,0\" = [\"1\", \"0\"]\n\"0,1,0\" = [\"0\", \"1\"]\n\"0,0,1\" = [\"0\", \"0\"]\n[patch.weights]\n\"1,0,0\" = 1\n\"0,1,0\" = 2\n\"0,0,1\" = 3\n";
    let cf = file(&format!(
        "{r}\n[[claim]]\nid = \"c\"\nop = \"subpatch\"\nvertices = [[\"0\", \"0\", \"1\"], [\"0\", \"1\", \"0\"], [\"1\", \"0\", \"0\"]]\nexpect = {{ control_points = {{ \"1,0,0\" = [\"0\", \"0\"], \"0,1,0\" = [\"0\", \"1\"], \"0,0,1\" = [\"1\", \"0\"] }}, weights = {{ \"1,0,0\" = 3, \"0,1,0\" = 2, \"0,0,1\" = 1 }}, domain_in_parent = [[\"0\", \"0\", \"1\"], [\"0\", \"1\", \"0\"], [\"1\", \"0\", \"0\"]] }}\n"
    ));
    let j = cf.judge(&cf.claims[0]).unwrap();
    assert_eq!(j.verdict, Verdict::Holds, "{}", j.exact.to_text());
}
