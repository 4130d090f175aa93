//! `tribez tangent`: the de Casteljau intermediate points, partial derivatives and normal at a point.

use std::path::PathBuf;

use num_rational::BigRational;
use serde_json::{Map, Value as Json, json};

use super::{CliError, Outcome, at_point, points_patch};
use crate::cli::OutputArgs;
use crate::report::{Render, json_rationals, tuple};
use tribez::hazmat::derivative::{TangentFrame, tangent_frame};
use tribez::hazmat::io::patch_file::{index_key, read_any_patch};
use tribez::hazmat::symbolic::cartesian_names;

/// Arguments of `tribez tangent`.
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
    let (patch, rational) = points_patch(&file, "tangent", read_any_patch(&args.patch)?)?;
    let m = patch.net.m();
    let domain = patch.domain_or_reference();
    let at = at_point(&args.at, args.cartesian, &domain, m)?;
    let frame = match &rational {
        None => tangent_frame(&patch.net, &domain, &at),
        Some(r) => r.tangent_frame(&domain, &at),
    }
    .map_err(|e| CliError::core(&file, e))?;
    let rational = rational.is_some();
    Outcome::rendered(
        &TangentReport {
            file,
            rational,
            degree: patch.net.degree(),
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
        let f = &self.frame;
        let m = self.at.len() - 1;
        let mut inter = Map::new();
        for (k, p) in f.intermediate.iter().enumerate() {
            inter.insert(self.unit_key(k), json_rationals(p));
        }
        let mut partials = Map::new();
        for (name, p) in cartesian_names(m).iter().zip(&f.partials) {
            partials.insert(name.clone(), json_rationals(p));
        }
        let opt =
            |v: &Option<Vec<BigRational>>| v.as_ref().map_or(Json::Null, |x| json_rationals(x));
        json!({
            "patch": self.file,
            "at": json_rationals(&self.at),
            "point": json_rationals(&f.point),
            "intermediate": inter,
            "partials": partials,
            "normal": opt(&f.normal),
            "normal_from_intermediate": opt(&f.normal_from_intermediate),
            "regular": f.regular,
        })
    }
}
