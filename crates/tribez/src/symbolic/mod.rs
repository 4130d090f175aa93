//! Polynomials with exact rational coefficients: the symbolic form of a patch.
//!
//! A patch of degree `n` is, coordinate by coordinate, the homogeneous polynomial
//! `P(λ) = Σ_{|α|=n} C(n;α) c_α λ^α` in the barycentric variables (`u, v, w` for triangles; the
//! homogeneous form does not use `u + v + w = 1`, docs/theory.md §0). Given a domain simplex, the
//! substitution `λ = λ(x)` (Cramer's rule, affine in `x`) gives the polynomial in the Cartesian
//! variables (`x, y` for triangles).
//!
//! ```
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::ControlNet;
//! use tribez::hazmat::symbolic::{Polynomial, barycentric_form};
//! // Finn's worked example, part (b): the exact x-component is 2uv + 2vw (docs/theory.md §15)
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let p = barycentric_form(&ControlNet::from_points(2, 2, &pts));
//! let names = ["u", "v", "w"];
//! assert_eq!(p[0].to_text(&names), "2*u*v + 2*v*w");
//! assert_eq!(p[0], Polynomial::parse("2uv + 2vw", &names).unwrap());
//! ```

mod error;
mod forms;
mod parse;
#[cfg(test)]
mod tests;

use std::collections::BTreeMap;
use std::fmt::Write;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::number::{gcd, q_add, q_mul, ratio};

pub use error::{PolyError, PolyErrorKind};
pub use forms::{
    barycentric_form, barycentric_names, barycentric_of_cartesian, cartesian_form, cartesian_names,
};
pub use parse::{
    MAX_COEFFICIENT_BITS, MAX_DEGREE, MAX_NESTING, MAX_TERM_PRODUCTS, MAX_WORK, check_names,
};

/// A polynomial in `nvars` variables with exact rational coefficients; no zero terms are stored.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Polynomial {
    nvars: usize,
    terms: BTreeMap<Vec<u32>, BigRational>,
}

impl Polynomial {
    /// The zero polynomial.
    pub fn zero(nvars: usize) -> Self {
        Polynomial {
            nvars,
            terms: BTreeMap::new(),
        }
    }

    /// A constant.
    pub fn constant(nvars: usize, c: BigRational) -> Self {
        Self::monomial(nvars, vec![0; nvars], c)
    }

    /// `c · x^exponents`.
    pub fn monomial(nvars: usize, exponents: Vec<u32>, c: BigRational) -> Self {
        assert_eq!(exponents.len(), nvars);
        let mut p = Self::zero(nvars);
        if !c.is_zero() {
            p.terms.insert(exponents, c);
        }
        p
    }

    /// The variable `x_i`.
    pub fn variable(nvars: usize, i: usize) -> Self {
        let mut e = vec![0; nvars];
        e[i] = 1;
        Self::monomial(nvars, e, BigRational::one())
    }

    /// Number of variables.
    pub fn nvars(&self) -> usize {
        self.nvars
    }

    /// True for the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Terms `(exponents, coefficient)`, in the display order (degree descending, then the
    /// first variable's exponent descending, …).
    pub fn terms(&self) -> Vec<(&[u32], &BigRational)> {
        let mut t: Vec<_> = self.terms.iter().map(|(e, c)| (e.as_slice(), c)).collect();
        t.sort_by(|a, b| {
            let da: u32 = a.0.iter().sum();
            let db: u32 = b.0.iter().sum();
            db.cmp(&da).then_with(|| b.0.cmp(a.0))
        });
        t
    }

    /// Total degree (`None` for zero).
    pub fn degree(&self) -> Option<u32> {
        self.terms.keys().map(|e| e.iter().sum()).max()
    }

    fn add_term(&mut self, e: Vec<u32>, c: BigRational) {
        if c.is_zero() {
            return;
        }
        let entry = self.terms.entry(e);
        match entry {
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(c);
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                *o.get_mut() = q_add(o.get(), &c);
                if o.get().is_zero() {
                    o.remove();
                }
            }
        }
    }

    /// `self + other`.
    pub fn add(&self, other: &Polynomial) -> Polynomial {
        let mut out = self.clone();
        for (e, c) in &other.terms {
            out.add_term(e.clone(), c.clone());
        }
        out
    }

    /// `self − other`.
    pub fn sub(&self, other: &Polynomial) -> Polynomial {
        self.add(&other.scale(&-BigRational::one()))
    }

    /// `c · self`.
    pub fn scale(&self, c: &BigRational) -> Polynomial {
        let mut out = Polynomial::zero(self.nvars);
        for (e, x) in &self.terms {
            out.add_term(e.clone(), q_mul(x, c));
        }
        out
    }

    /// `self · other`.
    ///
    /// Computed over the integers: with `self = A/a` and `other = B/b` (`a`, `b` the least common
    /// multiples of the coefficients' denominators, `A`, `B` integer polynomials) the product is
    /// `A·B / (a·b)`, so every term product is an integer product and each coefficient of the
    /// result is reduced to lowest terms once, instead of a gcd per term product.
    pub fn mul(&self, other: &Polynomial) -> Polynomial {
        let (a, da) = self.integer_form();
        let (b, db) = other.integer_form();
        let mut sums: BTreeMap<Vec<u32>, BigInt> = BTreeMap::new();
        for (ea, ca) in &a {
            for (eb, cb) in &b {
                let e: Vec<u32> = ea.iter().zip(eb.iter()).map(|(x, y)| x + y).collect();
                let product = ca * cb;
                match sums.entry(e) {
                    std::collections::btree_map::Entry::Vacant(v) => {
                        v.insert(product);
                    }
                    std::collections::btree_map::Entry::Occupied(mut o) => *o.get_mut() += product,
                }
            }
        }
        let d = da * db;
        let mut out = Polynomial::zero(self.nvars);
        for (e, c) in sums {
            if !c.is_zero() {
                out.terms.insert(e, ratio(c, d.clone()));
            }
        }
        out
    }

    /// `(A, a)` with `self = A / a`: `a` the least common multiple of the denominators, `A` the
    /// integer numerators over it.
    fn integer_form(&self) -> (Vec<(&[u32], BigInt)>, BigInt) {
        let mut lcm = BigInt::one();
        for c in self.terms.values() {
            let d = c.denom();
            if !d.is_one() && !(&lcm % d).is_zero() {
                let g = BigInt::from(gcd(lcm.magnitude(), d.magnitude()));
                lcm = lcm / g * d;
            }
        }
        let terms = self
            .terms
            .iter()
            .map(|(e, c)| {
                let n = if c.denom() == &lcm {
                    c.numer().clone()
                } else {
                    c.numer() * (&lcm / c.denom())
                };
                (e.as_slice(), n)
            })
            .collect();
        (terms, lcm)
    }

    /// `self^k`.
    pub fn pow(&self, k: u32) -> Polynomial {
        let mut out = Polynomial::constant(self.nvars, BigRational::one());
        for _ in 0..k {
            out = out.mul(self);
        }
        out
    }

    /// `∂/∂x_i`.
    pub fn derivative(&self, i: usize) -> Polynomial {
        let mut out = Polynomial::zero(self.nvars);
        for (e, c) in &self.terms {
            if e[i] > 0 {
                let mut f = e.clone();
                f[i] -= 1;
                out.add_term(f, c * BigRational::from_integer(BigInt::from(e[i])));
            }
        }
        out
    }

    /// Value at a point (exact).
    pub fn evaluate(&self, x: &[BigRational]) -> BigRational {
        assert_eq!(x.len(), self.nvars);
        self.terms
            .iter()
            .map(|(e, c)| {
                e.iter().zip(x).fold(c.clone(), |acc, (&k, xi)| {
                    acc * num_traits::pow(xi.clone(), k as usize)
                })
            })
            .sum()
    }

    /// Substitute polynomials (in some other set of variables) for the variables.
    pub fn compose(&self, subs: &[Polynomial]) -> Polynomial {
        assert_eq!(subs.len(), self.nvars);
        let nv = subs.first().map_or(0, Polynomial::nvars);
        let mut out = Polynomial::zero(nv);
        for (e, c) in &self.terms {
            let mut term = Polynomial::constant(nv, c.clone());
            for (s, &k) in subs.iter().zip(e) {
                term = term.mul(&s.pow(k));
            }
            out = out.add(&term);
        }
        out
    }

    /// Text like `2*u*v - 1/2*w^2 + 3`; `0` for the zero polynomial.
    pub fn to_text(&self, names: &[&str]) -> String {
        self.render(names, false)
    }

    /// LaTeX like `2uv - \frac{1}{2}w^{2} + 3`.
    pub fn to_latex(&self, names: &[&str]) -> String {
        self.render(names, true)
    }

    fn render(&self, names: &[&str], latex: bool) -> String {
        let terms = self.terms();
        if terms.is_empty() {
            return "0".into();
        }
        let mut out = String::new();
        for (idx, (e, c)) in terms.iter().enumerate() {
            let neg = c.is_negative();
            match (idx, neg) {
                (0, true) => out.push('-'),
                (0, false) => {}
                (_, true) => out.push_str(" - "),
                (_, false) => out.push_str(" + "),
            }
            let a = c.abs();
            let constant = e.iter().all(|&k| k == 0);
            let mut factors: Vec<String> = Vec::new();
            if !a.is_one() || constant {
                factors.push(if latex && !a.is_integer() {
                    format!("\\frac{{{}}}{{{}}}", a.numer(), a.denom())
                } else {
                    a.to_string()
                });
            }
            for (i, &k) in e.iter().enumerate() {
                match (k, latex) {
                    (0, _) => {}
                    (1, _) => factors.push(names[i].to_string()),
                    (k, false) => factors.push(format!("{}^{k}", names[i])),
                    (k, true) => factors.push(format!("{}^{{{k}}}", names[i])),
                }
            }
            let _ = write!(out, "{}", factors.join(if latex { " " } else { "*" }));
        }
        out
    }

    /// `−self`.
    fn negated(mut self) -> Polynomial {
        for c in self.terms.values_mut() {
            let x = std::mem::take(c);
            *c = -x;
        }
        self
    }

    /// `self += other`, in place.
    fn add_assign(&mut self, other: Polynomial) {
        for (e, c) in other.terms {
            self.add_term(e, c);
        }
    }

    /// The largest coefficient size, numerator plus denominator bits (0 for zero).
    fn max_coefficient_bits(&self) -> u64 {
        self.terms.values().map(coefficient_bits).max().unwrap_or(0)
    }
}

/// The size of a coefficient: bits of its numerator plus bits of its denominator.
fn coefficient_bits(c: &BigRational) -> u64 {
    c.numer().bits() + c.denom().bits()
}
