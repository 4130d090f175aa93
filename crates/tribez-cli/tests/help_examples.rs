//! Every command's `--help` ends with one to three examples (issue 11), and every example works:
//! each is run from a fresh directory holding a copy of the repository's `fixtures/` (examples
//! may write files there) and must end with exit status 0 or 1, never a usage or input error.
//! `reproduce` runs from a directory without fixtures: its fixtures are built in.

use std::path::{Path, PathBuf};

use assert_cmd::Command;

fn tribez() -> Command {
    Command::cargo_bin("tribez").expect("binary built")
}

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures")
}

fn stdout_of(args: &[&str]) -> String {
    let out = tribez().args(args).assert().code(0).get_output().clone();
    String::from_utf8(out.stdout).unwrap()
}

/// The subcommands listed by `tribez --help` (without `help`).
fn commands() -> Vec<String> {
    let help = stdout_of(&["--help"]);
    help.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(str::to_string)
        .collect()
}

/// The example command lines at the end of `tribez CMD --help`.
fn examples(cmd: &str) -> Vec<String> {
    let help = stdout_of(&[cmd, "--help"]);
    help.lines()
        .skip_while(|l| l.trim() != "Examples:")
        .skip(1)
        .map(str::trim)
        .filter(|l| l.starts_with("tribez "))
        .map(str::to_string)
        .collect()
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        let target = to.join(e.file_name());
        if e.file_type().unwrap().is_dir() {
            copy_dir(&e.path(), &target);
        } else {
            std::fs::copy(e.path(), target).unwrap();
        }
    }
}

#[test]
fn every_command_has_one_to_three_examples() {
    let cmds = commands();
    assert!(cmds.len() >= 15, "{cmds:?}");
    for cmd in &cmds {
        let ex = examples(cmd);
        assert!((1..=3).contains(&ex.len()), "{cmd}: {ex:?}");
        for e in &ex {
            assert!(
                e.starts_with(&format!("tribez {cmd} ")) || e == &format!("tribez {cmd}"),
                "{e}"
            );
        }
    }
}

#[test]
fn every_example_of_every_help_text_runs() {
    let work = tempfile::tempdir().unwrap();
    copy_dir(&fixtures(), &work.path().join("fixtures"));
    let bare = tempfile::tempdir().unwrap(); // no fixtures here
    let mut ran = 0;
    for cmd in commands() {
        for example in examples(&cmd) {
            // the examples use no quoting: words are separated by spaces
            let words: Vec<&str> = example.split_whitespace().skip(1).collect();
            let dir = if cmd == "reproduce" {
                bare.path()
            } else {
                work.path()
            };
            let out = tribez().args(&words).current_dir(dir).output().unwrap();
            let code = out.status.code();
            assert!(
                matches!(code, Some(0 | 1)),
                "`{example}` exited {code:?}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            assert!(
                !out.stdout.is_empty() || words.contains(&"-o"),
                "`{example}` printed nothing"
            );
            ran += 1;
        }
    }
    assert!(ran >= 15, "{ran} examples");
}

/// The description of each subcommand in `tribez --help` is the first line of its own
/// `--help` and `-h` (the subcommands' arguments are deferred; a doc comment on an arguments
/// struct would otherwise replace the description there).
#[test]
fn every_help_starts_with_its_listed_description() {
    let help = stdout_of(&["--help"]);
    let listed: Vec<(String, String)> = help
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| {
            let l = l.trim_start();
            let (name, about) = l.split_once(' ')?;
            (name != "help").then(|| (name.to_string(), about.trim().to_string()))
        })
        .collect();
    assert!(listed.len() >= 20, "{help}");
    for (name, about) in &listed {
        for flag in ["--help", "-h"] {
            let own = stdout_of(&[name, flag]);
            let first = own.lines().next().unwrap_or("");
            // the long help keeps the final period the listing drops
            assert_eq!(
                first.trim_end_matches('.'),
                about.trim_end_matches('.'),
                "tribez {name} {flag}"
            );
        }
    }
}
