//! The capability traits: what a kind of patch can do.
//!
//! | trait | what | implemented by |
//! |---|---|---|
//! | [`ExactEval`] | its shape, and exact evaluation at a point of its domain | every kind |
//! | [`FloatEval`] | the float program a float implementation runs, in f64 or f32 ([`FloatProgram`]) | every kind |
//! | [`ErrorBound`] | the exact value at the inputs as the float code saw them, the condition number and the proven bound of that float program | every kind |
//! | [`Constructions`] | degree elevation, subpatches, blossoms, splitting | Bézier, functional, rational |
//!
//! A kind is one file in this folder that implements these traits for its type; the commands
//! and [`crate::judge()`] work through the traits and never name a kind.
//!
//! Floats cross these traits as `f64`: an `f32` value widens exactly, and a precision says which
//! format the numbers belong to.

use std::borrow::Cow;

use num_rational::BigRational;
use num_traits::Zero;

use crate::any_patch::AnyPatch;
use crate::derivative::TangentFrame;
use crate::domain::Domain;
use crate::error::CoreError;
use crate::exact::Algorithm;
use crate::float::Precision;
use crate::patch::{BezierPatch, ControlNet};
use crate::subdivide::HalvingOrder;
use crate::symbolic::Polynomial;

/// How a point of a kind's domain is given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum InputSpace {
    /// `m + 1` barycentric coordinates (summing to 1; any sum evaluates the homogeneous form).
    Barycentric {
        /// The simplex dimension `m`.
        m: usize,
    },
    /// Cartesian coordinates `(x, y)` in a convex polygon (S-patches).
    Polygon {
        /// The polygon's vertices, counter-clockwise.
        vertices: Vec<[BigRational; 2]>,
    },
}

impl InputSpace {
    /// How many numbers one point has.
    pub fn len(&self) -> usize {
        match self {
            InputSpace::Barycentric { m } => m + 1,
            InputSpace::Polygon { .. } => 2,
        }
    }

    /// Never true (a point has at least one coordinate).
    pub fn is_empty(&self) -> bool {
        false
    }
}

/// The sizes of a patch.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shape {
    /// Dimension `m` of the simplex of the control net (`N − 1` for an S-patch over an `N`-gon).
    pub simplex_dim: usize,
    /// Degree `n` (an S-patch's depth).
    pub degree: usize,
    /// Dimension `d` of the points.
    pub dimension: usize,
    /// How a point of the domain is given.
    pub input: InputSpace,
}

/// Exact evaluation, prepared once for many points.
pub trait PointEvaluator: Send + Sync {
    /// The exact value at `input` (the kind's coordinates, [`InputSpace`]). Barycentric
    /// coordinates that do not sum to 1 evaluate the homogeneous form.
    fn evaluate(&self, input: &[BigRational]) -> Result<Vec<BigRational>, CoreError>;

    /// The barycentric coordinates the kind computes from `input` on its way (an S-patch's
    /// Wachspress coordinates `λ(p)`); `None` when the input already is barycentric.
    fn coordinates(&self, _input: &[BigRational]) -> Result<Option<Vec<BigRational>>, CoreError> {
        Ok(None)
    }

    /// `true` when [`evaluate`](Self::evaluate) and [`coordinates`](Self::coordinates) succeed
    /// at every input of the kind's length (a polynomial kind); `false` (the default) when some
    /// inputs of that length fail, as where a rational patch's weights sum to zero or outside an
    /// S-patch's polygon. A caller may start writing a report before evaluating its last point
    /// only when this is `true`.
    fn total(&self) -> bool {
        false
    }
}

/// Capability: exact evaluation.
pub trait ExactEval {
    /// The sizes.
    fn shape(&self) -> Shape;
    /// An exact evaluator (the per-patch precomputation done once).
    fn exact_evaluator(&self) -> Box<dyn PointEvaluator + '_>;
    /// The kind's input at a Cartesian point of its domain (`m` coordinates for a simplex,
    /// converted to barycentric coordinates by Cramer's rule; `(x, y)` for an S-patch).
    fn cartesian_input(&self, x: &[BigRational]) -> Result<Vec<BigRational>, CoreError>;
    /// The patch as polynomials with exact coefficients ([`SymbolicForm`]): in the barycentric
    /// variables `u, v, w, …` of its simplex, or with `cartesian` in the Cartesian variables
    /// `x, y, …` of its domain (docs/theory.md §3, §9). A rational patch gives its numerators
    /// `Σ w_α c_α B_α` over the denominator `Σ w_α B_α` (§10); an S-patch its rational form in
    /// `x, y` whatever `cartesian` says (§12).
    fn symbolic(&self, cartesian: bool) -> SymbolicForm;
}

/// A patch as polynomials ([`ExactEval::symbolic`]): component `k` is
/// `components[k] / denominator` (no denominator: a polynomial patch).
#[derive(Clone, Debug, PartialEq)]
pub struct SymbolicForm {
    /// The variables' names, in the order of the exponents of each term.
    pub names: Vec<String>,
    /// One polynomial per coordinate of the points (numerators, for a rational form).
    pub components: Vec<Polynomial>,
    /// The common denominator of a rational patch or an S-patch.
    pub denominator: Option<Polynomial>,
}

/// Capability: the float program of a kind, as a float implementation runs it.
pub trait FloatEval {
    /// The algorithms of the float program (the first is the default).
    fn float_algorithms(&self) -> &'static [Algorithm];
    /// The name of an algorithm in reports (`"casteljau"`, `"homogeneous de Casteljau"`, …).
    fn algorithm_name(&self, algorithm: Algorithm) -> &'static str;
    /// The patch as a float program of `precision` holds it: its numbers rounded to the nearest
    /// float. An error where a rounded number overflows or the rounded data is no longer valid
    /// (a polygon no longer convex), for the kinds whose bound needs it.
    fn float_program(&self, precision: Precision) -> Result<Box<dyn FloatProgram + '_>, CoreError>;
}

/// A kind's float program in one precision ([`FloatEval::float_program`]).
pub trait FloatProgram: Send + Sync {
    /// The precision.
    fn precision(&self) -> Precision;
    /// The input as the float code sees it: every coordinate rounded to the precision (nearest,
    /// ties to even), returned as f64 (exact). An error if one overflows.
    fn round_input(&self, input: &[BigRational]) -> Result<Vec<f64>, CoreError>;
    /// Run `algorithm` at `input` (floats of the precision): the result, coordinate by
    /// coordinate, as f64 (exact).
    fn run(&self, algorithm: Algorithm, input: &[f64]) -> Vec<f64>;
    /// The exact value at the input as seen with the patch's numbers as seen (`None` where it is
    /// undefined: a vanishing denominator, a point outside the rounded polygon, a non-finite
    /// input).
    fn exact_seen(&self, input: &[f64]) -> Option<Vec<BigRational>>;
    /// The error bound of this float program, where the kind has one.
    fn error_bound(&self) -> Option<&dyn ErrorBound>;
}

/// The exact side of one float evaluation ([`ErrorBound::seen`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Seen {
    /// The exact values of the input as the float code saw it.
    pub input: Vec<BigRational>,
    /// The exact value there, with the patch's numbers as seen (`None`: undefined).
    pub exact: Option<Vec<BigRational>>,
    /// The condition number per coordinate (`None`: undefined there).
    pub condition: Option<Vec<BigRational>>,
    /// The proven a-priori bound of the absolute error per coordinate (`None`: the point lies
    /// outside the bound's hypotheses).
    pub bound: Option<Vec<BigRational>>,
    /// Does the tolerance `cond=K` mean anything for this kind (`K ε κ` with [`Self::condition`])?
    pub cond_tolerance: bool,
}

/// One float evaluation, certified ([`ErrorBound::certify`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FloatCase {
    /// The exact values of the input as the float code saw it.
    pub input: Vec<BigRational>,
    /// The float result (as f64, exact).
    pub y: Vec<f64>,
    /// The exact value at the input as seen (`None`: not measured).
    pub exact: Option<Vec<BigRational>>,
    /// The condition number per coordinate (`None`: not measured).
    pub condition: Option<Vec<BigRational>>,
    /// The proven bound per coordinate against which `y` is judged (`None`: not judged).
    pub bound: Option<Vec<BigRational>>,
    /// Outside the bound's hypotheses (overflow, underflow, an uncertain denominator sign):
    /// counted, not judged.
    pub outside: bool,
    /// A failure the kind found itself (a case its proven bound rules out).
    pub failure: Option<String>,
    /// The intermediate coordinates the float program computes (an S-patch's `λ̂`), measured.
    pub coordinates: Option<CoordinateCase>,
}

/// Intermediate float coordinates, their exact values and their proven bound.
#[derive(Clone, Debug, PartialEq)]
pub struct CoordinateCase {
    /// The float coordinates (as f64).
    pub values: Vec<f64>,
    /// Their exact values.
    pub exact: Vec<BigRational>,
    /// Their proven absolute bound, where judged.
    pub bound: Option<Vec<BigRational>>,
}

/// How a kind's bound is explained in a certification report.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundText {
    /// The bound column's label (`None`: `γ_K` with `K` the algorithm's roundings).
    pub label: Option<String>,
    /// The explanation line under the table.
    pub note: &'static str,
    /// What the points not judged are (`"{count} points not judged: {outside}"`); `None`: the
    /// generic sentence.
    pub outside: Option<&'static str>,
    /// The intermediate coordinates ([`FloatCase::coordinates`]), if any.
    pub coordinates: Option<CoordinateText>,
}

/// How intermediate coordinates are named in a certification report.
#[derive(Clone, Debug, PartialEq)]
pub struct CoordinateText {
    /// All of them (`"Wachspress coordinates λ̂"`).
    pub all: &'static str,
    /// One of them, before "error" in a violation (`"Wachspress coordinate "`).
    pub one: &'static str,
}

/// Capability: the proven error bound of a float program.
pub trait ErrorBound: Send + Sync {
    /// The exact value at `input` as seen, the condition numbers and the a-priori bound of
    /// `algorithm` there.
    fn seen(&self, algorithm: Algorithm, input: &[f64]) -> Seen;
    /// [`ErrorBound::seen`] at an exact input that need not be floats of the precision: the
    /// exact barycentric coordinates `λ` of a float Cartesian point (docs/guide.md §7), where
    /// the value, `Σ|c_α| B_α(|λ|)` and the a-priori bound are those at `λ` itself. For a
    /// kind whose input is Cartesian (an S-patch) an input of floats is [`ErrorBound::seen`]'s;
    /// at other points its bound is not given (`Seen::bound` `None`).
    fn seen_exact(&self, algorithm: Algorithm, input: &[BigRational]) -> Seen;
    /// Run `algorithm` at `input` and judge its result against the proven bound.
    fn certify(&self, algorithm: Algorithm, input: &[f64]) -> FloatCase;
    /// The bound explained, for `algorithm`.
    fn text(&self, algorithm: Algorithm) -> BoundText;
    /// Why a point can lie outside the bound's hypotheses ([`Seen::bound`] is `None`), for
    /// the message of `tolerance = "bound"` there.
    fn no_bound_reason(&self) -> &'static str {
        "the algorithm's a-priori bound does not apply (Kε ≥ 1)"
    }
}

/// A piece of a construction: a patch of the parent's kind over a sub-simplex of the parent's
/// domain.
#[derive(Clone, Debug, PartialEq)]
pub struct SubPatch {
    /// Which piece: for [`Split::At`] piece `s` replaces corner `s` by the point (0-based); for
    /// [`Split::Halve`] 0 keeps corner `i`, 1 keeps corner `j`; for [`Split::Midpoints`] the
    /// corner pieces 0, 1, 2, then the middle one, 3.
    pub index: usize,
    /// Its simplex: `m + 1` barycentric points of the parent's domain, in order.
    pub domain_in_parent: Vec<Vec<BigRational>>,
    /// The patch, of the parent's kind and name. A parent with a Cartesian domain gives a piece
    /// whose domain is the image of [`SubPatch::domain_in_parent`], so that the piece takes the
    /// same Cartesian points to the same values as the parent.
    pub patch: AnyPatch,
}

/// How [`Constructions::pieces`] cuts a patch (docs/theory.md §5).
#[derive(Clone, Debug, PartialEq)]
pub enum Split<'a> {
    /// At a barycentric point `t`: the `m + 1` faces of the de Casteljau pyramid, piece `s`
    /// replacing corner `s` by `t`. A piece whose simplex is degenerate (`t_s = 0`: `t` lies on
    /// the facet opposite corner `s`) is left out.
    At(&'a [BigRational]),
    /// The four-way split of a triangle at its edge midpoints.
    Midpoints,
    /// Halving along the edge between corners `i` and `j` (0-based): by blossoms (`None`) or by
    /// the in-place additions and halvings of the Wikipedia article "Bézier triangle" in the
    /// given order (`Some`); the result is the same.
    Halve {
        /// The edge's corners, 0-based.
        edge: (usize, usize),
        /// `None`: blossoms; `Some(order)`: add-and-halve.
        add_and_halve: Option<HalvingOrder>,
    },
}

/// `input` must have `m + 1` coordinates.
pub(crate) fn check_len(input: &[BigRational], expected: usize) -> Result<(), CoreError> {
    if input.len() == expected {
        Ok(())
    } else {
        Err(CoreError::WrongLength {
            what: "point".into(),
            expected,
            found: input.len(),
        })
    }
}

/// The Cartesian domain of a piece over the sub-simplex `f` (barycentric points) of a parent
/// with domain `parent`: the image of `f`; the reference domain stays the reference domain.
fn piece_domain(
    parent: &Option<Domain>,
    f: Option<&[Vec<BigRational>]>,
) -> Result<Option<Domain>, CoreError> {
    match (parent, f) {
        (Some(d), Some(f)) => Ok(Some(Domain::new(
            f.iter().map(|v| d.cartesian(v)).collect(),
        )?)),
        (d, _) => Ok(d.clone()),
    }
}

/// The patch `like` with the net `net` over the sub-simplex `f` of its domain (`None`: the same
/// domain); its name is kept.
pub(crate) fn with_net(
    like: &BezierPatch,
    net: ControlNet<BigRational>,
    f: Option<&[Vec<BigRational>]>,
) -> Result<BezierPatch, CoreError> {
    Ok(BezierPatch {
        name: like.name.clone(),
        net,
        domain: piece_domain(&like.domain, f)?,
    })
}

/// Capability: the constructions, exact, returning patches of the same kind.
///
/// Elevation, subpatches and every split are linear in the control points, so a kind gives the
/// net they run on ([`Constructions::linear_net`]: the control points, or a rational patch's
/// homogeneous net `(w c, w)`) and the way back ([`Constructions::with_linear_net`]); the
/// constructions themselves are written once, here.
pub trait Constructions {
    /// The net the linear constructions run on: the control points, or for a rational patch
    /// the homogeneous net `(w_α c_α, w_α)` (docs/theory.md §10).
    fn linear_net(&self) -> Cow<'_, ControlNet<BigRational>>;
    /// The patch of this kind whose [`Constructions::linear_net`] is `net`, over the
    /// sub-simplex `f` of this patch's domain (`None`: the same domain), with this patch's name.
    fn with_linear_net(
        &self,
        net: ControlNet<BigRational>,
        f: Option<&[Vec<BigRational>]>,
    ) -> Result<AnyPatch, CoreError>;
    /// Degree elevation by `r` (docs/theory.md §6).
    fn elevate(&self, r: usize) -> Result<AnyPatch, CoreError> {
        self.with_linear_net(crate::elevate::elevate(&self.linear_net(), r), None)
    }
    /// The subpatch over the simplex with the given barycentric vertices (docs/theory.md §4):
    /// `c′_α = b[f_0^{α_0}, …, f_m^{α_m}]`. Its Cartesian domain, if the patch has one, is the
    /// image of the vertices.
    fn subpatch(&self, vertices: &[Vec<BigRational>]) -> Result<AnyPatch, CoreError> {
        let net = crate::blossom::subpatch(&self.linear_net(), vertices)?;
        self.with_linear_net(net, Some(vertices))
    }
    /// The pieces of a split (docs/theory.md §5), each over its sub-simplex.
    fn pieces(&self, split: &Split<'_>) -> Result<Vec<SubPatch>, CoreError> {
        use crate::subdivide as sd;
        let net = self.linear_net();
        let m = net.m();
        let pieces: Vec<(usize, sd::Piece<BigRational>)> = match split {
            Split::At(t) => {
                check_len(t, m + 1)?;
                sd::split_at(&net, t)
                    .into_iter()
                    .enumerate()
                    .filter(|(s, _)| !t[*s].is_zero())
                    .map(|(s, n)| {
                        let domain_in_parent = sd::replaced(m, s, t);
                        (
                            s,
                            sd::Piece {
                                domain_in_parent,
                                net: n,
                            },
                        )
                    })
                    .collect()
            }
            Split::Midpoints => sd::midpoint_split(&net)?.into_iter().enumerate().collect(),
            Split::Halve {
                edge: (i, j),
                add_and_halve,
            } => {
                sd::check_edge(m, i.saturating_add(1), j.saturating_add(1))?;
                let halves = match add_and_halve {
                    None => sd::halve(&net, *i, *j),
                    Some(order) => {
                        let [a, b] = sd::halve_domains(m, *i, *j);
                        [
                            sd::Piece {
                                domain_in_parent: a,
                                net: sd::add_and_halve(&net, *i, *j, *order),
                            },
                            sd::Piece {
                                domain_in_parent: b,
                                net: sd::add_and_halve(&net, *j, *i, *order),
                            },
                        ]
                    }
                };
                halves.into_iter().enumerate().collect()
            }
        };
        pieces
            .into_iter()
            .map(|(index, p)| {
                let patch = self.with_linear_net(p.net, Some(&p.domain_in_parent))?;
                Ok(SubPatch {
                    index,
                    domain_in_parent: p.domain_in_parent,
                    patch,
                })
            })
            .collect()
    }
    /// Split at the barycentric point `t` into `m + 1` pieces (piece `s` replaces corner `s`
    /// by `t`); a point on a facet is an error ([`CoreError::SplitOnFace`]), since a piece
    /// would be degenerate ([`Constructions::pieces`] leaves such pieces out instead).
    fn split_at(&self, t: &[BigRational]) -> Result<Vec<AnyPatch>, CoreError> {
        if let Some(s) = t.iter().position(Zero::is_zero) {
            return Err(CoreError::SplitOnFace { corner: s + 1 });
        }
        Ok(self
            .pieces(&Split::At(t))?
            .into_iter()
            .map(|p| p.patch)
            .collect())
    }
    /// The blossom `b[u_1, …, u_n]` at `n` barycentric arguments.
    fn blossom(&self, args: &[Vec<BigRational>]) -> Result<Vec<BigRational>, CoreError>;
    /// The graph `(x, y, f(x, y))` of a functional patch as a parametric patch, control points
    /// `(ξ_α, b_α)` at the Bézier abscissae (docs/theory.md §13); `None` for the kinds that are
    /// not functions.
    fn graph(&self) -> Option<Result<AnyPatch, CoreError>> {
        None
    }
    /// The domain simplex (the patch's own, or the reference simplex), for Cartesian points and
    /// directions.
    fn domain(&self) -> Domain;
    /// The mixed directional derivative `D_{d^{(1)}} ⋯ D_{d^{(r)}} p(λ)` at the barycentric point
    /// `at` along the barycentric `directions` (docs/theory.md §7). A polynomial patch refuses
    /// an order above its degree ([`CoreError::OrderTooHigh`]); a rational patch takes any
    /// order (Leibniz's rule, §10).
    fn derivative(
        &self,
        at: &[BigRational],
        directions: &[&[BigRational]],
    ) -> Result<Vec<BigRational>, CoreError>;
    /// The tangent frame at the barycentric point `at` over [`Self::domain`]: the de Casteljau
    /// points of level `n − 1`, the partial derivatives and the normal (docs/theory.md §7).
    fn tangent_frame(&self, at: &[BigRational]) -> Result<TangentFrame, CoreError>;
    /// The patch's points are projections `X/W` of a homogeneous net (rational patches): the
    /// de Casteljau points of a tangent frame are projected ones.
    fn projected(&self) -> bool {
        false
    }
}

impl<T: Constructions + ?Sized> Constructions for &T {
    fn linear_net(&self) -> Cow<'_, ControlNet<BigRational>> {
        (**self).linear_net()
    }
    fn with_linear_net(
        &self,
        net: ControlNet<BigRational>,
        f: Option<&[Vec<BigRational>]>,
    ) -> Result<AnyPatch, CoreError> {
        (**self).with_linear_net(net, f)
    }
    fn blossom(&self, args: &[Vec<BigRational>]) -> Result<Vec<BigRational>, CoreError> {
        (**self).blossom(args)
    }
    fn graph(&self) -> Option<Result<AnyPatch, CoreError>> {
        (**self).graph()
    }
    fn domain(&self) -> Domain {
        (**self).domain()
    }
    fn derivative(
        &self,
        at: &[BigRational],
        directions: &[&[BigRational]],
    ) -> Result<Vec<BigRational>, CoreError> {
        (**self).derivative(at, directions)
    }
    fn tangent_frame(&self, at: &[BigRational]) -> Result<TangentFrame, CoreError> {
        (**self).tangent_frame(at)
    }
    fn projected(&self) -> bool {
        (**self).projected()
    }
}

/// The floats of a precision, narrowed from the f64 that carries them across these traits.
pub(crate) trait Narrow: crate::float::Float + std::ops::Div<Output = Self> {
    /// `x` as this float (exact for a value of this precision; else rounded to nearest).
    fn narrow(x: f64) -> Self;
}

impl Narrow for f64 {
    fn narrow(x: f64) -> Self {
        x
    }
}

impl Narrow for f32 {
    fn narrow(x: f64) -> Self {
        x as f32
    }
}

/// Round `input` to `F` (nearest, ties to even) as f64; an error naming the precision if one
/// overflows.
pub(crate) fn round_input<F: Narrow>(input: &[BigRational]) -> Result<Vec<f64>, CoreError> {
    input
        .iter()
        .map(|q| {
            let x = F::round(q);
            if x.finite() {
                Ok(x.widen())
            } else {
                Err(CoreError::Overflows {
                    what: "an input",
                    precision: F::PRECISION.name(),
                })
            }
        })
        .collect()
}

/// The floats `input` (f64 carriers) as `F`.
pub(crate) fn narrowed<F: Narrow>(input: &[f64]) -> Vec<F> {
    input.iter().map(|&x| F::narrow(x)).collect()
}

/// The exact values of floats (`None` if one is not finite).
pub(crate) fn exact_values<F: crate::float::Float>(xs: &[F]) -> Option<Vec<BigRational>> {
    xs.iter().map(|x| x.exact()).collect()
}
