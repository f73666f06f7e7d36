//! `skylux bench raybox`, the BVH ray unit as built (issue 22 item 4): each bench room's
//! illuminance run goes through the unit's golden model attached to the engine
//! (`World::attach_bvh_unit`; bit-identical to software, `tests/tests/bvh_unit_rooms.rs`),
//! which counts what the unit and the HPS do per ray; a sample of the run's rays is then
//! timed on the cycle-accurate RTL block (`skylux_rtl::bvh::BvhInterleaved`, rays
//! interleaved) loaded with the room's tree. The projection takes the least of three rates: the fabric's (measured cycles
//! a ray), the port's (beats a ray) and the HPS's (its share of a ray, every constant sourced
//! or marked an estimate), against the A9 software estimate of the same run.

use crate::bench_raybox_traversal::{
    a9_cycles, bench_rooms, load_room, A9_CORES, A9_CYCLES_PER_BOX, A9_CYCLES_PER_CANDIDATE_READ,
    A9_CYCLES_PER_PRIMITIVE, A9_HZ, A9_STREAM_BYTES_PER_S, FABRIC_HZ,
};
use anyhow::Context;
use skylux_hps::engine::bvh_unit::unit_nodes;
use skylux_hps::engine::{illuminance, openings, traversal_stats, Settings, World};
use skylux_hps::fpga::bvh_unit::{
    BvhUnitBackend, BvhUnitError, GoldenBvhUnit, NodeWords, RayWords,
};
use skylux_regmap::bvh_format::{
    result_words, split_rays, traverse_counting, Order, UnitNode, RAY_WORDS,
};
use skylux_rtl::bvh::bench::BvhBench;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, RwLock};

/// Every how many rays one is kept for timing on the RTL block.
const SAMPLE_EVERY: u64 = 64;
/// Most rays timed on the RTL block per room.
const SAMPLE_MAX: usize = 4000;
/// **Estimate**: the HPS's cycles to hand the unit one ray as f32: six VCVT.F32.F64 and a
/// division-free inverse (the engine's query already holds 1/d), four 64-bit stores to the
/// cached buffer (`timing::a9`: VCVT 1 held cycle; stores 1 a cycle).
const A9_CYCLES_PER_RAY_SENT: f64 = 40.0;

/// The golden unit, keeping a sample of the rays it answers.
struct Recording {
    /// Written once by `load`, then read by every thread.
    golden: RwLock<GoldenBvhUnit>,
    seen: AtomicU64,
    kept: Mutex<Vec<(Order, RayWords)>>,
}

struct RecordingBackend(Arc<Recording>);

impl BvhUnitBackend for RecordingBackend {
    fn load(&mut self, nodes: &[NodeWords]) -> Result<(), BvhUnitError> {
        self.0
            .golden
            .write()
            .map_err(|_| BvhUnitError::Fault("recording lock poisoned".into()))?
            .load(nodes)
    }

    fn traverse(
        &self,
        order: Order,
        ray: &RayWords,
        results: &mut Vec<u64>,
    ) -> Result<(), BvhUnitError> {
        if self
            .0
            .seen
            .fetch_add(1, Ordering::Relaxed)
            .is_multiple_of(SAMPLE_EVERY)
        {
            if let Ok(mut kept) = self.0.kept.lock() {
                if kept.len() < SAMPLE_MAX {
                    kept.push((order, *ray));
                }
            }
        }
        self.0
            .golden
            .read()
            .map_err(|_| BvhUnitError::Fault("recording lock poisoned".into()))?
            .traverse(order, ray, results)
    }
}

/// What the unit did over one room's run, per ray it answered.
#[derive(Debug)]
struct UnitCounts {
    rays: u64,
    refused: u64,
    node_visits_per_ray: f64,
    candidates_per_ray: f64,
    primitives_per_ray: f64,
    /// f64 box tests of candidates near the interval's end (`engine::bvh_unit::FAR_END_M`).
    far_end_box_tests_per_ray: f64,
    closest_share: f64,
    primitives_per_closest_ray: f64,
    primitives_per_shadow_ray: f64,
}

/// The cycle-accurate block's timing on a sample of rays.
#[derive(Debug)]
pub struct RtlTiming {
    pub rays: usize,
    pub cycles: u64,
    pub node_visits: u64,
    pub result_words: u64,
    /// Whether every result word equalled the golden model's.
    pub matches_golden: bool,
}

impl UnitCounts {
    fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "rays": self.rays,
            "refused": self.refused,
            "node_visits_per_ray": self.node_visits_per_ray,
            "candidates_per_ray": self.candidates_per_ray,
            "primitives_per_ray": self.primitives_per_ray,
            "far_end_box_tests_per_ray": self.far_end_box_tests_per_ray,
            "closest_share": self.closest_share,
            "primitives_per_closest_ray": self.primitives_per_closest_ray,
            "primitives_per_shadow_ray": self.primitives_per_shadow_ray,
        })
    }
}

impl RtlTiming {
    fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "rays": self.rays,
            "cycles": self.cycles,
            "node_visits": self.node_visits,
            "result_words": self.result_words,
            "matches_golden": self.matches_golden,
        })
    }
}

fn project(counts: &UnitCounts, rtl: &RtlTiming, a9_cycles_per_query: f64) -> serde_json::Value {
    let cycles_per_ray = rtl.cycles as f64 / rtl.rays.max(1) as f64;
    let fabric = FABRIC_HZ / cycles_per_ray;
    // One 64-bit beat a clock on the port, reads and writes together (hardware-facts.md
    // §3.2): the ray's words in, candidates and the end word out.
    let beats = RAY_WORDS as f64 + counts.candidates_per_ray + 1.0;
    let port = FABRIC_HZ / beats;
    let read_cycles_per_beat = 8.0 / A9_STREAM_BYTES_PER_S * A9_HZ;
    let hps_cycles = A9_CYCLES_PER_RAY_SENT
        + (counts.candidates_per_ray + 1.0) * read_cycles_per_beat
        + counts.candidates_per_ray * A9_CYCLES_PER_CANDIDATE_READ
        + counts.primitives_per_ray * A9_CYCLES_PER_PRIMITIVE
        + counts.far_end_box_tests_per_ray * A9_CYCLES_PER_BOX;
    let hps = A9_CORES * A9_HZ / hps_cycles;
    let projected = fabric.min(port).min(hps);
    let a9 = A9_CORES * A9_HZ / a9_cycles_per_query;
    let bound = if projected == fabric {
        "the fabric (rays interleaved)"
    } else if projected == port {
        "the 64-bit f2sdram port"
    } else {
        "the HPS (sending rays, reading and testing candidates)"
    };
    serde_json::json!({
        "fabric_cycles_per_ray": cycles_per_ray,
        "traversal_tests_per_cycle": 2.0 * rtl.node_visits as f64 / rtl.cycles.max(1) as f64,
        "fabric_rays_per_s": fabric,
        "port_rays_per_s": port,
        "hps_cycles_per_ray": hps_cycles,
        "hps_rays_per_s": hps,
        "rays_per_s_projected": projected,
        "a9_cycles_per_ray": a9_cycles_per_query,
        "a9_rays_per_s": a9,
        "speedup_over_a9": projected / a9,
        "bound": bound,
    })
}

/// The unit on every bench room: counts, RTL timing, projection.
pub fn run(paths: u32) -> anyhow::Result<serde_json::Value> {
    let mut rooms = Vec::new();
    for room in bench_rooms() {
        let (scene, sensors) = load_room(&room)?;
        let settings = Settings {
            samples_per_sensor: paths,
            ..Settings::default()
        };
        // The A9 software estimate of the same run (the engine's own traversal, counted).
        let software = traversal_stats::measure(&scene, &sensors, &settings)
            .with_context(|| room.name.to_string())?;
        let q = (software.closest.queries + software.crossed.queries).max(1) as f64;
        let a9_per_query = (software.closest.queries as f64 * a9_cycles(&software.closest)
            + software.crossed.queries as f64 * a9_cycles(&software.crossed))
            / q;

        let mut world = World::new(&scene)?;
        let points: Vec<_> = sensors.iter().map(|s| s.position_m).collect();
        openings::add_openings(&mut world, &points);
        let nodes = unit_nodes(world.bvh(), &world.primitive_bounds())
            .with_context(|| room.name.to_string())?;
        let recording = Arc::new(Recording {
            golden: RwLock::new(GoldenBvhUnit::default()),
            seen: AtomicU64::new(0),
            kept: Mutex::new(Vec::new()),
        });
        world
            .attach_bvh_unit(Box::new(RecordingBackend(recording.clone())))
            .or_else(|e| anyhow::bail!("{}: {e}", room.name))?;
        illuminance(&world, &sensors, &settings, &|_, _| {})?;
        let unit = world.bvh_unit().context("attached")?;
        let rays = unit.stats.rays.load(Ordering::Relaxed);
        let per = |v: u64| v as f64 / rays.max(1) as f64;
        let closest_rays = unit.stats.closest_rays.load(Ordering::Relaxed);
        let closest_primitives = unit.stats.closest_primitives.load(Ordering::Relaxed);
        let primitives = unit.stats.primitives.load(Ordering::Relaxed);
        let counts = UnitCounts {
            rays,
            refused: unit.stats.refused.load(Ordering::Relaxed)
                + unit.stats.failed.load(Ordering::Relaxed),
            node_visits_per_ray: per(recording
                .golden
                .read()
                .map(|g| g.node_visits.load(Ordering::Relaxed))
                .unwrap_or(0)),
            candidates_per_ray: per(unit.stats.candidates.load(Ordering::Relaxed)),
            primitives_per_ray: per(unit.stats.primitives.load(Ordering::Relaxed)),
            far_end_box_tests_per_ray: per(unit.stats.far_end_box_tests.load(Ordering::Relaxed)),
            closest_share: per(closest_rays),
            primitives_per_closest_ray: closest_primitives as f64 / closest_rays.max(1) as f64,
            primitives_per_shadow_ray: (primitives - closest_primitives) as f64
                / rays.saturating_sub(closest_rays).max(1) as f64,
        };
        let sample = recording.kept.lock().map(|k| k.clone()).unwrap_or_default();
        let rtl = time_on_rtl(&nodes, &sample).with_context(|| room.name.to_string())?;
        if !rtl.matches_golden {
            anyhow::bail!(
                "{}: the RTL block's answers differ from the golden model's",
                room.name
            );
        }
        rooms.push(serde_json::json!({
            "room": room.name,
            "unit_nodes": nodes.len(),
            "software_queries": q,
            "counts": counts.to_json(),
            "rtl_sample": rtl.to_json(),
            "projection": project(&counts, &rtl, a9_per_query),
        }));
    }
    let least = rooms
        .iter()
        .filter_map(|r| r["projection"]["speedup_over_a9"].as_f64())
        .fold(f64::INFINITY, f64::min);
    Ok(serde_json::json!({
        "least_speedup_over_a9": least,
        "status": "built: the golden model in the engine (bit-identical), the RTL block timed cycle-accurately",
        "rooms": rooms,
        "a9_cycles_per_ray_sent_estimate": A9_CYCLES_PER_RAY_SENT,
    }))
}

/// Times `rays` on the cycle-accurate block loaded with `nodes`: each order's rays as one
/// batch streamed back to back from an idle block (tags 0, 1, ...), results always taken (the
/// fabric's own rate), each ray's words (told apart by tag: rays may interleave) compared
/// with the golden model's.
pub fn time_on_rtl(nodes: &[NodeWords], rays: &[(Order, RayWords)]) -> anyhow::Result<RtlTiming> {
    let unpacked: Vec<UnitNode> = nodes
        .iter()
        .enumerate()
        .map(|(k, w)| UnitNode::unpack(w).with_context(|| format!("node {k}: wrong magic byte")))
        .collect::<anyhow::Result<_>>()?;
    let mut timing = RtlTiming {
        rays: rays.len(),
        cycles: 0,
        node_visits: 0,
        result_words: 0,
        matches_golden: true,
    };
    for order in [Order::NearFirst, Order::ChildOrder] {
        let batch: Vec<RayWords> = rays
            .iter()
            .filter(|(o, _)| *o == order)
            .map(|(_, w)| *w)
            .collect();
        if batch.is_empty() {
            continue;
        }
        for ray in &batch {
            let mut visits = 0;
            let _ = traverse_counting(&unpacked, ray, order, &mut visits);
            timing.node_visits += visits as u64;
        }
        let mut bench = BvhBench::new(0x5eed);
        bench.idle(2);
        bench.load(nodes);
        bench.configure(nodes.len(), order);
        bench.idle(2);
        // A bound no correct run reaches: every visit of every ray a hundred times over.
        let max_cycles = 100 * (timing.node_visits + 10 * batch.len() as u64 + 100);
        let run = bench
            .run(&batch, || true, || true, max_cycles)
            .context("the RTL block did not finish the batch")?;
        timing.cycles += run.cycles;
        timing.result_words += run.words.len() as u64;
        // The tags the block gave (0, 1, ... modulo 256: the rays come back to back).
        let golden: Vec<Vec<u64>> = batch
            .iter()
            .zip(&run.tags)
            .map(|(ray, &tag)| result_words(&unpacked, ray, order, tag))
            .collect();
        timing.matches_golden &= run.tags.len() == batch.len()
            && run.tags.iter().enumerate().all(|(k, &t)| t == k as u8)
            && split_rays(&run.words, &run.tags) == Some(golden);
    }
    Ok(timing)
}
