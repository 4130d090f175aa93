//! Error maps (`tribez check --plot`, `tribez certify --plot`): the domain (a triangle, or an
//! S-patch's polygon) with every judged row at its position, coloured by its error in ULPs on a
//! logarithmic scale ([`LogScale`]) with a colour bar whose end labels are the smallest and the
//! largest error; failed rows ringed in red; the worst row ringed in black and labelled; rows
//! outside the domain where they are; the histogram of the errors beside the map.
//!
//! Rows arrive one at a time ([`MapBuilder::add`]) and are not all kept: up to [`MAX_DOTS`]
//! rows are drawn as dots; past that every row falls into a cell of a fixed grid over the view,
//! drawn in the colour of the largest error in it (so no bad row hides), and memory stays
//! bounded whatever the batch's size.

use super::colour::LogScale;
use super::project::Frame;
use super::svg::{Rgb, Svg};
use tribez::batch::ULP_BUCKETS;

/// Rows drawn one by one, at most (past that: grid cells).
pub const MAX_DOTS: usize = 20_000;
/// Grid cells, pixels.
const CELL: f64 = 3.0;
/// The ring of failed rows.
pub const FAILED: Rgb = Rgb(228, 26, 28);
/// The worst row's marker.
pub const WORST: Rgb = Rgb(0, 0, 0);
/// Text and outlines.
const INK: Rgb = Rgb(34, 34, 34);
/// Rows outside the domain: their outline; the domain.
const OUTLINE: Rgb = Rgb(120, 120, 120);
/// Rows whose error is not finite (a non-finite claimed number).
const NOT_FINITE: Rgb = Rgb(0, 0, 0);

/// One row (or point) drawn.
#[derive(Clone, Copy, Debug)]
struct Dot {
    at: [f64; 2],
    ulps: f64,
    pass: bool,
}

/// A cell of the grid: its largest error, rows, failed rows.
#[derive(Clone, Copy, Debug, Default)]
struct Cell {
    max: f64,
    rows: u32,
    failed: u32,
    not_finite: bool,
}

/// The grid rows fall into past [`MAX_DOTS`].
#[derive(Clone, Debug)]
struct Grid {
    /// The view's lower left corner and size (domain coordinates).
    lo: [f64; 2],
    size: [f64; 2],
    nx: usize,
    ny: usize,
    cells: Vec<Cell>,
}

/// What the worst row may be: rows whose error may be the largest (their upper bound reaches
/// every other row's lower bound).
#[derive(Clone, Debug, Default)]
struct WorstCandidates {
    floor: f64,
    exact_at_floor: bool,
    rows: Vec<(usize, [f64; 2], f64)>,
}

/// The map being assembled, row by row.
#[derive(Clone, Debug)]
pub struct MapBuilder {
    outline: Vec<[f64; 2]>,
    dots: Vec<Dot>,
    grid: Option<Grid>,
    /// Rows drawn (placed), failed rows, rows without a place (a non-finite input).
    rows: u64,
    failed: u64,
    unplaced: u64,
    outside: u64,
    not_finite: u64,
    /// The smallest and largest finite error, the smallest positive one.
    min: f64,
    max: f64,
    min_positive: Option<f64>,
    worst: WorstCandidates,
}

/// The finished map's data.
#[derive(Clone, Debug)]
pub struct MapData {
    b: MapBuilder,
}

/// How far beyond the domain the view reaches at most (in domain sizes on each side); rows
/// farther out are drawn at the view's edge.
const REACH: f64 = 1.0;

/// Is `p` inside the convex polygon `outline` (either orientation, edges included)?
fn inside(outline: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut sign = 0.0f64;
    for i in 0..outline.len() {
        let (a, b) = (outline[i], outline[(i + 1) % outline.len()]);
        let c = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        if c != 0.0 {
            if sign != 0.0 && c.signum() != sign {
                return false;
            }
            sign = c.signum();
        }
    }
    true
}

fn bbox(points: impl IntoIterator<Item = [f64; 2]>) -> ([f64; 2], [f64; 2]) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}

impl MapBuilder {
    /// A map over the convex polygon `outline` (a triangle's three vertices, or a polygon's),
    /// in domain coordinates.
    pub fn new(outline: Vec<[f64; 2]>) -> MapBuilder {
        MapBuilder {
            outline,
            dots: Vec::new(),
            grid: None,
            rows: 0,
            failed: 0,
            unplaced: 0,
            outside: 0,
            not_finite: 0,
            min: f64::INFINITY,
            max: f64::NEG_INFINITY,
            min_positive: None,
            worst: WorstCandidates::default(),
        }
    }

    /// The domain's outline.
    pub fn outline(&self) -> &[[f64; 2]] {
        &self.outline
    }

    /// The view's limits: the domain's box, widened to hold the rows, at most [`REACH`] domain
    /// sizes beyond it on each side.
    fn limits(&self) -> ([f64; 2], [f64; 2]) {
        let (dlo, dhi) = bbox(self.outline.iter().copied());
        let span = (dhi[0] - dlo[0])
            .max(dhi[1] - dlo[1])
            .max(f64::MIN_POSITIVE);
        let (rlo, rhi) = bbox(self.dots.iter().map(|d| d.at));
        let mut lo = [0.0; 2];
        let mut hi = [0.0; 2];
        for k in 0..2 {
            lo[k] = dlo[k].min(rlo[k]).max(dlo[k] - REACH * span);
            hi[k] = dhi[k].max(rhi[k]).min(dhi[k] + REACH * span);
        }
        (lo, hi)
    }

    /// Add a row: its number, its position in the domain (NaN: it has none), its error in ULPs
    /// (`ulps`, with a lower bound `lower` when `ulps` is the upper end of an enclosure), and
    /// whether it passed.
    pub fn add(&mut self, row: usize, at: [f64; 2], ulps: f64, lower: f64, pass: bool) {
        if !pass {
            self.failed += 1;
        }
        if ulps.is_finite() {
            self.min = self.min.min(ulps);
            self.max = self.max.max(ulps);
            if ulps > 0.0 {
                self.min_positive = Some(self.min_positive.map_or(ulps, |m| m.min(ulps)));
            }
        } else {
            self.not_finite += 1;
        }
        if !(at[0].is_finite() && at[1].is_finite()) {
            self.unplaced += 1;
            return;
        }
        self.rows += 1;
        if !inside(&self.outline, at) {
            self.outside += 1;
        }
        if ulps.is_finite() {
            self.worst_candidate(row, at, ulps, lower.min(ulps));
        }
        let dot = Dot { at, ulps, pass };
        match &mut self.grid {
            None if self.dots.len() < MAX_DOTS => self.dots.push(dot),
            None => {
                let (lo, hi) = self.limits();
                let size = [(hi[0] - lo[0]).max(1e-300), (hi[1] - lo[1]).max(1e-300)];
                // cells of CELL pixels in the map's box (MAP_W × MAP_H at the fitted scale)
                let s = (MAP_W / size[0]).min(MAP_H / size[1]);
                let nx = ((size[0] * s / CELL).ceil() as usize).clamp(1, 1024);
                let ny = ((size[1] * s / CELL).ceil() as usize).clamp(1, 1024);
                let mut grid = Grid {
                    lo,
                    size,
                    nx,
                    ny,
                    cells: vec![Cell::default(); nx * ny],
                };
                for d in self.dots.drain(..).chain(std::iter::once(dot)) {
                    grid.add(d);
                }
                self.grid = Some(grid);
            }
            Some(g) => g.add(dot),
        }
    }

    fn worst_candidate(&mut self, row: usize, at: [f64; 2], upper: f64, lower: f64) {
        let w = &mut self.worst;
        if lower > w.floor || w.rows.is_empty() {
            w.floor = w.floor.max(lower);
            w.exact_at_floor = false;
            if w.rows.len() > 64 {
                let floor = w.floor;
                w.rows.retain(|c| c.2 >= floor);
            }
        }
        if upper < w.floor {
            return;
        }
        if upper == lower && upper == w.floor {
            // an exact tie with an earlier exact row cannot be the worst (ties: the first row)
            if w.exact_at_floor {
                return;
            }
            w.exact_at_floor = true;
        }
        if w.rows.len() < 1 << 20 {
            w.rows.push((row, at, upper));
        }
    }

    /// The finished map.
    pub fn finish(self) -> MapData {
        MapData { b: self }
    }
}

impl Grid {
    fn add(&mut self, d: Dot) {
        let f = |k: usize, n: usize| {
            let t = (d.at[k] - self.lo[k]) / self.size[k];
            ((t * n as f64).floor() as isize).clamp(0, n as isize - 1) as usize
        };
        let (i, j) = (f(0, self.nx), f(1, self.ny));
        let c = &mut self.cells[j * self.nx + i];
        c.rows += 1;
        c.failed += u32::from(!d.pass);
        if d.ulps.is_finite() {
            c.max = c.max.max(d.ulps);
        } else {
            c.not_finite = true;
        }
    }
}

/// How a map draws: the frame of its box, the reach of the rows (`lo`, `hi`; a row beyond it
/// sits on its edge), the range of the errors and their colour scale.
struct MapView {
    frame: Frame,
    lo: [f64; 2],
    hi: [f64; 2],
    range: Option<(f64, f64)>,
    scale: Option<LogScale>,
}

impl MapView {
    /// The pixel of a row, clamped to the view.
    fn place(&self, p: [f64; 2]) -> [f64; 2] {
        let q = [
            p[0].clamp(self.lo[0], self.hi[0]),
            p[1].clamp(self.lo[1], self.hi[1]),
        ];
        self.frame.px(q)
    }

    /// The colour of an error of `u` ULPs (black when it is not finite).
    fn colour(&self, u: f64) -> Rgb {
        match self.scale {
            Some(s) if u.is_finite() => s.colour(u),
            _ => NOT_FINITE,
        }
    }
}

/// What a panel says besides its rows.
#[derive(Clone, Debug)]
pub struct Panel {
    /// The heading (file, algorithm and precision, …).
    pub title: String,
    /// The largest error the report states (the colour bar's top label; `None`: the rows').
    pub max_ulps: Option<f64>,
    /// The smallest error, computed exactly (the bottom label; `None`: the rows' figures').
    pub min_ulps: Option<f64>,
    /// The worst row: its number, its label's text. Its position is the row's own.
    pub worst: Option<(usize, String)>,
    /// Further rows ringed and labelled (`tribez hunt`'s worst rows): position, label.
    pub labels: Vec<([f64; 2], String)>,
    /// The histogram's counts ([`ULP_BUCKETS`]).
    pub histogram: [u64; 8],
    /// A note under the map.
    pub note: String,
}

/// A number of ULPs for people: `0`, up to 4 decimals from 10^-3 to 10^6, else scientific.
pub fn ulps_text(u: f64) -> String {
    tribez::hunt::ulps_text(u)
}

/// Width of an error map picture, and the height of one panel.
pub const WIDTH: f64 = 980.0;
/// The height of one panel.
pub const PANEL_H: f64 = 520.0;
const MAP_X: f64 = 24.0;
const MAP_Y: f64 = 48.0;
const MAP_W: f64 = 520.0;
const MAP_H: f64 = 400.0;

impl MapData {
    /// The smallest and the largest error (the colour bar's labels): the rows' smallest, and the
    /// report's largest (`max_ulps`) when given.
    pub fn range(&self, max_ulps: Option<f64>, min_ulps: Option<f64>) -> Option<(f64, f64)> {
        let hi = max_ulps
            .filter(|u| u.is_finite())
            .or_else(|| (self.b.max >= self.b.min).then_some(self.b.max))?;
        let lo = min_ulps.filter(|u| u.is_finite()).unwrap_or(self.b.min);
        Some((lo.min(hi), hi))
    }

    /// The position of row `row` if it may be the worst (see [`WorstCandidates`]).
    fn worst_at(&self, row: usize) -> Option<[f64; 2]> {
        self.b.worst.rows.iter().find(|c| c.0 == row).map(|c| c.1)
    }

    /// Draw the panel at vertical offset `y0`.
    pub fn draw(&self, svg: &mut Svg, y0: f64, panel: &Panel, id: &str) {
        let b = &self.b;
        svg.open_group(&[("id", id.to_string()), ("class", "error-map".into())]);
        svg.text([MAP_X, y0 + 26.0], 15.0, "start", INK, &panel.title, &[]);
        let view = self.view(y0, panel);
        svg.rect(
            MAP_X,
            y0 + MAP_Y,
            MAP_W,
            MAP_H,
            Rgb(250, 250, 250),
            Some((Rgb(220, 220, 220), 1.0)),
        );
        let mut attrs: Vec<(&str, String)> = vec![("class", "map".into())];
        attrs.extend(view.frame.attrs());
        svg.open_group(&attrs);
        let outline: Vec<[f64; 2]> = b.outline.iter().map(|&p| view.frame.px(p)).collect();
        svg.polygon(&outline, Rgb(255, 255, 255), Some((OUTLINE, 1.5)));
        self.draw_rows(svg, &view);
        self.draw_marks(svg, &view, panel, id);
        svg.close_group();
        self.draw_legend(svg, y0, panel);
        self.draw_colour_bar(svg, y0, &view);
        // the histogram
        histogram(
            svg,
            MAP_X + MAP_W + 22.0 + 110.0,
            y0 + MAP_Y,
            &panel.histogram,
            "rows",
        );
        svg.close_group();
    }

    /// Where the map of the panel at `y0` draws and how it colours: the rows' reach (or the
    /// grid's) fitted to the map's box, the colour scale of the panel's errors.
    fn view(&self, y0: f64, panel: &Panel) -> MapView {
        let b = &self.b;
        let (lo, hi) = b.grid.as_ref().map_or_else(
            || self.b.limits(),
            |g| (g.lo, [g.lo[0] + g.size[0], g.lo[1] + g.size[1]]),
        );
        let frame = Frame::fit(
            &[lo, hi],
            (MAP_X + 8.0, y0 + MAP_Y + 8.0, MAP_W - 16.0, MAP_H - 16.0),
        );
        let range = self.range(panel.max_ulps, panel.min_ulps);
        // the logarithmic part starts at the smallest error, or at the smallest positive one
        // when some errors are 0
        let scale = range.map(|(lo, hi)| {
            let floor = if lo > 0.0 {
                Some(lo)
            } else {
                b.min_positive.filter(|&f| f <= hi)
            };
            LogScale::new(lo, floor, hi)
        });
        MapView {
            frame,
            lo,
            hi,
            range,
            scale,
        }
    }

    /// The rows: the grid's cells (their largest error), or one dot per row.
    fn draw_rows(&self, svg: &mut Svg, view: &MapView) {
        let b = &self.b;
        if let Some(g) = &b.grid {
            let (cw, ch) = (g.size[0] / g.nx as f64, g.size[1] / g.ny as f64);
            for j in 0..g.ny {
                for i in 0..g.nx {
                    let c = g.cells[j * g.nx + i];
                    if c.rows == 0 {
                        continue;
                    }
                    let corner = view
                        .frame
                        .px([g.lo[0] + i as f64 * cw, g.lo[1] + (j + 1) as f64 * ch]);
                    let fill = if c.not_finite {
                        NOT_FINITE
                    } else {
                        view.colour(c.max)
                    };
                    let stroke = (c.failed > 0).then_some((FAILED, 0.8));
                    svg.rect(
                        corner[0],
                        corner[1],
                        cw * view.frame.s,
                        ch * view.frame.s,
                        fill,
                        stroke,
                    );
                }
            }
        } else {
            let r = if b.dots.len() <= 2_000 { 3.2 } else { 1.8 };
            let mut order: Vec<&Dot> = b.dots.iter().collect();
            // larger errors on top; failed rows above passing ones
            order.sort_by(|x, y| (!x.pass).cmp(&!y.pass).then(x.ulps.total_cmp(&y.ulps)));
            for d in order {
                let p = view.place(d.at);
                let out = !inside(&b.outline, d.at);
                let stroke = if !d.pass {
                    Some((FAILED, 1.4))
                } else if out {
                    Some((OUTLINE, 0.6))
                } else {
                    None
                };
                let rr = if d.pass { r } else { r + 1.2 };
                svg.circle(p, rr, Some(view.colour(d.ulps)), stroke, &[]);
            }
        }
    }

    /// The labelled rows and the worst row, each circled and named.
    fn draw_marks(&self, svg: &mut Svg, view: &MapView, panel: &Panel, id: &str) {
        // further labelled rows
        for (at, label) in &panel.labels {
            let p = view.place(*at);
            svg.circle(
                p,
                7.0,
                None,
                Some((WORST, 1.5)),
                &[("class", "labelled".into())],
            );
            let right = p[0] < MAP_X + MAP_W - 200.0;
            svg.text(
                [if right { p[0] + 10.0 } else { p[0] - 10.0 }, p[1] + 4.0],
                11.0,
                if right { "start" } else { "end" },
                WORST,
                label,
                &[("class", "label".into())],
            );
        }
        // the worst row
        if let Some((row, label)) = &panel.worst
            && let Some(at) = self.worst_at(*row)
        {
            let p = view.place(at);
            let top = view.range.map_or(NOT_FINITE, |(_, hi)| view.colour(hi));
            svg.circle(p, 3.0, Some(top), None, &[]);
            svg.circle(
                p,
                10.0,
                None,
                Some((WORST, 2.5)),
                &[
                    ("id", format!("{id}-worst")),
                    ("class", "worst".into()),
                    ("data-row", row.to_string()),
                ],
            );
            let right = p[0] < MAP_X + MAP_W - 200.0;
            svg.text(
                [if right { p[0] + 14.0 } else { p[0] - 14.0 }, p[1] - 12.0],
                12.0,
                if right { "start" } else { "end" },
                WORST,
                label,
                &[("class", "worst-label".into())],
            );
        }
    }

    /// The legend under the map: the marks' meaning and counts, and the notes.
    fn draw_legend(&self, svg: &mut Svg, y0: f64, panel: &Panel) {
        let b = &self.b;
        let ly = y0 + MAP_Y + MAP_H + 22.0;
        let mut x = MAP_X;
        svg.circle(
            [x + 5.0, ly - 4.0],
            4.5,
            Some(Rgb(255, 255, 255)),
            Some((FAILED, 1.4)),
            &[],
        );
        x += 14.0;
        let failed = format!("failed ({})", b.failed);
        svg.text([x, ly], 12.0, "start", INK, &failed, &[]);
        x += 12.0 + 7.0 * failed.len() as f64;
        svg.circle([x + 6.0, ly - 4.0], 6.0, None, Some((WORST, 2.0)), &[]);
        x += 16.0;
        svg.text([x, ly], 12.0, "start", INK, "worst row", &[]);
        x += 80.0;
        svg.circle(
            [x + 5.0, ly - 4.0],
            4.0,
            Some(Rgb(255, 255, 255)),
            Some((OUTLINE, 0.8)),
            &[],
        );
        x += 14.0;
        svg.text(
            [x, ly],
            12.0,
            "start",
            INK,
            &format!("outside the domain ({})", b.outside),
            &[],
        );
        let mut notes = Vec::new();
        if b.grid.is_some() {
            notes.push(format!(
                "{} rows: each cell shows the largest error in it",
                b.rows
            ));
        }
        if b.unplaced > 0 {
            notes.push(format!(
                "{} rows with a non-finite input not drawn",
                b.unplaced
            ));
        }
        if b.not_finite > 0 {
            notes.push(format!("{} non-finite results in black", b.not_finite));
        }
        if !panel.note.is_empty() {
            notes.push(panel.note.clone());
        }
        svg.text(
            [MAP_X, ly + 20.0],
            11.0,
            "start",
            OUTLINE,
            &notes.join("; "),
            &[],
        );
    }

    /// The colour bar beside the map, with its ends and ticks.
    fn draw_colour_bar(&self, svg: &mut Svg, y0: f64, view: &MapView) {
        let (bx, by, bw, bh) = (MAP_X + MAP_W + 22.0, y0 + MAP_Y + 20.0, 18.0, MAP_H - 40.0);
        svg.text(
            [bx - 4.0, by - 10.0],
            12.0,
            "start",
            INK,
            "error (ulp)",
            &[],
        );
        let steps = 64;
        let spread = view.range.is_some_and(|(lo, hi)| hi > lo);
        for k in 0..steps {
            let t = (k as f64 + 0.5) / steps as f64;
            let y = by + bh - (k as f64 + 1.0) * bh / steps as f64;
            let c = super::colour::map(if spread { t } else { 0.5 });
            svg.rect(bx, y, bw, bh / steps as f64 + 0.5, c, None);
        }
        if let (Some((lo, hi)), Some(s)) = (view.range, view.scale) {
            let label = |svg: &mut Svg, y: f64, v: f64, id: &str| {
                svg.text(
                    [bx + bw + 6.0, y + 4.0],
                    12.0,
                    "start",
                    INK,
                    &ulps_text(v),
                    &[("class", id.into()), ("data-value", format!("{v:?}"))],
                );
            };
            label(svg, by, hi, "scale-max");
            label(svg, by + bh, lo, "scale-min");
            for v in s.ticks() {
                let y = by + bh - s.t(v) * bh;
                if (y - by).abs() > 14.0 && (y - by - bh).abs() > 14.0 {
                    svg.line([bx + bw, y], [bx + bw + 4.0, y], INK, 1.0);
                    let text = if (1e-3..1e6).contains(&v) {
                        ulps_text(v)
                    } else {
                        format!("1e{}", v.log10().round())
                    };
                    svg.text([bx + bw + 6.0, y + 4.0], 10.0, "start", OUTLINE, &text, &[]);
                }
            }
            if s.lo < s.floor {
                svg.text(
                    [bx - 4.0, by + bh + 18.0],
                    10.0,
                    "start",
                    OUTLINE,
                    &format!("0 to {} ulp: bottom colour", ulps_text(s.floor)),
                    &[],
                );
            }
        }
    }
}

/// The histogram of errors in ULPs ([`ULP_BUCKETS`]) with its top left corner at `(hx, top)`:
/// one bar per bucket, its count beside it; `what` names what is counted.
pub fn histogram(svg: &mut Svg, hx: f64, top: f64, counts: &[u64; 8], what: &str) {
    svg.text(
        [hx, top + 10.0],
        12.0,
        "start",
        INK,
        &format!("histogram ({what} per error in ulp)"),
        &[],
    );
    let most = counts.iter().copied().max().unwrap_or(0).max(1);
    let row_h = (MAP_H - 40.0) / 8.0;
    let bar_x = hx + 78.0;
    let bar_w = 156.0;
    svg.open_group(&[("class", "histogram".into())]);
    for (k, (&label, &count)) in ULP_BUCKETS.iter().zip(counts).enumerate() {
        let y = top + 24.0 + k as f64 * row_h;
        svg.text(
            [bar_x - 6.0, y + row_h * 0.5 + 4.0],
            11.0,
            "end",
            INK,
            label,
            &[],
        );
        let w = bar_w * count as f64 / most as f64;
        if count > 0 {
            svg.rect(
                bar_x,
                y + 4.0,
                w.max(1.0),
                row_h - 8.0,
                Rgb(96, 125, 160),
                None,
            );
        }
        svg.text(
            [bar_x + w + 4.0, y + row_h * 0.5 + 4.0],
            11.0,
            "start",
            INK,
            &count.to_string(),
            &[
                ("class", "bucket".into()),
                ("data-count", count.to_string()),
            ],
        );
    }
    svg.close_group();
}

/// An SVG of one or more panels, one under the other.
pub fn svg(panels: &[(MapData, Panel)], title: &str) -> String {
    let height = PANEL_H * panels.len().max(1) as f64;
    let mut svg = Svg::new(WIDTH, height, &[]);
    svg.title(title);
    for (i, (data, panel)) in panels.iter().enumerate() {
        data.draw(
            &mut svg,
            i as f64 * PANEL_H,
            panel,
            &format!("map{}", i + 1),
        );
    }
    svg.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inside_a_triangle_either_way_round() {
        let t = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let r = [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]];
        for o in [&t[..], &r[..]] {
            assert!(inside(o, [0.2, 0.2]));
            assert!(inside(o, [0.5, 0.5]));
            assert!(!inside(o, [0.6, 0.6]));
            assert!(!inside(o, [-0.1, 0.2]));
        }
    }

    #[test]
    fn past_the_dots_rows_fall_into_cells_and_the_worst_is_found() {
        let mut b = MapBuilder::new(vec![[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]);
        let n = MAX_DOTS + 10;
        for i in 0..n {
            let t = i as f64 / n as f64;
            let u = if i == 7 { 100.0 } else { t };
            b.add(i + 1, [t * 0.5, 0.25], u, u, i != 7);
        }
        let m = b.finish();
        assert!(m.b.grid.is_some() && m.b.dots.is_empty());
        assert_eq!(m.b.rows, n as u64);
        assert_eq!(m.worst_at(8), Some([7.0 / n as f64 * 0.5, 0.25]));
        assert_eq!(m.range(None, None), Some((0.0, 100.0)));
        assert_eq!(m.range(Some(90.0), Some(0.5)), Some((0.5, 90.0)));
        let cells = m.b.grid.as_ref().unwrap().cells.iter();
        assert_eq!(cells.map(|c| u64::from(c.rows)).sum::<u64>(), n as u64);
    }

    #[test]
    fn ulps_read_like_the_reports() {
        assert_eq!(ulps_text(0.0), "0");
        assert_eq!(ulps_text(3.0), "3");
        assert_eq!(ulps_text(0.5), "0.5");
        assert_eq!(ulps_text(1.0 / 3.0), "0.3333");
        assert_eq!(ulps_text(2.5e-7), "2.500e-7");
    }
}
