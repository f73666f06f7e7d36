//! `luxmeters.csv` (shared/spec/campaign.md): `time,sensor,lux`, one reading per line; an
//! empty `lux` is a gap, skipped and counted, never read as zero.

use chrono::{DateTime, FixedOffset, SecondsFormat};
use std::path::{Path, PathBuf};

/// One lux-meter reading.
#[derive(Clone, Debug, PartialEq)]
pub struct LuxmeterReading {
    pub time: DateTime<FixedOffset>,
    pub sensor: String,
    pub illuminance_lux: f64,
}

/// Why `luxmeters.csv` could not be read; names the file and line.
#[derive(Debug, thiserror::Error)]
pub enum LuxmeterError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}:{line}: {reason}")]
    Line {
        path: PathBuf,
        line: usize,
        reason: String,
    },
}

/// Reads the file; returns the readings and the number of gaps.
pub fn read_luxmeters(path: &Path) -> Result<(Vec<LuxmeterReading>, usize), LuxmeterError> {
    let bytes = std::fs::read(path).map_err(|source| LuxmeterError::Io {
        path: path.into(),
        source,
    })?;
    parse_luxmeters(path, &String::from_utf8_lossy(&bytes))
}

/// Parses `luxmeters.csv` text; `path` names it in errors. Columns are found by their
/// header names; other columns are ignored.
pub fn parse_luxmeters(
    path: &Path,
    text: &str,
) -> Result<(Vec<LuxmeterReading>, usize), LuxmeterError> {
    let err = |line: usize, reason: String| LuxmeterError::Line {
        path: path.into(),
        line,
        reason,
    };
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (hl, header) = lines.next().ok_or_else(|| {
        err(
            1,
            "empty file: expected the header `time,sensor,lux`".into(),
        )
    })?;
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let col = |n: &str| {
        names
            .iter()
            .position(|c| *c == n)
            .ok_or_else(|| err(hl, format!("no `{n}` column in the header `{header}`")))
    };
    let (tc, sc, lc) = (col("time")?, col("sensor")?, col("lux")?);
    let mut readings = Vec::new();
    let mut gaps = 0;
    for (line, text) in lines {
        let fields: Vec<&str> = text.split(',').map(str::trim).collect();
        if fields.len() != names.len() {
            return Err(err(
                line,
                format!("{} fields, the header has {}", fields.len(), names.len()),
            ));
        }
        let time = DateTime::parse_from_rfc3339(fields[tc]).map_err(|e| {
            err(
                line,
                format!("time `{}` is not RFC 3339 with an offset: {e}", fields[tc]),
            )
        })?;
        let sensor = fields[sc];
        if sensor.is_empty() {
            return Err(err(line, "empty sensor name".into()));
        }
        if fields[lc].is_empty() {
            gaps += 1;
            continue;
        }
        let lux: f64 = fields[lc]
            .parse()
            .map_err(|_| err(line, format!("lux `{}` is not a number", fields[lc])))?;
        if !lux.is_finite() || lux < 0.0 {
            return Err(err(
                line,
                format!("lux {lux} must be finite and not negative"),
            ));
        }
        readings.push(LuxmeterReading {
            time,
            sensor: sensor.to_string(),
            illuminance_lux: lux,
        });
    }
    Ok((readings, gaps))
}

/// Writes readings as `luxmeters.csv`.
pub fn write_luxmeters<W: std::io::Write>(
    out: &mut W,
    readings: &[LuxmeterReading],
) -> std::io::Result<()> {
    writeln!(out, "time,sensor,lux")?;
    for r in readings {
        writeln!(
            out,
            "{},{},{}",
            r.time.to_rfc3339_opts(SecondsFormat::AutoSi, false),
            r.sensor,
            r.illuminance_lux
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn reads_gaps_and_names_bad_lines() {
        let p = Path::new("luxmeters.csv");
        let (r, gaps) = parse_luxmeters(
            p,
            "time,sensor,lux\n2017-05-08T10:00:00+02:00,S1,10234.5\n2017-05-08T10:00:00+02:00,S2,\n",
        )
        .unwrap();
        assert_eq!((r.len(), gaps), (1, 1));
        assert_eq!(r[0].illuminance_lux, 10234.5);
        let e = parse_luxmeters(p, "time,sensor,lux\n2017-05-08T10:00:00+02:00,S1,abc\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("luxmeters.csv:2") && e.contains("abc"), "{e}");
        let e = parse_luxmeters(p, "time,lux\n").unwrap_err().to_string();
        assert!(e.contains("sensor"), "{e}");
        let e = parse_luxmeters(p, "time,sensor,lux\n2017-05-08 10:00,S1,1\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("RFC 3339"), "{e}");
    }

    #[test]
    fn round_trips() {
        let readings = vec![LuxmeterReading {
            time: DateTime::parse_from_rfc3339("2017-05-08T10:00:00+02:00").unwrap(),
            sensor: "S3".into(),
            illuminance_lux: 123.456,
        }];
        let mut out = Vec::new();
        write_luxmeters(&mut out, &readings).unwrap();
        let (back, _) = parse_luxmeters(Path::new("x"), &String::from_utf8(out).unwrap()).unwrap();
        assert_eq!(back, readings);
    }

    proptest! {
        /// Any text: an answer or an error, never a panic.
        #[test]
        fn never_panics(text in "\\PC{0,200}") {
            let _ = parse_luxmeters(Path::new("fuzz.csv"), &text);
        }
        #[test]
        fn never_panics_on_near_valid(lines in proptest::collection::vec("[0-9T:+.,S-]{0,40}", 0..6)) {
            let text = format!("time,sensor,lux\n{}", lines.join("\n"));
            let _ = parse_luxmeters(Path::new("fuzz.csv"), &text);
        }
    }
}
