//! Path tracing of the irradiance at a sensor, with the meaning of rtrace's controls.
//!
//! One sample is one path from the sensor: next-event estimation towards every distant
//! `light` (the sun) at each diffuse vertex and at the sensor itself, and a cosine-weighted
//! continuation whose rays collect the sky and ground `glow`s and local emitters they hit.
//! Rays that hit a distant `light` collect nothing, as in RADIANCE (source.c
//! `badcomponent`), since next-event estimation already counts it. `-ab` bounds the number
//! of diffuse (ambient) bounces including the one from the sensor; specular events (glass,
//! mirror, smooth or Gaussian highlights) do not count against it, as in RADIANCE, and are
//! bounded by [`Settings::max_specular_events`] (rtrace's `-lr`). No Russian roulette: every
//! path runs to its bounce limit or until it leaves the scene or is absorbed, so the
//! estimate is unbiased for the given limits.

use super::error::EngineError;
use super::material::{basis, cosine_direction, glass_fractions, Material, Scatter};
use super::ray::Ray;
use super::rng::Rng;
use super::sky::{DistantEmitter, DistantKind};
use super::world::World;
use glam::DVec3;
use std::f64::consts::PI;

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
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            ambient_bounces: 5,
            samples_per_sensor: 1024,
            seed: 1,
            max_specular_events: 16,
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
fn sample_cone(source: &DistantEmitter, rng: &mut Rng) -> DVec3 {
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
    if settings.ambient_bounces == 0 {
        return e;
    }
    // Indirect: cosine-weighted direction, so E = π L(ω) per sample.
    let d = cosine_direction(normal, rng);
    e + PI
        * trace(
            world,
            Ray::new(position_m, d),
            None,
            1,
            settings,
            rng,
            &mut |t, dir| t * world.escape_radiance(dir),
        )
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
    );
}

/// Radiance arriving back along `ray`, for a path that has already made `ambient_used`
/// diffuse bounces.
/// Radiance arriving back along `ray`; a ray that leaves the scene with path throughput `t`
/// in direction `d` adds `escape(t, d)`.
fn trace(
    world: &World,
    mut ray: Ray,
    mut from: Option<u32>,
    mut ambient_used: u32,
    settings: &Settings,
    rng: &mut Rng,
    escape: &mut dyn FnMut(DVec3, DVec3) -> DVec3,
) -> DVec3 {
    let mut throughput = DVec3::ONE;
    let mut radiance = DVec3::ZERO;
    let mut specular_events = 0u32;
    // Invisible surfaces are passed without scattering; bound them too.
    let mut crossings = 0u32;
    loop {
        let Some(hit) = world.intersect(&ray, from) else {
            return radiance + escape(throughput, ray.direction);
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
                for source in world.distant_sources() {
                    if source.kind != DistantKind::Light {
                        continue;
                    }
                    let l = sample_cone(source, rng);
                    let c = shading.source_coefficient(l, source.solid_angle_sr);
                    if c != DVec3::ZERO {
                        radiance += throughput
                            * c
                            * source.radiance(l)
                            * world.shadow_transmission(p, from, l);
                    }
                }
                let allow_diffuse = ambient_used < settings.ambient_bounces;
                match shading.sample(allow_diffuse, rng) {
                    Scatter::Absorbed => return radiance,
                    Scatter::Diffuse { direction, weight } => {
                        ambient_used += 1;
                        throughput *= weight;
                        direction
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
        ray = Ray::new(p, next);
    }
}
