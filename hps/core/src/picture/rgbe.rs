//! RADIANCE pictures (`.hdr`): RGBE pixels under a header with the view.

use super::{output_error, OutputError, Picture};
use glam::DVec3;
use std::path::Path;

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
pub fn write_hdr(path: &Path, image: &Picture, exposure: Option<f64>) -> Result<(), OutputError> {
    let mut out = Vec::with_capacity(image.radiance_rgb.len() * 4 + 256);
    out.extend_from_slice(b"#?RADIANCE\n");
    out.extend_from_slice(
        format!("SOFTWARE= skylux {} render\n", env!("CARGO_PKG_VERSION")).as_bytes(),
    );
    out.extend_from_slice(
        format!("SAMPLES= {} paths per pixel\n", image.samples_per_pixel).as_bytes(),
    );
    out.extend_from_slice(format!("VIEW= {}\n", image.view).as_bytes());
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

/// Most pixels a picture may hold when read: 2^24 (4096 × 4096), 12 bytes each, so a
/// picture (and what glare evaluation derives from it) fits a 32-bit process's memory.
pub const MAX_READ_PIXELS: u64 = 1 << 24;

/// Most header bytes read before the blank line that ends a header.
const MAX_HEADER_BYTES: usize = 1 << 20;

/// How a picture's pixels are encoded (the header's `FORMAT=`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelFormat {
    /// `32-bit_rle_rgbe`: RADIANCE RGB radiance, W/sr/m² per channel.
    Rgbe,
    /// `32-bit_rle_xyze`: CIE XYZ, Y × 179 lm/W being luminance.
    Xyze,
}

/// A RADIANCE picture as read from a `.hdr` file: pixels rows from the top, divided by the
/// header's exposure (so in the units the renderer computed), with the header's view.
#[derive(Clone, Debug, PartialEq)]
pub struct HdrPicture {
    pub width_px: u32,
    pub height_px: u32,
    /// The `VIEW=` lines' options in order (later options win), None without any.
    pub view: Option<String>,
    /// Product of the `EXPOSURE=` lines (1 without any): the factor the stored values carry.
    pub exposure: f64,
    pub format: PixelFormat,
    /// Product of the `PIXASPECT=` lines (1 without any): a pixel's height over its width.
    pub pixel_aspect: f64,
    /// RGB (or XYZ) per pixel, rows from the top, exposure removed.
    pub pixels: Vec<[f32; 3]>,
}

/// Why a picture could not be read: the file and where in it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}: {message}", path.display())]
pub struct PictureReadError {
    pub path: std::path::PathBuf,
    pub message: String,
}

/// Reads a RADIANCE picture (`.hdr`, `.pic`): header, resolution line in any of the eight
/// orientations, and scanlines flat, run-length encoded (new style) or old-style RLE.
pub fn read_hdr(path: &Path) -> Result<HdrPicture, PictureReadError> {
    let bytes = std::fs::read(path).map_err(|e| PictureReadError {
        path: path.into(),
        message: e.to_string(),
    })?;
    parse_hdr(path, &bytes)
}

/// [`read_hdr`] on bytes already read; `path` names them in errors.
pub fn parse_hdr(path: &Path, bytes: &[u8]) -> Result<HdrPicture, PictureReadError> {
    let fail = |message: String| PictureReadError {
        path: path.into(),
        message,
    };
    let header = parse_header(bytes).map_err(fail)?;
    let (layout, data_start) =
        parse_resolution(bytes, header.end, header.lines + 1).map_err(fail)?;
    let mut reader = ScanReader {
        bytes,
        at: data_start,
    };
    let pixels = read_pixels(&mut reader, &layout, header.exposure).map_err(fail)?;
    Ok(HdrPicture {
        width_px: layout.width_px,
        height_px: layout.height_px,
        view: header.view,
        exposure: header.exposure,
        format: header.format,
        pixel_aspect: header.pixel_aspect,
        pixels,
    })
}

/// What the header says, and where it ends.
struct Header {
    view: Option<String>,
    exposure: f64,
    format: PixelFormat,
    pixel_aspect: f64,
    /// Index of the first byte after the blank line.
    end: usize,
    /// Lines in the header, the blank one included.
    lines: usize,
}

fn parse_header(bytes: &[u8]) -> Result<Header, String> {
    if !bytes.starts_with(b"#?") {
        return Err("not a RADIANCE picture: the first line does not start with `#?`".into());
    }
    let mut header = Header {
        view: None,
        exposure: 1.0,
        format: PixelFormat::Rgbe,
        pixel_aspect: 1.0,
        end: 0,
        lines: 0,
    };
    let mut at = 0;
    loop {
        let Some(len) = bytes[at..].iter().position(|&b| b == b'\n') else {
            return Err(format!(
                "header line {}: the file ends inside the header (no blank line before the \
                 resolution)",
                header.lines + 1
            ));
        };
        header.lines += 1;
        let line = String::from_utf8_lossy(&bytes[at..at + len]).into_owned();
        at += len + 1;
        if at > MAX_HEADER_BYTES {
            return Err(format!(
                "header longer than {MAX_HEADER_BYTES} bytes without a blank line"
            ));
        }
        if line.trim().is_empty() {
            header.end = at;
            return Ok(header);
        }
        header_line(&mut header, line.trim_end())
            .map_err(|m| format!("header line {}: {m}", header.lines))?;
    }
}

/// Applies one header line (`VIEW=`, `EXPOSURE=`, `PIXASPECT=`, `FORMAT=`; others are kept
/// by RADIANCE as comments and ignored here).
fn header_line(header: &mut Header, line: &str) -> Result<(), String> {
    if let Some(value) = line.strip_prefix("PIXASPECT=") {
        match value.trim().parse::<f64>() {
            Ok(a) if a.is_finite() && a > 0.0 => header.pixel_aspect *= a,
            _ => {
                return Err(format!(
                    "PIXASPECT `{}` is not a positive number",
                    value.trim()
                ))
            }
        }
        if !(header.pixel_aspect.is_finite() && header.pixel_aspect > 0.0) {
            return Err("the PIXASPECT lines multiply to 0 or infinity".into());
        }
        return Ok(());
    }
    if let Some(view) = line.strip_prefix("VIEW=") {
        let view = view.trim();
        header.view = Some(match header.view.take() {
            Some(before) => format!("{before} {view}"),
            None => view.to_string(),
        });
    } else if let Some(value) = line.strip_prefix("EXPOSURE=") {
        match value.trim().parse::<f64>() {
            Ok(e) if e.is_finite() && e > 0.0 => header.exposure *= e,
            _ => {
                return Err(format!(
                    "EXPOSURE `{}` is not a positive number",
                    value.trim()
                ))
            }
        }
        if !(header.exposure.is_finite() && header.exposure > 0.0) {
            return Err("the EXPOSURE lines multiply to 0 or infinity".into());
        }
    } else if let Some(format) = line.strip_prefix("FORMAT=") {
        header.format = match format.trim() {
            "32-bit_rle_rgbe" => PixelFormat::Rgbe,
            "32-bit_rle_xyze" => PixelFormat::Xyze,
            other => {
                return Err(format!(
                    "FORMAT `{other}` is not a RADIANCE picture format (32-bit_rle_rgbe or \
                     32-bit_rle_xyze)"
                ))
            }
        };
    }
    Ok(())
}

/// Where each stored pixel goes: scanlines along the major axis.
struct Layout {
    width_px: u32,
    height_px: u32,
    /// Scanlines, and pixels in each.
    scanlines: u32,
    scan_len: u32,
    /// Scanlines are rows (`±Y n ±X m`), else columns.
    rows_major: bool,
    /// The major axis runs down (`-Y`) or left (`-X`), the minor axis likewise.
    major_decreasing: bool,
    minor_decreasing: bool,
}

impl Layout {
    /// Index (rows from the top) of pixel `i` of scanline `s`.
    fn index(&self, s: u32, i: u32) -> usize {
        let major = if self.major_decreasing {
            self.scanlines - 1 - s
        } else {
            s
        };
        let minor = if self.minor_decreasing {
            self.scan_len - 1 - i
        } else {
            i
        };
        // Axis coordinates increase rightwards (x) and upwards (y).
        let (x, y) = if self.rows_major {
            (minor, major)
        } else {
            (major, minor)
        };
        (self.height_px - 1 - y) as usize * self.width_px as usize + x as usize
    }
}

fn parse_resolution(bytes: &[u8], start: usize, line: usize) -> Result<(Layout, usize), String> {
    let end = bytes[start..]
        .iter()
        .take(64)
        .position(|&b| b == b'\n')
        .ok_or(format!(
            "line {line}: no resolution line (`-Y height +X width`) after the header"
        ))?;
    let text = String::from_utf8_lossy(&bytes[start..start + end]).into_owned();
    let bad = || format!("line {line}: `{text}` is not a resolution line (`-Y height +X width`)");
    let words: Vec<&str> = text.split_whitespace().collect();
    let [a, n1, b, n2] = words[..] else {
        return Err(bad());
    };
    let axis = |w: &str| -> Option<(bool, char)> {
        let mut c = w.chars();
        let sign = c.next()?;
        let letter = c.next()?;
        (c.next().is_none() && matches!(sign, '+' | '-') && matches!(letter, 'X' | 'Y'))
            .then_some((sign == '-', letter))
    };
    let ((major_dec, major), (minor_dec, minor)) =
        (axis(a).ok_or_else(bad)?, axis(b).ok_or_else(bad)?);
    if major == minor {
        return Err(bad());
    }
    let count = |w: &str| w.parse::<u32>().ok().filter(|&n| n > 0);
    let (scanlines, scan_len) = (count(n1).ok_or_else(bad)?, count(n2).ok_or_else(bad)?);
    if u64::from(scanlines) * u64::from(scan_len) > MAX_READ_PIXELS {
        return Err(format!(
            "line {line}: {scan_len} × {scanlines} pixels is more than the {MAX_READ_PIXELS} \
             this reader accepts"
        ));
    }
    let rows_major = major == 'Y';
    let (width_px, height_px) = if rows_major {
        (scan_len, scanlines)
    } else {
        (scanlines, scan_len)
    };
    // `-Y` (the first scanline at the top) decreases along y; `+X` increases along x.
    let layout = Layout {
        width_px,
        height_px,
        scanlines,
        scan_len,
        rows_major,
        major_decreasing: major_dec,
        minor_decreasing: minor_dec,
    };
    Ok((layout, start + end + 1))
}

/// The bytes after the resolution line, read forwards.
struct ScanReader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl ScanReader<'_> {
    fn byte(&mut self) -> Option<u8> {
        let b = *self.bytes.get(self.at)?;
        self.at += 1;
        Some(b)
    }

    fn four(&mut self) -> Option<[u8; 4]> {
        let s = self.bytes.get(self.at..self.at + 4)?;
        self.at += 4;
        Some([s[0], s[1], s[2], s[3]])
    }
}

/// Decodes every scanline and places it, exposure removed (colr_color: (m + ½) 2^(e−136)).
fn read_pixels(
    reader: &mut ScanReader<'_>,
    layout: &Layout,
    exposure: f64,
) -> Result<Vec<[f32; 3]>, String> {
    let pixel_count = layout.width_px as usize * layout.height_px as usize;
    let mut pixels = vec![[0f32; 3]; pixel_count];
    let mut scan = vec![[0u8; 4]; layout.scan_len as usize];
    for s in 0..layout.scanlines {
        read_scanline(reader, &mut scan)
            .map_err(|m| format!("scanline {} of {}: {m}", s + 1, layout.scanlines))?;
        for (i, colr) in scan.iter().enumerate() {
            pixels[layout.index(s, i as u32)] = colr_to_float(*colr, exposure);
        }
    }
    Ok(pixels)
}

fn colr_to_float([r, g, b, e]: [u8; 4], exposure: f64) -> [f32; 3] {
    if e == 0 {
        return [0.0; 3];
    }
    let f = 2f64.powi(i32::from(e) - (128 + 8)) / exposure;
    let v = |m: u8| ((f64::from(m) + 0.5) * f) as f32;
    [v(r), v(g), v(b)]
}

/// One scanline (color.c `freadcolrs`): new-style RLE when the line is 8 to 32767 pixels
/// long and starts with 2 2 and its length, else old-style (flat, with repeat codes).
fn read_scanline(reader: &mut ScanReader<'_>, scan: &mut [[u8; 4]]) -> Result<(), String> {
    const TRUNCATED: &str = "the file ends inside the scanline (truncated)";
    let len = scan.len();
    if !(8..=0x7fff).contains(&len) {
        return read_old_scanline(reader, scan, None);
    }
    let first = reader.four().ok_or(TRUNCATED)?;
    if first[0] != 2 || first[1] != 2 || first[2] & 0x80 != 0 {
        return read_old_scanline(reader, scan, Some(first));
    }
    let declared = (usize::from(first[2]) << 8) | usize::from(first[3]);
    if declared != len {
        return Err(format!(
            "run-length scanline says {declared} pixels, the picture {len}"
        ));
    }
    for component in 0..4 {
        let mut j = 0;
        while j < len {
            let code = usize::from(reader.byte().ok_or(TRUNCATED)?);
            if code > 128 {
                let run = code & 127;
                let value = reader.byte().ok_or(TRUNCATED)?;
                if j + run > len {
                    return Err("a run passes the end of the scanline".into());
                }
                scan[j..j + run]
                    .iter_mut()
                    .for_each(|p| p[component] = value);
                j += run;
            } else {
                if code == 0 || j + code > len {
                    return Err(format!(
                        "bad literal count {code} at pixel {j} of component {component}"
                    ));
                }
                for p in &mut scan[j..j + code] {
                    p[component] = reader.byte().ok_or(TRUNCATED)?;
                }
                j += code;
            }
        }
    }
    Ok(())
}

/// Old-style scanline: 4-byte pixels, where 1 1 1 n repeats the previous pixel n times
/// (n shifted left by 8 for each repeat code in a row).
fn read_old_scanline(
    reader: &mut ScanReader<'_>,
    scan: &mut [[u8; 4]],
    mut pending: Option<[u8; 4]>,
) -> Result<(), String> {
    const TRUNCATED: &str = "the file ends inside the scanline (truncated)";
    let mut j = 0;
    let mut shift = 0u32;
    while j < scan.len() {
        let colr = match pending.take() {
            Some(c) => c,
            None => reader.four().ok_or(TRUNCATED)?,
        };
        if colr[0] == 1 && colr[1] == 1 && colr[2] == 1 {
            if j == 0 || shift > 24 {
                return Err(format!("bad repeat code at pixel {j}"));
            }
            let count = (u64::from(colr[3]) << shift) as usize;
            if count > scan.len() - j {
                return Err(format!(
                    "a repeat of {count} passes the end of the scanline"
                ));
            }
            let previous = scan[j - 1];
            scan[j..j + count].iter_mut().for_each(|p| *p = previous);
            j += count;
            shift += 8;
        } else {
            scan[j] = colr;
            j += 1;
            shift = 0;
        }
    }
    Ok(())
}
