//! `tribez join`: smoothness of two patches across their common domain edge, or a C1 neighbour.

use std::path::PathBuf;

use serde_json::{Map, Value as Json, json};

use super::{CliError, Outcome, parse_list};
use crate::cli::OutputArgs;
use crate::report::{Render, json_rationals, tuple};
use tribez::hazmat::io::patch_file::{index_key, patch_to_json, patch_to_toml, read_patch};
use tribez::hazmat::join::{Join, Violation, analyse, c1_neighbour};
use tribez::hazmat::patch::BezierPatch as Patch;

/// Arguments of `tribez join`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The first patch (A).
    pub a: PathBuf,
    /// The second patch (B); its domain must share an edge with A's (vertices in any order).
    pub b: Option<PathBuf>,
    /// Instead of checking a pair, build B: a neighbour of A that makes the pair C1.
    #[arg(long = "make-c1", requires = "domain", conflicts_with = "b")]
    pub make_c1: bool,
    /// With --make-c1: the new vertex X,Y of B's domain (B's domain is [a_I, a_J, (X,Y)]).
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    pub domain: Option<String>,
    /// With --make-c1: the common edge, as A's corners I,J (numbered 1 to 3); default 1,2.
    #[arg(
        long,
        value_name = "I,J",
        default_value = "1,2",
        allow_hyphen_values = true
    )]
    pub edge: String,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The join report.
pub struct JoinReport {
    a: String,
    b: String,
    degree: usize,
    join: Join,
}

/// A patch written as a patch file (TOML for text, JSON for json).
pub struct PatchOutput(pub Patch);

impl Render for PatchOutput {
    fn text(&self) -> String {
        patch_to_toml(&self.0)
    }
    fn json(&self) -> Json {
        patch_to_json(&self.0)
    }
}

/// Run `tribez join`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let afile = args.a.display().to_string();
    let a = read_patch(&args.a)?;
    if args.make_c1 {
        let text = args.domain.as_deref().unwrap_or_default();
        let v = parse_list(text, "--domain")?;
        let edge: Vec<usize> = args
            .edge
            .split(',')
            .map(|s| {
                s.trim()
                    .parse::<usize>()
                    .ok()
                    .filter(|&k| (1..=a.net.m() + 1).contains(&k))
                    .map(|k| k - 1)
            })
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| {
                CliError::Usage(format!(
                    "--edge {}: expected two corner numbers from 1 to {}, like 1,2",
                    args.edge,
                    a.net.m() + 1
                ))
            })?;
        let b = c1_neighbour(&a, &edge, v)
            .map_err(|e| CliError::core(format!("{afile}: --make-c1 --domain {text}"), e))?;
        return Outcome::rendered(&PatchOutput(b), args.out.format, true);
    }
    let bpath = args.b.as_ref().ok_or_else(|| {
        CliError::Usage("give two patches (A B), or one with --make-c1 --domain X,Y".into())
    })?;
    let bfile = bpath.display().to_string();
    let b = read_patch(bpath)?;
    let join = analyse(&a, &b).map_err(|e| CliError::core(format!("{afile} and {bfile}"), e))?;
    Outcome::rendered(
        &JoinReport {
            a: afile,
            b: bfile,
            degree: a.net.degree(),
            join,
        },
        args.out.format,
        true,
    )
}

fn condition(rho: usize) -> String {
    format!("C{rho}")
}

fn points_json(points: &[(Vec<u32>, Vec<num_rational::BigRational>)], labels: &[&str]) -> Json {
    Json::Array(
        points
            .iter()
            .zip(labels)
            .map(|((idx, p), who)| json!({"patch": who, "index": index_key(idx), "point": json_rationals(p)}))
            .collect(),
    )
}

/// One violation as JSON (shared with the claim op).
pub fn violation_json(v: &Violation) -> Json {
    match v {
        Violation::Row {
            rho,
            index,
            actual,
            required,
            difference,
        } => json!({
            "condition": condition(*rho),
            "index": index_key(index),
            "actual": json_rationals(actual),
            "required": json_rationals(required),
            "difference": json_rationals(difference),
        }),
        Violation::Coplanarity {
            index,
            points,
            volume,
        } => json!({
            "condition": "coplanarity",
            "index": index_key(index),
            "points": points_json(points, &["A", "A", "A", "B"]),
            "volume": volume.to_string(),
        }),
        Violation::G1 {
            reason,
            determinant,
            witness,
        } => {
            let mut o = Map::new();
            o.insert("condition".into(), json!("G1"));
            o.insert("reason".into(), json!(reason));
            if let Some(d) = determinant {
                o.insert("determinant".into(), json!(d.to_text(&["t"])));
            }
            if let Some(w) = witness {
                let mut wj = json!({"t": w.t.to_string(), "at": json_rationals(&w.at), "value": w.value.to_string()});
                if let (Some(na), Some(nb)) = (&w.normal_a, &w.normal_b) {
                    wj["normal_a"] = json_rationals(na);
                    wj["normal_b"] = json_rationals(nb);
                }
                o.insert("witness".into(), wj);
            }
            Json::Object(o)
        }
    }
}

fn violation_text(v: &Violation) -> String {
    match v {
        Violation::Row {
            rho,
            index,
            actual,
            required,
            difference,
        } => format!(
            "{}: B[{}] = {} but C{rho} requires {} (difference {})",
            condition(*rho),
            index_key(index),
            tuple(actual),
            tuple(required),
            tuple(difference)
        ),
        Violation::Coplanarity {
            index,
            points,
            volume,
        } => format!(
            "coplanarity: quadrilateral A[{}], A[{}], A[{}], B[{}] is not planar: det[P2−P1, P3−P1, P4−P1] = {volume}",
            index_key(&points[0].0),
            index_key(&points[1].0),
            index_key(&points[2].0),
            index_key(index)
        ),
        Violation::G1 {
            reason,
            determinant,
            witness,
        } => {
            let mut s = format!("G1: {reason}");
            if let Some(d) = determinant {
                s += &format!("\n    det[E, X_A, X_B](t) = {}", d.to_text(&["t"]));
            }
            if let Some(w) = witness {
                s += &format!(
                    "\n    at t = {} (A's point {}) it is {}",
                    w.t,
                    tuple(&w.at),
                    w.value
                );
                if let (Some(na), Some(nb)) = (&w.normal_a, &w.normal_b) {
                    s += &format!(
                        "; normals {} (A) and {} (B) are not parallel",
                        tuple(na),
                        tuple(nb)
                    );
                }
            }
            s
        }
    }
}

fn opt_bool(b: Option<bool>) -> Json {
    b.map_or(Json::Null, Json::Bool)
}

impl Render for JoinReport {
    fn text(&self) -> String {
        let j = &self.join;
        let f = &j.facet;
        let one = |v: &[usize]| {
            v.iter()
                .map(|k| (k + 1).to_string())
                .collect::<Vec<_>>()
                .join(",")
        };
        let word = |b: Option<bool>| {
            b.map_or("not decided".to_string(), |x| {
                if x { "yes".into() } else { "no".into() }
            })
        };
        let mut out = format!(
            "{} and {}: degree {}\nshared edge {} = A's vertices {} = B's vertices {}\nmu (B's fourth vertex w.r.t. A's domain) = {}{}\n",
            self.a,
            self.b,
            self.degree,
            tribez::hazmat::domain::format_points(&f.vertices),
            one(&f.a),
            one(&f.b),
            tuple(&j.mu),
            if j.opposite_sides {
                ""
            } else {
                " (same side: the domains overlap)"
            }
        );
        out += &format!(
            "C0: {}\nC1: {}\nmax smoothness: C^{}{}\nG1: {}\nFinn's notes coplanarity: {}\n",
            word(Some(j.c0)),
            word(Some(j.c1)),
            j.max_smoothness,
            if j.max_smoothness == self.degree as i64 {
                " (B is the extension of A: the same polynomial, C^r for every r)"
            } else {
                ""
            },
            word(j.g1),
            word(j.coplanarity)
        );
        if let [det] = j.g1_minors.as_slice() {
            out += &format!("det[E, X_A, X_B](t) = {}\n", det.to_text(&["t"]));
        }
        if !j.violations.is_empty() {
            out += "violations:\n";
            for v in &j.violations {
                out += &format!("  {}\n", violation_text(v));
            }
        }
        for n in &j.notes {
            out += &format!("note: {n}\n");
        }
        out
    }

    fn json(&self) -> Json {
        let j = &self.join;
        let f = &j.facet;
        let one = |v: &[usize]| v.iter().map(|k| k + 1).collect::<Vec<_>>();
        json!({
            "a": self.a,
            "b": self.b,
            "degree": self.degree,
            "shared_edge": {
                "vertices": f.vertices.iter().map(|v| json_rationals(v)).collect::<Vec<_>>(),
                "a_vertices": one(&f.a),
                "b_vertices": one(&f.b),
            },
            "mu": json_rationals(&j.mu),
            "opposite_sides": j.opposite_sides,
            "c0": j.c0,
            "c1": j.c1,
            "g1": opt_bool(j.g1),
            "coplanarity": opt_bool(j.coplanarity),
            "max_smoothness": j.max_smoothness,
            "rows_agree": j.rows_agree,
            "g1_minors": j.g1_minors.iter().map(|p| p.to_text(&["t"])).collect::<Vec<_>>(),
            "violations": j.violations.iter().map(violation_json).collect::<Vec<_>>(),
            "notes": j.notes,
        })
    }
}
