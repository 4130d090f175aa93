//! Unsigned multi-limb arithmetic for the exact Horner kernel: little-endian `u64` limbs,
//! in place, no allocation in the hot loop (GMP's `mul_1` / `addmul_1` in safe Rust).

pub(super) use crate::number::gcd_u64;

/// Remove leading zero limbs.
#[inline]
pub(super) fn trim(x: &mut Vec<u64>) {
    while x.last() == Some(&0) {
        x.pop();
    }
}

/// `x ← x · w`.
#[inline]
pub(super) fn mul_word(x: &mut Vec<u64>, w: u64) {
    if w == 0 {
        x.clear();
        return;
    }
    let mut carry = 0u64;
    for d in x.iter_mut() {
        let t = u128::from(*d) * u128::from(w) + u128::from(carry);
        *d = t as u64;
        carry = (t >> 64) as u64;
    }
    if carry != 0 {
        x.push(carry);
    }
}

/// `x ← x + s · v` (`v` any number of limbs), two limbs of `v` per pass over `x` (GMP's
/// `addmul_2`: half the loads and stores of `x` of one pass per limb).
#[inline]
pub(super) fn add_mul(x: &mut Vec<u64>, s: &[u64], v: &[u64]) {
    // the passes over the longer operand: fewer of them, each longer (less per-pass overhead)
    let (s, v) = if s.len() >= v.len() { (s, v) } else { (v, s) };
    if v.is_empty() {
        return;
    }
    // room for the product and for a carry out of the top of x
    let need = x.len().max(s.len() + v.len()) + 1;
    x.resize(need, 0);
    let mut i = 0;
    while i + 1 < v.len() {
        addmul_2(&mut x[i..], s, v[i], v[i + 1]);
        i += 2;
    }
    if i < v.len() {
        addmul_1(&mut x[i..], s, v[i]);
    }
    trim(x);
}

/// `x ← x + s · w` for a word `w`; `x` is longer than `s` and has room for the carry.
#[inline]
fn addmul_1(x: &mut [u64], s: &[u64], w: u64) {
    if w == 0 {
        return;
    }
    let mut carry = 0u64;
    let (head, tail) = x.split_at_mut(s.len());
    for (d, &sj) in head.iter_mut().zip(s) {
        let t = u128::from(sj) * u128::from(w) + u128::from(*d) + u128::from(carry);
        *d = t as u64;
        carry = (t >> 64) as u64;
    }
    propagate(tail, carry);
}

/// `x ← x + s · (v0 + v1·2^64)`; `x` is at least two limbs longer than `s` and has room for the
/// carry. Each step adds `s_i v0` at limb `i` and `s_i v1` at limb `i + 1`, carrying two limbs.
#[inline]
fn addmul_2(x: &mut [u64], s: &[u64], v0: u64, v1: u64) {
    let (mut c0, mut c1) = (0u64, 0u64);
    let (head, tail) = x.split_at_mut(s.len());
    for (d, &si) in head.iter_mut().zip(s) {
        // Both below 2^128: (2^64 − 1)^2 + 2 (2^64 − 1) = 2^128 − 1.
        let p0 = u128::from(si) * u128::from(v0) + u128::from(*d) + u128::from(c0);
        *d = p0 as u64;
        let p1 = u128::from(si) * u128::from(v1) + (p0 >> 64) + u128::from(c1);
        c0 = p1 as u64;
        c1 = (p1 >> 64) as u64;
    }
    let t0 = u128::from(tail[0]) + u128::from(c0);
    tail[0] = t0 as u64;
    let t1 = u128::from(tail[1]) + u128::from(c1) + (t0 >> 64);
    tail[1] = t1 as u64;
    propagate(&mut tail[2..], (t1 >> 64) as u64);
}

/// Add the word `carry` at the bottom of `x` (which has room for it).
#[inline]
fn propagate(x: &mut [u64], mut carry: u64) {
    let mut k = 0;
    while carry != 0 {
        let (r, o) = x[k].overflowing_add(carry);
        x[k] = r;
        carry = u64::from(o);
        k += 1;
    }
}

/// `out ← Σ_i s_i w_i` for `r` numbers `s_i` of `width` limbs each, stored one after another
/// in `mat`, and words `w_i`: column by column, the products' low and high halves summed apart
/// (each sum below `r · 2^64`), so a column costs `r` products and no carry chain between them.
#[inline]
pub(super) fn dot_columns(out: &mut Vec<u64>, mat: &[u64], width: usize, words: &[u64]) {
    debug_assert_eq!(mat.len(), width * words.len());
    out.clear();
    out.resize(width + 2, 0);
    let mut carry = 0u128;
    for (l, o) in out.iter_mut().take(width).enumerate() {
        let (mut lo, mut hi) = (carry, 0u128);
        for (i, &w) in words.iter().enumerate() {
            let p = u128::from(mat[i * width + l]) * u128::from(w);
            lo += u128::from(p as u64);
            hi += p >> 64;
        }
        *o = lo as u64;
        carry = (lo >> 64) + hi;
    }
    out[width] = carry as u64;
    out[width + 1] = (carry >> 64) as u64;
    trim(out);
}

/// `x ← x · w + s · v`, one fused pass when `v` is a single limb.
#[inline]
pub(super) fn mul_word_add_mul(x: &mut Vec<u64>, w: u64, s: &[u64], v: &[u64]) {
    if v.len() != 1 || w == 0 {
        mul_word(x, w);
        add_mul(x, s, v);
        return;
    }
    let v = v[0];
    if x.len() < s.len() {
        x.resize(s.len(), 0);
    }
    let (mut c1, mut c2) = (0u64, 0u64);
    let (head, tail) = x.split_at_mut(s.len());
    for (d, &sv) in head.iter_mut().zip(s) {
        let t1 = u128::from(*d) * u128::from(w) + u128::from(c1);
        let t2 = u128::from(sv) * u128::from(v) + u128::from(t1 as u64) + u128::from(c2);
        *d = t2 as u64;
        c1 = (t1 >> 64) as u64;
        c2 = (t2 >> 64) as u64;
    }
    for d in tail.iter_mut() {
        let t = u128::from(*d) * u128::from(w) + u128::from(c1) + u128::from(c2);
        *d = t as u64;
        c1 = (t >> 64) as u64;
        c2 = 0;
    }
    let top = u128::from(c1) + u128::from(c2);
    if top != 0 {
        x.push(top as u64);
        if top >> 64 != 0 {
            x.push((top >> 64) as u64);
        }
    }
    trim(x);
}

/// `out ← a · b`.
pub(super) fn mul_into(out: &mut Vec<u64>, a: &[u64], b: &[u64]) {
    out.clear();
    add_mul(out, a, b);
}

/// Compare trimmed magnitudes.
pub(super) fn cmp(a: &[u64], b: &[u64]) -> std::cmp::Ordering {
    a.len()
        .cmp(&b.len())
        .then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

/// `x ← x − y` for `x ≥ y`.
pub(super) fn sub_assign(x: &mut Vec<u64>, y: &[u64]) {
    let mut borrow = false;
    for (i, d) in x.iter_mut().enumerate() {
        let b = y.get(i).copied().unwrap_or(0);
        if i >= y.len() && !borrow {
            break;
        }
        let (r1, o1) = d.overflowing_sub(b);
        let (r2, o2) = r1.overflowing_sub(u64::from(borrow));
        *d = r2;
        borrow = o1 || o2;
    }
    debug_assert!(!borrow);
    trim(x);
}

/// `x ← y − x` for `y ≥ x`.
pub(super) fn rsub_assign(x: &mut Vec<u64>, y: &[u64]) {
    x.resize(y.len(), 0);
    let mut borrow = false;
    for (d, &b) in x.iter_mut().zip(y) {
        let (r1, o1) = b.overflowing_sub(*d);
        let (r2, o2) = r1.overflowing_sub(u64::from(borrow));
        *d = r2;
        borrow = o1 || o2;
    }
    debug_assert!(!borrow);
    trim(x);
}

/// Signed `(neg_x, x) ← (neg_x, x) + (neg_y, y)`.
pub(super) fn signed_add(neg_x: &mut bool, x: &mut Vec<u64>, neg_y: bool, y: &[u64]) {
    if *neg_x == neg_y {
        add(x, y);
    } else if cmp(x, y) != std::cmp::Ordering::Less {
        sub_assign(x, y);
    } else {
        rsub_assign(x, y);
        *neg_x = neg_y;
    }
    if x.is_empty() {
        *neg_x = false;
    }
}

/// `x ← x + y`.
#[inline]
pub(super) fn add(x: &mut Vec<u64>, y: &[u64]) {
    let need = x.len().max(y.len()) + 1;
    x.resize(need, 0);
    let mut carry = false;
    for (d, &b) in x.iter_mut().zip(y) {
        let (r1, o1) = d.overflowing_add(b);
        let (r2, o2) = r1.overflowing_add(u64::from(carry));
        *d = r2;
        carry = o1 || o2;
    }
    let mut k = y.len();
    while carry {
        let (r, o) = x[k].overflowing_add(1);
        x[k] = r;
        carry = o;
        k += 1;
    }
    trim(x);
}

/// `d⁻¹ mod 2^64` for odd `d` (Newton's iteration `x ← x(2 − dx)`, doubling the correct bits
/// from the 3 that `x = d` has, since `d² ≡ 1 mod 8`).
#[inline]
pub(super) fn inverse_odd(d: u64) -> u64 {
    debug_assert!(d % 2 == 1);
    let mut x = d;
    for _ in 0..5 {
        x = x.wrapping_mul(2u64.wrapping_sub(d.wrapping_mul(x)));
    }
    x
}

/// One step of Hensel (2-adic) division of `x` by odd `d`: with the running borrow `c`, the
/// quotient limb `q = (x_i − c) d⁻¹ mod 2^64` and the next borrow `⌊q d / 2^64⌋ + [x_i < c]`,
/// so that `Σ_{j≤i} x_j 2^{64j} + c' 2^{64(i+1)} = d Σ_{j≤i} q_j 2^{64j}` (GMP's `bdiv`,
/// Jebelean 1993): no division instruction, one product per limb.
#[inline(always)]
fn hensel_step(x: u64, c: u64, d: u64, dinv: u64) -> (u64, u64) {
    let (s, borrow) = x.overflowing_sub(c);
    let q = s.wrapping_mul(dinv);
    let hi = ((u128::from(q) * u128::from(d)) >> 64) as u64;
    (q, hi + u64::from(borrow))
}

/// `c` with `x ≡ −c · 2^{64k} (mod d)`, `0 ≤ c ≤ d`, for odd `d` and `k = x.len()`
/// (GMP's `modexact_1_odd`). Since `2^{64k}` is a unit modulo `d`, `gcd(x, d) = gcd(c, d)`, and
/// `d | x` exactly when `c ∈ {0, d}`.
#[inline]
pub(super) fn rem_hensel(x: &[u64], d: u64, dinv: u64) -> u64 {
    let mut c = 0u64;
    for &l in x {
        c = hensel_step(l, c, d, dinv).1;
    }
    c
}

/// `x ← x / d` for odd `d` known to divide `x` (Hensel division: the final borrow is zero).
#[inline]
pub(super) fn div_exact_odd(x: &mut Vec<u64>, d: u64, dinv: u64) {
    let mut c = 0u64;
    for l in x.iter_mut() {
        let (q, next) = hensel_step(*l, c, d, dinv);
        *l = q;
        c = next;
    }
    debug_assert_eq!(c, 0, "div_exact_odd: {d} does not divide");
    trim(x);
}

/// `x ← x << s` (bits).
pub(super) fn shl(x: &mut Vec<u64>, s: u64) {
    if x.is_empty() || s == 0 {
        return;
    }
    let limbs = (s / 64) as usize;
    let bits = (s % 64) as u32;
    if bits > 0 {
        let mut carry = 0u64;
        for d in x.iter_mut() {
            let next = *d >> (64 - bits);
            *d = (*d << bits) | carry;
            carry = next;
        }
        if carry != 0 {
            x.push(carry);
        }
    }
    if limbs > 0 {
        x.splice(0..0, std::iter::repeat_n(0, limbs));
    }
}

/// `x ← x >> s` (bits).
pub(super) fn shr(x: &mut Vec<u64>, s: u64) {
    let limbs = (s / 64) as usize;
    let bits = (s % 64) as u32;
    if limbs >= x.len() {
        x.clear();
        return;
    }
    x.drain(..limbs);
    if bits > 0 {
        let n = x.len();
        for i in 0..n {
            let hi = if i + 1 < n {
                x[i + 1] << (64 - bits)
            } else {
                0
            };
            x[i] = (x[i] >> bits) | hi;
        }
    }
    trim(x);
}

/// Number of trailing zero bits (`x ≠ 0`).
pub(super) fn trailing_zeros(x: &[u64]) -> u64 {
    let mut tz = 0u64;
    for &l in x {
        if l == 0 {
            tz += 64;
        } else {
            return tz + u64::from(l.trailing_zeros());
        }
    }
    tz
}

/// An odd word divisor with the constants of the divisibility test by multiplication
/// (Granlund and Montgomery, "Division by invariant integers using multiplication", §9): for
/// odd `p`, `p | x` exactly when `x · p⁻¹ mod 2^64 ≤ ⌊(2^64 − 1)/p⌋`, since multiplication by
/// `p⁻¹` maps the multiples `0, p, 2p, …` of `p` below `2^64` onto `0, 1, 2, …` and the other
/// words above them.
#[derive(Clone, Copy, Debug)]
pub(super) struct OddDivisor {
    pub(super) p: u64,
    pub(super) inv: u64,
    limit: u64,
}

impl OddDivisor {
    pub(super) fn new(p: u64) -> Self {
        OddDivisor {
            p,
            inv: inverse_odd(p),
            limit: u64::MAX / p,
        }
    }

    /// `p | x`.
    #[inline]
    pub(super) fn divides(&self, x: u64) -> bool {
        x.wrapping_mul(self.inv) <= self.limit
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigUint;

    fn big(x: &[u64]) -> BigUint {
        let halves: Vec<u32> = x
            .iter()
            .flat_map(|&l| [l as u32, (l >> 32) as u32])
            .collect();
        BigUint::new(halves)
    }

    /// `add_mul` (one and two limbs of `v` per pass) and `dot_columns` against num-bigint, on
    /// every length up to 9 limbs, with limbs near `2^64` (the carries' worst case), zeros and
    /// small words, from a fixed-seed generator.
    #[test]
    fn add_mul_and_dot_columns_match_num_bigint() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            match state % 4 {
                0 => u64::MAX - (state >> 60),
                1 => 0,
                2 => state >> 48,
                _ => state,
            }
        };
        let mut limbs = |len: usize| -> Vec<u64> { (0..len).map(|_| next()).collect() };
        for xs in 0..9 {
            for ss in 1..9 {
                for vs in 1..6 {
                    let (x0, s, v) = (limbs(xs), limbs(ss), limbs(vs));
                    let mut x = x0.clone();
                    add_mul(&mut x, &s, &v);
                    assert_eq!(
                        big(&x),
                        big(&x0) + big(&s) * big(&v),
                        "{x0:?} + {s:?} {v:?}"
                    );
                    assert_ne!(x.last(), Some(&0), "trimmed");
                }
                let rows = xs % 8 + 1;
                let (mat, words) = (limbs(rows * ss), limbs(rows));
                let mut out = vec![7];
                dot_columns(&mut out, &mat, ss, &words);
                let expected: BigUint = mat
                    .chunks(ss)
                    .zip(&words)
                    .map(|(s, &w)| big(s) * BigUint::from(w))
                    .sum();
                assert_eq!(big(&out), expected);
                assert_ne!(out.last(), Some(&0), "trimmed");
            }
        }
    }

    /// A carry out of the top of an `x` longer than the product: `x = 2^{64·6} − 1` plus
    /// `s·v = 1·1` needs a seventh limb.
    #[test]
    fn add_mul_carries_out_of_a_long_x() {
        for (s, v) in [
            (vec![1u64], vec![1u64]),
            (vec![1, 0], vec![1]),
            (vec![1], vec![1, 0]),
        ] {
            let mut x = vec![u64::MAX; 6];
            add_mul(&mut x, &s, &v);
            assert_eq!(x, [0, 0, 0, 0, 0, 0, 1], "{s:?} {v:?}");
        }
        let mut x = vec![u64::MAX; 5];
        add_mul(&mut x, &[u64::MAX, u64::MAX], &[2]);
        assert_eq!(
            big(&x),
            (BigUint::from(1u8) << 320u32) - 1u32 + ((BigUint::from(1u8) << 128u32) - 1u32) * 2u32
        );
    }

    #[test]
    fn limb_operations_match_num_bigint() {
        let a = vec![u64::MAX, 7, u64::MAX];
        let s = vec![u64::MAX, u64::MAX];
        let v = vec![3, u64::MAX];
        let mut x = a.clone();
        add_mul(&mut x, &s, &v);
        assert_eq!(big(&x), big(&a) + big(&s) * big(&v));
        let mut y = a.clone();
        mul_word(&mut y, u64::MAX);
        assert_eq!(big(&y), big(&a) * BigUint::from(u64::MAX));
        let mut z = a.clone();
        add(&mut z, &s);
        assert_eq!(big(&z), big(&a) + big(&s));
        let mut t = a.clone();
        shr(&mut t, 70);
        assert_eq!(big(&t), big(&a) >> 70u32);
        assert_eq!(trailing_zeros(&[0, 8]), 67);
        for (x, y) in [
            (12u64, 18u64),
            (0, 5),
            (5, 0),
            (0, 0),
            (1 << 40, 3 << 38),
            (u64::MAX, 3),
        ] {
            let (mut a, mut b) = (x, y);
            while b != 0 {
                (a, b) = (b, a % b);
            }
            assert_eq!(gcd_u64(x, y), a, "gcd({x}, {y})");
        }
        for p in [1u64, 3, 5, 65_521, 4_294_967_291, u64::MAX] {
            let d = OddDivisor::new(p);
            for x in [
                0u64,
                1,
                2,
                p,
                p - 1,
                p.wrapping_add(1),
                p.wrapping_mul(3),
                u64::MAX,
                u64::MAX / p * p,
            ] {
                assert_eq!(d.divides(x), x % p == 0, "{p} | {x}");
            }
        }
        let mut f = a.clone();
        mul_word_add_mul(&mut f, u64::MAX, &s, &[u64::MAX]);
        assert_eq!(
            big(&f),
            big(&a) * BigUint::from(u64::MAX) + big(&s) * BigUint::from(u64::MAX)
        );
        let mut p = Vec::new();
        mul_into(&mut p, &s, &a);
        assert_eq!(big(&p), big(&a) * big(&s));
        for d in [1u64, 3, 65_521, 4_294_967_291, u64::MAX] {
            let inv = inverse_odd(d);
            assert_eq!(d.wrapping_mul(inv), 1);
            let c = rem_hensel(&a, d, inv);
            // x + c 2^{64k} ≡ 0 (mod d), c ≤ d
            let k = a.len() as u32;
            assert!(c <= d);
            assert_eq!(
                (big(&a) + (BigUint::from(c) << (64 * k))) % d,
                BigUint::from(0u8),
                "d = {d}"
            );
            let mut prod = a.clone();
            mul_word(&mut prod, d);
            assert!(matches!(rem_hensel(&prod, d, inv), 0) || rem_hensel(&prod, d, inv) == d);
            div_exact_odd(&mut prod, d, inv);
            assert_eq!(prod, a);
        }
        let mut sh = a.clone();
        shl(&mut sh, 70);
        assert_eq!(big(&sh), big(&a) << 70u32);
        let mut sh = a.clone();
        shl(&mut sh, 64);
        assert_eq!(big(&sh), big(&a) << 64u32);
        let (mut neg, mut x) = (false, s.clone());
        signed_add(&mut neg, &mut x, true, &a);
        assert!(neg);
        assert_eq!(big(&x), big(&a) - big(&s));
        signed_add(&mut neg, &mut x, false, &a);
        assert!(!neg);
        assert_eq!(big(&x), big(&s));
        signed_add(&mut neg, &mut x, true, &s);
        assert!(x.is_empty() && !neg);
    }
}
