//! Reading polynomial text ([`Polynomial::parse`]): the grammar, the variable names, and the
//! limits checked before each power, product or division is computed, so that hostile text
//! cannot run for long or allocate much. Errors are [`PolyError`]s.

use num_rational::BigRational;
use num_traits::One;

use super::error::{PolyError, PolyErrorKind};
use super::{Polynomial, coefficient_bits};
use crate::number::{q_div, q_pow};

impl Polynomial {
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
    ///   (`check_names`); names are not case-folded.
    ///
    /// Limits, checked BEFORE each power, product or division is computed (so hostile text
    /// cannot run for long or allocate much): total degree at most `MAX_DEGREE` (also for any
    /// intermediate product and any exponent), coefficient size (numerator plus denominator
    /// bits) at most `MAX_COEFFICIENT_BITS`, at most `MAX_TERM_PRODUCTS` term products in
    /// one multiplication, and parentheses nested at most `MAX_NESTING` deep. Numbers obey the
    /// limits of [`crate::number::parse_rational`].
    ///
    /// ```
    /// use tribez::hazmat::symbolic::Polynomial;
    /// let xy = ["x", "y"];
    /// let p = |s| Polynomial::parse(s, &xy).unwrap();
    /// assert_eq!(p("x**2 - 2*x"), p("x^2 - 2x"));
    /// assert_eq!(p("(x + 1)**3/4").to_text(&xy), "1/4*x^3 + 3/4*x^2 + 3/4*x + 1/4");
    /// assert_eq!(p("3*x*y/2"), p("3/2 x y"));
    /// assert!(Polynomial::parse("x^4294967296", &xy).unwrap_err().to_string().contains("200"));
    /// assert!(Polynomial::parse("x/y", &xy).is_err());
    /// ```
    pub fn parse(text: &str, names: &[&str]) -> Result<Polynomial, PolyError> {
        Self::parse_with_work_limit(text, names, MAX_WORK)
    }

    /// [`Polynomial::parse`] with a work limit of `limit` word operations instead of
    /// `MAX_WORK` (the fuzz target reads with a smaller one, so that each input is quick).
    pub fn parse_with_work_limit(
        text: &str,
        names: &[&str],
        limit: u64,
    ) -> Result<Polynomial, PolyError> {
        check_names(names)?;
        let mut p = PolyParser {
            s: text.chars().collect(),
            pos: 0,
            names,
            depth: 0,
            work: Budget { spent: 0, limit },
        };
        if p.peek().is_none() {
            return Err(PolyErrorKind::Empty.into());
        }
        let out = p.expr()?;
        match p.peek() {
            None => Ok(out),
            Some(')') => p.err(PolyErrorKind::UnmatchedClose),
            Some(c) => p.err(PolyErrorKind::Unexpected { found: c }),
        }
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

/// Checks variable names for [`Polynomial::parse`]: each non-empty, starting with a letter,
/// then letters, digits or `_`, and no name twice. The error names the offending name and its
/// position (from 1).
pub fn check_names(names: &[&str]) -> Result<(), PolyError> {
    for (i, name) in names.iter().enumerate() {
        let mut chars = name.chars();
        match chars.next() {
            None => return Err(PolyErrorKind::EmptyName { index: i + 1 }.into()),
            Some(c) if !c.is_alphabetic() => {
                return Err(PolyErrorKind::NameStart {
                    index: i + 1,
                    name: name.to_string(),
                }
                .into());
            }
            Some(_) => {}
        }
        if !chars.all(|c| c.is_alphanumeric() || c == '_') {
            return Err(PolyErrorKind::NameCharacters {
                index: i + 1,
                name: name.to_string(),
            }
            .into());
        }
        if names[..i].contains(name) {
            return Err(PolyErrorKind::NameTwice {
                name: name.to_string(),
            }
            .into());
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

    fn err<T>(&self, kind: PolyErrorKind) -> Result<T, PolyError> {
        Err(PolyError::at(kind, self.pos + 1))
    }

    /// Is `**` (or `^`) next?
    fn power_operator(&mut self) -> Option<usize> {
        match (self.peek(), self.at(self.pos + 1)) {
            (Some('*'), Some('*')) => Some(2),
            (Some('^'), _) => Some(1),
            _ => None,
        }
    }

    fn expr(&mut self) -> Result<Polynomial, PolyError> {
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

    fn term(&mut self) -> Result<Polynomial, PolyError> {
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
                    out = checked_div(&out, &f, &mut self.work).map_err(|e| PolyError {
                        at: Some(start + 1),
                        ..e
                    })?;
                }
                Some(c) if c.is_alphabetic() || c.is_ascii_digit() || c == '.' || c == '(' => {
                    let f = self.unary(Juxtaposed::Nothing)?;
                    out = checked_mul(&out, &f, &mut self.work)?;
                }
                Some('*') => return self.err(PolyErrorKind::PowerWithoutBase),
                _ => return Ok(out),
            }
        }
    }

    fn unary(&mut self, after: Juxtaposed) -> Result<Polynomial, PolyError> {
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

    fn power(&mut self, after: Juxtaposed) -> Result<Polynomial, PolyError> {
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
            return self.err(PolyErrorKind::ChainedPower);
        }
        checked_pow(&base, k, &mut self.work)
    }

    /// The digits of an exponent, as a number (values above [`MAX_DEGREE`] are reported whole).
    fn exponent(&mut self) -> Result<u64, PolyError> {
        match self.peek() {
            Some('-' | '−') => return self.err(PolyErrorKind::NegativeExponent),
            Some(c) if c.is_ascii_digit() => {}
            _ => return self.err(PolyErrorKind::NoExponent),
        }
        let start = self.pos;
        while self.at(self.pos).is_some_and(|c| c.is_ascii_digit()) {
            self.pos += 1;
        }
        let digits: String = self.s[start..self.pos].iter().collect();
        if matches!(self.at(self.pos), Some('.' | 'e' | 'E')) {
            return self.err(PolyErrorKind::NotIntegerExponent);
        }
        let trimmed = digits.trim_start_matches('0');
        // Anything that does not fit a u64 is above every limit; say so with its digits.
        trimmed.parse::<u64>().or_else(|_| {
            if trimmed.is_empty() {
                Ok(0)
            } else {
                Err(PolyError::at(
                    PolyErrorKind::ExponentTooLarge {
                        digits: abbreviate(&digits),
                        max: MAX_DEGREE,
                    },
                    start + 1,
                ))
            }
        })
    }

    fn primary(&mut self, after: Juxtaposed) -> Result<Polynomial, PolyError> {
        let nv = self.nv();
        match self.peek() {
            Some(c) if c.is_ascii_digit() || c == '.' => {
                if after == Juxtaposed::Nothing {
                    return self.err(PolyErrorKind::NumberAfterFactor {
                        context: self.context(),
                    });
                }
                let q = self.number()?;
                Ok(Polynomial::constant(nv, q))
            }
            Some('(') => {
                if self.depth >= MAX_NESTING {
                    return self.err(PolyErrorKind::TooDeep { max: MAX_NESTING });
                }
                let open = self.pos;
                self.pos += 1;
                self.depth += 1;
                if self.peek() == Some(')') {
                    return self.err(PolyErrorKind::EmptyParentheses);
                }
                let inner = self.expr()?;
                self.depth -= 1;
                if self.peek() != Some(')') {
                    return Err(PolyError::at(PolyErrorKind::Unclosed, open + 1));
                }
                self.pos += 1;
                Ok(inner)
            }
            Some(c) if c.is_alphabetic() => self.variable(),
            None => Err(PolyErrorKind::NoTermAtEnd.into()),
            Some(c) => self.err(PolyErrorKind::NoTerm { found: c }),
        }
    }

    /// A few characters from the current position, for error messages.
    fn context(&self) -> String {
        let from = self.pos.saturating_sub(3);
        self.s[from..(self.pos + 3).min(self.s.len())]
            .iter()
            .collect()
    }

    fn number(&mut self) -> Result<BigRational, PolyError> {
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
        let q =
            crate::number::parse_rational(&text).map_err(|e| PolyError::at(e.into(), start + 1))?;
        if coefficient_bits(&q) > MAX_COEFFICIENT_BITS {
            return Err(PolyErrorKind::NumberTooLarge {
                at: start + 1,
                max: MAX_COEFFICIENT_BITS,
            }
            .into());
        }
        Ok(q)
    }

    fn variable(&mut self) -> Result<Polynomial, PolyError> {
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
            return self.err(self.unknown_variable(false));
        };
        let len = name.chars().count();
        if self
            .at(self.pos + len)
            .is_some_and(|c| c.is_ascii_digit() || c == '_')
        {
            return self.err(self.unknown_variable(true));
        }
        self.pos += len;
        Ok(Polynomial::variable(nv, i))
    }

    /// The word at the current position is none of the variables.
    fn unknown_variable(&self, hint: bool) -> PolyErrorKind {
        PolyErrorKind::UnknownVariable {
            word: self.word(),
            names: self.names.iter().map(|n| n.to_string()).collect(),
            hint,
        }
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

fn check_degree(d: u64) -> Result<(), PolyError> {
    if d > u64::from(MAX_DEGREE) {
        return Err(PolyErrorKind::DegreeTooHigh {
            degree: d,
            max: MAX_DEGREE,
        }
        .into());
    }
    Ok(())
}

fn check_bits(bits: u64) -> Result<(), PolyError> {
    if bits > MAX_COEFFICIENT_BITS {
        return Err(PolyErrorKind::CoefficientTooLarge {
            bits,
            max: MAX_COEFFICIENT_BITS,
        }
        .into());
    }
    Ok(())
}

/// A sum adds at most one bit to the larger numerator, and multiplies denominators.
/// Charge `pairs` coefficient products of `bits` bits each against the budget [`MAX_WORK`].
fn charge(work: &mut Budget, pairs: usize, bits: u64) -> Result<(), PolyError> {
    let words = bits / 64 + 1;
    charge_units(
        work,
        (pairs as u64).saturating_mul(words.saturating_mul(words)),
        &format!("coefficients of about {bits} bits in {pairs} products"),
    )
}

/// Charge `units` word operations (`what` says what for, in the error).
fn charge_units(work: &mut Budget, units: u64, what: &str) -> Result<(), PolyError> {
    work.spent = work.spent.saturating_add(units);
    if work.spent > work.limit {
        return Err(PolyErrorKind::TooMuchWork {
            limit: work.limit,
            what: what.to_string(),
        }
        .into());
    }
    Ok(())
}

/// Lehmer's gcd costs a few products' worth of word operations per word of its arguments.
const GCD_WEIGHT: u64 = 8;

/// Charge `a + b`: each coefficient sum of two terms with the same monomial cross-multiplies the
/// denominators, then reduces by a gcd with their product, which costs about
/// `words(numerator)·words(denominators) + GCD_WEIGHT·words(denominators)²` (cheap when the
/// denominators are small, whatever the numerators).
fn charge_sum(a: &Polynomial, b: &Polynomial, work: &mut Budget) -> Result<(), PolyError> {
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

fn check_sum(a: &Polynomial, b: &Polynomial) -> Result<(), PolyError> {
    check_bits(a.max_coefficient_bits() + b.max_coefficient_bits() + 1)
}

/// `a · b`, after checking the degree, the number of term products and the coefficient size.
fn checked_mul(a: &Polynomial, b: &Polynomial, work: &mut Budget) -> Result<Polynomial, PolyError> {
    if a.is_zero() || b.is_zero() {
        return Ok(Polynomial::zero(a.nvars));
    }
    let deg = |p: &Polynomial| u64::from(p.degree().unwrap_or(0));
    check_degree(deg(a) + deg(b))?;
    let pairs = a.terms.len().saturating_mul(b.terms.len());
    if pairs > MAX_TERM_PRODUCTS {
        return Err(PolyErrorKind::TooManyTermProducts {
            left: a.terms.len(),
            right: b.terms.len(),
            max: MAX_TERM_PRODUCTS,
        }
        .into());
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
fn checked_div(a: &Polynomial, b: &Polynomial, work: &mut Budget) -> Result<Polynomial, PolyError> {
    if b.degree().unwrap_or(0) > 0 {
        return Err(PolyErrorKind::DivisorNotConstant.into());
    }
    let c = b
        .terms
        .values()
        .next()
        .ok_or(PolyErrorKind::DivisionByZero)?;
    check_bits(a.max_coefficient_bits() + coefficient_bits(c))?;
    charge(
        work,
        a.terms.len(),
        a.max_coefficient_bits() + coefficient_bits(c),
    )?;
    Ok(a.scale(&q_div(&BigRational::one(), c)))
}

/// `p^k`, after checking the degree `deg(p)·k` and the coefficient size `bits(p)·k`.
fn checked_pow(p: &Polynomial, k: u64, work: &mut Budget) -> Result<Polynomial, PolyError> {
    if k == 0 {
        return Ok(Polynomial::constant(p.nvars, BigRational::one()));
    }
    if p.is_zero() {
        return Ok(p.clone());
    }
    let deg = u64::from(p.degree().unwrap_or(0));
    if deg.saturating_mul(k) > u64::from(MAX_DEGREE) {
        return Err(PolyErrorKind::PowerDegreeTooHigh {
            exponent: k,
            degree: deg.saturating_mul(k),
            max: MAX_DEGREE,
        }
        .into());
    }
    check_bits(p.max_coefficient_bits().saturating_mul(k))?;
    if deg == 0 {
        // invariant: the zero polynomial returned above, so a degree-0 `p` has its one constant term
        let c = p.terms.values().next().expect("non-zero");
        let k = u32::try_from(k).map_err(|_| PolyErrorKind::ExponentOverflow)?;
        charge(work, 1, coefficient_bits(c).saturating_mul(u64::from(k)))?;
        return Ok(Polynomial::constant(p.nvars, q_pow(c, k)));
    }
    let mut out = p.clone();
    for _ in 1..k {
        out = checked_mul(&out, p, work)?;
    }
    Ok(out)
}
