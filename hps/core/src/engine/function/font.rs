//! RADIANCE's polygonal fonts (`.fnt`), which the text patterns draw with: the reader of
//! `src/common/font.c` (`getfont`), its test of a point against a glyph (`inglyph`, in
//! `src/rt/text.c`), and its three ways of spacing a line (`uniftext`, `squeeztext`,
//! `proptext`).
//!
//! The format: white-space separated integers, `#` starting a comment to the end of the
//! line. Per glyph: its character number (1 to 255), its vertex count N (0 to
//! [`MAX_VERTICES`], 0 for a space), then N pairs `x y` on a grid of 0 to 255 (y up): one
//! polygon, holes joined to the outline by a cut. A glyph is drawn in a cell 255 wide
//! (uniform spacing) or as wide as its own extent (proportional and squeezed spacing).
//!
//! Spacings are kept as RADIANCE keeps them, in `short`s: the arithmetic below wraps as C's
//! conversion to `short` does, so a line lays out the same and no input can overflow.

/// Most vertices one glyph may have (font.c refuses more).
pub const MAX_VERTICES: usize = 32000;
/// The glyph grid's largest coordinate: cells are 255 units (font.c `GORD`).
pub const GRID_UNITS: i32 = 255;
/// The initial extent of every glyph (font.c starts `left right top bottom` at 128, so an
/// extent always reaches the middle of the cell: a narrow glyph on the left counts as
/// wider, in the mean width and in squeezed spacing, as RADIANCE counts it).
const EXTENT_START: u8 = 128;
/// fgetval.c reads a word into 64 bytes: a longer one is not a number.
const MAX_WORD_BYTES: usize = 63;

/// A font file that cannot be read: the file, the 1-based line, what was wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("font file {file}, line {line}: {message}")]
pub struct FontError {
    pub file: String,
    pub line: usize,
    pub message: String,
}

/// One glyph: its polygon and extent, in grid units (0 to 255, y up).
#[derive(Debug, Clone, PartialEq)]
pub struct Glyph {
    vertices: Vec<[u8; 2]>,
    left: u8,
    right: u8,
    bottom: u8,
    top: u8,
}

/// A font: up to 255 glyphs by character code, and the mean glyph width that proportional
/// spacing aims at.
#[derive(Debug, Clone, PartialEq)]
pub struct Font {
    glyphs: Vec<Option<Glyph>>,
    /// Mean width of the glyphs with an area, grid units (font.c `mwidth`).
    mean_width: i32,
}

/// A line of text laid out: per character the advance from the previous character's origin
/// to its own (`spc[0]` is the first character's; one more entry than characters), and the
/// line's width, in grid units (text.c `TLINE`).
#[derive(Debug, Clone, PartialEq)]
pub struct LineSpacing {
    pub advances: Vec<i16>,
    pub width: i32,
}

/// fgetval.c's words, with the line each starts on.
struct Words<'a> {
    bytes: &'a [u8],
    at: usize,
    line: usize,
    /// The line of the last word read (where an unexpected end of file is reported).
    last_line: usize,
}

impl<'a> Words<'a> {
    /// The next word (None at the end of the file) and its line; a `#` ends a word.
    fn next_word(&mut self) -> Option<(&'a [u8], usize)> {
        loop {
            while self.at < self.bytes.len() && self.bytes[self.at].is_ascii_whitespace() {
                self.line += usize::from(self.bytes[self.at] == b'\n');
                self.at += 1;
            }
            if self.bytes.get(self.at) == Some(&b'#') {
                while self.at < self.bytes.len() && self.bytes[self.at] != b'\n' {
                    self.at += 1;
                }
                continue;
            }
            break;
        }
        if self.at >= self.bytes.len() {
            return None;
        }
        let start = self.at;
        while self.at < self.bytes.len()
            && !self.bytes[self.at].is_ascii_whitespace()
            && self.bytes[self.at] != b'#'
        {
            self.at += 1;
        }
        self.last_line = self.line;
        Some((&self.bytes[start..self.at], self.line))
    }
}

/// A word as `fgetval(fp, 'i', ..)` reads it: an optional sign and digits, no more than
/// [`MAX_WORD_BYTES`]; the value saturates (only ranges are checked after).
fn integer(word: &[u8]) -> Option<i64> {
    if word.len() > MAX_WORD_BYTES {
        return None;
    }
    let (negative, digits) = match word.first() {
        Some(b'-') => (true, &word[1..]),
        Some(b'+') => (false, &word[1..]),
        _ => (false, word),
    };
    if digits.is_empty() || !digits.iter().all(u8::is_ascii_digit) {
        return None;
    }
    let magnitude = digits.iter().fold(0i64, |v, d| {
        v.saturating_mul(10).saturating_add(i64::from(d - b'0'))
    });
    Some(if negative { -magnitude } else { magnitude })
}

impl Font {
    /// Reads font file `file`'s bytes (named in errors), refusing what font.c refuses: a
    /// character number outside 1..255 or given twice, a vertex count outside
    /// 0..[`MAX_VERTICES`], a coordinate outside 0..255, a word that is not an integer.
    pub fn parse(file: &str, bytes: &[u8]) -> Result<Font, FontError> {
        let mut words = Words {
            bytes,
            at: 0,
            line: 1,
            last_line: 1,
        };
        let error = |line: usize, message: String| FontError {
            file: file.to_string(),
            line,
            message,
        };
        let mut glyphs: Vec<Option<Glyph>> = vec![None; 256];
        let (mut width_sum, mut counted) = (0i32, 0i32);
        while let Some((word, line)) = words.next_word() {
            let code = integer(word).ok_or_else(|| {
                error(
                    line,
                    format!(
                        "`{}` is not an integer (a character number)",
                        String::from_utf8_lossy(word)
                    ),
                )
            })?;
            if !(1..=255).contains(&code) {
                return Err(error(
                    line,
                    format!("illegal character number {code} (1 to 255)"),
                ));
            }
            let slot = code as usize;
            if glyphs[slot].is_some() {
                return Err(error(line, format!("character {code} is given twice")));
            }
            let (count, line) = match words.next_word() {
                Some((w, l)) => (
                    integer(w).filter(|n| (0..=MAX_VERTICES as i64).contains(n)),
                    l,
                ),
                None => (None, words.last_line),
            };
            let count = count.ok_or_else(|| {
                error(
                    line,
                    format!("bad vertex count for character {code} (0 to {MAX_VERTICES})"),
                )
            })? as usize;
            let mut glyph = Glyph {
                vertices: Vec::with_capacity(count.min(1024)),
                left: EXTENT_START,
                right: EXTENT_START,
                bottom: EXTENT_START,
                top: EXTENT_START,
            };
            for k in 0..count {
                let mut vertex = [0u8; 2];
                for (axis, v) in vertex.iter_mut().enumerate() {
                    let (value, line) = match words.next_word() {
                        Some((w, l)) => (integer(w).filter(|n| (0..=255).contains(n)), l),
                        None => (None, words.last_line),
                    };
                    *v = value.ok_or_else(|| {
                        error(
                            line,
                            format!(
                                "bad {} of vertex {} of character {code} (an integer, 0 to 255)",
                                ["x", "y"][axis],
                                k + 1
                            ),
                        )
                    })? as u8;
                }
                glyph.left = glyph.left.min(vertex[0]);
                glyph.right = glyph.right.max(vertex[0]);
                glyph.bottom = glyph.bottom.min(vertex[1]);
                glyph.top = glyph.top.max(vertex[1]);
                glyph.vertices.push(vertex);
            }
            // font.c: only glyphs with an area count towards the mean width.
            if glyph.right != glyph.left && glyph.top != glyph.bottom {
                counted += 1;
                width_sum += i32::from(glyph.right - glyph.left);
            }
            glyphs[slot] = Some(glyph);
        }
        Ok(Font {
            glyphs,
            mean_width: if counted > 0 { width_sum / counted } else { 0 },
        })
    }

    /// The glyph of byte `c` (None: the font has none; byte 0 never has one).
    pub fn glyph(&self, c: u8) -> Option<&Glyph> {
        self.glyphs.get(usize::from(c)).and_then(Option::as_ref)
    }

    /// The mean width of the glyphs with an area, grid units.
    pub fn mean_width(&self) -> i32 {
        self.mean_width
    }

    /// How many characters have a glyph.
    pub fn glyph_count(&self) -> usize {
        self.glyphs.iter().flatten().count()
    }

    /// font.c `uniftext`: every character with a glyph takes a cell of 255; one without
    /// takes none.
    pub fn uniform_spacing(&self, text: &[u8]) -> LineSpacing {
        let mut advances = Vec::with_capacity(text.len() + 1);
        advances.push(0i16);
        let mut width = 0i32;
        for &c in text {
            let advance = if self.glyph(c).is_some() {
                GRID_UNITS
            } else {
                0
            };
            width = width.wrapping_add(advance);
            advances.push(advance as i16);
        }
        LineSpacing { advances, width }
    }

    /// font.c `squeeztext`: each glyph as wide as its extent, `gap` grid units between
    /// glyphs (half of it before the first and after the last), a space as wide as the
    /// mean glyph.
    pub fn squeezed_spacing(&self, text: &[u8], gap: i32) -> LineSpacing {
        let n = text.len();
        let mut sp = vec![0i16; n + 1];
        let mut width = 0i32;
        let (mut t, mut s) = (0usize, 0usize);
        let add = |slot: &mut i16, v: i32| *slot = i32::from(*slot).wrapping_add(v) as i16;
        // Characters before the first glyph take no room.
        let mut glyph = None;
        while t < n {
            glyph = self.glyph(text[t]);
            t += 1;
            if glyph.is_some() {
                break;
            }
            sp[s] = 0;
            s += 1;
        }
        let half = gap / 2;
        sp[s] = half as i16;
        while let Some(g) = glyph {
            if g.vertices.is_empty() {
                // A space: its own origin where the last glyph ended, the mean width on.
                width = width.wrapping_add(i32::from(sp[s]));
                s += 1;
                sp[s] = self.mean_width as i16;
            } else {
                add(&mut sp[s], half.wrapping_sub(i32::from(g.left)));
                width = width.wrapping_add(i32::from(sp[s]));
                s += 1;
                sp[s] = i32::from(g.right).wrapping_add(half) as i16;
            }
            glyph = None;
            while t < n {
                glyph = self.glyph(text[t]);
                t += 1;
                if glyph.is_some() {
                    break;
                }
                width = width.wrapping_add(i32::from(sp[s]));
                s += 1;
                sp[s] = 0;
            }
        }
        add(&mut sp[s], half);
        width = width.wrapping_add(i32::from(sp[s]));
        LineSpacing {
            advances: sp,
            width,
        }
    }

    /// font.c `proptext`: squeezed, then each run of characters stretched or shrunk so
    /// that each character with a glyph (and the spaces right after it) averages the mean
    /// width plus `gap`; a glyph followed by more than `indent_spaces` spaces ends a run,
    /// so indentation stays aligned.
    pub fn proportional_spacing(&self, text: &[u8], gap: i32, indent_spaces: usize) -> LineSpacing {
        let n = text.len();
        let LineSpacing {
            advances: mut sp, ..
        } = self.squeezed_spacing(text, gap);
        let is_space = |c: u8| self.glyph(c).is_some_and(|g| g.vertices.is_empty());
        let mut width = i32::from(sp[0]);
        let (mut t, mut s) = (0usize, 1usize);
        while t < n {
            let (mut target, mut actual) = (0i32, 0i32);
            let mut next = s;
            let (mut end, mut tab) = (t, t);
            while end < n {
                tab = end + 1;
                actual = actual.wrapping_add(i32::from(sp[next]));
                next += 1;
                if self.glyph(text[end]).is_some() {
                    while tab < n && is_space(text[tab]) {
                        actual = actual.wrapping_add(i32::from(sp[next]));
                        next += 1;
                        tab += 1;
                    }
                    target += (tab - end) as i32;
                }
                if indent_spaces > 0 && tab - end > indent_spaces {
                    break;
                }
                end = tab;
            }
            target = target.wrapping_mul(self.mean_width.wrapping_add(gap));
            width = width.wrapping_add(target);
            let mut left = target.wrapping_sub(actual);
            while s < next {
                let share = left / (next - s) as i32;
                sp[s] = i32::from(sp[s]).wrapping_add(share) as i16;
                s += 1;
                left = left.wrapping_sub(share);
            }
            t = tab;
        }
        LineSpacing {
            advances: sp,
            width,
        }
    }
}

impl Glyph {
    /// text.c `inglyph`: whether (x, y), in grid units of the glyph's cell, is inside its
    /// polygon (even-odd crossings of a ray towards +x, the test point moved by half a unit
    /// off the integer grid so that no vertex lies on it).
    pub fn contains(&self, x: f64, y: f64) -> bool {
        // C's conversion to int (x and y lie in the cell here; `as` saturates elsewhere).
        let (xi, yi) = (x as i32, y as i32);
        if i32::from(self.left) > xi
            || i32::from(self.right) <= xi
            || i32::from(self.bottom) > yi
            || i32::from(self.top) <= yi
        {
            return false;
        }
        let (xt, yt) = (xi * 2 + 1, yi * 2 + 1);
        let n = self.vertices.len();
        let mut crossings = 0u32;
        for k in 0..n {
            let [x0, y0] = self.vertices[(k + n - 1) % n].map(i32::from);
            let [x1, y1] = self.vertices[k].map(i32::from);
            if (y0 * 2 > yt) == (y1 * 2 > yt) {
                continue;
            }
            match (x0 * 2 > xt, x1 * 2 > xt) {
                (true, true) => crossings += 1,
                (false, false) => {}
                _ => {
                    let (x0, y0, x1, y1) =
                        (f64::from(x0), f64::from(y0), f64::from(x1), f64::from(y1));
                    let left_of = (y0 - y) * (x1 - x) > (x0 - x) * (y1 - y);
                    crossings += u32::from((y1 > y0) != left_of);
                }
            }
        }
        crossings % 2 == 1
    }

    /// Its vertices, grid units.
    pub fn vertices(&self) -> &[[u8; 2]] {
        &self.vertices
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square `A` (20..120 x 0..200), a narrow `I` (0..40), a ring `O` with a hole (cut
    /// along y = 100), a space.
    const FONT: &str = "# test\n65 4 20 0 120 0 120 200 20 200\n\
        73 4 0 0 40 0 40 200 0 200\n\
        79 10 0 0 200 0 200 200 0 200 0 100 50 100 50 150 150 150 150 50 50 50\n\
        32 0\n";

    #[test]
    fn glyphs_extents_and_mean_width() {
        let f = Font::parse("t.fnt", FONT.as_bytes()).unwrap();
        assert_eq!(f.glyph_count(), 4);
        // Extents start at 128 (font.c): A spans 20..128, I 0..128.
        assert_eq!(f.mean_width(), (108 + 128 + 200) / 3);
        let a = f.glyph(b'A').unwrap();
        assert!(a.contains(50.5, 100.5));
        assert!(!a.contains(10.5, 100.5) && !a.contains(130.5, 100.5));
        let o = f.glyph(b'O').unwrap();
        assert!(o.contains(20.5, 20.5) && o.contains(180.5, 180.5));
        assert!(!o.contains(100.5, 100.5), "the hole");
        assert!(!f.glyph(b' ').unwrap().contains(100.0, 100.0));
        assert!(f.glyph(b'Z').is_none() && f.glyph(0).is_none());
    }

    #[test]
    fn spacings_follow_font_c() {
        let f = Font::parse("t.fnt", FONT.as_bytes()).unwrap();
        let u = f.uniform_spacing(b"AZI");
        assert_eq!((u.advances, u.width), (vec![0, 255, 0, 255], 510));
        // Squeezed, gap 20: A's left edge 20 units in, 20 between extents, 20 after (the
        // extents reach 128 at least).
        let s = f.squeezed_spacing(b"AI", 20);
        assert_eq!(s.advances, vec![10 + 10 - 20, 128 + 10 + 10, 128 + 10 + 10]);
        assert_eq!(
            s.width,
            s.advances.iter().map(|&a| i32::from(a)).sum::<i32>()
        );
        // Proportional: the run of two glyphs averages mean width + gap each.
        let p = f.proportional_spacing(b"AI", 20, 3);
        assert_eq!(
            p.width,
            i32::from(p.advances[0]) + 2 * (f.mean_width() + 20)
        );
        assert_eq!(
            p.width,
            p.advances.iter().map(|&a| i32::from(a)).sum::<i32>()
        );
    }

    #[test]
    fn malformed_fonts_name_the_file_and_line() {
        let cases: &[(&str, usize, &str)] = &[
            ("65 4 0 0 1 0 1 1\n", 1, "vertex 4"),
            ("\n\n0 0\n", 3, "illegal character"),
            ("65 0\n65 0\n", 2, "twice"),
            ("65 x\n", 1, "vertex count"),
            ("65 2\n0 0\n256 0\n", 3, "0 to 255"),
            ("A 0\n", 1, "not an integer"),
            ("65 40000\n", 1, "vertex count"),
        ];
        for (text, line, fragment) in cases {
            let e = Font::parse("bad.fnt", text.as_bytes()).unwrap_err();
            assert_eq!((e.file.as_str(), e.line), ("bad.fnt", *line), "{e}");
            assert!(e.to_string().contains(fragment), "{e}");
        }
        // Comments end words and lines.
        let f = Font::parse("c.fnt", b"65 3#x\n0 0 9 0 9 9 # y\n").unwrap();
        assert_eq!(f.glyph(b'A').unwrap().vertices().len(), 3);
    }
}
