//! The library's reports are the command line's: `tribez::claims::check_claims` and
//! `tribez::certify` render (text, and JSON through `Serialize`) exactly what `tribez check` and
//! `tribez certify` print, so that the Python package and other callers of the library show the
//! same reports as the command.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use tribez::claims::{ClaimsOptions, check_claims};
use tribez::{CertifyOptions, CertifyPoints, Patch, Precision, certify};

fn tribez() -> Command {
    Command::cargo_bin("tribez").expect("binary built")
}

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures")
}

fn stdout(args: &[&str]) -> String {
    let out = tribez().args(args).output().expect("tribez runs");
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

fn pretty(value: &impl serde::Serialize) -> String {
    serde_json::to_string_pretty(value).expect("serializable") + "\n"
}

#[test]
fn check_claims_is_what_tribez_check_prints() {
    for file in [
        "finn_day30.claims.toml",
        "beyond",
        "certify/float_eval.claims.toml",
    ] {
        let path = fixtures().join(file);
        let report = check_claims(&path, &ClaimsOptions::default()).expect("fixtures read");
        assert!(report.success(), "{file}");
        assert_eq!(report.failed(), 0, "{file}");
        let p = path.to_str().expect("UTF-8 path");
        assert_eq!(report.to_string(), stdout(&["check", p]), "{file}: text");
        assert_eq!(
            pretty(&report),
            stdout(&["check", p, "--format", "json"]),
            "{file}: JSON"
        );
    }
}

#[test]
fn certify_is_what_tribez_certify_prints() {
    for (file, precision) in [
        ("finn_day30.toml", None),
        ("beyond/octant_quartic.toml", Some(Precision::F64)),
        ("beyond/pentagon_depth2.toml", Some(Precision::F32)),
    ] {
        let path = fixtures().join(file);
        let p = path.to_str().expect("UTF-8 path");
        let patch = Patch::from_file(&path).expect("fixture reads");
        let options = CertifyOptions {
            points: CertifyPoints::Random { count: 40, seed: 7 },
            precision,
            algorithm: None,
            label: p.to_string(),
        };
        let report = certify(&patch, &options).expect("certifies");
        assert!(report.success(), "{file}");
        let mut args = vec!["certify", p, "--random", "40", "--seed", "7"];
        let name = precision.map(|p| p.name());
        if let Some(name) = &name {
            args.extend(["--precision", name]);
        }
        assert_eq!(report.to_string(), stdout(&args), "{file}: text");
        args.extend(["--format", "json"]);
        assert_eq!(pretty(&report), stdout(&args), "{file}: JSON");
    }
}
