//! A battery of random campaigns for the loop (issue 18): random rooms, sites, dates and
//! skies, each with no undeclared effect, one, or a pair, drawn from [`EFFECT_RANGES`].
//! Everything is a function of the seed; the rooms are RADIANCE text the case writes where
//! it is asked ([`BatteryCase::write_room`]), and the truth is meant to come from RADIANCE
//! ([`crate::campaign::TruthSource::Radiance`]), not from the engine the loop's model uses.

use crate::campaign::{CampaignSpec, DaySky, LoggerSchedule, TruthSource};
use chrono::NaiveDate;
use glam::DVec3;
use skylux_hps::campaign::Site;
use skylux_hps::sun::position::{solar_position, Site as SunSite};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// What sky an effect needs to be visible at all.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SkyNeed {
    /// Any sky.
    Any,
    /// The sun on at least one day (not two overcast days).
    Sun,
    /// As [`SkyNeed::Sun`], and the sun in the camera's field at [`MIN_SUN_IN_VIEW`]
    /// captures of a day that is not overcast: an effect seen only in the frames' sun (the
    /// shutter's overhead, the camera's orientation) acts on nothing where the camera never
    /// sees it (campaign #71 of the seed-18 battery: a 14 µs overhead, façade 169° at 15°N, the
    /// sun north of the camera's field all day, hold-out 1.4 % with and without it). Extra
    /// vignetting too: under overcast skies alone it dims the sky seen through the window
    /// by a near-uniform few %, which a glazing factor matches (campaign #11: 0.39 beside a
    /// glazing of 0.74 on two overcast days, fitted as a glazing of 0.78 and a vignetting of
    /// 0.06); the sun crossing the field at different off-axis angles tells them apart.
    SunInView,
    /// A clear first day (the colour of a clear sky against the other day's).
    Clear,
    /// Partly cloudy days: the light must change within minutes.
    Partly,
}

/// One effect class of the battery: the loop's name, the range its magnitude is drawn from
/// (uniformly; a random sign where `signed`), the sky it needs, and why that range.
#[derive(Clone, Copy, Debug)]
pub struct EffectRange {
    pub name: &'static str,
    pub min: f64,
    pub max: f64,
    pub signed: bool,
    pub unit: &'static str,
    pub sky: SkyNeed,
    pub reason: &'static str,
}

/// The battery's effect classes and their physical ranges (one table, for the docs to cite).
pub const EFFECT_RANGES: &[EffectRange] = &[
    EffectRange {
        name: "glazing_transmittance",
        min: 0.55,
        max: 0.9,
        signed: false,
        unit: "relative",
        sky: SkyNeed::Any,
        reason: "soiled glazing loses 10-45 % of its transmittance",
    },
    EffectRange {
        name: "light_leak",
        min: 0.002,
        max: 0.02,
        signed: false,
        unit: "lux/lux",
        sky: SkyNeed::Any,
        reason: "light through gaps, a door or a skylight the scene omits: 0.2-2 % of outdoors",
    },
    EffectRange {
        name: "ground_reflectance",
        min: 0.4,
        max: 0.8,
        signed: false,
        unit: "",
        sky: SkyNeed::Any,
        reason: "snow or light paving outside, where the model assumes 0.2",
    },
    EffectRange {
        name: "orientation_error",
        min: 2.0,
        max: 10.0,
        signed: true,
        unit: "deg",
        sky: SkyNeed::SunInView,
        reason: "a camera mounted by eye or by compass (magnetic declination) is off by degrees",
    },
    EffectRange {
        name: "clock_offset",
        min: 60.0,
        max: 1800.0,
        signed: true,
        unit: "s",
        sky: SkyNeed::Partly,
        reason: "a logger set by hand, or left on the other side of a daylight-saving change",
    },
    EffectRange {
        name: "shutter_overhead",
        min: 1.0,
        max: 15.0,
        signed: false,
        unit: "µs",
        sky: SkyNeed::SunInView,
        reason: "the MT9P031's shutter adds a fraction of a row time to every exposure",
    },
    EffectRange {
        name: "spectral_mismatch",
        min: 10_000.0,
        max: 25_000.0,
        signed: false,
        unit: "K",
        sky: SkyNeed::Clear,
        reason: "a clear sky's colour temperature away from the sun, against a D65 calibration",
    },
    EffectRange {
        name: "glazing_angular",
        min: 0.1,
        max: 0.3,
        signed: false,
        unit: "b0",
        sky: SkyNeed::Sun,
        reason: "coated or multiple glazing loses more at incidence than clean glass (b0 0.05)",
    },
    EffectRange {
        name: "vignetting",
        min: 0.2,
        max: 0.5,
        signed: false,
        unit: "",
        sky: SkyNeed::SunInView,
        reason: "a fisheye's relative illumination miscalibrated or changed by a dome",
    },
    EffectRange {
        name: "sky_outside_fov",
        min: 45.0,
        max: 60.0,
        signed: false,
        unit: "deg",
        sky: SkyNeed::Any,
        reason: "a housing or baffle clips the image 45-60° off axis",
    },
];

/// The effect class of that name.
pub fn effect_range(name: &str) -> Option<&'static EffectRange> {
    EFFECT_RANGES.iter().find(|e| e.name == name)
}

/// The room of a case: a box with one glazed opening, as RADIANCE text.
#[derive(Clone, Debug, PartialEq)]
pub struct BatteryRoom {
    pub width_m: f64,
    pub depth_m: f64,
    pub height_m: f64,
    /// Direction the façade faces (its outward normal), degrees from north towards east.
    pub facade_azimuth_deg: f64,
    /// Normal-incidence transmittance of the glazing.
    pub glazing_transmittance: f64,
    pub floor_reflectance: f64,
    pub wall_reflectance: f64,
    pub ceiling_reflectance: f64,
    pub scene_rad: String,
    pub sensors_pts: String,
}

/// One campaign of the battery.
#[derive(Clone, Debug)]
pub struct BatteryCase {
    pub index: usize,
    /// The case's own seed (the campaign's noise and clouds).
    pub seed: u64,
    /// `none`, an effect's name, or two joined by `+`.
    pub class: String,
    /// The undeclared effects in the world, `(name, value)`.
    pub effects: Vec<(&'static str, f64)>,
    pub room: BatteryRoom,
    pub site: Site,
    pub utc_offset_s: i32,
    pub days: Vec<(NaiveDate, DaySky)>,
    /// Local clock hours of the captures.
    pub hours: Vec<f64>,
    /// The declared camera axis, degrees (azimuth from north towards east, altitude).
    pub camera_azimuth_deg: f64,
    pub camera_altitude_deg: f64,
}

/// Why a battery case could not be written or turned into a campaign.
#[derive(Debug, thiserror::Error)]
pub enum BatteryError {
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("battery case {case}: {message}")]
    Invalid { case: usize, message: String },
}

impl BatteryCase {
    /// Writes `scene.rad` and `sensors.pts` into `dir` (created).
    pub fn write_room(&self, dir: &Path) -> Result<(), BatteryError> {
        let io = |path: &Path| {
            let path = path.to_path_buf();
            move |source| BatteryError::Io { path, source }
        };
        std::fs::create_dir_all(dir).map_err(io(dir))?;
        for (name, text) in [
            ("scene.rad", &self.room.scene_rad),
            ("sensors.pts", &self.room.sensors_pts),
        ] {
            let path = dir.join(name);
            std::fs::write(&path, text).map_err(io(&path))?;
        }
        Ok(())
    }

    /// Both days partly cloudy, with the capture times that go with them.
    pub fn make_partly_cloudy(&mut self) {
        for d in &mut self.days {
            d.1 = DaySky::Partly;
        }
        self.hours = capture_hours(&self.site, self.utc_offset_s, &self.days);
    }

    /// The campaign of this case with the room in `room_dir` (see [`Self::write_room`]): truth
    /// from RADIANCE, frames at a quarter resolution, a continuous logger where the light
    /// must be followed between captures.
    pub fn spec(&self, room_dir: PathBuf) -> Result<CampaignSpec, BatteryError> {
        let mut spec = CampaignSpec::lausanne(room_dir);
        spec.name = format!("battery-{}-{}", self.index, self.class);
        spec.site = self.site.clone();
        spec.utc_offset_s = self.utc_offset_s;
        spec.days = self.days.clone();
        spec.hours = self.hours.clone();
        spec.device.orientation.axis_azimuth_deg = self.camera_azimuth_deg;
        spec.device.orientation.axis_altitude_deg = self.camera_altitude_deg;
        spec.skip = 4;
        spec.truth = TruthSource::RADIANCE;
        spec.seed = self.seed;
        for (name, value) in &self.effects {
            spec.effects
                .set(&format!("{name}={value}"))
                .map_err(|message| BatteryError::Invalid {
                    case: self.index,
                    message,
                })?;
        }
        let partly = self.days.iter().any(|d| d.1 == DaySky::Partly);
        if partly || spec.effects.clock_offset_s != 0.0 {
            let step_s = self
                .hours
                .windows(2)
                .map(|w| (w[1] - w[0]) * 3600.0)
                .fold(3600.0, f64::min);
            spec.logger = Some(LoggerSchedule::continuous(step_s));
        }
        Ok(spec)
    }
}

/// A deterministic stream of uniform numbers (splitmix64).
struct Draw(u64);

impl Draw {
    fn unit(&mut self) -> f64 {
        let x = skylux_hps::engine::rng::splitmix64(&mut self.0);
        (x >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    fn below(&mut self, n: usize) -> usize {
        ((self.unit() * n as f64) as usize).min(n.saturating_sub(1))
    }
    fn sign(&mut self) -> f64 {
        if self.unit() < 0.5 {
            -1.0
        } else {
            1.0
        }
    }
    /// A random permutation of 0..n (Fisher-Yates).
    fn permutation(&mut self, n: usize) -> Vec<usize> {
        let mut v: Vec<usize> = (0..n).collect();
        for i in (1..n).rev() {
            let j = self.below(i + 1);
            v.swap(i, j);
        }
        v
    }
}

/// What a case holds: no effect, one class, or a pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Bucket {
    None,
    Single(usize),
    Pair,
}

/// Two classes make sense together unless their skies exclude each other.
fn compatible(a: &EffectRange, b: &EffectRange) -> bool {
    let needs = [a.sky, b.sky];
    a.name != b.name && !(needs.contains(&SkyNeed::Partly) && needs.contains(&SkyNeed::Clear))
}

/// `n` cases drawn from `seed`: n / (classes + 2) cases with each single class, as many with
/// a pair of compatible classes and as many with none; the rest spread over the buckets in a
/// random order. The same `(n, seed)` always gives the same cases.
pub fn battery_campaigns(n: usize, seed: u64) -> Vec<BatteryCase> {
    let mut draw = Draw(seed ^ 0x5EED_BA77_E4E5);
    let classes = EFFECT_RANGES.len();
    let buckets: Vec<Bucket> = std::iter::once(Bucket::None)
        .chain(std::iter::once(Bucket::Pair))
        .chain((0..classes).map(Bucket::Single))
        .collect();
    let per = n / buckets.len();
    let mut plan: Vec<Bucket> = buckets
        .iter()
        .flat_map(|b| std::iter::repeat_n(*b, per))
        .collect();
    let order = draw.permutation(buckets.len());
    plan.extend(order.iter().take(n - plan.len()).map(|&i| buckets[i]));
    plan.into_iter()
        .enumerate()
        .map(|(index, bucket)| {
            let case_seed = skylux_hps::engine::rng::splitmix64(&mut draw.0);
            draw_case(index, case_seed, bucket)
        })
        .collect()
}

/// One case from its own seed.
fn draw_case(index: usize, seed: u64, bucket: Bucket) -> BatteryCase {
    let mut d = Draw(seed);
    let chosen: Vec<&EffectRange> = match bucket {
        Bucket::None => vec![],
        Bucket::Single(i) => vec![&EFFECT_RANGES[i]],
        Bucket::Pair => {
            let pairs: Vec<(usize, usize)> = (0..EFFECT_RANGES.len())
                .flat_map(|i| (i + 1..EFFECT_RANGES.len()).map(move |j| (i, j)))
                .filter(|&(i, j)| compatible(&EFFECT_RANGES[i], &EFFECT_RANGES[j]))
                .collect();
            let (i, j) = pairs[d.below(pairs.len())];
            vec![&EFFECT_RANGES[i], &EFFECT_RANGES[j]]
        }
    };
    let effects: Vec<(&'static str, f64)> = chosen
        .iter()
        .map(|e| {
            let v = d.range(e.min, e.max);
            (e.name, if e.signed { d.sign() * v } else { v })
        })
        .collect();
    let class = if effects.is_empty() {
        "none".to_string()
    } else {
        effects.iter().map(|e| e.0).collect::<Vec<_>>().join("+")
    };
    let latitude_deg = d.range(-45.0, 60.0);
    let longitude_deg = d.range(-180.0, 180.0);
    let site = Site {
        latitude_deg,
        longitude_deg,
        elevation_m: d.range(0.0, 1000.0),
    };
    let utc_offset_s = (longitude_deg / 15.0).round() as i32 * 3600;
    let equator = if latitude_deg >= 0.0 { 180.0 } else { 0.0 };
    let facade_azimuth_deg = (equator + d.range(-100.0, 100.0)).rem_euclid(360.0);
    let room = draw_room(&mut d, facade_azimuth_deg);
    let days = draw_days(&mut d, &chosen);
    // Where the light changes within minutes, captures every half hour: a device in service
    // captures every few minutes, and a logger clock offset or a passing cloud is only seen
    // at the captures where the sun's state differs between the two clocks.
    let hours = capture_hours(&site, utc_offset_s, &days);
    let mut case = BatteryCase {
        index,
        seed,
        class,
        effects,
        room,
        site,
        utc_offset_s,
        days,
        hours,
        camera_azimuth_deg: facade_azimuth_deg,
        camera_altitude_deg: d.range(10.0, 25.0),
    };
    // Other dates until the camera sees the sun (the draws of a case that needs no redraw are
    // unchanged, so its campaign is the same as before the rule).
    if chosen.iter().any(|e| e.sky == SkyNeed::SunInView) {
        for _ in 0..MAX_REDRAWS {
            if case.sun_in_view_captures() >= MIN_SUN_IN_VIEW {
                break;
            }
            case.days = draw_days(&mut d, &chosen);
            case.hours = capture_hours(&case.site, case.utc_offset_s, &case.days);
        }
    }
    case
}

/// Fewest captures of a day that is not overcast with the sun in the camera's field, for an
/// effect that needs it ([`SkyNeed::SunInView`]).
pub const MIN_SUN_IN_VIEW: usize = 3;

/// Redraws of the dates before a case is kept as drawn.
const MAX_REDRAWS: usize = 64;

impl BatteryCase {
    /// Captures of a day that is not overcast at which the sun is above 5° and inside the
    /// declared camera's frame (5 % in from its edges).
    pub fn sun_in_view_captures(&self) -> usize {
        let mut device = skylux_hps::camera::DeviceConfig::default();
        device.orientation.axis_azimuth_deg = self.camera_azimuth_deg;
        device.orientation.axis_altitude_deg = self.camera_altitude_deg;
        let camera = skylux_hps::camera::CameraModel::new(device);
        let (w, h) = (f64::from(RAW_WIDTH_PX), f64::from(RAW_HEIGHT_PX));
        let sun_site = SunSite {
            latitude_deg: self.site.latitude_deg,
            longitude_deg: self.site.longitude_deg,
            elevation_m: self.site.elevation_m,
        };
        let mut count = 0;
        for (date, sky) in &self.days {
            if *sky == DaySky::Overcast {
                continue;
            }
            for &hour in &self.hours {
                let midnight = date.and_hms_opt(0, 0, 0).expect("midnight");
                let local = midnight + chrono::Duration::seconds((hour * 3600.0).round() as i64);
                let utc =
                    (local - chrono::Duration::seconds(i64::from(self.utc_offset_s))).and_utc();
                let Ok(sun) = solar_position(utc, &sun_site, None) else {
                    continue;
                };
                let inside = camera.project(sun.direction()).is_some_and(|p| {
                    (0.05 * w..0.95 * w).contains(&p.x_px) && (0.05 * h..0.95 * h).contains(&p.y_px)
                });
                if sun.altitude_deg() > 5.0 && inside {
                    count += 1;
                }
            }
        }
        count
    }
}

/// The MT9P031's active array, pixels (hardware-facts: 2592 × 1944).
const RAW_WIDTH_PX: u32 = 2592;
const RAW_HEIGHT_PX: u32 = 1944;

/// Two dates of a year and their skies: random, except as the effects need.
fn draw_days(d: &mut Draw, chosen: &[&EffectRange]) -> Vec<(NaiveDate, DaySky)> {
    let year = 2019 + d.below(5) as i32;
    let mut dates: Vec<NaiveDate> = (0..2)
        .map(|_| {
            let jan1 = NaiveDate::from_ymd_opt(year, 1, 1).expect("1 January");
            jan1 + chrono::Duration::days(d.below(365) as i64)
        })
        .collect();
    dates.sort();
    if dates[0] == dates[1] {
        dates[1] += chrono::Duration::days(1);
    }
    let kinds = [DaySky::Clear, DaySky::Overcast, DaySky::Partly];
    let mut skies = [kinds[d.below(3)], kinds[d.below(3)]];
    let needs: Vec<SkyNeed> = chosen.iter().map(|e| e.sky).collect();
    if needs.contains(&SkyNeed::Partly) {
        skies = [DaySky::Partly, DaySky::Partly];
    } else if needs.contains(&SkyNeed::Clear) {
        skies[0] = DaySky::Clear;
    } else if (needs.contains(&SkyNeed::Sun) || needs.contains(&SkyNeed::SunInView))
        && skies.iter().all(|s| *s == DaySky::Overcast)
    {
        skies[0] = if d.unit() < 0.5 {
            DaySky::Clear
        } else {
            DaySky::Partly
        };
    }
    dates.into_iter().zip(skies).collect()
}

/// The capture times of a case. Where the light changes within minutes, captures every half
/// hour: a device in service captures every few minutes, and a logger clock offset or a
/// passing cloud is only seen at the captures where the sun's state differs between the two
/// clocks.
fn capture_hours(site: &Site, utc_offset_s: i32, days: &[(NaiveDate, DaySky)]) -> Vec<f64> {
    let partly = days.iter().any(|d| d.1 == DaySky::Partly);
    daylight_hours(site, utc_offset_s, days, if partly { 0.5 } else { 1.0 })
}

/// Local hours, `step_h` apart from midnight, at which the sun is above 5° on either day (the
/// simulator skips a capture with the sun under 3°).
fn daylight_hours(
    site: &Site,
    utc_offset_s: i32,
    days: &[(NaiveDate, DaySky)],
    step_h: f64,
) -> Vec<f64> {
    let sun_site = SunSite {
        latitude_deg: site.latitude_deg,
        longitude_deg: site.longitude_deg,
        elevation_m: site.elevation_m,
    };
    let steps = (24.0 / step_h).round() as i64;
    (0..steps)
        .map(|k| k as f64 * step_h)
        .filter(|&h| {
            days.iter().any(|(date, _)| {
                let midnight = date.and_hms_opt(0, 0, 0).expect("midnight");
                let local = midnight + chrono::Duration::seconds((h * 3600.0).round() as i64);
                let utc = (local - chrono::Duration::seconds(i64::from(utc_offset_s))).and_utc();
                solar_position(utc, &sun_site, None).is_ok_and(|s| s.altitude_deg() > 5.0)
            })
        })
        .collect()
}

/// RADIANCE `glass` transmissivity for a normal-incidence transmittance τ: the relation in
/// the RADIANCE reference manual (`glass`): tn = (√(0.8402528435 + 0.0072522239 τ²) −
/// 0.9166530661) / 0.0036261119 / τ.
pub fn glass_transmissivity(transmittance: f64) -> f64 {
    let t = transmittance;
    ((0.840_252_843_5 + 0.007_252_223_9 * t * t).sqrt() - 0.916_653_066_1) / 0.003_626_111_9 / t
}

/// A box room: x across, y into the room from the façade at y = 0, z up; then turned so the
/// façade's outward normal (−y) faces `facade_azimuth_deg`.
fn draw_room(d: &mut Draw, facade_azimuth_deg: f64) -> BatteryRoom {
    let (w, depth, h) = (d.range(3.0, 8.0), d.range(4.0, 9.0), d.range(2.6, 3.5));
    let glazing_transmittance = d.range(0.6, 0.88);
    let (floor, wall, ceiling) = (d.range(0.2, 0.45), d.range(0.35, 0.7), d.range(0.6, 0.8));
    // The opening: 40-90 % of the width, from a sill of 0.7-1.0 m to 0.2-0.4 m under the
    // ceiling.
    let ww = w * d.range(0.4, 0.9);
    let (x0, x1) = ((w - ww) / 2.0, (w + ww) / 2.0);
    let (sill, head) = (d.range(0.7, 1.0), h - d.range(0.2, 0.4));
    // Turning the local −y onto the façade azimuth A: a rotation by π − A about z.
    let phi = std::f64::consts::PI - facade_azimuth_deg.to_radians();
    let turn = |p: DVec3| {
        DVec3::new(
            p.x * phi.cos() - p.y * phi.sin(),
            p.x * phi.sin() + p.y * phi.cos(),
            p.z,
        )
    };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "# Skylux battery room: {w:.3} x {depth:.3} x {h:.3} m, facade facing \
         {facade_azimuth_deg:.1} deg, glazing transmittance {glazing_transmittance:.3}\n"
    );
    for (name, rho) in [
        ("floor_mat", floor),
        ("wall_mat", wall),
        ("ceiling_mat", ceiling),
    ] {
        let _ = writeln!(
            t,
            "void plastic {name}\n0\n0\n5 {rho:.4} {rho:.4} {rho:.4} 0 0\n"
        );
    }
    let tn = glass_transmissivity(glazing_transmittance);
    let _ = writeln!(
        t,
        "void glass glazing_mat\n0\n0\n3 {tn:.6} {tn:.6} {tn:.6}\n"
    );
    let mut polygon = |material: &str, name: &str, corners: &[[f64; 3]]| {
        let _ = writeln!(t, "{material} polygon {name}\n0\n0\n{}", 3 * corners.len());
        for c in corners {
            let p = turn(DVec3::from_array(*c));
            let _ = writeln!(t, "\t{:.6} {:.6} {:.6}", p.x, p.y, p.z);
        }
        t.push('\n');
    };
    polygon(
        "floor_mat",
        "floor",
        &[[0., 0., 0.], [w, 0., 0.], [w, depth, 0.], [0., depth, 0.]],
    );
    polygon(
        "ceiling_mat",
        "ceiling",
        &[[0., 0., h], [0., depth, h], [w, depth, h], [w, 0., h]],
    );
    polygon(
        "wall_mat",
        "wall_left",
        &[[0., depth, 0.], [0., depth, h], [0., 0., h], [0., 0., 0.]],
    );
    polygon(
        "wall_mat",
        "wall_right",
        &[[w, 0., 0.], [w, 0., h], [w, depth, h], [w, depth, 0.]],
    );
    polygon(
        "wall_mat",
        "wall_back",
        &[
            [w, depth, 0.],
            [w, depth, h],
            [0., depth, h],
            [0., depth, 0.],
        ],
    );
    polygon(
        "wall_mat",
        "facade_below",
        &[[0., 0., 0.], [0., 0., sill], [w, 0., sill], [w, 0., 0.]],
    );
    polygon(
        "wall_mat",
        "facade_above",
        &[[0., 0., head], [0., 0., h], [w, 0., h], [w, 0., head]],
    );
    polygon(
        "wall_mat",
        "facade_left",
        &[
            [0., 0., sill],
            [0., 0., head],
            [x0, 0., head],
            [x0, 0., sill],
        ],
    );
    polygon(
        "wall_mat",
        "facade_right",
        &[[x1, 0., sill], [x1, 0., head], [w, 0., head], [w, 0., sill]],
    );
    polygon(
        "glazing_mat",
        "window",
        &[
            [x0, 0., sill],
            [x0, 0., head],
            [x1, 0., head],
            [x1, 0., sill],
        ],
    );
    // 4-8 sensors at 0.8 m, facing up: on the room's axis from 1 m behind the façade to
    // 0.8 m before the back wall, or on two such lines at a third and two thirds of the width.
    let n = 4 + d.below(5);
    let grid = n.is_multiple_of(2) && d.unit() < 0.5;
    let columns: Vec<f64> = if grid {
        vec![w / 3.0, 2.0 * w / 3.0]
    } else {
        vec![w / 2.0]
    };
    let rows = n / columns.len();
    let (y0, y1) = (1.0, depth - 0.8);
    let mut pts = String::new();
    for r in 0..rows {
        let y = y0 + (y1 - y0) * r as f64 / (rows - 1).max(1) as f64;
        for &x in &columns {
            let p = turn(DVec3::new(x, y, 0.8));
            let _ = writeln!(pts, "{:.4} {:.4} {:.4} 0 0 1", p.x, p.y, p.z);
        }
    }
    BatteryRoom {
        width_m: w,
        depth_m: depth,
        height_m: h,
        facade_azimuth_deg,
        glazing_transmittance,
        floor_reflectance: floor,
        wall_reflectance: wall,
        ceiling_reflectance: ceiling,
        scene_rad: t,
        sensors_pts: pts,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn glass_transmissivity_matches_the_reference_room() {
        // shared/scenes/test-module: Tn = 0.65 -> glass transmissivity 0.708456.
        assert!((glass_transmissivity(0.65) - 0.708456).abs() < 2e-6);
    }

    /// Every case of an effect seen only in the frames' sun shows the camera the sun.
    #[test]
    fn the_seed_18_battery_shows_the_sun_to_the_effects_seen_in_it() {
        let cases = battery_campaigns(120, 18);
        let needing: Vec<&BatteryCase> = cases
            .iter()
            .filter(|c| {
                c.effects.iter().any(|(name, _)| {
                    effect_range(name).is_some_and(|r| r.sky == SkyNeed::SunInView)
                })
            })
            .collect();
        assert!(needing.len() >= 20, "{} cases", needing.len());
        for c in needing {
            assert!(
                c.sun_in_view_captures() >= MIN_SUN_IN_VIEW,
                "#{} {}",
                c.index,
                c.class
            );
        }
        // Campaign #71 (a shutter overhead) was drawn with the sun out of the camera's field
        // all day (redrawn, so it is among the cases above); a case that needs no redraw is as
        // it was (#70).
        let dates =
            |i: usize| -> Vec<String> { cases[i].days.iter().map(|d| d.0.to_string()).collect() };
        assert_eq!(dates(70), ["2022-06-28", "2022-11-13"]);
    }

    /// Deterministic per seed, the buckets as specified, every draw within its range, and
    /// every room a scene and sensors the loader reads, its glazing facing the façade.
    #[test]
    fn battery_is_deterministic_ranged_and_loadable() {
        let a = battery_campaigns(26, 7);
        let b = battery_campaigns(26, 7);
        assert_eq!(a.len(), 26);
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(
                (&x.class, &x.effects, &x.room),
                (&y.class, &y.effects, &y.room)
            );
            assert_eq!((&x.days, &x.hours), (&y.days, &y.hours));
        }
        assert_ne!(battery_campaigns(26, 8)[0].room, a[0].room);
        // 26 = 2 × 12 + 2: two of each bucket, two left over.
        let count = |f: &dyn Fn(&BatteryCase) -> bool| a.iter().filter(|c| f(c)).count();
        assert!(count(&|c| c.class == "none") >= 2);
        assert!(count(&|c| c.effects.len() == 2) >= 2);
        for e in EFFECT_RANGES {
            assert!(count(&|c| c.class == e.name) >= 2, "{}", e.name);
        }
        let dir = tempfile::tempdir().unwrap();
        for c in &a {
            for (name, v) in &c.effects {
                let r = effect_range(name).unwrap();
                let m = if r.signed { v.abs() } else { *v };
                assert!((r.min..=r.max).contains(&m), "{name} = {v}");
            }
            if c.effects.len() == 2 {
                assert_ne!(c.effects[0].0, c.effects[1].0);
            }
            let kinds: Vec<DaySky> = c.days.iter().map(|d| d.1).collect();
            if c.class.contains("clock_offset") {
                assert_eq!(kinds, [DaySky::Partly, DaySky::Partly]);
            }
            if c.class.contains("spectral_mismatch") {
                assert_eq!(kinds[0], DaySky::Clear);
            }
            if c.effects
                .iter()
                .any(|(name, _)| effect_range(name).is_some_and(|r| r.sky == SkyNeed::SunInView))
            {
                assert!(
                    c.sun_in_view_captures() >= MIN_SUN_IN_VIEW,
                    "case {} ({}): the camera never sees the sun",
                    c.index,
                    c.class
                );
            }
            assert!((-45.0..=60.0).contains(&c.site.latitude_deg));
            assert!((-180.0..=180.0).contains(&c.site.longitude_deg));
            assert_eq!(
                c.utc_offset_s,
                (c.site.longitude_deg / 15.0).round() as i32 * 3600
            );
            let equator = if c.site.latitude_deg >= 0.0 {
                180.0
            } else {
                0.0
            };
            let off = (c.room.facade_azimuth_deg - equator + 540.0).rem_euclid(360.0) - 180.0;
            assert!(off.abs() <= 100.0);
            assert!((10.0..=25.0).contains(&c.camera_altitude_deg));
            assert!(!c.hours.is_empty());
            let r = &c.room;
            assert!((3.0..=8.0).contains(&r.width_m) && (4.0..=9.0).contains(&r.depth_m));
            assert!((2.6..=3.5).contains(&r.height_m));
            assert!((0.6..=0.88).contains(&r.glazing_transmittance));
            let room = dir.path().join(c.index.to_string());
            c.write_room(&room).unwrap();
            let scene = skylux_hps::scene::load(room.join("scene.rad")).unwrap();
            let sensors = skylux_hps::scene::load_sensors(room.join("sensors.pts")).unwrap();
            assert!((4..=8).contains(&sensors.len()));
            assert!(sensors.iter().all(|s| (s.position_m.z - 0.8).abs() < 1e-9));
            let world = skylux_hps::engine::World::new(&scene).unwrap();
            let glazing = skylux_hps::validation::glazing::Glazing::of_world(&world).unwrap();
            let n = glazing.primary().normal_out;
            let facing = (n.x.atan2(n.y).to_degrees() + 360.0) % 360.0;
            let diff = (facing - r.facade_azimuth_deg + 540.0).rem_euclid(360.0) - 180.0;
            assert!(
                diff.abs() < 1e-3,
                "glazing faces {facing}, façade {}",
                r.facade_azimuth_deg
            );
            let spec = c.spec(room).unwrap();
            assert_eq!(spec.days.len(), 2);
        }
    }
}
