//! The floating-point paths that tribez certifies: the same generic algorithms run in `f64` and
//! `f32`, plus `glam` kernels for points in `ℝ³` (the layout a GPU shader uses).
//!
//! Rounding the exact control points to floats is correctly rounded (never through f64 for f32).
//! The glam kernels perform exactly the operations of the generic de Casteljau, in the same
//! order (`((λ_0 x_0 + λ_1 x_1) + λ_2 x_2)` per coordinate, no FMA), so they give bit-identical
//! results; a test checks it.

use glam::{DVec3, Vec3};
use num_rational::BigRational;

use crate::number::{round_f32, round_f64};
use crate::patch::ControlNet;

/// Floating-point precision of a path or of a claimed value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Precision {
    /// IEEE binary64.
    F64,
    /// IEEE binary32 (what a shader computes).
    F32,
}

impl Precision {
    /// `"f64"` or `"f32"`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::F64 => "f64",
            Precision::F32 => "f32",
        }
    }

    /// Unit roundoff `ε`: `2^-53` or `2^-24`, as the exponent.
    pub fn unit_roundoff_log2(self) -> i32 {
        match self {
            Precision::F64 => -53,
            Precision::F32 => -24,
        }
    }
}

/// A text that is not a precision (`"f64"` or `"f32"`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown precision `{text}` (expected f64 or f32)")]
pub struct ParsePrecisionError {
    /// The text.
    pub text: String,
}

/// `"f64"` or `"f32"`, exactly (the strings of the command line and of claim files), and
/// [`Display`](std::fmt::Display) writes them back.
///
/// ```
/// use tribez::Precision;
/// assert_eq!("f32".parse::<Precision>().unwrap(), Precision::F32);
/// assert_eq!(Precision::F64.to_string(), "f64");
/// assert_eq!(
///     "f16".parse::<Precision>().unwrap_err().to_string(),
///     "unknown precision `f16` (expected f64 or f32)"
/// );
/// ```
impl std::str::FromStr for Precision {
    type Err = ParsePrecisionError;
    fn from_str(s: &str) -> Result<Self, ParsePrecisionError> {
        match s {
            "f64" => Ok(Precision::F64),
            "f32" => Ok(Precision::F32),
            _ => Err(ParsePrecisionError { text: s.into() }),
        }
    }
}

impl std::fmt::Display for Precision {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The control net rounded to the nearest f64, coordinate by coordinate.
pub fn net_f64(net: &ControlNet<BigRational>) -> ControlNet<f64> {
    net.map(round_f64)
}

/// The control net rounded directly to the nearest f32.
pub fn net_f32(net: &ControlNet<BigRational>) -> ControlNet<f32> {
    net.map(round_f32)
}

macro_rules! glam_casteljau {
    ($name:ident, $vec:ty, $s:ty) => {
        /// de Casteljau on a triangle with points in `ℝ³`, same operation order as the generic
        /// code. `points` in canonical order (`(n+1)(n+2)/2` of them). The pyramid runs in place
        /// in one buffer (on the stack up to degree 20).
        pub fn $name(points: &[$vec], n: usize, u: [$s; 3]) -> $vec {
            let len = (n + 1) * (n + 2) / 2;
            assert_eq!(
                points.len(),
                len,
                "control net size does not match the degree"
            );
            fn run(level: &mut [$vec], n: usize, u: [$s; 3]) -> $vec {
                for q in (1..=n).rev() {
                    // level has degree q; child ranks of β = (i, j, k) at degree q - 1 are
                    // rank_q(i+1, j, k) = base + j, rank_q(i, j+1, k) = base + j + 1 and
                    // rank_q(i, j, k+1) = base_next + j, with base = rank_q(q-k, 0, k); β's own
                    // rank at degree q − 1 is base − k + j, never after a node still to be read.
                    for k in 0..q {
                        let base = k * (2 * q + 3 - k) / 2;
                        let base_next = base + q + 1 - k;
                        for j in 0..q - k {
                            let a = level[base + j];
                            let b = level[base + j + 1];
                            let c = level[base_next + j];
                            level[base - k + j] = a * u[0] + b * u[1] + c * u[2];
                        }
                    }
                }
                level[0]
            }
            macro_rules! on_stack {
                ($cap:expr) => {{
                    let mut buf = [<$vec>::ZERO; $cap];
                    buf[..len].copy_from_slice(points);
                    run(&mut buf[..len], n, u)
                }};
            }
            match n {
                0..=4 => on_stack!(15),
                5..=10 => on_stack!(66),
                11..=20 => on_stack!(231),
                _ => run(&mut points.to_vec(), n, u),
            }
        }
    };
}

glam_casteljau!(casteljau_dvec3, DVec3, f64);
glam_casteljau!(casteljau_vec3, Vec3, f32);

macro_rules! glam_horner {
    ($name:ident, $prep:ident, $vec:ty, $s:ty) => {
        /// The Bernstein form `Σ_α s_α u^i v^j w^k` of a triangle by nested Horner, the scheme of
        /// the exact kernel (and of `bezier`'s `evaluate_barycentric_multi`): per row `k`,
        /// `t ← t·u + s_{(i,j,k)} v^j` for `j = 1..n−k`, and across rows `acc ← acc·w + t_k`
        /// for `k = n−1..0`. `scaled` are the multinomial-scaled points of the prepare function,
        /// in canonical order.
        ///
        /// Error: every term `s_α u^i v^j w^k` passes through at most `2n + 5` roundings (two for
        /// `C(n;α)·c_α` when the multinomial is not representable, `j − 1` for `v^j`, one for the
        /// product, `1 + 2(n−k−j)` in its row, `1 + 2k` across rows), so
        /// `|computed − p(λ)| ≤ γ_{2n+5} Σ_α |c_α| B_α(|λ|)` (docs/theory.md §14), with `p` evaluated
        /// exactly at the float inputs; a test checks it.
        pub fn $name(scaled: &[$vec], n: usize, u: [$s; 3]) -> $vec {
            debug_assert_eq!(scaled.len(), (n + 1) * (n + 2) / 2);
            let mut acc = scaled[scaled.len() - 1];
            for k in (0..n).rev() {
                let base = k * (2 * n + 3 - k) / 2;
                let mut t = scaled[base];
                let mut vp: $s = 1.0;
                for j in 1..=n - k {
                    vp *= u[1];
                    t = t * u[0] + scaled[base + j] * vp;
                }
                acc = acc * u[2] + t;
            }
            acc
        }

        /// The points `C(n;α) c_α` (rounded once, the multinomial rounded first if it is not
        /// representable) for the Horner kernel, from a `d = 3` triangle net.
        pub fn $prep(net: &ControlNet<$s>) -> Vec<$vec> {
            assert_eq!(net.m(), 2, "the glam kernels are for triangles");
            net.entries()
                .map(|(alpha, p)| {
                    let c = <$s as crate::scalar::Scalar>::from_biguint(
                        &crate::simplex::multinomial(alpha),
                    );
                    <$vec>::new(p[0], p[1], p[2]) * c
                })
                .collect()
        }
    };
}

glam_horner!(horner_dvec3, horner_points_dvec3, DVec3, f64);
glam_horner!(horner_vec3, horner_points_vec3, Vec3, f32);

macro_rules! glam_horner_many {
    ($name:ident, $single:ident, $vec:ty, $s:ty) => {
        /// [`
        #[doc = stringify!($single)]
        /// `] at many points (the batch form, like `bezier`'s `evaluate_barycentric_multi`): four
        /// points run interleaved to hide the latency of the Horner chains; each point performs
        /// exactly the operations of the single-point kernel, so the results are bit-identical.
        pub fn $name(scaled: &[$vec], n: usize, points: &[[$s; 3]], out: &mut Vec<$vec>) {
            const W: usize = 4;
            out.clear();
            out.reserve(points.len());
            let mut chunks = points.chunks_exact(W);
            for u in &mut chunks {
                let mut acc = [scaled[scaled.len() - 1]; W];
                for k in (0..n).rev() {
                    let base = k * (2 * n + 3 - k) / 2;
                    let mut t = [scaled[base]; W];
                    let mut vp: [$s; W] = [1.0; W];
                    for j in 1..=n - k {
                        let c = scaled[base + j];
                        for l in 0..W {
                            vp[l] *= u[l][1];
                            t[l] = t[l] * u[l][0] + c * vp[l];
                        }
                    }
                    for l in 0..W {
                        acc[l] = acc[l] * u[l][2] + t[l];
                    }
                }
                out.extend_from_slice(&acc);
            }
            for &u in chunks.remainder() {
                out.push($single(scaled, n, u));
            }
        }
    };
}

glam_horner_many!(horner_dvec3_many, horner_dvec3, DVec3, f64);
glam_horner_many!(horner_vec3_many, horner_vec3, Vec3, f32);

/// Points of a `d = 3` net as glam `DVec3`.
pub fn dvec3_points(net: &ControlNet<f64>) -> Vec<DVec3> {
    net.points().map(|p| DVec3::new(p[0], p[1], p[2])).collect()
}

/// Points of a `d = 3` net as glam `Vec3`.
pub fn vec3_points(net: &ControlNet<f32>) -> Vec<Vec3> {
    net.points().map(|p| Vec3::new(p[0], p[1], p[2])).collect()
}

/// A machine float that tribez can round to, convert exactly, and judge in ULPs.
pub trait Float: crate::scalar::Scalar + Copy + PartialOrd + Send + Sync + 'static {
    /// Its precision.
    const PRECISION: Precision;
    /// The float nearest `q` (ties to even), computed from `q` directly.
    fn round(q: &BigRational) -> Self;
    /// Its exact value (`None` for NaN and infinities).
    fn exact(self) -> Option<BigRational>;
    /// C99 hex-float text.
    fn hex(self) -> String;
    /// Shortest round-trip decimal text.
    fn decimal(self) -> String;
    /// `|x − q| / ulp(q)` exactly, for `x` the exact value of a float of this precision.
    fn ulps(x: &BigRational, q: &BigRational) -> BigRational;
    /// Is this finite?
    fn finite(self) -> bool;
    /// As f64 (exact widening).
    fn widen(self) -> f64;
    /// de Casteljau through the glam kernel, for a triangle with points in R³ (`None` otherwise).
    fn casteljau_glam(net: &ControlNet<Self>, lambda: &[Self]) -> Option<Vec<Self>>;
}

impl Float for f64 {
    const PRECISION: Precision = Precision::F64;
    fn round(q: &BigRational) -> Self {
        round_f64(q)
    }
    fn exact(self) -> Option<BigRational> {
        crate::number::exact_f64(self)
    }
    fn hex(self) -> String {
        crate::number::hex_f64(self)
    }
    fn decimal(self) -> String {
        crate::number::display_f64(self)
    }
    fn ulps(x: &BigRational, q: &BigRational) -> BigRational {
        crate::number::ulps_error_f64(x, q)
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
    fn widen(self) -> f64 {
        self
    }
    fn casteljau_glam(net: &ControlNet<Self>, lambda: &[Self]) -> Option<Vec<Self>> {
        (net.m() == 2 && net.dim() == 3).then(|| {
            let p = casteljau_dvec3(
                &dvec3_points(net),
                net.degree(),
                [lambda[0], lambda[1], lambda[2]],
            );
            vec![p.x, p.y, p.z]
        })
    }
}

impl Float for f32 {
    const PRECISION: Precision = Precision::F32;
    fn round(q: &BigRational) -> Self {
        round_f32(q)
    }
    fn exact(self) -> Option<BigRational> {
        crate::number::exact_f32(self)
    }
    fn hex(self) -> String {
        crate::number::hex_f32(self)
    }
    fn decimal(self) -> String {
        crate::number::display_f32(self)
    }
    fn ulps(x: &BigRational, q: &BigRational) -> BigRational {
        crate::number::ulps_error_f32(x, q)
    }
    fn finite(self) -> bool {
        self.is_finite()
    }
    fn widen(self) -> f64 {
        f64::from(self)
    }
    fn casteljau_glam(net: &ControlNet<Self>, lambda: &[Self]) -> Option<Vec<Self>> {
        (net.m() == 2 && net.dim() == 3).then(|| {
            let p = casteljau_vec3(
                &vec3_points(net),
                net.degree(),
                [lambda[0], lambda[1], lambda[2]],
            );
            vec![p.x, p.y, p.z]
        })
    }
}

/// de Casteljau in floating point: the glam kernel for triangles in R³ (bit-identical to the
/// generic code, which runs otherwise).
pub fn casteljau<F: Float>(net: &ControlNet<F>, lambda: &[F]) -> Vec<F> {
    F::casteljau_glam(net, lambda).unwrap_or_else(|| crate::casteljau::evaluate(net, lambda))
}

/// The control net rounded to the float type `F`.
pub fn net_to<F: Float>(net: &ControlNet<BigRational>) -> ControlNet<F> {
    net.map(F::round)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::casteljau;
    use crate::number::parse_rational;
    use crate::simplex::Simplex;

    fn pseudo_random_net(n: usize, seed: u64) -> ControlNet<BigRational> {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 33) as i64 % 2001 - 1000
        };
        let simplex = Simplex::new(2, n);
        let coords = (0..simplex.len() * 3)
            .map(|_| BigRational::new(next().into(), (next().abs() + 1).into()))
            .collect();
        ControlNet::new(simplex, 3, coords)
    }

    /// `γ_k = k u / (1 − k u)` exactly.
    fn gamma(k: usize, p: Precision) -> BigRational {
        let u = crate::number::pow2(i64::from(p.unit_roundoff_log2()));
        let ku = &u * BigRational::from_integer(k.into());
        &ku / (BigRational::from_integer(1.into()) - &ku)
    }

    fn check_horner<F: Float>(
        net: &ControlNet<BigRational>,
        u: &[BigRational; 3],
        computed: [F; 3],
    ) {
        let fnet: ControlNet<F> = net_to(net);
        let exact_net = fnet.map(|x| x.exact().unwrap());
        let lam: Vec<BigRational> = u.iter().map(|x| F::round(x).exact().unwrap()).collect();
        let exact =
            crate::exact::evaluate_rational(&exact_net, &lam, crate::exact::Algorithm::Bernstein);
        let abs_lam: Vec<BigRational> = lam.iter().map(num_traits::Signed::abs).collect();
        let basis = crate::bernstein::basis(net.simplex(), &abs_lam);
        let g = gamma(2 * net.degree() + 5, F::PRECISION);
        for c in 0..3 {
            let bound: BigRational = basis
                .iter()
                .zip(exact_net.points())
                .map(|(b, p)| b * num_traits::Signed::abs(&p[c]))
                .sum::<BigRational>()
                * &g;
            let err = num_traits::Signed::abs(&(computed[c].exact().unwrap() - &exact[c]));
            assert!(
                err <= bound,
                "n = {}: error {err} above the bound {bound}",
                net.degree()
            );
        }
    }

    #[test]
    fn horner_kernels_are_within_the_a_priori_bound() {
        for n in [0, 1, 2, 3, 7, 12, 20, 30] {
            let net = pseudo_random_net(n, n as u64 + 11);
            for u in [
                ["0.2", "0.7", "0.1"],
                ["1/3", "1/3", "1/3"],
                ["0.9", "0.0625", "0.0375"],
                ["0", "0", "1"],
            ] {
                let u = u.map(|t| parse_rational(t).unwrap());
                let s64 = horner_points_dvec3(&net_f64(&net));
                let v = horner_dvec3(&s64, n, [0, 1, 2].map(|k| round_f64(&u[k])));
                check_horner::<f64>(&net, &u, [v.x, v.y, v.z]);
                let s32 = horner_points_vec3(&net_f32(&net));
                let v = horner_vec3(&s32, n, [0, 1, 2].map(|k| round_f32(&u[k])));
                check_horner::<f32>(&net, &u, [v.x, v.y, v.z]);
            }
        }
    }

    #[test]
    fn batch_horner_is_bit_identical_to_the_single_point_kernel() {
        for n in [0, 1, 5, 13] {
            let net = pseudo_random_net(n, n as u64 + 3);
            let pts: Vec<[f64; 3]> = (0..11)
                .map(|i| {
                    let a = i as f64 / 13.0;
                    let b = (1.0 - a) / 3.0;
                    [1.0 - a - b, a, b]
                })
                .collect();
            let s64 = horner_points_dvec3(&net_f64(&net));
            let mut out = Vec::new();
            horner_dvec3_many(&s64, n, &pts, &mut out);
            assert_eq!(
                out,
                pts.iter()
                    .map(|&u| horner_dvec3(&s64, n, u))
                    .collect::<Vec<_>>()
            );
            let p32: Vec<[f32; 3]> = pts.iter().map(|p| p.map(|x| x as f32)).collect();
            let s32 = horner_points_vec3(&net_f32(&net));
            let mut out = Vec::new();
            horner_vec3_many(&s32, n, &p32, &mut out);
            assert_eq!(
                out,
                p32.iter()
                    .map(|&u| horner_vec3(&s32, n, u))
                    .collect::<Vec<_>>()
            );
        }
    }

    #[test]
    fn glam_kernels_are_bit_identical_to_the_generic_code() {
        // every buffer size of the kernel: the stack arrays (n ≤ 4, ≤ 10, ≤ 20) and the heap
        for n in [0, 1, 2, 3, 4, 5, 7, 10, 12, 20, 21, 25] {
            let net = pseudo_random_net(n, n as u64 + 7);
            let u = ["0.2", "0.7", "0.1"].map(|t| parse_rational(t).unwrap());
            let n64 = net_f64(&net);
            let u64_: Vec<f64> = u.iter().map(round_f64).collect();
            let generic = casteljau::evaluate(&n64, &u64_);
            let fast = casteljau_dvec3(&dvec3_points(&n64), n, [u64_[0], u64_[1], u64_[2]]);
            assert_eq!(generic, vec![fast.x, fast.y, fast.z]);
            let n32 = net_f32(&net);
            let u32_: Vec<f32> = u.iter().map(round_f32).collect();
            let generic = casteljau::evaluate(&n32, &u32_);
            let fast = casteljau_vec3(&vec3_points(&n32), n, [u32_[0], u32_[1], u32_[2]]);
            assert_eq!(generic, vec![fast.x, fast.y, fast.z]);
        }
    }
}
