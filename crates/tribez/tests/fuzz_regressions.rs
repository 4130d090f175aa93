//! Replays the fuzzers' regression corpus on stable Rust: every input that ever crashed or hung
//! a fuzz target (`fuzz/regressions/<target>/<file>`) is fed to the same entry point
//! ([`tribez::hazmat::io::fuzz`]); the test fails if one panics (a hang shows as a test that does not
//! finish). Each target has its directory, and every directory is a target.

use std::path::Path;

use tribez::hazmat::io::fuzz::{TARGETS, run};

#[test]
fn every_regression_input_is_handled() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz/regressions");
    let mut dirs: Vec<String> = std::fs::read_dir(&root)
        .expect("fuzz/regressions")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    dirs.sort();
    let mut targets: Vec<String> = TARGETS.iter().map(ToString::to_string).collect();
    targets.sort();
    assert_eq!(dirs, targets, "one directory per fuzz target");
    let mut replayed = 0;
    for target in TARGETS {
        let mut files: Vec<_> = std::fs::read_dir(root.join(target))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.file_name().is_some_and(|n| n != ".gitkeep"))
            .collect();
        files.sort();
        for f in files {
            let data = std::fs::read(&f).unwrap();
            eprintln!("{target}: {}", f.display());
            assert!(run(target, &data));
            replayed += 1;
        }
    }
    assert!(replayed > 0, "the corpus is empty");
}

/// The fuzz targets are built with nightly Rust only (cargo-fuzz), so CI never compiles them: this
/// keeps each `fuzz/fuzz_targets/<target>.rs` calling its entry point by the library's public path
/// (`tribez::hazmat::io::fuzz::<target>`), and every target listed in `fuzz/Cargo.toml`, so that a
/// change to the library's module layout cannot silently break fuzzing.
#[test]
fn every_fuzz_target_calls_its_entry_point_by_a_public_path() {
    let fuzz = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let text = std::fs::read_to_string(fuzz.join("Cargo.toml")).unwrap();
    // parsed, so that a malformed manifest (a duplicate key) fails here and not in cargo-fuzz
    let manifest: toml_edit::DocumentMut = text.parse().expect("fuzz/Cargo.toml parses");
    let bins: Vec<(String, String)> = manifest["bin"]
        .as_array_of_tables()
        .expect("[[bin]] tables")
        .iter()
        .map(|t| {
            let field = |k: &str| t[k].as_str().unwrap_or_default().to_string();
            (field("name"), field("path"))
        })
        .collect();
    assert_eq!(
        bins.len(),
        TARGETS.len(),
        "fuzz/Cargo.toml declares {bins:?}"
    );
    for target in TARGETS {
        let source = std::fs::read_to_string(fuzz.join(format!("fuzz_targets/{target}.rs")))
            .unwrap_or_else(|e| panic!("fuzz/fuzz_targets/{target}.rs: {e}"));
        let call = format!("tribez::hazmat::io::fuzz::{target}(data)");
        assert!(
            source.contains(&call),
            "fuzz/fuzz_targets/{target}.rs must call {call}"
        );
        let declared = (target.to_string(), format!("fuzz_targets/{target}.rs"));
        assert!(
            bins.contains(&declared),
            "fuzz/Cargo.toml must declare the target {target} at {}",
            declared.1
        );
    }
}
