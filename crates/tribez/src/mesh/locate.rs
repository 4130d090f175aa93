//! Exact point location in a mesh (docs/theory.md §17).
//!
//! The predicates are exact signs of `2×2` determinants of rationals:
//! `orient(p, q, r) = (q − p) × (r − p) = (q_x − p_x)(r_y − p_y) − (q_y − p_y)(r_x − p_x)`,
//! positive when `p, q, r` turn counter-clockwise. The barycentric coordinates of `x` in the
//! counter-clockwise triangle `(p0, p1, p2)` are `λ_i = orient(x, p_{i+1}, p_{i+2}) / D` with
//! `D = orient(p0, p1, p2) > 0`; `x` lies in the closed triangle iff every `λ_i ≥ 0`.
//!
//! To avoid testing every triangle, a uniform grid over the mesh's bounding box lists the
//! triangles whose bounding box meets each cell. Cells are found with the `f64` nearest to the
//! exact coordinates; rounding to nearest is monotone, so `x_min ≤ x ≤ x_max` implies
//! `fl(x_min) ≤ fl(x) ≤ fl(x_max)` and every monotone cell map keeps a triangle's candidates:
//! the grid only filters, the answer comes from the exact predicates.

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::number::round_f64;

/// `(q − p) × (r − p)`, exact: positive iff `p, q, r` turn counter-clockwise.
pub fn orient(p: &[BigRational; 2], q: &[BigRational; 2], r: &[BigRational; 2]) -> BigRational {
    (&q[0] - &p[0]) * (&r[1] - &p[1]) - (&q[1] - &p[1]) * (&r[0] - &p[0])
}

/// Barycentric coordinates of `x` relative to `(p0, p1, p2)` (which must not be collinear):
/// `λ_i = orient(x, p_{i+1}, p_{i+2}) / orient(p0, p1, p2)`. They sum to 1 exactly.
pub fn barycentric(tri: [&[BigRational; 2]; 3], x: &[BigRational; 2]) -> [BigRational; 3] {
    let d = orient(tri[0], tri[1], tri[2]);
    let l1 = orient(x, tri[2], tri[0]) / &d;
    let l2 = orient(x, tri[0], tri[1]) / &d;
    let l0 = BigRational::from_integer(1.into()) - &l1 - &l2;
    [l0, l1, l2]
}

/// One triangle containing a point, with the point's exact barycentric coordinates relative to
/// the triangle's vertices in file order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Located {
    /// The triangle (0-based).
    pub triangle: usize,
    /// `(λ0, λ1, λ2)`, each `≥ 0`, summing to 1.
    pub barycentric: [BigRational; 3],
}

impl Located {
    /// Where in the triangle: `"interior"`, `"edge a–b"` or `"vertex v"` (given its vertices).
    pub fn position(&self, vertices: [usize; 3]) -> String {
        let zero: Vec<usize> = (0..3).filter(|&i| self.barycentric[i].is_zero()).collect();
        match zero.len() {
            0 => "interior".into(),
            1 => {
                let (a, b) = (vertices[(zero[0] + 1) % 3], vertices[(zero[0] + 2) % 3]);
                format!("edge {}–{}", a.min(b), a.max(b))
            }
            _ => {
                let i = (0..3).find(|i| !zero.contains(i)).unwrap_or(0);
                format!("vertex {}", vertices[i])
            }
        }
    }
}

/// The triangles whose (closed) bounding boxes meet each cell of a uniform grid.
#[derive(Debug, Clone)]
pub(crate) struct Grid {
    x0: f64,
    y0: f64,
    /// Cells per unit length.
    sx: f64,
    sy: f64,
    side: usize,
    cells: Vec<Vec<u32>>,
    /// Triangles covering too many cells, or everything if the box is not finite: always tested.
    everywhere: Vec<u32>,
    /// Each triangle's cells `[cx0, cx1, cy0, cy1]` (inclusive; the cells of its rounded box,
    /// also for those in `everywhere`).
    ranges: Vec<[u16; 4]>,
}

/// A triangle covering more cells than this is tested for every point instead.
pub(crate) const MAX_CELLS_PER_TRIANGLE: usize = 64;
/// The grid has at most `MAX_SIDE²` cells (a side fits in `u16`).
const MAX_SIDE: usize = 1024;

impl Grid {
    pub(crate) fn new(vertices: &[[BigRational; 2]], triangles: &[[usize; 3]]) -> Grid {
        let fv: Vec<[f64; 2]> = vertices
            .iter()
            .map(|v| [round_f64(&v[0]), round_f64(&v[1])])
            .collect();
        Grid::from_floats(&fv, triangles)
    }

    /// The grid from the vertices rounded to nearest (`fv[v] = [fl(x_v), fl(y_v)]`).
    pub(crate) fn from_floats(fv: &[[f64; 2]], triangles: &[[usize; 3]]) -> Grid {
        let bbox = |t: &[usize; 3]| {
            let xs = t.map(|i| fv[i][0]);
            let ys = t.map(|i| fv[i][1]);
            (
                xs.iter().copied().fold(f64::INFINITY, f64::min),
                xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                ys.iter().copied().fold(f64::INFINITY, f64::min),
                ys.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            )
        };
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for t in triangles {
            let (a, b, c, d) = bbox(t);
            x0 = x0.min(a);
            x1 = x1.max(b);
            y0 = y0.min(c);
            y1 = y1.max(d);
        }
        let side = ((triangles.len() as f64).sqrt().ceil() as usize).clamp(1, MAX_SIDE);
        let (sx, sy) = (side as f64 / (x1 - x0), side as f64 / (y1 - y0));
        if !(sx.is_finite() && sy.is_finite() && x0.is_finite() && y0.is_finite()) || side == 1 {
            return Grid {
                x0: 0.0,
                y0: 0.0,
                sx: 0.0,
                sy: 0.0,
                side: 1,
                cells: vec![Vec::new()],
                everywhere: by_xmin(fv, triangles).map(|i| i as u32).collect(),
                ranges: vec![[0; 4]; triangles.len()],
            };
        }
        let mut grid = Grid {
            x0,
            y0,
            sx,
            sy,
            side,
            cells: vec![Vec::new(); side * side],
            everywhere: Vec::new(),
            ranges: vec![[0; 4]; triangles.len()],
        };
        for i in by_xmin(fv, triangles) {
            let (a, b, c, d) = bbox(&triangles[i]);
            let r = grid.box_cells(a, b, c, d);
            grid.ranges[i] = r.map(|c| c as u16);
            let [cx0, cx1, cy0, cy1] = r;
            if (cx1 - cx0 + 1) * (cy1 - cy0 + 1) > MAX_CELLS_PER_TRIANGLE {
                grid.everywhere.push(i as u32);
                continue;
            }
            for cy in cy0..=cy1 {
                for cx in cx0..=cx1 {
                    grid.cells[cy * side + cx].push(i as u32);
                }
            }
        }
        grid
    }

    /// The cell of coordinate `v`: `floor((v − origin)·scale)` clamped, monotone in `v`.
    fn cell(&self, v: f64, origin: f64, scale: f64) -> usize {
        let c = ((v - origin) * scale).floor();
        if c.is_nan() || c < 0.0 {
            0
        } else {
            (c as usize).min(self.side - 1)
        }
    }

    /// Cells per row (and per column); 1 when every triangle is in `everywhere`.
    pub(crate) fn side(&self) -> usize {
        self.side
    }

    /// The cell `cy·side + cx` of the point `(x, y)` (rounded to `f64`).
    pub(crate) fn point_cell(&self, x: f64, y: f64) -> usize {
        self.cell(y, self.y0, self.sy) * self.side + self.cell(x, self.x0, self.sx)
    }

    /// The cells `[cx0, cx1, cy0, cy1]` (inclusive) of the box `[xmin, xmax] × [ymin, ymax]`
    /// (rounded to `f64`): every point of the box is in one of them.
    pub(crate) fn box_cells(&self, xmin: f64, xmax: f64, ymin: f64, ymax: f64) -> [usize; 4] {
        [
            self.cell(xmin, self.x0, self.sx),
            self.cell(xmax, self.x0, self.sx),
            self.cell(ymin, self.y0, self.sy),
            self.cell(ymax, self.y0, self.sy),
        ]
    }

    /// Triangle `t`'s cells `[cx0, cx1, cy0, cy1]`, and whether it is listed in them (`false`:
    /// it is in `everywhere`).
    pub(crate) fn triangle_cells(&self, t: usize) -> ([usize; 4], bool) {
        let r = self.ranges[t].map(usize::from);
        let listed =
            self.side > 1 && (r[1] - r[0] + 1) * (r[3] - r[2] + 1) <= MAX_CELLS_PER_TRIANGLE;
        (r, listed)
    }

    /// The triangles listed in cell `c` (`cy·side + cx`), by increasing rounded `x_min`.
    pub(crate) fn cell_triangles(&self, c: usize) -> &[u32] {
        &self.cells[c]
    }

    /// The triangles tested for every point, by increasing rounded `x_min`.
    pub(crate) fn everywhere(&self) -> &[u32] {
        &self.everywhere
    }

    /// The triangles to test for the point `(x, y)` (rounded to `f64`).
    pub(crate) fn candidates(&self, x: f64, y: f64) -> impl Iterator<Item = usize> + '_ {
        let cell = if self.side == 1 {
            &self.cells[0]
        } else {
            &self.cells[self.point_cell(x, y)]
        };
        cell.iter()
            .chain(self.everywhere.iter())
            .map(|&i| i as usize)
    }
}

/// The triangles by increasing rounded `x_min` (the minimum of the rounded `x` of their
/// vertices), then number: the order of every list of the grid.
fn by_xmin(fv: &[[f64; 2]], triangles: &[[usize; 3]]) -> impl Iterator<Item = usize> {
    let xmin = |t: &[usize; 3]| t.iter().map(|&v| fv[v][0]).fold(f64::INFINITY, f64::min);
    let mut keyed: Vec<(f64, usize)> = triangles
        .iter()
        .enumerate()
        .map(|(i, t)| (xmin(t), i))
        .collect();
    keyed.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    keyed.into_iter().map(|(_, i)| i)
}

/// Whether every `λ` is `≥ 0`, from the numerators alone (the denominator is positive).
pub(crate) fn inside(tri: [&[BigRational; 2]; 3], x: &[BigRational; 2]) -> bool {
    !orient(x, tri[1], tri[2]).is_negative()
        && !orient(x, tri[2], tri[0]).is_negative()
        && !orient(x, tri[0], tri[1]).is_negative()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::number::parse_rational;

    fn p(x: &str, y: &str) -> [BigRational; 2] {
        [parse_rational(x).unwrap(), parse_rational(y).unwrap()]
    }

    #[test]
    fn barycentric_by_hand() {
        // Triangle (0,0), (4,0), (0,2); point (1, 1/2): λ1 = x/4 = 1/4, λ2 = y/2 = 1/4,
        // λ0 = 1/2 (the triangle is the image of the reference one under x = 4λ1, y = 2λ2).
        let (a, b, c) = (p("0", "0"), p("4", "0"), p("0", "2"));
        let l = barycentric([&a, &b, &c], &p("1", "1/2"));
        let q = |s: &str| parse_rational(s).unwrap();
        assert_eq!(l, [q("1/2"), q("1/4"), q("1/4")]);
        assert!(inside([&a, &b, &c], &p("2", "1"))); // on the hypotenuse
        assert!(!inside([&a, &b, &c], &p("2", "1.0000000000000000000001")));
        assert!(orient(&a, &b, &c) > BigRational::zero());
    }
}
