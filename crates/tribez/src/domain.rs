//! The domain simplex in `ℝ^m`, barycentric coordinates by Cramer's rule, and directional
//! coordinates (Floater's notes §2 and §4; docs/theory.md §2 and §11).
//!
//! For a triangle `T = [a1, a2, a3]` in the plane and a point `t`, the barycentric coordinates
//! solve `[1 1 1; x1 x2 x3; y1 y2 y3] (u, v, w)ᵀ = (1, t_x, t_y)ᵀ`, so `u = D1/D`, `v = D2/D`,
//! `w = D3/D` with `D = det M = 2·signedArea(T)` and `D_k` the determinant with column `k`
//! replaced by `(1, t)`. Directional coordinates of a vector `d` use `(0, d)` instead and sum to 0.
//!
//! ```
//! use tribez::hazmat::domain::Domain;
//! use tribez::hazmat::number::parse_rational as q;
//! let r = |v: &[&str]| v.iter().map(|s| q(s).unwrap()).collect::<Vec<_>>();
//! // docs/theory.md §2: T = (1,2), (7,3), (2,8)
//! let t = Domain::new(vec![r(&["1", "2"]), r(&["7", "3"]), r(&["2", "8"])]).unwrap();
//! let s = |v: Vec<num_rational::BigRational>| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
//! assert_eq!(s(t.barycentric(&r(&["3", "4"])).unwrap()), ["3/7", "2/7", "2/7"]);
//! assert_eq!(s(t.direction(&r(&["1", "-2"])).unwrap()), ["1/7", "8/35", "-13/35"]);
//! ```

use num_rational::BigRational;
use num_traits::{One, Zero};

use crate::error::CoreError;
pub use crate::number::{format_points, format_tuple};

/// A non-degenerate simplex with `m + 1` vertices in `ℚ^m`.
#[derive(Clone, Debug, PartialEq)]
pub struct Domain {
    vertices: Vec<Vec<BigRational>>,
    det: BigRational,
}

impl Domain {
    /// The simplex with the given vertices; an error if they are affinely dependent or their
    /// dimensions disagree.
    pub fn new(vertices: Vec<Vec<BigRational>>) -> Result<Self, CoreError> {
        let m = vertices.len().saturating_sub(1);
        if m == 0 {
            return Err(CoreError::DomainTooSmall);
        }
        for (i, v) in vertices.iter().enumerate() {
            if v.len() != m {
                return Err(CoreError::WrongLength {
                    what: format!("domain vertex {}", i + 1),
                    expected: m,
                    found: v.len(),
                });
            }
        }
        let det = determinant(homogeneous_matrix(&vertices, None));
        if det.is_zero() {
            return Err(CoreError::DegenerateDomain(format_points(&vertices)));
        }
        Ok(Domain { vertices, det })
    }

    /// The reference simplex: vertex `k` is the unit vector `e_{k+1}` for `k < m`, and the last
    /// vertex is the origin. For triangles `(1,0), (0,1), (0,0)`, so that `u = x`, `v = y`,
    /// `w = 1 − x − y` (Floater's notes).
    pub fn reference(m: usize) -> Self {
        let mut vertices = vec![vec![BigRational::zero(); m]; m + 1];
        for (k, v) in vertices.iter_mut().enumerate().take(m) {
            v[k] = BigRational::one();
        }
        // invariant: e_1, …, e_m and the origin are affinely independent for every m ≥ 1 (callers pass a patch's simplex dimension, which patch constructors keep ≥ 1)
        Domain::new(vertices).expect("the reference simplex is not degenerate")
    }

    /// Dimension `m`.
    pub fn m(&self) -> usize {
        self.vertices.len() - 1
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Vec<BigRational>] {
        &self.vertices
    }

    /// `det M`, which is `m!` times the signed volume (twice the signed area for triangles).
    pub fn determinant(&self) -> &BigRational {
        &self.det
    }

    /// Barycentric coordinates of a Cartesian point, by Cramer's rule.
    pub fn barycentric(&self, point: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        self.cramer(point, true)
    }

    /// Directional coordinates of a Cartesian vector (they sum to zero).
    pub fn direction(&self, vector: &[BigRational]) -> Result<Vec<BigRational>, CoreError> {
        self.cramer(vector, false)
    }

    /// The Cartesian point with barycentric coordinates `lambda`: `Σ λ_k a_k`.
    pub fn cartesian(&self, lambda: &[BigRational]) -> Vec<BigRational> {
        (0..self.m())
            .map(|c| {
                lambda
                    .iter()
                    .zip(&self.vertices)
                    .map(|(l, v)| l * &v[c])
                    .sum()
            })
            .collect()
    }

    fn cramer(&self, rhs: &[BigRational], point: bool) -> Result<Vec<BigRational>, CoreError> {
        let m = self.m();
        if rhs.len() != m {
            return Err(CoreError::WrongLength {
                what: if point {
                    "Cartesian point".into()
                } else {
                    "Cartesian vector".into()
                },
                expected: m,
                found: rhs.len(),
            });
        }
        let column: Vec<BigRational> = std::iter::once(if point {
            BigRational::one()
        } else {
            BigRational::zero()
        })
        .chain(rhs.iter().cloned())
        .collect();
        Ok((0..=m)
            .map(|k| {
                determinant(homogeneous_matrix(&self.vertices, Some((k, &column)))) / &self.det
            })
            .collect())
    }
}

/// The `(m+1)×(m+1)` matrix with columns `(1, a_k)`, column `replace.0` replaced.
fn homogeneous_matrix(
    vertices: &[Vec<BigRational>],
    replace: Option<(usize, &[BigRational])>,
) -> Vec<Vec<BigRational>> {
    let m = vertices.len() - 1;
    let mut rows = vec![vec![BigRational::zero(); m + 1]; m + 1];
    for (k, v) in vertices.iter().enumerate() {
        let col: Vec<BigRational> = match replace {
            Some((r, c)) if r == k => c.to_vec(),
            _ => std::iter::once(BigRational::one())
                .chain(v.iter().cloned())
                .collect(),
        };
        for (row, x) in rows.iter_mut().zip(col) {
            row[k] = x;
        }
    }
    rows
}

/// Exact determinant by Gaussian elimination over the rationals.
pub fn determinant(mut a: Vec<Vec<BigRational>>) -> BigRational {
    let n = a.len();
    let mut det = BigRational::one();
    for col in 0..n {
        let Some(pivot) = (col..n).find(|&r| !a[r][col].is_zero()) else {
            return BigRational::zero();
        };
        if pivot != col {
            a.swap(pivot, col);
            det = -det;
        }
        let p = a[col][col].clone();
        det *= &p;
        for r in col + 1..n {
            if a[r][col].is_zero() {
                continue;
            }
            let f = &a[r][col] / &p;
            let (top, bottom) = a.split_at_mut(r);
            for (x, pivot_row_x) in bottom[0][col..].iter_mut().zip(&top[col][col..]) {
                *x -= &f * pivot_row_x;
            }
        }
    }
    det
}

/// Check that barycentric coordinates have `m + 1` entries summing to one.
pub fn check_barycentric(lambda: &[BigRational], m: usize, what: &str) -> Result<(), CoreError> {
    if lambda.len() != m + 1 {
        return Err(CoreError::WrongLength {
            what: what.into(),
            expected: m + 1,
            found: lambda.len(),
        });
    }
    let sum: BigRational = lambda.iter().sum();
    if !sum.is_one() {
        return Err(CoreError::NotBarycentric {
            coords: format_tuple(lambda),
            sum: sum.to_string(),
        });
    }
    Ok(())
}

/// Check that a barycentric direction has `m + 1` entries summing to zero.
pub fn check_direction(d: &[BigRational], m: usize, what: &str) -> Result<(), CoreError> {
    if d.len() != m + 1 {
        return Err(CoreError::WrongLength {
            what: what.into(),
            expected: m + 1,
            found: d.len(),
        });
    }
    let sum: BigRational = d.iter().sum();
    if !sum.is_zero() {
        return Err(CoreError::DirectionSum {
            coords: format_tuple(d),
            sum: sum.to_string(),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational;
    use crate::testing::r;

    #[test]
    fn tetrahedron_cramer_theory_section_11() {
        let t = Domain::new(vec![
            r(&["0", "0", "0"]),
            r(&["2", "0", "0"]),
            r(&["0", "3", "0"]),
            r(&["1", "1", "4"]),
        ])
        .unwrap();
        assert_eq!(
            t.barycentric(&r(&["1/2", "1/2", "1"])).unwrap(),
            r(&["13/24", "1/8", "1/12", "1/4"])
        );
    }

    #[test]
    fn determinant_is_twice_the_signed_area() {
        let t = Domain::new(vec![r(&["1", "2"]), r(&["7", "3"]), r(&["2", "8"])]).unwrap();
        assert_eq!(t.determinant(), &parse_rational("35").unwrap());
        let cw = Domain::new(vec![r(&["1", "2"]), r(&["2", "8"]), r(&["7", "3"])]).unwrap();
        assert_eq!(cw.determinant(), &parse_rational("-35").unwrap());
    }

    #[test]
    fn degenerate_domain_is_an_error() {
        let e = Domain::new(vec![r(&["0", "0"]), r(&["1", "1"]), r(&["2", "2"])]).unwrap_err();
        assert!(matches!(e, CoreError::DegenerateDomain(_)));
    }

    #[test]
    fn reference_triangle_maps_x_y_to_u_v() {
        let t = Domain::reference(2);
        assert_eq!(
            t.barycentric(&r(&["1/4", "1/2"])).unwrap(),
            r(&["1/4", "1/2", "1/4"])
        );
        assert_eq!(t.cartesian(&r(&["1/4", "1/2", "1/4"])), r(&["1/4", "1/2"]));
    }
}
