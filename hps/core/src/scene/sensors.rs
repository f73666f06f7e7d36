//! Virtual sensor points: RADIANCE `.pts` files, as `rtrace` reads them.
//!
//! One sensor per line, `x y z dx dy dz` (position in metres, then the direction the sensor
//! faces). Lines that are blank or start with `#` are skipped, and a `#` ends a line. Sensors
//! are named `S1`, `S2`, ... in line order (campaign format, shared/spec/campaign.md).

use super::error::{line_of_offset, SourceLocation};
use super::shape::unit_vector;
use glam::DVec3;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// One virtual sensor.
#[derive(Clone, Debug, PartialEq)]
pub struct Sensor {
    /// `S1`, `S2`, ... in the order of the file's sensor lines.
    pub name: String,
    /// Where the sensor is, in the world frame.
    pub position_m: DVec3,
    /// Unit vector the sensor faces (the normal of its cosine-weighted hemisphere).
    pub direction: DVec3,
    /// The line it comes from.
    pub origin: SourceLocation,
}

/// Why a sensors file could not be read. Each variant from the text names the file and line.
#[derive(Debug, thiserror::Error)]
pub enum SensorsError {
    #[error("cannot read sensors file {}: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },

    #[error("{at}: not UTF-8 text (invalid byte sequence on this line); expected `x y z dx dy dz` lines")]
    NotUtf8 { at: SourceLocation },

    #[error("{at}: found {found} values; expected 6 (x y z dx dy dz)")]
    FieldCount { at: SourceLocation, found: usize },

    #[error("{at}: {field} is `{token}`; expected a finite number")]
    BadNumber {
        at: SourceLocation,
        field: &'static str,
        token: String,
    },

    #[error("{at}: direction (dx dy dz) is ({dx} {dy} {dz}); expected a non-zero vector")]
    ZeroDirection {
        at: SourceLocation,
        dx: f64,
        dy: f64,
        dz: f64,
    },

    #[error("{}: no sensor lines; expected at least one `x y z dx dy dz` line", path.display())]
    NoSensors { path: PathBuf },
}

const FIELDS: [&str; 6] = ["x", "y", "z", "dx", "dy", "dz"];

/// Reads a `.pts` file.
pub fn load_sensors(path: impl AsRef<Path>) -> Result<Vec<Sensor>, SensorsError> {
    let path = path.as_ref();
    let bytes = std::fs::read(path).map_err(|source| SensorsError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_sensors(path, &bytes)
}

/// Reads `.pts` text; `label` names it in errors and in each sensor's origin.
pub fn parse_sensors(label: impl AsRef<Path>, bytes: &[u8]) -> Result<Vec<Sensor>, SensorsError> {
    let file: Arc<Path> = Arc::from(label.as_ref());
    let at = |line: usize| SourceLocation {
        file: file.clone(),
        line,
    };
    let text = std::str::from_utf8(bytes).map_err(|e| SensorsError::NotUtf8 {
        at: at(line_of_offset(bytes, e.valid_up_to())),
    })?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut sensors = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let line_number = index + 1;
        let content = line.split('#').next().unwrap_or("");
        let words: Vec<&str> = content.split_ascii_whitespace().collect();
        if words.is_empty() {
            continue;
        }
        if words.len() != FIELDS.len() {
            return Err(SensorsError::FieldCount {
                at: at(line_number),
                found: words.len(),
            });
        }
        let mut values = [0.0_f64; 6];
        for ((value, word), field) in values.iter_mut().zip(&words).zip(FIELDS) {
            *value = word
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| SensorsError::BadNumber {
                    at: at(line_number),
                    field,
                    token: word.to_string(),
                })?;
        }
        let [x, y, z, dx, dy, dz] = values;
        let direction =
            unit_vector(DVec3::new(dx, dy, dz)).ok_or_else(|| SensorsError::ZeroDirection {
                at: at(line_number),
                dx,
                dy,
                dz,
            })?;
        sensors.push(Sensor {
            name: format!("S{}", sensors.len() + 1),
            position_m: DVec3::new(x, y, z),
            direction,
            origin: at(line_number),
        });
    }
    if sensors.is_empty() {
        return Err(SensorsError::NoSensors {
            path: file.to_path_buf(),
        });
    }
    Ok(sensors)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_and_blank_lines_do_not_take_a_name() {
        let text = "# header\n\n1 2 3 0 0 2\n  # note\n4 5 6 1 0 0 # east\r\n";
        let s = parse_sensors("a.pts", text.as_bytes()).unwrap();
        assert_eq!(s.len(), 2);
        assert_eq!(s[0].name, "S1");
        assert_eq!(s[0].direction, DVec3::Z);
        assert_eq!(s[0].origin.line, 3);
        assert_eq!(s[1].name, "S2");
        assert_eq!(s[1].position_m, DVec3::new(4.0, 5.0, 6.0));
        assert_eq!(s[1].origin.line, 5);
    }

    #[test]
    fn errors_name_file_line_and_field() {
        let cases: [(&str, &str); 5] = [
            ("1 2 3 0 0\n", "a.pts:1: found 5 values"),
            ("\n1 2 3 0 0 1 7\n", "a.pts:2: found 7 values"),
            ("1 2 x 0 0 1\n", "a.pts:1: z is `x`"),
            ("1 2 3 0 0 nan\n", "a.pts:1: dz is `nan`"),
            ("# c\n1 2 3 0 0 0\n", "a.pts:2: direction"),
        ];
        for (text, expected) in cases {
            let err = parse_sensors("a.pts", text.as_bytes()).unwrap_err();
            assert!(err.to_string().starts_with(expected), "{text:?}: {err}");
        }
        let err = parse_sensors("a.pts", b"# nothing\n").unwrap_err();
        assert!(matches!(err, SensorsError::NoSensors { .. }), "{err}");
        let err = parse_sensors("a.pts", b"1 2 3 0 0 1\n\xff\n").unwrap_err();
        assert!(err.to_string().starts_with("a.pts:2:"), "{err}");
    }
}
