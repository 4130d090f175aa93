//! Mesh files: reading, writing back, and one test per kind of bad input.

use super::*;
use crate::io::tree::Document;
use crate::number::parse_rational;

fn q(s: &str) -> BigRational {
    parse_rational(s).unwrap()
}

const SQUARE: &str = r#"
name = "unit square, f = x^2, quadratic"
degree = 2
vertices = [["0", "0"], [1, 0], ["1", "1"], ["0", "1"]]
triangles = [[0, 1, 2],
             [0, 2, 3]]

[ordinates]
vertex = ["0", "1", "1", "0"]
[ordinates.edge]
0-1 = ["0"]
0-2 = ["0"]
0-3 = ["0"]
1-2 = ["1"]
2-3 = ["0"]
"#;

fn toml(text: &str) -> Result<(Mesh, MeshLines), InputError> {
    mesh_from_document(&Document::parse_toml("m.toml", text)?)
}

fn json(text: &str) -> Result<(Mesh, MeshLines), InputError> {
    mesh_from_document(&Document::parse_json("m.json", text)?)
}

use crate::io::InputError;

#[test]
fn reads_the_square_and_writes_it_back() {
    let (m, lines) = toml(SQUARE).unwrap();
    assert_eq!(m.degree(), 2);
    assert_eq!(m.ordinate_count(), 9);
    assert!(m.check().is_empty());
    assert_eq!(lines.triangles, [5, 6]);
    // f = x² (the blossom x₁x₂ at the edges): at (1/3, 1/4), 1/9.
    let hits = m.lookup(&[q("1/3"), q("1/4")]).unwrap();
    assert_eq!(hits[0].1, q("1/9"));
    let again = Mesh::from_toml(&m.to_toml()).unwrap();
    assert_eq!(again, m);
    let again = Mesh::from_json(&m.to_json().to_string()).unwrap();
    assert_eq!(again, m);
    // Geometry only: written without an ordinates table, read back the same.
    let bare = m.with_degree(3).unwrap();
    assert!(!bare.to_toml().contains("ordinates"));
    assert_eq!(Mesh::from_toml(&bare.to_toml()).unwrap(), bare);
}

#[test]
fn json_mesh_with_interior_ordinates() {
    let text = r#"{"degree": 3, "vertices": [["0","0"],["1","0"],["0","1"]],
        "triangles": [[0,1,2]],
        "ordinates": {"vertex": [1, 2, 3],
                      "edge": {"0-1": [4, 5], "0-2": [6, 7], "1-2": [8, 9]},
                      "interior": {"0": ["1/7"]}}}"#;
    let (m, _) = json(text).unwrap();
    assert!(m.check().is_empty());
    // Canonical order of the one triangle: 300 210 120 030 201 111 021 102 012 003
    // = vertex 0, edge 0–1 k=1, edge 0–1 k=2, vertex 1, edge 0–2 k=1, interior, edge 1–2 k=1,
    //   edge 0–2 k=2, edge 1–2 k=2, vertex 2.
    let b: Vec<String> = m
        .triangle_ordinates(0)
        .unwrap()
        .iter()
        .map(|x| x.to_string())
        .collect();
    assert_eq!(b, ["1", "4", "5", "2", "6", "1/7", "8", "7", "9", "3"]);
    assert_eq!(Mesh::from_toml(&m.to_toml()).unwrap(), m);
}

/// The error of `text` (TOML) as one line.
fn error(text: &str) -> String {
    let e = toml(text).unwrap_err().to_string();
    assert_eq!(e.lines().count(), 1, "{e}");
    e
}

fn with(replace: &str, by: &str) -> String {
    assert!(SQUARE.contains(replace), "{replace}");
    SQUARE.replacen(replace, by, 1)
}

#[test]
fn every_bad_input_is_one_located_line() {
    let cases: Vec<(String, &str)> = vec![
        (with("degree = 2\n", ""), "m.toml:1: missing key `degree`"),
        (
            with("degree = 2", "degree = 0"),
            "m.toml:3: degree: degree 0 is out of range: a mesh has degree 1 to 30",
        ),
        (
            with("degree = 2", "degree = 31"),
            "m.toml:3: degree: degree 31 is out of range",
        ),
        (
            with("degree = 2", "degree = -1"),
            "m.toml:3: degree: `-1` is not a non-negative integer",
        ),
        (
            with("name =", "nmae ="),
            "m.toml:2: nmae: unknown key (expected one of: name, degree, vertices, triangles, ordinates)",
        ),
        (
            with("vertices = [", "vertices = 3 # ["),
            "m.toml:4: vertices: expected an array, found a number",
        ),
        (
            with(
                r#"[["0", "0"], [1, 0], ["1", "1"], ["0", "1"]]"#,
                r#"[["0", "0"], [1, 0]]"#,
            ),
            "m.toml:4: vertices: vertices: 2, expected 3 to 1000000",
        ),
        (
            with(r#"[1, 0]"#, r#"[1, 0, 0]"#),
            "m.toml:4: vertices[1]: 3 entries, expected 2",
        ),
        (
            with(r#"["1", "1"]"#, r#"["1", "1/0"]"#),
            "m.toml:4: vertices[2][1]:",
        ),
        (
            with("[0, 2, 3]]", "[0, 2]]"),
            "m.toml:6: triangles[1]: 2 entries, expected 3",
        ),
        (
            with("[0, 2, 3]]", "[0, 2, 4]]"),
            "m.toml:6: triangles[1][2]: triangle 1 names vertex 4, but the vertices are 0 to 3",
        ),
        (
            with("[0, 2, 3]]", "[0, 2, 0]]"),
            "m.toml:6: triangles[1][2]: triangle 1 names vertex 0 twice",
        ),
        (
            with("[0, 2, 3]]", "[0, 2, 1.5]]"),
            "m.toml:6: triangles[1][2]: `1.5` is not a non-negative integer",
        ),
        (
            with(
                "triangles = [[0, 1, 2],\n             [0, 2, 3]]",
                "triangles = []",
            ),
            "m.toml:5: triangles: triangles: 0, expected 1 to 2000000",
        ),
        (
            with(
                r#"vertex = ["0", "1", "1", "0"]"#,
                r#"vertex = ["0", "1", "1"]"#,
            ),
            "m.toml:9: ordinates.vertex: 3 entries, expected 4",
        ),
        (
            with(r#"vertex = ["0","#, r#"vertx = ["0","#),
            "m.toml:9: ordinates.vertx: unknown key (expected one of: vertex, edge, interior)",
        ),
        (
            with(r#"0-1 = ["0"]"#, r#"0-1 = ["0", "1"]"#),
            "m.toml:11: ordinates.edge.0-1: 2 entries, expected 1",
        ),
        (
            with(r#"0-1 = ["0"]"#, r#"0_1 = ["0"]"#),
            "m.toml:11: ordinates.edge.0_1: `0_1` is not an edge: write `a-b`, two vertex numbers with a < b",
        ),
        (
            with(r#"0-1 = ["0"]"#, r#"1-0 = ["0"]"#),
            "m.toml:11: ordinates.edge.1-0: write the lower vertex first (`0-1`)",
        ),
        (
            with(r#"0-1 = ["0"]"#, r#"1-3 = ["0"]"#),
            "m.toml:11: ordinates.edge.1-3: no triangle has the edge 1–3",
        ),
        (
            with(r#"0-1 = ["0"]"#, r#"00-1 = ["0"]"#).replacen("0-2 =", "0-1 =", 1),
            "m.toml:12: ordinates.edge.0-1: edge 0–1 given twice",
        ),
        (
            with(
                r#"0-1 = ["0"]"#,
                "0-1 = [\"0\"]\n[ordinates.interior]\n0 = [\"1\"]",
            ),
            "m.toml:13: ordinates.interior.0: `0` is not a triangle with interior ordinates (a mesh of degree 2 has none)",
        ),
        (
            with(r#"0-1 = ["0"]"#, r#"0-1 = [true]"#),
            "m.toml:11: ordinates.edge.0-1[0]: expected a number, found a boolean",
        ),
        (
            SQUARE[..SQUARE.find("[ordinates]").unwrap()].to_string() + "ordinates = 1\n",
            "m.toml:8: ordinates: expected a table, found a number",
        ),
        (
            with("name = \"unit square, f = x^2, quadratic\"", "name = 7"),
            "m.toml:2: name: expected a string, found a number",
        ),
    ];
    for (text, expected) in cases {
        let got = error(&text);
        assert!(
            got.starts_with(expected),
            "expected {expected:?}\n     got {got:?}"
        );
    }
    // Interior keys of a cubic mesh.
    let cubic = r#"degree = 3
vertices = [["0","0"],["1","0"],["0","1"]]
triangles = [[0,1,2]]
[ordinates.interior]
"#;
    for (key, expected) in [
        (
            "1",
            "`1` is not a triangle with interior ordinates (the triangles are 0 to 0)",
        ),
        (
            "x",
            "`x` is not a triangle with interior ordinates (not a triangle number)",
        ),
        ("00", "ordinates.interior.00: triangle 0 given twice"),
    ] {
        let text = format!("{cubic}0 = [\"1\"]\n{key} = [\"1\"]\n");
        let got = error(&text);
        assert!(got.contains(expected), "{got}");
    }
    let got = error(&format!("{cubic}0 = [\"1\", \"2\"]\n"));
    assert!(
        got.ends_with("ordinates.interior.0: 2 entries, expected 1"),
        "{got}"
    );
    // JSON syntax errors keep the parser's location.
    let e = json("{\"degree\": 2,\n \"vertices\": [}")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("m.json:2:"), "{e}");
}

#[test]
fn check_problems_are_located_at_their_line() {
    let text = with("[0, 2, 3]]", "[0, 3, 2]]");
    let (m, lines) = toml(&text).unwrap();
    let problems: Vec<String> = m
        .check()
        .into_iter()
        .map(|p| lines.locate(p).to_string())
        .collect();
    assert_eq!(
        problems,
        [
            "m.toml:6: triangles[1]: triangle 1 (vertices [0, 3, 2]) is clockwise: list its vertices counter-clockwise"
        ]
    );
    let text = SQUARE.replacen(r#"0-1 = ["0"]"#, "", 1);
    let (m, lines) = toml(&text).unwrap();
    let problems: Vec<String> = m
        .check()
        .into_iter()
        .map(|p| lines.locate(p).to_string())
        .collect();
    assert_eq!(
        problems,
        ["m.toml:8: ordinates: edge 0–1, ordinate 1 is missing"]
    );
}
