//! Variable-resolution tensor-tree BSDFs (`TensorTree3`, `TensorTree4`) with the semantics of
//! RADIANCE's `bsdf_t.c`: coordinates in the unit hypercube (incident then outgoing, each
//! through the Shirley–Chiu square), children ordered with dimension 0 as the lowest bit,
//! leaf grids with dimension 0 varying slowest, nearest-leaf lookup (no interpolation), and
//! the isotropic form folded onto the incident plane's azimuth.

use super::error::BsdfError;
use super::scattering_text::Token;
use super::shirley_chiu::{disk_to_square, square_to_disk};
use super::side::Side;
use super::xml::RawBlock;
use glam::DVec3;
use std::f64::consts::PI;

/// RADIANCE's FTINY for double vectors (`fvect.h`).
const FTINY: f64 = 1e-6;
/// Deepest branching accepted (cells of 2⁻²⁰ are far below any measurement).
const MAX_DEPTH: usize = 20;
/// The integer cell width RADIANCE's sampling uses (`iwmax`, 2¹⁶).
const CELL_WIDTH_UNITS: f64 = 65536.0;

#[derive(Debug, Clone)]
enum Node {
    /// 2^dims children.
    Branch(Vec<Node>),
    /// A grid of 2^(dims·log2_res) leaves.
    Grid { log2_res: u32, values: Vec<f32> },
}

/// One tensor tree of one part, in 1/sr.
#[derive(Debug, Clone)]
pub struct TensorTree {
    pub side: Side,
    dims: usize,
    root: Node,
}

/// A leaf met in a traversal: value, lower corner and width in the unit hypercube.
struct Leaf {
    value: f32,
    corner: [f64; 4],
    width: f64,
}

impl TensorTree {
    /// Reads one block of a `TensorTree3` (dims 3) or `TensorTree4` (dims 4) file.
    pub fn from_block(block: &RawBlock, dims: usize, file: &str) -> Result<TensorTree, BsdfError> {
        if let Some(basis) = &block.angle_basis {
            if !basis.name.eq_ignore_ascii_case("LBNL/Shirley-Chiu") {
                let message = format!(
                    "unsupported basis '{}' for a tensor tree (LBNL/Shirley-Chiu)",
                    basis.name
                );
                return Err(BsdfError::new(file, basis.line, "AngleBasis", message));
            }
        } else {
            return Err(BsdfError::new(
                file,
                block.line,
                "AngleBasis",
                "missing <AngleBasis> (LBNL/Shirley-Chiu)",
            ));
        }
        let mut tokens = block.data.tokens(file);
        let root = parse_node(&mut tokens, dims, 0)?;
        if let Some((_, line)) = tokens.next_token()? {
            return Err(tokens.error(line, "text after the end of the tree"));
        }
        Ok(TensorTree {
            side: Side::from_window(block.direction),
            dims,
            root,
        })
    }

    /// Width of the smallest leaf (RADIANCE `SDsmallestLeaf`).
    pub fn smallest_leaf(&self) -> f64 {
        let mut smallest = 1.0f64;
        self.visit(&mut |leaf| smallest = smallest.min(leaf.width));
        smallest
    }

    /// Calls `f` on every leaf.
    fn visit(&self, f: &mut dyn FnMut(&Leaf)) {
        self.visit_slice(&[None; 4], f);
    }

    /// Calls `f` on every leaf whose cell holds `fixed[i]` in each dimension given.
    fn visit_slice(&self, fixed: &[Option<f64>; 4], f: &mut dyn FnMut(&Leaf)) {
        visit_node(&self.root, self.dims, [0.0; 4], 1.0, fixed, f);
    }

    /// The leaf at `pos`: its value and lower corner (RADIANCE `SDlookupTre`).
    fn lookup(&self, pos: &[f64; 4]) -> (f32, [f64; 4]) {
        let (value, corner, _) = self.lookup_leaf(pos);
        (value, corner)
    }

    /// The projected solid angle π w² of the leaf holding a direction pair, w its width in
    /// the hypercube (RADIANCE `SDqueryTreProjSA` for two vectors); None when the pair is not
    /// this part's. As there, `v1` is the outgoing and `v2` the incident direction.
    pub fn pair_projected_solid_angle(&self, v1: DVec3, v2: DVec3) -> Option<f64> {
        let pos = self.position(v2, v1)?;
        let (_, _, width) = self.lookup_leaf(&pos);
        Some(PI * width * width)
    }

    /// [`TensorTree::lookup`] with the leaf's width.
    fn lookup_leaf(&self, pos: &[f64; 4]) -> (f32, [f64; 4], f64) {
        let mut corner = [0.0; 4];
        let mut width = 1.0;
        let mut p = *pos;
        let mut node = &self.root;
        loop {
            match node {
                Node::Branch(children) => {
                    width *= 0.5;
                    let mut n = 0;
                    for i in 0..self.dims {
                        let s = 2.0 * p[i];
                        let upper = s >= 1.0;
                        n |= (upper as usize) << i;
                        p[i] = s - upper as u8 as f64;
                        corner[i] += upper as u8 as f64 * width;
                    }
                    node = &children[n];
                }
                Node::Grid { log2_res, values } => {
                    let res = 1usize << log2_res;
                    let mut index = 0;
                    for i in 0..self.dims {
                        let k = ((res as f64 * p[i]) as usize).min(res - 1);
                        index = index * res + k;
                        corner[i] += (res as f64 * p[i]).floor().max(0.0) * width / res as f64;
                    }
                    return (values[index], corner, width / res as f64);
                }
            }
        }
    }

    /// The largest directional-hemispherical value over incident cells (`get_extrema`).
    pub fn max_hemispherical(&self) -> f64 {
        let step = self.smallest_leaf().max(0.03125);
        let limit = if self.dims == 3 {
            0.5 - FTINY
        } else {
            1.0 - FTINY
        };
        let mut max_hemi = 0.0f64;
        let mut b0 = 0.0;
        while b0 < limit {
            let mut b1 = 0.0;
            loop {
                let mut lo = [b0, b1, 0.0, 0.0];
                let mut hi = [b0 + step, b1 + step, 1.0, 1.0];
                if self.dims == 3 {
                    (lo[1], hi[1]) = (0.0, 1.0);
                }
                max_hemi = max_hemi.max(average_over_box(&self.root, self.dims, &lo, &hi));
                b1 += step;
                if self.dims == 3 || b1 >= 1.0 - FTINY {
                    break;
                }
            }
            b0 += step;
        }
        PI * max_hemi
    }

    /// Takes the smallest value out as a Lambertian part and returns its hemispherical value
    /// π·min, unless it is below 0.01 or above 1.5 (RADIANCE `subtract_min_Y`; the isotropic
    /// form skips its unused half, incident coordinates ≥ 0.5).
    pub fn extract_diffuse(&mut self) -> f64 {
        let cap = (1.5 / PI) as f32;
        let mut min_value = if self.dims == 3 { cap } else { f32::MAX };
        let dims = self.dims;
        self.visit(&mut |leaf| {
            if dims == 4 || leaf.corner[0] < 0.5 {
                min_value = min_value.min(leaf.value);
            }
        });
        if min_value >= cap || min_value as f64 <= 0.01 / PI {
            return 0.0;
        }
        subtract(&mut self.root, min_value);
        PI * min_value as f64
    }

    /// Hypercube position of a direction pair, or None when the pair is not this part's
    /// (RADIANCE `SDqueryTre`; transmission answers either way round by reciprocity).
    fn position(&self, incident: DVec3, outgoing: DVec3) -> Option<[f64; 4]> {
        let (i, o) = match self.side {
            Side::FrontReflection if outgoing.z < 0.0 || incident.z < 0.0 => return None,
            Side::BackReflection if outgoing.z > 0.0 || incident.z > 0.0 => return None,
            Side::FrontTransmission if outgoing.z > 0.0 => {
                (incident.z <= 0.0).then_some((outgoing, incident))?
            }
            Side::FrontTransmission if incident.z < 0.0 => return None,
            Side::BackTransmission if incident.z > 0.0 => {
                (outgoing.z <= 0.0).then_some((outgoing, incident))?
            }
            Side::BackTransmission if outgoing.z < 0.0 => return None,
            _ => (incident, outgoing),
        };
        Some(self.hypercube(i, o))
    }

    fn hypercube(&self, incident: DVec3, outgoing: DVec3) -> [f64; 4] {
        if self.dims == 3 {
            let turned = turn_about_z(outgoing, -(-incident.y).atan2(-incident.x));
            let [s0, s1] = disk_to_square(turned.x, turned.y);
            [isotropic_coordinate(incident), s0, s1, 0.0]
        } else {
            let [a, b] = disk_to_square(-incident.x, -incident.y);
            let [c, d] = disk_to_square(outgoing.x, outgoing.y);
            [a, b, c, d]
        }
    }

    /// f(ωi, ωo) of this part in 1/sr, or 0 when the pair is not this part's. RADIANCE
    /// perturbs each leaf by up to ±0.02 % from its corner (`SDqueryTre`); kept for agreement.
    pub fn eval(&self, incident: DVec3, outgoing: DVec3) -> f64 {
        let Some(pos) = self.position(incident, outgoing) else {
            return 0.0;
        };
        let (value, corner) = self.lookup(&pos);
        let d: f64 = (0..self.dims)
            .map(|i| {
                let x = (2u32 << i) as f64 / (corner[i] + 0.01687);
                x - x.trunc() - 0.5
            })
            .sum();
        (value as f64 * (1.0 + 1e-4 * d)) as f32 as f64
    }

    /// The outgoing distribution for `incident`, with the incident coordinates quantized to
    /// `quantum` as RADIANCE does (`SDgetTreCDist`, `make_cdist`). None when `incident` is
    /// not on this part's side, or for an isotropic tree used the other way round, which
    /// RADIANCE does not handle either ("XXX unhandled reciprocity").
    pub fn distribution(&self, incident: DVec3, quantum: f64) -> Option<CellDistribution<'_>> {
        let reversed = match self.side {
            Side::FrontReflection if incident.z < 0.0 => return None,
            Side::BackReflection if incident.z > 0.0 => return None,
            Side::FrontTransmission => incident.z < 0.0,
            Side::BackTransmission => incident.z > 0.0,
            _ => false,
        };
        if reversed && self.dims == 3 {
            return None;
        }
        let mut coords = if self.dims == 3 {
            vec![isotropic_coordinate(incident)]
        } else if reversed {
            disk_to_square(incident.x, incident.y).to_vec()
        } else {
            disk_to_square(-incident.x, -incident.y).to_vec()
        };
        for c in coords.iter_mut() {
            *c = (*c / quantum).floor() * quantum + 0.5 * quantum;
        }
        if coords.iter().any(|c| !(0.0..1.0).contains(c)) {
            return None;
        }
        let offset = if reversed { 2 } else { 0 };
        let mut fixed = [None; 4];
        for (k, c) in coords.iter().enumerate() {
            fixed[offset + k] = Some(*c);
        }
        Some(CellDistribution::build(self, incident, fixed, reversed))
    }
}

/// The incident coordinate of the isotropic form: 0.5 − sinθ/2, so [0, 0.5) is used.
fn isotropic_coordinate(incident: DVec3) -> f64 {
    (0.5 - FTINY) - 0.5 * (incident.x * incident.x + incident.y * incident.y).sqrt()
}

/// `v` turned by `angle` (radians, right-handed) about +z (RADIANCE `spinvector`).
fn turn_about_z(v: DVec3, angle: f64) -> DVec3 {
    if angle == 0.0 {
        return v;
    }
    let (s, c) = angle.sin_cos();
    DVec3::new(v.x * c - v.y * s, v.y * c + v.x * s, v.z)
}

fn parse_node(
    tokens: &mut super::scattering_text::Tokens,
    dims: usize,
    depth: usize,
) -> Result<Node, BsdfError> {
    let line = tokens.line();
    match tokens.next_token()? {
        Some((Token::Open, _)) => {}
        _ => return Err(tokens.error(line, "missing '{' in tensor tree")),
    }
    if depth > MAX_DEPTH {
        return Err(tokens.error(line, format!("tensor tree deeper than {MAX_DEPTH} levels")));
    }
    let mut values = Vec::new();
    let mut children = Vec::new();
    loop {
        let line = tokens.line();
        let mut lookahead = tokens.clone();
        match lookahead.next_token()? {
            Some((Token::Open, _)) if values.is_empty() => {
                children.push(parse_node(tokens, dims, depth + 1)?)
            }
            Some((Token::Value(v), _)) if children.is_empty() => {
                values.push(v);
                *tokens = lookahead;
            }
            Some((Token::Close, _)) => {
                *tokens = lookahead;
                break;
            }
            Some(_) => {
                return Err(tokens.error(line, "values and branches mixed in one tensor-tree node"))
            }
            None => return Err(tokens.error(line, "missing '}' in tensor tree (truncated?)")),
        }
    }
    if !children.is_empty() {
        if children.len() != 1 << dims {
            let message = format!(
                "a branch has {} children, a {dims}-D tree needs {}",
                children.len(),
                1 << dims
            );
            return Err(tokens.error(line, message));
        }
        return Ok(Node::Branch(children));
    }
    let n = values.len();
    let log2_res = (0..=(30 / dims) as u32).find(|k| 1usize << (dims as u32 * k) == n);
    match log2_res {
        Some(log2_res) => Ok(Node::Grid { log2_res, values }),
        None => Err(tokens.error(line, format!("{n} values in a leaf grid, not 2^({dims}·k)"))),
    }
}

fn visit_node(
    node: &Node,
    dims: usize,
    corner: [f64; 4],
    width: f64,
    fixed: &[Option<f64>; 4],
    f: &mut dyn FnMut(&Leaf),
) {
    match node {
        Node::Branch(children) => {
            let half = 0.5 * width;
            for (n, child) in children.iter().enumerate() {
                let mut c = corner;
                let mut keep = true;
                for i in 0..dims {
                    let upper = n >> i & 1 == 1;
                    if upper {
                        c[i] += half;
                    }
                    if let Some(p) = fixed[i] {
                        keep &= (p < corner[i] + half) != upper;
                    }
                }
                if keep {
                    visit_node(child, dims, c, half, fixed, f);
                }
            }
        }
        Node::Grid { log2_res, values } => {
            visit_grid(*log2_res, values, dims, corner, width, fixed, f)
        }
    }
}

fn visit_grid(
    log2_res: u32,
    values: &[f32],
    dims: usize,
    corner: [f64; 4],
    width: f64,
    fixed: &[Option<f64>; 4],
    f: &mut dyn FnMut(&Leaf),
) {
    let res = 1usize << log2_res;
    let cell = width / res as f64;
    let mut ranges = [(0usize, 1usize); 4];
    for i in 0..dims {
        ranges[i] = match fixed[i] {
            Some(p) => {
                let k = (((p - corner[i]) / cell) as usize).min(res - 1);
                (k, k + 1)
            }
            None => (0, res),
        };
    }
    let mut index = [0usize; 4];
    let count: usize = ranges[..dims].iter().map(|r| r.1 - r.0).product();
    for mut step in 0..count {
        for i in (0..dims).rev() {
            let span = ranges[i].1 - ranges[i].0;
            index[i] = ranges[i].0 + step % span;
            step /= span;
        }
        let flat = index[..dims].iter().fold(0, |acc, &k| acc * res + k);
        let mut c = corner;
        for i in 0..dims {
            c[i] += index[i] as f64 * cell;
        }
        f(&Leaf {
            value: values[flat],
            corner: c,
            width: cell,
        });
    }
}

/// Mean leaf value over the box [lo, hi) in the node's unit cube (RADIANCE `SDavgTreBox`).
fn average_over_box(node: &Node, dims: usize, lo: &[f64; 4], hi: &[f64; 4]) -> f64 {
    for i in 0..dims {
        if lo[i] >= 1.0 || hi[i] <= 0.0 || lo[i] >= hi[i] {
            return 0.0;
        }
    }
    match node {
        Node::Branch(children) => {
            let (mut sum, mut weights) = (0.0, 1e-20);
            for (n, child) in children.iter().enumerate() {
                let (mut sub_lo, mut sub_hi) = ([0.0; 4], [0.0; 4]);
                let mut w = 1.0;
                for i in 0..dims {
                    let shift = (n >> i & 1) as f64;
                    sub_lo[i] = (2.0 * lo[i] - shift).max(0.0);
                    sub_hi[i] = (2.0 * hi[i] - shift).min(1.0);
                    w *= (sub_hi[i] - sub_lo[i]).max(0.0);
                }
                if w > 1e-10 {
                    sum += w * average_over_box(child, dims, &sub_lo, &sub_hi);
                    weights += w;
                }
            }
            sum / weights
        }
        Node::Grid { log2_res, values } => {
            let res = 1usize << log2_res;
            let mut ranges = [(0usize, 1usize); 4];
            for i in 0..dims {
                let first = if lo[i] <= 0.0 {
                    0
                } else {
                    (res as f64 * lo[i]) as usize
                };
                let last = if hi[i] >= 1.0 {
                    res
                } else {
                    ((res as f64 * hi[i] + 0.999999) as usize).min(res)
                };
                ranges[i] = (first, last.max(first));
            }
            let count: usize = ranges[..dims].iter().map(|r| r.1 - r.0).product();
            let mut sum = 0.0;
            for mut step in 0..count {
                let mut flat = 0;
                let mut stride = 1;
                for i in (0..dims).rev() {
                    let span = ranges[i].1 - ranges[i].0;
                    flat += (ranges[i].0 + step % span) * stride;
                    stride *= res;
                    step /= span;
                }
                sum += values[flat] as f64;
            }
            if count == 0 {
                0.0
            } else {
                sum / count as f64
            }
        }
    }
}

fn subtract(node: &mut Node, amount: f32) {
    match node {
        Node::Branch(children) => children.iter_mut().for_each(|c| subtract(c, amount)),
        Node::Grid { values, .. } => values.iter_mut().for_each(|v| *v = (*v - amount).max(0.0)),
    }
}

/// One outgoing cell of a distribution: its square, in outgoing Shirley–Chiu coordinates.
struct OutgoingCell {
    corner: [f64; 2],
    width: f64,
    value: f64,
}

/// Scattered directions for one incident direction, by cell weight f·area.
pub struct CellDistribution<'a> {
    tree: &'a TensorTree,
    incident: DVec3,
    fixed: [Option<f64>; 4],
    reversed: bool,
    cells: Vec<OutgoingCell>,
    cumulative: Vec<f64>,
}

impl<'a> CellDistribution<'a> {
    fn build(
        tree: &'a TensorTree,
        incident: DVec3,
        fixed: [Option<f64>; 4],
        reversed: bool,
    ) -> Self {
        let mut cells = Vec::new();
        let out = if reversed { 0 } else { tree.dims - 2 };
        tree.visit_slice(&fixed, &mut |leaf| {
            let mut corner = [leaf.corner[out], leaf.corner[out + 1]];
            if reversed {
                corner = [1.0 - corner[0] - leaf.width, 1.0 - corner[1] - leaf.width];
            }
            cells.push(OutgoingCell {
                corner,
                width: leaf.width,
                value: leaf.value as f64,
            });
        });
        let mut cumulative = Vec::with_capacity(cells.len() + 1);
        let mut sum = 0.0;
        cumulative.push(0.0);
        for cell in &cells {
            // RADIANCE weighs by integer widths in units of 2⁻¹⁶ (`build_scaffold`).
            let units = (cell.width * CELL_WIDTH_UNITS + 0.5).floor();
            sum += cell.value * units * units;
            cumulative.push(sum);
        }
        CellDistribution {
            tree,
            incident,
            fixed,
            reversed,
            cells,
            cumulative,
        }
    }

    /// ∫ f cos θo dωo over the scattered hemisphere: π Σ value·area (`make_cdist`).
    pub fn total(&self) -> f64 {
        (1e-20 + self.cumulative.last().unwrap_or(&0.0)) * PI
            / (CELL_WIDTH_UNITS * CELL_WIDTH_UNITS)
    }

    /// Does this distribution send light out to +z?
    fn outgoing_front(&self) -> bool {
        let side = if self.reversed {
            self.tree.side.reversed()
        } else {
            self.tree.side
        };
        side.outgoing_front()
    }

    /// A scattered direction for `u` in [0,1)³, uniform in projected solid angle in its cell.
    pub fn sample(&self, u: [f64; 3]) -> DVec3 {
        if self.cells.is_empty() {
            return DVec3::ZERO;
        }
        let target = u[0] * self.cumulative.last().copied().unwrap_or(0.0);
        let k = self
            .cumulative
            .partition_point(|&c| c <= target)
            .clamp(1, self.cells.len().max(1))
            - 1;
        let cell = &self.cells[k.min(self.cells.len() - 1)];
        let [x, y] = square_to_disk(
            cell.corner[0] + u[1] * cell.width,
            cell.corner[1] + u[2] * cell.width,
        );
        let mut z = (1.0 - x * x - y * y).max(0.0).sqrt();
        if !self.outgoing_front() {
            z = -z;
        }
        let v = DVec3::new(x, y, z);
        if self.tree.dims == 3 {
            turn_about_z(v, (-self.incident.y).atan2(-self.incident.x))
        } else {
            v
        }
    }

    /// The density of `sample` per projected steradian times `total`, at `outgoing`.
    pub fn weight_per_projected_sr(&self, outgoing: DVec3) -> f64 {
        if (outgoing.z > 0.0) != self.outgoing_front() || self.cells.is_empty() {
            return 0.0;
        }
        let mut pos = [0.0; 4];
        for (i, p) in self.fixed.iter().enumerate() {
            if let Some(p) = p {
                pos[i] = *p;
            }
        }
        if self.tree.dims == 3 {
            let turned = turn_about_z(outgoing, -(-self.incident.y).atan2(-self.incident.x));
            [pos[1], pos[2]] = disk_to_square(turned.x, turned.y);
        } else if self.reversed {
            let [a, b] = disk_to_square(outgoing.x, outgoing.y);
            [pos[0], pos[1]] = [1.0 - a, 1.0 - b];
        } else {
            [pos[2], pos[3]] = disk_to_square(outgoing.x, outgoing.y);
        }
        self.tree.lookup(&pos).0 as f64
    }
}
