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
            if fast_claimed_line(&line, self.precision, &mut out, self.dim) {
                continue;
            }
            match tribez::batch::parse_claimed_line(&line, self.dim, self.precision) {
                Ok(v) => out.extend(v),
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

/// The common answer lines read fast: `dim` comma-separated hex floats (`%a`) or plain decimals,
/// each finite, non-zero and normal in the precision, appended to `out` as the float of the
/// precision nearest the text (hex floats of at most 13 fraction digits are exact in `f64`;
/// decimals are read correctly rounded by the standard library). Anything else (quotes, JSON,
/// `p/q`, zeros, subnormals, not-finite values, a wrong count) returns false with `out`
/// unchanged, and the line goes to [`tribez::batch::parse_claimed_line`], which reads every
/// syntax `check --results` reads and gives the same numbers.
fn fast_claimed_line(line: &str, precision: Precision, out: &mut Vec<f64>, dim: usize) -> bool {
    let start = out.len();
    let mut fields = line.trim().split(',');
    for _ in 0..dim {
        let value = fields.next().map(str::trim).and_then(|f| {
            if f.len() > 40 {
                return None;
            }
            let b = f.as_bytes();
            let unsigned = b.strip_prefix(b"-").or(b.strip_prefix(b"+")).unwrap_or(b);
            if unsigned.len() > 2 && (unsigned[..2] == *b"0x" || unsigned[..2] == *b"0X") {
                hex_float(f)
            } else if plain_decimal(unsigned) {
                match precision {
                    Precision::F64 => f.parse::<f64>().ok(),
                    Precision::F32 => f.parse::<f32>().ok().map(f64::from),
                }
            } else {
                None
            }
        });
        let normal = |v: f64| match precision {
            Precision::F64 => v.is_normal(),
            Precision::F32 => (v as f32).is_normal(),
        };
        match value {
            Some(v) if normal(v) => out.push(match precision {
                Precision::F64 => v,
                Precision::F32 => f64::from(v as f32),
            }),
            _ => {
                out.truncate(start);
                return false;
            }
        }
    }
    if fields.next().is_some() {
        out.truncate(start);
        return false;
    }
    true
}

/// `[+-]?0x` hex digits, an optional `.` and hex digits (at most 13 digits in all after the
/// leading one), then `p[+-]?` decimal digits: its exact value when that is a normal `f64`.
fn hex_float(f: &str) -> Option<f64> {
    let (negative, rest) = match f.as_bytes().first()? {
        b'-' => (true, &f[1..]),
        b'+' => (false, &f[1..]),
        _ => (false, f),
    };
    let rest = rest.get(2..)?;
    let (mantissa, exponent) = rest.split_once(['p', 'P'])?;
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if int.len() != 1 || frac.len() > 13 {
        return None;
    }
    let mut m: u64 = 0;
    for c in int.bytes().chain(frac.bytes()) {
        m = m * 16 + u64::from((c as char).to_digit(16)?);
    }
    let e = exponent.strip_prefix('+').unwrap_or(exponent);
    if e.is_empty()
        || e.len() > 6
        || !e
            .trim_start_matches('-')
            .bytes()
            .all(|c| c.is_ascii_digit())
    {
        return None;
    }
    let e: i32 = e.parse().ok()?;
    // m < 2^53 is an f64, and so is 2^shift: their product is exact unless it leaves the
    // normal range (refused below)
    let shift = e - 4 * frac.len() as i32;
    if !(-1000..=1000).contains(&shift) || m >= 1 << 53 {
        return None;
    }
    let v = m as f64 * f64::from_bits(((shift + 1023) as u64) << 52);
    let v = if negative { -v } else { v };
    v.is_normal().then_some(v)
}

/// Digits with at most one `.` (at least one digit), then optionally `e` or `E`, a sign and
/// digits.
fn plain_decimal(b: &[u8]) -> bool {
    let (mantissa, exponent) = match b.iter().position(|&c| c == b'e' || c == b'E') {
        Some(i) => (&b[..i], Some(&b[i + 1..])),
        None => (b, None),
    };
    let digits = mantissa.iter().filter(|c| c.is_ascii_digit()).count();
    let dots = mantissa.iter().filter(|&&c| c == b'.').count();
    let mantissa_ok = digits > 0 && dots <= 1 && digits + dots == mantissa.len();
    let exponent_ok = exponent.is_none_or(|e| {
        let e = e.strip_prefix(b"-").or(e.strip_prefix(b"+")).unwrap_or(e);
        !e.is_empty() && e.len() <= 4 && e.iter().all(u8::is_ascii_digit)
    });
    mantissa_ok && exponent_ok
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The fast reader gives what the library's reader gives, on the lines targets write
    /// (`%a`, `repr`, `%.17g`) and on lines it must leave to the library.
    #[test]
    fn fast_answer_lines_read_as_the_library_reads_them() {
        let mut lines: Vec<String> = [
            "0x1.8p+0",
            "0x1p-1,0x1.fffffffffffffp+1023",
            "-0x1.5555555555555p-2, 0X1.8P+0",
            " 0x1.0000000000001p+0 ",
            "+0x1.8p+0",
            "1.5,-2.25",
            "0.1,1e-5",
            "5.,.5",
            "1e308,1E-300",
            "3.4028235e38,1e39",
            "0x1.ffffffp-127,0x1.fffffffp+0",
            "0x0p+0,1",
            "-0.0,1",
            "0x1p-1074,1",
            "1e400,1",
            "nan,1",
            "inf,1",
            "1/3,1",
            "\"1.5\",1",
            "[1, 2]",
            "1,2,3",
            "1",
            "",
            "0x1.8p,1",
            "0x.8p+1,1",
            "0x10p+0,1",
            "1e,1",
            "1.2.3,1",
            "f64:0.1,1",
            "0x1.00000000000001p+0,1",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        // f64 and f32 values as hex and decimal, from a fixed generator
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..2000 {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let v = f64::from_bits(x >> 2) * if x & 1 == 0 { 1.0 } else { -1.0 };
            let w = f64::from(v as f32);
            lines.push(format!(
                "{},{}",
                tribez::hunt::hex(Precision::F64, v),
                tribez::hunt::hex(Precision::F32, w)
            ));
            lines.push(format!("{v:?},{w:e}"));
        }
        for precision in [Precision::F64, Precision::F32] {
            for line in &lines {
                let want = tribez::batch::parse_claimed_line(line, 2, precision);
                let mut got = vec![7.0];
                if fast_claimed_line(line, precision, &mut got, 2) {
                    let want = want.unwrap_or_else(|e| panic!("{line}: fast read, library: {e}"));
                    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&got[1..]), bits(&want), "{line} ({precision:?})");
                } else {
                    assert_eq!(got, [7.0], "{line}");
                }
            }
        }
        // the common lines do take the fast path
        let mut got = Vec::new();
        assert!(fast_claimed_line(
            "0x1.8p+0,-0x1.5555555555555p-2",
            Precision::F64,
            &mut got,
            2
        ));
        assert!(fast_claimed_line("0.1", Precision::F32, &mut got, 1));
        assert_eq!(got, [1.5, -1.0 / 3.0, f64::from(0.1f32)]);
    }
}
