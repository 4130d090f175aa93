//! A small SVG writer: elements appended to a string, every attribute value and text escaped for
//! XML, numbers printed with two decimals (a hundredth of a pixel).

use std::fmt::Write;

/// `text` with the five XML special characters escaped (safe in attribute values and text).
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            // characters XML 1.0 does not allow (control characters other than tab, newline, CR)
            c if (c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r') => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

/// A coordinate or length: two decimals, no trailing zeros, `-0` printed as `0`.
pub fn num(x: f64) -> String {
    let x = if x.is_finite() { x } else { 0.0 };
    let s = format!("{x:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" || s.is_empty() {
        "0".into()
    } else {
        s.into()
    }
}

/// An RGB colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    /// `#rrggbb`.
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }

    /// Each channel scaled by `k` (0 to 1).
    pub fn scaled(self, k: f64) -> Rgb {
        let s = |c: u8| (f64::from(c) * k.clamp(0.0, 1.0)).round() as u8;
        Rgb(s(self.0), s(self.1), s(self.2))
    }
}

/// An SVG document being written.
pub struct Svg {
    out: String,
}

impl Svg {
    /// A `width` × `height` pixel document with a white background; `attrs` are extra root
    /// attributes (already escaped pairs).
    pub fn new(width: f64, height: f64, attrs: &[(&str, String)]) -> Svg {
        let mut out = String::with_capacity(1 << 16);
        let _ = write!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="DejaVu Sans, Helvetica, Arial, sans-serif""#,
            w = num(width),
            h = num(height)
        );
        for (k, v) in attrs {
            let _ = write!(out, r#" {k}="{}""#, escape(v));
        }
        out.push_str(">\n");
        let _ = writeln!(
            out,
            r##"<rect x="0" y="0" width="{}" height="{}" fill="#ffffff"/>"##,
            num(width),
            num(height)
        );
        Svg { out }
    }

    /// Open a group with attributes (values escaped here).
    pub fn open_group(&mut self, attrs: &[(&str, String)]) {
        self.out.push_str("<g");
        self.attrs(attrs);
        self.out.push_str(">\n");
    }

    /// Close the group opened last.
    pub fn close_group(&mut self) {
        self.out.push_str("</g>\n");
    }

    fn attrs(&mut self, attrs: &[(&str, String)]) {
        for (k, v) in attrs {
            let _ = write!(self.out, r#" {k}="{}""#, escape(v));
        }
    }

    /// A filled polygon (`stroke`: outline colour and width).
    pub fn polygon(&mut self, points: &[[f64; 2]], fill: Rgb, stroke: Option<(Rgb, f64)>) {
        self.out.push_str(r#"<polygon points=""#);
        self.points(points);
        let _ = write!(self.out, r#"" fill="{}""#, fill.hex());
        if let Some((c, w)) = stroke {
            let _ = write!(
                self.out,
                r#" stroke="{}" stroke-width="{}" stroke-linejoin="round""#,
                c.hex(),
                num(w)
            );
        }
        self.out.push_str("/>\n");
    }

    /// An open polyline.
    pub fn polyline(&mut self, points: &[[f64; 2]], stroke: Rgb, width: f64, extra: &str) {
        if points.len() < 2 {
            return;
        }
        self.out.push_str(r#"<polyline points=""#);
        self.points(points);
        let _ = writeln!(
            self.out,
            r#"" fill="none" stroke="{}" stroke-width="{}" stroke-linejoin="round" stroke-linecap="round"{extra}/>"#,
            stroke.hex(),
            num(width)
        );
    }

    fn points(&mut self, points: &[[f64; 2]]) {
        for (i, p) in points.iter().enumerate() {
            if i > 0 {
                self.out.push(' ');
            }
            let _ = write!(self.out, "{},{}", num(p[0]), num(p[1]));
        }
    }

    /// A line segment.
    pub fn line(&mut self, a: [f64; 2], b: [f64; 2], stroke: Rgb, width: f64) {
        let _ = writeln!(
            self.out,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{}" stroke-width="{}" stroke-linecap="round"/>"#,
            num(a[0]),
            num(a[1]),
            num(b[0]),
            num(b[1]),
            stroke.hex(),
            num(width)
        );
    }

    /// A circle; `attrs` are extra attributes (values escaped here).
    pub fn circle(
        &mut self,
        c: [f64; 2],
        r: f64,
        fill: Option<Rgb>,
        stroke: Option<(Rgb, f64)>,
        attrs: &[(&str, String)],
    ) {
        let _ = write!(
            self.out,
            r#"<circle cx="{}" cy="{}" r="{}" fill="{}""#,
            num(c[0]),
            num(c[1]),
            num(r),
            fill.map_or("none".to_string(), Rgb::hex)
        );
        if let Some((s, w)) = stroke {
            let _ = write!(
                self.out,
                r#" stroke="{}" stroke-width="{}""#,
                s.hex(),
                num(w)
            );
        }
        self.attrs(attrs);
        self.out.push_str("/>\n");
    }

    /// A rectangle.
    pub fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, fill: Rgb, stroke: Option<(Rgb, f64)>) {
        let _ = write!(
            self.out,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="{}""#,
            num(x),
            num(y),
            num(w),
            num(h),
            fill.hex()
        );
        if let Some((s, sw)) = stroke {
            let _ = write!(
                self.out,
                r#" stroke="{}" stroke-width="{}""#,
                s.hex(),
                num(sw)
            );
        }
        self.out.push_str("/>\n");
    }

    /// Text at `(x, y)` (the baseline); `anchor` is `start`, `middle` or `end`; `attrs` are
    /// extra attributes (values escaped here). The text has a white halo so it reads over a
    /// picture.
    pub fn text(
        &mut self,
        at: [f64; 2],
        size: f64,
        anchor: &str,
        fill: Rgb,
        text: &str,
        attrs: &[(&str, String)],
    ) {
        let _ = write!(
            self.out,
            r##"<text x="{}" y="{}" font-size="{}" text-anchor="{anchor}" fill="{}" stroke="#ffffff" stroke-width="3" stroke-linejoin="round" paint-order="stroke""##,
            num(at[0]),
            num(at[1]),
            num(size),
            fill.hex()
        );
        self.attrs(attrs);
        let _ = writeln!(self.out, ">{}</text>", escape(text));
    }

    /// A `<title>` (a tooltip in browsers, the accessible name).
    pub fn title(&mut self, text: &str) {
        let _ = writeln!(self.out, "<title>{}</title>", escape(text));
    }

    /// The finished document.
    pub fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_every_special_character() {
        assert_eq!(
            escape(r#"a<b & "c" 'd'>"#),
            "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;"
        );
        assert_eq!(escape("x\u{1}y"), "x\u{FFFD}y");
    }

    #[test]
    fn numbers_have_two_decimals_at_most() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.256), "1.26");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(num(12.5), "12.5");
    }
}
