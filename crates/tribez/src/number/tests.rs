//! The number module's unit and property tests (one file for all its concepts).

use super::round::{BINARY32, BINARY64, floor_log2_mag, is_power_of_two, round_big, round_small};
use super::*;
use num_bigint::{BigUint, Sign};
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

fn q(s: &str) -> BigRational {
    parse_rational(s).unwrap_or_else(|e| panic!("{s}: {e}"))
}

fn fmt(s: &str) -> String {
    format_rational(&q(s))
}

fn ratio(n: i128, d: i128) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// Exact decimal text of a dyadic rational m/2^k (m·5^k / 10^k).
fn dyadic_decimal(x: &BigRational) -> String {
    let k = x.denom().bits() - 1;
    assert!(is_power_of_two(x.denom().magnitude()));
    let digits = (x.numer().abs() * BigInt::from(5u32).pow(k as u32)).to_string();
    let sign = if x.numer().sign() == Sign::Minus {
        "-"
    } else {
        ""
    };
    format!("{sign}{digits}e-{k}")
}

fn f64_bits_eq(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits()
}

// ----- parsing -----

#[test]
fn parses_integers_and_fractions() {
    assert_eq!(fmt("7"), "7");
    assert_eq!(fmt("-12"), "-12");
    assert_eq!(fmt("+3"), "3");
    assert_eq!(fmt("  42\t\n"), "42");
    assert_eq!(fmt("-0"), "0");
    assert_eq!(fmt("007"), "7");
    assert_eq!(fmt("4/9"), "4/9");
    assert_eq!(fmt("-3/6"), "-1/2");
    assert_eq!(fmt("+10/5"), "2");
    assert_eq!(fmt("0/5"), "0");
    assert_eq!(fmt("-0/5"), "0");
    assert_eq!(
        fmt("123456789012345678901234567890/10"),
        "12345678901234567890123456789"
    );
}

#[test]
fn parses_decimals_exactly() {
    assert_eq!(fmt("0.125"), "1/8");
    assert_eq!(fmt("-1.5e-3"), "-3/2000");
    assert_eq!(fmt(".5"), "1/2");
    assert_eq!(fmt("5."), "5");
    assert_eq!(fmt("1E10"), "10000000000");
    assert_eq!(fmt("2e+3"), "2000");
    assert_eq!(fmt("0.1"), "1/10");
    assert_eq!(fmt("-0.0"), "0");
    assert_eq!(fmt("1.25e-0"), "5/4");
    assert_eq!(fmt("12.5e-1"), "5/4");
    assert_eq!(fmt("1e-00005"), "1/100000");
    assert_eq!(
        q("1e100000"),
        BigRational::from_integer(BigInt::from(10u32).pow(100_000))
    );
    assert_eq!(
        q("1e-100000").recip(),
        BigRational::from_integer(BigInt::from(10u32).pow(100_000))
    );
}

#[test]
fn parses_hex_floats() {
    assert_eq!(fmt("0x1.8p-3"), "3/16");
    assert_eq!(fmt("-0X1P+4"), "-16");
    assert_eq!(fmt("0x.8p0"), "1/2");
    assert_eq!(fmt("0x10"), "16");
    assert_eq!(fmt("0xff"), "255");
    assert_eq!(fmt("0x1.p1"), "2");
    assert_eq!(fmt("0xA.Bp0"), "171/16");
    assert_eq!(fmt("0x1.8e"), "199/128"); // `e` is a hex digit, not an exponent
    assert_eq!(fmt("0x1p-1074"), format!("1/{}", BigInt::one() << 1074u32));
    assert_eq!(q("0x1.999999999999ap-4"), exact_f64(0.1).unwrap());
    assert_eq!(q("0x0.0000000000001p-1022"), exact_f64(5e-324).unwrap());
}

#[test]
fn parses_float_prefixes() {
    assert_eq!(fmt("f64:0.1"), "3602879701896397/36028797018963968");
    assert_eq!(q("f64:0.1"), exact_f64(0.1).unwrap());
    assert_eq!(q("f64: -2.5e-3 "), exact_f64(-2.5e-3).unwrap());
    assert_eq!(q("f64:1/3"), exact_f64(1.0 / 3.0).unwrap());
    assert_eq!(q("f64:0x1.8p-3"), q("3/16"));
    assert_eq!(q("f64:1e-400"), BigRational::zero());
    assert_eq!(q("f64:-1e-400"), BigRational::zero());
    assert_eq!(
        q("f64:1.7976931348623157e308"),
        exact_f64(f64::MAX).unwrap()
    );
    // 0.1f32 = 13421773 / 2^27
    assert_eq!(fmt("f32:0.1"), "13421773/134217728");
    assert_eq!(q("f32:0.1"), exact_f32(0.1f32).unwrap());
    assert_eq!(q("f32:3.4028235e38"), exact_f32(f32::MAX).unwrap());
    assert_eq!(q("f32:1e-50"), BigRational::zero());
    // Rounded directly to f32: no double rounding through f64.
    let via_direct = q("f32:0x1.000001000000001p0"); // 1 + 2^-24 + 2^-60
    assert_eq!(via_direct, q("0x1.000002p0")); // 1 + 2^-23
}

#[test]
fn rejects_bad_text() {
    use NumberError::*;
    let err = |s: &str| parse_rational(s).unwrap_err();
    assert_eq!(err(""), Empty);
    assert_eq!(err("   "), Empty);
    for s in [
        "abc",
        "1/-2",
        "1/+2",
        "--1",
        "+-1",
        "-+1",
        "- 1",
        "1 2",
        "1/2/3",
        "/2",
        "1/",
        ".",
        "e5",
        "1e",
        "1e+",
        "1e--5",
        "1.2.3",
        "0x",
        "0x.p1",
        "0x1p",
        "0x1.8q",
        "0xg",
        "1_000",
        "0x1_0",
        "f64:",
        "f64:f64:1",
        "f32:abc",
        "F64:1",
        "1/2.5",
        "0x10/3",
        "١",
        "1e5.5",
        "0b101",
        "1,5",
        "++1",
    ] {
        assert_eq!(err(s), Syntax(s.trim().to_owned()), "{s:?}");
    }
    assert_eq!(err("1/0"), ZeroDenominator("1/0".into()));
    assert_eq!(err("-0/00"), ZeroDenominator("-0/00".into()));
    for s in ["nan", "NaN", "-nan", "f64:nan"] {
        assert_eq!(err(s), Nan(s.into()));
    }
    for s in ["inf", "-inf", "+Infinity", "INF", "f32:inf"] {
        assert_eq!(err(s), Infinite(s.into()));
    }
    for s in [
        "1e100001",
        "1e-100001",
        "0x1p100001",
        "0e9999999999999999999999",
        "f64:1e-1000000",
    ] {
        assert_eq!(err(s), ExponentTooLarge(s.into()), "{s}");
    }
    assert_eq!(
        err("f64:1e999"),
        NotFinite {
            text: "f64:1e999".into(),
            format: "f64"
        }
    );
    assert_eq!(
        err("f64:-0x1p1024"),
        NotFinite {
            text: "f64:-0x1p1024".into(),
            format: "f64"
        }
    );
    assert_eq!(
        err("f32:1e39"),
        NotFinite {
            text: "f32:1e39".into(),
            format: "f32"
        }
    );
}

#[test]
fn error_messages() {
    let msg = |s: &str| parse_rational(s).unwrap_err().to_string();
    assert_eq!(msg("1/0"), "`1/0`: zero denominator");
    assert_eq!(
        msg("abc"),
        "`abc`: not a number (expected an integer, p/q, decimal, hex float, or f64:/f32: prefix)"
    );
    assert_eq!(msg("f64:1e999"), "`f64:1e999`: not a finite f64");
    // control characters are shown escaped, so that the message is one line (found by the
    // fuzz target `hunt_answer`: a line break inside an answer's field)
    assert_eq!(
        msg("1\n\u{15}2\t3"),
        "`1\\n\\u{15}2\\t3`: not a number (expected an integer, p/q, decimal, hex float, or f64:/f32: prefix)"
    );
    assert_eq!(msg("nan"), "`nan`: NaN has no exact value");
    assert_eq!(msg("-inf"), "`-inf`: infinity has no exact value");
}

// ----- printing -----

#[test]
fn formats_rationals() {
    assert_eq!(format_rational(&ratio(6, -4)), "-3/2");
    assert_eq!(format_rational(&ratio(0, -7)), "0");
    let raw = BigRational::new_raw(BigInt::from(6), BigInt::from(-4));
    assert_eq!(format_rational(&raw), "-3/2");
    let raw_zero = BigRational::new_raw(BigInt::from(0), BigInt::from(-4));
    assert_eq!(format_rational(&raw_zero), "0");
    let raw_int = BigRational::new_raw(BigInt::from(-8), BigInt::from(-4));
    assert_eq!(format_rational(&raw_int), "2");
}

#[test]
fn decimal_strings() {
    let d = |s: &str, n| to_decimal_string(&q(s), n);
    assert_eq!(d("1/3", 5), "0.33333");
    assert_eq!(d("2/3", 3), "0.667");
    assert_eq!(d("-1/8", 17), "-0.125");
    assert_eq!(d("12", 17), "12");
    assert_eq!(d("0", 5), "0");
    assert_eq!(d("1", 1), "1");
    assert_eq!(d("100", 3), "100");
    assert_eq!(d("1000", 3), "1e3");
    assert_eq!(d("9.96", 2), "10");
    assert_eq!(d("99.6", 2), "1e2");
    assert_eq!(d("0.25", 1), "0.2"); // tie to even
    assert_eq!(d("0.35", 1), "0.4"); // tie to even
    assert_eq!(d("0.3500001", 1), "0.4");
    assert_eq!(d("1/7", 0), "0.1"); // digits clamped to 1
    assert_eq!(d("0.00001", 3), "0.00001");
    assert_eq!(d("0.000001", 3), "1e-6");
    assert_eq!(d("1.2345e-20", 5), "1.2345e-20");
    assert_eq!(d("-1.2345e-20", 3), "-1.23e-20");
    assert_eq!(d("1e300", 17), "1e300");
    assert_eq!(d("1e-300", 17), "1e-300");
    assert_eq!(
        d("123456789012345678901234567890", 40),
        "1.2345678901234567890123456789e29"
    );
    assert_eq!(
        to_decimal_string(&exact_f64(0.1).unwrap(), 17),
        "0.10000000000000001"
    );
    assert_eq!(
        to_decimal_string(&exact_f64(0.1).unwrap(), 55),
        "0.1000000000000000055511151231257827021181583404541015625"
    );
}

#[test]
fn display_floats() {
    assert_eq!(display_f64(0.1), "0.1");
    assert_eq!(display_f64(1.0), "1");
    assert_eq!(display_f64(-0.0), "-0");
    assert_eq!(display_f64(1e300), "1e300");
    assert_eq!(display_f64(5e-324), "5e-324");
    assert_eq!(display_f64(0.1 + 0.2), "0.30000000000000004");
    assert_eq!(display_f64(f64::INFINITY), "inf");
    assert_eq!(display_f32(0.1), "0.1");
    assert_eq!(display_f32(1e-40), "1e-40");
    assert_eq!(display_f32(f32::MAX), "3.4028235e38");
}

#[test]
fn hex_texts() {
    assert_eq!(hex_f64(0.1), "0x1.999999999999ap-4");
    assert_eq!(q(&hex_f64(0.1)), exact_f64(0.1).unwrap());
    assert_eq!(hex_f64(1.0), "0x1p+0");
    assert_eq!(hex_f64(-1.0), "-0x1p+0");
    assert_eq!(hex_f64(0.0), "0x0p+0");
    assert_eq!(hex_f64(-0.0), "-0x0p+0");
    assert_eq!(hex_f64(1.5), "0x1.8p+0");
    assert_eq!(hex_f64(5e-324), "0x0.0000000000001p-1022");
    assert_eq!(hex_f64(f64::MIN_POSITIVE), "0x1p-1022");
    assert_eq!(hex_f64(f64::MAX), "0x1.fffffffffffffp+1023");
    assert_eq!(hex_f64(f64::INFINITY), "inf");
    assert_eq!(hex_f64(f64::NEG_INFINITY), "-inf");
    assert_eq!(hex_f64(f64::NAN), "nan");
    assert_eq!(hex_f32(0.1), "0x1.99999ap-4");
    assert_eq!(hex_f32(-2.0), "-0x1p+1");
    assert_eq!(hex_f32(f32::from_bits(1)), "0x0.000002p-126");
    assert_eq!(hex_f32(f32::MAX), "0x1.fffffep+127");
    assert_eq!(hex_f32(f32::NAN), "nan");
}

// ----- exact values and rounding -----

#[test]
fn exact_values() {
    assert_eq!(
        format_rational(&exact_f64(0.1).unwrap()),
        "3602879701896397/36028797018963968"
    );
    assert_eq!(exact_f64(1.0).unwrap(), BigRational::one());
    assert_eq!(exact_f64(-0.0).unwrap(), BigRational::zero());
    assert_eq!(exact_f64(-3.0).unwrap(), ratio(-3, 1));
    assert_eq!(exact_f64(5e-324).unwrap(), pow2(-1074));
    assert_eq!(exact_f64(f64::MIN_POSITIVE).unwrap(), pow2(-1022));
    assert_eq!(exact_f64(f64::MAX).unwrap(), pow2(1024) - pow2(971));
    assert_eq!(exact_f64(2f64.powi(100)).unwrap(), pow2(100));
    assert_eq!(exact_f64(f64::INFINITY), None);
    assert_eq!(exact_f64(f64::NAN), None);
    assert_eq!(exact_f32(0.1).unwrap(), ratio(13421773, 1 << 27));
    assert_eq!(exact_f32(f32::from_bits(1)).unwrap(), pow2(-149));
    assert_eq!(exact_f32(f32::MAX).unwrap(), pow2(128) - pow2(104));
    assert_eq!(exact_f32(f32::NEG_INFINITY), None);
}

#[test]
fn round_trips_of_special_values() {
    let specials = [
        0.0,
        1.0,
        -1.0,
        0.5,
        2.0,
        1024.0,
        0.1,
        f64::MIN_POSITIVE,
        -f64::MIN_POSITIVE,
        5e-324,
        -5e-324,
        f64::MAX,
        f64::MIN,
        f64::EPSILON,
        2f64.powi(-1000),
        2f64.powi(1000),
        f64::from_bits(0x000F_FFFF_FFFF_FFFF),
    ];
    for x in specials {
        assert!(f64_bits_eq(round_f64(&exact_f64(x).unwrap()), x), "{x:e}");
    }
    assert!(f64_bits_eq(round_f64(&exact_f64(-0.0).unwrap()), 0.0));
    for x in [
        0.0f32,
        1.0,
        -0.1,
        f32::MIN_POSITIVE,
        f32::from_bits(1),
        f32::MAX,
        f32::MIN,
    ] {
        assert_eq!(
            round_f32(&exact_f32(x).unwrap()).to_bits(),
            x.to_bits(),
            "{x:e}"
        );
    }
}

#[test]
fn rounding_ties_and_edges() {
    let one = BigRational::one();
    // 1 + 2^-53 is halfway between 1 and 1 + 2^-52: ties to even, down.
    assert_eq!(round_f64(&(&one + pow2(-53))), 1.0);
    // 1 + 3·2^-53 is halfway between 1 + 2^-52 and 1 + 2^-51: up.
    assert_eq!(
        round_f64(&(&one + pow2(-53) * ratio(3, 1))),
        1.0 + 2f64.powi(-51)
    );
    assert_eq!(
        round_f64(&(&one + pow2(-53) + pow2(-200))),
        1.0 + 2f64.powi(-52)
    );
    assert_eq!(round_f64(&(&one - pow2(-54))), 1.0); // tie below 1: even is 1
    assert_eq!(
        round_f64(&(&one - pow2(-54) - pow2(-300))),
        1.0 - 2f64.powi(-53)
    );
    // Overflow: 2^1024 - 2^970 is a tie between MAX and 2^1024: to infinity.
    let tie = pow2(1024) - pow2(970);
    assert_eq!(round_f64(&tie), f64::INFINITY);
    assert_eq!(round_f64(&-&tie), f64::NEG_INFINITY);
    assert_eq!(round_f64(&(&tie - pow2(-1000))), f64::MAX);
    assert_eq!(round_f64(&(&tie - BigRational::one())), f64::MAX);
    assert_eq!(round_f64(&(tie / ratio(3, 1) * ratio(3, 1))), f64::INFINITY);
    assert_eq!(round_f64(&pow2(5000)), f64::INFINITY);
    assert_eq!(round_f64(&q("1e100000")), f64::INFINITY);
    // Subnormals: 2^-1075 is a tie between 0 and 2^-1074: to 0 (even).
    assert!(f64_bits_eq(round_f64(&pow2(-1075)), 0.0));
    assert!(f64_bits_eq(round_f64(&-pow2(-1075)), -0.0));
    assert_eq!(round_f64(&(pow2(-1075) + pow2(-2000))), 5e-324);
    assert_eq!(round_f64(&(pow2(-1075) * ratio(3, 1))), 1e-323); // tie 1.5 → 2
    assert_eq!(round_f64(&q("1e-100000")), 0.0);
    assert_eq!(round_f64(&(ratio(1, 3) * pow2(-1070))), f64::from_bits(5)); // 16/3 → 5
    // The largest subnormal rounds up into the normal range.
    assert_eq!(round_f64(&(pow2(-1022) - pow2(-1076))), f64::MIN_POSITIVE);
    assert!(f64_bits_eq(round_f64(&BigRational::zero()), 0.0));
    assert!(round_f64(&BigRational::new_raw(BigInt::one(), BigInt::zero())).is_nan());
    // Small (u64) and big paths, non-dyadic.
    assert_eq!(round_f64(&ratio(1, 3)), 1.0 / 3.0);
    assert_eq!(round_f64(&ratio(-2, 3)), -2.0 / 3.0);
    assert_eq!(
        round_f64(&ratio(u64::MAX as i128, 1)),
        18446744073709551615.0
    );
    assert_eq!(
        round_f64(&ratio(1, u64::MAX as i128)),
        5.421010862427522e-20
    );
    // 2^-1050/3 = (2^24/3)·2^-1074 = 5592405.33·2^-1074
    assert_eq!(
        round_f64(&(ratio(1, 3) * pow2(-1050))),
        f64::from_bits(5592405)
    );
    assert_eq!(
        round_f64(&BigRational::new_raw(BigInt::from(1), BigInt::from(-3))),
        -1.0 / 3.0
    );
}

#[test]
fn f32_rounds_once() {
    // q = 1 + 2^-24 + 2^-60: just above the midpoint of 1 and 1 + 2^-23.
    let q1 = BigRational::one() + pow2(-24) + pow2(-60);
    assert_eq!(round_f32(&q1), 1.0 + 2f32.powi(-23));
    // Via f64 it would first become 1 + 2^-24, then tie to even down to 1.
    let via_f64 = round_f64(&q1);
    assert_eq!(via_f64, 1.0 + 2f64.powi(-24));
    assert_eq!(via_f64 as f32, 1.0);
    assert_eq!(round_f32(&(BigRational::one() + pow2(-24))), 1.0);
    // Overflow tie 2^128 - 2^103.
    let tie = pow2(128) - pow2(103);
    assert_eq!(round_f32(&tie), f32::INFINITY);
    assert_eq!(round_f32(&(&tie - pow2(-10))), f32::MAX);
    // Subnormal ties around 2^-149.
    assert_eq!(round_f32(&pow2(-150)).to_bits(), 0);
    assert_eq!(round_f32(&-pow2(-150)).to_bits(), (-0.0f32).to_bits());
    assert_eq!(round_f32(&(pow2(-150) * ratio(3, 1))), f32::from_bits(2));
    assert_eq!(round_f32(&ratio(1, 10)), 0.1f32);
    assert_eq!(round_f32(&ratio(1, 3)), 1.0f32 / 3.0);
}

#[test]
fn faithful() {
    let tenth = ratio(1, 10);
    assert!(is_faithful_f64(0.1, &tenth));
    assert!(is_faithful_f64(0.1f64.next_down(), &tenth)); // 0.1 is above 1/10
    assert!(!is_faithful_f64(0.1f64.next_up(), &tenth));
    assert!(!is_faithful_f64(f64::NAN, &tenth));
    assert!(is_faithful_f64(1.0, &BigRational::one()));
    assert!(!is_faithful_f64(1.0f64.next_up(), &BigRational::one()));
    assert!(is_faithful_f64(-0.0, &BigRational::zero()));
    assert!(!is_faithful_f64(5e-324, &BigRational::zero()));
    assert!(is_faithful_f64(0.0, &pow2(-1100)));
    assert!(is_faithful_f64(5e-324, &pow2(-1100)));
    assert!(is_faithful_f64(-0.0, &-pow2(-1100)));
    assert!(is_faithful_f64(-5e-324, &-pow2(-1100)));
    assert!(!is_faithful_f64(5e-324, &-pow2(-1100)));
    assert!(is_faithful_f64(f64::MAX, &pow2(2000)));
    assert!(is_faithful_f64(f64::INFINITY, &pow2(2000)));
    assert!(is_faithful_f64(f64::NEG_INFINITY, &-pow2(2000)));
    assert!(is_faithful_f64(f64::MIN, &-pow2(2000)));
    assert!(!is_faithful_f64(
        f64::INFINITY,
        &exact_f64(f64::MAX).unwrap()
    ));
    assert!(is_faithful_f32(0.1, &tenth));
    assert!(is_faithful_f32(0.1f32.next_down(), &tenth));
    assert!(!is_faithful_f32(0.1f32.next_up(), &tenth));
}

#[test]
fn ulps_and_log2() {
    assert_eq!(floor_log2(&ratio(1, 1)), 0);
    assert_eq!(floor_log2(&ratio(-7, 1)), 2);
    assert_eq!(floor_log2(&ratio(8, 1)), 3);
    assert_eq!(floor_log2(&ratio(1, 10)), -4);
    assert_eq!(floor_log2(&ratio(1, 8)), -3);
    assert_eq!(floor_log2(&ratio(3, 4)), -1);
    assert_eq!(floor_log2(&(pow2(300) - pow2(-300))), 299);
    assert_eq!(floor_log2(&(pow2(300) + pow2(-300))), 300);
    assert_eq!(floor_log2(&BigRational::zero()), i64::MIN);
    assert_eq!(ulp_f64(&BigRational::one()), pow2(-52));
    assert_eq!(ulp_f64(&ratio(1, 10)), pow2(-56));
    assert_eq!(ulp_f64(&BigRational::zero()), pow2(-1074));
    assert_eq!(ulp_f64(&pow2(-1060)), pow2(-1074));
    assert_eq!(ulp_f64(&exact_f64(f64::MAX).unwrap()), pow2(971));
    assert_eq!(ulp_f32(&BigRational::one()), pow2(-23));
    assert_eq!(ulp_f32(&BigRational::zero()), pow2(-149));
    assert_eq!(ulp_f32(&pow2(-140)), pow2(-149));
    // docs/theory.md §14.4: |0.1 - 1/10| = 1/180143985094819840 = 0.4 ulp(1/10).
    let x = exact_f64(0.1).unwrap();
    assert_eq!(
        format_rational(&(&x - ratio(1, 10))),
        "1/180143985094819840"
    );
    assert_eq!(ulps_error_f64(&x, &ratio(1, 10)), ratio(2, 5));
    // (0.1 + 0.2) - 3/10 = 0.8 ulp(3/10).
    let sum = exact_f64(0.1 + 0.2).unwrap();
    assert_eq!(ulps_error_f64(&sum, &ratio(3, 10)), ratio(4, 5));
    // f32: 1/10 is in [2^-4, 2^-3), so ulp = 2^-27, and 0.1f32 = 13421773/2^27;
    // 13421773/2^27 - 1/10 = (134217730 - 134217728)/(10·2^27) = (1/5)·2^-27.
    assert_eq!(
        ulps_error_f32(&exact_f32(0.1).unwrap(), &ratio(1, 10)),
        ratio(1, 5)
    );
}

#[test]
fn steps() {
    assert_eq!(steps_f64(0.1 + 0.2, 0.3), 1);
    assert_eq!(steps_f64(0.3, 0.1 + 0.2), 1);
    assert_eq!(steps_f64(-5e-324, 5e-324), 2);
    assert_eq!(steps_f64(-0.0, 0.0), 0);
    assert_eq!(steps_f64(1.0, 1.0), 0);
    assert_eq!(steps_f64(1.0, 2.0), 1 << 52);
    assert_eq!(steps_f64(f64::MAX, f64::INFINITY), 1);
    assert_eq!(
        steps_f64(f64::NEG_INFINITY, f64::INFINITY),
        2 * 0x7FF0_0000_0000_0000
    );
    assert_eq!(steps_f64(f64::NAN, 1.0), u64::MAX);
    assert_eq!(steps_f32(-f32::from_bits(1), f32::from_bits(1)), 2);
    assert_eq!(steps_f32(1.0, 1.0f32.next_up()), 1);
    assert_eq!(steps_f32(f32::NEG_INFINITY, f32::INFINITY), 2 * 0x7F80_0000);
    assert_eq!(steps_f64(round_f64(&ratio(3, 10)), 0.1 + 0.2), 1);
}

// ----- properties -----

/// A decimal text with up to 25 mantissa digits, a point somewhere, and an exponent.
fn decimal_text(exp: std::ops::Range<i32>) -> impl Strategy<Value = String> {
    (
        any::<bool>(),
        "[0-9]{1,25}",
        any::<prop::sample::Index>(),
        exp,
    )
        .prop_map(|(neg, digits, point, e)| {
            let p = point.index(digits.len() + 1);
            let sign = if neg { "-" } else { "" };
            format!("{sign}{}.{}e{e}", &digits[..p], &digits[p..])
        })
}

fn any_rational() -> impl Strategy<Value = BigRational> {
    (any::<i128>(), any::<u128>(), -1200i64..1200, 0u32..3).prop_map(|(n, d, k, which)| {
        let d = match which {
            0 => d.max(1),
            1 => d >> (d % 128).max(1), // often small
            _ => u128::from(d as u64 >> 40),
        }
        .max(1);
        BigRational::new(BigInt::from(n), BigInt::from(d)) * pow2(k)
    })
}

proptest! {
    #[test]
    fn f64_bits_round_trip(bits in any::<u64>()) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        let back = round_f64(&exact_f64(x).unwrap());
        let expected = if x == 0.0 { 0.0 } else { x };
        prop_assert_eq!(back.to_bits(), expected.to_bits());
        prop_assert_eq!(q(&hex_f64(x)), exact_f64(x).unwrap());
        prop_assert_eq!(to_decimal_string(&exact_f64(x).unwrap(), 17).parse::<f64>().unwrap(), x);
        prop_assert_eq!(q(&display_f64(x)), exact_decimal_of(&display_f64(x)));
        prop_assert_eq!(display_f64(x).parse::<f64>().unwrap(), x);
    }

    #[test]
    fn f32_bits_round_trip(bits in any::<u32>()) {
        let x = f32::from_bits(bits);
        prop_assume!(x.is_finite());
        let back = round_f32(&exact_f32(x).unwrap());
        let expected = if x == 0.0 { 0.0 } else { x };
        prop_assert_eq!(back.to_bits(), expected.to_bits());
        prop_assert_eq!(q(&hex_f32(x)), exact_f32(x).unwrap());
        prop_assert_eq!(display_f32(x).parse::<f32>().unwrap(), x);
    }

    /// `round_up_f64(q)` is the least float not below `q`: not below it, and its predecessor
    /// below it (checked on exact values; ±∞ and `f64::MIN` at the ends).
    #[test]
    fn round_up_is_the_least_float_not_below(q in any_rational()) {
        let x = round_up_f64(&q);
        match exact_f64(x) {
            Some(v) => {
                prop_assert!(v >= q, "{x:e} below {q}");
                if x != f64::MIN {
                    prop_assert!(exact_f64(x.next_down()).unwrap() < q, "{x:e} not the least");
                }
            }
            None => prop_assert!(x == f64::INFINITY && q > exact_f64(f64::MAX).unwrap()),
        }
    }

    #[test]
    fn decimal_agrees_with_std_f64(s in decimal_text(-345..330)) {
        let expected: f64 = s.parse().unwrap();
        let got = round_f64(&q(&s));
        prop_assert!(got == expected && (got == 0.0 || f64_bits_eq(got, expected)), "{} → {:e} vs std {:e}", s, got, expected);
    }

    #[test]
    fn decimal_agrees_with_std_f32(s in decimal_text(-70..45)) {
        let expected: f32 = s.parse().unwrap();
        let got = round_f32(&q(&s));
        prop_assert!(got == expected && (got == 0.0 || got.to_bits() == expected.to_bits()), "{} → {:e} vs std {:e}", s, got, expected);
    }

    #[test]
    fn midpoints_tie_to_even(bits in any::<u64>()) {
        let x = f64::from_bits(bits & !(1 << 63));
        prop_assume!(x.is_finite() && x != f64::MAX);
        let mid = (exact_f64(x).unwrap() + exact_f64(x.next_up()).unwrap()) / ratio(2, 1);
        let text = dyadic_decimal(&mid);
        let expected: f64 = text.parse().unwrap();
        prop_assert_eq!(round_f64(&mid).to_bits(), expected.to_bits());
        prop_assert_eq!(round_f64(&q(&text)).to_bits(), expected.to_bits());
        // ties go to the even significand
        prop_assert_eq!(expected.to_bits() & 1, 0);
    }

    #[test]
    fn f32_midpoints_tie_to_even(bits in any::<u32>()) {
        let x = f32::from_bits(bits & !(1 << 31));
        prop_assume!(x.is_finite() && x != f32::MAX);
        let mid = (exact_f32(x).unwrap() + exact_f32(x.next_up()).unwrap()) / ratio(2, 1);
        let expected: f32 = dyadic_decimal(&mid).parse().unwrap();
        prop_assert_eq!(round_f32(&mid).to_bits(), expected.to_bits());
        prop_assert_eq!(expected.to_bits() & 1, 0);
    }

    #[test]
    fn rounding_error_within_half_ulp(r in any_rational()) {
        let x = round_f64(&r);
        if x.is_finite() {
            let err = (exact_f64(x).unwrap() - &r).abs();
            prop_assert!(err <= ulp_f64(&r) / ratio(2, 1));
            prop_assert!(ulps_error_f64(&exact_f64(x).unwrap(), &r) <= ratio(1, 2));
        } else {
            prop_assert!(r.abs() >= pow2(1024) - pow2(970));
        }
        let y = round_f32(&r);
        if y.is_finite() {
            let err = (exact_f32(y).unwrap() - &r).abs();
            prop_assert!(err <= ulp_f32(&r) / ratio(2, 1));
        } else {
            prop_assert!(r.abs() >= pow2(128) - pow2(103));
        }
    }

    #[test]
    fn small_and_big_paths_agree(a in any::<u64>(), b in 1u64.., wide in any::<bool>()) {
        let b = if wide { b } else { b >> (b % 64) }.max(1);
        let (ba, bb) = (BigUint::from(a), BigUint::from(b));
        prop_assume!(a != 0);
        for f in [BINARY64, BINARY32] {
            prop_assert_eq!(round_small(a, b, f), round_big(&ba, &bb, f));
        }
        prop_assert_eq!(floor_log2_mag(&ba, &bb), floor_log2(&ratio(i128::from(a), i128::from(b))));
        // floor_log2 defining property
        let e = floor_log2(&ratio(i128::from(a), i128::from(b)));
        let r = ratio(i128::from(a), i128::from(b));
        prop_assert!(pow2(e) <= r && r < pow2(e + 1));
    }

    #[test]
    fn faithful_pair(r in any_rational()) {
        let x = round_f64(&r);
        prop_assert!(is_faithful_f64(x, &r));
        let exact = exact_f64(x).is_some_and(|v| v == r);
        let neighbours = [x.next_down(), x.next_up()]
            .into_iter()
            .filter(|&y| y != x && is_faithful_f64(y, &r))
            .count();
        prop_assert_eq!(neighbours, if exact { 0 } else { 1 });
        let y = round_f32(&r);
        prop_assert!(is_faithful_f32(y, &r));
    }

    #[test]
    fn steps_count_next_up(bits in any::<u64>(), n in 0u64..5) {
        let x = f64::from_bits(bits);
        prop_assume!(x.is_finite());
        let mut y = x;
        for _ in 0..n { y = y.next_up(); }
        prop_assume!(y.is_finite());
        prop_assert_eq!(steps_f64(x, y), n);
    }

    #[test]
    fn parse_never_panics(s in "\\PC{0,30}") {
        let _ = parse_rational(&s);
    }

    #[test]
    fn parse_never_panics_on_number_like(s in "[-+ ]{0,2}(f64:|f32:)?(0[xX])?[0-9a-fA-F.]{0,6}([eEpP][-+]?[0-9]{0,7})?(/[-+]?[0-9]{0,3})?") {
        let _ = parse_rational(&s);
    }
}

/// The exact value of a decimal text via an independent route (std's integer parser).
fn exact_decimal_of(s: &str) -> BigRational {
    let (mant, exp) = s.split_once('e').unwrap_or((s, "0"));
    let exp: i32 = exp.parse().unwrap();
    let (neg, mant) = mant.strip_prefix('-').map_or((false, mant), |m| (true, m));
    let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
    let digits: BigInt = format!("{int}{frac}").parse().unwrap();
    let e = exp - frac.len() as i32;
    let power = BigRational::from_integer(BigInt::from(10).pow(e.unsigned_abs()));
    let v = BigRational::from_integer(digits);
    let v = if e >= 0 { v * power } else { v / power };
    if neg { -v } else { v }
}

// ----- size limits (digits, exponents) and the float range -----

#[test]
fn digit_limit() {
    // At the limit: the value agrees with num-bigint's own decimal parser.
    let n = "7".repeat(MAX_DIGITS);
    assert_eq!(
        q(&n),
        BigRational::from_integer(n.parse::<BigInt>().unwrap())
    );
    let half = "3".repeat(MAX_DIGITS / 2);
    let frac = format!("{half}/{}", "9".repeat(MAX_DIGITS / 2));
    let want = BigRational::new(
        half.parse().unwrap(),
        "9".repeat(MAX_DIGITS / 2).parse().unwrap(),
    );
    assert_eq!(q(&frac), want); // = 1/3
    let dec = format!("0.{}", "1".repeat(MAX_DIGITS - 1));
    let ones: BigInt = "1".repeat(MAX_DIGITS - 1).parse().unwrap();
    assert_eq!(
        q(&dec),
        BigRational::new(ones, BigInt::from(10u32).pow(MAX_DIGITS as u32 - 1))
    );
    // One more digit, in every form: an error naming the limit, on one line.
    for text in [
        "7".repeat(MAX_DIGITS + 1),
        format!("-{}.5e3", "7".repeat(MAX_DIGITS)),
        format!("1/{}", "3".repeat(MAX_DIGITS)),
        format!("0x{}", "f".repeat(MAX_DIGITS + 1)),
        format!("f64:{}", "7".repeat(MAX_DIGITS + 1)),
    ] {
        let e = parse_rational(&text).unwrap_err();
        assert!(
            matches!(
                e,
                NumberError::TooManyDigits {
                    digits: 100_001,
                    limit: 100_000,
                    ..
                }
            ),
            "{e:?}"
        );
        let msg = e.to_string();
        assert!(
            msg.contains("100001 digits, above the limit of 100000 digits"),
            "{msg}"
        );
        assert!(msg.contains("characters)"), "{msg}");
        assert!(msg.len() < 200 && !msg.contains('\n'), "{msg}");
        assert!(e.is_size_limit());
    }
    // A long malformed text is a syntax error, abbreviated.
    let bad = format!("{}x", "7".repeat(MAX_DIGITS * 2));
    let e = parse_rational(&bad).unwrap_err();
    assert_eq!(
        e,
        NumberError::Syntax(format!("{}… (200001 characters)", "7".repeat(32)))
    );
    assert!(!e.is_size_limit());
}

#[test]
fn out_of_float_range_tells_overflow_from_too_long() {
    use OutOfRange::*;
    for (text, want) in [
        ("1e999999", Some(Overflow { negative: false })),
        ("-1e999999", Some(Overflow { negative: true })),
        ("1e-999999", Some(Underflow { negative: false })),
        (
            "-0.5e-99999999999999999999",
            Some(Underflow { negative: true }),
        ),
        ("0x1p99999999", Some(Overflow { negative: false })),
        ("0x.01p-99999999", Some(Underflow { negative: false })),
        ("0.001e100001", Some(Overflow { negative: false })),
        ("1e400", Some(Overflow { negative: false })),
        ("10e399", Some(Overflow { negative: false })), // 1e400
        ("99e398", None),                               // 9.9e399: not certain from the digit count
        ("1e-399", None),
        ("1e300", None),
        ("0e999999", None), // zero
        ("0.000e-999999", None),
        ("1e99x", None),
        ("abc", None),
        ("1/0", None),
        ("f64:1e999999", None),
    ] {
        assert_eq!(out_of_float_range(text), want, "{text}");
    }
    // Overflow and underflow agree with correct rounding where the value can be read.
    assert_eq!(round_f64(&q("1e400")), f64::INFINITY);
    assert_eq!(round_f32(&q("-1e400")), f32::NEG_INFINITY);
    assert_eq!(round_f64(&q("1e-400")), 0.0);
    // Too many digits: the size decides.
    let big = "1".repeat(MAX_DIGITS + 1);
    assert!(parse_rational(&big).unwrap_err().is_size_limit());
    assert_eq!(out_of_float_range(&big), Some(Overflow { negative: false }));
    assert_eq!(
        out_of_float_range(&format!("1/{big}")),
        Some(Underflow { negative: false })
    );
    // A huge written exponent on a small mantissa: refused, yet in range (not an overflow).
    let tiny_mantissa = format!("0.{}1e100001", "0".repeat(99_998));
    let e = parse_rational(&tiny_mantissa).unwrap_err();
    assert!(matches!(e, NumberError::ExponentTooLarge(_)) && e.is_size_limit());
    assert_eq!(out_of_float_range(&tiny_mantissa), None);
    assert!(!parse_rational("1e99x").unwrap_err().is_size_limit());
}

#[test]
fn generic_float_functions_are_the_named_ones() {
    // The `_f64`/`_f32` names are the generic code at each format; spot checks of the
    // f32 instances against hand-derived values.
    assert_eq!(ulp::<f32>(&BigRational::one()), pow2(-23));
    assert_eq!(exact_value(-2.5f32).unwrap(), ratio(-5, 2));
    assert_eq!(hex_float(1.5f32), "0x1.8p+0");
    assert_eq!(display_float(1e-5f32), "0.00001");
    assert_eq!(display_float(9.999999e-6f32), "9.999999e-6");
    assert_eq!(super::steps(1.0f32, 2.0f32), 1 << 23);
    assert!(is_faithful(0.1f32, &ratio(1, 10)));
    assert_eq!(
        ulps_error::<f32>(&exact_f32(0.1).unwrap(), &ratio(1, 10)),
        ratio(1, 5)
    );
    assert_eq!(<f32 as BinaryFloat>::NAME, "f32");
}

proptest! {
    #[test]
    fn decimal_reduction_agrees_with_gcd(s in decimal_text(-60..60)) {
        // Powers of 2 and 5 removed by shifts and divisions = num-rational's gcd reduction.
        prop_assert_eq!(q(&s), exact_decimal_of(&s));
    }

    #[test]
    fn f32_display_and_hex_round_trip_through_the_generic_code(bits in any::<u32>()) {
        let x = f32::from_bits(bits);
        prop_assume!(x.is_finite());
        prop_assert_eq!(display_float(x), display_f32(x));
        prop_assert_eq!(q(&hex_float(x)), exact_value(x).unwrap());
    }
}

// ----- the word fast paths of parsing and printing, against the general code -----

/// Random limbs with runs of zeros and all-ones words (carries, the top chunk of `10^19`).
fn limbs_strategy() -> impl Strategy<Value = Vec<u64>> {
    prop::collection::vec(
        prop_oneof![
            any::<u64>(),
            Just(0u64),
            Just(u64::MAX),
            Just(9_999_999_999_999_999_999u64),
            Just(10_000_000_000_000_000_000u64),
        ],
        0..120,
    )
}

#[test]
fn decimal_printing_at_the_edges() {
    let ten = BigUint::from(10u32);
    // around every chunk and split boundary (10^(19·2^k) has 2^k limbs or so)
    let around = [455, 456, 457, 911, 912, 913, 1500, 3000, 10_000, 30_000];
    for k in (0..120u32).chain(around) {
        for x in [
            ten.pow(k),
            ten.pow(k) - 1u32,
            ten.pow(k) + 1u32,
            ten.pow(k) * 7u32 / 3u32,
        ] {
            let mut s = String::new();
            push_decimal(&mut s, &x);
            assert_eq!(s, x.to_string());
        }
    }
    // around every limb boundary, the stack paths' largest sizes (8, 20 and 47 limbs), the split, and
    // the split's halves
    for bits in (0..=100u32).map(|k| 64 * k) {
        let p = BigUint::one() << bits;
        for x in [p.clone(), &p - 1u32, &p + 1u32, &p * 3u32 - 1u32] {
            let mut s = String::new();
            push_decimal(&mut s, &x);
            assert_eq!(s, x.to_string());
        }
    }
    let mut s = String::new();
    push_decimal(&mut s, &BigUint::zero());
    assert_eq!(s, "0");
    // p/0 (only new_raw builds it) and a negative denominator
    let raw = BigRational::new_raw(BigInt::from(-7), BigInt::zero());
    assert_eq!(format_rational(&raw), "-7/0");
}

/// The general path of the parser on `p/q`: num-bigint's own reading and reduction.
fn general(neg: bool, p: &str, q: &str) -> BigRational {
    let n = BigInt::parse_bytes(p.as_bytes(), 10).unwrap();
    let d = BigInt::parse_bytes(q.as_bytes(), 10).unwrap();
    BigRational::new(if neg { -n } else { n }, d)
}

proptest! {
    #[test]
    fn word_gcd_equals_euclid(x in any::<u64>(), y in any::<u64>(), shift in 0u32..64) {
        for (x, y) in [(x, y), (x >> shift, y), (x << shift, y << (shift / 2))] {
            let (mut a, mut b) = (x, y);
            while b != 0 {
                (a, b) = (b, a % b);
            }
            prop_assert_eq!(gcd_u64(x, y), a);
        }
    }

    #[test]
    fn push_decimal_equals_num_bigint(limbs in limbs_strategy()) {
        let mut x = BigUint::zero();
        for w in &limbs {
            x = (x << 64u32) + BigUint::from(*w);
        }
        let mut s = String::from("x");
        push_decimal(&mut s, &x);
        prop_assert_eq!(&s[1..], x.to_string());
        let neg = BigRational::new_raw(-BigInt::from(x.clone()) - 1, BigInt::from(x.clone()) * 2u32 + 1u32);
        prop_assert_eq!(format_rational(&neg), neg.to_string());
    }

    #[test]
    fn word_sized_fractions_parse_as_the_general_path(p in any::<u64>(), q in 1u64.., neg: bool,
                                                      pd in 1usize..20, qd in 1usize..20,
                                                      zeros in 0usize..3) {
        // p and q cut to pd and qd digits (some with leading zeros), also 19- and 20-digit ones
        let cut = |x: u64, d: usize| {
            let t = x.to_string();
            let t = &t[t.len().saturating_sub(d)..];
            format!("{}{t}", "0".repeat(zeros))
        };
        let (ps, qs) = (cut(p, pd), cut(q, qd));
        let sign = if neg { "-" } else { "" };
        for (a, b) in [(ps.as_str(), qs.as_str()), (&p.to_string(), &q.to_string())] {
            let text = format!("{sign}{a}/{b}");
            if b.bytes().all(|c| c == b'0') {
                prop_assert!(parse_rational(&text).is_err());
                continue;
            }
            let x = parse_rational(&text).unwrap();
            prop_assert_eq!(&x, &general(neg, a, b));
            // lowest terms with a positive denominator, as num-rational keeps them
            prop_assert!(x.denom().sign() == Sign::Plus);
            prop_assert!(num_integer::Integer::gcd(x.numer(), x.denom()).is_one());
            prop_assert_eq!(parse_rational(&format!("{sign}{a}")).unwrap(), general(neg, a, "1"));
        }
    }
}

/// A float of any kind: normal, subnormal, zero, either sign, near a given one or anywhere.
fn any_finite_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>().prop_filter("finite", |x| x.is_finite()),
        (-1e3f64..1e3),
        (0u64..1 << 20).prop_map(f64::from_bits), // subnormals near 0
        Just(0.0),
        Just(-0.0),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]
    /// `ulps_error_up` (integers, no gcd) is `round_up_f64` of the exact `ulps_error`, in both
    /// formats, at claimed values near the exact one (the batch engine's case: a few ulps off)
    /// and anywhere.
    #[test]
    fn ulps_error_up_is_the_rounded_up_exact_error(
        y in any_finite_f64(),
        near in any::<bool>(),
        steps in -5i64..=5,
        num in any::<i64>(),
        den in 1u64..u64::MAX,
        scale in -1100i64..1100,
    ) {
        let q = if near {
            // q a hair from y: y moved some ulps, plus a tiny fraction
            let z = f64::from_bits((y.to_bits() as i64).wrapping_add(steps) as u64);
            let z = if z.is_finite() { z } else { y };
            exact_f64(z).unwrap() + BigRational::new(num.into(), den.into()) * pow2(-1200)
        } else {
            BigRational::new(num.into(), den.into()) * pow2(scale)
        };
        let yq = exact_f64(y).unwrap();
        prop_assert_eq!(ulps_error_up::<f64>(y, &q), Some(round_up_f64(&ulps_error_f64(&yq, &q))));
        prop_assert_eq!(ulps_error_up::<f32>(y, &q), Some(round_up_f64(&ulps_error_f32(&yq, &q))));
    }
}

#[test]
fn ulps_error_up_by_hand() {
    let q = |s: &str| parse_rational(s).unwrap();
    // 1 against 1 + 2^-53 (ulp 2^-52): 1/2 ulp exactly; against 1 + 2^-53 + 2^-200: above 1/2
    assert_eq!(
        ulps_error_up::<f64>(1.0, &q("0x1.00000000000008p0")),
        Some(0.5)
    );
    assert_eq!(
        ulps_error_up::<f64>(1.0, &(q("0x1.00000000000008p0") + pow2(-200))),
        Some(0.5f64.next_up())
    );
    // 0.1 against 1/10: 2/5 ulp (docs of ulps_error_f64), 2/5 rounded up
    assert_eq!(
        ulps_error_up::<f64>(0.1, &q("1/10")),
        Some(round_up_f64(&q("2/5")))
    );
    assert_eq!(ulps_error_up::<f64>(-3.0, &q("-3")), Some(0.0));
    assert_eq!(ulps_error_up::<f64>(f64::NAN, &q("1")), None);
}
