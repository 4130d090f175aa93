//! `tribez locate` and `tribez ray`: the parameters of a planar triangle patch that map to a
//! point, and the hits of a ray on a patch in ℝ³, exactly (real algebraic parameters).

use std::path::PathBuf;

use serde_json::Value as Json;

use super::{CliError, Outcome, parse_list};
use crate::cli::OutputArgs;
use crate::report::{Render, to_json};
use tribez::Patch;
use tribez::Rational;
use tribez::algebraic::{Degenerate, Expr, Locations, RayHits, RealAlgebraic, locate, ray_hits};

// Arguments of `tribez locate` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct LocateArgs {
    /// The patch file: a triangle patch (m = 2) with points in the plane (d = 2), Bézier or rational.
    pub patch: PathBuf,
    /// The point x,y to locate.
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    pub point: String,
    /// Search the whole parameter plane, not only the closed triangle.
    #[arg(long)]
    pub anywhere: bool,
    #[command(flatten)]
    pub out: OutputArgs,
}

// Arguments of `tribez ray` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct RayArgs {
    /// The patch file: a triangle patch in ℝ³ (Bézier or rational), or a functional patch (its graph).
    pub patch: PathBuf,
    /// The ray's origin x,y,z.
    #[arg(
        long,
        value_name = "X,Y,Z",
        allow_hyphen_values = true,
        required_unless_present = "height"
    )]
    pub origin: Option<String>,
    /// The ray's direction a,b,c (not zero).
    #[arg(
        long,
        value_name = "A,B,C",
        allow_hyphen_values = true,
        required_unless_present = "height"
    )]
    pub direction: Option<String>,
    /// A functional patch's height at x,y: the vertical line through (x, y), the data lookup.
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true, conflicts_with_all = ["origin", "direction"])]
    pub height: Option<String>,
    #[command(flatten)]
    pub out: OutputArgs,
}

fn point<const N: usize>(text: &str, flag: &str) -> Result<[Rational; N], CliError> {
    let v = parse_list(text, flag)?;
    let n = v.len();
    v.try_into().map_err(|_| {
        CliError::Usage(format!(
            "{flag} {text}: expected {N} coordinates, found {n}"
        ))
    })
}

fn usage(file: &str, e: impl std::fmt::Display) -> CliError {
    CliError::Usage(format!("{file}: {e}"))
}

/// `name = p/q`, or `name ≈ 0.707… (root of … in (lo, hi))`.
pub fn alg_text(name: &str, x: &RealAlgebraic) -> String {
    match x.as_rational() {
        Some(r) => format!("{name} = {r}"),
        None => format!("{name} {}", x.to_text()),
    }
}

fn expr_text(name: &str, x: &Expr) -> String {
    match x.rational() {
        Some(r) => format!("{name} = {r}"),
        None => format!("{name} ≈ {}", x.decimal()),
    }
}

/// The report of `tribez locate`.
pub struct LocateReport {
    file: String,
    point: [Rational; 2],
    anywhere: bool,
    found: Locations,
}

/// Run `tribez locate`.
pub fn run_locate(args: &LocateArgs) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let p: [Rational; 2] = point(&args.point, "--point")?;
    let patch = Patch::from_file(&args.patch)?;
    let found = locate(&patch, &p, args.anywhere).map_err(|e| CliError::about(&file, e))?;
    Outcome::rendered(
        &LocateReport {
            file,
            point: p,
            anywhere: args.anywhere,
            found,
        },
        args.out.format,
        true,
    )
}

impl Render for LocateReport {
    fn text(&self) -> String {
        let f = &self.found;
        let mut out = format!(
            "{}: ({}, {}) {}",
            self.file,
            self.point[0],
            self.point[1],
            if let Some(d) = &f.degenerate {
                degenerate_text(d, self.anywhere, f.points.len(), |l| {
                    format!("({}, {})", alg_text("s", &l.s), alg_text("t", &l.t))
                })
            } else {
                format!(
                    "has {} parameter point{} {}\n",
                    f.points.len(),
                    if f.points.len() == 1 { "" } else { "s" },
                    if self.anywhere {
                        "in the plane"
                    } else {
                        "in the closed triangle"
                    }
                )
            }
        );
        for (k, l) in f.points.iter().enumerate() {
            out += &format!(
                "{}. {}\n   {}\n   {}{}\n",
                k + 1,
                alg_text("s", &l.s),
                alg_text("t", &l.t),
                expr_text("λ0 = 1 − s − t", &l.lambda0),
                if l.jacobian_zero && l.multiplicity == 0 {
                    "\n   the Jacobian vanishes here (a point of a curve of solutions)".to_string()
                } else if l.jacobian_zero {
                    format!(
                        "\n   the Jacobian vanishes here (multiplicity {})",
                        l.multiplicity
                    )
                } else {
                    String::new()
                }
            );
        }
        out
    }

    fn json(&self) -> Json {
        let f = &self.found;
        serde_json::to_value(LocateJson {
            patch: &self.file,
            point: [self.point[0].to_string(), self.point[1].to_string()],
            anywhere: self.anywhere,
            infinite: f.infinite,
            count: f.points.len(),
            parameters: &f.points,
            degenerate: f.degenerate.as_ref().map(|d| DegenerateJson {
                dimension: d.dimension,
                curve: &d.curve,
                boundary: &d.boundary[..],
            }),
        })
        .expect("serializable")
    }
}

/// The JSON of `tribez locate`.
#[derive(serde::Serialize)]
struct LocateJson<'a> {
    patch: &'a str,
    point: [String; 2],
    anywhere: bool,
    infinite: bool,
    count: usize,
    parameters: &'a [tribez::algebraic::Located],
    degenerate: Option<DegenerateJson<'a, &'a [tribez::algebraic::Located]>>,
}

/// The JSON of a solution set that is not finite: `{dimension, curve, boundary}`.
#[derive(serde::Serialize)]
struct DegenerateJson<'a, B: serde::Serialize> {
    dimension: usize,
    curve: &'a str,
    boundary: B,
}

/// The first line's end for a solution set that is not finite (`locate` and `ray`): the
/// dimension, the curve, the points where it meets the boundary, and the isolated points to
/// follow.
fn degenerate_text<T>(
    d: &Degenerate<T>,
    anywhere: bool,
    isolated: usize,
    point: impl Fn(&T) -> String,
) -> String {
    let region = if anywhere {
        "the plane"
    } else {
        "the closed triangle"
    };
    let mut out = if d.dimension == 2 {
        format!("is the image of every parameter point of {region} (infinitely many)\n")
    } else {
        let mut t = format!(
            "is the image of a whole curve of parameters (infinitely many): the pieces of {} = 0 in {region}\n",
            d.curve
        );
        if !d.boundary.is_empty() {
            t += &format!(
                "   meeting the boundary of the triangle at {}\n",
                d.boundary.iter().map(&point).collect::<Vec<_>>().join(", ")
            );
        }
        t
    };
    if isolated > 0 {
        out += &format!(
            "   and {isolated} isolated parameter point{} off it:\n",
            if isolated == 1 { "" } else { "s" }
        );
    }
    out
}

/// One hit in the JSON of `tribez ray`.
#[derive(serde::Serialize)]
struct HitJson<'a> {
    tau: &'a Expr,
    first: bool,
    s: &'a RealAlgebraic,
    t: &'a RealAlgebraic,
    lambda0: &'a Expr,
    kind: &'static str,
    multiplicity: usize,
}

/// The JSON of `tribez ray --height`.
#[derive(serde::Serialize)]
struct HeightJson<'a> {
    patch: &'a str,
    height_at: [String; 2],
    barycentric: Vec<String>,
    height: String,
    /// The height rounded to the nearest f64, in hexadecimal.
    f64: String,
}

/// The JSON of `tribez ray`.
#[derive(serde::Serialize)]
struct RayJson<'a> {
    patch: &'a str,
    origin: Vec<String>,
    direction: Vec<String>,
    infinite: bool,
    count: usize,
    hits: Vec<HitJson<'a>>,
    degenerate: Option<DegenerateJson<'a, Vec<HitJson<'a>>>>,
}

/// The report of `tribez ray`.
pub enum RayReport {
    /// A ray.
    Ray {
        /// The patch file.
        file: String,
        /// Origin.
        origin: [Rational; 3],
        /// Direction.
        direction: [Rational; 3],
        /// The hits.
        hits: Box<RayHits>,
    },
    /// `--height x,y` on a functional patch.
    Height {
        /// The patch file.
        file: String,
        /// The point (x, y).
        at: [Rational; 2],
        /// Its barycentric coordinates in the domain.
        lambda: Vec<Rational>,
        /// The height f(x, y).
        z: Rational,
    },
}

/// Run `tribez ray`.
pub fn run_ray(args: &RayArgs) -> Result<Outcome, CliError> {
    let file = args.patch.display().to_string();
    let patch = Patch::from_file(&args.patch)?;
    let report = if let Some(h) = &args.height {
        let at: [Rational; 2] = point(h, "--height")?;
        let (tribez::PatchKind::Functional, Some(domain)) = (patch.kind(), patch.domain()) else {
            return Err(usage(
                &file,
                format!(
                    "--height takes a functional patch, not {}",
                    patch.described()
                ),
            ));
        };
        if patch.simplex_dim() != 2 {
            return Err(usage(
                &file,
                "--height takes a functional patch over a triangle (m = 2)",
            ));
        }
        let lambda = domain
            .barycentric(&at)
            .map_err(|e| CliError::about(&file, e))?;
        if lambda.iter().any(|l| l < &Rational::from_integer(0.into())) {
            return Err(usage(
                &file,
                format!(
                    "--height {h}: the point ({}, {}) lies outside the patch's domain triangle",
                    at[0], at[1]
                ),
            ));
        }
        let z = patch.evaluate(&lambda)?[0].clone();
        RayReport::Height {
            file,
            at,
            lambda,
            z,
        }
    } else {
        let o: [Rational; 3] = point(args.origin.as_deref().unwrap_or_default(), "--origin")?;
        let d: [Rational; 3] = point(args.direction.as_deref().unwrap_or_default(), "--direction")?;
        let hits = ray_hits(&patch, &o, &d).map_err(|e| CliError::about(&file, e))?;
        RayReport::Ray {
            file,
            origin: o,
            direction: d,
            hits: Box::new(hits),
        }
    };
    Outcome::rendered(&report, args.out.format, true)
}

fn hit_json(h: &tribez::algebraic::Hit, first: bool) -> HitJson<'_> {
    HitJson {
        tau: &h.tau,
        first,
        s: &h.s,
        t: &h.t,
        lambda0: &h.lambda0,
        kind: if h.touch { "touch" } else { "cross" },
        multiplicity: h.multiplicity,
    }
}

fn tuple(xs: &[Rational]) -> String {
    tribez::format::format_tuple(xs)
}

impl Render for RayReport {
    fn text(&self) -> String {
        match self {
            RayReport::Height {
                file,
                at,
                lambda,
                z,
            } => format!(
                "{file}: height at ({}, {}) = {z} (≈ {}), barycentric {}\n",
                at[0],
                at[1],
                tribez::format::to_decimal_string(z, 17),
                tuple(lambda)
            ),
            RayReport::Ray {
                file,
                origin,
                direction,
                hits,
            } => {
                let mut out = format!(
                    "{file}: ray from {} along {}: ",
                    tuple(origin),
                    tuple(direction)
                );
                match &hits.degenerate {
                    Some(d) if d.dimension == 2 => {
                        out += "the patch lies on the ray's line (infinitely many hits)\n";
                    }
                    Some(d) => {
                        out += &format!(
                            "it runs along the surface (infinitely many hits): the parameters on the pieces of {} = 0 in the closed triangle with τ ≥ 0\n",
                            d.curve
                        );
                        if !d.boundary.is_empty() {
                            out += &format!(
                                "   ending (or touching the boundary) at {}\n",
                                d.boundary
                                    .iter()
                                    .map(|h| format!(
                                        "({}, {}, {})",
                                        expr_text("τ", &h.tau),
                                        alg_text("s", &h.s),
                                        alg_text("t", &h.t)
                                    ))
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            );
                        }
                        if !hits.hits.is_empty() {
                            out += &format!(
                                "   and {} isolated hit{} off it:\n",
                                hits.hits.len(),
                                if hits.hits.len() == 1 { "" } else { "s" }
                            );
                        }
                    }
                    None => {
                        out += &format!(
                            "{} hit{}\n",
                            hits.hits.len(),
                            if hits.hits.len() == 1 { "" } else { "s" }
                        );
                    }
                }
                for (k, h) in hits.hits.iter().enumerate() {
                    out += &format!(
                        "{}. {}{}, {}\n   {}\n   {}\n   {}\n",
                        k + 1,
                        expr_text("τ", &h.tau),
                        if k == 0 { " (first hit)" } else { "" },
                        if h.touch { "touches" } else { "crosses" },
                        alg_text("s", &h.s),
                        alg_text("t", &h.t),
                        expr_text("λ0 = 1 − s − t", &h.lambda0),
                    );
                }
                out
            }
        }
    }

    fn json(&self) -> Json {
        match self {
            RayReport::Height {
                file,
                at,
                lambda,
                z,
            } => to_json(&HeightJson {
                patch: file,
                height_at: [at[0].to_string(), at[1].to_string()],
                barycentric: lambda.iter().map(ToString::to_string).collect(),
                height: z.to_string(),
                f64: tribez::format::hex_f64(tribez::format::round_f64(z)),
            }),
            RayReport::Ray {
                file,
                origin,
                direction,
                hits,
            } => to_json(&RayJson {
                patch: file,
                origin: origin.iter().map(ToString::to_string).collect(),
                direction: direction.iter().map(ToString::to_string).collect(),
                infinite: hits.infinite,
                count: hits.hits.len(),
                hits: hits
                    .hits
                    .iter()
                    .enumerate()
                    .map(|(k, h)| hit_json(h, k == 0))
                    .collect(),
                degenerate: hits.degenerate.as_ref().map(|d| DegenerateJson {
                    dimension: d.dimension,
                    curve: &d.curve,
                    boundary: d.boundary.iter().map(|h| hit_json(h, false)).collect(),
                }),
            }),
        }
    }
}
