//! RADIANCE's matrix format (`rcollate`, `rmtxop`, `dctimestep`, `rfluxmtx`, `gendaymtx`):
//! a text header ended by an empty line (`NROWS=`, `NCOLS=`, `NCOMP=`, `FORMAT=ascii|float|
//! double`, `BYTEORDER=`), then rows × columns × components values, row-major, components
//! innermost. One home for reading theirs and writing ours, so each reads the other's.
//!
//! Reading is strict and never panics: every malformed header field, value or size is an
//! error naming the file and the field (and the line, for ascii values); a header cannot make
//! the reader allocate more than the file holds.

use std::fmt;
use std::path::Path;

/// How the values are stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MatrixFormat {
    Ascii,
    Float,
    Double,
}

impl MatrixFormat {
    fn label(self) -> &'static str {
        match self {
            MatrixFormat::Ascii => "ascii",
            MatrixFormat::Float => "float",
            MatrixFormat::Double => "double",
        }
    }
}

/// A matrix file that cannot be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MatrixError {
    /// The file as the caller named it.
    pub file: String,
    /// The header field or part at fault (`NROWS`, `FORMAT`, `data line 12`, ...).
    pub field: String,
    pub message: String,
}

impl MatrixError {
    fn new(file: &str, field: impl Into<String>, message: impl Into<String>) -> Self {
        MatrixError {
            file: file.to_string(),
            field: field.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for MatrixError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}: {}", self.file, self.field, self.message)
    }
}

impl std::error::Error for MatrixError {}

/// A matrix of `rows` × `cols` entries of `ncomp` components each (RADIANCE's RGB: 3).
#[derive(Debug, Clone, PartialEq)]
pub struct RadianceMatrix {
    pub rows: usize,
    pub cols: usize,
    pub ncomp: usize,
    /// Row-major, components innermost: `values[(r * cols + c) * ncomp + k]`.
    pub values: Vec<f64>,
}

/// RADIANCE's photopic weights of its RGB primaries (`rmtxop -c 0.265 0.670 0.065`).
pub const RGB_LUMINANCE_WEIGHTS: [f64; 3] = [0.265, 0.670, 0.065];

impl RadianceMatrix {
    pub fn zeros(rows: usize, cols: usize, ncomp: usize) -> Self {
        RadianceMatrix {
            rows,
            cols,
            ncomp,
            values: vec![0.0; rows * cols * ncomp],
        }
    }

    /// A one-component matrix from row-major values; None when the length is not rows × cols.
    pub fn from_grey(rows: usize, cols: usize, values: Vec<f64>) -> Option<Self> {
        (rows.checked_mul(cols) == Some(values.len())).then_some(RadianceMatrix {
            rows,
            cols,
            ncomp: 1,
            values,
        })
    }

    pub fn get(&self, row: usize, col: usize, comp: usize) -> f64 {
        self.values[(row * self.cols + col) * self.ncomp + comp]
    }

    /// The same matrix with every entry given `ncomp` equal components (a grey matrix for
    /// programs that expect RGB).
    pub fn with_components(&self, ncomp: usize) -> Option<Self> {
        if self.ncomp == ncomp {
            return Some(self.clone());
        }
        if self.ncomp != 1 {
            return None;
        }
        Some(RadianceMatrix {
            rows: self.rows,
            cols: self.cols,
            ncomp,
            values: self
                .values
                .iter()
                .flat_map(|&v| std::iter::repeat_n(v, ncomp))
                .collect(),
        })
    }

    /// Photopic brightness of each entry (RGB weighted as RADIANCE does; one component as is).
    pub fn brightness(&self) -> RadianceMatrix {
        let values = self
            .values
            .chunks_exact(self.ncomp.max(1))
            .map(|c| {
                if c.len() == 3 {
                    c.iter()
                        .zip(RGB_LUMINANCE_WEIGHTS)
                        .map(|(v, w)| v * w)
                        .sum()
                } else {
                    c.iter().sum::<f64>() / c.len() as f64
                }
            })
            .collect();
        RadianceMatrix {
            rows: self.rows,
            cols: self.cols,
            ncomp: 1,
            values,
        }
    }

    /// Sum of each row (component `comp`).
    pub fn row_sums(&self, comp: usize) -> Vec<f64> {
        (0..self.rows)
            .map(|r| (0..self.cols).map(|c| self.get(r, c, comp)).sum())
            .collect()
    }

    /// The product `self × other`, component by component as `rmtxop` and `dctimestep` take
    /// it; a one-component factor multiplies every component of the other. None when the
    /// shapes do not chain.
    pub fn multiply(&self, other: &RadianceMatrix) -> Option<RadianceMatrix> {
        if self.cols != other.rows {
            return None;
        }
        let ncomp = match (self.ncomp, other.ncomp) {
            (a, b) if a == b => a,
            (1, b) => b,
            (a, 1) => a,
            _ => return None,
        };
        let (ka, kb) = (usize::from(self.ncomp != 1), usize::from(other.ncomp != 1));
        let mut out = RadianceMatrix::zeros(self.rows, other.cols, ncomp);
        for r in 0..self.rows {
            for j in 0..self.cols {
                let a_base = (r * self.cols + j) * self.ncomp;
                let b_base = j * other.cols * other.ncomp;
                for c in 0..other.cols {
                    let o = (r * other.cols + c) * ncomp;
                    for k in 0..ncomp {
                        out.values[o + k] += self.values[a_base + k * ka]
                            * other.values[b_base + c * other.ncomp + k * kb];
                    }
                }
            }
        }
        Some(out)
    }

    /// Reads a matrix file.
    pub fn read(path: &Path) -> Result<Self, MatrixError> {
        let file = path.display().to_string();
        let bytes = std::fs::read(path)
            .map_err(|e| MatrixError::new(&file, "file", format!("cannot read: {e}")))?;
        Self::parse(&file, &bytes)
    }

    /// Parses the bytes of a matrix file; `file` names it in errors. `NROWS` may be missing
    /// (the rows are then what the data holds, as RADIANCE reads a stream); `NCOMP` defaults
    /// to 3 and the byte order (`BYTEORDER=` or rcontrib's `BigEndian=`) to this machine's, as
    /// in RADIANCE's `cm_load`.
    pub fn parse(file: &str, bytes: &[u8]) -> Result<Self, MatrixError> {
        Self::parse_with_header(file, bytes).map(|(m, _)| m)
    }

    /// [`Self::parse`], also returning the header's lines (a writer's own fields, such as
    /// `skylux dc`'s `SKYLUX_` lines).
    pub fn parse_with_header(file: &str, bytes: &[u8]) -> Result<(Self, Vec<String>), MatrixError> {
        let err = |field: &str, message: String| MatrixError::new(file, field, message);
        let end = find_header_end(bytes).ok_or_else(|| {
            err(
                "header",
                "no end of header (an empty line); write the matrix with its header".into(),
            )
        })?;
        let header =
            std::str::from_utf8(&bytes[..end]).map_err(|_| err("header", "not text".into()))?;
        let (mut rows, mut cols, mut ncomp) = (None, None, 3usize);
        let mut format = MatrixFormat::Ascii;
        let mut big_endian = cfg!(target_endian = "big");
        for line in header.lines() {
            let Some((key, value)) = line.split_once('=') else {
                continue;
            };
            let value = value.trim();
            let count = |key: &str| {
                value
                    .parse::<usize>()
                    .map_err(|_| err(key, format!("'{value}' is not a count")))
            };
            match key.trim() {
                "NROWS" => rows = Some(count("NROWS")?),
                "NCOLS" => cols = Some(count("NCOLS")?),
                "NCOMP" => ncomp = count("NCOMP")?,
                "FORMAT" => {
                    format = match value {
                        "ascii" => MatrixFormat::Ascii,
                        "float" => MatrixFormat::Float,
                        "double" => MatrixFormat::Double,
                        _ => {
                            return Err(err(
                                "FORMAT",
                                format!("'{value}' (expected ascii, float or double)"),
                            ))
                        }
                    }
                }
                "BYTEORDER" => {
                    big_endian = match value {
                        "BigEndian" => true,
                        "LittleEndian" => false,
                        _ => {
                            return Err(err(
                                "BYTEORDER",
                                format!("'{value}' (expected BigEndian or LittleEndian)"),
                            ))
                        }
                    }
                }
                // What rcontrib and rfluxmtx write instead of BYTEORDER.
                "BigEndian" => {
                    big_endian = match value {
                        "1" => true,
                        "0" => false,
                        _ => return Err(err("BigEndian", format!("'{value}' (expected 0 or 1)"))),
                    }
                }
                _ => {}
            }
        }
        let cols = cols.ok_or_else(|| err("NCOLS", "missing".into()))?;
        if cols == 0 || ncomp == 0 {
            return Err(err(
                "NCOLS/NCOMP",
                format!("{cols} columns of {ncomp} components: nothing to read"),
            ));
        }
        let per_row = cols
            .checked_mul(ncomp)
            .ok_or_else(|| err("NCOLS", format!("{cols} x {ncomp} components overflows")))?;
        let data = &bytes[end..];
        let values: Vec<f64> = match format {
            MatrixFormat::Ascii => parse_ascii(file, header, data)?,
            MatrixFormat::Float | MatrixFormat::Double => {
                let size = if format == MatrixFormat::Float { 4 } else { 8 };
                if !data.len().is_multiple_of(size) {
                    return Err(err(
                        "data",
                        format!(
                            "{} data bytes, not whole {} values",
                            data.len(),
                            format.label()
                        ),
                    ));
                }
                data.chunks_exact(size)
                    .map(|c| decode(c, big_endian))
                    .collect()
            }
        };
        let rows = match rows {
            Some(r) => r,
            None if values.len().is_multiple_of(per_row) => values.len() / per_row,
            None => {
                return Err(err(
                    "data",
                    format!(
                        "{} values are not whole rows of {cols} x {ncomp} (no NROWS)",
                        values.len()
                    ),
                ))
            }
        };
        if rows == 0 {
            return Err(err("NROWS", "no rows".into()));
        }
        if rows.checked_mul(per_row) != Some(values.len()) {
            return Err(err(
                "data",
                format!(
                    "{} values for NROWS={rows} x NCOLS={cols} x NCOMP={ncomp}",
                    values.len()
                ),
            ));
        }
        if let Some(bad) = values.iter().position(|v| !v.is_finite()) {
            return Err(err("data", format!("value {} is not finite", bad + 1)));
        }
        let lines = header.lines().map(str::to_string).collect();
        Ok((
            RadianceMatrix {
                rows,
                cols,
                ncomp,
                values,
            },
            lines,
        ))
    }

    /// The file's bytes: a header (`#?RADIANCE`, the caller's `header` lines, the sizes),
    /// then the values. Binary formats are little-endian and say so.
    pub fn to_bytes(&self, format: MatrixFormat, header: &[String]) -> Vec<u8> {
        encode(
            self.rows,
            self.cols,
            self.ncomp,
            &self.values,
            format,
            header,
        )
    }

    pub fn write(
        &self,
        path: &Path,
        format: MatrixFormat,
        header: &[String],
    ) -> std::io::Result<()> {
        std::fs::write(path, self.to_bytes(format, header))
    }
}

/// The bytes of a `rows` × `cols` × `ncomp` matrix of `values` (row-major, components
/// innermost) with `header` lines: [`RadianceMatrix::to_bytes`] without owning the values.
pub fn encode(
    rows: usize,
    cols: usize,
    ncomp: usize,
    values: &[f64],
    format: MatrixFormat,
    header: &[String],
) -> Vec<u8> {
    let mut out = String::from("#?RADIANCE\n");
    for line in header {
        // A header line may not be empty (that would end the header) nor hold newlines.
        let line = line.replace('\n', " ");
        if !line.trim().is_empty() {
            out.push_str(&line);
            out.push('\n');
        }
    }
    out.push_str(&format!(
        "NROWS={rows}\nNCOLS={cols}\nNCOMP={ncomp}\nFORMAT={}\n",
        format.label()
    ));
    if format != MatrixFormat::Ascii {
        out.push_str("BYTEORDER=LittleEndian\n");
    }
    out.push('\n');
    let mut bytes = out.into_bytes();
    match format {
        MatrixFormat::Ascii => {
            let mut text = String::with_capacity(values.len() * 16);
            for row in values.chunks((cols * ncomp).max(1)) {
                let line: Vec<String> = row.iter().map(|v| format!("{v:.9e}")).collect();
                text.push_str(&line.join(" "));
                text.push('\n');
            }
            bytes.extend_from_slice(text.as_bytes());
        }
        MatrixFormat::Float => {
            for v in values {
                bytes.extend_from_slice(&(*v as f32).to_le_bytes());
            }
        }
        MatrixFormat::Double => {
            for v in values {
                bytes.extend_from_slice(&v.to_le_bytes());
            }
        }
    }
    bytes
}

/// The offset just past the empty line ending the header.
fn find_header_end(bytes: &[u8]) -> Option<usize> {
    if bytes.starts_with(b"\n") {
        return Some(1);
    }
    bytes.windows(2).position(|w| w == b"\n\n").map(|p| p + 2)
}

fn decode(c: &[u8], big_endian: bool) -> f64 {
    match (c.len(), big_endian) {
        (4, false) => f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])),
        (4, true) => f64::from(f32::from_be_bytes([c[0], c[1], c[2], c[3]])),
        (_, false) => f64::from_le_bytes(std::array::from_fn(|k| c[k])),
        (_, true) => f64::from_be_bytes(std::array::from_fn(|k| c[k])),
    }
}

/// Whitespace-separated numbers; a bad one is named by its line in the file.
fn parse_ascii(file: &str, header: &str, data: &[u8]) -> Result<Vec<f64>, MatrixError> {
    let text = std::str::from_utf8(data)
        .map_err(|_| MatrixError::new(file, "data", "FORMAT=ascii but the data is not text"))?;
    // `header` ends with its empty line.
    let first_line = header.lines().count() + 1;
    let mut values = Vec::new();
    for (k, line) in text.lines().enumerate() {
        for word in line.split_whitespace() {
            let v = word.parse::<f64>().map_err(|_| {
                MatrixError::new(
                    file,
                    format!("data line {}", first_line + k),
                    format!("'{word}' is not a number"),
                )
            })?;
            values.push(v);
        }
    }
    Ok(values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_format_round_trips() {
        let m = RadianceMatrix {
            rows: 2,
            cols: 3,
            ncomp: 3,
            values: (0..18).map(|k| 0.25 * k as f64 - 1.0).collect(),
        };
        for format in [
            MatrixFormat::Ascii,
            MatrixFormat::Float,
            MatrixFormat::Double,
        ] {
            let bytes = m.to_bytes(format, &["skylux test".into()]);
            assert_eq!(RadianceMatrix::parse("m", &bytes).unwrap(), m, "{format:?}");
        }
    }

    #[test]
    fn bad_files_name_the_field() {
        let cases: [(&[u8], &str); 8] = [
            (b"#?RADIANCE\nNROWS=1\n", "header"),
            (b"NROWS=1\nNCOLS=x\n\n1", "NCOLS"),
            (b"NROWS=1\n\n1", "NCOLS"),
            (b"NROWS=1\nNCOLS=2\nNCOMP=1\n\n1 2 3", "data"),
            (b"NROWS=0\nNCOLS=4000000000\nNCOMP=1\n\n", "NROWS"),
            (b"NCOLS=1\nNCOMP=1\nFORMAT=rgbe\n\n", "FORMAT"),
            (b"NCOLS=1\nNCOMP=1\n\n1\n2 x\n", "data line 5"),
            (
                b"NROWS=4000000000\nNCOLS=4000000000\nNCOMP=3\nFORMAT=float\n\n\0\0\0\0",
                // A 32-bit usize cannot hold NCOLS × NCOMP: refused at the header there.
                if cfg!(target_pointer_width = "32") {
                    "NCOLS"
                } else {
                    "data"
                },
            ),
        ];
        for (bytes, field) in cases {
            let e = RadianceMatrix::parse("bad.mtx", bytes).unwrap_err();
            assert_eq!(e.file, "bad.mtx");
            assert!(e.field.starts_with(field), "{e}");
        }
    }

    #[test]
    fn products_chain_components() {
        let a = RadianceMatrix::from_grey(1, 2, vec![1.0, 2.0]).unwrap();
        let b = RadianceMatrix {
            rows: 2,
            cols: 1,
            ncomp: 3,
            values: vec![1.0, 2.0, 3.0, 10.0, 20.0, 30.0],
        };
        assert_eq!(a.multiply(&b).unwrap().values, vec![21.0, 42.0, 63.0]);
        assert!(b.multiply(&b).is_none());
    }
}
