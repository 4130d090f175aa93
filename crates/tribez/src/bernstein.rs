//! The Bernstein basis on a simplex and the direct Bernstein form of a patch.
//!
//! `B^n_α(λ) = C(n; α) λ_0^{α_0} ⋯ λ_m^{α_m}` with the multinomial coefficient
//! `C(n; α) = n!/(α_0! ⋯ α_m!)`; `Σ_{|α|=n} B^n_α(λ) = (λ_0 + ⋯ + λ_m)^n` (partition of unity on
//! `Σλ = 1`), and the recursion `B^n_α = Σ_k λ_k B^{n−1}_{α−e_k}` (docs/theory.md §1).
//!
//! ```
//! use tribez::hazmat::bernstein::basis;
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::simplex::Simplex;
//! // docs/theory.md §1: the cubic basis at (1/2, 1/3, 1/6)
//! let u = [q("1/2").unwrap(), q("1/3").unwrap(), q("1/6").unwrap()];
//! let b: Vec<String> = basis(&Simplex::new(2, 3), &u).iter().map(|x| x.to_string()).collect();
//! assert_eq!(b, ["1/8", "1/4", "1/6", "1/27", "1/8", "1/6", "1/18", "1/24", "1/36", "1/216"]);
//! ```

use crate::patch::ControlNet;
use crate::scalar::Scalar;
use crate::simplex::{Simplex, multinomial};

/// Powers `x^0, …, x^n`.
fn powers<T: Scalar>(x: &T, n: usize) -> Vec<T> {
    let mut out = Vec::with_capacity(n + 1);
    out.push(T::one());
    for e in 1..=n {
        let next = out[e - 1].clone() * x;
        out.push(next);
    }
    out
}

/// All basis values `B^n_α(λ)` in canonical order.
pub fn basis<T: Scalar>(simplex: &Simplex, lambda: &[T]) -> Vec<T> {
    let n = simplex.degree();
    let pw: Vec<Vec<T>> = lambda.iter().map(|x| powers(x, n)).collect();
    simplex
        .iter()
        .map(|alpha| {
            let mut b = T::from_biguint(&multinomial(alpha));
            for (k, &a) in alpha.iter().enumerate() {
                b = b * &pw[k][a as usize];
            }
            b
        })
        .collect()
}

/// `p(λ) = Σ_α c_α B^n_α(λ)`, summed in canonical order.
pub fn evaluate<T: Scalar>(net: &ControlNet<T>, lambda: &[T]) -> Vec<T> {
    let b = basis(net.simplex(), lambda);
    (0..net.dim())
        .map(|c| T::weighted_sum(b.iter().zip(net.points().map(|p| &p[c]))))
        .collect()
}
