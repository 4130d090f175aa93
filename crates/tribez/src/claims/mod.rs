//! Claims: one format for the worked examples of the sources (`fixtures/`) and for the outputs of
//! other code. A claim names an operation, its inputs, the claimed value and a tolerance;
//! tribez computes the exact value and judges the claim.
//!
//! ```toml
//! source = "D. L. Finn, MA 323 course notes, Day 30"
//! patch = "finn_day30.toml"            # a patch file beside this one, or an inline [patch] table
//!
//! [[claim]]
//! id = "worked-example-a"
//! op = "eval"
//! at = ["1/2", "1/3", "1/6"]
//! expect = ["4/9", "5/9", "29/36"]
//! source = "§30.1, example (a)"
//!
//! [[claim]]
//! id = "worked-example-b-x"
//! op = "symbolic"
//! expect = ["2uv + v^2 + vw", "2uw + 2vw + 2v^2 + 2w^2", "4uv + 2vw + w^2"]
//! erratum = "the printed x-component is wrong: 2uv + 2vw (docs/theory.md §15)"
//! ```
//!
//! Every claim may carry `tolerance` (`exact` by default; `ulps=N`, `abs=E`, `rel=E`,
//! `correctly_rounded`, `faithful`, `cond=K`, `bound`: [`crate::certify::measures::Tolerance`])
//! and `precision = "f64"` or `"f32"`: every number of the claim then denotes the float nearest
//! its text, the verdict uses the exact value at the inputs as the code saw them, and the error
//! at the intended inputs is reported beside it ([`FloatLeaf`]).
//!
//! A claim marked `erratum` records a value that the source prints and that is known to be
//! wrong: its disagreement is listed as an erratum and does not fail the run; if it ever
//! agrees, the stale erratum fails the run.

pub mod ops;
mod report;
pub mod value;

pub use report::{
    ClaimsOptions, ClaimsReport, FileResults, FoundFiles, check_claims, check_files, check_paths,
    claim_files_of,
};

use std::path::{Path, PathBuf};

use crate::certify::measures::{Leaf, Measures, Tolerance};
use crate::float::Precision;
use crate::io::patch_file::any_patch_from_document;
use crate::io::tree::{Document, Node, Value as NodeValue};
use crate::io::{ClaimProblem, InputError, NamedAt, Problem};
use crate::patch::BezierPatch;
use value::{Mismatch, Value, compare};

/// Keys a claim file may have at its top level.
pub const FILE_KEYS: &[&str] = &["source", "description", "patch", "patches", "claim"];
/// Keys every claim may have, besides its operation's own inputs.
pub const CLAIM_KEYS: &[&str] = &[
    "id",
    "op",
    "source",
    "expect",
    "erratum",
    "tolerance",
    "precision",
    "note",
];

/// A parsed claim file.
pub struct ClaimFile {
    /// The file.
    pub path: PathBuf,
    /// Its document (claims are read lazily from it).
    pub doc: Document,
    /// Where the claims come from.
    pub source: Option<String>,
    /// Named patches: `""` for the file's `patch`, else the names under `[patches]` (any kind;
    /// [`ClaimFile::patch_for`] gives a claim's).
    pub patches: Vec<(String, crate::patch_type::Patch)>,
    /// The claims in file order.
    pub claims: Vec<Claim>,
}

/// One claim.
pub struct Claim {
    /// Identifier (unique in its file).
    pub id: String,
    /// Operation name.
    pub op: String,
    /// The claim's table.
    pub node: Node,
    /// Where in the source the claimed value is printed.
    pub source: Option<String>,
    /// Set when the claimed value is a known misprint; the text says what is wrong.
    pub erratum: Option<String>,
}

/// How a claim came out.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// The claimed value is right.
    Holds,
    /// The claimed value is wrong.
    Fails(Vec<Mismatch>),
    /// Wrong, and recorded as a known erratum of the source.
    KnownErratum(Vec<Mismatch>),
    /// Recorded as an erratum, yet it agrees with the exact value: the record is stale.
    StaleErratum,
}

impl Verdict {
    /// The verdict of a claim with these `mismatches`, recorded as an erratum or not.
    pub(crate) fn of(mismatches: Vec<Mismatch>, erratum: bool) -> Verdict {
        match (mismatches.is_empty(), erratum) {
            (true, false) => Verdict::Holds,
            (true, true) => Verdict::StaleErratum,
            (false, false) => Verdict::Fails(mismatches),
            (false, true) => Verdict::KnownErratum(mismatches),
        }
    }

    /// Does this verdict fail a run?
    pub fn fails_run(&self) -> bool {
        matches!(self, Verdict::Fails(_) | Verdict::StaleErratum)
    }
}

/// A judged claim.
#[derive(Clone, Debug)]
pub struct Judged {
    /// The claim file.
    pub file: String,
    /// The claim id.
    pub id: String,
    /// The operation.
    pub op: String,
    /// The source reference.
    pub source: Option<String>,
    /// The erratum note, if any.
    pub erratum: Option<String>,
    /// The exact value.
    pub exact: Value,
    /// The claimed value.
    pub claimed: Value,
    /// The verdict.
    pub verdict: Verdict,
    /// The tolerance the claim was judged with.
    pub tolerance: Tolerance,
    /// The claim's precision (float claims).
    pub precision: Option<Precision>,
    /// Float evaluation claims: per coordinate, both errors (at the inputs as the code saw them,
    /// and at the intended inputs).
    pub floats: Vec<FloatLeaf>,
}

/// One coordinate of a float evaluation claim, judged both ways.
#[derive(Clone, Debug)]
pub struct FloatLeaf {
    /// The claimed float, shortest decimal.
    pub decimal: String,
    /// The claimed float, hex.
    pub hex: String,
    /// Its exact value.
    pub claimed: num_rational::BigRational,
    /// The exact value at the inputs (and control points) as the code saw them: rounded to the precision.
    pub exact_seen: num_rational::BigRational,
    /// The error against it (the algorithm's own error; the verdict uses this one).
    pub seen: Measures,
    /// The exact value at the intended inputs (the exact text, the exact patch).
    pub exact_intended: num_rational::BigRational,
    /// The error against it (including what input rounding adds).
    pub intended: Measures,
    /// `Σ|c_i| B_i(|λ|)` at the inputs as seen.
    pub condition: num_rational::BigRational,
    /// The a-priori bound of the claim's algorithm (if `Kε < 1`).
    pub bound: Option<num_rational::BigRational>,
}

fn resolve_patch(
    doc: &Document,
    node: &Node,
    key: &str,
    dir: &Path,
) -> Result<crate::patch_type::Patch, InputError> {
    match &node.value {
        NodeValue::String(rel) => {
            let path = dir.join(rel);
            crate::io::patch_file::read_any_patch(&path)
                .map(Into::into)
                .map_err(|mut e| {
                    if e.line.is_none() {
                        e.named_at = Some(Box::new(NamedAt {
                            file: doc.file.clone(),
                            line: node.line,
                            key: key.to_string(),
                        }));
                    }
                    e
                })
        }
        NodeValue::Table(_) => any_patch_from_document(doc, node, key).map(Into::into),
        other => Err(doc.error(
            node,
            key,
            ClaimProblem::NotAPatch {
                found: other.kind(),
            },
        )),
    }
}

impl ClaimFile {
    /// Read a claim file (TOML or JSON).
    pub fn read(path: &Path) -> Result<Self, InputError> {
        Self::from_document(Document::read(path)?, path)
    }

    /// A claim file from its parsed document; `path` names it, and patch files named in it are
    /// read beside it.
    pub fn from_document(doc: Document, path: &Path) -> Result<Self, InputError> {
        let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        let root = doc.root_table()?;
        doc.check_keys(&doc.root, root, FILE_KEYS, "")?;
        let source = Document::get(root, "source")
            .map(|n| doc.string(n, "source").map(str::to_string))
            .transpose()?;
        let mut patches = Vec::new();
        if let Some(p) = Document::get(root, "patch") {
            patches.push((String::new(), resolve_patch(&doc, p, "patch", &dir)?));
        }
        if let Some(ps) = Document::get(root, "patches") {
            for (name, p) in doc.table(ps, "patches")? {
                patches.push((
                    name.clone(),
                    resolve_patch(&doc, p, &format!("patches.{name}"), &dir)?,
                ));
            }
        }
        let mut claims = Vec::new();
        let list = Document::get(root, "claim")
            .ok_or_else(|| doc.error(&doc.root, "claim", ClaimProblem::NoClaims))?;
        for (i, c) in doc.array(list, "claim")?.iter().enumerate() {
            let key = format!("claim[{i}]");
            let t = doc.table(c, &key)?;
            let get_str = |name: &str| -> Result<Option<String>, InputError> {
                Document::get(t, name)
                    .map(|n| doc.string(n, &format!("{key}.{name}")).map(str::to_string))
                    .transpose()
            };
            let op = get_str("op")?
                .ok_or_else(|| doc.error(c, &key, Problem::MissingKey { key: "op" }))?;
            let id = get_str("id")?.unwrap_or_else(|| format!("{op}-{}", i + 1));
            if claims.iter().any(|x: &Claim| x.id == id) {
                return Err(doc.error(
                    c,
                    &format!("{key}.id"),
                    ClaimProblem::DuplicateId { id: id.clone() },
                ));
            }
            claims.push(Claim {
                id,
                op,
                node: c.clone(),
                source: get_str("source")?,
                erratum: get_str("erratum")?,
            });
        }
        Ok(ClaimFile {
            path: path.to_path_buf(),
            doc,
            source,
            patches,
            claims,
        })
    }

    /// The polynomial patch a claim refers to; a rational patch or an S-patch is an error for
    /// the claim's operation.
    pub(crate) fn polynomial_for(&self, claim: &Claim) -> Result<&BezierPatch, InputError> {
        let any = self.patch_for(claim)?.as_any();
        any.polynomial().ok_or_else(|| {
            self.doc.error(
                &claim.node,
                &claim.id,
                ClaimProblem::KindNotTaken {
                    op: claim.op.clone(),
                    kind: any.kind_name(),
                },
            )
        })
    }

    /// The patch (of any kind) a claim refers to: `patch = "name"` in the claim (a name under
    /// `[patches]`), else the file's `patch`.
    pub fn patch_for(&self, claim: &Claim) -> Result<&crate::patch_type::Patch, InputError> {
        let t = self.doc.table(&claim.node, &claim.id)?;
        let name = match Document::get(t, "patch") {
            Some(n) => self
                .doc
                .string(n, &format!("{}.patch", claim.id))?
                .to_string(),
            None => String::new(),
        };
        self.patches
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, p)| p)
            .ok_or_else(|| {
                if name.is_empty() {
                    self.doc
                        .error(&claim.node, &claim.id, ClaimProblem::NeedsPatch)
                } else {
                    self.doc.error(
                        &claim.node,
                        &format!("{}.patch", claim.id),
                        ClaimProblem::NoSuchPatch { name },
                    )
                }
            })
    }

    /// Judge every claim.
    pub fn judge_all(&self) -> Result<Vec<Judged>, InputError> {
        self.claims.iter().map(|c| self.judge(c)).collect()
    }

    /// The claim's tolerance and precision (located errors for unknown ones).
    pub fn tolerance_of(
        &self,
        claim: &Claim,
    ) -> Result<(Tolerance, Option<Precision>), InputError> {
        let t = self.doc.table(&claim.node, &claim.id)?;
        let tolerance = match Document::get(t, "tolerance") {
            Some(n) => Tolerance::parse(self.doc.string(n, &format!("{}.tolerance", claim.id))?)
                .map_err(|e| self.doc.error(n, &format!("{}.tolerance", claim.id), e))?,
            None => Tolerance::Exact,
        };
        let precision = match Document::get(t, "precision") {
            Some(n) => Some(
                self.doc
                    .string(n, &format!("{}.precision", claim.id))?
                    .parse::<Precision>()
                    .map_err(|e| self.doc.error(n, &format!("{}.precision", claim.id), e))?,
            ),
            None => None,
        };
        let at = |name: &str| Document::get(t, name).unwrap_or(&claim.node);
        if tolerance.needs_precision() && precision.is_none() {
            return Err(self.doc.error(
                at("tolerance"),
                &format!("{}.tolerance", claim.id),
                ClaimProblem::ToleranceNeedsPrecision { tolerance },
            ));
        }
        // `lookup` has a condition number too (in the triangle found; `bound` it refuses itself)
        if tolerance.needs_condition() && claim.op != "eval" && claim.op != "lookup" {
            return Err(self.doc.error(
                at("tolerance"),
                &format!("{}.tolerance", claim.id),
                ClaimProblem::ToleranceEvalOnly { tolerance },
            ));
        }
        Ok((tolerance, precision))
    }

    /// Judge one claim.
    pub fn judge(&self, claim: &Claim) -> Result<Judged, InputError> {
        let inputs = ops::Inputs::new(self, claim)?;
        let op = ops::ClaimOp::parse(&inputs)?;
        if let ops::ClaimOp::Inverse(inverse) = &op {
            return ops::inverse::judge(self, claim, &inputs, inverse);
        }
        if let ops::ClaimOp::Lookup(lookup) = &op {
            return ops::lookup::judge(self, claim, &inputs, lookup);
        }
        let (tolerance, precision) = self.tolerance_of(claim)?;
        // with `precision`, every operation but `eval` computes from the inputs as the code saw
        // them; `eval` keeps both views (its float view below)
        let exact = match precision {
            Some(p) if !op.is_eval() => op.seen(&inputs, p)?.compute(&inputs)?,
            _ => op.compute(&inputs)?,
        };
        let t = self.doc.table(&claim.node, &claim.id)?;
        let expect = Document::get(t, "expect").ok_or_else(|| {
            self.doc
                .error(&claim.node, &claim.id, ClaimProblem::MissingExpect)
        })?;
        let key = format!("{}.expect", claim.id);
        let mut claimed = ops::read_claimed(&self.doc, expect, &exact, &key)?;
        if let Some(p) = precision {
            claimed = value::round_numbers(&claimed, p).ok_or_else(|| {
                self.doc.error(
                    expect,
                    &key,
                    Problem::Overflows {
                        what: "a claimed number",
                        precision: p,
                    },
                )
            })?;
        }
        let float_eval = match (precision, &op) {
            (Some(p), ops::ClaimOp::Point(eval @ ops::PointOp::Eval { .. })) => {
                Some(ops::float_view(&inputs, eval, p)?)
            }
            _ => None,
        };
        let tolerance = match &float_eval {
            Some(f) => tolerance.for_patch(f.simplex_degree.0, f.simplex_degree.1),
            None => tolerance,
        };
        let judged_against = float_eval
            .as_ref()
            .map_or_else(|| exact.clone(), |f| Value::numbers(&f.exact_seen));
        let leaf = |k: usize| Leaf {
            precision,
            condition: float_eval
                .as_ref()
                .filter(|f| f.cond_tolerance)
                .and_then(|f| f.condition.get(k).cloned()),
            bound: float_eval
                .as_ref()
                .and_then(|f| f.bound.get(k).cloned().flatten()),
        };
        let mut mismatches = Vec::new();
        compare(
            &claimed,
            &judged_against,
            &tolerance,
            &leaf,
            &mut 0,
            "",
            &mut mismatches,
        )
        .map_err(|e| {
            self.doc
                .error(&claim.node, &format!("{}.tolerance", claim.id), e)
        })?;
        let mut floats = Vec::new();
        if let (Some(f), Value::List(items), Some(p)) = (&float_eval, &claimed, precision) {
            for (k, item) in items.iter().enumerate() {
                let (Value::Number(y), Some(es), Some(ei)) =
                    (item, f.exact_seen.get(k), f.exact_intended.get(k))
                else {
                    continue;
                };
                let (decimal, hex) = match p {
                    Precision::F64 => {
                        let x = crate::number::round_f64(y);
                        (crate::number::display_f64(x), crate::number::hex_f64(x))
                    }
                    Precision::F32 => {
                        let x = crate::number::round_f32(y);
                        (crate::number::display_f32(x), crate::number::hex_f32(x))
                    }
                };
                floats.push(FloatLeaf {
                    decimal,
                    hex,
                    claimed: y.clone(),
                    exact_seen: es.clone(),
                    seen: Measures::new(y, es, Some(p)),
                    exact_intended: ei.clone(),
                    intended: Measures::new(y, ei, Some(p)),
                    condition: f.condition[k].clone(),
                    bound: f.bound[k].clone(),
                });
            }
        }
        let verdict = Verdict::of(mismatches, claim.erratum.is_some());
        Ok(Judged {
            file: self.path.display().to_string(),
            id: claim.id.clone(),
            op: claim.op.clone(),
            source: claim.source.clone().or_else(|| self.source.clone()),
            erratum: claim.erratum.clone(),
            exact: judged_against,
            claimed,
            verdict,
            tolerance,
            precision,
            floats,
        })
    }
}

/// The claim files under `dir` (recursively): `*.claims.toml` and `*.claims.json`, sorted;
/// symbolic links to directories are not followed, each file counts once, and anything that is
/// not a regular file is skipped (`crate::io::walk::claim_files` also returns notes on what
/// was skipped).
pub fn find_claim_files(dir: &Path) -> Result<Vec<PathBuf>, InputError> {
    Ok(crate::io::walk::claim_files(dir)?.files)
}
