//! `tribez tangent`: the de Casteljau intermediate points, partial derivatives and normal at a point.

use std::path::PathBuf;

use num_rational::BigRational;
use serde_json::Value as Json;

use super::{CliError, Outcome, at_point};
use crate::cli::OutputArgs;
use crate::report::ser::OrderedMap;
use crate::report::{Render, strings, to_json, tuple};
use tribez::Patch;
use tribez::constructions::TangentFrame;
use tribez::constructions::cartesian_names;
use tribez::files::index_key;

// Arguments of `tribez tangent` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// The point: barycentric coordinates summing to 1, or Cartesian with --cartesian.
    #[arg(long = "at", value_name = "POINT", allow_hyphen_values = true)]
    pub at: String,
    /// The point is Cartesian (converted by the domain, Cramer's rule).
    #[arg(long)]
    pub cartesian: bool,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The tangent report.
pub struct TangentReport {
    file: String,
    rational: bool,
    degree: usize,
    at: Vec<BigRational>,
    frame: TangentFrame,
}

/// Run `tribez tangent`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = Patch::from_file(&args.patch)?;
    let constructions = super::constructions(&patch, &file, "tangent")?;
    let at = at_point(
        &args.at,
        args.cartesian,
        &constructions.domain(),
        patch.simplex_dim(),
    )?;
    let frame = constructions
        .tangent_frame(&at)
        .map_err(|e| CliError::core(&file, e))?;
    let rational = constructions.projected();
    Outcome::rendered(
        &TangentReport {
            file,
            rational,
            degree: patch.degree(),
            at,
            frame,
        },
        args.out.format,
        true,
    )
}

impl TangentReport {
    fn unit_key(&self, k: usize) -> String {
        let mut e = vec![0u32; self.at.len()];
        e[k] = 1;
        index_key(&e)
    }
}

/// The JSON of `tribez tangent`.
#[derive(serde::Serialize)]
struct TangentJson<'a> {
    patch: &'a str,
    at: Vec<String>,
    point: Vec<String>,
    /// `"1,0,0"` → the de Casteljau point of level n − 1 at that unit index.
    intermediate: OrderedMap<Vec<String>>,
    /// `"x"` → the partial derivative.
    partials: OrderedMap<Vec<String>>,
    normal: Option<Vec<String>>,
    normal_from_intermediate: Option<Vec<String>>,
    regular: bool,
}

impl serde::Serialize for TangentReport {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let f = &self.frame;
        let m = self.at.len() - 1;
        TangentJson {
            patch: &self.file,
            at: strings(&self.at),
            point: strings(&f.point),
            intermediate: OrderedMap(
                f.intermediate
                    .iter()
                    .enumerate()
                    .map(|(k, p)| (self.unit_key(k), strings(p)))
                    .collect(),
            ),
            partials: OrderedMap(
                cartesian_names(m)
                    .into_iter()
                    .zip(&f.partials)
                    .map(|(name, p)| (name, strings(p)))
                    .collect(),
            ),
            normal: f.normal.as_deref().map(strings),
            normal_from_intermediate: f.normal_from_intermediate.as_deref().map(strings),
            regular: f.regular,
        }
        .serialize(s)
    }
}

impl Render for TangentReport {
    fn text(&self) -> String {
        let f = &self.frame;
        let m = self.at.len() - 1;
        let mut out = format!(
            "{}: degree {}, at {}\npoint {}\n",
            self.file,
            self.degree,
            tuple(&self.at),
            tuple(&f.point)
        );
        out += &format!(
            "de Casteljau level {}{} (the tangent plane passes through these):\n",
            self.degree - 1,
            if self.rational {
                ", projected: c = X/W"
            } else {
                ""
            }
        );
        for (k, p) in f.intermediate.iter().enumerate() {
            out += &format!("  c[{}] = {}\n", self.unit_key(k), tuple(p));
        }
        for (name, p) in cartesian_names(m).iter().zip(&f.partials) {
            out += &format!("p_{name} = {}\n", tuple(p));
        }
        if let (Some(nrm), Some(via)) = (&f.normal, &f.normal_from_intermediate) {
            out += &format!("normal p_x × p_y = {}\n", tuple(nrm));
            out += &format!(
                "{}(c[0,1,0] − c[1,0,0]) × (c[0,0,1] − c[1,0,0]) = {} ({})\n",
                if self.rational {
                    "(n²/D)(W_100 W_010 W_001/W³)"
                } else {
                    "(n²/D)"
                },
                tuple(via),
                if nrm == via { "equal" } else { "DIFFERENT" }
            );
        }
        if !f.regular {
            out += &format!(
                "SINGULAR point: the first partials are linearly dependent, so they span no tangent {}
",
                if m == 1 { "line" } else { "plane" }
            );
        }
        out
    }

    fn json(&self) -> Json {
        to_json(self)
    }
}
