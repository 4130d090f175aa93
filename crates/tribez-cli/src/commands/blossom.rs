//! `tribez blossom`: the blossom (polar form) `b[u_1, …, u_n]` of a patch (docs/theory.md §4).
//!
//! Through the kind's [`tribez::Constructions::blossom`]: for a rational patch the rational
//! blossom `X[u_1, …, u_n] / W[u_1, …, u_n]`, the blossom of the homogeneous net `(w c, w)`
//! projected; an error where the weight blossom `W` is 0.

use std::path::PathBuf;

use num_rational::BigRational;
use serde_json::Value as Json;

use super::construct::barycentric_points;
use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::{Render, to_json, tuple};
use tribez::CoreError;
use tribez::Patch;

// Arguments of `tribez blossom` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json; polynomial or rational).
    pub patch: PathBuf,
    /// One argument of the blossom: a barycentric point (`1/2,1/2,0`). Give exactly n (the degree).
    #[arg(long = "arg", value_name = "POINT", allow_hyphen_values = true)]
    pub args: Vec<String>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The blossom value; JSON `{"point": [..]}`.
#[derive(serde::Serialize)]
pub struct BlossomReport {
    #[serde(skip)]
    args: Vec<Vec<BigRational>>,
    #[serde(serialize_with = "crate::report::ser::rationals")]
    point: Vec<BigRational>,
}

/// Run `tribez blossom`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = Patch::from_file(&args.patch)?;
    let constructions = super::constructions(&patch, &file, "blossom")?;
    let n = patch.degree();
    if args.args.len() != n {
        return Err(CliError::core(
            "--arg",
            CoreError::BlossomArity {
                degree: n,
                found: args.args.len(),
            },
        ));
    }
    let points = barycentric_points(&args.args, "arg", patch.simplex_dim())?;
    let point = constructions
        .blossom(&points)
        .map_err(|e| CliError::core("--arg", e))?;
    Outcome::rendered(
        &BlossomReport {
            args: points,
            point,
        },
        args.out.format,
        true,
    )
}

impl Render for BlossomReport {
    fn text(&self) -> String {
        format!(
            "b[{}] = {}\n",
            self.args
                .iter()
                .map(|a| tuple(a))
                .collect::<Vec<_>>()
                .join(", "),
            tuple(&self.point)
        )
    }
    fn json(&self) -> Json {
        to_json(self)
    }
}
