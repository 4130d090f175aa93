use tribez::{Degree, Patch, Precision, SimplexDim, Tolerance, judge, parse_rational};

fn main() -> Result<(), tribez::Error> {
    let q = |s: &str| parse_rational(s).expect("an exact number");

    // The worked example: a quadratic triangle (m = 2, degree 2) with points in R^3, control
    // points in the order 200, 110, 020, 101, 011, 002.
    let points = [
        ["0", "0", "0"],
        ["1", "0", "2"],
        ["0", "2", "0"],
        ["0", "1", "0"],
        ["1", "1", "1"],
        ["0", "2", "1"],
    ];
    let net = points.iter().map(|p| p.map(q).to_vec()).collect();
    let patch = Patch::bezier(SimplexDim(2), Degree(2), net)?;

    // Exactly, at (1/2, 1/3, 1/6).
    let exact = patch.evaluate(&[q("1/2"), q("1/3"), q("1/6")])?;
    assert_eq!(exact, [q("4/9"), q("5/9"), q("29/36")]);
    println!("exact: ({}, {}, {})", exact[0], exact[1], exact[2]);

    // A float program: the Bernstein sum in f64 at the same point, as f64 sees it.
    let input = [0.5, 1.0 / 3.0, 1.0 / 6.0];
    let [u, v, w] = input;
    let basis = [u * u, 2.0 * u * v, v * v, 2.0 * u * w, 2.0 * v * w, w * w];
    let c: Vec<[f64; 3]> = points
        .iter()
        .map(|p| p.map(|x| x.parse().unwrap()))
        .collect();
    let claimed: Vec<f64> = (0..3)
        .map(|k| basis.iter().zip(&c).map(|(b, p)| b * p[k]).sum())
        .collect();

    // Judge it: within 2 ULPs of the exact value at the input as the program saw it?
    let tolerance = Tolerance::parse("ulps=2").expect("a tolerance");
    let verdict = judge(&patch, &input, &claimed, &tolerance, Precision::F64)?;
    print!("{verdict}");
    assert!(verdict.passed);
    Ok(())
}
