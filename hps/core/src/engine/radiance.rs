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
use super::material::{Interaction, Material, Scatter, Shading};
use super::ray::Ray;
use super::rng::Rng;
use super::sky::{source_seen, DistantEmitter, DistantKind};
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
    ray_radiance_with(world, ray, settings, SunDisc::Sampled, rng)
}

/// [`ray_radiance`] with the small discs of distant `light`s counted as `sun_disc` says.
pub(crate) fn ray_radiance_with(
    world: &World,
    ray: Ray,
    settings: &Settings,
    sun_disc: SunDisc,
    rng: &mut Rng,
) -> DVec3 {
    follow_view_ray(world, ray, settings, rng, sun_disc, &mut |seen, rng| {
        seen.throughput * trace_radiance(world, seen.ray, seen.from, settings, rng)
    })
}

/// Largest solid angle of a distant `light` whose image [`SunDisc::Apart`] integrates: a
/// disc up to about 2° across (the sun's is 0.53°, 6.8e-5 sr).
pub(crate) const DISC_APART_MAX_SR: f64 = 1e-3;

/// A distant `light` small enough for [`SunDisc::Apart`].
pub(crate) fn is_disc_apart(source: &DistantEmitter) -> bool {
    source.kind == DistantKind::Light && source.solid_angle_sr <= DISC_APART_MAX_SR
}

/// How a view ray that goes straight on (through glass and invisible surfaces) to a distant
/// `light` counts its disc.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SunDisc {
    /// It sees the disc when it falls inside it.
    Sampled,
    /// It does not: the caller adds the disc's image itself ([`super::render`], integrating
    /// the disc over each pixel instead of hitting it by chance).
    Apart,
}

/// A surface the integrator shades, as a view ray meets it (after any glass, mirrors and
/// invisible surfaces on the way).
pub(crate) struct ViewShading<'a> {
    /// The ray that hit it, and the primitive it started from.
    pub ray: Ray,
    pub from: Option<u32>,
    pub primitive: u32,
    pub position_m: DVec3,
    /// The material after its patterns at this hit.
    pub material: &'a Material,
    pub shading: &'a Shading,
    /// The shading normal (a texture may have perturbed it) and the geometric one.
    pub normal: DVec3,
    pub geometric_normal: DVec3,
    /// What the way from the eye passes on of the surface's radiance.
    pub throughput: DVec3,
}

/// [`ray_radiance`] with the shaded surfaces' radiance, throughput included, from `shade`:
/// a renderer may estimate it its own way ([`super::render`]).
pub(crate) fn follow_view_ray(
    world: &World,
    ray: Ray,
    settings: &Settings,
    rng: &mut Rng,
    sun_disc: SunDisc,
    shade: &mut dyn FnMut(&ViewShading, &mut Rng) -> DVec3,
) -> DVec3 {
    let mut ray = ray;
    // Turned by a mirror or a reflection: no longer the straight line the disc's image is
    // integrated along.
    let mut turned = false;
    let mut from: Option<u32> = None;
    let mut throughput = DVec3::ONE;
    let mut specular_events = 0u32;
    let mut crossings = 0u32;
    // What the scattering at `aBSDF`s passed through straight has added.
    let mut scattered = DVec3::ZERO;
    loop {
        let Some(hit) = world.intersect(&ray, from) else {
            let d = ray.direction;
            let seen = match source_seen(world.distant_sources(), d) {
                Some(s) if sun_disc == SunDisc::Apart && !turned && is_disc_apart(s) => {
                    world.escape_radiance(d)
                }
                _ => seen_from_eye(world, d),
            };
            return scattered + throughput * seen;
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
            Interaction::Shaded(shading) => {
                // The integrator shades this surface (by default tracing again from where the
                // ray started: one repeated intersection keeps the shading code in one place).
                let seen = ViewShading {
                    ray,
                    from,
                    primitive: hit.primitive,
                    position_m: p,
                    material: &material,
                    shading: &shading,
                    normal,
                    geometric_normal: hit.normal,
                    throughput,
                };
                scattered += shade(&seen, rng);
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
        turned |= next != d;
        from = Some(hit.primitive);
        ray = Ray::new(p, next);
    }
}
