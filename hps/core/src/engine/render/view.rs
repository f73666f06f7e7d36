//! RADIANCE's views (src/common/image.c): the same options (`-vt{v,h,a}`, `-vp`, `-vd`,
//! `-vu`, `-vh`, `-vv`, `-vs`, `-vl`, `-vo`), the same image vectors (`setview`), the same ray
//! per image position (`viewray`) and the same resolution fitting (`normaspect` with square
//! pixels, rpict's default `-pa 1`), so that a view file written for rpict frames the same
//! picture and `vwrays` gives the same rays.

use crate::engine::ray::{Ray, FTINY};
use glam::DVec3;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

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
        self.with_file_bytes(path, &bytes)
    }

    /// [`Self::with_file`] on a view file's bytes; `path` names it in errors.
    pub fn with_file_bytes(self, path: &Path, bytes: &[u8]) -> Result<View, ViewError> {
        // A picture's header ends at its first blank line; a text file has none before EOF
        // or only trailing ones.
        let text = String::from_utf8_lossy(bytes);
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

    /// RADIANCE's `viewloc`, the inverse of [`PreparedView::ray`]: the image position
    /// (x, y), both in [0, 1] inside the image, at which a ray from the view point in
    /// `direction` lands; None when the view cannot show that direction (behind a perspective
    /// or hemispherical view, beyond an angular fisheye's circle, or a zero direction).
    /// Positions outside [0, 1] are directions beside the image.
    pub fn locate(&self, direction: DVec3) -> Option<(f64, f64)> {
        let v = &self.view;
        let d = direction.try_normalize()?;
        let along = d.dot(self.direction);
        let (h, vert) = (d.dot(self.hvec) / self.hn2, d.dot(self.vvec) / self.vn2);
        let (x, y) = match v.kind {
            ViewType::Perspective => {
                if along <= FTINY {
                    return None;
                }
                (h / along, vert / along)
            }
            ViewType::Hemispherical => {
                if along < 0.0 {
                    return None;
                }
                (h, vert)
            }
            ViewType::Angular => {
                // setview leaves an angular view's image vectors unit: ray() gives
                // sin(πr) = |(d · hvec, d · vvec)| and cos(πr) = d · direction.
                let (h, vert) = (d.dot(self.hvec), d.dot(self.vvec));
                let r = along.clamp(-1.0, 1.0).acos() / PI;
                let sine = (h * h + vert * vert).sqrt();
                let s = if sine <= FTINY { 1.0 / PI } else { r / sine };
                let (x, y) = (
                    h * s * 180.0 / v.horizontal_deg,
                    vert * s * 180.0 / v.vertical_deg,
                );
                if (x * v.horizontal_deg / 180.0).powi(2) + (y * v.vertical_deg / 180.0).powi(2)
                    > 1.0 + 1e-9
                {
                    return None;
                }
                (x, y)
            }
        };
        Some((x + 0.5 - v.shift, y + 0.5 - v.lift))
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
