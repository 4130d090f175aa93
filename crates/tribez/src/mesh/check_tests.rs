//! [`Mesh::check_geometry`] against a brute-force reference: every pair of triangles and every
//! edge against every vertex, exact predicates only (no grid, no floats, no box filters), with
//! the listing order and truncation of the check written out independently.

use std::cmp::Ordering;
use std::collections::HashSet;

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

use super::*;
use crate::number::parse_rational;

fn q(s: &str) -> BigRational {
    parse_rational(s).unwrap()
}

fn exact_point_order(a: &[BigRational; 2], b: &[BigRational; 2]) -> Ordering {
    a[0].cmp(&b[0]).then_with(|| a[1].cmp(&b[1]))
}

/// The geometric problems, by brute force (the reference for [`Mesh::check_geometry`]).
fn reference(m: &Mesh) -> Vec<MeshError> {
    let p = |v: usize| &m.vertices()[v];
    let tris = m.triangles();
    let mut out = Vec::new();
    // Orientation, in triangle order.
    let mut good = Vec::new(); // (triangle, counter-clockwise vertices)
    for (t, tri) in tris.iter().enumerate() {
        let o = orient(p(tri[0]), p(tri[1]), p(tri[2]));
        if o.is_zero() {
            out.push(MeshError::Degenerate {
                triangle: t,
                vertices: *tri,
            });
            continue;
        }
        let mut ccw = *tri;
        if o.is_negative() {
            out.push(MeshError::Clockwise {
                triangle: t,
                vertices: *tri,
            });
            ccw.swap(1, 2);
        }
        good.push((t, ccw));
    }
    // Duplicate triangles: in each group with one vertex set (groups by sorted vertex set),
    // consecutive members by triangle number.
    let key = |t: usize| {
        let mut k = tris[t];
        k.sort_unstable();
        k
    };
    let mut by_key: Vec<usize> = (0..tris.len()).collect();
    by_key.sort_by_key(|&t| (key(t), t));
    for w in by_key.windows(2) {
        if key(w[0]) == key(w[1]) {
            out.push(MeshError::DuplicateTriangle {
                first: w[0],
                second: w[1],
            });
        }
    }
    // Vertices at one point: consecutive in the order by exact (x, y), then number.
    let mut order: Vec<usize> = (0..m.vertices().len()).collect();
    order.sort_by(|&a, &b| exact_point_order(p(a), p(b)).then(a.cmp(&b)));
    for w in order.windows(2) {
        if exact_point_order(p(w[0]), p(w[1])) == Ordering::Equal {
            out.push(MeshError::DuplicateVertex {
                first: w[0],
                second: w[1],
            });
        }
    }
    let used: HashSet<usize> = tris.iter().flatten().copied().collect();
    for v in 0..m.vertices().len() {
        if !used.contains(&v) {
            out.push(MeshError::UnusedVertex { vertex: v });
        }
    }
    if out.len() >= MAX_PROBLEMS {
        return out;
    }
    // Overlaps: every pair of non-degenerate triangles by the separating-axis test. When there
    // are too many, the first ones of a sweep by exact x_min are kept: pairs ranked by
    // (rank of the earlier triangle, rank of the later one), the rank ordering the triangles
    // by x_min, then by position in `good`.
    let xmin = |g: usize| good[g].1.iter().map(|&v| &p(v)[0]).min().unwrap();
    let mut rank_order: Vec<usize> = (0..good.len()).collect();
    rank_order.sort_by(|&g, &h| xmin(g).cmp(xmin(h)).then(g.cmp(&h)));
    let mut rank = vec![0; good.len()];
    for (r, &g) in rank_order.iter().enumerate() {
        rank[g] = r;
    }
    let inner = |a: [usize; 3], b: [usize; 3]| {
        // every edge of `a` has a vertex of `b` strictly on its inner side
        (0..3).all(|i| {
            b.iter()
                .any(|&r| orient(p(a[i]), p(a[(i + 1) % 3]), p(r)).is_positive())
        })
    };
    // (an exact box filter first, only to keep the reference quick: triangles whose interiors
    // meet have boxes whose interiors meet)
    let bounds = |g: usize, k: usize| {
        let c = good[g].1.map(|v| &p(v)[k]);
        (c.into_iter().min().unwrap(), c.into_iter().max().unwrap())
    };
    let boxes_meet = |g: usize, h: usize| {
        (0..2).all(|k| {
            let ((gl, gh), (hl, hh)) = (bounds(g, k), bounds(h, k));
            gl < hh && hl < gh
        })
    };
    let mut overlaps = Vec::new();
    for g in 0..good.len() {
        for h in g + 1..good.len() {
            if boxes_meet(g, h) && inner(good[g].1, good[h].1) && inner(good[h].1, good[g].1) {
                let (t, u) = (good[g].0, good[h].0);
                overlaps.push((
                    (rank[g].min(rank[h]), rank[g].max(rank[h])),
                    (t.min(u), t.max(u)),
                ));
            }
        }
    }
    overlaps.sort_unstable();
    overlaps.truncate(MAX_PROBLEMS - out.len());
    let mut overlaps: Vec<(usize, usize)> = overlaps.into_iter().map(|(_, pair)| pair).collect();
    overlaps.sort_unstable();
    out.extend(
        overlaps
            .into_iter()
            .map(|(first, second)| MeshError::Overlap { first, second }),
    );
    if out.len() >= MAX_PROBLEMS {
        return out;
    }
    // T-junctions: triangles in order, each edge once (where first met), its vertices inside
    // in the order of `order`.
    let mut seen = HashSet::new();
    for (t, tri) in tris.iter().enumerate() {
        for i in 0..3 {
            let (a, b) = (tri[i].min(tri[(i + 1) % 3]), tri[i].max(tri[(i + 1) % 3]));
            if !seen.insert((a, b)) {
                continue;
            }
            for &v in &order {
                if !used.contains(&v) || v == a || v == b {
                    continue;
                }
                // exact box first (a filter, only to keep the reference quick)
                let (lo, hi) = if p(a)[0] <= p(b)[0] { (a, b) } else { (b, a) };
                if p(v)[0] < p(lo)[0] || p(v)[0] > p(hi)[0] {
                    continue;
                }
                let dot = (&p(v)[0] - &p(a)[0]) * (&p(v)[0] - &p(b)[0])
                    + (&p(v)[1] - &p(a)[1]) * (&p(v)[1] - &p(b)[1]);
                if orient(p(a), p(b), p(v)).is_zero() && dot.is_negative() {
                    out.push(MeshError::TJunction {
                        vertex: v,
                        a,
                        b,
                        triangle: t,
                    });
                    if out.len() >= MAX_PROBLEMS {
                        return out;
                    }
                }
            }
        }
    }
    out
}

fn geometry(m: &Mesh) -> Vec<MeshError> {
    let mut out = Vec::new();
    m.check_geometry(&mut out);
    out
}

fn mesh(vertices: &[(&str, &str)], triangles: Vec<[usize; 3]>) -> Mesh {
    let vs = vertices.iter().map(|&(x, y)| [q(x), q(y)]).collect();
    Mesh::new(vs, triangles, 1).unwrap()
}

/// Coordinates on a small lattice (halves from −2 to 2), so that coincidences are common, and
/// now and then one that is no float (1/3, 0.1, ...) or very close to a lattice value.
fn coordinate() -> impl Strategy<Value = BigRational> {
    prop_oneof![
        8 => (-4i64..=4).prop_map(|k| BigRational::new(k.into(), 2.into())),
        1 => prop::sample::select(vec![
            "1/3", "-1/3", "2/3", "0.1", "-0.1", "0.3", "1e-30", "-1e-30", "1/2", "1.5",
            "0.5000000000000000000001", "7/10",
        ])
        .prop_map(q),
    ]
}

/// Three distinct vertices out of `n`, in a random rotation and orientation.
fn triangle(n: usize) -> impl Strategy<Value = [usize; 3]> {
    (
        prop::sample::subsequence((0..n).collect::<Vec<_>>(), 3),
        0..3usize,
        any::<bool>(),
    )
        .prop_map(|(s, rot, flip)| {
            let mut t = [s[0], s[1], s[2]];
            if flip {
                t.swap(1, 2);
            }
            t.rotate_left(rot);
            t
        })
}

/// Random triangles on random lattice points.
fn random_mesh() -> impl Strategy<Value = Mesh> {
    (3usize..=12)
        .prop_flat_map(|n| {
            (
                prop::collection::vec([coordinate(), coordinate()], n),
                prop::collection::vec(triangle(n), 1..=24),
            )
        })
        .prop_map(|(vertices, triangles)| Mesh::new(vertices, triangles, 1).unwrap())
}

/// A `k × k` lattice of squares cut along diagonals (a valid mesh), then damaged: some vertices
/// moved to nearby lattice or non-float points, some triangles added, some removed. Large enough
/// for the grid to have many cells and triangles that cover too many of them.
fn damaged_grid() -> impl Strategy<Value = Mesh> {
    (2usize..=8)
        .prop_flat_map(|k| {
            let n = (k + 1) * (k + 1);
            (
                Just(k),
                prop::collection::vec((0..n, coordinate(), coordinate()), 0..4),
                prop::collection::vec(triangle(n), 0..4),
                prop::collection::vec(any::<prop::sample::Index>(), 0..3),
                any::<bool>(),
            )
        })
        .prop_map(|(k, moves, extra, removed, flip)| {
            let side = k + 1;
            let mut vertices: Vec<[BigRational; 2]> = (0..side * side)
                .map(|i| {
                    let c = |j: usize| BigRational::new((j as i64).into(), 4.into());
                    [c(i % side), c(i / side)]
                })
                .collect();
            let quarter = BigRational::new(1.into(), 4.into());
            for (v, dx, dy) in moves {
                vertices[v] = [
                    &vertices[v][0] + dx * &quarter,
                    &vertices[v][1] + dy * &quarter,
                ];
            }
            let mut triangles = Vec::new();
            for j in 0..k {
                for i in 0..k {
                    let a = j * side + i;
                    let (b, c, d) = (a + 1, a + side + 1, a + side);
                    if flip && (i + j) % 2 == 1 {
                        triangles.extend([[a, b, d], [b, c, d]]);
                    } else {
                        triangles.extend([[a, b, c], [a, c, d]]);
                    }
                }
            }
            for r in removed {
                if triangles.len() > 1 {
                    triangles.remove(r.index(triangles.len()));
                }
            }
            triangles.extend(extra);
            Mesh::new(vertices, triangles, 1).unwrap()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_meshes_agree_with_the_reference(m in random_mesh()) {
        prop_assert_eq!(geometry(&m), reference(&m));
    }

    #[test]
    fn damaged_grids_agree_with_the_reference(m in damaged_grid()) {
        prop_assert_eq!(geometry(&m), reference(&m));
    }
}

#[test]
fn a_tiny_orientation_is_decided_exactly() {
    // 0=(0,0) 1=(1,0) 2=(1/2, 10^-30) 3=(1/2, 0) 4=(1/2, -1) 5=(1/2, 1). Triangle 0 = (0, 1, 2)
    // has area 10^-30/2 > 0: counter-clockwise, not degenerate (its orientation rounded to
    // floats cannot be told from 0). Below edge 0–1: 1 = (0, 4, 3) and 2 = (3, 4, 1), split at
    // 3 = (1/2, 0), the midpoint of 0–1: a T-junction of edge 0–1 (first met in triangle 0).
    // Above: 3 = (0, 2, 5) and 4 = (2, 1, 5), which with triangle 0 tile the triangle
    // (0,0), (1,0), (1/2,1): no overlap. Vertex 2 is 10^-30 above 0–1, not on it.
    let m = mesh(
        &[
            ("0", "0"),
            ("1", "0"),
            ("1/2", "1e-30"),
            ("1/2", "0"),
            ("1/2", "-1"),
            ("1/2", "1"),
        ],
        vec![[0, 1, 2], [0, 4, 3], [3, 4, 1], [0, 2, 5], [2, 1, 5]],
    );
    let expected = vec![MeshError::TJunction {
        vertex: 3,
        a: 0,
        b: 1,
        triangle: 0,
    }];
    assert_eq!(geometry(&m), expected);
    assert_eq!(reference(&m), expected);
    // (0, 2, 1) is clockwise by 10^-30; it lies inside (0, 1, 3) with 3 = (1/2, 2·10^-30),
    // which shares edge 0–1 with it: an overlap. Vertex 2 is on no edge of (0, 1, 3): edge
    // 0–3 reaches x = 1/2 only at 3.
    let m = mesh(
        &[("0", "0"), ("1", "0"), ("1/2", "1e-30"), ("1/2", "2e-30")],
        vec![[0, 2, 1], [0, 1, 3]],
    );
    let expected = vec![
        MeshError::Clockwise {
            triangle: 0,
            vertices: [0, 2, 1],
        },
        MeshError::Overlap {
            first: 0,
            second: 1,
        },
    ];
    assert_eq!(geometry(&m), expected);
    assert_eq!(reference(&m), expected);
    // A vertex on the line of an edge but 10^-30 beyond its end: no T-junction; and one
    // 10^-30 before the end: a T-junction. 0=(0,0) 1=(1,0) 2=(1/2,1) 3=(1+10^-30, 0)
    // 4=(1−10^-30, 0) 5=(1/2,−1): triangles (0, 1, 2), (0, 5, 4), (4, 5, 3).
    let m = mesh(
        &[
            ("0", "0"),
            ("1", "0"),
            ("1/2", "1"),
            ("1.000000000000000000000000000001", "0"),
            ("0.999999999999999999999999999999", "0"),
            ("1/2", "-1"),
        ],
        vec![[0, 1, 2], [0, 5, 4], [4, 5, 3]],
    );
    let got = geometry(&m);
    assert_eq!(got, reference(&m));
    assert_eq!(
        got,
        vec![
            // (4, 5, 3) and (0, 1, 2) meet only along 4–1 (on the x axis): no overlap.
            MeshError::TJunction {
                vertex: 4,
                a: 0,
                b: 1,
                triangle: 0
            },
            // 1 = (1, 0) lies between 4 and 3 on edge 3–4.
            MeshError::TJunction {
                vertex: 1,
                a: 3,
                b: 4,
                triangle: 2
            },
        ]
    );
}

#[test]
fn coordinates_beyond_floats_are_decided_exactly() {
    // The square of side 10^400 (its coordinates round to infinity) cut along 0–2, with a
    // vertex 4 at the midpoint of the diagonal used by a third triangle (4, 1, 2) inside
    // (0, 1, 2): an overlap and a T-junction of edge 0–2 (first met in triangle 0).
    let big = "1e400";
    let half = "5e399";
    let m = mesh(
        &[
            ("0", "0"),
            (big, "0"),
            (big, big),
            ("0", big),
            (half, half),
            ("-1e400", "1"),
        ],
        vec![[0, 1, 2], [0, 2, 3], [4, 1, 2]],
    );
    let got = geometry(&m);
    assert_eq!(got, reference(&m));
    assert_eq!(
        got,
        vec![
            MeshError::UnusedVertex { vertex: 5 },
            MeshError::Overlap {
                first: 0,
                second: 2
            },
            MeshError::TJunction {
                vertex: 4,
                a: 0,
                b: 2,
                triangle: 0
            },
        ]
    );
    // Beyond floats on one side only (10^400 and −1): a valid mesh.
    let m = mesh(
        &[("-1", "-1"), (big, "-1"), (big, big), ("-1", big)],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    assert!(geometry(&m).is_empty());
}

/// A deterministic shuffle of `0..n` (so that triangle numbers and x order differ).
fn shuffled(n: usize) -> Vec<usize> {
    let mut order: Vec<usize> = (0..n).collect();
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    for i in (1..n).rev() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        order.swap(i, (state % (i as u64 + 1)) as usize);
    }
    order
}

#[test]
fn too_many_overlaps_are_cut_as_the_reference_cuts_them() {
    // 60 triangles (k/100, 0), (1 + k/100, 0), (1/2 + k/100, 1), shuffled: every two overlap
    // (1770 pairs), so which 1000 are listed depends on the order of the sweep in x.
    let n = 60;
    let mut vertices = Vec::new();
    for k in 0..n {
        let s = BigRational::new((k as i64).into(), 100.into());
        vertices.push([s.clone(), BigRational::zero()]);
        vertices.push([
            &s + BigRational::from_integer(1.into()),
            BigRational::zero(),
        ]);
        vertices.push([&s + q("1/2"), BigRational::from_integer(1.into())]);
    }
    let triangles = shuffled(n)
        .into_iter()
        .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    let m = Mesh::new(vertices, triangles, 1).unwrap();
    let got = geometry(&m);
    assert_eq!(got.len(), MAX_PROBLEMS);
    assert_eq!(got, reference(&m));
}

#[test]
fn too_many_t_junctions_are_cut_as_the_reference_cuts_them() {
    // Above the segment (0,0)–(1,0): triangle (0, 1, 2) with 2 = (1/2, 1); below it a fan of
    // 1100 triangles from 3 = (1/2, −1) to the points k/1100 on the segment, which are
    // numbered in a shuffled order: 1099 T-junctions on edge 0–1, listed by x, the first 1000
    // kept.
    let n = 1100;
    let mut vertices = vec![
        [q("0"), q("0")],
        [q("1"), q("0")],
        [q("1/2"), q("1")],
        [q("1/2"), q("-1")],
    ];
    // vertex 4 + i sits at x = (numbers[i] + 1)/n; by_x[j] is the vertex at x = j/n
    let numbers = shuffled(n - 1);
    let mut by_x = vec![0; n + 1];
    by_x[n] = 1;
    for (i, &j) in numbers.iter().enumerate() {
        vertices.push([
            BigRational::new((j as i64 + 1).into(), (n as i64).into()),
            q("0"),
        ]);
        by_x[j + 1] = 4 + i;
    }
    let mut triangles = vec![[0, 1, 2]];
    triangles.extend((0..n).map(|k| [by_x[k], 3, by_x[k + 1]]));
    let m = Mesh::new(vertices, triangles, 1).unwrap();
    let got = geometry(&m);
    assert_eq!(got.len(), MAX_PROBLEMS);
    assert_eq!(got, reference(&m));
    assert_eq!(
        got[0],
        MeshError::TJunction {
            vertex: by_x[1],
            a: 0,
            b: 1,
            triangle: 0
        }
    );
}

#[test]
fn a_triangle_over_a_grid_is_checked_against_every_cell() {
    // The 8 × 8 lattice of squares of side 1/4 cut along the diagonals (i, j)–(i+1, j+1), plus
    // triangle 128 = (0,0), (2,0), (2,2) over its lower right half. With 129 triangles the
    // grid has 12 × 12 cells; triangle 128 covers all of them (it is tested everywhere) and so
    // does its diagonal edge (whose candidates come from the scan in x). It overlaps the
    // triangles below the diagonal: both of each square right of it (2 · 28) and the lower one
    // of each square on it (8): 64. Its edges pass through 7 lattice vertices each: 21
    // T-junctions, listed by x, then y.
    let side = 9;
    let at = |i: usize, j: usize| j * side + i;
    let vertices: Vec<[BigRational; 2]> = (0..side * side)
        .map(|v| {
            let c = |k: usize| BigRational::new((k as i64).into(), 4.into());
            [c(v % side), c(v / side)]
        })
        .collect();
    let mut triangles = Vec::new();
    for j in 0..side - 1 {
        for i in 0..side - 1 {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            triangles.extend([[a, b, c], [a, c, d]]);
        }
    }
    triangles.push([at(0, 0), at(8, 0), at(8, 8)]);
    let m = Mesh::new(vertices, triangles, 1).unwrap();
    let got = geometry(&m);
    assert_eq!(got, reference(&m));
    let overlaps = got
        .iter()
        .filter(|e| matches!(e, MeshError::Overlap { second: 128, .. }))
        .count();
    assert_eq!((got.len(), overlaps), (64 + 21, 64));
    // the bottom edge 0–8 first: its vertices (1/4, 0), (2/4, 0), ... by x
    assert_eq!(
        got[64],
        MeshError::TJunction {
            vertex: 1,
            a: 0,
            b: 8,
            triangle: 128
        }
    );
}
