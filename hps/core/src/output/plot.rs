//! PNG plots for the loop reports: residual against a variable (scatter), time series (lines)
//! and grouped bars (an error per sensor before / after / baseline).
//!
//! Plotters draws with its bitmap backend and pure-Rust PNG encoder. Text goes through
//! ab_glyph with a TrueType font read at run time from a standard system path
//! ([`FONT_PATHS`]); without one, the same plots are drawn without any text (no title, axis
//! labels or legend) and [`PlotOutcome::text`] says so. Nothing here panics on any data:
//! non-finite and absurdly large values are skipped and counted, empty and constant data get
//! a default range, and every failure is a [`PlotError`].

use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// Where a sans-serif TrueType font is looked for, in order (Debian/Ubuntu, Fedora, Arch,
/// Alpine, then Liberation as a stand-in). `SKYLUX_PLOT_FONT` overrides the list.
pub const FONT_PATHS: &[&str] = &[
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",
];

/// The family name the loaded font is registered under. A plot drawn without text never
/// names a family, so a stray text call without a font fails loudly instead of silently.
const FAMILY: &str = "skylux-sans";

/// Values beyond this magnitude are not plotted (skipped and counted): plotters' axis
/// arithmetic is in f64 and pixel casts, and such a value is a fault, not data to look at.
pub const MAX_PLOTTABLE: f64 = 1e12;

/// Whether a plot may draw text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Text {
    /// Text if a system font is found, else none.
    Auto,
    /// No text at all.
    Off,
}

/// Size and words of one plot.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub width_px: u32,
    pub height_px: u32,
    pub text: Text,
}

impl Frame {
    /// An 800x500 frame with text if a font is found.
    pub fn new(title: &str, x_label: &str, y_label: &str) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            width_px: 800,
            height_px: 500,
            text: Text::Auto,
        }
    }
}

/// One labelled set of points.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// One group of bars: a label and one value per series (`None`: no bar).
#[derive(Clone, Debug, PartialEq)]
pub struct BarGroup {
    pub label: String,
    pub values: Vec<Option<f64>>,
}

/// What was drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlotOutcome {
    /// Whether text (title, axes, legend) was drawn.
    pub text: bool,
    /// Points or bars drawn.
    pub drawn: usize,
    /// Points or bars skipped: non-finite or beyond [`MAX_PLOTTABLE`].
    pub skipped: usize,
}

/// Why a plot could not be written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    #[error("plot {path}: size {width_px}x{height_px} px is outside 64..=8192 on each side")]
    Size {
        path: PathBuf,
        width_px: u32,
        height_px: u32,
    },
    #[error("plot {path}: {message}")]
    Draw { path: PathBuf, message: String },
}

/// Loads and registers the system font once per process; whether one is available.
fn system_font() -> bool {
    static LOADED: OnceLock<bool> = OnceLock::new();
    *LOADED.get_or_init(|| {
        let candidates: Vec<PathBuf> = match std::env::var_os("SKYLUX_PLOT_FONT") {
            Some(p) => vec![PathBuf::from(p)],
            None => FONT_PATHS.iter().map(PathBuf::from).collect(),
        };
        for path in candidates {
            if let Ok(bytes) = std::fs::read(&path) {
                // Plotters keeps fonts for the whole process as `&'static`: one leak, once.
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                if plotters::style::register_font(FAMILY, FontStyle::Normal, bytes).is_ok() {
                    return true;
                }
            }
        }
        false
    })
}

fn plottable(v: f64) -> bool {
    v.is_finite() && v.abs() <= MAX_PLOTTABLE
}

/// A padded range over `values`; (0, 1) when empty, widened when constant.
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if lo > hi {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    let pad = if span > 0.0 {
        0.05 * span
    } else {
        (0.05 * lo.abs()).max(0.5)
    };
    (lo - pad, hi + pad)
}

/// Series colours, distinguishable in print (Okabe & Ito colour-blind-safe palette).
const PALETTE: [RGBColor; 6] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
];

fn colour(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

type Chart<'a> = ChartContext<'a, BitMapBackend<'a>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The figure's size, if it is one the backend can draw (64 to 8192 pixels a side).
fn checked_size(path: &Path, frame: &Frame) -> Result<(u32, u32), PlotError> {
    let (w, h) = (frame.width_px, frame.height_px);
    if !((64..=8192).contains(&w) && (64..=8192).contains(&h)) {
        return Err(PlotError::Size {
            path: path.into(),
            width_px: w,
            height_px: h,
        });
    }
    Ok((w, h))
}

/// The runs of plottable points: a line breaks at a point that cannot be drawn (a NaN).
fn segments(points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
    let mut segments: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for &(px, py) in points {
        if plottable(px) && plottable(py) {
            if let Some(seg) = segments.last_mut() {
                seg.push((px, py));
            }
        } else if segments.last().is_some_and(|seg| !seg.is_empty()) {
            segments.push(Vec::new());
        }
    }
    segments.retain(|s| !s.is_empty());
    segments
}

/// Draws `s` as a line in colour `c` (a lone point as a cross), labelled once in the legend.
fn draw_line(chart: &mut Chart<'_>, s: &Series, c: RGBColor, text: bool) -> Result<(), String> {
    for (j, seg) in segments(&s.points).into_iter().enumerate() {
        let d = if seg.len() == 1 {
            chart
                .draw_series(
                    seg.into_iter()
                        .map(move |p| Cross::new(p, 5, c.stroke_width(2))),
                )
                .map_err(|e| e.to_string())?
        } else {
            chart
                .draw_series(LineSeries::new(seg, c.stroke_width(2)))
                .map_err(|e| e.to_string())?
        };
        if text && j == 0 {
            d.label(s.label.as_str()).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 16, y)], c.stroke_width(2))
            });
        }
    }
    Ok(())
}

/// Draws `s` as dots of `radius_px` in colour `c`, labelled in the legend.
fn draw_points(
    chart: &mut Chart<'_>,
    s: &Series,
    c: RGBColor,
    radius_px: i32,
    text: bool,
) -> Result<(), String> {
    let points = s
        .points
        .iter()
        .copied()
        .filter(|(x, y)| plottable(*x) && plottable(*y));
    let d = chart
        .draw_series(points.map(move |p| Circle::new(p, radius_px, c.mix(0.75).filled())))
        .map_err(|e| e.to_string())?;
    if text {
        d.label(s.label.as_str())
            .legend(move |(x, y)| Circle::new((x + 8, y), 4, c.filled()));
    }
    Ok(())
}

/// The legend box.
fn draw_legend(chart: &mut Chart<'_>, font_px: u32) -> Result<(), String> {
    chart
        .configure_series_labels()
        .label_font((FAMILY, font_px))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| e.to_string())
}

/// Opens the PNG, draws the frame (with or without text) and hands the chart to `draw`.
fn with_chart(
    path: &Path,
    frame: &Frame,
    x: (f64, f64),
    y: (f64, f64),
    draw: impl FnOnce(&mut Chart<'_>, bool) -> Result<(), String>,
) -> Result<bool, PlotError> {
    let (w, h) = checked_size(path, frame)?;
    let text = frame.text == Text::Auto && system_font();
    let fail = |message: String| PlotError::Draw {
        path: path.into(),
        message,
    };
    let root = BitMapBackend::new(path, (w, h)).into_drawing_area();
    let result = (|| -> Result<(), String> {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mut chart = build(&root, frame, x, y, text)?;
        draw(&mut chart, text)?;
        if text {
            draw_legend(&mut chart, 14)?;
        }
        root.present().map_err(|e| e.to_string())
    })();
    result.map_err(fail)?;
    Ok(text)
}

fn build<'a>(
    root: &DrawingArea<BitMapBackend<'a>, Shift>,
    frame: &Frame,
    x: (f64, f64),
    y: (f64, f64),
    text: bool,
) -> Result<Chart<'a>, String> {
    let mut builder = ChartBuilder::on(root);
    builder.margin(12);
    if text {
        builder
            .caption(&frame.title, (FAMILY, 20))
            .x_label_area_size(44)
            .y_label_area_size(64);
    }
    let mut chart = builder
        .build_cartesian_2d(x.0..x.1, y.0..y.1)
        .map_err(|e| e.to_string())?;
    let mut mesh = chart.configure_mesh();
    mesh.light_line_style(RGBColor(235, 235, 235));
    if text {
        mesh.x_desc(frame.x_label.as_str())
            .y_desc(frame.y_label.as_str())
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 14));
    }
    mesh.draw().map_err(|e| e.to_string())?;
    // The zero line: residuals are read against it.
    if y.0 < 0.0 && y.1 > 0.0 {
        chart
            .draw_series(LineSeries::new([(x.0, 0.0), (x.1, 0.0)], BLACK.mix(0.5)))
            .map_err(|e| e.to_string())?;
    }
    Ok(chart)
}

fn count(series: &[Series]) -> (usize, usize) {
    let all: usize = series.iter().map(|s| s.points.len()).sum();
    let good = series
        .iter()
        .flat_map(|s| &s.points)
        .filter(|(x, y)| plottable(*x) && plottable(*y))
        .count();
    (good, all - good)
}

fn xy_ranges(series: &[Series]) -> ((f64, f64), (f64, f64)) {
    let good = || {
        series
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .filter(|(x, y)| plottable(*x) && plottable(*y))
    };
    (range(good().map(|p| p.0)), range(good().map(|p| p.1)))
}

/// Scatter plot of several labelled series (e.g. the residual against a variable, before and
/// after), written to `path` as PNG.
pub fn scatter_png(
    path: &Path,
    frame: &Frame,
    series: &[Series],
) -> Result<PlotOutcome, PlotError> {
    let (drawn, skipped) = count(series);
    let (x, y) = xy_ranges(series);
    let text = with_chart(path, frame, x, y, |chart, text| {
        for (i, s) in series.iter().enumerate() {
            draw_points(chart, s, colour(i), 2, text)?;
        }
        Ok(())
    })?;
    Ok(PlotOutcome {
        text,
        drawn,
        skipped,
    })
}

/// Line plot of several labelled series (e.g. a residual against time). A line breaks at a
/// skipped point, so a caller marks a gap with a NaN.
pub fn lines_png(path: &Path, frame: &Frame, series: &[Series]) -> Result<PlotOutcome, PlotError> {
    let (drawn, skipped) = count(series);
    let (x, y) = xy_ranges(series);
    let text = with_chart(path, frame, x, y, |chart, text| {
        for (i, s) in series.iter().enumerate() {
            draw_line(chart, s, colour(i), text)?;
        }
        Ok(())
    })?;
    Ok(PlotOutcome {
        text,
        drawn,
        skipped,
    })
}

/// Grouped bar chart: one group per label (e.g. a sensor), one bar per series in each group
/// (e.g. before, after, baseline). Bars start at zero; negative values go down.
pub fn grouped_bars_png(
    path: &Path,
    frame: &Frame,
    series_labels: &[String],
    groups: &[BarGroup],
) -> Result<PlotOutcome, PlotError> {
    let n_series = series_labels
        .len()
        .max(groups.iter().map(|g| g.values.len()).max().unwrap_or(0))
        .max(1);
    let values = || {
        groups
            .iter()
            .flat_map(|g| g.values.iter().flatten().copied())
    };
    let drawn = values().filter(|v| plottable(*v)).count();
    let skipped = values().count() - drawn;
    let (lo, hi) = range(values().filter(|v| plottable(*v)).chain([0.0]));
    // Room above the bars for the group labels.
    let y = (lo.min(0.0), hi + 0.08 * (hi - lo));
    let x = (0.0, groups.len().max(1) as f64);
    let width = 0.8 / n_series as f64;
    let text = with_chart(path, frame, x, y, |chart, text| {
        for s in 0..n_series {
            let c = colour(s);
            let bars: Vec<_> = groups
                .iter()
                .enumerate()
                .filter_map(|(g, group)| {
                    let v = group.values.get(s).copied().flatten()?;
                    plottable(v).then(|| {
                        let x0 = g as f64 + 0.1 + s as f64 * width;
                        Rectangle::new([(x0, 0.0), (x0 + width * 0.95, v)], c.filled())
                    })
                })
                .collect();
            let drawn = chart.draw_series(bars).map_err(|e| e.to_string())?;
            if text {
                let label = series_labels
                    .get(s)
                    .cloned()
                    .unwrap_or_else(|| format!("series {}", s + 1));
                drawn.label(label).legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 12, y + 5)], c.filled())
                });
            }
        }
        if text {
            let style =
                TextStyle::from((FAMILY, 14).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
            let labels = groups.iter().enumerate().map(|(g, group)| {
                plotters::element::Text::new(
                    group.label.clone(),
                    (g as f64 + 0.5, y.1),
                    style.clone(),
                )
            });
            chart.draw_series(labels).map_err(|e| e.to_string())?;
        }
        Ok(())
    })?;
    Ok(PlotOutcome {
        text,
        drawn,
        skipped,
    })
}

/// One panel of [`panels_png`]: a y axis shared by reference lines and measured points.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    pub y_label: String,
    /// Drawn as lines (a line breaks at a skipped point, e.g. a NaN).
    pub lines: Vec<Series>,
    /// Drawn as points.
    pub points: Vec<Series>,
}

/// Panels stacked vertically over one x axis (e.g. quantities of a day against time), in one
/// PNG: `frame` gives the title (on the first panel), the x label (on every panel) and the
/// size of the whole figure. Colours follow the series' order across lines then points, so
/// a measured series can take the colour of its reference by position.
pub fn panels_png(path: &Path, frame: &Frame, panels: &[Panel]) -> Result<PlotOutcome, PlotError> {
    let (w, h) = checked_size(path, frame)?;
    if panels.is_empty() {
        return Err(PlotError::Draw {
            path: path.into(),
            message: "no panel to draw".into(),
        });
    }
    let text = frame.text == Text::Auto && system_font();
    let all: Vec<Series> = panels
        .iter()
        .flat_map(|p| p.lines.iter().chain(&p.points).cloned())
        .collect();
    let (drawn, skipped) = count(&all);
    let (x, _) = xy_ranges(&all);
    let fail = |message: String| PlotError::Draw {
        path: path.into(),
        message,
    };
    let root = BitMapBackend::new(path, (w, h)).into_drawing_area();
    let result = (|| -> Result<(), String> {
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let areas = root.split_evenly((panels.len(), 1));
        for (k, (panel, area)) in panels.iter().zip(&areas).enumerate() {
            let series: Vec<Series> = panel.lines.iter().chain(&panel.points).cloned().collect();
            let (_, y) = xy_ranges(&series);
            let panel_frame = Frame {
                title: if k == 0 {
                    frame.title.clone()
                } else {
                    String::new()
                },
                x_label: frame.x_label.clone(),
                y_label: panel.y_label.clone(),
                ..frame.clone()
            };
            let mut chart = build(area, &panel_frame, x, y, text)?;
            for (i, s) in panel.lines.iter().enumerate() {
                draw_line(&mut chart, s, colour(i), text)?;
            }
            for (i, s) in panel.points.iter().enumerate() {
                draw_points(&mut chart, s, colour(panel.lines.len() + i), 3, text)?;
            }
            if text {
                draw_legend(&mut chart, 13)?;
            }
        }
        root.present().map_err(|e| e.to_string())
    })();
    result.map_err(fail)?;
    Ok(PlotOutcome {
        text,
        drawn,
        skipped,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small(text: Text) -> Frame {
        Frame {
            width_px: 160,
            height_px: 120,
            text,
            ..Frame::new("t", "x", "y")
        }
    }

    fn is_png(path: &Path) -> bool {
        std::fs::read(path).is_ok_and(|b| b.starts_with(b"\x89PNG\r\n\x1a\n"))
    }

    fn series(points: Vec<(f64, f64)>) -> Vec<Series> {
        vec![
            Series {
                label: "before".into(),
                points: points.clone(),
            },
            Series {
                label: "after".into(),
                points: points.into_iter().map(|(x, y)| (x, 0.5 * y)).collect(),
            },
        ]
    }

    /// Awkward data of every kind is drawn or skipped and counted, with and without text.
    #[test]
    fn awkward_data_never_fails() {
        let dir = tempfile::tempdir().unwrap();
        // (name, points, points drawn over both series)
        type Case = (&'static str, Vec<(f64, f64)>, usize);
        let cases: Vec<Case> = vec![
            ("empty", vec![], 0),
            ("constant", vec![(1.0, 5.0); 10], 20),
            ("single", vec![(3.0, -2.0)], 2),
            (
                "nan_inf",
                vec![
                    (f64::NAN, 1.0),
                    (1.0, f64::INFINITY),
                    (2.0, 3.0),
                    (3.0, 1e300),
                ],
                2,
            ),
            ("tiny_span", vec![(0.0, 1.0), (1e-300, 1.0 + 1e-15)], 4),
            ("huge", vec![(-1e12, -1e12), (1e12, 1e12)], 4),
        ];
        for text in [Text::Auto, Text::Off] {
            for (name, points, drawn) in &cases {
                let p = dir.path().join(format!("{name}_{text:?}.png"));
                let s = series(points.clone());
                let out = scatter_png(&p, &small(text), &s).unwrap();
                assert_eq!(out.drawn, *drawn, "{name}");
                assert_eq!(out.drawn + out.skipped, 2 * points.len(), "{name}");
                assert!(is_png(&p), "{name}");
                let out = lines_png(&p, &small(text), &s).unwrap();
                assert_eq!(out.drawn, *drawn, "{name}");
                if text == Text::Off {
                    assert!(!out.text);
                }
            }
        }
    }

    /// The font is found on a machine that has one, and text is then drawn.
    #[test]
    fn text_follows_the_font() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.png");
        let out = scatter_png(&p, &small(Text::Auto), &series(vec![(0.0, 1.0)])).unwrap();
        let font_exists = match std::env::var_os("SKYLUX_PLOT_FONT") {
            Some(f) => Path::new(&f).is_file(),
            None => FONT_PATHS.iter().any(|f| Path::new(f).is_file()),
        };
        assert_eq!(out.text, font_exists);
    }

    #[test]
    fn bars_and_errors() {
        let dir = tempfile::tempdir().unwrap();
        let labels = ["before".to_string(), "after".into(), "baseline".into()];
        let groups = vec![
            BarGroup {
                label: "S1".into(),
                values: vec![Some(0.25), Some(0.07), Some(0.37)],
            },
            BarGroup {
                label: "S2".into(),
                values: vec![Some(f64::NAN), None, Some(-0.1)],
            },
        ];
        for text in [Text::Auto, Text::Off] {
            let p = dir.path().join(format!("bars_{text:?}.png"));
            let out = grouped_bars_png(&p, &small(text), &labels, &groups).unwrap();
            assert_eq!((out.drawn, out.skipped), (4, 1));
            assert!(is_png(&p));
            let out = grouped_bars_png(&p, &small(text), &[], &[]).unwrap();
            assert_eq!((out.drawn, out.skipped), (0, 0));
        }
        let bad = Frame {
            width_px: 0,
            ..small(Text::Off)
        };
        assert!(matches!(
            scatter_png(&dir.path().join("x.png"), &bad, &[]),
            Err(PlotError::Size { .. })
        ));
        let missing_dir = dir.path().join("no/such/folder/x.png");
        assert!(matches!(
            lines_png(&missing_dir, &small(Text::Off), &series(vec![(0.0, 1.0)])),
            Err(PlotError::Draw { .. })
        ));
    }

    /// Lines break at a NaN and draw each piece.
    #[test]
    fn lines_break_at_gaps() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("gap.png");
        let s = vec![Series {
            label: "r".into(),
            points: vec![
                (0.0, 1.0),
                (1.0, 2.0),
                (f64::NAN, f64::NAN),
                (3.0, 1.0),
                (4.0, 0.0),
            ],
        }];
        let out = lines_png(&p, &small(Text::Off), &s).unwrap();
        assert_eq!((out.drawn, out.skipped), (4, 1));
        assert!(is_png(&p));
    }
}
