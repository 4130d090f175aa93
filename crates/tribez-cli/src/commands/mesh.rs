//! `tribez mesh check`, `tribez mesh patch` and `tribez lookup`: meshes of functional Bézier
//! triangles sharing their ordinates (docs/theory.md §17, docs/guide.md "Meshes").

use std::path::{Path, PathBuf};

use num_rational::BigRational;
use serde::Serialize;
use serde_json::Value as Json;

use super::construct::PatchReport;
use super::{CliError, Outcome, parse_list};
use crate::cli::{OutputArgs, TextOrJson, examples};
use crate::report::{Render, to_json};
use tribez::ResultsChecker;
use tribez::files::read_points;
use tribez::kernels::Float;
use tribez::mesh::{Located, Mesh, MeshLines, read_mesh};

// Arguments of `tribez mesh` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// What to do with the mesh.
    #[command(subcommand)]
    pub command: MeshCommand,
}

// The subcommands of `tribez mesh` (a plain comment: see `Command`).
#[derive(Debug, clap::Subcommand)]
pub enum MeshCommand {
    /// Validate a mesh file: a conforming triangulation (counter-clockwise, no degenerate or duplicate triangles, no overlaps, no T-junctions) with every ordinate present; each problem located.
    #[command(after_help = examples::MESH_CHECK)]
    Check(CheckArgs),
    /// Write one triangle of a mesh as an ordinary functional patch file.
    #[command(after_help = examples::MESH_PATCH)]
    Patch(PatchArgs),
}

/// Arguments of `tribez mesh check`.
#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    /// The mesh file (.toml or .json).
    pub mesh: PathBuf,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// Arguments of `tribez mesh patch` (with `-o FILE` the file's extension chooses the format:
/// `.json` JSON, `.toml` TOML, anything else `--format`).
#[derive(Debug, clap::Args)]
pub struct PatchArgs {
    /// The mesh file (.toml or .json).
    pub mesh: PathBuf,
    /// The triangle (0-based, as in the file).
    #[arg(long, value_name = "K", value_parser = crate::cli::whole_number::<usize>(0, u64::MAX))]
    pub triangle: usize,
    #[command(flatten)]
    pub out: OutputArgs,
}

// Arguments of `tribez lookup` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct LookupArgs {
    /// The mesh file (.toml or .json).
    pub mesh: PathBuf,
    /// A point x,y. Repeatable.
    #[arg(long = "at", value_name = "X,Y", allow_hyphen_values = true)]
    pub at: Vec<String>,
    /// Read points x,y from a CSV or JSON file (one point per row).
    #[arg(long, value_name = "FILE")]
    pub points: Option<PathBuf>,
    /// Also run the float lookup a GPU runs in this precision (barycentric coordinates from the float point, then de Casteljau) and show its errors.
    #[arg(long, value_name = "f64|f32")]
    pub float: Option<tribez::Precision>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The outputs of the `mesh` commands.
pub fn output(args: &Args) -> &OutputArgs {
    match &args.command {
        MeshCommand::Check(a) => &a.out,
        MeshCommand::Patch(a) => &a.out,
    }
}

/// Run `tribez mesh …`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    match &args.command {
        MeshCommand::Check(a) => run_check(a),
        MeshCommand::Patch(a) => run_patch(a),
    }
}

/// Read a mesh that must be valid (every ordinate present): the first problem is the error.
pub fn read_valid_mesh(path: &Path) -> Result<(Mesh, MeshLines), CliError> {
    let (mesh, lines) = read_mesh(path)?;
    if let Some(p) = mesh.check().into_iter().next() {
        return Err(lines.locate(p).into());
    }
    Ok((mesh, lines))
}

/// The report of `tribez mesh check`.
pub struct CheckReport {
    file: String,
    mesh: Mesh,
    problems: Vec<String>,
}

fn run_check(args: &CheckArgs) -> Result<Outcome, CliError> {
    let (mesh, lines) = read_mesh(&args.mesh)?;
    let problems: Vec<String> = mesh
        .check()
        .into_iter()
        .map(|p| lines.locate(p).to_string())
        .collect();
    let ok = problems.is_empty();
    let report = CheckReport {
        file: args.mesh.display().to_string(),
        mesh,
        problems,
    };
    Outcome::rendered(&report, args.out.format, ok)
}

impl Render for CheckReport {
    fn text(&self) -> String {
        let m = &self.mesh;
        let mut out = format!(
            "{}: degree {}, {} vertices, {} edges, {} triangles, {} ordinates\n",
            self.file,
            m.degree(),
            m.vertices().len(),
            m.edges().len(),
            m.triangles().len(),
            m.ordinate_count()
        );
        if self.problems.is_empty() {
            out += "valid: a conforming counter-clockwise triangulation with every ordinate (C0 by construction)\n";
        } else {
            let n = self.problems.len();
            out += &format!(
                "INVALID: {n}{} problem{}\n",
                if n >= tribez::mesh::MAX_PROBLEMS {
                    "+"
                } else {
                    ""
                },
                if n == 1 { "" } else { "s" }
            );
            for p in &self.problems {
                out += &format!("  {p}\n");
            }
        }
        out
    }

    fn json(&self) -> Json {
        let m = &self.mesh;
        to_json(&CheckJson {
            mesh: &self.file,
            degree: m.degree(),
            vertices: m.vertices().len(),
            edges: m.edges().len(),
            triangles: m.triangles().len(),
            ordinates: m.ordinate_count(),
            valid: self.problems.is_empty(),
            problems: &self.problems,
        })
    }
}

fn run_patch(args: &PatchArgs) -> Result<Outcome, CliError> {
    let (mesh, lines) = read_valid_mesh(&args.mesh)?;
    if args.triangle >= mesh.triangles().len() {
        return Err(CliError::Usage(format!(
            "--triangle {}: {} has triangles 0 to {}",
            args.triangle,
            lines.file,
            mesh.triangles().len() - 1
        )));
    }
    let patch = mesh.triangle_patch(args.triangle)?;
    Outcome::rendered(&PatchReport::of(patch), patch_format(&args.out)?, true)
}

/// The format of the patch file `mesh patch` writes: with `-o`, chosen by the file's extension
/// as `fit -o` chooses (`.json` JSON, `.toml` TOML, either case), so that a `.json` file never
/// holds TOML; `--format json` with a `.toml` name is a usage error. Other names (and standard
/// output) take `--format`.
fn patch_format(out: &OutputArgs) -> Result<TextOrJson, CliError> {
    let ext = out
        .output
        .as_ref()
        .and_then(|p| p.extension())
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    match (ext.as_deref(), out.format) {
        (Some("json"), _) => Ok(TextOrJson::Json),
        (Some("toml"), TextOrJson::Json) => Err(CliError::Usage(format!(
            "-o {}: a .toml file, but --format json asks for JSON (name it .json, or drop --format json)",
            out.output
                .as_ref()
                .map_or(String::new(), |p| p.display().to_string())
        ))),
        (Some("toml"), _) => Ok(TextOrJson::Text),
        _ => Ok(out.format),
    }
}

/// One float lookup, judged.
struct FloatRow {
    precision: tribez::Precision,
    triangle: usize,
    point: [BigRational; 2],
    barycentric: [BigRational; 3],
    value: Option<BigRational>,
    text: (String, String),
    exact_seen: BigRational,
    ulps_seen: Option<BigRational>,
    ulps_intended: Option<BigRational>,
}

/// The result at one point.
struct LookupRow {
    label: String,
    point: [BigRational; 2],
    hits: Vec<(Located, BigRational)>,
    float: Option<FloatRow>,
}

/// The report of `tribez lookup`.
pub struct LookupReport {
    file: String,
    mesh: Mesh,
    rows: Vec<LookupRow>,
}

fn float_row<F: Float + std::ops::Div<Output = F>>(
    mesh: &Mesh,
    p: &[BigRational; 2],
    t: usize,
    intended: &BigRational,
) -> Result<FloatRow, CliError> {
    let point = [F::round(&p[0]), F::round(&p[1])];
    if !point[0].finite() || !point[1].finite() {
        return Err(CliError::Usage(format!(
            "the point ({}, {}) overflows {}",
            p[0],
            p[1],
            F::PRECISION.name()
        )));
    }
    let f = mesh
        .float_lookup::<F>(t, point)
        .map_err(tribez::Error::from)?;
    let value = f.value.exact();
    let exact = |x: F| x.exact().unwrap_or_default();
    Ok(FloatRow {
        precision: F::PRECISION,
        triangle: t,
        point: point.map(exact),
        barycentric: f.barycentric.map(exact),
        ulps_seen: value.as_ref().map(|v| F::ulps(v, &f.exact_seen)),
        ulps_intended: value.as_ref().map(|v| F::ulps(v, intended)),
        value,
        text: (f.value.decimal(), f.value.hex()),
        exact_seen: f.exact_seen,
    })
}

/// Run `tribez lookup`.
pub fn run_lookup(args: &LookupArgs) -> Result<Outcome, CliError> {
    let (mesh, _) = read_valid_mesh(&args.mesh)?;
    let mut raw = Vec::new();
    for a in &args.at {
        let p = parse_list(a, "--at")?;
        if p.len() != 2 {
            return Err(CliError::Usage(format!(
                "--at {a}: expected 2 coordinates x,y, found {}",
                p.len()
            )));
        }
        raw.push((format!("--at {a}"), p));
    }
    if let Some(path) = &args.points {
        for (i, p) in read_points(path, 2)?.into_iter().enumerate() {
            raw.push((format!("{}: point {}", path.display(), i + 1), p));
        }
    }
    if raw.is_empty() {
        return Err(CliError::Usage(
            "give at least one point with --at or --points".into(),
        ));
    }
    let mut rows = Vec::with_capacity(raw.len());
    for (label, p) in raw {
        let point = [p[0].clone(), p[1].clone()];
        let hits = mesh.lookup(&point).map_err(tribez::Error::from)?;
        let float = match (args.float, hits.first()) {
            (Some(prec), Some((l, v))) => Some(match prec {
                tribez::Precision::F64 => float_row::<f64>(&mesh, &point, l.triangle, v)?,
                tribez::Precision::F32 => float_row::<f32>(&mesh, &point, l.triangle, v)?,
            }),
            _ => None,
        };
        rows.push(LookupRow {
            label,
            point,
            hits,
            float,
        });
    }
    let all_inside = rows.iter().all(|r| !r.hits.is_empty());
    let report = LookupReport {
        file: args.mesh.display().to_string(),
        mesh,
        rows,
    };
    // A point outside the mesh has no value: reported, and the exit status is 1.
    Outcome::rendered(&report, args.out.format, all_inside)
}

fn decimal(q: &BigRational) -> String {
    tribez::format::to_decimal_string(q, 17)
}

impl Render for LookupReport {
    fn text(&self) -> String {
        let mut out = String::new();
        for r in &self.rows {
            out += &format!("{} ({}, {}):", r.label, r.point[0], r.point[1]);
            let Some((_, value)) = r.hits.first() else {
                out += " outside the mesh\n";
                continue;
            };
            out += &format!(" value {value} ≈ {}\n", decimal(value));
            for (l, _) in &r.hits {
                let t = self.mesh.triangles()[l.triangle];
                let [a, b, c] = &l.barycentric;
                out += &format!(
                    "  triangle {} ({}), λ = ({a}, {b}, {c})\n",
                    l.triangle,
                    l.position(t)
                );
            }
            if let Some(f) = &r.float {
                out += &format!(
                    "  {} lookup in triangle {}: {} ({}), {} ulp at the point as seen ({}, {}), {} ulp at the intended point\n",
                    f.precision.name(),
                    f.triangle,
                    f.text.0,
                    f.text.1,
                    f.ulps_seen.as_ref().map_or("-".into(), decimal),
                    f.point[0],
                    f.point[1],
                    f.ulps_intended.as_ref().map_or("-".into(), decimal),
                );
            }
        }
        out
    }

    fn json(&self) -> Json {
        let s = |q: &BigRational| q.to_string();
        let strings = |xs: &[BigRational]| xs.iter().map(s).collect::<Vec<_>>();
        to_json(&LookupJson {
            mesh: &self.file,
            results: self
                .rows
                .iter()
                .map(|r| LookupRowJson {
                    at: strings(&r.point),
                    inside: !r.hits.is_empty(),
                    value: r.hits.first().map(|h| s(&h.1)),
                    triangles: r
                        .hits
                        .iter()
                        .map(|(l, v)| HitJson {
                            triangle: l.triangle,
                            position: l.position(self.mesh.triangles()[l.triangle]),
                            barycentric: strings(&l.barycentric),
                            value: s(v),
                        })
                        .collect(),
                    float: r.float.as_ref().map(|f| FloatJson {
                        precision: f.precision.name(),
                        triangle: f.triangle,
                        point_as_seen: strings(&f.point),
                        barycentric: strings(&f.barycentric),
                        value: f.value.as_ref().map(s),
                        decimal: &f.text.0,
                        hex: &f.text.1,
                        exact_at_point_as_seen: s(&f.exact_seen),
                        ulps_vs_exact_at_inputs: f.ulps_seen.as_ref().map(s),
                        ulps_vs_exact_at_intended_inputs: f.ulps_intended.as_ref().map(s),
                    }),
                })
                .collect(),
        })
    }
}

/// The JSON of `tribez mesh check`.
#[derive(Serialize)]
struct CheckJson<'a> {
    mesh: &'a str,
    degree: usize,
    vertices: usize,
    edges: usize,
    triangles: usize,
    ordinates: usize,
    valid: bool,
    problems: &'a [String],
}

/// The JSON of `tribez lookup` (exact numbers as strings `p/q`).
#[derive(Serialize)]
struct LookupJson<'a> {
    mesh: &'a str,
    results: Vec<LookupRowJson<'a>>,
}

/// One point of `tribez lookup`: its value and every triangle holding it.
#[derive(Serialize)]
struct LookupRowJson<'a> {
    at: Vec<String>,
    inside: bool,
    value: Option<String>,
    triangles: Vec<HitJson>,
    /// The float lookup (`--float`); absent without it or outside the mesh.
    #[serde(skip_serializing_if = "Option::is_none")]
    float: Option<FloatJson<'a>>,
}

/// One triangle holding a point: where in it, its barycentric coordinates, the value there.
#[derive(Serialize)]
struct HitJson {
    triangle: usize,
    #[serde(rename = "where")]
    position: String,
    barycentric: Vec<String>,
    value: String,
}

/// The float lookup at a point, judged.
#[derive(Serialize)]
struct FloatJson<'a> {
    precision: &'static str,
    triangle: usize,
    point_as_seen: Vec<String>,
    barycentric: Vec<String>,
    value: Option<String>,
    decimal: &'a str,
    hex: &'a str,
    exact_at_point_as_seen: String,
    ulps_vs_exact_at_inputs: Option<String>,
    ulps_vs_exact_at_intended_inputs: Option<String>,
}

/// Run `tribez check --mesh MESH --results FILE`: other code's lookups judged row by row
/// (text, JSON and JUnit like `check --patch --results`).
pub fn run_batch(args: &super::check::Args) -> Result<Outcome, CliError> {
    use std::io::{IsTerminal, Write};
    if !args.paths.is_empty() {
        return Err(CliError::Usage(
            "give either claim files or --mesh/--results, not both".into(),
        ));
    }
    args.refuse(&["--plot", "--html", "--cartesian"], |flag| {
        format!("{flag} is not available with --mesh (the rows are x, y, value: Cartesian already)")
    })?;
    let mesh_path = args.mesh.as_ref().expect("checked by the caller");
    let results = args.results.as_ref().expect("checked by the caller");
    let (mesh, _) = read_valid_mesh(mesh_path)?;
    let options = super::batch::options(args)?;
    let checker = tribez::batch::MeshBatchChecker::new(mesh, &options)?;
    let show = std::io::stderr().is_terminal();
    let mut progress = |rows: u64, failed: u64| {
        if show {
            eprint!("\rtribez check: {rows} rows, {failed} failed");
            let _ = std::io::stderr().flush();
        }
    };
    let report = checker.check_file(results, &mesh_path.display().to_string(), &mut progress);
    if show {
        eprintln!();
    }
    let mut report = report?;
    let worst: Vec<super::baseline::Worst> = report
        .worst
        .iter()
        .map(|w| super::baseline::Worst {
            op: "lookup".into(),
            algorithm: "claimed".into(),
            precision: report.precision.map_or("exact", |p| p.name()).into(),
            ulps: w.ulps,
            at: format!("{}:{}", report.file, w.line),
        })
        .collect();
    report.baseline_regressions = super::baseline::regressions(args.baseline.as_deref(), &worst)?;
    let success = report.failed == 0 && report.baseline_regressions.is_empty();
    if let Some(path) = &args.junit {
        super::write_junit(path, &report)?;
    }
    super::baseline::record_if_clean(args.record_baseline.as_deref(), &worst, success)?;
    Outcome::rendered(&report, args.out.format, success)
}
