//! `skylux bench raybox`, the traversal part (issue 22 item 4): a ray unit that holds the
//! room's tree in block RAM and traverses it itself, **sized and projected from measured
//! traversal counts**, before the unit was built (the built unit: `bench_raybox_unit`). The
//! counts come from an illuminance run on
//! each room (`engine::traversal_stats`): the engine's traversals, and a sample of them again
//! on a tree of one primitive a leaf (the unit's), where the unit would traverse each query
//! over its whole interval and send every crossed leaf as a candidate, and the HPS would test
//! exactly the candidates not past its best hit. Every cost constant is stated with its
//! source or marked as an estimate.

use anyhow::Context;
use skylux_hps::engine::traversal_stats::{self, TraversalCounts, TraversalStats};
use skylux_hps::engine::Settings;
use skylux_hps::scene;
use skylux_regmap::raybox_format::COORD_BITS;
use std::path::{Path, PathBuf};

/// Clock of the fabric (`sys.clock_hz`) and of the Cortex-A9 (hardware-facts.md §2).
pub(crate) const FABRIC_HZ: f64 = skylux_regmap::SYS_CLOCK_HZ as f64;
pub(crate) const A9_HZ: f64 = 925e6;
pub(crate) const A9_CORES: f64 = 2.0;
/// Cortex-A9 cycles per f64 slab test (`bench_raybox::A9_CYCLES_PER_TEST`, an estimate from
/// the operation mix).
pub(crate) const A9_CYCLES_PER_BOX: f64 = 60.0;
/// **Estimate**: the software traversal's own work per interior node besides its two box
/// tests (load the pair of boxes, order the children, push or pop the stack): about 20
/// instructions, single-issue bound by their loads.
const A9_CYCLES_PER_NODE: f64 = 20.0;
/// **Estimate**: a leaf's bookkeeping (bounds of the primitive range, the loop).
const A9_CYCLES_PER_LEAF: f64 = 10.0;
/// **Estimate**: one exact primitive test in f64 (a polygon: plane distance, one VDIV.F64 of
/// 20 held cycles, and an inside test over its edges; about 40 VFP operations, which the
/// A9's single VFP issue slot takes at one to two cycles each: `timing::a9`).
pub(crate) const A9_CYCLES_PER_PRIMITIVE: f64 = 120.0;
/// How the HPS hands a query to the unit.
#[derive(Copy, Clone, Debug)]
enum RayInterface {
    /// The HPS quantises the ray as `engine::accel::quantise` does (origin to the grid, three
    /// `encode_inverse`: a log2, a power of two and roundings each; the growth bound) and
    /// writes 4 beats. **Estimate**: 200 cycles.
    HpsQuantises,
    /// The HPS writes origin, direction and interval as f32 (VCVT.F32.F64, 1 held cycle each,
    /// `timing::a9`; 3 beats) and the fabric quantises them, its growth covering f32's
    /// rounding. **Estimate**: 40 cycles.
    FabricQuantises,
}

impl RayInterface {
    fn cycles_sent(self) -> f64 {
        match self {
            Self::HpsQuantises => 200.0,
            Self::FabricQuantises => 40.0,
        }
    }
    fn beats(self) -> f64 {
        match self {
            Self::HpsQuantises => 4.0,
            Self::FabricQuantises => 3.0,
        }
    }
    fn name(self) -> &'static str {
        match self {
            Self::HpsQuantises => "hps_quantises",
            Self::FabricQuantises => "fabric_quantises",
        }
    }
}

/// **Estimate**: the HPS's part of reading back one candidate (decode, compare its entry with
/// the best hit).
pub(crate) const A9_CYCLES_PER_CANDIDATE_READ: f64 = 10.0;
/// Cached streaming over the DMA buffer, bytes per second (`timing::a9::DRAM_STREAM_BYTES_PER_S`,
/// the udmabuf mapping with explicit maintenance, bitstream/README.md).
pub(crate) const A9_STREAM_BYTES_PER_S: f64 = skylux_hps::timing::a9::DRAM_STREAM_BYTES_PER_S;
/// Port beats (64-bit, one a clock for reads and writes together on f2sdram, hardware-facts.md
/// §3.2) per query: the ray ([`RayInterface::beats`]) and an end marker; one beat per
/// candidate (primitive index, conservative entry distance).
const BEATS_PER_END: f64 = 1.0;
/// A node of the unit's tree in block RAM: its two children's boxes on the unit's grid (six
/// coordinates of `COORD_BITS` each) and two child references (a leaf flag and a 19-bit
/// index).
const NODE_BITS: u64 = 2 * 6 * COORD_BITS as u64 + 2 * 20;
/// M10K blocks as 256 words of 40 bits (Cyclone V Device Handbook, "Embedded Memory Blocks":
/// the M10K's 256 x 40 configuration), true dual port: one copy serves two lanes.
const M10K_WORDS: u64 = 256;
const M10K_WIDTH_BITS: u64 = 40;
/// Free for the tree: the device's 397 M10K less the core's 171 (BENCHMARKS.md, map v0.4).
const M10K_FREE: u64 = 397 - 171;
/// A lane tests a node's two children in one clock: two slab datapaths of the measured lane
/// (1,496 ALMs, 6 DSP blocks each, BENCHMARKS.md "Ray-box unit") and, **estimated**, 600
/// ALMs of traversal control (node fetch, per-ray stack addressing, candidate FIFO).
const LANE_ALMS: f64 = 2.0 * 1496.0 + 600.0;
const LANE_DSP: u64 = 12;
/// ALMs the core may give lanes within its 60 % budget of 32,070: 19,242 less the core
/// without the ray-box unit (8,717 − 3,253 = 5,464) and the unit's front end (1,757).
const LANE_ALM_BUDGET: f64 = 0.6 * 32_070.0 - 5_464.0 - 1_757.0;
/// DSP blocks free for lanes: 87 less the core's 7 besides the ray-box lane.
const LANE_DSP_BUDGET: u64 = 87 - 7;

/// One room of the comparison: where it is, its scene files, its points.
pub(crate) struct BenchRoom {
    pub(crate) name: &'static str,
    dir: PathBuf,
    scene: &'static [&'static str],
    points: &'static str,
}

pub(crate) fn bench_rooms() -> Vec<BenchRoom> {
    let shared = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared");
    vec![
        BenchRoom {
            name: "reference room (scenes/test-module)",
            dir: shared.join("scenes/test-module"),
            scene: &["scene.rad"],
            points: "sensors.pts",
        },
        BenchRoom {
            name: "LBNL matrix tutorial room (radiance-corpus/sariths-matrix-tutorial/room)",
            dir: shared.join("data/radiance-corpus/sariths-matrix-tutorial/room"),
            scene: &["materials.rad", "room.rad"],
            points: "points.txt",
        },
    ]
}

/// A bench room's scene (with [`SKY`]) and its sensors.
pub(crate) fn load_room(room: &BenchRoom) -> anyhow::Result<(scene::Scene, Vec<scene::Sensor>)> {
    let options = scene::LoadOptions {
        working_directory: Some(room.dir.clone()),
        ..Default::default()
    };
    let mut s = scene::Scene::new();
    for f in room.scene {
        s.add_file_with(room.dir.join(f), &options)
            .with_context(|| format!("{}: {f}", room.name))?;
    }
    s.add_bytes("sky.rad", SKY.as_bytes())?;
    let sensors = scene::load_sensors(room.dir.join(room.points))?;
    Ok((s, sensors))
}

/// The sky of the counts: a sun 50° up in the south-east and uniform sky and ground glows.
/// The traversals' work depends on the geometry and the paths, not on the sky's details.
const SKY: &str = "void light solar 0 0 3 5e6 5e6 5e6\n\
                   solar source sun 0 0 4 0.45 -0.45 0.766 0.533\n\
                   void glow sky_glow 0 0 4 3000 3000 3000 0\n\
                   sky_glow source sky 0 0 4 0 0 1 180\n\
                   void glow ground_glow 0 0 4 600 600 600 0\n\
                   ground_glow source ground 0 0 4 0 0 -1 180\n";

/// Cycles and beats per query of each design, weighted over the run's mix of queries.
#[derive(Debug)]
struct Projection {
    interface: RayInterface,
    closest_share: f64,
    a9_cycles_per_query: f64,
    unit_hps_cycles_per_query: f64,
    unit_pair_tests_per_query: f64,
    unit_port_beats_per_query: f64,
    interior_nodes: u64,
    node_memory_m10k_per_copy: u64,
    stack_bits_per_ray: u64,
    lanes: u64,
    lanes_by_alm: u64,
    lanes_by_dsp: u64,
    lanes_by_m10k: u64,
    fabric_rays_per_s: f64,
    port_rays_per_s: f64,
    hps_rays_per_s: f64,
    rays_per_s_projected: f64,
    a9_rays_per_s: f64,
    speedup_over_a9: f64,
    bound: &'static str,
}

impl Projection {
    fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "ray_interface": self.interface.name(),
            "closest_share": self.closest_share,
            "a9_cycles_per_query": self.a9_cycles_per_query,
            "unit_hps_cycles_per_query": self.unit_hps_cycles_per_query,
            "unit_pair_tests_per_query": self.unit_pair_tests_per_query,
            "unit_port_beats_per_query": self.unit_port_beats_per_query,
            "interior_nodes": self.interior_nodes,
            "node_memory_m10k_per_copy": self.node_memory_m10k_per_copy,
            "stack_bits_per_ray": self.stack_bits_per_ray,
            "lanes": self.lanes,
            "lanes_by_alm": self.lanes_by_alm,
            "lanes_by_dsp": self.lanes_by_dsp,
            "lanes_by_m10k": self.lanes_by_m10k,
            // Each lane tests a node's two children a clock.
            "traversal_tests_per_cycle": 2.0 * self.lanes as f64,
            "fabric_rays_per_s": self.fabric_rays_per_s,
            "port_rays_per_s": self.port_rays_per_s,
            "hps_rays_per_s": self.hps_rays_per_s,
            "rays_per_s_projected": self.rays_per_s_projected,
            "a9_rays_per_s": self.a9_rays_per_s,
            "speedup_over_a9": self.speedup_over_a9,
            "bound": self.bound,
        })
    }
}

fn per_query(c: &TraversalCounts) -> (f64, f64, f64, f64) {
    let q = c.queries.max(1) as f64;
    (
        c.root_tests as f64 / q,
        c.pair_tests as f64 / q,
        c.leaves as f64 / q,
        c.primitives as f64 / q,
    )
}

/// A9 software cycles per query of `c` (the engine's tree).
pub(crate) fn a9_cycles(c: &TraversalCounts) -> f64 {
    let (root, pairs, leaves, prims) = per_query(c);
    root * A9_CYCLES_PER_BOX
        + pairs * (2.0 * A9_CYCLES_PER_BOX + A9_CYCLES_PER_NODE)
        + leaves * A9_CYCLES_PER_LEAF
        + prims * A9_CYCLES_PER_PRIMITIVE
}

/// The HPS's cycles per query with the unit: send it, read `sent` candidates (8 bytes each at
/// the cached streaming rate, plus their decoding), test `tested` of them exactly.
fn unit_hps_cycles(interface: RayInterface, sent: f64, tested: f64) -> f64 {
    let read_cycles_per_beat = 8.0 / A9_STREAM_BYTES_PER_S * A9_HZ;
    interface.cycles_sent()
        + (interface.beats() + BEATS_PER_END) * read_cycles_per_beat
        + sent * (A9_CYCLES_PER_CANDIDATE_READ + read_cycles_per_beat)
        + tested * A9_CYCLES_PER_PRIMITIVE
}

fn project(s: &TraversalStats, interface: RayInterface) -> Projection {
    let total = (s.closest.queries + s.crossed.queries).max(1) as f64;
    let wc = s.closest.queries as f64 / total;
    let wx = 1.0 - wc;
    // Software: the whole run's averages on the engine's tree.
    let a9 = wc * a9_cycles(&s.closest) + wx * a9_cycles(&s.crossed);
    // The unit: the samples on its tree. Closest: it traverses and sends every crossed leaf,
    // the HPS tests those not past its best hit. Shadow rays: every crossed leaf, all tested
    // (an upper bound: the HPS may stop at the first opaque one).
    let (_, whole_pairs, whole_leaves, _) = per_query(&s.closest_unit_whole);
    let (_, _, pruned_leaves, _) = per_query(&s.closest_unit_pruned);
    let (_, crossed_pairs, crossed_leaves, _) = per_query(&s.crossed_unit);
    let hps = wc * unit_hps_cycles(interface, whole_leaves, pruned_leaves)
        + wx * unit_hps_cycles(interface, crossed_leaves, crossed_leaves);
    let pairs = wc * (1.0 + whole_pairs) + wx * (1.0 + crossed_pairs);
    let beats = interface.beats() + BEATS_PER_END + wc * whole_leaves + wx * crossed_leaves;
    let interior = (s.unit_tree.nodes as u64).saturating_sub(s.unit_tree.leaves as u64);
    let m10k_per_copy = NODE_BITS.div_ceil(M10K_WIDTH_BITS) * interior.max(1).div_ceil(M10K_WORDS);
    // Per ray in flight: the depth's worth of (node index, entry distance) entries.
    let stack_bits = s.unit_tree.max_depth as u64 * (20 + 32);
    let lanes_by_alm = (LANE_ALM_BUDGET / LANE_ALMS).floor().max(0.0) as u64;
    let lanes_by_dsp = LANE_DSP_BUDGET / LANE_DSP;
    // Each copy of the node memory serves two lanes.
    let lanes_by_m10k = 2 * (M10K_FREE / m10k_per_copy.max(1));
    let lanes = lanes_by_alm.min(lanes_by_dsp).min(lanes_by_m10k);
    let fabric = lanes as f64 * FABRIC_HZ / pairs.max(1.0);
    let port = FABRIC_HZ / beats;
    let hps_rate = A9_CORES * A9_HZ / hps;
    let projected = fabric.min(port).min(hps_rate);
    let bound = if projected == hps_rate {
        "HPS (sending queries, reading and testing candidates)"
    } else if projected == port {
        "the 64-bit f2sdram port"
    } else {
        "the lanes"
    };
    let a9_rate = A9_CORES * A9_HZ / a9;
    Projection {
        interface,
        closest_share: wc,
        a9_cycles_per_query: a9,
        unit_hps_cycles_per_query: hps,
        unit_pair_tests_per_query: pairs,
        unit_port_beats_per_query: beats,
        interior_nodes: interior,
        node_memory_m10k_per_copy: m10k_per_copy,
        stack_bits_per_ray: stack_bits,
        lanes,
        lanes_by_alm,
        lanes_by_dsp,
        lanes_by_m10k,
        fabric_rays_per_s: fabric,
        port_rays_per_s: port,
        hps_rays_per_s: hps_rate,
        rays_per_s_projected: projected,
        a9_rays_per_s: a9_rate,
        speedup_over_a9: projected / a9_rate,
        bound,
    }
}

/// The counts and the projection for every bench room, `paths` paths a sensor.
pub fn run(paths: u32) -> anyhow::Result<serde_json::Value> {
    let mut out = Vec::new();
    for room in bench_rooms() {
        let (s, sensors) = load_room(&room)?;
        let settings = Settings {
            samples_per_sensor: paths,
            ..Settings::default()
        };
        let stats = traversal_stats::measure(&s, &sensors, &settings)
            .with_context(|| room.name.to_string())?;
        let projections: Vec<_> = [RayInterface::HpsQuantises, RayInterface::FabricQuantises]
            .into_iter()
            .map(|i| project(&stats, i).to_json())
            .collect();
        out.push(serde_json::json!({
            "room": room.name,
            "sensors": sensors.len(),
            "paths_per_sensor": paths,
            "counts": stats,
            "projections": projections,
        }));
    }
    Ok(serde_json::json!({
        "status": "modelled: the sizing from measured traversal counts that came before the \
                   unit was built (issue 22 item 4; the built unit: bvh_unit)",
        "rooms": out,
        "constants": {
            "a9_cycles_per_box": A9_CYCLES_PER_BOX,
            "a9_cycles_per_node_estimate": A9_CYCLES_PER_NODE,
            "a9_cycles_per_leaf_estimate": A9_CYCLES_PER_LEAF,
            "a9_cycles_per_primitive_estimate": A9_CYCLES_PER_PRIMITIVE,
            "a9_cycles_per_candidate_read_estimate": A9_CYCLES_PER_CANDIDATE_READ,
            "node_bits": NODE_BITS,
            "lane_alms_estimate": LANE_ALMS,
            "lane_dsp": LANE_DSP,
            "m10k_free": M10K_FREE,
        },
    }))
}
