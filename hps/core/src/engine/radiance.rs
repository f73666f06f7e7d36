//! The radiance along one ray, as `rtrace` (without `-I`) computes it: what a camera pixel
//! sees.
//!
//! The ray is followed through the surfaces RADIANCE traces as a primary ray without shading
//! (invisible surfaces, `mirror`, `glass`); at the first other surface the path continues as
//! the integrator's paths do ([`super::integrator`]: next-event estimation of the sun at every
//! diffuse vertex, cosine-weighted continuation bounded by `-ab`, specular events by `-lr`).
//!
//! The one difference from a path leaving a sensor: until a diffuse or specular (normal.c)
//! scattering, a ray that leaves the scene inside the cone of a distant `light` sees its
//! radiance. RADIANCE source.c only blanks a `light` for rays descended from an ambient or
//! specular ray (`badcomponent`: `crtype & (AMBIENT|SPECULAR)`); a primary ray, and its
//! mirror-reflected or glass-transmitted children, see the sun's disc.
//!
//! A mirror seen from its back is black, as in RADIANCE (mirror.c `m_mirror`: `r->rod < 0`).
//!
//! An `aBSDF` with a through component both scatters the ray (the integrator shades it,
//! leaving the peak out of the sampled transmission) and lets it go on straight with the
//! through transmittance, still a view ray (m_bsdf.c `sample_sdf`: a `TRANS` child), so the
//! sun's disc and the view outside are seen through it.

use super::integrator::{trace_radiance, Settings, MAX_CROSSINGS};
use super::material::{Interaction, Scatter};
use super::ray::Ray;
use super::rng::Rng;
use super::sky::{source_seen, DistantKind};
use super::world::World;
use glam::DVec3;

/// What a ray leaving the scene along unit `d` sees when it descends from no ambient or
/// specular (normal.c) ray: a distant `light` containing `d`, else what any path sees.
pub fn seen_from_eye(world: &World, d: DVec3) -> DVec3 {
    match source_seen(world.distant_sources(), d) {
        Some(s) if s.kind == DistantKind::Light => s.radiance(d),
        _ => world.escape_radiance(d),
    }
}

/// One estimate of the radiance (W/sr/m² per RGB channel) arriving back along `ray`, with the
/// meaning of rtrace's value for that ray (no `-I`). Unbiased for the given `-ab` and `-lr`:
/// the mean of many estimates converges to rtrace's with `-aa 0` (pure path tracing).
pub fn ray_radiance(world: &World, ray: Ray, settings: &Settings, rng: &mut Rng) -> DVec3 {
    let mut ray = ray;
    let mut from: Option<u32> = None;
    let mut throughput = DVec3::ONE;
    let mut specular_events = 0u32;
    let mut crossings = 0u32;
    // What the scattering at `aBSDF`s passed through straight has added.
    let mut scattered = DVec3::ZERO;
    loop {
        let Some(hit) = world.intersect(&ray, from) else {
            return scattered + throughput * seen_from_eye(world, ray.direction);
        };
        let d = ray.direction;
        let p = ray.at(hit.t_m);
        let flat = world.is_flat(hit.primitive);
        let (material, normal) = world
            .material(hit.primitive)
            .at_hit(&hit.as_seen(p, d, flat), rng);
        throughput *= material.arrival_factor(d, hit.normal, hit.t_m, true);
        let next = match material.interact(d, normal, flat, true) {
            Interaction::PassThrough => {
                crossings += 1;
                if crossings > MAX_CROSSINGS {
                    return scattered;
                }
                d
            }
            Interaction::Emits(l) => return scattered + throughput * l,
            Interaction::Absorbed => return scattered,
            Interaction::Specular(step) => {
                specular_events += 1;
                if specular_events > settings.max_specular_events {
                    return scattered;
                }
                match step.sample(rng) {
                    Scatter::Specular { direction, weight }
                    | Scatter::Diffuse { direction, weight } => {
                        throughput *= weight;
                        direction
                    }
                    Scatter::Absorbed => return scattered,
                }
            }
            Interaction::Shaded(_) => {
                // The integrator shades this surface: trace again from where the ray started
                // (one repeated intersection, which keeps the shading code in one place).
                scattered += throughput * trace_radiance(world, ray, from, settings, rng);
                let through = material.view_through(d, normal);
                if through <= 0.0 {
                    return scattered;
                }
                crossings += 1;
                if crossings > MAX_CROSSINGS {
                    return scattered;
                }
                throughput *= through;
                d
            }
        };
        if throughput.max_element() <= 0.0 {
            return scattered;
        }
        from = Some(hit.primitive);
        ray = Ray::new(p, next);
    }
}
