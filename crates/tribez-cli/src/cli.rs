//! The argument pieces every command shares: output options, the formats each command offers,
//! parsers for numbers given on the command line (negative values reach them and get a clear
//! error, never clap's "unexpected argument"), and the examples each `--help` shows.
//!
//! This module depends on nothing in [`crate::commands`]; each command's own arguments live
//! beside its code there and use what is defined here, and the list of commands
//! ([`crate::commands::Command`]) is assembled in `commands`.

use std::path::PathBuf;

use crate::report::Format;

// Output options of a command whose result is text or JSON (a plain comment: see `Command`).
#[derive(Debug, Clone, clap::Args)]
pub struct OutputArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = TextOrJson::Text)]
    pub format: TextOrJson,
    /// Write the output to FILE (whole or not at all; a regular file, its permissions kept) instead of standard output.
    #[arg(long, short = 'o', value_name = "FILE")]
    pub output: Option<PathBuf>,
}

// Output options of a command whose result is also a formula or a matrix (LaTeX); a plain
// comment, see `Command`.
#[derive(Debug, Clone, clap::Args)]
pub struct LatexOutputArgs {
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Write the output to FILE (whole or not at all; a regular file, its permissions kept) instead of standard output.
    #[arg(long, short = 'o', value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// The formats of a command without a LaTeX form.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum TextOrJson {
    /// Text for people.
    Text,
    /// JSON for machines (exact numbers as strings in lowest terms).
    Json,
}

impl From<TextOrJson> for Format {
    fn from(f: TextOrJson) -> Format {
        match f {
            TextOrJson::Text => Format::Text,
            TextOrJson::Json => Format::Json,
        }
    }
}

/// The value of `--algorithm`: a float evaluation algorithm, or every one the command runs
/// (`all`, where the command offers it). Parsed by [`algorithm`], the one value parser of the
/// flag.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AlgorithmChoice {
    /// de Casteljau (bound γ_{(m+1)n} Σ|c_i|B_i(|λ|)).
    Casteljau,
    /// The direct Bernstein form (bound γ_{N+n+m+2} Σ|c_i|B_i(|λ|)).
    Bernstein,
    /// Every algorithm the patch's kind offers.
    All,
}

impl AlgorithmChoice {
    /// The values of a command that judges one algorithm (`check`: the bound of `--tolerance
    /// bound`).
    pub const ONE: &'static [AlgorithmChoice] =
        &[AlgorithmChoice::Casteljau, AlgorithmChoice::Bernstein];
    /// The values of a command that can run every algorithm (`certify`).
    pub const ANY: &'static [AlgorithmChoice] = &[
        AlgorithmChoice::Casteljau,
        AlgorithmChoice::Bernstein,
        AlgorithmChoice::All,
    ];

    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            AlgorithmChoice::Casteljau => "casteljau",
            AlgorithmChoice::Bernstein => "bernstein",
            AlgorithmChoice::All => "all",
        }
    }

    /// What `--help` says of the value.
    fn help(self) -> &'static str {
        match self {
            AlgorithmChoice::Casteljau => "de Casteljau (bound γ_{(m+1)n} Σ|c_i|B_i(|λ|))",
            AlgorithmChoice::Bernstein => {
                "The direct Bernstein form (bound γ_{N+n+m+2} Σ|c_i|B_i(|λ|))"
            }
            AlgorithmChoice::All => "Every algorithm the patch's kind offers",
        }
    }

    /// The corresponding algorithm; `None` for `all`.
    pub fn algorithm(self) -> Option<tribez::Algorithm> {
        match self {
            AlgorithmChoice::Casteljau => Some(tribez::Algorithm::Casteljau),
            AlgorithmChoice::Bernstein => Some(tribez::Algorithm::Bernstein),
            AlgorithmChoice::All => None,
        }
    }
}

impl std::fmt::Display for AlgorithmChoice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The value parser of `--algorithm`, offering the values `offered` ([`AlgorithmChoice::ONE`]
/// or [`AlgorithmChoice::ANY`]). Any other value is one line: ``--algorithm: unknown algorithm
/// `X` (known: …)``.
pub fn algorithm(offered: &'static [AlgorithmChoice]) -> AlgorithmParser {
    AlgorithmParser(offered)
}

/// See [`algorithm`].
#[derive(Clone, Debug)]
pub struct AlgorithmParser(&'static [AlgorithmChoice]);

impl clap::builder::TypedValueParser for AlgorithmParser {
    type Value = AlgorithmChoice;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        _arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<AlgorithmChoice, clap::Error> {
        let text = value.to_string_lossy();
        self.0
            .iter()
            .copied()
            .find(|c| c.name() == text)
            .ok_or_else(|| {
                let known: Vec<&str> = self.0.iter().map(|c| c.name()).collect();
                clap::Error::raw(
                    clap::error::ErrorKind::InvalidValue,
                    format!(
                        "--algorithm: unknown algorithm `{text}` (known: {})\n",
                        known.join(", ")
                    ),
                )
                .with_cmd(cmd)
            })
    }

    fn possible_values(
        &self,
    ) -> Option<Box<dyn Iterator<Item = clap::builder::PossibleValue> + '_>> {
        Some(Box::new(self.0.iter().map(|c| {
            clap::builder::PossibleValue::new(c.name()).help(c.help())
        })))
    }
}

/// The largest `--random N` of `tribez certify` (each point is evaluated exactly).
pub const MAX_RANDOM_POINTS: usize = 1_000_000;

/// A clap value parser for a whole number from `lo` to `hi`: a negative number, a fraction or a
/// number beyond the limit gets one line naming the range.
pub fn whole_number<T>(lo: u64, hi: u64) -> impl Fn(&str) -> Result<T, String> + Clone + Send + Sync
where
    T: TryFrom<u64> + Clone + Send + Sync + 'static,
{
    move |text: &str| {
        let range = || {
            if hi == u64::MAX {
                format!("expected a whole number, at least {lo}")
            } else {
                format!("expected a whole number from {lo} to {hi}")
            }
        };
        let t = text.trim();
        let digits = t.strip_prefix('+').unwrap_or(t);
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(range());
        }
        // beyond u64: too large; leading zeros are fine
        match digits.parse::<u64>() {
            Ok(v) if (lo..=hi).contains(&v) => T::try_from(v).map_err(|_| range()),
            _ => Err(range()),
        }
    }
}

/// A clap value parser for `--random N`: 1 to [`MAX_RANDOM_POINTS`].
pub fn random_count(text: &str) -> Result<usize, String> {
    if whole_number::<usize>(0, 0)(text).is_ok() {
        return Err(format!(
            "needs at least one point (a whole number from 1 to {MAX_RANDOM_POINTS})"
        ));
    }
    whole_number(1, MAX_RANDOM_POINTS as u64)(text)
}

/// A clap value parser for a seed: any whole number from 0 to 2^64 - 1.
pub fn seed(text: &str) -> Result<u64, String> {
    whole_number(0, u64::MAX)(text)
}

/// The examples each command's `--help` ends with. Every line that starts with `tribez ` is run
/// by the test suite from a directory holding the repository's `fixtures/`
/// (`tests/help_examples.rs`), so they stay true.
pub mod examples {
    /// `tribez reproduce`.
    pub const REPRODUCE: &str = "\
Examples:
  tribez reproduce
  tribez reproduce --format json -o reproduce.json";
    /// `tribez hunt` (`sed -u` answers a constant for every row, unbuffered).
    pub const HUNT: &str = "\
Examples:
  tribez hunt fixtures/finn_day30.toml --budget 200 --seed 1 -- sed -u s/.*/0,0,0/
  tribez hunt fixtures/finn_day30.toml --precision f32 --tolerance ulps=4 --budget 300 --claims-out worst.claims.toml -- sed -u s/.*/1,1,1/";
    /// `tribez eval`.
    pub const EVAL: &str = "\
Examples:
  tribez eval fixtures/finn_day30.toml --at 1/2,1/3,1/6
  tribez eval fixtures/finn_day30.toml --at -1/2,1,1/2 --float f64
  tribez eval fixtures/finn_day30.toml --cartesian --at -1,2";
    /// `tribez symbolic`.
    pub const SYMBOLIC: &str = "\
Examples:
  tribez symbolic fixtures/finn_day30.toml
  tribez symbolic fixtures/finn_day30.toml --cartesian --format latex";
    /// `tribez graph`.
    pub const GRAPH: &str = "\
Examples:
  tribez graph fixtures/beyond/functional_linear.toml -o graph.toml";
    /// `tribez check`.
    pub const CHECK: &str = "\
Examples:
  tribez check fixtures/finn_day30.claims.toml
  tribez check --patch fixtures/peers/peer_cubic.toml --results fixtures/peers/bezier_results.csv --precision f64 --tolerance ulps=4 --plot map.svg --html report.html
  tribez check --patch fixtures/inverse/peer/triangle.toml --locate-results fixtures/inverse/peer/locate.rows.csv --precision f64 --tolerance ulps=16";
    /// `tribez certify`.
    pub const CERTIFY: &str = "\
Examples:
  tribez certify fixtures/certify/finn_quadratic.toml --random 1000 --seed 7
  tribez certify fixtures/finn_day30.toml --random 200 --precision f32 --junit certify.xml
  tribez certify fixtures/certify/finn_quadratic.toml --random 2000 --plot certify.svg --html certify.html";
    /// `tribez blossom`.
    pub const BLOSSOM: &str = "\
Examples:
  tribez blossom fixtures/finn_day30.toml --arg 1,0,0 --arg 0,1,0
  tribez blossom fixtures/finn_day30.toml --arg 1/2,1/3,1/6 --arg -1,1,1";
    /// `tribez subpatch`.
    pub const SUBPATCH: &str = "\
Examples:
  tribez subpatch fixtures/finn_day30.toml --vertex 1,0,0 --vertex 0,1,0 --vertex 1/3,1/3,1/3
  tribez subpatch fixtures/finn_day30.toml --vertex -1,1,1 --vertex 1,0,0 --vertex 0,1,0 -o bigger.toml";
    /// `tribez subdivide`.
    pub const SUBDIVIDE: &str = "\
Examples:
  tribez subdivide fixtures/finn_day30.toml --at 1/3,1/3,1/3
  tribez subdivide fixtures/finn_day30.toml --midpoints --format json -o pieces.json
  tribez subdivide fixtures/finn_day30.toml --at 1/2,1/2,0";
    /// `tribez halve`.
    pub const HALVE: &str = "\
Examples:
  tribez halve fixtures/finn_day30.toml --edge 1,2
  tribez halve fixtures/finn_day30.toml --edge 2,3 --add-and-halve";
    /// `tribez elevate`.
    pub const ELEVATE: &str = "\
Examples:
  tribez elevate fixtures/finn_day30.toml
  tribez elevate fixtures/finn_day30.toml --by 2 -o cubic.toml";
    /// `tribez matrix`.
    pub const MATRIX: &str = "\
Examples:
  tribez matrix halve --degree 3
  tribez matrix halve --degree 2 --edge 2,3 --piece 2 --format latex
  tribez matrix subpatch --degree 2 --vertex 1,0,0 --vertex 0,1,0 --vertex -1,1,1";
    /// `tribez derivative`.
    pub const DERIVATIVE: &str = "\
Examples:
  tribez derivative fixtures/finn_day30.toml --at 1/3,1/3,1/3 --dir 1,-1,0
  tribez derivative fixtures/finn_day30.toml --at 1/3,1/3,1/3 --dir 1,-1,0 --dir 0,1,-1";
    /// `tribez tangent`.
    pub const TANGENT: &str = "\
Examples:
  tribez tangent fixtures/finn_day30.toml --at 1/2,1/3,1/6";
    /// `tribez plot`.
    pub const PLOT: &str = "\
Examples:
  tribez plot fixtures/finn_day30.toml -o finn.svg --labels
  tribez plot fixtures/peers/peer_cubic.toml -o cubic.png --view 30,20 --samples 64";
    /// `tribez join`.
    pub const JOIN: &str = "\
Examples:
  tribez join fixtures/joins/quad_a.toml fixtures/joins/quad_b_c1.toml
  tribez join fixtures/joins/quad_a.toml --make-c1 --domain 6,-3 -o neighbour.toml";
    /// `tribez intersect`.
    pub const INTERSECT: &str = "\
Examples:
  tribez intersect fixtures/inverse/parabola.toml fixtures/inverse/line_half.toml
  tribez intersect fixtures/inverse/cubic_a.toml fixtures/inverse/cubic_b.toml --format json";
    /// `tribez locate`.
    pub const LOCATE: &str = "\
Examples:
  tribez locate fixtures/inverse/quad_triangle.toml --point 1/2,1/2
  tribez locate fixtures/inverse/quad_triangle.toml --point 1/2,1/2 --anywhere --format json";
    /// `tribez ray`.
    pub const RAY: &str = "\
Examples:
  tribez ray fixtures/inverse/dome.toml --origin 1/4,1/4,2 --direction 0,0,-1
  tribez ray fixtures/inverse/dome.toml --origin -1,-1,0 --direction 2,2,1 --format json
  tribez ray fixtures/inverse/hill.toml --height 1/3,1/3";
    /// `tribez mesh`.
    pub const MESH: &str = "\
Examples:
  tribez mesh check fixtures/mesh/hexagon_cubic.toml
  tribez mesh patch fixtures/mesh/hexagon_cubic.toml --triangle 2 -o triangle2.toml";
    /// `tribez mesh check`.
    pub const MESH_CHECK: &str = "\
Examples:
  tribez mesh check fixtures/mesh/hexagon_cubic.toml
  tribez mesh check fixtures/mesh/hexagon_cubic.toml --format json";
    /// `tribez mesh patch`.
    pub const MESH_PATCH: &str = "\
Examples:
  tribez mesh patch fixtures/mesh/hexagon_cubic.toml --triangle 2 -o triangle2.toml";
    /// `tribez lookup`.
    pub const LOOKUP: &str = "\
Examples:
  tribez lookup fixtures/mesh/hexagon_cubic.toml --at 1/3,1/5
  tribez lookup fixtures/mesh/hexagon_cubic.toml --at 1/2,0 --float f32
  tribez lookup fixtures/mesh/hexagon_cubic.toml --points fixtures/mesh/points.csv --format json";
    /// `tribez fit`.
    pub const FIT: &str = "\
Examples:
  tribez fit fixtures/fit/numpy/data.csv --mesh fixtures/fit/numpy/mesh.toml -o fitted.toml
  tribez fit fixtures/fit/small/data.csv --mesh fixtures/fit/small/mesh.toml --degree 3 --smoothness c1 --format json";
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_numbers_name_their_range() {
        let p = whole_number::<usize>(1, 10);
        assert_eq!(p("7"), Ok(7));
        assert_eq!(p("+7"), Ok(7));
        assert_eq!(p("010"), Ok(10));
        for bad in [
            "-5",
            "0",
            "11",
            "1.5",
            "",
            "x",
            "18446744073709551616",
            "99999999999999999999999",
        ] {
            assert_eq!(
                p(bad),
                Err("expected a whole number from 1 to 10".into()),
                "{bad}"
            );
        }
        assert_eq!(seed("18446744073709551615"), Ok(u64::MAX));
        assert_eq!(
            whole_number::<usize>(1, u64::MAX)("0"),
            Err("expected a whole number, at least 1".into())
        );
        assert!(random_count("1000001").is_err());
        assert!(
            random_count("0")
                .unwrap_err()
                .contains("at least one point")
        );
        assert_eq!(random_count("1000000"), Ok(1_000_000));
    }
}
