//! The one-call judge and the one patch type. Expected values: fixtures/judge/derive.py (Python
//! fractions), the rational example by hand (in that script's comments), the pentagon from
//! fixtures/beyond/pentagon.claims.toml.

use tribez::{
    Algorithm, Degree, Error, Patch, PatchKind, Precision, Rational, Refusal, SimplexDim,
    Tolerance, judge, judge_algorithm, judge_with, parse_rational,
};

fn q(s: &str) -> Rational {
    parse_rational(s).unwrap()
}

fn qs(xs: &[&str]) -> Vec<Rational> {
    xs.iter().map(|x| q(x)).collect()
}

fn finn() -> Patch {
    let pts = [
        ["0", "0", "0"],
        ["1", "0", "2"],
        ["0", "2", "0"],
        ["0", "1", "0"],
        ["1", "1", "1"],
        ["0", "2", "1"],
    ];
    Patch::bezier(
        SimplexDim(2),
        Degree(2),
        pts.iter().map(|p| qs(p)).collect(),
    )
    .unwrap()
}

fn tol(s: &str) -> Tolerance {
    Tolerance::parse(s).unwrap()
}

const INPUT: [f64; 3] = [0.5, 1.0 / 3.0, 1.0 / 6.0];
/// RN(4/9), RN(5/9), RN(29/36): the nearest floats of the values at the intended input.
const RN_INTENDED: [f64; 3] = [0.4444444444444444, 0.5555555555555556, 0.8055555555555556];
/// The nearest floats of the exact values at the input as seen.
const RN_SEEN: [f64; 3] = [0.4444444444444444, 0.5555555555555555, 0.8055555555555555];

#[test]
fn the_worked_example_evaluates_exactly() {
    let p = finn();
    assert_eq!(p.kind(), PatchKind::Bezier);
    assert_eq!((p.simplex_dim(), p.degree(), p.dimension()), (2, 2, 3));
    assert_eq!(
        p.evaluate(&qs(&["1/2", "1/3", "1/6"])).unwrap(),
        qs(&["4/9", "5/9", "29/36"])
    );
    // not barycentric: an error; the homogeneous form is a separate call
    assert!(p.evaluate(&qs(&["1/2", "1/3", "1/3"])).is_err());
    assert!(p.evaluate_homogeneous(&qs(&["1/2", "1/3", "1/3"])).is_ok());
}

#[test]
fn judged_at_the_input_as_seen_and_as_intended() {
    let p = finn();
    let intended = qs(&["1/2", "1/3", "1/6"]);
    let j = judge_with(
        &p,
        &INPUT,
        &RN_INTENDED,
        &tol("correctly_rounded"),
        Precision::F64,
        Some(&intended),
    )
    .unwrap();
    // the input as seen sums to 1 - 2^-55: its exact values are those of the floats
    assert_eq!(j.input_seen[0], q("1/2"));
    assert_eq!(j.input_seen[1], Rational::from_float(1.0f64 / 3.0).unwrap());
    let seen = [
        "144230468292634090784514614988345/324518553658426726783156020576256",
        "360576170731585217954087282729871/649037107316853453566312041152512",
        "1045670895121597162691330586035997/1298074214633706907132624082305024",
    ];
    let ulps_seen = [
        "2001599834386887/18014398509481984",
        "50039995859672177/72057594037927936",
        "100079991719344355/144115188075855872",
    ];
    let ulps_intended = ["4/9", "2/9", "2/9"];
    let cr = [true, false, false];
    for c in 0..3 {
        let k = &j.coordinates[c];
        assert_eq!(k.exact, q(seen[c]), "coordinate {c}");
        assert_eq!(k.ulps, Some(q(ulps_seen[c])), "coordinate {c}");
        assert_eq!(k.ulps_intended, Some(q(ulps_intended[c])), "coordinate {c}");
        assert_eq!(k.correctly_rounded, cr[c], "coordinate {c}");
        assert_eq!(k.passed, cr[c], "coordinate {c}");
        // non-negative control coordinates and input: the condition number is the value
        assert_eq!(k.condition.as_ref(), Some(&k.exact));
    }
    assert_eq!(j.coordinates[0].exact_intended, Some(q("4/9")));
    assert!(!j.passed);
    assert_eq!(
        j.coordinates[0].bound,
        Some(q(
            "9723079600786696311211505006134509236472370569773713349243024083618792976866357677391746738307855852970343408863592690463039245681580151750543087265624262460985306411221064444987860868267033354926691330054103824046541891524980527281525030889104345040249097965399701750545237202337380743872017437165849143092362012621604470430800477658546185/32841643250247457787048287939504832224857525624036623399292297213079297599038507598789496936786386181353344944786549622664909150138607852819304548861409130872929261316611623275367732513243522960323558090071881483023535554266939502120607728452147447849674996317835141296375673744706107046407227732263370949477989875573948552446000665757831673257382029295616"
        ))
    );
    // under ulps=1 the nearest floats of the intended values pass (0.69 ulp at most), not
    // under ulps=1/2
    assert!(
        judge(&p, &INPUT, &RN_INTENDED, &tol("ulps=1"), Precision::F64)
            .unwrap()
            .passed
    );
    let half = judge(&p, &INPUT, &RN_INTENDED, &tol("ulps=1/2"), Precision::F64).unwrap();
    assert_eq!(
        half.coordinates
            .iter()
            .map(|c| c.passed)
            .collect::<Vec<_>>(),
        [true, false, false]
    );
}

#[test]
fn correctly_rounded_at_the_input_as_seen() {
    let p = finn();
    let j = judge(
        &p,
        &INPUT,
        &RN_SEEN,
        &tol("correctly_rounded"),
        Precision::F64,
    )
    .unwrap();
    assert!(j.passed);
    assert!(j.coordinates.iter().all(|c| c.correctly_rounded));
    // one ULP off (the next float up) in the first coordinate fails correctly_rounded; the
    // nearest float lies 0.11 ulp above the exact value, so the next one up lies 1.11 ulp above
    let mut off = RN_SEEN;
    off[0] = f64::from_bits(off[0].to_bits() + 1);
    let j = judge(&p, &INPUT, &off, &tol("correctly_rounded"), Precision::F64).unwrap();
    assert!(!j.passed);
    assert!(!j.coordinates[0].correctly_rounded);
    assert_eq!(
        j.coordinates[0].ulps,
        Some(q("1") + q("2001599834386887/18014398509481984"))
    );
    assert!(j.coordinates[1].passed && j.coordinates[2].passed);
    // the a-priori bound accepts both (an error of about one ulp is far below γ_6 · cond)
    assert!(
        judge(&p, &INPUT, &off, &tol("bound"), Precision::F64)
            .unwrap()
            .passed
    );
    // and the Bernstein form has a bound too
    assert!(
        judge_algorithm(
            &p,
            Algorithm::Bernstein,
            &INPUT,
            &off,
            &tol("bound"),
            Precision::F64,
            None
        )
        .unwrap()
        .passed
    );
}

#[test]
fn f32_rounds_the_input_and_the_control_points() {
    let p = finn();
    // 1/3 and 1/6 in f32 are other numbers than in f64: the input as seen is theirs
    let j = judge(&p, &INPUT, &[0.0, 0.0, 0.0], &tol("abs=1"), Precision::F32).unwrap();
    assert_eq!(j.input_seen[1], Rational::from_float(1.0f32 / 3.0).unwrap());
    assert!(j.passed);
    assert_eq!(j.precision, Precision::F32);
}

#[test]
fn rational_patch_quarter_circle() {
    let pts = vec![qs(&["1", "0"]), qs(&["1", "1"]), qs(&["0", "1"])];
    let p = Patch::rational(SimplexDim(1), Degree(2), pts, qs(&["1", "1", "2"])).unwrap();
    assert_eq!(p.kind(), PatchKind::Rational);
    assert_eq!(
        p.evaluate(&qs(&["1/2", "1/2"])).unwrap(),
        qs(&["3/5", "4/5"])
    );
    let j = judge(
        &p,
        &[0.5, 0.5],
        &[0.6, 0.8],
        &tol("correctly_rounded"),
        Precision::F64,
    )
    .unwrap();
    assert!(j.passed, "{j}");
    assert_eq!(j.coordinates[1].exact, q("4/5"));
    assert!(
        j.coordinates
            .iter()
            .all(|c| c.bound.is_some() && c.condition.is_some())
    );
    assert_eq!(j.algorithm, "homogeneous de Casteljau");
}

fn fixture(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures")
        .join(name)
}

#[test]
fn s_patch_pentagon() {
    let p = Patch::from_file(fixture("beyond/pentagon_depth2.toml")).unwrap();
    assert_eq!(p.kind(), PatchKind::SPatch);
    assert_eq!(
        p.evaluate(&qs(&["2", "2"])).unwrap(),
        qs(&["63147/128164", "100083/128164", "-15609/64082"])
    );
    let claimed = [0.49270465965481725, 0.7808979120501857, -0.2435785399956306];
    let j = judge(
        &p,
        &[2.0, 2.0],
        &claimed,
        &tol("correctly_rounded"),
        Precision::F64,
    )
    .unwrap();
    assert!(j.passed, "{j}");
    // cond=K is not defined for S-patches (the float coordinates add their own error)
    assert!(matches!(
        judge(&p, &[2.0, 2.0], &claimed, &tol("cond=4"), Precision::F64),
        Err(Error::Refusal(Refusal::Unsupported { .. }))
    ));
    assert!(matches!(
        judge(&p, &[2.0, 2.0], &claimed, &tol("cond"), Precision::F64),
        Err(Error::Refusal(Refusal::Unsupported { .. }))
    ));
}

/// `cond` without K is `cond=(m+1)·n`: 6 for Finn's quadratic triangle. At the corner (0, 1, 0)
/// the value is c_020 = (0, 2, 0), the condition number of the second coordinate |c_020| = 2; a
/// claim 3 ulps above 2 is off by 3·2^-51 = 12ε, within K·ε·2 exactly when K ≥ 6 (by hand).
#[test]
fn cond_without_k_takes_the_degree_constant() {
    let p = finn();
    let y = 2f64.next_up().next_up().next_up();
    let j = judge(
        &p,
        &[0.0, 1.0, 0.0],
        &[0.0, y, 0.0],
        &tol("cond"),
        Precision::F64,
    )
    .unwrap();
    assert!(j.passed, "{j}");
    assert_eq!(j.tolerance, tol("cond=6"));
    let j = judge(
        &p,
        &[0.0, 1.0, 0.0],
        &[0.0, y, 0.0],
        &tol("cond=5"),
        Precision::F64,
    )
    .unwrap();
    assert!(!j.passed, "{j}");
}

#[test]
fn sizes_are_errors_never_panics() {
    let p = finn();
    let r = tol("ulps=1");
    assert!(matches!(
        judge(&p, &[0.5, 0.5], &RN_SEEN, &r, Precision::F64),
        Err(Error::Refusal(Refusal::Size {
            expected: 3,
            found: 2,
            ..
        }))
    ));
    assert!(matches!(
        judge(&p, &INPUT, &[0.5], &r, Precision::F64),
        Err(Error::Refusal(Refusal::Size {
            expected: 3,
            found: 1,
            ..
        }))
    ));
    assert!(judge(&p, &[f64::NAN, 0.5, 0.5], &RN_SEEN, &r, Precision::F64).is_err());
    // a wrong number of control points, or of weights, or ragged points
    let six: Vec<Vec<Rational>> = (0..6).map(|_| qs(&["0", "0"])).collect();
    assert!(matches!(
        Patch::bezier(SimplexDim(2), Degree(3), six.clone()),
        Err(Error::Refusal(Refusal::Size {
            expected: 10,
            found: 6,
            ..
        }))
    ));
    // (m, n) = (1, 5) also has 6 points: the newtypes keep the call unambiguous
    assert_eq!(
        Patch::bezier(SimplexDim(1), Degree(5), six.clone())
            .unwrap()
            .degree(),
        5
    );
    assert!(Patch::bezier(SimplexDim(2), Degree(1_000_000), six.clone()).is_err());
    assert!(Patch::bezier(SimplexDim(0), Degree(1), six.clone()).is_err());
    assert!(Patch::rational(SimplexDim(2), Degree(2), six.clone(), qs(&["1"])).is_err());
    let mut ragged = six;
    ragged[3] = qs(&["1"]);
    assert!(Patch::bezier(SimplexDim(2), Degree(2), ragged).is_err());
    assert!(Patch::bezier(SimplexDim(2), Degree(2), vec![]).is_err());
}

#[test]
fn toml_round_trip_and_serialisation() {
    let p = finn();
    let back = Patch::from_toml(&p.to_toml()).unwrap();
    assert_eq!(back, p);
    let j = judge(
        &p,
        &INPUT,
        &RN_SEEN,
        &tol("correctly_rounded"),
        Precision::F64,
    )
    .unwrap();
    let v = serde_json::to_value(&j).unwrap();
    assert_eq!(v["passed"], true);
    assert_eq!(v["precision"], "f64");
    assert_eq!(v["tolerance"], "correctly_rounded");
    assert_eq!(v["kind"], "bezier");
    assert_eq!(v["input_seen"][0], "1/2");
    assert!(j.to_string().starts_with("passed under correctly_rounded"));
}
