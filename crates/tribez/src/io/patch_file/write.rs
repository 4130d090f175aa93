//! Writing patches of any kind as TOML patch files or as JSON in the patch-file layout (numbers
//! as exact strings, control points in canonical order).

use num_rational::BigRational;
use serde_json::{Map, Value as Json, json};

use super::index_key;
use crate::any_patch::AnyPatch;
use crate::patch::BezierPatch;

pub(super) fn strings(xs: &[BigRational]) -> Vec<String> {
    xs.iter().map(ToString::to_string).collect()
}

/// The patch as JSON, in the patch-file layout (numbers as exact strings, canonical order).
pub fn patch_to_json(patch: &BezierPatch) -> Json {
    let mut obj = Map::new();
    if let Some(name) = &patch.name {
        obj.insert("name".into(), json!(name));
    }
    obj.insert("degree".into(), json!(patch.net.degree()));
    if let Some(d) = &patch.domain {
        obj.insert(
            "domain".into(),
            json!(d.vertices().iter().map(|v| strings(v)).collect::<Vec<_>>()),
        );
    }
    let mut cps = Map::new();
    for (alpha, p) in patch.net.entries() {
        cps.insert(index_key(alpha), json!(strings(p)));
    }
    obj.insert("control_points".into(), Json::Object(cps));
    Json::Object(obj)
}

fn toml_string(s: &str) -> String {
    serde_json::to_string(s).unwrap_or_else(|_| format!("\"{s}\""))
}

fn toml_list(xs: &[BigRational]) -> String {
    format!(
        "[{}]",
        xs.iter()
            .map(|x| toml_string(&x.to_string()))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// The patch as a TOML patch file.
pub fn patch_to_toml(patch: &BezierPatch) -> String {
    let mut out = String::new();
    if let Some(name) = &patch.name {
        out += &format!("name = {}\n", toml_string(name));
    }
    out += &format!("degree = {}\n", patch.net.degree());
    if let Some(d) = &patch.domain {
        out += &format!(
            "domain = [{}]\n",
            d.vertices()
                .iter()
                .map(|v| toml_list(v))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    out += "\n[control_points]\n";
    for (alpha, p) in patch.net.entries() {
        out += &format!("\"{}\" = {}\n", index_key(alpha), toml_list(p));
    }
    out
}

/// A patch of any kind as a TOML patch file (`kind` for functional patches, `polygon` for
/// S-patches, `[weights]` for rational patches).
pub fn any_patch_to_toml(patch: &AnyPatch) -> String {
    match patch {
        AnyPatch::Bezier(p) => patch_to_toml(p),
        AnyPatch::Functional(p) => format!("kind = \"functional\"\n{}", patch_to_toml(p)),
        AnyPatch::Rational(r) => {
            let mut out = patch_to_toml(&r.patch);
            out += "\n[weights]\n";
            for (alpha, w) in r.patch.net.simplex().iter().zip(&r.weights) {
                out += &format!(
                    "\"{}\" = {}\n",
                    index_key(alpha),
                    toml_string(&w.to_string())
                );
            }
            out
        }
        AnyPatch::SPatch(s) => {
            let mut out = String::new();
            if let Some(name) = &s.name {
                out += &format!("name = {}\n", toml_string(name));
            }
            out += &format!("degree = {}\n", s.net.degree());
            let vs: Vec<String> = s.polygon.vertices().iter().map(|v| toml_list(v)).collect();
            out += &format!("polygon = [{}]\n\n[control_points]\n", vs.join(", "));
            for (alpha, p) in s.net.entries() {
                out += &format!("\"{}\" = {}\n", index_key(alpha), toml_list(p));
            }
            out
        }
    }
}

/// A patch of any kind as JSON, in the patch-file layout.
pub fn any_patch_to_json(patch: &AnyPatch) -> Json {
    match patch {
        AnyPatch::Bezier(p) => patch_to_json(p),
        AnyPatch::Functional(p) => {
            let mut j = patch_to_json(p);
            j["kind"] = json!("functional");
            j
        }
        AnyPatch::Rational(r) => {
            let mut j = patch_to_json(&r.patch);
            let w: Map<String, Json> = r
                .patch
                .net
                .simplex()
                .iter()
                .zip(&r.weights)
                .map(|(a, w)| (index_key(a), json!(w.to_string())))
                .collect();
            j["weights"] = Json::Object(w);
            j
        }
        AnyPatch::SPatch(s) => {
            let mut obj = Map::new();
            if let Some(name) = &s.name {
                obj.insert("name".into(), json!(name));
            }
            obj.insert("degree".into(), json!(s.net.degree()));
            obj.insert(
                "polygon".into(),
                json!(
                    s.polygon
                        .vertices()
                        .iter()
                        .map(|v| strings(v))
                        .collect::<Vec<_>>()
                ),
            );
            let cps: Map<String, Json> = s
                .net
                .entries()
                .map(|(a, p)| (index_key(a), json!(strings(p))))
                .collect();
            obj.insert("control_points".into(), Json::Object(cps));
            Json::Object(obj)
        }
    }
}
