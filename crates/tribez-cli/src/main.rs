//! The `tribez` command: parse arguments, run one command, map the outcome to an exit status
//! (0 every claim holds, 1 some claim fails, 2 bad input or usage).

use clap::Parser;

mod cli;
mod commands;
mod report;

fn main() {
    let cli = cli::Cli::parse();
    std::process::exit(commands::main(cli));
}
