//! The `tribez` command: parse arguments, run one command, map the outcome to an exit status
//! (0 every claim holds, 1 some claim fails, 2 bad input or usage).

use clap::Parser;

fn main() {
    let cli = tribez::cli::Cli::parse();
    std::process::exit(tribez::commands::main(cli));
}
