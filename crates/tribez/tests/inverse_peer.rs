//! The Python package `bezier` judged by tribez: fixtures/inverse/peer/ holds bezier's
//! `Curve.intersect` and `Triangle.locate` answers on random inputs (bezier_inverse.py; the
//! seed is in each file's first line). SymPy/mpmath at 50 digits classified every answer
//! independently of tribez (an `erratum` on each claim that misses or adds a solution or is more
//! than 16 ulps off); tribez must agree claim by claim. bezier is not needed to run this test.

use std::path::PathBuf;

use tribez::claims::{ClaimFile, Verdict};

#[test]
fn tribez_agrees_with_sympy_about_bezier() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse/peer");
    let mut counts = [0usize; 2];
    for (name, expected_claims) in [("intersect.claims.toml", 24), ("locate.claims.toml", 24)] {
        let file = ClaimFile::read(&dir.join(name)).unwrap();
        assert_eq!(file.claims.len(), expected_claims, "{name}");
        for j in file.judge_all().unwrap() {
            match (&j.verdict, j.erratum.is_some()) {
                (Verdict::Holds, false) => counts[0] += 1,
                (Verdict::KnownErratum(_), true) => counts[1] += 1,
                (v, _) => panic!(
                    "{name} {}: SymPy and tribez disagree: {v:?} ({:?})",
                    j.id, j.erratum
                ),
            }
        }
    }
    // the run is not vacuous: both verdicts occur
    assert!(counts[0] > 20 && counts[1] > 0, "{counts:?}");
}

/// The same answers of bezier's `Triangle.locate` as a batch of rows (`locate.rows.csv`, written
/// from the claims file by locate_rows.py: row i is claim i, on line i + 3): the batch must fail
/// exactly the rows whose claim SymPy gave an erratum, and for the same reason (an extra pair, or
/// parameters more than 16 ulps off).
#[test]
fn the_locate_batch_fails_exactly_the_rows_sympy_found_wrong() {
    use tribez::batch::{InverseBatchChecker, InverseBatchOptions, InverseKind};
    use tribez::hazmat::io::patch_file::read_any_patch;
    use tribez::{Patch, Precision, ResultsChecker, Tolerance};

    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse/peer");
    let claims = ClaimFile::read(&dir.join("locate.claims.toml")).unwrap();
    let expected: Vec<(usize, &str)> = claims
        .claims
        .iter()
        .enumerate()
        .filter_map(|(i, c)| {
            let e = c.erratum.as_deref()?;
            let kind = if e.starts_with("extra pair") {
                "extra"
            } else {
                assert!(e.contains("ulps from"), "{e}");
                "coordinate"
            };
            Some((i + 3, kind))
        })
        .collect();
    assert_eq!(expected.len(), 5);
    let patch = Patch::from(read_any_patch(&dir.join("triangle.toml")).unwrap());
    let options = InverseBatchOptions {
        kind: InverseKind::Locate,
        tolerance: Tolerance::parse("ulps=16").unwrap(),
        precision: Some(Precision::F64),
        anywhere: false,
    };
    let checker = InverseBatchChecker::new(patch, "triangle.toml", &options).unwrap();
    let report = checker
        .check_file(
            &dir.join("locate.rows.csv"),
            "triangle.toml",
            &mut |_, _| {},
        )
        .unwrap();
    assert_eq!((report.checked, report.passed, report.failed), (24, 19, 5));
    let got: Vec<(usize, &str)> = report
        .failures
        .iter()
        .map(|f| {
            // every failure of one row is of one kind here
            let kinds: Vec<&str> = f.mismatches.iter().map(|m| m.kind).collect();
            assert!(kinds.iter().all(|k| *k == kinds[0]), "{kinds:?}");
            (f.line, kinds[0])
        })
        .collect();
    assert_eq!(got, expected);
    // an extra pair: the point as bezier saw it has no parameters in the closed triangle
    assert!(report.failures[0].exact.is_empty());
    assert_eq!((report.extra, report.missed), (3, 0));
}
