//! The de Casteljau algorithm on a simplex, and the blossom (polar form) it computes.
//!
//! One step with argument `x = (x_0, …, x_m)` maps a net of degree `q` to one of degree `q − 1`:
//!
//! `c^{r}_β = Σ_{k=0..m} x_k c^{r−1}_{β+e_k}`,  `|β| = q − 1`   (docs/theory.md §3, §11).
//!
//! With the same argument `λ` at each of the `n` levels the apex is `p(λ)`; with different
//! arguments `x_1, …, x_n` it is the blossom `b[x_1, …, x_n]` (§4), symmetric and multi-affine.
//! Arguments need not sum to one: every formula here is a homogeneous identity, so these routines
//! evaluate the homogeneous form (what a float program that computes `w = 1 − u − v` sees).
//!
//! Written once, generic over [`Scalar`]: exact rationals, big integers (homogeneous integer
//! evaluation) and the f64/f32 float paths all run this code.
//!
//! ```
//! use tribez::hazmat::casteljau::evaluate;
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::ControlNet;
//! // Finn's worked example: the point [4/9, 5/9, 29/36]
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let net = ControlNet::from_points(2, 2, &pts);
//! let u = [q("1/2").unwrap(), q("1/3").unwrap(), q("1/6").unwrap()];
//! let p: Vec<String> = evaluate(&net, &u).iter().map(|x| x.to_string()).collect();
//! assert_eq!(p, ["4/9", "5/9", "29/36"]);
//! ```

use crate::patch::ControlNet;
use crate::scalar::Scalar;
use crate::simplex::Simplex;

/// One de Casteljau step with argument `x` (length `m + 1`): degree `q` to `q − 1`.
pub fn step<T: Scalar>(net: &ControlNet<T>, x: &[T]) -> ControlNet<T> {
    let m = net.m();
    assert_eq!(
        x.len(),
        m + 1,
        "argument has the wrong number of coordinates"
    );
    assert!(net.degree() >= 1, "cannot step below degree 0");
    let dim = net.dim();
    let stencil = net.simplex().step_stencil();
    let lower = Simplex::new(m, net.degree() - 1);
    let mut coords = Vec::with_capacity(lower.len() * dim);
    for children in stencil.chunks_exact(m + 1) {
        for c in 0..dim {
            coords.push(T::weighted_sum(
                x.iter().zip(children.iter().map(|&r| &net.point(r)[c])),
            ));
        }
    }
    ControlNet::new(lower, dim, coords)
}

/// Apply the given arguments one per level: `b[x_1, …, x_r, ·^{n−r}]`, a net of degree `n − r`.
///
/// With `r = n` the result has one point, the blossom value.
pub fn partial_blossom<T: Scalar>(net: &ControlNet<T>, args: &[&[T]]) -> ControlNet<T> {
    assert!(
        args.len() <= net.degree(),
        "more blossom arguments than the degree"
    );
    let mut level = net.clone();
    for x in args {
        level = step(&level, x);
    }
    level
}

/// The blossom `b[x_1, …, x_n]` (exactly `n` arguments).
pub fn blossom<T: Scalar>(net: &ControlNet<T>, args: &[&[T]]) -> Vec<T> {
    assert_eq!(
        args.len(),
        net.degree(),
        "the blossom takes exactly n arguments"
    );
    partial_blossom(net, args).point(0).to_vec()
}

/// All levels of the de Casteljau pyramid at `λ`: `levels[r]` has degree `n − r`; the last is
/// the point `p(λ)`.
pub fn levels<T: Scalar>(net: &ControlNet<T>, lambda: &[T]) -> Vec<ControlNet<T>> {
    let mut out = Vec::with_capacity(net.degree() + 1);
    out.push(net.clone());
    for _ in 0..net.degree() {
        // invariant: `out` holds the net pushed above, so it is never empty
        let next = step(out.last().expect("non-empty"), lambda);
        out.push(next);
    }
    out
}

/// `p(λ)` by de Casteljau.
pub fn evaluate<T: Scalar>(net: &ControlNet<T>, lambda: &[T]) -> Vec<T> {
    let args = vec![lambda; net.degree()];
    partial_blossom(net, &args).point(0).to_vec()
}
