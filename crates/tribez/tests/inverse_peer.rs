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
