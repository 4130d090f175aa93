//! Judging one row: the float filter first, exact arithmetic when it cannot decide.

use num_rational::BigRational;

use super::parse::Num;
use super::report::FailedCoord;
use super::{BatchError, BatchOptions};
use crate::certify::bound::{a_priori, condition};
use crate::certify::filter::cartesian::{CartesianMap, CartesianPoint};
use crate::certify::filter::{Decision, Enclosure, Filter, RowJudgement, Scratch, Thresholds};
use crate::certify::measures::{Leaf, Measures, Tolerance, as_float};
use crate::exact::{Algorithm, ExactEvaluator};
use crate::float::Precision;
use crate::patch::{BezierPatch, ControlNet};

/// How one row came out.
pub(super) struct RowOutcome {
    pub(super) line: usize,
    pub(super) pass: bool,
    pub(super) fell_back: bool,
    /// The largest error in ULPs over the coordinates (upper bound if filter-decided).
    pub(super) ulps: f64,
    /// A lower bound on it (equal to `ulps` when computed exactly).
    pub(super) ulps_lower: f64,
    /// The ULP figures were computed exactly by [`Prepared::filtered`] (the verdict was not).
    pub(super) settled_exactly: bool,
    pub(super) failure: Option<String>,
    /// The parsed row (kept for failures and the worst row, to report them exactly); empty for
    /// a row [`Prepared::filtered`] decided, until its caller fills them.
    pub(super) inputs: Vec<Num>,
    pub(super) claimed: Vec<Num>,
}

/// Everything prepared once per patch.
pub(super) struct Prepared {
    pub(super) patch: BezierPatch,
    pub(super) precision: Option<Precision>,
    pub(super) tolerance: Tolerance,
    pub(super) algorithm: Algorithm,
    pub(super) cartesian: bool,
    pub(super) row_detail: bool,
    pub(super) filter: Option<(Filter, Thresholds)>,
    /// Cartesian rows: the barycentric map in floats, with radii (docs/theory.md §14.5).
    pub(super) cartesian_map: Option<CartesianMap>,
    pub(super) seen: ExactEvaluator,
    pub(super) seen_net: ControlNet<BigRational>,
    pub(super) intended: ExactEvaluator,
}

impl Prepared {
    pub(super) fn new(options: &BatchOptions, patch: BezierPatch) -> Result<Self, BatchError> {
        let BatchOptions {
            tolerance,
            precision,
            algorithm,
            cartesian,
            row_detail,
        } = options.clone();
        if tolerance.needs_precision() && precision.is_none() {
            return Err(BatchError::ToleranceNeedsPrecision { tolerance });
        }
        let seen_net = match precision {
            Some(p) => {
                if patch.net.coords().iter().any(|q| as_float(q, p).is_none()) {
                    return Err(BatchError::ControlPointOverflows { precision: p });
                }
                patch.net.map(|q| as_float(q, p).unwrap_or_default())
            }
            None => patch.net.clone(),
        };
        let (m, n) = (patch.net.m(), patch.net.degree());
        let tolerance = tolerance.for_patch(m, n);
        let cartesian_map = if cartesian {
            CartesianMap::new(&patch.domain_or_reference())
        } else {
            None
        };
        let filter = precision
            .filter(|_| !cartesian || cartesian_map.is_some())
            .map(|p| {
                let fnet = seen_net.map(crate::number::round_f64);
                (
                    Filter::new(&fnet),
                    Thresholds::new(&tolerance, p, algorithm, m, n),
                )
            });
        Ok(Prepared {
            seen: ExactEvaluator::new(&seen_net),
            intended: ExactEvaluator::new(&patch.net),
            seen_net,
            patch,
            precision,
            tolerance,
            algorithm,
            cartesian,
            row_detail,
            filter,
            cartesian_map,
        })
    }

    pub(super) fn width(&self) -> usize {
        let m = self.patch.net.m();
        if self.cartesian { m } else { m + 1 }
    }

    /// Barycentric coordinates of an input row (exact), as seen or intended.
    pub(super) fn barycentric(&self, xs: Vec<BigRational>) -> Option<Vec<BigRational>> {
        if self.cartesian {
            self.patch.domain_or_reference().barycentric(&xs).ok()
        } else {
            Some(xs)
        }
    }

    /// The exact value of a number as the code saw it: the float it denotes with a precision,
    /// its text's exact value without (`None` for `nan`, `inf`, empty).
    fn seen_value(&self, x: &Num) -> Option<BigRational> {
        match x {
            Num::Value { float, text_exact } => match self.precision {
                Some(_) => crate::number::exact_f64(*float),
                None => text_exact.clone(),
            },
            Num::NotFinite(..) => None,
        }
    }

    /// The barycentric point of a row's inputs as the code saw them.
    fn seen_point(&self, inputs: &[Num]) -> Option<Vec<BigRational>> {
        inputs
            .iter()
            .map(|x| self.seen_value(x))
            .collect::<Option<Vec<_>>>()
            .and_then(|x| self.barycentric(x))
    }

    /// Judge one row exactly; `intended` are the row's inputs as intended (the exact values of
    /// their texts), for the error at the intended inputs.
    pub(super) fn exact_row(
        &self,
        inputs: &[Num],
        claimed: &[Num],
        intended: Option<&[BigRational]>,
        detail: bool,
    ) -> (bool, f64, Option<String>, Vec<FailedCoord>) {
        let Some(lambda) = self.seen_point(inputs) else {
            return (false, f64::INFINITY, Some("an input is not a finite number (or the Cartesian point has no barycentric coordinates)".into()), Vec::new());
        };
        let exact = self.seen.evaluate_fast(&lambda);
        let cond = if self.tolerance.needs_condition() {
            Some(condition(&self.seen_net, &lambda))
        } else {
            None
        };
        let (m, n) = (self.patch.net.m(), self.patch.net.degree());
        let intended: Option<Vec<BigRational>> = if detail {
            intended
                .and_then(|x| self.barycentric(x.to_vec()))
                .map(|l| self.intended.evaluate_fast(&l))
        } else {
            None
        };
        let mut pass = true;
        let mut worst = 0f64;
        let mut reason = None;
        let mut coords = Vec::new();
        for (c, y) in claimed.iter().enumerate() {
            let Num::Value { float, .. } = y else {
                pass = false;
                worst = f64::INFINITY;
                if let Num::NotFinite(what, _) = y {
                    reason.get_or_insert_with(|| {
                        format!("claimed coordinate [{c}] is not a finite number: {what}")
                    });
                }
                continue;
            };
            let yq = self.seen_value(y).unwrap_or_default();
            let leaf = Leaf {
                precision: self.precision,
                condition: cond.as_ref().map(|s| s[c].clone()),
                bound: cond.as_ref().and_then(|s| {
                    a_priori(
                        self.algorithm,
                        self.precision.unwrap_or(Precision::F64),
                        m,
                        n,
                        &s[c],
                        &lambda,
                    )
                }),
            };
            let ok = self
                .tolerance
                .accepts(&yq, &exact[c], &leaf)
                .unwrap_or(false);
            let meas = Measures::new(&yq, &exact[c], self.precision.or(Some(Precision::F64)));
            // rounded up, so that the histogram puts the row in its true bucket
            let u = meas
                .ulps
                .as_ref()
                .map_or(f64::INFINITY, crate::number::round_up_f64);
            worst = worst.max(u);
            if !ok {
                pass = false;
                reason.get_or_insert_with(|| {
                    format!(
                        "coordinate [{c}] breaks tolerance `{}`: {}",
                        self.tolerance,
                        meas.text()
                    )
                });
            }
            if detail {
                let (decimal, hex) = match self.precision {
                    Some(Precision::F32) => (
                        crate::number::display_f32(*float as f32),
                        crate::number::hex_f32(*float as f32),
                    ),
                    _ => (
                        crate::number::display_f64(*float),
                        crate::number::hex_f64(*float),
                    ),
                };
                let ei = intended.as_ref().map(|v| v[c].clone());
                coords.push(FailedCoord {
                    index: c,
                    decimal,
                    hex,
                    intended: ei.as_ref().map(|e| Measures::new(&yq, e, self.precision)),
                    exact_intended: ei,
                    exact_seen: exact[c].clone(),
                    seen: meas,
                });
            }
        }
        (pass, worst, reason, coords)
    }

    /// Judge one row: filter first, exact when undecided; the ULP figures settled as
    /// [`Prepared::filtered`] settles them.
    pub(super) fn row(
        &self,
        line: usize,
        inputs: Vec<Num>,
        claimed: Vec<Num>,
        scratch: &mut RowScratch,
    ) -> RowOutcome {
        let finite = |xs: &[Num]| xs.iter().all(|x| matches!(x, Num::Value { .. }));
        if !finite(&inputs) || !finite(&claimed) {
            let (_, _, reason, _) = self.exact_row(&inputs, &claimed, None, false);
            return RowOutcome {
                line,
                pass: false,
                fell_back: false,
                ulps: f64::INFINITY,
                ulps_lower: f64::INFINITY,
                settled_exactly: false,
                failure: reason,
                inputs,
                claimed,
            };
        }
        scratch.load(&inputs, &claimed);
        if let Some(mut o) = self.filtered(line, scratch) {
            o.inputs = inputs;
            o.claimed = claimed;
            return o;
        }
        let (pass, ulps, reason, _) = self.exact_row(&inputs, &claimed, None, false);
        RowOutcome {
            line,
            pass,
            fell_back: self.filter.is_some(),
            ulps,
            ulps_lower: ulps,
            settled_exactly: false,
            failure: if pass { None } else { reason },
            inputs,
            claimed,
        }
    }

    /// Judge a row of finite floats (in `scratch.lambda` and `scratch.ys`: the numbers as the
    /// code saw them) by the float filter alone, and settle its ULP figures: `None` when there
    /// is no filter or it cannot decide (the row then needs exact arithmetic). The outcome's
    /// numbers (`inputs`, `claimed`) are left empty, for the caller to fill when it keeps the
    /// row.
    ///
    /// Settling, for the histogram and the worst-row search: a row the plain filter stage
    /// decided gets the compensated enclosure (the errors, to a small fraction of an ulp,
    /// instead of the looseness of the plain bounds); a row whose enclosure still straddles a
    /// histogram boundary (an error that may be exactly 0, or exactly 1/2 ulp as at a rounding
    /// midpoint) is computed exactly, so every row lands in its true bucket. So are Cartesian
    /// rows decided at their double-double barycentric coordinates (as tight); a Cartesian row
    /// only the widened stage decided keeps its enclosure's ends (upper bounds, like every
    /// filter-decided row's figures): its enclosure is a few ulps wide, and settling it would
    /// cost the exact arithmetic the filter saved.
    pub(super) fn filtered(&self, line: usize, scratch: &mut RowScratch) -> Option<RowOutcome> {
        let (filter, th) = self.filter.as_ref()?;
        let RowScratch {
            filter: sc,
            enc,
            lambda,
            ys,
            point,
        } = scratch;
        enc.resize(filter.dim(), Enclosure::default());
        let RowJudgement {
            decision,
            mut ulps,
            mut ulps_lower,
            tight,
        } = match &self.cartesian_map {
            None => filter.judge_tight(th, lambda, ys, sc, enc),
            Some(map) => {
                if map.barycentric(lambda, point) {
                    filter.judge_cartesian(th, point, ys, sc, enc)
                } else {
                    RowJudgement {
                        decision: Decision::Undecided,
                        ulps: f64::INFINITY,
                        ulps_lower: 0.0,
                        tight: false,
                    }
                }
            }
        };
        let pass = match decision {
            Decision::Pass => true,
            Decision::Fail => false,
            Decision::Undecided => return None,
        };
        let mut settled_exactly = false;
        if ulps.is_finite() && (self.cartesian_map.is_none() || tight) {
            // (a Cartesian row gets here tight only: its inputs are not barycentric)
            if !tight {
                let (lo, hi) = filter.ulps_bounds(th, lambda, ys, sc, enc);
                ulps_lower = ulps_lower.max(lo);
                ulps = ulps.min(hi);
            }
            use super::UlpHistogram;
            if UlpHistogram::bucket(ulps_lower) != UlpHistogram::bucket(ulps) {
                ulps = self.exact_ulps(lambda, ys);
                ulps_lower = ulps;
                settled_exactly = true;
            }
        }
        Some(RowOutcome {
            line,
            pass,
            fell_back: false,
            ulps,
            ulps_lower,
            settled_exactly,
            failure: (!pass).then(String::new),
            inputs: Vec::new(),
            claimed: Vec::new(),
        })
    }
}

impl Prepared {
    /// The row's largest error in ULPs, computed exactly, from its finite floats (the numbers as
    /// the code saw them, with a precision; no verdict, condition number or report figures: the
    /// histogram's lean path).
    fn exact_ulps(&self, inputs: &[f64], claimed: &[f64]) -> f64 {
        let Some(lambda) = inputs
            .iter()
            .map(|&x| crate::number::exact_f64(x))
            .collect::<Option<Vec<_>>>()
            .and_then(|x| self.barycentric(x))
        else {
            return f64::INFINITY;
        };
        let exact = self.seen.evaluate_fast(&lambda);
        claimed
            .iter()
            .zip(&exact)
            .map(|(&y, q)| {
                // round_up_f64 of ulps_error_f32/f64 of the exact y, without a gcd
                let u = match self.precision {
                    Some(Precision::F32) => crate::number::ulps_error_up::<f32>(y, q),
                    _ => crate::number::ulps_error_up::<f64>(y, q),
                };
                u.unwrap_or(f64::INFINITY)
            })
            .fold(0.0, f64::max)
    }
}

/// Per-thread buffers of the judge: the filter's scratch and enclosures, the row's inputs and
/// claimed values as floats, and (Cartesian rows) its barycentric coordinates with their radii.
#[derive(Default)]
pub(super) struct RowScratch {
    filter: Scratch,
    enc: Vec<Enclosure>,
    /// The row's inputs as floats.
    pub(super) lambda: Vec<f64>,
    /// The row's claimed coordinates as floats.
    pub(super) ys: Vec<f64>,
    point: CartesianPoint,
}

impl RowScratch {
    /// Load an in-memory row's numbers as the code saw them (each rounded to `precision`: an
    /// `f32` batch takes the nearest `f32`, as [`super::memory_num`] does); false if one of them
    /// is not finite there (the row is then judged from its [`Num`]s).
    pub(super) fn load_floats(
        &mut self,
        inputs: &[f64],
        claimed: &[f64],
        precision: Option<Precision>,
    ) -> bool {
        let seen = |x: f64| match precision {
            Some(Precision::F32) => f64::from(x as f32),
            _ => x,
        };
        self.lambda.clear();
        self.lambda.extend(inputs.iter().map(|&x| seen(x)));
        self.ys.clear();
        self.ys.extend(claimed.iter().map(|&x| seen(x)));
        self.lambda.iter().chain(&self.ys).all(|x| x.is_finite())
    }

    /// Load a row's numbers as floats (NaN for a number that is not finite).
    fn load(&mut self, inputs: &[Num], claimed: &[Num]) {
        let float = |x: &Num| match x {
            Num::Value { float, .. } => *float,
            Num::NotFinite(..) => f64::NAN,
        };
        self.lambda.clear();
        self.lambda.extend(inputs.iter().map(float));
        self.ys.clear();
        self.ys.extend(claimed.iter().map(float));
    }
}
