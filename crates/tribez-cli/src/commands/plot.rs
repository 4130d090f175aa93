//! `tribez plot`: a picture of a patch with its control net (SVG, or PNG), sampled from exact
//! values ([`crate::picture::patch`]).

use std::path::PathBuf;

use super::{CliError, Outcome, OutputTarget};
use crate::picture::patch::{Labels, MAX_SAMPLES, PlotOptions};
use crate::picture::project::{DEFAULT_VIEW, View};
use tribez::Patch;

// Arguments of `tribez plot` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (any kind: Bézier, rational, functional, S-patch).
    pub patch: PathBuf,
    /// The picture to write: FILE.svg or FILE.png (whole or not at all).
    #[arg(long, short = 'o', value_name = "FILE")]
    pub output: PathBuf,
    /// The view of a picture in R^3: azimuth and elevation in degrees (the elevation from -90
    /// to 90) [default: -60,30].
    #[arg(long, value_name = "AZIMUTH,ELEVATION", allow_hyphen_values = true)]
    pub view: Option<String>,
    /// Segments per domain edge the patch is sampled at (exact values; a curve takes 8 times
    /// as many).
    #[arg(long, value_name = "N", default_value_t = 32,
          value_parser = crate::cli::whole_number::<usize>(1, MAX_SAMPLES as u64),
          allow_negative_numbers = true)]
    pub samples: usize,
    /// Label control points with their multi-indices: the corners (`--labels`), every point
    /// (`--labels all`) or none.
    #[arg(long, value_enum, value_name = "WHICH", num_args = 0..=1,
          default_value_t = Labels::None, default_missing_value = "corners")]
    pub labels: Labels,
}

impl OutputTarget for Args {
    /// The picture is staged by [`run`]; nothing goes to standard output.
    fn output(&self) -> Option<&PathBuf> {
        None
    }
}

/// Run `tribez plot`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    crate::picture::format_of(&args.output, "-o")?;
    let view = match &args.view {
        Some(text) => View::parse(text).map_err(CliError::Usage)?,
        None => DEFAULT_VIEW,
    };
    let patch = Patch::from_file(&args.patch)?;
    let options = PlotOptions {
        view,
        samples: args.samples,
        labels: args.labels,
        title: args.patch.display().to_string(),
    };
    let svg = crate::picture::patch::plot(&patch, &options)?;
    crate::picture::stage(&args.output, &svg, "-o")?;
    Ok(Outcome {
        output: Vec::new(),
        success: true,
    })
}
