//! Views: the orthographic projection of R^3 onto the picture, and fitting data to a frame.
//!
//! A view is given by its azimuth `a` and elevation `e` in degrees (as in most plotting
//! programs): the viewer looks at the origin from the direction
//! `v = (cos e cos a, cos e sin a, sin e)`. A point `X` goes to the picture coordinates
//! `(r·X, u·X)` with `r = (−sin a, cos a, 0)` to the right and `u = (−sin e cos a, −sin e sin a,
//! cos e)` up; `v·X` is its depth (larger is nearer). The picture then maps `(p, q)` to the pixel
//! `(ox + s·p, oy − s·q)` ([`Frame`]); every picture states `ox`, `oy` and `s` as the attributes
//! `data-origin` and `data-scale` of its plot group, so a test can project a point itself.

/// The default view: azimuth −60°, elevation 30°.
pub const DEFAULT_VIEW: View = View {
    azimuth: -60.0,
    elevation: 30.0,
};

/// An orthographic view from azimuth and elevation (degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Degrees, any finite value.
    pub azimuth: f64,
    /// Degrees, from −90 to 90.
    pub elevation: f64,
}

impl View {
    /// Parse `AZIMUTH,ELEVATION` (degrees; the elevation from −90 to 90).
    pub fn parse(text: &str) -> Result<View, String> {
        let bad = || {
            format!(
                "--view `{text}`: expected AZIMUTH,ELEVATION in degrees (two numbers, the elevation from -90 to 90), e.g. --view -60,30"
            )
        };
        let parts: Vec<&str> = text.split(',').map(str::trim).collect();
        let [a, e] = parts[..] else {
            return Err(bad());
        };
        let number = |s: &str| {
            s.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite() && x.abs() <= 1e6)
        };
        match (number(a), number(e)) {
            (Some(azimuth), Some(elevation)) if (-90.0..=90.0).contains(&elevation) => {
                Ok(View { azimuth, elevation })
            }
            _ => Err(bad()),
        }
    }

    /// The right, up and towards-the-viewer unit vectors.
    pub fn axes(&self) -> ([f64; 3], [f64; 3], [f64; 3]) {
        let (a, e) = (self.azimuth.to_radians(), self.elevation.to_radians());
        let (sa, ca, se, ce) = (a.sin(), a.cos(), e.sin(), e.cos());
        (
            [-sa, ca, 0.0],
            [-se * ca, -se * sa, ce],
            [ce * ca, ce * sa, se],
        )
    }
}

/// The dot product.
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The cross product.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a − b`.
pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a / |a|` (zero stays zero).
pub fn normalize(a: [f64; 3]) -> [f64; 3] {
    let n = dot(a, a).sqrt();
    if n > 0.0 && n.is_finite() {
        [a[0] / n, a[1] / n, a[2] / n]
    } else {
        [0.0, 0.0, 0.0]
    }
}

/// The map from picture coordinates to pixels: `(ox + s·p, oy − s·q)` (y grows downwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// Pixel of the origin.
    pub ox: f64,
    /// Pixel of the origin.
    pub oy: f64,
    /// Pixels per unit.
    pub s: f64,
}

impl Frame {
    /// The frame fitting the points' bounding box into the pixel box `(x, y, w, h)`, centred,
    /// the same scale on both axes. Non-finite points are ignored; no points (or one) give a
    /// unit box around the origin (or the point).
    pub fn fit<'a>(
        points: impl IntoIterator<Item = &'a [f64; 2]>,
        (x, y, w, h): (f64, f64, f64, f64),
    ) -> Frame {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in points {
            if p[0].is_finite() && p[1].is_finite() {
                for k in 0..2 {
                    lo[k] = lo[k].min(p[k]);
                    hi[k] = hi[k].max(p[k]);
                }
            }
        }
        if lo[0] > hi[0] {
            lo = [-0.5, -0.5];
            hi = [0.5, 0.5];
        }
        for k in 0..2 {
            if hi[k] - lo[k] <= f64::EPSILON * (hi[k].abs() + lo[k].abs()).max(1e-300) {
                let c = 0.5 * (hi[k] + lo[k]);
                let half = 0.5
                    * (hi[0] - lo[0])
                        .max(hi[1] - lo[1])
                        .max(c.abs() * 1e-6)
                        .max(1e-12);
                lo[k] = c - half;
                hi[k] = c + half;
            }
        }
        let s = (w / (hi[0] - lo[0])).min(h / (hi[1] - lo[1]));
        let s = if s.is_finite() && s > 0.0 { s } else { 1.0 };
        let cx = 0.5 * (lo[0] + hi[0]);
        let cy = 0.5 * (lo[1] + hi[1]);
        Frame {
            ox: x + 0.5 * w - s * cx,
            oy: y + 0.5 * h + s * cy,
            s,
        }
    }

    /// The pixel of picture coordinates `p`.
    pub fn px(&self, p: [f64; 2]) -> [f64; 2] {
        [self.ox + self.s * p[0], self.oy - self.s * p[1]]
    }

    /// The group attributes stating the frame (see the module's documentation).
    pub fn attrs(&self) -> [(&'static str, String); 2] {
        [
            ("data-origin", format!("{} {}", self.ox, self.oy)),
            ("data-scale", format!("{}", self.s)),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn views_parse_and_refuse() {
        assert_eq!(
            View::parse("-60,30").unwrap(),
            View {
                azimuth: -60.0,
                elevation: 30.0
            }
        );
        assert_eq!(View::parse(" 10 , 90 ").unwrap().elevation, 90.0);
        for bad in [
            "", "1", "1,2,3", "a,b", "0,91", "0,-90.5", "nan,0", "inf,0", "1e9,0",
        ] {
            assert!(View::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn the_axes_are_orthonormal_and_the_view_from_above_keeps_x_and_y() {
        let top = View {
            azimuth: -90.0,
            elevation: 90.0,
        };
        // from above with azimuth −90°: x to the right, y up the picture
        let (r, u, v) = top.axes();
        let x = [1.0, 2.0, 3.0];
        let (p, depth) = ([dot(r, x), dot(u, x)], dot(v, x));
        assert!(
            (p[0] - 1.0).abs() < 1e-12 && (p[1] - 2.0).abs() < 1e-12,
            "{p:?}"
        );
        assert!((depth - 3.0).abs() < 1e-12);
        let (r, u, v) = DEFAULT_VIEW.axes();
        for (a, b, want) in [
            (r, r, 1.0),
            (u, u, 1.0),
            (v, v, 1.0),
            (r, u, 0.0),
            (r, v, 0.0),
            (u, v, 0.0),
        ] {
            assert!((dot(a, b) - want).abs() < 1e-12);
        }
        // right-handed: r × u = v
        let c = cross(r, u);
        assert!((0..3).all(|k| (c[k] - v[k]).abs() < 1e-12));
    }

    #[test]
    fn fitting_centres_the_box_with_one_scale() {
        let f = Frame::fit(&[[0.0, 0.0], [2.0, 1.0]], (10.0, 20.0, 100.0, 100.0));
        assert_eq!(f.s, 50.0);
        assert_eq!(f.px([0.0, 0.0]), [10.0, 95.0]);
        assert_eq!(f.px([2.0, 1.0]), [110.0, 45.0]);
        let one = Frame::fit(&[[3.0, 3.0]], (0.0, 0.0, 10.0, 10.0));
        assert_eq!(one.px([3.0, 3.0]), [5.0, 5.0]);
    }
}
