//! The BVH ray unit's memory formats and its bit-exact golden model (issue 22 item 4): the
//! unit holds the room's tree in block RAM, takes rays as f32 words, traverses in the fabric
//! and streams out the leaves the ray may reach, for the HPS to finish exactly. Written here
//! once for the RTL, the engine (`skylux_hps::engine::bvh_unit`) and the tests.
//!
//! # Why the answer is conservative (no false miss)
//!
//! The unit tests, exactly in integers, the ray `o' + t d'` on the 2^-12 m grid of
//! [`crate::raybox_format`], where `o'` is the f32 origin truncated to the grid and
//! `d'_i = 1 / inv'_i` with `inv'_i` the f32 inverse direction read as a 24-bit mantissa and
//! a shift (exact: f32's significand is the format's normalised mantissa). Against the true
//! ray `o + t d`:
//! - origin: f32 rounding, at most 2^-24 × 256 m = 0.0625 step, plus truncation, under
//!   1 step;
//! - direction: f32 rounding of `1/d_i` is relative 2^-24, so `|d'_i - d_i| <= 2^-24 |d_i|
//!   (1 + 2^-23)`; an inverse beyond the mantissa's range (`|d_i| <= 2^-24`, including 0) is
//!   clamped to `MANT_MAX`, so `|d'_i - d_i| <= 2^-24 (1 + 2^-23)`. Every point of a box in the
//!   ±256 m range lies within 512√3 m = 887 m of an origin in that range, so `t |d| <= 887 m`
//!   wherever it matters and, for `|d| >= 1/2` (the HPS sends no other ray), the deviation is
//!   at most 887 m × 2 × 2^-24 (1 + 2^-23) = 0.43 step.
//!
//! So each point of the true ray is within 1.5 steps per axis of the unit's ray at the same
//! `t`; the HPS rounds each box outward and grows it by [`GROWTH_STEPS`] = 2 steps, and the
//! ray's interval is widened by 2 steps each way (the conversion truncates, error under one
//! step). The unit's slab test then reports every box the true ray crosses, with an entry
//! distance never after the true one (the slab test's own outward rounding,
//! [`crate::raybox_format`]).
//!
//! # Node memory
//!
//! `bvh.node_count` nodes of [`NODE_WORDS`] little-endian 64-bit words, node 0 first. A node
//! holds two children: each a box (lower and upper corners, three 21-bit coordinates a word,
//! as `raybox_format`'s planes) and a 16-bit reference:
//!
//! ```text
//! word 0  child 0 lower corner  [20:0] x  [41:21] y  [62:42] z
//! word 1  child 0 upper corner
//! word 2  child 1 lower corner
//! word 3  child 1 upper corner
//! word 4  [15:0] child 0 reference  [31:16] child 1 reference  [55:32] 0  [63:56] NODE_MAGIC
//!
//! reference  [15] valid  [14] leaf  [13:0] index: a node of this memory, or (leaf) the
//!            HPS's own leaf number, returned as is
//! ```
//!
//! Traversal starts at node 0 (the HPS makes it hold the tree's root as its child 0).
//!
//! # Rays and results (format v2)
//!
//! A ray is [`RAY_WORDS`] words of f32 bit patterns: `origin x | origin y << 32`,
//! `origin z | inv x << 32`, `inv y | inv z << 32`, `t_min | t_max << 32`. For each ray the
//! unit writes its candidates as it finds them, then one end word; every word carries the
//! ray's tag:
//!
//! ```text
//! candidate  [31:0] t_near (2^-12 m, signed)  [45:32] leaf  [53:46] tag  [62:54] 0  [63] 0
//! end        [31:0] candidates written  [39:32] refusal (0: none)  [47:40] tag  [62:48] 0
//!            [63] 1
//! ```
//!
//! **Tags.** A ray's tag is its sequence number modulo 256 ([`TAG_BITS`]): the number of rays
//! the unit accepted before it since it was last idle. The unit is idle when it holds no ray
//! word, traverses no ray and has no result word unread; its tag counter restarts at 0 on
//! every such clock (power-up is one). So a HPS that sends a ray only after reading the end
//! word of every ray it sent before numbers its rays 0, 1, 2, ... from that ray on, in the
//! order it sends them.
//!
//! **Order.** The unit holds several rays at once (the RTL's `RAYS_IN_FLIGHT`, 8), so words
//! of different rays may interleave in the output; each ray's own words keep their order
//! (its candidates in the order of [`traverse`], then its end word). The unit holds far
//! fewer than 256 rays, so a ray enters only after the end word of the ray 256 before it (the
//! same tag) was written: each word belongs to the earliest ray of its tag whose end word has
//! not come ([`split_rays`]).
//!
//! **Refusals.** A refused ray (a value the grid cannot hold, a stack overflow, a reference
//! outside the memory, a traversal longer than the memory) ends with its refusal code. The
//! candidates it found before the refusal were already streamed and are counted in its end
//! word; the HPS discards them and answers the ray in software. So the end word always
//! counts the candidate words written with its tag.

use crate::raybox_format::{test, three, unthree, WorkItem, MANT_MAX};
use alloc::vec::Vec;

/// 64-bit words per node.
pub const NODE_WORDS: usize = 5;
/// 64-bit words per ray.
pub const RAY_WORDS: usize = 4;
/// The byte a valid node carries in bits [63:56] of its last word.
pub const NODE_MAGIC: u8 = 0xB9;
/// Width of a node index: the node memory holds up to 2^9 = 512 nodes (a tree of 513 leaves,
/// ten times the largest measured room's; docs/raybox-bvh.md).
pub const NODE_INDEX_BITS: u32 = 9;
/// Nodes the memory holds.
pub const MAX_NODES: usize = 1 << NODE_INDEX_BITS;
/// Entries of the per-ray stack (the measured trees are 7 to 9 deep).
pub const STACK_DEPTH: usize = 32;
/// Grid steps by which the HPS grows every box beyond outward rounding (module docs).
pub const GROWTH_STEPS: i32 = 2;
/// Grid steps by which the unit widens the ray's interval each way.
pub const INTERVAL_WIDENING_STEPS: i64 = 2;
/// Reference bit: the child exists.
pub const REF_VALID: u16 = 1 << 15;
/// Reference bit: the child is a leaf.
pub const REF_LEAF: u16 = 1 << 14;
/// Reference bits holding the index.
pub const REF_INDEX_MASK: u16 = (1 << 14) - 1;
/// Bit of a result word that marks a ray's end word.
pub const RESULT_END_BIT: u32 = 63;
/// Width of a ray's tag (module docs): 256 rays may be unanswered at once, far more than the
/// unit holds.
pub const TAG_BITS: u32 = 8;
/// Where a candidate word's tag starts (after the leaf's 14 bits at 32).
pub const CANDIDATE_TAG_SHIFT: u32 = 46;
/// Where an end word's tag starts (after the refusal code at 32).
pub const END_TAG_SHIFT: u32 = 40;

/// Why the unit refused a ray (the end word's refusal code).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Refusal {
    /// A field the grid cannot hold: NaN, an origin beyond ±256 m, a zero inverse direction.
    Unrepresentable = 1,
    /// The tree is deeper than [`STACK_DEPTH`].
    StackOverflow = 2,
    /// A reference to a node at or beyond `bvh.node_count`.
    BadReference = 3,
    /// More node visits than nodes: the memory does not hold a tree.
    Runaway = 4,
}

impl Refusal {
    pub const fn code(self) -> u8 {
        self as u8
    }

    pub const fn from_code(code: u8) -> Option<Refusal> {
        match code {
            1 => Some(Refusal::Unrepresentable),
            2 => Some(Refusal::StackOverflow),
            3 => Some(Refusal::BadReference),
            4 => Some(Refusal::Runaway),
            _ => None,
        }
    }
}

/// The order in which the unit visits a node's two children.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Order {
    /// The child the ray enters first (child 0 on a tie): closest-hit queries.
    NearFirst,
    /// Child 0 first: shadow rays, whose product of transmissions must be taken in the
    /// software traversal's order to be bit-identical.
    ChildOrder,
}

/// One node: two children's boxes (grid steps) and references.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct UnitNode {
    pub lower: [[i32; 3]; 2],
    pub upper: [[i32; 3]; 2],
    pub reference: [u16; 2],
}

impl UnitNode {
    /// The node's memory words (fields truncated to their widths).
    pub const fn pack(&self) -> [u64; NODE_WORDS] {
        [
            three(self.lower[0]),
            three(self.upper[0]),
            three(self.lower[1]),
            three(self.upper[1]),
            (self.reference[0] as u64)
                | ((self.reference[1] as u64) << 16)
                | ((NODE_MAGIC as u64) << 56),
        ]
    }

    /// Reads a node as the unit loads it; `None` when the magic byte is wrong.
    pub const fn unpack(words: &[u64; NODE_WORDS]) -> Option<UnitNode> {
        if (words[4] >> 56) as u8 != NODE_MAGIC {
            return None;
        }
        Some(UnitNode {
            lower: [unthree(words[0]), unthree(words[2])],
            upper: [unthree(words[1]), unthree(words[3])],
            reference: [words[4] as u16, (words[4] >> 16) as u16],
        })
    }
}

/// A ray as the HPS sends it.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct RayF32 {
    pub origin_m: [f32; 3],
    pub inverse_direction: [f32; 3],
    pub t_min_m: f32,
    pub t_max_m: f32,
}

impl RayF32 {
    pub fn pack(&self) -> [u64; RAY_WORDS] {
        let b = |x: f32| x.to_bits() as u64;
        [
            b(self.origin_m[0]) | (b(self.origin_m[1]) << 32),
            b(self.origin_m[2]) | (b(self.inverse_direction[0]) << 32),
            b(self.inverse_direction[1]) | (b(self.inverse_direction[2]) << 32),
            b(self.t_min_m) | (b(self.t_max_m) << 32),
        ]
    }
}

/// The ray in the unit's integer form, after the f32 front end.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct GridRay {
    pub origin: [i32; 3],
    pub mant: [i32; 3],
    pub shift: [u8; 3],
    pub t_min: i32,
    pub t_max: i32,
}

/// The f32 fields of a ray's words: origin x, y, z, inverse x, y, z, t_min, t_max.
pub const fn ray_fields(words: &[u64; RAY_WORDS]) -> [u32; 8] {
    [
        words[0] as u32,
        (words[0] >> 32) as u32,
        words[1] as u32,
        (words[1] >> 32) as u32,
        words[2] as u32,
        (words[2] >> 32) as u32,
        words[3] as u32,
        (words[3] >> 32) as u32,
    ]
}

const fn exponent(bits: u32) -> u32 {
    (bits >> 23) & 0xff
}

const fn significand(bits: u32) -> u32 {
    (bits & 0x7f_ffff) | 0x80_0000
}

const fn negative(bits: u32) -> bool {
    bits >> 31 == 1
}

/// An origin coordinate in grid steps, truncated toward zero; `None` for NaN, infinities and
/// magnitudes of 256 m or more (exponent 135 and up). Value × 2^12 = significand ×
/// 2^(exponent - 138), so the shift right is 138 - exponent (at least 4 in range).
pub const fn origin_steps(bits: u32) -> Option<i32> {
    let e = exponent(bits);
    if e >= 135 {
        return None;
    }
    if e == 0 {
        return Some(0); // zero or subnormal: under one step
    }
    let k = 138 - e;
    let magnitude = if k >= 32 { 0 } else { significand(bits) >> k } as i32;
    Some(if negative(bits) {
        -magnitude
    } else {
        magnitude
    })
}

/// An inverse direction as (mantissa, right shift) with `inv = mant × 2^-shift`, exactly:
/// the significand is the mantissa and the shift is 150 - exponent. Magnitudes of 2^24 and
/// more (infinity included) clamp to `MANT_MAX` with shift 0; `None` for NaN, zero,
/// subnormals and magnitudes under 2^-40 (the shift's six bits), which no direction of
/// length at least 1/2 has.
pub const fn inverse_mant_shift(bits: u32) -> Option<(i32, u8)> {
    let e = exponent(bits);
    if e == 255 && bits & 0x7f_ffff != 0 {
        return None;
    }
    let (m, s) = if e > 150 {
        (MANT_MAX, 0u8)
    } else if e < 87 {
        return None;
    } else {
        (significand(bits) as i32, (150 - e) as u8)
    };
    Some((if negative(bits) { -m } else { m }, s))
}

/// A distance in grid steps, truncated toward zero and saturated to 32 bits; infinities
/// saturate, `None` for NaN.
pub const fn distance_steps(bits: u32) -> Option<i64> {
    let e = exponent(bits);
    if e == 255 && bits & 0x7f_ffff != 0 {
        return None;
    }
    let magnitude: i64 = if e >= 145 {
        i32::MAX as i64 // 2^31 steps or more, infinity included
    } else if e >= 138 {
        (significand(bits) as i64) << (e - 138)
    } else if e == 0 || 138 - e >= 32 {
        0
    } else {
        (significand(bits) >> (138 - e)) as i64
    };
    Some(if negative(bits) {
        -magnitude
    } else {
        magnitude
    })
}

const fn saturate(v: i64) -> i32 {
    if v > i32::MAX as i64 {
        i32::MAX
    } else if v < i32::MIN as i64 {
        i32::MIN
    } else {
        v as i32
    }
}

/// The f32 front end: a ray's words to its grid form; `None` when a field is unrepresentable.
pub const fn grid_ray(words: &[u64; RAY_WORDS]) -> Option<GridRay> {
    let f = ray_fields(words);
    let mut ray = GridRay {
        origin: [0; 3],
        mant: [0; 3],
        shift: [0; 3],
        t_min: 0,
        t_max: 0,
    };
    let mut axis = 0;
    while axis < 3 {
        match origin_steps(f[axis]) {
            Some(o) => ray.origin[axis] = o,
            None => return None,
        }
        match inverse_mant_shift(f[3 + axis]) {
            Some((m, s)) => {
                ray.mant[axis] = m;
                ray.shift[axis] = s;
            }
            None => return None,
        }
        axis += 1;
    }
    match (distance_steps(f[6]), distance_steps(f[7])) {
        (Some(lo), Some(hi)) => {
            ray.t_min = saturate(lo - INTERVAL_WIDENING_STEPS);
            ray.t_max = saturate(hi + INTERVAL_WIDENING_STEPS);
        }
        _ => return None,
    }
    Some(ray)
}

/// The slab test of one child box: (hit, entry distance), `raybox_format`'s arithmetic with
/// the entry plane chosen by the direction's sign.
pub const fn child_test(ray: &GridRay, lower: &[i32; 3], upper: &[i32; 3]) -> (bool, i32) {
    let mut entry_plane = [0; 3];
    let mut exit_plane = [0; 3];
    let mut axis = 0;
    while axis < 3 {
        if ray.mant[axis] > 0 {
            entry_plane[axis] = lower[axis];
            exit_plane[axis] = upper[axis];
        } else {
            entry_plane[axis] = upper[axis];
            exit_plane[axis] = lower[axis];
        }
        axis += 1;
    }
    let r = test(&WorkItem {
        origin: ray.origin,
        entry_plane,
        exit_plane,
        mant: ray.mant,
        shift: ray.shift,
        t_min: ray.t_min,
        t_max: ray.t_max,
    });
    (r.hit, r.t_near)
}

/// A leaf the ray may reach, with its conservative entry distance.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Candidate {
    pub leaf: u16,
    pub t_near: i32,
}

/// Packs a candidate word of the ray tagged `tag`.
pub const fn pack_candidate(c: Candidate, tag: u8) -> u64 {
    (c.t_near as u32 as u64)
        | (((c.leaf & REF_INDEX_MASK) as u64) << 32)
        | ((tag as u64) << CANDIDATE_TAG_SHIFT)
}

/// Packs the end word of the ray tagged `tag`.
pub const fn pack_end(candidates: u32, refusal: Option<Refusal>, tag: u8) -> u64 {
    let code = match refusal {
        Some(r) => r.code(),
        None => 0,
    };
    (candidates as u64)
        | ((code as u64) << 32)
        | ((tag as u64) << END_TAG_SHIFT)
        | (1u64 << RESULT_END_BIT)
}

/// What a result word says.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum ResultWord {
    Candidate {
        candidate: Candidate,
        tag: u8,
    },
    /// The ray's end: candidates written, refusal code (0: none).
    End {
        candidates: u32,
        refusal_code: u8,
        tag: u8,
    },
}

impl ResultWord {
    /// The tag of the ray the word belongs to.
    pub const fn tag(&self) -> u8 {
        match self {
            ResultWord::Candidate { tag, .. } | ResultWord::End { tag, .. } => *tag,
        }
    }
}

pub const fn unpack_result(word: u64) -> ResultWord {
    if word >> RESULT_END_BIT == 1 {
        ResultWord::End {
            candidates: word as u32,
            refusal_code: (word >> 32) as u8,
            tag: (word >> END_TAG_SHIFT) as u8,
        }
    } else {
        ResultWord::Candidate {
            candidate: Candidate {
                leaf: ((word >> 32) as u16) & REF_INDEX_MASK,
                t_near: word as u32 as i32,
            },
            tag: (word >> CANDIDATE_TAG_SHIFT) as u8,
        }
    }
}

/// The tag of any result word.
pub const fn result_tag(word: u64) -> u8 {
    unpack_result(word).tag()
}

/// One ray's traversal: the candidates in the order the unit writes them (up to the refusal
/// point when refused), and the refusal.
pub type Traversal = (Vec<Candidate>, Option<Refusal>);

/// The golden model of one ray's traversal: the candidates in the order the unit writes
/// them and, for a refused ray, why (its candidates found before the refusal are written
/// too; the HPS drops them and answers the whole ray in software).
///
/// Depth first from node 0: at a node, both valid children are tested; of those hit, the
/// first in `order` is visited and the other pushed with its entry distance; a leaf visited
/// or popped is written as a candidate. Each node visit counts; more visits than
/// `nodes.len()` (a cycle in the references) refuses the ray.
pub fn traverse(nodes: &[UnitNode], words: &[u64; RAY_WORDS], order: Order) -> Traversal {
    traverse_counting(nodes, words, order, &mut 0)
}

/// [`traverse`], adding the node visits (pair tests) it made to `visits`: the unit's work,
/// for sizing it.
pub fn traverse_counting(
    nodes: &[UnitNode],
    words: &[u64; RAY_WORDS],
    order: Order,
    visits: &mut usize,
) -> Traversal {
    let mut out = Vec::new();
    let refusal = walk(nodes, words, order, visits, &mut out).err();
    (out, refusal)
}

/// [`traverse_counting`]'s walk, writing candidates to `out` as found.
fn walk(
    nodes: &[UnitNode],
    words: &[u64; RAY_WORDS],
    order: Order,
    visits: &mut usize,
    out: &mut Vec<Candidate>,
) -> Result<(), Refusal> {
    let ray = grid_ray(words).ok_or(Refusal::Unrepresentable)?;
    let mut stack: Vec<(u16, i32)> = Vec::with_capacity(STACK_DEPTH);
    let mut current = 0usize;
    let start = *visits;
    loop {
        let node = nodes.get(current).ok_or(Refusal::BadReference)?;
        *visits += 1;
        if *visits - start > nodes.len() {
            return Err(Refusal::Runaway);
        }
        let mut hits = [(0u16, 0i32); 2];
        let mut n = 0;
        let tested = [0, 1].map(|c| {
            let r = node.reference[c];
            let (hit, t) = child_test(&ray, &node.lower[c], &node.upper[c]);
            (r & REF_VALID != 0 && hit, r, t)
        });
        let first = match order {
            Order::NearFirst if tested[0].0 && tested[1].0 && tested[1].2 < tested[0].2 => 1,
            _ => 0,
        };
        for c in [first, 1 - first] {
            if tested[c].0 {
                hits[n] = (tested[c].1, tested[c].2);
                n += 1;
            }
        }
        if n == 2 {
            if stack.len() == STACK_DEPTH {
                return Err(Refusal::StackOverflow);
            }
            stack.push(hits[1]);
        }
        let mut next = if n > 0 { Some(hits[0]) } else { None };
        loop {
            match next {
                Some((r, t)) if r & REF_LEAF != 0 => {
                    out.push(Candidate {
                        leaf: r & REF_INDEX_MASK,
                        t_near: t,
                    });
                    next = None;
                }
                Some((r, _)) => {
                    current = (r & REF_INDEX_MASK) as usize;
                    break;
                }
                None => match stack.pop() {
                    Some(e) => next = Some(e),
                    None => return Ok(()),
                },
            }
        }
    }
}

/// The result words the unit writes for one ray tagged `tag`: its candidates (up to the
/// refusal point when refused), then its end word counting them.
pub fn result_words(
    nodes: &[UnitNode],
    words: &[u64; RAY_WORDS],
    order: Order,
    tag: u8,
) -> Vec<u64> {
    let (candidates, refusal) = traverse(nodes, words, order);
    let mut out: Vec<u64> = candidates.iter().map(|&c| pack_candidate(c, tag)).collect();
    out.push(pack_end(candidates.len() as u32, refusal, tag));
    out
}

/// Splits a result stream into each ray's words, in arrival order, given the rays' tags in
/// the order they were sent. Rays may share a tag (the count restarted, or came round after
/// 256), but a ray's tag is reused only after its end word (the unit holds far fewer than
/// 256 rays), so each word belongs to the earliest ray of its tag whose end word has not
/// come. `None` when a word belongs to no ray.
pub fn split_rays(words: &[u64], tags: &[u8]) -> Option<Vec<Vec<u64>>> {
    let mut out: Vec<Vec<u64>> = alloc::vec![Vec::new(); tags.len()];
    // Per tag, the rays carrying it, and how many of them have ended.
    let mut rays: Vec<Vec<usize>> = alloc::vec![Vec::new(); 1 << TAG_BITS];
    for (k, &t) in tags.iter().enumerate() {
        rays[t as usize].push(k);
    }
    let mut ended = alloc::vec![0usize; 1 << TAG_BITS];
    for &w in words {
        let tag = result_tag(w) as usize;
        let ray = *rays[tag].get(ended[tag])?;
        out[ray].push(w);
        if w >> RESULT_END_BIT == 1 {
            ended[tag] += 1;
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raybox_format::{COORD_MAX, COORD_MIN};

    fn leaf(i: u16) -> u16 {
        REF_VALID | REF_LEAF | i
    }

    fn node(i: u16) -> u16 {
        REF_VALID | i
    }

    /// A ray along +x from the origin, t in [0, 100 m].
    fn ray_x() -> [u64; RAY_WORDS] {
        RayF32 {
            origin_m: [0.0, 0.0, 0.0],
            inverse_direction: [1.0, f32::INFINITY, f32::INFINITY],
            t_min_m: 0.0,
            t_max_m: 100.0,
        }
        .pack()
    }

    fn cube(lo_m: f32, hi_m: f32) -> ([i32; 3], [i32; 3]) {
        let s = |m: f32| (m * 4096.0) as i32;
        ([s(lo_m), s(-1.0), s(-1.0)], [s(hi_m), s(1.0), s(1.0)])
    }

    #[test]
    fn pack_round_trip_and_magic() {
        let n = UnitNode {
            lower: [[COORD_MIN, -1, 5], [0, 1, 2]],
            upper: [[COORD_MAX, 7, -9], [3, 4, 5]],
            reference: [leaf(17), node(3)],
        };
        let mut w = n.pack();
        assert_eq!(UnitNode::unpack(&w), Some(n));
        w[4] ^= 1 << 57;
        assert_eq!(UnitNode::unpack(&w), None);
        let c = Candidate {
            leaf: 0x3abc,
            t_near: -7,
        };
        let w = pack_candidate(c, 0xa5);
        assert_eq!(
            unpack_result(w),
            ResultWord::Candidate {
                candidate: c,
                tag: 0xa5
            }
        );
        assert_eq!(w >> 54, 0, "bits [63:54] of a candidate are 0");
        let e = pack_end(12, Some(Refusal::Runaway), 0xff);
        assert_eq!(
            unpack_result(e),
            ResultWord::End {
                candidates: 12,
                refusal_code: 4,
                tag: 0xff
            }
        );
        assert_eq!(e, 12 | 4 << 32 | 0xff << 40 | 1 << 63);
        assert_eq!(result_tag(e), 0xff);
    }

    #[test]
    fn front_end_conversions_are_exact_where_they_should_be() {
        // 1.5 m = 6144 steps; -0.3 m truncates toward zero.
        assert_eq!(origin_steps(1.5f32.to_bits()), Some(6144));
        assert_eq!(
            origin_steps((-0.3f32).to_bits()),
            Some(-((0.3f32 as f64 * 4096.0) as i32))
        );
        assert_eq!(
            origin_steps(255.99f32.to_bits()),
            Some((255.99f32 * 4096.0) as i32)
        );
        assert_eq!(origin_steps(256.0f32.to_bits()), None);
        assert_eq!(origin_steps(f32::NAN.to_bits()), None);
        assert_eq!(origin_steps(0.0f32.to_bits()), Some(0));
        // The inverse's significand is the mantissa, exactly.
        for inv in [1.0f32, -3.7, 1.0e-7, 16_777_215.0, 2.5e-12] {
            let (m, s) = inverse_mant_shift(inv.to_bits()).unwrap();
            assert_eq!(m as f64 / 2f64.powi(s as i32), inv as f64, "{inv}");
        }
        assert_eq!(
            inverse_mant_shift(f32::NEG_INFINITY.to_bits()),
            Some((-MANT_MAX, 0))
        );
        assert_eq!(inverse_mant_shift(0.0f32.to_bits()), None);
        assert_eq!(inverse_mant_shift(f32::NAN.to_bits()), None);
        assert_eq!(
            distance_steps(f32::INFINITY.to_bits()),
            Some(i32::MAX as i64)
        );
        assert_eq!(distance_steps(2.0f32.to_bits()), Some(8192));
        assert_eq!(distance_steps(f32::NAN.to_bits()), None);
    }

    #[test]
    fn near_first_and_child_order() {
        let far = cube(10.0, 11.0);
        let near = cube(2.0, 3.0);
        // Node 0 holds the root (node 1) as child 0; node 1's children: far leaf 5, near leaf 6.
        let nodes = [
            UnitNode {
                lower: [cube(0.0, 20.0).0, [0; 3]],
                upper: [cube(0.0, 20.0).1, [0; 3]],
                reference: [node(1), 0],
            },
            UnitNode {
                lower: [far.0, near.0],
                upper: [far.1, near.1],
                reference: [leaf(5), leaf(6)],
            },
        ];
        let (near_first, refusal) = traverse(&nodes, &ray_x(), Order::NearFirst);
        assert_eq!(refusal, None);
        assert_eq!(
            near_first.iter().map(|c| c.leaf).collect::<Vec<_>>(),
            [6, 5]
        );
        assert!(near_first[0].t_near <= 2 * 4096 && near_first[0].t_near > 2 * 4096 - 8);
        let (child_order, _) = traverse(&nodes, &ray_x(), Order::ChildOrder);
        assert_eq!(
            child_order.iter().map(|c| c.leaf).collect::<Vec<_>>(),
            [5, 6]
        );
        // A ray 2 m off in y misses both leaves (and the root box).
        let mut off = ray_x();
        off[0] = 0f32.to_bits() as u64 | ((2.0f32.to_bits() as u64) << 32);
        assert_eq!(traverse(&nodes, &off, Order::NearFirst), (Vec::new(), None));
        let words = result_words(&nodes, &ray_x(), Order::NearFirst, 7);
        assert_eq!(words.len(), 3);
        assert_eq!(
            unpack_result(words[2]),
            ResultWord::End {
                candidates: 2,
                refusal_code: 0,
                tag: 7
            }
        );
        assert!(words.iter().all(|&w| result_tag(w) == 7));
    }

    #[test]
    fn refusals() {
        let everywhere = ([COORD_MIN; 3], [COORD_MAX; 3]);
        let self_loop = [UnitNode {
            lower: [everywhere.0; 2],
            upper: [everywhere.1; 2],
            reference: [node(0), 0],
        }];
        assert_eq!(
            traverse(&self_loop, &ray_x(), Order::NearFirst),
            (Vec::new(), Some(Refusal::Runaway))
        );
        let dangling = [UnitNode {
            reference: [node(9), 0],
            ..self_loop[0]
        }];
        assert_eq!(
            traverse(&dangling, &ray_x(), Order::NearFirst),
            (Vec::new(), Some(Refusal::BadReference))
        );
        let mut nan = ray_x();
        nan[3] = f32::NAN.to_bits() as u64;
        assert_eq!(
            traverse(&self_loop, &nan, Order::NearFirst),
            (Vec::new(), Some(Refusal::Unrepresentable))
        );
        // A chain deeper than the stack: every node pushes leaf 0 and descends.
        let chain: Vec<UnitNode> = (0..STACK_DEPTH as u16 + 2)
            .map(|i| UnitNode {
                lower: [everywhere.0; 2],
                upper: [everywhere.1; 2],
                reference: [node(i + 1), leaf(0)],
            })
            .collect();
        // Nothing is popped before the overflow, so no candidate is written.
        assert_eq!(
            traverse(&chain, &ray_x(), Order::ChildOrder),
            (Vec::new(), Some(Refusal::StackOverflow))
        );
        assert_eq!(
            unpack_result(result_words(&chain, &ray_x(), Order::ChildOrder, 3)[0]),
            ResultWord::End {
                candidates: 0,
                refusal_code: 2,
                tag: 3
            }
        );
        // A ring whose nodes each write a leaf: the candidates before the runaway are
        // written, counted by the refused end word.
        let ring: Vec<UnitNode> = (0..3u16)
            .map(|i| UnitNode {
                lower: [everywhere.0; 2],
                upper: [everywhere.1; 2],
                reference: [leaf(10 + i), node((i + 1) % 3)],
            })
            .collect();
        let (c, r) = traverse(&ring, &ray_x(), Order::ChildOrder);
        assert_eq!(r, Some(Refusal::Runaway));
        assert_eq!(c.iter().map(|c| c.leaf).collect::<Vec<_>>(), [10, 11, 12]);
        let words = result_words(&ring, &ray_x(), Order::ChildOrder, 200);
        assert_eq!(words.len(), 4);
        assert_eq!(
            unpack_result(words[3]),
            ResultWord::End {
                candidates: 3,
                refusal_code: 4,
                tag: 200
            }
        );
        // Rays 0 and 256 share tag 0; ray 1 interleaves with ray 0.
        let a = result_words(&ring, &ray_x(), Order::ChildOrder, 0);
        let b = result_words(&ring, &ray_x(), Order::NearFirst, 1);
        let mut stream = alloc::vec![a[0], b[0], a[1], b[1], b[2], a[2], a[3], b[3]];
        stream.extend(&a);
        let tags: Vec<u8> = (0..257).map(|k| k as u8).collect();
        let split = split_rays(&stream, &tags).unwrap();
        assert_eq!((&split[0], &split[1], &split[256]), (&a, &b, &a));
        assert!(split[2..256].iter().all(Vec::is_empty));
        assert_eq!(split_rays(&stream, &tags[..256]), None);
    }
}
