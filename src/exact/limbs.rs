//! Unsigned multi-limb arithmetic for the exact Horner kernel: little-endian `u64` limbs,
//! in place, no allocation in the hot loop (GMP's `mul_1` / `addmul_1` in safe Rust).

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

/// `x ← x + s · v` (`v` any number of limbs).
#[inline]
pub(super) fn add_mul(x: &mut Vec<u64>, s: &[u64], v: &[u64]) {
    if s.is_empty() || v.is_empty() {
        return;
    }
    let need = x.len().max(s.len() + v.len()) + 1;
    x.resize(need, 0);
    for (i, &vi) in v.iter().enumerate() {
        if vi == 0 {
            continue;
        }
        let mut carry = 0u64;
        for (d, &sj) in x[i..i + s.len()].iter_mut().zip(s) {
            let t = u128::from(sj) * u128::from(vi) + u128::from(*d) + u128::from(carry);
            *d = t as u64;
            carry = (t >> 64) as u64;
        }
        let mut k = i + s.len();
        while carry != 0 {
            let (r, o) = x[k].overflowing_add(carry);
            x[k] = r;
            carry = u64::from(o);
            k += 1;
        }
    }
    trim(x);
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
    if a.len() >= b.len() {
        add_mul(out, a, b);
    } else {
        add_mul(out, b, a);
    }
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

/// `x mod d` (`d > 0`).
#[inline]
pub(super) fn rem_word(x: &[u64], d: u64) -> u64 {
    if d < 1 << 32 {
        // Native 64-by-32 divisions on half limbs instead of the 128-bit software division.
        let mut r = 0u64;
        for &l in x.iter().rev() {
            r = ((r << 32) | (l >> 32)) % d;
            r = ((r << 32) | (l & 0xffff_ffff)) % d;
        }
        return r;
    }
    let mut r = 0u128;
    let d = u128::from(d);
    for &l in x.iter().rev() {
        r = ((r << 64) | u128::from(l)) % d;
    }
    r as u64
}

/// `x ← x / d` for a `d` known to divide `x`.
#[inline]
pub(super) fn div_word_exact(x: &mut Vec<u64>, d: u64) {
    if d < 1 << 32 {
        let mut r = 0u64;
        for l in x.iter_mut().rev() {
            let hi = (r << 32) | (*l >> 32);
            let (qh, rh) = (hi / d, hi % d);
            let lo = (rh << 32) | (*l & 0xffff_ffff);
            let (ql, rl) = (lo / d, lo % d);
            *l = (qh << 32) | ql;
            r = rl;
        }
        debug_assert_eq!(r, 0);
        trim(x);
        return;
    }
    let mut r = 0u128;
    let dd = u128::from(d);
    for l in x.iter_mut().rev() {
        let cur = (r << 64) | u128::from(*l);
        *l = (cur / dd) as u64;
        r = cur % dd;
    }
    debug_assert_eq!(r, 0);
    trim(x);
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

/// `gcd(a, b)` of machine words.
pub(super) fn gcd_u64(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
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
        assert_eq!(
            BigUint::from(rem_word(&a, 1_000_003)),
            big(&a) % 1_000_003u64
        );
        let mut w = y.clone();
        div_word_exact(&mut w, u64::MAX);
        assert_eq!(big(&w), big(&a));
        let mut t = a.clone();
        shr(&mut t, 70);
        assert_eq!(big(&t), big(&a) >> 70u32);
        assert_eq!(trailing_zeros(&[0, 8]), 67);
        assert_eq!(gcd_u64(12, 18), 6);
        let mut f = a.clone();
        mul_word_add_mul(&mut f, u64::MAX, &s, &[u64::MAX]);
        assert_eq!(
            big(&f),
            big(&a) * BigUint::from(u64::MAX) + big(&s) * BigUint::from(u64::MAX)
        );
        let mut p = Vec::new();
        mul_into(&mut p, &s, &a);
        assert_eq!(big(&p), big(&a) * big(&s));
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
