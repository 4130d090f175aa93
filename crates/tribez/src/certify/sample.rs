//! Reproducible random sample points for certification runs: a SplitMix64 generator, so that the
//! same seed gives the same points on every machine and in every language binding.

/// A small deterministic generator (SplitMix64): the same seed gives the same points everywhere.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Random barycentric points (m+1 coordinates): 70% inside, 15% within 1e-9 of an edge,
/// 15% outside the simplex (coordinates down to −1/2; every coordinate finite, in [−1/2, 3/2]); `w = 1 − u − v` computed in f64 (so the
/// coordinates need not sum to 1 exactly; the exact value is the homogeneous form there).
pub fn random_points(m: usize, count: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut r = SplitMix(seed);
    (0..count)
        .map(|i| {
            let kind = i % 20;
            let mut lam: Vec<f64> = (0..m).map(|_| r.unit()).collect();
            // (every draw 0 would divide 0 by 0: the maximum keeps the point finite)
            let total: f64 = (lam.iter().sum::<f64>() + r.unit()).max(f64::MIN_POSITIVE);
            lam.iter_mut().for_each(|x| *x /= total);
            if kind < 3 {
                let k = (r.next_u64() % m as u64) as usize;
                lam[k] = r.unit() * 1e-9;
            } else if kind < 6 {
                let k = (r.next_u64() % m as u64) as usize;
                lam[k] = -0.5 * r.unit();
            }
            let last = lam.iter().fold(1.0, |acc, x| acc - x);
            lam.push(last);
            lam
        })
        .collect()
}

/// Random Cartesian points of a convex polygon (vertices in f64): 70% random convex
/// combinations of the vertices, 15% within about 1e-9 of an edge, 15% near a vertex.
pub fn random_polygon_points(vertices: &[[f64; 2]], count: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut r = SplitMix(seed);
    let nv = vertices.len();
    let centroid = [0, 1].map(|c| vertices.iter().map(|v| v[c]).sum::<f64>() / nv as f64);
    (0..count)
        .map(|i| {
            let kind = i % 20;
            if kind < 3 {
                let j = (r.next_u64() % nv as u64) as usize;
                let (a, b) = (vertices[j], vertices[(j + 1) % nv]);
                let t = r.unit();
                let s = 1e-9 * r.unit();
                [0, 1].map(|c| {
                    let e = a[c] + t * (b[c] - a[c]);
                    e + s * (centroid[c] - e)
                })
            } else if kind < 6 {
                let j = (r.next_u64() % nv as u64) as usize;
                let s = 1e-6 * r.unit();
                [0, 1].map(|c| vertices[j][c] + s * (centroid[c] - vertices[j][c]))
            } else {
                let w: Vec<f64> = (0..nv).map(|_| r.unit()).collect();
                let total: f64 = w.iter().sum();
                [0, 1].map(|c| {
                    vertices
                        .iter()
                        .zip(&w)
                        .map(|(v, wi)| v[c] * wi)
                        .sum::<f64>()
                        / total
                })
            }
        })
        .collect()
}
