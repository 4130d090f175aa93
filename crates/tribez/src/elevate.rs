//! Degree elevation (docs/theory.md §6, §11), any simplex dimension.
//!
//! One step, `n → n + 1` (terms with a negative index are omitted):
//!
//! `c^{(1)}_α = Σ_{k=0..m} α_k c_{α−e_k} / (n + 1)`,  `|α| = n + 1`.
//!
//! `r` steps at once:
//!
//! `c^{(r)}_a = Σ_{|b|=n, b ≤ a} C(n; b) · C(r; a − b) / C(n + r; a) · c_b`,  `|a| = n + r`,
//!
//! with multinomial coefficients `C(n; b) = n!/(b_0!⋯b_m!)`. In homogeneous form elevation is
//! multiplication by `(u_0 + … + u_m)^r`: the same surface.
//!
//! ```
//! use tribez::hazmat::elevate::elevate;
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::ControlNet;
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let net = ControlNet::from_points(2, 2, &pts);
//! // docs/theory.md §6: Finn's net elevated to degree 3 has c_{111} = (2/3, 2/3, 1).
//! let up = elevate(&net, 1);
//! let s: Vec<String> = up.at(&[1, 1, 1]).iter().map(|x| x.to_string()).collect();
//! assert_eq!(s, ["2/3", "2/3", "1"]);
//! ```

use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::blossom::Field;
use crate::patch::ControlNet;
use crate::scalar::{cast, downcast_ref};
use crate::simplex::{Simplex, multinomial, rank};

/// One elevation step: `c^{(1)}_α = Σ_k α_k c_{α−e_k} / (n+1)`.
pub fn elevate_once<T: Field>(net: &ControlNet<T>) -> ControlNet<T> {
    let (m, n, dim) = (net.m(), net.degree(), net.dim());
    let up = Simplex::new(m, n + 1);
    let den = T::from_u64(n as u64 + 1);
    let mut coords = Vec::with_capacity(up.len() * dim);
    let mut beta = vec![0u32; m + 1];
    for alpha in up.iter() {
        for c in 0..dim {
            let mut acc: Option<T> = None;
            for k in 0..=m {
                if alpha[k] == 0 {
                    continue;
                }
                beta.copy_from_slice(alpha);
                beta[k] -= 1;
                let term = T::from_u64(u64::from(alpha[k])) * &net.point(rank(&beta))[c];
                acc = Some(match acc {
                    None => term,
                    Some(a) => a + term,
                });
            }
            // invariant: |α| = n + 1 ≥ 1, so some α_k > 0 and the loop above set `acc`
            coords.push(acc.expect("some α_k > 0") / &den);
        }
    }
    ControlNet::new(up, dim, coords)
}

/// Elevate by `r` steps at once with the closed form of docs/theory.md §6 (`r = 0` returns the
/// net). Generic (floats too); for exact rationals the sums run on integers (each coordinate
/// brought to a common denominator `L_c`, one division, one gcd, per result): the
/// `constructions` benchmark compares this kernel with the generic code run on rationals
/// ("degree 30: elevate by 1" against "…, generic code"), and the tests check both equal.
pub fn elevate<T: Field>(net: &ControlNet<T>, r: usize) -> ControlNet<T> {
    if r == 0 {
        return net.clone();
    }
    match downcast_ref::<_, ControlNet<BigRational>>(net) {
        // invariant: the downcast found T = BigRational, so the cast back succeeds
        Some(q) => cast(elevate_integer(q, r)).expect("T is BigRational"),
        None => elevate_generic(net, r),
    }
}

/// [`elevate`] through the generic code only, whatever `T` is (`r ≥ 1`).
fn elevate_generic<T: Field>(net: &ControlNet<T>, r: usize) -> ControlNet<T> {
    let (m, n, dim) = (net.m(), net.degree(), net.dim());
    let up = Simplex::new(m, n + r);
    let steps = Simplex::new(m, r);
    // C(n; b) for the net's indices, C(r; γ) for the steps.
    let cn: Vec<BigUint> = net.simplex().iter().map(multinomial).collect();
    let cr: Vec<BigUint> = steps.iter().map(multinomial).collect();
    let mut coords = Vec::with_capacity(up.len() * dim);
    let mut b = vec![0u32; m + 1];
    let mut acc: Vec<T> = vec![T::zero(); dim];
    for a in up.iter() {
        acc.iter_mut().for_each(|x| *x = T::zero());
        for (gi, gamma) in steps.iter().enumerate() {
            if gamma.iter().zip(a).any(|(g, x)| g > x) {
                continue;
            }
            for k in 0..=m {
                b[k] = a[k] - gamma[k];
            }
            let rb = rank(&b);
            let w = T::from_biguint(&(&cn[rb] * &cr[gi]));
            for (c, x) in acc.iter_mut().enumerate() {
                *x = x.clone() + w.clone() * &net.point(rb)[c];
            }
        }
        let den = T::from_biguint(&multinomial(a));
        coords.extend(acc.iter().map(|x| x.clone() / &den));
    }
    ControlNet::new(up, dim, coords)
}

/// The integer kernel of [`elevate`] for exact rationals (`r ≥ 1`): each coordinate brought to
/// a common denominator `L_c`, the sums `Σ C(n;b) C(r;a−b) z_b` taken on integers, one
/// division (one gcd) per result.
fn elevate_integer(net: &ControlNet<BigRational>, r: usize) -> ControlNet<BigRational> {
    let (m, n, dim) = (net.m(), net.degree(), net.dim());
    let den: Vec<BigInt> = (0..dim)
        .map(|c| {
            net.points()
                .fold(BigInt::one(), |acc, p| acc.lcm(p[c].denom()))
        })
        .collect();
    // C(n; b) z_b, per point and coordinate
    let z: Vec<BigInt> = net
        .entries()
        .flat_map(|(b, p)| {
            let k = BigInt::from(multinomial(b));
            p.iter()
                .zip(&den)
                .map(move |(x, l)| x.numer() * (l / x.denom()) * &k)
                .collect::<Vec<_>>()
        })
        .collect();
    let up = Simplex::new(m, n + r);
    let steps = Simplex::new(m, r);
    let cr: Vec<BigInt> = steps.iter().map(|g| BigInt::from(multinomial(g))).collect();
    let mut coords = Vec::with_capacity(up.len() * dim);
    let mut b = vec![0u32; m + 1];
    let mut acc: Vec<BigInt> = vec![BigInt::zero(); dim];
    for a in up.iter() {
        acc.iter_mut().for_each(|x| *x = BigInt::zero());
        for (gi, gamma) in steps.iter().enumerate() {
            if gamma.iter().zip(a).any(|(g, x)| g > x) {
                continue;
            }
            for k in 0..=m {
                b[k] = a[k] - gamma[k];
            }
            let rb = rank(&b);
            for (c, x) in acc.iter_mut().enumerate() {
                *x += &z[rb * dim + c] * &cr[gi];
            }
        }
        let ca = BigInt::from(multinomial(a));
        coords.extend(
            acc.iter()
                .zip(&den)
                .map(|(x, l)| BigRational::new(x.clone(), l * &ca)),
        );
    }
    ControlNet::new(up, dim, coords)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::casteljau::evaluate;
    use crate::domain::Domain;
    use crate::simplex;
    use crate::symbolic::cartesian_form;
    use crate::testing::finn;
    use proptest::prelude::*;

    #[test]
    fn finn_elevated_to_degree_three() {
        let want = [
            ["0", "0", "0"],
            ["2/3", "0", "4/3"],
            ["2/3", "2/3", "4/3"],
            ["0", "2", "0"],
            ["0", "2/3", "0"],
            ["2/3", "2/3", "1"],
            ["2/3", "4/3", "2/3"],
            ["0", "4/3", "1/3"],
            ["2/3", "4/3", "1"],
            ["0", "2", "1"],
        ];
        for net in [
            elevate(&finn(), 1),
            elevate_once(&finn()),
            elevate_generic(&finn(), 1),
        ] {
            for (p, w) in net.points().zip(want) {
                assert_eq!(p.iter().map(ToString::to_string).collect::<Vec<_>>(), w);
            }
        }
    }

    #[test]
    fn floats_elevate_too() {
        let f = finn().map(crate::number::round_f64);
        let up = elevate(&f, 2);
        assert_eq!(up.degree(), 4);
        assert_eq!(up.at(&[4, 0, 0]), &[0.0, 0.0, 0.0]);
    }

    fn small_rational() -> impl Strategy<Value = BigRational> {
        (-6i64..=6, 1i64..=4).prop_map(|(a, b)| BigRational::new(a.into(), b.into()))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        #[test]
        fn same_surface(m in 1usize..=3, n in 0usize..=4, r in 1usize..=3, seed in proptest::collection::vec(small_rational(), 80)) {
            let len = simplex::count(m, n);
            let coords: Vec<BigRational> = (0..len).map(|i| seed[i % seed.len()].clone() + BigRational::from_integer((i as i64).into())).collect();
            let net = ControlNet::new(Simplex::new(m, n), 1, coords);
            let up = elevate(&net, r);
            let mut steps = net.clone();
            for _ in 0..r {
                steps = elevate_once(&steps);
            }
            prop_assert_eq!(&up, &steps);
            // the integer kernel (rationals) equals the generic code
            prop_assert_eq!(&elevate_generic(&net, r), &up);
            let mut at: Vec<BigRational> = seed[..m].to_vec();
            let s: BigRational = at.iter().sum();
            at.push(BigRational::one() - s);
            prop_assert_eq!(evaluate(&up, &at), evaluate(&net, &at));
            let d = Domain::reference(m);
            prop_assert_eq!(cartesian_form(&up, &d), cartesian_form(&net, &d));
        }
    }
}
