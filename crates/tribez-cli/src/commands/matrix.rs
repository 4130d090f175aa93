//! `tribez matrix`: the exact matrix that maps a parent's control points to a child's, for
//! halving (docs/theory.md §5.2) or any subpatch (§4): `c′_α = Σ_β M_{αβ} c_β`, rows and columns in
//! the canonical order of docs/theory.md §1 (the order of the Wikipedia article's 10×10 matrix).

use num_rational::BigRational;
use serde_json::Value as Json;

use super::construct::{barycentric_points, parse_edge};
use super::{CliError, Outcome};
use crate::cli::LatexOutputArgs;
use crate::report::{Render, to_json};
use tribez::constructions::halve_domains;
use tribez::constructions::subpatch_matrix;
use tribez::constructions::{Simplex, binomial};

/// The largest matrix `tribez matrix` prints: this many rows (degree 43 on a triangle).
pub const MAX_ROWS: usize = tribez::limits::MAX_MATRIX_ROWS;

/// Which matrix.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Kind {
    /// Halving along an edge (--edge I,J, --piece 1|2).
    Halve,
    /// A subpatch over the simplex given with --vertex (m+1 times).
    Subpatch,
}

// Arguments of `tribez matrix` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// halve or subpatch.
    #[arg(value_enum)]
    pub kind: Kind,
    /// The degree n.
    #[arg(long, value_parser = crate::cli::whole_number::<usize>(0, u64::MAX), allow_negative_numbers = true)]
    pub degree: usize,
    /// halve: the simplex dimension m (2 = triangle, the default; 1 curves, 3 tetrahedra).
    #[arg(long, default_value_t = 2, value_parser = crate::cli::whole_number::<usize>(1, tribez::limits::MAX_SIMPLEX_DIMENSION as u64), allow_negative_numbers = true)]
    pub simplex: usize,
    /// halve: the edge, two corner numbers (default 1,2).
    #[arg(long, value_name = "I,J", allow_hyphen_values = true)]
    pub edge: Option<String>,
    /// halve: piece 1 (default) replaces corner J by the midpoint (keeps corner I), piece 2 replaces corner I.
    #[arg(long, value_parser = crate::cli::whole_number::<u8>(1, 2), allow_negative_numbers = true)]
    pub piece: Option<u8>,
    /// subpatch: a vertex of the sub-simplex in the parent's barycentric coordinates (m+1 of them; m is their count minus one).
    #[arg(long = "vertex", value_name = "POINT", allow_hyphen_values = true)]
    pub vertices: Vec<String>,
    #[command(flatten)]
    pub out: LatexOutputArgs,
}

/// The matrix and what it is.
pub struct MatrixReport {
    title: String,
    order: Simplex,
    rows: Vec<Vec<BigRational>>,
}

/// Run `tribez matrix`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let (m, f, title) = match args.kind {
        Kind::Halve => {
            if !args.vertices.is_empty() {
                return Err(CliError::Usage("--vertex belongs to `matrix subpatch`; `matrix halve` takes --edge and --piece".into()));
            }
            let edge = args.edge.as_deref().unwrap_or("1,2");
            let piece = args.piece.unwrap_or(1);
            let m = args.simplex; // 1 to 16 (clap)
            let (i, j) = parse_edge(edge, m)?;
            let [a, b] = halve_domains(m, i, j);
            let (f, replaced) = if piece == 1 { (a, j) } else { (b, i) };
            (
                m,
                f,
                format!(
                    "halving along edge {}, piece {}: corner {} replaced by the midpoint",
                    edge,
                    piece,
                    replaced + 1
                ),
            )
        }
        Kind::Subpatch => {
            if args.edge.is_some() || args.piece.is_some() {
                return Err(CliError::Usage(
                    "--edge and --piece belong to `matrix halve`; `matrix subpatch` takes --vertex"
                        .into(),
                ));
            }
            if args.vertices.len() < 2 {
                return Err(CliError::Usage(
                    "give the sub-simplex with --vertex, m+1 times (3 for a triangle)".into(),
                ));
            }
            let m = args.vertices.len() - 1;
            let f = barycentric_points(&args.vertices, "vertex", m)?;
            (m, f, "subpatch".to_string())
        }
    };
    let n = args.degree;
    // m >= 1, so the matrix has at least n + 1 rows: cap n before computing n + m
    let len = if n >= MAX_ROWS {
        u128::MAX
    } else {
        binomial((n + m) as u64, m as u64)
    };
    if len > MAX_ROWS as u128 {
        return Err(CliError::check(
            format!("--degree {n}"),
            if len == u128::MAX {
                format!("the matrix would have more than {MAX_ROWS} rows, the limit")
            } else {
                format!("the matrix would have {len} rows, above the limit of {MAX_ROWS}")
            },
        ));
    }
    let context = args
        .vertices
        .iter()
        .map(|v| format!("--vertex {v}"))
        .collect::<Vec<_>>()
        .join(" ");
    let rows = subpatch_matrix(m, n, &f).map_err(|e| CliError::core(context, e))?;
    let title = format!(
        "{title}; degree {n} on the {m}-simplex; child = M · parent, rows and columns in canonical order"
    );
    Outcome::rendered(
        &MatrixReport {
            title,
            order: Simplex::new(m, n),
            rows,
        },
        args.out.format,
        true,
    )
}

fn key(alpha: &[u32]) -> String {
    tribez::files::index_key(alpha)
}

fn latex_number(q: &BigRational) -> String {
    if q.is_integer() {
        q.to_string()
    } else {
        let sign = if q.numer() < &0.into() { "-" } else { "" };
        format!(
            "{sign}\\frac{{{}}}{{{}}}",
            num_traits::Signed::abs(q.numer()),
            q.denom()
        )
    }
}

/// The JSON of `tribez matrix`: the multi-indices in the canonical order, and the rows.
#[derive(serde::Serialize)]
struct MatrixJson {
    order: Vec<Vec<u32>>,
    rows: Vec<Vec<String>>,
}

impl serde::Serialize for MatrixReport {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        MatrixJson {
            order: self.order.iter().map(<[u32]>::to_vec).collect(),
            rows: self
                .rows
                .iter()
                .map(|r| crate::report::strings(r))
                .collect(),
        }
        .serialize(s)
    }
}

impl Render for MatrixReport {
    fn text(&self) -> String {
        let cells: Vec<Vec<String>> = self
            .rows
            .iter()
            .map(|r| r.iter().map(ToString::to_string).collect())
            .collect();
        let width = cells
            .iter()
            .flatten()
            .map(String::len)
            .chain(self.order.iter().map(|a| key(a).len()))
            .max()
            .unwrap_or(1);
        let label = self.order.iter().map(|a| key(a).len()).max().unwrap_or(1);
        let mut out = format!(
            "{}\n{:label$}   {}\n",
            self.title,
            "",
            self.order
                .iter()
                .map(|a| format!("{:>width$}", key(a)))
                .collect::<Vec<_>>()
                .join(" ")
        );
        for (alpha, row) in self.order.iter().zip(&cells) {
            out += &format!(
                "{:>label$} [ {} ]\n",
                key(alpha),
                row.iter()
                    .map(|c| format!("{c:>width$}"))
                    .collect::<Vec<_>>()
                    .join(" ")
            );
        }
        out
    }
    fn json(&self) -> Json {
        to_json(self)
    }
    fn latex(&self) -> Option<String> {
        let rows: Vec<String> = self
            .rows
            .iter()
            .map(|r| r.iter().map(latex_number).collect::<Vec<_>>().join(" & "))
            .collect();
        Some(format!(
            "% {}\n\\begin{{pmatrix}}\n{}\n\\end{{pmatrix}}\n",
            self.title,
            rows.join(" \\\\\n")
        ))
    }
}
