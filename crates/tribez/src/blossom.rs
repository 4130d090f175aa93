//! Blossoms and subpatches over any simplex (docs/theory.md §4, §11).
//!
//! The blossom `b[x_1, …, x_n]` is de Casteljau run with a different argument at each level
//! ([`crate::casteljau::blossom`]). The same polynomial over the simplex with vertices
//! `f_0, …, f_m` (each a barycentric point of the parent's domain; they may lie outside it) has
//! control points
//!
//! `c′_α = b[f_0^{α_0}, f_1^{α_1}, …, f_m^{α_m}]`,  `|α| = n`  (`x^r`: `x` repeated `r` times),
//!
//! and then `p′(β) = p(β_0 f_0 + … + β_m f_m)`. Index convention: slot `k` of `α` belongs to
//! vertex `f_k`, canonical order of [`crate::simplex`].
//!
//! [`subpatch`] computes all of them with `m + 1` de Casteljau pyramids at most (one per vertex
//! that differs from the parent's), by exchanging one vertex at a time: the pyramid of the net
//! over `[g_0, …, g_m]` at a point `x = Σ λ_t g_t` holds `b[x^r, g^β]` at level `r`, and its face
//! with slot `t` zero is the net over the simplex with `g_t` replaced by `x` (§5.1).
//! [`subpatch_by_blossoms`] is the definition itself, one blossom per control point, for any
//! vertices (also affinely dependent ones).
//!
//! ```
//! use tribez::hazmat::blossom::subpatch;
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::ControlNet;
//! let r = |v: &[&str]| v.iter().map(|s| q(s).unwrap()).collect::<Vec<_>>();
//! // Finn's net; the half [a1, (1/2,1/2,0), a3] of docs/theory.md §5.2
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let net = ControlNet::from_points(2, 2, &pts);
//! let half = subpatch(&net, &[r(&["1", "0", "0"]), r(&["1/2", "1/2", "0"]), r(&["0", "0", "1"])]).unwrap();
//! let s = |p: &[num_rational::BigRational]| p.iter().map(|x| x.to_string()).collect::<Vec<_>>();
//! assert_eq!(s(half.at(&[0, 2, 0])), ["1/2", "1/2", "1"]);
//! assert_eq!(s(half.at(&[0, 1, 1])), ["1/2", "1", "1/2"]);
//! ```

use std::ops::Div;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::casteljau::{self, levels};
use crate::error::CoreError;
use crate::patch::ControlNet;
use crate::scalar::{Scalar, cast, downcast_ref};
use crate::simplex::{self, Simplex};

/// A [`Scalar`] with division: the exact rationals and the machine floats (not `BigInt`).
pub trait Field: Scalar + Div<Output = Self> + for<'a> Div<&'a Self, Output = Self> {}
impl<T: Scalar + Div<Output = T> + for<'a> Div<&'a T, Output = T>> Field for T {}

/// The blossom `b[x_1, …, x_n]`, checking that there are exactly `n` arguments of `m + 1`
/// coordinates each (the arguments may be any points, also homogeneous ones).
pub fn blossom<T: Scalar>(net: &ControlNet<T>, args: &[Vec<T>]) -> Result<Vec<T>, CoreError> {
    if args.len() != net.degree() {
        return Err(CoreError::BlossomArity {
            degree: net.degree(),
            found: args.len(),
        });
    }
    for (i, a) in args.iter().enumerate() {
        if a.len() != net.m() + 1 {
            return Err(CoreError::WrongLength {
                what: format!("blossom argument {}", i + 1),
                expected: net.m() + 1,
                found: a.len(),
            });
        }
    }
    let refs: Vec<&[T]> = args.iter().map(Vec::as_slice).collect();
    Ok(casteljau::blossom(net, &refs))
}

/// The face of a de Casteljau pyramid (`levels[r]` of degree `n − r`) with slot `s` zero:
/// `d_α = c^{α_s}_{α with α_s set to 0}` (docs/theory.md §5.1, §11). If the pyramid was built at
/// `x`, this is the net over the parent simplex with vertex `s` replaced by `x`.
pub fn pyramid_face<T: Scalar>(levels: &[ControlNet<T>], s: usize) -> ControlNet<T> {
    let top = &levels[0];
    let (m, n, dim) = (top.m(), top.degree(), top.dim());
    let sx = Simplex::new(m, n);
    let mut coords = Vec::with_capacity(sx.len() * dim);
    let mut beta = vec![0u32; m + 1];
    for alpha in sx.iter() {
        beta.copy_from_slice(alpha);
        let r = beta[s] as usize;
        beta[s] = 0;
        coords.extend_from_slice(levels[r].point(simplex::rank(&beta)));
    }
    ControlNet::new(sx, dim, coords)
}

/// Barycentric coordinates of `x` with respect to the points `g` (all given in the same
/// barycentric coordinates): solves `Σ_t λ_t g_t = x`. `None` if the `g` are dependent.
pub fn coordinates_in<T: Field>(g: &[Vec<T>], x: &[T]) -> Option<Vec<T>> {
    let k = g.len();
    // Augmented matrix A λ = x with A[i][t] = g_t[i].
    let mut a: Vec<Vec<T>> = (0..k)
        .map(|i| {
            (0..k)
                .map(|t| g[t][i].clone())
                .chain([x[i].clone()])
                .collect()
        })
        .collect();
    for col in 0..k {
        let p = (col..k).find(|&r| !a[r][col].is_zero())?;
        a.swap(col, p);
        let pivot = a[col][col].clone();
        for x in a[col].iter_mut().skip(col) {
            *x = x.clone() / &pivot;
        }
        let prow = a[col].clone();
        for (r, row) in a.iter_mut().enumerate() {
            if r != col && !row[col].is_zero() {
                let f = row[col].clone();
                for (x, p) in row.iter_mut().zip(&prow).skip(col) {
                    *x = x.clone() - f.clone() * p;
                }
            }
        }
    }
    Some(a.into_iter().map(|row| row[k].clone()).collect())
}

fn unit<T: Scalar>(m: usize, k: usize) -> Vec<T> {
    (0..=m)
        .map(|i| if i == k { T::one() } else { T::zero() })
        .collect()
}

/// The vertex exchanges that turn the parent simplex into `[f_0, …, f_m]`: each step replaces
/// the vertex in slot `t` by the point with coordinates `λ` in the current simplex; at the end,
/// slot `slot_of[s]` holds `f_s`. An error if the `f` are affinely dependent.
struct Plan<T> {
    steps: Vec<(Vec<T>, usize)>,
    slot_of: Vec<usize>,
}

fn plan<T: Field>(f: &[Vec<T>], m: usize) -> Result<Plan<T>, CoreError> {
    check_vertices(f, m)?;
    let mut g: Vec<Vec<T>> = (0..=m).map(|k| unit(m, k)).collect();
    let mut held = vec![false; m + 1];
    let mut slot_of = vec![0usize; m + 1];
    let mut steps = Vec::new();
    for s in 0..=m {
        if !held[s] && f[s] == g[s] {
            held[s] = true;
            slot_of[s] = s;
            continue;
        }
        // invariant: g starts as the unit simplex and each step replaces slot t only where λ_t ≠ 0 (the exchange lemma), so g stays non-degenerate and coordinates_in answers; f's lengths were checked by check_vertices
        let lambda = coordinates_in(&g, &f[s]).expect("the current simplex is non-degenerate");
        let free = |t: usize| !held[t] && !lambda[t].is_zero();
        let t = if free(s) {
            s
        } else {
            (0..=m)
                .find(|&t| free(t))
                .ok_or_else(|| CoreError::DegenerateDomain("of the sub-simplex".into()))?
        };
        steps.push((lambda, t));
        g[t] = f[s].clone();
        held[t] = true;
        slot_of[s] = t;
    }
    Ok(Plan { steps, slot_of })
}

/// Relabel the slots: the result's slot `s` is `net`'s slot `slot_of[s]`.
fn permute<T: Clone>(net: ControlNet<T>, slot_of: &[usize]) -> ControlNet<T> {
    if slot_of.iter().enumerate().all(|(s, &t)| s == t) {
        return net;
    }
    let sx = net.simplex().clone();
    let mut gamma = vec![0u32; sx.dimension() + 1];
    let mut coords = Vec::with_capacity(net.coords().len());
    for alpha in sx.iter() {
        for (s, &t) in slot_of.iter().enumerate() {
            gamma[t] = alpha[s];
        }
        coords.extend_from_slice(net.at(&gamma));
    }
    ControlNet::new(sx, net.dim(), coords)
}

/// The net of the same polynomial over the simplex `[f_0, …, f_m]` (barycentric points of the
/// parent; any, also outside): `c′_α = b[f_0^{α_0}, …, f_m^{α_m}]`. Needs affinely independent
/// vertices; computed with one de Casteljau pyramid per vertex that is not already the parent's
/// vertex in its slot. Generic (floats too). For exact rationals the pyramids run on integers
/// (the net in homogeneous integer form, one gcd per coordinate at the end): the
/// `constructions` benchmark compares this kernel with the generic code run on rationals
/// ("degree 30: subpatch" against "degree 30: subpatch, generic code"), and the tests check
/// both equal.
pub fn subpatch<T: Field>(net: &ControlNet<T>, f: &[Vec<T>]) -> Result<ControlNet<T>, CoreError> {
    let plan = plan(f, net.m())?;
    Ok(permute(exchange(net, &plan.steps), &plan.slot_of))
}

/// The vertex exchanges of a plan, each the face of a de Casteljau pyramid: on integers for
/// exact rationals ([`IntegerNet`]), else the generic code.
fn exchange<T: Field>(net: &ControlNet<T>, steps: &Vec<(Vec<T>, usize)>) -> ControlNet<T> {
    if steps.is_empty() {
        return net.clone();
    }
    let rational = downcast_ref::<_, ControlNet<BigRational>>(net)
        .zip(downcast_ref::<_, Vec<(Vec<BigRational>, usize)>>(steps));
    if let Some((q, steps)) = rational {
        let mut cur = IntegerNet::new(q);
        for (lambda, t) in steps {
            cur = cur.faces(lambda, &[*t]).remove(0);
        }
        // invariant: this branch runs only when the downcast above found T = BigRational, so the cast back succeeds
        return cast(cur.rational()).expect("T is BigRational");
    }
    exchange_generic(net, steps)
}

/// The generic vertex exchanges (the reference the integer kernel is tested against).
fn exchange_generic<T: Field>(net: &ControlNet<T>, steps: &[(Vec<T>, usize)]) -> ControlNet<T> {
    let mut cur = net.clone();
    for (lambda, t) in steps {
        if net.degree() > 0 {
            cur = pyramid_face(&levels(&cur, lambda), *t);
        }
    }
    cur
}

/// [`subpatch`] through the generic code only, whatever `T` is.
#[cfg(test)]
pub(crate) fn subpatch_generic<T: Field>(
    net: &ControlNet<T>,
    f: &[Vec<T>],
) -> Result<ControlNet<T>, CoreError> {
    let plan = plan(f, net.m())?;
    Ok(permute(exchange_generic(net, &plan.steps), &plan.slot_of))
}

/// A rational net in integer form: coordinate `c` of every point is `z / den[c]`.
struct IntegerNet {
    net: ControlNet<BigInt>,
    den: Vec<BigInt>,
}

impl IntegerNet {
    fn new(net: &ControlNet<BigRational>) -> Self {
        let den: Vec<BigInt> = (0..net.dim())
            .map(|c| {
                net.points()
                    .fold(BigInt::one(), |acc, p| acc.lcm(p[c].denom()))
            })
            .collect();
        let coords = net
            .points()
            .flat_map(|p| p.iter().zip(&den).map(|(x, l)| x.numer() * (l / x.denom())))
            .collect();
        IntegerNet {
            net: ControlNet::new(net.simplex().clone(), net.dim(), coords),
            den,
        }
    }

    fn rational(&self) -> ControlNet<BigRational> {
        let dim = self.net.dim();
        let coords = self
            .net
            .coords()
            .iter()
            .enumerate()
            .map(|(i, z)| BigRational::new(z.clone(), self.den[i % dim].clone()))
            .collect();
        ControlNet::new(self.net.simplex().clone(), dim, coords)
    }

    /// The faces `slots` of the de Casteljau pyramid at `λ`, run on integers: with
    /// `λ = a / d`, level `r` of the integer pyramid is `d^r` times the rational one, so face
    /// entry `α` is multiplied by `d^{n − α_t}` and every face gets the denominator `den · d^n`.
    fn faces(&self, lambda: &[BigRational], slots: &[usize]) -> Vec<IntegerNet> {
        let (a, d) = crate::exact::common_denominator(lambda);
        let (m, n, dim) = (self.net.m(), self.net.degree(), self.net.dim());
        let mut pows = vec![BigInt::one()];
        for k in 0..n {
            let next = &pows[k] * &d;
            pows.push(next);
        }
        let lv = if n == 0 {
            vec![self.net.clone()]
        } else {
            levels(&self.net, &a)
        };
        let den: Vec<BigInt> = self.den.iter().map(|x| x * &pows[n]).collect();
        let sx = self.net.simplex();
        slots
            .iter()
            .map(|&t| {
                let mut coords = Vec::with_capacity(sx.len() * dim);
                let mut beta = vec![0u32; m + 1];
                for alpha in sx.iter() {
                    beta.copy_from_slice(alpha);
                    let r = beta[t] as usize;
                    beta[t] = 0;
                    let scale = &pows[n - r];
                    coords.extend(lv[r].point(simplex::rank(&beta)).iter().map(|z| z * scale));
                }
                IntegerNet {
                    net: ControlNet::new(sx.clone(), dim, coords),
                    den: den.clone(),
                }
            })
            .collect()
    }
}

/// The integer kernel of the split at `t` ([`crate::subdivide::split_at`]): `Some` pieces
/// when `T` is `BigRational` (the pyramid run on integers, as in [`subpatch`]), `None` for
/// every other type, which runs the generic code.
pub(crate) fn split_at_kernel<T: Scalar>(
    net: &ControlNet<T>,
    t: &[T],
) -> Option<Vec<ControlNet<T>>> {
    let q = downcast_ref::<_, ControlNet<BigRational>>(net)?;
    let t = t.to_vec();
    let t = downcast_ref::<_, Vec<BigRational>>(&t)?;
    let slots: Vec<usize> = (0..=net.m()).collect();
    let pieces: Vec<ControlNet<BigRational>> = IntegerNet::new(q)
        .faces(t, &slots)
        .iter()
        .map(IntegerNet::rational)
        .collect();
    cast(pieces)
}

fn check_vertices<T: Scalar>(f: &[Vec<T>], m: usize) -> Result<(), CoreError> {
    if f.len() != m + 1 {
        return Err(CoreError::WrongLength {
            what: "the list of sub-simplex vertices".into(),
            expected: m + 1,
            found: f.len(),
        });
    }
    for (i, v) in f.iter().enumerate() {
        if v.len() != m + 1 {
            return Err(CoreError::WrongLength {
                what: format!("vertex {}", i + 1),
                expected: m + 1,
                found: v.len(),
            });
        }
    }
    Ok(())
}

/// The definition `c′_α = b[f_0^{α_0}, …, f_m^{α_m}]`, one blossom per control point (slow:
/// `O(n^{2m+1})`), for any vertices, also affinely dependent ones. The reference that
/// [`subpatch`] is tested against.
pub fn subpatch_by_blossoms<T: Scalar>(
    net: &ControlNet<T>,
    f: &[Vec<T>],
) -> Result<ControlNet<T>, CoreError> {
    let m = net.m();
    check_vertices(f, m)?;
    let sx = net.simplex().clone();
    let mut coords = Vec::with_capacity(net.coords().len());
    for alpha in sx.iter() {
        let args: Vec<&[T]> = alpha
            .iter()
            .enumerate()
            .flat_map(|(k, &a)| std::iter::repeat_n(f[k].as_slice(), a as usize))
            .collect();
        coords.extend(casteljau::blossom(net, &args));
    }
    Ok(ControlNet::new(sx, net.dim(), coords))
}

/// The point `β_0 f_0 + … + β_m f_m` of the parent that a sub-simplex's `β` maps to.
pub fn map_point<T: Scalar>(f: &[Vec<T>], beta: &[T]) -> Vec<T> {
    (0..f[0].len())
        .map(|i| T::weighted_sum(beta.iter().zip(f.iter().map(|v| &v[i]))))
        .collect()
}

/// The largest subdivision matrix tribez prints or claims (rows = control points of the child):
/// degree 43 for triangles.
pub const MAX_MATRIX_ROWS: usize = 1000;

/// The matrix of the subpatch map for degree `n` on the `m`-simplex: row `α` (child), column `β`
/// (parent), both in canonical order; `c′_α = Σ_β M_{αβ} c_β`. Computed by running `subpatch`
/// on the net whose control point `β` is the unit vector `e_β`.
pub fn subpatch_matrix(
    m: usize,
    n: usize,
    f: &[Vec<BigRational>],
) -> Result<Vec<Vec<BigRational>>, CoreError> {
    let sx = Simplex::new(m, n);
    let len = sx.len();
    let mut coords = vec![BigRational::zero(); len * len];
    for r in 0..len {
        coords[r * len + r] = BigRational::one();
    }
    let child = subpatch(&ControlNet::new(sx, len, coords), f)?;
    Ok(child.points().map(<[BigRational]>::to_vec).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{finn, r, s};
    use proptest::prelude::*;

    #[test]
    fn blossom_values_of_theory_section_4() {
        let net = finn();
        let e1 = r(&["1", "0", "0"]);
        let e3 = r(&["0", "0", "1"]);
        assert_eq!(
            s(&blossom(&net, &[e1, e3.clone()]).unwrap()),
            ["0", "1", "0"]
        );
        assert_eq!(
            s(&blossom(&net, &[r(&["1/2", "1/2", "0"]), e3.clone()]).unwrap()),
            ["1/2", "1", "1/2"]
        );
        assert_eq!(
            s(&blossom(&net, &[r(&["1/2", "1/3", "1/6"]), e3]).unwrap()),
            ["1/3", "7/6", "1/2"]
        );
    }

    #[test]
    fn blossom_arity_is_checked() {
        let err = blossom(&finn(), &[r(&["1", "0", "0"])]).unwrap_err();
        assert_eq!(
            err.to_string(),
            "the blossom of a degree-2 patch takes exactly 2 arguments, got 1"
        );
    }

    #[test]
    fn central_midpoint_triangle_of_theory_section_5_3() {
        let f = [
            r(&["0", "1/2", "1/2"]),
            r(&["1/2", "0", "1/2"]),
            r(&["1/2", "1/2", "0"]),
        ];
        let c = subpatch(&finn(), &f).unwrap();
        let want = [
            ["1/2", "3/2", "3/4"],
            ["1/2", "1", "1"],
            ["0", "1", "1/4"],
            ["1/2", "1", "3/4"],
            ["1/2", "1/2", "3/4"],
            ["1/2", "1/2", "1"],
        ];
        for (p, w) in c.points().zip(want) {
            assert_eq!(s(p), w);
        }
    }

    #[test]
    fn collinear_vertices_are_rejected() {
        let f = [
            r(&["1", "0", "0"]),
            r(&["0", "1", "0"]),
            r(&["1/2", "1/2", "0"]),
        ];
        assert!(matches!(
            subpatch(&finn(), &f),
            Err(CoreError::DegenerateDomain(_))
        ));
        // … while the definition still gives the (degenerate) net.
        assert!(subpatch_by_blossoms(&finn(), &f).is_ok());
    }

    #[test]
    fn vertices_already_in_place_or_permuted() {
        let id = [
            r(&["1", "0", "0"]),
            r(&["0", "1", "0"]),
            r(&["0", "0", "1"]),
        ];
        assert_eq!(subpatch(&finn(), &id).unwrap(), finn());
        // A vertex permutation relabels the net: c′_{ijk} = c_{jki} for f = (e2, e3, e1).
        let perm = [id[1].clone(), id[2].clone(), id[0].clone()];
        let c = subpatch(&finn(), &perm).unwrap();
        for (alpha, p) in c.entries() {
            assert_eq!(p, finn().at(&[alpha[2], alpha[0], alpha[1]]));
        }
    }

    #[test]
    fn matrix_of_the_identity_subpatch_is_the_identity() {
        let id = [
            r(&["1", "0", "0"]),
            r(&["0", "1", "0"]),
            r(&["0", "0", "1"]),
        ];
        let m = subpatch_matrix(2, 3, &id).unwrap();
        for (i, row) in m.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                assert_eq!(x.is_one(), i == j);
            }
        }
    }

    fn small_rational() -> impl Strategy<Value = BigRational> {
        (-6i64..=6, 1i64..=4).prop_map(|(a, b)| BigRational::new(a.into(), b.into()))
    }

    /// A random net of degree 0..=4 on the m-simplex (m = 1..=3), with 2-d points.
    fn net_strategy() -> impl Strategy<Value = ControlNet<BigRational>> {
        (1usize..=3, 0usize..=4).prop_flat_map(|(m, n)| {
            let len = simplex::count(m, n) * 2;
            proptest::collection::vec(small_rational(), len)
                .prop_map(move |c| ControlNet::new(Simplex::new(m, n), 2, c))
        })
    }

    fn bary(m: usize) -> impl Strategy<Value = Vec<BigRational>> {
        proptest::collection::vec(small_rational(), m).prop_map(|mut v| {
            let s: BigRational = v.iter().sum();
            v.push(BigRational::one() - s);
            v
        })
    }

    fn net_and_vertices() -> impl Strategy<
        Value = (
            ControlNet<BigRational>,
            Vec<Vec<BigRational>>,
            Vec<BigRational>,
        ),
    > {
        net_strategy().prop_flat_map(|net| {
            let m = net.m();
            (
                Just(net),
                proptest::collection::vec(bary(m), m + 1),
                bary(m),
            )
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn subpatch_equals_the_definition_and_the_parent((net, f, beta) in net_and_vertices()) {
            let slow = subpatch_by_blossoms(&net, &f).unwrap();
            match subpatch(&net, &f) {
                Ok(fast) => {
                    prop_assert_eq!(&fast, &slow);
                    // the integer kernel (rationals) and the generic code agree with the definition
                    prop_assert_eq!(&subpatch_generic(&net, &f).unwrap(), &slow);
                    let x = map_point(&f, &beta);
                    prop_assert_eq!(casteljau::evaluate(&fast, &beta), casteljau::evaluate(&net, &x));
                }
                Err(CoreError::DegenerateDomain(_)) => {
                    prop_assert!(crate::domain::determinant(f.clone()).is_zero());
                }
                Err(e) => prop_assert!(false, "unexpected error {e}"),
            }
        }

        #[test]
        fn blossom_is_symmetric_multiaffine_diagonal((net, f, beta) in net_and_vertices()) {
            let n = net.degree();
            prop_assume!(n >= 1);
            let m = net.m();
            let args: Vec<Vec<BigRational>> = (0..n).map(|i| f[i % (m + 1)].clone()).collect();
            let b = blossom(&net, &args).unwrap();
            let mut rev = args.clone();
            rev.reverse();
            prop_assert_eq!(&blossom(&net, &rev).unwrap(), &b);
            // affine in the first argument: b[(1−t) x + t y, …] = (1−t) b[x, …] + t b[y, …]
            let t = beta[0].clone();
            let y = beta.clone();
            let mix: Vec<BigRational> = args[0].iter().zip(&y).map(|(a, c)| (BigRational::one() - &t) * a + &t * c).collect();
            let mut a2 = args.clone();
            a2[0] = mix;
            let mut a3 = args.clone();
            a3[0] = y;
            let by = blossom(&net, &a3).unwrap();
            let want: Vec<BigRational> = b.iter().zip(&by).map(|(p, q)| (BigRational::one() - &t) * p + &t * q).collect();
            prop_assert_eq!(blossom(&net, &a2).unwrap(), want);
            // the diagonal
            prop_assert_eq!(blossom(&net, &vec![beta.clone(); n]).unwrap(), casteljau::evaluate(&net, &beta));
            // control points at b[e_0^{α_0}, …]
            let units: Vec<Vec<BigRational>> = (0..=m).map(|k| unit(m, k)).collect();
            for (alpha, p) in net.entries() {
                let args: Vec<Vec<BigRational>> = alpha.iter().enumerate().flat_map(|(k, &a)| std::iter::repeat_n(units[k].clone(), a as usize)).collect();
                prop_assert_eq!(blossom(&net, &args).unwrap(), p.to_vec());
            }
        }
    }
}
