//! RADIANCE's data files (`.dat`), which `brightdata` and `colordata` interpolate: the reader
//! and the interpolation of `src/rt/data.c` (`getdata`, `data_interp`).
//!
//! The format: the number of dimensions N (1 to [`MAX_DIMENSIONS`]); per dimension
//! `begin end n` for n evenly spaced points, or `0 0 n p1 .. pn` for n monotonic points;
//! then the values, later dimensions changing faster. Between points the value is
//! multilinear; past the ends it is extrapolated for one division and then tapers off
//! harmonically to zero (data.c). Text after the last value is ignored, as RADIANCE does.

/// Most dimensions a data file may have (RADIANCE `MAXDDIM`).
pub const MAX_DIMENSIONS: usize = 5;
/// Most values a data file may hold: bounds the memory a malformed count could ask for.
pub const MAX_VALUES: usize = 1 << 24;
/// RADIANCE's `FTINY`: an interpolation coefficient smaller than this is skipped.
const FTINY: f64 = 1e-6;

/// A data file that cannot be read: the file, the 1-based line, what was wrong.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("data file {file}, line {line}: {message}")]
pub struct DataError {
    pub file: String,
    pub line: usize,
    pub message: String,
}

/// One dimension of the grid.
#[derive(Debug, Clone, PartialEq)]
struct Dimension {
    origin: f64,
    /// Last point minus the first (negative for decreasing points).
    size: f64,
    count: usize,
    /// The points, if not evenly spaced.
    points: Option<Vec<f64>>,
}

/// A data file, read.
#[derive(Debug, Clone, PartialEq)]
pub struct DataArray {
    dimensions: Vec<Dimension>,
    values: Vec<f64>,
}

/// Numbers of a text with their lines.
struct Tokens<'a> {
    file: &'a str,
    words: std::iter::Peekable<Box<dyn Iterator<Item = (usize, &'a str)> + 'a>>,
    line: usize,
}

impl<'a> Tokens<'a> {
    fn new(file: &'a str, text: &'a str) -> Self {
        let words: Box<dyn Iterator<Item = (usize, &'a str)>> = Box::new(
            text.lines()
                .enumerate()
                .flat_map(|(n, l)| l.split_whitespace().map(move |w| (n + 1, w))),
        );
        Tokens {
            file,
            words: words.peekable(),
            line: 1,
        }
    }

    fn error(&self, message: impl Into<String>) -> DataError {
        DataError {
            file: self.file.to_string(),
            line: self.line,
            message: message.into(),
        }
    }

    fn real(&mut self, what: &str) -> Result<f64, DataError> {
        let Some((line, word)) = self.words.next() else {
            return Err(self.error(format!("unexpected end of file: expected {what}")));
        };
        self.line = line;
        word.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| self.error(format!("`{word}` is not a number ({what})")))
    }

    fn count(
        &mut self,
        what: &str,
        range: std::ops::RangeInclusive<usize>,
    ) -> Result<usize, DataError> {
        let Some((line, word)) = self.words.next() else {
            return Err(self.error(format!("unexpected end of file: expected {what}")));
        };
        self.line = line;
        word.parse::<usize>()
            .ok()
            .filter(|n| range.contains(n))
            .ok_or_else(|| {
                self.error(format!(
                    "`{word}` is not a valid {what} ({} to {})",
                    range.start(),
                    range.end()
                ))
            })
    }
}

impl DataArray {
    /// Reads the text of data file `file` (named in errors).
    pub fn parse(file: &str, text: &str) -> Result<DataArray, DataError> {
        let mut t = Tokens::new(file, text);
        let n = t.count("number of dimensions", 1..=MAX_DIMENSIONS)?;
        let mut dimensions = Vec::with_capacity(n);
        let mut total: usize = 1;
        for d in 1..=n {
            let dimension = read_dimension(&mut t, d)?;
            total = total
                .checked_mul(dimension.count)
                .filter(|&v| v <= MAX_VALUES)
                .ok_or_else(|| t.error(format!("more than {MAX_VALUES} values")))?;
            dimensions.push(dimension);
        }
        let mut values = Vec::with_capacity(total.min(1 << 16)); // grows with what the file holds
        for k in 0..total {
            values.push(t.real(&format!("value {} of {total}", k + 1))?);
        }
        Ok(DataArray { dimensions, values })
    }

    /// A picture as `colorpict` reads it (data.c `getpict`): two evenly spaced dimensions,
    /// y then x, from 0 to the picture's size with its smaller side 1 (pixel aspect
    /// included), one array per channel; `rows_from_top` are the stored channel values
    /// (exposure not removed), `width` per row. The first pixel sits at coordinate 0 and the
    /// last at the size, as RADIANCE places them.
    pub fn from_picture(
        rows_from_top: &[[f32; 3]],
        width: usize,
        height: usize,
        pixel_aspect: f64,
    ) -> Option<[DataArray; 3]> {
        if width < 2 || height < 2 || rows_from_top.len() != width * height {
            return None;
        }
        let (w, h) = (width as f64, height as f64);
        let (y_size, x_size) = if w <= h * pixel_aspect {
            (pixel_aspect * h / w, 1.0)
        } else {
            (1.0, w / h / pixel_aspect)
        };
        let dimension = |size: f64, count: usize| Dimension {
            origin: 0.0,
            size,
            count,
            points: None,
        };
        let channel = |c: usize| DataArray {
            dimensions: vec![dimension(y_size, height), dimension(x_size, width)],
            // Row 0 of the array is the bottom row of the picture.
            values: (0..height)
                .rev()
                .flat_map(|row| rows_from_top[row * width..(row + 1) * width].iter())
                .map(|p| f64::from(p[c]))
                .collect(),
        };
        Some([channel(0), channel(1), channel(2)])
    }

    pub fn dimension_count(&self) -> usize {
        self.dimensions.len()
    }

    /// The value at `point` (one coordinate per dimension; missing ones are 0).
    pub fn value(&self, point: &[f64]) -> f64 {
        interpolate(&self.dimensions, &self.values, point, 1.0)
    }
}

/// `begin end n`, or `0 0 n` and n monotonic points.
fn read_dimension(t: &mut Tokens<'_>, d: usize) -> Result<Dimension, DataError> {
    let begin = t.real(&format!("begin of dimension {d}"))?;
    let end = t.real(&format!("end of dimension {d}"))?;
    let count = t.count(&format!("point count of dimension {d}"), 2..=MAX_VALUES)?;
    if end - begin != 0.0 {
        return Ok(Dimension {
            origin: begin,
            size: end - begin,
            count,
            points: None,
        });
    }
    let mut points = Vec::with_capacity(count.min(4096));
    for j in 0..count {
        points.push(t.real(&format!("point {} of dimension {d}", j + 1))?);
    }
    // data.c: every step goes the same way as the next one.
    if points.windows(3).any(|w| (w[0] < w[1]) != (w[1] < w[2])) {
        return Err(t.error(format!("the points of dimension {d} are not monotonic")));
    }
    Ok(Dimension {
        origin: points[0],
        size: points[count - 1] - points[0],
        count,
        points: Some(points),
    })
}

/// data.c `data_interp`: the lower grid index and fractional position along the first
/// dimension, the two coefficients (linear inside, extrapolated one division, then tapering
/// harmonically), and the recursion into the remaining dimensions.
fn interpolate(dimensions: &[Dimension], values: &[f64], point: &[f64], coef: f64) -> f64 {
    if coef.abs() <= FTINY {
        return 0.0;
    }
    let (dim, rest) = (&dimensions[0], &dimensions[1..]);
    let p = point.first().copied().unwrap_or(0.0);
    let (i, x) = position(dim, p);
    let (c0, c1) = coefficients(i, x);
    let stride: usize = rest.iter().map(|d| d.count).product();
    let pick = |k: usize, c: f64| {
        let block = &values[k * stride..(k + 1) * stride];
        if rest.is_empty() {
            c * coef * block[0]
        } else {
            interpolate(rest, block, point.get(1..).unwrap_or(&[]), c * coef)
        }
    };
    pick(i, c0) + pick(i + 1, c1)
}

/// The lower index (0 to n − 2) and the fractional grid position of `p`.
fn position(dim: &Dimension, p: f64) -> (usize, f64) {
    let last = dim.count - 2;
    match &dim.points {
        None => {
            let x = (p - dim.origin) / dim.size * (dim.count - 1) as f64;
            // C's conversion truncates towards zero; NaN and negatives end at 0.
            let i = if x.is_finite() && x > 0.0 {
                (x.trunc() as usize).min(last)
            } else if x.is_finite() {
                0
            } else if x > 0.0 {
                last
            } else {
                0
            };
            (i, x)
        }
        Some(points) => {
            let i = bisect(points, dim.size, p).min(last);
            let step = points[i + 1] - points[i];
            let x = if step != 0.0 {
                i as f64 + (p - points[i]) / step
            } else {
                i as f64
            };
            (i, x)
        }
    }
}

/// data.c's bisection over irregular points (increasing or decreasing).
fn bisect(points: &[f64], size: f64, p: f64) -> usize {
    let n = points.len();
    let (mut lower, mut upper) = if size > 0.0 { (0, n) } else { (n, 0) };
    loop {
        let i = (lower + upper) >> 1;
        if p >= points[i.min(n - 1)] {
            lower = i;
        } else {
            upper = i;
        }
        if i == (lower + upper) >> 1 {
            return i;
        }
    }
}

/// The two interpolation coefficients at grid position `x` above index `i`. Below the grid
/// by more than one division the taper is 1 / (i - x) in all, weighted (2, -1) towards the
/// edge, as rtrace 6.0a (the pyradiance wheel) computes it: a constant array of 1 reads
/// 1/1.5 at x = i - 1.5 and 0.2 at x = i - 5 there (measured; data.c revision 2.41 as
/// published reads the same magnitudes with the opposite sign, which rtrace does not).
fn coefficients(i: usize, x: f64) -> (f64, f64) {
    let i = i as f64;
    if x > i + 2.0 {
        let c0 = 1.0 / (i - 1.0 - x);
        (c0, -2.0 * c0)
    } else if x < i - 1.0 {
        let c1 = 1.0 / (x - i);
        (-2.0 * c1, c1)
    } else if x.is_nan() {
        (0.0, 0.0)
    } else {
        (i + 1.0 - x, x - i)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_inside_extrapolated_then_tapering_outside() {
        let d = DataArray::parse("t.dat", "1\n0 2 3\n1 3 4\n").unwrap();
        assert_eq!(d.value(&[0.0]), 1.0);
        assert_eq!(d.value(&[0.5]), 2.0);
        assert_eq!(d.value(&[1.5]), 3.5);
        // One division past the end: extrapolated along the last segment.
        assert!((d.value(&[3.0]) - 5.0).abs() < 1e-12);
        // Beyond: tapers to zero, from above and from below with the sign of the data (a
        // constant array reads 1 / (divisions beyond), as rtrace reads it).
        assert!(d.value(&[100.0]).abs() < 0.2);
        let one = DataArray::parse("one.dat", "1\n0 1 2\n1 1\n").unwrap();
        assert!((one.value(&[-1.5]) - 1.0 / 1.5).abs() < 1e-12);
        assert!((one.value(&[-5.0]) - 0.2).abs() < 1e-12);
        assert!((one.value(&[3.0]) - 0.25).abs() < 1e-12);
        let irregular = DataArray::parse("u.dat", "1\n0 0 3 0 1 4\n0 1 4\n").unwrap();
        assert!((irregular.value(&[2.5]) - 2.5).abs() < 1e-12);
        let two = DataArray::parse("v.dat", "2\n0 1 2\n0 1 2\n0 1\n2 3\n").unwrap();
        assert!((two.value(&[0.5, 0.5]) - 1.5).abs() < 1e-12);
    }

    #[test]
    fn malformed_files_name_the_file_and_line() {
        let e = DataArray::parse("bad.dat", "1\n0 1 3\n1 2\n").unwrap_err();
        assert_eq!((e.file.as_str(), e.line), ("bad.dat", 3));
        assert!(e.message.contains("end of file"), "{e}");
        let e = DataArray::parse("bad.dat", "9\n").unwrap_err();
        assert!(e.message.contains("number of dimensions"), "{e}");
        let e = DataArray::parse("bad.dat", "1\n0 0 3 1 3 2\n1 2 3").unwrap_err();
        assert!(e.message.contains("monotonic") && e.line == 2, "{e}");
        let e = DataArray::parse("bad.dat", "3\n0 1 4096\n0 1 4096\n0 1 4096\n").unwrap_err();
        assert!(e.message.contains("more than"), "{e}");
    }
}
