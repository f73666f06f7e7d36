//! `gensurf material name 'x(s,t)' 'y(s,t)' 'z(s,t)' m n [-s] [-i] [-e expr] [-f file]`: a
//! parametric surface tessellated into an m by n grid of quadrilaterals (or pairs of
//! triangles where a quadrilateral is not flat), as RADIANCE's gensurf.c writes it. The
//! normal follows the right-hand rule in (s, t) (`-i` turns it round). A function
//! `valid(s,t)` that is not positive drops a vertex. `-s` smooths the surface: each polygon
//! gets a `texfunc Phong` of `surf.cal` that interpolates the vertex normals (bilinearly, on
//! the two coordinates across the dominant axis). Where `z(s,t)` names a readable file, the
//! surface comes from its points (z alone, or x, y and z when all three name it), bilinearly
//! interpolated. `-o` (Wavefront output) is not scene text and is refused.

use super::functions::Functions;
use super::text::polygon;
use glam::DVec3;
use std::fmt::Write as _;
use std::path::Path;

const USAGE: &str = "gensurf material name x(s,t) y(s,t) z(s,t) m n [-s] [-i] [-e expr] [-f file]";
/// Most steps along s or t, and most cells in all.
const MAX_STEPS: usize = 10_000;
const MAX_CELLS: usize = 250_000;
/// RADIANCE's `FTINY` (fvect.h).
const TINY: f64 = 1e-6;
const NAMES: [&str; 3] = ["X`SYS`", "Y`SYS`", "Z`SYS`"];
const WHAT: [&str; 3] = ["x(s,t)", "y(s,t)", "z(s,t)"];

/// One grid vertex, as gensurf.c keeps it.
#[derive(Clone, Copy, Default)]
struct Vertex {
    valid: bool,
    p: DVec3,
    /// Averaged normal (smoothing only).
    n: DVec3,
}

/// Points read from a data file (gensurf.c `loaddata`): t-major, s fastest.
struct DataGrid {
    /// Values per point: 1 (z) or 3 (x, y, z).
    per_point: usize,
    /// Points along s and t.
    m: usize,
    n: usize,
    /// Whether the points include the borders (m + 1 by n + 1 for an m by n surface) or
    /// sit at the cells' centres (m by n).
    border: bool,
    values: Vec<f64>,
}

impl DataGrid {
    fn read(path: &Path, m: usize, n: usize, per_point: usize) -> Result<Self, String> {
        let text = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let text = String::from_utf8_lossy(&text);
        let with_border = (m + 1) * (n + 1) * per_point;
        let mut values = Vec::with_capacity(with_border.min(1 << 16));
        for word in text.split_whitespace() {
            if values.len() == with_border {
                return Err(format!(
                    "{}: bad number of data points (more than {with_border})",
                    path.display()
                ));
            }
            let v = word
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| format!("{}: garbled data value: {word}", path.display()))?;
            values.push(v);
        }
        let grid = if values.len() == with_border {
            Self {
                per_point,
                m: m + 1,
                n: n + 1,
                border: true,
                values,
            }
        } else if values.len() == m * n * per_point {
            Self {
                per_point,
                m,
                n,
                border: false,
                values,
            }
        } else {
            return Err(format!(
                "{}: bad number of data points ({} values for {m} x {n} or {} x {} points of {per_point})",
                path.display(),
                values.len(),
                m + 1,
                n + 1
            ));
        };
        if grid.m < 2 || grid.n < 2 {
            return Err(format!(
                "{}: bad number of data points (fewer than 2 x 2)",
                path.display()
            ));
        }
        Ok(grid)
    }

    /// Component `k` (of `per_point`) at (s, t), bilinearly (gensurf.c `l_dataval`).
    fn value(&self, k: usize, s: f64, t: f64) -> f64 {
        let (u, v) = if self.border {
            (s * (self.m - 1) as f64, t * (self.n - 1) as f64)
        } else {
            (s * self.m as f64 - 0.5, t * self.n as f64 - 0.5)
        };
        // C's conversion truncates towards zero, then the index is clamped to the grid.
        let clamp = |x: f64, count: usize| (x.trunc().max(0.0) as usize).min(count - 2);
        let (i, j) = (clamp(u, self.m), clamp(v, self.n));
        let at = |i: usize, j: usize| self.values[self.per_point * (j * self.m + i) + k];
        let (fi, fj) = (i as f64, j as f64);
        (fj + 1.0 - v) * ((fi + 1.0 - u) * at(i, j) + (u - fi) * at(i + 1, j))
            + (v - fj) * ((fi + 1.0 - u) * at(i, j + 1) + (u - fi) * at(i + 1, j + 1))
    }
}

/// Where the coordinates come from.
struct Surface {
    functions: Functions,
    data: Option<DataGrid>,
    check_valid: bool,
}

impl Surface {
    fn vertex(&self, s: f64, t: f64) -> Result<Vertex, String> {
        if self.check_valid && self.functions.value("valid", &[s, t], "valid(s,t)")? <= 0.0 {
            return Ok(Vertex::default());
        }
        let mut p = [0.0; 3];
        for (k, c) in p.iter_mut().enumerate() {
            *c = match &self.data {
                Some(d) if d.per_point == 3 => d.value(k, s, t),
                Some(d) if k == 2 => d.value(0, s, t),
                _ => self.functions.value(NAMES[k], &[s, t], WHAT[k])?,
            };
        }
        Ok(Vertex {
            valid: true,
            p: DVec3::from_array(p),
            n: DVec3::ZERO,
        })
    }
}

/// The generator's state: options, rows and the polygon count.
struct Writer<'a> {
    material: &'a str,
    name: &'a str,
    smooth: bool,
    reverse: bool,
    polygons: usize,
    out: String,
}

pub(super) fn generate(args: &[String], dir: &Path) -> Result<String, String> {
    if args.len() < 7 {
        return Err(format!("{} argument(s) given; usage: {USAGE}", args.len()));
    }
    let mut functions = Functions::new();
    let flags = functions.options(&args[7..], dir, &["-s", "-i", "-o"], USAGE)?;
    if flags.contains(&"-o") {
        return Err("-o writes Wavefront .OBJ, not a scene: use it outside the scene".into());
    }
    let m = functions.count(&args[5], "m", MAX_STEPS)?;
    let n = functions.count(&args[6], "n", MAX_STEPS)?;
    if m * n > MAX_CELLS {
        return Err(format!("{m} x {n} cells: more than {MAX_CELLS}"));
    }
    let data = if args[4] == "-" {
        return Err("points from standard input (`-`) cannot be read in a scene".into());
    } else if dir.join(&args[4]).is_file() {
        let all = args[4] == args[2] && args[4] == args[3];
        let grid = DataGrid::read(&dir.join(&args[4]), m, n, if all { 3 } else { 1 })?;
        if !all {
            functions.define(NAMES[0], "s,t", &args[2], WHAT[0])?;
            functions.define(NAMES[1], "s,t", &args[3], WHAT[1])?;
        }
        Some(grid)
    } else {
        for k in 0..3 {
            functions.define(NAMES[k], "s,t", &args[2 + k], WHAT[k])?;
        }
        None
    };
    let check_valid = functions.has_function("valid", 2);
    let surface = Surface {
        functions,
        data,
        check_valid,
    };
    let mut w = Writer {
        material: &args[0],
        name: &args[1],
        smooth: flags.contains(&"-s"),
        reverse: flags.contains(&"-i"),
        polygons: 0,
        out: String::new(),
    };
    // Three rows of n + 3 vertices (one beyond each end for the smoothed normals), reused
    // in turn as gensurf.c reuses its buffers: a vertex left invalid keeps the normal its
    // buffer last held, and the polygons around it use that.
    let mut rows = [
        vec![Vertex::default(); n + 3],
        vec![Vertex::default(); n + 3],
        vec![Vertex::default(); n + 3],
    ];
    for (k, row) in rows.iter_mut().enumerate() {
        w.compute_row(&surface, (k as f64 - 1.0) / m as f64, row, n)?;
    }
    w.compute_normals(&mut rows, n);
    for i in 0..m {
        rows.rotate_left(1);
        w.compute_row(&surface, (i + 2) as f64 / m as f64, &mut rows[2], n)?;
        w.compute_normals(&mut rows, n);
        let (r0, r1) = (&rows[0], &rows[1]);
        // Index k of a row is the vertex at t = (k - 1) / n.
        for j in 1..=n {
            let mut flip = (j - 1) % 2 == 1;
            if !(r0[j].valid && r1[j + 1].valid) {
                flip = true;
            } else if !(r1[j].valid && r0[j + 1].valid) {
                flip = false;
            }
            if flip {
                w.square([&r0[j], &r1[j], &r0[j + 1], &r1[j + 1]])?;
            } else {
                w.square([&r1[j], &r1[j + 1], &r0[j], &r0[j + 1]])?;
            }
        }
    }
    Ok(w.out)
}

impl Writer<'_> {
    /// The vertices of the row at `s`: t from 0 to 1, and one step beyond each end when
    /// smoothing. Without smoothing a row outside [0, 1] is not computed (never used).
    fn compute_row(
        &self,
        surface: &Surface,
        s: f64,
        row: &mut [Vertex],
        n: usize,
    ) -> Result<(), String> {
        let range = if self.smooth {
            0..=n + 2
        } else {
            if !(-TINY..=1.0 + TINY).contains(&s) {
                return Ok(());
            }
            1..=n + 1
        };
        for k in range {
            let t = (k as f64 - 1.0) / n as f64;
            let keep_normal = row[k].n;
            row[k] = surface.vertex(s, t)?;
            // gensurf.c leaves an invalid vertex's normal as it was.
            row[k].n = keep_normal;
        }
        Ok(())
    }

    /// The averaged normals of the middle row from its neighbours across and along.
    fn compute_normals(&self, rows: &mut [Vec<Vertex>; 3], n: usize) {
        if !self.smooth {
            return;
        }
        for k in 1..=n + 1 {
            let (r0, r1, r2) = (&rows[0], &rows[1], &rows[2]);
            if !r1[k].valid {
                continue;
            }
            let across = match (r0[k].valid, r2[k].valid) {
                (false, false) => None,
                (false, true) => Some(r2[k].p - r1[k].p),
                (true, false) => Some(r1[k].p - r0[k].p),
                (true, true) => Some(r2[k].p - r0[k].p),
            };
            let along = match (r1[k - 1].valid, r1[k + 1].valid) {
                (false, false) => None,
                (false, true) => Some(r1[k + 1].p - r1[k].p),
                (true, false) => Some(r1[k].p - r1[k - 1].p),
                (true, true) => Some(r1[k + 1].p - r1[k - 1].p),
            };
            rows[1][k].n = match (across, along) {
                (Some(v1), Some(v2)) => {
                    let c = if self.reverse {
                        v2.cross(v1)
                    } else {
                        v1.cross(v2)
                    };
                    normalize(c).0
                }
                _ => DVec3::ZERO,
            };
        }
    }

    /// One grid cell: a flat quadrilateral, or its two triangles (or the one whose three
    /// vertices are valid).
    fn square(&mut self, p: [&Vertex; 4]) -> Result<(), String> {
        let [p0, mut p1, mut p2, p3] = p;
        if self.reverse {
            std::mem::swap(&mut p1, &mut p2);
        }
        let (vc1, ok1) = if p0.valid && p1.valid && p2.valid {
            normalize((p1.p - p0.p).cross(p2.p - p0.p))
        } else {
            (DVec3::ZERO, false)
        };
        let (vc2, ok2) = if p1.valid && p2.valid && p3.valid {
            normalize((p2.p - p3.p).cross(p1.p - p3.p))
        } else {
            (DVec3::ZERO, false)
        };
        if !(ok1 || ok2) {
            return Ok(());
        }
        let interpolation = if self.smooth {
            normal_interpolation([p0, p1, p2, p3])
        } else {
            None
        };
        if ok1 && ok2 && vc1.dot(vc2) >= 1.0 - TINY * TINY {
            self.polygon(
                interpolation,
                -0.5 * vc1 - 0.5 * vc2,
                &[p0.p, p1.p, p3.p, p2.p],
            )?;
            return Ok(());
        }
        if ok1 {
            self.polygon(interpolation, -vc1, &[p0.p, p1.p, p2.p])?;
        }
        if ok2 {
            self.polygon(interpolation, -vc2, &[p2.p, p1.p, p3.p])?;
        }
        Ok(())
    }

    /// A polygon, after its `texfunc Phong` when smoothing found an interpolation (whose
    /// constant term is offset by `offset`: surf.cal adds the polygon's own normal back).
    fn polygon(
        &mut self,
        interpolation: Option<(usize, [DVec3; 4])>,
        offset: DVec3,
        vertices: &[DVec3],
    ) -> Result<(), String> {
        self.polygons += 1;
        let id = format!("{}.{}", self.name, self.polygons);
        let points: Vec<[f64; 3]> = vertices.iter().map(|v| v.to_array()).collect();
        if points.iter().flatten().any(|c| !c.is_finite()) {
            return Err(format!("{id}: a vertex is not finite"));
        }
        let Some((axis, m)) = interpolation else {
            polygon(&mut self.out, self.material, &id, &points);
            return Ok(());
        };
        let last = m[3] + offset;
        let _ = write!(
            self.out,
            "\n{} texfunc Phong\n4 surf_dx surf_dy surf_dz surf.cal\n0\n13 {axis}",
            self.material
        );
        for v in [m[0], m[1], m[2], last] {
            if !v.is_finite() {
                return Err(format!("{id}: the smoothing normals are not finite"));
            }
            let _ = write!(self.out, " {} {} {}", v.x, v.y, v.z);
        }
        self.out.push('\n');
        polygon(&mut self.out, "Phong", &id, &points);
        Ok(())
    }
}

/// fvect.c `normalize`: the unit vector and whether the length was not zero.
fn normalize(v: DVec3) -> (DVec3, bool) {
    let l2 = v.length_squared();
    if l2 <= 0.0 {
        return (v, false);
    }
    (v / l2.sqrt(), true)
}

/// gensurf.c `norminterp`: the dominant axis of the summed vertex normals, and the 4 x 3
/// matrix that maps (u v, u, v, 1) of the two other coordinates to the normal, solved so that
/// it gives each vertex's own normal at that vertex. `None` when the system is singular.
fn normal_interpolation(p: [&Vertex; 4]) -> Option<(usize, [DVec3; 4])> {
    let sum = p[0].n + p[1].n + p[2].n + p[3].n;
    let mut axis = if sum.x.abs() > sum.y.abs() { 0 } else { 1 };
    if sum[axis].abs() <= sum.z.abs() {
        axis = 2;
    }
    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut rows = [[0.0; 4]; 4];
    for (row, q) in rows.iter_mut().zip(&p) {
        *row = [q.p[u] * q.p[v], q.p[u], q.p[v], 1.0];
    }
    let inverse = invert4(rows)?;
    let mut out = [DVec3::ZERO; 4];
    for (j, o) in out.iter_mut().enumerate() {
        *o = (0..4).fold(DVec3::ZERO, |acc, k| acc + inverse[j][k] * p[k].n);
    }
    Some((axis, out))
}

/// mat4.c `invmat4`: Gauss-Jordan with partial pivoting; `None` when no pivot exceeds
/// `FTINY` in magnitude.
fn invert4(mut a: [[f64; 4]; 4]) -> Option<[[f64; 4]; 4]> {
    let mut inv = [[0.0; 4]; 4];
    for (i, row) in inv.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for i in 0..4 {
        let mut pivot = None;
        let mut largest = TINY;
        for (k, row) in a.iter().enumerate().skip(i) {
            if row[i].abs() > largest {
                largest = row[i].abs();
                pivot = Some(k);
            }
        }
        let k = pivot?;
        a.swap(i, k);
        inv.swap(i, k);
        let d = a[i][i];
        for c in 0..4 {
            a[i][c] /= d;
            inv[i][c] /= d;
        }
        for j in 0..4 {
            if j != i {
                let f = a[j][i];
                for c in 0..4 {
                    a[j][c] -= a[i][c] * f;
                    inv[j][c] -= inv[i][c] * f;
                }
            }
        }
    }
    Some(inv)
}
