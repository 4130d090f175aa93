//! `tribez join`: smoothness of two patches across their common domain edge, or a C1 neighbour.

use std::path::PathBuf;

use serde::Serialize;
use serde_json::Value as Json;

use super::construct::PatchReport;
use super::{CliError, Outcome, parse_list};
use crate::cli::OutputArgs;
use crate::report::{Render, strings, to_json, tuple};
use tribez::constructions::{Join, Violation, analyse_join as analyse, c1_neighbour};
use tribez::files::{index_key, read_bezier_patch as read_patch};

// Arguments of `tribez join` (a plain comment: see `Command`).
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
    #[arg(
        long,
        value_name = "X,Y",
        allow_hyphen_values = true,
        requires = "make_c1",
        conflicts_with = "b"
    )]
    pub domain: Option<String>,
    /// With --make-c1: the common edge, as A's corners I,J (numbered 1 to 3); default 1,2.
    #[arg(
        long,
        value_name = "I,J",
        default_value = "1,2",
        allow_hyphen_values = true,
        requires = "make_c1",
        conflicts_with = "b"
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
        return Outcome::rendered(&PatchReport::of(b), args.out.format, true);
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

/// One corner of a quadrilateral in a coplanarity violation.
#[derive(Serialize)]
struct CornerJson {
    patch: &'static str,
    index: String,
    point: Vec<String>,
}

/// Where a G1 violation shows: the parameter, A's point, the value, and the normals.
#[derive(Serialize)]
struct WitnessJson {
    t: String,
    at: Vec<String>,
    value: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal_a: Option<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    normal_b: Option<Vec<String>>,
}

/// One violated condition, as JSON: `condition` names it (`C1`, `coplanarity`, `G1`).
#[derive(Serialize)]
#[serde(untagged)]
enum ViolationJson<'a> {
    Row {
        condition: String,
        index: String,
        actual: Vec<String>,
        required: Vec<String>,
        difference: Vec<String>,
    },
    Coplanarity {
        condition: &'static str,
        index: String,
        points: Vec<CornerJson>,
        volume: String,
    },
    G1 {
        condition: &'static str,
        reason: &'a str,
        #[serde(skip_serializing_if = "Option::is_none")]
        determinant: Option<String>,
        #[serde(skip_serializing_if = "Option::is_none")]
        witness: Option<WitnessJson>,
    },
}

impl<'a> From<&'a Violation> for ViolationJson<'a> {
    fn from(v: &'a Violation) -> Self {
        match v {
            Violation::Row {
                rho,
                index,
                actual,
                required,
                difference,
            } => ViolationJson::Row {
                condition: condition(*rho),
                index: index_key(index),
                actual: strings(actual),
                required: strings(required),
                difference: strings(difference),
            },
            Violation::Coplanarity {
                index,
                points,
                volume,
            } => ViolationJson::Coplanarity {
                condition: "coplanarity",
                index: index_key(index),
                points: points
                    .iter()
                    .zip(["A", "A", "A", "B"])
                    .map(|((idx, p), patch)| CornerJson {
                        patch,
                        index: index_key(idx),
                        point: strings(p),
                    })
                    .collect(),
                volume: volume.to_string(),
            },
            Violation::G1 {
                reason,
                determinant,
                witness,
            } => ViolationJson::G1 {
                condition: "G1",
                reason,
                determinant: determinant.as_ref().map(|d| d.to_text(&["t"])),
                witness: witness.as_ref().map(|w| {
                    let normals = w.normal_a.as_ref().zip(w.normal_b.as_ref());
                    WitnessJson {
                        t: w.t.to_string(),
                        at: strings(&w.at),
                        value: w.value.to_string(),
                        normal_a: normals.map(|(na, _)| strings(na)),
                        normal_b: normals.map(|(_, nb)| strings(nb)),
                    }
                }),
            },
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

/// The domain edge two patches share.
#[derive(Serialize)]
struct SharedEdgeJson {
    vertices: Vec<Vec<String>>,
    a_vertices: Vec<usize>,
    b_vertices: Vec<usize>,
}

/// The JSON of `tribez join`.
#[derive(Serialize)]
struct JoinJson<'a> {
    a: &'a str,
    b: &'a str,
    degree: usize,
    shared_edge: SharedEdgeJson,
    mu: Vec<String>,
    opposite_sides: bool,
    c0: bool,
    c1: bool,
    g1: Option<bool>,
    coplanarity: Option<bool>,
    max_smoothness: i64,
    rows_agree: &'a [bool],
    g1_minors: Vec<String>,
    violations: Vec<ViolationJson<'a>>,
    notes: &'a [String],
}

impl Serialize for JoinReport {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let j = &self.join;
        let f = &j.facet;
        let one = |v: &[usize]| v.iter().map(|k| k + 1).collect::<Vec<_>>();
        JoinJson {
            a: &self.a,
            b: &self.b,
            degree: self.degree,
            shared_edge: SharedEdgeJson {
                vertices: f.vertices.iter().map(|v| strings(v)).collect(),
                a_vertices: one(&f.a),
                b_vertices: one(&f.b),
            },
            mu: strings(&j.mu),
            opposite_sides: j.opposite_sides,
            c0: j.c0,
            c1: j.c1,
            g1: j.g1,
            coplanarity: j.coplanarity,
            max_smoothness: j.max_smoothness,
            rows_agree: &j.rows_agree,
            g1_minors: j.g1_minors.iter().map(|p| p.to_text(&["t"])).collect(),
            violations: j.violations.iter().map(ViolationJson::from).collect(),
            notes: &j.notes,
        }
        .serialize(s)
    }
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
            tribez::format::format_points(&f.vertices),
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
        to_json(self)
    }
}
