//! Falsecolour PNG pictures of luminance (or π × luminance in lux) with a colour legend, as
//! RADIANCE's `falsecolor` draws them.

use super::{output_error, OutputError, Picture};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// What the falsecolour legend is labelled in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LegendUnit {
    /// Luminance, cd/m².
    Luminance,
    /// Illuminance on a white Lambertian diffuser seen with that luminance: E = π L, lux.
    /// (falsecolor's `-i` scales an irradiance picture to lux; a radiance picture of a
    /// diffuser of reflectance 1 gives the same numbers times π.)
    Lux,
    /// A relative error, (rendered − measured)/measured, dimensionless (`skylux compare`).
    RelativeError,
}

/// How values map to colours.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ColourScale {
    /// 0 to the maximum.
    Linear,
    /// max / 10^decades to the maximum, logarithmic (falsecolor's `-log`).
    Log { decades: f64 },
}

/// Options of the falsecolour picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FalsecolourOptions {
    pub unit: LegendUnit,
    pub scale: ColourScale,
    /// Top of the scale in the legend's unit; None: a round number (1, 2 or 5 × 10^k) at or
    /// above the 99th percentile of the picture.
    pub maximum: Option<f64>,
    /// Bottom of a linear scale (None: 0); below 0 for signed values such as errors.
    pub minimum: Option<f64>,
    /// Labelled divisions of the legend (falsecolor's `-n`, default 8).
    pub divisions: u32,
}

impl Default for FalsecolourOptions {
    fn default() -> Self {
        Self {
            unit: LegendUnit::Luminance,
            scale: ColourScale::Linear,
            maximum: None,
            minimum: None,
            divisions: 8,
        }
    }
}

/// What was drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FalsecolourOutcome {
    /// Top of the scale used, in the legend's unit.
    pub maximum: f64,
    /// Whether the legend's numbers were drawn (a system font was found).
    pub text: bool,
    pub width_px: u32,
    pub height_px: u32,
}

/// The "Turbo" colour map (Mikhailov, Google AI blog, 2019), by its published polynomial
/// approximation: perceptually ordered from dark blue to dark red, for `t` in [0, 1].
pub fn turbo(t: f64) -> [u8; 3] {
    let x = t.clamp(0.0, 1.0);
    let (x2, x3) = (x * x, x * x * x);
    let (x4, x5) = (x3 * x, x3 * x2);
    let r = 0.13572138 + 4.61539260 * x - 42.66032258 * x2 + 132.13108234 * x3 - 152.94239396 * x4
        + 59.28637943 * x5;
    let g = 0.09140261 + 2.19418839 * x + 4.84296658 * x2 - 14.18503333 * x3
        + 4.27729857 * x4
        + 2.82956604 * x5;
    let b = 0.10667330 + 12.64194608 * x - 60.58204836 * x2 + 110.36276771 * x3 - 89.90310912 * x4
        + 27.34824973 * x5;
    let q = |v: f64| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    [q(r), q(g), q(b)]
}

/// The smallest of 1, 2, 5 × 10^k at or above `v` (> 0).
fn round_up(v: f64) -> f64 {
    if v.is_nan() || v <= 0.0 || !v.is_finite() {
        return 1.0;
    }
    let p = 10f64.powf(v.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * p >= v * (1.0 - 1e-12) {
            return m * p;
        }
    }
    10.0 * p
}

/// Where the legend's font is looked for: the plots' list (`output::plot::FONT_PATHS`,
/// `SKYLUX_PLOT_FONT` first).
const FAMILY: &str = "skylux-render-sans";

fn legend_font() -> bool {
    static LOADED: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *LOADED.get_or_init(|| {
        let mut candidates: Vec<PathBuf> = Vec::new();
        if let Some(p) = std::env::var_os("SKYLUX_PLOT_FONT") {
            candidates.push(PathBuf::from(p));
        }
        candidates.extend(crate::output::plot::FONT_PATHS.iter().map(PathBuf::from));
        for path in candidates {
            if let Ok(bytes) = std::fs::read(&path) {
                // Plotters keeps fonts for the whole process as `&'static`: one leak, once.
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                if plotters::style::register_font(FAMILY, plotters::style::FontStyle::Normal, bytes)
                    .is_ok()
                {
                    return true;
                }
            }
        }
        false
    })
}

/// Formats a legend value with 3 significant digits.
fn legend_label(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else if v.abs() >= 1e5 || v.abs() < 1e-2 {
        format!("{v:.2e}")
    } else {
        let decimals = (2 - v.abs().log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    }
}

/// Writes a falsecolour PNG of the image's luminance (or π × luminance in lux) with a colour
/// legend on the right. Small images are enlarged by a whole factor (nearest pixel) so the
/// picture is at least about 400 pixels high.
pub fn write_falsecolour_png(
    path: &Path,
    image: &Picture,
    options: &FalsecolourOptions,
) -> Result<FalsecolourOutcome, OutputError> {
    write_falsecolour_png_marked(path, image, options, &[])
}

/// [`write_falsecolour_png`] with some pixels drawn in a colour of their own: `marks` holds
/// one entry per pixel (rows from the top), or is empty for none (glare sources' outlines).
pub fn write_falsecolour_png_marked(
    path: &Path,
    image: &Picture,
    options: &FalsecolourOptions,
    marks: &[Option<[u8; 3]>],
) -> Result<FalsecolourOutcome, OutputError> {
    use plotters::prelude::*;
    if !marks.is_empty() && marks.len() != image.luminance_cd_m2.len() {
        return Err(output_error(
            path,
            format!(
                "{} marks for {} pixels",
                marks.len(),
                image.luminance_cd_m2.len()
            ),
        ));
    }
    let factor = match options.unit {
        LegendUnit::Luminance | LegendUnit::RelativeError => 1.0,
        LegendUnit::Lux => PI,
    };
    let values: Vec<f64> = image.luminance_cd_m2.iter().map(|l| l * factor).collect();
    let maximum = scale_maximum(&values, options).map_err(|e| output_error(path, e))?;
    let minimum = scale_minimum(maximum, options).map_err(|e| output_error(path, e))?;
    let (w, h) = (image.width_px, image.height_px);
    let zoom = (400 / h.max(1)).clamp(1, (4096 / w.max(1)).max(1));
    let legend_w = 170u32;
    let pic_w = w * zoom;
    let pic_h = h * zoom;
    let total_w = pic_w + legend_w;
    let total_h = pic_h.max(320);
    let text = legend_font();
    let draw_error = |e: &dyn std::fmt::Display| output_error(path, e);
    {
        let root = BitMapBackend::new(path, (total_w, total_h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| draw_error(&e))?;
        for row in 0..h {
            for column in 0..w {
                let i = image.index(column, row);
                let mark = marks.get(i).copied().flatten();
                let [r, g, b] = mark.unwrap_or_else(|| {
                    turbo(scale_position(values[i], minimum, maximum, options.scale))
                });
                let colour = RGBColor(r, g, b);
                for dy in 0..zoom {
                    for dx in 0..zoom {
                        root.draw_pixel(
                            ((column * zoom + dx) as i32, (row * zoom + dy) as i32),
                            &colour,
                        )
                        .map_err(|e| draw_error(&e))?;
                    }
                }
            }
        }
        draw_legend(&root, options, (minimum, maximum), pic_w, total_h, text)
            .map_err(|e| draw_error(&e))?;
        root.present().map_err(|e| draw_error(&e))?;
    }
    Ok(FalsecolourOutcome {
        maximum,
        text,
        width_px: total_w,
        height_px: total_h,
    })
}

/// Top of the scale: the given maximum, else a round number at or above the 99th
/// percentile of `values`; checks the log scale's decades too.
fn scale_maximum(values: &[f64], options: &FalsecolourOptions) -> Result<f64, String> {
    let maximum = match options.maximum {
        Some(m) if m > 0.0 && m.is_finite() => m,
        Some(m) => return Err(format!("scale maximum {m} must be > 0")),
        None => {
            let mut sorted: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
            sorted.sort_by(f64::total_cmp);
            let p99 = sorted
                .get(((sorted.len() as f64 * 0.99) as usize).min(sorted.len().saturating_sub(1)))
                .copied()
                .unwrap_or(1.0);
            round_up(p99)
        }
    };
    if let ColourScale::Log { decades } = options.scale {
        if !(decades > 0.0 && decades.is_finite()) {
            return Err(format!("log scale decades {decades} must be > 0"));
        }
    }
    Ok(maximum)
}

/// Bottom of the scale: the given minimum (linear scales only, below the maximum), else 0.
fn scale_minimum(maximum: f64, options: &FalsecolourOptions) -> Result<f64, String> {
    match (options.minimum, options.scale) {
        (None, _) => Ok(0.0),
        (Some(m), ColourScale::Linear) if m.is_finite() && m < maximum => Ok(m),
        (Some(m), ColourScale::Linear) => Err(format!(
            "scale minimum {m} must be finite and below the maximum {maximum}"
        )),
        (Some(_), ColourScale::Log { .. }) => {
            Err("a log scale starts at max / 10^decades, not at a given minimum".into())
        }
    }
}

/// Where `v` lies on the colour scale, 0 at `minimum` and 1 at `maximum`.
fn scale_position(v: f64, minimum: f64, maximum: f64, scale: ColourScale) -> f64 {
    match scale {
        ColourScale::Linear => (v - minimum) / (maximum - minimum),
        ColourScale::Log { decades } => {
            if v <= 0.0 {
                0.0
            } else {
                ((v / maximum).log10() + decades) / decades
            }
        }
    }
}

/// The colour bar right of the picture (top = `maximum`), and its labels if `text`.
fn draw_legend(
    root: &plotters::drawing::DrawingArea<
        plotters::backend::BitMapBackend<'_>,
        plotters::coord::Shift,
    >,
    options: &FalsecolourOptions,
    (minimum, maximum): (f64, f64),
    pic_w: u32,
    total_h: u32,
    text: bool,
) -> Result<(), String> {
    use plotters::prelude::*;
    use plotters::style::text_anchor::{HPos, Pos, VPos};
    let err = |e: &dyn std::fmt::Display| e.to_string();
    let (bar_x, bar_w) = (pic_w as i32 + 16, 24i32);
    let (bar_top, bar_bottom) = (36i32, total_h as i32 - 16);
    let span = (bar_bottom - bar_top).max(1);
    for y in bar_top..bar_bottom {
        let t = 1.0 - f64::from(y - bar_top) / f64::from(span);
        let [r, g, b] = turbo(t);
        root.draw(&Rectangle::new(
            [(bar_x, y), (bar_x + bar_w, y + 1)],
            RGBColor(r, g, b).filled(),
        ))
        .map_err(|e| err(&e))?;
    }
    if !text {
        return Ok(());
    }
    let divisions = options.divisions.max(1);
    let unit = match options.unit {
        LegendUnit::Luminance => "cd/m²",
        LegendUnit::Lux => "lux (π L)",
        LegendUnit::RelativeError => "(R - M)/M",
    };
    let scale = match options.scale {
        ColourScale::Linear => "linear",
        ColourScale::Log { .. } => "log",
    };
    let style = TextStyle::from((FAMILY, 14).into_font()).color(&BLACK);
    root.draw(&Text::new(
        format!("{unit}, {scale}"),
        (pic_w as i32 + 8, 8),
        style.clone(),
    ))
    .map_err(|e| err(&e))?;
    for k in 0..=divisions {
        let t = f64::from(k) / f64::from(divisions);
        let value = match options.scale {
            ColourScale::Linear => minimum + t * (maximum - minimum),
            ColourScale::Log { decades } => maximum * 10f64.powf((t - 1.0) * decades),
        };
        let y = bar_bottom - (t * f64::from(span)) as i32;
        root.draw(&Text::new(
            legend_label(value),
            (bar_x + bar_w + 6, y),
            style.clone().pos(Pos::new(HPos::Left, VPos::Center)),
        ))
        .map_err(|e| err(&e))?;
        root.draw(&PathElement::new(
            vec![(bar_x + bar_w, y), (bar_x + bar_w + 4, y)],
            BLACK,
        ))
        .map_err(|e| err(&e))?;
    }
    Ok(())
}
