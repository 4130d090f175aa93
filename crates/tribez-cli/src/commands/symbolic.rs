//! `tribez symbolic`: the patch as polynomials with exact coefficients.
//!
//! Every kind gives its form through [`tribez::ExactEval::symbolic`]: a rational patch its
//! numerators `Σ w_α c_α B_α` and the common denominator `Σ w_α B_α`; an S-patch its rational
//! form in `x, y` (docs/theory.md §12): numerators `Σ_α P_α C(d;α) Π ω_i^{α_i}` over `(Σ ω)^d`.

use std::path::PathBuf;

use serde::Serialize;
use serde_json::Value as Json;

use super::{CliError, Outcome};
use crate::cli::LatexOutputArgs;
use crate::report::{Render, to_json};
use tribez::Patch;
use tribez::constructions::Polynomial;

// Arguments of `tribez symbolic` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (.toml or .json).
    pub patch: PathBuf,
    /// Use the Cartesian variables of the domain (x, y) instead of the barycentric ones (u, v, w).
    #[arg(long)]
    pub cartesian: bool,
    #[command(flatten)]
    pub out: LatexOutputArgs,
}

/// Polynomials with their variable names.
pub struct SymbolicReport {
    file: String,
    names: Vec<String>,
    components: Vec<Polynomial>,
    /// The common denominator of a rational patch or an S-patch.
    denominator: Option<Polynomial>,
}

/// Run `tribez symbolic`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let patch = Patch::from_file(&args.patch)?;
    let form = patch.exact().symbolic(args.cartesian);
    let report = SymbolicReport {
        file: args.patch.display().to_string(),
        names: form.names,
        components: form.components,
        denominator: form.denominator,
    };
    Outcome::rendered(&report, args.out.format, true)
}

impl SymbolicReport {
    fn names(&self) -> Vec<&str> {
        self.names.iter().map(String::as_str).collect()
    }
}

/// One term of a polynomial in JSON: its exact coefficient and the exponents of the variables.
#[derive(Serialize)]
struct TermJson<'a> {
    coefficient: String,
    exponents: &'a [u32],
}

/// The JSON of `tribez symbolic`: the variables, each component as its list of terms, and the
/// common denominator (rational patches, S-patches) as text.
#[derive(Serialize)]
struct SymbolicJson<'a> {
    variables: &'a [String],
    components: Vec<Vec<TermJson<'a>>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    denominator: Option<String>,
}

impl Serialize for SymbolicReport {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        SymbolicJson {
            variables: &self.names,
            components: self
                .components
                .iter()
                .map(|p| {
                    p.terms()
                        .into_iter()
                        .map(|(e, c)| TermJson {
                            coefficient: c.to_string(),
                            exponents: e,
                        })
                        .collect()
                })
                .collect(),
            denominator: self.denominator.as_ref().map(|d| d.to_text(&self.names())),
        }
        .serialize(s)
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
        if let Some(d) = &self.denominator {
            out += &format!("denominator {}\n", d.to_text(&names));
        }
        out
    }

    fn json(&self) -> Json {
        to_json(self)
    }

    fn latex(&self) -> Option<String> {
        let names = self.names();
        let rows: Vec<String> = self.components.iter().map(|p| p.to_latex(&names)).collect();
        let matrix = format!(
            "\\begin{{pmatrix}}\n{}\n\\end{{pmatrix}}",
            rows.join(" \\\\\n")
        );
        Some(match &self.denominator {
            Some(d) => format!("\\frac{{1}}{{{}}}\n{matrix}\n", d.to_latex(&names)),
            None => format!("{matrix}\n"),
        })
    }
}
