//! Tests of fits, with independent expected values: SymPy's exact solution of the normal
//! equations (fixtures/fit/small/derive.py, which derives the C1 conditions from gradients
//! rather than the μ rule), polynomials reproduced (checked by evaluating the polynomial itself),
//! hand derivations.

use std::path::PathBuf;

use num_rational::BigRational;
use num_traits::{One, Zero};

use super::*;
use crate::mesh::{Mesh, OrdinateId};
use crate::number::parse_rational;

fn q(s: &str) -> BigRational {
    parse_rational(s).unwrap()
}

fn v(x: &str, y: &str) -> [BigRational; 2] {
    [q(x), q(y)]
}

fn fixtures() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fixtures/fit")
}

/// The square [0, 2]² cut by its diagonals (as in fixtures/fit/small).
fn diamond(n: usize) -> Mesh {
    Mesh::new(
        vec![
            v("0", "0"),
            v("2", "0"),
            v("2", "2"),
            v("0", "2"),
            v("1", "1"),
        ],
        vec![[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
        n,
    )
    .unwrap()
}

/// An irregular mesh of 6 triangles around two interior vertices, with a non-convex
/// quadrilateral across one interior edge (so some μ has a negative entry besides μ_c).
fn irregular(n: usize) -> Mesh {
    Mesh::new(
        vec![
            v("0", "0"),
            v("3", "0"),
            v("4", "2"),
            v("2", "4"),
            v("-1", "3"),
            v("1", "1"),
            v("5/2", "3/2"),
        ],
        vec![
            [0, 1, 5],
            [1, 6, 5],
            [1, 2, 6],
            [2, 3, 6],
            [3, 5, 6],
            [3, 4, 5],
            [4, 0, 5],
        ],
        n,
    )
    .unwrap()
}

fn point(line: usize, x: BigRational, y: BigRational, value: BigRational) -> DataPoint {
    DataPoint { line, x, y, value }
}

/// Points `(x, y)` of the mesh's triangles: for each triangle, the points with barycentric
/// coordinates `(i, j, k)/m`, `i + j + k = m`, slightly pulled towards the centroid by a
/// rational factor so they are not the Bézier abscissae.
fn sample_points(mesh: &Mesh, m: u32) -> Vec<[BigRational; 2]> {
    let mut out = Vec::new();
    let third = q("1/3");
    let pull = q("1/7");
    for tri in mesh.triangles() {
        let p = tri.map(|i| mesh.vertices()[i].clone());
        for i in 0..=m {
            for j in 0..=m - i {
                let k = m - i - j;
                let mut l = [i, j, k].map(|a| BigRational::new(a.into(), m.into()));
                for c in l.iter_mut() {
                    *c = &*c * (BigRational::one() - &pull) + &third * &pull;
                }
                let x = &l[0] * &p[0][0] + &l[1] * &p[1][0] + &l[2] * &p[2][0];
                let y = &l[0] * &p[0][1] + &l[1] * &p[1][1] + &l[2] * &p[2][1];
                out.push([x, y]);
            }
        }
    }
    out
}

fn poly(x: &BigRational, y: &BigRational, n: usize) -> BigRational {
    // A polynomial of degree exactly n (n ≥ 1) with every kind of term.
    let mut s = q("7/5") - x * q("2") + y * q("1/3");
    for d in 2..=n {
        let e = d as i32;
        s += x.pow(e) * q("1/4") - y.pow(e - 1) * x * q("3/2") + y.pow(e) * q("-2/7");
    }
    s
}

#[test]
fn sympy_small_fits() {
    let dir = fixtures().join("small");
    let text = std::fs::read_to_string(dir.join("expected.json")).unwrap();
    let expected: serde_json::Value = serde_json::from_str(&text).unwrap();
    let data = read_data(&dir.join("data.csv")).unwrap();
    assert_eq!(data.len(), 49);
    let cases = expected["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 4);
    for case in cases {
        let n = case["degree"].as_u64().unwrap() as usize;
        let smoothness: Smoothness = case["smoothness"].as_str().unwrap().parse().unwrap();
        let options = FitOptions {
            degree: Some(n),
            smoothness,
            regularize: false,
        };
        let f = fit(&diamond(1), &data, "data.csv", &options).unwrap();
        let want: Vec<BigRational> = case["ordinates"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| q(s.as_str().unwrap()))
            .collect();
        let got: Vec<BigRational> = f
            .mesh
            .ordinates()
            .iter()
            .map(|o| o.clone().unwrap())
            .collect();
        assert_eq!(got, want, "degree {n} {smoothness}");
        assert_eq!(
            f.rss,
            q(case["rss"].as_str().unwrap()),
            "degree {n} {smoothness}"
        );
    }
}

#[test]
fn polynomials_are_reproduced_exactly() {
    for n in 1..=4 {
        for (name, mesh) in [("diamond", diamond(n)), ("irregular", irregular(n))] {
            let pts = sample_points(&mesh, n as u32 + 1);
            let data: Vec<DataPoint> = pts
                .iter()
                .enumerate()
                .map(|(i, p)| point(i + 1, p[0].clone(), p[1].clone(), poly(&p[0], &p[1], n)))
                .collect();
            for smoothness in [Smoothness::C0, Smoothness::C1] {
                let options = FitOptions {
                    smoothness,
                    ..FitOptions::default()
                };
                let f = fit(&mesh, &data, "d", &options).unwrap();
                assert!(f.rss.is_zero(), "{name} n={n} {smoothness}");
                assert!(f.max_residual.as_ref().unwrap().0.is_zero());
                // The fitted mesh is the polynomial: compare with the polynomial itself at
                // other points (every piece has degree n; (n+2)-point lattices pin it down).
                for p in sample_points(&mesh, n as u32 + 2) {
                    for (_, value) in f.mesh.lookup(&p).unwrap() {
                        assert_eq!(value, poly(&p[0], &p[1], n), "{name} n={n} at {p:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn linear_data_give_the_values_at_the_abscissae() {
    // docs/theory.md §13: a linear function has ordinates ℓ(ξ_α) (linear precision).
    let mesh = irregular(3);
    let l = |x: &BigRational, y: &BigRational| q("5/3") + x * q("-1/2") + y * q("4");
    let data: Vec<DataPoint> = sample_points(&mesh, 3)
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let value = l(&p[0], &p[1]);
            point(i + 1, p[0].clone(), p[1].clone(), value)
        })
        .collect();
    let f = fit(&mesh, &data, "d", &FitOptions::default()).unwrap();
    for (g, o) in f.mesh.ordinates().iter().enumerate() {
        let xi = mesh.abscissa(g);
        assert_eq!(
            o.as_ref().unwrap(),
            &l(&xi[0], &xi[1]),
            "{}",
            mesh.ordinate_id(g)
        );
    }
}

/// The gradient of triangle `t`'s piece at the Cartesian point `p`, from the patch's own
/// directional derivatives along the barycentric directions of the unit vectors.
fn gradient(mesh: &Mesh, t: usize, p: &[BigRational; 2]) -> [BigRational; 2] {
    let patch = mesh.triangle_patch(t).unwrap();
    let tri = mesh.triangles()[t].map(|i| mesh.vertices()[i].clone());
    let bary = |x: &[BigRational; 2]| crate::mesh::barycentric([&tri[0], &tri[1], &tri[2]], x);
    let at = bary(p);
    let c = patch.constructions().unwrap();
    let mut out = [BigRational::zero(), BigRational::zero()];
    for (k, e) in [v("1", "0"), v("0", "1")].iter().enumerate() {
        let moved = [&p[0] + &e[0], &p[1] + &e[1]];
        let b1 = bary(&moved);
        let dir: Vec<BigRational> = (0..3).map(|i| &b1[i] - &at[i]).collect();
        out[k] = c.derivative(&at, &[&dir]).unwrap()[0].clone();
    }
    out
}

#[test]
fn c1_fits_are_c1_across_every_interior_edge() {
    for n in 2..=4 {
        for mesh in [diamond(n), irregular(n)] {
            // Data that no polynomial fits: values of a rational function of x and y.
            let data: Vec<DataPoint> = sample_points(&mesh, n as u32 + 2)
                .into_iter()
                .enumerate()
                .map(|(i, p)| {
                    let value = BigRational::one() / (BigRational::one() + &p[0] * &p[0] + &p[1]);
                    point(i + 1, p[0].clone(), p[1].clone(), value)
                })
                .collect();
            let options = FitOptions {
                smoothness: Smoothness::C1,
                regularize: true,
                ..FitOptions::default()
            };
            let f = fit(&mesh, &data, "d", &options).unwrap();
            assert!(!f.rss.is_zero());
            let x: Vec<BigRational> = f
                .mesh
                .ordinates()
                .iter()
                .map(|o| o.clone().unwrap())
                .collect();
            let edges = interior_edges(&mesh);
            assert!(!edges.is_empty());
            // The μ rule holds exactly, row by row.
            for row in c1_constraints(&mesh) {
                let s: BigRational = row.iter().map(|(g, c)| c * &x[*g]).sum();
                assert!(s.is_zero());
            }
            // Independently: the gradients of both pieces agree at n points of every interior
            // edge (the gradient along an edge is a polynomial of degree n − 1).
            for e in &edges {
                let (pa, pb) = (&mesh.vertices()[e.a], &mesh.vertices()[e.b]);
                for s in 0..n {
                    let t = BigRational::new((2 * s + 1).into(), (2 * n).into());
                    let p = [
                        &pa[0] + (&pb[0] - &pa[0]) * &t,
                        &pa[1] + (&pb[1] - &pa[1]) * &t,
                    ];
                    assert_eq!(
                        gradient(&f.mesh, e.t, &p),
                        gradient(&f.mesh, e.u, &p),
                        "edge {}–{} n={n}",
                        e.a,
                        e.b
                    );
                }
            }
            // And the C0 fit of the same data is not C1 (so the check above can fail).
            let c0 = fit(&mesh, &data, "d", &FitOptions::default()).unwrap();
            let differs = edges.iter().any(|e| {
                let (pa, pb) = (&mesh.vertices()[e.a], &mesh.vertices()[e.b]);
                let mid = [(&pa[0] + &pb[0]) / q("2"), (&pa[1] + &pb[1]) / q("2")];
                gradient(&c0.mesh, e.t, &mid) != gradient(&c0.mesh, e.u, &mid)
            });
            assert!(differs);
        }
    }
}

#[test]
fn mu_of_a_non_convex_pair() {
    // Edge 1–5 of `irregular`: T = (0, 1, 5) with c = 0, U = (1, 6, 5) with d = 6 = (5/2, 3/2).
    // d = μ_a·(3, 0) + μ_b·(1, 1) + μ_c·(0, 0) with a = 1, b = 5: μ_b = 3/2 from y,
    // 3μ_a + 3/2 = 5/2 gives μ_a = 1/3, and μ_c = 1 − 1/3 − 3/2 = −5/6.
    let mesh = irregular(2);
    let e = interior_edges(&mesh)
        .into_iter()
        .find(|e| (e.a, e.b) == (1, 5))
        .unwrap();
    assert_eq!((e.t, e.c, e.u, e.d), (0, 0, 1, 6));
    assert_eq!(mu(&mesh, &e), [q("1/3"), q("3/2"), q("-5/6")]);
}

#[test]
fn rank_deficiency_names_the_ordinates() {
    // The unit square cut along 0–2, quadratic; data only in triangle 0 = (0, 1, 2). Triangle
    // 1 = (0, 2, 3) shares vertex 0, vertex 2 and edge 0–2 with it; vertex 3 and the edges
    // 0–3 and 2–3 are seen by no data.
    let mesh = Mesh::new(
        vec![v("0", "0"), v("1", "0"), v("1", "1"), v("0", "1")],
        vec![[0, 1, 2], [0, 2, 3]],
        2,
    )
    .unwrap();
    let data: Vec<DataPoint> = sample_points(&mesh, 3)
        .into_iter()
        .filter(|p| p[0] > p[1])
        .enumerate()
        .map(|(i, p)| point(i + 1, p[0].clone(), p[1].clone(), &p[0] * &p[1]))
        .collect();
    let missing = vec![
        OrdinateId::Vertex { v: 3 },
        OrdinateId::Edge { a: 0, b: 3, k: 1 },
        OrdinateId::Edge { a: 2, b: 3, k: 1 },
    ];
    match fit(&mesh, &data, "d", &FitOptions::default()) {
        Err(e @ FitError::RankDeficient { .. }) => {
            let FitError::RankDeficient {
                undetermined,
                rank,
                dimension,
                unknowns,
            } = &e
            else {
                unreachable!()
            };
            assert_eq!(undetermined, &missing);
            assert_eq!((*rank, *dimension, *unknowns), (6, 9, 9));
            assert_eq!(
                e.to_string(),
                "the data do not determine 3 of the 9 ordinates (rank 6 of 9): the ordinate of vertex 3; edge 0–3, ordinate 1; edge 2–3, ordinate 1; add data near them, or regularize (--regularize) for the minimum-norm fit"
            );
        }
        other => panic!("{other:?}"),
    }
    // Minimum norm: the free ordinates affect no residual, so they are 0; the others fit xy
    // exactly (a quadratic on triangle 0).
    let options = FitOptions {
        regularize: true,
        ..FitOptions::default()
    };
    let f = fit(&mesh, &data, "d", &options).unwrap();
    assert_eq!(f.undetermined, missing);
    assert!(f.rss.is_zero());
    let o = f.mesh.ordinates();
    for id in [3usize, 4 + 2, 4 + 4] {
        assert_eq!(o[id], Some(BigRational::zero()), "{}", mesh.ordinate_id(id));
    }
    // xy on triangle 0 = (0,0), (1,0), (1,1): the blossom gives b200 = 0, b020 = 0,
    // b002 = 1, b110 = 0, b011 = (1·1 + 0·1)/2 = 1/2, b101 = (0·1 + 0·1)/2 = 0.
    assert_eq!(o[2], Some(q("1")));
    let e12 = mesh.global_index(0, [0, 1, 1]);
    assert_eq!(o[e12], Some(q("1/2")));
}

#[test]
fn a_point_outside_is_named() {
    let data = parse_data("1/2,1/2,1\n# gap\n3,1/2,0\n", "pts.csv").unwrap();
    let e = fit(&diamond(2), &data, "pts.csv", &FitOptions::default()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "pts.csv:3: the point (3, 1/2) lies outside the mesh"
    );
}

#[test]
fn too_many_unknowns() {
    let mesh = irregular(30);
    let data = parse_data("1,1,1\n", "d").unwrap();
    let e = fit(&mesh, &data, "d", &FitOptions::default()).unwrap_err();
    // 7 vertices, 13 edges of 29 ordinates, 7 triangles of 28·27/2 = 406.
    assert_eq!(
        e,
        FitError::TooManyUnknowns {
            unknowns: 7 + 13 * 29 + 7 * 406,
            max: MAX_FIT_UNKNOWNS
        }
    );
}

#[test]
fn data_parser_errors() {
    let bad = [
        ("", "d.csv: no points"),
        (
            "x,y\n1,2,3\n",
            "d.csv:1: a header line of 2 names, expected 3 (one per column)",
        ),
        ("1,2,3\n1,2\n", "d.csv:2: 2 fields, expected 3"),
    ];
    for (text, message) in bad {
        assert_eq!(
            parse_data(text, "d.csv").unwrap_err().to_string(),
            message,
            "{text:?}"
        );
    }
    let e = parse_data("1,2,3\n1,2,1/0\n", "d.csv")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("d.csv:2:") && e.contains("zero denominator"),
        "{e}"
    );
    let e = data::parse_limited("1,1,1\n2,2,2\n3,3,3\n", "d.csv", 2)
        .unwrap_err()
        .to_string();
    assert_eq!(e, "d.csv:3: more than 2 rows (the limit of a fit's data)");
}

fn float_of(q: &BigRational) -> BigRational {
    crate::number::exact_f64(crate::number::round_f64(q)).unwrap()
}

#[test]
fn float_fits_are_judged() {
    let dir = fixtures().join("small");
    let data = read_data(&dir.join("data.csv")).unwrap();
    let mesh = diamond(2);
    let exact = fit(&mesh, &data, "data.csv", &FitOptions::default()).unwrap();
    let x: Vec<BigRational> = exact
        .mesh
        .ordinates()
        .iter()
        .map(|o| o.clone().unwrap())
        .collect();
    let judge = |ords: Vec<BigRational>, tol: &str| {
        let m = mesh.with_ordinates(ords).unwrap();
        let options = FloatFitOptions {
            tolerance: tol.parse().unwrap(),
            ..FloatFitOptions::default()
        };
        judge_float_fit(&m, &data, "m", "data.csv", &options).unwrap()
    };
    // The exact fit itself.
    let r = judge(x.clone(), "exact");
    assert!(r.passed && r.error_norm == 0.0 && r.rss_excess.exact == "0");
    // Rounded to the nearest f64: an error far below what the conditioning allows.
    let rounded: Vec<BigRational> = x.iter().map(float_of).collect();
    let r = judge(rounded.clone(), "cond");
    assert!(r.passed, "{r:?}");
    assert!(r.error_ratio.unwrap() < 1.0);
    assert!(r.condition_bound.unwrap() >= 1.0);
    assert!(!judge(rounded.clone(), "exact").passed);
    // Perturbed by 1e-6 in one ordinate: far beyond it.
    let mut off = rounded;
    off[0] = &off[0] + q("1/1000000");
    let r = judge(off.clone(), "cond");
    assert!(!r.passed && r.error_ratio.unwrap() > 1.0);
    assert!(q(&r.max_abs_error.exact) > q("9/10000000"));
    assert!(judge(off.clone(), "abs=1/100000").passed);
    assert!(!judge(off, "abs=1/10000000").passed);
    // The residual of a worse fit exceeds the minimum.
    let r = judge(vec![BigRational::zero(); x.len()], "rel=2");
    assert!(r.passed);
    assert!(q(&r.rss_excess.exact) > BigRational::zero());
    let m = mesh.with_ordinates(x).unwrap();
    let options = FloatFitOptions {
        tolerance: "ulps=1".parse().unwrap(),
        ..FloatFitOptions::default()
    };
    let e = judge_float_fit(&m, &data, "m", "d", &options).unwrap_err();
    assert_eq!(
        e.to_string(),
        "tolerance `ulps=1` does not apply to fits (use cond=K, cond, abs=E, rel=E or exact)"
    );
}

#[test]
fn the_numpy_fits_are_judged() {
    // fixtures/fit/numpy: numpy's lstsq fit (fit_numpy.py) passes the default tolerance (`cond`,
    // K = 1, f64); the same fit with one ordinate moved by 1e-6 fails it by orders of magnitude,
    // and passes an absolute tolerance above the move. `tribez check --mesh --fit` relies on
    // these (crates/tribez-cli/tests/fit_cli.rs).
    let dir = fixtures().join("numpy");
    let data = read_data(&dir.join("data.csv")).unwrap();
    let judge = |file: &str, tolerance: &str| {
        let m = Mesh::from_file(dir.join(file)).unwrap();
        let options = FloatFitOptions {
            tolerance: tolerance.parse().unwrap(),
            ..FloatFitOptions::default()
        };
        judge_float_fit(&m, &data, file, "data.csv", &options).unwrap()
    };
    assert_eq!(
        FloatFitOptions::default(),
        FloatFitOptions {
            tolerance: "cond".parse().unwrap(),
            precision: crate::float::Precision::F64,
        }
    );
    let good = judge("fitted_numpy.toml", "cond");
    assert!(good.passed && good.error_ratio.unwrap() < 1.0, "{good:?}");
    assert_eq!((good.rank, good.ordinates), (49, 49));
    let bad = judge("fitted_numpy_perturbed.toml", "cond");
    assert!(!bad.passed && bad.error_ratio.unwrap() > 1e3, "{bad:?}");
    assert!(judge("fitted_numpy_perturbed.toml", "abs=2e-6").passed);
    assert!(!judge("fitted_numpy_perturbed.toml", "abs=1e-7").passed);
}

/// The minimum-norm fit from the rows (minnorm.rs, taken when there are fewer distinct points
/// than ordinates) equals the general path's (the kernel of the normal equations, §18.4), which
/// the tests above check against SymPy: same ordinates, rank, undetermined ordinates and
/// residual. Cases: points at a vertex and on edges (determined ordinates), repeated points with
/// different values (least squares takes their mean), triangles without data, several degrees.
#[test]
fn minimum_norm_from_rows_equals_the_kernel_path() {
    let cases: Vec<(usize, &str)> = vec![
        (2, "1,1,1\n1/2,1/4,2\n3/2,1/4,-1\n"),
        (3, "2,0,5\n1,1,1\n1,1,3\n1/2,1/4,2\n3/2,1/4,-1\n1,0,0\n"),
        (
            4,
            "0,0,1\n2,0,2\n2,2,3\n0,2,4\n1,1,0\n1/3,1/7,9\n5/3,1/2,-2\n1,3/2,1/5\n",
        ),
        (3, "1/2,1/2,1\n1/2,1/2,2\n1/2,1/2,4\n3/2,1/2,0\n"),
        // a point at every vertex and nothing else: the vertex ordinates are determined
        (2, "0,0,1\n2,0,2\n2,2,3\n0,2,4\n1,1,5\n"),
    ];
    for (n, text) in cases {
        let mesh = diamond(n);
        let data = parse_data(text, "d.csv").unwrap();
        let design = Design::new(&mesh, &data, "d.csv").unwrap();
        let unknowns = mesh.ordinate_count();
        assert!(design.rank_bound < unknowns);
        let fast = minnorm::minimum_norm_by_rows(&design, unknowns).expect("full row rank");
        let general = solve_least_squares(design.normal(), &[], Regularize::MinimumNorm).unwrap();
        assert_eq!(fast.x, general.x, "degree {n}: {text}");
        assert_eq!(fast.rank, general.rank, "degree {n}: {text}");
        assert_eq!(
            fast.undetermined, general.undetermined,
            "degree {n}: {text}"
        );
        assert_eq!(fast.rss, general.rss, "degree {n}: {text}");
        // and `fit` takes it, without regularisation refusing at once
        let f = fit(
            &mesh,
            &data,
            "d.csv",
            &FitOptions {
                degree: None,
                regularize: true,
                ..FitOptions::default()
            },
        )
        .unwrap();
        assert_eq!(f.rss, general.rss);
        match fit(&mesh, &data, "d.csv", &FitOptions::default()) {
            Err(FitError::RankDeficient {
                undetermined, rank, ..
            }) => {
                assert_eq!(rank, general.rank);
                let ids: Vec<OrdinateId> = general
                    .undetermined
                    .iter()
                    .map(|&g| mesh.ordinate_id(g))
                    .collect();
                assert_eq!(undetermined, ids);
            }
            other => panic!("{other:?}"),
        }
    }
}

/// Issue 35 §5: the `cond` tolerance is evaluated exactly at any scale and at `x* = 0`
/// (fixtures/fit/scale/derive.py gives the verdicts, from Python `fractions`).
#[test]
fn float_fit_verdicts_at_any_scale() {
    let dir = fixtures().join("scale");
    let text = std::fs::read_to_string(dir.join("expected.json")).unwrap();
    let e: serde_json::Value = serde_json::from_str(&text).unwrap();
    for c in e["cases"].as_array().unwrap() {
        let (mesh, _) = crate::mesh::read_mesh(&dir.join(c["mesh"].as_str().unwrap())).unwrap();
        let data = read_data(&dir.join(c["data"].as_str().unwrap())).unwrap();
        for (tol, want) in c["verdicts"].as_object().unwrap() {
            let options = FloatFitOptions {
                tolerance: crate::Tolerance::parse(tol).unwrap(),
                ..FloatFitOptions::default()
            };
            let r = judge_float_fit(&mesh, &data, "m", "d", &options).unwrap();
            assert_eq!(
                r.passed,
                want.as_bool().unwrap(),
                "{}: {tol}: {}",
                c["mesh"],
                r.text()
            );
            assert!(r.allowed_error.is_some_and(|a| a > 0.0 && a.is_finite()));
        }
    }
}

/// `sqrt_bound` brackets `√q` within a relative `2^-64` at any scale; exact squares are hit.
#[test]
fn sqrt_bounds_bracket_the_root() {
    for s in [
        "4",
        "2",
        "1/3",
        "1e-300",
        "7e300",
        "1e-5000",
        "123456789/1000",
        "1/4",
    ] {
        let x = q(s);
        let (lo, hi) = (judge::sqrt_bound(&x, false), judge::sqrt_bound(&x, true));
        assert!(&lo * &lo <= x && x <= &hi * &hi, "{s}");
        // hi − lo ≤ 2^-63 · lo
        let width = (&hi - &lo) * BigRational::from_integer(num_bigint::BigInt::one() << 63u32);
        assert!(width <= lo, "{s}");
    }
    assert_eq!(judge::sqrt_bound(&q("4"), false), q("2"));
    assert_eq!(judge::sqrt_bound(&q("0"), true), q("0"));
}
