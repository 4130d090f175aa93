//! `--plot FILE` and `--html FILE` of `tribez check --patch P --results R` and `tribez
//! certify`: the error maps of their runs and the HTML report, staged with the run's other
//! outputs.

use std::path::{Path, PathBuf};

use num_rational::BigRational;

use super::errmap::{self, MapBuilder, MapData, Panel, ulps_text};
use super::html::{self, HtmlReport, Section};
use crate::error::CliError;
use tribez::batch::{BatchChecker, BatchReport, FailedCoord, RowPoint, UlpHistogram};
use tribez::claims::ClaimsReport;
use tribez::format::format_tuple;
use tribez::format::{format_rational, round_f64, to_decimal_string};
use tribez::{CertifyReport, Patch};

/// The picture outputs a run asked for.
#[derive(Clone, Debug, Default)]
pub struct Pictures {
    /// `--plot FILE`.
    pub plot: Option<PathBuf>,
    /// `--html FILE`.
    pub html: Option<PathBuf>,
}

impl Pictures {
    /// Any picture asked for?
    pub fn any(&self) -> bool {
        self.plot.is_some() || self.html.is_some()
    }

    /// Refuse bad file names before the run (one line, exit status 2).
    pub fn check_names(&self) -> Result<(), CliError> {
        if let Some(p) = &self.plot {
            super::format_of(p, "--plot")?;
        }
        if let Some(h) = &self.html {
            super::check_html_name(h)?;
        }
        Ok(())
    }
}

/// The outline of a patch's domain for an error map (its triangle, or an S-patch's polygon),
/// or why there is no map (`flag` names the option).
pub fn outline(patch: &Patch, flag: &str) -> Result<Vec<[f64; 2]>, CliError> {
    let vertices: Vec<Vec<BigRational>> = patch.domain_vertices();
    if vertices.first().is_none_or(|v| v.len() != 2) {
        return Err(CliError::Usage(format!(
            "{flag}: error maps are drawn over triangles and polygons; this patch is over the {}-simplex",
            patch.simplex_dim()
        )));
    }
    Ok(vertices
        .iter()
        .map(|v| [round_f64(&v[0]), round_f64(&v[1])])
        .collect())
}

/// The position in the domain (Cartesian) of barycentric coordinates `lambda` (homogeneous:
/// divided by their sum) over the triangle `outline`.
pub fn position(outline: &[[f64; 2]], lambda: &[f64]) -> [f64; 2] {
    let total: f64 = lambda.iter().sum();
    let mut p = [0.0; 2];
    for (l, v) in lambda.iter().zip(outline) {
        p[0] += l * v[0];
        p[1] += l * v[1];
    }
    [p[0] / total, p[1] / total]
}

/// A rational exactly (lowest terms) and, when it is not an integer, to 17 significant digits.
fn exact_text(q: &BigRational) -> String {
    let exact = format_rational(q);
    if q.is_integer() {
        exact
    } else {
        format!("{exact} ≈ {}", to_decimal_string(q, 17))
    }
}

fn coord_rows(coords: &[FailedCoord], line: usize) -> Vec<Vec<String>> {
    coords
        .iter()
        .map(|c| {
            vec![
                line.to_string(),
                c.index.to_string(),
                format!("{} ({})", c.decimal, c.hex),
                exact_text(&c.exact_seen),
                c.seen
                    .ulps
                    .as_ref()
                    .map_or("-".into(), |u| ulps_text(round_f64(u))),
                c.exact_intended.as_ref().map_or("-".into(), exact_text),
            ]
        })
        .collect()
}

const COORD_HEADER: [&str; 6] = [
    "line",
    "coordinate",
    "claimed (shortest decimal, hexadecimal)",
    "exact value at the inputs as seen",
    "error (ulp)",
    "exact value at the inputs as intended",
];

/// The rows of a batch that may have the smallest error: their lower bound is at most the
/// smallest upper bound seen (a row the float filter decided has an enclosure of its error, not
/// the error). [`Smallest::settle`] computes the smallest error exactly from them.
#[derive(Clone, Debug)]
pub struct Smallest {
    ceiling: Option<f64>,
    /// A row with exactly the ceiling's error is among the candidates.
    exact_at_ceiling: bool,
    rows: Vec<RowPoint>,
    complete: bool,
}

/// At most this many candidates are kept (past it the smallest error is the figures').
const MAX_SMALLEST: usize = 4096;

impl Smallest {
    /// No rows yet.
    pub fn new() -> Smallest {
        Smallest {
            ceiling: None,
            exact_at_ceiling: false,
            rows: Vec::new(),
            complete: true,
        }
    }

    /// A row, as judged.
    pub fn add(&mut self, r: &RowPoint) {
        if !r.ulps.is_finite() || self.ceiling.is_some_and(|c| r.ulps_lower > c) {
            return;
        }
        let exact = r.ulps_lower == r.ulps;
        if self.ceiling.is_none_or(|c| r.ulps < c) {
            let c = r.ulps;
            self.ceiling = Some(c);
            self.exact_at_ceiling = false;
            if self.rows.len() >= 64 {
                self.rows.retain(|x| x.ulps_lower <= c);
            }
        } else if exact && self.exact_at_ceiling && self.ceiling == Some(r.ulps) {
            // another row with exactly the smallest error known: nothing to learn
            return;
        }
        if exact && self.ceiling == Some(r.ulps) {
            self.exact_at_ceiling = true;
        }
        if self.rows.len() < MAX_SMALLEST {
            self.rows.push(r.clone());
        } else {
            self.complete = false;
        }
    }

    /// The smallest error, exactly: every candidate whose lower bound is below the best exact
    /// error so far is judged again in memory ([`BatchChecker::check_rows`] computes one row's
    /// error exactly); `None` when there were too many candidates or a row could not be judged.
    pub fn settle(mut self, checker: &BatchChecker) -> Option<f64> {
        let ceiling = self.ceiling?;
        if !self.complete {
            return None;
        }
        self.rows.retain(|r| r.ulps_lower <= ceiling);
        self.rows
            .sort_by(|a, b| a.ulps_lower.total_cmp(&b.ulps_lower));
        let mut best: Option<f64> = None;
        for r in &self.rows {
            if best.is_some_and(|b| r.ulps_lower >= b) {
                break;
            }
            let exact = if r.ulps_lower == r.ulps {
                r.ulps
            } else {
                let (report, _) = checker
                    .check_rows(&r.inputs, &r.claimed, r.row, "<row>", "<patch>")
                    .ok()?;
                report.max_ulps?
            };
            best = Some(best.map_or(exact, |b| b.min(exact)));
        }
        best
    }
}

/// The panel of a batch's error map.
fn batch_panel(report: &BatchReport, min_ulps: Option<f64>) -> Panel {
    Panel {
        title: format!(
            "{}: {} rows against {}, tolerance {} — {} failed",
            report.file, report.checked, report.patch, report.tolerance, report.failed
        ),
        max_ulps: report.max_ulps,
        min_ulps,
        worst: report.worst.as_ref().map(|w| {
            (
                w.line,
                format!("worst: line {}, {} ulp", w.line, ulps_text(w.ulps)),
            )
        }),
        histogram: report.histogram.counts,
        labels: Vec::new(),
        note: if report.histogram_upper_bounds {
            "rows the float filter decided: the upper end of their error's enclosure (the scale's ends are exact)".into()
        } else {
            String::new()
        },
    }
}

/// Stage `--plot` and `--html` of a batch run (`command`: the arguments that reproduce it).
pub fn batch(
    pictures: &Pictures,
    report: &BatchReport,
    map: MapData,
    min_ulps: Option<f64>,
    command: &[String],
) -> Result<(), CliError> {
    let panel = batch_panel(report, min_ulps);
    let range = map.range(panel.max_ulps, panel.min_ulps);
    let panels = [(map, panel)];
    let svg = errmap::svg(&panels, &format!("error map of {}", report.file));
    if let Some(path) = &pictures.plot {
        super::stage(path, &svg, "--plot")?;
    }
    let Some(path) = &pictures.html else {
        return Ok(());
    };
    let passed = report.failed == 0;
    let mut summary = vec![
        ("results".to_string(), report.file.clone()),
        ("patch".into(), report.patch.clone()),
        ("tolerance".into(), report.tolerance.to_string()),
        (
            "numbers".into(),
            report
                .precision
                .map_or("exact".into(), |p| format!("each the nearest {}", p.name())),
        ),
        ("rows checked".into(), report.checked.to_string()),
        ("passed".into(), report.passed.to_string()),
        ("failed".into(), report.failed.to_string()),
    ];
    if report.histogram_upper_bounds {
        summary.push((
            "decided by the float filter / exact arithmetic".into(),
            format!(
                "{} / {}",
                report.checked - report.fell_back,
                report.fell_back
            ),
        ));
    }
    if let Some((lo, hi)) = range {
        summary.push(("smallest error (ulp)".into(), ulps_text(lo)));
        summary.push(("largest error (ulp)".into(), ulps_text(hi)));
    }
    let mut sections = Vec::new();
    if let Some(w) = &report.worst {
        sections.push(Section::Table {
            heading: format!("Worst row: line {} ({} ulp)", w.line, ulps_text(w.ulps)),
            note: "The error is computed exactly against the exact value at the inputs as the code saw them (the floats).".into(),
            header: COORD_HEADER.map(String::from).to_vec(),
            rows: coord_rows(&w.coords, w.line),
        });
    }
    if !report.failures.is_empty() {
        let mut rows = Vec::new();
        for f in &report.failures {
            let mut r = coord_rows(&f.coords, f.line);
            if r.is_empty() {
                r.push(vec![
                    f.line.to_string(),
                    "-".into(),
                    f.reason.clone(),
                    "-".into(),
                    "-".into(),
                    "-".into(),
                ]);
            }
            rows.extend(r);
        }
        let more = report.failures_not_listed();
        sections.push(Section::Table {
            heading: format!("Failures ({} of {})", report.failures.len(), report.failed),
            note: if more > 0 {
                format!(
                    "The first {} failed rows; {more} more are counted, not listed.",
                    report.failures.len()
                )
            } else {
                String::new()
            },
            header: COORD_HEADER.map(String::from).to_vec(),
            rows,
        });
    }
    let page = html::render(&HtmlReport {
        title: format!("tribez check: {}", report.file),
        passed,
        verdict: if passed {
            format!(
                "all {} rows within tolerance {}",
                report.checked, report.tolerance
            )
        } else {
            format!(
                "{} of {} rows fail tolerance {}",
                report.failed, report.checked, report.tolerance
            )
        },
        summary,
        reproduce: html::shell_line(command),
        pictures: svg,
        sections,
        text: report.text(),
    });
    crate::output::stage(path, page.as_bytes())
}

/// Stage `--plot` and `--html` of a certification run (one panel per algorithm and precision).
pub fn certify(
    pictures: &Pictures,
    patch: &Patch,
    report: &CertifyReport,
    command: &[String],
) -> Result<(), CliError> {
    let outline = outline(
        patch,
        if pictures.plot.is_some() {
            "--plot"
        } else {
            "--html"
        },
    )?;
    let panels = certify_panels(patch, report, outline);
    let svg = errmap::svg(&panels, &format!("error maps of {}", report.patch));
    if let Some(path) = &pictures.plot {
        super::stage(path, &svg, "--plot")?;
    }
    let Some(path) = &pictures.html else {
        return Ok(());
    };
    let passed = report.success();
    let summary = certify_summary(report, &panels);
    let mut sections = vec![Section::Table {
        heading: "Worst points".into(),
        note: "The float result is the float program's, rerun at the point rounded to the precision; the exact value is at that rounded point.".into(),
        header: ["run", "point (exact)", "error (ulp)", "float result", "exact value"]
            .map(String::from)
            .to_vec(),
        rows: certify_worst_rows(patch, report),
    }];
    let violations = certify_violations(report);
    if !violations.is_empty() {
        sections.push(Section::Table {
            heading: "Bound exceeded".into(),
            note: "At most 100 per run.".into(),
            header: vec!["run".into(), "where and by how much".into()],
            rows: violations,
        });
    }
    let page = html::render(&HtmlReport {
        title: format!("tribez certify: {}", report.patch),
        passed,
        verdict: if passed {
            "every result within its proven bound".into()
        } else {
            "some result exceeds its proven bound (or a baseline regressed)".into()
        },
        summary,
        reproduce: report
            .random
            .as_ref()
            .map_or_else(|| html::shell_line(command), |r| r.reproduce.clone()),
        pictures: svg,
        sections,
        text: report.text(),
    });
    crate::output::stage(path, page.as_bytes())
}

/// One error map per run (algorithm and precision) of `certify`: every point at its place in
/// the domain (`outline`), the worst point marked.
fn certify_panels(
    patch: &Patch,
    report: &CertifyReport,
    outline: Vec<[f64; 2]>,
) -> Vec<(MapData, Panel)> {
    let polygon = outline.len() != 3 || matches!(patch.kind(), tribez::PatchKind::SPatch);
    let positions: Vec<[f64; 2]> = report
        .inputs
        .iter()
        .map(|p| {
            let x: Vec<f64> = p.iter().map(round_f64).collect();
            if polygon {
                [x[0], x[1]]
            } else {
                position(&outline, &x)
            }
        })
        .collect();
    let mut panels = Vec::new();
    for row in &report.rows {
        let mut b = MapBuilder::new(outline.clone());
        let mut histogram = UlpHistogram::default();
        for (i, (r, &at)) in row.per_point.iter().zip(&positions).enumerate() {
            b.add(i + 1, at, r.ulps, r.ulps, !r.exceeded);
            histogram.add(r.ulps);
        }
        let worst = row
            .per_point
            .iter()
            .position(|r| r.ulps == row.max_ulps && row.worst_point.is_some());
        let (a, p) = (row.algorithm.name(), row.precision.name());
        panels.push((
            b.finish(),
            Panel {
                title: format!(
                    "{}: {a} in {p}, {} points — max {} ulp, {}",
                    report.patch,
                    report.points,
                    ulps_text(row.max_ulps),
                    if row.within_bound() {
                        "within the bound"
                    } else {
                        "BOUND EXCEEDED"
                    }
                ),
                max_ulps: Some(row.max_ulps),
                min_ulps: None,
                labels: Vec::new(),
                worst: worst.map(|i| {
                    (
                        i + 1,
                        format!("worst: point {}, {} ulp", i + 1, ulps_text(row.max_ulps)),
                    )
                }),
                histogram: histogram.counts,
                note: if row.outside_hypothesis > 0 {
                    format!(
                        "{} points outside the bound's hypotheses (not judged)",
                        row.outside_hypothesis
                    )
                } else {
                    String::new()
                },
            },
        ));
    }
    panels
}

/// The summary table of the `certify` HTML report: the points, and per run the range of the
/// errors, the share correctly rounded, the largest error ÷ bound and the verdict.
fn certify_summary(report: &CertifyReport, panels: &[(MapData, Panel)]) -> Vec<(String, String)> {
    let mut summary = vec![
        ("patch".to_string(), report.patch.clone()),
        ("points".into(), report.points.to_string()),
    ];
    if let Some(r) = &report.random {
        summary.push((
            "random points".into(),
            format!("{}, seed {}", r.count, r.seed),
        ));
    }
    for (row, (data, _)) in report.rows.iter().zip(panels) {
        let range = data.range(Some(row.max_ulps), None);
        summary.push((
            format!("{} {}", row.algorithm.name(), row.precision.name()),
            format!(
                "errors from {} to {} ulp; {:.2}% correctly rounded; largest error ÷ bound {}; {}",
                range.map_or("-".into(), |r| ulps_text(r.0)),
                ulps_text(row.max_ulps),
                100.0 * row.correctly_rounded as f64 / row.coordinates.max(1) as f64,
                ulps_text(row.max_bound_ratio),
                if row.within_bound() {
                    "within the bound"
                } else {
                    "BOUND EXCEEDED"
                }
            ),
        ));
    }
    summary
}

/// The worst point of each run of `certify`: the point, its error, the float program's result
/// there (rerun at the point rounded to the precision) and the exact value at that point.
fn certify_worst_rows(patch: &Patch, report: &CertifyReport) -> Vec<Vec<String>> {
    let float = patch.float();
    let mut worst_rows = Vec::new();
    for row in &report.rows {
        let Some(point) = &row.worst_point else {
            continue;
        };
        let case = float
            .and_then(|f| f.float_program(row.precision).ok())
            .and_then(|prog| {
                let input = prog.round_input(point).ok()?;
                let y = prog.run(row.algorithm, &input);
                Some((y, prog.exact_seen(&input)))
            });
        let (y, exact) = case.unwrap_or_default();
        worst_rows.push(vec![
            format!("{} {}", row.algorithm.name(), row.precision.name()),
            format_tuple(point),
            ulps_text(row.max_ulps),
            y.iter()
                .map(|v| format!("{v:?}"))
                .collect::<Vec<_>>()
                .join(", "),
            exact.map_or("undefined".into(), |e| {
                e.iter().map(exact_text).collect::<Vec<_>>().join(", ")
            }),
        ]);
    }
    worst_rows
}

/// The bound violations of `certify`, at most 100 per run.
fn certify_violations(report: &CertifyReport) -> Vec<Vec<String>> {
    report
        .rows
        .iter()
        .flat_map(|r| {
            r.violations.iter().take(100).map(move |v| {
                vec![
                    format!("{} {}", r.algorithm.name(), r.precision.name()),
                    v.clone(),
                ]
            })
        })
        .collect()
}

/// Stage the `--html` report of `tribez check` on claim files (`paths` as given).
pub fn claims(path: &Path, report: &ClaimsReport, paths: &[PathBuf]) -> Result<(), CliError> {
    let histogram = report.histogram();
    let pictures = if histogram.is_empty() {
        String::new()
    } else {
        let mut svg = super::svg::Svg::new(340.0, 420.0, &[]);
        svg.title("the histogram of the float claims' errors");
        errmap::histogram(&mut svg, 10.0, 10.0, &histogram.counts, "float claims");
        svg.finish()
    };
    let row = |j: &tribez::claims::Judged| {
        vec![
            j.file.clone(),
            j.id.clone(),
            j.op.clone(),
            j.claimed.to_text(),
            j.exact.to_text(),
            j.tolerance.to_string(),
        ]
    };
    let all = || report.files.iter().flat_map(|f| &f.claims);
    let failures: Vec<Vec<String>> = all().filter(|j| j.verdict.fails_run()).map(row).collect();
    let errata: Vec<Vec<String>> = all()
        .filter(|j| matches!(j.verdict, tribez::claims::Verdict::KnownErratum(_)))
        .map(row)
        .collect();
    let header = [
        "file",
        "claim",
        "operation",
        "claimed",
        "exact",
        "tolerance",
    ]
    .map(String::from)
    .to_vec();
    let mut sections = Vec::new();
    if !failures.is_empty() {
        sections.push(Section::Table {
            heading: format!("Failures ({})", failures.len()),
            note: String::new(),
            header: header.clone(),
            rows: failures,
        });
    }
    if !errata.is_empty() {
        sections.push(Section::Table {
            heading: format!("Known errata ({})", errata.len()),
            note: "Values printed in the sources that the exact computation contradicts (they do not fail the run).".into(),
            header,
            rows: errata,
        });
    }
    let mut command = vec!["tribez".to_string(), "check".into()];
    command.extend(paths.iter().map(|p| p.display().to_string()));
    let passed = report.success();
    let page = html::render(&HtmlReport {
        title: format!(
            "tribez check: {} claims in {} files",
            report.claims(),
            report.files.len()
        ),
        passed,
        verdict: if passed {
            format!("all {} claims hold", report.claims())
        } else {
            format!("{} of {} claims fail", report.failed(), report.claims())
        },
        summary: vec![
            ("files".into(), report.files.len().to_string()),
            ("claims".into(), report.claims().to_string()),
            ("passed".into(), report.passed().to_string()),
            ("known errata".into(), report.errata().to_string()),
            ("failed".into(), report.failed().to_string()),
        ],
        reproduce: html::shell_line(&command),
        pictures,
        sections,
        text: report.text(),
    });
    crate::output::stage(path, page.as_bytes())
}

/// The arguments of `tribez check` that reproduce a batch run.
pub fn batch_command(
    patch: &Path,
    results: &Path,
    tolerance: Option<&str>,
    precision: Option<&str>,
    cartesian: bool,
    algorithm: &str,
) -> Vec<String> {
    let mut c: Vec<String> = vec![
        "tribez".into(),
        "check".into(),
        "--patch".into(),
        patch.display().to_string(),
        "--results".into(),
        results.display().to_string(),
    ];
    if let Some(t) = tolerance {
        c.extend(["--tolerance".into(), t.into()]);
    }
    if let Some(p) = precision {
        c.extend(["--precision".into(), p.into()]);
    }
    if cartesian {
        c.push("--cartesian".into());
    }
    if algorithm != "casteljau" {
        c.extend(["--algorithm".into(), algorithm.into()]);
    }
    c
}

/// Stage `--plot` and `--html` of `tribez hunt`: every evaluated row on the error map (`map`,
/// with `histogram` the rows' counts by error), the worst rows ringed and labelled by rank
/// (`labels`: their positions), the worst of all as the map's worst row.
pub fn hunt(
    pictures: &Pictures,
    report: &crate::commands::hunt::Report,
    map: MapData,
    histogram: [u64; 8],
    labels: Vec<[f64; 2]>,
) -> Result<(), CliError> {
    let h = &report.hunt;
    let panel = Panel {
        title: format!(
            "{}: {} rows of {} against {}, tolerance {} — {} broke it",
            html::shell_line(&report.program),
            h.evaluated,
            h.precision.name(),
            report.patch,
            h.tolerance,
            h.broke
        ),
        max_ulps: h.max_ulps().filter(|u| u.is_finite()),
        min_ulps: None,
        worst: h.worst.first().map(|w| {
            (
                usize::try_from(w.row).unwrap_or(usize::MAX),
                format!("worst: row {}, {} ulp", w.row, ulps_text(w.ulps)),
            )
        }),
        labels: labels
            .into_iter()
            .zip(&h.worst)
            .enumerate()
            .skip(1)
            .map(|(i, (at, w))| (at, format!("{}. row {}", i + 1, w.row)))
            .collect(),
        histogram,
        note: "rows the float filter decided: the upper end of their error's enclosure; the labelled rows' errors are exact".into(),
    };
    let range = map.range(panel.max_ulps, panel.min_ulps);
    let panels = [(map, panel)];
    let svg = errmap::svg(
        &panels,
        &format!("tribez hunt: error map of {}", report.patch),
    );
    if let Some(path) = &pictures.plot {
        super::stage(path, &svg, "--plot")?;
    }
    let Some(path) = &pictures.html else {
        return Ok(());
    };
    let passed = h.broke == 0;
    let mut summary = vec![
        ("program".to_string(), html::shell_line(&report.program)),
        ("patch".into(), report.patch.clone()),
        ("tolerance".into(), h.tolerance.to_string()),
        ("precision".into(), h.precision.name().into()),
        ("seed".into(), h.seed.to_string()),
        ("rows evaluated".into(), h.evaluated.to_string()),
        ("broke the tolerance".into(), h.broke.to_string()),
    ];
    if let Some((lo, hi)) = range {
        summary.push(("smallest error (ulp)".into(), ulps_text(lo)));
        summary.push(("largest error (ulp)".into(), ulps_text(hi)));
    }
    let p = h.precision;
    let hex = |xs: &[f64]| {
        xs.iter()
            .map(|&x| tribez::hunt::hex(p, x))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let rows = h
        .worst
        .iter()
        .enumerate()
        .map(|(i, r)| {
            vec![
                (i + 1).to_string(),
                r.row.to_string(),
                hex(&r.input),
                hex(&r.claimed),
                r.exact
                    .iter()
                    .map(|q| tribez::hunt::decimal(q, 17))
                    .collect::<Vec<_>>()
                    .join(", "),
                ulps_text(r.ulps),
                if r.passed { "within" } else { "breaks" }.into(),
            ]
        })
        .collect();
    let sections = vec![Section::Table {
        heading: format!("The {} worst rows", h.worst.len()),
        note: "Each error is computed exactly against the exact value at the input as the program saw it.".into(),
        header: ["rank", "row", "input", "claimed", "exact", "error (ulp)", "tolerance"]
            .map(String::from)
            .to_vec(),
        rows,
    }];
    let page = html::render(&HtmlReport {
        title: format!("tribez hunt: {}", html::shell_line(&report.program)),
        passed,
        verdict: if passed {
            format!("no row of {} broke tolerance {}", h.evaluated, h.tolerance)
        } else {
            format!(
                "{} of {} rows broke tolerance {}",
                h.broke, h.evaluated, h.tolerance
            )
        },
        summary,
        reproduce: html::shell_line(&report.command),
        pictures: svg,
        sections,
        text: crate::report::Render::text(report),
    });
    crate::output::stage(path, page.as_bytes())
}
