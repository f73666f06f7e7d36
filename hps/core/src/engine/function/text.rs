//! Text on a surface, as RADIANCE's `brighttext`, `colortext` and `mixtext` draw it
//! (`src/rt/text.c`): whether a hit lies inside a glyph of the text (the foreground) or not
//! (the background, everywhere outside the text's box included).
//!
//! The text's plane coordinates come from the anchor and the two motion vectors: a hit's
//! offset from the anchor is split along the right vector (character cells) and the down
//! vector (lines) by the dual basis text.c computes (`gettext`), so the vectors need not be
//! orthogonal. Line k spans k to k + 1 down; along it, characters are placed by the font's
//! spacing (`font.rs`) in grid units, 255 to a cell, or, when the spacing argument is
//! given, the font's mean width plus 255 × |spacing| to a cell (text.c `intext`).

use super::font::{Font, LineSpacing, GRID_UNITS};
use glam::DVec3;
use std::sync::Arc;

/// RADIANCE's `FTINY`: motion vectors whose cross product's square is under FTINY⁴ are
/// refused (text.c: "illegal motion vector").
const FTINY: f64 = 1e-6;
/// text.c lays out proportional text with `proptext(.., 3)`: a glyph followed by more than
/// three spaces ends a run, so columns stay aligned.
const INDENT_SPACES: usize = 3;
/// text.c reads a text file with `fgets` into 512 bytes: a longer line continues as the
/// next one.
pub const LINE_BUFFER_BYTES: usize = 511;

/// One laid-out line: its bytes and their advances.
#[derive(Debug, Clone)]
struct Line {
    text: Vec<u8>,
    spacing: LineSpacing,
}

/// A text pattern's text in place: which hits fall inside a glyph.
#[derive(Debug, Clone)]
pub struct TextLayout {
    anchor_m: DVec3,
    /// Dual of the right vector: a point's offset dotted with it is its position in cells.
    right_per_m: DVec3,
    /// Dual of the down vector: the offset dotted with it is its position in lines.
    down_per_m: DVec3,
    /// Grid units per character cell.
    cell_units: f64,
    font: Arc<Font>,
    lines: Vec<Line>,
}

impl TextLayout {
    /// Lays out `lines` in `font` at `anchor_m` with the right and down motion vectors and
    /// the optional spacing argument (text.c `gettext`). Fails on motion vectors that span
    /// no plane.
    pub fn new(
        font: Arc<Font>,
        lines: Vec<Vec<u8>>,
        anchor_m: DVec3,
        right_m: DVec3,
        down_m: DVec3,
        spacing: Option<f64>,
    ) -> Result<TextLayout, String> {
        let normal = down_m.cross(right_m);
        let mut right = normal.cross(down_m);
        let length_squared = right.length_squared();
        if length_squared.is_nan() || length_squared <= FTINY.powi(4) {
            return Err(format!(
                "illegal motion vectors: right ({} {} {}) and down ({} {} {}) span no plane",
                right_m.x, right_m.y, right_m.z, down_m.x, down_m.y, down_m.z
            ));
        }
        right *= down_m.length_squared() / length_squared;
        let mut down = right_m.cross(normal);
        down *= right_m.length_squared() / down.length_squared();
        // text.c: the spacing in grid units, truncated as C converts to int.
        let gap = (spacing.unwrap_or(0.0) * f64::from(GRID_UNITS)) as i32;
        let lines = lines
            .into_iter()
            .map(|text| {
                let spacing = match gap {
                    g if g < 0 => font.squeezed_spacing(&text, g.saturating_neg()),
                    g if g > 0 => font.proportional_spacing(&text, g, INDENT_SPACES),
                    _ => font.uniform_spacing(&text),
                };
                Line { text, spacing }
            })
            .collect();
        let cell_units = match spacing {
            Some(s) => f64::from(font.mean_width()) + f64::from(GRID_UNITS) * s.abs(),
            None => f64::from(GRID_UNITS),
        };
        Ok(TextLayout {
            anchor_m,
            right_per_m: right,
            down_per_m: down,
            cell_units,
            font,
            lines,
        })
    }

    /// Whether `point_m` (scene coordinates) lies inside a glyph (text.c `intext`).
    pub fn is_foreground(&self, point_m: DVec3) -> bool {
        let offset = point_m - self.anchor_m;
        let x = offset.dot(self.right_per_m) * self.cell_units;
        let down = offset.dot(self.down_per_m);
        // Before the anchor, or not a number: background (text.c tests x < 0 and y < 0).
        let inside = |v: f64| v.is_finite() && v >= 0.0;
        if !inside(x) || !inside(down) {
            return false;
        }
        // C's conversions to int (saturating here, where C's would be undefined).
        let mut h = x as i32;
        let row = down as i32;
        let fraction = x - f64::from(h);
        let y = (f64::from(row) + 1.0 - down) * f64::from(GRID_UNITS);
        let Some(line) = usize::try_from(row).ok().and_then(|r| self.lines.get(r)) else {
            return false;
        };
        if h >= line.spacing.width {
            return false;
        }
        for (k, &advance) in line.spacing.advances.iter().enumerate() {
            h = h.wrapping_sub(i32::from(advance));
            if h < 0 {
                break;
            }
            let glyph = line.text.get(k).and_then(|&c| self.font.glyph(c));
            if h < GRID_UNITS && glyph.is_some_and(|g| g.contains(f64::from(h) + fraction, y)) {
                return true;
            }
        }
        false
    }
}

/// A text file's lines as text.c reads them with `fgets` into its 512-byte buffer: split
/// after each newline and after every [`LINE_BUFFER_BYTES`] bytes, cut at a NUL byte (C
/// strings end there), the one trailing newline removed.
pub fn text_file_lines(bytes: &[u8]) -> Vec<Vec<u8>> {
    let mut lines = Vec::new();
    let mut rest = bytes;
    while !rest.is_empty() {
        let limit = rest.len().min(LINE_BUFFER_BYTES);
        let end = rest[..limit]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(limit, |i| i + 1);
        let mut line = &rest[..end];
        rest = &rest[end..];
        if let Some(nul) = line.iter().position(|&b| b == 0) {
            line = &line[..nul];
        }
        if let Some(stripped) = line.strip_suffix(b"\n") {
            line = stripped;
        }
        lines.push(line.to_vec());
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A full square `A` and a space.
    fn font() -> Arc<Font> {
        Arc::new(Font::parse("t.fnt", b"65 4 0 0 255 0 255 255 0 255\n32 0\n").unwrap())
    }

    #[test]
    fn cells_lines_and_the_box() {
        let (r, d) = (DVec3::new(0.5, 0.0, 0.0), DVec3::new(0.0, -1.0, 0.0));
        let t = TextLayout::new(
            font(),
            vec![b"A A".to_vec(), b"AA".to_vec()],
            DVec3::ZERO,
            r,
            d,
            None,
        )
        .unwrap();
        let at = |x: f64, y: f64| t.is_foreground(DVec3::new(x, y, 0.0));
        assert!(at(0.25, -0.5) && !at(0.75, -0.5) && at(1.25, -0.5));
        assert!(at(0.75, -1.5), "second line");
        assert!(!at(-0.1, -0.5) && !at(0.25, 0.1) && !at(1.6, -0.5) && !at(0.25, -2.5));
        // Motion vectors along one line are refused.
        assert!(TextLayout::new(font(), vec![], DVec3::ZERO, r, 2.0 * r, None).is_err());
    }

    #[test]
    fn text_files_split_as_fgets_does() {
        assert_eq!(
            text_file_lines(b"ab\ncd"),
            vec![b"ab".to_vec(), b"cd".to_vec()]
        );
        assert_eq!(
            text_file_lines(b"a\0b\n\n"),
            vec![b"a".to_vec(), b"".to_vec()]
        );
        let long = vec![b'x'; 600];
        let lines = text_file_lines(&long);
        assert_eq!((lines[0].len(), lines[1].len()), (511, 89));
        assert!(text_file_lines(b"").is_empty());
    }
}
