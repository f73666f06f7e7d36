//! Raw Bayer frames: binary PGM (`P5`), maxval 4095, 16-bit big-endian samples (the PGM
//! standard's byte order for maxval > 255), one 12-bit sample per pixel, not black-subtracted;
//! width and height even (campaign.md "Raw frames").

use std::io::Write;
use std::path::{Path, PathBuf};

/// Largest 12-bit sample.
pub const MAX_SAMPLE_DN: u16 = 4095;

/// One raw frame: samples in row-major order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RawFrame {
    pub width: usize,
    pub height: usize,
    pub samples_dn: Vec<u16>,
}

/// Why a raw frame could not be read. Each names the file and what was wrong.
#[derive(Debug, thiserror::Error)]
pub enum RawFrameError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: PGM header: {what}")]
    Header { path: PathBuf, what: String },
    #[error("{path}: {what}")]
    Invalid { path: PathBuf, what: String },
}

impl RawFrame {
    /// A frame of `width` x `height` zero samples.
    pub fn new(width: usize, height: usize) -> Self {
        Self {
            width,
            height,
            samples_dn: vec![0; width * height],
        }
    }

    /// The sample at column `x`, row `y`.
    pub fn at(&self, x: usize, y: usize) -> u16 {
        self.samples_dn[y * self.width + x]
    }

    /// Reads a PGM file.
    pub fn read(path: &Path) -> Result<Self, RawFrameError> {
        let bytes = std::fs::read(path).map_err(|source| RawFrameError::Io {
            path: path.into(),
            source,
        })?;
        Self::parse(&bytes, path)
    }

    /// Parses PGM bytes; `path` only names the source in messages.
    pub fn parse(bytes: &[u8], path: &Path) -> Result<Self, RawFrameError> {
        let header = |what: String| RawFrameError::Header {
            path: path.into(),
            what,
        };
        let mut pos = 0;
        let mut tokens = Vec::with_capacity(4);
        while tokens.len() < 4 {
            // Skip whitespace and comments.
            while pos < bytes.len() && (bytes[pos].is_ascii_whitespace() || bytes[pos] == b'#') {
                if bytes[pos] == b'#' {
                    while pos < bytes.len() && bytes[pos] != b'\n' {
                        pos += 1;
                    }
                } else {
                    pos += 1;
                }
            }
            let start = pos;
            while pos < bytes.len() && !bytes[pos].is_ascii_whitespace() && bytes[pos] != b'#' {
                pos += 1;
            }
            if start == pos {
                return Err(header(format!(
                    "truncated after {} of 4 fields (magic, width, height, maxval)",
                    tokens.len()
                )));
            }
            tokens.push(String::from_utf8_lossy(&bytes[start..pos]).into_owned());
        }
        if tokens[0] != "P5" {
            return Err(header(format!(
                "magic is {:?}, expected \"P5\" (binary greymap)",
                tokens[0]
            )));
        }
        let number = |i: usize, name: &str| -> Result<usize, RawFrameError> {
            tokens[i]
                .parse::<usize>()
                .map_err(|_| header(format!("{name} {:?} is not a whole number", tokens[i])))
        };
        let (width, height, maxval) = (
            number(1, "width")?,
            number(2, "height")?,
            number(3, "maxval")?,
        );
        if maxval != MAX_SAMPLE_DN as usize {
            return Err(header(format!(
                "maxval is {maxval}, expected {MAX_SAMPLE_DN} (12-bit samples)"
            )));
        }
        if width == 0 || height == 0 || width % 2 != 0 || height % 2 != 0 {
            return Err(header(format!(
                "size {width}x{height}: width and height must be even and non-zero"
            )));
        }
        // Exactly one whitespace byte separates the header from the samples.
        if pos >= bytes.len() || !bytes[pos].is_ascii_whitespace() {
            return Err(header("no whitespace after maxval".into()));
        }
        pos += 1;
        let count = width
            .checked_mul(height)
            .filter(|n| *n <= (1 << 28))
            .ok_or_else(|| header(format!("size {width}x{height} is too large")))?;
        let data = &bytes[pos..];
        if data.len() < 2 * count {
            return Err(RawFrameError::Invalid {
                path: path.into(),
                what: format!(
                    "truncated: {width}x{height} needs {} bytes of samples, the file has {}",
                    2 * count,
                    data.len()
                ),
            });
        }
        let mut samples_dn = Vec::with_capacity(count);
        for (i, pair) in data[..2 * count].chunks_exact(2).enumerate() {
            let v = u16::from_be_bytes([pair[0], pair[1]]);
            if v > MAX_SAMPLE_DN {
                return Err(RawFrameError::Invalid {
                    path: path.into(),
                    what: format!(
                        "sample at column {}, row {} is {v}, above maxval {MAX_SAMPLE_DN}",
                        i % width,
                        i / width
                    ),
                });
            }
            samples_dn.push(v);
        }
        Ok(Self {
            width,
            height,
            samples_dn,
        })
    }

    /// The frame as PGM bytes.
    pub fn to_pgm(&self) -> Vec<u8> {
        let mut out =
            format!("P5\n{} {}\n{}\n", self.width, self.height, MAX_SAMPLE_DN).into_bytes();
        out.reserve(2 * self.samples_dn.len());
        for v in &self.samples_dn {
            out.extend_from_slice(&v.to_be_bytes());
        }
        out
    }

    /// Writes the frame as a PGM file.
    pub fn write(&self, path: &Path) -> Result<(), RawFrameError> {
        let io = |source| RawFrameError::Io {
            path: path.into(),
            source,
        };
        let mut f = std::fs::File::create(path).map_err(io)?;
        f.write_all(&self.to_pgm()).map_err(io)
    }
}
