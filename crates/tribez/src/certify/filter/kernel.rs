//! The lean kernels: [`Filter::evaluate_compensated`](super::Filter) and the plain
//! [`Filter::evaluate`](super::Filter) for small `m` and `dim` (`m ≤ 3`, `dim ≤ 4`), with the
//! loops unrolled at compile time over one in-place buffer. The plain kernel performs the generic
//! code's operations in the generic code's order (a test checks the numbers are identical); the
//! compensated one is described below.
//!
//! **In place.** The node `β` of degree `q − 1` (a step's output) overwrites the slot of its
//! child `β + e_0`. Its other readers are the parents `β + e_0 − e_k` (`k ≥ 1`), whose first
//! index is one larger; processing the parents of a step in decreasing `β_0` therefore reads
//! every child before it is overwritten (the slot `β + e_0` is written by `β` alone). Slots keep
//! the ranks of the degree-`n` net, so the first step reads the control points (prepared once,
//! with their Dekker splits) and writes the buffer, and the apex ends in the slot of `n·e_0`.
//!
//! **Arithmetic.** Exactly the model of the generic [`Filter::evaluate_compensated`](super::Filter):
//! TwoProduct (Dekker, with the splits of `λ` taken once per row and the split of each node
//! value taken once, when the node is computed) and TwoSum give every node value `V` with its
//! exact local error; the correction `Ê` and its running bound
//! `ν = Σ_k |λ_k| ν_k + ε Σ|partials| + (m+1)η` follow the children's. On the first step the
//! children's corrections are 0, so the products `λ_k Ê_k` and the additions of them are exact
//! and contribute no rounding term. The condition number `Σ|c_i| B_i(|λ|)` is carried in the same
//! pass (`s = Σ_k |λ_k| s_k`), so this one pass yields everything the plain stage provided
//! besides its own (looser) bound.
//!
//! **FMA.** On an x86-64 processor with AVX2 and FMA (detected at run time; the build targets
//! plain x86-64) the compensated kernel runs compiled for those features, and TwoProduct's
//! error is one fused multiply-add, `π = fma(λ_k, V_k, −p)`. Under the guards below Dekker's
//! `π` is exact too, so both are `λ_k V_k − p` and the two kernels compute the same bits (tests
//! compare them on the stress cases and on random nets); the node splits are then not computed.
//! `tribez check --results` at n = 3 spends about 40% less time in this kernel with FMA
//! (docs/performance.md).
//!
//! **Double-double points** (Cartesian rows, docs/theory.md §14.5): the kernels built with `DD`
//! evaluate at `λ + lo` for a low part `lo` (about `ε|λ|`). A node's exact value is
//! `Σ_k (λ_k + lo_k)(V_k + Ê_k + e_k)` with `|e_k| ≤ ν_k`; the products `lo_k V_k`, rounded, join
//! the correction like `λ_k Ê_k` (their roundings enter `ν` the same way), and the terms left out,
//! `lo_k Ê_k` and `lo_k e_k`, add `|lo_k| (|Ê_k| + ν_k)` to `ν`, with one more underflow
//! allowance per child. Without `DD` the low parts are not read and the code is the kernel above.
//!
//! **Layout.** A node holds `L` lanes (`L = 2` for `dim ≤ 2`, `4` for `dim ≤ 4`, padded with
//! zeros, which stay zeros) of six quantities (value, its split hi/lo, correction, ν, condition),
//! so every operation is a fixed-width loop the compiler turns into SIMD, and a child costs one
//! bounds check.
//!
//! **Guards** (TwoProduct is exact when the split does not overflow and `e_a + e_b ≥ −970`, i.e.
//! no partial product underflows; TwoSum when nothing overflows): every `|λ_k|` is 0 or in
//! `[2^-300, 2^300]`, and every control coordinate and node value is 0 or in `[2^-500, 2^500]`;
//! then every non-zero product lies in `[2^-800, 2^800]` and every sum below `2^805`. A zero
//! factor gives `p = π = 0` exactly. A tripped guard (checked once per node, not per product)
//! gives an undecided enclosure (`mu` NaN), as in the generic code.

use super::{EPS, Enclosure, TINY};
use crate::simplex::{Simplex, rank};

/// `2^27 + 1`, Dekker's splitting constant for f64.
const SPLIT: f64 = 134_217_729.0;
/// `2^k` for `|k| < 1000`.
const fn pow2(k: i64) -> f64 {
    f64::from_bits(((k + 1023) as u64) << 52)
}
/// Range of non-zero barycentric coordinates.
const LAMBDA_MIN: f64 = pow2(-300);
const LAMBDA_MAX: f64 = pow2(300);
/// Range of non-zero control coordinates and node values.
const VALUE_MIN: f64 = pow2(-500);
const VALUE_MAX: f64 = pow2(500);

/// `x` is 0 or within `[lo, hi]` in magnitude (false for NaN and infinities).
#[inline(always)]
fn in_range(x: f64, lo: f64, hi: f64) -> bool {
    let a = x.abs();
    a == 0.0 || (lo <= a && a <= hi)
}

/// Dekker's split `a = hi + lo` with `hi` of 26 bits (exact for `|a| < 2^995`).
#[inline(always)]
fn split(a: f64) -> (f64, f64) {
    let c = SPLIT * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// The error `π` of `p = fl(a b)` from the splits of `a` and `b` (Dekker): `a b = p + π`.
#[inline(always)]
fn product_error(p: f64, ah: f64, al: f64, bh: f64, bl: f64) -> f64 {
    al * bl - (((p - ah * bh) - al * bh) - ah * bl)
}

/// Knuth's TwoSum.
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// One monomorphised compensated kernel: the net at `λ` (or at `λ + λ_lo`, the second slice, in
/// the kernels built with `DD`).
type KernelFn = fn(&Lean, &[f64], &[f64], &mut Vec<f64>) -> bool;
/// One monomorphised plain kernel.
type PlainFn = fn(&Lean, &[f64], &mut Vec<f64>);
/// One monomorphised widening kernel.
type WidenFn = fn(&Lean, &[f64], &[f64], &mut Vec<f64>);

/// Quantities of a node in the buffer.
const V: usize = 0;
const H: usize = 1;
const LO: usize = 2;
const E: usize = 3;
const NU: usize = 4;
const S: usize = 5;
/// Quantities of a control point: value, hi, lo, |value|.
const ABS: usize = 3;

/// A net prepared for the lean kernel.
#[derive(Clone, Debug)]
pub(super) struct Lean {
    dim: usize,
    lanes: usize,
    nodes: usize,
    /// Per parent, over all steps (first step first): `[out slot, child slot_0, …, child slot_m]`.
    stencil: Vec<u32>,
    /// The number of parents of the first step (their children are control points).
    first: usize,
    /// The apex's slot.
    apex: usize,
    /// Per control point, four groups of `lanes` numbers: coordinates, their Dekker splits hi
    /// and lo, absolute values (zero-padded).
    control: Vec<f64>,
    /// Every control coordinate is 0 or in `[2^-500, 2^500]`.
    control_ok: bool,
    kernels: Kernels,
}

/// The monomorphised kernels of one `(m, lanes)`.
#[derive(Clone, Copy, Debug)]
struct Kernels {
    /// The compensated kernel run by [`Lean::run`] (with FMA where the processor has it).
    fast: KernelFn,
    /// The same at a double-double point ([`Lean::run_dd`]).
    fast_dd: KernelFn,
    /// The compensated kernels with Dekker's TwoProduct (the references the fast ones equal;
    /// read by the tests).
    #[cfg_attr(not(test), allow(dead_code))]
    dekker: KernelFn,
    #[cfg_attr(not(test), allow(dead_code))]
    dekker_dd: KernelFn,
    plain: PlainFn,
    widen: WidenFn,
}

/// Buffers of the lean kernel (one node per control point: six groups of `lanes` numbers).
#[derive(Clone, Debug, Default)]
pub(super) struct LeanScratch {
    buf: Vec<f64>,
    plain: Vec<f64>,
    widen: Vec<f64>,
}

/// The apex of one lean run, per coordinate (`lanes` entries; the first `dim` count).
pub(super) struct Apex<'a> {
    pub value: &'a [f64],
    pub corr: &'a [f64],
    pub nu: &'a [f64],
    pub s: &'a [f64],
}

/// The kernel of this processor: [`run_fma`] where it has AVX2 and FMA, [`run`] otherwise.
#[cfg(target_arch = "x86_64")]
fn fast<const M1: usize, const L: usize, const DD: bool>() -> KernelFn {
    if fma_detected() {
        run_fma::<M1, L, DD>
    } else {
        run::<M1, L, DD>
    }
}
#[cfg(not(target_arch = "x86_64"))]
fn fast<const M1: usize, const L: usize, const DD: bool>() -> KernelFn {
    run::<M1, L, DD>
}

impl Kernels {
    fn of<const M1: usize, const L: usize>() -> Kernels {
        Kernels {
            fast: fast::<M1, L, false>(),
            fast_dd: fast::<M1, L, true>(),
            dekker: run::<M1, L, false>,
            dekker_dd: run::<M1, L, true>,
            plain: run_plain::<M1, L>,
            widen: run_widen::<M1, L>,
        }
    }
}

macro_rules! pick {
    ($m1:expr; $($a:literal),*; $lanes:expr) => {
        match ($m1, $lanes) {
            $(
                ($a, 2) => Some(Kernels::of::<$a, 2>()),
                ($a, 4) => Some(Kernels::of::<$a, 4>()),
            )*
            _ => None,
        }
    };
}

impl Lean {
    /// Prepare a net of `dim` coordinates per point on the m-simplex, degree `n ≥ 1`; `None`
    /// when no kernel is compiled for this `(m, dim)` (`m ≤ 3`, `dim ≤ 4`; the generic code then
    /// serves).
    pub(super) fn new(m: usize, n: usize, dim: usize, coords: &[f64]) -> Option<Lean> {
        let lanes = match dim {
            1 | 2 => 2,
            3 | 4 => 4,
            _ => return None,
        };
        if n == 0 {
            return None;
        }
        let kernels = pick!(m + 1; 2, 3, 4; lanes)?;
        let nodes = Simplex::new(m, n).len();
        // slot[r] of the nodes of the current degree q (the children), by rank
        let mut slot: Vec<usize> = (0..nodes).collect();
        let mut stencil = Vec::new();
        let mut first = 0;
        for q in (1..=n).rev() {
            let lower = Simplex::new(m, q - 1);
            let mut parents: Vec<(u32, Vec<u32>)> = Vec::with_capacity(lower.len());
            let mut next = vec![0usize; lower.len()];
            let mut child = vec![0u32; m + 1];
            for (r, beta) in lower.iter().enumerate() {
                let mut row = Vec::with_capacity(m + 2);
                for k in 0..=m {
                    child.copy_from_slice(beta);
                    child[k] += 1;
                    row.push(slot[rank(&child)] as u32);
                }
                next[r] = row[0] as usize;
                row.insert(0, row[0]);
                parents.push((beta[0], row));
            }
            // decreasing β_0 (stable), so every child is read before its slot is overwritten
            parents.sort_by_key(|(b0, _)| std::cmp::Reverse(*b0));
            if q == n {
                first = parents.len();
            }
            for (_, row) in parents {
                stencil.extend(row);
            }
            slot = next;
        }
        let mut control = vec![0.0; nodes * 4 * lanes];
        for (i, point) in coords.chunks_exact(dim).enumerate() {
            for (c, &x) in point.iter().enumerate() {
                let (h, l) = split(x);
                let base = i * 4 * lanes + c;
                control[base + V * lanes] = x;
                control[base + H * lanes] = h;
                control[base + LO * lanes] = l;
                control[base + ABS * lanes] = x.abs();
            }
        }
        Some(Lean {
            dim,
            lanes,
            nodes,
            stencil,
            first,
            apex: slot[0],
            control,
            control_ok: coords.iter().all(|&x| in_range(x, VALUE_MIN, VALUE_MAX)),
            kernels,
        })
    }

    /// Run the plain kernel at `lambda`: the apex's value, running bound μ (in `nu`) and
    /// condition number; `corr` is empty.
    pub(super) fn run_plain<'a>(&self, lambda: &[f64], sc: &'a mut LeanScratch) -> Apex<'a> {
        (self.kernels.plain)(self, lambda, &mut sc.plain);
        let l = self.lanes;
        let base = self.apex * 3 * l;
        let q = |k: usize| &sc.plain[base + k * l..base + k * l + self.dim];
        Apex {
            value: q(0),
            corr: &[],
            nu: q(1),
            s: q(2),
        }
    }

    /// The widening pass of a Cartesian row ([`run_widen`]) at `a = |λ̂|` with radii `d`: per
    /// coordinate (`dim` entries) `S(a)` and the bound on `S(a + d) − S(a)`, before the
    /// allowances for their own roundings.
    pub(super) fn run_widen<'a>(
        &self,
        a: &[f64],
        d: &[f64],
        sc: &'a mut LeanScratch,
    ) -> (&'a [f64], &'a [f64]) {
        (self.kernels.widen)(self, a, d, &mut sc.widen);
        let l = self.lanes;
        let base = self.apex * 2 * l;
        (
            &sc.widen[base..base + self.dim],
            &sc.widen[base + l..base + l + self.dim],
        )
    }

    /// Run the kernel at `lambda` (`m + 1` floats); false when a guard tripped (the apex is then
    /// meaningless).
    pub(super) fn run<'a>(&self, lambda: &[f64], sc: &'a mut LeanScratch) -> (bool, Apex<'a>) {
        self.run_with(self.kernels.fast, lambda, &[], sc)
    }

    /// [`Lean::run`] at the double-double point `λ = hi + lo` (`|lo_k|` at most about `ε|hi_k|`):
    /// the products `lo_k V_k` join the corrections and `ν` grows by `|lo_k| (|Ê_k| + ν_k)` for
    /// the terms left out (module documentation).
    pub(super) fn run_dd<'a>(
        &self,
        hi: &[f64],
        lo: &[f64],
        sc: &'a mut LeanScratch,
    ) -> (bool, Apex<'a>) {
        self.run_with(self.kernels.fast_dd, hi, lo, sc)
    }

    /// [`Lean::run`] with Dekker's TwoProduct whatever the processor has (the reference that
    /// the FMA kernel must equal bit for bit).
    #[cfg(test)]
    pub(super) fn run_dekker<'a>(
        &self,
        lambda: &[f64],
        sc: &'a mut LeanScratch,
    ) -> (bool, Apex<'a>) {
        self.run_with(self.kernels.dekker, lambda, &[], sc)
    }

    /// [`Lean::run_dd`] with Dekker's TwoProduct (the reference of the FMA kernel).
    #[cfg(test)]
    pub(super) fn run_dd_dekker<'a>(
        &self,
        hi: &[f64],
        lo: &[f64],
        sc: &'a mut LeanScratch,
    ) -> (bool, Apex<'a>) {
        self.run_with(self.kernels.dekker_dd, hi, lo, sc)
    }

    /// Whether [`Lean::run`] is the FMA kernel (false where the processor lacks AVX2 or FMA).
    #[cfg(test)]
    pub(super) fn uses_fma(&self) -> bool {
        !std::ptr::fn_addr_eq(self.kernels.fast, self.kernels.dekker)
    }

    fn run_with<'a>(
        &self,
        kernel: KernelFn,
        lambda: &[f64],
        lo: &[f64],
        sc: &'a mut LeanScratch,
    ) -> (bool, Apex<'a>) {
        let ok = kernel(self, lambda, lo, &mut sc.buf);
        let l = self.lanes;
        let base = self.apex * 6 * l;
        let q = |k: usize| &sc.buf[base + k * l..base + k * l + self.dim];
        (
            ok,
            Apex {
                value: q(V),
                corr: q(E),
                nu: q(NU),
                s: q(S),
            },
        )
    }
}

/// The kernel for `M1 = m + 1` barycentric coordinates and `L` lanes, TwoProduct by Dekker (at
/// `λ + lo` with `DD`).
fn run<const M1: usize, const L: usize, const DD: bool>(
    lean: &Lean,
    lambda: &[f64],
    lo: &[f64],
    buf: &mut Vec<f64>,
) -> bool {
    run_body::<M1, L, false, DD>(lean, lambda, lo, buf)
}

/// [`run`] compiled for AVX2 and FMA where the processor has them (checked at run time on every
/// call), [`run`] itself otherwise. The error of a product comes from one fused multiply-add,
/// `π = fma(a, b, −p)`, which is `a b − p` exactly whenever Dekker's is (the guards below make
/// both exact), so the two compute the same numbers (a test compares them bit for bit); node
/// values need no split.
#[cfg(target_arch = "x86_64")]
fn run_fma<const M1: usize, const L: usize, const DD: bool>(
    lean: &Lean,
    lambda: &[f64],
    lo: &[f64],
    buf: &mut Vec<f64>,
) -> bool {
    if fma_detected() {
        // SAFETY: the processor has the features `run_fma_unchecked` is compiled for (just
        // detected), which is the one requirement of calling it.
        unsafe { run_fma_unchecked::<M1, L, DD>(lean, lambda, lo, buf) }
    } else {
        run::<M1, L, DD>(lean, lambda, lo, buf)
    }
}

/// Whether this x86-64 processor has AVX2 and FMA (detected once by the standard library and
/// cached).
#[cfg(target_arch = "x86_64")]
fn fma_detected() -> bool {
    std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn run_fma_unchecked<const M1: usize, const L: usize, const DD: bool>(
    lean: &Lean,
    lambda: &[f64],
    lo: &[f64],
    buf: &mut Vec<f64>,
) -> bool {
    run_body::<M1, L, true, DD>(lean, lambda, lo, buf)
}

/// The compensated kernel; `FMA` picks how TwoProduct's error is computed (`true` only inside a
/// function compiled with the `fma` target feature, where `mul_add` is one instruction); `DD`
/// evaluates at `λ + lo` (`lo` is not read without it).
#[inline(always)]
fn run_body<const M1: usize, const L: usize, const FMA: bool, const DD: bool>(
    lean: &Lean,
    lambda: &[f64],
    lo: &[f64],
    buf: &mut Vec<f64>,
) -> bool {
    let len = lean.nodes * 6 * L;
    if buf.len() != len {
        buf.resize(len, 0.0);
    }
    let nodes: &mut [[[f64; L]; 6]] = buf.as_chunks_mut::<L>().0.as_chunks_mut::<6>().0;
    let control: &[[[f64; L]; 4]] = lean.control.as_chunks::<L>().0.as_chunks::<4>().0;
    let lam: [f64; M1] = std::array::from_fn(|k| lambda[k]);
    let la: [f64; M1] = lam.map(f64::abs);
    let lh: [f64; M1] = lam.map(|x| split(x).0);
    let ll: [f64; M1] = std::array::from_fn(|k| lam[k] - lh[k]);
    // the low parts of a double-double point, and their magnitudes
    let low: [f64; M1] = std::array::from_fn(|k| if DD { lo[k] } else { 0.0 });
    let low_abs: [f64; M1] = low.map(f64::abs);
    // underflow allowance per node: one product per child may underflow (two with `DD`)
    let tiny = if DD { 2.0 } else { 1.0 } * M1 as f64 * TINY;
    let mut ok = lean.control_ok;
    for x in lam {
        ok &= in_range(x, LAMBDA_MIN, LAMBDA_MAX);
    }
    // the node values' range, over all nodes and lanes (zeros excluded from the minimum)
    let mut vmax = [0f64; L];
    let mut vmin = [f64::INFINITY; L];
    let (first, rest) = lean.stencil.split_at(lean.first * (M1 + 1));
    // first step: the children are control points (no corrections, no ν)
    for row in first.chunks_exact(M1 + 1) {
        let kids: [&[[f64; L]; 4]; M1] = std::array::from_fn(|k| &control[row[k + 1] as usize]);
        let mut acc = [0f64; L];
        let mut corr = [0f64; L];
        let mut partial = [0f64; L];
        let mut cond = [0f64; L];
        for k in 0..M1 {
            let kid = kids[k];
            for c in 0..L {
                let p = lam[k] * kid[V][c];
                let pi = if FMA {
                    lam[k].mul_add(kid[V][c], -p)
                } else {
                    product_error(p, lh[k], ll[k], kid[H][c], kid[LO][c])
                };
                cond[c] += la[k] * kid[ABS][c];
                if k == 0 {
                    acc[c] = p;
                    corr[c] = pi;
                } else {
                    let (sum, sigma) = two_sum(acc[c], p);
                    acc[c] = sum;
                    corr[c] += pi;
                    partial[c] += corr[c].abs();
                    corr[c] += sigma;
                    partial[c] += corr[c].abs();
                }
                if DD {
                    // lo_k V_k, rounded, into the correction (the children have Ê = ν = 0)
                    let t = low[k] * kid[V][c];
                    corr[c] += t;
                    partial[c] += t.abs() + corr[c].abs();
                }
            }
        }
        let out = &mut nodes[row[0] as usize];
        for c in 0..L {
            if !FMA {
                let (vh, vl) = split(acc[c]);
                out[H][c] = vh;
                out[LO][c] = vl;
            }
            let a = acc[c].abs();
            vmax[c] = vmax[c].max(a);
            vmin[c] = vmin[c].min(if a == 0.0 { f64::INFINITY } else { a });
            out[V][c] = acc[c];
            out[E][c] = corr[c];
            out[NU][c] = if DD {
                EPS * partial[c] + tiny
            } else {
                EPS * partial[c]
            };
            out[S][c] = cond[c];
        }
    }
    // later steps, in place
    for row in rest.chunks_exact(M1 + 1) {
        let mut acc = [0f64; L];
        let mut corr = [0f64; L];
        let mut partial = [0f64; L];
        let mut carried = [0f64; L];
        let mut cond = [0f64; L];
        for k in 0..M1 {
            // read in place: every child is read before the parent is written (a copy of the
            // children, 6·L words each, compiled to a memcpy per node under whole-program
            // optimisation)
            let kid = &nodes[row[k + 1] as usize];
            for c in 0..L {
                let p = lam[k] * kid[V][c];
                let pi = if FMA {
                    lam[k].mul_add(kid[V][c], -p)
                } else {
                    product_error(p, lh[k], ll[k], kid[H][c], kid[LO][c])
                };
                let t = lam[k] * kid[E][c];
                carried[c] += la[k] * kid[NU][c];
                cond[c] += la[k] * kid[S][c];
                if k == 0 {
                    acc[c] = p;
                    corr[c] = pi + t;
                    partial[c] = t.abs() + corr[c].abs();
                } else {
                    let (sum, sigma) = two_sum(acc[c], p);
                    acc[c] = sum;
                    corr[c] += pi;
                    partial[c] += corr[c].abs();
                    corr[c] += sigma;
                    partial[c] += corr[c].abs();
                    corr[c] += t;
                    partial[c] += t.abs() + corr[c].abs();
                }
                if DD {
                    // lo_k V_k, rounded, into the correction; lo_k Ê_k and lo_k times the
                    // child's own error are left out: |lo_k| (|Ê_k| + ν_k) into ν
                    let t = low[k] * kid[V][c];
                    corr[c] += t;
                    partial[c] += t.abs() + corr[c].abs();
                    carried[c] += low_abs[k] * (kid[E][c].abs() + kid[NU][c]);
                }
            }
        }
        let out = &mut nodes[row[0] as usize];
        for c in 0..L {
            if !FMA {
                let (vh, vl) = split(acc[c]);
                out[H][c] = vh;
                out[LO][c] = vl;
            }
            let a = acc[c].abs();
            vmax[c] = vmax[c].max(a);
            vmin[c] = vmin[c].min(if a == 0.0 { f64::INFINITY } else { a });
            out[V][c] = acc[c];
            out[E][c] = corr[c];
            out[NU][c] = carried[c] + EPS * partial[c] + tiny;
            out[S][c] = cond[c];
        }
    }
    for c in 0..L {
        // an infinity fails the first comparison; `max`/`min` skip NaN, but a NaN node value
        // comes only from an infinity before it (or reaches the apex, checked by `enclosures`)
        ok &= vmax[c] <= VALUE_MAX && vmin[c] >= VALUE_MIN;
    }
    ok
}

/// The plain stage ([`super::Filter::evaluate`]) for `M1 = m + 1` barycentric coordinates and
/// `L` lanes, in place like [`run`]: per node the value, the running bound
/// `μ = Σ_k |λ_k| μ_k + ε (Σ_k |p_k| + Σ_{k≥1} |s_k|) + (m + 1) η` and the condition number,
/// with the same operations in the same order as the generic code (so the same numbers).
fn run_plain<const M1: usize, const L: usize>(lean: &Lean, lambda: &[f64], buf: &mut Vec<f64>) {
    let len = lean.nodes * 3 * L;
    if buf.len() != len {
        buf.resize(len, 0.0);
    }
    let nodes: &mut [[[f64; L]; 3]] = buf.as_chunks_mut::<L>().0.as_chunks_mut::<3>().0;
    let control: &[[[f64; L]; 4]] = lean.control.as_chunks::<L>().0.as_chunks::<4>().0;
    let lam: [f64; M1] = std::array::from_fn(|k| lambda[k]);
    let la: [f64; M1] = lam.map(f64::abs);
    let (first, rest) = lean.stencil.split_at(lean.first * (M1 + 1));
    for row in first.chunks_exact(M1 + 1) {
        let kids: [&[[f64; L]; 4]; M1] = std::array::from_fn(|k| &control[row[k + 1] as usize]);
        let mut acc = [0f64; L];
        let mut rounding = [0f64; L];
        let mut cond = [0f64; L];
        for k in 0..M1 {
            let kid = kids[k];
            for c in 0..L {
                let p = lam[k] * kid[V][c];
                if k == 0 {
                    acc[c] = p;
                    rounding[c] = p.abs();
                    cond[c] = la[k] * kid[ABS][c];
                } else {
                    acc[c] += p;
                    rounding[c] += p.abs() + acc[c].abs();
                    cond[c] += la[k] * kid[ABS][c];
                }
            }
        }
        let out = &mut nodes[row[0] as usize];
        for c in 0..L {
            out[0][c] = acc[c];
            // the children's μ are 0: Σ|λ_k|·0 = 0 exactly
            out[1][c] = EPS * rounding[c] + M1 as f64 * TINY;
            out[2][c] = cond[c];
        }
    }
    for row in rest.chunks_exact(M1 + 1) {
        let mut acc = [0f64; L];
        let mut rounding = [0f64; L];
        let mut carried = [0f64; L];
        let mut cond = [0f64; L];
        for k in 0..M1 {
            // read in place, as in `run_body`
            let kid = &nodes[row[k + 1] as usize];
            for c in 0..L {
                let p = lam[k] * kid[0][c];
                if k == 0 {
                    acc[c] = p;
                    rounding[c] = p.abs();
                    carried[c] = la[k] * kid[1][c];
                    cond[c] = la[k] * kid[2][c];
                } else {
                    acc[c] += p;
                    rounding[c] += p.abs() + acc[c].abs();
                    carried[c] += la[k] * kid[1][c];
                    cond[c] += la[k] * kid[2][c];
                }
            }
        }
        let out = &mut nodes[row[0] as usize];
        for c in 0..L {
            out[0][c] = acc[c];
            out[1][c] = carried[c] + EPS * rounding[c] + M1 as f64 * TINY;
            out[2][c] = cond[c];
        }
    }
}

/// The widening pass of a Cartesian row ([`super::Filter`]'s `widening`) for `M1 = m + 1`
/// coordinates and `L` lanes, in place like [`run`]: de Casteljau on `|c|` at `a + d`, each node
/// split into its part `A = Σ_k a_k A_k` at `a` and the rest `Δ = Σ_k ((a_k + d_k) Δ_k + d_k A_k)`,
/// from `A = |c|`, `Δ = 0` on the control points, with the same operations in the same order as
/// the generic code (so the same numbers).
fn run_widen<const M1: usize, const L: usize>(
    lean: &Lean,
    a: &[f64],
    d: &[f64],
    buf: &mut Vec<f64>,
) {
    let len = lean.nodes * 2 * L;
    if buf.len() != len {
        buf.resize(len, 0.0);
    }
    let nodes: &mut [[[f64; L]; 2]] = buf.as_chunks_mut::<L>().0.as_chunks_mut::<2>().0;
    let control: &[[[f64; L]; 4]] = lean.control.as_chunks::<L>().0.as_chunks::<4>().0;
    let a: [f64; M1] = std::array::from_fn(|k| a[k]);
    let d: [f64; M1] = std::array::from_fn(|k| d[k]);
    let ad: [f64; M1] = std::array::from_fn(|k| a[k] + d[k]);
    let (first, rest) = lean.stencil.split_at(lean.first * (M1 + 1));
    for row in first.chunks_exact(M1 + 1) {
        let mut acc = [0f64; L];
        let mut delta = [0f64; L];
        for k in 0..M1 {
            let kid = &control[row[k + 1] as usize];
            for c in 0..L {
                acc[c] += a[k] * kid[ABS][c];
                // the control points' Δ is 0 (kept as a product, as the generic code has it)
                delta[c] += ad[k] * 0.0 + d[k] * kid[ABS][c];
            }
        }
        nodes[row[0] as usize] = [acc, delta];
    }
    for row in rest.chunks_exact(M1 + 1) {
        let mut acc = [0f64; L];
        let mut delta = [0f64; L];
        for k in 0..M1 {
            // read in place, as in `run_body`
            let kid = &nodes[row[k + 1] as usize];
            for c in 0..L {
                acc[c] += a[k] * kid[0][c];
                delta[c] += ad[k] * kid[1][c] + d[k] * kid[0][c];
            }
        }
        nodes[row[0] as usize] = [acc, delta];
    }
}

/// The lean kernel's result as enclosures (the constants as in [`super::Filter`]).
pub(super) fn enclosures(
    ok: bool,
    apex: &Apex<'_>,
    mu_inflate: f64,
    mu_absolute: f64,
    s_rel: f64,
    out: &mut [Enclosure],
) {
    for (c, o) in out.iter_mut().enumerate() {
        let (value, corr, nu, s) = (apex.value[c], apex.corr[c], apex.nu[c], apex.s[c]);
        *o = Enclosure {
            value,
            corr,
            mu: if ok && value.is_finite() && corr.is_finite() && nu.is_finite() {
                nu * mu_inflate + mu_absolute
            } else {
                f64::NAN
            },
            s_lo: (s * (1.0 - s_rel) - mu_absolute).max(0.0),
            s_hi: s * (1.0 + s_rel) + mu_absolute,
        };
    }
}
