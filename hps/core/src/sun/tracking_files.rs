//! The files `skylux sun` writes: `sun.csv`, one row per capture, and `sun.png`.

use super::position::angle_between_deg;
use super::tracking::{DniSource, SunTrack, TrackingError};
use crate::camera::alt_az_from_direction;
use crate::output::plot::{panels_png, Frame, Panel, Series};
use crate::output::write_atomic;
use chrono::Timelike;
use glam::DVec3;
use std::path::Path;

fn opt(v: Option<f64>, decimals: usize) -> String {
    match v {
        Some(v) if v.is_finite() => format!("{v:.decimals$}"),
        _ => String::new(),
    }
}

fn sci(v: Option<f64>) -> String {
    match v {
        Some(v) if v.is_finite() => format!("{v:.6e}"),
        _ => String::new(),
    }
}

/// The header of `sun.csv`.
pub const CSV_HEADER: &str = "time,capture,measured_altitude_deg,measured_azimuth_deg,\
spa_altitude_deg,spa_azimuth_deg,error_deg,image_x_px,image_y_px,disk_luminance_cd_m2,dni_lux,\
dni_source,pyranometer_dni_w_m2,pyranometer_dni_lux,fitted_altitude_deg,fitted_azimuth_deg,\
fitted_error_deg,flags,note";

/// `sun.csv`: one row per capture. Measured angles are through the declared camera; the
/// `fitted_*` columns through the fitted one (empty without a fit). `flags` lists the
/// extraction's flags separated by `;`, or `no_sun:<reason>`; `note` says it in words.
pub fn csv_text(tracks: &[SunTrack], fitted: Option<&[Option<DVec3>]>) -> String {
    let mut s = String::from(CSV_HEADER);
    s.push('\n');
    for (i, t) in tracks.iter().enumerate() {
        let (spa_alt, spa_az) = alt_az_from_direction(t.spa_direction);
        let measured = t.measured_direction.map(alt_az_from_direction);
        let fit_dir = fitted.and_then(|f| f.get(i).copied().flatten());
        let fit = fit_dir.map(alt_az_from_direction);
        let mut flags: Vec<String> = t.flags.iter().map(|f| f.name().to_string()).collect();
        if let Some(tag) = t.no_sun {
            flags.push(format!("no_sun:{tag}"));
        }
        let capture = t
            .capture_dir
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let fields = [
            t.time.to_rfc3339(),
            quote(&capture),
            opt(measured.map(|m| m.0), 5),
            opt(measured.map(|m| m.1), 5),
            format!("{spa_alt:.5}"),
            format!("{spa_az:.5}"),
            opt(t.error_deg(), 5),
            opt(t.image_point.map(|p| p.x_px), 3),
            opt(t.image_point.map(|p| p.y_px), 3),
            sci(t.disk_luminance_cd_m2),
            opt(t.dni_lux, 1),
            t.dni_source.as_str().into(),
            opt(t.pyranometer.as_ref().map(|p| p.dni_w_m2), 2),
            opt(t.pyranometer.as_ref().map(|p| p.dni_lux), 1),
            opt(fit.map(|m| m.0), 5),
            opt(fit.map(|m| m.1), 5),
            opt(fit_dir.map(|d| angle_between_deg(d, t.spa_direction)), 5),
            flags.join(";"),
            quote(t.note.as_deref().unwrap_or("")),
        ];
        s.push_str(&fields.join(","));
        s.push('\n');
    }
    s
}

/// A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
fn quote(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// Writes `sun.csv` atomically.
pub fn write_csv(
    path: &Path,
    tracks: &[SunTrack],
    fitted: Option<&[Option<DVec3>]>,
) -> Result<(), TrackingError> {
    write_atomic(path, csv_text(tracks, fitted).as_bytes())?;
    Ok(())
}

/// Hours since local midnight of the first capture's day (in the first capture's offset), so
/// a day reads as clock time and later days continue past 24.
fn hours_axis(tracks: &[SunTrack]) -> Vec<f64> {
    let Some(first) = tracks.first() else {
        return vec![];
    };
    let offset = *first.time.offset();
    let midnight = first
        .time
        .with_hour(0)
        .and_then(|t| t.with_minute(0))
        .and_then(|t| t.with_second(0))
        .and_then(|t| t.with_nanosecond(0))
        .unwrap_or(first.time);
    tracks
        .iter()
        .map(|t| (t.time.with_timezone(&offset) - midnight).num_seconds() as f64 / 3600.0)
        .collect()
}

/// `sun.png`: disk luminance, altitude and azimuth against time, measured and reference (SPA;
/// the pyranometer's DNI for the luminance), and the angle between measured and SPA sun, one
/// panel each; the fitted camera's angles too when `fitted` is given. Lines break between
/// days and where there is no reference.
pub fn write_plot(
    path: &Path,
    title: &str,
    tracks: &[SunTrack],
    fitted: Option<&[Option<DVec3>]>,
) -> Result<(), TrackingError> {
    let plot = TrackPlot {
        hours: hours_axis(tracks),
        tracks,
        fitted,
    };
    let offset = tracks
        .first()
        .map(|t| t.time.offset().to_string())
        .unwrap_or_default();
    let frame = Frame {
        width_px: 900,
        height_px: 1200,
        ..Frame::new(title, &format!("local time (h, UTC{offset})"), "")
    };
    panels_png(
        path,
        &frame,
        &[
            plot.luminance_panel(),
            plot.angle_panel("altitude (deg)", SunAngle::Altitude),
            plot.angle_panel("azimuth (deg)", SunAngle::Azimuth),
            plot.error_panel(),
        ],
    )?;
    Ok(())
}

/// Which of the sun's angles a panel shows.
#[derive(Clone, Copy)]
enum SunAngle {
    Altitude,
    Azimuth,
}

impl SunAngle {
    fn of(self, d: DVec3) -> f64 {
        let (alt, az) = alt_az_from_direction(d);
        match self {
            SunAngle::Altitude => alt,
            SunAngle::Azimuth => az,
        }
    }
}

/// The tracks against local hours, and the fitted camera's directions if any.
struct TrackPlot<'a> {
    hours: Vec<f64>,
    tracks: &'a [SunTrack],
    fitted: Option<&'a [Option<DVec3>]>,
}

type TrackValue<'f> = &'f dyn Fn(usize, &SunTrack) -> Option<f64>;

impl TrackPlot<'_> {
    /// Points where `f` has a value.
    fn series(&self, label: &str, f: TrackValue) -> Series {
        Series {
            label: label.into(),
            points: self
                .tracks
                .iter()
                .enumerate()
                .filter_map(|(i, t)| f(i, t).map(|v| (self.hours[i], v)))
                .collect(),
        }
    }

    /// A line through every capture, broken where `f` has no value and across nights.
    fn line(&self, label: &str, f: TrackValue) -> Series {
        Series {
            label: label.into(),
            points: with_night_breaks(
                self.tracks
                    .iter()
                    .enumerate()
                    .map(|(i, t)| (self.hours[i], f(i, t).unwrap_or(f64::NAN)))
                    .collect(),
            ),
        }
    }

    fn fitted_direction(&self, i: usize) -> Option<DVec3> {
        self.fitted.and_then(|f| f.get(i).copied().flatten())
    }

    fn luminance_panel(&self) -> Panel {
        let mut luminance = Panel {
            y_label: "disk luminance (Gcd/m2)".into(),
            lines: vec![self.line("pyranometer DNI / disk", &|_, t| {
                t.reference_luminance_cd_m2().map(|l| l / 1e9)
            })],
            points: vec![self.series("map", &|_, t| {
                (t.dni_source == DniSource::Map)
                    .then_some(t.disk_luminance_cd_m2)
                    .flatten()
                    .map(|l| l / 1e9)
            })],
        };
        if self
            .tracks
            .iter()
            .any(|t| t.dni_source == DniSource::Pyranometer)
        {
            luminance
                .points
                .push(self.series("saturated: pyranometer", &|_, t| {
                    (t.dni_source == DniSource::Pyranometer)
                        .then_some(t.disk_luminance_cd_m2)
                        .flatten()
                        .map(|l| l / 1e9)
                }));
        }
        luminance
    }

    fn angle_panel(&self, label: &str, angle: SunAngle) -> Panel {
        let mut p = Panel {
            y_label: label.into(),
            lines: vec![self.line("SPA", &|_, t| Some(angle.of(t.spa_direction)))],
            points: vec![self.series("measured, declared camera", &|_, t| {
                t.measured_direction.map(|d| angle.of(d))
            })],
        };
        if self.fitted.is_some() {
            p.points
                .push(self.series("measured, fitted camera", &|i, _| {
                    self.fitted_direction(i).map(|d| angle.of(d))
                }));
        }
        p
    }

    fn error_panel(&self) -> Panel {
        let mut error = Panel {
            y_label: "angle to SPA's sun (deg)".into(),
            lines: vec![self.line("SPA", &|_, _| Some(0.0))],
            points: vec![self.series("declared camera", &|_, t| t.error_deg())],
        };
        if self.fitted.is_some() {
            error.points.push(self.series("fitted camera", &|i, t| {
                self.fitted_direction(i)
                    .map(|d| angle_between_deg(d, t.spa_direction))
            }));
        }
        error
    }
}

/// A NaN between captures more than 8 hours apart breaks reference lines across nights.
fn with_night_breaks(points: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(points.len());
    for p in points {
        if out
            .last()
            .is_some_and(|q: &(f64, f64)| p.0 - q.0 > 8.0 && q.0.is_finite())
        {
            out.push((f64::NAN, f64::NAN));
        }
        out.push(p);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use chrono::{DateTime, FixedOffset};
    use std::path::PathBuf;

    fn time(text: &str) -> DateTime<FixedOffset> {
        DateTime::parse_from_rfc3339(text).unwrap()
    }

    #[test]
    fn csv_quotes_and_tags() {
        let t = SunTrack {
            time: time("2017-05-08T12:00:00+02:00"),
            capture_dir: PathBuf::from("captures/a,b"),
            spa_direction: DVec3::new(0.0, -0.5, 0.8).normalize(),
            measured_direction: None,
            image_point: None,
            disk_luminance_cd_m2: None,
            dni_lux: None,
            dni_source: DniSource::None,
            pyranometer: None,
            flags: vec![],
            no_sun: Some("below_threshold"),
            note: Some("no group reaches \"5e8\", no sun".into()),
        };
        let text = csv_text(&[t], None);
        let line = text.lines().nth(1).unwrap();
        assert!(line.contains("\"a,b\""), "{line}");
        assert!(line.contains(",none,"), "{line}");
        assert!(line.contains("no_sun:below_threshold"), "{line}");
        assert!(
            line.ends_with("\"no group reaches \"\"5e8\"\", no sun\""),
            "{line}"
        );
        assert_eq!(
            text.lines().next().unwrap().split(',').count(),
            line.split(',').count() - 2 // the two quoted commas
        );
    }
}
