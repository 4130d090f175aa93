//! `tribez derivative`: exact directional derivatives of any order `r <= n` at a point.

use std::path::PathBuf;

use num_rational::BigRational;
use serde_json::Value as Json;

use super::{CliError, Outcome, at_point, check_direction, parse_list};
use crate::cli::OutputArgs;
use crate::report::{Render, to_json, tuple};
use tribez::CoreError;
use tribez::Patch;

// Arguments of `tribez derivative` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// The point: barycentric coordinates summing to 1 (`1/2,1/3,1/6`), or Cartesian with --cartesian.
    #[arg(long = "at", value_name = "POINT", allow_hyphen_values = true)]
    pub at: String,
    /// The point is Cartesian (converted by the domain, Cramer's rule).
    #[arg(long)]
    pub cartesian: bool,
    /// A barycentric direction (m+1 components summing to 0, e.g. `1,0,-1`). Repeat for higher orders.
    #[arg(long = "dir", value_name = "D", allow_hyphen_values = true)]
    pub dir: Vec<String>,
    /// A Cartesian direction vector (m components, e.g. `1,-2`), converted by the domain (Floater's notes eqs. 9-10). Repeatable; mixes with --dir.
    #[arg(long = "vector", value_name = "X,Y", allow_hyphen_values = true)]
    pub vector: Vec<String>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The derivative report.
pub struct DerivativeReport {
    file: String,
    at: Vec<BigRational>,
    directions: Vec<Vec<BigRational>>,
    value: Vec<BigRational>,
}

/// The JSON of `tribez derivative`.
#[derive(serde::Serialize)]
struct DerivativeJson<'a> {
    patch: &'a str,
    at: Vec<String>,
    order: usize,
    directions: Vec<Vec<String>>,
    value: Vec<String>,
}

impl serde::Serialize for DerivativeReport {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use crate::report::strings;
        DerivativeJson {
            patch: &self.file,
            at: strings(&self.at),
            order: self.directions.len(),
            directions: self.directions.iter().map(|d| strings(d)).collect(),
            value: strings(&self.value),
        }
        .serialize(s)
    }
}

/// Run `tribez derivative`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = Patch::from_file(&args.patch)?;
    let constructions = super::constructions(&patch, &file, "derivative")?;
    let m = patch.simplex_dim();
    let domain = constructions.domain();
    let at = at_point(&args.at, args.cartesian, &domain, m)?;
    let mut directions = Vec::new();
    for d in &args.dir {
        let v = parse_list(d, "--dir")?;
        check_direction(&v, m, "direction").map_err(|e| CliError::core(format!("--dir {d}"), e))?;
        directions.push(v);
    }
    for x in &args.vector {
        let v = parse_list(x, "--vector")?;
        directions.push(
            domain
                .direction(&v)
                .map_err(|e| CliError::core(format!("--vector {x}"), e))?,
        );
    }
    if directions.is_empty() {
        return Err(CliError::Usage(
            "give at least one direction with --dir (barycentric) or --vector (Cartesian)".into(),
        ));
    }
    let refs: Vec<&[BigRational]> = directions.iter().map(Vec::as_slice).collect();
    // an order above the degree concerns the patch; anything else the point
    let value = constructions.derivative(&at, &refs).map_err(|e| match e {
        CoreError::OrderTooHigh { .. } => CliError::core(&file, e),
        e => CliError::core(format!("--at {}", args.at), e),
    })?;
    Outcome::rendered(
        &DerivativeReport {
            file,
            at,
            directions,
            value,
        },
        args.out.format,
        true,
    )
}

impl Render for DerivativeReport {
    fn text(&self) -> String {
        let dirs = self
            .directions
            .iter()
            .map(|d| tuple(d))
            .collect::<Vec<_>>()
            .join(", ");
        format!(
            "{}: derivative of order {} along the barycentric direction(s) {dirs}\nat {}: {}\n",
            self.file,
            self.directions.len(),
            tuple(&self.at),
            tuple(&self.value)
        )
    }

    fn json(&self) -> Json {
        to_json(self)
    }
}
