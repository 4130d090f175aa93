//! Unit tests of polynomials: arithmetic, the symbolic forms, and polynomial text (its grammar,
//! names, limits and every error message).

use super::*;
use crate::domain::Domain;
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
    let e = Polynomial::parse("(1e9999 + u + v)^9", &uvw)
        .unwrap_err()
        .to_string();
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
    let e = Polynomial::parse_with_work_limit(&huge, &uvw, 1 << 20)
        .unwrap_err()
        .to_string();
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
    let err = |s: &str| Polynomial::parse(s, &names3()).unwrap_err().to_string();
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
        Polynomial::parse("v + w", &["", "v", "w"])
            .unwrap_err()
            .to_string(),
        "variable name 1 is empty"
    );
    assert_eq!(
        Polynomial::parse("x + y", &["", "y", "z"])
            .unwrap_err()
            .to_string(),
        "variable name 1 is empty"
    );
    assert_eq!(
        check_names(&["u", "v", ""]).unwrap_err().to_string(),
        "variable name 3 is empty"
    );
    assert!(
        check_names(&["u", "u"])
            .unwrap_err()
            .to_string()
            .contains("twice")
    );
    assert!(
        check_names(&["2u"])
            .unwrap_err()
            .to_string()
            .contains("start with a letter")
    );
    assert!(
        check_names(&["u v"])
            .unwrap_err()
            .to_string()
            .contains("only letters")
    );
    assert!(
        check_names(&["u*v"])
            .unwrap_err()
            .to_string()
            .contains("only letters")
    );
    assert!(check_names(&["u", "u1", "λ_2"]).is_ok());
    let p = Polynomial::parse("u1 u + λ_2", &["u", "u1", "λ_2"]).unwrap();
    assert_eq!(p.to_text(&["u", "u1", "λ_2"]), "u*u1 + λ_2");
}

#[test]
fn ambiguous_juxtapositions_are_errors() {
    let err = |s: &str| Polynomial::parse(s, &names3()).unwrap_err().to_string();
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
    let e = Polynomial::parse(&ten, &names3()).unwrap_err().to_string();
    assert!(e.contains("limit of 1048576 bits"), "{e}");
    let three = Polynomial::parse("1e100000*1e100000*1e100000 u", &names3()).unwrap();
    let big = BigRational::from_integer(BigInt::from(10u32).pow(300_000u32));
    assert_eq!(three, Polynomial::monomial(3, vec![1, 0, 0], big));
    let e = Polynomial::parse("2^4294967295", &names3())
        .unwrap_err()
        .to_string();
    assert!(e.contains("bits"), "{e}");
    assert_eq!(
        Polynomial::parse("2^1000", &names3()).unwrap(),
        Polynomial::constant(3, BigRational::from_integer(BigInt::one() << 1000usize))
    );
    // (u+v+w+1)^20 has C(23,3) = 1771 terms; times itself: 3136441 term products.
    let e = Polynomial::parse("(u+v+w+1)^20 * (u+v+w+1)^20", &names3())
        .unwrap_err()
        .to_string();
    assert!(e.contains("limit of 1000000 term products"), "{e}");
}

#[test]
fn sympy_printed_polynomials() {
    // fixtures/polynomials/sympy_printed.txt: SymPy's printing of a product of powers and
    // SymPy's own expansion of it (made by sympy_printed.py beside it).
    let xyz = ["x", "y", "z"];
    let text = include_str!("../../../../fixtures/polynomials/sympy_printed.txt");
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
