//! Subdivision: split at a point, halve along an edge, four-way midpoint split (docs/theory.md §5).
//!
//! Every piece is a subpatch ([`crate::blossom`]) over a sub-simplex whose vertices are given in
//! the parent's barycentric coordinates (`domain_in_parent`); evaluated at `β` it equals the
//! parent at `β_0 f_0 + … + β_m f_m`, exactly.
//!
//! * **Split at a point `t`** (any `m`): `m + 1` pieces; piece `s` is the parent simplex with
//!   vertex `s` replaced by `t`, and its net is the face of the de Casteljau pyramid at `t` with
//!   slot `s` zero: `d_α = c^{α_s}_{α with α_s = 0}` (§5.1, §11).
//! * **Halving along the edge `I, J`** (corners numbered from 1, any `m`): the cut runs from the
//!   midpoint `M` of corners `I` and `J` to the opposite corner(s). The first piece is the parent
//!   with corner `J` replaced by `M`, the second with corner `I` replaced by `M`, each keeping the
//!   parent's vertex order. Along every line from corner `I` towards `J` the net is split like a
//!   Bézier curve: `d_α = 2^{−α_J} Σ_l C(α_J, l) c_{α + (α_J − l) e_I − (α_J − l) e_J}` for the first
//!   piece (§5.2). [`add_and_halve`] does it with additions and halvings only, in place, in the
//!   order of the Wikipedia article's table.
//! * **Four-way midpoint split** (triangles): `[a1, m12, m13]`, `[m12, a2, m23]`,
//!   `[m13, m23, a3]`, central `[m23, m13, m12]`, each keeping the orientation (§5.3).
//!
//! ```
//! use tribez::hazmat::subdivide::split_at;
//! use tribez::hazmat::number::parse_rational as q;
//! use tribez::hazmat::patch::ControlNet;
//! let pts: Vec<Vec<_>> = [[0, 0, 0], [1, 0, 2], [0, 2, 0], [0, 1, 0], [1, 1, 1], [0, 2, 1]]
//!     .iter().map(|p| p.iter().map(|&x| q(&x.to_string()).unwrap()).collect()).collect();
//! let net = ControlNet::from_points(2, 2, &pts);
//! let t = [q("1/2").unwrap(), q("1/3").unwrap(), q("1/6").unwrap()];
//! let pieces = split_at(&net, &t);
//! // docs/theory.md §5.1: T1 = [t, a2, a3] has d200 = p(t) and d110 = c¹010.
//! let s = |p: &[num_rational::BigRational]| p.iter().map(|x| x.to_string()).collect::<Vec<_>>();
//! assert_eq!(s(pieces[0].at(&[2, 0, 0])), ["4/9", "5/9", "29/36"]);
//! assert_eq!(s(pieces[0].at(&[1, 1, 0])), ["2/3", "5/6", "7/6"]);
//! ```

use crate::blossom::{Field, pyramid_face, split_at_kernel, subpatch};
use crate::casteljau::levels;
use crate::error::CoreError;
use crate::patch::ControlNet;
use crate::scalar::Scalar;
use crate::simplex;

/// A piece of a subdivision: its vertices in the parent's barycentric coordinates, and its net.
#[derive(Clone, Debug, PartialEq)]
pub struct Piece<T> {
    /// The sub-simplex, vertex `k` as a barycentric point of the parent.
    pub domain_in_parent: Vec<Vec<T>>,
    /// The net of the same polynomial over that sub-simplex.
    pub net: ControlNet<T>,
}

fn unit<T: Scalar>(m: usize, k: usize) -> Vec<T> {
    (0..=m)
        .map(|i| if i == k { T::one() } else { T::zero() })
        .collect()
}

/// The vertices of the parent simplex with vertex `s` replaced by `x`.
pub fn replaced<T: Scalar>(m: usize, s: usize, x: &[T]) -> Vec<Vec<T>> {
    (0..=m)
        .map(|k| if k == s { x.to_vec() } else { unit(m, k) })
        .collect()
}

/// Split at the point `t` (`m + 1` barycentric coordinates): the `m + 1` faces of the
/// de Casteljau pyramid; piece `s` is the parent with vertex `s` replaced by `t`. For exact
/// rationals the pyramid runs on integers ([`crate::blossom::subpatch`]'s kernel; benchmark
/// "degree 30: split at a point" against "…, generic code"), tested equal to the generic code.
pub fn split_at<T: Scalar>(net: &ControlNet<T>, t: &[T]) -> Vec<ControlNet<T>> {
    assert_eq!(
        t.len(),
        net.m() + 1,
        "the split point has the wrong number of coordinates"
    );
    split_at_kernel(net, t).unwrap_or_else(|| split_at_generic(net, t))
}

/// [`split_at`] through the generic code only, whatever `T` is.
fn split_at_generic<T: Scalar>(net: &ControlNet<T>, t: &[T]) -> Vec<ControlNet<T>> {
    if net.degree() == 0 {
        return vec![net.clone(); net.m() + 1];
    }
    let lv = levels(net, t);
    (0..=net.m()).map(|s| pyramid_face(&lv, s)).collect()
}

/// [`split_at`] with the pieces' domains. A piece whose simplex is degenerate (`t_s = 0`: the
/// point lies on the facet opposite vertex `s`) is an error.
pub fn split_at_pieces<T: Scalar>(
    net: &ControlNet<T>,
    t: &[T],
) -> Result<Vec<Piece<T>>, CoreError> {
    let m = net.m();
    if let Some(s) = t.iter().position(num_traits::Zero::is_zero) {
        return Err(CoreError::SplitOnFace { corner: s + 1 });
    }
    Ok(split_at(net, t)
        .into_iter()
        .enumerate()
        .map(|(s, n)| Piece {
            domain_in_parent: replaced(m, s, t),
            net: n,
        })
        .collect())
}

/// Check an edge `I, J` given with corners numbered from 1; returns the 0-based pair.
pub fn check_edge(m: usize, i: usize, j: usize) -> Result<(usize, usize), CoreError> {
    if i == j || !(1..=m + 1).contains(&i) || !(1..=m + 1).contains(&j) {
        return Err(CoreError::BadEdge {
            i,
            j,
            corners: m + 1,
        });
    }
    Ok((i - 1, j - 1))
}

/// The midpoint of corners `i` and `j` (0-based).
pub fn midpoint<T: Field>(m: usize, i: usize, j: usize) -> Vec<T> {
    let half = T::one() / T::from_u64(2);
    (0..=m)
        .map(|k| {
            if k == i || k == j {
                half.clone()
            } else {
                T::zero()
            }
        })
        .collect()
}

/// The two sub-simplices of halving along the edge between corners `i` and `j` (0-based): the
/// parent with corner `j` replaced by the midpoint, then with corner `i` replaced.
pub fn halve_domains<T: Field>(m: usize, i: usize, j: usize) -> [Vec<Vec<T>>; 2] {
    let mid = midpoint(m, i, j);
    [replaced(m, j, &mid), replaced(m, i, &mid)]
}

/// Halve along the edge between corners `i` and `j` (0-based), by blossoms: two pieces, the
/// first keeping corner `i`, the second keeping corner `j`.
pub fn halve<T: Field>(net: &ControlNet<T>, i: usize, j: usize) -> [Piece<T>; 2] {
    halve_domains(net.m(), i, j).map(|d| {
        // invariant: halve_domains gives the two halves of the simplex (a vertex replaced by an edge midpoint), never degenerate
        let n = subpatch(net, &d).expect("a half is non-degenerate");
        Piece {
            domain_in_parent: d,
            net: n,
        }
    })
}

/// The four-way midpoint split of a triangle (docs/theory.md §5.3), each piece with the
/// orientation of the parent: `[a1, m12, m13]`, `[m12, a2, m23]`, `[m13, m23, a3]`,
/// `[m23, m13, m12]`.
pub fn midpoint_split<T: Field>(net: &ControlNet<T>) -> Result<Vec<Piece<T>>, CoreError> {
    if net.m() != 2 {
        return Err(CoreError::MidpointSplit { m: net.m() });
    }
    let (m12, m13, m23) = (
        midpoint::<T>(2, 0, 1),
        midpoint::<T>(2, 0, 2),
        midpoint::<T>(2, 1, 2),
    );
    let domains = [
        vec![unit(2, 0), m12.clone(), m13.clone()],
        vec![m12.clone(), unit(2, 1), m23.clone()],
        vec![m13.clone(), m23.clone(), unit(2, 2)],
        vec![m23, m13, m12],
    ];
    domains
        .into_iter()
        .map(|d| {
            Ok(Piece {
                net: subpatch(net, &d)?,
                domain_in_parent: d,
            })
        })
        .collect()
}

/// The order of the in-place updates of `add_and_halve`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HalvingOrder {
    /// the Wikipedia article's table read row by row, top to bottom, each row left to right: along each line
    /// `P_0 … P_d` (from the kept corner), passes `s = 1, …, d`, pass `s` updating
    /// `P_j := (P_{j−1} + P_j)/2` for `j = d−s+1, …, d`. Correct (docs/theory.md §5.2).
    TopDown,
    /// The same passes in the reverse order, `s = d, …, 1` (the longest row of the table first).
    /// WRONG: gives different points (docs/theory.md §5.2, §15); kept to exhibit the erratum.
    BottomFirst,
}

/// Halving with additions and exact divisions by two only, in place (the Wikipedia article): the piece that
/// keeps corner `keep` and replaces corner `replace` (0-based) by the midpoint of the two. With
/// [`HalvingOrder::TopDown`] this equals [`halve`]'s piece, for every degree and dimension.
pub fn add_and_halve<T: Field>(
    net: &ControlNet<T>,
    keep: usize,
    replace: usize,
    order: HalvingOrder,
) -> ControlNet<T> {
    assert!(keep != replace && keep <= net.m() && replace <= net.m());
    let two = T::from_u64(2);
    let dim = net.dim();
    let mut coords = net.coords().to_vec();
    let mut alpha = vec![0u32; net.m() + 1];
    let lines: Vec<Vec<u32>> = net
        .simplex()
        .iter()
        .filter(|a| a[replace] == 0)
        .map(<[u32]>::to_vec)
        .collect();
    for start in lines {
        let d = start[keep] as usize;
        // ranks of P_0 … P_d along the line from corner `keep` towards corner `replace`
        let ranks: Vec<usize> = (0..=d)
            .map(|j| {
                alpha.copy_from_slice(&start);
                alpha[keep] -= j as u32;
                alpha[replace] += j as u32;
                simplex::rank(&alpha)
            })
            .collect();
        let passes: Vec<usize> = match order {
            HalvingOrder::TopDown => (1..=d).collect(),
            HalvingOrder::BottomFirst => (1..=d).rev().collect(),
        };
        for s in passes {
            for j in d + 1 - s..=d {
                let (a, b) = (ranks[j - 1], ranks[j]);
                for c in 0..dim {
                    coords[b * dim + c] =
                        (coords[a * dim + c].clone() + &coords[b * dim + c]) / &two;
                }
            }
        }
    }
    ControlNet::new(net.simplex().clone(), dim, coords)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::blossom::{map_point, subpatch_generic};
    use crate::casteljau::evaluate;
    use crate::testing::{finn, r, s};
    use num_rational::BigRational;
    use num_traits::One;
    use proptest::prelude::*;

    #[test]
    fn split_of_theory_section_5_1() {
        let pieces = split_at_pieces(&finn(), &r(&["1/2", "1/3", "1/6"])).unwrap();
        let t1 = &pieces[0].net;
        let want = [
            ["4/9", "5/9", "29/36"],
            ["2/3", "5/6", "7/6"],
            ["0", "2", "0"],
            ["1/3", "7/6", "1/2"],
            ["1", "1", "1"],
            ["0", "2", "1"],
        ];
        for (p, w) in t1.points().zip(want) {
            assert_eq!(s(p), w);
        }
        assert_eq!(s(&pieces[0].domain_in_parent[0]), ["1/2", "1/3", "1/6"]);
    }

    #[test]
    fn half_of_theory_section_5_2() {
        let [a, _] = halve(&finn(), 0, 1);
        let want = [
            ["0", "0", "0"],
            ["1/2", "0", "1"],
            ["1/2", "1/2", "1"],
            ["0", "1", "0"],
            ["1/2", "1", "1/2"],
            ["0", "2", "1"],
        ];
        for (p, w) in a.net.points().zip(want) {
            assert_eq!(s(p), w);
        }
    }

    #[test]
    fn bottom_first_differs_and_top_down_agrees() {
        let net = finn();
        let [a, b] = halve(&net, 0, 1);
        assert_eq!(add_and_halve(&net, 0, 1, HalvingOrder::TopDown), a.net);
        assert_eq!(add_and_halve(&net, 1, 0, HalvingOrder::TopDown), b.net);
        assert_ne!(add_and_halve(&net, 0, 1, HalvingOrder::BottomFirst), a.net);
    }

    /// The identity net of degree n on the triangle: control point β is the unit vector e_β, so a
    /// linear construction applied to it gives its matrix (row α = child point α).
    fn identity(n: usize) -> ControlNet<BigRational> {
        let sx = simplex::Simplex::new(2, n);
        let len = sx.len();
        let coords = (0..len * len)
            .map(|i| {
                if i / len == i % len {
                    BigRational::one()
                } else {
                    BigRational::default()
                }
            })
            .collect();
        ControlNet::new(sx, len, coords)
    }

    #[test]
    fn add_and_halve_equals_the_matrix_for_every_degree_up_to_8() {
        for n in 0..=8 {
            for (keep, replace, piece) in [(0, 1, 0), (1, 0, 1), (1, 2, 0), (2, 0, 0)] {
                let (i, j) = if piece == 0 {
                    (keep, replace)
                } else {
                    (replace, keep)
                };
                let f = &halve_domains::<BigRational>(2, i, j)[piece];
                let matrix = crate::blossom::subpatch_matrix(2, n, f).unwrap();
                let added = add_and_halve(&identity(n), keep, replace, HalvingOrder::TopDown);
                let rows: Vec<Vec<BigRational>> =
                    added.points().map(<[BigRational]>::to_vec).collect();
                assert_eq!(rows, matrix, "n = {n}, keep {keep}, replace {replace}");
            }
        }
    }

    #[test]
    fn halving_matrices_follow_the_closed_form_of_theory_5_2() {
        // d_ijk = 2^-j Σ_l C(j,l) c_(i+j−l, l, k) (first half), 2^-i Σ_l C(i,l) c_(i−l, j+l, k) (second).
        let n = 5;
        let sx = simplex::Simplex::new(2, n);
        let binom = |a: u32, b: u32| {
            BigRational::from_integer(simplex::binomial_exact(a.into(), b.into()).into())
        };
        let pow2 = |e: u32| BigRational::from_integer(num_bigint::BigInt::from(1u64 << e));
        for piece in 0..2 {
            let f = &halve_domains::<BigRational>(2, 0, 1)[piece];
            let matrix = crate::blossom::subpatch_matrix(2, n, f).unwrap();
            for (r, a) in sx.iter().enumerate() {
                let (i, j, k) = (a[0], a[1], a[2]);
                let mut want = vec![BigRational::default(); sx.len()];
                if piece == 0 {
                    for l in 0..=j {
                        want[sx.rank(&[i + j - l, l, k])] = binom(j, l) / pow2(j);
                    }
                } else {
                    for l in 0..=i {
                        want[sx.rank(&[i - l, j + l, k])] = binom(i, l) / pow2(i);
                    }
                }
                assert_eq!(matrix[r], want, "piece {piece}, row {a:?}");
            }
        }
    }

    #[test]
    fn the_same_code_runs_in_f64() {
        // Finn's integer net halved: every value is dyadic, so f64 is exact here.
        let exact = halve(&finn(), 0, 1);
        let float = halve(&finn().map(crate::number::round_f64), 0, 1);
        for (e, f) in exact.iter().zip(&float) {
            assert_eq!(e.net.map(crate::number::round_f64), f.net);
        }
        assert_eq!(
            add_and_halve(
                &finn().map(crate::number::round_f64),
                0,
                1,
                HalvingOrder::TopDown
            ),
            float[0].net
        );
        assert_eq!(
            midpoint_split(&finn().map(crate::number::round_f64)).unwrap()[3].net,
            midpoint_split(&finn()).unwrap()[3]
                .net
                .map(crate::number::round_f64)
        );
    }

    #[test]
    fn bad_edges_and_split_points() {
        assert!(check_edge(2, 1, 1).is_err());
        assert!(check_edge(2, 0, 2).is_err());
        assert!(check_edge(2, 1, 4).is_err());
        assert_eq!(check_edge(3, 4, 1).unwrap(), (3, 0));
        assert!(split_at_pieces(&finn(), &r(&["1/2", "1/2", "0"])).is_err());
        let curve = ControlNet::from_points(1, 1, &[r(&["0"]), r(&["1"])]);
        assert!(midpoint_split(&curve).is_err());
    }

    fn small_rational() -> impl Strategy<Value = BigRational> {
        (-6i64..=6, 1i64..=4).prop_map(|(a, b)| BigRational::new(a.into(), b.into()))
    }

    fn net_and_point()
    -> impl Strategy<Value = (ControlNet<BigRational>, Vec<BigRational>, Vec<BigRational>)> {
        (1usize..=3, 0usize..=5)
            .prop_flat_map(|(m, n)| {
                let len = simplex::count(m, n) * 2;
                (
                    proptest::collection::vec(small_rational(), len)
                        .prop_map(move |c| ControlNet::new(simplex::Simplex::new(m, n), 2, c)),
                    proptest::collection::vec(small_rational(), m),
                    proptest::collection::vec(small_rational(), m),
                )
            })
            .prop_map(|(net, mut t, mut q)| {
                let st: BigRational = t.iter().sum();
                t.push(BigRational::one() - st);
                let sq: BigRational = q.iter().sum();
                q.push(BigRational::one() - sq);
                (net, t, q)
            })
    }

    fn check_pieces(
        parent: &ControlNet<BigRational>,
        pieces: &[Piece<BigRational>],
        q: &[BigRational],
    ) -> Result<(), TestCaseError> {
        for p in pieces {
            prop_assert_eq!(
                evaluate(&p.net, q),
                evaluate(parent, &map_point(&p.domain_in_parent, q))
            );
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn every_piece_is_the_parent_at_the_mapped_point((net, t, q) in net_and_point()) {
            let m = net.m();
            if let Ok(pieces) = split_at_pieces(&net, &t) {
                prop_assert_eq!(pieces.len(), m + 1);
                // the integer kernel (rationals) equals the generic code
                let generic = split_at_generic(&net, &t);
                prop_assert_eq!(pieces.iter().map(|p| &p.net).collect::<Vec<_>>(), generic.iter().collect::<Vec<_>>());
                check_pieces(&net, &pieces, &q)?;
            }
            for (i, j) in [(0, 1), (m, 0), (1, m)] {
                if i != j {
                    let halves = halve(&net, i, j);
                    check_pieces(&net, &halves, &q)?;
                    for (h, d) in halves.iter().zip(halve_domains::<BigRational>(m, i, j)) {
                        prop_assert_eq!(&subpatch_generic(&net, &d).unwrap(), &h.net);
                    }
                    prop_assert_eq!(&add_and_halve(&net, i, j, HalvingOrder::TopDown), &halves[0].net);
                    prop_assert_eq!(&add_and_halve(&net, j, i, HalvingOrder::TopDown), &halves[1].net);
                }
            }
            if m == 2 {
                let four = midpoint_split(&net).unwrap();
                check_pieces(&net, &four, &q)?;
                for p in &four {
                    prop_assert_eq!(&subpatch_generic(&net, &p.domain_in_parent).unwrap(), &p.net);
                }
            }
        }
    }
}
