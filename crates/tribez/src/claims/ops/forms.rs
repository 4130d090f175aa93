//! Polynomial forms: `symbolic`, `basis`, `basis_sum`, `implicit`; and the functional patch's
//! `abscissae`, `ordinates`, `graph`.

use std::borrow::Cow;

use num_rational::BigRational;

use super::construct::check_count;
use super::inputs::Inputs;
use super::{OpName, Value, keyed, seen};
use crate::any_patch::AnyPatch;
use crate::domain::Domain;
use crate::io::patch_file::{MAX_DEGREE, MAX_SIMPLEX_DIMENSION, index_key};
use crate::io::{ClaimProblem, InputError, NeededKind};
use crate::patch::BezierPatch;
use crate::rational::homogenised_residual;
use crate::simplex::{Simplex, multinomial};
use crate::symbolic::{
    Polynomial, barycentric_form, barycentric_names, cartesian_form, cartesian_names,
};

type Q = BigRational;

/// `basis` and `basis_sum`: the Bernstein polynomials of a degree, symbolic or at a point.
#[derive(Clone, Debug, PartialEq)]
pub struct Basis {
    /// `basis_sum`: their sum.
    pub sum: bool,
    /// Simplex dimension.
    pub m: usize,
    /// Degree.
    pub degree: usize,
    /// A barycentric point to evaluate at (any sum), if given.
    pub at: Option<Vec<Q>>,
    /// Symbolic in the Cartesian coordinates of the reference simplex (else barycentric).
    pub cartesian: bool,
    /// The variable names of a symbolic result.
    pub names: Vec<String>,
}

/// A polynomial form with its parsed inputs.
#[derive(Clone, Debug)]
pub enum Form<'a> {
    /// `symbolic`: the patch as polynomials.
    Symbolic {
        /// The patch.
        patch: Cow<'a, BezierPatch>,
        /// In the domain's Cartesian coordinates (else barycentric).
        cartesian: bool,
        /// Variable names.
        names: Vec<String>,
        /// One coordinate only (0-based), if given.
        component: Option<usize>,
    },
    /// `basis`, `basis_sum`.
    Basis(Basis),
    /// `implicit`: the residual `W^k F(X/W)` of `equation` on the patch.
    Implicit {
        /// The patch (any kind).
        patch: Cow<'a, AnyPatch>,
        /// `F`, in the coordinates' names.
        equation: Polynomial,
        /// The residual's variable names.
        names: Vec<String>,
    },
    /// `abscissae` of a patch's domain and degree.
    Abscissae {
        /// The patch.
        patch: Cow<'a, BezierPatch>,
    },
    /// `ordinates` of a polynomial over a domain.
    Ordinates {
        /// The domain.
        domain: Domain,
        /// The degree (at most [`MAX_DEGREE`]).
        degree: usize,
        /// The polynomial in the domain's Cartesian coordinates.
        function: Polynomial,
    },
    /// `graph` of a functional patch.
    Graph {
        /// The functional patch.
        patch: Cow<'a, BezierPatch>,
    },
}

fn variables(inputs: &Inputs<'_>) -> Result<bool, InputError> {
    match inputs.opt_string("variables")?.as_deref() {
        None | Some("barycentric") => Ok(false),
        Some("cartesian") => Ok(true),
        Some(other) => Err(inputs.error(
            "variables",
            ClaimProblem::NotOneOf {
                text: other.to_string(),
                choices: &["barycentric", "cartesian"],
            },
        )),
    }
}

fn parse_polynomial(
    inputs: &Inputs<'_>,
    name: &str,
    vars: &[String],
) -> Result<Polynomial, InputError> {
    let text = inputs
        .opt_string(name)?
        .ok_or_else(|| inputs.missing(name))?;
    let refs: Vec<&str> = vars.iter().map(String::as_str).collect();
    Polynomial::parse(&text, &refs).map_err(|reason| {
        inputs.error(
            name,
            ClaimProblem::BadPolynomial {
                text: text.clone(),
                reason,
            },
        )
    })
}

fn parse_basis(inputs: &Inputs<'_>, sum: bool) -> Result<Basis, InputError> {
    let degree = inputs.usize("degree")?;
    let m = inputs.opt_usize("simplex")?.unwrap_or(2);
    if !(1..=MAX_SIMPLEX_DIMENSION).contains(&m) || degree > MAX_DEGREE {
        return Err(inputs.error(
            "degree",
            ClaimProblem::DegreeOutOfRange {
                degree,
                m,
                max_degree: MAX_DEGREE,
                max_m: MAX_SIMPLEX_DIMENSION,
            },
        ));
    }
    check_count(inputs, "degree", m, degree)?;
    let at = inputs.opt_rationals("at")?;
    if let Some(at) = &at
        && at.len() != m + 1
    {
        return Err(inputs.error(
            "at",
            ClaimProblem::CoordinateCount {
                found: at.len(),
                expected: m + 1,
            },
        ));
    }
    let cartesian = variables(inputs)?;
    let names = if cartesian {
        inputs.names(cartesian_names(m))?
    } else {
        inputs.names(barycentric_names(m))?
    };
    Ok(Basis {
        sum,
        m,
        degree,
        at,
        cartesian,
        names,
    })
}

impl<'a> Form<'a> {
    /// Parse the inputs of `name` (one of this module's operations).
    pub fn parse(inputs: &Inputs<'a>, name: OpName) -> Result<Self, InputError> {
        Ok(match name {
            OpName::Symbolic => {
                let patch = inputs.patch()?;
                let m = patch.net.m();
                let cartesian = variables(inputs)?;
                let names = inputs.names(if cartesian {
                    cartesian_names(m)
                } else {
                    barycentric_names(m)
                })?;
                let component = inputs.opt_usize("component")?;
                if let Some(c) = component
                    && c >= patch.net.dim()
                {
                    return Err(inputs.error(
                        "component",
                        ClaimProblem::NoSuchComponent {
                            component: c,
                            dim: patch.net.dim(),
                        },
                    ));
                }
                Form::Symbolic {
                    patch,
                    cartesian,
                    names,
                    component,
                }
            }
            OpName::Basis => Form::Basis(parse_basis(inputs, false)?),
            OpName::BasisSum => Form::Basis(parse_basis(inputs, true)?),
            OpName::Implicit => {
                let patch = inputs.any_patch()?;
                let (d, default_names) = match patch.as_ref() {
                    AnyPatch::Bezier(p) | AnyPatch::Functional(p) => {
                        (p.net.dim(), barycentric_names(p.net.m()))
                    }
                    AnyPatch::Rational(r) => {
                        (r.patch.net.dim(), barycentric_names(r.patch.net.m()))
                    }
                    AnyPatch::SPatch(s) => (s.net.dim(), cartesian_names(2)),
                };
                let coords: Vec<String> = match inputs.opt_strings("coordinates")? {
                    Some(c) if c.len() != d => {
                        return Err(inputs.error(
                            "coordinates",
                            ClaimProblem::CoordinateNames {
                                given: c.len(),
                                dim: d,
                            },
                        ));
                    }
                    Some(c) => c,
                    None => cartesian_names(d),
                };
                let equation = parse_polynomial(inputs, "equation", &coords)?;
                let names = inputs.names(default_names)?;
                Form::Implicit {
                    patch,
                    equation,
                    names,
                }
            }
            OpName::Abscissae => Form::Abscissae {
                patch: inputs.patch()?,
            },
            OpName::Ordinates => {
                let domain = inputs.domain("domain")?;
                let m = domain.m();
                let degree = inputs.usize("degree")?;
                if degree > MAX_DEGREE {
                    return Err(inputs.error(
                        "degree",
                        ClaimProblem::DegreeAbove {
                            degree,
                            limit: MAX_DEGREE,
                        },
                    ));
                }
                check_count(inputs, "degree", m, degree)?;
                let names = inputs.names(cartesian_names(m))?;
                let function = parse_polynomial(inputs, "function", &names)?;
                Form::Ordinates {
                    domain,
                    degree,
                    function,
                }
            }
            OpName::Graph => {
                let AnyPatch::Functional(p) = inputs.file.patch_for(inputs.claim)?.as_any() else {
                    return Err(inputs.error(
                        "patch",
                        ClaimProblem::NeedsKind {
                            op: "graph",
                            needs: NeededKind::Functional,
                        },
                    ));
                };
                Form::Graph {
                    patch: Cow::Borrowed(p),
                }
            }
            // invariant: the caller dispatches only the polynomial-form operations here
            other => unreachable!("`{}` is not a polynomial form", other.name()),
        })
    }

    /// The form on the inputs as seen in precision `p` (module doc of `ops`; polynomial texts
    /// stay exact).
    pub fn seen(
        &self,
        inputs: &Inputs<'_>,
        p: crate::float::Precision,
    ) -> Result<Self, InputError> {
        Ok(match self {
            Form::Symbolic {
                patch,
                cartesian,
                names,
                component,
            } => Form::Symbolic {
                patch: Cow::Owned(seen::patch(inputs, patch, p)?),
                cartesian: *cartesian,
                names: names.clone(),
                component: *component,
            },
            Form::Basis(b) => Form::Basis(Basis {
                at: b
                    .at
                    .as_ref()
                    .map(|at| seen::numbers(inputs, "at", at, p))
                    .transpose()?,
                ..b.clone()
            }),
            Form::Implicit {
                patch,
                equation,
                names,
            } => Form::Implicit {
                patch: Cow::Owned(seen::any_patch(inputs, patch, p)?),
                equation: equation.clone(),
                names: names.clone(),
            },
            Form::Abscissae { patch } => Form::Abscissae {
                patch: Cow::Owned(seen::patch(inputs, patch, p)?),
            },
            Form::Ordinates {
                domain,
                degree,
                function,
            } => Form::Ordinates {
                domain: seen::domain(inputs, "domain", domain, p)?,
                degree: *degree,
                function: function.clone(),
            },
            Form::Graph { patch } => Form::Graph {
                patch: Cow::Owned(seen::patch(inputs, patch, p)?),
            },
        })
    }

    /// The exact value.
    pub fn compute(&self, inputs: &Inputs<'_>) -> Result<Value, InputError> {
        match self {
            Form::Symbolic {
                patch,
                cartesian,
                names,
                component,
            } => {
                let polys = if *cartesian {
                    cartesian_form(&patch.net, &patch.domain_or_reference())
                } else {
                    barycentric_form(&patch.net)
                };
                Ok(match component {
                    None => Value::List(
                        polys
                            .into_iter()
                            .map(|p| Value::Poly(p, names.clone()))
                            .collect(),
                    ),
                    Some(c) => Value::Poly(polys[*c].clone(), names.clone()),
                })
            }
            Form::Basis(b) => Ok(basis(b)),
            Form::Implicit {
                patch,
                equation,
                names,
            } => {
                let (x, w) = match patch.as_ref() {
                    AnyPatch::Bezier(p) | AnyPatch::Functional(p) => {
                        // the barycentric form is homogeneous of degree n, and so is its weight
                        // W = Σ_α B_α = (Σλ)^n (not 1): W^k F(X/W) is then a homogeneous
                        // polynomial, zero exactly when the patch lies on F = 0
                        let m = p.net.m();
                        let sum = (0..=m).fold(Polynomial::zero(m + 1), |acc, i| {
                            acc.add(&Polynomial::variable(m + 1, i))
                        });
                        // invariant: patch degrees are capped far below u32::MAX when read
                        let n = u32::try_from(p.net.degree()).expect("degrees are capped");
                        (barycentric_form(&p.net), sum.pow(n))
                    }
                    AnyPatch::Rational(r) => {
                        let mut h = r.homogeneous_form();
                        // invariant: a rational patch's homogeneous form has its weight as the last component
                        let w = h.pop().expect("weight component");
                        (h, w)
                    }
                    AnyPatch::SPatch(s) => s.rational_form(),
                };
                Ok(Value::Poly(
                    homogenised_residual(equation, &x, &w),
                    names.clone(),
                ))
            }
            Form::Abscissae { patch } => {
                let xi =
                    crate::functional::abscissae(&patch.domain_or_reference(), patch.net.degree());
                Ok(keyed(
                    patch.net.simplex(),
                    xi.iter().map(|x| Value::numbers(x)),
                ))
            }
            Form::Ordinates {
                domain,
                degree,
                function,
            } => {
                let b: Vec<Q> = crate::functional::ordinates(domain, *degree, function)
                    .map_err(|e| inputs.error("function", e))?;
                Ok(keyed(
                    &Simplex::new(domain.m(), *degree),
                    b.into_iter().map(Value::Number),
                ))
            }
            Form::Graph { patch } => {
                let g = crate::functional::graph(patch).map_err(|e| inputs.error("patch", e))?;
                Ok(keyed(g.net.simplex(), g.net.points().map(Value::numbers)))
            }
        }
    }
}

/// The Bernstein basis of a degree (symbolic or at a point), or its sum.
fn basis(b: &Basis) -> Value {
    let (m, n) = (b.m, b.degree);
    let simplex = Simplex::new(m, n);
    if let Some(at) = &b.at {
        let values = crate::bernstein::basis(&simplex, at);
        return if b.sum {
            Value::Number(values.iter().sum())
        } else {
            Value::Map(
                simplex
                    .iter()
                    .map(index_key)
                    .zip(values.into_iter().map(Value::Number))
                    .collect(),
            )
        };
    }
    let polys: Vec<Polynomial> = simplex
        .iter()
        .map(|alpha| {
            Polynomial::monomial(
                m + 1,
                alpha.to_vec(),
                Q::from_integer(multinomial(alpha).into()),
            )
        })
        .collect();
    let polys = if b.cartesian {
        let subs = crate::symbolic::barycentric_of_cartesian(&Domain::reference(m));
        polys.iter().map(|p| p.compose(&subs)).collect::<Vec<_>>()
    } else {
        polys
    };
    if b.sum {
        let total = polys
            .iter()
            .fold(Polynomial::zero(b.names.len()), |acc, p| acc.add(p));
        Value::Poly(total, b.names.clone())
    } else {
        Value::Map(
            simplex
                .iter()
                .map(index_key)
                .zip(polys.into_iter().map(|p| Value::Poly(p, b.names.clone())))
                .collect(),
        )
    }
}
