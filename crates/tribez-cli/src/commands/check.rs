//! `tribez check`: judge claim files (and directories of them), or a batch of evaluation results
//! from another implementation (`--patch PATCH --results FILE`, see [`super::batch`]).

use std::path::PathBuf;

use num_traits::ToPrimitive;
use serde_json::{Value as Json, json};

use super::{CliError, Outcome};
use crate::cli::OutputArgs;
use crate::report::{Exporter, JunitCase, Render, UlpHistogram, junit_xml};
use tribez::claims::{ClaimFile, Judged, Verdict};
use tribez::hazmat::number::to_decimal_string;

/// Arguments of `tribez check`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Claim files (`*.claims.toml`, `*.claims.json`) or directories searched recursively.
    #[arg(value_name = "FILE_OR_DIR")]
    pub paths: Vec<PathBuf>,
    /// Batch mode: the patch the results are about.
    #[arg(long, value_name = "PATCH", requires = "results")]
    pub patch: Option<PathBuf>,
    /// Batch mode: CSV, JSON-lines or JSON-array-of-rows results (input coordinates, then the
    /// claimed coordinates).
    #[arg(long, value_name = "FILE", requires = "patch")]
    pub results: Option<PathBuf>,
    /// Batch mode: the tolerance every row is judged with (default `exact`): `exact`, `ulps=N`,
    /// `abs=E`, `rel=E`, `correctly_rounded`, `faithful`, `cond=K` (|y − q| ≤ K·ε·Σ|c|B(|λ|)),
    /// `cond` (K = (m+1)·n for this patch: de Casteljau's own constant, n = 3 on a triangle gives
    /// K = 9) or `bound`.
    #[arg(long, value_name = "T")]
    pub tolerance: Option<String>,
    /// Batch mode: each number denotes the nearest float of this precision (f64 or f32).
    #[arg(long, value_name = "f64|f32")]
    pub precision: Option<String>,
    /// Batch mode: the input columns are Cartesian coordinates in the patch's domain.
    #[arg(long)]
    pub cartesian: bool,
    /// Batch mode: the algorithm whose a-priori bound `--tolerance bound` uses.
    #[arg(long, value_enum, default_value_t = super::batch::AlgorithmChoice::Casteljau)]
    pub algorithm: super::batch::AlgorithmChoice,
    /// Also write a JUnit XML report to FILE (one test case per claim file).
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Write the worst error per operation, algorithm and precision to FILE, when every claim
    /// holds and no worst error regressed against --baseline (which is read first, so both may
    /// name the same file).
    #[arg(long, value_name = "FILE")]
    pub record_baseline: Option<PathBuf>,
    /// Fail when any worst error is larger than recorded in FILE.
    #[arg(long, value_name = "FILE")]
    pub baseline: Option<PathBuf>,
    #[command(flatten)]
    pub out: OutputArgs,
}

/// The judged claims, grouped by file.
pub struct CheckReport {
    /// `(file, its judged claims)` in order.
    pub files: Vec<(String, Vec<Judged>)>,
    /// The word for a claim that holds (`passed`; `reproduced` for `tribez reproduce`).
    pub ok_word: &'static str,
    /// Baseline comparison lines (regressions), if a baseline was given.
    pub regressions: Vec<String>,
}

/// Judge every claim file under `paths` (files or directories).
pub fn judge_paths(paths: &[PathBuf]) -> Result<Vec<(String, Vec<Judged>)>, CliError> {
    let mut files = Vec::new();
    for p in paths {
        if p.is_dir() {
            let walk = tribez::hazmat::io::walk::claim_files(p)?;
            for note in &walk.notes {
                eprintln!("note: {note}");
            }
            let found = walk.files;
            if found.is_empty() {
                return Err(CliError::Usage(format!(
                    "{}: no claim files (*.claims.toml, *.claims.json)",
                    p.display()
                )));
            }
            files.extend(found);
        } else if p.exists() {
            files.push(p.clone());
        } else {
            return Err(tribez::hazmat::io::InputError::file(
                p.display().to_string(),
                "no such file or directory",
            )
            .into());
        }
    }
    let mut out = Vec::new();
    for f in files {
        let judged = ClaimFile::read(&f)?.judge_all()?;
        out.push((f.display().to_string(), judged));
    }
    Ok(out)
}

/// Run `tribez check`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    if args.results.is_some() {
        if !args.paths.is_empty() {
            return Err(CliError::Usage(
                "give either claim files or --patch/--results, not both".into(),
            ));
        }
        return super::batch::run(args);
    }
    for (flag, given) in [
        ("--tolerance", args.tolerance.is_some()),
        ("--precision", args.precision.is_some()),
        ("--cartesian", args.cartesian),
    ] {
        if given {
            return Err(CliError::Usage(format!(
                "{flag} applies to batches (--patch PATCH --results FILE); claim files state it per claim"
            )));
        }
    }
    if args.paths.is_empty() {
        return Err(CliError::Usage(
            "give claim files or directories, or --patch PATCH --results FILE".into(),
        ));
    }
    let files = judge_paths(&args.paths)?;
    let mut report = CheckReport {
        files,
        ok_word: "passed",
        regressions: Vec::new(),
    };
    let worst = report.worst_errors();
    let all_hold = report.success();
    report.regressions = super::baseline::judge(
        args.baseline.as_deref(),
        args.record_baseline.as_deref(),
        &worst,
        all_hold,
    )?;
    let success = report.success();
    if let Some(path) = &args.junit {
        super::write_atomically(path, report.junit().as_bytes())?;
    }
    Outcome::rendered(&report, args.out.format, success)
}

fn verdict_word(v: &Verdict, ok: &'static str) -> &'static str {
    match v {
        Verdict::Holds => ok,
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

fn short(file: &str) -> String {
    std::path::Path::new(file)
        .file_name()
        .map_or(file.to_string(), |f| f.to_string_lossy().into_owned())
}

impl CheckReport {
    fn judged(&self) -> impl Iterator<Item = &Judged> {
        self.files.iter().flat_map(|(_, j)| j)
    }

    /// Every claim holds (errata aside) and no baseline regressed.
    pub fn success(&self) -> bool {
        !self.judged().any(|j| j.verdict.fails_run()) && self.regressions.is_empty()
    }

    /// Errors in ULPs (as seen) of every float coordinate, with where.
    fn float_errors(&self) -> Vec<(f64, &Judged, usize)> {
        self.judged()
            .flat_map(|j| {
                j.floats.iter().enumerate().map(move |(k, f)| {
                    (
                        f.seen
                            .ulps
                            .as_ref()
                            .and_then(ToPrimitive::to_f64)
                            .unwrap_or(f64::INFINITY),
                        j,
                        k,
                    )
                })
            })
            .collect()
    }

    /// The worst error (ULPs at the inputs as seen) per operation, algorithm and precision.
    pub fn worst_errors(&self) -> Vec<super::baseline::Worst> {
        let mut out: Vec<super::baseline::Worst> = Vec::new();
        for (ulps, j, _) in self.float_errors() {
            let key = (
                j.op.clone(),
                "claimed".to_string(),
                j.precision.map_or("exact", |p| p.name()).to_string(),
            );
            match out
                .iter_mut()
                .find(|w| (w.op.clone(), w.algorithm.clone(), w.precision.clone()) == key)
            {
                Some(w) if w.ulps < ulps => {
                    w.ulps = ulps;
                    w.at = format!("{} / {}", j.file, j.id);
                }
                Some(_) => {}
                None => out.push(super::baseline::Worst {
                    op: key.0,
                    algorithm: key.1,
                    precision: key.2,
                    ulps,
                    at: format!("{} / {}", j.file, j.id),
                }),
            }
        }
        out
    }
}

impl Render for CheckReport {
    fn text(&self) -> String {
        let mut out = format!(
            "{:<34} {:<30} {:<18} {:<40} verdict\n",
            "file", "claim", "tolerance", "exact value"
        );
        for j in self.judged() {
            out += &format!(
                "{:<34} {:<30} {:<18} {:<40} {}\n",
                clip(&short(&j.file), 34),
                clip(&j.id, 30),
                clip(
                    &format!(
                        "{}{}",
                        j.tolerance,
                        j.precision
                            .map_or(String::new(), |p| format!(" {}", p.name()))
                    ),
                    18
                ),
                clip(&j.exact.to_text(), 40),
                verdict_word(&j.verdict, self.ok_word)
            );
        }
        let errata: Vec<&Judged> = self
            .judged()
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
        let failed: Vec<&Judged> = self.judged().filter(|j| j.verdict.fails_run()).collect();
        if !failed.is_empty() {
            out += "\nFailures\n";
            for j in &failed {
                out += &format!(
                    "  {} / {} (tolerance {}): claimed {}\n    exact {}\n",
                    j.file,
                    j.id,
                    j.tolerance,
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
                for (k, f) in j.floats.iter().enumerate() {
                    out += &format!(
                        "    [{k}] claimed {} = {}; exact at the inputs as seen {} ({}); at the intended inputs {} ({})\n",
                        f.decimal,
                        f.hex,
                        to_decimal_string(&f.exact_seen, 20),
                        f.seen.text(),
                        to_decimal_string(&f.exact_intended, 20),
                        f.intended.text()
                    );
                }
            }
        }
        let errors = self.float_errors();
        if !errors.is_empty() {
            let mut h = UlpHistogram::default();
            errors.iter().for_each(|e| h.add(e.0));
            out += "\nErrors of float claims in ULPs (against the exact value at the inputs as the code saw them)\n";
            out += &h.text();
            if let Some((u, j, k)) = errors.iter().max_by(|a, b| a.0.total_cmp(&b.0)) {
                out += &format!(
                    "  worst: {} ulp at {} / {}[{k}]\n",
                    to_decimal_string(
                        &num_rational::BigRational::from_float(*u).unwrap_or_default(),
                        4
                    ),
                    j.file,
                    j.id
                );
            }
        }
        for r in &self.regressions {
            out += &format!("\nbaseline regression: {r}");
        }
        if !self.regressions.is_empty() {
            out += "\n";
        }
        let count = |f: fn(&Verdict) -> bool| self.judged().filter(|j| f(&j.verdict)).count();
        out += &format!(
            "\n{} claim{} in {} file{}: {} {}, {} known errata, {} failed\n",
            self.judged().count(),
            if self.judged().count() == 1 { "" } else { "s" },
            self.files.len(),
            if self.files.len() == 1 { "" } else { "s" },
            count(|v| matches!(v, Verdict::Holds)),
            self.ok_word,
            count(|v| matches!(v, Verdict::KnownErratum(_))),
            failed.len()
        );
        out
    }

    fn json(&self) -> Json {
        let claims: Vec<Json> = self
            .judged()
            .map(|j| {
                let mismatches = match &j.verdict {
                    Verdict::Fails(ms) | Verdict::KnownErratum(ms) => {
                        ms.iter().map(|m| json!({"path": m.path, "claimed": m.claimed, "exact": m.exact, "reason": m.reason})).collect()
                    }
                    _ => vec![],
                };
                let floats: Vec<Json> = j
                    .floats
                    .iter()
                    .map(|f| {
                        json!({
                            "claimed": {"decimal": f.decimal, "hex": f.hex, "exact": f.claimed.to_string()},
                            "exact_at_inputs_as_seen": f.exact_seen.to_string(),
                            "error_at_inputs_as_seen": f.seen.to_json(),
                            "exact_at_intended_inputs": f.exact_intended.to_string(),
                            "error_at_intended_inputs": f.intended.to_json(),
                            "condition": f.condition.to_string(),
                            "bound": f.bound.as_ref().map(ToString::to_string),
                        })
                    })
                    .collect();
                json!({
                    "file": j.file, "id": j.id, "op": j.op, "source": j.source, "erratum": j.erratum,
                    "tolerance": j.tolerance.text(), "precision": j.precision.map(|p| p.name()),
                    "verdict": verdict_word(&j.verdict, self.ok_word), "exact": j.exact.to_json(), "claimed": j.claimed.to_json(),
                    "mismatches": mismatches, "float": floats,
                })
            })
            .collect();
        let failed = self.judged().filter(|j| j.verdict.fails_run()).count();
        let mut h = UlpHistogram::default();
        self.float_errors().iter().for_each(|e| h.add(e.0));
        json!({
            "claims": claims,
            "summary": {
                "claims": self.judged().count(),
                "files": self.files.len(),
                "passed": self.judged().filter(|j| j.verdict == Verdict::Holds).count(),
                "errata": self.judged().filter(|j| matches!(j.verdict, Verdict::KnownErratum(_))).count(),
                "failed": failed,
                "ulp_histogram": h.json(),
                "baseline_regressions": self.regressions,
            },
        })
    }
}

impl Exporter for CheckReport {
    fn junit(&self) -> String {
        let cases: Vec<JunitCase> = self
            .files
            .iter()
            .map(|(file, judged)| JunitCase {
                name: file.clone(),
                checks: judged.len(),
                failures: judged
                    .iter()
                    .filter(|j| j.verdict.fails_run())
                    .map(|j| {
                        format!(
                            "{}: claimed {}, exact {} (tolerance {})",
                            j.id,
                            j.claimed.to_text(),
                            j.exact.to_text(),
                            j.tolerance
                        )
                    })
                    .collect(),
            })
            .collect();
        junit_xml("check", &cases)
    }
}
