//! `tribez symbolic`: the patch as polynomials with exact coefficients.

use std::path::PathBuf;

use serde_json::{Value as Json, json};

use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::io::patch_file::read_patch;
use crate::report::Render;
use crate::symbolic::{
    Polynomial, barycentric_form, barycentric_names, cartesian_form, cartesian_names,
};

/// Arguments of `tribez symbolic`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// Use the Cartesian variables of the domain (x, y) instead of the barycentric ones (u, v, w).
    #[arg(long)]
    pub cartesian: bool,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Polynomials with their variable names.
pub struct SymbolicReport {
    file: String,
    names: Vec<String>,
    components: Vec<Polynomial>,
}

/// Run `tribez symbolic`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let patch = read_patch(&args.patch)?;
    let m = patch.net.m();
    let (names, components) = if args.cartesian {
        (
            cartesian_names(m),
            cartesian_form(&patch.net, &patch.domain_or_reference()),
        )
    } else {
        (barycentric_names(m), barycentric_form(&patch.net))
    };
    let report = SymbolicReport {
        file: args.patch.display().to_string(),
        names,
        components,
    };
    Outcome::rendered(&report, args.out.format, true)
}

impl SymbolicReport {
    fn names(&self) -> Vec<&str> {
        self.names.iter().map(String::as_str).collect()
    }
}

impl Render for SymbolicReport {
    fn text(&self) -> String {
        let names = self.names();
        let mut out = format!(
            "{}: in the variables {}\n",
            self.file,
            self.names.join(", ")
        );
        for (c, p) in self.components.iter().enumerate() {
            out += &format!("[{c}] {}\n", p.to_text(&names));
        }
        out
    }

    fn json(&self) -> Json {
        let components: Vec<Json> = self
            .components
            .iter()
            .map(|p| {
                Json::Array(
                    p.terms()
                        .into_iter()
                        .map(|(e, c)| json!({ "coefficient": c.to_string(), "exponents": e }))
                        .collect(),
                )
            })
            .collect();
        json!({ "variables": self.names, "components": components })
    }

    fn latex(&self) -> Option<String> {
        let names = self.names();
        let rows: Vec<String> = self.components.iter().map(|p| p.to_latex(&names)).collect();
        Some(format!(
            "\\begin{{pmatrix}}\n{}\n\\end{{pmatrix}}\n",
            rows.join(" \\\\\n")
        ))
    }
}
