//! Every error of tribez's own float algorithms lies within its proven a-priori bound
//! (`src/certify/bound.rs`): more than 100,000 random cases, including ill-conditioned ones
//! (huge and tiny control points, a polynomial with a double zero line, points near the edges and
//! outside the simplex, where the bound uses |λ|). Cases are judged by the float filter and, when
//! it cannot decide, exactly.

use num_rational::BigRational;
use tribez::hazmat::certify::Certifier;
use tribez::hazmat::certify::filter::{Enclosure, Scratch};
use tribez::hazmat::certify::sample::{SplitMix, random_points};
use tribez::hazmat::exact::Algorithm;
use tribez::hazmat::float::Float;
use tribez::hazmat::patch::ControlNet;
use tribez::hazmat::simplex::Simplex;

fn net(
    m: usize,
    n: usize,
    dim: usize,
    mut f: impl FnMut(&[u32], usize) -> f64,
) -> ControlNet<BigRational> {
    let s = Simplex::new(m, n);
    let coords = s
        .iter()
        .flat_map(|a| {
            (0..dim)
                .map(|c| BigRational::from_float(f(a, c)).unwrap())
                .collect::<Vec<_>>()
        })
        .collect();
    ControlNet::new(s, dim, coords)
}

fn patches() -> Vec<(String, ControlNet<BigRational>)> {
    let mut r = SplitMix(99);
    let mut out = Vec::new();
    for n in [1, 3, 6] {
        out.push((
            format!("random n={n}"),
            net(2, n, 2, |_, _| r.unit() * 2.0 - 1.0),
        ));
        out.push((
            format!("huge and tiny n={n}"),
            net(2, n, 2, |_, c| {
                (r.unit() - 0.5) * if c == 0 { 1e30 } else { 1e-25 }
            }),
        ));
        // alternating huge and tiny magnitudes inside one coordinate
        out.push((
            format!("mixed n={n}"),
            net(2, n, 1, |a, _| {
                (r.unit() - 0.3) * if a[0] % 2 == 0 { 1e20 } else { 1e-20 }
            }),
        ));
        // (λ0 − λ1)^n: c_(i,j,0) = (−1)^j, else 0; a zero of order n along λ0 = λ1 (ill-conditioned)
        out.push((
            format!("(u-v)^n n={n}"),
            net(2, n, 1, |a, _| {
                if a[2] == 0 {
                    if a[1] % 2 == 0 { 1.0 } else { -1.0 }
                } else {
                    0.0
                }
            }),
        ));
    }
    out.push((
        "tetrahedron n=3".into(),
        net(3, 3, 3, |_, _| r.unit() * 8.0 - 4.0),
    ));
    out.push((
        "huge f64 n=3".into(),
        net(2, 3, 1, |_, _| (r.unit() - 0.5) * 1e250),
    ));
    out.push((
        "tiny f64 n=4".into(),
        net(2, 4, 1, |_, _| (r.unit() - 0.5) * 1e-250),
    ));
    out
}

fn points(m: usize, count: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut pts = random_points(m, count, seed);
    // points near the line λ0 = λ1 (where (u−v)^n is ill-conditioned)
    let mut r = SplitMix(seed ^ 0xABCD);
    for p in pts.iter_mut().step_by(7) {
        p[1] = p[0] * (1.0 + (r.unit() - 0.5) * 1e-6);
        let s: f64 = p[..m].iter().sum();
        p[m] = 1.0 - s;
    }
    pts
}

fn run<F: Float>(
    net: &ControlNet<BigRational>,
    pts: &[Vec<f64>],
    name: &str,
) -> (usize, usize, usize) {
    let cert = Certifier::<F>::new(net);
    let mut scratch = (Scratch::default(), Vec::<Enclosure>::new());
    let (mut cases, mut fell_back, mut outside) = (0, 0, 0);
    for p in pts {
        let lam: Vec<F> = p
            .iter()
            .map(|x| F::round(&BigRational::from_float(*x).unwrap()))
            .collect();
        for alg in [Algorithm::Casteljau, Algorithm::Bernstein] {
            let (_, check) = cert.check(alg, &lam, &mut scratch);
            assert!(
                check.within,
                "{name} {:?} {alg:?}: error beyond the bound at {p:?}",
                F::PRECISION
            );
            cases += 1;
            fell_back += usize::from(check.fell_back);
            outside += usize::from(check.outside_hypothesis);
            // de Casteljau's bound covers underflow; our data never overflows
            assert!(
                !(alg == Algorithm::Casteljau && check.outside_hypothesis),
                "{name}: de Casteljau outside its hypothesis at {p:?}"
            );
        }
    }
    (cases, fell_back, outside)
}

#[test]
fn every_error_lies_within_its_bound() {
    let (mut cases, mut fell_back, mut outside) = (0, 0, 0);
    for (i, (name, net)) in patches().iter().enumerate() {
        let pts = points(net.m(), 2000, i as u64 + 1);
        let mut runs = vec![run::<f64>(net, &pts, name)];
        if !name.starts_with("huge f64") {
            // 1e250 overflows f32: that patch is certified in f64 only
            runs.push(run::<f32>(net, &pts, name));
        }
        for (c, f, o) in runs {
            cases += c;
            fell_back += f;
            outside += o;
        }
    }
    eprintln!("{cases} cases, {fell_back} judged exactly, {outside} outside the hypothesis");
    assert!(cases >= 100_000, "{cases}");
    // Only the Bernstein form can leave its hypothesis (no underflow): with control values of
    // 1e-25 and coordinates of 1e-9 near the edges, its f32 products underflow (about 5% here).
    assert!(
        outside * 10 < cases,
        "{outside} of {cases} outside the hypothesis"
    );
}

#[test]
fn the_exact_judgement_agrees_with_the_filter() {
    // A sample judged both ways: when the filter says "within", the exact check agrees.
    let (name, net) = &patches()[3];
    let cert = Certifier::<f64>::new(net);
    let mut scratch = (Scratch::default(), Vec::<Enclosure>::new());
    for p in points(2, 300, 5) {
        let lam: Vec<f64> = p.clone();
        for alg in [Algorithm::Casteljau, Algorithm::Bernstein] {
            let (y, check) = cert.check(alg, &lam, &mut scratch);
            if !check.outside_hypothesis {
                assert!(cert.exact_within(alg, &lam, &y), "{name} {alg:?} {p:?}");
            }
        }
    }
}
