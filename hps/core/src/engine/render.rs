//! Images of a scene from a view (`skylux render`, issue 5 item 7): RADIANCE's views, the
//! radiance of every pixel by path tracing, and the three outputs (OpenEXR, RADIANCE `.hdr`,
//! falsecolour PNG with a legend).
//!
//! Views have RADIANCE's meaning (src/common/image.c): the same options (`-vt{v,h,a}`, `-vp`,
//! `-vd`, `-vu`, `-vh`, `-vv`, `-vs`, `-vl`, `-vo`), the same image vectors (`setview`), the
//! same ray per image position (`viewray`) and the same resolution fitting (`normaspect` with
//! square pixels, rpict's default `-pa 1`), so that a view file written for rpict frames the
//! same picture and `vwrays` gives the same rays.
//!
//! A pixel's value is the mean of `samples_per_pixel` estimates of rtrace's value
//! ([`super::radiance::ray_radiance`]) for rays through jittered positions in the pixel
//! (stratified on a √n × √n grid, the rest uniform). Each pixel has its own random stream
//! from (seed, pixel index), and rows are spread over rayon's threads, so an image does not
//! depend on the number of threads.

use super::error::EngineError;
use super::illuminance::lux_from_irradiance;
use super::integrator::Settings;
use super::radiance::ray_radiance;
use super::ray::Ray;
use super::rng::Rng;
use super::world::World;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

/// RADIANCE's `FTINY` (fvect.h), the tolerance `setview` checks sizes with.
const FTINY: f64 = 1e-6;
/// Largest image side, and most pixels: the image and its statistics (40 bytes a pixel) must
/// fit in a 32-bit process's memory.
pub const MAX_SIDE_PX: u32 = 16384;
pub const MAX_PIXELS: u64 = 1 << 24;

/// RADIANCE's view types that are traced (view.h `VT_*`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewType {
    /// `-vtv`: perspective.
    Perspective,
    /// `-vth`: hemispherical fisheye (orthographic projection of the hemisphere).
    Hemispherical,
    /// `-vta`: angular fisheye (equidistant: image radius proportional to angle).
    Angular,
}

impl ViewType {
    fn letter(self) -> char {
        match self {
            ViewType::Perspective => 'v',
            ViewType::Hemispherical => 'h',
            ViewType::Angular => 'a',
        }
    }
}

/// A view as rpict's options give it; [`View::prepare`] checks it and computes the image
/// vectors.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    pub kind: ViewType,
    /// `-vp`: eye position, m.
    pub position_m: DVec3,
    /// `-vd`: view direction (any length but zero).
    pub direction: DVec3,
    /// `-vu`: up vector.
    pub up: DVec3,
    /// `-vh`, `-vv`: full horizontal and vertical view angles, degrees.
    pub horizontal_deg: f64,
    pub vertical_deg: f64,
    /// `-vs`, `-vl`: image shift and lift, in image widths and heights.
    pub shift: f64,
    pub lift: f64,
    /// `-vo`: fore clipping distance, m (rays start this far along the view ray).
    pub fore_m: f64,
}

impl Default for View {
    /// RADIANCE's `stdview` (view.h `STDVIEW`).
    fn default() -> Self {
        View {
            kind: ViewType::Perspective,
            position_m: DVec3::ZERO,
            direction: DVec3::Y,
            up: DVec3::Z,
            horizontal_deg: 45.0,
            vertical_deg: 45.0,
            shift: 0.0,
            lift: 0.0,
            fore_m: 0.0,
        }
    }
}

/// Why a view cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ViewError {
    /// One option of a view string is wrong.
    #[error("view option `{option}`: {message}")]
    Option { option: String, message: String },
    /// A view file's line is wrong, or the file has no view.
    #[error("view file {path}{}: {message}", line.map(|l| format!(":{l}")).unwrap_or_default())]
    File {
        path: PathBuf,
        line: Option<usize>,
        message: String,
    },
    /// The options parse but do not make a view (RADIANCE `setview`'s checks).
    #[error("view `{view}`: {message}")]
    Invalid { view: String, message: String },
}

fn option_error(option: &str, message: impl Into<String>) -> ViewError {
    ViewError::Option {
        option: option.into(),
        message: message.into(),
    }
}

impl View {
    /// A view from an rpict-style string (`-vtv -vp 1 2 1.2 -vd 0 -1 0 -vh 60 -vv 45`),
    /// starting from RADIANCE's default view. A leading `VIEW=` (as in a picture header) or
    /// program name (`rpict`, `rvu`) is skipped.
    pub fn parse(text: &str) -> Result<View, ViewError> {
        View::default().with_options(text)
    }

    /// This view with the options in `text` applied over it, in order (later options win, as
    /// in RADIANCE).
    pub fn with_options(mut self, text: &str) -> Result<View, ViewError> {
        let text = text.trim();
        let text = text.strip_prefix("VIEW=").unwrap_or(text);
        let mut tokens = text.split_whitespace().peekable();
        if let Some(first) = tokens.peek() {
            if matches!(*first, "rpict" | "rvu" | "rview" | "rpiece" | "pinterp") {
                tokens.next();
            }
        }
        let mut any = false;
        while let Some(option) = tokens.next() {
            let mut numbers = |count: usize| -> Result<Vec<f64>, ViewError> {
                (0..count)
                    .map(|i| {
                        let t = tokens.next().ok_or_else(|| {
                            option_error(option, format!("expected {count} number(s), found {i}"))
                        })?;
                        match t.parse::<f64>() {
                            Ok(v) if v.is_finite() => Ok(v),
                            _ => Err(option_error(
                                option,
                                format!("expected a number, found `{t}`"),
                            )),
                        }
                    })
                    .collect()
            };
            let vec3 = |v: Vec<f64>| DVec3::new(v[0], v[1], v[2]);
            match option {
                "-vtv" => self.kind = ViewType::Perspective,
                "-vth" => self.kind = ViewType::Hemispherical,
                "-vta" => self.kind = ViewType::Angular,
                o if o.starts_with("-vt") => {
                    return Err(option_error(
                        o,
                        "unsupported view type; expected -vtv (perspective), -vth \
                         (hemispherical fisheye) or -vta (angular fisheye)",
                    ))
                }
                "-vp" => self.position_m = vec3(numbers(3)?),
                "-vd" => self.direction = vec3(numbers(3)?),
                "-vu" => self.up = vec3(numbers(3)?),
                "-vh" => self.horizontal_deg = numbers(1)?[0],
                "-vv" => self.vertical_deg = numbers(1)?[0],
                "-vs" => self.shift = numbers(1)?[0],
                "-vl" => self.lift = numbers(1)?[0],
                "-vo" => self.fore_m = numbers(1)?[0],
                "-va" => {
                    if numbers(1)?[0] != 0.0 {
                        return Err(option_error(
                            option,
                            "aft clipping is not supported (only -va 0)",
                        ));
                    }
                }
                "-vf" => {
                    return Err(option_error(
                        option,
                        "a view file cannot be named inside a view string; give it as \
                         --view-file",
                    ))
                }
                o => {
                    return Err(option_error(
                        o,
                        "unknown view option; expected -vt{v,h,a}, -vp, -vd, -vu, -vh, -vv, \
                         -vs, -vl, -vo or -va",
                    ))
                }
            }
            any = true;
        }
        if !any {
            return Err(option_error(text, "no view option given"));
        }
        Ok(self)
    }

    /// This view with the view lines of a RADIANCE view file applied over it: lines starting
    /// with `VIEW=` (picture headers), with a view program's name (`rvu -vtv ...`) or with a
    /// `-v` option. Blank lines and `#` comments are skipped; any other line is an error.
    pub fn with_file(self, path: &Path) -> Result<View, ViewError> {
        let bytes = std::fs::read(path).map_err(|e| ViewError::File {
            path: path.into(),
            line: None,
            message: e.to_string(),
        })?;
        // A picture's header ends at its first blank line; a text file has none before EOF
        // or only trailing ones.
        let text = String::from_utf8_lossy(&bytes);
        let mut view = self;
        let mut found = false;
        for (i, line) in text.lines().enumerate() {
            let t = line.trim();
            if t.is_empty() {
                if text.starts_with("#?") {
                    break; // end of a picture header
                }
                continue;
            }
            if t.starts_with('#') {
                continue;
            }
            let first = t.split_whitespace().next().unwrap_or("");
            let is_view = t.starts_with("VIEW=")
                || first.starts_with("-v")
                || matches!(first, "rpict" | "rvu" | "rview" | "rpiece" | "pinterp");
            if !is_view {
                if text.starts_with("#?") {
                    continue; // other header lines of a picture
                }
                return Err(ViewError::File {
                    path: path.into(),
                    line: Some(i + 1),
                    message: format!("not a view line: `{t}`"),
                });
            }
            view = view.with_options(t).map_err(|e| ViewError::File {
                path: path.into(),
                line: Some(i + 1),
                message: e.to_string(),
            })?;
            found = true;
        }
        if !found {
            return Err(ViewError::File {
                path: path.into(),
                line: None,
                message: "no view found".into(),
            });
        }
        Ok(view)
    }

    /// The view as RADIANCE writes it (image.c `fprintview`, `%.6g` numbers), without the
    /// leading `VIEW=`.
    pub fn to_radiance_string(&self) -> String {
        let v = |d: DVec3| format!("{} {} {}", g6(d.x), g6(d.y), g6(d.z));
        format!(
            "-vt{} -vp {} -vd {} -vu {} -vh {} -vv {} -vo {} -va 0 -vs {} -vl {}",
            self.kind.letter(),
            v(self.position_m),
            v(self.direction),
            v(self.up),
            g6(self.horizontal_deg),
            g6(self.vertical_deg),
            g6(self.fore_m),
            g6(self.shift),
            g6(self.lift)
        )
    }

    /// RADIANCE's `setview`: checks the view and computes its image vectors.
    pub fn prepare(&self) -> Result<PreparedView, ViewError> {
        let invalid = |message: &str| ViewError::Invalid {
            view: self.to_radiance_string(),
            message: message.into(),
        };
        if self.fore_m < -FTINY {
            return Err(invalid("illegal fore clipping plane (-vo must be >= 0)"));
        }
        let direction = self
            .direction
            .try_normalize()
            .ok_or(invalid("zero view direction (-vd)"))?;
        let up = self
            .up
            .try_normalize()
            .ok_or(invalid("zero view up vector (-vu)"))?;
        let hvec = direction
            .cross(up)
            .try_normalize()
            .ok_or(invalid("view up (-vu) parallel to view direction (-vd)"))?;
        let vvec = hvec.cross(direction);
        let (h, v) = (self.horizontal_deg, self.vertical_deg);
        if h <= FTINY {
            return Err(invalid("illegal horizontal view size (-vh must be > 0)"));
        }
        if v <= FTINY {
            return Err(invalid("illegal vertical view size (-vv must be > 0)"));
        }
        let (hn, vn) = match self.kind {
            ViewType::Perspective => {
                if h >= 180.0 - FTINY {
                    return Err(invalid("illegal horizontal view size (-vh must be < 180)"));
                }
                if v >= 180.0 - FTINY {
                    return Err(invalid("illegal vertical view size (-vv must be < 180)"));
                }
                (
                    2.0 * (h * (PI / 360.0)).tan(),
                    2.0 * (v * (PI / 360.0)).tan(),
                )
            }
            ViewType::Angular => {
                if h > 360.0 + FTINY {
                    return Err(invalid("illegal horizontal view size (-vh must be <= 360)"));
                }
                if v > 360.0 + FTINY {
                    return Err(invalid("illegal vertical view size (-vv must be <= 360)"));
                }
                (h * (PI / 180.0), v * (PI / 180.0))
            }
            ViewType::Hemispherical => {
                if h > 180.0 + FTINY {
                    return Err(invalid("illegal horizontal view size (-vh must be <= 180)"));
                }
                if v > 180.0 + FTINY {
                    return Err(invalid("illegal vertical view size (-vv must be <= 180)"));
                }
                (
                    2.0 * (h * (PI / 360.0)).sin(),
                    2.0 * (v * (PI / 360.0)).sin(),
                )
            }
        };
        // setview scales the image vectors by their lengths, except for the angular fisheye.
        let (hvec, vvec) = if self.kind == ViewType::Angular {
            (hvec, vvec)
        } else {
            (hvec * hn, vvec * vn)
        };
        Ok(PreparedView {
            view: self.clone(),
            direction,
            hvec,
            vvec,
            hn2: hn * hn,
            vn2: vn * vn,
        })
    }
}

/// `%.6g`, as RADIANCE prints view parameters.
fn g6(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let exp = x.abs().log10().floor() as i32;
    if !(-5..6).contains(&exp) {
        let s = format!("{x:.5e}");
        // Trim the mantissa's trailing zeros as %g does.
        match s.split_once('e') {
            Some((m, e)) => {
                let m = if m.contains('.') {
                    m.trim_end_matches('0').trim_end_matches('.')
                } else {
                    m
                };
                let e: i32 = e.parse().unwrap_or(0);
                format!("{m}e{}{:02}", if e < 0 { '-' } else { '+' }, e.abs())
            }
            None => s,
        }
    } else {
        let decimals = (5 - exp).max(0) as usize;
        let s = format!("{x:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    }
}

/// A checked view with RADIANCE's image vectors (`VIEW` after `setview`).
#[derive(Clone, Debug, PartialEq)]
pub struct PreparedView {
    pub view: View,
    /// Unit view direction.
    direction: DVec3,
    /// Horizontal and vertical image vectors (scaled as setview scales them).
    hvec: DVec3,
    vvec: DVec3,
    hn2: f64,
    vn2: f64,
}

impl PreparedView {
    /// Height over width of the view's image (view.h `viewaspect`).
    pub fn aspect(&self) -> f64 {
        (self.vn2 / self.hn2).sqrt()
    }

    /// rpict's resolution for at most `max_x` × `max_y` pixels with square pixels
    /// (image.c `normaspect` with pixel aspect 1): one side is reduced to the view's aspect.
    pub fn fit_resolution(&self, max_x: u32, max_y: u32) -> (u32, u32) {
        let va = self.aspect();
        let (x, y) = (f64::from(max_x), f64::from(max_y));
        if va * x > y {
            (((y / va) + 0.5).max(1.0) as u32, max_y)
        } else {
            (max_x, ((x * va) + 0.5).max(1.0) as u32)
        }
    }

    /// RADIANCE's `viewray`: the ray through image position (x, y), both in [0, 1] from the
    /// left and from the bottom of the image; None outside a fisheye's circle.
    pub fn ray(&self, x: f64, y: f64) -> Option<Ray> {
        let v = &self.view;
        let x = x + v.shift - 0.5;
        let y = y + v.lift - 0.5;
        let d = match v.kind {
            ViewType::Perspective => self.direction + x * self.hvec + y * self.vvec,
            ViewType::Hemispherical => {
                let z = 1.0 - x * x * self.hn2 - y * y * self.vn2;
                if z < 0.0 {
                    return None;
                }
                z.sqrt() * self.direction + x * self.hvec + y * self.vvec
            }
            ViewType::Angular => {
                let x = x * (v.horizontal_deg / 180.0);
                let y = y * (v.vertical_deg / 180.0);
                let r2 = x * x + y * y;
                if r2 > 1.0 {
                    return None;
                }
                let r = r2.sqrt();
                let z = (PI * r).cos();
                let s = if r <= FTINY {
                    PI
                } else {
                    (1.0 - z * z).sqrt() / r
                };
                z * self.direction + (x * s) * self.hvec + (y * s) * self.vvec
            }
        };
        let origin = v.position_m + v.fore_m * d;
        let direction = d.try_normalize()?;
        Some(Ray::new(origin, direction))
    }

    /// The ray through the centre of pixel (`column`, `row`) of a `width` × `height` image,
    /// row 0 at the top (rpict's and vwrays' order, pix2loc with PIXSTANDARD).
    pub fn pixel_centre_ray(&self, column: u32, row: u32, width: u32, height: u32) -> Option<Ray> {
        self.ray(
            (f64::from(column) + 0.5) / f64::from(width),
            (f64::from(height - 1 - row) + 0.5) / f64::from(height),
        )
    }
}

/// Image size, samples and tracing controls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    pub width_px: u32,
    pub height_px: u32,
    /// Paths per pixel, at least 1.
    pub samples_per_pixel: u32,
    /// `-ab`, `-lr` and the seed; `samples_per_sensor` is not used.
    pub trace: Settings,
}

impl RenderSettings {
    pub fn validate(&self) -> Result<(), EngineError> {
        for (name, value) in [
            ("image width (-x)", self.width_px),
            ("image height (-y)", self.height_px),
        ] {
            if value == 0 || value > MAX_SIDE_PX {
                return Err(EngineError::Setting {
                    name,
                    value: value.to_string(),
                    expected: "1 to 16384 pixels",
                });
            }
        }
        if u64::from(self.width_px) * u64::from(self.height_px) > MAX_PIXELS {
            return Err(EngineError::Setting {
                name: "image size (-x × -y)",
                value: format!("{}x{}", self.width_px, self.height_px),
                expected: "at most 16777216 pixels",
            });
        }
        if self.samples_per_pixel == 0 {
            return Err(EngineError::Setting {
                name: "samples per pixel (--spp)",
                value: "0".into(),
                expected: "at least 1",
            });
        }
        Ok(())
    }
}

/// A rendered image, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderedImage {
    pub width_px: u32,
    pub height_px: u32,
    pub view: View,
    /// Mean radiance per pixel, W/sr/m² per RGB channel (what rpict writes).
    pub radiance_rgb: Vec<DVec3>,
    /// 179 × (0.265 R + 0.670 G + 0.065 B) of the radiance, cd/m².
    pub luminance_cd_m2: Vec<f64>,
    /// Standard error of each pixel's luminance, s / √n over its samples (0 for one sample).
    pub luminance_stderr_cd_m2: Vec<f64>,
    pub samples_per_pixel: u32,
}

impl RenderedImage {
    /// Index of pixel (`column`, `row`), row 0 at the top.
    pub fn index(&self, column: u32, row: u32) -> usize {
        row as usize * self.width_px as usize + column as usize
    }
}

/// Luminance (cd/m²) from RGB radiance (W/sr/m²): RADIANCE's 179 lm/W and `bright` weights,
/// the same conversion as illuminance from irradiance.
pub fn luminance_from_radiance(radiance_rgb: DVec3) -> f64 {
    lux_from_irradiance(radiance_rgb)
}

/// Renders `view` of `world`. `progress` is called with (rows done, rows in all) from the
/// worker threads.
pub fn render(
    world: &World,
    view: &PreparedView,
    settings: &RenderSettings,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Result<RenderedImage, EngineError> {
    settings.validate()?;
    let (w, h) = (settings.width_px, settings.height_px);
    let n = settings.samples_per_pixel;
    let grid = (f64::from(n).sqrt() as u32).max(1);
    let done = std::sync::atomic::AtomicU64::new(0);
    let rows: Vec<Vec<(DVec3, f64, f64)>> = (0..h)
        .into_par_iter()
        .map(|row| {
            let out = (0..w)
                .map(|column| {
                    let pixel = u64::from(row) * u64::from(w) + u64::from(column);
                    let mut rng = Rng::for_stream(settings.trace.seed, pixel);
                    let (mut rgb, mut sum, mut sum2) = (DVec3::ZERO, 0.0, 0.0);
                    for s in 0..n {
                        let (jx, jy) = if s < grid * grid {
                            (
                                (f64::from(s % grid) + rng.uniform()) / f64::from(grid),
                                (f64::from(s / grid) + rng.uniform()) / f64::from(grid),
                            )
                        } else {
                            (rng.uniform(), rng.uniform())
                        };
                        let x = (f64::from(column) + jx) / f64::from(w);
                        let y = (f64::from(h - 1 - row) + jy) / f64::from(h);
                        let l = match view.ray(x, y) {
                            Some(ray) => ray_radiance(world, ray, &settings.trace, &mut rng),
                            None => DVec3::ZERO,
                        };
                        let lum = luminance_from_radiance(l);
                        rgb += l;
                        sum += lum;
                        sum2 += lum * lum;
                    }
                    let nf = f64::from(n);
                    let mean = sum / nf;
                    let var = if n > 1 {
                        ((sum2 - nf * mean * mean) / (nf - 1.0)).max(0.0)
                    } else {
                        0.0
                    };
                    (rgb / nf, mean, (var / nf).sqrt())
                })
                .collect();
            let d = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress(d, u64::from(h));
            out
        })
        .collect();
    let mut image = RenderedImage {
        width_px: w,
        height_px: h,
        view: view.view.clone(),
        radiance_rgb: Vec::with_capacity((w * h) as usize),
        luminance_cd_m2: Vec::with_capacity((w * h) as usize),
        luminance_stderr_cd_m2: Vec::with_capacity((w * h) as usize),
        samples_per_pixel: n,
    };
    for (rgb, lum, se) in rows.into_iter().flatten() {
        image.radiance_rgb.push(rgb);
        image.luminance_cd_m2.push(lum);
        image.luminance_stderr_cd_m2.push(se);
    }
    Ok(image)
}

/// Why an output file could not be written.
#[derive(Debug, thiserror::Error)]
#[error("{path}: {message}")]
pub struct OutputError {
    pub path: PathBuf,
    pub message: String,
}

fn output_error(path: &Path, message: impl ToString) -> OutputError {
    OutputError {
        path: path.into(),
        message: message.to_string(),
    }
}

/// Writes the image as OpenEXR: float32 channels `R`, `G`, `B` (radiance, W/sr/m²) and `Y`
/// (luminance, cd/m²), and the view in the header attribute `skylux.view` (RADIANCE's syntax).
pub fn write_exr(path: &Path, image: &RenderedImage) -> Result<(), OutputError> {
    use exr::prelude::*;
    let channel = |f: &dyn Fn(usize) -> f64| -> Vec<f32> {
        (0..image.radiance_rgb.len()).map(|i| f(i) as f32).collect()
    };
    let channels = AnyChannels::sort(smallvec::smallvec![
        AnyChannel::new("R", FlatSamples::F32(channel(&|i| image.radiance_rgb[i].x))),
        AnyChannel::new("G", FlatSamples::F32(channel(&|i| image.radiance_rgb[i].y))),
        AnyChannel::new("B", FlatSamples::F32(channel(&|i| image.radiance_rgb[i].z))),
        AnyChannel::new(
            "Y",
            FlatSamples::F32(channel(&|i| image.luminance_cd_m2[i]))
        ),
    ]);
    let mut layer = Layer::new(
        (image.width_px as usize, image.height_px as usize),
        LayerAttributes::named("render"),
        Encoding::FAST_LOSSLESS,
        channels,
    );
    let view = image.view.to_radiance_string();
    if let (Some(name), Some(value)) = (Text::new_or_none("skylux.view"), Text::new_or_none(&view))
    {
        layer
            .attributes
            .other
            .insert(name, AttributeValue::Text(value));
    }
    Image::from_layer(layer)
        .write()
        .to_file(path)
        .map_err(|e| output_error(path, e))
}

/// RADIANCE's RGBE encoding of one colour (color.c `setcolr`): a shared exponent and three
/// 8-bit mantissas, 0 for values below 1e-32.
pub fn rgbe(c: DVec3) -> [u8; 4] {
    let c = c.max(DVec3::ZERO);
    let d = c.max_element();
    if d.is_nan() || d <= 1e-32 {
        return [0; 4];
    }
    if !d.is_finite() {
        return [255, 255, 255, 255];
    }
    // frexp: d = m 2^e with m in [0.5, 1).
    let mut e = d.log2().floor() as i32 + 1;
    let mut m = d / 2f64.powi(e);
    if m >= 1.0 {
        m /= 2.0;
        e += 1;
    } else if m < 0.5 {
        m *= 2.0;
        e -= 1;
    }
    if e + 128 > 255 {
        return [255, 255, 255, 255];
    }
    if e + 128 < 0 {
        return [0; 4];
    }
    let scale = m * 256.0 / d;
    [
        (c.x * scale) as u8,
        (c.y * scale) as u8,
        (c.z * scale) as u8,
        (e + 128) as u8,
    ]
}

/// Writes the image as a RADIANCE picture: a header with the view (`VIEW=`), `EXPOSURE=` if
/// `exposure` is given (the factor by which the values were multiplied; they are written
/// unscaled here and the line only documents the factor) and `FORMAT=32-bit_rle_rgbe`, the
/// standard resolution line `-Y height +X width`, then flat RGBE scanlines from the top
/// (which every RADIANCE reader accepts).
pub fn write_hdr(
    path: &Path,
    image: &RenderedImage,
    exposure: Option<f64>,
) -> Result<(), OutputError> {
    let mut out = Vec::with_capacity(image.radiance_rgb.len() * 4 + 256);
    out.extend_from_slice(b"#?RADIANCE\n");
    out.extend_from_slice(
        format!("SOFTWARE= skylux {} render\n", env!("CARGO_PKG_VERSION")).as_bytes(),
    );
    out.extend_from_slice(
        format!("SAMPLES= {} paths per pixel\n", image.samples_per_pixel).as_bytes(),
    );
    out.extend_from_slice(format!("VIEW= {}\n", image.view.to_radiance_string()).as_bytes());
    if let Some(e) = exposure {
        out.extend_from_slice(format!("EXPOSURE={e:e}\n").as_bytes());
    }
    out.extend_from_slice(b"FORMAT=32-bit_rle_rgbe\n\n");
    out.extend_from_slice(format!("-Y {} +X {}\n", image.height_px, image.width_px).as_bytes());
    for c in &image.radiance_rgb {
        out.extend_from_slice(&rgbe(*c));
    }
    std::fs::write(path, out).map_err(|e| output_error(path, e))
}

/// What the falsecolour legend is labelled in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LegendUnit {
    /// Luminance, cd/m².
    Luminance,
    /// Illuminance on a white Lambertian diffuser seen with that luminance: E = π L, lux.
    /// (falsecolor's `-i` scales an irradiance picture to lux; a radiance picture of a
    /// diffuser of reflectance 1 gives the same numbers times π.)
    Lux,
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
    /// Labelled divisions of the legend (falsecolor's `-n`, default 8).
    pub divisions: u32,
}

impl Default for FalsecolourOptions {
    fn default() -> Self {
        Self {
            unit: LegendUnit::Luminance,
            scale: ColourScale::Linear,
            maximum: None,
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
    image: &RenderedImage,
    options: &FalsecolourOptions,
) -> Result<FalsecolourOutcome, OutputError> {
    use plotters::prelude::*;
    use plotters::style::text_anchor::{HPos, Pos, VPos};
    let factor = match options.unit {
        LegendUnit::Luminance => 1.0,
        LegendUnit::Lux => PI,
    };
    let values: Vec<f64> = image.luminance_cd_m2.iter().map(|l| l * factor).collect();
    let maximum = match options.maximum {
        Some(m) if m > 0.0 && m.is_finite() => m,
        Some(m) => return Err(output_error(path, format!("scale maximum {m} must be > 0"))),
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
            return Err(output_error(
                path,
                format!("log scale decades {decades} must be > 0"),
            ));
        }
    }
    let position = |v: f64| -> f64 {
        match options.scale {
            ColourScale::Linear => v / maximum,
            ColourScale::Log { decades } => {
                if v <= 0.0 {
                    0.0
                } else {
                    ((v / maximum).log10() + decades) / decades
                }
            }
        }
    };
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
                let v = values[image.index(column, row)];
                let [r, g, b] = turbo(position(v));
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
        // The colour bar: top = maximum.
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
            .map_err(|e| draw_error(&e))?;
        }
        let divisions = options.divisions.max(1);
        if text {
            let unit = match options.unit {
                LegendUnit::Luminance => "cd/m²".to_string(),
                LegendUnit::Lux => "lux (π L)".to_string(),
            };
            let scale = match options.scale {
                ColourScale::Linear => "linear".to_string(),
                ColourScale::Log { .. } => "log".to_string(),
            };
            let style = TextStyle::from((FAMILY, 14).into_font()).color(&BLACK);
            root.draw(&Text::new(
                format!("{unit}, {scale}"),
                (pic_w as i32 + 8, 8),
                style.clone(),
            ))
            .map_err(|e| draw_error(&e))?;
            for k in 0..=divisions {
                let t = f64::from(k) / f64::from(divisions);
                let value = match options.scale {
                    ColourScale::Linear => t * maximum,
                    ColourScale::Log { decades } => maximum * 10f64.powf((t - 1.0) * decades),
                };
                let y = bar_bottom - (t * f64::from(span)) as i32;
                root.draw(&Text::new(
                    legend_label(value),
                    (bar_x + bar_w + 6, y),
                    style.clone().pos(Pos::new(HPos::Left, VPos::Center)),
                ))
                .map_err(|e| draw_error(&e))?;
                root.draw(&PathElement::new(
                    vec![(bar_x + bar_w, y), (bar_x + bar_w + 4, y)],
                    BLACK,
                ))
                .map_err(|e| draw_error(&e))?;
            }
        }
        root.present().map_err(|e| draw_error(&e))?;
    }
    Ok(FalsecolourOutcome {
        maximum,
        text,
        width_px: total_w,
        height_px: total_h,
    })
}
