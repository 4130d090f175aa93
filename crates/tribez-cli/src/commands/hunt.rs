//! `tribez hunt PATCH -- PROGRAM [ARGS...]`: search for the inputs where another program is
//! least accurate. The search is the library's [`tribez::hunt`]; this file runs the program
//! and talks to it over a pipe (guide, "Hunting for the worst inputs"), and renders the report
//! (text, JSON, JUnit, a claim file, the error map).
//!
//! The pipe protocol: each row is written to the program's standard input as one line, its
//! numbers comma-separated hex floats; the program answers one line per row, in order, its
//! result's coordinates comma-separated in any syntax `check --results` reads. A writer thread
//! writes a batch while a reader thread reads the answers, so a program that answers line by
//! line and one that reads a whole batch first both work. A program that exits early, answers
//! a malformed line or the wrong number of coordinates, or nothing within `--timeout`, ends the
//! hunt (exit status 2, one line naming the row); the program is always killed and reaped.

use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::time::{Duration, Instant};

use serde_json::Value as Json;

use super::{CliError, Outcome};
use crate::cli::{OutputArgs, whole_number};
use crate::report::{JunitCase, JunitSuite, Render, to_json};
use tribez::hunt::{
    HuntError, HuntLabels, HuntOptions, HuntReport, MAX_BATCH, MAX_BUDGET, MAX_TOP,
};
use tribez::{Patch, Precision, Tolerance};

// The arguments of `tribez hunt` (a plain comment: see `Command`).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The patch file (a polynomial Bézier patch).
    pub patch: PathBuf,
    /// The precision of the rows and of the program's answers.
    #[arg(long, default_value = "f64", value_name = "f64|f32")]
    pub precision: String,
    /// The tolerance every row is judged with (as `check --results`): exact, ulps=N, abs=E, rel=E, correctly_rounded, faithful, cond=K, cond, bound.
    #[arg(long, default_value = "cond", value_name = "T")]
    pub tolerance: String,
    /// Rows given to the program, at most.
    #[arg(long, default_value_t = 10_000, value_name = "N", value_parser = whole_number::<u64>(1, MAX_BUDGET))]
    pub budget: u64,
    /// The seed of the search (the report prints it; the same seed repeats the hunt).
    #[arg(long, value_name = "S", value_parser = crate::cli::seed)]
    pub seed: Option<u64>,
    /// Give the program Cartesian points of the domain (else barycentric coordinates).
    #[arg(long)]
    pub cartesian: bool,
    /// The most rows written to the program before its answers are awaited.
    #[arg(long, default_value_t = 4096, value_name = "B", value_parser = whole_number::<usize>(1, MAX_BATCH as u64))]
    pub batch: usize,
    /// The worst rows reported.
    #[arg(long, default_value_t = 10, value_name = "K", value_parser = whole_number::<usize>(1, MAX_TOP as u64))]
    pub top: usize,
    /// Write the worst rows as `eval` claims that `tribez check FILE` judges again.
    #[arg(long, value_name = "FILE")]
    pub claims_out: Option<PathBuf>,
    /// Draw every evaluated row on the error map, the worst rows labelled (FILE.svg or FILE.png).
    #[arg(long, value_name = "FILE")]
    pub plot: Option<PathBuf>,
    /// Write a self-contained HTML report with the error map.
    #[arg(long, value_name = "FILE")]
    pub html: Option<PathBuf>,
    /// Write JUnit XML: one test case per reported row.
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Seconds to wait for each answer line before the program is deemed hung.
    #[arg(long, default_value = "60", value_name = "SECONDS", value_parser = seconds)]
    pub timeout: f64,
    #[command(flatten)]
    pub out: OutputArgs,
    /// The program to hunt in, and its arguments (after `--`).
    #[arg(last = true, required = true, value_name = "PROGRAM")]
    pub program: Vec<String>,
}

fn seconds(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 && x <= 1e6 => Ok(x),
        _ => Err("expected a number of seconds, more than 0 and at most 1000000".into()),
    }
}

/// The longest answer line read from the program (1 MiB).
const MAX_LINE: usize = 1 << 20;

/// Why a program broke the protocol: the message names the row.
#[derive(Debug)]
struct Broken(String);

impl std::fmt::Display for Broken {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// What the reader thread sends: answer lines (in order), then the end of the output or a read
/// error.
enum Read_ {
    Lines(Vec<String>),
    End,
    TooLong,
    Failed(String),
}

/// The running program: killed and reaped when dropped (whatever ended the hunt).
struct Target {
    child: Child,
    name: String,
    writer: Option<(Sender<Vec<u8>>, std::thread::JoinHandle<()>)>,
    write_error: Receiver<String>,
    lines: Receiver<Read_>,
    pending: std::collections::VecDeque<String>,
    ended: bool,
    timeout: Duration,
    precision: Precision,
    width: usize,
    dim: usize,
    rows_sent: u64,
}

impl Drop for Target {
    fn drop(&mut self) {
        self.writer.take();
        if !matches!(self.child.try_wait(), Ok(Some(_))) {
            let _ = self.child.kill();
        }
        let _ = self.child.wait();
    }
}

impl Target {
    fn start(
        program: &[String],
        args: &Args,
        width: usize,
        dim: usize,
    ) -> Result<Target, CliError> {
        let name = program[0].clone();
        let mut child = Command::new(&program[0])
            .args(&program[1..])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .map_err(|e| CliError::Usage(format!("{name}: cannot start the program: {e}")))?;
        let stdin: ChildStdin = child.stdin.take().expect("piped");
        let stdout = child.stdout.take().expect("piped");
        let (line_tx, lines) = mpsc::channel();
        std::thread::spawn(move || read_lines(stdout, &line_tx));
        let (write_tx, write_rx) = mpsc::channel::<Vec<u8>>();
        let (err_tx, write_error) = mpsc::channel();
        let handle = std::thread::spawn(move || {
            let mut stdin = stdin;
            for buf in write_rx {
                if let Err(e) = stdin.write_all(&buf).and_then(|()| stdin.flush()) {
                    let _ = err_tx.send(e.to_string());
                    return;
                }
            }
            // the channel closed: close standard input
        });
        Ok(Target {
            child,
            name,
            writer: Some((write_tx, handle)),
            write_error,
            lines,
            pending: Default::default(),
            ended: false,
            timeout: Duration::from_secs_f64(args.timeout),
            precision: args.precision.parse().unwrap_or(Precision::F64),
            width,
            dim,
            rows_sent: 0,
        })
    }

    /// How the program ended, if it has (for messages).
    fn status(&mut self) -> String {
        // give an exiting program a moment to be reaped
        for _ in 0..20 {
            if let Ok(Some(s)) = self.child.try_wait() {
                return format!(" ({s})");
            }
            std::thread::sleep(Duration::from_millis(5));
        }
        String::new()
    }

    /// Give the program `rows` and read its answers.
    fn call(&mut self, rows: &[f64]) -> Result<Vec<f64>, Broken> {
        let n = rows.len() / self.width;
        let first = self.rows_sent + 1;
        let mut buf = String::with_capacity(n * self.width * 24);
        for row in rows.chunks(self.width) {
            for (i, &x) in row.iter().enumerate() {
                if i > 0 {
                    buf.push(',');
                }
                buf.push_str(&tribez::hunt::hex(self.precision, x));
            }
            buf.push('\n');
        }
        self.rows_sent += n as u64;
        if let Some((tx, _)) = &self.writer {
            // a closed channel means the writer failed: told below by the missing answers
            let _ = tx.send(buf.into_bytes());
        }
        let mut out = Vec::with_capacity(n * self.dim);
        for i in 0..n as u64 {
            let row = first + i;
            let line = self.next_line(row, rows, first)?;
            match tribez::batch::read_claimed_line(&line, self.dim, self.precision, &mut out) {
                Ok(()) => {}
                Err(e) => {
                    return Err(Broken(format!(
                        "{}: row {row} ({}): the answer `{}` is not {}: {e}",
                        self.name,
                        self.row_text(rows, first, row),
                        shorten(&line),
                        match self.dim {
                            1 => "1 number".to_string(),
                            d => format!("{d} numbers"),
                        }
                    )));
                }
            }
        }
        Ok(out)
    }

    fn row_text(&self, rows: &[f64], first: u64, row: u64) -> String {
        let i = (row - first) as usize;
        rows[i * self.width..(i + 1) * self.width]
            .iter()
            .map(|&x| tribez::hunt::hex(self.precision, x))
            .collect::<Vec<_>>()
            .join(",")
    }

    fn next_line(&mut self, row: u64, rows: &[f64], first: u64) -> Result<String, Broken> {
        loop {
            if let Some(l) = self.pending.pop_front() {
                return Ok(l);
            }
            let ended = |t: &mut Target, why: &str| {
                let status = t.status();
                let input = t.row_text(rows, first, row);
                Broken(format!("{}: row {row} ({input}): {why}{status}", t.name))
            };
            if self.ended {
                return Err(ended(self, "the program's output ended before its answer"));
            }
            match self.lines.recv_timeout(self.timeout) {
                Ok(Read_::Lines(ls)) => self.pending.extend(ls),
                Ok(Read_::End) | Err(RecvTimeoutError::Disconnected) => {
                    self.ended = true;
                    let why = match self.write_error.try_recv() {
                        Ok(e) => {
                            format!("the program exited before its answer (writing its input: {e})")
                        }
                        Err(_) => "the program's output ended before its answer".into(),
                    };
                    return Err(ended(self, &why));
                }
                Ok(Read_::TooLong) => {
                    return Err(ended(
                        self,
                        &format!("the answer line is longer than {MAX_LINE} bytes"),
                    ));
                }
                Ok(Read_::Failed(e)) => {
                    return Err(ended(self, &format!("reading the program's output: {e}")));
                }
                Err(RecvTimeoutError::Timeout) => {
                    let _ = self.child.kill();
                    let secs = self.timeout.as_secs_f64();
                    return Err(ended(
                        self,
                        &format!("no answer within {secs} s (--timeout); the program was stopped"),
                    ));
                }
            }
        }
    }

    /// Close standard input and wait (at most the timeout) for the program to exit; an answer
    /// line beyond the rows given is an error.
    fn finish(mut self) -> Result<(), CliError> {
        if let Some((tx, handle)) = self.writer.take() {
            drop(tx);
            let _ = handle.join();
        }
        let deadline = Instant::now() + self.timeout;
        loop {
            if let Some(l) = self.pending.pop_front() {
                if !l.trim().is_empty() {
                    return Err(CliError::Usage(format!(
                        "{}: answered more lines than the {} rows given (`{}`)",
                        self.name,
                        self.rows_sent,
                        shorten(&l)
                    )));
                }
                continue;
            }
            if self.ended {
                break;
            }
            let left = deadline.saturating_duration_since(Instant::now());
            match self.lines.recv_timeout(left) {
                Ok(Read_::Lines(ls)) => self.pending.extend(ls),
                Ok(_) | Err(RecvTimeoutError::Disconnected) => self.ended = true,
                Err(RecvTimeoutError::Timeout) => break,
            }
        }
        Ok(())
    }
}

fn shorten(s: &str) -> String {
    let s = s.trim_end();
    if s.chars().count() > 80 {
        format!("{}…", s.chars().take(80).collect::<String>())
    } else {
        s.to_string()
    }
}

/// The reader thread: lines of the program's output, sent in groups (a group ends where the
/// output has nothing more buffered, so that a program answering line by line is never kept
/// waiting), then the end.
fn read_lines(stdout: impl Read, tx: &Sender<Read_>) {
    let mut r = BufReader::with_capacity(1 << 16, stdout);
    let mut group = Vec::new();
    loop {
        let mut line = Vec::new();
        let mut too_long = false;
        let got = loop {
            let buf = match r.fill_buf() {
                Ok(b) => b,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(e) => {
                    let _ = tx.send(Read_::Lines(std::mem::take(&mut group)));
                    let _ = tx.send(Read_::Failed(e.to_string()));
                    return;
                }
            };
            if buf.is_empty() {
                break !line.is_empty();
            }
            match memchr(buf) {
                Some(i) => {
                    line.extend_from_slice(&buf[..i]);
                    r.consume(i + 1);
                    break true;
                }
                None => {
                    let len = buf.len();
                    line.extend_from_slice(buf);
                    r.consume(len);
                }
            }
            if line.len() > MAX_LINE {
                too_long = true;
                break true;
            }
        };
        if too_long {
            let _ = tx.send(Read_::Lines(std::mem::take(&mut group)));
            let _ = tx.send(Read_::TooLong);
            return;
        }
        if !got {
            let _ = tx.send(Read_::Lines(std::mem::take(&mut group)));
            let _ = tx.send(Read_::End);
            return;
        }
        if line.last() == Some(&b'\r') {
            line.pop();
        }
        group.push(String::from_utf8_lossy(&line).into_owned());
        if (r.buffer().is_empty() || group.len() >= 4096)
            && tx.send(Read_::Lines(std::mem::take(&mut group))).is_err()
        {
            return;
        }
    }
}

fn memchr(b: &[u8]) -> Option<usize> {
    b.iter().position(|&c| c == b'\n')
}

/// The hunt's report, with what the command line adds: the patch's and program's names, the
/// command that repeats the hunt.
pub struct Report {
    /// The library's report.
    pub hunt: HuntReport,
    /// The patch file as given.
    pub patch: String,
    /// The program and its arguments.
    pub program: Vec<String>,
    /// The command that repeats the hunt.
    pub command: Vec<String>,
}

impl Report {
    /// How the command line names the program and the way to repeat the hunt.
    fn labels(&self) -> (String, String) {
        (
            crate::picture::html::shell_line(&self.program),
            crate::picture::html::shell_line(&self.command),
        )
    }
}

fn hexes(p: Precision, xs: &[f64]) -> Vec<String> {
    tribez::hunt::hexes(p, xs)
}

fn ulps_text(u: f64) -> String {
    tribez::hunt::ulps_text(u)
}

impl Render for Report {
    fn text(&self) -> String {
        let (program, reproduce) = self.labels();
        self.hunt.text(&HuntLabels {
            tool: "tribez hunt",
            patch: &self.patch,
            program: &program,
            reproduce: &reproduce,
        })
    }

    fn json(&self) -> Json {
        to_json(&self.hunt.json(&self.patch, &self.program, &self.command))
    }

    fn junit(&self) -> Option<JunitSuite> {
        let p = self.hunt.precision;
        Some(JunitSuite {
            suite: "tribez hunt",
            cases: self
                .hunt
                .worst
                .iter()
                .map(|r| JunitCase {
                    name: format!("{}.row {}", self.patch, r.row),
                    checks: 1,
                    failures: if r.passed {
                        Vec::new()
                    } else {
                        vec![format!(
                            "row {} at ({}): {} ulp, breaks {}{}",
                            r.row,
                            hexes(p, &r.input).join(", "),
                            ulps_text(r.ulps),
                            self.hunt.tolerance,
                            r.reason
                                .as_ref()
                                .map(|s| format!(": {s}"))
                                .unwrap_or_default()
                        )]
                    },
                })
                .collect(),
        })
    }
}

/// The path of `target` relative to the directory `from` (both made absolute first).
fn relative(target: &Path, from: &Path) -> PathBuf {
    let abs = |p: &Path| {
        std::fs::canonicalize(p).unwrap_or_else(|_| {
            std::env::current_dir()
                .map(|d| d.join(p))
                .unwrap_or_else(|_| p.to_path_buf())
        })
    };
    let (t, f) = (abs(target), abs(from));
    let tc: Vec<_> = t.components().collect();
    let fc: Vec<_> = f.components().collect();
    let common = tc.iter().zip(&fc).take_while(|(a, b)| a == b).count();
    let mut out = PathBuf::new();
    for _ in common..fc.len() {
        out.push("..");
    }
    for c in &tc[common..] {
        out.push(c);
    }
    out
}

/// The claim file of the worst rows (`--claims-out`), its patch the file as a path relative to
/// the claim file's directory.
fn claims_file(report: &Report, patch: &Path, out: &Path) -> String {
    let dir = out
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let rel = relative(patch, dir);
    let (program, reproduce) = report.labels();
    report.hunt.claims_file(
        &HuntLabels {
            tool: "tribez hunt",
            patch: &report.patch,
            program: &program,
            reproduce: &reproduce,
        },
        &HuntReport::toml_entry("patch", &rel.to_string_lossy()),
    )
}

/// Run `tribez hunt`.
pub fn run(args: &Args) -> Result<Outcome, CliError> {
    let precision: Precision = args
        .precision
        .parse()
        .map_err(|e| CliError::about("--precision", e))?;
    let tolerance =
        Tolerance::parse(&args.tolerance).map_err(|e| CliError::about("--tolerance", e))?;
    let pictures = crate::picture::reports::Pictures {
        plot: args.plot.clone(),
        html: args.html.clone(),
    };
    pictures.check_names()?;
    let patch = Patch::from_file(&args.patch)?;
    let seed = args.seed.unwrap_or_else(|| {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos() as u64 ^ u64::from(std::process::id()))
            .unwrap_or(0)
    });
    let options = HuntOptions {
        precision,
        tolerance,
        budget: args.budget,
        seed,
        cartesian: args.cartesian,
        batch: args.batch,
        top: args.top,
    };
    let m = patch.simplex_dim();
    let width = if args.cartesian { m } else { m + 1 };
    let dim = patch.dimension();
    let mut map = if pictures.any() {
        let outline = crate::picture::reports::outline(
            &patch,
            if args.plot.is_some() {
                "--plot"
            } else {
                "--html"
            },
        )?;
        Some(crate::picture::errmap::MapBuilder::new(outline))
    } else {
        None
    };
    let mut target = Target::start(&args.program, args, width, dim)?;
    let cartesian = args.cartesian;
    let mut histogram = tribez::batch::UlpHistogram::default();
    let place = |outline: &[[f64; 2]], input: &[f64]| {
        if cartesian {
            [input[0], input.get(1).copied().unwrap_or(0.0)]
        } else {
            crate::picture::reports::position(outline, input)
        }
    };
    let result = tribez::hunt::hunt_each_row(
        &patch,
        &options,
        &mut |rows: &[f64]| target.call(rows),
        &mut |r| {
            if let Some(map) = &mut map {
                histogram.add(r.ulps);
                let at = place(map.outline(), r.input);
                let row = usize::try_from(r.row).unwrap_or(usize::MAX);
                map.add(row, at, r.ulps, r.ulps, r.pass);
            }
        },
    );
    let hunt = match result {
        Ok(h) => h,
        Err(HuntError::Target(Broken(msg))) => return Err(CliError::Usage(msg)),
        Err(e) => return Err(CliError::about(args.patch.display().to_string(), e)),
    };
    target.finish()?;
    let mut command: Vec<String> = vec![
        "tribez".into(),
        "hunt".into(),
        args.patch.display().to_string(),
        "--precision".into(),
        precision.name().into(),
        "--tolerance".into(),
        args.tolerance.clone(),
        "--budget".into(),
        args.budget.to_string(),
        "--seed".into(),
        seed.to_string(),
    ];
    if args.cartesian {
        command.push("--cartesian".into());
    }
    if args.batch != 4096 {
        command.extend(["--batch".into(), args.batch.to_string()]);
    }
    if args.top != 10 {
        command.extend(["--top".into(), args.top.to_string()]);
    }
    command.push("--".into());
    command.extend(args.program.iter().cloned());
    let report = Report {
        hunt,
        patch: args.patch.display().to_string(),
        program: args.program.clone(),
        command,
    };
    let success = report.hunt.broke == 0;
    if let Some(path) = &args.claims_out {
        super::write_atomically(path, claims_file(&report, &args.patch, path).as_bytes())?;
    }
    if let Some(path) = &args.junit {
        super::write_junit(path, &report)?;
    }
    if let Some(map) = map {
        let labels = report
            .hunt
            .worst
            .iter()
            .map(|r| place(map.outline(), &r.input))
            .collect();
        crate::picture::reports::hunt(&pictures, &report, map.finish(), histogram.counts, labels)?;
    }
    Outcome::rendered(&report, args.out.format, success)
}
