//! The histogram of a batch's errors in ULPs.

use serde_json::Value as Json;

/// A histogram of errors in ULPs: buckets `0`, `≤ 1/2`, `≤ 1`, `≤ 2`, `≤ 4`, `≤ 16`, `≤ 256`, `> 256`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct UlpHistogram {
    /// Counts per bucket.
    pub counts: [u64; 8],
}

/// The bucket labels of [`UlpHistogram`].
pub const ULP_BUCKETS: [&str; 8] = [
    "0",
    "(0, 1/2]",
    "(1/2, 1]",
    "(1, 2]",
    "(2, 4]",
    "(4, 16]",
    "(16, 256]",
    "> 256",
];

impl UlpHistogram {
    /// The bucket of an error of `ulps` ULPs (an index into [`ULP_BUCKETS`]).
    pub fn bucket(ulps: f64) -> usize {
        if ulps == 0.0 {
            0
        } else if ulps <= 0.5 {
            1
        } else if ulps <= 1.0 {
            2
        } else if ulps <= 2.0 {
            3
        } else if ulps <= 4.0 {
            4
        } else if ulps <= 16.0 {
            5
        } else if ulps <= 256.0 {
            6
        } else {
            7
        }
    }

    /// Count one error of `ulps` ULPs.
    pub fn add(&mut self, ulps: f64) {
        self.counts[Self::bucket(ulps)] += 1;
    }

    /// Is it empty?
    pub fn is_empty(&self) -> bool {
        self.counts.iter().all(|&c| c == 0)
    }

    /// A small text histogram (bars scaled to 40 characters).
    pub fn text(&self) -> String {
        let max = self.counts.iter().copied().max().unwrap_or(0).max(1);
        let mut out = String::new();
        for (label, &c) in ULP_BUCKETS.iter().zip(&self.counts) {
            let bar = "#".repeat(((c as f64 / max as f64) * 40.0).ceil() as usize);
            out += &format!("  {label:>10} ulp  {c:>10}  {bar}\n");
        }
        out
    }

    /// JSON: bucket label → count.
    pub fn json(&self) -> Json {
        Json::Object(
            ULP_BUCKETS
                .iter()
                .zip(self.counts)
                .map(|(l, c)| (l.to_string(), Json::from(c)))
                .collect(),
        )
    }
}
