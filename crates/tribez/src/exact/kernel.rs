//! The fast exact kernel behind [`super::ExactEvaluator::evaluate_fast`].
//!
//! **Per patch** (once): for each coordinate `c` the integer Bernstein coefficients
//! `s_α = C(n;α)(z_α + K_c)` as machine-word limbs, where `z_α = c_α L_c` are the control points
//! brought to the common denominator `L_c` and `K_c = max(0, −min_α z_α)` makes every `s_α ≥ 0`
//! (so the kernel runs on unsigned limbs only); the prime factorisation of `L_c` (all control
//! point denominators are factored by trial division when their odd parts are below `2^64`, which
//! covers every 16-bit or dyadic workload), and residue tables for those primes.
//!
//! **Per point** `λ = a/D` with `a_k ≥ 0` and `D` machine words:
//!
//! `H_c = Σ_α s_α a^α`, `N_c = H_c − K_c (Σ_k a_k)^n` (because `Σ_α C(n;α) a^α = (Σa)^n`),
//! `p_c(λ) = N_c / (L_c D^n)`,
//!
//! with `H_c` computed by nested homogeneous Horner in canonical order (docs/theory.md §1): on the
//! `t`-simplex, `H = Σ_{k=0..N} a_t^k H_k` with `H_k` the face block `α_t = k` of degree `N − k`
//! on `(a_0, …, a_{t−1})`, run as `S ← S·a_t + H_k` for `k = N … 0` (all blocks are contiguous in
//! the canonical order); on an edge (`t = 1`) `Σ_j s_j a_0^{N−j} a_1^j` as `T ← T·a_0 + s_j a_1^j`.
//! Every multiplication of an accumulator is by one machine word, in place; only the edge terms
//! `s_j a_1^j` multiply by a short power of `a_1` (`⌈j·bits(a_1)/64⌉` limbs).
//!
//! Triangles run one of two specialisations of the same sum, both tested equal to the rational de
//! Casteljau algorithm: when `max_α |z_α| · (Σ_k a_k)^n < 2^{64W−1}` for `W ≤ 4` (small degrees),
//! the plain nested Horner modulo `2^{64W}` in two's complement ([`horner_fixed`]: the value is
//! exact because only the final one must fit); otherwise the row-scaled form ([`Rows`]), whose rows
//! run in blocks of `b` coordinates per machine word (`a_0^b < 2^64`).
//!
//! The reduction to lowest terms never runs a big gcd: `gcd(N, L D^n)` is the product of
//! `gcd(N, D^n)`, found by at most `n` word gcds `g = gcd(N mod D, D)`, `N ← N/g`, and of
//! `p^{min(v_p(N), v_p(L))}` over the known primes `p` of `L` (powers of two by trailing zeros,
//! odd primes by residues modulo word-sized products `M` of primes, computed as dot products of
//! the limbs of `N` with precomputed powers `2^{64h} mod M`). The two factors are coprime
//! after the first step, so their product is the whole gcd. A prime of `L` reached at its full
//! exponent by one control point only (most primes, with random denominators) needs no residue:
//! `p | N` exactly when `p` divides that point's multinomial or a coordinate `a_k` it involves
//! (see `Lone`); candidates are confirmed by a remainder before they are divided out. Word gcds
//! are binary, and whether a known odd prime divides a word is one product by its inverse modulo
//! `2^64` and a comparison ([`OddDivisor`]), so that the reduction of a numerator of up to
//! `CHUNK` limbs runs no division instruction.

use std::sync::OnceLock;

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use rayon::prelude::*;

use super::limbs::{
    OddDivisor, add, add_mul, div_exact_odd, dot_columns, gcd_u64, inverse_odd, mul_into, mul_word,
    mul_word_add_mul, rem_hensel, shl, shr, signed_add, trailing_zeros, trim,
};
use crate::patch::ControlNet;
use crate::simplex::count;

/// `(a, D)` with `λ_k = a_k / D`, when every `a_k ≥ 0` and `D` fit a machine word.
pub fn word_point(lambda: &[BigRational]) -> Option<(Vec<u64>, u64)> {
    let mut d: u64 = 1;
    for x in lambda {
        let q = x.denom().to_u64()?;
        d = (d / gcd_u64(d, q)).checked_mul(q)?;
    }
    lambda
        .iter()
        .map(|x| {
            let p = x.numer().to_u64()?;
            p.checked_mul(d / x.denom().to_u64()?)
        })
        .collect::<Option<Vec<u64>>>()
        .map(|a| (a, d))
}

/// `a / b` for `b | a`. A word `b = 2^t o` (`o` odd) divides by a shift and a Hensel division by
/// `o` (no division instruction; a denominator is nearly always a word); others by num-bigint.
pub fn div_exact(a: &BigInt, b: &BigInt) -> BigInt {
    match b.to_u64() {
        Some(w) if w != 0 => {
            let mut x = to_limbs(a.magnitude());
            let t = w.trailing_zeros();
            debug_assert!(trailing_zeros(&x) >= u64::from(t) || x.is_empty());
            shr(&mut x, u64::from(t));
            let o = w >> t;
            if o > 1 {
                div_exact_odd(&mut x, o, inverse_odd(o));
            }
            let q = BigInt::from_biguint(a.sign(), from_limbs(&x));
            debug_assert_eq!(&q * b, *a, "div_exact: {b} does not divide {a}");
            q
        }
        _ => a / b,
    }
}

/// `lcm(a, b)` (non-negative), computing the gcd on the smaller operand (`gcd(a mod b, b)`); when
/// that one is a word `2^t o` (`o` odd), on words: `gcd = 2^min(t, v₂(a)) · gcd(r, o)` with `r`
/// the Hensel remainder of `a` by `o` (which has the same gcd with `o`), and the lcm is one
/// product by a word.
pub fn lcm_big(a: &BigInt, b: &BigInt) -> BigInt {
    if a.is_zero() || b.is_zero() {
        return BigInt::zero();
    }
    let (big, small) = if a.magnitude().bits() >= b.magnitude().bits() {
        (a, b)
    } else {
        (b, a)
    };
    if let Some(w) = small.magnitude().to_u64() {
        let mut x = to_limbs(big.magnitude());
        lcm_word(&mut x, w);
        return BigInt::from(from_limbs(&x));
    }
    let g = (big % small).gcd(small);
    (big / &g * small).abs()
}

/// `x ← lcm(x, w)` on limbs, for `x ≠ 0` and a word `w = 2^t o ≠ 0` (`o` odd): the gcd is
/// `2^min(t, v₂(x)) · gcd(r, o)` with `r` the Hensel remainder of `x` by `o` (which has the same
/// gcd with `o`), and the lcm one product by the word `w / gcd`.
fn lcm_word(x: &mut Vec<u64>, w: u64) {
    debug_assert!(w != 0 && x.last().is_some_and(|&l| l != 0));
    let t = w.trailing_zeros();
    let o = w >> t;
    let odd_gcd = if o > 1 {
        gcd_u64(rem_hensel(x, o, inverse_odd(o)), o)
    } else {
        1
    };
    let g = (1u64 << t.min(trailing_zeros(x) as u32)) * odd_gcd;
    mul_word(x, w / g);
}

/// `lcm(start, x_1, x_2, …)` (all non-negative), folded on limbs while the `x_i` are nonzero words
/// (denominators nearly always are): one conversion in and out instead of one per step.
pub fn lcm_fold<'a>(start: &BigInt, xs: impl Iterator<Item = &'a BigInt>) -> BigInt {
    let mut acc = to_limbs(start.magnitude());
    for x in xs {
        match x.magnitude().to_u64() {
            Some(w) if w != 0 && !acc.is_empty() => lcm_word(&mut acc, w),
            _ => acc = to_limbs(lcm_big(&BigInt::from(from_limbs(&acc)), x).magnitude()),
        }
    }
    BigInt::from(from_limbs(&acc))
}

/// The primes below `2^16` (sieved once, when a number needs trial division beyond
/// [`PRIMES_BELOW_256`]).
fn small_primes() -> &'static [u32] {
    static PRIMES: OnceLock<Vec<u32>> = OnceLock::new();
    PRIMES.get_or_init(|| {
        const LIMIT: usize = 1 << 16;
        let mut sieve = vec![true; LIMIT + 1];
        let mut out = Vec::new();
        for i in 2..=LIMIT {
            if sieve[i] {
                out.push(i as u32);
                let mut j = i * i;
                while j <= LIMIT {
                    sieve[j] = false;
                    j += i;
                }
            }
        }
        out
    })
}

/// The 54 primes below 256, sieved at compile time: they factor every odd part below
/// `257² = 66049` (all 16-bit denominators) without the sieve to `2^16`.
const PRIMES_BELOW_256: [u32; 54] = {
    let mut composite = [false; 256];
    let mut out = [0u32; 54];
    let (mut i, mut count) = (2, 0);
    while i < 256 {
        if !composite[i] {
            out[count] = i as u32;
            count += 1;
            let mut j = i * i;
            while j < 256 {
                composite[j] = true;
                j += i;
            }
        }
        i += 1;
    }
    assert!(count == 54);
    out
};

/// The prime factorisation of an odd word by trial division up to `2^16`, ascending; `None` when
/// a cofactor `≥ 2^32` is left (it could be composite).
fn factor_odd(mut r: u64) -> Option<Vec<(u64, u32)>> {
    let mut out = Vec::new();
    let mut divide = |r: &mut u64, p: u64| {
        let mut e = 0u32;
        while r.is_multiple_of(p) {
            *r /= p;
            e += 1;
        }
        if e > 0 {
            out.push((p, e));
        }
    };
    for &p in &PRIMES_BELOW_256[1..] {
        let p = u64::from(p);
        if p * p > r {
            break;
        }
        divide(&mut r, p);
    }
    // every prime below 257 that could divide r has been tried: a cofactor below 257² is 1 or a
    // prime (so a 16-bit denominator never needs the sieve)
    if r >= 257 * 257 {
        for &p in &small_primes()[PRIMES_BELOW_256.len()..] {
            let p = u64::from(p);
            if p * p > r {
                break;
            }
            divide(&mut r, p);
        }
    }
    if r > 1 {
        if r >= 1 << 32 {
            return None;
        }
        out.push((r, 1));
    }
    Some(out)
}

/// The odd part of a positive `q` and its power of two `v₂(q)`, or `None` when the odd part
/// does not fit a word.
fn odd_part(q: &BigUint) -> Option<(u64, u64)> {
    let tz = q.trailing_zeros().unwrap_or(0);
    match q.to_u64() {
        Some(w) => Some((w >> tz, tz)),
        None => Some(((q >> tz).to_u64()?, tz)),
    }
}

/// The prime factorisation of a least common multiple of denominators: `2^e2 · Π p^e`.
#[derive(Clone, Debug, Default)]
pub struct Factors {
    e2: u64,
    /// Odd primes with exponents, ascending.
    odd: Vec<(u64, u32)>,
    /// Each denominator's odd part, factored (for [`census`]), ascending by the odd part.
    of_odd_part: Vec<(u64, Vec<(u64, u32)>)>,
}

impl Factors {
    /// Factor the lcm of `denominators` (positive), or `None` if some odd part is not fully
    /// factored by trial division up to `2^16` (odd part `≥ 2^64`, or a cofactor `≥ 2^32`).
    pub fn of<'a>(denominators: impl Iterator<Item = &'a BigInt>) -> Option<Factors> {
        let mut e2 = 0u64;
        let mut odd_parts = Vec::new();
        for q in denominators {
            let (odd, tz) = odd_part(q.magnitude())?;
            e2 = e2.max(tz);
            odd_parts.push(odd);
        }
        odd_parts.sort_unstable();
        odd_parts.dedup();
        let mut exps: std::collections::BTreeMap<u64, u32> = Default::default();
        let mut of_odd_part = Vec::with_capacity(odd_parts.len());
        for odd in odd_parts {
            let primes = factor_odd(odd)?;
            for &(p, e) in &primes {
                let slot = exps.entry(p).or_insert(0);
                *slot = (*slot).max(e);
            }
            of_odd_part.push((odd, primes));
        }
        Some(Factors {
            e2,
            odd: exps.into_iter().collect(),
            of_odd_part,
        })
    }

    /// The number they factor.
    pub fn product(&self) -> BigUint {
        let mut words: Vec<u64> = vec![1];
        for &(p, e) in &self.odd {
            for _ in 0..e {
                mul_word(&mut words, p);
            }
        }
        from_limbs(&words) << self.e2
    }
}

/// Limbs per residue-table row (small under test, so that the multi-chunk path runs too).
const CHUNK: usize = if cfg!(test) { 3 } else { 128 };

/// A prime `p` of `L_c` (exponent `e`) at which exactly one control point `α` has a denominator
/// with the full exponent `e`. Modulo `p` every other term of `N = Σ C(n;α) z_α a^α` vanishes and
/// `p ∤ z_α` (its numerator is coprime to its denominator, and `L_c / q_α` has no factor `p`), so
/// `p | N` exactly when `p | C(n;α)` or `p | a_k` for some `k` with `α_k > 0`: decided per point
/// from `gcd(a_k, L_c)` without reading `N`. With random denominators most primes of `L_c` are
/// such primes; only the others need residues of `N`.
#[derive(Clone, Debug)]
struct Lone {
    p: OddDivisor,
    e: u32,
    /// `p | C(n;α)`: then `p | N` at every point.
    always: bool,
    /// The `k` with `α_k > 0`.
    support: Vec<u32>,
}

/// Which odd primes of `L_c` are [`Lone`]: factor each control point's denominator (all fit a
/// word when `L_c` was factored) and count the points at the full exponent.
fn census(
    factors: &Factors,
    net: &ControlNet<BigRational>,
    c: usize,
) -> (Vec<(u64, u32)>, Vec<Lone>) {
    use std::collections::HashMap;
    let full = |p: u64| {
        factors
            .odd
            .binary_search_by_key(&p, |&(q, _)| q)
            .map(|i| factors.odd[i].1)
            .ok()
    };
    // prime -> (points at the full exponent, the first such point's rank)
    let mut at_full: HashMap<u64, (usize, usize)> = HashMap::new();
    for (r, point) in net.points().enumerate() {
        let (odd, _) = odd_part(point[c].denom().magnitude())
            // invariant: this runs only for nets whose denominators' odd parts were factored above (word-sized, else the kernel is not used)
            .expect("factored denominators have word-sized odd parts");
        let i = factors
            .of_odd_part
            .binary_search_by_key(&odd, |&(o, _)| o)
            // invariant: `factors` was built from the odd parts of these same denominators
            .expect("every denominator's odd part was factored");
        for &(p, e) in &factors.of_odd_part[i].1 {
            if full(p) == Some(e) {
                let slot = at_full.entry(p).or_insert((0, r));
                slot.0 += 1;
            }
        }
    }
    let simplex = net.simplex();
    let n = net.degree() as u64;
    let alphas: Vec<&[u32]> = simplex.iter().collect();
    let (mut shared, mut lone) = (Vec::new(), Vec::new());
    for &(p, e) in &factors.odd {
        match at_full.get(&p) {
            Some(&(1, r)) => {
                let alpha = alphas[r];
                // Legendre: v_p(C(n;α)) = (Σ_k s_p(α_k) − s_p(n)) / (p − 1), s_p the sum of
                // the base-p digits, so p | C(n;α) exactly when the digit sums differ.
                let always = alpha
                    .iter()
                    .map(|&x| digit_sum(u64::from(x), p))
                    .sum::<u64>()
                    > digit_sum(n, p);
                let support = (0u32..)
                    .zip(alpha)
                    .filter(|&(_, &x)| x > 0)
                    .map(|(k, _)| k)
                    .collect();
                lone.push(Lone {
                    p: OddDivisor::new(p),
                    e,
                    always,
                    support,
                });
            }
            _ => shared.push((p, e)),
        }
    }
    (shared, lone)
}

/// The cost of one word gcd in [`FastNet::new`]'s choice between lone primes and residues, in
/// limb products (0 under test, so that the small nets of the tests take the lone path too).
const GCD_COST: u64 = if cfg!(test) { 0 } else { 600 };

/// How many word-sized products the ascending `primes` fill (as [`Reducer::new`] packs them).
fn moduli_count(primes: impl Iterator<Item = u64>) -> usize {
    let (mut count, mut m) = (0, 1u64);
    for p in primes {
        match m.checked_mul(p) {
            Some(next) if count > 0 => m = next,
            _ => {
                count += 1;
                m = p;
            }
        }
    }
    count
}

/// The sum of the base-`p` digits of `x`.
fn digit_sum(mut x: u64, p: u64) -> u64 {
    let mut s = 0;
    while x > 0 {
        s += x % p;
        x /= p;
    }
    s
}

/// Residue tables for the odd primes of `L_c` that are not [`Lone`], and the lone ones.
#[derive(Clone, Debug)]
struct Reducer {
    /// The primes read off residues of `N`, with their exponents in `L_c`, ascending.
    shared: Vec<(OddDivisor, u32)>,
    /// The lone primes that divide `N` at every point (`p | C(n;α)`), with their exponents.
    always: Vec<(OddDivisor, u32)>,
    /// The other lone primes: decided per point from the coordinates.
    lone: Vec<Lone>,
    /// `(M, first prime, end prime, 2^{64·CHUNK} mod M)`: `M` the product of `shared[first..end]`, `< 2^64`.
    moduli: Vec<(u64, usize, usize, u64)>,
    /// `2^{64h} mod M` for `h < CHUNK`, `CHUNK` entries per modulus.
    table: Vec<u64>,
    /// `M⁻¹ mod 2^64` per modulus.
    inverses: Vec<u64>,
}

impl Reducer {
    fn new(shared: Vec<(u64, u32)>, lone: Vec<Lone>) -> Self {
        let mut moduli = Vec::new();
        let mut i = 0;
        while i < shared.len() {
            let mut m = shared[i].0;
            let mut j = i + 1;
            while let Some(next) = shared.get(j).and_then(|&(p, _)| m.checked_mul(p)) {
                m = next;
                j += 1;
            }
            moduli.push((m, i, j, 0));
            i = j;
        }
        let mut table = Vec::with_capacity(moduli.len() * CHUNK);
        for (m, _, _, big) in &mut moduli {
            let mm = u128::from(*m);
            let mut x = 1 % mm;
            for _ in 0..CHUNK {
                table.push(x as u64);
                x = (x << 64) % mm;
            }
            *big = x as u64;
        }
        let inverses = moduli.iter().map(|&(m, ..)| inverse_odd(m)).collect();
        let (always, lone): (Vec<Lone>, Vec<Lone>) = lone.into_iter().partition(|l| l.always);
        Reducer {
            always: always.into_iter().map(|l| (l.p, l.e)).collect(),
            shared: shared
                .into_iter()
                .map(|(p, e)| (OddDivisor::new(p), e))
                .collect(),
            lone,
            moduli,
            table,
            inverses,
        }
    }

    /// Divide `limbs` by `gcd(limbs, L_odd)` (`L_odd` the odd part of `L`), pushing the primes
    /// removed (with multiplicity) onto `removed`. `g[k]` is `gcd(a_k, P)` for the point `a`, `P`
    /// a multiple of every lone prime's `p` (see [`lone_gcds`]): `p | a_k` exactly when
    /// `p | g[k]`, which decides the lone primes; a candidate is divided out only after its
    /// residue confirms it. A shared prime whose residue is zero divides `N`: its first power is
    /// divided out unchecked, together with the others' in as few word divisions as their
    /// product fills (`sure` holds them); only its higher powers are checked.
    fn strip_odd(
        &self,
        limbs: &mut Vec<u64>,
        g: &[u64],
        removed: &mut Vec<u64>,
        hits: &mut Vec<(OddDivisor, u32)>,
        sure: &mut Vec<(OddDivisor, u32)>,
    ) {
        if limbs.is_empty() {
            return;
        }
        sure.clear();
        hits.clear();
        hits.extend_from_slice(&self.always);
        // With random points every g_k is 1 nearly always: then no lone prime divides N.
        if !self.lone.is_empty() && g.iter().any(|&x| x != 1) {
            for l in &self.lone {
                if l.support.iter().any(|&k| {
                    let g = g[k as usize];
                    g != 1 && l.p.divides(g)
                }) {
                    hits.push((l.p, l.e));
                }
            }
        }
        let single = limbs.len() <= CHUNK;
        for (k, &(m, first, end, big)) in self.moduli.iter().enumerate() {
            let row = &self.table[k * CHUNK..(k + 1) * CHUNK];
            let mut r = 0u64;
            for chunk in limbs.chunks(CHUNK).rev() {
                // dot = Σ l_h (2^{64h} mod M) < 2^{135}, as three limbs w.
                let (mut lo, mut hi) = (0u128, 0u128);
                for (&l, &t) in chunk.iter().zip(row) {
                    let prod = u128::from(l) * u128::from(t);
                    lo += u128::from(prod as u64);
                    hi += prod >> 64;
                }
                let mid = (lo >> 64) + u128::from(hi as u64);
                let w = [lo as u64, mid as u64, ((hi >> 64) + (mid >> 64)) as u64];
                if single {
                    // Only divisibility matters: the Hensel remainder of the dot product is
                    // `N · 2^{−192} mod M`, divisible by the same primes of M as N.
                    r = rem_hensel(&w, m, self.inverses[k]);
                } else {
                    // Chunks from the top: r ← r·2^{64·CHUNK} + dot (mod M), each step
                    // `x·y + z` with `x, y < M < 2^64` and `z < 2^64`, below 2^128.
                    let mm = u128::from(m);
                    let t64 = (1u128 << 64) % mm;
                    let mut dot = u128::from(w[2]) % mm;
                    dot = (dot * t64 + u128::from(w[1])) % mm;
                    dot = (dot * t64 + u128::from(w[0])) % mm;
                    r = ((u128::from(r) * u128::from(big) + dot) % mm) as u64;
                }
            }
            for &(p, e) in &self.shared[first..end] {
                if p.divides(r) {
                    sure.push((p, e));
                }
            }
        }
        // p | r exactly when p | N (r is N times a power of 2 modulo M, or N mod M)
        let start = removed.len();
        removed.extend(sure.iter().map(|(p, _)| p.p));
        div_exact_words(limbs, &removed[start..]);
        let more = sure.iter().map(|&(p, e)| (p, e - 1));
        for (p, e) in more.chain(hits.iter().copied()) {
            for _ in 0..e {
                // `rem_hensel` is in 0..=p, and 0 or p when p divides.
                let c = rem_hensel(limbs, p.p, p.inv);
                if c != 0 && c != p.p {
                    break;
                }
                div_exact_odd(limbs, p.p, p.inv);
                removed.push(p.p);
            }
        }
    }
}

/// One coordinate's per-patch data.
#[derive(Clone, Debug)]
struct Coordinate {
    form: Form,
    /// `L_c`.
    denominator: BigUint,
    /// `L_c = 2^{e2} · odd`: the limbs of the odd part, and `e2`.
    odd_denominator: Vec<u64>,
    e2: u64,
    reducer: Option<Reducer>,
}

/// How a coordinate's numerator is computed.
#[derive(Clone, Debug)]
enum Form {
    /// A triangle: the row form ([`Rows`]), and the global form as well when some point's result
    /// may fit four limbs ([`horner_fixed`]); at high degrees it never does, and the global form,
    /// whose numbers are `|L_c|`-sized, is not built.
    Triangle { rows: Rows, small: Option<Global> },
    /// Any other simplex: the nested Horner on the global form.
    Simplex(Global),
}

/// The global form of a coordinate: `C(n;α)(z_α + K_c)` with one denominator `L_c` for all.
#[derive(Clone, Debug)]
struct Global {
    /// Limbs of `C(n;α)(z_α + K_c)`, `starts[r]..starts[r+1]` for rank `r`.
    limbs: Vec<u64>,
    starts: Vec<usize>,
    /// `K_c` (zero when no `z_α` is negative).
    shift: BigUint,
    /// `max_α bits(|z_α|)`: with `σ = Σ_k a_k`, `|N| ≤ max|z_α| σ^n < 2^{z_bits + n·bits(σ)}`,
    /// which decides whether [`horner_fixed`] may run.
    z_bits: u64,
    /// `K_c` as limbs (for [`horner_fixed`]).
    shift_limbs: Vec<u64>,
}

/// The nets the global form is built from: `C(n;α) z_α` and `z_α` (one coordinate per column),
/// and the multinomials `C(n;α)` by rank.
pub type IntegerNetsRef<'a> = (
    &'a ControlNet<BigInt>,
    &'a ControlNet<BigInt>,
    &'a [BigUint],
);

impl Global {
    fn new((scaled, integer, multinomials): IntegerNetsRef<'_>, c: usize) -> Global {
        let min = integer
            .points()
            .map(|p| &p[c])
            .min()
            .cloned()
            .unwrap_or_default();
        let shift = if min.is_negative() {
            min.magnitude().clone()
        } else {
            BigUint::zero()
        };
        let mut limbs = Vec::new();
        let mut starts = vec![0];
        for ((s, z), mult) in scaled.points().zip(integer.points()).zip(multinomials) {
            let v = if shift.is_zero() {
                s[c].magnitude().clone()
            } else {
                // C(n;α) (z + K) = s + C(n;α) K.
                debug_assert_eq!(&(BigInt::from(mult.clone()) * &z[c]), &s[c]);
                (&s[c] + BigInt::from(mult * &shift)).magnitude().clone()
            };
            limbs.extend(to_limbs(&v));
            starts.push(limbs.len());
        }
        Global {
            limbs,
            starts,
            shift_limbs: to_limbs(&shift),
            shift,
            z_bits: integer.points().map(|p| p[c].bits()).max().unwrap_or(0),
        }
    }
}

/// A triangle with each row `k` (`α_2 = k`) brought to its own common denominator `L_k`:
/// row integers `z_j = c_{(n−k−j, j, k)} L_k`, coefficients `C(n−k, j)(z_j + K_k)` made
/// non-negative by the row's shift `K_k` (corrected by `K_k (a_0 + a_1)^{n−k}` per point), and
/// the outer Horner in `a_2` on the fractions `S_k / M_k`,
/// `M_k = lcm(L_k, …, L_n)`: `S_k = S_{k+1} a_2 e_k + R_k f_k` with the per-patch integers
/// `e_k = M_k / M_{k+1}` and `f_k = C(n, k) M_k / L_k`; `M_0 = L_c`. The accumulators are
/// `|L_k|`-sized inside a row instead of `|L_c|`-sized: about `n/4` times fewer limb operations
/// at degree 20 than the global form.
#[derive(Clone, Debug)]
struct Rows {
    /// `C(N, j)(z_j + K_k)` (all `≥ 0`): row `k` at `offset[k]`, its numbers zero-padded to
    /// `width[k]` limbs each (the row's longest), one after another in `j`.
    limbs: Vec<u64>,
    offset: Vec<usize>,
    width: Vec<usize>,
    /// `K_k = max(0, −min_j z_j)` per row; the row sum is `H_k − K_k (a_0 + a_1)^{n−k}`.
    shift: Vec<Vec<u64>>,
    e: Vec<Vec<u64>>,
    f: Vec<Vec<u64>>,
}

impl Rows {
    fn new(n: usize, net: &ControlNet<BigRational>, c: usize) -> Rows {
        let (mut limbs, mut offset, mut width, mut shift) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let mut row_lcm = Vec::with_capacity(n + 1);
        for k in 0..=n {
            let nn = n - k;
            let base = k * (2 * n + 3 - k) / 2;
            let vals: Vec<&BigRational> = (0..=nn).map(|j| &net.point(base + j)[c]).collect();
            let l = lcm_fold(&BigInt::one(), vals.iter().map(|x| x.denom()));
            let z: Vec<BigInt> = vals
                .iter()
                .map(|x| x.numer() * div_exact(&l, x.denom()))
                .collect();
            let min = z.iter().min().cloned().unwrap_or_default();
            let kk = if min.is_negative() {
                -min
            } else {
                BigInt::zero()
            };
            let coefs: Vec<Vec<u64>> = z
                .iter()
                .enumerate()
                .map(|(j, zj)| {
                    let t = (zj + &kk)
                        * BigInt::from(crate::simplex::binomial_exact(nn as u64, j as u64));
                    to_limbs(t.magnitude())
                })
                .collect();
            let w = coefs.iter().map(Vec::len).max().unwrap_or(0);
            offset.push(limbs.len());
            width.push(w);
            for t in coefs {
                limbs.extend(&t);
                limbs.extend(std::iter::repeat_n(0, w - t.len()));
            }
            shift.push(to_limbs(kk.magnitude()));
            row_lcm.push(l);
        }
        let mut e = vec![Vec::new(); n + 1];
        let mut f = vec![Vec::new(); n + 1];
        let mut m_next = BigInt::one();
        for k in (0..=n).rev() {
            // lcm(m_{k+1}, L_k) from the row's denominators (words: no big gcd)
            let base = k * (2 * n + 3 - k) / 2;
            let m_k = lcm_fold(&m_next, (0..=n - k).map(|j| net.point(base + j)[c].denom()));
            debug_assert_eq!(m_k, lcm_big(&m_next, &row_lcm[k]));
            e[k] = to_limbs((&m_k / &m_next).magnitude());
            f[k] = to_limbs(
                (&m_k / &row_lcm[k]
                    * BigInt::from(crate::simplex::binomial_exact(n as u64, k as u64)))
                .magnitude(),
            );
            m_next = m_k;
        }
        Rows {
            limbs,
            offset,
            width,
            shift,
            e,
            f,
        }
    }

    /// The numerator over `L_c` at `a` into `s` (its magnitude); returns whether it is negative.
    /// `pw[j] = a_1^j` and `sp[N] = (a_0 + a_1)^N`; `block` the point's [`Block`] words.
    ///
    /// A row `Σ_j s_j a_0^{N−j} a_1^j` runs by blocks of `b` consecutive `j` (the first block
    /// short when `b ∤ N + 1`): `R ← R·a_0^b + a_1^{j_0} Σ_{i<b} s_{j_0+i} a_0^{b−1−i} a_1^i`,
    /// whose multipliers `a_0^b` and `a_0^{b−1−i} a_1^i` are single words, so that a step of the
    /// accumulator multiplies by `b` coordinates at once instead of one.
    #[allow(clippy::too_many_arguments)] // the per-point inputs and the reused buffers
    fn evaluate(
        &self,
        n: usize,
        a: &[u64],
        pw: &[Vec<u64>],
        sp: &[Vec<u64>],
        block: &Block,
        bufs: &mut [Vec<u64>; 4],
        s: &mut Vec<u64>,
    ) -> bool {
        let [r, corr, y, z] = bufs;
        s.clear();
        let mut s_neg = false;
        let b = block.b;
        for k in (0..=n).rev() {
            let nn = n - k;
            let w = self.width[k];
            let coefs = |j: usize, len: usize| {
                &self.limbs[self.offset[k] + j * w..self.offset[k] + (j + len) * w]
            };
            // The first, possibly short, block: j = 0..r0.
            let r0 = match (nn + 1) % b {
                0 => b,
                r0 => r0,
            };
            let mut short = [0u64; 8];
            let first = if r0 == b {
                &block.words[..b]
            } else {
                for (i, x) in short.iter_mut().enumerate().take(r0) {
                    *x = block.word(r0, i);
                }
                &short[..r0]
            };
            dot_columns(r, coefs(0, r0), w, first);
            let mut j0 = r0;
            while j0 <= nn {
                dot_columns(z, coefs(j0, b), w, &block.words[..b]);
                mul_word_add_mul(r, block.a0b, z, &pw[j0]);
                j0 += b;
            }
            let mut r_neg = false;
            if !self.shift[k].is_empty() {
                mul_into(corr, &self.shift[k], &sp[nn]);
                signed_add(&mut r_neg, r, true, corr);
            }
            if k < n {
                mul_word(s, a[2]);
                match self.e[k].as_slice() {
                    [1] => {}
                    &[w] => mul_word(s, w),
                    e => {
                        mul_into(y, s, e);
                        std::mem::swap(s, y);
                    }
                }
            }
            if s.is_empty() || s_neg == r_neg {
                // Same sign: accumulate R_k f_k in place.
                add_mul(s, &self.f[k], r);
                s_neg = r_neg && !s.is_empty();
            } else {
                mul_into(z, r, &self.f[k]);
                signed_add(&mut s_neg, s, r_neg, z);
            }
        }
        s_neg
    }
}

/// The single-word multipliers of a point's blocked row Horner ([`Rows::evaluate`]): the block
/// length `b` (at most 8) with `a_0^b < 2^64` and every `a_0^{b−1−i} a_1^i < 2^64`.
struct Block {
    b: usize,
    /// `a_0^b`.
    a0b: u64,
    /// `a_0^{b−1−i} a_1^i`, `i < b`.
    words: [u64; 8],
    a0: u64,
    a1: u64,
}

impl Block {
    fn new(a0: u64, a1: u64) -> Self {
        let bits = (64 - (a0 | a1).leading_zeros()).max(1) as usize;
        // x < 2^bits, so x^b < 2^{b·bits} ≤ 2^64.
        let b = (64 / bits).clamp(1, 8);
        let mut block = Block {
            b,
            a0b: a0.pow(b as u32),
            words: [0; 8],
            a0,
            a1,
        };
        for i in 0..b {
            block.words[i] = block.word(b, i);
        }
        block
    }

    /// `a_0^{r−1−i} a_1^i` (`i < r ≤ b`: below `2^64`).
    fn word(&self, r: usize, i: usize) -> u64 {
        self.a0.pow((r - 1 - i) as u32) * self.a1.pow(i as u32)
    }
}

impl Global {
    #[inline]
    fn coef(&self, r: usize) -> &[u64] {
        &self.limbs[self.starts[r]..self.starts[r + 1]]
    }
}

/// Per-thread buffers of the kernel, reused from point to point.
#[derive(Default)]
struct Scratch {
    pw: Vec<Vec<u64>>,
    sp: Vec<Vec<u64>>,
    bufs: Vec<Vec<u64>>,
    row_bufs: [Vec<u64>; 4],
    acc: Vec<u64>,
    /// [`lone_gcds`] of the point.
    lone: Vec<u64>,
    reduce: ReduceScratch,
}

thread_local! {
    static SCRATCH: std::cell::RefCell<Scratch> = std::cell::RefCell::new(Scratch::default());
}

/// `out[j] = x^j` for `j = 0..=n`, in place.
fn fill_powers(out: &mut Vec<Vec<u64>>, n: usize, x: &[u64]) {
    if out.len() < n + 1 {
        out.resize(n + 1, Vec::new());
    }
    out[0].clear();
    out[0].push(1);
    for j in 1..=n {
        let (lo, hi) = out.split_at_mut(j);
        if let &[w] = x {
            hi[0].clear();
            hi[0].extend_from_slice(&lo[j - 1]);
            mul_word(&mut hi[0], w);
        } else {
            mul_into(&mut hi[0], &lo[j - 1], x);
        }
    }
}

/// The per-patch data of the fast kernel.
#[derive(Clone, Debug)]
pub struct FastNet {
    m: usize,
    n: usize,
    /// `count(t, N)` for `t ≤ m`, `N ≤ n`: `counts[t * (n + 1) + N]`.
    counts: Vec<usize>,
    coords: Vec<Coordinate>,
    /// The product of the distinct lone primes of every coordinate that are not always hit, as
    /// limbs (empty when there are none): one `gcd(a_k, P)` per point serves every coordinate.
    lone_product: Vec<u64>,
}

/// `g[k] = gcd(a_k, P)` for each coordinate of the point (`0` when `a_k = 0`, which every prime
/// divides), `P` odd, as limbs: one Hensel remainder of `P` by the odd part of `a_k` (coprime
/// to 2, so the remainder's factor `2^{−64·len}` changes no gcd) and a word gcd.
fn lone_gcds(g: &mut Vec<u64>, a: &[u64], p: &[u64]) {
    g.clear();
    g.extend(a.iter().map(|&x| {
        let odd = x >> x.trailing_zeros().min(63);
        match x {
            0 => 0,
            _ if odd == 1 => 1,
            _ => gcd_u64(rem_hensel(p, odd, inverse_odd(odd)), odd),
        }
    }));
}

fn to_limbs(x: &BigUint) -> Vec<u64> {
    x.to_u64_digits()
}

fn from_limbs(x: &[u64]) -> BigUint {
    from_limbs_with(x, &mut Vec::new())
}

/// [`from_limbs`] through the reusable buffer `halves` (num-bigint builds from 32-bit digits),
/// so that the only allocation is the result's.
fn from_limbs_with(x: &[u64], halves: &mut Vec<u32>) -> BigUint {
    halves.clear();
    halves.extend(x.iter().flat_map(|&l| [l as u32, (l >> 32) as u32]));
    BigUint::from_slice(halves)
}

impl FastNet {
    /// Whether [`FastNet::new`] needs the [`IntegerNetsRef`] of `net` (whose least common
    /// denominators are `denominators`): for every simplex but the triangle, and for a triangle
    /// when some coordinate's `z_α` may be short enough for [`horner_fixed`] (`bits(z_α)` is
    /// `bits(p) + bits(L_c) − bits(q)` for `p/q` give or take one; the estimate only decides
    /// whether the fixed-width path is prepared, never whether it is sound).
    pub fn needs_integer_nets(net: &ControlNet<BigRational>, denominators: &[BigInt]) -> bool {
        let n = net.degree() as u64;
        net.m() != 2
            || denominators.iter().enumerate().any(|(c, l)| {
                let bits = net
                    .points()
                    .map(|p| (p[c].numer().bits() + l.bits()).saturating_sub(p[c].denom().bits()))
                    .max()
                    .unwrap_or(0);
                // the fixed path runs only when z_bits + n + 1 ≤ FIXED_BITS, and z_bits ≥ bits − 1
                bits + n <= FIXED_BITS
            })
    }

    /// Prepare `net`, whose least common denominators are `denominators` (factored when their
    /// odd parts split into small primes); `nets` are its [`IntegerNetsRef`], given exactly when
    /// [`FastNet::needs_integer_nets`] holds.
    pub fn new(
        net: &ControlNet<BigRational>,
        nets: Option<IntegerNetsRef<'_>>,
        denominators: &[BigInt],
        factored: Vec<Option<Factors>>,
    ) -> Self {
        let (m, n, dim) = (net.m(), net.degree(), net.dim());
        let mut counts = vec![0; (m + 1) * (n + 1)];
        for t in 0..=m {
            for nn in 0..=n {
                counts[t * (n + 1) + nn] = if t == 0 { 1 } else { count(t, nn) };
            }
        }
        // The coordinates are prepared independently, on all cores (at high degrees this is the
        // serial part of a whole evaluation run).
        debug_assert_eq!(factored.len(), dim);
        let coords = factored
            .into_par_iter()
            .enumerate()
            .map(|(c, f)| {
                let global = nets.map(|nets| Global::new(nets, c));
                let form =
                    if m == 2 {
                        Form::Triangle {
                            rows: Rows::new(n, net, c),
                            small: global,
                        }
                    } else {
                        // invariant: the integer nets are built for every simplex except the triangle, which takes the branch above
                        Form::Simplex(global.expect(
                            "the integer nets are given for every simplex but the triangle",
                        ))
                    };
                Coordinate {
                    form,
                    denominator: denominators[c].magnitude().clone(),
                    odd_denominator: to_limbs(
                        &(denominators[c].magnitude()
                            >> denominators[c].magnitude().trailing_zeros().unwrap_or(0)),
                    ),
                    e2: denominators[c].magnitude().trailing_zeros().unwrap_or(0),
                    reducer: f.map(|f| {
                        let (shared, lone) = census(&f, net, c);
                        // Deciding lone primes costs m + 1 word gcds with L per point; residues
                        // cost a pass over N (about as long as L) per modulus they fill. Keep
                        // the cheaper (the gcds win at high degrees, where L has many primes).
                        let limbs = denominators[c].bits().div_ceil(64) + 1;
                        let saved =
                            moduli_count(lone.iter().map(|l| l.p.p)) as u64 * (2 * limbs + 30);
                        let cost = (m as u64 + 1) * (2 * limbs + GCD_COST);
                        if saved > cost {
                            Reducer::new(shared, lone)
                        } else {
                            Reducer::new(f.odd.clone(), Vec::new())
                        }
                    }),
                }
            })
            .collect::<Vec<Coordinate>>();
        let mut primes: Vec<u64> = coords
            .iter()
            .filter_map(|c| c.reducer.as_ref())
            .flat_map(|r| r.lone.iter().map(|l| l.p.p))
            .collect();
        primes.sort_unstable();
        primes.dedup();
        let lone_product = if primes.is_empty() {
            Vec::new()
        } else {
            to_limbs(&primes.iter().fold(BigUint::one(), |acc, &p| acc * p))
        };
        FastNet {
            m,
            n,
            counts,
            coords,
            lone_product,
        }
    }

    #[inline]
    fn count(&self, t: usize, nn: usize) -> usize {
        self.counts[t * (self.n + 1) + nn]
    }

    /// `Σ s_α a^α` over the sub-simplex of dimension `t`, degree `nn`, starting at rank `base`,
    /// into `bufs[0]`.
    #[allow(clippy::too_many_arguments)] // the recursion's state; a struct would only rename it
    fn horner(
        &self,
        c: &Global,
        t: usize,
        nn: usize,
        base: usize,
        a: &[u64],
        pw: &[Vec<u64>],
        bufs: &mut [Vec<u64>],
    ) {
        // invariant: the caller gives one buffer per remaining level, and recursion stops before they run out
        let (head, rest) = bufs.split_first_mut().expect("one buffer per level");
        head.clear();
        if t == 1 {
            head.extend_from_slice(c.coef(base));
            for (j, p) in pw.iter().enumerate().take(nn + 1).skip(1) {
                mul_word(head, a[0]);
                add_mul(head, c.coef(base + j), p);
            }
            return;
        }
        let mut off = base + self.count(t, nn) - 1;
        head.extend_from_slice(c.coef(off));
        for k in (0..nn).rev() {
            off -= self.count(t - 1, nn - k);
            mul_word(head, a[t]);
            self.horner(c, t - 1, nn - k, off, a, pw, rest);
            add(head, &rest[0]);
        }
    }

    /// The homogeneous form at `λ = a / d` (`d ≥ 1`), in lowest terms.
    pub fn evaluate(&self, a: &[u64], d: u64) -> Vec<BigRational> {
        assert_eq!(
            a.len(),
            self.m + 1,
            "point has the wrong number of coordinates"
        );
        SCRATCH.with_borrow_mut(|scratch| self.evaluate_with(a, d, scratch))
    }

    fn evaluate_with(&self, a: &[u64], d: u64, scratch: &mut Scratch) -> Vec<BigRational> {
        let n = self.n;
        let Scratch {
            pw,
            sp,
            bufs,
            row_bufs,
            acc,
            lone,
            reduce: red,
        } = scratch;
        if !self.lone_product.is_empty() {
            lone_gcds(lone, a, &self.lone_product);
        }
        let g = lone.as_slice();
        // Powers a_1^j, j = 0..n (reusing the thread's buffers: no allocation per point).
        fill_powers(pw, n, &[a[1]]);
        if bufs.len() < self.m {
            bufs.resize(self.m, Vec::new());
        }
        let mut sums_ready = false;
        let block = Block::new(a[0], a.get(1).copied().unwrap_or(0));
        let den = PointDenominator::new(d, n);
        let mut sum_pow: Option<BigUint> = None;
        let sum: u128 = a.iter().map(|&x| u128::from(x)).sum();
        let sum_bits = u64::from(128 - sum.leading_zeros());
        self.coords
            .iter()
            .map(|c| match &c.form {
                Form::Triangle { rows, small } => {
                    if let Some(global) = small {
                        // Small results: fixed-width two's complement, no lengths to track.
                        let need = global.z_bits + n as u64 * sum_bits + 1;
                        let fixed = match need {
                            0..=128 => Some(horner_fixed::<2>(global, n, a, sum, acc)),
                            129..=192 => Some(horner_fixed::<3>(global, n, a, sum, acc)),
                            193..=FIXED_BITS => Some(horner_fixed::<4>(global, n, a, sum, acc)),
                            _ => None,
                        };
                        if let Some(neg) = fixed {
                            return reduce(c, neg, acc, g, &den, red);
                        }
                    }
                    if !sums_ready {
                        let (sum, carry) = a[0].overflowing_add(a[1]);
                        let sum01 = [sum, u64::from(carry)];
                        fill_powers(sp, n, &sum01[..1 + usize::from(carry)]);
                        sums_ready = true;
                    }
                    let neg = rows.evaluate(n, a, pw, sp, &block, row_bufs, acc);
                    reduce(c, neg, acc, g, &den, red)
                }
                Form::Simplex(global) => {
                    self.horner(global, self.m, n, 0, a, pw, bufs);
                    let mut h = std::mem::take(&mut bufs[0]);
                    trim(&mut h);
                    let (neg, mut limbs) = if global.shift.is_zero() {
                        (false, h)
                    } else {
                        let sp = sum_pow.get_or_insert_with(|| {
                            a.iter().fold(BigUint::zero(), |s, &x| s + x).pow(n as u32)
                        });
                        let v = BigInt::from(from_limbs(&h)) - BigInt::from(&global.shift * &*sp);
                        (v.sign() == Sign::Minus, to_limbs(v.magnitude()))
                    };
                    reduce(c, neg, &mut limbs, g, &den, red)
                }
            })
            .collect()
    }
}

/// The most bits a result of [`horner_fixed`] may need (four limbs).
const FIXED_BITS: u64 = 256;

/// `x ← x · w mod 2^{64W}`.
#[inline(always)]
fn mul_word_fixed<const W: usize>(x: &mut [u64; W], w: u64) {
    let mut carry = 0u64;
    for d in x.iter_mut() {
        let t = u128::from(*d) * u128::from(w) + u128::from(carry);
        *d = t as u64;
        carry = (t >> 64) as u64;
    }
}

/// `x ← x + s · p mod 2^{64W}` (`s` any length: limbs from `W` on vanish modulo `2^{64W}`).
#[inline(always)]
fn add_mul_fixed<const W: usize>(x: &mut [u64; W], s: &[u64], p: &[u64; W]) {
    for (i, &si) in s.iter().enumerate().take(W) {
        let mut carry = 0u64;
        for (d, &pj) in x[i..].iter_mut().zip(p) {
            let t = u128::from(si) * u128::from(pj) + u128::from(*d) + u128::from(carry);
            *d = t as u64;
            carry = (t >> 64) as u64;
        }
    }
}

/// A triangle's numerator `N = Σ_α s_α a^α − K_c σ^n` (`σ = Σ_k a_k`, given as `sum`) computed modulo `2^{64W}`
/// in two's complement, into `out` as a magnitude; returns whether `N < 0`. Exact when
/// `|N| < 2^{64W − 1}`, which the caller ensures from `|N| ≤ max_α |z_α| σ^n`: every operation is
/// a ring operation modulo `2^{64W}`, so the intermediate values may wrap; only the final value
/// must fit. The nested Horner is the plain one (`T ← T a_0 + s_j a_1^j` along a row, then
/// `S ← S a_2 + T`): at the small degrees where the result fits four limbs it has no lengths,
/// signs or allocations to track.
fn horner_fixed<const W: usize>(
    c: &Global,
    n: usize,
    a: &[u64],
    sum: u128,
    out: &mut Vec<u64>,
) -> bool {
    let mut s = [0u64; W];
    for k in (0..=n).rev() {
        let base = k * (2 * n + 3 - k) / 2;
        let mut t = [0u64; W];
        let mut p = [0u64; W];
        p[0] = 1;
        add_mul_fixed(&mut t, c.coef(base), &p);
        for j in 1..=n - k {
            mul_word_fixed(&mut t, a[0]);
            mul_word_fixed(&mut p, a[1]);
            add_mul_fixed(&mut t, c.coef(base + j), &p);
        }
        mul_word_fixed(&mut s, a[2]);
        // s ← s + t
        let mut carry = false;
        for (d, &x) in s.iter_mut().zip(&t) {
            let (r1, o1) = d.overflowing_add(x);
            let (r2, o2) = r1.overflowing_add(u64::from(carry));
            *d = r2;
            carry = o1 || o2;
        }
    }
    if !c.shift_limbs.is_empty() {
        // s ← s − K σ^n, as s + K·(−σ^n): σ^n by word products when σ is one word.
        let mut q = [0u64; W];
        q[0] = 1;
        for _ in 0..n {
            match u64::try_from(sum) {
                Ok(w) => mul_word_fixed(&mut q, w),
                Err(_) => {
                    let mut next = [0u64; W];
                    let sigma = [sum as u64, (sum >> 64) as u64];
                    add_mul_fixed(&mut next, &sigma, &q);
                    q = next;
                }
            }
        }
        negate_fixed(&mut q);
        add_mul_fixed(&mut s, &c.shift_limbs, &q);
    }
    let neg = s[W - 1] >> 63 == 1;
    if neg {
        negate_fixed(&mut s);
    }
    out.clear();
    out.extend_from_slice(&s);
    trim(out);
    neg
}

/// `x ← −x mod 2^{64W}`.
#[inline(always)]
fn negate_fixed<const W: usize>(x: &mut [u64; W]) {
    let mut carry = true;
    for d in x.iter_mut() {
        let (r, o) = (!*d).overflowing_add(u64::from(carry));
        *d = r;
        carry = o;
    }
}

/// The point's share `D^n = 2^{n·v₂(D)} · D_odd^n` of every denominator `L_c D^n`.
struct PointDenominator {
    n: usize,
    d: u64,
    /// `v₂(D)`, `D_odd`, `D_odd⁻¹ mod 2^64`.
    tz: u64,
    odd: u64,
    odd_inv: u64,
    /// `D_odd^n` as limbs.
    odd_pow: Vec<u64>,
}

impl PointDenominator {
    fn new(d: u64, n: usize) -> Self {
        let tz = u64::from(d.trailing_zeros());
        let odd = d >> tz;
        let mut odd_pow = vec![1u64];
        for _ in 0..n {
            mul_word(&mut odd_pow, odd);
        }
        PointDenominator {
            n,
            d,
            tz,
            odd,
            odd_inv: inverse_odd(odd),
            odd_pow,
        }
    }
}

/// Multiply the words of `factors` into as few machine words as fit, and divide `x` by each.
fn div_exact_words(x: &mut Vec<u64>, factors: &[u64]) {
    let mut word = 1u64;
    for &f in factors {
        match word.checked_mul(f) {
            Some(w) => word = w,
            None => {
                div_exact_odd(x, word, inverse_odd(word));
                word = f;
            }
        }
    }
    if word > 1 {
        div_exact_odd(x, word, inverse_odd(word));
    }
}

/// `±limbs / (L_c D^n)` in lowest terms.
///
/// `gcd(N, L_c D^n)` is removed prime by prime without a big gcd: the power of two by trailing
/// zeros against `v₂(L_c) + n·v₂(D)`; the odd part of `D^n` by at most `n` rounds of
/// `g = gcd(N mod D_odd, D_odd)`, `N ← N/g` (a round removes `p^{min(v_p(N), v_p(D))}` of each
/// prime, so `n` rounds remove `p^{min(v_p(N), n·v_p(D))}`); then the odd primes of `L_c` up to
/// their exponents in `L_c` from what is left, which makes `p^{min(v_p(N), v_p(L_c D^n))}` in all.
/// Remainders and exact quotients by odd words are Hensel divisions (no division instruction).
/// `g` is the point's [`lone_gcds`] (empty when no coordinate has lone primes to decide).
fn reduce(
    c: &Coordinate,
    neg: bool,
    limbs: &mut Vec<u64>,
    g: &[u64],
    pt: &PointDenominator,
    scratch: &mut ReduceScratch,
) -> BigRational {
    let sign = if neg { Sign::Minus } else { Sign::Plus };
    if limbs.is_empty() {
        return BigRational::zero();
    }
    let Some(reducer) = &c.reducer else {
        let v = BigInt::from_biguint(sign, from_limbs(limbs));
        let dn = BigUint::from(pt.d).pow(pt.n as u32);
        return BigRational::new(v, BigInt::from(&c.denominator * dn));
    };
    let ReduceScratch {
        from_d,
        from_l,
        hits,
        sure,
        l,
        dp,
        den,
        halves,
    } = scratch;
    // Powers of two.
    let twos = c.e2 + pt.n as u64 * pt.tz;
    let s2 = trailing_zeros(limbs).min(twos);
    shr(limbs, s2);
    // The odd part of D^n.
    from_d.clear();
    if pt.odd > 1 {
        for _ in 0..pt.n {
            let g = gcd_u64(rem_hensel(limbs, pt.odd, pt.odd_inv), pt.odd);
            if g == 1 {
                break;
            }
            div_exact_odd(limbs, g, inverse_odd(g));
            from_d.push(g);
        }
    }
    // The odd primes of L_c.
    from_l.clear();
    reducer.strip_odd(limbs, g, from_l, hits, sure);
    if from_l.is_empty() && from_d.is_empty() {
        mul_into(den, &c.odd_denominator, &pt.odd_pow);
    } else {
        l.clear();
        l.extend_from_slice(&c.odd_denominator);
        div_exact_words(l, from_l);
        dp.clear();
        dp.extend_from_slice(&pt.odd_pow);
        div_exact_words(dp, from_d);
        mul_into(den, l, dp);
    }
    shl(den, twos - s2);
    let numer = from_limbs_with(limbs, halves);
    BigRational::new_raw(
        BigInt::from_biguint(sign, numer),
        BigInt::from(from_limbs_with(den, halves)),
    )
}

/// [`reduce`]'s buffers, reused from coordinate to coordinate and point to point.
#[derive(Default)]
struct ReduceScratch {
    from_d: Vec<u64>,
    from_l: Vec<u64>,
    hits: Vec<(OddDivisor, u32)>,
    sure: Vec<(OddDivisor, u32)>,
    l: Vec<u64>,
    dp: Vec<u64>,
    den: Vec<u64>,
    halves: Vec<u32>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Trial division by every odd number up to the square root: the reference for
    /// [`factor_odd`] (which divides by the primes below 256, then by the sieved primes below
    /// `2^16`, and refuses a cofactor `≥ 2^32`).
    fn naive(mut r: u64) -> Vec<(u64, u32)> {
        let mut out = Vec::new();
        let mut p = 3;
        while p * p <= r {
            let mut e = 0;
            while r.is_multiple_of(p) {
                r /= p;
                e += 1;
            }
            if e > 0 {
                out.push((p, e));
            }
            p += 2;
        }
        if r > 1 {
            out.push((r, 1));
        }
        out
    }

    #[test]
    fn factor_odd_agrees_with_naive_trial_division() {
        let cases = [
            1,
            3,
            255,
            257 * 257,
            255 * 257,
            251 * 251 * 3,
            65_537 * 257,
            65_521 * 65_519,
            3u64.pow(40),
            65_521 * 65_521 * 7,
        ];
        for r in cases {
            assert_eq!(factor_odd(r), Some(naive(r)), "{r}");
        }
        // every odd number below 70,000 (across 257² = 66,049, where the sieve takes over)
        for r in (1..70_000).step_by(2) {
            assert_eq!(factor_odd(r), Some(naive(r)), "{r}");
        }
        // a cofactor of 2^32 or more is refused (it could be composite)
        assert_eq!(factor_odd(4_294_967_311), None);
        assert_eq!(factor_odd((1 << 61) - 1), None);
        assert_eq!(factor_odd(65_537 * 4_294_967_311), None);
        assert_eq!(factor_odd(1_000_003 * 999_983), None);
    }
}
