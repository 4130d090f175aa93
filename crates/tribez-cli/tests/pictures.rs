//! Pictures (issue 15): `tribez plot`, `--plot` error maps and `--html` reports on `check` and
//! `certify`. Every picture is rasterised (resvg) and judged by its pixels: not blank, the
//! control net's colour at the pixels where the test itself projects the control points (the
//! projection documented in `picture/project.rs`, with the frame the picture states), the worst
//! row's ring where the test itself places that row, the colour bar's end labels equal to the
//! smallest and largest error derived by hand; every SVG and HTML parses as XML, the HTML
//! references nothing outside itself; bad input is one line and exit status 2, leaving no file.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use resvg::tiny_skia::Pixmap;

mod common;
use common::{fails, fixtures, listing, tribez};

/// Exit status 2, nothing on standard output, one line on standard error: that line.
fn fails_exit_2(cmd: &mut Command) -> String {
    fails(cmd, &[])
}

/// The control net's colour (`picture::patch::NET`).
const NET: [u8; 3] = [220, 38, 127];

fn rasterise(svg: &str) -> Pixmap {
    let tree = resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default()).unwrap();
    let size = tree.size().to_int_size();
    let mut pixmap = Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    pixmap
}

fn pixel(p: &Pixmap, x: f64, y: f64) -> [u8; 3] {
    let c = p
        .pixel(x.round() as u32, y.round() as u32)
        .unwrap_or_else(|| panic!("({x}, {y}) outside the picture"))
        .demultiply();
    [c.red(), c.green(), c.blue()]
}

fn near(a: [u8; 3], b: [u8; 3], tolerance: i32) -> bool {
    (0..3).all(|k| (i32::from(a[k]) - i32::from(b[k])).abs() <= tolerance)
}

/// Not blank: many colours, and most of the picture is not the background.
fn assert_not_blank(p: &Pixmap, min_ink: usize) {
    let mut colours = std::collections::HashSet::new();
    let mut ink = 0;
    for c in p.pixels() {
        let c = c.demultiply();
        colours.insert([c.red(), c.green(), c.blue()]);
        if c.red() < 240 || c.green() < 240 || c.blue() < 240 {
            ink += 1;
        }
    }
    assert!(colours.len() > 30, "{} colours", colours.len());
    assert!(ink >= min_ink, "{ink} pixels drawn");
}

/// The picture coordinates of `x` seen from azimuth `a` and elevation `e` (degrees): the
/// viewer looks from `(cos e cos a, cos e sin a, sin e)`; right is `(−sin a, cos a, 0)`, up is
/// `(−sin e cos a, −sin e sin a, cos e)`.
fn project((a, e): (f64, f64), x: [f64; 3]) -> [f64; 2] {
    let (a, e) = (a.to_radians(), e.to_radians());
    let right = [-a.sin(), a.cos(), 0.0];
    let up = [-e.sin() * a.cos(), -e.sin() * a.sin(), e.cos()];
    let dot = |u: [f64; 3]| u[0] * x[0] + u[1] * x[1] + u[2] * x[2];
    [dot(right), dot(up)]
}

/// The frame a group states: pixel = (ox + s·p, oy − s·q).
fn frame(node: roxmltree::Node<'_, '_>) -> (f64, f64, f64) {
    let origin: Vec<f64> = node
        .attribute("data-origin")
        .unwrap()
        .split(' ')
        .map(|t| t.parse().unwrap())
        .collect();
    let s: f64 = node.attribute("data-scale").unwrap().parse().unwrap();
    (origin[0], origin[1], s)
}

fn to_pixel((ox, oy, s): (f64, f64, f64), p: [f64; 2]) -> [f64; 2] {
    [ox + s * p[0], oy - s * p[1]]
}

/// Run `tribez plot FILE -o out.svg ARGS` and check the control points `points` (the test's own
/// copy of the fixture's numbers, as picture points in R^3) are drawn in the net's colour.
fn plot_shows_net(file: &str, args: &[&str], points: &[[f64; 3]]) -> String {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p.svg");
    tribez()
        .arg("plot")
        .arg(fixtures().join(file))
        .arg("-o")
        .arg(&out)
        .args(args)
        .assert()
        .code(0);
    let svg = std::fs::read_to_string(&out).unwrap();
    let doc = roxmltree::Document::parse(&svg).expect("the SVG parses as XML");
    let plot = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("plot"))
        .expect("the plot group");
    let view: Vec<f64> = plot
        .attribute("data-view")
        .unwrap()
        .split(' ')
        .map(|t| t.parse().unwrap())
        .collect();
    let f = frame(plot);
    let pixmap = rasterise(&svg);
    assert_not_blank(&pixmap, 5_000);
    for p in points {
        let [x, y] = to_pixel(f, project((view[0], view[1]), *p));
        let c = pixel(&pixmap, x, y);
        assert!(near(c, NET, 40), "{file}: {p:?} at ({x}, {y}) is {c:?}");
    }
    svg
}

#[test]
fn a_surface_is_shaded_with_its_net_at_the_projected_control_points() {
    // Finn's worked example: p200 = (0,0,0), p110 = (1,0,2), p020 = (0,2,0), p101 = (0,1,0),
    // p011 = (1,1,1), p002 = (0,2,1)
    let net = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 2.0],
        [0.0, 2.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 1.0],
        [0.0, 2.0, 1.0],
    ];
    for view in ["30,20", "-60,30", "-150,-10"] {
        let svg = plot_shows_net("finn_day30.toml", &["--view", view], &net);
        // the surface is shaded: many triangles of several shades
        let pixmap = rasterise(&svg);
        let shades: std::collections::HashSet<[u8; 3]> = pixmap
            .pixels()
            .iter()
            .map(|c| {
                let c = c.demultiply();
                [c.red(), c.green(), c.blue()]
            })
            .filter(|c| i32::from(c[2]) > i32::from(c[0]) + 30)
            .collect();
        assert!(shades.len() > 20, "{view}: {} blue shades", shades.len());
    }
}

#[test]
fn every_kind_is_drawn_with_its_net() {
    // a curve in the plane: its control polygon (0,0), (1,2), (3,3), (4,0)
    let curve = plot_shows_net(
        "beyond/cubic_curve.toml",
        &[],
        &[
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 0.0],
            [3.0, 3.0, 0.0],
            [4.0, 0.0, 0.0],
        ],
    );
    assert!(curve.contains("<polyline"), "the curve is drawn");
    // a functional patch over (1,1), (5,2), (2,6): its graph; the corners' ordinates 3/2, -6, 2
    plot_shows_net(
        "beyond/functional_linear.toml",
        &["--view", "-60,30"],
        &[[1.0, 1.0, 1.5], [5.0, 2.0, -6.0], [2.0, 6.0, 2.0]],
    );
    // a rational patch (the sphere octant): its corner control points
    plot_shows_net(
        "beyond/octant_quartic.toml",
        &["--view", "45,35"],
        &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    );
    // an S-patch over a pentagon: its corner control points
    plot_shows_net(
        "beyond/pentagon_depth2.toml",
        &["--view", "-60,30"],
        &[
            [2.0, 1.0, 0.0],
            [4.0 / 3.0, 1.0 / 3.0, 0.0],
            [-2.0, 1.0, -2.0],
            [0.0, 3.0, 0.0],
            [0.0, -1.0, 0.0],
        ],
    );
}

#[test]
fn a_planar_patch_shows_iso_parameter_lines_and_labels() {
    let dir = tempfile::tempdir().unwrap();
    let patch = dir.path().join("planar.toml");
    // a quadratic in the plane: corners (0,0), (4,0), (0,4); the middle points pulled about
    std::fs::write(
        &patch,
        r#"degree = 2
[control_points]
"2,0,0" = ["0", "0"]
"1,1,0" = ["2", "-1"]
"0,2,0" = ["4", "0"]
"1,0,1" = ["-1", "2"]
"0,1,1" = ["2", "2"]
"0,0,2" = ["0", "4"]
"#,
    )
    .unwrap();
    let out = dir.path().join("planar.svg");
    tribez()
        .arg("plot")
        .arg(&patch)
        .arg("-o")
        .arg(&out)
        .arg("--labels")
        .assert()
        .code(0);
    let svg = std::fs::read_to_string(&out).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let iso = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("iso-lines"))
        .unwrap();
    // 9 levels of each of the three barycentric coordinates
    assert_eq!(
        iso.children()
            .filter(|n| n.has_tag_name("polyline"))
            .count(),
        27
    );
    let labels: Vec<&str> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("net-label"))
        .filter_map(|n| n.text())
        .collect();
    assert_eq!(labels, ["(2,0,0)", "(0,2,0)", "(0,0,2)"]);
    let plot = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("plot"))
        .unwrap();
    let f = frame(plot);
    let pixmap = rasterise(&svg);
    for p in [
        [0.0, 0.0],
        [2.0, -1.0],
        [4.0, 0.0],
        [-1.0, 2.0],
        [2.0, 2.0],
        [0.0, 4.0],
    ] {
        let [x, y] = to_pixel(f, p);
        assert!(near(pixel(&pixmap, x, y), NET, 40), "{p:?}");
    }
    // the image of the domain is filled: the centroid's image b(1/3,1/3,1/3) = (1, 7/9)
    let [x, y] = to_pixel(f, [1.0, 7.0 / 9.0]);
    let c = pixel(&pixmap, x, y);
    assert!(c != [255, 255, 255], "{c:?}");
}

#[test]
fn png_pictures_are_the_svg_rasterised_at_twice_the_size() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("finn.PNG");
    tribez()
        .arg("plot")
        .arg(fixtures().join("finn_day30.toml"))
        .arg("-o")
        .arg(&out)
        .assert()
        .code(0);
    let png = Pixmap::decode_png(&std::fs::read(&out).unwrap()).expect("a PNG");
    assert_eq!((png.width(), png.height()), (1600, 1280));
    assert_not_blank(&png, 20_000);
}

/// The hand-made batch: the patch f(u, v, w) = 4u + 8v (degree 1, d = 1) and five rows whose
/// errors are known by hand (the claimed values are the exact value plus k ulps, written in
/// hexadecimal: ulp(4) = 2^-50, ulp(3) = 2^-51, ulp(1.5) = 2^-52):
///
/// | line | (u, v, w)          | exact | claimed                 | error   |
/// |------|--------------------|-------|-------------------------|---------|
/// | 1    | (1/2, 1/4, 1/4)    | 4     | 4                       | 0       |
/// | 2    | (1/4, 1/4, 1/2)    | 3     | 0x1.8000000000003p+1    | 3 ulps  |
/// | 3    | (1/8, 1/8, 3/4)    | 3/2   | 0x1.8000000000001p+0    | 1 ulp   |
/// | 4    | (0, 1/2, 1/2)      | 4     | 0x1.0000000000005p+2    | 5 ulps  |
/// | 5    | (-1/4, 1/2, 3/4)   | 3     | 3                       | 0 (outside the triangle) |
///
/// With `ulps=2`, lines 2 and 4 fail; line 4 is the worst (5 ulps); the smallest error is 0.
fn hand_batch(dir: &Path) -> (PathBuf, PathBuf) {
    let patch = dir.join("linear.toml");
    std::fs::write(
        &patch,
        "degree = 1\n[control_points]\n\"1,0,0\" = [\"4\"]\n\"0,1,0\" = [\"8\"]\n\"0,0,1\" = [\"0\"]\n",
    )
    .unwrap();
    let results = dir.join("results.csv");
    std::fs::write(
        &results,
        "0.5,0.25,0.25,4\n\
         0.25,0.25,0.5,0x1.8000000000003p+1\n\
         0.125,0.125,0.75,0x1.8000000000001p+0\n\
         0,0.5,0.5,0x1.0000000000005p+2\n\
         -0.25,0.5,0.75,3\n",
    )
    .unwrap();
    (patch, results)
}

#[test]
fn the_error_map_marks_the_worst_and_failed_rows_and_labels_the_scale_by_hand() {
    let dir = tempfile::tempdir().unwrap();
    let (patch, results) = hand_batch(dir.path());
    let map = dir.path().join("map.svg");
    let html = dir.path().join("report.html");
    let out = tribez()
        .args(["check", "--patch"])
        .arg(&patch)
        .arg("--results")
        .arg(&results)
        .args([
            "--precision",
            "f64",
            "--tolerance",
            "ulps=2",
            "--format",
            "json",
        ])
        .arg("--plot")
        .arg(&map)
        .arg("--html")
        .arg(&html)
        .assert()
        .code(1)
        .get_output()
        .stdout
        .clone();
    let json: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(json["summary"]["failed"], 2, "{json}");
    let svg = std::fs::read_to_string(&map).unwrap();
    let doc = roxmltree::Document::parse(&svg).expect("the SVG parses as XML");
    let label = |class: &str| {
        let n = doc
            .descendants()
            .find(|n| n.attribute("class") == Some(class))
            .unwrap_or_else(|| panic!("{class}"));
        (
            n.attribute("data-value").unwrap().parse::<f64>().unwrap(),
            n.text().unwrap().to_string(),
        )
    };
    assert_eq!(label("scale-max"), (5.0, "5".to_string()));
    assert_eq!(label("scale-min"), (0.0, "0".to_string()));
    let worst = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("worst"))
        .unwrap();
    assert_eq!(worst.attribute("data-row"), Some("4"));
    let f = frame(
        doc.descendants()
            .find(|n| n.attribute("class") == Some("map"))
            .unwrap(),
    );
    let pixmap = rasterise(&svg);
    assert_not_blank(&pixmap, 5_000);
    // line 4 at (u, v, w) = (0, 1/2, 1/2): on the reference triangle (1,0), (0,1), (0,0) the
    // point (x, y) = (u, v) = (0, 1/2); its ring (radius 10) is black
    let [cx, cy] = to_pixel(f, [0.0, 0.5]);
    let dark = [(10.0, 0.0), (-10.0, 0.0), (0.0, 10.0), (0.0, -10.0)]
        .iter()
        .filter(|(dx, dy)| pixel(&pixmap, cx + dx, cy + dy).iter().all(|&c| c < 90))
        .count();
    assert!(
        dark >= 3,
        "the worst row's ring at ({cx}, {cy}): {dark} of 4"
    );
    // line 2 failed, at (1/4, 1/4): a red ring around its dot
    let [fx, fy] = to_pixel(f, [0.25, 0.25]);
    let red = (0..16)
        .map(|k| f64::from(k) * std::f64::consts::PI / 8.0)
        .filter(|t| {
            let c = pixel(&pixmap, fx + 4.4 * t.cos(), fy + 4.4 * t.sin());
            c[0] > 170 && c[1] < 110 && c[2] < 110
        })
        .count();
    assert!(red >= 4, "the failed row's ring: {red} of 16 red");
    // line 5 lies outside the triangle, drawn where it is: (x, y) = (-1/4, 1/2)
    let [ox, oy] = to_pixel(f, [-0.25, 0.5]);
    assert!(pixel(&pixmap, ox, oy) != [255, 255, 255]);
    assert!(svg.contains("outside the domain (1)"));

    // the HTML report
    let page = std::fs::read_to_string(&html).unwrap();
    assert_self_contained(&page);
    let doc = parse_html(&page);
    let summary = |key: &str| {
        doc.descendants()
            .find(|n| n.has_tag_name("th") && n.text() == Some(key))
            .and_then(|th| th.next_sibling_element())
            .and_then(|td| td.text())
            .unwrap_or_else(|| panic!("{key}"))
            .to_string()
    };
    assert_eq!(summary("smallest error (ulp)"), "0");
    assert_eq!(summary("largest error (ulp)"), "5");
    assert_eq!(summary("failed"), "2");
    let reproduce = doc
        .descendants()
        .find(|n| n.attribute("id") == Some("reproduce"))
        .unwrap();
    let command: String = reproduce.descendants().filter_map(|n| n.text()).collect();
    assert!(
        command.starts_with("tribez check --patch ")
            && command.ends_with("--tolerance ulps=2 --precision f64"),
        "{command}"
    );
    assert!(
        doc.descendants().any(|n| n.tag_name().name() == "svg"
            && n.tag_name().namespace() == Some("http://www.w3.org/2000/svg")),
        "the error map is inline SVG"
    );
    let cells: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("td"))
        .filter_map(|n| n.text())
        .collect();
    // the worst row's exact value (4) and claimed value in hexadecimal
    assert!(
        cells.iter().any(|c| c.contains("0x1.0000000000005p+2")),
        "{cells:?}"
    );
    assert!(cells.contains(&"4"), "{cells:?}");
    assert!(page.contains("Failures (2 of 2)"));
}

/// The HTML report parsed as XML (its one declaration, `<!DOCTYPE html>`, allowed).
fn parse_html(page: &str) -> roxmltree::Document<'_> {
    let options = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    roxmltree::Document::parse_with_options(page, options).expect("the HTML parses as XML")
}

/// The page references nothing outside itself and runs no script.
fn assert_self_contained(page: &str) {
    let doc = parse_html(page);
    for n in doc.descendants() {
        assert!(!n.has_tag_name("script") && !n.has_tag_name("link") && !n.has_tag_name("img"));
        for a in n.attributes() {
            let name = a.name();
            assert!(!name.starts_with("on"), "event handler {name}");
            if matches!(
                name,
                "src" | "href" | "action" | "data" | "srcset" | "poster"
            ) {
                assert!(a.value().starts_with('#'), "{name}={}", a.value());
            }
        }
    }
    assert!(!page.contains("url(") && !page.contains("@import"));
}

#[test]
fn certify_draws_one_map_per_run_with_the_reports_largest_error() {
    let dir = tempfile::tempdir().unwrap();
    let map = dir.path().join("c.svg");
    let html = dir.path().join("c.html");
    let out = tribez()
        .arg("certify")
        .arg(fixtures().join("certify/finn_quadratic.toml"))
        .args([
            "--random",
            "400",
            "--seed",
            "5",
            "--format",
            "json",
            "--precision",
            "f64",
        ])
        .arg("--plot")
        .arg(&map)
        .arg("--html")
        .arg(&html)
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let json: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let runs = json["results"].as_array().unwrap();
    assert_eq!(runs.len(), 2, "de Casteljau and Bernstein in f64");
    let svg = std::fs::read_to_string(&map).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let maps: Vec<_> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("error-map"))
        .collect();
    assert_eq!(maps.len(), 2);
    let pixmap = rasterise(&svg);
    for (m, run) in maps.iter().zip(runs) {
        let top = m
            .descendants()
            .find(|n| n.attribute("class") == Some("scale-max"))
            .unwrap();
        let max: f64 = top.attribute("data-value").unwrap().parse().unwrap();
        assert_eq!(max, run["max_ulps"].as_f64().unwrap());
        let bottom = m
            .descendants()
            .find(|n| n.attribute("class") == Some("scale-min"))
            .unwrap();
        let min: f64 = bottom.attribute("data-value").unwrap().parse().unwrap();
        assert!(0.0 <= min && min <= max);
        // the worst point, where the test places it: the report's exact point on the reference
        // triangle (x, y) = (u, v) / (u + v + w)
        let point: Vec<f64> = run["worst_point"]
            .as_array()
            .unwrap()
            .iter()
            .map(|q| {
                let t = q.as_str().unwrap();
                match t.split_once('/') {
                    Some((a, b)) => a.parse::<f64>().unwrap() / b.parse::<f64>().unwrap(),
                    None => t.parse().unwrap(),
                }
            })
            .collect();
        let total: f64 = point.iter().sum();
        let f = frame(
            m.descendants()
                .find(|n| n.attribute("class") == Some("map"))
                .unwrap(),
        );
        let [cx, cy] = to_pixel(f, [point[0] / total, point[1] / total]);
        let dark = [(10.0, 0.0), (-10.0, 0.0), (0.0, 10.0), (0.0, -10.0)]
            .iter()
            .filter(|(dx, dy)| pixel(&pixmap, cx + dx, cy + dy).iter().all(|&c| c < 90))
            .count();
        assert!(
            dark >= 3,
            "the worst point's ring at ({cx}, {cy}): {dark} of 4"
        );
    }
    let page = std::fs::read_to_string(&html).unwrap();
    assert_self_contained(&page);
    assert!(page.contains("tribez certify "), "the command to reproduce");
}

#[test]
fn bad_plot_arguments_are_one_line_and_exit_2_leaving_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let finn = fixtures().join("finn_day30.toml");
    let cases: [(&[&str], &str); 9] = [
        (&["-o", "p.jpg"], "unknown picture format `.jpg`"),
        (&["-o", "p"], "(no extension)"),
        (&["-o", "p.svg", "--view", "10"], "AZIMUTH,ELEVATION"),
        (&["-o", "p.svg", "--view", "0,95"], "from -90 to 90"),
        (&["-o", "p.svg", "--view", "x,1"], "AZIMUTH,ELEVATION"),
        (&["-o", "p.svg", "--samples", "0"], "from 1 to 256"),
        (&["-o", "p.svg", "--samples", "257"], "from 1 to 256"),
        (&["-o", "p.svg", "--samples", "-4"], "from 1 to 256"),
        (&["-o", "p.svg", "--labels", "some"], "some"),
    ];
    for (args, want) in cases {
        let err = fails_exit_2(
            tribez()
                .current_dir(dir.path())
                .arg("plot")
                .arg(&finn)
                .args(args),
        );
        assert!(err.contains(want), "{args:?}: {err}");
    }
    // a tetrahedron, and points in R^4, cannot be drawn
    let tetra = fixtures().join("beyond/tetra_quadratic.toml");
    let err = fails_exit_2(
        tribez()
            .current_dir(dir.path())
            .arg("plot")
            .arg(&tetra)
            .args(["-o", "t.svg"]),
    );
    assert!(err.contains("3-simplex"), "{err}");
    let r4 = dir.path().join("r4.toml");
    std::fs::write(
        &r4,
        "degree = 1\n[control_points]\n\"1,0,0\" = [\"0\",\"0\",\"0\",\"0\"]\n\"0,1,0\" = [\"1\",\"0\",\"0\",\"0\"]\n\"0,0,1\" = [\"0\",\"1\",\"0\",\"1\"]\n",
    )
    .unwrap();
    let err = fails_exit_2(
        tribez()
            .current_dir(dir.path())
            .arg("plot")
            .arg(&r4)
            .args(["-o", "t.svg"]),
    );
    assert!(err.contains("in 4"), "{err}");
    assert_eq!(listing(dir.path()), ["r4.toml"]);
}

#[test]
fn bad_plot_and_html_options_of_check_and_certify_are_exit_2_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let (patch, results) = hand_batch(dir.path());
    let batch = |extra: &[&str]| {
        let mut c = tribez();
        c.current_dir(dir.path())
            .args(["check", "--patch"])
            .arg(&patch)
            .arg("--results")
            .arg(&results)
            .args(["--precision", "f64"])
            .args(extra);
        c
    };
    for (extra, want) in [
        (
            &["--plot", "m.txt", "--html", "r.html"][..],
            "unknown picture format `.txt`",
        ),
        (&["--plot", "m.svg", "--html", "r.txt"][..], "--html"),
        // a baseline that is not one
        (
            &[
                "--plot",
                "m.svg",
                "--html",
                "r.html",
                "--baseline",
                "linear.toml",
            ][..],
            "linear.toml",
        ),
        // the pictures are staged, then recording the baseline fails: nothing is written
        (
            &[
                "--tolerance",
                "ulps=8",
                "--plot",
                "m.svg",
                "--html",
                "r.html",
                "--record-baseline",
                ".",
            ][..],
            "not a file name",
        ),
    ] {
        let err = fails_exit_2(&mut batch(extra));
        assert!(err.contains(want), "{extra:?}: {err}");
    }
    let err = fails_exit_2(
        tribez()
            .current_dir(dir.path())
            .arg("check")
            .arg(fixtures().join("finn_day30.claims.toml"))
            .args(["--plot", "m.svg"]),
    );
    assert!(
        err.contains("--plot draws the error map of a batch"),
        "{err}"
    );
    let err = fails_exit_2(
        tribez()
            .current_dir(dir.path())
            .arg("certify")
            .arg(fixtures().join("beyond/tetra_quadratic.toml"))
            .args(["--random", "10", "--plot", "m.svg"]),
    );
    assert!(err.contains("triangles and polygons"), "{err}");
    let err = fails_exit_2(
        tribez()
            .current_dir(dir.path())
            .arg("certify")
            .arg(fixtures().join("finn_day30.toml"))
            .args(["--random", "10", "--html", "r.svg"]),
    );
    assert!(err.contains("--html"), "{err}");
    assert_eq!(listing(dir.path()), ["linear.toml", "results.csv"]);
}

#[test]
fn the_readme_pictures_are_made_by_the_commands_it_shows() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let joined = readme.replace("\\\n", " ");
    let commands: Vec<&str> = joined
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("tribez ") && l.contains("docs/pictures/"))
        .collect();
    assert_eq!(commands.len(), 2, "{commands:?}");
    let dir = tempfile::tempdir().unwrap();
    for command in commands {
        let mut args: Vec<String> = command
            .split_whitespace()
            .skip(1)
            .map(String::from)
            .collect();
        let at = args
            .iter()
            .position(|a| a.starts_with("docs/pictures/"))
            .unwrap();
        let committed = root.join(&args[at]);
        let fresh = dir.path().join(committed.file_name().unwrap());
        args[at] = fresh.display().to_string();
        let out = tribez().current_dir(&root).args(&args).output().unwrap();
        assert!(matches!(out.status.code(), Some(0 | 1)), "{command}");
        assert!(
            std::fs::read(&fresh).unwrap() == std::fs::read(&committed).unwrap(),
            "{} is not what `{command}` draws now: run it from the repository root",
            committed.display()
        );
    }
}

#[test]
fn claim_files_get_an_html_report_with_their_errata() {
    let dir = tempfile::tempdir().unwrap();
    let html = dir.path().join("claims.html");
    tribez()
        .arg("check")
        .arg(fixtures().join("finn_day30.claims.toml"))
        .arg("--html")
        .arg(&html)
        .assert()
        .code(0);
    let page = std::fs::read_to_string(&html).unwrap();
    assert_self_contained(&page);
    let doc = parse_html(&page);
    let cell = |key: &str| {
        doc.descendants()
            .find(|n| n.has_tag_name("th") && n.text() == Some(key))
            .and_then(|th| th.next_sibling_element())
            .and_then(|td| td.text())
            .unwrap_or_else(|| panic!("{key}"))
            .to_string()
    };
    assert_eq!(cell("failed"), "0");
    // Finn's notes print the first component of example (b)'s closed form wrongly
    // (README, "Reproduce a textbook"): a known erratum, listed with its exact value
    assert_ne!(cell("known errata"), "0");
    let cells: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("td"))
        .filter_map(|n| n.text())
        .collect();
    assert!(cells.contains(&"worked-example-b-x"), "{cells:?}");
}

/// The colour bar of `bezier`'s results: its ends are the smallest and the largest error of the
/// 2,000 rows, computed independently by fixtures/peers/exact_errors.py (plain Python fractions):
/// line 1319 at 0.00096857501577748387 ulp and line 417 at 320.7 ulp. The smallest is exact even
/// though the float filter decided that row (its figure in the histogram is an upper bound).
#[test]
fn the_colour_bar_of_the_bezier_results_ends_at_their_exact_smallest_and_largest_errors() {
    let dir = tempfile::tempdir().unwrap();
    let map = dir.path().join("bezier.svg");
    let peers = fixtures().join("peers");
    tribez()
        .args(["check", "--patch"])
        .arg(peers.join("peer_cubic.toml"))
        .arg("--results")
        .arg(peers.join("bezier_results.csv"))
        .args(["--precision", "f64", "--tolerance", "cond=9", "--plot"])
        .arg(&map)
        .assert()
        .code(0);
    let svg = std::fs::read_to_string(&map).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let value = |class: &str| -> f64 {
        doc.descendants()
            .find(|n| n.attribute("class") == Some(class))
            .and_then(|n| n.attribute("data-value"))
            .unwrap()
            .parse()
            .unwrap()
    };
    // the f64 nearest the script's 20 digits
    let smallest: f64 = "0.00096857501577748387".parse().unwrap();
    assert_eq!(value("scale-min"), smallest);
    assert!((value("scale-max") - 320.7).abs() < 0.05);
    let worst = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("worst"))
        .unwrap();
    assert_eq!(worst.attribute("data-row"), Some("417"));
}
