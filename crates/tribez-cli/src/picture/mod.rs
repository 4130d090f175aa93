//! Pictures: patches with their control nets (`tribez plot`), error maps (`--plot` on `check`
//! and `certify`) and the self-contained HTML report (`--html`).
//!
//! Every picture is SVG written directly ([`svg`]); a `.png` file is that SVG rasterised by
//! resvg (pure Rust). Geometry is sampled from exact values and converted to `f64` only to be
//! drawn. Files are written like every output of the command line: staged, and committed only
//! when the run ends with exit status 0 or 1 ([`crate::output`]).

pub mod colour;
pub mod errmap;
pub mod html;
pub mod patch;
pub mod project;
pub mod reports;
pub mod svg;

use std::path::Path;

use crate::error::CliError;

/// The file formats of pictures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PictureFormat {
    /// SVG (text).
    Svg,
    /// PNG (the SVG rasterised).
    Png,
}

/// The format a picture file's name asks for (`.svg` or `.png`, any case); `flag` names the
/// option in the error.
pub fn format_of(path: &Path, flag: &str) -> Result<PictureFormat, CliError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("svg") => Ok(PictureFormat::Svg),
        Some("png") => Ok(PictureFormat::Png),
        other => Err(CliError::check(
            path.display().to_string(),
            format!(
                "{flag}: unknown picture format {} (give a file name ending in .svg or .png)",
                other.map_or("(no extension)".to_string(), |e| format!("`.{e}`"))
            ),
        )),
    }
}

/// `--html FILE` must name an `.html` or `.htm` file.
pub fn check_html_name(path: &Path) -> Result<(), CliError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("html" | "htm") => Ok(()),
        _ => Err(CliError::check(
            path.display().to_string(),
            "--html: give a file name ending in .html (one self-contained HTML file)",
        )),
    }
}

/// The SVG rasterised (resvg) at `zoom` times its size: premultiplied RGBA pixels.
pub fn rasterise(svg: &str, zoom: f32, fonts: bool) -> Result<resvg::tiny_skia::Pixmap, String> {
    let mut options = resvg::usvg::Options::default();
    if fonts {
        options.fontdb_mut().load_system_fonts();
    }
    let tree = resvg::usvg::Tree::from_str(svg, &options).map_err(|e| e.to_string())?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(zoom)
        .ok_or("empty picture")?;
    let mut pixmap =
        resvg::tiny_skia::Pixmap::new(size.width(), size.height()).ok_or("picture too large")?;
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(zoom, zoom),
        &mut pixmap.as_mut(),
    );
    Ok(pixmap)
}

/// Stage the picture `svg` as `path` in the format its name asks for (PNG: rasterised at twice
/// the size, with the system's fonts for the text).
pub fn stage(path: &Path, svg: &str, flag: &str) -> Result<(), CliError> {
    let file = path.display().to_string();
    let bytes = match format_of(path, flag)? {
        PictureFormat::Svg => svg.as_bytes().to_vec(),
        PictureFormat::Png => rasterise(svg, 2.0, true)
            .and_then(|p| p.encode_png().map_err(|e| e.to_string()))
            .map_err(|e| CliError::check(&file, format!("cannot draw the picture: {e}")))?,
    };
    crate::output::stage(path, &bytes)
}
