//! The report of checking claim files: [`check_claims`] (a claim file or a directory of them),
//! [`ClaimsReport`] with its text ([`ClaimsReport::text`], the `Display`) and its JSON (the
//! [`serde::Serialize`] impl): exactly what `tribez check` and `tribez reproduce` print.

use std::fmt;
use std::path::{Path, PathBuf};

use num_rational::BigRational;
use serde::Serialize;
use serde_json::Value as Json;

use super::{ClaimFile, FloatLeaf, Judged, Verdict};
use crate::api_error::Error;
use crate::certify::measures::Measures;
use crate::io::{ClaimProblem, InputError, Problem};
use crate::number::to_decimal_string;
use crate::report::UlpHistogram;
use crate::report::WorstError;

/// How claims are checked and reported.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ClaimsOptions {
    /// Report a claim that holds as `reproduced` (as `tribez reproduce` does) rather than
    /// `passed`.
    pub reproduce: bool,
}

/// The claim files found under some paths ([`claim_files_of`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FoundFiles {
    /// The claim files, in order: each directory's sorted by path.
    pub files: Vec<PathBuf>,
    /// `"PATH: skipped: REASON"` for every entry of a directory that is not read.
    pub notes: Vec<String>,
}

/// The claim files of `paths`: a file is taken as it is; a directory is searched recursively
/// for `*.claims.toml` and `*.claims.json`.
///
/// Errors: a path that does not exist, or a directory without claim files.
pub fn claim_files_of<P: AsRef<Path>>(paths: &[P]) -> Result<FoundFiles, Error> {
    let mut found = FoundFiles::default();
    for p in paths {
        let p = p.as_ref();
        if p.is_dir() {
            let walk = crate::io::walk::claim_files(p)?;
            found.notes.extend(walk.notes);
            if walk.files.is_empty() {
                return Err(
                    InputError::file(p.display().to_string(), ClaimProblem::NoClaimFiles).into(),
                );
            }
            found.files.extend(walk.files);
        } else if p.exists() {
            found.files.push(p.to_path_buf());
        } else {
            return Err(InputError::file(p.display().to_string(), Problem::NoSuchFile).into());
        }
    }
    Ok(found)
}

/// Read and judge the claim files `files`, in order.
pub fn check_files<P: AsRef<Path>>(
    files: &[P],
    options: &ClaimsOptions,
) -> Result<ClaimsReport, Error> {
    let mut out = Vec::new();
    for f in files {
        let f = f.as_ref();
        let claims = ClaimFile::read(f)?.judge_all()?;
        out.push(FileResults {
            file: f.display().to_string(),
            claims,
        });
    }
    Ok(ClaimsReport {
        files: out,
        reproduce: options.reproduce,
        baseline_regressions: Vec::new(),
        notes: Vec::new(),
    })
}

/// Check a claim file, or every claim file under a directory (searched recursively): the
/// report of `tribez check PATH`.
///
/// ```
/// # let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
/// use tribez::claims::{ClaimsOptions, check_claims};
/// let report = check_claims(&root.join("finn_day30.claims.toml"), &ClaimsOptions::default()).unwrap();
/// assert!(report.success());
/// assert_eq!(report.failed(), 0);
/// assert!(report.errata() >= 1); // Finn's printed x-component of the symbolic form
/// ```
pub fn check_claims(path: &Path, options: &ClaimsOptions) -> Result<ClaimsReport, Error> {
    check_paths(&[path], options)
}

/// Check the claim files of several paths (files, or directories searched recursively).
pub fn check_paths<P: AsRef<Path>>(
    paths: &[P],
    options: &ClaimsOptions,
) -> Result<ClaimsReport, Error> {
    let found = claim_files_of(paths)?;
    let mut report = check_files(&found.files, options)?;
    report.notes = found.notes;
    Ok(report)
}

/// The judged claims of one file.
#[derive(Clone, Debug)]
pub struct FileResults {
    /// The claim file, as given.
    pub file: String,
    /// Its claims, judged, in file order.
    pub claims: Vec<Judged>,
}

/// The report of checking claim files.
#[derive(Clone, Debug)]
pub struct ClaimsReport {
    /// The files, in order.
    pub files: Vec<FileResults>,
    /// Claims that hold are `reproduced` ([`ClaimsOptions::reproduce`]), not `passed`.
    pub reproduce: bool,
    /// Worst errors that got worse than a recorded baseline, one line each (filled by whoever
    /// compares against a baseline, as `tribez check --baseline` does; empty otherwise).
    pub baseline_regressions: Vec<String>,
    /// Entries of the directories searched that were skipped (not part of the text or JSON).
    pub notes: Vec<String>,
}

/// A claim's verdict as reports name it: `ok` for one that holds.
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
    Path::new(file)
        .file_name()
        .map_or(file.to_string(), |f| f.to_string_lossy().into_owned())
}

impl ClaimsReport {
    /// The word for a claim that holds: `passed`, or `reproduced`.
    pub fn ok_word(&self) -> &'static str {
        if self.reproduce {
            "reproduced"
        } else {
            "passed"
        }
    }

    /// Every judged claim, file by file.
    pub fn judged(&self) -> impl Iterator<Item = &Judged> {
        self.files.iter().flat_map(|f| &f.claims)
    }

    /// How many claims were judged.
    pub fn claims(&self) -> usize {
        self.judged().count()
    }

    /// How many claims hold.
    pub fn passed(&self) -> usize {
        self.judged()
            .filter(|j| j.verdict == Verdict::Holds)
            .count()
    }

    /// How many claims fail the run (wrong values, and stale errata).
    pub fn failed(&self) -> usize {
        self.judged().filter(|j| j.verdict.fails_run()).count()
    }

    /// How many claims are known errata of their sources (wrong as printed, not failing).
    pub fn errata(&self) -> usize {
        self.judged()
            .filter(|j| matches!(j.verdict, Verdict::KnownErratum(_)))
            .count()
    }

    /// Every claim holds (errata aside) and no baseline regressed.
    pub fn success(&self) -> bool {
        self.failed() == 0 && self.baseline_regressions.is_empty()
    }

    /// The error in ULPs at the inputs as seen of every float coordinate (infinite where
    /// unmeasured), with its claim and coordinate.
    pub fn float_errors(&self) -> Vec<(f64, &Judged, usize)> {
        self.judged()
            .flat_map(|j| {
                j.floats.iter().enumerate().map(move |(k, f)| {
                    (
                        // rounded up: the histogram's buckets are then exact
                        f.seen
                            .ulps
                            .as_ref()
                            .map_or(f64::INFINITY, crate::number::round_up_f64),
                        j,
                        k,
                    )
                })
            })
            .collect()
    }

    /// The histogram of [`Self::float_errors`].
    pub fn histogram(&self) -> UlpHistogram {
        let mut h = UlpHistogram::default();
        self.float_errors().iter().for_each(|e| h.add(e.0));
        h
    }

    /// The worst error (ULPs at the inputs as seen) per operation and precision (algorithm
    /// `claimed`), where it occurred as `FILE / ID`: what a baseline records.
    pub fn worst_errors(&self) -> Vec<WorstError> {
        let mut out: Vec<WorstError> = Vec::new();
        for (ulps, j, _) in self.float_errors() {
            let precision = j.precision.map_or("exact", |p| p.name());
            let at = || format!("{} / {}", j.file, j.id);
            match out
                .iter_mut()
                .find(|w| w.op == j.op && w.algorithm == "claimed" && w.precision == precision)
            {
                Some(w) if w.ulps < ulps => {
                    w.ulps = ulps;
                    w.at = at();
                }
                Some(_) => {}
                None => out.push(WorstError {
                    op: j.op.clone(),
                    algorithm: "claimed".into(),
                    precision: precision.into(),
                    ulps,
                    at: at(),
                }),
            }
        }
        out
    }

    /// The report for people (what `tribez check` prints).
    pub fn text(&self) -> String {
        let ok_word = self.ok_word();
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
                verdict_word(&j.verdict, ok_word)
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
                        out += &format!("    at {}: {}\n", where_(&m.path), m.reason);
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
                                where_(&m.path),
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
                    crate::number::ulps_decimal(&BigRational::from_float(*u).unwrap_or_default()),
                    j.file,
                    j.id
                );
            }
        }
        for r in &self.baseline_regressions {
            out += &format!("\nbaseline regression: {r}");
        }
        if !self.baseline_regressions.is_empty() {
            out += "\n";
        }
        let (claims, files) = (self.claims(), self.files.len());
        out += &format!(
            "\n{} claim{} in {} file{}: {} {}, {} known errata, {} failed\n",
            claims,
            if claims == 1 { "" } else { "s" },
            files,
            if files == 1 { "" } else { "s" },
            self.passed(),
            ok_word,
            self.errata(),
            failed.len()
        );
        out
    }
}

/// Where in a value a mismatch is: its path, or `the value`.
fn where_(path: &str) -> &str {
    if path.is_empty() { "the value" } else { path }
}

impl fmt::Display for ClaimsReport {
    /// [`ClaimsReport::text`].
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text())
    }
}

/// The report as JSON (the layout of `tribez check --format json`).
#[derive(Serialize)]
struct ReportJson<'a> {
    claims: Vec<ClaimJson<'a>>,
    summary: SummaryJson<'a>,
}

#[derive(Serialize)]
struct ClaimJson<'a> {
    file: &'a str,
    id: &'a str,
    op: &'a str,
    source: &'a Option<String>,
    erratum: &'a Option<String>,
    tolerance: String,
    precision: Option<&'static str>,
    verdict: &'static str,
    exact: Json,
    claimed: Json,
    mismatches: Vec<MismatchJson<'a>>,
    float: Vec<FloatJson<'a>>,
}

#[derive(Serialize)]
struct MismatchJson<'a> {
    path: &'a str,
    claimed: &'a str,
    exact: &'a str,
    reason: &'a str,
}

#[derive(Serialize)]
struct FloatJson<'a> {
    claimed: FloatClaimedJson<'a>,
    exact_at_inputs_as_seen: String,
    error_at_inputs_as_seen: &'a Measures,
    exact_at_intended_inputs: String,
    error_at_intended_inputs: &'a Measures,
    condition: String,
    bound: Option<String>,
}

#[derive(Serialize)]
struct FloatClaimedJson<'a> {
    decimal: &'a str,
    hex: &'a str,
    exact: String,
}

#[derive(Serialize)]
struct SummaryJson<'a> {
    claims: usize,
    files: usize,
    passed: usize,
    errata: usize,
    failed: usize,
    ulp_histogram: UlpHistogram,
    baseline_regressions: &'a [String],
}

impl<'a> From<&'a FloatLeaf> for FloatJson<'a> {
    fn from(f: &'a FloatLeaf) -> Self {
        FloatJson {
            claimed: FloatClaimedJson {
                decimal: &f.decimal,
                hex: &f.hex,
                exact: f.claimed.to_string(),
            },
            exact_at_inputs_as_seen: f.exact_seen.to_string(),
            error_at_inputs_as_seen: &f.seen,
            exact_at_intended_inputs: f.exact_intended.to_string(),
            error_at_intended_inputs: &f.intended,
            condition: f.condition.to_string(),
            bound: f.bound.as_ref().map(ToString::to_string),
        }
    }
}

impl Serialize for ClaimsReport {
    /// The layout of `tribez check --format json`: `claims` (one object per claim: file, id,
    /// op, source, erratum, tolerance, precision, verdict, exact and claimed values, the
    /// mismatching leaves, the float coordinates' errors) and `summary` (counts, the ULP
    /// histogram, baseline regressions). Exact numbers are strings `p/q`.
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let ok_word = self.ok_word();
        let claims = self
            .judged()
            .map(|j| {
                let mismatches = match &j.verdict {
                    Verdict::Fails(ms) | Verdict::KnownErratum(ms) => ms
                        .iter()
                        .map(|m| MismatchJson {
                            path: &m.path,
                            claimed: &m.claimed,
                            exact: &m.exact,
                            reason: &m.reason,
                        })
                        .collect(),
                    _ => vec![],
                };
                ClaimJson {
                    file: &j.file,
                    id: &j.id,
                    op: &j.op,
                    source: &j.source,
                    erratum: &j.erratum,
                    tolerance: j.tolerance.text(),
                    precision: j.precision.map(|p| p.name()),
                    verdict: verdict_word(&j.verdict, ok_word),
                    exact: j.exact.to_json(),
                    claimed: j.claimed.to_json(),
                    mismatches,
                    float: j.floats.iter().map(FloatJson::from).collect(),
                }
            })
            .collect();
        ReportJson {
            claims,
            summary: SummaryJson {
                claims: self.claims(),
                files: self.files.len(),
                passed: self.passed(),
                errata: self.errata(),
                failed: self.failed(),
                ulp_histogram: self.histogram(),
                baseline_regressions: &self.baseline_regressions,
            },
        }
        .serialize(s)
    }
}
