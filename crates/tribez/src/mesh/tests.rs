//! Tests of the mesh type. Expected values are derived by hand in the comments.

use super::*;
use crate::batch::ResultsChecker;
use crate::number::parse_rational;

fn q(s: &str) -> BigRational {
    parse_rational(s).unwrap()
}

fn v(x: &str, y: &str) -> [BigRational; 2] {
    [q(x), q(y)]
}

/// The unit square 0=(0,0) 1=(1,0) 2=(1,1) 3=(0,1), cut along the diagonal 0–2.
fn square(n: usize) -> Mesh {
    Mesh::new(
        vec![v("0", "0"), v("1", "0"), v("1", "1"), v("0", "1")],
        vec![[0, 1, 2], [0, 2, 3]],
        n,
    )
    .unwrap()
}

#[test]
fn numbering_of_a_cubic_square() {
    let m = square(3);
    // Edges sorted: 0–1, 0–2, 0–3, 1–2, 2–3 (5 edges, 2 ordinates each), 2 interiors:
    // 4 + 10 + 2 = 16.
    assert_eq!(m.edges(), &[[0, 1], [0, 2], [0, 3], [1, 2], [2, 3]]);
    assert_eq!(m.ordinate_count(), 16);
    assert_eq!(m.ordinate_id(3), OrdinateId::Vertex { v: 3 });
    assert_eq!(m.ordinate_id(4), OrdinateId::Edge { a: 0, b: 1, k: 1 });
    assert_eq!(m.ordinate_id(7), OrdinateId::Edge { a: 0, b: 2, k: 2 });
    assert_eq!(m.ordinate_id(13), OrdinateId::Edge { a: 2, b: 3, k: 2 });
    assert_eq!(
        m.ordinate_id(15),
        OrdinateId::Interior {
            triangle: 1,
            index: 0,
            alpha: [1, 1, 1]
        }
    );
    // The shared edge 0–2 read from both triangles: in (0, 1, 2) α = (2, 0, 1) has weight 1
    // on vertex 2; in (0, 2, 3) α = (2, 1, 0) too: both are edge 0–2 ordinate 1 = 4 + 2.
    assert_eq!(m.global_index(0, [2, 0, 1]), 6);
    assert_eq!(m.global_index(1, [2, 1, 0]), 6);
    assert_eq!(m.global_index(0, [1, 0, 2]), 7);
    assert_eq!(m.global_index(1, [1, 2, 0]), 7);
    // Edge 1–2 in triangle 0: α = (0, 1, 2) puts 2 on vertex 2, the higher: ordinate 2.
    assert_eq!(m.global_index(0, [0, 1, 2]), 4 + 3 * 2 + 1);
    // Edge 2–3 in triangle 1 = (0, 2, 3): α = (0, 2, 1) puts 1 on vertex 3: ordinate 1.
    assert_eq!(m.global_index(1, [0, 2, 1]), 4 + 4 * 2);
    assert_eq!(m.global_index(1, [0, 0, 3]), 3);
    assert_eq!(m.global_index(0, [1, 1, 1]), 14);
    // Every global ordinate appears in some triangle, and ordinate_id inverts global_index.
    let mut hit = [false; 16];
    for t in 0..2 {
        for g in m.local_indices(t) {
            hit[g] = true;
        }
    }
    assert!(hit.iter().all(|&h| h));
    assert_eq!(m.abscissa(7), v("2/3", "2/3")); // ((0,0) + 2·(1,1))/3
    assert_eq!(m.abscissa(15), v("1/3", "2/3")); // ((0,0) + (1,1) + (0,1))/3
}

#[test]
fn degree_and_sizes_are_checked() {
    let m = square(2);
    assert_eq!(
        m.with_degree(0),
        Err(MeshError::Degree {
            degree: 0,
            max: MAX_MESH_DEGREE
        })
    );
    assert!(matches!(
        m.with_degree(MAX_MESH_DEGREE + 1),
        Err(MeshError::Degree { .. })
    ));
    assert_eq!(
        m.with_degree(4).unwrap().ordinate_count(),
        4 + 5 * 3 + 2 * 3
    );
    assert_eq!(
        m.with_ordinates(vec![q("1")]),
        Err(MeshError::OrdinateCount {
            expected: 9,
            found: 1
        })
    );
    let bad = Mesh::new(m.vertices().to_vec(), vec![[0, 1, 4]], 2);
    assert_eq!(
        bad,
        Err(MeshError::VertexOutOfRange {
            triangle: 0,
            vertex: 4,
            last: 3
        })
    );
    let bad = Mesh::new(m.vertices().to_vec(), vec![[0, 1, 2], [0, 2, 0]], 2);
    assert_eq!(
        bad,
        Err(MeshError::RepeatedVertex {
            triangle: 1,
            vertex: 0
        })
    );
    assert!(matches!(
        Mesh::new(m.vertices().to_vec(), vec![], 2),
        Err(MeshError::Count {
            what: "triangles",
            ..
        })
    ));
}

/// f(x, y) = x² on the square, degree 2: the blossom of x² is x₁x₂, so the ordinate at vertex
/// v is x_v² and at the edge a–b it is x_a x_b.
fn x_squared() -> Mesh {
    let m = square(2);
    let x = |i: usize| m.vertices()[i][0].clone();
    let ords = (0..m.ordinate_count())
        .map(|g| match m.ordinate_id(g) {
            OrdinateId::Vertex { v } => x(v) * x(v),
            OrdinateId::Edge { a, b, .. } => x(a) * x(b),
            OrdinateId::Interior { .. } => unreachable!("degree 2 has no interiors"),
        })
        .collect();
    m.with_ordinates(ords).unwrap()
}

#[test]
fn lookup_reproduces_x_squared() {
    let m = x_squared();
    // Interior of triangle 0 (below the diagonal): x = 1/3, y = 1/4.
    let hits = m.lookup(&v("1/3", "1/4")).unwrap();
    assert_eq!(hits.len(), 1);
    assert_eq!(hits[0].0.triangle, 0);
    assert_eq!(hits[0].1, q("1/9"));
    // In triangle 0 = (0,0),(1,0),(1,1): λ1 = x − y = 1/12, λ2 = y = 1/4, λ0 = 1 − x = 2/3.
    assert_eq!(hits[0].0.barycentric, [q("2/3"), q("1/12"), q("1/4")]);
    // On the diagonal both triangles contain the point and agree (C0): x² = 4/25.
    let hits = m.lookup(&v("2/5", "2/5")).unwrap();
    assert_eq!(
        hits.iter().map(|h| h.0.triangle).collect::<Vec<_>>(),
        [0, 1]
    );
    assert!(hits.iter().all(|h| h.1 == q("4/25")));
    assert_eq!(hits[0].0.position([0, 1, 2]), "edge 0–2");
    // At vertex 0 both, value 0; at vertex 2 both, value 1.
    let hits = m.lookup(&v("1", "1")).unwrap();
    assert_eq!(hits.len(), 2);
    assert!(hits.iter().all(|h| h.1 == q("1")));
    assert_eq!(hits[1].0.position([0, 2, 3]), "vertex 2");
    // Outside (barely): nothing.
    assert!(
        m.lookup(&v("1.000000000000000000001", "1/2"))
            .unwrap()
            .is_empty()
    );
    assert!(m.lookup(&v("-1/3", "1/2")).unwrap().is_empty());
}

#[test]
fn triangle_patch_is_the_functional_patch() {
    let m = x_squared();
    let patch = m.triangle_patch(1).unwrap();
    assert_eq!(patch.kind(), crate::PatchKind::Functional);
    // Triangle 1 = (0,0),(1,1),(0,1); the point λ = (1/2, 1/4, 1/4) is (1/4, 1/2): x² = 1/16.
    let value = patch.evaluate(&[q("1/2"), q("1/4"), q("1/4")]).unwrap();
    assert_eq!(value, [q("1/16")]);
    assert!(matches!(
        m.triangle_patch(2),
        Err(crate::Error::Mesh(MeshError::TriangleOutOfRange {
            triangle: 2,
            last: 1
        }))
    ));
    let empty = square(2);
    assert_eq!(
        empty.triangle_patch(0).unwrap_err().to_string(),
        "the ordinate of vertex 0 is missing"
    );
}

#[test]
fn a_valid_mesh_passes_the_check() {
    assert!(x_squared().check().is_empty());
    // Without ordinates, the geometry still passes; the ordinates are listed missing.
    let problems = square(2).check();
    assert_eq!(problems.len(), 9);
    assert_eq!(problems[4].to_string(), "edge 0–1, ordinate 1 is missing");
}

fn check(vertices: &[[&str; 2]], triangles: Vec<[usize; 3]>) -> Vec<MeshError> {
    let vs = vertices.iter().map(|p| v(p[0], p[1])).collect();
    let mut out = Vec::new();
    Mesh::new(vs, triangles, 1)
        .unwrap()
        .check_geometry(&mut out);
    out
}

const SQUARE: [[&str; 2]; 4] = [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]];

#[test]
fn check_finds_each_geometric_problem() {
    // Clockwise: (0, 2, 1) turns clockwise.
    assert_eq!(
        check(&SQUARE, vec![[0, 2, 1], [0, 2, 3]]),
        vec![MeshError::Clockwise {
            triangle: 0,
            vertices: [0, 2, 1]
        }]
    );
    // Degenerate: (0,0), (1,1), (2,2).
    let line = [["0", "0"], ["1", "1"], ["2", "2"], ["0", "1"]];
    let got = check(&line, vec![[0, 1, 2], [0, 1, 3]]);
    assert_eq!(
        got[0],
        MeshError::Degenerate {
            triangle: 0,
            vertices: [0, 1, 2]
        }
    );
    // Duplicate triangle (same vertices, rotated): also an overlap.
    let got = check(&SQUARE, vec![[0, 1, 2], [1, 2, 0], [0, 2, 3]]);
    assert_eq!(
        got,
        vec![
            MeshError::DuplicateTriangle {
                first: 0,
                second: 1
            },
            MeshError::Overlap {
                first: 0,
                second: 1
            }
        ]
    );
    // Two vertices at one point: a crack along the diagonal.
    let five = [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"], ["1", "1"]];
    assert_eq!(
        check(&five, vec![[0, 1, 2], [0, 4, 3]]),
        vec![MeshError::DuplicateVertex {
            first: 2,
            second: 4
        }]
    );
    // An unused vertex.
    let five = [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"], ["5", "5"]];
    assert_eq!(
        check(&five, vec![[0, 1, 2], [0, 2, 3]]),
        vec![MeshError::UnusedVertex { vertex: 4 }]
    );
    // Overlap: two triangles of the square on the same side of their common edge 0–2...
    let got = check(&SQUARE, vec![[0, 1, 2], [0, 1, 3]]);
    assert_eq!(
        got,
        vec![MeshError::Overlap {
            first: 0,
            second: 1
        }]
    );
    // ...and a small triangle inside a big one, touching nothing.
    let nested = [
        ["0", "0"],
        ["4", "0"],
        ["0", "4"],
        ["1", "1"],
        ["2", "1"],
        ["1", "2"],
    ];
    assert_eq!(
        check(&nested, vec![[0, 1, 2], [3, 4, 5]]),
        vec![MeshError::Overlap {
            first: 0,
            second: 1
        }]
    );
    // Touching along an edge or at a vertex only is no overlap.
    let touching = [["0", "0"], ["1", "0"], ["0", "1"], ["2", "0"], ["1", "1"]];
    assert!(check(&touching, vec![[0, 1, 2], [1, 3, 4]]).is_empty());
    // T-junction: 0=(0,0) 1=(2,0) 2=(1,2) 3=(1,-2) 4=(1,0). Above the x axis one triangle
    // (0, 1, 2); below it two, (0, 3, 4) and (4, 3, 1), split at 4, the midpoint of edge 0–1.
    let t = [["0", "0"], ["2", "0"], ["1", "2"], ["1", "-2"], ["1", "0"]];
    assert_eq!(
        check(&t, vec![[0, 1, 2], [0, 3, 4], [4, 3, 1]]),
        vec![MeshError::TJunction {
            vertex: 4,
            a: 0,
            b: 1,
            triangle: 0
        }]
    );
}

#[test]
fn lookups_from_a_reader_are_judged_as_from_a_file() {
    // f = x + 2y on the linear square: ordinates 0, 1, 3, 2 at (0,0), (1,0), (1,1), (0,1).
    let m = square(1)
        .with_ordinates(vec![q("0"), q("1"), q("3"), q("2")])
        .unwrap();
    let checker = crate::batch::MeshBatchChecker::new(m, &crate::batch::BatchOptions::default())
        .expect("a valid mesh");
    // rows: f(1/2, 1/4) = 1 (right, triangle 0), f(1/4, 1/2) = 5/4 (right, triangle 1),
    // f(1/2, 1/2) = 3/2 claimed 2 (line 4), and (2, 2) outside the mesh (line 5)
    let text = "x,y,value\n1/2,1/4,1\n1/4,1/2,5/4\n1/2,1/2,2\n2,2,6\n";
    let from_reader = checker
        .check_reader(
            std::io::Cursor::new(text),
            crate::batch::Format::Csv,
            "lookups",
            "square",
            &mut |_, _| {},
        )
        .unwrap();
    assert_eq!(
        (from_reader.checked, from_reader.passed, from_reader.failed),
        (4, 2, 2)
    );
    let mut lines: Vec<usize> = from_reader.failures.iter().map(|f| f.line).collect();
    lines.sort();
    assert_eq!(lines, [4, 5]);
    let outside = from_reader.failures.iter().find(|f| f.line == 5).unwrap();
    assert_eq!(outside.reason, "the point (2, 2) is outside the mesh");
    assert_eq!(
        (from_reader.file.as_str(), from_reader.patch.as_str()),
        ("lookups", "square")
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lookups.csv");
    std::fs::write(&path, text).unwrap();
    let from_file = checker.check_file(&path, "square", &mut |_, _| {}).unwrap();
    assert_eq!(
        (from_file.checked, from_file.passed, from_file.failed),
        (4, 2, 2)
    );
    let mut file_lines: Vec<usize> = from_file.failures.iter().map(|f| f.line).collect();
    file_lines.sort();
    assert_eq!(file_lines, lines);
}
