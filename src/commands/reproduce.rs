//! `tribez reproduce`: judge every claim of the fixtures, listing the known errata apart.

use std::path::PathBuf;

use serde_json::{Value as Json, json};

use super::{CliError, Outcome};
use crate::claims::{ClaimFile, Judged, Verdict, find_claim_files};
use crate::cli::OutputArgs;
use crate::report::Render;

/// Arguments of `tribez reproduce`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Directory of claim files (`*.claims.toml`, `*.claims.json`); default: the built-in `fixtures/`.
    pub dir: Option<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The reproduction report.
pub struct ReproduceReport {
    judged: Vec<Judged>,
}

/// The built-in fixtures directory: `./fixtures` if present, else the one in the source tree.
pub fn default_fixtures() -> PathBuf {
    let local = PathBuf::from("fixtures");
    if local.is_dir() {
        local
    } else {
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fixtures")
    }
}

/// Run `tribez reproduce`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let dir = args.dir.clone().unwrap_or_else(default_fixtures);
    let files = find_claim_files(&dir)?;
    if files.is_empty() {
        return Err(CliError::Usage(format!(
            "{}: no claim files (*.claims.toml, *.claims.json)",
            dir.display()
        )));
    }
    let mut judged = Vec::new();
    for f in files {
        judged.extend(ClaimFile::read(&f)?.judge_all()?);
    }
    let success = !judged.iter().any(|j| j.verdict.fails_run());
    Outcome::rendered(&ReproduceReport { judged }, args.out.format, success)
}

fn verdict_word(v: &Verdict) -> &'static str {
    match v {
        Verdict::Holds => "reproduced",
        Verdict::Fails(_) => "FAILED",
        Verdict::KnownErratum(_) => "erratum",
        Verdict::StaleErratum => "FAILED (erratum reproduces)",
    }
}

fn clip(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        format!("{}…", s.chars().take(n - 1).collect::<String>())
    }
}

impl Render for ReproduceReport {
    fn text(&self) -> String {
        let mut out = format!(
            "{:<34} {:<30} {:<44} verdict\n",
            "fixture", "claim", "exact value"
        );
        for j in &self.judged {
            let file = std::path::Path::new(&j.file)
                .file_name()
                .map_or(j.file.clone(), |f| f.to_string_lossy().into_owned());
            out += &format!(
                "{:<34} {:<30} {:<44} {}\n",
                clip(&file, 34),
                clip(&j.id, 30),
                clip(&j.exact.to_text(), 44),
                verdict_word(&j.verdict)
            );
        }
        let errata: Vec<&Judged> = self
            .judged
            .iter()
            .filter(|j| matches!(j.verdict, Verdict::KnownErratum(_)))
            .collect();
        if !errata.is_empty() {
            out +=
                "\nErrata: values printed in the sources that the exact computation contradicts\n";
            for j in errata {
                out += &format!(
                    "  {} / {} ({})\n",
                    j.file,
                    j.id,
                    j.source.as_deref().unwrap_or("no source given")
                );
                out += &format!(
                    "    printed: {}\n    exact:   {}\n",
                    j.claimed.to_text(),
                    j.exact.to_text()
                );
                if let Verdict::KnownErratum(ms) = &j.verdict {
                    for m in ms {
                        out += &format!(
                            "    at {}: {}\n",
                            if m.path.is_empty() {
                                "the value"
                            } else {
                                &m.path
                            },
                            m.reason
                        );
                    }
                }
                out += &format!("    note: {}\n", j.erratum.as_deref().unwrap_or(""));
            }
        }
        let failed: Vec<&Judged> = self
            .judged
            .iter()
            .filter(|j| j.verdict.fails_run())
            .collect();
        if !failed.is_empty() {
            out += "\nFailures\n";
            for j in &failed {
                out += &format!(
                    "  {} / {}: claimed {}\n    exact {}\n",
                    j.file,
                    j.id,
                    j.claimed.to_text(),
                    j.exact.to_text()
                );
                match &j.verdict {
                    Verdict::Fails(ms) => {
                        for m in ms {
                            out += &format!(
                                "    at {}: claimed {}, exact {}: {}\n",
                                if m.path.is_empty() {
                                    "the value"
                                } else {
                                    &m.path
                                },
                                m.claimed,
                                m.exact,
                                m.reason
                            );
                        }
                    }
                    _ => {
                        out += "    marked as an erratum, but the claimed value is exactly right: remove the erratum\n"
                    }
                }
            }
        }
        let count = |f: fn(&Verdict) -> bool| self.judged.iter().filter(|j| f(&j.verdict)).count();
        out += &format!(
            "\n{} claims: {} reproduced, {} known errata, {} failed\n",
            self.judged.len(),
            count(|v| matches!(v, Verdict::Holds)),
            count(|v| matches!(v, Verdict::KnownErratum(_))),
            failed.len()
        );
        out
    }

    fn json(&self) -> Json {
        let claims: Vec<Json> = self
            .judged
            .iter()
            .map(|j| {
                let mismatches = match &j.verdict {
                    Verdict::Fails(ms) | Verdict::KnownErratum(ms) => ms
                        .iter()
                        .map(|m| json!({"path": m.path, "claimed": m.claimed, "exact": m.exact, "reason": m.reason}))
                        .collect(),
                    _ => vec![],
                };
                json!({
                    "file": j.file, "id": j.id, "op": j.op, "source": j.source, "erratum": j.erratum,
                    "verdict": verdict_word(&j.verdict), "exact": j.exact.to_json(), "claimed": j.claimed.to_json(),
                    "mismatches": mismatches,
                })
            })
            .collect();
        let failed = self.judged.iter().filter(|j| j.verdict.fails_run()).count();
        json!({ "claims": claims, "summary": { "claims": self.judged.len(), "failed": failed } })
    }
}
