//! One camera sample split at the first Lambertian surface it sees, for the filtered render
//! ([`super::filter`]).
//!
//! A Lambertian surface sends ρ/π · E(x) towards every viewer, E its irradiance. E has two
//! parts of very different character: the sun's direct light (and its mirror images), whose
//! shadows are sharp, and the rest (sky through the windows, interreflections), which varies
//! slowly along a surface but is what makes a path-traced image grainy. The sample keeps
//! the first part and every non-Lambertian surface's radiance as the path tracer gives it,
//! and hands back the rest apart, with the surface's reflectance and position, so that the
//! rest can be averaged over neighbouring pixels on the same surface.
//!
//! Each part is an unbiased estimate: the sum of a sample's parts has the mean of
//! [`super::super::radiance::ray_radiance`] for the same ray.

use super::super::integrator::{surface_irradiance_sample, IrradiancePart, Settings};
use super::super::radiance::{follow_view_ray, SunDisc, ViewShading};
use super::super::ray::Ray;
use super::super::rng::Rng;
use super::super::world::World;
use glam::DVec3;

/// Where the smooth part was found: the first Lambertian surface the ray met.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceFeature {
    pub position_m: DVec3,
    /// Unit normal, on the side the ray came from.
    pub normal: DVec3,
    /// Distance along the view ray's straight segments from the eye (a scale for how far
    /// apart two neighbouring pixels' points are).
    pub eye_distance_m: f64,
}

/// One camera sample in parts: its radiance is `unfiltered_rgb + albedo_rgb ⊙ rest_rgb`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSample {
    /// The radiance (W/sr/m² per RGB channel) that is not to be filtered.
    pub unfiltered_rgb: DVec3,
    /// Throughput from the eye × ρ/π of the first Lambertian surface (zero if none).
    pub albedo_rgb: DVec3,
    /// One estimate of that surface's irradiance less the sun's direct light (W/m²).
    pub rest_irradiance_rgb: DVec3,
    pub feature: Option<SurfaceFeature>,
}

/// One sample of the radiance along `ray` in parts; `sun_disc` as [`follow_view_ray`] takes it.
pub(crate) fn camera_sample(
    world: &World,
    ray: Ray,
    settings: &Settings,
    sun_disc: SunDisc,
    rng: &mut Rng,
) -> CameraSample {
    let eye = ray.origin_m;
    let mut sample = CameraSample {
        unfiltered_rgb: DVec3::ZERO,
        albedo_rgb: DVec3::ZERO,
        rest_irradiance_rgb: DVec3::ZERO,
        feature: None,
    };
    let mut shade = |seen: &ViewShading, rng: &mut Rng| -> DVec3 {
        let lobe = seen.shading.diffuse_lobe(true);
        let plain = seen.material.is_lambertian() && seen.normal == seen.geometric_normal;
        match lobe {
            Some(lobe) if plain && sample.feature.is_none() => {
                let irradiance = |part, rng: &mut Rng| {
                    surface_irradiance_sample(
                        world,
                        seen.position_m,
                        lobe.normal,
                        Some(seen.primitive),
                        part,
                        settings,
                        rng,
                    )
                };
                let albedo = seen.throughput * lobe.front_rgb;
                sample.albedo_rgb = albedo;
                sample.rest_irradiance_rgb = irradiance(IrradiancePart::Rest, rng);
                sample.feature = Some(SurfaceFeature {
                    position_m: seen.position_m,
                    normal: lobe.normal,
                    eye_distance_m: seen.position_m.distance(eye),
                });
                albedo * irradiance(IrradiancePart::DirectSun, rng)
            }
            _ => {
                seen.throughput
                    * super::super::integrator::trace_radiance(
                        world, seen.ray, seen.from, settings, rng,
                    )
            }
        }
    };
    let unfiltered = follow_view_ray(world, ray, settings, rng, sun_disc, &mut shade);
    sample.unfiltered_rgb = unfiltered;
    sample
}
