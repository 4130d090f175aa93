//! Exact least-squares fits of scattered data by a mesh of functional Bézier triangles
//! (docs/theory.md §18), the fit that Wolfe's blog "Bezier Triangles" calls challenging: for
//! fixed vertices it is a linear least-squares problem, solved here exactly.
//!
//! Given a [`Mesh`] (its vertices, triangles and degree `n`; its ordinates, if any, are
//! ignored) and data rows `(x_i, y_i, v_i)`, [`fit`] finds the ordinates `b` that minimise
//! `Σ_i (f_b(x_i, y_i) − v_i)²` over the C0 spline space (every ordinate free: neighbours share
//! their edge ordinates) or over its C1 subspace (the μ rule across every interior edge,
//! [`c1_constraints`]). Row `i` of the design matrix holds the Bernstein values
//! `B^n_α(λ(x_i, y_i))` of the triangle containing the point at the global ordinates
//! [`Mesh::global_index`] of that triangle.
//!
//! ```
//! use tribez::fit::{FitOptions, fit, parse_data};
//! use tribez::mesh::Mesh;
//! use tribez::parse_rational as q;
//! let v = |x: &str, y: &str| [q(x).unwrap(), q(y).unwrap()];
//! // One linear triangle and three data values at its corners, plus one at the centroid that
//! // disagrees: the plane through the corners moves by a least-squares compromise.
//! let mesh = Mesh::new(vec![v("0", "0"), v("1", "0"), v("0", "1")], vec![[0, 1, 2]], 1).unwrap();
//! let data = parse_data("0,0,0\n1,0,0\n0,1,0\n1/3,1/3,1\n", "d.csv").unwrap();
//! let f = fit(&mesh, &data, "d.csv", &FitOptions::default()).unwrap();
//! // By symmetry every ordinate is one c; the residuals are c at the corners and c − 1 at the
//! // centroid, and d/dc [3c² + (c − 1)²] = 0 gives c = 1/4.
//! assert_eq!(f.mesh.ordinates()[0], Some(q("1/4").unwrap()));
//! assert_eq!(f.rss, q("3/4").unwrap()); // 3·(1/16) + (3/4)²
//! ```

mod c1;
mod data;
mod judge;
mod minnorm;
#[cfg(test)]
mod tests;

use std::fmt;
use std::str::FromStr;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use serde::Serialize;

pub use c1::{InteriorEdge, c1_constraints, interior_edges, mu};
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub use data::fuzz_fit_data;
pub use data::{DataPoint, MAX_DATA_ROWS, parse_data, read_data};
pub use judge::{FloatFitOptions, FloatFitReport, OrdinateError, judge_float_fit};

use crate::linalg::LinalgError;
use crate::linalg::exact::IntVec;
use crate::linalg::lsq::{BlockSums, NormalEquations, Regularize, solve_least_squares};
use crate::mesh::{Mesh, MeshError, OrdinateId};
use crate::number::{format_rational, ratio, to_decimal_string};
use crate::simplex::{Simplex, multinomial};

/// The most ordinates a fit solves for (the exact solver's dense modular elimination takes
/// `O(N³)` word operations and `N²` words of memory).
pub const MAX_FIT_UNKNOWNS: usize = 2000;

/// The function space of a fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Smoothness {
    /// Continuous: every ordinate of the mesh free.
    #[default]
    C0,
    /// Continuously differentiable: the μ rule across every interior edge.
    C1,
}

impl fmt::Display for Smoothness {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Smoothness::C0 => "c0",
            Smoothness::C1 => "c1",
        })
    }
}

impl FromStr for Smoothness {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.trim().to_ascii_lowercase().as_str() {
            "c0" => Ok(Smoothness::C0),
            "c1" => Ok(Smoothness::C1),
            _ => Err(format!("`{s}` is not a smoothness (expected c0 or c1)")),
        }
    }
}

/// How to fit.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FitOptions {
    /// Fit at this degree instead of the mesh's own.
    pub degree: Option<usize>,
    /// C0 (default) or C1.
    pub smoothness: Smoothness,
    /// When the data do not determine every ordinate: `false` (default) is an error naming
    /// them; `true` gives the least-squares solution of least Euclidean norm of the ordinate
    /// vector.
    pub regularize: bool,
}

/// Why a fit has no answer. `Display` is one line.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FitError {
    /// A data point outside every triangle of the mesh.
    #[error("{file}:{line}: the point ({x}, {y}) lies outside the mesh")]
    Outside {
        /// The data file.
        file: String,
        /// Its line (1-based).
        line: usize,
        /// `x`, exact.
        x: String,
        /// `y`, exact.
        y: String,
    },
    /// The data do not determine every ordinate (the least-squares solution is not unique).
    #[error(
        "the data do not determine {} of the {unknowns} ordinates (rank {rank} of {dimension}): {}; add data near them, or regularize (--regularize) for the minimum-norm fit",
        undetermined.len(),
        list(undetermined)
    )]
    RankDeficient {
        /// The ordinates left free, in the global numbering's order.
        undetermined: Vec<OrdinateId>,
        /// The rank of the reduced normal matrix.
        rank: usize,
        /// The dimension of the space searched.
        dimension: usize,
        /// The number of ordinates.
        unknowns: usize,
    },
    /// More ordinates than [`MAX_FIT_UNKNOWNS`].
    #[error("{unknowns} ordinates to fit, above the limit of {max} for an exact fit")]
    TooManyUnknowns {
        /// The ordinates of the mesh at the fit's degree.
        unknowns: usize,
        /// [`MAX_FIT_UNKNOWNS`].
        max: usize,
    },
    /// The mesh is not a valid triangulation, or the degree is out of range.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// The solver failed to certify a solution (not expected).
    #[error(transparent)]
    Solver(LinalgError),
    /// A tolerance that does not apply to a fit ([`judge_float_fit`] takes `cond=K`, `cond`,
    /// `abs=E`, `rel=E` and `exact`).
    #[error(
        "tolerance `{tolerance}` does not apply to fits (use cond=K, cond, abs=E, rel=E or exact)"
    )]
    Tolerance {
        /// The tolerance as written.
        tolerance: String,
    },
    /// The float fit judged ([`judge_float_fit`]) lacks an ordinate.
    #[error("{file}: the fitted mesh has no value for {id}")]
    MissingOrdinate {
        /// The mesh file.
        file: String,
        /// The ordinate.
        id: OrdinateId,
    },
}

fn list(ids: &[OrdinateId]) -> String {
    const SHOWN: usize = 8;
    let mut s: Vec<String> = ids.iter().take(SHOWN).map(ToString::to_string).collect();
    if ids.len() > SHOWN {
        s.push(format!("and {} more", ids.len() - SHOWN));
    }
    s.join("; ")
}

/// One located data row: the triangle, `β` with `B^n_α(λ) = β_α / den` in canonical order.
#[derive(Debug, Clone)]
struct DesignRow {
    line: usize,
    triangle: usize,
    beta: Vec<BigInt>,
    den: BigInt,
    value: BigRational,
}

/// The located data and the normal equations of a fit at the mesh's degree.
#[derive(Debug, Clone)]
pub(crate) struct Design {
    rows: Vec<DesignRow>,
    indices: Vec<Vec<usize>>,
    /// The normal equations, accumulated when first asked for ([`Design::normal`]).
    normal: std::cell::OnceCell<NormalEquations>,
    unknowns: usize,
    /// One entry per distinct data point: its first row (in `rows`), the sum of its values and
    /// how many rows it has.
    distinct: Vec<(usize, BigRational, usize)>,
    /// An upper bound of the rank of the design matrix: `Σ_t min(distinct points located in t,
    /// (n+1)(n+2)/2)` (the rows of a triangle touch only its ordinates; equal points give equal
    /// rows).
    rank_bound: usize,
}

impl Design {
    /// Locate every data point exactly and compute its row of the design matrix (the normal
    /// equations are accumulated on first use, [`Design::normal`]).
    pub(crate) fn new(mesh: &Mesh, data: &[DataPoint], file: &str) -> Result<Design, FitError> {
        let n = mesh.degree();
        let unknowns = mesh.ordinate_count();
        if unknowns > MAX_FIT_UNKNOWNS {
            return Err(FitError::TooManyUnknowns {
                unknowns,
                max: MAX_FIT_UNKNOWNS,
            });
        }
        let simplex = Simplex::new(2, n);
        let multi: Vec<BigInt> = simplex
            .iter()
            .map(|a| BigInt::from(multinomial(a)))
            .collect();
        let k = simplex.len();
        let mut rows = Vec::with_capacity(data.len());
        let mut seen: std::collections::HashMap<(BigRational, BigRational), usize> =
            std::collections::HashMap::new();
        let mut distinct: Vec<(usize, BigRational, usize)> = Vec::new();
        let mut per_triangle = vec![0usize; mesh.triangles().len()];
        for p in data {
            let point = [p.x.clone(), p.y.clone()];
            let located = mesh.locate(&point);
            let Some(l) = located.first() else {
                return Err(FitError::Outside {
                    file: file.to_string(),
                    line: p.line,
                    x: format_rational(&p.x),
                    y: format_rational(&p.y),
                });
            };
            // λ_i = l_i / D with integers l_i, D > 0.
            let d = l
                .barycentric
                .iter()
                .fold(BigInt::one(), |acc, q| acc.lcm(q.denom()));
            let li: Vec<BigInt> = l
                .barycentric
                .iter()
                .map(|q| q.numer() * (&d / q.denom()))
                .collect();
            let powers: Vec<Vec<BigInt>> = li.iter().map(|x| crate::exact::powers(x, n)).collect();
            let beta: Vec<BigInt> = simplex
                .iter()
                .zip(&multi)
                .map(|(a, c)| {
                    c * &powers[0][a[0] as usize]
                        * &powers[1][a[1] as usize]
                        * &powers[2][a[2] as usize]
                })
                .collect();
            let den = num_traits::pow(d, n);
            match seen.entry((p.x.clone(), p.y.clone())) {
                std::collections::hash_map::Entry::Occupied(e) => {
                    let (_, sum, count) = &mut distinct[*e.get()];
                    *sum += &p.value;
                    *count += 1;
                }
                std::collections::hash_map::Entry::Vacant(e) => {
                    e.insert(distinct.len());
                    distinct.push((rows.len(), p.value.clone(), 1));
                    per_triangle[l.triangle] += 1;
                }
            }
            rows.push(DesignRow {
                line: p.line,
                triangle: l.triangle,
                beta,
                den,
                value: p.value.clone(),
            });
        }
        let indices: Vec<Vec<usize>> = (0..mesh.triangles().len())
            .map(|t| mesh.local_indices(t))
            .collect();
        let rank_bound: usize = per_triangle.iter().map(|&c| c.min(k)).sum();
        Ok(Design {
            rows,
            indices,
            normal: std::cell::OnceCell::new(),
            unknowns,
            distinct,
            rank_bound,
        })
    }

    /// The normal equations, accumulated exactly on first use, one block per triangle over
    /// integers ([`BlockSums`]).
    pub(crate) fn normal(&self) -> &NormalEquations {
        self.normal.get_or_init(|| {
            let k = self.indices.first().map_or(0, Vec::len);
            let mut blocks: Vec<Option<BlockSums>> = vec![None; self.indices.len()];
            for r in &self.rows {
                blocks[r.triangle]
                    .get_or_insert_with(|| BlockSums::new(k))
                    .add(&r.beta, &r.den, &r.value);
            }
            let mut normal = NormalEquations::new(self.unknowns);
            for (t, b) in blocks.iter().enumerate() {
                if let Some(b) = b {
                    normal.add_block(b, &self.indices[t]);
                }
            }
            normal
        })
    }

    /// The largest absolute residual `|f_x(x_i, y_i) − v_i|` and its line (the first of equal
    /// ones), exactly.
    pub(crate) fn max_residual(&self, x: &[BigRational]) -> Option<(BigRational, usize)> {
        let xv = IntVec::from_rationals(x);
        // Residual of a row: s/(den·X.den) − v = (s·v.d − v.n·den·X.den) / (den·X.den·v.d),
        // compared by cross-multiplication and reduced once at the end.
        let mut best: Option<(BigInt, BigInt, usize)> = None;
        for r in &self.rows {
            let idx = &self.indices[r.triangle];
            let s: BigInt = r
                .beta
                .iter()
                .zip(idx)
                .filter(|(b, _)| !b.is_zero())
                .map(|(b, &g)| b * &xv.num[g])
                .sum();
            let dd = &r.den * &xv.den;
            let num = (s * r.value.denom() - r.value.numer() * &dd).abs();
            let den = dd * r.value.denom();
            let better = match &best {
                None => true,
                Some((bn, bd, _)) => &num * bd > bn * &den,
            };
            if better {
                best = Some((num, den, r.line));
            }
        }
        best.map(|(n, d, line)| (ratio(n, d), line))
    }
}

/// An exact least-squares fit ([`fit`]).
#[derive(Debug, Clone)]
pub struct Fit {
    /// The fitted mesh (every ordinate given).
    pub mesh: Mesh,
    /// C0 or C1.
    pub smoothness: Smoothness,
    /// The number of data rows.
    pub rows: usize,
    /// The number of ordinates.
    pub unknowns: usize,
    /// The number of linear constraints (C1: `n` per interior edge).
    pub constraints: usize,
    /// The dimension of the space searched (the ordinates less the rank of the constraints).
    pub dimension: usize,
    /// The rank of the reduced normal matrix (`dimension` when the fit is unique).
    pub rank: usize,
    /// The ordinates the data do not determine (empty unless regularised).
    pub undetermined: Vec<OrdinateId>,
    /// Whether the minimum-norm solution was asked for.
    pub regularized: bool,
    /// The residual sum of squares, exact.
    pub rss: BigRational,
    /// The largest absolute residual, exact, and the line of the data where it occurs.
    pub max_residual: Option<(BigRational, usize)>,
}

/// The exact least-squares fit of `data` (from `file`, named in errors) on `mesh` (module
/// documentation). The mesh's geometry is checked first ([`Mesh::check_geometry`]).
///
/// # Errors
/// [`FitError::Outside`] naming the first row outside the mesh; [`FitError::RankDeficient`]
/// naming the ordinates the data do not determine (unless `options.regularize`);
/// [`FitError::Mesh`] for an invalid mesh or degree; [`FitError::TooManyUnknowns`].
pub fn fit(
    mesh: &Mesh,
    data: &[DataPoint],
    file: &str,
    options: &FitOptions,
) -> Result<Fit, FitError> {
    let mesh = prepare(mesh, options.degree)?;
    let design = Design::new(&mesh, data, file)?;
    let constraints = match options.smoothness {
        Smoothness::C0 => Vec::new(),
        Smoothness::C1 => c1_constraints(&mesh),
    };
    let regularize = if options.regularize {
        Regularize::MinimumNorm
    } else {
        Regularize::No
    };
    let unknowns = mesh.ordinate_count();
    if constraints.is_empty() && design.rank_bound < unknowns {
        // Rank-deficient for certain: the minimum-norm fit and the undetermined ordinates from
        // the rows (minnorm.rs), an m × m problem where the normal equations' kernel is large.
        if let Some(m) = minnorm::minimum_norm_by_rows(&design, unknowns) {
            let undetermined: Vec<OrdinateId> = m
                .undetermined
                .iter()
                .map(|&g| mesh.ordinate_id(g))
                .collect();
            if !options.regularize {
                return Err(FitError::RankDeficient {
                    undetermined,
                    rank: m.rank,
                    dimension: unknowns,
                    unknowns,
                });
            }
            let max_residual = design.max_residual(&m.x);
            return Ok(Fit {
                mesh: mesh.with_ordinates(m.x)?,
                smoothness: options.smoothness,
                rows: data.len(),
                unknowns,
                constraints: 0,
                dimension: unknowns,
                rank: m.rank,
                undetermined,
                regularized: true,
                rss: m.rss,
                max_residual,
            });
        }
    }
    let sol =
        solve_least_squares(design.normal(), &constraints, regularize).map_err(|e| match e {
            LinalgError::RankDeficient {
                undetermined,
                rank,
                dimension,
            } => FitError::RankDeficient {
                undetermined: undetermined.iter().map(|&g| mesh.ordinate_id(g)).collect(),
                rank,
                dimension,
                unknowns,
            },
            e => FitError::Solver(e),
        })?;
    let max_residual = design.max_residual(&sol.x);
    let undetermined = sol
        .undetermined
        .iter()
        .map(|&g| mesh.ordinate_id(g))
        .collect();
    Ok(Fit {
        mesh: mesh.with_ordinates(sol.x)?,
        smoothness: options.smoothness,
        rows: data.len(),
        unknowns,
        constraints: constraints.len(),
        dimension: sol.dimension,
        rank: sol.rank,
        undetermined,
        regularized: options.regularize,
        rss: sol.rss,
        max_residual,
    })
}

/// The mesh at the fit's degree, its geometry checked.
pub(crate) fn prepare(mesh: &Mesh, degree: Option<usize>) -> Result<Mesh, FitError> {
    let mesh = match degree {
        Some(n) => mesh.with_degree(n)?,
        None => mesh.clone(),
    };
    let mut problems = Vec::new();
    mesh.check_geometry(&mut problems);
    if let Some(p) = problems.into_iter().next() {
        return Err(FitError::Mesh(p));
    }
    Ok(mesh)
}

/// Significant digits of the decimals in reports.
pub const DECIMAL_DIGITS: usize = 17;

/// An exact number for a report: lowest terms `p/q`, and a decimal of [`DECIMAL_DIGITS`]
/// significant digits.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct ExactNumber {
    /// `p/q` in lowest terms (or an integer).
    pub exact: String,
    /// The value rounded to 17 significant digits.
    pub decimal: String,
}

impl ExactNumber {
    /// Of `q`.
    pub fn of(q: &BigRational) -> Self {
        ExactNumber {
            exact: format_rational(q),
            decimal: to_decimal_string(q, DECIMAL_DIGITS),
        }
    }

    /// The exact text if at most `limit` characters, else a note of its size.
    pub fn exact_or_size(&self, limit: usize) -> String {
        if self.exact.len() <= limit {
            self.exact.clone()
        } else {
            format!(
                "{} digits",
                self.exact.chars().filter(char::is_ascii_digit).count()
            )
        }
    }
}

/// One fitted ordinate in a report.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct OrdinateValue {
    /// Where it sits ([`OrdinateId`]'s text).
    pub id: String,
    /// Its value.
    pub value: ExactNumber,
}

/// The report of a fit (`tribez fit --format json`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct FitReport {
    /// The data file.
    pub data: String,
    /// The mesh file.
    pub mesh: String,
    /// The degree.
    pub degree: usize,
    /// `"c0"` or `"c1"`.
    pub smoothness: Smoothness,
    /// Data rows.
    pub rows: usize,
    /// Triangles.
    pub triangles: usize,
    /// Ordinates.
    pub ordinates: usize,
    /// Linear constraints (C1).
    pub constraints: usize,
    /// Dimension of the space searched.
    pub dimension: usize,
    /// Rank of the reduced normal matrix.
    pub rank: usize,
    /// Whether the minimum-norm solution was asked for.
    pub regularized: bool,
    /// The ordinates the data do not determine (regularised fits only).
    pub undetermined: Vec<String>,
    /// `Σ (f(x_i, y_i) − v_i)²`.
    pub residual_sum_of_squares: ExactNumber,
    /// `max |f(x_i, y_i) − v_i|`.
    pub max_abs_residual: Option<ExactNumber>,
    /// The line of the data where the largest absolute residual occurs (the first such).
    pub max_abs_residual_line: Option<usize>,
    /// The fitted ordinates, in the global numbering.
    pub fitted: Vec<OrdinateValue>,
}

impl Fit {
    /// The report, naming the data and mesh files.
    pub fn report(&self, data: &str, mesh: &str) -> FitReport {
        FitReport {
            data: data.to_string(),
            mesh: mesh.to_string(),
            degree: self.mesh.degree(),
            smoothness: self.smoothness,
            rows: self.rows,
            triangles: self.mesh.triangles().len(),
            ordinates: self.unknowns,
            constraints: self.constraints,
            dimension: self.dimension,
            rank: self.rank,
            regularized: self.regularized,
            undetermined: self.undetermined.iter().map(ToString::to_string).collect(),
            residual_sum_of_squares: ExactNumber::of(&self.rss),
            max_abs_residual: self.max_residual.as_ref().map(|(q, _)| ExactNumber::of(q)),
            max_abs_residual_line: self.max_residual.as_ref().map(|(_, l)| *l),
            fitted: self
                .mesh
                .ordinates()
                .iter()
                .enumerate()
                .map(|(g, q)| OrdinateValue {
                    id: self.mesh.ordinate_id(g).to_string(),
                    value: ExactNumber::of(q.as_ref().unwrap_or(&BigRational::zero())),
                })
                .collect(),
        }
    }
}

impl FitReport {
    /// The text of `tribez fit`.
    pub fn text(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
        let _ = writeln!(
            s,
            "fit of {} ({}) on {} ({}, degree {}), {}: {} ordinates",
            self.data,
            plural(self.rows, "row"),
            self.mesh,
            plural(self.triangles, "triangle"),
            self.degree,
            self.smoothness.to_string().to_uppercase(),
            self.ordinates
        );
        if self.constraints > 0 || self.dimension != self.ordinates {
            let _ = writeln!(
                s,
                "  {} smoothness constraints: {} degrees of freedom",
                self.constraints, self.dimension
            );
        }
        if self.undetermined.is_empty() {
            let _ = writeln!(
                s,
                "  rank {}: every ordinate determined by the data",
                self.rank
            );
        } else {
            let _ = writeln!(
                s,
                "  rank {} of {}: minimum-norm solution; {} ordinates not determined by the data: {}",
                self.rank,
                self.dimension,
                self.undetermined.len(),
                self.undetermined.join("; ")
            );
        }
        let _ = writeln!(
            s,
            "residual sum of squares: {} (exact {})",
            self.residual_sum_of_squares.decimal,
            self.residual_sum_of_squares.exact_or_size(60)
        );
        if let (Some(m), Some(line)) = (&self.max_abs_residual, self.max_abs_residual_line) {
            let _ = writeln!(
                s,
                "largest absolute residual: {} at line {line} (exact {})",
                m.decimal,
                m.exact_or_size(60)
            );
        }
        let _ = writeln!(
            s,
            "fitted ordinates (17 significant digits; exact in --format json and the fitted mesh):"
        );
        for o in &self.fitted {
            let _ = writeln!(s, "  {}: {}", o.id, o.value.decimal);
        }
        s
    }
}
