//! Reading number texts at the digit limit (`tribez::hazmat::number::MAX_DIGITS`, 100,000 digits):
//! each must take well under a second. `cargo bench --bench numbers`.

use criterion::{Criterion, criterion_group, criterion_main};
use num_bigint::BigUint;
use tribez::hazmat::number::{MAX_DIGITS, parse_rational, push_decimal};

fn numbers(c: &mut Criterion) {
    let n = MAX_DIGITS;
    let cases = [
        ("integer", "7".repeat(n)),
        // numerator and denominator almost coprime: the gcd (quadratic) does real work
        (
            "p/q",
            format!("{}1/{}3", "8".repeat(n / 2 - 1), "9".repeat(n / 2 - 1)),
        ),
        ("decimal", format!("0.{}", "123456789".repeat((n - 1) / 9))),
        // many factors 5 to cancel against the power of ten
        (
            "decimal 5^k",
            format!("0.{}", num_bigint::BigUint::from(5u32).pow(140_000)),
        ),
        ("1e-100000", "1e-100000".to_string()),
    ];
    for (name, text) in &cases {
        c.bench_function(&format!("parse {name} of {} characters", text.len()), |b| {
            b.iter(|| parse_rational(text).unwrap())
        });
    }
    // printing: tribez's decimal digits against num-bigint's, from the sizes of exact results at
    // degree 3 to 20 (5 and 33 limbs) to the digit limit
    for limbs in [5u32, 13, 33, 5200] {
        let x = (BigUint::from(3u32).pow(limbs * 41) * 7u32) >> 1u32;
        let shift = x.bits() - u64::from(limbs) * 64 + 1;
        let x = x >> shift;
        c.bench_function(&format!("print {limbs} limbs, tribez"), |b| {
            b.iter(|| {
                let mut s = String::new();
                push_decimal(&mut s, &x);
                s
            })
        });
        c.bench_function(&format!("print {limbs} limbs, num-bigint"), |b| {
            b.iter(|| x.to_string())
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = numbers
}
criterion_main!(benches);
