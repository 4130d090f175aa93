//! `tribez eval` for rational patches and S-patches: exact values, and the float path judged
//! in ULPs against them (the certification hook of these kinds).
//!
//! * Rational: the point is `X/W` from homogeneous de Casteljau; the ratio of the two
//!   polynomial patches (Bernstein sums) is computed as well and must agree exactly. The float
//!   path runs de Casteljau on the rounded homogeneous net and divides once.
//! * S-patch: points are Cartesian (`--cartesian`); the report gives the Wachspress coordinates
//!   `λ(p)` and `S(p)`. The float path computes `λ` and de Casteljau in floats.

use num_rational::BigRational;
use num_traits::Zero;
use serde_json::{Value as Json, json};

use super::eval::{Args, FloatChoice};
use super::{CliError, Outcome, check_barycentric, parse_list};
use crate::report::{Render, json_rationals, tuple};
use tribez::error::CoreError;
use tribez::exact::{Algorithm, ExactEvaluator};
use tribez::float::{Float, Precision};
use tribez::io::points::read_points;
use tribez::number::to_decimal_string;
use tribez::rational::RationalPatch;
use tribez::spatch::{Polygon, SPatch};

/// The points of `--at` and `--points`, with a description each (for every kind of patch).
pub(super) fn raw_points(
    args: &Args,
    width: usize,
) -> Result<Vec<(String, Vec<BigRational>)>, CliError> {
    let mut raw = Vec::new();
    for a in &args.at {
        raw.push((format!("--at {a}"), parse_list(a, "--at")?));
    }
    if let Some(path) = &args.points {
        for (i, p) in read_points(path, width)?.into_iter().enumerate() {
            raw.push((format!("{}: point {}", path.display(), i + 1), p));
        }
    }
    if raw.is_empty() {
        return Err(CliError::Usage(
            "give at least one point with --at or --points".into(),
        ));
    }
    Ok(raw)
}

/// One float coordinate: decimal, hex, exact value, ULPs at the rounded inputs, ULPs at the
/// intended inputs.
type JudgedValue = (
    String,
    String,
    Option<BigRational>,
    Option<BigRational>,
    Option<BigRational>,
);

/// A float result judged against exact values.
struct Judged {
    precision: Precision,
    inputs: Vec<BigRational>,
    /// `None` when the exact value at the rounded inputs is undefined.
    exact_at_inputs: Option<Vec<BigRational>>,
    values: Vec<JudgedValue>,
}

fn judge<F: Float>(
    values: &[F],
    inputs: Vec<BigRational>,
    exact_at_inputs: Option<Vec<BigRational>>,
    intended: &[BigRational],
) -> Judged {
    let values = values
        .iter()
        .enumerate()
        .map(|(c, &v)| {
            let x = v.exact();
            let alg = match (&x, &exact_at_inputs) {
                (Some(x), Some(e)) => Some(F::ulps(x, &e[c])),
                _ => None,
            };
            let total = x.as_ref().map(|x| F::ulps(x, &intended[c]));
            (v.decimal(), v.hex(), x, alg, total)
        })
        .collect();
    Judged {
        precision: F::PRECISION,
        inputs,
        exact_at_inputs,
        values,
    }
}

struct Row {
    at: Vec<BigRational>,
    cartesian: Option<Vec<BigRational>>,
    lambda: Option<Vec<BigRational>>,
    point: Vec<BigRational>,
    floats: Vec<Judged>,
}

struct Report {
    file: String,
    kind: &'static str,
    header: String,
    algorithm: &'static str,
    rows: Vec<Row>,
}

fn precisions(c: Option<FloatChoice>) -> Vec<Precision> {
    match c {
        None => vec![],
        Some(FloatChoice::F64) => vec![Precision::F64],
        Some(FloatChoice::F32) => vec![Precision::F32],
        Some(FloatChoice::All) => vec![Precision::F64, Precision::F32],
    }
}

fn rational_float<F: Float + std::ops::Div<Output = F>>(
    r: &RationalPatch,
    lambda: &[BigRational],
    intended: &[BigRational],
) -> Judged {
    let lam: Vec<F> = lambda.iter().map(F::round).collect();
    let lam_exact: Vec<BigRational> = lam.iter().map(|x| x.exact().expect("finite")).collect();
    let values = r.evaluate_float::<F>(&lam);
    // the exact value at what the float code saw: the rounded homogeneous net at the rounded λ
    let h = r
        .homogeneous()
        .map(|q| F::round(q).exact().unwrap_or_default());
    let v = ExactEvaluator::new(&h).evaluate(&lam_exact, Algorithm::Casteljau);
    let (w, x) = v.split_last().expect("d + 1");
    let exact = (!w.is_zero()).then(|| x.iter().map(|c| c / w).collect());
    judge(&values, lam_exact, exact, intended)
}

/// `tribez eval` on a rational patch.
pub fn rational(args: &Args, file: String, r: RationalPatch) -> Result<Outcome, CliError> {
    let m = r.patch.net.m();
    let width = if args.cartesian { m } else { m + 1 };
    let domain = r.patch.domain_or_reference();
    let mut rows = Vec::new();
    for (what, p) in raw_points(args, width)? {
        let (at, cartesian) = if args.cartesian {
            (
                domain
                    .barycentric(&p)
                    .map_err(|e| CliError::core(&what, e))?,
                Some(p),
            )
        } else {
            if args.homogeneous {
                if p.len() != m + 1 {
                    return Err(CliError::core(
                        &what,
                        CoreError::WrongLength {
                            what: "point".into(),
                            expected: m + 1,
                            found: p.len(),
                        },
                    ));
                }
            } else {
                check_barycentric(&p, m, "point").map_err(|e| CliError::core(&what, e))?;
            }
            (p, None)
        };
        let point = r.evaluate(&at).map_err(|e| CliError::core(&what, e))?;
        let ratio = r
            .evaluate_ratio(&at)
            .map_err(|e| CliError::core(&what, e))?;
        debug_assert_eq!(
            point, ratio,
            "homogeneous de Casteljau and the ratio of two patches must agree exactly"
        );
        let mut floats = Vec::new();
        for p in precisions(args.float) {
            floats.push(match p {
                Precision::F64 => rational_float::<f64>(&r, &at, &point),
                Precision::F32 => rational_float::<f32>(&r, &at, &point),
            });
        }
        rows.push(Row {
            at,
            cartesian,
            lambda: None,
            point,
            floats,
        });
    }
    let net = &r.patch.net;
    let header = format!(
        "rational, degree {} over the {}-simplex, points in R^{}",
        net.degree(),
        net.m(),
        net.dim()
    );
    Outcome::rendered(
        &Report {
            file,
            kind: "rational",
            header,
            algorithm: "homogeneous de Casteljau",
            rows,
        },
        args.out.format,
        true,
    )
}

fn spatch_float<F: Float + std::ops::Div<Output = F>>(
    s: &SPatch,
    p: &[BigRational],
    intended: &[BigRational],
) -> Judged {
    let q = [F::round(&p[0]), F::round(&p[1])];
    let inputs: Vec<BigRational> = q.iter().map(|x| x.exact().expect("finite")).collect();
    let values = s.evaluate_float::<F>(&q);
    let rounded_vertices: Vec<Vec<BigRational>> = s
        .polygon
        .vertices()
        .iter()
        .map(|v| {
            v.iter()
                .map(|c| F::round(c).exact().unwrap_or_default())
                .collect()
        })
        .collect();
    let exact = Polygon::new(rounded_vertices).ok().and_then(|poly| {
        let sr = SPatch {
            name: None,
            polygon: poly,
            net: s.net.map(|c| F::round(c).exact().unwrap_or_default()),
        };
        sr.evaluate(&inputs).ok().map(|(_, v)| v)
    });
    judge(&values, inputs, exact, intended)
}

/// `tribez eval` on an S-patch (Cartesian points only).
pub fn spatch(args: &Args, file: String, s: SPatch) -> Result<Outcome, CliError> {
    if !args.cartesian {
        return Err(CliError::Usage(format!(
            "{file} is an S-patch: give Cartesian points of its polygon with --cartesian --at x,y"
        )));
    }
    let mut rows = Vec::new();
    for (what, p) in raw_points(args, 2)? {
        if p.len() != 2 {
            return Err(CliError::core(
                &what,
                CoreError::WrongLength {
                    what: "point".into(),
                    expected: 2,
                    found: p.len(),
                },
            ));
        }
        let (lambda, point) = s.evaluate(&p).map_err(|e| CliError::core(&what, e))?;
        let mut floats = Vec::new();
        for pr in precisions(args.float) {
            floats.push(match pr {
                Precision::F64 => spatch_float::<f64>(&s, &p, &point),
                Precision::F32 => spatch_float::<f32>(&s, &p, &point),
            });
        }
        rows.push(Row {
            at: p.clone(),
            cartesian: Some(p),
            lambda: Some(lambda),
            point,
            floats,
        });
    }
    let header = format!(
        "S-patch, depth {} over a {}-gon, points in R^{}",
        s.net.degree(),
        s.polygon.len(),
        s.net.dim()
    );
    Outcome::rendered(
        &Report {
            file,
            kind: "s-patch",
            header,
            algorithm: "Wachspress + de Casteljau",
            rows,
        },
        args.out.format,
        true,
    )
}

fn opt(q: &Option<BigRational>) -> Json {
    q.as_ref().map_or(Json::Null, |x| json!(x.to_string()))
}

impl Render for Report {
    fn text(&self) -> String {
        let mut out = format!("{}: {}\n", self.file, self.header);
        for r in &self.rows {
            match (&r.cartesian, &r.lambda) {
                (Some(c), Some(l)) => {
                    out += &format!(
                        "at {} (Wachspress {}): {}\n",
                        tuple(c),
                        tuple(l),
                        tuple(&r.point)
                    )
                }
                (Some(c), None) => {
                    out += &format!(
                        "at {} (Cartesian {}): {}\n",
                        tuple(&r.at),
                        tuple(c),
                        tuple(&r.point)
                    )
                }
                _ => out += &format!("at {}: {}\n", tuple(&r.at), tuple(&r.point)),
            }
            for f in &r.floats {
                out += &format!(
                    "  {} {}: inputs as the code saw them {}\n",
                    f.precision.name(),
                    self.algorithm,
                    tuple(&f.inputs)
                );
                for (c, (dec, hex, exact, alg, total)) in f.values.iter().enumerate() {
                    let ulps = |u: &Option<BigRational>| {
                        u.as_ref().map_or("n/a".into(), |x| to_decimal_string(x, 4))
                    };
                    out += &format!(
                        "    [{c}] {dec} = {hex} = {}; {} ulp from the exact value at those inputs ({}), {} ulp from the exact value at the intended inputs\n",
                        exact
                            .as_ref()
                            .map_or("not finite".into(), ToString::to_string),
                        ulps(alg),
                        f.exact_at_inputs
                            .as_ref()
                            .map_or("undefined".into(), |e| e[c].to_string()),
                        ulps(total),
                    );
                }
            }
        }
        out
    }

    fn json(&self) -> Json {
        let results: Vec<Json> = self
            .rows
            .iter()
            .map(|r| {
                let mut o = json!({ "at": json_rationals(&r.at), "point": json_rationals(&r.point) });
                if let Some(c) = &r.cartesian {
                    o["cartesian"] = json_rationals(c);
                }
                if let Some(l) = &r.lambda {
                    o["wachspress"] = json_rationals(l);
                }
                if !r.floats.is_empty() {
                    o["float"] = Json::Array(
                        r.floats
                            .iter()
                            .map(|f| {
                                json!({
                                    "precision": f.precision.name(),
                                    "algorithm": self.algorithm,
                                    "inputs": json_rationals(&f.inputs),
                                    "exact_at_inputs": f.exact_at_inputs.as_ref().map_or(Json::Null, |e| json_rationals(e)),
                                    "value": f.values.iter().map(|(dec, hex, x, a, t)| json!({
                                        "decimal": dec, "hex": hex, "exact": opt(x),
                                        "ulps_vs_exact_at_inputs": opt(a), "ulps_vs_exact_at_intended_inputs": opt(t),
                                    })).collect::<Vec<_>>(),
                                })
                            })
                            .collect(),
                    );
                }
                o
            })
            .collect();
        json!({ "patch": self.file, "kind": self.kind, "results": results })
    }
}
