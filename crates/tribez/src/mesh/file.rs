//! Mesh files: TOML or JSON (by extension), the number syntax of patch files (docs/guide.md,
//! "Mesh files").
//!
//! ```toml
//! name = "unit square, quadratic"          # optional
//! degree = 2
//! vertices = [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]]
//! triangles = [[0, 1, 2], [0, 2, 3]]       # vertex indices, 0-based, counter-clockwise
//!
//! [ordinates]                              # optional: a mesh without ordinates is geometry only
//! vertex = ["0", "1", "2", "1"]            # one per vertex
//! [ordinates.edge]                         # n − 1 per edge "a-b" (a < b), from a to b
//! 0-1 = ["1/2"]
//! # …
//! [ordinates.interior]                     # (n−1)(n−2)/2 per triangle (n ≥ 3), canonical order
//! # 0 = ["1"]
//! ```
//!
//! Every size the file controls (vertices, triangles, degree, ordinates) is checked against the
//! caps of [`super`] before anything is allocated for it. Any ordinate may be absent (in an
//! absent table or key); `tribez mesh check` lists the absent ones.

use std::path::Path;

use num_rational::BigRational;
use serde_json::{Map, Value as Json, json};

use super::{MAX_MESH_DEGREE, MAX_ORDINATES, MAX_TRIANGLES, MAX_VERTICES, Mesh, MeshError};
use crate::io::tree::{Document, Node};
use crate::io::{InputError, Problem};

/// The keys of a mesh file.
pub const MESH_KEYS: &[&str] = &["name", "degree", "vertices", "triangles", "ordinates"];
/// The keys of its `ordinates` table.
pub const ORDINATE_KEYS: &[&str] = &["vertex", "edge", "interior"];

/// What is wrong in a mesh file (carried by [`Problem::Format`]).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum MeshFileProblem {
    /// An array of the wrong length.
    #[error("{found} entries, expected {expected}")]
    Length {
        /// Entries given.
        found: usize,
        /// Entries expected.
        expected: usize,
    },
    /// An edge key that is not `a-b` with two vertex numbers.
    #[error("`{key}` is not an edge: write `a-b`, two vertex numbers with a < b")]
    EdgeKey {
        /// The key.
        key: String,
    },
    /// An edge key with the higher vertex first.
    #[error(
        "write the lower vertex first (`{b}-{a}`): an edge's ordinates run from its lower to its higher vertex"
    )]
    EdgeOrder {
        /// The first vertex written.
        a: usize,
        /// The second.
        b: usize,
    },
    /// An edge no triangle has.
    #[error("no triangle has the edge {a}–{b}")]
    NoSuchEdge {
        /// Lower vertex.
        a: usize,
        /// Higher vertex.
        b: usize,
    },
    /// The same edge or triangle twice (keys spelled differently).
    #[error("{what} given twice")]
    Twice {
        /// `"edge 3–7"`, `"triangle 2"`.
        what: String,
    },
    /// Interior ordinates for a mesh of degree below 3, or for a triangle that does not exist.
    #[error("`{key}` is not a triangle with interior ordinates ({reason})")]
    InteriorKey {
        /// The key.
        key: String,
        /// Why.
        reason: String,
    },
    /// An invalid mesh (located at the entry at fault).
    #[error(transparent)]
    Mesh(#[from] MeshError),
}

impl From<MeshFileProblem> for Problem {
    fn from(problem: MeshFileProblem) -> Self {
        Problem::Format(crate::io::FormatProblem::new(problem))
    }
}

/// Where each part of a mesh is in its file, to locate [`Mesh::check`]'s problems.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MeshLines {
    /// The file name.
    pub file: String,
    /// The line of each vertex.
    pub vertices: Vec<usize>,
    /// The line of each triangle.
    pub triangles: Vec<usize>,
    /// The line of the `ordinates` table (or of `degree` without one).
    pub ordinates: usize,
}

impl MeshLines {
    /// `problem` as an error at the line and key of the entry it names first.
    pub fn locate(&self, problem: MeshError) -> InputError {
        let (line, key) = match &problem {
            MeshError::Degenerate { triangle, .. }
            | MeshError::Clockwise { triangle, .. }
            | MeshError::TJunction { triangle, .. } => self.triangle(*triangle),
            MeshError::DuplicateTriangle { second, .. } | MeshError::Overlap { second, .. } => {
                self.triangle(*second)
            }
            MeshError::DuplicateVertex { second, .. } => self.vertex(*second),
            MeshError::UnusedVertex { vertex } => self.vertex(*vertex),
            MeshError::MissingOrdinate(_) => (Some(self.ordinates), "ordinates".to_string()),
            _ => (None, String::new()),
        };
        let e = InputError::at(&self.file, line, None, MeshFileProblem::Mesh(problem));
        if key.is_empty() { e } else { e.with_key(key) }
    }

    fn triangle(&self, t: usize) -> (Option<usize>, String) {
        (self.triangles.get(t).copied(), format!("triangles[{t}]"))
    }

    fn vertex(&self, v: usize) -> (Option<usize>, String) {
        (self.vertices.get(v).copied(), format!("vertices[{v}]"))
    }
}

impl Mesh {
    /// Read a mesh file (`.toml` or `.json`).
    pub fn from_file(path: impl AsRef<Path>) -> Result<Mesh, crate::Error> {
        Ok(read_mesh(path.as_ref())?.0)
    }

    /// Parse a mesh file's text in TOML.
    pub fn from_toml(text: &str) -> Result<Mesh, crate::Error> {
        let doc = Document::parse_toml("<toml>", text)?;
        Ok(mesh_from_document(&doc)?.0)
    }

    /// Parse a mesh file's text in JSON.
    pub fn from_json(text: &str) -> Result<Mesh, crate::Error> {
        let doc = Document::parse_json("<json>", text)?;
        Ok(mesh_from_document(&doc)?.0)
    }

    /// The mesh file, TOML (numbers as exact strings; absent ordinates left out).
    pub fn to_toml(&self) -> String {
        let list = |v: &[BigRational]| {
            let items: Vec<String> = v.iter().map(|x| format!("\"{x}\"")).collect();
            format!("[{}]", items.join(", "))
        };
        let mut out = format!("degree = {}\nvertices = [", self.degree);
        let vs: Vec<String> = self.vertices.iter().map(|v| list(v)).collect();
        out += &vs.join(", ");
        out += "]\ntriangles = [";
        let ts: Vec<String> = self
            .triangles
            .iter()
            .map(|t| format!("[{}, {}, {}]", t[0], t[1], t[2]))
            .collect();
        out += &ts.join(", ");
        out += "]\n";
        let parts = self.ordinate_parts();
        if parts.is_empty() {
            return out;
        }
        out += "\n[ordinates]\n";
        if let Some(v) = &parts.vertex {
            out += &format!("vertex = {}\n", list(v));
        }
        if !parts.edge.is_empty() {
            out += "\n[ordinates.edge]\n";
            for (key, v) in &parts.edge {
                out += &format!("{key} = {}\n", list(v));
            }
        }
        if !parts.interior.is_empty() {
            out += "\n[ordinates.interior]\n";
            for (t, v) in &parts.interior {
                out += &format!("{t} = {}\n", list(v));
            }
        }
        out
    }

    /// The mesh file, JSON (the same keys as TOML).
    pub fn to_json(&self) -> Json {
        let list =
            |v: &[BigRational]| Json::Array(v.iter().map(|x| json!(x.to_string())).collect());
        let mut obj = Map::new();
        obj.insert("degree".into(), json!(self.degree));
        obj.insert(
            "vertices".into(),
            Json::Array(self.vertices.iter().map(|v| list(v)).collect()),
        );
        obj.insert("triangles".into(), json!(self.triangles));
        let parts = self.ordinate_parts();
        if !parts.is_empty() {
            let mut o = Map::new();
            if let Some(v) = &parts.vertex {
                o.insert("vertex".into(), list(v));
            }
            if !parts.edge.is_empty() {
                let e = parts.edge.iter().map(|(k, v)| (k.clone(), list(v)));
                o.insert("edge".into(), Json::Object(e.collect()));
            }
            if !parts.interior.is_empty() {
                let e = parts.interior.iter().map(|(k, v)| (k.to_string(), list(v)));
                o.insert("interior".into(), Json::Object(e.collect()));
            }
            obj.insert("ordinates".into(), Json::Object(o));
        }
        Json::Object(obj)
    }

    /// The ordinates grouped as in the file; a group is written only if complete.
    fn ordinate_parts(&self) -> Parts {
        let complete = |r: std::ops::Range<usize>| -> Option<Vec<BigRational>> {
            self.ordinates[r].iter().cloned().collect()
        };
        let n = self.degree;
        let vertex = complete(0..self.vertex_end());
        let edge = (0..self.edges.len())
            .filter_map(|e| {
                let start = self.vertex_end() + e * (n - 1);
                let [a, b] = self.edges[e];
                complete(start..start + n - 1).map(|v| (format!("{a}-{b}"), v))
            })
            .filter(|(_, v)| !v.is_empty())
            .collect();
        let per = super::interior_count(n);
        let interior = (0..self.triangles.len())
            .filter_map(|t| {
                let start = self.edge_end() + t * per;
                complete(start..start + per).map(|v| (t, v))
            })
            .filter(|(_, v)| !v.is_empty())
            .collect();
        Parts {
            vertex,
            edge,
            interior,
        }
    }
}

struct Parts {
    vertex: Option<Vec<BigRational>>,
    edge: Vec<(String, Vec<BigRational>)>,
    interior: Vec<(usize, Vec<BigRational>)>,
}

impl Parts {
    fn is_empty(&self) -> bool {
        self.vertex.is_none() && self.edge.is_empty() && self.interior.is_empty()
    }
}

/// Read a mesh file, with the lines of its parts.
pub fn read_mesh(path: &Path) -> Result<(Mesh, MeshLines), InputError> {
    let doc = Document::read(path)?;
    mesh_from_document(&doc)
}

fn required<'a>(
    doc: &Document,
    table: &'a [(String, Node)],
    key: &'static str,
) -> Result<&'a Node, InputError> {
    Document::get(table, key).ok_or_else(|| doc.error(&doc.root, "", Problem::MissingKey { key }))
}

/// The number of vertices (`what = "vertices"`, at least 3) or triangles (at least 1), checked
/// before anything is allocated for them.
fn capped(
    doc: &Document,
    node: &Node,
    what: &'static str,
    found: usize,
    max: usize,
) -> Result<(), InputError> {
    let min = if what == "vertices" { 3 } else { 1 };
    if !(min..=max).contains(&found) {
        return Err(doc.error(
            node,
            what,
            MeshFileProblem::Mesh(MeshError::Count {
                what,
                found,
                min,
                max,
            }),
        ));
    }
    Ok(())
}

/// Parse a mesh from a document (the whole file).
pub fn mesh_from_document(doc: &Document) -> Result<(Mesh, MeshLines), InputError> {
    let root = doc.root_table()?;
    doc.check_keys(&doc.root, root, MESH_KEYS, "")?;
    if let Some(name) = Document::get(root, "name") {
        doc.string(name, "name")?;
    }
    let degree_node = required(doc, root, "degree")?;
    let degree = doc.usize(degree_node, "degree")?;
    if degree == 0 || degree > MAX_MESH_DEGREE {
        return Err(doc.error(
            degree_node,
            "degree",
            MeshFileProblem::Mesh(MeshError::Degree {
                degree,
                max: MAX_MESH_DEGREE,
            }),
        ));
    }
    // Vertices.
    let vnode = required(doc, root, "vertices")?;
    let vitems = doc.array(vnode, "vertices")?;
    capped(doc, vnode, "vertices", vitems.len(), MAX_VERTICES)?;
    let mut vertices = Vec::with_capacity(vitems.len());
    let mut lines = MeshLines {
        file: doc.file.clone(),
        vertices: Vec::with_capacity(vitems.len()),
        ..MeshLines::default()
    };
    for (i, item) in vitems.iter().enumerate() {
        let key = format!("vertices[{i}]");
        let xy = doc.array(item, &key)?;
        if xy.len() != 2 {
            return Err(doc.error(
                item,
                &key,
                MeshFileProblem::Length {
                    found: xy.len(),
                    expected: 2,
                },
            ));
        }
        let x = doc.rational(&xy[0], &format!("{key}[0]"))?;
        let y = doc.rational(&xy[1], &format!("{key}[1]"))?;
        vertices.push([x, y]);
        lines.vertices.push(item.line);
    }
    // Triangles.
    let tnode = required(doc, root, "triangles")?;
    let titems = doc.array(tnode, "triangles")?;
    capped(doc, tnode, "triangles", titems.len(), MAX_TRIANGLES)?;
    let mut triangles = Vec::with_capacity(titems.len());
    lines.triangles.reserve(titems.len());
    for (t, item) in titems.iter().enumerate() {
        let key = format!("triangles[{t}]");
        let ids = doc.array(item, &key)?;
        if ids.len() != 3 {
            return Err(doc.error(
                item,
                &key,
                MeshFileProblem::Length {
                    found: ids.len(),
                    expected: 3,
                },
            ));
        }
        let mut tri = [0usize; 3];
        for (i, node) in ids.iter().enumerate() {
            let v = doc.usize(node, &format!("{key}[{i}]"))?;
            if v >= vertices.len() {
                let e = MeshError::VertexOutOfRange {
                    triangle: t,
                    vertex: v,
                    last: vertices.len() - 1,
                };
                return Err(doc.error(node, &format!("{key}[{i}]"), MeshFileProblem::Mesh(e)));
            }
            if tri[..i].contains(&v) {
                let e = MeshError::RepeatedVertex {
                    triangle: t,
                    vertex: v,
                };
                return Err(doc.error(node, &format!("{key}[{i}]"), MeshFileProblem::Mesh(e)));
            }
            tri[i] = v;
        }
        triangles.push(tri);
        lines.triangles.push(item.line);
    }
    lines.ordinates = degree_node.line;
    let mesh = Mesh::new(vertices, triangles, degree)
        .map_err(|e| doc.error(&doc.root, "", MeshFileProblem::Mesh(e)))?;
    let Some(onode) = Document::get(root, "ordinates") else {
        return Ok((mesh, lines));
    };
    lines.ordinates = onode.line;
    let ordinates = read_ordinates(doc, onode, &mesh)?;
    let mesh = mesh
        .with_optional_ordinates(ordinates)
        .map_err(|e| doc.error(onode, "ordinates", MeshFileProblem::Mesh(e)))?;
    Ok((mesh, lines))
}

fn read_ordinates(
    doc: &Document,
    onode: &Node,
    mesh: &Mesh,
) -> Result<Vec<Option<BigRational>>, InputError> {
    let table = doc.table(onode, "ordinates")?;
    doc.check_keys(onode, table, ORDINATE_KEYS, "ordinates")?;
    // The count is capped by Mesh::new (MAX_ORDINATES).
    debug_assert!(mesh.ordinate_count() <= MAX_ORDINATES);
    let mut out: Vec<Option<BigRational>> = vec![None; mesh.ordinate_count()];
    let n = mesh.degree;
    let length = |node: &Node, key: &str, expected: usize, found: usize| {
        if found == expected {
            Ok(())
        } else {
            Err(doc.error(node, key, MeshFileProblem::Length { found, expected }))
        }
    };
    if let Some(node) = Document::get(table, "vertex") {
        let key = "ordinates.vertex";
        let items = doc.array(node, key)?;
        length(node, key, mesh.vertices.len(), items.len())?;
        for (v, item) in items.iter().enumerate() {
            out[v] = Some(doc.rational(item, &format!("{key}[{v}]"))?);
        }
    }
    if let Some(node) = Document::get(table, "edge") {
        let entries = doc.table(node, "ordinates.edge")?;
        let mut given = vec![false; mesh.edges.len()];
        for (k, item) in entries {
            let key = format!("ordinates.edge.{k}");
            let (a, b) = parse_edge_key(k).ok_or_else(|| {
                doc.error(item, &key, MeshFileProblem::EdgeKey { key: k.clone() })
            })?;
            if a >= b {
                let p = if a == b {
                    MeshFileProblem::EdgeKey { key: k.clone() }
                } else {
                    MeshFileProblem::EdgeOrder { a, b }
                };
                return Err(doc.error(item, &key, p));
            }
            let e = mesh
                .edge_index(a, b)
                .ok_or_else(|| doc.error(item, &key, MeshFileProblem::NoSuchEdge { a, b }))?;
            if std::mem::replace(&mut given[e], true) {
                let what = format!("edge {a}–{b}");
                return Err(doc.error(item, &key, MeshFileProblem::Twice { what }));
            }
            let items = doc.array(item, &key)?;
            length(item, &key, n - 1, items.len())?;
            let start = mesh.vertex_end() + e * (n - 1);
            for (i, x) in items.iter().enumerate() {
                out[start + i] = Some(doc.rational(x, &format!("{key}[{i}]"))?);
            }
        }
    }
    if let Some(node) = Document::get(table, "interior") {
        let entries = doc.table(node, "ordinates.interior")?;
        let per = super::interior_count(n);
        let mut given = vec![false; if per == 0 { 0 } else { mesh.triangles.len() }];
        for (k, item) in entries {
            let key = format!("ordinates.interior.{k}");
            let bad = |reason: String| {
                doc.error(
                    item,
                    &key,
                    MeshFileProblem::InteriorKey {
                        key: k.clone(),
                        reason,
                    },
                )
            };
            if per == 0 {
                return Err(bad(format!("a mesh of degree {n} has none")));
            }
            let t = parse_index(k).ok_or_else(|| bad("not a triangle number".into()))?;
            if t >= mesh.triangles.len() {
                let last = mesh.triangles.len() - 1;
                return Err(bad(format!("the triangles are 0 to {last}")));
            }
            if std::mem::replace(&mut given[t], true) {
                let what = format!("triangle {t}");
                return Err(doc.error(item, &key, MeshFileProblem::Twice { what }));
            }
            let items = doc.array(item, &key)?;
            length(item, &key, per, items.len())?;
            let start = mesh.edge_end() + t * per;
            for (i, x) in items.iter().enumerate() {
                out[start + i] = Some(doc.rational(x, &format!("{key}[{i}]"))?);
            }
        }
    }
    Ok(out)
}

/// A decimal vertex or triangle number (ASCII digits only, no sign, at most 12 digits).
fn parse_index(s: &str) -> Option<usize> {
    let s = s.trim();
    (!s.is_empty() && s.len() <= 12 && s.bytes().all(|c| c.is_ascii_digit()))
        .then(|| s.parse().ok())
        .flatten()
}

fn parse_edge_key(s: &str) -> Option<(usize, usize)> {
    let (a, b) = s.split_once('-')?;
    Some((parse_index(a)?, parse_index(b)?))
}

/// The fuzz target `mesh` (`tribez::hazmat::io::fuzz::mesh`): the first byte chooses TOML (even)
/// or JSON (odd); a mesh read is checked, written back in both formats and read again (the same
/// mesh), and looked up at its first vertex and the centroid of its first triangle: in a mesh
/// that passes [`Mesh::check`], every triangle containing a point gives the same value there.
#[cfg(any(fuzzing, feature = "unstable-internals"))]
pub fn fuzz_mesh(data: &[u8]) {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let doc = if first % 2 == 0 {
        Document::parse_toml("fuzz.toml", text)
    } else {
        Document::parse_json("fuzz.json", text)
    };
    let Ok(Ok((mesh, lines))) = doc.map(|d| mesh_from_document(&d)) else {
        return;
    };
    let problems = mesh.check();
    for p in &problems {
        let _ = lines.locate(p.clone()).to_string();
    }
    let toml = mesh.to_toml();
    assert_eq!(
        Mesh::from_toml(&toml).as_ref(),
        Ok(&mesh),
        "TOML round trip of\n{toml}"
    );
    let json = mesh.to_json().to_string();
    assert_eq!(
        Mesh::from_json(&json).as_ref(),
        Ok(&mesh),
        "JSON round trip of\n{json}"
    );
    let t = mesh.triangles[0].map(|v| &mesh.vertices[v]);
    let third = BigRational::new(1.into(), 3.into());
    let centroid = [0, 1].map(|c| (&t[0][c] + &t[1][c] + &t[2][c]) * &third);
    for point in [mesh.vertices[0].clone(), centroid] {
        let hits = mesh.locate(&point);
        if problems.is_empty() {
            assert!(!hits.is_empty());
            let values: Vec<BigRational> = hits.iter().map(|h| mesh.value(h).unwrap()).collect();
            assert!(values.windows(2).all(|w| w[0] == w[1]), "C0 at {point:?}");
        }
    }
}
