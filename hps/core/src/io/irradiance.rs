//! Measured irradiance records: readers for the real station files (NOAA SURFRAD and NREL MIDC
//! one-minute CSVs, `shared/data/irradiance/`) and the campaign's `pyranometer.csv`
//! (campaign.md), and a writer for the latter.
//!
//! What the station files do, and how the reader answers:
//! - **Stamps.** A stamp names one instant of an averaging interval: its start, centre or end.
//!   Which one is the caller's explicit choice ([`StampConvention`]); nothing is guessed. SURFRAD
//!   stamps the end (its column is even named `time_utc_interval_end`). Every record carries
//!   its interval in UTC, and [`IrradianceRecord::centre_utc`] is where the sun should be
//!   computed for an average.
//! - **Gaps.** An empty field, a `NaN`, or a missing-value sentinel (SURFRAD writes −9999.9;
//!   anything ≤ [`MISSING_SENTINEL_MAX_WM2`]) is `None`, never zero, and is counted. Absent
//!   minutes between rows are counted too.
//! - **Quality flags.** SURFRAD follows the BSRN philosophy: flag 0 is good, > 0 failed a QC
//!   level, and the value is kept in the file. [`FlaggedValues`] decides whether a flagged value
//!   becomes a gap (the default) or is kept; the flag itself is always in the record.
//! - **Night.** Thermopile pyranometers read slightly negative at night (thermal offset, a few
//!   W/m²; the MIDC file reads about −7.7 W/m²). These are measurements, not gaps: they are kept
//!   as read unless [`NegativeIrradiance::ClampToZero`] is chosen, and counted either way.
//!
//! Errors name the file, the line (1-based) and the field. The readers never panic on any
//! input (`tests/irradiance_records.rs` fuzzes them).

use chrono::{DateTime, FixedOffset, SecondsFormat, TimeDelta, Utc};
use std::path::Path;

/// Values at or below this are missing-value sentinels, not measurements: SURFRAD writes
/// −9999.9 for missing data (SURFRAD README), and no thermopile offset comes near −999 W/m².
pub const MISSING_SENTINEL_MAX_WM2: f64 = -999.0;

/// Which instant of its averaging interval a record's stamp refers to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StampConvention {
    IntervalStart,
    IntervalCentre,
    IntervalEnd,
}

impl StampConvention {
    /// The interval `[start, end)` that `stamp` denotes under this convention; `None` if it
    /// would leave chrono's date range.
    pub fn interval(
        self,
        stamp: DateTime<Utc>,
        length: TimeDelta,
    ) -> Option<(DateTime<Utc>, DateTime<Utc>)> {
        let start = match self {
            StampConvention::IntervalStart => stamp,
            StampConvention::IntervalCentre => stamp.checked_sub_signed(length / 2)?,
            StampConvention::IntervalEnd => stamp.checked_sub_signed(length)?,
        };
        Some((start, start.checked_add_signed(length)?))
    }
}

/// What to do with a value whose quality flag is not 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FlaggedValues {
    /// The value becomes a gap (`None`) and is counted.
    Drop,
    /// The value is kept; the flag stays in the record.
    Keep,
}

/// What to do with negative irradiance (night-time thermal offset).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NegativeIrradiance {
    /// Keep the value as measured.
    Keep,
    /// Replace it by 0 W/m² (a measured "no sun", not a gap).
    ClampToZero,
}

/// How to read a station file. The stamp convention and interval have no default on purpose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReadOptions {
    pub stamp: StampConvention,
    /// Length of the averaging interval (one minute for both station files).
    pub interval: TimeDelta,
    pub flagged: FlaggedValues,
    pub negative: NegativeIrradiance,
}

impl ReadOptions {
    /// The given convention and interval; flagged values dropped, negative values kept.
    pub fn new(stamp: StampConvention, interval: TimeDelta) -> Self {
        Self {
            stamp,
            interval,
            flagged: FlaggedValues::Drop,
            negative: NegativeIrradiance::Keep,
        }
    }
}

/// The station file layouts this module reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RecordFormat {
    /// NOAA SURFRAD daily file as CSV: `time_*`, `file_solar_zenith_deg`, `ghi`, `dni`, `dhi`
    /// each with a `*_flag`, optional `temp_air`, `pressure` (hPa) with flags.
    Surfrad,
    /// NREL MIDC export: `time_*`, `Global* [W/m^2]`, optional `Direct* [W/m^2]`,
    /// `Diffuse* [W/m^2]`, `Temperature* [deg C]`, `*Pressure* [mBar]`. No flags, no zenith.
    Midc,
}

/// Quality flags as written in the file; `None` where the file has no flag for that value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QualityFlags {
    pub ghi: Option<u16>,
    pub dhi: Option<u16>,
    pub dni: Option<u16>,
}

/// One averaging interval of a station file.
#[derive(Clone, Debug, PartialEq)]
pub struct IrradianceRecord {
    /// Line in the file, 1-based.
    pub line: usize,
    /// The stamp as written, with its offset.
    pub stamp: DateTime<FixedOffset>,
    pub interval_start_utc: DateTime<Utc>,
    pub interval_end_utc: DateTime<Utc>,
    /// Global horizontal irradiance; `None` for a gap (or a dropped flagged value).
    pub ghi_wm2: Option<f64>,
    /// Diffuse horizontal irradiance.
    pub dhi_wm2: Option<f64>,
    /// Direct normal irradiance.
    pub dni_wm2: Option<f64>,
    pub flags: QualityFlags,
    /// The file's own solar zenith, where the format has one (SURFRAD).
    pub file_zenith_deg: Option<f64>,
    pub air_temperature_c: Option<f64>,
    /// Station pressure.
    pub pressure_hpa: Option<f64>,
}

impl IrradianceRecord {
    /// Middle of the averaging interval: where the sun is for an average over it.
    pub fn centre_utc(&self) -> DateTime<Utc> {
        self.interval_start_utc + (self.interval_end_utc - self.interval_start_utc) / 2
    }
}

/// Per-channel counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChannelCounts {
    pub ghi: usize,
    pub dhi: usize,
    pub dni: usize,
}

/// Which irradiance channels the file has at all.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Channels {
    pub ghi: bool,
    pub dhi: bool,
    pub dni: bool,
}

/// What the reader met on the way, for the report (gaps are counted, never hidden).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ReadSummary {
    pub rows: usize,
    /// Values missing in the file (empty, NaN, sentinel), in channels the file has.
    pub gaps: ChannelCounts,
    /// Flagged values turned into gaps ([`FlaggedValues::Drop`]).
    pub flagged_dropped: ChannelCounts,
    /// Flagged values kept ([`FlaggedValues::Keep`]).
    pub flagged_kept: ChannelCounts,
    /// Negative values met (kept or clamped, per [`NegativeIrradiance`]).
    pub negative: ChannelCounts,
    /// Whole intervals absent between consecutive rows.
    pub missing_intervals: u64,
    /// Steps between rows that are not a whole number of intervals (a wrong `interval`?).
    pub irregular_steps: usize,
    /// Header columns this reader does not use.
    pub ignored_columns: Vec<String>,
}

/// A whole station file.
#[derive(Clone, Debug, PartialEq)]
pub struct IrradianceSeries {
    /// The file it came from, as given.
    pub source: String,
    pub format: RecordFormat,
    pub channels: Channels,
    pub records: Vec<IrradianceRecord>,
    pub summary: ReadSummary,
}

/// Why a file could not be read; each names the file, and the line and field where it applies.
#[derive(Debug, thiserror::Error)]
pub enum IrradianceError {
    #[error("{file}: {source}")]
    Io {
        file: String,
        #[source]
        source: std::io::Error,
    },
    #[error("{file} line {line}: not UTF-8 text")]
    NotUtf8 { file: String, line: usize },
    #[error("{file}: no header line")]
    Empty { file: String },
    #[error("{file} line {line}: header is neither SURFRAD (time_*, ghi, ghi_flag, ...) nor MIDC (time_*, Global* [W/m^2], ...)")]
    UnknownFormat { file: String, line: usize },
    #[error("{file} line {line}: required column {column:?} is missing from the header")]
    MissingColumn {
        file: String,
        line: usize,
        column: String,
    },
    #[error("{file} line {line}: {found} fields, the header has {expected}")]
    FieldCount {
        file: String,
        line: usize,
        found: usize,
        expected: usize,
    },
    #[error("{file} line {line}, field {field:?}: {value:?} is not {expected}")]
    Field {
        file: String,
        line: usize,
        field: String,
        value: String,
        expected: &'static str,
    },
    #[error("{file} line {line}, field {field:?}: stamp {stamp} is not after the previous row's")]
    Order {
        file: String,
        line: usize,
        field: String,
        stamp: String,
    },
    #[error("read options: the averaging interval must be between 1 ms and 1 day, not {interval}")]
    Interval { interval: TimeDelta },
}

/// Reads a SURFRAD or MIDC CSV file (the format is recognised from its header).
pub fn read_irradiance_file(
    path: &Path,
    options: &ReadOptions,
) -> Result<IrradianceSeries, IrradianceError> {
    let name = path.display().to_string();
    let text = read_text(path, &name)?;
    parse_irradiance_csv(&name, &text, options)
}

/// Parses the text of a SURFRAD or MIDC CSV file; `file` only names it in errors.
pub fn parse_irradiance_csv(
    file: &str,
    text: &str,
    options: &ReadOptions,
) -> Result<IrradianceSeries, IrradianceError> {
    if options.interval < TimeDelta::milliseconds(1) || options.interval > TimeDelta::days(1) {
        return Err(IrradianceError::Interval {
            interval: options.interval,
        });
    }
    let mut lines = data_lines(text);
    let (header_line, header) = lines.next().ok_or_else(|| IrradianceError::Empty {
        file: file.to_string(),
    })?;
    let layout = Layout::from_header(file, header_line, header)?;
    let mut series = IrradianceSeries {
        source: file.to_string(),
        format: layout.format,
        channels: Channels {
            ghi: layout.ghi.is_some(),
            dhi: layout.dhi.is_some(),
            dni: layout.dni.is_some(),
        },
        records: Vec::new(),
        summary: ReadSummary {
            ignored_columns: layout.ignored.clone(),
            ..ReadSummary::default()
        },
    };
    let interval_ms = options.interval.num_milliseconds();
    let mut previous: Option<(DateTime<Utc>, DateTime<Utc>)> = None; // (stamp, interval end)
    for (line, text) in lines {
        let fields: Vec<&str> = text.split(',').collect();
        if fields.len() != layout.names.len() {
            return Err(IrradianceError::FieldCount {
                file: file.to_string(),
                line,
                found: fields.len(),
                expected: layout.names.len(),
            });
        }
        let ctx = LineContext {
            file,
            line,
            fields: &fields,
            names: &layout.names,
        };
        let stamp_text = fields[layout.time];
        let stamp = DateTime::parse_from_rfc3339(stamp_text.trim()).map_err(|_| {
            ctx.field_error(
                layout.time,
                "an ISO 8601 / RFC 3339 time with an explicit UTC offset",
            )
        })?;
        let stamp_utc = stamp.with_timezone(&Utc);
        let (start, end) = options
            .stamp
            .interval(stamp_utc, options.interval)
            .ok_or_else(|| ctx.field_error(layout.time, "a time within chrono's range"))?;
        if let Some((prev_stamp, prev_end)) = previous {
            if stamp_utc <= prev_stamp {
                return Err(IrradianceError::Order {
                    file: file.to_string(),
                    line,
                    field: layout.names[layout.time].clone(),
                    stamp: stamp_text.trim().to_string(),
                });
            }
            let step_ms = (start - prev_end).num_milliseconds();
            if step_ms != 0 {
                if step_ms > 0 && step_ms % interval_ms == 0 {
                    series.summary.missing_intervals = series
                        .summary
                        .missing_intervals
                        .saturating_add((step_ms / interval_ms) as u64);
                } else {
                    series.summary.irregular_steps += 1;
                }
            }
        }
        previous = Some((stamp_utc, end));

        let mut flags = QualityFlags::default();
        let s = &mut series.summary;
        let ghi_wm2 = ctx.irradiance(
            layout.ghi,
            options,
            &mut flags.ghi,
            &mut s.gaps.ghi,
            &mut s.flagged_dropped.ghi,
            &mut s.flagged_kept.ghi,
            &mut s.negative.ghi,
        )?;
        let dhi_wm2 = ctx.irradiance(
            layout.dhi,
            options,
            &mut flags.dhi,
            &mut s.gaps.dhi,
            &mut s.flagged_dropped.dhi,
            &mut s.flagged_kept.dhi,
            &mut s.negative.dhi,
        )?;
        let dni_wm2 = ctx.irradiance(
            layout.dni,
            options,
            &mut flags.dni,
            &mut s.gaps.dni,
            &mut s.flagged_dropped.dni,
            &mut s.flagged_kept.dni,
            &mut s.negative.dni,
        )?;
        let file_zenith_deg = match layout.zenith {
            Some(i) => {
                let z = ctx.number(i)?;
                if let Some(z) = z {
                    if !(0.0..=180.0).contains(&z) {
                        return Err(ctx.field_error(i, "a zenith angle in [0, 180] degrees"));
                    }
                }
                z
            }
            None => None,
        };
        let air_temperature_c = ctx.ancillary(layout.temperature, options)?;
        let pressure_hpa = ctx.ancillary(layout.pressure, options)?;
        series.summary.rows += 1;
        series.records.push(IrradianceRecord {
            line,
            stamp,
            interval_start_utc: start,
            interval_end_utc: end,
            ghi_wm2,
            dhi_wm2,
            dni_wm2,
            flags,
            file_zenith_deg,
            air_temperature_c,
            pressure_hpa,
        });
    }
    Ok(series)
}

/// A value column and its flag column, if the format has one.
#[derive(Clone, Copy, Debug)]
struct Column {
    value: usize,
    flag: Option<usize>,
}

/// Where each quantity sits in a file, from its header.
struct Layout {
    format: RecordFormat,
    names: Vec<String>,
    time: usize,
    ghi: Option<Column>,
    dhi: Option<Column>,
    dni: Option<Column>,
    zenith: Option<usize>,
    temperature: Option<Column>,
    pressure: Option<Column>,
    ignored: Vec<String>,
}

impl Layout {
    fn from_header(file: &str, line: usize, header: &str) -> Result<Self, IrradianceError> {
        let names: Vec<String> = header.split(',').map(|n| n.trim().to_string()).collect();
        let find = |pred: &dyn Fn(&str) -> bool| names.iter().position(|n| pred(n));
        let exact = |name: &str| names.iter().position(|n| n == name);
        let missing = |column: &str| IrradianceError::MissingColumn {
            file: file.to_string(),
            line,
            column: column.to_string(),
        };
        let time = find(&|n| n.to_ascii_lowercase().starts_with("time"));
        let is_surfrad = exact("ghi_flag").is_some();
        let is_midc = find(&|n| n.starts_with("Global") && n.ends_with("[W/m^2]")).is_some();
        let mut layout = if is_surfrad {
            let flagged = |name: &str| -> Result<Column, IrradianceError> {
                Ok(Column {
                    value: exact(name).ok_or_else(|| missing(name))?,
                    flag: Some(
                        exact(&format!("{name}_flag"))
                            .ok_or_else(|| missing(&format!("{name}_flag")))?,
                    ),
                })
            };
            let optional = |name: &str| {
                exact(name).map(|value| Column {
                    value,
                    flag: exact(&format!("{name}_flag")),
                })
            };
            Layout {
                format: RecordFormat::Surfrad,
                time: time.ok_or_else(|| missing("time_*"))?,
                ghi: Some(flagged("ghi")?),
                dhi: Some(flagged("dhi")?),
                dni: Some(flagged("dni")?),
                zenith: exact("file_solar_zenith_deg").or_else(|| exact("solar_zenith")),
                temperature: optional("temp_air"),
                pressure: optional("pressure"),
                names: Vec::new(),
                ignored: Vec::new(),
            }
        } else if is_midc {
            let unflagged =
                |pred: &dyn Fn(&str) -> bool| find(pred).map(|value| Column { value, flag: None });
            let temperature =
                unflagged(&|n| n.starts_with("Temperature @ 2m") && n.ends_with("[deg C]"))
                    .or_else(|| {
                        unflagged(&|n| n.starts_with("Temperature") && n.ends_with("[deg C]"))
                    });
            Layout {
                format: RecordFormat::Midc,
                time: time.ok_or_else(|| missing("time_*"))?,
                ghi: unflagged(&|n| {
                    n.starts_with("Global") && n.ends_with("[W/m^2]") && !n.contains("Accumulated")
                }),
                dhi: unflagged(&|n| n.starts_with("Diffuse") && n.ends_with("[W/m^2]")),
                dni: unflagged(&|n| n.starts_with("Direct") && n.ends_with("[W/m^2]")),
                zenith: None,
                temperature,
                pressure: unflagged(&|n| n.contains("Pressure") && n.ends_with("[mBar]")),
                names: Vec::new(),
                ignored: Vec::new(),
            }
        } else {
            return Err(IrradianceError::UnknownFormat {
                file: file.to_string(),
                line,
            });
        };
        let mut used = vec![layout.time];
        used.extend(layout.zenith);
        for c in [
            layout.ghi,
            layout.dhi,
            layout.dni,
            layout.temperature,
            layout.pressure,
        ]
        .into_iter()
        .flatten()
        {
            used.push(c.value);
            used.extend(c.flag);
        }
        layout.ignored = names
            .iter()
            .enumerate()
            .filter(|(i, _)| !used.contains(i))
            .map(|(_, n)| n.clone())
            .collect();
        layout.names = names;
        Ok(layout)
    }
}

/// One data line being read, for values and for errors that name it.
struct LineContext<'a> {
    file: &'a str,
    line: usize,
    fields: &'a [&'a str],
    names: &'a [String],
}

impl LineContext<'_> {
    fn field_error(&self, index: usize, expected: &'static str) -> IrradianceError {
        IrradianceError::Field {
            file: self.file.to_string(),
            line: self.line,
            field: self.names.get(index).cloned().unwrap_or_default(),
            value: clip(self.fields.get(index).copied().unwrap_or_default()),
            expected,
        }
    }

    /// A number, or `None` for a gap (empty, NaN, sentinel). Infinity is an error.
    fn number(&self, index: usize) -> Result<Option<f64>, IrradianceError> {
        let text = self.fields.get(index).copied().unwrap_or_default().trim();
        if text.is_empty() {
            return Ok(None);
        }
        let v: f64 = text
            .parse()
            .map_err(|_| self.field_error(index, "a number or an empty field"))?;
        if v.is_nan() || v <= MISSING_SENTINEL_MAX_WM2 {
            Ok(None)
        } else if v.is_infinite() {
            Err(self.field_error(index, "a finite number"))
        } else {
            Ok(Some(v))
        }
    }

    fn flag(&self, index: Option<usize>) -> Result<Option<u16>, IrradianceError> {
        match index {
            None => Ok(None),
            Some(i) => {
                let text = self.fields.get(i).copied().unwrap_or_default().trim();
                text.parse::<u16>()
                    .map(Some)
                    .map_err(|_| self.field_error(i, "a quality flag (integer, 0 = good)"))
            }
        }
    }

    /// An irradiance value after gap, flag and night handling, with the counts kept.
    #[allow(clippy::too_many_arguments)]
    fn irradiance(
        &self,
        column: Option<Column>,
        options: &ReadOptions,
        flag_out: &mut Option<u16>,
        gaps: &mut usize,
        dropped: &mut usize,
        kept: &mut usize,
        negative: &mut usize,
    ) -> Result<Option<f64>, IrradianceError> {
        let Some(column) = column else {
            return Ok(None);
        };
        let value = self.number(column.value)?;
        let flag = self.flag(column.flag)?;
        *flag_out = flag;
        let Some(mut v) = value else {
            *gaps += 1;
            return Ok(None);
        };
        if flag.is_some_and(|f| f != 0) {
            match options.flagged {
                FlaggedValues::Drop => {
                    *dropped += 1;
                    return Ok(None);
                }
                FlaggedValues::Keep => *kept += 1,
            }
        }
        if v < 0.0 {
            *negative += 1;
            if options.negative == NegativeIrradiance::ClampToZero {
                v = 0.0;
            }
        }
        Ok(Some(v))
    }

    /// Temperature or pressure: a gap if missing or flagged (with [`FlaggedValues::Drop`]).
    fn ancillary(
        &self,
        column: Option<Column>,
        options: &ReadOptions,
    ) -> Result<Option<f64>, IrradianceError> {
        let Some(column) = column else {
            return Ok(None);
        };
        let value = self.number(column.value)?;
        let flag = self.flag(column.flag)?;
        if flag.is_some_and(|f| f != 0) && options.flagged == FlaggedValues::Drop {
            return Ok(None);
        }
        Ok(value)
    }
}

/// Keeps error messages short whatever the input.
fn clip(text: &str) -> String {
    const MAX_CHARS: usize = 60;
    if text.chars().count() <= MAX_CHARS {
        text.to_string()
    } else {
        let mut s: String = text.chars().take(MAX_CHARS).collect();
        s.push('…');
        s
    }
}

/// Numbered non-empty lines, without CR, BOM or `#` comment lines.
fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.split('\n')
        .enumerate()
        .map(|(i, l)| (i + 1, l.strip_suffix('\r').unwrap_or(l)))
        .filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'))
}

fn read_text(path: &Path, name: &str) -> Result<String, IrradianceError> {
    let bytes = std::fs::read(path).map_err(|source| IrradianceError::Io {
        file: name.to_string(),
        source,
    })?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        IrradianceError::NotUtf8 {
            file: name.to_string(),
            line: 1 + valid.iter().filter(|&&b| b == b'\n').count(),
        }
    })
}

// ---------------------------------------------------------------------------------------------
// campaign.md `pyranometer.csv`: time,ghi_wm2,dhi_wm2[,dni_wm2]

/// One row of the campaign's `pyranometer.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct PyranometerRow {
    pub time: DateTime<FixedOffset>,
    pub ghi_wm2: Option<f64>,
    pub dhi_wm2: Option<f64>,
    pub dni_wm2: Option<f64>,
}

/// A read `pyranometer.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct PyranometerTable {
    pub rows: Vec<PyranometerRow>,
    /// Columns not in campaign format v1, ignored (campaign.md: a warning, never an error).
    pub ignored_columns: Vec<String>,
}

/// Campaign rows from station records, stamped at each interval's centre (where the average
/// applies) in the given offset.
pub fn to_pyranometer_rows(
    records: &[IrradianceRecord],
    offset: FixedOffset,
) -> Vec<PyranometerRow> {
    records
        .iter()
        .map(|r| PyranometerRow {
            time: r.centre_utc().with_timezone(&offset),
            ghi_wm2: r.ghi_wm2,
            dhi_wm2: r.dhi_wm2,
            dni_wm2: r.dni_wm2,
        })
        .collect()
}

/// Writes `pyranometer.csv`: header `time,ghi_wm2,dhi_wm2,dni_wm2`, RFC 3339 times with an
/// explicit offset, an empty field for a gap, numbers in Rust's shortest round-trip form.
/// A non-finite value is refused (a gap must be `None`, not NaN).
pub fn write_pyranometer_csv<W: std::io::Write>(
    out: &mut W,
    rows: &[PyranometerRow],
) -> std::io::Result<()> {
    writeln!(out, "time,ghi_wm2,dhi_wm2,dni_wm2")?;
    for (i, r) in rows.iter().enumerate() {
        let mut line = r.time.to_rfc3339_opts(SecondsFormat::AutoSi, false);
        for (name, v) in [
            ("ghi_wm2", r.ghi_wm2),
            ("dhi_wm2", r.dhi_wm2),
            ("dni_wm2", r.dni_wm2),
        ] {
            line.push(',');
            match v {
                Some(v) if v.is_finite() => line.push_str(&v.to_string()),
                Some(v) => {
                    return Err(std::io::Error::new(
                        std::io::ErrorKind::InvalidInput,
                        format!("pyranometer row {i}: {name} is {v}; write a gap as None"),
                    ))
                }
                None => {}
            }
        }
        writeln!(out, "{line}")?;
    }
    Ok(())
}

/// Reads a campaign `pyranometer.csv`.
pub fn read_pyranometer_file(path: &Path) -> Result<PyranometerTable, IrradianceError> {
    let name = path.display().to_string();
    let text = read_text(path, &name)?;
    parse_pyranometer_csv(&name, &text)
}

/// Parses the text of a campaign `pyranometer.csv`; `file` only names it in errors.
pub fn parse_pyranometer_csv(file: &str, text: &str) -> Result<PyranometerTable, IrradianceError> {
    let mut lines = data_lines(text);
    let (header_line, header) = lines.next().ok_or_else(|| IrradianceError::Empty {
        file: file.to_string(),
    })?;
    let names: Vec<String> = header.split(',').map(|n| n.trim().to_string()).collect();
    let column = |name: &str| names.iter().position(|n| n == name);
    let required = |name: &str| {
        column(name).ok_or_else(|| IrradianceError::MissingColumn {
            file: file.to_string(),
            line: header_line,
            column: name.to_string(),
        })
    };
    let (time, ghi, dhi) = (
        required("time")?,
        required("ghi_wm2")?,
        required("dhi_wm2")?,
    );
    let dni = column("dni_wm2");
    let ignored_columns = names
        .iter()
        .filter(|n| !["time", "ghi_wm2", "dhi_wm2", "dni_wm2"].contains(&n.as_str()))
        .cloned()
        .collect();
    let mut rows = Vec::new();
    for (line, text) in lines {
        let fields: Vec<&str> = text.split(',').collect();
        if fields.len() != names.len() {
            return Err(IrradianceError::FieldCount {
                file: file.to_string(),
                line,
                found: fields.len(),
                expected: names.len(),
            });
        }
        let ctx = LineContext {
            file,
            line,
            fields: &fields,
            names: &names,
        };
        let time = DateTime::parse_from_rfc3339(fields[time].trim())
            .map_err(|_| ctx.field_error(time, "an RFC 3339 time with an explicit offset"))?;
        // Campaign values are plain numbers or empty: NaN, infinity or a sentinel is malformed.
        let value = |i: usize| -> Result<Option<f64>, IrradianceError> {
            let t = fields[i].trim();
            if t.is_empty() {
                return Ok(None);
            }
            match t.parse::<f64>() {
                Ok(v) if v.is_finite() && v > MISSING_SENTINEL_MAX_WM2 => Ok(Some(v)),
                _ => Err(ctx.field_error(i, "a finite irradiance in W/m² or an empty field")),
            }
        };
        rows.push(PyranometerRow {
            time,
            ghi_wm2: value(ghi)?,
            dhi_wm2: value(dhi)?,
            dni_wm2: dni.map(value).transpose()?.flatten(),
        });
    }
    Ok(PyranometerTable {
        rows,
        ignored_columns,
    })
}
