//! `tribez intersect`: every intersection of two planar curves, exactly (real algebraic
//! parameters, tangency and multiplicity, overlaps).

use std::path::PathBuf;

use serde_json::Value as Json;

use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::Render;
use tribez::Patch;
use tribez::algebraic::{Curve, CurveIntersections, intersect_curves, point_text};

// Arguments of `tribez intersect` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The first curve (a patch file with m = 1 and points in the plane; Bézier or rational).
    pub a: PathBuf,
    /// The second curve.
    pub b: PathBuf,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The report of `tribez intersect`.
pub struct IntersectReport {
    a: String,
    b: String,
    result: CurveIntersections,
}

fn curve(path: &std::path::Path, which: &str) -> Result<Curve, CliError> {
    let file = path.display().to_string();
    let patch = Patch::from_file(path)?;
    Curve::from_patch(&patch, which).map_err(|e| CliError::about(file, e))
}

/// Run `tribez intersect`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let a = curve(&args.a, "the curve")?;
    let b = curve(&args.b, "the curve")?;
    let result = intersect_curves(&a, &b)
        .map_err(|e| CliError::about(format!("{} × {}", args.a.display(), args.b.display()), e))?;
    Outcome::rendered(
        &IntersectReport {
            a: args.a.display().to_string(),
            b: args.b.display().to_string(),
            result,
        },
        args.out.format,
        true,
    )
}

use super::inverse::alg_text as number_text;

impl Render for IntersectReport {
    fn text(&self) -> String {
        let r = &self.result;
        let mut out = format!(
            "{} × {}: {} intersection point{}{}\n",
            self.a,
            self.b,
            r.points.len(),
            if r.points.len() == 1 { "" } else { "s" },
            match r.overlaps.len() {
                0 => String::new(),
                1 => ", 1 overlap".into(),
                n => format!(", {n} overlaps"),
            }
        );
        for (k, p) in r.points.iter().enumerate() {
            let [x, y] = point_text(&p.point);
            out += &format!(
                "{}. {}\n   {}\n   point ({x}, {y}){}\n",
                k + 1,
                number_text("s", &p.s),
                number_text("t", &p.t),
                match (p.tangential, p.multiplicity) {
                    (true, Some(m)) => format!(", tangential (multiplicity {m})"),
                    (true, None) =>
                        ", tangential (the curves touch at the end of a shared piece)".to_string(),
                    (false, Some(m)) if m > 1 => format!(", multiplicity {m}"),
                    _ => String::new(),
                }
            );
        }
        for o in &r.overlaps {
            out += &format!(
                "overlap: s from {} to {}, t from {} to {}{}\n",
                o.s[0].to_text(),
                o.s[1].to_text(),
                o.t[0].to_text(),
                o.t[1].to_text(),
                match o.t[0].cmp_exact(&o.t[1]) {
                    std::cmp::Ordering::Less => " (t increasing with s)",
                    std::cmp::Ordering::Greater => " (t decreasing as s increases)",
                    std::cmp::Ordering::Equal => "",
                }
            );
        }
        if let Some(g) = &r.relation
            && !r.overlaps.is_empty()
        {
            out += &format!("on each overlap: {} = 0\n", relation_text(g));
        }
        out
    }

    fn json(&self) -> Json {
        let r = &self.result;
        serde_json::to_value(IntersectJson {
            a: &self.a,
            b: &self.b,
            count: r.points.len(),
            intersections: &r.points,
            overlaps: &r.overlaps,
            relation: r.relation.as_ref().map(relation_terms),
        })
        .expect("serializable")
    }
}

/// The JSON of `tribez intersect`.
#[derive(serde::Serialize)]
struct IntersectJson<'a> {
    a: &'a str,
    b: &'a str,
    count: usize,
    intersections: &'a [tribez::algebraic::Intersection],
    overlaps: &'a [tribez::algebraic::Overlap],
    /// The relation `Σ c·s^i·t^j = 0` of the overlaps (integer coefficients), when the curves
    /// lie on one algebraic curve.
    #[serde(skip_serializing_if = "Option::is_none")]
    relation: Option<Vec<RelationTerm>>,
}

/// One term `c·s^i·t^j` of the relation (the integer `c` as a string).
#[derive(serde::Serialize)]
struct RelationTerm {
    coefficient: String,
    s: usize,
    t: usize,
}

/// The relation's terms with integer coefficients: `(c, i, j)` for `c·s^i·t^j`, by `i` then
/// `j` (the polynomial's `y` is `s`, its `x` is `t`).
fn relation_int(g: &tribez::algebraic::BiPoly) -> Vec<(num_bigint::BigInt, usize, usize)> {
    use num_integer::Integer;
    let l =
        g.c.iter()
            .flatten()
            .fold(num_bigint::BigInt::from(1), |l, x| l.lcm(x.denom()));
    let mut out = Vec::new();
    for (i, row) in g.c.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            if !num_traits::Zero::is_zero(x) {
                out.push((x.numer() * (&l / x.denom()), i, j));
            }
        }
    }
    out
}

fn relation_terms(g: &tribez::algebraic::BiPoly) -> Vec<RelationTerm> {
    relation_int(g)
        .into_iter()
        .map(|(c, s, t)| RelationTerm {
            coefficient: c.to_string(),
            s,
            t,
        })
        .collect()
}

fn relation_text(g: &tribez::algebraic::BiPoly) -> String {
    let mut out = String::new();
    for (k, (c, i, j)) in relation_int(g).into_iter().enumerate() {
        let neg = c < num_bigint::BigInt::from(0);
        let a = if neg { -c } else { c };
        out += match (k, neg) {
            (0, true) => "-",
            (0, false) => "",
            (_, true) => " - ",
            (_, false) => " + ",
        };
        let mut factors = Vec::new();
        if a != num_bigint::BigInt::from(1) || (i == 0 && j == 0) {
            factors.push(a.to_string());
        }
        for (v, e) in [("s", i), ("t", j)] {
            match e {
                0 => {}
                1 => factors.push(v.to_string()),
                e => factors.push(format!("{v}^{e}")),
            }
        }
        out += &factors.join("·");
    }
    out
}
