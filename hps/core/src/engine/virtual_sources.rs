//! The sun reflected by plane mirrors as a second source: RADIANCE's virtual source method
//! (src/rt/virtuals.c, m_mirror.c; Ward, "The RADIANCE lighting simulation and rendering
//! system", SIGGRAPH 1994, §3.2) for one reflection.
//!
//! A `mirror` polygon facing a distant `light` makes a virtual distant source: the same disc
//! of sky mirrored in the polygon's plane. At a shaded point the virtual source is sampled
//! like the real one: a direction l in the sun's cone, its mirror image l' = l − 2 (l·n) n,
//! and the shadow ray along l' must reach the mirror's front inside the polygon (through
//! glass, invisible and smooth `trans` surfaces, as any shadow ray), then continue along l
//! from the mirror to the sky unobstructed. Its contribution is the shading coefficient for
//! l' times the mirror's reflectance times the sun's radiance along l.
//!
//! Nothing is counted twice: a path that reaches a distant `light` after a mirror bounce
//! collects nothing (integrator.rs; RADIANCE's `badcomponent`), as in RADIANCE, where light
//! from the sun via a mirror reaches diffuse surfaces through the virtual source only. One
//! reflection is followed (RADIANCE's default `-dr 2` also follows mirror-to-mirror).

use super::material::scattering::reflect;
use super::material::{HitPoint, Material, ShadowCrossing, VirtualSourceReflectance};
use super::ray::Ray;
use super::rng::Rng;
use super::sampling::sample_cone;
use super::sky::DistantKind;
use super::world::World;
use glam::DVec3;

/// Most surfaces a shadow ray passes through on its way to the mirror.
const MAX_CROSSINGS: usize = 64;

/// What a shadow ray towards a light source from `origin` (leaving surface `from`) along
/// unit `dir` keeps on its way to the front of primitive `target` (the mirror of a virtual
/// source; an `aBSDF` passes it with its through component): the product of the transmissions crossed and the hit
/// point on `target`; None if something opaque comes first, the ray misses `target` or meets
/// its back.
fn transmission_to(
    world: &World,
    origin: DVec3,
    from: Option<u32>,
    dir: DVec3,
    target: u32,
) -> Option<(DVec3, DVec3)> {
    let mut ray = Ray::new(origin, dir);
    let mut from = from;
    let mut t = DVec3::ONE;
    for _ in 0..MAX_CROSSINGS {
        let hit = world.intersect(&ray, from)?;
        let p = ray.at(hit.t_m);
        if hit.primitive == target {
            return (hit.normal.dot(dir) < 0.0).then_some((t, p));
        }
        let flat = world.is_flat(hit.primitive);
        match world
            .material(hit.primitive)
            .light_crossing_at(&hit.as_seen(p, dir, flat))
        {
            ShadowCrossing::PassThrough => {}
            ShadowCrossing::Transmits(factor) => t *= factor,
            ShadowCrossing::Opaque => return None,
        }
        if t == DVec3::ZERO {
            return None;
        }
        ray = Ray::new(p, dir);
        from = Some(hit.primitive);
    }
    None
}

/// One estimate of the light of every distant `light` reflected once by a mirror polygon
/// towards `position_m` (on surface `from`, if any): Σ over mirrors and lights of
/// `coefficient(l', Ω)` × mirror reflectance × radiance × transmissions, where
/// `coefficient(direction, solid_angle_sr)` turns a source's radiance into the quantity
/// wanted (irradiance: Ω cos θ; reflected radiance: normal.c `dirnorm`). Draws no random
/// numbers when the scene has no mirror facing a light, so scenes without mirrors trace as
/// before.
pub fn mirrored_lights(
    world: &World,
    position_m: DVec3,
    from: Option<u32>,
    rng: &mut Rng,
    coefficient: &mut dyn FnMut(DVec3, f64) -> DVec3,
) -> DVec3 {
    let mut total = DVec3::ZERO;
    if !world
        .distant_sources()
        .iter()
        .any(|s| s.kind == DistantKind::Light)
    {
        return total;
    }
    for &(mirror, n, reflectance) in world.mirrors() {
        if Some(mirror) == from {
            continue;
        }
        for source in world.distant_sources() {
            // The mirror must face the source (virtuals.c: a virtual source only for a mirror
            // whose front sees it).
            if source.kind != DistantKind::Light || source.direction.dot(n) <= 0.0 {
                continue;
            }
            let l = sample_cone(source, rng);
            let ln = l.dot(n);
            if ln <= 0.0 {
                continue;
            }
            let virtual_dir = reflect(l, n);
            let c = coefficient(virtual_dir, source.solid_angle_sr);
            if c == DVec3::ZERO {
                continue;
            }
            let Some((t_in, q)) = transmission_to(world, position_m, from, virtual_dir, mirror)
            else {
                continue;
            };
            let reflectance = match reflectance {
                VirtualSourceReflectance::Uniform(rgb) => rgb,
                VirtualSourceReflectance::AtEachPoint => {
                    let distance_m = (q - position_m).length();
                    reflectance_at(world, mirror, (q, distance_m), virtual_dir, n, rng)
                }
            };
            let t_out = world.source_transmission(q, Some(mirror), l);
            total += c * reflectance * source.radiance(l) * t_in * t_out;
        }
    }
    total
}

/// A patterned mirror's reflectance where the relayed ray along unit `dir` meets it at `q`,
/// `distance_m` from where it left
/// (m_mirror.c: its colour times the patterns there; textures do not turn a relayed ray).
fn reflectance_at(
    world: &World,
    mirror: u32,
    (q, distance_m): (DVec3, f64),
    dir: DVec3,
    normal: DVec3,
    rng: &mut Rng,
) -> DVec3 {
    let hit = HitPoint {
        point_m: q,
        direction: dir,
        normal,
        distance_m,
        flat: true,
    };
    match world.material(mirror).at_hit(&hit, rng).0.as_ref() {
        Material::Mirror(m) => m.reflectance_rgb,
        _ => DVec3::ZERO,
    }
}
