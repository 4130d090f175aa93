//! `intersect`, `locate` and `ray` claims (fixtures/inverse/inverse.claims.toml): expected values
//! from SymPy (fixtures/inverse/derive.py, derive_surfaces.py); the missed root's polynomial
//! 61x^2 − 61x + 1 and its decimal 0.016671377448997771102… from SymPy's factorisation of the
//! resultant of cubic_a and cubic_b (27/4 (2s − 1)(61s^2 − 61s + 1)).

use std::path::PathBuf;

use tribez::claims::{ClaimFile, Verdict};

fn file() -> ClaimFile {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/inverse/inverse.claims.toml");
    ClaimFile::read(&p).unwrap()
}

fn reasons(v: &Verdict) -> Vec<String> {
    match v {
        Verdict::Fails(m) | Verdict::KnownErratum(m) => m
            .iter()
            .map(|m| format!("{}: {}", m.path, m.reason))
            .collect(),
        _ => Vec::new(),
    }
}

#[test]
fn inverse_claims_are_judged_against_the_algebraic_values() {
    let f = file();
    let judged = f.judge_all().unwrap();
    let by = |id: &str| judged.iter().find(|j| j.id == id).unwrap();
    for id in [
        "cubics-correctly-rounded",
        "cubics-count",
        "cubics-four-ulps-allowed",
        "locate-golden",
        "ray-dome",
    ] {
        assert_eq!(
            by(id).verdict,
            Verdict::Holds,
            "{id}: {:?}",
            reasons(&by(id).verdict)
        );
    }
    // the missed intersection is shown exactly: polynomial, interval, decimal
    let missed = reasons(&by("cubics-missed").verdict);
    assert_eq!(missed.len(), 1, "{missed:?}");
    assert!(missed[0].starts_with("solution 1: missed"), "{missed:?}");
    assert!(
        missed[0].contains("root of 61x^2 - 61x + 1 in ("),
        "{missed:?}"
    );
    assert!(missed[0].contains("0.016671377448997771"), "{missed:?}");
    // the extra pair is the fourth claimed one
    let extra = reasons(&by("cubics-extra").verdict);
    assert_eq!(extra.len(), 1, "{extra:?}");
    assert!(extra[0].starts_with("[3]: extra"), "{extra:?}");
    // 3 ulps off: only s of the first claimed pair breaks ulps=2
    let off = reasons(&by("cubics-three-ulps-off").verdict);
    assert_eq!(off.len(), 1, "{off:?}");
    assert!(
        off[0].starts_with("[0][0]: s = 0.01667137744899778"),
        "{off:?}"
    );
    assert!(off[0].contains("ulps=2"), "{off:?}");
    // without precision, decimals are not the irrational parameters; 1/2 is exact
    let exact = reasons(&by("cubics-exact-irrational").verdict);
    assert_eq!(exact.len(), 4, "{exact:?}");
    assert!(exact.iter().all(|r| !r.starts_with("[1]")), "{exact:?}");
}

#[test]
fn bad_inverse_claims_are_located_errors() {
    let dir = tempfile::tempdir().unwrap();
    let fixtures = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse");
    for name in ["cubic_a.toml", "cubic_b.toml", "dome.toml"] {
        std::fs::copy(fixtures.join(name), dir.path().join(name)).unwrap();
    }
    let cases = [
        (
            "patches = [\"a\"]\nexpect = 1",
            "an intersection needs two curves, 1 named",
        ),
        (
            "patches = [\"a\", \"c\"]\nexpect = 1",
            "no patch named `c` under [patches]",
        ),
        (
            "patches = [\"a\", \"b\"]\nexpect = [[\"1\"]]",
            "1 parameters, expected 2 (s, t)",
        ),
        ("patches = [\"a\", \"b\"]", "missing key `expect`"),
        (
            "patches = [\"a\", \"d\"]\nexpect = 0",
            "must be a planar curve",
        ),
        (
            "patches = [\"a\", \"b\"]\nexpect = [[\"1e999\", \"0\"]]\nprecision = \"f64\"",
            "overflows f64",
        ),
    ];
    for (body, words) in cases {
        let text = format!(
            "[patches]\na = \"cubic_a.toml\"\nb = \"cubic_b.toml\"\nd = \"dome.toml\"\n\n[[claim]]\nid = \"x\"\nop = \"intersect\"\n{body}\n"
        );
        let p = dir.path().join("x.claims.toml");
        std::fs::write(&p, text).unwrap();
        let err = ClaimFile::read(&p)
            .and_then(|f| f.judge_all())
            .unwrap_err()
            .to_string();
        assert!(err.contains(words), "{body}: {err}");
        assert!(err.contains("x.claims.toml:"), "{body}: located: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    // a ray with a zero direction
    let p = dir.path().join("r.claims.toml");
    std::fs::write(
        &p,
        "patch = \"dome.toml\"\n[[claim]]\nid = \"r\"\nop = \"ray\"\norigin = [\"0\", \"0\", \"1\"]\ndirection = [\"0\", \"0\", \"0\"]\nexpect = 0\n",
    )
    .unwrap();
    let err = ClaimFile::read(&p)
        .and_then(|f| f.judge_all())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("r.direction: the ray's direction is zero"),
        "{err}"
    );
}

/// `ray` claims in the `height` form (fixtures/inverse/height.claims.toml, values by hand): the
/// vertical line through (x, y) of a functional patch, claimed as (z, s, t).
#[test]
fn height_claims_are_the_data_lookup() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse");
    let f = ClaimFile::read(&dir.join("height.claims.toml")).unwrap();
    let judged = f.judge_all().unwrap();
    assert_eq!(judged.len(), 5);
    for j in &judged {
        if j.id == "height-wrong" {
            let r = reasons(&j.verdict);
            assert!(matches!(j.verdict, Verdict::KnownErratum(_)), "{r:?}");
            assert_eq!(r.len(), 1, "{r:?}");
            assert!(r[0].starts_with("[0][0]: z = 0.625000001"), "{r:?}");
            assert!(r[0].contains("against 5/8"), "{r:?}");
        } else {
            assert_eq!(
                j.verdict,
                Verdict::Holds,
                "{}: {:?}",
                j.id,
                reasons(&j.verdict)
            );
        }
    }
    // `height` with `origin`, or on a patch that is not functional: an error naming the input
    let dir = tempfile::tempdir().unwrap();
    let hill = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse/hill.toml");
    let dome = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/inverse/dome.toml");
    for (patch, extra, says) in [
        (
            &hill,
            "origin = [\"0\", \"0\", \"1\"]\n",
            "instead of `origin`",
        ),
        (&dome, "", "takes a functional patch"),
    ] {
        let text = format!(
            "[patches]\np = {:?}\n\n[[claim]]\nid = \"h\"\nop = \"ray\"\npatch = \"p\"\nheight = [\"0\", \"0\"]\n{extra}expect = []\n",
            patch.display().to_string()
        );
        let path = dir.path().join("h.claims.toml");
        std::fs::write(&path, text).unwrap();
        let e = ClaimFile::read(&path)
            .and_then(|f| f.judge_all())
            .unwrap_err()
            .to_string();
        assert!(e.contains(says), "{e}");
    }
}
