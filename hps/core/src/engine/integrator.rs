//! Path tracing of the irradiance at a sensor, with the meaning of rtrace's controls.
//!
//! One sample is one path from the sensor: next-event estimation towards every distant
//! `light` (the sun) at each diffuse vertex and at the sensor itself, and a cosine-weighted
//! continuation whose rays collect the sky and ground `glow`s and local emitters they hit.
//! Rays that hit a distant `light` collect nothing, as in RADIANCE (source.c
//! `badcomponent`), since next-event estimation already counts it. `-ab` bounds the number
//! of diffuse (ambient) bounces including the one from the sensor; specular events (glass,
//! mirror, smooth or Gaussian highlights) do not count against it, as in RADIANCE, and are
//! bounded by [`Settings::max_specular_events`] (rtrace's `-lr`). With Russian roulette
//! (paths from sensors and cameras, [`Settings::russian_roulette`]), a path past its third
//! diffuse bounce continues with probability min(1, throughput /
//! `RUSSIAN_ROULETTE_THROUGHPUT`) and is reweighted by its inverse (Arvo & Kirk 1990):
//! unbiased for the given limits, and paths whose remaining contribution is small stop
//! early. The daylight-coefficient paths ([`escape_sample`]) run to their limits.
//!
//! Sky light is found three ways at every vertex that may scatter diffusely (the sensor
//! itself and each diffuse vertex within `-ab`): by the sampled continuation leaving the
//! scene, by a direction towards a random point on a window ([`super::portal`]), and by a
//! direction drawn from the sky's own brightness ([`super::sky_sampling`]). The three are
//! combined by multiple importance sampling with the balance heuristic (Veach & Guibas,
//! "Optimally combining sampling techniques for Monte Carlo rendering", SIGGRAPH 1995): a
//! sample from any of them counts f L T / (p_bsdf + p_portal + p_sky), so every light path is
//! counted once in expectation whichever strategies can produce it, and paths only the
//! continuation can produce (sky seen after a mirror, a reflection in the glass, a diffuse
//! vertex past `-ab`) still count in full.
//!
//! The sun's patch (where the sun shines in through a window) is found the same way: at the
//! sensor and at every diffuse vertex, a point on a portal is followed along the sun's
//! direction into the room to the first opaque surface, connected to the vertex, and the
//! sun's next-event estimate there is carried back; the vertex's own diffuse sample that
//! reaches the same point weights its sun estimate there by the balance heuristic in area
//! measure ([`Settings::sun_portal_sampling`]).
//!
//! Light a `BSDF` window passes reaches no next-event strategy; at the sensors and at the
//! Lambertian vertices with such a window in front, the continuation mixes directions towards
//! the windows into the cosine lobe (`Continuation`, [`Settings::bsdf_window_sampling`]), and
//! a sensor also directions from its table of the light the windows send it
//! ([`super::window_sun`]).

use super::error::EngineError;
use super::material::{DiffuseLobe, Interaction, Scatter, Shading};
use super::portal::Portals;
use super::ray::Ray;
use super::rng::Rng;
use super::sampling::{cosine_direction, sample_cone};
use super::sky::{DistantEmitter, DistantKind};
use super::sky_sampling::SkyDistribution;
use super::virtual_sources::mirrored_lights;
use super::window_sun::SensorWindowLight;
use super::world::{Hit, World};
use glam::DVec3;
use std::f64::consts::PI;

/// Diffuse bounces a path always makes before Russian roulette may end it.
const RUSSIAN_ROULETTE_AFTER: u32 = 3;
/// Path throughput below which Russian roulette may end a path: it continues with
/// probability min(1, throughput / this), as rtrace's `-lw` sets the weight below which its
/// rays play roulette. Below 1, so that a path that survives a deep bounce does not carry
/// many times its light, which dominated the variance (BENCHMARKS.md).
const RUSSIAN_ROULETTE_THROUGHPUT: f64 = 0.25;
/// Diffuse bounces after which more change a room's illuminance by less than the loop can
/// see: a room of reflectance 0.8 keeps 0.8⁸ ≈ 17 % of its light past 8 bounces, and on the
/// reference room 12 bounces read up to 6 % more at the back than 5 (`-ab 5` truncates;
/// sim/tests/radiance_truth.rs). With Russian roulette past the third bounce most paths end
/// long before, so the cost over 5 is small (BENCHMARKS.md, the loop). The loop's model, the
/// daemon's and the simulated worlds' truths all use it.
pub const CONVERGED_AMBIENT_BOUNCES: u32 = 12;

/// Controls, named after rtrace's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// `-ab`: most diffuse bounces per path (0: direct sun only).
    pub ambient_bounces: u32,
    /// `-ad`: paths per sensor.
    pub samples_per_sensor: u32,
    /// Seed of every random stream; the same seed gives the same result on any thread count.
    pub seed: u64,
    /// Like `-lr`: most specular events (glass, mirror, highlights) per path.
    pub max_specular_events: u32,
    /// Next-event estimation of the sky through the world's portals (windows), combined with
    /// the sampled continuation by multiple importance sampling. Unbiased either way; on, it
    /// cuts the variance of a room lit through windows many times.
    pub portal_sampling: bool,
    /// Next-event estimation of the sky by its brightness (the circumsolar region), combined
    /// likewise.
    pub sky_sampling: bool,
    /// Russian roulette past the third diffuse bounce (unbiased; most paths of a room with
    /// reflectances near 0.5 then stop after three or four bounces instead of `-ab`).
    pub russian_roulette: bool,
    /// Next-event estimation of the sun's patch: points where the sun shines in through a
    /// portal, sampled by projecting portal points along the sun's direction and connected to
    /// each diffuse vertex, combined with the continuation by multiple importance sampling.
    pub sun_portal_sampling: bool,
    /// Stratified numbers for the first decisions of each sensor path ([`super::qmc`]);
    /// unbiased, and the standard error then comes from independent replicates
    /// (`engine::illuminance`).
    pub stratified: bool,
    /// Path reuse across sensors (`engine::illuminance`): the first vertex of each sensor's
    /// path, when it is a Lambertian surface, also lights the other sensors of its group
    /// that see it, weighted by the balance heuristic over the group's sensors. Unbiased.
    pub path_reuse: bool,
    /// At the sensors and at Lambertian vertices with a `BSDF` window in front, continuations
    /// mixed with directions towards the windows (`Continuation`), and at the sensors with
    /// directions from a table of the light the windows send them (`engine::window_sun`).
    /// Unbiased; on, the light a window of blinds or a shade passes is found by many more
    /// paths.
    pub bsdf_window_sampling: bool,
    /// Next-event estimation of the sunlit surfaces past the portals (the ground, a façade
    /// or an overhang outside a window): a sky strategy's direction that meets an opaque
    /// surface beyond a portal carries the sun's light reflected there, combined with the
    /// continuation that reaches the same surface by multiple importance sampling. Unbiased;
    /// on, the sunlit ground that a room sees only through its windows no longer reaches it
    /// by rare continuations of great weight.
    pub sunlit_outside_sampling: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            ambient_bounces: 5,
            samples_per_sensor: 1024,
            seed: 1,
            max_specular_events: 16,
            portal_sampling: true,
            sky_sampling: true,
            russian_roulette: true,
            sun_portal_sampling: true,
            stratified: true,
            path_reuse: true,
            bsdf_window_sampling: true,
            sunlit_outside_sampling: true,
        }
    }
}

impl Settings {
    pub fn validate(&self) -> Result<(), EngineError> {
        if self.samples_per_sensor == 0 {
            return Err(EngineError::Setting {
                name: "samples per sensor (-ad)",
                value: "0".into(),
                expected: "at least 1",
            });
        }
        Ok(())
    }
}

/// One estimate of the irradiance (W/m² per RGB channel) at `position_m` on a surface facing
/// unit `normal`, as rtrace -I defines it: ∫ L(ω) cos θ dω over the hemisphere.
pub fn irradiance_sample(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    settings: &Settings,
    rng: &mut Rng,
) -> DVec3 {
    sensor_path(world, position_m, normal, settings, rng, SensorPath::WHOLE).0
}

/// The two parts of a surface point's irradiance that a renderer treats apart
/// ([`super::render`]): the sun's and its mirror images' direct light, sharp-edged, and all
/// the rest (sky, ground and interreflections), smooth over a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IrradiancePart {
    DirectSun,
    Rest,
}

/// One estimate of `part` of the irradiance at `position_m` on primitive `from` (excluded
/// from its own rays), facing unit `normal`: the two parts' estimates add up to an
/// [`irradiance_sample`] there.
pub fn surface_irradiance_sample(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    from: Option<u32>,
    part: IrradiancePart,
    settings: &Settings,
    rng: &mut Rng,
) -> DVec3 {
    let what = SensorPath {
        table: None,
        from,
        direct: part == IrradiancePart::DirectSun,
        rest: part == IrradiancePart::Rest,
        shared: false,
    };
    sensor_path(world, position_m, normal, settings, rng, what).0
}

/// What one sensor path estimates.
#[derive(Clone, Copy, Debug)]
struct SensorPath<'a> {
    /// The sensor's table of the `BSDF` windows' light, mixed into its first direction.
    table: Option<&'a SensorWindowLight>,
    /// The primitive the point lies on, which its rays must not hit again.
    from: Option<u32>,
    /// The distant `light`s' direct light (and their mirror images).
    direct: bool,
    /// Everything else.
    rest: bool,
    /// Path reuse: the first vertex is handed back instead of added.
    shared: bool,
}

impl SensorPath<'_> {
    const WHOLE: SensorPath<'static> = SensorPath {
        table: None,
        from: None,
        direct: true,
        rest: true,
        shared: false,
    };
}

/// The first vertex of a sensor's path when other sensors may use it (path reuse,
/// `engine::illuminance`): a Lambertian surface the sensor sees directly, and the path's
/// estimate of the radiance it sends back, the same towards every viewer on that side.
#[derive(Clone, Copy, Debug)]
pub struct SharedVertex {
    pub position_m: DVec3,
    /// The surface's geometric normal there (either side).
    pub normal: DVec3,
    pub primitive: u32,
    pub radiance_rgb: DVec3,
}

/// [`irradiance_sample`] split for path reuse: the irradiance estimate less what arrives from
/// a Lambertian first vertex, and that vertex with its radiance estimate. Without the
/// sun-patch strategy at the sensor (the shared vertex's own sun estimate then counts in
/// full), so the vertex's estimate does not depend on which sensor found it.
pub fn irradiance_sample_shared(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    settings: &Settings,
    rng: &mut Rng,
) -> (DVec3, Option<SharedVertex>) {
    irradiance_sample_shared_with(world, position_m, normal, None, settings, rng)
}

/// [`irradiance_sample_shared`] for a sensor whose first directions also follow its `table`
/// of the `BSDF` windows' light ([`SensorWindowLight`]).
pub fn irradiance_sample_shared_with(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    table: Option<&SensorWindowLight>,
    settings: &Settings,
    rng: &mut Rng,
) -> (DVec3, Option<SharedVertex>) {
    let what = SensorPath {
        shared: true,
        table,
        ..SensorPath::WHOLE
    };
    sensor_path(world, position_m, normal, settings, rng, what)
}

/// [`irradiance_sample`] for a sensor whose first directions also follow its `table` of the
/// `BSDF` windows' light ([`SensorWindowLight`]).
pub fn irradiance_sample_with(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    table: Option<&SensorWindowLight>,
    settings: &Settings,
    rng: &mut Rng,
) -> DVec3 {
    let what = SensorPath {
        table,
        ..SensorPath::WHOLE
    };
    sensor_path(world, position_m, normal, settings, rng, what).0
}

fn sensor_path(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    settings: &Settings,
    rng: &mut Rng,
    what: SensorPath<'_>,
) -> (DVec3, Option<SharedVertex>) {
    let SensorPath { from, shared, .. } = what;
    let mut e = DVec3::ZERO;
    if what.direct {
        // Direct: E = L Ω cos θ averaged over the disc (sampled uniformly in solid angle).
        for source in world.distant_sources() {
            if source.kind != DistantKind::Light {
                continue;
            }
            let l = sample_cone(source, rng);
            let cos = l.dot(normal);
            if cos > 0.0 {
                e += source.radiance(l)
                    * (source.solid_angle_sr * cos)
                    * world.source_transmission(position_m, from, l);
            }
        }
        // The sun via plane mirrors (virtual sources).
        e += mirrored_lights(world, position_m, from, rng, &mut |l, sr| {
            DVec3::splat(sr * l.dot(normal).max(0.0))
        });
    }
    if settings.ambient_bounces == 0 || !what.rest {
        return (e, None);
    }
    let nee = SkyNee::new(world, settings);
    let continuation = Continuation::of_sensor(world, settings, position_m, normal, what.table);
    if let Some(nee) = &nee {
        // A shared first vertex's estimate must not depend on the sensor that found it, so
        // neither strategy that the vertex's own sun estimate is weighted against acts here.
        e += nee.estimate(world, position_m, from, &continuation, !shared, rng);
        if !shared {
            e += nee.sun_estimate(world, position_m, from, &continuation, rng);
        }
    }
    // Indirect: E = L(ω) cos θ / p(ω) per sample (π L(ω) for the cosine lobe alone).
    let Some((d, weight, pdf_sr)) = continuation.sample_direction(rng) else {
        return (e, None);
    };
    let last = LastDiffuse {
        position_m,
        pdf_sr,
        sun_patch_sampled: !shared,
        outside_sampled: !shared,
        survival: 1.0,
    };
    let ray = Ray::new(position_m, d);
    let first = if shared {
        world
            .intersect(&ray, from)
            .filter(|h| world.material(h.primitive).is_lambertian())
    } else {
        None
    };
    let l = trace(
        world,
        ray,
        from,
        1,
        settings,
        rng,
        &mut |t, ray| t * world.escape_radiance(ray.direction),
        nee.as_ref(),
        Some(last),
        settings.russian_roulette,
        false,
    );
    match first {
        Some(h) => (
            e,
            Some(SharedVertex {
                position_m: ray.at(h.t_m),
                normal: h.normal,
                primitive: h.primitive,
                radiance_rgb: l,
            }),
        ),
        None => (e + weight * l, None),
    }
}

/// The density with which a sensor at `position_m` facing unit `normal` chooses its first
/// direction `d` (per steradian): the cosine lobe's, or its mixture with the `BSDF` windows
/// in front of it and its `table` ([`Continuation`]). What path reuse weights a shared
/// vertex by.
pub fn sensor_direction_pdf(
    world: &World,
    settings: &Settings,
    position_m: DVec3,
    normal: DVec3,
    table: Option<&SensorWindowLight>,
    d: DVec3,
) -> f64 {
    SensorDirections::new(world, settings, position_m, normal, table).pdf_sr(d)
}

/// How a sensor chooses its first direction, set up once for many densities
/// ([`sensor_direction_pdf`]).
#[derive(Clone, Copy)]
pub struct SensorDirections<'a>(Continuation<'a>);

impl<'a> SensorDirections<'a> {
    pub fn new(
        world: &'a World,
        settings: &Settings,
        position_m: DVec3,
        normal: DVec3,
        table: Option<&'a SensorWindowLight>,
    ) -> Self {
        Self(Continuation::of_sensor(
            world, settings, position_m, normal, table,
        ))
    }

    /// The density per steradian of unit `d`.
    pub fn pdf_sr(&self, d: DVec3) -> f64 {
        self.0.eval(d).1
    }
}

/// Where the path's last diffuse scattering happened and the density (per steradian) with
/// which it chose the current direction: what the weight of an escape found by the
/// continuation needs.
#[derive(Clone, Copy, Debug)]
struct LastDiffuse {
    position_m: DVec3,
    pdf_sr: f64,
    /// The vertex also sampled the sun's patch ([`SkyNee::sun_estimate`]), so the next
    /// vertex's sun estimate shares the light with it by multiple importance sampling.
    sun_patch_sampled: bool,
    /// The vertex also sampled the sunlit surfaces past the portals
    /// ([`SkyNee::sunlit_outside`]): the sun estimate of a surface the path then meets beyond
    /// a portal, through clear surfaces only, shares the light with it.
    outside_sampled: bool,
    /// The Russian-roulette survival of the continuation (1 without roulette).
    survival: f64,
}

/// Share of a Lambertian vertex's continuations sent towards the `BSDF` windows' area, and
/// of a sensor's when it has no [`SensorWindowLight`]. On the LBNL tutorial room with its
/// blinds the RMS error at equal paths was 1.90 % at 0.5, 1.68 % at 0.3 and 0.2, 1.75 % at
/// 0.1 and 5.0 % at 0.7 (2,048 paths, six seeds; docs/bsdf.md): deep in a room most of a
/// vertex's light still comes off the room's other surfaces, which the cosine lobe finds.
const WINDOW_SHARE: f64 = 0.3;
/// Shares of a sensor's first directions sent towards the windows' area and drawn from its
/// [`SensorWindowLight`] (the rest from its cosine lobe), when it has one. On the tutorial
/// room the RMS error at equal paths fell from 1.68 % to 1.33-1.44 % with them; 0.1 and
/// 0.3 did better than 0.05/0.2, 0.15/0.25, 0.2/0.3, 0.1/0.4 and 0.05/0.5 (docs/bsdf.md).
const SENSOR_WINDOW_SHARE: f64 = 0.1;
const SENSOR_TABLE_SHARE: f64 = 0.3;

/// How a diffuse vertex chooses its continuation: by its lobe, or, at a Lambertian vertex of
/// a room with `BSDF` windows, by a mixture of the lobe and directions towards a point drawn
/// uniformly over the windows (defensive mixture sampling, Hesterberg 1995; Veach 1997
/// §9.2.4 for its one-sample balance heuristic). A window of blinds or a shade passes the
/// sky and the sun by its BSDF, which no next-event strategy of the room's vertices can
/// sample, so without this only the continuation that happens to hit the window finds that
/// light. A sensor also mixes in the directions of its table of the windows' light
/// ([`SensorWindowLight`]). Every weight that needs the continuation's density (the sky's
/// and the sun patch's next-event estimates here, an escape or sun estimate it finds, path
/// reuse's densities of the sensors' first directions) takes the mixture's.
#[derive(Clone, Copy)]
struct Continuation<'a> {
    lobe: DiffuseLobe,
    /// The vertex.
    at: DVec3,
    /// The windows mixed in (None: the lobe alone).
    windows: Option<&'a Portals>,
    /// The path throughput before the bounce, when Russian roulette will act after it.
    roulette_throughput: Option<DVec3>,
    /// Share of the directions towards the windows' area (with `windows`).
    window_share: f64,
    /// A sensor's table of the windows' light, and the share of directions drawn from it
    /// (0 without a table).
    table: Option<&'a SensorWindowLight>,
    table_share: f64,
}

impl<'a> Continuation<'a> {
    /// A sensor's: its cosine lobe, mixed with the `BSDF` windows in front of it and with its
    /// `table` of their light; no roulette.
    fn of_sensor(
        world: &'a World,
        settings: &Settings,
        at: DVec3,
        normal: DVec3,
        table: Option<&'a SensorWindowLight>,
    ) -> Self {
        let windows = world.bsdf_windows();
        let mix = settings.bsdf_window_sampling && windows.any_in_front(at, normal);
        let table = table.filter(|_| mix);
        let (window_share, table_share) = match table {
            Some(_) => (SENSOR_WINDOW_SHARE, SENSOR_TABLE_SHARE),
            None => (WINDOW_SHARE, 0.0),
        };
        Self {
            lobe: DiffuseLobe::sensor(normal),
            at,
            windows: mix.then_some(windows),
            roulette_throughput: None,
            window_share,
            table,
            table_share,
        }
    }

    /// (f |cos θ|, the density with which the continuation chooses unit `d`).
    fn eval(&self, d: DVec3) -> (DVec3, f64) {
        let (f, pdf) = self.lobe.eval(d);
        let Some(w) = self.windows else {
            return (f, pdf);
        };
        let table_pdf = self.table.map_or(0.0, |t| t.pdf_sr(d));
        let lobe_share = 1.0 - self.window_share - self.table_share;
        (
            f,
            lobe_share * pdf + self.window_share * w.pdf(self.at, d) + self.table_share * table_pdf,
        )
    }

    /// The Russian-roulette survival of the continuation in unit direction `d` ([`Tracer::bounce`]).
    fn survival(&self, d: DVec3) -> f64 {
        let Some(throughput) = self.roulette_throughput else {
            return 1.0;
        };
        let (f, pdf) = self.eval(d);
        if (pdf).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return 1.0;
        }
        ((throughput * f / pdf).max_element() / RUSSIAN_ROULETTE_THROUGHPUT).min(1.0)
    }

    /// A direction, its weight f |cos θ| / p and p: from the lobe's front (a Lambertian
    /// reflector, a sensor) alone or from the mixture; None when a window's direction lies
    /// behind the surface or in its plane, or a table's draw fails.
    fn sample_direction(&self, rng: &mut Rng) -> Option<(DVec3, DVec3, f64)> {
        let Some(windows) = self.windows else {
            // ρ/π |cos θ| over front_probability |cos θ| / π, cancelled exactly.
            let d = cosine_direction(self.lobe.normal, rng);
            let pdf_sr = self.eval(d).1;
            return Some((
                d,
                self.lobe.front_rgb * (PI / self.lobe.front_probability),
                pdf_sr,
            ));
        };
        let u = rng.uniform();
        let d = if u < self.window_share {
            windows.sample(self.at, rng)?.0
        } else if u < self.window_share + self.table_share {
            self.table?.sample(rng)?
        } else {
            cosine_direction(self.lobe.normal, rng)
        };
        let (f, pdf) = self.eval(d);
        (pdf > 0.0 && pdf.is_finite() && f != DVec3::ZERO).then(|| (d, f / pdf, pdf))
    }
}

/// Next-event estimation of the light beyond the scene (sky and ground `glow`s, environment)
/// through portals and by the sky's brightness.
struct SkyNee<'a> {
    portals: Option<&'a Portals>,
    sky: Option<&'a SkyDistribution>,
    /// Portals through which sunlit points are sampled (see [`SkyNee::sun_estimate`]).
    sun_portals: Option<&'a Portals>,
    /// The sky strategies' directions also collect the sun reflected by the opaque surface
    /// they meet beyond a portal ([`SkyNee::sunlit_outside`]).
    sunlit_outside: bool,
}

impl<'a> SkyNee<'a> {
    /// The strategies `settings` asks for that the world supports; None if none applies or
    /// nothing beyond the scene is bright.
    fn new(world: &'a World, settings: &Settings) -> Option<Self> {
        let bright = world.has_escape_radiance();
        let has_light = world
            .distant_sources()
            .iter()
            .any(|s| s.kind == DistantKind::Light);
        // Sampled for the sky, or for the sunlit surfaces past them.
        let sunlit_outside = has_light && settings.sunlit_outside_sampling;
        let portals =
            ((bright || sunlit_outside) && settings.portal_sampling && !world.portals().is_empty())
                .then(|| world.portals());
        let sky = if bright && settings.sky_sampling {
            world.sky_distribution()
        } else {
            None
        };
        let sun_portals =
            (has_light && settings.sun_portal_sampling && !world.portals().is_empty())
                .then(|| world.portals());
        let sunlit_outside = sunlit_outside && portals.is_some();
        (portals.is_some() || sky.is_some() || sun_portals.is_some()).then_some(Self {
            portals,
            sky,
            sun_portals,
            sunlit_outside,
        })
    }

    /// Distance from `y` along unit `dir` to the first surface that is neither glass nor
    /// invisible (infinite if none).
    fn opaque_distance(world: &World, y: DVec3, from: Option<u32>, dir: DVec3) -> f64 {
        world
            .first_opaque(&Ray::new(y, dir), from)
            .map_or(f64::INFINITY, |h| h.t_m)
    }

    /// Area density at the point `y` (primitive `primitive`, geometric normal `n_y`) of the
    /// sun-patch strategy for the sun in unit direction `s`.
    fn sun_patch_pdf(&self, world: &World, y: DVec3, n_y: DVec3, primitive: u32, s: DVec3) -> f64 {
        let Some(portals) = self.sun_portals else {
            return 0.0;
        };
        let t_max = Self::opaque_distance(world, y, Some(primitive), s);
        portals.projected_area_pdf(y, n_y, s, t_max)
    }

    /// The sun reflected once more, by way of its patch: for each distant `light`, a point
    /// on a portal is followed along the sun's direction into the room to the first opaque
    /// surface y (where the sun may shine through the window), y is connected to the vertex
    /// `x`, and the sun's next-event estimate at y is carried back. Combined by the balance
    /// heuristic with the path that reaches y by the vertex's own continuation (density
    /// q p(ω) |cos θ_y| / d², q that continuation's Russian-roulette survival), whose sun
    /// estimate at y [`trace`] weights to match.
    fn sun_estimate(
        &self,
        world: &World,
        x: DVec3,
        from: Option<u32>,
        continuation: &Continuation,
        rng: &mut Rng,
    ) -> DVec3 {
        let Some(portals) = self.sun_portals else {
            return DVec3::ZERO;
        };
        let mut sum = DVec3::ZERO;
        for source in world.distant_sources() {
            if source.kind != DistantKind::Light {
                continue;
            }
            let s = source.direction;
            let Some((p, triangle)) = portals.sample_point(rng) else {
                continue;
            };
            // Into the room from the portal point, through glass and invisible surfaces.
            let ray = Ray::new(p - s * 1e-7, -s);
            let found = world.first_opaque(&ray, None).and_then(|hit| {
                let m = world.material(hit.primitive);
                m.is_shaded_somewhere()
                    .then(|| (ray.at(hit.t_m), hit.normal, hit.primitive, m))
            });
            // The sun-cone sample is drawn whatever happens, so the stream stays aligned.
            let l = sample_cone(source, rng);
            let Some((y, n_y, prim_y, m)) = found else {
                continue;
            };
            let to = y - x;
            let d2 = to.length_squared();
            if (d2).partial_cmp(&1e-12) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            let dist = d2.sqrt();
            let w = to / dist;
            let (f, pdf_lobe) = continuation.eval(w);
            if f == DVec3::ZERO {
                continue;
            }
            let cos_y = n_y.dot(w).abs();
            if (cos_y).partial_cmp(&1e-9) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            let flat_y = world.is_flat(prim_y);
            let hit_y = super::material::HitPoint {
                point_m: y,
                direction: w,
                normal: n_y,
                distance_m: dist,
                flat: flat_y,
            };
            let (m_y, shading_normal) = m.at_hit(&hit_y, rng);
            let Some(shading) = m_y.shading(w, shading_normal, flat_y) else {
                continue;
            };
            let c = shading.source_coefficient(l, source.solid_angle_sr);
            if c == DVec3::ZERO || !brighter_than_zero(c * source.radiance(l)) {
                continue;
            }
            // x must see y directly.
            if world.blocked_within(&Ray::new(x, w), from, dist * (1.0 - 1e-6)) {
                continue;
            }
            // Only a point whose way back to the portal counts in the density (see
            // `Portals::projected_area_pdf`).
            let t_max = Self::opaque_distance(world, y, Some(prim_y), s);
            if !portals.projection_crosses(triangle, y, s, t_max) {
                continue;
            }
            let t = world.source_transmission(shading.origin_towards(y, l), Some(prim_y), l);
            if t == DVec3::ZERO {
                continue;
            }
            let p_a = continuation.survival(w) * pdf_lobe * cos_y / d2;
            let p_b = portals.projected_area_pdf(y, n_y, s, t_max);
            // Seen through an opening, y is also the sunlit outside's (area measure).
            let p_c = self.outside_pdf_sr(x, w, dist) * cos_y / d2;
            let total = p_a + p_b + p_c;
            if (total).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            sum += f * (cos_y / d2) * c * source.radiance(l) * t / total;
        }
        sum
    }

    /// Density of the next-event strategies for unit `d` from `x`. With portals, the sky
    /// strategy keeps only directions through a portal (a sample that misses them is
    /// dropped before any ray is traced), so its density is the sky's where a portal is
    /// crossed and 0 elsewhere; directions outside the portals are then left entirely to the
    /// continuation, which keeps the estimate unbiased when light also enters elsewhere.
    fn pdf_sr(&self, x: DVec3, d: DVec3) -> f64 {
        self.pdf_sr_given(self.portals.map(|p| p.pdf(x, d)), d)
    }

    /// [`SkyNee::pdf_sr`] with the portals' density for `d` already known (`portal_pdf`,
    /// None without portals).
    fn pdf_sr_given(&self, portal_pdf: Option<f64>, d: DVec3) -> f64 {
        match (portal_pdf, self.sky) {
            (Some(pp), Some(s)) => {
                if pp > 0.0 {
                    pp + s.pdf(d)
                } else {
                    0.0
                }
            }
            (Some(pp), None) => pp,
            (None, Some(s)) => s.pdf(d),
            (None, None) => 0.0,
        }
    }

    /// Balance-heuristic weight of an escape in unit direction `d` found by the continuation
    /// sampled at `last`.
    fn continuation_weight(&self, last: &LastDiffuse, d: DVec3) -> f64 {
        let other = self.pdf_sr(last.position_m, d);
        if other > 0.0 {
            last.pdf_sr / (last.pdf_sr + other)
        } else {
            1.0
        }
    }

    /// One sample from each strategy at `x` (leaving surface `from`), for the diffuse `lobe`:
    /// Σ f |cos| L T / (p_lobe + p_portal + p_sky), the reflected radiance (or irradiance for
    /// a sensor) they estimate; with `outside`, also the sunlit surfaces past the portals
    /// their directions meet ([`SkyNee::sunlit_outside`]).
    fn estimate(
        &self,
        world: &World,
        x: DVec3,
        from: Option<u32>,
        lobe: &Continuation,
        outside: bool,
        rng: &mut Rng,
    ) -> DVec3 {
        let outside = outside && self.sunlit_outside;
        let mut sum = DVec3::ZERO;
        if let Some(portals) = self.portals {
            if let Some((d, pp)) = portals.sample(x, rng) {
                sum += self.one(world, x, from, lobe, d, Some(pp), outside, rng);
            }
        }
        if let Some(sky) = self.sky {
            let (d, _) = sky.sample(rng);
            let pp = self.portals.map(|p| p.pdf(x, d));
            if pp.is_none_or(|pp| pp > 0.0) {
                sum += self.one(world, x, from, lobe, d, pp, outside, rng);
            }
        }
        sum
    }

    #[allow(clippy::too_many_arguments)]
    fn one(
        &self,
        world: &World,
        x: DVec3,
        from: Option<u32>,
        lobe: &Continuation,
        d: DVec3,
        portal_pdf: Option<f64>,
        outside: bool,
        rng: &mut Rng,
    ) -> DVec3 {
        let (f, pdf_lobe) = lobe.eval(d);
        if f == DVec3::ZERO {
            return DVec3::ZERO;
        }
        let l = world.escape_radiance(d);
        if l == DVec3::ZERO && !outside {
            return DVec3::ZERO;
        }
        let p_nee = self.pdf_sr_given(portal_pdf, d);
        let denominator = pdf_lobe + p_nee;
        if (denominator).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return DVec3::ZERO;
        }
        let shadow = world.transmission_within(x, from, d, f64::INFINITY);
        if shadow.transmission == DVec3::ZERO {
            return if outside {
                self.sunlit_outside(world, x, from, lobe, d, p_nee, shadow.blocked_at_m, rng)
            } else {
                DVec3::ZERO
            };
        }
        f * l * shadow.transmission / denominator
    }

    /// Density (per steradian) of the sky strategies for unit `d` from `x` when the opaque
    /// surface `dist` away along it lies past a portal, as [`SkyNee::sunlit_outside`] counts
    /// it; 0 otherwise (or when that strategy is off).
    fn outside_pdf_sr(&self, x: DVec3, d: DVec3, dist: f64) -> f64 {
        let Some(portals) = self.portals.filter(|_| self.sunlit_outside) else {
            return 0.0;
        };
        let (pp, first) = portals.pdf_and_first_crossing(x, d);
        if pp > 0.0 && lies_beyond(first, dist) {
            self.pdf_sr_given(Some(pp), d)
        } else {
            0.0
        }
    }

    /// The sun reflected towards `x` by the opaque surface y that unit `d` (a sky strategy's
    /// direction, density `p_nee` per steradian, whose shadow ray was found blocked
    /// `blocked_at_m` away) meets
    /// past a portal, through the glass on the way: the ground, a façade, an overhang
    /// outside. Combined by the balance heuristic with the continuation that reaches y
    /// through clear surfaces (its density q p(ω), q its Russian-roulette survival), whose
    /// sun estimate at y [`Tracer::sun`] weights to match, and, where nothing lies between x
    /// and y (an opening), with the sun-patch strategy's density at y.
    #[allow(clippy::too_many_arguments)]
    fn sunlit_outside(
        &self,
        world: &World,
        x: DVec3,
        from: Option<u32>,
        lobe: &Continuation,
        d: DVec3,
        p_nee: f64,
        blocked_at_m: f64,
        rng: &mut Rng,
    ) -> DVec3 {
        let Some(portals) = self.portals else {
            return DVec3::ZERO;
        };
        // Blocked before the portals: nothing past them is seen (the common case deep in a
        // room, settled without another ray).
        let (_, first) = portals.pdf_and_first_crossing(x, d);
        if !lies_beyond(first, blocked_at_m) {
            return DVec3::ZERO;
        }
        let ray = Ray::new(x, d);
        let Some(hit) = world.first_opaque(&ray, from) else {
            return DVec3::ZERO;
        };
        let cos_y = hit.normal.dot(d).abs();
        let material = world.material(hit.primitive);
        if !lies_beyond(first, hit.t_m) || cos_y <= 1e-9 || !material.is_shaded_somewhere() {
            return DVec3::ZERO;
        }
        let y = ray.at(hit.t_m);
        let flat = world.is_flat(hit.primitive);
        let (m_y, shading_normal) = material.at_hit(&hit.as_seen(y, d, flat), rng);
        let Some(shading) = m_y.shading(d, shading_normal, flat) else {
            return DVec3::ZERO;
        };
        let (f, pdf_lobe) = lobe.eval(d);
        let p_continuation = lobe.survival(d) * pdf_lobe;
        let mut clear: Option<(DVec3, bool)> = None;
        let mut sum = DVec3::ZERO;
        for source in world.distant_sources() {
            if source.kind != DistantKind::Light {
                continue;
            }
            let Some(light) = light_at(world, &shading, y, Some(hit.primitive), source, rng) else {
                continue;
            };
            // The glass between x and y, once.
            let (t_clear, crossed) = *clear.get_or_insert_with(|| {
                let s = world.transmission_within(x, from, d, hit.t_m * (1.0 - 1e-6));
                (s.transmission, s.crossed)
            });
            if t_clear == DVec3::ZERO {
                return sum;
            }
            // Nothing between x and y: the sun-patch strategy may reach y too.
            let p_patch_sr = if crossed {
                0.0
            } else {
                self.sun_patch_pdf(world, y, hit.normal, hit.primitive, source.direction)
                    * hit.t_m
                    * hit.t_m
                    / cos_y
            };
            let total = p_continuation + p_nee + p_patch_sr;
            if (total).partial_cmp(&0.0) == Some(std::cmp::Ordering::Greater) {
                sum += f * t_clear * light / total;
            }
        }
        sum
    }
}

/// Whether the surface `dist` away along a line lies past the portal crossed `first_crossing`
/// away: what [`SkyNee::sunlit_outside`] counts and every weight against it tests alike. The
/// margin keeps a portal in the plane of a surface (an opening's cell over the wall around the
/// hole) from counting by rounding on one side and not on the other.
fn lies_beyond(first_crossing: f64, dist: f64) -> bool {
    first_crossing < dist * (1.0 - 1e-6) - 1e-6
}

/// One path from a sensor, as [`irradiance_sample`] traces it, with no distant `light` and
/// each escape handed to `escape(weight, direction)` instead of being looked up: the weight
/// is the escaping ray's contribution to the irradiance per unit radiance along it (π times
/// the path throughput, per RGB channel). Daylight coefficients are built on this.
pub fn escape_sample(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    settings: &Settings,
    rng: &mut Rng,
    escape: &mut dyn FnMut(DVec3, DVec3),
) {
    escape_ray_sample(world, position_m, normal, settings, rng, &mut |w, ray| {
        escape(w, ray.direction)
    });
}

/// [`escape_sample`] handing over the escaping ray itself (where it leaves from, too): the
/// view matrix keeps only the escapes through the window.
pub fn escape_ray_sample(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    settings: &Settings,
    rng: &mut Rng,
    escape: &mut dyn FnMut(DVec3, &Ray),
) {
    if settings.ambient_bounces == 0 {
        return;
    }
    let d = cosine_direction(normal, rng);
    trace(
        world,
        Ray::new(position_m, d),
        None,
        1,
        settings,
        rng,
        &mut |t, ray| {
            escape(PI * t, ray);
            DVec3::ZERO
        },
        None,
        None,
        false,
        false,
    );
}

/// One path along `ray` (not from a sensor: no cosine, no π), each escape handed to
/// `escape(throughput, escaping ray)`: the mean over such paths of the throughput escaping
/// through a sky patch is the radiance seen along `ray` per unit patch radiance (how
/// `rfluxmtx` builds a daylight matrix from a sender). At most `-ab` diffuse bounces.
pub fn escape_path(
    world: &World,
    ray: Ray,
    settings: &Settings,
    rng: &mut Rng,
    escape: &mut dyn FnMut(DVec3, &Ray),
) {
    trace(
        world,
        ray,
        None,
        0,
        settings,
        rng,
        &mut |t, ray| {
            escape(t, ray);
            DVec3::ZERO
        },
        None,
        None,
        false,
        false,
    );
}

/// Radiance back along `ray` (leaving the flat surface `from`, if any) for a path with no
/// diffuse bounce yet: how `radiance::ray_radiance` continues a camera ray. The first surface
/// met is shaded as a view ray meets it (an `aBSDF` leaves its through component, which
/// `ray_radiance` follows, out of its sampled transmission).
pub(crate) fn trace_radiance(
    world: &World,
    ray: Ray,
    from: Option<u32>,
    settings: &Settings,
    rng: &mut Rng,
) -> DVec3 {
    let nee = SkyNee::new(world, settings);
    trace(
        world,
        ray,
        from,
        0,
        settings,
        rng,
        &mut |t, ray| t * world.escape_radiance(ray.direction),
        nee.as_ref(),
        None,
        settings.russian_roulette,
        true,
    )
}

/// Most invisible surfaces a path passes before it is taken as lost.
pub(crate) const MAX_CROSSINGS: u32 = 1000;

/// What the path does after a vertex.
enum Next {
    /// Goes on from the vertex in this direction after a crossing or a specular event.
    Straight(DVec3),
    /// Goes on from the vertex in this direction after a diffuse bounce.
    Bounce(DVec3),
    /// Ends.
    End,
}

/// What stays fixed while one path is traced.
struct Tracer<'a, 'e> {
    world: &'a World,
    settings: &'a Settings,
    nee: Option<&'a SkyNee<'a>>,
    roulette: bool,
    /// What an escaping ray collects: `on_escape(throughput, ray)`.
    on_escape: &'e mut dyn FnMut(DVec3, &Ray) -> DVec3,
}

/// The state of one path as [`trace`] follows it.
struct PathState {
    ray: Ray,
    from: Option<u32>,
    ambient_used: u32,
    throughput: DVec3,
    radiance: DVec3,
    specular_events: u32,
    /// Invisible surfaces passed without scattering; bounded too.
    crossings: u32,
    last: Option<LastDiffuse>,
    /// Density × Russian-roulette survival with which the last diffuse vertex chose this
    /// segment, while the path has gone straight from it with no crossing: what the sun-patch
    /// strategy's weight at the next vertex needs.
    direct: Option<f64>,
    /// Since the last diffuse vertex the path has crossed only clear surfaces (glass, no
    /// material), as the sunlit-outside strategy's rays do.
    clear_only: bool,
    /// Where the next segment starts when not at the vertex (a proxy's transmitted light,
    /// [`Shading::origin_towards`]).
    next_origin: Option<DVec3>,
    /// The ray is a camera's, not yet scattered: the next surface is met as a view ray.
    view: bool,
}

/// Radiance arriving back along `ray`, for a path that has already made `ambient_used`
/// diffuse bounces; a ray that leaves the scene with path throughput `t` in direction `d`
/// adds `escape(t, d)`. With `nee`, every vertex that may scatter diffusely also estimates
/// the sky by next-event estimation, and an escape straight from the diffuse vertex `last`
/// (through glass and invisible surfaces only) is weighted by multiple importance sampling.
/// `view`: `ray` is a camera ray, and the first surface it meets is shaded as such.
#[allow(clippy::too_many_arguments)]
fn trace(
    world: &World,
    ray: Ray,
    from: Option<u32>,
    ambient_used: u32,
    settings: &Settings,
    rng: &mut Rng,
    escape: &mut dyn FnMut(DVec3, &Ray) -> DVec3,
    nee: Option<&SkyNee>,
    last: Option<LastDiffuse>,
    roulette: bool,
    view: bool,
) -> DVec3 {
    let mut tracer = Tracer {
        world,
        settings,
        nee,
        roulette,
        on_escape: escape,
    };
    let mut path = PathState {
        ray,
        from,
        ambient_used,
        throughput: DVec3::ONE,
        radiance: DVec3::ZERO,
        specular_events: 0,
        crossings: 0,
        last,
        direct: last.filter(|l| l.sun_patch_sampled).map(|l| l.pdf_sr),
        clear_only: true,
        next_origin: None,
        view,
    };
    loop {
        let Some(hit) = world.intersect(&path.ray, path.from) else {
            return tracer.escape(&path);
        };
        let p = path.ray.at(hit.t_m);
        path.from = Some(hit.primitive);
        let d = path.ray.direction;
        let flat = world.is_flat(hit.primitive);
        let (material, normal) = world
            .material(hit.primitive)
            .at_hit(&hit.as_seen(p, d, flat), rng);
        path.throughput *= material.arrival_factor(d, hit.normal, hit.t_m, false);
        let view = std::mem::take(&mut path.view);
        let next = match material.interact(d, normal, flat, view) {
            Interaction::PassThrough => path.cross(d),
            Interaction::Emits(l) => {
                path.radiance += path.throughput * l;
                Next::End
            }
            Interaction::Absorbed => Next::End,
            Interaction::Specular(step) => {
                if !world.material(hit.primitive).is_clear() {
                    path.clear_only = false;
                }
                path.specular(settings, |rng| step.sample(rng), rng)
            }
            Interaction::Shaded(shading) => tracer.shade(&mut path, &hit, p, &shading, rng),
        };
        match next {
            Next::End => return path.radiance,
            Next::Bounce(direction) => {
                path.ray = Ray::new(path.next_origin.take().unwrap_or(p), direction)
            }
            Next::Straight(next) => {
                if path.throughput.max_element() <= 0.0 {
                    return path.radiance;
                }
                if next != d {
                    // Turned by a specular event: no next-event strategy produces this path.
                    path.last = None;
                }
                // Any crossing or specular event: the next vertex is not reached directly.
                path.direct = None;
                path.ray = Ray::new(path.next_origin.take().unwrap_or(p), next);
            }
        }
    }
}

impl PathState {
    /// Passes an invisible surface.
    fn cross(&mut self, d: DVec3) -> Next {
        self.crossings += 1;
        if self.crossings > MAX_CROSSINGS {
            Next::End
        } else {
            Next::Straight(d)
        }
    }

    /// A specular event, counted against `-lr` before `sample` draws it.
    fn specular(
        &mut self,
        settings: &Settings,
        sample: impl FnOnce(&mut Rng) -> Scatter,
        rng: &mut Rng,
    ) -> Next {
        self.specular_events += 1;
        if self.specular_events > settings.max_specular_events {
            return Next::End;
        }
        match sample(rng) {
            Scatter::Specular { direction, weight } | Scatter::Diffuse { direction, weight } => {
                self.throughput *= weight;
                Next::Straight(direction)
            }
            Scatter::Absorbed => Next::End,
        }
    }
}

impl<'a> Tracer<'a, '_> {
    /// The path leaves the scene: what it collects there, weighted against the next-event
    /// strategies of its last diffuse vertex.
    fn escape(&mut self, path: &PathState) -> DVec3 {
        let d = path.ray.direction;
        let weight = match (self.nee, &path.last) {
            (Some(nee), Some(last)) => nee.continuation_weight(last, d),
            _ => 1.0,
        };
        path.radiance + (self.on_escape)(path.throughput * weight, &path.ray)
    }

    /// A vertex on a shaded surface: direct light from the sun, its mirror images and the sky
    /// by next-event estimation, then the continuation sampled from the shading.
    fn shade(
        &mut self,
        path: &mut PathState,
        hit: &Hit,
        p: DVec3,
        shading: &Shading,
        rng: &mut Rng,
    ) -> Next {
        self.sun(path, hit, p, shading, rng);
        path.radiance += path.throughput
            * mirrored_lights(self.world, p, path.from, rng, &mut |l, sr| {
                let c = shading.source_coefficient(l, sr);
                // As for the sun itself (the mirrored sun is white light scaled by the
                // mirror's colour, so the coefficient's brightness decides).
                if brighter_than_zero(c) {
                    c
                } else {
                    DVec3::ZERO
                }
            });
        let allow_diffuse = path.ambient_used < self.settings.ambient_bounces;
        let lambertian = self.world.material(hit.primitive).is_lambertian();
        let continuation = self.sky(path, p, shading, allow_diffuse, lambertian, rng);
        if let Some(c) = continuation.filter(|c| c.windows.is_some()) {
            // A Lambertian surface continues from the point itself.
            return match c.sample_direction(rng) {
                Some((direction, weight, pdf_sr)) => {
                    self.bounce(path, p, direction, weight, Some(pdf_sr), continuation, rng)
                }
                None => Next::End,
            };
        }
        let scatter = shading.sample(allow_diffuse, rng);
        if let Scatter::Diffuse { direction, .. } | Scatter::Specular { direction, .. } = scatter {
            path.next_origin = Some(shading.origin_towards(p, direction));
        }
        match scatter {
            Scatter::Absorbed => Next::End,
            Scatter::Diffuse { direction, weight } => {
                self.bounce(path, p, direction, weight, None, continuation, rng)
            }
            Scatter::Specular { direction, weight } => {
                path.clear_only = false;
                path.specular(
                    self.settings,
                    |_| Scatter::Specular { direction, weight },
                    rng,
                )
            }
        }
    }

    /// Next-event estimation of every distant `light` at the vertex; reached straight from a
    /// diffuse vertex, the sun-patch strategy there could have produced this vertex too, and
    /// so could the sunlit-outside strategy past a portal, so the estimate is weighted by
    /// the balance heuristic in area measure.
    fn sun(&self, path: &mut PathState, hit: &Hit, p: DVec3, shading: &Shading, rng: &mut Rng) {
        let d = path.ray.direction;
        // The continuation's density and its geometry term, per unit area, and whether the
        // sun patch's density counts.
        let straight = match (self.nee, path.last.filter(|_| path.clear_only)) {
            (Some(nee), Some(last)) => {
                let dist = if path.direct.is_some() {
                    hit.t_m
                } else {
                    (p - last.position_m).length()
                };
                let g = hit.normal.dot(d).abs() / (dist * dist);
                let patch = path.direct.is_some() && nee.sun_portals.is_some();
                Some((nee, last, dist, g, patch))
            }
            _ => None,
        };
        // The sunlit outside's density, once, when some light arrives.
        let mut outside: Option<f64> = None;
        for source in self.world.distant_sources() {
            if source.kind != DistantKind::Light {
                continue;
            }
            let Some(light) = light_at(self.world, shading, p, path.from, source, rng) else {
                continue;
            };
            let w = match straight {
                Some((nee, last, dist, g, patch)) if last.pdf_sr * last.survival > 0.0 => {
                    let p_a = last.pdf_sr * last.survival * g;
                    let p_b = if patch {
                        nee.sun_patch_pdf(
                            self.world,
                            p,
                            hit.normal,
                            hit.primitive,
                            source.direction,
                        )
                    } else {
                        0.0
                    };
                    let p_c = *outside.get_or_insert_with(|| {
                        if last.outside_sampled {
                            nee.outside_pdf_sr(last.position_m, d, dist) * g
                        } else {
                            0.0
                        }
                    });
                    p_a / (p_a + p_b + p_c)
                }
                _ => 1.0,
            };
            path.radiance += path.throughput * light * w;
        }
    }

    /// Next-event estimation of the sky and of the sun's patch at a vertex that may scatter
    /// diffusely; returns how the vertex continues, which the weights of what its
    /// continuation finds need. `lambertian`: the surface scatters only by its diffuse lobe,
    /// so the continuation may mix in directions towards the BSDF windows.
    fn sky(
        &self,
        path: &mut PathState,
        p: DVec3,
        shading: &Shading,
        allow_diffuse: bool,
        lambertian: bool,
        rng: &mut Rng,
    ) -> Option<Continuation<'a>> {
        let lobe = shading.diffuse_lobe(allow_diffuse)?;
        let windows = self.world.bsdf_windows();
        // Not at a surface behind or beside every window (the window's own wall): there no
        // direction towards a window leaves the surface.
        let mix = lambertian
            && self.settings.bsdf_window_sampling
            && windows.any_in_front(p, lobe.normal);
        let continuation = Continuation {
            lobe,
            at: p,
            windows: mix.then_some(windows),
            roulette_throughput: (self.roulette && path.ambient_used + 1 > RUSSIAN_ROULETTE_AFTER)
                .then_some(path.throughput),
            window_share: WINDOW_SHARE,
            table: None,
            table_share: 0.0,
        };
        if let Some(nee) = self.nee {
            path.radiance +=
                path.throughput * nee.estimate(self.world, p, path.from, &continuation, true, rng);
            if nee.sun_portals.is_some() {
                path.radiance += path.throughput
                    * nee.sun_estimate(self.world, p, path.from, &continuation, rng);
            }
        }
        Some(continuation)
    }

    /// A diffuse bounce in unit `direction` with weight `weight` (and the continuation's
    /// density for it, when its sampling already found it), then Russian roulette.
    #[allow(clippy::too_many_arguments)]
    fn bounce(
        &self,
        path: &mut PathState,
        p: DVec3,
        direction: DVec3,
        weight: DVec3,
        pdf_sr: Option<f64>,
        continuation: Option<Continuation>,
        rng: &mut Rng,
    ) -> Next {
        path.ambient_used += 1;
        path.throughput *= weight;
        path.last = continuation.map(|c| LastDiffuse {
            position_m: p,
            pdf_sr: pdf_sr.unwrap_or_else(|| c.eval(direction).1),
            sun_patch_sampled: true,
            outside_sampled: true,
            survival: 1.0,
        });
        path.clear_only = true;
        let mut survival = 1.0;
        if self.roulette && path.ambient_used > RUSSIAN_ROULETTE_AFTER {
            let q = (path.throughput.max_element() / RUSSIAN_ROULETTE_THROUGHPUT).min(1.0);
            if (q).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) || rng.uniform() >= q {
                return Next::End;
            }
            path.throughput /= q;
            survival = q;
        }
        // Every diffuse vertex samples the sun patch, so the next vertex weights its sun.
        if let Some(last) = path.last.as_mut() {
            last.survival = survival;
        }
        path.direct = path.last.map(|l| l.pdf_sr * survival);
        if path.throughput.max_element() <= 0.0 {
            return Next::End;
        }
        Next::Bounce(direction)
    }
}

/// One distant `source`'s next-event estimate at the shaded point `p` (on primitive `from`):
/// the radiance its sampled direction brings, times the shading's coefficient and what the
/// scene transmits towards it; None when nothing arrives.
fn light_at(
    world: &World,
    shading: &Shading,
    p: DVec3,
    from: Option<u32>,
    source: &DistantEmitter,
    rng: &mut Rng,
) -> Option<DVec3> {
    let l = sample_cone(source, rng);
    let c = shading.source_coefficient(l, source.solid_angle_sr);
    if c == DVec3::ZERO || !brighter_than_zero(c * source.radiance(l)) {
        return None;
    }
    let t = world.source_transmission(shading.origin_towards(p, l), from, l);
    (t != DVec3::ZERO).then(|| c * source.radiance(l) * t)
}

/// RADIANCE's test before a source's shadow ray (direct.c): a contribution whose brightness
/// (`bright`: 0.265 R + 0.670 G + 0.065 B) is not positive is dropped, so a pattern that
/// goes negative (a data file extrapolated, a function) darkens to black under the sun
/// rather than below it, as rtrace shows it; a contribution with some negative channels
/// but a positive brightness is kept.
fn brighter_than_zero(c: DVec3) -> bool {
    0.265 * c.x + 0.670 * c.y + 0.065 * c.z > 0.0
}
