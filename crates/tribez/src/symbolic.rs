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

use std::collections::BTreeMap;
use std::fmt::Write;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::domain::Domain;
use crate::number::{gcd, q_add, q_div, q_mul, q_pow, ratio};
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

    /// Parse polynomial text, as tribez prints it ([`Polynomial::to_text`]) or as SymPy and
    /// Python print it (`x**2/4 - 3*x*y/2 + 1`, `(x + 1)**3/4`), so that SymPy's output can be
    /// pasted. Every error is one line.
    ///
    /// Grammar (whitespace is allowed between tokens):
    ///
    /// ```text
    /// expr     := term (("+" | "-") term)*
    /// term     := unary (("*" | "/") unary | unary)*    juxtaposition multiplies: 2uv, 2(u+v)
    /// unary    := ("+" | "-") unary | power             so -x**2 is -(x**2), as in Python
    /// power    := primary [("^" | "**") digits | "²" | "³"]
    /// primary  := number | variable | "(" expr ")"
    /// number   := digits ["." digits] [("e" | "E") ["+" | "-"] digits]   (also ".5", "5.")
    /// ```
    ///
    /// * `*` and `/` are left-associative: `3/4*u` is `(3/4)·u`, `x/2*y` is `x·y/2`. The divisor
    ///   of `/` must be a non-zero constant (`t/2`, `x/(2/3)`); dividing by a variable is an error.
    /// * `**` is the power (as in Python), never two multiplications; a chained power
    ///   (`x**2**3`, right-associative in Python) must be written with parentheses; exponents are
    ///   non-negative integers.
    /// * A number stands first in a term or after an explicit `*` or `/`: `x2`, `x 2`, `(u)2` and
    ///   `2 3` are errors (is `x2` meant as `x·2`, `x^2` or a variable?). `−` (U+2212) is a minus.
    /// * Variables are the given names, matched longest first (`u1` before `u`). A name must be
    ///   non-empty, start with a letter and continue with letters, digits or `_`
    ///   ([`check_names`]); names are not case-folded.
    ///
    /// Limits, checked BEFORE each power, product or division is computed (so hostile text
    /// cannot run for long or allocate much): total degree at most [`MAX_DEGREE`] (also for any
    /// intermediate product and any exponent), coefficient size (numerator plus denominator
    /// bits) at most [`MAX_COEFFICIENT_BITS`], at most [`MAX_TERM_PRODUCTS`] term products in
    /// one multiplication, and parentheses nested at most [`MAX_NESTING`] deep. Numbers obey the
    /// limits of [`crate::number::parse_rational`].
    ///
    /// ```
    /// use tribez::hazmat::symbolic::Polynomial;
    /// let xy = ["x", "y"];
    /// let p = |s| Polynomial::parse(s, &xy).unwrap();
    /// assert_eq!(p("x**2 - 2*x"), p("x^2 - 2x"));
    /// assert_eq!(p("(x + 1)**3/4").to_text(&xy), "1/4*x^3 + 3/4*x^2 + 3/4*x + 1/4");
    /// assert_eq!(p("3*x*y/2"), p("3/2 x y"));
    /// assert!(Polynomial::parse("x^4294967296", &xy).unwrap_err().contains("200"));
    /// assert!(Polynomial::parse("x/y", &xy).is_err());
    /// ```
    pub fn parse(text: &str, names: &[&str]) -> Result<Polynomial, String> {
        Self::parse_with_work_limit(text, names, MAX_WORK)
    }

    /// [`Polynomial::parse`] with a work limit of `limit` word operations instead of
    /// [`MAX_WORK`] (the fuzz target reads with a smaller one, so that each input is quick).
    pub fn parse_with_work_limit(
        text: &str,
        names: &[&str],
        limit: u64,
    ) -> Result<Polynomial, String> {
        check_names(names)?;
        let mut p = PolyParser {
            s: text.chars().collect(),
            pos: 0,
            names,
            depth: 0,
            work: Budget { spent: 0, limit },
        };
        if p.peek().is_none() {
            return Err("empty polynomial".into());
        }
        let out = p.expr()?;
        match p.peek() {
            None => Ok(out),
            Some(')') => Err(format!("unmatched `)` at character {}", p.pos + 1)),
            Some(c) => Err(format!("unexpected `{c}` at character {}", p.pos + 1)),
        }
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

/// The largest total degree polynomial text may have, also for an exponent or an intermediate
/// product while it is read (the largest patch degree tribez reads is 200 as well).
pub const MAX_DEGREE: u32 = 200;

/// The largest coefficient size (bits of the numerator plus bits of the denominator) polynomial
/// text may produce while it is read: 2^20 bits, about 315,000 decimal digits (a number of
/// 100,000 digits, or `1e100000`, is 332,193 bits: three such factors fit, four do not).
pub const MAX_COEFFICIENT_BITS: u64 = 1 << 20;

/// The most term-by-term products one multiplication in polynomial text may take
/// (`(number of terms of a) · (number of terms of b)`).
pub const MAX_TERM_PRODUCTS: usize = 1_000_000;

/// The most arithmetic polynomial text may cost while it is read, in word operations: each
/// product of two coefficients of `a` and `b` bits is counted as `(⌊(a + b)/64⌋ + 1)²`
/// (products are taken over the integers and each coefficient of a product is reduced to lowest
/// terms once, see [`Polynomial::mul`]). 2^30 is about forty times the cost of reading one
/// number of 100,000 digits, so such numbers, and sums and products of up to three of them, are read,
/// while text that would multiply many huge coefficients (`(1e9999 + u + v)^9`) is refused
/// before it is computed instead of running for minutes.
pub const MAX_WORK: u64 = 1 << 30;

/// The deepest nesting of parentheses in polynomial text.
pub const MAX_NESTING: usize = 64;

fn coefficient_bits(c: &BigRational) -> u64 {
    c.numer().bits() + c.denom().bits()
}

/// Checks variable names for [`Polynomial::parse`]: each non-empty, starting with a letter,
/// then letters, digits or `_`, and no name twice. The error names the offending name and its
/// position (from 1).
pub fn check_names(names: &[&str]) -> Result<(), String> {
    for (i, name) in names.iter().enumerate() {
        let mut chars = name.chars();
        match chars.next() {
            None => return Err(format!("variable name {} is empty", i + 1)),
            Some(c) if !c.is_alphabetic() => {
                return Err(format!(
                    "variable name {} `{name}` must start with a letter",
                    i + 1
                ));
            }
            Some(_) => {}
        }
        if !chars.all(|c| c.is_alphanumeric() || c == '_') {
            return Err(format!(
                "variable name {} `{name}` may hold only letters, digits and `_`",
                i + 1
            ));
        }
        if names[..i].contains(name) {
            return Err(format!("variable name `{name}` is given twice"));
        }
    }
    Ok(())
}

struct PolyParser<'a> {
    s: Vec<char>,
    pos: usize,
    names: &'a [&'a str],
    depth: usize,
    /// The arithmetic spent so far, and the most it may spend.
    work: Budget,
}

/// Word operations spent while polynomial text is read, and the limit ([`MAX_WORK`] unless
/// [`Polynomial::parse_with_work_limit`] says otherwise).
struct Budget {
    spent: u64,
    limit: u64,
}

/// What a factor of a term was, for the rule "a number only first or after `*` or `/`".
#[derive(Clone, Copy, PartialEq, Eq)]
enum Juxtaposed {
    /// First factor of the term, or after an explicit `*` or `/`.
    Operator,
    /// After another factor with nothing (or only spaces) between.
    Nothing,
}

impl PolyParser<'_> {
    fn nv(&self) -> usize {
        self.names.len()
    }

    fn peek(&mut self) -> Option<char> {
        while self.s.get(self.pos).is_some_and(|c| c.is_whitespace()) {
            self.pos += 1;
        }
        self.s.get(self.pos).copied()
    }

    fn at(&self, i: usize) -> Option<char> {
        self.s.get(i).copied()
    }

    fn err<T>(&self, what: impl std::fmt::Display) -> Result<T, String> {
        Err(format!("{what} at character {}", self.pos + 1))
    }

    /// Is `**` (or `^`) next?
    fn power_operator(&mut self) -> Option<usize> {
        match (self.peek(), self.at(self.pos + 1)) {
            (Some('*'), Some('*')) => Some(2),
            (Some('^'), _) => Some(1),
            _ => None,
        }
    }

    fn expr(&mut self) -> Result<Polynomial, String> {
        let mut out = self.term()?;
        loop {
            let negate = match self.peek() {
                Some('+') => false,
                Some('-' | '−') => true,
                _ => return Ok(out),
            };
            self.pos += 1;
            let t = self.term()?;
            check_sum(&out, &t)?;
            charge_sum(&out, &t, &mut self.work)?;
            out.add_assign(if negate { t.negated() } else { t });
        }
    }

    fn term(&mut self) -> Result<Polynomial, String> {
        let mut out = self.unary(Juxtaposed::Operator)?;
        loop {
            match self.peek() {
                Some('*') if self.at(self.pos + 1) != Some('*') => {
                    self.pos += 1;
                    let f = self.unary(Juxtaposed::Operator)?;
                    out = checked_mul(&out, &f, &mut self.work)?;
                }
                Some('/') => {
                    self.pos += 1;
                    let start = self.pos;
                    let f = self.unary(Juxtaposed::Operator)?;
                    out = checked_div(&out, &f, &mut self.work)
                        .map_err(|e| format!("{e} at character {}", start + 1))?;
                }
                Some(c) if c.is_alphabetic() || c.is_ascii_digit() || c == '.' || c == '(' => {
                    let f = self.unary(Juxtaposed::Nothing)?;
                    out = checked_mul(&out, &f, &mut self.work)?;
                }
                Some('*') => return self.err("`**` without a base"),
                _ => return Ok(out),
            }
        }
    }

    fn unary(&mut self, after: Juxtaposed) -> Result<Polynomial, String> {
        match self.peek() {
            Some('+') => {
                self.pos += 1;
                self.unary(Juxtaposed::Operator)
            }
            Some('-' | '−') => {
                self.pos += 1;
                Ok(self.unary(Juxtaposed::Operator)?.negated())
            }
            _ => self.power(after),
        }
    }

    fn power(&mut self, after: Juxtaposed) -> Result<Polynomial, String> {
        let base = self.primary(after)?;
        let k: u64 = match self.power_operator() {
            Some(len) => {
                self.pos += len;
                self.exponent()?
            }
            None => match self.at(self.pos) {
                Some('²') => {
                    self.pos += 1;
                    2
                }
                Some('³') => {
                    self.pos += 1;
                    3
                }
                _ => return Ok(base),
            },
        };
        if self.power_operator().is_some() || matches!(self.at(self.pos), Some('²' | '³')) {
            return self
                .err("a chained power is ambiguous (write x**(2*3) as x**6, or use parentheses)");
        }
        checked_pow(&base, k, &mut self.work)
    }

    /// The digits of an exponent, as a number (values above [`MAX_DEGREE`] are reported whole).
    fn exponent(&mut self) -> Result<u64, String> {
        match self.peek() {
            Some('-' | '−') => return self.err("a negative exponent is not a polynomial"),
            Some(c) if c.is_ascii_digit() => {}
            _ => return self.err("expected an exponent (a non-negative integer) after the power"),
        }
        let start = self.pos;
        while self.at(self.pos).is_some_and(|c| c.is_ascii_digit()) {
            self.pos += 1;
        }
        let digits: String = self.s[start..self.pos].iter().collect();
        if matches!(self.at(self.pos), Some('.' | 'e' | 'E')) {
            return self.err("an exponent must be a non-negative integer");
        }
        let trimmed = digits.trim_start_matches('0');
        // Anything that does not fit a u64 is above every limit; say so with its digits.
        trimmed.parse::<u64>().or_else(|_| {
            if trimmed.is_empty() {
                Ok(0)
            } else {
                Err(format!(
                    "exponent {} is above the maximum degree {MAX_DEGREE} at character {}",
                    abbreviate(&digits),
                    start + 1
                ))
            }
        })
    }

    fn primary(&mut self, after: Juxtaposed) -> Result<Polynomial, String> {
        let nv = self.nv();
        match self.peek() {
            Some(c) if c.is_ascii_digit() || c == '.' => {
                if after == Juxtaposed::Nothing {
                    return self.err(format!(
                        "a number after a factor needs an explicit `*` (is `{}` meant as a product or a power?)",
                        self.context()
                    ));
                }
                let q = self.number()?;
                Ok(Polynomial::constant(nv, q))
            }
            Some('(') => {
                if self.depth >= MAX_NESTING {
                    return self.err(format!("parentheses nested deeper than {MAX_NESTING}"));
                }
                let open = self.pos;
                self.pos += 1;
                self.depth += 1;
                if self.peek() == Some(')') {
                    return self.err("empty parentheses");
                }
                let inner = self.expr()?;
                self.depth -= 1;
                if self.peek() != Some(')') {
                    return Err(format!("unclosed `(` at character {}", open + 1));
                }
                self.pos += 1;
                Ok(inner)
            }
            Some(c) if c.is_alphabetic() => self.variable(),
            None => Err("expected a term at the end of the text".into()),
            Some(c) => self.err(format!("expected a term, found `{c}`")),
        }
    }

    /// A few characters from the current position, for error messages.
    fn context(&self) -> String {
        let from = self.pos.saturating_sub(3);
        self.s[from..(self.pos + 3).min(self.s.len())]
            .iter()
            .collect()
    }

    fn number(&mut self) -> Result<BigRational, String> {
        let start = self.pos;
        let digits = |p: &mut Self| {
            let from = p.pos;
            while p.at(p.pos).is_some_and(|c| c.is_ascii_digit()) {
                p.pos += 1;
            }
            p.pos > from
        };
        digits(self);
        if self.at(self.pos) == Some('.') {
            self.pos += 1;
            digits(self);
        }
        if let Some('e' | 'E') = self.at(self.pos) {
            // An exponent only when digits follow (so that a variable named `e` is not swallowed).
            let sign = usize::from(matches!(self.at(self.pos + 1), Some('+' | '-')));
            if self
                .at(self.pos + 1 + sign)
                .is_some_and(|c| c.is_ascii_digit())
            {
                self.pos += 1 + sign;
                digits(self);
            }
        }
        let text: String = self.s[start..self.pos].iter().collect();
        let q = crate::number::parse_rational(&text)
            .map_err(|e| format!("{e} at character {}", start + 1))?;
        if coefficient_bits(&q) > MAX_COEFFICIENT_BITS {
            return Err(format!(
                "the number at character {} has more than {MAX_COEFFICIENT_BITS} bits (the coefficient size limit)",
                start + 1
            ));
        }
        Ok(q)
    }

    fn variable(&mut self) -> Result<Polynomial, String> {
        let nv = self.nv();
        let rest = &self.s[self.pos..];
        let matches = |n: &str| {
            let len = n.chars().count();
            rest.len() >= len && rest.iter().zip(n.chars()).all(|(a, b)| *a == b)
        };
        let Some((i, name)) = self
            .names
            .iter()
            .enumerate()
            .filter(|(_, n)| matches(n))
            .max_by_key(|(_, n)| n.len())
        else {
            return self.err(format!(
                "unknown variable `{}` (expected one of {})",
                self.word(),
                self.names.join(", ")
            ));
        };
        let len = name.chars().count();
        if self
            .at(self.pos + len)
            .is_some_and(|c| c.is_ascii_digit() || c == '_')
        {
            return self.err(format!(
                "unknown variable `{}` (expected one of {}; write a product with `*`, a power with `**` or `^`)",
                self.word(),
                self.names.join(", ")
            ));
        }
        self.pos += len;
        Ok(Polynomial::variable(nv, i))
    }

    /// The run of letters, digits and `_` at the current position (abbreviated).
    fn word(&self) -> String {
        let w: String = self.s[self.pos..]
            .iter()
            .take_while(|c| c.is_alphanumeric() || **c == '_')
            .collect();
        abbreviate(&w)
    }
}

/// At most 24 characters of `s`, with `…` when cut.
fn abbreviate(s: &str) -> String {
    if s.chars().count() <= 24 {
        s.to_owned()
    } else {
        format!("{}…", s.chars().take(24).collect::<String>())
    }
}

fn check_degree(d: u64) -> Result<(), String> {
    if d > u64::from(MAX_DEGREE) {
        return Err(format!(
            "degree {d} is above the maximum degree {MAX_DEGREE} of polynomial text"
        ));
    }
    Ok(())
}

fn check_bits(bits: u64) -> Result<(), String> {
    if bits > MAX_COEFFICIENT_BITS {
        return Err(format!(
            "a coefficient would have about {bits} bits, above the limit of {MAX_COEFFICIENT_BITS} bits"
        ));
    }
    Ok(())
}

/// A sum adds at most one bit to the larger numerator, and multiplies denominators.
/// Charge `pairs` coefficient products of `bits` bits each against the budget [`MAX_WORK`].
fn charge(work: &mut Budget, pairs: usize, bits: u64) -> Result<(), String> {
    let words = bits / 64 + 1;
    charge_units(
        work,
        (pairs as u64).saturating_mul(words.saturating_mul(words)),
        &format!("coefficients of about {bits} bits in {pairs} products"),
    )
}

/// Charge `units` word operations (`what` says what for, in the error).
fn charge_units(work: &mut Budget, units: u64, what: &str) -> Result<(), String> {
    work.spent = work.spent.saturating_add(units);
    if work.spent > work.limit {
        return Err(format!(
            "the text needs more than {} word operations of exact arithmetic ({what}), above the work limit of polynomial text",
            work.limit
        ));
    }
    Ok(())
}

/// Lehmer's gcd costs a few products' worth of word operations per word of its arguments.
const GCD_WEIGHT: u64 = 8;

/// Charge `a + b`: each coefficient sum of two terms with the same monomial cross-multiplies the
/// denominators, then reduces by a gcd with their product, which costs about
/// `words(numerator)·words(denominators) + GCD_WEIGHT·words(denominators)²` (cheap when the
/// denominators are small, whatever the numerators).
fn charge_sum(a: &Polynomial, b: &Polynomial, work: &mut Budget) -> Result<(), String> {
    let (small, large) = if a.terms.len() <= b.terms.len() {
        (a, b)
    } else {
        (b, a)
    };
    let meet = small
        .terms
        .keys()
        .filter(|e| large.terms.contains_key(*e))
        .count() as u64;
    if meet == 0 {
        return Ok(());
    }
    let denominator_bits = |p: &Polynomial| p.terms.values().map(|c| c.denom().bits()).max();
    let d = denominator_bits(a).unwrap_or(0) + denominator_bits(b).unwrap_or(0);
    let n = a.max_coefficient_bits() + b.max_coefficient_bits();
    let (wd, wn) = (d / 64 + 1, n / 64 + 1);
    let per_sum = wn
        .saturating_mul(wd)
        .saturating_add(GCD_WEIGHT.saturating_mul(wd.saturating_mul(wd)));
    charge_units(
        work,
        meet.saturating_mul(per_sum),
        &format!("{meet} sums of coefficients of about {n} bits"),
    )
}

fn check_sum(a: &Polynomial, b: &Polynomial) -> Result<(), String> {
    check_bits(a.max_coefficient_bits() + b.max_coefficient_bits() + 1)
}

/// `a · b`, after checking the degree, the number of term products and the coefficient size.
fn checked_mul(a: &Polynomial, b: &Polynomial, work: &mut Budget) -> Result<Polynomial, String> {
    if a.is_zero() || b.is_zero() {
        return Ok(Polynomial::zero(a.nvars));
    }
    let deg = |p: &Polynomial| u64::from(p.degree().unwrap_or(0));
    check_degree(deg(a) + deg(b))?;
    let pairs = a.terms.len().saturating_mul(b.terms.len());
    if pairs > MAX_TERM_PRODUCTS {
        return Err(format!(
            "a product of {} by {} terms is above the limit of {MAX_TERM_PRODUCTS} term products",
            a.terms.len(),
            b.terms.len()
        ));
    }
    // Each coefficient of the product is a sum of at most min(|a|, |b|) products.
    let sum_bits = u64::BITS - (a.terms.len().min(b.terms.len()) as u64).leading_zeros();
    check_bits(a.max_coefficient_bits() + b.max_coefficient_bits() + u64::from(sum_bits))?;
    charge(
        work,
        pairs,
        a.max_coefficient_bits() + b.max_coefficient_bits(),
    )?;
    Ok(a.mul(b))
}

/// `a / b` for a non-zero constant `b`.
fn checked_div(a: &Polynomial, b: &Polynomial, work: &mut Budget) -> Result<Polynomial, String> {
    if b.degree().unwrap_or(0) > 0 {
        return Err(
            "the divisor is not a constant (only division by a number is a polynomial)".into(),
        );
    }
    let c = b
        .terms
        .values()
        .next()
        .ok_or_else(|| "division by zero".to_string())?;
    check_bits(a.max_coefficient_bits() + coefficient_bits(c))?;
    charge(
        work,
        a.terms.len(),
        a.max_coefficient_bits() + coefficient_bits(c),
    )?;
    Ok(a.scale(&q_div(&BigRational::one(), c)))
}

/// `p^k`, after checking the degree `deg(p)·k` and the coefficient size `bits(p)·k`.
fn checked_pow(p: &Polynomial, k: u64, work: &mut Budget) -> Result<Polynomial, String> {
    if k == 0 {
        return Ok(Polynomial::constant(p.nvars, BigRational::one()));
    }
    if p.is_zero() {
        return Ok(p.clone());
    }
    let deg = u64::from(p.degree().unwrap_or(0));
    if deg.saturating_mul(k) > u64::from(MAX_DEGREE) {
        return Err(format!(
            "exponent {k} gives degree {}, above the maximum degree {MAX_DEGREE} of polynomial text",
            deg.saturating_mul(k)
        ));
    }
    check_bits(p.max_coefficient_bits().saturating_mul(k))?;
    if deg == 0 {
        // invariant: the zero polynomial returned above, so a degree-0 `p` has its one constant term
        let c = p.terms.values().next().expect("non-zero");
        let k = u32::try_from(k).map_err(|_| "exponent too large".to_string())?;
        charge(work, 1, coefficient_bits(c).saturating_mul(u64::from(k)))?;
        return Ok(Polynomial::constant(p.nvars, q_pow(c, k)));
    }
    let mut out = p.clone();
    for _ in 1..k {
        out = checked_mul(&out, p, work)?;
    }
    Ok(out)
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
    // invariant: `zero` has the domain's m coordinates
    let base = domain.barycentric(&zero).expect("dimension matches");
    let mut out: Vec<Polynomial> = base
        .iter()
        .map(|b| Polynomial::constant(m, b.clone()))
        .collect();
    for c in 0..m {
        let mut unit = zero.clone();
        unit[c] = BigRational::one();
        // invariant: `unit` has the domain's m coordinates
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
    use proptest::prelude::*;

    fn names3() -> [&'static str; 3] {
        ["u", "v", "w"]
    }

    /// The work limit: one number of 100,000 digits and a few products of such numbers are
    /// read; a ninth power of a trinomial whose constant has about 33,000 bits (the fuzzer's
    /// timeout, `fuzz/regressions/polynomial/timeout-9b8e…`) is refused before it is computed.
    #[test]
    fn the_work_limit_refuses_many_products_of_huge_coefficients() {
        let uvw = ["u", "v", "w"];
        let big = format!("1{}", "0".repeat(99_999));
        assert!(Polynomial::parse(&big, &uvw).is_ok());
        assert!(Polynomial::parse(&format!("{big}*u*{big} + {big}/3"), &uvw).is_ok());
        let e = Polynomial::parse("(1e9999 + u + v)^9", &uvw).unwrap_err();
        assert!(e.contains("work limit"), "{e}");
    }

    /// Sums are charged by the size of their denominators: numbers of 2,000 digits over small
    /// denominators add cheaply, while the same sums of fractions whose denominators have 2,000
    /// digits (each sum a gcd of such numbers) exceed a work limit of 2^20.
    #[test]
    fn sums_are_charged_by_the_size_of_their_denominators() {
        let uvw = ["u", "v", "w"];
        let big = format!("1{}", "0".repeat(2_000));
        let small = format!("{big} + {big}/3 + {big}/7 + {big}/11 + {big}/13");
        assert!(Polynomial::parse_with_work_limit(&small, &uvw, 1 << 20).is_ok());
        let huge = format!("1/{big}1 + 1/{big}3 + 1/{big}7 + 1/{big}9 + 1/{big}11");
        let e = Polynomial::parse_with_work_limit(&huge, &uvw, 1 << 20).unwrap_err();
        assert!(
            e.contains("work limit") && e.contains("sums of coefficients"),
            "{e}"
        );
        assert!(Polynomial::parse(&huge, &uvw).is_ok());
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

    /// `c · x^e` in the variables of `names3()`, from a hand-written coefficient.
    fn mono(e: [u32; 3], c: &str) -> Polynomial {
        Polynomial::monomial(3, e.to_vec(), parse_rational(c).unwrap())
    }

    fn sum(terms: &[Polynomial]) -> Polynomial {
        terms.iter().fold(Polynomial::zero(3), |a, t| a.add(t))
    }

    #[test]
    fn double_star_is_the_power_not_two_products() {
        // x**2 - 2*x was read as x*2 - 2*x = 0: a false pass of `symbolic` claims.
        let p = Polynomial::parse("u**2 - 2*u", &names3()).unwrap();
        assert_eq!(p, sum(&[mono([2, 0, 0], "1"), mono([1, 0, 0], "-2")]));
        assert!(!p.is_zero());
        assert_eq!(p, Polynomial::parse("u^2 - 2u", &names3()).unwrap());
        assert_eq!(p, Polynomial::parse("u ** 2 - 2 * u", &names3()).unwrap());
    }

    #[test]
    fn parentheses_and_division_by_numbers() {
        let p = |s: &str| Polynomial::parse(s, &names3()).unwrap();
        // (u+v)^2 = u^2 + 2uv + v^2
        let square = sum(&[
            mono([2, 0, 0], "1"),
            mono([1, 1, 0], "2"),
            mono([0, 2, 0], "1"),
        ]);
        assert_eq!(p("(u+v)^2"), square);
        assert_eq!(p("(u + v)**2"), square);
        assert_eq!(p("(u+v)(u+v)"), square);
        assert_eq!(p("w/2"), mono([0, 0, 1], "1/2"));
        assert_eq!(p("3*w/4"), mono([0, 0, 1], "3/4"));
        assert_eq!(p("3/4*w"), mono([0, 0, 1], "3/4"));
        assert_eq!(p("u/(2/3)"), mono([1, 0, 0], "3/2"));
        assert_eq!(p("u/2/3"), mono([1, 0, 0], "1/6"));
        // (u+1)^3/4 = (u^3 + 3u^2 + 3u + 1)/4
        assert_eq!(
            p("(u+1)**3/4"),
            sum(&[
                mono([3, 0, 0], "1/4"),
                mono([2, 0, 0], "3/4"),
                mono([1, 0, 0], "3/4"),
                mono([0, 0, 0], "1/4"),
            ])
        );
        // Python's precedence: -u**2 is -(u**2); 2*(u - (v - w)) nests.
        assert_eq!(p("-u**2"), mono([2, 0, 0], "-1"));
        assert_eq!(
            p("2*(u - (v - w))"),
            sum(&[
                mono([1, 0, 0], "2"),
                mono([0, 1, 0], "-2"),
                mono([0, 0, 1], "2")
            ])
        );
        assert_eq!(p("u*-v"), mono([1, 1, 0], "-1"));
        assert_eq!(
            p("1.5e1*u + 2E-1"),
            sum(&[mono([1, 0, 0], "15"), mono([0, 0, 0], "1/5")])
        );
        assert_eq!(p("(2)^3"), mono([0, 0, 0], "8"));
        assert_eq!(p("u^0"), mono([0, 0, 0], "1"));
    }

    #[test]
    fn exponents_too_large_say_so() {
        let err = |s: &str| Polynomial::parse(s, &names3()).unwrap_err();
        // u^4294967296 was read as u^0 (u32 wrap): a false pass.
        for s in ["u^4294967296", "u**4294967296", "u^4294967295", "u^201"] {
            let e = err(s);
            assert!(e.contains("maximum degree 200"), "{s}: {e}");
            assert!(e.contains("exponent"), "{s}: {e}");
        }
        let e = err("u^99999999999999999999999999999999");
        assert!(e.contains("exponent 999999999999999999999999…"), "{e}");
        assert!(e.contains("maximum degree 200"), "{e}");
        // the exponents of one term summed past u32 (an overflow before)
        let e = err("v^4294967295v");
        assert!(e.contains("maximum degree 200"), "{e}");
        let e = err("u^150 v^51");
        assert_eq!(
            e,
            "degree 201 is above the maximum degree 200 of polynomial text"
        );
        assert_eq!(
            Polynomial::parse("u^200", &names3()).unwrap().degree(),
            Some(200)
        );
        assert_eq!(
            Polynomial::parse("u^100 v^100", &names3())
                .unwrap()
                .degree(),
            Some(200)
        );
        assert!(err("u^-1").contains("negative exponent"));
        assert!(err("u^").contains("expected an exponent"));
        assert!(err("u^1.5").contains("non-negative integer"));
        assert!(err("u**2**3").contains("chained power"));
        assert!(err("u^2^3").contains("chained power"));
    }

    #[test]
    fn empty_or_bad_variable_names_are_rejected() {
        // Used to loop forever: the empty name matched everywhere without advancing.
        assert_eq!(
            Polynomial::parse("v + w", &["", "v", "w"]).unwrap_err(),
            "variable name 1 is empty"
        );
        assert_eq!(
            Polynomial::parse("x + y", &["", "y", "z"]).unwrap_err(),
            "variable name 1 is empty"
        );
        assert_eq!(
            check_names(&["u", "v", ""]).unwrap_err(),
            "variable name 3 is empty"
        );
        assert!(check_names(&["u", "u"]).unwrap_err().contains("twice"));
        assert!(
            check_names(&["2u"])
                .unwrap_err()
                .contains("start with a letter")
        );
        assert!(check_names(&["u v"]).unwrap_err().contains("only letters"));
        assert!(check_names(&["u*v"]).unwrap_err().contains("only letters"));
        assert!(check_names(&["u", "u1", "λ_2"]).is_ok());
        let p = Polynomial::parse("u1 u + λ_2", &["u", "u1", "λ_2"]).unwrap();
        assert_eq!(p.to_text(&["u", "u1", "λ_2"]), "u*u1 + λ_2");
    }

    #[test]
    fn ambiguous_juxtapositions_are_errors() {
        let err = |s: &str| Polynomial::parse(s, &names3()).unwrap_err();
        // `u2` could be u·2, u^2 or a variable u2.
        assert!(err("u2").contains("unknown variable `u2`"), "{}", err("u2"));
        assert!(err("u 2").contains("explicit `*`"));
        assert!(err("2 3").contains("explicit `*`"));
        assert!(err("(u)2").contains("explicit `*`"));
        assert!(err("u* *v").contains("expected a term"));
        assert!(err("u + ").contains("expected a term"));
        assert!(err("(u + v").contains("unclosed `(` at character 1"));
        assert!(err("u + v)").contains("unmatched `)` at character 6"));
        assert!(err("()").contains("empty parentheses"));
        assert!(err("u @ v").contains("unexpected `@`"));
        assert!(err("u/v").contains("not a constant"));
        assert!(err("u/(v - v)").contains("division by zero"));
        assert!(err("u/0").contains("division by zero"));
        let deep = format!("{}u{}", "(".repeat(65), ")".repeat(65));
        assert!(err(&deep).contains("nested deeper than 64"));
        let ok = format!("{}u{}", "(".repeat(64), ")".repeat(64));
        assert_eq!(
            Polynomial::parse(&ok, &names3()).unwrap(),
            mono([1, 0, 0], "1")
        );
        // Numbers obey the number syntax and its limits.
        assert!(err("1e100001 u").contains("exponent"));
    }

    #[test]
    fn coefficient_and_product_sizes_are_capped_before_computing() {
        // Ten factors 1e100000 took 46 s: the fourth is refused before it is multiplied.
        let ten = ["1e100000"; 10].join("*");
        let e = Polynomial::parse(&ten, &names3()).unwrap_err();
        assert!(e.contains("limit of 1048576 bits"), "{e}");
        let three = Polynomial::parse("1e100000*1e100000*1e100000 u", &names3()).unwrap();
        let big = BigRational::from_integer(BigInt::from(10u32).pow(300_000u32));
        assert_eq!(three, Polynomial::monomial(3, vec![1, 0, 0], big));
        let e = Polynomial::parse("2^4294967295", &names3()).unwrap_err();
        assert!(e.contains("bits"), "{e}");
        assert_eq!(
            Polynomial::parse("2^1000", &names3()).unwrap(),
            Polynomial::constant(3, BigRational::from_integer(BigInt::one() << 1000usize))
        );
        // (u+v+w+1)^20 has C(23,3) = 1771 terms; times itself: 3136441 term products.
        let e = Polynomial::parse("(u+v+w+1)^20 * (u+v+w+1)^20", &names3()).unwrap_err();
        assert!(e.contains("limit of 1000000 term products"), "{e}");
    }

    #[test]
    fn sympy_printed_polynomials() {
        // fixtures/polynomials/sympy_printed.txt: SymPy's printing of a product of powers and
        // SymPy's own expansion of it (made by sympy_printed.py beside it).
        let xyz = ["x", "y", "z"];
        let text = include_str!("../../../fixtures/polynomials/sympy_printed.txt");
        let mut n = 0;
        for line in text.lines().filter(|l| !l.trim().is_empty()) {
            let (printed, expanded) = line.split_once(" ; ").expect("two sides");
            let a = Polynomial::parse(printed, &xyz).unwrap_or_else(|e| panic!("{printed}: {e}"));
            let b = Polynomial::parse(expanded, &xyz).unwrap_or_else(|e| panic!("{expanded}: {e}"));
            assert_eq!(a, b, "{line}");
            n += 1;
        }
        assert!(n >= 50);
    }

    /// SymPy's printing of a polynomial (`3*x**2*y/4`, `-x/2`, `x**3`, `-7/2`): written here
    /// independently of `to_text`.
    fn sympy_style(p: &Polynomial, names: &[&str]) -> String {
        let mut out = String::new();
        for (i, (e, c)) in p.terms().into_iter().enumerate() {
            let sign = if c.is_negative() { "-" } else { "+" };
            out.push_str(match (i, sign) {
                (0, "+") => "",
                (0, _) => "-",
                (_, "+") => " + ",
                _ => " - ",
            });
            let mut factors: Vec<String> = e
                .iter()
                .zip(names)
                .filter(|(k, _)| **k > 0)
                .map(|(k, n)| {
                    if *k == 1 {
                        n.to_string()
                    } else {
                        format!("{n}**{k}")
                    }
                })
                .collect();
            let (num, den) = (c.numer().abs(), c.denom().clone());
            if !num.is_one() || factors.is_empty() {
                factors.insert(0, num.to_string());
            }
            out.push_str(&factors.join("*"));
            if !den.is_one() {
                out.push_str(&format!("/{den}"));
            }
        }
        if out.is_empty() { "0".into() } else { out }
    }

    fn poly_strategy() -> impl Strategy<Value = Polynomial> {
        proptest::collection::vec(
            (proptest::collection::vec(0u32..5, 3), -30i64..30, 1i64..12),
            0..8,
        )
        .prop_map(|terms| {
            let mut p = Polynomial::zero(3);
            for (e, a, b) in terms {
                p.add_term(e, BigRational::new(a.into(), b.into()));
            }
            p
        })
    }

    proptest! {
        #[test]
        fn sympy_printing_round_trips(p in poly_strategy()) {
            let names = ["x", "y", "z"];
            let text = sympy_style(&p, &names);
            prop_assert_eq!(&Polynomial::parse(&text, &names).unwrap(), &p, "{}", text);
            prop_assert_eq!(&Polynomial::parse(&p.to_text(&names), &names).unwrap(), &p);
            // the power operator and (a+b)**2 in SymPy's unexpanded style
            let sq = format!("({text})**2");
            prop_assert_eq!(Polynomial::parse(&sq, &names).unwrap(), p.mul(&p));
        }

        /// The integer-form product equals the term-by-term product of rationals (each term
        /// product reduced, then summed), the definition it replaces.
        #[test]
        fn product_equals_the_term_by_term_product(a in poly_strategy(), b in poly_strategy()) {
            let mut want = Polynomial::zero(a.nvars);
            for (ea, ca) in &a.terms {
                for (eb, cb) in &b.terms {
                    let e = ea.iter().zip(eb).map(|(x, y)| x + y).collect();
                    want.add_term(e, ca * cb);
                }
            }
            let got = a.mul(&b);
            // Ratio's == compares values: check lowest terms and the stored zeros separately
            for c in got.terms.values() {
                prop_assert!(!c.is_zero());
                prop_assert!(c.denom().is_positive());
                prop_assert!(num_integer::Integer::gcd(c.numer(), c.denom()).is_one());
            }
            prop_assert_eq!(got, want);
        }

        #[test]
        fn parse_never_panics(s in "[uvw0-9.*^/+()e -]{0,40}") {
            let _ = Polynomial::parse(&s, &names3());
        }
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
