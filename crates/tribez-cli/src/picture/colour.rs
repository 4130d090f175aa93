//! Colours: the error maps' sequential colour map (perceptually ordered, dark blue to yellow,
//! readable in grey and by most colour-blind readers) and the logarithmic scale of errors in ULPs.

use super::svg::Rgb;

/// The colour map's anchors, evenly spaced from 0 to 1 (the viridis map at ninths).
const ANCHORS: [Rgb; 10] = [
    Rgb(68, 1, 84),
    Rgb(72, 36, 117),
    Rgb(65, 68, 135),
    Rgb(53, 95, 141),
    Rgb(42, 120, 142),
    Rgb(33, 145, 140),
    Rgb(34, 168, 132),
    Rgb(68, 191, 112),
    Rgb(122, 209, 81),
    Rgb(253, 231, 37),
];

/// The colour at `t` in [0, 1] (clamped), interpolated linearly between the anchors.
pub fn map(t: f64) -> Rgb {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (ANCHORS.len() - 1) as f64;
    let i = (x.floor() as usize).min(ANCHORS.len() - 2);
    let f = x - i as f64;
    let (a, b) = (ANCHORS[i], ANCHORS[i + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + (f64::from(q) - f64::from(p)) * f).round() as u8;
    Rgb(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// A logarithmic scale of errors from `lo` to `hi` ULPs (the smallest and largest error): `t =
/// (log u − log f) / (log hi − log f)` where `f` is the smallest positive error; errors from 0 to
/// `f` take the bottom colour (`log 0` is not a number), every error ≥ `hi` the top one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogScale {
    /// The smallest error (the colour bar's bottom label).
    pub lo: f64,
    /// The largest error (the colour bar's top label).
    pub hi: f64,
    /// The smallest positive error (where the logarithmic part starts).
    pub floor: f64,
}

impl LogScale {
    /// The scale of errors whose smallest is `lo`, smallest positive `floor` (if any) and
    /// largest `hi`.
    pub fn new(lo: f64, floor: Option<f64>, hi: f64) -> LogScale {
        let floor = floor.filter(|f| *f > 0.0 && f.is_finite()).unwrap_or(hi);
        LogScale { lo, hi, floor }
    }

    /// The position of an error of `u` ULPs on the scale, from 0 to 1.
    pub fn t(&self, u: f64) -> f64 {
        if self.hi <= self.floor || self.floor <= 0.0 {
            // one value (or only zeros): the middle of the map for all
            return if self.hi > self.lo && u >= self.hi {
                1.0
            } else if self.hi > self.lo {
                0.0
            } else {
                0.5
            };
        }
        if u <= self.floor {
            return 0.0;
        }
        ((u.ln() - self.floor.ln()) / (self.hi.ln() - self.floor.ln())).clamp(0.0, 1.0)
    }

    /// The colour of an error of `u` ULPs.
    pub fn colour(&self, u: f64) -> Rgb {
        map(self.t(u))
    }

    /// Powers of ten strictly inside the logarithmic part (colour bar ticks), at most 12.
    pub fn ticks(&self) -> Vec<f64> {
        if self.hi <= self.floor || self.floor <= 0.0 {
            return Vec::new();
        }
        let (a, b) = (
            self.floor.log10().floor() as i32,
            self.hi.log10().ceil() as i32,
        );
        let step = ((b - a) / 10).max(1);
        (a..=b)
            .step_by(step as usize)
            .map(|k| 10f64.powi(k))
            .filter(|&v| v > self.floor * 1.05 && v < self.hi / 1.05)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_map_runs_from_dark_to_light() {
        assert_eq!(map(0.0), ANCHORS[0]);
        assert_eq!(map(1.0), ANCHORS[9]);
        assert_eq!(map(-3.0), ANCHORS[0]);
        assert_eq!(map(f64::NAN), ANCHORS[0]);
        // luminance grows along the map
        let lum =
            |c: Rgb| 0.2126 * f64::from(c.0) + 0.7152 * f64::from(c.1) + 0.0722 * f64::from(c.2);
        let mut last = -1.0;
        for k in 0..=20 {
            let l = lum(map(f64::from(k) / 20.0));
            assert!(l > last, "step {k}");
            last = l;
        }
    }

    #[test]
    fn the_scale_is_logarithmic_between_the_smallest_positive_and_largest_error() {
        let s = LogScale::new(0.0, Some(0.01), 100.0);
        assert_eq!(s.t(0.0), 0.0);
        assert_eq!(s.t(0.01), 0.0);
        assert!((s.t(1.0) - 0.5).abs() < 1e-12);
        assert_eq!(s.t(100.0), 1.0);
        assert_eq!(s.t(1e9), 1.0);
        assert_eq!(s.ticks(), vec![0.1, 1.0, 10.0]);
        let one = LogScale::new(2.0, Some(2.0), 2.0);
        assert_eq!(one.t(2.0), 0.5);
        let zeros = LogScale::new(0.0, None, 0.0);
        assert_eq!(zeros.t(0.0), 0.5);
    }
}
