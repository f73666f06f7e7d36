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
//! (paths from sensors and cameras, [`Settings::russian_roulette`]), a path past its third diffuse bounce continues with
//! probability min(1, throughput / `RUSSIAN_ROULETTE_THROUGHPUT`) and is reweighted by its inverse (Russian roulette, Arvo &
//! Kirk 1990): unbiased for the given limits, and paths whose remaining contribution is small
//! stop early. The daylight-coefficient paths ([`escape_sample`]) run to their limits.
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

use super::error::EngineError;
use super::material::{basis, cosine_direction, glass_fractions, DiffuseLobe, Material, Scatter};
use super::portal::Portals;
use super::ray::Ray;
use super::rng::Rng;
use super::sky::{DistantEmitter, DistantKind};
use super::sky_sampling::SkyDistribution;
use super::world::World;
use glam::DVec3;
use std::f64::consts::PI;

/// Diffuse bounces a path always makes before Russian roulette may end it.
const RUSSIAN_ROULETTE_AFTER: u32 = 3;
/// Path throughput below which Russian roulette may end a path: it continues with
/// probability min(1, throughput / this), as rtrace's `-lw` sets the weight below which its
/// rays play roulette. With 1 (survival = throughput) a path in a room of reflectance 0.5
/// survived its fourth bounce one time in eight and carried eight times its light: on the
/// reference room half the variance came from that. 0.25 cut variance × time by 1.3
/// (measured with 32 seeds over thresholds 1, 0.5, 0.3, 0.2 and 0.15, and roulette from the
/// 1st to the 4th bounce; see BENCHMARKS.md).
const RUSSIAN_ROULETTE_THROUGHPUT: f64 = 0.25;
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
    /// ([`super::illuminance`]).
    pub stratified: bool,
    /// Path reuse across sensors ([`super::illuminance`]): the first vertex of each sensor's
    /// path, when it is a Lambertian surface, also lights the other sensors of its group
    /// that see it, weighted by the balance heuristic over the group's sensors. Unbiased.
    pub path_reuse: bool,
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

/// A direction uniformly distributed in the cone of a distant source (pdf 1/Ω).
pub(crate) fn sample_cone(source: &DistantEmitter, rng: &mut Rng) -> DVec3 {
    let cos_theta = 1.0 - rng.uniform() * (1.0 - source.cos_half_angle);
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let phi = 2.0 * PI * rng.uniform();
    let (u, v) = basis(source.direction);
    (u * (sin_theta * phi.cos()) + v * (sin_theta * phi.sin()) + source.direction * cos_theta)
        .normalize()
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
    sensor_path(world, position_m, normal, settings, rng, false).0
}

/// The first vertex of a sensor's path when other sensors may use it (path reuse,
/// [`super::illuminance`]): a Lambertian surface the sensor sees directly, and the path's
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
    sensor_path(world, position_m, normal, settings, rng, true)
}

fn sensor_path(
    world: &World,
    position_m: DVec3,
    normal: DVec3,
    settings: &Settings,
    rng: &mut Rng,
    shared: bool,
) -> (DVec3, Option<SharedVertex>) {
    let mut e = DVec3::ZERO;
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
                * world.shadow_transmission(position_m, None, l);
        }
    }
    // The sun via plane mirrors (virtual sources).
    e += super::virtual_sources::mirrored_lights(world, position_m, None, rng, &mut |l, sr| {
        DVec3::splat(sr * l.dot(normal).max(0.0))
    });
    if settings.ambient_bounces == 0 {
        return (e, None);
    }
    let nee = SkyNee::new(world, settings);
    let lobe = DiffuseLobe::sensor(normal);
    if let Some(nee) = &nee {
        e += nee.estimate(world, position_m, None, &lobe, rng);
        if !shared {
            e += nee.sun_estimate(world, position_m, None, &lobe, 1.0, 1.0, rng);
        }
    }
    // Indirect: cosine-weighted direction, so E = π L(ω) per sample.
    let d = cosine_direction(normal, rng);
    let last = LastDiffuse {
        position_m,
        pdf_sr: lobe.eval(d).1,
        sun_patch_sampled: !shared,
    };
    let ray = Ray::new(position_m, d);
    let first = if shared {
        world.intersect(&ray, None).filter(
            |h| matches!(world.material(h.primitive), Material::Normal(m) if m.is_lambertian()),
        )
    } else {
        None
    };
    let l = trace(
        world,
        ray,
        None,
        1,
        settings,
        rng,
        &mut |t, dir| t * world.escape_radiance(dir),
        nee.as_ref(),
        Some(last),
        settings.russian_roulette,
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
        None => (e + PI * l, None),
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
}

/// Next-event estimation of the light beyond the scene (sky and ground `glow`s, environment)
/// through portals and by the sky's brightness.
struct SkyNee<'a> {
    portals: Option<&'a Portals>,
    sky: Option<&'a SkyDistribution>,
    /// Portals through which sunlit points are sampled (see [`SkyNee::sun_estimate`]).
    sun_portals: Option<&'a Portals>,
}

impl<'a> SkyNee<'a> {
    /// The strategies `settings` asks for that the world supports; None if none applies or
    /// nothing beyond the scene is bright.
    fn new(world: &'a World, settings: &Settings) -> Option<Self> {
        let bright = world.has_escape_radiance();
        let portals = (bright && settings.portal_sampling && !world.portals().is_empty())
            .then(|| world.portals());
        let sky = if bright && settings.sky_sampling {
            world.sky_distribution()
        } else {
            None
        };
        let has_light = world
            .distant_sources()
            .iter()
            .any(|s| s.kind == DistantKind::Light);
        let sun_portals =
            (has_light && settings.sun_portal_sampling && !world.portals().is_empty())
                .then(|| world.portals());
        (portals.is_some() || sky.is_some() || sun_portals.is_some()).then_some(Self {
            portals,
            sky,
            sun_portals,
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
    /// heuristic with the path that reaches y by the vertex's own diffuse sampling (density
    /// `q` p(ω) |cos θ_y| / d², `q_front`/`q_back` the Russian-roulette survival of that
    /// continuation), whose sun estimate at y [`trace`] weights to match.
    #[allow(clippy::too_many_arguments)]
    fn sun_estimate(
        &self,
        world: &World,
        x: DVec3,
        from: Option<u32>,
        lobe: &DiffuseLobe,
        q_front: f64,
        q_back: f64,
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
            let Some((p, _)) = portals.sample_point(rng) else {
                continue;
            };
            // Into the room from the portal point, through glass and invisible surfaces.
            let ray = Ray::new(p - s * 1e-7, -s);
            let found = world.first_opaque(&ray, None).and_then(|hit| {
                match world.material(hit.primitive) {
                    Material::Normal(m) => Some((ray.at(hit.t_m), hit.normal, hit.primitive, m)),
                    _ => None,
                }
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
            let (f, pdf_lobe) = lobe.eval(w);
            if f == DVec3::ZERO {
                continue;
            }
            let cos_y = n_y.dot(w).abs();
            if (cos_y).partial_cmp(&1e-9) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            let shading = m.shade(w, n_y, world.is_flat(prim_y));
            let c = shading.source_coefficient(l, source.solid_angle_sr);
            if c == DVec3::ZERO {
                continue;
            }
            // x must see y directly.
            match world.intersect(&Ray::new(x, w), from) {
                Some(h)
                    if h.primitive == prim_y && (h.t_m - dist).abs() <= 1e-6 * dist.max(1.0) => {}
                _ => continue,
            }
            let t = world.shadow_transmission(y, Some(prim_y), l);
            if t == DVec3::ZERO {
                continue;
            }
            let q = if lobe.normal.dot(w) > 0.0 {
                q_front
            } else {
                q_back
            };
            let p_a = q * pdf_lobe * cos_y / d2;
            let p_b = self.sun_patch_pdf(world, y, n_y, prim_y, s);
            if (p_a + p_b).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
                continue;
            }
            sum += f * (cos_y / d2) * c * source.radiance(l) * t / (p_a + p_b);
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
    /// a sensor) they estimate.
    fn estimate(
        &self,
        world: &World,
        x: DVec3,
        from: Option<u32>,
        lobe: &DiffuseLobe,
        rng: &mut Rng,
    ) -> DVec3 {
        let mut sum = DVec3::ZERO;
        if let Some(portals) = self.portals {
            if let Some((d, pp)) = portals.sample(x, rng) {
                sum += self.one(world, x, from, lobe, d, Some(pp));
            }
        }
        if let Some(sky) = self.sky {
            let (d, _) = sky.sample(rng);
            let pp = self.portals.map(|p| p.pdf(x, d));
            if pp.is_none_or(|pp| pp > 0.0) {
                sum += self.one(world, x, from, lobe, d, pp);
            }
        }
        sum
    }

    fn one(
        &self,
        world: &World,
        x: DVec3,
        from: Option<u32>,
        lobe: &DiffuseLobe,
        d: DVec3,
        portal_pdf: Option<f64>,
    ) -> DVec3 {
        let (f, pdf_lobe) = lobe.eval(d);
        if f == DVec3::ZERO {
            return DVec3::ZERO;
        }
        let l = world.escape_radiance(d);
        if l == DVec3::ZERO {
            return DVec3::ZERO;
        }
        let denominator = pdf_lobe + self.pdf_sr_given(portal_pdf, d);
        if (denominator).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return DVec3::ZERO;
        }
        let t = world.shadow_transmission(x, from, d);
        if t == DVec3::ZERO {
            return DVec3::ZERO;
        }
        f * l * t / denominator
    }
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
        &mut |t, dir| {
            escape(PI * t, dir);
            DVec3::ZERO
        },
        None,
        None,
        false,
    );
}

/// Radiance back along `ray` (leaving the flat surface `from`, if any) for a path with no
/// diffuse bounce yet: how [`super::radiance::ray_radiance`] continues a camera ray.
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
        &mut |t, dir| t * world.escape_radiance(dir),
        nee.as_ref(),
        None,
        settings.russian_roulette,
    )
}

/// Radiance arriving back along `ray`, for a path that has already made `ambient_used`
/// diffuse bounces; a ray that leaves the scene with path throughput `t` in direction `d`
/// adds `escape(t, d)`. With `nee`, every vertex that may scatter diffusely also estimates
/// the sky by next-event estimation, and an escape straight from the diffuse vertex `last`
/// (through glass and invisible surfaces only) is weighted by multiple importance sampling.
#[allow(clippy::too_many_arguments)]
fn trace(
    world: &World,
    mut ray: Ray,
    mut from: Option<u32>,
    mut ambient_used: u32,
    settings: &Settings,
    rng: &mut Rng,
    escape: &mut dyn FnMut(DVec3, DVec3) -> DVec3,
    nee: Option<&SkyNee>,
    mut last: Option<LastDiffuse>,
    roulette: bool,
) -> DVec3 {
    // Density × Russian-roulette survival with which the last diffuse vertex chose this
    // segment, while the path has gone straight from it with no crossing: what the sun-patch
    // strategy's weight at the next vertex needs.
    let mut direct: Option<f64> = last.filter(|l| l.sun_patch_sampled).map(|l| l.pdf_sr);
    let mut throughput = DVec3::ONE;
    let mut radiance = DVec3::ZERO;
    let mut specular_events = 0u32;
    // Invisible surfaces are passed without scattering; bound them too.
    let mut crossings = 0u32;
    loop {
        let Some(hit) = world.intersect(&ray, from) else {
            let weight = match (nee, &last) {
                (Some(nee), Some(last)) => nee.continuation_weight(last, ray.direction),
                _ => 1.0,
            };
            return radiance + escape(throughput * weight, ray.direction);
        };
        let p = ray.at(hit.t_m);
        from = Some(hit.primitive);
        let d = ray.direction;
        let next = match world.material(hit.primitive) {
            Material::Invisible => {
                crossings += 1;
                if crossings > 1000 {
                    return radiance;
                }
                d
            }
            Material::Emitter(e) => {
                // Light leaves the front only (source.c m_light: `r->rod < 0` is black).
                if e.illuminates && d.dot(hit.normal) < 0.0 {
                    radiance += throughput * e.radiance(d);
                }
                return radiance;
            }
            Material::Mirror { reflectance_rgb } => {
                // The back is black (RADIANCE m_mirror.c: `r->rod < 0` returns no light).
                if d.dot(hit.normal) > 0.0 {
                    return radiance;
                }
                specular_events += 1;
                if specular_events > settings.max_specular_events {
                    return radiance;
                }
                throughput *= *reflectance_rgb;
                d - 2.0 * d.dot(hit.normal) * hit.normal
            }
            Material::Glass(g) => {
                specular_events += 1;
                if specular_events > settings.max_specular_events {
                    return radiance;
                }
                let (t, r) = glass_fractions(g, d.dot(hit.normal).abs());
                let (bt, br) = (super::material::bright(t), super::material::bright(r));
                if bt + br <= 0.0 || (bt + br).is_nan() {
                    return radiance;
                }
                // Choose transmission or reflection in proportion to brightness.
                if rng.uniform() * (bt + br) < bt {
                    throughput *= t * ((bt + br) / bt);
                    d
                } else {
                    throughput *= r * ((bt + br) / br);
                    d - 2.0 * d.dot(hit.normal) * hit.normal
                }
            }
            Material::Normal(m) => {
                let shading = m.shade(d, hit.normal, world.is_flat(hit.primitive));
                // Reached straight from a diffuse vertex: the sun-patch strategy there could
                // have produced this vertex too (balance heuristic, area densities).
                let p_direct = match (nee, direct) {
                    (Some(nee), Some(pdf)) if nee.sun_portals.is_some() => {
                        Some(pdf * hit.normal.dot(d).abs() / (hit.t_m * hit.t_m))
                    }
                    _ => None,
                };
                for source in world.distant_sources() {
                    if source.kind != DistantKind::Light {
                        continue;
                    }
                    let l = sample_cone(source, rng);
                    let c = shading.source_coefficient(l, source.solid_angle_sr);
                    if c != DVec3::ZERO {
                        let t = world.shadow_transmission(p, from, l);
                        if t == DVec3::ZERO {
                            continue;
                        }
                        let w = match (nee, p_direct) {
                            (Some(nee), Some(p_a)) if p_a > 0.0 => {
                                let p_b = nee.sun_patch_pdf(
                                    world,
                                    p,
                                    hit.normal,
                                    hit.primitive,
                                    source.direction,
                                );
                                p_a / (p_a + p_b)
                            }
                            _ => 1.0,
                        };
                        radiance += throughput * c * source.radiance(l) * t * w;
                    }
                }
                radiance += throughput
                    * super::virtual_sources::mirrored_lights(world, p, from, rng, &mut |l, sr| {
                        shading.source_coefficient(l, sr)
                    });
                let allow_diffuse = ambient_used < settings.ambient_bounces;
                let lobe = match nee {
                    Some(nee) => shading.diffuse_lobe(allow_diffuse).inspect(|lobe| {
                        radiance += throughput * nee.estimate(world, p, from, lobe, rng);
                        if nee.sun_portals.is_some() {
                            // The continuation's Russian-roulette survival, per side.
                            let q = |f: DVec3, prob: f64| {
                                if roulette
                                    && ambient_used + 1 > RUSSIAN_ROULETTE_AFTER
                                    && prob > 0.0
                                {
                                    ((throughput * f * (PI / prob)).max_element()
                                        / RUSSIAN_ROULETTE_THROUGHPUT)
                                        .min(1.0)
                                } else {
                                    1.0
                                }
                            };
                            let q_front = q(lobe.front_rgb, lobe.front_probability);
                            let q_back = q(lobe.back_rgb, lobe.back_probability);
                            radiance += throughput
                                * nee.sun_estimate(world, p, from, lobe, q_front, q_back, rng);
                        }
                    }),
                    None => None,
                };
                match shading.sample(allow_diffuse, rng) {
                    Scatter::Absorbed => return radiance,
                    Scatter::Diffuse { direction, weight } => {
                        ambient_used += 1;
                        throughput *= weight;
                        last = lobe.map(|lobe| LastDiffuse {
                            position_m: p,
                            pdf_sr: lobe.eval(direction).1,
                            sun_patch_sampled: true,
                        });
                        let mut survival = 1.0;
                        if roulette && ambient_used > RUSSIAN_ROULETTE_AFTER {
                            let q =
                                (throughput.max_element() / RUSSIAN_ROULETTE_THROUGHPUT).min(1.0);
                            if (q).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
                                || rng.uniform() >= q
                            {
                                return radiance;
                            }
                            throughput /= q;
                            survival = q;
                        }
                        // Every diffuse vertex samples the sun patch (at the sensor and every
                        // bounce: limited to the first two, the deep sensors of the reference
                        // room had 2.3 times the variance at equal paths, for some 15 % less
                        // time per path), so the next vertex weights its sun.
                        direct = last.map(|l| l.pdf_sr * survival);
                        if throughput.max_element() <= 0.0 {
                            return radiance;
                        }
                        ray = Ray::new(p, direction);
                        continue;
                    }
                    Scatter::Specular { direction, weight } => {
                        specular_events += 1;
                        if specular_events > settings.max_specular_events {
                            return radiance;
                        }
                        throughput *= weight;
                        direction
                    }
                }
            }
        };
        if throughput.max_element() <= 0.0 {
            return radiance;
        }
        if next != d {
            // Turned by a specular event: no next-event strategy produces this path.
            last = None;
        }
        // Any crossing or specular event: the next vertex is not reached directly.
        direct = None;
        ray = Ray::new(p, next);
    }
}
