//! The BVH ray unit (issue 22 item 4) in the engine, on the two bench rooms: the reference
//! room and the LBNL matrix tutorial room of `../shared/data/radiance-corpus`. With the unit's
//! golden model traversing (`World::attach_bvh_unit`), every hit decision and the whole
//! illuminance run are bit-identical to the software traversal, and the unit answered the
//! rays (none fell back to software).

use glam::DVec3;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use skylux_hps::engine::ray::Ray;
use skylux_hps::engine::{illuminance, Settings, World};
use skylux_hps::fpga::bvh_unit::GoldenBvhUnit;
use skylux_hps::scene;
use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;

fn shared() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../shared")
}

/// The bench's sky (`skylux bench raybox --traversal-only`): a sun 50° up and uniform glows.
const SKY: &str = "void light solar 0 0 3 5e6 5e6 5e6\n\
                   solar source sun 0 0 4 0.45 -0.45 0.766 0.533\n\
                   void glow sky_glow 0 0 4 3000 3000 3000 0\n\
                   sky_glow source sky 0 0 4 0 0 1 180\n\
                   void glow ground_glow 0 0 4 600 600 600 0\n\
                   ground_glow source ground 0 0 4 0 0 -1 180\n";

fn room(dir: &Path, files: &[&str], points: &str) -> (scene::Scene, Vec<scene::Sensor>) {
    let options = scene::LoadOptions {
        working_directory: Some(dir.to_path_buf()),
        ..Default::default()
    };
    let mut s = scene::Scene::new();
    for f in files {
        s.add_file_with(dir.join(f), &options)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.join(f).display()));
    }
    s.add_bytes("sky.rad", SKY.as_bytes()).unwrap();
    let sensors = scene::load_sensors(dir.join(points)).unwrap();
    (s, sensors)
}

fn check_room(
    scene: &scene::Scene,
    sensors: &[scene::Sensor],
    min_hits: usize,
    min_unit_rays: u64,
) {
    let software = World::new(scene).unwrap();
    let mut unit = World::new(scene).unwrap();
    unit.attach_bvh_unit(Box::<GoldenBvhUnit>::default())
        .expect("the room's tree fits the unit");

    let mut rng = StdRng::seed_from_u64(22);
    let mut hits = 0;
    for s in sensors {
        for _ in 0..2000 {
            let d = DVec3::new(
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
            )
            .normalize();
            let ray = Ray::new(s.position_m, d);
            let a = software
                .intersect(&ray, None)
                .map(|h| (h.primitive, h.t_m.to_bits()));
            let b = unit
                .intersect(&ray, None)
                .map(|h| (h.primitive, h.t_m.to_bits()));
            assert_eq!(a, b, "ray {ray:?}");
            hits += a.is_some() as usize;
        }
    }
    assert!(hits > min_hits, "{hits} hits: the rays must meet the room");

    let settings = Settings {
        ambient_bounces: 3,
        samples_per_sensor: 256,
        seed: 5,
        ..Default::default()
    };
    let a = illuminance(&software, sensors, &settings, &|_, _| {}).unwrap();
    let b = illuminance(&unit, sensors, &settings, &|_, _| {}).unwrap();
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(
            x.illuminance_lux.to_bits(),
            y.illuminance_lux.to_bits(),
            "{}: {} vs {}",
            x.name,
            x.illuminance_lux,
            y.illuminance_lux
        );
        assert_eq!(x.stderr_lux.to_bits(), y.stderr_lux.to_bits(), "{}", x.name);
    }
    assert!(a.iter().any(|s| s.illuminance_lux > 0.0));
    let stats = &unit.bvh_unit().unwrap().stats;
    let rays = stats.rays.load(Ordering::Relaxed);
    println!(
        "unit rays {rays}, candidates {}, refused {}, failed {}, primitives {}, closest rays {} primitives {}",
        stats.candidates.load(Ordering::Relaxed),
        stats.refused.load(Ordering::Relaxed),
        stats.failed.load(Ordering::Relaxed),
        stats.primitives.load(Ordering::Relaxed),
        stats.closest_rays.load(Ordering::Relaxed),
        stats.closest_primitives.load(Ordering::Relaxed),
    );
    assert!(rays > min_unit_rays, "{rays}");
    assert_eq!(stats.refused.load(Ordering::Relaxed), 0);
    assert_eq!(stats.failed.load(Ordering::Relaxed), 0);
}

#[test]
fn reference_room_is_bit_identical_through_the_unit() {
    let (s, sensors) = room(
        &shared().join("scenes/test-module"),
        &["scene.rad"],
        "sensors.pts",
    );
    check_room(&s, &sensors, 1000, 20_000);
}

#[test]
fn lbnl_tutorial_room_is_bit_identical_through_the_unit() {
    let (s, sensors) = room(
        &shared().join("data/radiance-corpus/sariths-matrix-tutorial/room"),
        &["materials.rad", "room.rad"],
        "points.txt",
    );
    check_room(&s, &sensors, 1000, 500_000);
}
