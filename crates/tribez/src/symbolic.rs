//! Polynomials with exact rational coefficients: the symbolic form of a patch.
//!
//! A patch of degree `n` is, coordinate by coordinate, the homogeneous polynomial
//! `P(λ) = Σ_{|α|=n} C(n;α) c_α λ^α` in the barycentric variables (`u, v, w` for triangles; the
//! homogeneous form does not use `u + v + w = 1`, docs/theory.md §0). Given a domain simplex, the
//! substitution `λ = λ(x)` (Cramer's rule, affine in `x`) gives the polynomial in the Cartesian
//! variables (`x, y` for triangles).
//!
//! ```
//! use tribez::number::parse_rational as q;
//! use tribez::patch::ControlNet;
//! use tribez::symbolic::{Polynomial, barycentric_form};
//! // Finn's worked example, part (b): the exact x-component is 2uv + 2vw (docs/theory.md §15)
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let p = barycentric_form(&ControlNet::from_points(2, 2, &pts));
//! let names = ["u", "v", "w"];
//! assert_eq!(p[0].to_text(&names), "2*u*v + 2*v*w");
//! assert_eq!(p[0], Polynomial::parse("2uv + 2vw", &names).unwrap());
//! ```

use std::collections::BTreeMap;
use std::fmt::Write;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::domain::Domain;
use crate::patch::ControlNet;
use crate::simplex::multinomial;

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
                *o.get_mut() += c;
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
            out.add_term(e.clone(), x * c);
        }
        out
    }

    /// `self · other`.
    pub fn mul(&self, other: &Polynomial) -> Polynomial {
        let mut out = Polynomial::zero(self.nvars);
        for (ea, ca) in &self.terms {
            for (eb, cb) in &other.terms {
                let e = ea.iter().zip(eb).map(|(a, b)| a + b).collect();
                out.add_term(e, ca * cb);
            }
        }
        out
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

    /// Parse a polynomial: a sum of terms, each an optional sign, an optional rational or
    /// decimal coefficient and factors `x`, `x^k` (or `x²`, `x³`), separated by `*`, spaces or
    /// nothing (`2uv + v^2 + vw`). Variables are the given single-token names.
    pub fn parse(text: &str, names: &[&str]) -> Result<Polynomial, String> {
        PolyParser {
            s: text.chars().collect(),
            pos: 0,
            names,
        }
        .parse()
    }
}

struct PolyParser<'a> {
    s: Vec<char>,
    pos: usize,
    names: &'a [&'a str],
}

impl PolyParser<'_> {
    /// Is the character at `i` part of a number? Digits, `.`, `/`, and `e`/`E` only when an
    /// exponent follows (so that a variable named `e` is not swallowed).
    fn number_char_at(&self, i: usize) -> bool {
        match self.s.get(i) {
            Some(c) if c.is_ascii_digit() || matches!(c, '.' | '/') => true,
            Some('e' | 'E') => self
                .s
                .get(i + 1)
                .is_some_and(|c| c.is_ascii_digit() || *c == '-'),
            _ => false,
        }
    }

    fn peek(&mut self) -> Option<char> {
        while self.s.get(self.pos).is_some_and(|c| c.is_whitespace()) {
            self.pos += 1;
        }
        self.s.get(self.pos).copied()
    }

    fn parse(mut self) -> Result<Polynomial, String> {
        let nv = self.names.len();
        let mut out = Polynomial::zero(nv);
        if self.peek().is_none() {
            return Err("empty polynomial".into());
        }
        let mut first = true;
        while self.peek().is_some() {
            let mut sign = BigRational::one();
            match self.peek() {
                Some('+') => self.pos += 1,
                Some('-' | '−') => {
                    self.pos += 1;
                    sign = -sign;
                }
                _ if !first => {
                    return Err(format!("expected + or - at character {}", self.pos + 1));
                }
                _ => {}
            }
            first = false;
            let term = self.term()?;
            out = out.add(&term.scale(&sign));
        }
        Ok(out)
    }

    fn term(&mut self) -> Result<Polynomial, String> {
        let nv = self.names.len();
        let mut coef = BigRational::one();
        let mut exps = vec![0u32; nv];
        let mut any = false;
        loop {
            match self.peek() {
                Some(c) if c.is_ascii_digit() || c == '.' => {
                    let start = self.pos;
                    while self.number_char_at(self.pos) {
                        self.pos += 1;
                    }
                    let text: String = self.s[start..self.pos].iter().collect();
                    let q = crate::number::parse_rational(&text).map_err(|e| e.to_string())?;
                    coef *= q;
                    any = true;
                }
                Some('*') if any => self.pos += 1,
                Some('(') => {
                    // A parenthesised rational coefficient such as (1/2).
                    let close = self.s[self.pos..]
                        .iter()
                        .position(|&c| c == ')')
                        .ok_or("unclosed parenthesis")?;
                    let text: String = self.s[self.pos + 1..self.pos + close].iter().collect();
                    let q = crate::number::parse_rational(&text).map_err(|_| {
                        format!("only a number may stand in parentheses, not `{text}`")
                    })?;
                    coef *= q;
                    self.pos += close + 1;
                    any = true;
                }
                Some(c) if c.is_alphabetic() => {
                    let rest: String = self.s[self.pos..].iter().collect();
                    let (i, name) = self
                        .names
                        .iter()
                        .enumerate()
                        .filter(|(_, n)| rest.starts_with(**n))
                        .max_by_key(|(_, n)| n.len())
                        .ok_or_else(|| {
                            format!(
                                "unknown variable at `{}` (expected one of {})",
                                rest.chars().take(8).collect::<String>(),
                                self.names.join(", ")
                            )
                        })?;
                    self.pos += name.chars().count();
                    let mut k = 1u32;
                    match self.s.get(self.pos) {
                        Some('^') => {
                            self.pos += 1;
                            let start = self.pos;
                            while self.s.get(self.pos).is_some_and(char::is_ascii_digit) {
                                self.pos += 1;
                            }
                            let t: String = self.s[start..self.pos].iter().collect();
                            k = t
                                .parse()
                                .map_err(|_| "expected an exponent after ^".to_string())?;
                        }
                        Some('²') => {
                            self.pos += 1;
                            k = 2;
                        }
                        Some('³') => {
                            self.pos += 1;
                            k = 3;
                        }
                        _ => {}
                    }
                    exps[i] += k;
                    any = true;
                }
                _ => break,
            }
        }
        if !any {
            return Err(format!("expected a term at character {}", self.pos + 1));
        }
        Ok(Polynomial::monomial(nv, exps, coef))
    }
}

/// Default variable names for `m + 1` barycentric coordinates: `u, v, w` for triangles, `u, v`
/// for curves, `u0, u1, …` otherwise.
pub fn barycentric_names(m: usize) -> Vec<String> {
    match m {
        1 => vec!["u".into(), "v".into()],
        2 => vec!["u".into(), "v".into(), "w".into()],
        _ => (0..=m).map(|k| format!("u{k}")).collect(),
    }
}

/// Default Cartesian variable names: `x`, `x, y`, `x, y, z`, else `x1, …`.
pub fn cartesian_names(m: usize) -> Vec<String> {
    match m {
        1 => vec!["x".into()],
        2 => vec!["x".into(), "y".into()],
        3 => vec!["x".into(), "y".into(), "z".into()],
        _ => (1..=m).map(|k| format!("x{k}")).collect(),
    }
}

/// The homogeneous polynomial of each coordinate, in the barycentric variables.
pub fn barycentric_form(net: &ControlNet<BigRational>) -> Vec<Polynomial> {
    let nv = net.m() + 1;
    (0..net.dim())
        .map(|c| {
            let mut p = Polynomial::zero(nv);
            for (alpha, pt) in net.entries() {
                let k = BigRational::from_integer(BigInt::from(multinomial(alpha)));
                p.add_term(alpha.to_vec(), k * &pt[c]);
            }
            p
        })
        .collect()
}

/// The barycentric coordinates of a domain as affine polynomials in the Cartesian variables.
pub fn barycentric_of_cartesian(domain: &Domain) -> Vec<Polynomial> {
    let m = domain.m();
    let zero = vec![BigRational::zero(); m];
    let base = domain.barycentric(&zero).expect("dimension matches");
    let mut out: Vec<Polynomial> = base
        .iter()
        .map(|b| Polynomial::constant(m, b.clone()))
        .collect();
    for c in 0..m {
        let mut unit = zero.clone();
        unit[c] = BigRational::one();
        let at = domain.barycentric(&unit).expect("dimension matches");
        for (k, poly) in out.iter_mut().enumerate() {
            let slope = &at[k] - &base[k];
            *poly = poly.add(&Polynomial::variable(m, c).scale(&slope));
        }
    }
    out
}

/// Each coordinate as a polynomial in the Cartesian variables of `domain`.
pub fn cartesian_form(net: &ControlNet<BigRational>, domain: &Domain) -> Vec<Polynomial> {
    let subs = barycentric_of_cartesian(domain);
    barycentric_form(net)
        .iter()
        .map(|p| p.compose(&subs))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational;

    fn names3() -> [&'static str; 3] {
        ["u", "v", "w"]
    }

    #[test]
    fn parse_print_round_trip() {
        let p = Polynomial::parse("2uv + v^2 - 1/2*w² + (3/4) u v w - 7", &names3()).unwrap();
        assert_eq!(
            p.to_text(&names3()),
            "3/4*u*v*w + 2*u*v + v^2 - 1/2*w^2 - 7"
        );
        assert_eq!(
            Polynomial::parse(&p.to_text(&names3()), &names3()).unwrap(),
            p
        );
        assert_eq!(
            p.to_latex(&names3()),
            "\\frac{3}{4} u v w + 2 u v + v^{2} - \\frac{1}{2} w^{2} - 7"
        );
    }

    #[test]
    fn parse_errors() {
        assert!(Polynomial::parse("", &names3()).is_err());
        assert!(Polynomial::parse("2q", &names3()).is_err());
        assert!(Polynomial::parse("u v + ", &names3()).is_err());
    }

    #[test]
    fn finn_monomial_form_theory_section_9() {
        // docs/theory.md §9: Finn's net in monomials on the reference triangle is
        // (2y − 2y², 2 − 2x − 2y + 2y², 1 − 2x + x² + 4xy − y²).
        let net = crate::testing::finn();
        let xy = ["x", "y"];
        let got = cartesian_form(&net, &Domain::reference(2));
        let want = [
            "2y - 2y^2",
            "2 - 2x - 2y + 2y^2",
            "1 - 2x + x^2 + 4xy - y^2",
        ];
        for (g, w) in got.iter().zip(want) {
            assert_eq!(g, &Polynomial::parse(w, &xy).unwrap());
        }
        let at = [
            parse_rational("1/2").unwrap(),
            parse_rational("1/3").unwrap(),
        ];
        assert_eq!(got[2].evaluate(&at), parse_rational("29/36").unwrap());
    }
}
