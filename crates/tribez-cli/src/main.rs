//! The `tribez` command: parse arguments, run one command, map the outcome to an exit status
//! (0 every claim holds, 1 some claim fails, 2 bad input or usage).

use std::io::Write;

use clap::Parser;

mod cli;
mod commands;
mod error;
mod output;
mod picture;
mod report;

fn main() {
    let cli = match commands::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => std::process::exit(usage(&e)),
    };
    std::process::exit(commands::main(cli));
}

/// Print clap's help or version, or its usage error as one line; a help text that cannot be written (`> /dev/full`)
/// is an error too. Returns the exit status (0 for help and version, 2 for a usage error).
fn usage(e: &clap::Error) -> i32 {
    let status = e.exit_code();
    let text = e.render().to_string();
    if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
        let _ = std::io::stderr().write_all(text.as_bytes());
        return status;
    }
    if e.use_stderr() {
        let _ = writeln!(std::io::stderr(), "tribez: {}", one_line(&text));
        return status;
    }
    match output::write_stdout(text.as_bytes()) {
        Ok(()) => status,
        Err(err) => {
            let _ = writeln!(std::io::stderr(), "tribez: {err}");
            2
        }
    }
}

/// clap's error as one line: its first paragraph (the error and what it concerns, without the
/// usage and the pointer to `--help`), whitespace collapsed, without the `error: ` prefix.
fn one_line(text: &str) -> String {
    let first: Vec<&str> = text
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .flat_map(str::split_whitespace)
        .collect();
    let line = first.join(" ");
    line.strip_prefix("error: ").unwrap_or(&line).to_string()
}
