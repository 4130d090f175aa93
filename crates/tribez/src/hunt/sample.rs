//! The rows a hunt gives its target (docs/theory.md, "Hunting for the worst inputs"): uniform
//! points of the domain, the places floats fail (coordinates near 0 and 1 at every scale
//! `2^-k`, corners and edges, binade boundaries, near zeros of a coordinate of the value, where
//! the condition number `Σ|c_i| B_i(λ) / |Σ c_i B_i(λ)|` is large), and moves of one coordinate
//! of a bad row by `±2^k` ulps.
//!
//! Index convention: a barycentric row is `λ_0, …, λ_m` (the patch's canonical order); a
//! Cartesian row is `x_1, …, x_m` in the patch's domain, whose vertex `k` has barycentric
//! coordinate `λ_k`. Every row is made of floats of the hunt's precision (an `f32` row holds
//! `f32` values as `f64`s); a barycentric row is made consistent by setting its largest
//! coordinate (other than the one just chosen) to the float nearest `1 − Σ_{others} λ_i`.

use crate::certify::sample::SplitMix;
use crate::domain::Domain;
use crate::float::Precision;
use crate::patch::ControlNet;
use crate::simplex::Simplex;

/// The geometry a sampler needs: the precision, the simplex, the control net in `f64` (and its
/// absolute values, for the condition number), the domain's vertices in `f64` (Cartesian rows).
pub(super) struct Space {
    pub precision: Precision,
    pub m: usize,
    pub net: ControlNet<f64>,
    /// The control points and their absolute values, interleaved: point `r` is
    /// `c_r[0..d], |c_r|[0..d]` at `points[2dr..2d(r+1)]` (one de Casteljau pass gives both).
    pub points: Vec<f64>,
    /// The de Casteljau step stencils, from degree `n` down to 1: entry `n − l` is
    /// [`Simplex::step_stencil`] of degree `l`.
    pub stencils: Vec<Vec<usize>>,
    /// Vertex `k` of the domain (`m` coordinates).
    pub vertices: Vec<Vec<f64>>,
    /// `inverse[i][j]`: row `i < m` of the inverse of the `m × m` matrix `V_k − V_m` (columns
    /// `k < m`), so that `λ_i = Σ_j inverse[i][j] (x_j − V_m[j])` for `i < m`.
    pub inverse: Vec<Vec<f64>>,
    /// The exact domain (whether a Cartesian row is inside it).
    pub domain: Domain,
    pub cartesian: bool,
}

/// The largest `k` of a move by `2^k` ulps (`52` for `f64`, `23` for `f32`).
pub(super) fn max_shift(p: Precision) -> u32 {
    match p {
        Precision::F64 => 52,
        Precision::F32 => 23,
    }
}

/// `x` rounded to the precision (as an `f64`).
pub(super) fn round(p: Precision, x: f64) -> f64 {
    match p {
        Precision::F64 => x,
        Precision::F32 => f64::from(x as f32),
    }
}

/// `x` moved by `steps` floats of the precision (negative: down), through zero and the
/// subnormals; `None` if that leaves the finite floats.
pub(super) fn step(p: Precision, x: f64, steps: i64) -> Option<f64> {
    let y = match p {
        Precision::F64 => {
            let b = x.to_bits() as i64;
            let ordered = if b < 0 { i64::MIN - b } else { b };
            let o = ordered.checked_add(steps)?;
            f64::from_bits((if o < 0 { i64::MIN - o } else { o }) as u64)
        }
        Precision::F32 => {
            let b = i64::from((x as f32).to_bits() as i32);
            let ordered = if b < 0 { i64::from(i32::MIN) - b } else { b };
            let o = ordered.checked_add(steps)?;
            let o = i32::try_from(o).ok()?;
            let bits = if o < 0 { i32::MIN.wrapping_sub(o) } else { o };
            f64::from(f32::from_bits(bits as u32))
        }
    };
    y.is_finite().then_some(y)
}

impl Space {
    /// Numbers per row given to the target.
    pub fn width(&self) -> usize {
        if self.cartesian { self.m } else { self.m + 1 }
    }

    /// The geometry of `net` (rounded to `f64`) for rows of `precision`.
    pub fn new(
        precision: Precision,
        net: ControlNet<f64>,
        vertices: Vec<Vec<f64>>,
        inverse: Vec<Vec<f64>>,
        domain: Domain,
        cartesian: bool,
    ) -> Space {
        let (m, n) = (net.m(), net.degree());
        let points = net
            .points()
            .flat_map(|c| c.iter().copied().chain(c.iter().map(|x| x.abs())))
            .collect();
        let stencils = (1..=n)
            .rev()
            .map(|l| Simplex::new(m, l).step_stencil())
            .collect();
        Space {
            precision,
            m,
            net,
            points,
            stencils,
            vertices,
            inverse,
            domain,
            cartesian,
        }
    }

    /// The value of the patch at `λ` in `f64`, and `Σ|c_i| B_i(λ)`, by de Casteljau on the
    /// control points and their absolute values together: at each step
    /// `b_β ← Σ_k λ_k b_{β+e_k}` over the indices `β` of one degree less.
    pub fn value_and_scale(&self, lambda: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let w = 2 * self.net.dim();
        let mut from = self.points.clone();
        let mut to = vec![0.0; from.len()];
        for stencil in &self.stencils {
            for (beta, parents) in stencil.chunks_exact(self.m + 1).enumerate() {
                let out = &mut to[beta * w..(beta + 1) * w];
                out.fill(0.0);
                for (&l, &r) in lambda.iter().zip(parents) {
                    for (o, &b) in out.iter_mut().zip(&from[r * w..(r + 1) * w]) {
                        *o += l * b;
                    }
                }
            }
            std::mem::swap(&mut from, &mut to);
        }
        let d = self.net.dim();
        (from[..d].to_vec(), from[d..w].to_vec())
    }

    /// The largest condition number over the value's coordinates at `λ`, in `f64` (an estimate
    /// used to rank candidates, never to judge).
    pub fn condition(&self, lambda: &[f64]) -> f64 {
        let (v, s) = self.value_and_scale(lambda);
        v.iter()
            .zip(&s)
            .map(|(v, s)| if *s == 0.0 { 0.0 } else { s / v.abs() })
            .fold(0.0, f64::max)
    }

    /// The Cartesian point of barycentric coordinates `λ`, in `f64`.
    pub fn to_cartesian(&self, lambda: &[f64]) -> Vec<f64> {
        (0..self.m)
            .map(|j| {
                lambda
                    .iter()
                    .zip(&self.vertices)
                    .map(|(l, v)| l * v[j])
                    .sum()
            })
            .collect()
    }

    /// The barycentric coordinates of a Cartesian point, in `f64`.
    pub fn to_barycentric(&self, x: &[f64]) -> Vec<f64> {
        let last = &self.vertices[self.m];
        let d: Vec<f64> = x.iter().zip(last).map(|(a, b)| a - b).collect();
        let mut lambda: Vec<f64> = self
            .inverse
            .iter()
            .map(|row| row.iter().zip(&d).map(|(a, b)| a * b).sum())
            .collect();
        let rest = 1.0 - lambda.iter().sum::<f64>();
        lambda.push(rest);
        lambda
    }

    /// The row given to the target for the (unrounded) barycentric point `λ`: rounded to the
    /// precision and made consistent (barycentric), or its Cartesian point rounded. `None` when
    /// that leaves the domain.
    pub fn row_of(&self, lambda: &[f64]) -> Option<Vec<f64>> {
        if self.cartesian {
            let x: Vec<f64> = self
                .to_cartesian(lambda)
                .into_iter()
                .map(|x| round(self.precision, x))
                .collect();
            self.inside_cartesian(&x).then_some(x)
        } else {
            let mut row: Vec<f64> = lambda.iter().map(|&l| round(self.precision, l)).collect();
            let keep = usize::MAX;
            self.consistent(&mut row, keep).then_some(row)
        }
    }

    /// Set the largest coordinate other than `keep` to the float nearest `1 − Σ others`
    /// (computed in `f64`, then rounded to the precision); false when that is negative or any
    /// coordinate is negative or not finite.
    pub fn consistent(&self, row: &mut [f64], keep: usize) -> bool {
        let Some(a) = (0..row.len())
            .filter(|&i| i != keep)
            .max_by(|&i, &j| row[i].total_cmp(&row[j]).then(j.cmp(&i)))
        else {
            return false;
        };
        let others: f64 = row
            .iter()
            .enumerate()
            .filter(|&(i, _)| i != a)
            .map(|(_, x)| x)
            .sum();
        row[a] = round(self.precision, 1.0 - others);
        row.iter().all(|x| x.is_finite() && *x >= 0.0)
    }

    /// A Cartesian point inside the closed domain: its exact barycentric coordinates (Cramer's
    /// rule on the float point's exact value) are all at least 0. Points whose barycentric
    /// coordinates in `f64` are negative are refused first, without exact arithmetic (such a
    /// point may be inside by a hair: refusing it only costs the sampler a candidate).
    pub fn inside_cartesian(&self, x: &[f64]) -> bool {
        if !(x.iter().all(|v| v.is_finite()) && self.to_barycentric(x).iter().all(|&l| l >= 0.0)) {
            return false;
        }
        let exact: Option<Vec<_>> = x.iter().map(|&v| crate::number::exact_f64(v)).collect();
        exact
            .and_then(|x| self.domain.barycentric(&x).ok())
            .is_some_and(|l| l.iter().all(|l| !num_traits::Signed::is_negative(l)))
    }
}

/// The kinds of sample of the places floats fail (see the module documentation).
const SPECIAL_KINDS: u64 = 8;

/// A random scale `2^-k · r`, `r` uniform in `[1, 2)`, `k` uniform in `1..=kmax` (`kmax`: 64
/// for `f64`, 40 for `f32`: the coordinates a program meets near an edge, below its precision
/// too).
fn tiny(r: &mut SplitMix, p: Precision) -> f64 {
    let kmax = match p {
        Precision::F64 => 64,
        Precision::F32 => 40,
    };
    let k = 1 + (r.next_u64() % kmax) as i32;
    (1.0 + r.unit()) * 2f64.powi(-k)
}

/// A uniform point of the simplex with `n` coordinates (normalised exponentials).
pub(super) fn uniform(r: &mut SplitMix, n: usize) -> Vec<f64> {
    let mut e: Vec<f64> = (0..n).map(|_| -(1.0 - r.unit()).ln()).collect();
    let s: f64 = e.iter().sum();
    if s > 0.0 {
        for x in &mut e {
            *x /= s;
        }
    } else {
        e[0] = 1.0;
    }
    e
}

impl Space {
    /// A uniform random row of the domain.
    pub fn uniform_row(&self, r: &mut SplitMix) -> Vec<f64> {
        loop {
            if let Some(row) = self.row_of(&uniform(r, self.m + 1)) {
                return row;
            }
        }
    }

    /// A row at a place where floats fail (one of [`SPECIAL_KINDS`] kinds, chosen at random).
    pub fn special_row(&self, r: &mut SplitMix) -> Vec<f64> {
        for _ in 0..64 {
            let lambda = self.special_lambda(r);
            if let Some(row) = self.row_of(&lambda) {
                return row;
            }
        }
        self.uniform_row(r)
    }

    fn special_lambda(&self, r: &mut SplitMix) -> Vec<f64> {
        let n = self.m + 1;
        let p = self.precision;
        let j = (r.next_u64() % n as u64) as usize;
        let spread = |r: &mut SplitMix, mass: f64, skip: &[usize]| -> Vec<f64> {
            let rest = uniform(r, n);
            let kept: f64 = (0..n).filter(|i| !skip.contains(i)).map(|i| rest[i]).sum();
            (0..n)
                .map(|i| {
                    if skip.contains(&i) || kept == 0.0 {
                        0.0
                    } else {
                        mass * rest[i] / kept
                    }
                })
                .collect()
        };
        match r.next_u64() % SPECIAL_KINDS {
            // a corner, or a point a tiny distance from one
            0 => {
                let t = if r.next_u64().is_multiple_of(4) {
                    0.0
                } else {
                    tiny(r, p)
                };
                let mut l = spread(r, t, &[j]);
                l[j] = 1.0 - t;
                l
            }
            // on an edge (one coordinate exactly 0)
            1 => spread(r, 1.0, &[j]),
            // near an edge: one coordinate `2^-k · r`
            2 | 3 => {
                let t = tiny(r, p);
                let mut l = spread(r, 1.0 - t, &[j]);
                l[j] = t;
                l
            }
            // near a corner along two edges: two tiny coordinates
            4 if n > 2 => {
                let k = (j + 1 + (r.next_u64() % (n as u64 - 1)) as usize) % n;
                let (s, t) = (tiny(r, p), tiny(r, p));
                let mut l = spread(r, 1.0 - s - t, &[j, k]);
                l[j] = s;
                l[k] = t;
                l
            }
            // a binade boundary: one coordinate `2^-k` moved by a few floats
            5 => {
                let k = 1 + (r.next_u64() % 60) as i32;
                let steps = (r.next_u64() % 9) as i64 - 4;
                let t = step(p, 2f64.powi(-k), steps).unwrap_or(0.0);
                let mut l = spread(r, 1.0 - t, &[j]);
                l[j] = t;
                l
            }
            // near a zero of a coordinate of the value
            6 => self.near_zero(r).unwrap_or_else(|| self.high_condition(r)),
            // the largest condition number among a few candidates
            _ => self.high_condition(r),
        }
    }

    /// A point where a coordinate of the value changes sign along the segment between two
    /// random points (found by bisection in `f64`), or `None` if no coordinate changes sign
    /// along a few segments.
    fn near_zero(&self, r: &mut SplitMix) -> Option<Vec<f64>> {
        let n = self.m + 1;
        for _ in 0..4 {
            let a = if r.next_u64().is_multiple_of(2) {
                uniform(r, n)
            } else {
                self.special_edge(r)
            };
            let b = uniform(r, n);
            let (va, _) = self.value_and_scale(&a);
            let (vb, _) = self.value_and_scale(&b);
            let Some(c) = (0..va.len()).find(|&c| va[c] * vb[c] < 0.0) else {
                continue;
            };
            let (mut lo, mut hi) = (0.0f64, 1.0f64);
            let at =
                |t: f64| -> Vec<f64> { a.iter().zip(&b).map(|(x, y)| x + t * (y - x)).collect() };
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                let (vm, _) = self.value_and_scale(&at(mid));
                if (vm[c] < 0.0) == (va[c] < 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return Some(at(if r.next_u64().is_multiple_of(2) {
                lo
            } else {
                hi
            }));
        }
        None
    }

    /// A point near an edge (for [`Self::near_zero`]'s segments).
    fn special_edge(&self, r: &mut SplitMix) -> Vec<f64> {
        let n = self.m + 1;
        let j = (r.next_u64() % n as u64) as usize;
        let t = tiny(r, self.precision);
        let mut l = uniform(r, n);
        let s: f64 = (0..n).filter(|&i| i != j).map(|i| l[i]).sum();
        for (i, x) in l.iter_mut().enumerate() {
            *x = if i == j { t } else { *x * (1.0 - t) / s };
        }
        l
    }

    /// The candidate of largest condition number among 16 (uniform and near-edge points).
    fn high_condition(&self, r: &mut SplitMix) -> Vec<f64> {
        let mut best = (f64::NEG_INFINITY, uniform(r, self.m + 1));
        for i in 0..16 {
            let l = if i % 2 == 0 {
                uniform(r, self.m + 1)
            } else {
                self.special_edge(r)
            };
            let c = self.condition(&l);
            let c = if c.is_nan() { f64::INFINITY } else { c };
            if c > best.0 {
                best = (c, l);
            }
        }
        best.1
    }

    /// A move of one coordinate of `row` by `±2^k` floats (`k` uniform in `0..=max_shift`),
    /// kept consistent (barycentric) or inside the domain (Cartesian); `None` when the move
    /// leaves it.
    pub fn local_move(&self, r: &mut SplitMix, row: &[f64]) -> Option<Vec<f64>> {
        let w = row.len();
        let j = (r.next_u64() % w as u64) as usize;
        let k = (r.next_u64() % u64::from(max_shift(self.precision) + 1)) as u32;
        let sign = if r.next_u64().is_multiple_of(2) {
            1
        } else {
            -1
        };
        let mut out = row.to_vec();
        out[j] = step(self.precision, row[j], sign * (1i64 << k))?;
        if self.cartesian {
            self.inside_cartesian(&out).then_some(out)
        } else {
            if out[j] < 0.0 || out[j] > 1.0 {
                return None;
            }
            self.consistent(&mut out, j).then_some(out)
        }
    }
}
