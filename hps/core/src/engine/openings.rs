//! Openings: holes in a room's envelope with nothing in them (a window left unglazed, a door,
//! a model that leaves the glazing to another file, as the LBNL matrix tutorial's room does
//! for `rfluxmtx`). Glass and invisible polygons are portals by themselves
//! ([`super::world::World::portals`]); an opening has no polygon, so the sky beyond it would
//! be found only by the paths' own chance. Found here from points inside the room and added
//! to the portals, it is sampled as a window is.
//!
//! Portals are a sampling distribution only (`super::portal`): a rectangle that covers some
//! wall as well as the hole, or misses part of the hole, costs efficiency, never correctness.
//! So the search is simple: the room's box is measured by axis rays from the interior points,
//! each face of the box is cut into cells, and a cell is open when a ray from an interior
//! point passes through its centre into what lies beyond without meeting a surface there.
//! The open cells of a face are merged into rectangles.

use super::ray::Ray;
use super::world::World;
use glam::DVec3;
use rayon::prelude::*;

/// Cells along each side of a face of the room's box.
const CELLS_PER_SIDE: usize = 48;
/// Interior points whose rays test each cell (the nearest ones).
const TESTERS_PER_CELL: usize = 4;
/// Most interior points used (the sensors of a large grid say nothing more about the room).
const MOST_POINTS: usize = 256;
/// A point is inside the room when at least this many of its six axis rays meet a surface.
const ENCLOSED_AXES: usize = 5;

/// An opening: a rectangle on a face of the room's box, corners in order.
pub type Opening = [DVec3; 4];

/// Finds the openings of the room around `interior_points_m` ([`find_openings`]) and adds
/// them to the world's portals; returns how many. Callers that know where the room is (the
/// sensors) call it once after building the world.
pub fn add_openings(world: &mut World, interior_points_m: &[DVec3]) -> usize {
    let found = find_openings(world, interior_points_m);
    world.add_opening_portals(&found);
    found.len()
}

/// The openings of the room holding `interior_points_m` (sensors, say), as rectangles in the
/// planes of the room box's faces. Empty when no point is enclosed or nothing is open.
pub fn find_openings(world: &World, interior_points_m: &[DVec3]) -> Vec<Opening> {
    let step = interior_points_m.len().div_ceil(MOST_POINTS).max(1);
    let points: Vec<DVec3> = interior_points_m
        .iter()
        .step_by(step)
        .copied()
        .filter(|p| p.is_finite() && enclosed(world, *p))
        .collect();
    let Some(room) = RoomBox::measure(world, &points) else {
        return Vec::new();
    };
    let mut openings = Vec::new();
    for axis in 0..3 {
        for upper in [false, true] {
            openings.extend(room.face_openings(world, &points, axis, upper));
        }
    }
    openings
}

/// Whether enough of the six axis rays from `p` meet a surface.
fn enclosed(world: &World, p: DVec3) -> bool {
    AXES.iter()
        .filter(|d| world.intersect(&Ray::new(p, **d), None).is_some())
        .count()
        >= ENCLOSED_AXES
}

const AXES: [DVec3; 6] = [
    DVec3::NEG_X,
    DVec3::X,
    DVec3::NEG_Y,
    DVec3::Y,
    DVec3::NEG_Z,
    DVec3::Z,
];

/// The box the interior points' axis rays measure: per axis and side, the farthest surface
/// met (None on a side where every ray escaped).
struct RoomBox {
    lower: [Option<f64>; 3],
    upper: [Option<f64>; 3],
    /// The points' own extent, where a side has no surface.
    min: DVec3,
    max: DVec3,
}

impl RoomBox {
    fn measure(world: &World, points: &[DVec3]) -> Option<Self> {
        let first = *points.first()?;
        let mut room = RoomBox {
            lower: [None; 3],
            upper: [None; 3],
            min: first,
            max: first,
        };
        for &p in points {
            room.min = room.min.min(p);
            room.max = room.max.max(p);
            for (k, d) in AXES.iter().enumerate() {
                let Some(hit) = world.intersect(&Ray::new(p, *d), None) else {
                    continue;
                };
                let at = (p + *d * hit.t_m)[k / 2];
                let side = if k % 2 == 0 {
                    &mut room.lower[k / 2]
                } else {
                    &mut room.upper[k / 2]
                };
                *side = Some(match (*side, k % 2 == 0) {
                    (None, _) => at,
                    (Some(s), true) => s.min(at),
                    (Some(s), false) => s.max(at),
                });
            }
        }
        Some(room)
    }

    /// The open rectangles of one face: `axis` 0, 1, 2 for x, y, z, on its `upper` side.
    fn face_openings(
        &self,
        world: &World,
        points: &[DVec3],
        axis: usize,
        upper: bool,
    ) -> Vec<Opening> {
        let plane = if upper {
            self.upper[axis]
        } else {
            self.lower[axis]
        };
        let Some(plane) = plane else {
            return Vec::new();
        };
        let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
        let extent = |k: usize| -> (f64, f64) {
            let lo = self.lower[k].unwrap_or(self.min[k]);
            let hi = self.upper[k].unwrap_or(self.max[k]);
            (lo.min(hi), lo.max(hi))
        };
        let ((a0, a1), (b0, b1)) = (extent(a), extent(b));
        if !(a1 - a0 > 0.0 && b1 - b0 > 0.0) {
            return Vec::new();
        }
        let n = CELLS_PER_SIDE;
        let (da, db) = ((a1 - a0) / n as f64, (b1 - b0) / n as f64);
        let point_at = |u: f64, v: f64| {
            let mut c = DVec3::ZERO;
            c[axis] = plane;
            c[a] = u;
            c[b] = v;
            c
        };
        // Tolerance for "the surface is at the cell": round-off of the box's own hits.
        let scale = (a1 - a0).max(b1 - b0).max(1e-3);
        let tolerance_m = 1e-6 * scale + 1e-6;
        // The cells are independent: tested in parallel (the search runs before every
        // illuminance computation, the daemon's cycle and the bench's runs included).
        let open: Vec<bool> = (0..n * n)
            .into_par_iter()
            .map(|i| {
                let (ia, ib) = (i % n, i / n);
                let c = point_at(a0 + (ia as f64 + 0.5) * da, b0 + (ib as f64 + 0.5) * db);
                cell_is_open(world, points, c, tolerance_m)
            })
            .collect();
        rectangles(&open, n)
            .into_iter()
            .map(|(ia0, ia1, ib0, ib1)| {
                let (u0, u1) = (a0 + ia0 as f64 * da, a0 + ia1 as f64 * da);
                let (v0, v1) = (b0 + ib0 as f64 * db, b0 + ib1 as f64 * db);
                [
                    point_at(u0, v0),
                    point_at(u1, v0),
                    point_at(u1, v1),
                    point_at(u0, v1),
                ]
            })
            .collect()
    }
}

/// A cell centred on `c` is open when the ray from the nearest interior point that reaches
/// `c` at all (the nearest few are tried, nearest first) passes it with nothing there; a
/// surface at `c` closes it.
fn cell_is_open(world: &World, points: &[DVec3], c: DVec3, tolerance_m: f64) -> bool {
    let mut nearest: Vec<(f64, DVec3)> =
        points.iter().map(|p| (p.distance_squared(c), *p)).collect();
    let k = TESTERS_PER_CELL.min(nearest.len());
    if k == 0 {
        return false;
    }
    nearest.select_nth_unstable_by(k - 1, |x, y| x.0.total_cmp(&y.0));
    let testers = &mut nearest[..k];
    testers.sort_by(|x, y| x.0.total_cmp(&y.0));
    for &(d2, p) in testers.iter() {
        let dist = d2.sqrt();
        if dist <= tolerance_m {
            continue;
        }
        let d = (c - p) / dist;
        match world.intersect(&Ray::new(p, d), None) {
            None => return true,
            Some(hit) if hit.t_m > dist + tolerance_m => return true,
            Some(hit) if hit.t_m >= dist - tolerance_m => return false,
            // Something in the way: ask the next.
            Some(_) => {}
        }
    }
    false
}

/// The open cells of an `n` × `n` grid (row-major, row = second index) as rectangles
/// (a0, a1, b0, b1) in cell units, end exclusive: each row's runs, a run extended over the
/// following rows that hold the same run.
fn rectangles(open: &[bool], n: usize) -> Vec<(usize, usize, usize, usize)> {
    let mut used = vec![false; n * n];
    let mut out = Vec::new();
    for b in 0..n {
        let mut a = 0;
        while a < n {
            if !open[b * n + a] || used[b * n + a] {
                a += 1;
                continue;
            }
            let start = a;
            while a < n && open[b * n + a] && !used[b * n + a] {
                a += 1;
            }
            let run = start..a;
            let mut end_b = b + 1;
            while end_b < n
                && run
                    .clone()
                    .all(|x| open[end_b * n + x] && !used[end_b * n + x])
            {
                end_b += 1;
            }
            for row in b..end_b {
                for x in run.clone() {
                    used[row * n + x] = true;
                }
            }
            out.push((start, a, b, end_b));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene;

    /// A closed 4 × 3 × 2.5 m box with a 2 × 1 m hole in its y = 0 wall (the wall as four
    /// polygons around the hole), and another with the hole glazed.
    fn room(glazed: bool) -> World {
        World::new(&scene::parse("room.rad", room_text(glazed).as_bytes()).unwrap()).unwrap()
    }

    fn room_text(glazed: bool) -> String {
        let mut text =
            String::from("void plastic w 0 0 5 .5 .5 .5 0 0\nvoid glass g 0 0 3 .9 .9 .9\n");
        let quad = |name: &str, v: [[f64; 3]; 4], m: &str| {
            let mut s = format!("{m} polygon {name} 0 0 12");
            for p in v {
                s += &format!(" {} {} {}", p[0], p[1], p[2]);
            }
            s + "\n"
        };
        let (x, y, z) = (4.0, 3.0, 2.5);
        text += &quad(
            "floor",
            [[0., 0., 0.], [0., y, 0.], [x, y, 0.], [x, 0., 0.]],
            "w",
        );
        text += &quad(
            "ceiling",
            [[0., 0., z], [x, 0., z], [x, y, z], [0., y, z]],
            "w",
        );
        text += &quad(
            "west",
            [[0., 0., 0.], [0., 0., z], [0., y, z], [0., y, 0.]],
            "w",
        );
        text += &quad(
            "east",
            [[x, 0., 0.], [x, y, 0.], [x, y, z], [x, 0., z]],
            "w",
        );
        text += &quad(
            "north",
            [[0., y, 0.], [0., y, z], [x, y, z], [x, y, 0.]],
            "w",
        );
        // The south wall around a hole x 1..3, z 1..2.
        text += &quad(
            "s1",
            [[0., 0., 0.], [x, 0., 0.], [x, 0., 1.], [0., 0., 1.]],
            "w",
        );
        text += &quad(
            "s2",
            [[0., 0., 2.], [x, 0., 2.], [x, 0., z], [0., 0., z]],
            "w",
        );
        text += &quad(
            "s3",
            [[0., 0., 1.], [1., 0., 1.], [1., 0., 2.], [0., 0., 2.]],
            "w",
        );
        text += &quad(
            "s4",
            [[3., 0., 1.], [x, 0., 1.], [x, 0., 2.], [3., 0., 2.]],
            "w",
        );
        if glazed {
            text += &quad(
                "pane",
                [[1., 0., 1.], [3., 0., 1.], [3., 0., 2.], [1., 0., 2.]],
                "g",
            );
        }
        text
    }

    fn sensors() -> Vec<DVec3> {
        (0..12)
            .map(|i| DVec3::new(0.5 + (i % 4) as f64, 0.5 + (i / 4) as f64, 0.8))
            .collect()
    }

    /// The hole is found where it is: every rectangle in the plane y = 0, within half a
    /// cell of the hole (a cell is open when its centre is), and together they cover the
    /// hole's area to within a cell along each side.
    #[test]
    fn the_hole_in_a_wall_is_found_and_nothing_else() {
        let openings = find_openings(&room(false), &sensors());
        assert!(!openings.is_empty());
        let (cell_x, cell_z) = (4.0 / 48.0, 2.5 / 48.0);
        let mut area_m2 = 0.0;
        for o in &openings {
            for p in o {
                assert!(p.y.abs() < 1e-9, "{o:?}");
                assert!(
                    (1.0 - cell_x / 2.0..=3.0 + cell_x / 2.0).contains(&p.x),
                    "{o:?}"
                );
                assert!(
                    (1.0 - cell_z / 2.0..=2.0 + cell_z / 2.0).contains(&p.z),
                    "{o:?}"
                );
            }
            area_m2 += (o[1] - o[0]).length() * (o[3] - o[0]).length();
        }
        let (least, most) = (
            (2.0 - cell_x) * (1.0 - cell_z),
            (2.0 + cell_x) * (1.0 + cell_z),
        );
        assert!(area_m2 >= least && area_m2 <= most, "{area_m2}");
    }

    /// A glazed hole is no opening (the pane is a portal of its own), and a closed room or
    /// points outside every room have none.
    #[test]
    fn glass_and_closed_rooms_have_no_openings() {
        assert!(find_openings(&room(true), &sensors()).is_empty());
        let outside = [DVec3::new(50.0, 50.0, 50.0)];
        assert!(find_openings(&room(false), &outside).is_empty());
        assert!(find_openings(&room(false), &[]).is_empty());
    }

    /// The sun through a found opening, whose edge cells overlap the wall below the sill
    /// (where the sun-patch strategy's way back to the portal and the wall are at the same
    /// distance): with the opening as a portal the sensors read what plain path tracing
    /// reads (sun-patch strategy off: escapes found by chance), within 4 combined standard
    /// errors, and with less noise. Before the sampler and the density decided that
    /// distance alike (`Portals::projection_crosses`), the LBNL tutorial room read 1-3 %
    /// high this way.
    #[test]
    fn the_sun_through_an_opening_is_counted_once() {
        use crate::engine::{illuminance, Settings};
        // The sun 40° up in the south-east, low enough that its patch reaches the floor.
        let sun = glam::DVec3::new(0.35, -0.65, 0.64).normalize();
        let text = room_text(false)
            + &format!(
                "void light solar 0 0 3 1e5 1e5 1e5\nsolar source sun 0 0 4 {} {} {} 0.533\n",
                sun.x, sun.y, sun.z
            );
        // Out of the beam (it reaches y < 1.3 m at their height), lit by the patch's light.
        let sensors_text: String = (0..12)
            .map(|i| {
                format!(
                    "{} {} 0.8 0 0 1\n",
                    0.5 + (i % 4) as f64,
                    1.6 + 0.6 * (i / 4) as f64
                )
            })
            .collect();
        let sensors = scene::parse_sensors("s.pts", sensors_text.as_bytes()).unwrap();
        let run = |openings: bool, sun_patch: bool| {
            let mut world =
                World::new(&scene::parse("room.rad", text.as_bytes()).unwrap()).unwrap();
            if openings {
                let points: Vec<DVec3> = sensors.iter().map(|s| s.position_m).collect();
                assert!(add_openings(&mut world, &points) > 0);
            }
            let settings = Settings {
                ambient_bounces: 8,
                samples_per_sensor: 8192,
                sun_portal_sampling: sun_patch,
                seed: 5,
                ..Settings::default()
            };
            illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap()
        };
        let (se_with, se_plain) =
            agree_within_4_sigma(&run(true, true), &run(false, false), "the opening");
        assert!(se_with < 0.5 * se_plain, "{se_with} against {se_plain}");
    }

    /// The sunlit ground outside the window, which the room sees only through it: with the
    /// sunlit-outside strategy (`Settings::sunlit_outside_sampling`) the sensors read what
    /// they read without it, within 4 combined standard errors, through a pane of glass and
    /// through the bare opening, with and without path reuse (which turns the strategy off
    /// at the sensors), and with less noise. Sensors face up (the ground's light comes by
    /// the ceiling) and towards the window (they see the ground).
    #[test]
    fn the_sunlit_ground_past_a_window_is_counted_once() {
        use crate::engine::{illuminance, Settings};
        // The sun 40° up in the south-east: on the ground and on the room's floor.
        let sun = glam::DVec3::new(0.35, -0.65, 0.64).normalize();
        let sensors_text: String = (0..12)
            .map(|i| {
                let (x, y) = (0.5 + (i % 4) as f64, 1.6 + 0.6 * (i / 4) as f64);
                let facing = if i % 3 == 0 { "0 -1 0" } else { "0 0 1" };
                format!("{x} {y} 0.8 {facing}\n")
            })
            .collect();
        let sensors = scene::parse_sensors("s.pts", sensors_text.as_bytes()).unwrap();
        for glazed in [true, false] {
            let text = room_text(glazed)
                + "void plastic grass 0 0 5 .3 .3 .3 0 0\n\
                   grass polygon ground 0 0 12 -20 -30 0 24 -30 0 24 0 0 -20 0 0\n"
                + &format!(
                    "void light solar 0 0 3 1e5 1e5 1e5\nsolar source sun 0 0 4 {} {} {} 0.533\n",
                    sun.x, sun.y, sun.z
                );
            let mut world =
                World::new(&scene::parse("room.rad", text.as_bytes()).unwrap()).unwrap();
            let points: Vec<DVec3> = sensors.iter().map(|s| s.position_m).collect();
            add_openings(&mut world, &points);
            assert!(!world.portals().is_empty());
            for reuse in [true, false] {
                let run = |outside: bool| {
                    let settings = Settings {
                        ambient_bounces: 8,
                        samples_per_sensor: 8192,
                        sunlit_outside_sampling: outside,
                        path_reuse: reuse,
                        seed: 9,
                        ..Settings::default()
                    };
                    illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap()
                };
                let (se_with, se_without) = agree_within_4_sigma(
                    &run(true),
                    &run(false),
                    &format!("the strategy (glazed {glazed}, reuse {reuse})"),
                );
                eprintln!("glazed {glazed}, reuse {reuse}: {se_with:.4} against {se_without:.4}");
                assert!(
                    se_with < 0.8 * se_without,
                    "glazed {glazed}, reuse {reuse}: {se_with} against {se_without}"
                );
            }
        }
    }

    /// Asserts that every sensor of `with` reads what it reads in `without` within 4
    /// combined standard errors, and returns the two runs' summed relative standard errors.
    fn agree_within_4_sigma(
        with: &[crate::engine::illuminance::SensorIlluminance],
        without: &[crate::engine::illuminance::SensorIlluminance],
        what: &str,
    ) -> (f64, f64) {
        let (mut se_with, mut se_without) = (0.0, 0.0);
        for (a, b) in with.iter().zip(without) {
            let z = (a.illuminance_lux - b.illuminance_lux)
                / (a.stderr_lux.powi(2) + b.stderr_lux.powi(2)).sqrt();
            assert!(
                z.abs() < 4.0,
                "{}: {:.1} ± {:.1} lux with {what}, {:.1} ± {:.1} without",
                a.name,
                a.illuminance_lux,
                a.stderr_lux,
                b.illuminance_lux,
                b.stderr_lux
            );
            se_with += a.stderr_lux / a.illuminance_lux;
            se_without += b.stderr_lux / b.illuminance_lux;
        }
        (se_with, se_without)
    }

    #[test]
    fn open_cells_merge_into_rectangles() {
        let n = 4;
        #[rustfmt::skip]
        let open = [
            false, true, true, false,
            false, true, true, false,
            true,  true, false, false,
            false, false, false, true,
        ];
        let r = rectangles(&open, n);
        assert_eq!(r, vec![(1, 3, 0, 2), (0, 2, 2, 3), (3, 4, 3, 4)]);
    }
}
