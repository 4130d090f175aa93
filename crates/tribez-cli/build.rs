//! Embeds the repository's `fixtures/` in the `tribez` binary, so that `tribez reproduce` works
//! from any directory and from an installed binary (`cargo install --path crates/tribez-cli`).
//! Generates `$OUT_DIR/fixtures.rs`: `FIXTURES: &[(&str, &[u8])]`, each file's path relative to
//! `fixtures/` (with `/` separators) and its bytes (`include_bytes!`). The derivation scripts
//! (`*.py`) and hidden files are left out.
//!
//! `crates/tribez-cli/fixtures` is a symbolic link to the repository's `fixtures/`, so that
//! `cargo package` (which follows it) puts the fixtures in the crate, and a `cargo install
//! tribez-cli` from the registry embeds them too; where the link is not one (a checkout without
//! symbolic links), the repository's directory is read directly.

use std::path::{Path, PathBuf};

fn main() {
    let manifest = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let root = [manifest.join("fixtures"), manifest.join("../../fixtures")]
        .into_iter()
        .find(|d| d.is_dir())
        .unwrap_or_else(|| manifest.join("fixtures"));
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed={}", root.display());
    let mut files = Vec::new();
    if root.is_dir() {
        collect(&root, &root, &mut files);
    }
    files.sort();
    let mut out = String::from("/// The embedded fixtures: (path under `fixtures/`, bytes).\n");
    out += "pub static FIXTURES: &[(&str, &[u8])] = &[\n";
    for (rel, abs) in &files {
        println!("cargo:rerun-if-changed={}", abs.display());
        out += &format!(
            "    ({rel:?}, include_bytes!({:?})),\n",
            abs.display().to_string()
        );
    }
    out += "];\n";
    let dest =
        PathBuf::from(std::env::var_os("OUT_DIR").expect("set by cargo")).join("fixtures.rs");
    std::fs::write(dest, out).expect("write fixtures.rs");
}

fn collect(root: &Path, dir: &Path, files: &mut Vec<(String, PathBuf)>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("read fixtures directory")
        .map(|e| e.expect("read fixtures entry"))
        .collect();
    entries.sort_by_key(|e| e.file_name());
    for e in entries {
        let name = e.file_name().to_string_lossy().into_owned();
        let path = e.path();
        // a directory changed (a file added or removed) reruns the script
        let kind = std::fs::symlink_metadata(&path)
            .expect("stat fixture")
            .file_type();
        if name.starts_with('.') {
            continue;
        }
        if kind.is_dir() {
            println!("cargo:rerun-if-changed={}", path.display());
            collect(root, &path, files);
        } else if kind.is_file() && !name.ends_with(".py") {
            let rel = path
                .strip_prefix(root)
                .expect("under fixtures")
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join("/");
            let abs = path.canonicalize().expect("canonical fixture path");
            files.push((rel, abs));
        }
    }
}
