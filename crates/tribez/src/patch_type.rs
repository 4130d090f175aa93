//! [`Patch`]: one type for every kind of patch, and the newtypes that keep the simplex
//! dimension `m` and the degree `n` apart.

use std::path::Path;

use num_rational::BigRational;

use crate::any_patch::AnyPatch;
use crate::api_error::{Error, Refusal};
use crate::capability::{Constructions, ExactEval, FloatEval, InputSpace, Shape};
use crate::domain::Domain;
use crate::error::CoreError;
use crate::float::Float;
use crate::patch::{BezierPatch, ControlNet};
use crate::rational::RationalPatch;
use crate::simplex::Simplex;
use crate::spatch::{Polygon, SPatch};

/// The dimension `m` of the domain simplex (2: a triangle, 3: a tetrahedron, …).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SimplexDim(pub usize);

/// The degree `n` of a patch (an S-patch's depth).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Degree(pub usize);

/// The kinds of patch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PatchKind {
    /// A polynomial Bézier simplex.
    Bezier,
    /// A rational Bézier simplex (a weight per control point).
    Rational,
    /// A functional (nonparametric) patch: one ordinate per control point over a domain.
    Functional,
    /// An S-patch over a convex polygon (Loop and DeRose).
    SPatch,
}

impl PatchKind {
    /// `"Bézier"`, `"rational"`, `"functional"` or `"S-patch"`.
    pub fn name(self) -> &'static str {
        match self {
            PatchKind::Bezier => "Bézier",
            PatchKind::Rational => "rational",
            PatchKind::Functional => "functional",
            PatchKind::SPatch => "S-patch",
        }
    }

    /// `"Bézier patches"`, `"rational patches"`, …: the plural, for messages.
    pub fn plural(self) -> &'static str {
        match self {
            PatchKind::Bezier => "Bézier patches",
            PatchKind::Rational => "rational patches",
            PatchKind::Functional => "functional patches",
            PatchKind::SPatch => "S-patches",
        }
    }
}

impl std::fmt::Display for PatchKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A patch of any kind: a Bézier simplex of any dimension, a rational or functional patch, or
/// an S-patch. What it can do is reached through the capability traits
/// ([`Patch::exact`], [`Patch::float`], [`Patch::constructions`]).
///
/// ```
/// use tribez::{Degree, Patch, SimplexDim, parse_rational};
/// let q = |s: &str| parse_rational(s).unwrap();
/// let p = |xs: [&str; 3]| xs.map(q).to_vec();
/// // Finn's worked example: control points 200, 110, 020, 101, 011, 002
/// let patch = Patch::bezier(SimplexDim(2), Degree(2), vec![
///     p(["0", "0", "0"]), p(["1", "0", "2"]), p(["0", "2", "0"]),
///     p(["0", "1", "0"]), p(["1", "1", "1"]), p(["0", "2", "1"]),
/// ]).unwrap();
/// let value = patch.evaluate(&[q("1/2"), q("1/3"), q("1/6")]).unwrap();
/// assert_eq!(value, [q("4/9"), q("5/9"), q("29/36")]);
/// // a wrong number of control points is an error, never a panic: degree 3 needs C(5, 2) = 10
/// assert!(Patch::bezier(SimplexDim(2), Degree(3), vec![p(["0", "0", "0"])]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Patch {
    any: AnyPatch,
}

/// Is `found` the number `C(n + m, m)` of control points of degree `n` over the `m`-simplex?
/// Computed without overflow and in at most `found` steps, so no size the caller did not
/// allocate is ever allocated or looped over.
fn check_count(m: usize, n: usize, found: usize, what: &'static str) -> Result<(), Error> {
    if m == 0 {
        return Err(CoreError::SimplexDimZero.into());
    }
    let too_many = || {
        Error::Core(CoreError::TooFew {
            degree: n,
            m,
            what,
            found,
        })
    };
    // C(n + m, m) >= m + 1 when n >= 1
    if n >= 1 && m >= found {
        return Err(too_many());
    }
    let mut c: u128 = 1;
    for i in 1..=m as u128 {
        c = c.checked_mul(n as u128 + i).ok_or_else(too_many)? / i;
    }
    match usize::try_from(c) {
        Ok(expected) if expected == found => Ok(()),
        Ok(expected) => Err(Error::Refusal(Refusal::Size {
            what,
            expected,
            found,
        })),
        Err(_) => Err(too_many()),
    }
}

/// The net of `points` (all of one dimension `d ≥ 1`) over the `m`-simplex of degree `n`.
fn net(
    m: usize,
    n: usize,
    points: Vec<Vec<BigRational>>,
) -> Result<ControlNet<BigRational>, Error> {
    check_count(m, n, points.len(), "control points")?;
    let d = points[0].len();
    if d == 0 {
        return Err(Error::Refusal(Refusal::Size {
            what: "coordinates of a control point",
            expected: 1,
            found: 0,
        }));
    }
    if let Some(p) = points.iter().find(|p| p.len() != d) {
        return Err(Error::Refusal(Refusal::Size {
            what: "coordinates of a control point",
            expected: d,
            found: p.len(),
        }));
    }
    let coords = points.into_iter().flatten().collect();
    Ok(ControlNet::new(Simplex::new(m, n), d, coords))
}

impl Patch {
    /// A Bézier simplex: `C(n + m, m)` control points in the canonical order (multi-indices
    /// `α = (α_0, …, α_m)`, `|α| = n`, in decreasing lexicographic order: for a quadratic
    /// triangle 200, 110, 020, 101, 011, 002 … as in the patch files), all with the same
    /// number `d ≥ 1` of coordinates. A wrong count is an error.
    pub fn bezier(m: SimplexDim, n: Degree, points: Vec<Vec<BigRational>>) -> Result<Patch, Error> {
        Ok(Patch {
            any: AnyPatch::Bezier(BezierPatch::new(net(m.0, n.0, points)?)),
        })
    }

    /// A rational Bézier simplex: the points as for [`Patch::bezier`] and one weight each.
    pub fn rational(
        m: SimplexDim,
        n: Degree,
        points: Vec<Vec<BigRational>>,
        weights: Vec<BigRational>,
    ) -> Result<Patch, Error> {
        let net = net(m.0, n.0, points)?;
        if weights.len() != net.len() {
            return Err(Error::Refusal(Refusal::Size {
                what: "weights",
                expected: net.len(),
                found: weights.len(),
            }));
        }
        Ok(Patch {
            any: AnyPatch::Rational(RationalPatch::new(BezierPatch::new(net), weights)),
        })
    }

    /// A functional patch: one ordinate per multi-index (canonical order) over the domain
    /// simplex with the given `m + 1` vertices in `ℝ^m`.
    pub fn functional(
        domain: Vec<Vec<BigRational>>,
        n: Degree,
        ordinates: Vec<BigRational>,
    ) -> Result<Patch, Error> {
        let domain = Domain::new(domain)?;
        let points = ordinates.into_iter().map(|z| vec![z]).collect();
        let mut patch = BezierPatch::new(net(domain.m(), n.0, points)?);
        patch.domain = Some(domain);
        Ok(Patch {
            any: AnyPatch::Functional(patch),
        })
    }

    /// An S-patch of depth `n` over the strictly convex polygon with the given vertices
    /// (counter-clockwise, `N ≥ 3`): control points indexed by `α ∈ ℕ^N`, `|α| = n`, in the
    /// canonical order.
    pub fn spatch(
        polygon: Vec<[BigRational; 2]>,
        n: Degree,
        points: Vec<Vec<BigRational>>,
    ) -> Result<Patch, Error> {
        let polygon = Polygon::new(polygon.into_iter().map(Vec::from).collect())?;
        let net = net(polygon.len() - 1, n.0, points)?;
        Ok(Patch {
            any: AnyPatch::SPatch(SPatch::new(polygon, net)?),
        })
    }

    /// Read a patch file (`.toml` or `.json`) of any kind.
    pub fn from_file(path: impl AsRef<Path>) -> Result<Patch, Error> {
        Ok(crate::io::patch_file::read_any_patch(path.as_ref())?.into())
    }

    /// Parse a patch file's text in TOML.
    pub fn from_toml(text: &str) -> Result<Patch, Error> {
        let doc = crate::io::tree::Document::parse_toml("<toml>", text)?;
        Ok(crate::io::patch_file::any_patch_from_document(&doc, &doc.root, "")?.into())
    }

    /// Parse a patch file's text in JSON.
    pub fn from_json(text: &str) -> Result<Patch, Error> {
        let doc = crate::io::tree::Document::parse_json("<json>", text)?;
        Ok(crate::io::patch_file::any_patch_from_document(&doc, &doc.root, "")?.into())
    }

    /// The patch file's text in TOML (reads back to an equal patch).
    pub fn to_toml(&self) -> String {
        crate::io::patch_file::any_patch_to_toml(&self.any)
    }

    /// The patch file's text in JSON.
    pub fn to_json(&self) -> String {
        self.to_json_value().to_string()
    }

    /// The patch file in JSON, as a JSON value (to embed in a larger document).
    ///
    /// ```
    /// let p = tribez::Patch::from_toml("degree = 1\n[control_points]\n\"1,0\" = [\"0\"]\n\"0,1\" = [\"1/2\"]\n").unwrap();
    /// let json = p.to_json_value();
    /// assert_eq!(json["degree"], 1);
    /// assert_eq!(json.to_string(), p.to_json());
    /// assert_eq!(tribez::Patch::from_json(&p.to_json()).unwrap(), p);
    /// ```
    pub fn to_json_value(&self) -> serde_json::Value {
        crate::io::patch_file::any_patch_to_json(&self.any)
    }

    /// Parse a patch file's text in TOML, naming it `file` in error messages (as
    /// [`Patch::from_toml`], which names it `<toml>`).
    pub fn from_toml_named(text: &str, file: &str) -> Result<Patch, Error> {
        let doc = crate::io::tree::Document::parse_toml(file, text)?;
        Ok(crate::io::patch_file::any_patch_from_document(&doc, &doc.root, "")?.into())
    }

    /// Parse a patch file's text in JSON, naming it `file` in error messages (as
    /// [`Patch::from_json`], which names it `<json>`).
    ///
    /// ```
    /// let e = tribez::Patch::from_json_named("{\"degree\": 1}", "mine.json").unwrap_err();
    /// assert!(e.to_string().starts_with("mine.json"), "{e}");
    /// ```
    pub fn from_json_named(text: &str, file: &str) -> Result<Patch, Error> {
        let doc = crate::io::tree::Document::parse_json(file, text)?;
        Ok(crate::io::patch_file::any_patch_from_document(&doc, &doc.root, "")?.into())
    }

    /// Its kind.
    pub fn kind(&self) -> PatchKind {
        match &self.any {
            AnyPatch::Bezier(_) => PatchKind::Bezier,
            AnyPatch::Rational(_) => PatchKind::Rational,
            AnyPatch::Functional(_) => PatchKind::Functional,
            AnyPatch::SPatch(_) => PatchKind::SPatch,
        }
    }

    /// The name the file gave it.
    pub fn name(&self) -> Option<&str> {
        match &self.any {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => p.name.as_deref(),
            AnyPatch::Rational(r) => r.patch.name.as_deref(),
            AnyPatch::SPatch(s) => s.name.as_deref(),
        }
    }

    /// Capability: exact evaluation (every kind).
    pub fn exact(&self) -> &dyn ExactEval {
        match &self.any {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => p,
            AnyPatch::Rational(r) => r,
            AnyPatch::SPatch(s) => s,
        }
    }

    /// Capability: the float program and its error bound (every kind today).
    pub fn float(&self) -> Option<&dyn FloatEval> {
        Some(match &self.any {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => p,
            AnyPatch::Rational(r) => r,
            AnyPatch::SPatch(s) => s,
        })
    }

    /// Capability: the constructions (Bézier, functional and rational patches; not S-patches).
    pub fn constructions(&self) -> Option<Box<dyn Constructions + '_>> {
        crate::capability::constructions(&self.any)
    }

    /// Its sizes.
    pub fn shape(&self) -> Shape {
        self.exact().shape()
    }

    /// Degree `n` (an S-patch's depth).
    pub fn degree(&self) -> usize {
        self.shape().degree
    }

    /// Dimension `d` of its points (1 for a functional patch).
    pub fn dimension(&self) -> usize {
        self.shape().dimension
    }

    /// Dimension `m` of the simplex of its control net (`N − 1` for an S-patch over an `N`-gon).
    pub fn simplex_dim(&self) -> usize {
        self.shape().simplex_dim
    }

    /// The exact value at a point: barycentric coordinates summing to 1 (`m + 1` of them), or
    /// for an S-patch a Cartesian point `(x, y)` of its polygon.
    pub fn evaluate(&self, input: &[BigRational]) -> Result<Vec<BigRational>, Error> {
        if let InputSpace::Barycentric { m } = self.shape().input {
            crate::domain::check_barycentric(input, m, "point")?;
        }
        Ok(self.exact().exact_evaluator().evaluate(input)?)
    }

    /// The exact value of the homogeneous form at barycentric coordinates of any sum (for an
    /// S-patch the same as [`Patch::evaluate`]).
    pub fn evaluate_homogeneous(&self, input: &[BigRational]) -> Result<Vec<BigRational>, Error> {
        Ok(self.exact().exact_evaluator().evaluate(input)?)
    }

    /// `"a Bézier patch"`, `"a rational patch"`, `"a functional patch"` or `"an S-patch"`: its
    /// kind with the article, for messages.
    ///
    /// ```
    /// let p = tribez::Patch::from_toml("degree = 1\n[control_points]\n\"1,0\" = [\"0\"]\n\"0,1\" = [\"1\"]\n").unwrap();
    /// assert_eq!(p.described(), "a Bézier patch");
    /// ```
    pub fn described(&self) -> &'static str {
        self.any.described()
    }

    /// Give it a name (or none), as a patch file's `name`.
    pub fn set_name(&mut self, name: Option<String>) {
        *self.any.name_mut() = name;
    }

    /// Its control net: the control points `c_α` in the canonical order (a rational patch's
    /// points, not its homogeneous net; an S-patch's points indexed by `α ∈ ℕ^N`).
    ///
    /// ```
    /// // the line segment from 0 to 1, degree 1: c_10 = 0, c_01 = 1
    /// let p = tribez::Patch::from_toml("degree = 1\n[control_points]\n\"1,0\" = [\"0\"]\n\"0,1\" = [\"1\"]\n").unwrap();
    /// let net = p.control_net();
    /// assert_eq!((net.m(), net.degree(), net.dim(), net.len()), (1, 1, 1, 2));
    /// let q = |s: &str| tribez::parse_rational(s).unwrap();
    /// assert_eq!(net.coords(), [q("0"), q("1")]);
    /// ```
    pub fn control_net(&self) -> &ControlNet<BigRational> {
        match &self.any {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => &p.net,
            AnyPatch::Rational(r) => &r.patch.net,
            AnyPatch::SPatch(s) => &s.net,
        }
    }

    /// A rational patch's weights `w_α` (canonical order); `None` for the other kinds.
    pub fn weights(&self) -> Option<&[BigRational]> {
        match &self.any {
            AnyPatch::Rational(r) => Some(&r.weights),
            _ => None,
        }
    }

    /// An S-patch's polygon (its vertices, counter-clockwise); `None` for the other kinds.
    pub fn polygon(&self) -> Option<&[[BigRational; 2]]> {
        match &self.any {
            AnyPatch::SPatch(s) => Some(s.polygon.vertices()),
            _ => None,
        }
    }

    /// The domain simplex of the kinds over a simplex: the file's `domain`, or the reference
    /// simplex (vertices `e_1, …, e_m` and the origin) when there
    /// is none; `None` for an S-patch (see [`Patch::polygon`]).
    pub fn domain(&self) -> Option<Domain> {
        match &self.any {
            AnyPatch::Bezier(p) | AnyPatch::Functional(p) => Some(p.domain_or_reference()),
            AnyPatch::Rational(r) => Some(r.patch.domain_or_reference()),
            AnyPatch::SPatch(_) => None,
        }
    }

    /// The vertices of its domain in the plane or space of its inputs: the domain simplex's
    /// `m + 1` vertices, or an S-patch's polygon's `N` vertices.
    pub fn domain_vertices(&self) -> Vec<Vec<BigRational>> {
        match &self.any {
            AnyPatch::SPatch(s) => s.polygon.vertices().iter().map(|v| v.to_vec()).collect(),
            _ => self
                .domain()
                .map(|d| d.vertices().to_vec())
                .unwrap_or_default(),
        }
    }

    /// The polynomial patch, for the kinds that are one (Bézier and functional patches).
    pub fn polynomial(&self) -> Option<&BezierPatch> {
        self.any.polynomial()
    }

    /// tribez's own float path in `F` (`f64` or `f32`), without certification: de Casteljau on
    /// the control net rounded to `F` (rounded once, here), a rational patch by homogeneous de
    /// Casteljau and one division, an S-patch by float Wachspress coordinates then de Casteljau.
    /// Numbers beyond `F` become infinities (the float programs of [`Patch::float`] refuse them
    /// instead).
    ///
    /// ```
    /// // the quadratic curve with control points 0, 1, 0: p(λ) = 2 λ_0 λ_1; in f64 every step of
    /// // de Casteljau at (1/2, 1/2) is exact: (0 + 1)/2, (1 + 0)/2, then 1/2
    /// let p = tribez::Patch::from_toml(
    ///     "degree = 2\n[control_points]\n\"2,0\" = [\"0\"]\n\"1,1\" = [\"1\"]\n\"0,2\" = [\"0\"]\n",
    /// )
    /// .unwrap();
    /// let f = p.float_evaluator::<f64>();
    /// assert_eq!(f.evaluate(&[0.5, 0.5]).unwrap(), [0.5]);
    /// // (3/4, 1/4): 2 · 3/4 · 1/4 = 3/8, exact in binary
    /// assert_eq!(f.evaluate(&[0.75, 0.25]).unwrap(), [0.375]);
    /// assert!(f.evaluate(&[1.0]).is_err()); // a point needs m + 1 = 2 coordinates
    /// ```
    pub fn float_evaluator<F: Float + std::ops::Div<Output = F>>(&self) -> FloatEvaluator<'_, F> {
        FloatEvaluator {
            patch: self,
            net: self.polynomial().map(|p| crate::float::net_to::<F>(&p.net)),
        }
    }

    /// The representation by kind (unstable).
    pub fn as_any(&self) -> &AnyPatch {
        &self.any
    }

    /// The representation by kind (unstable).
    pub fn into_any(self) -> AnyPatch {
        self.any
    }
}

/// tribez's own float path of a patch in `F` ([`Patch::float_evaluator`]), prepared once for
/// many points.
#[derive(Clone, Debug)]
pub struct FloatEvaluator<'a, F> {
    patch: &'a Patch,
    /// The control net rounded to `F`, for the polynomial kinds.
    net: Option<ControlNet<F>>,
}

impl<F: Float + std::ops::Div<Output = F>> FloatEvaluator<'_, F> {
    /// The value at `input`: `m + 1` barycentric coordinates, or an S-patch's Cartesian `(x, y)`
    /// (a wrong number of coordinates is an error).
    pub fn evaluate(&self, input: &[F]) -> Result<Vec<F>, CoreError> {
        let expected = match &self.patch.any {
            AnyPatch::SPatch(_) => 2,
            _ => self.patch.control_net().m() + 1,
        };
        if input.len() != expected {
            return Err(CoreError::WrongLength {
                what: "point".into(),
                expected,
                found: input.len(),
            });
        }
        Ok(match (&self.patch.any, &self.net) {
            (AnyPatch::Bezier(_) | AnyPatch::Functional(_), Some(net)) => {
                crate::float::casteljau(net, input)
            }
            (AnyPatch::Rational(r), _) => r.evaluate_float::<F>(input),
            (AnyPatch::SPatch(s), _) => s.evaluate_float::<F>(&[input[0], input[1]]),
            (AnyPatch::Bezier(p) | AnyPatch::Functional(p), None) => {
                crate::float::casteljau(&crate::float::net_to::<F>(&p.net), input)
            }
        })
    }
}

/// A polynomial Bézier simplex (of kind [`PatchKind::Bezier`]).
impl From<BezierPatch> for Patch {
    fn from(patch: BezierPatch) -> Self {
        Patch {
            any: AnyPatch::Bezier(patch),
        }
    }
}

impl From<AnyPatch> for Patch {
    fn from(any: AnyPatch) -> Self {
        Patch { any }
    }
}
