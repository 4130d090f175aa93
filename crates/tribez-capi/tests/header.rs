//! The committed header `include/tribez.h` is what cbindgen generates from the sources now:
//! a change to the ABI that is not regenerated fails here. `TRIBEZ_BLESS=1` rewrites it.

use std::path::Path;

#[test]
fn committed_header_is_fresh() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut fresh = Vec::new();
    cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header")
        .write(&mut fresh);
    let fresh = String::from_utf8(fresh).expect("UTF-8");
    let path = dir.join("include/tribez.h");
    if std::env::var_os("TRIBEZ_BLESS").is_some() {
        std::fs::write(&path, &fresh).expect("write include/tribez.h");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == fresh,
        "include/tribez.h differs from cbindgen's output for the sources: regenerate it with \
         `TRIBEZ_BLESS=1 cargo test -p tribez-capi --test header` and commit it"
    );
    // every exported function is declared, and the test-only entry point is not
    for name in [
        "tribez_check_f64",
        "tribez_report_merge",
        "tribez_error_message",
    ] {
        assert!(fresh.contains(&format!("{name}(")), "{name} missing");
    }
    assert!(!fresh.contains("tribez__panic_for_test"));
}
