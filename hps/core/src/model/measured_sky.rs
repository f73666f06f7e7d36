//! The room's engine world under one capture's measured sky, for what traces the room itself
//! rather than applying daylight coefficients (the daemon's full Monte-Carlo check, its
//! occupant views): the map's patches with the sun disk removed as the environment, a uniform
//! ground of the model's reflectance below the horizon, and the extracted sun as a `light` of
//! the solar disk's solid angle (the concentrated source the model's prediction uses).

use super::prediction::ModelState;
use super::terms::{CaptureTerms, MIN_COVERAGE};
use crate::engine::sky::DistantEmitter;
use crate::engine::{World, WHITE_EFFICACY_LM_PER_W};
use crate::hdr::{GroupGeometry, LuminanceMap};
use crate::sky::SkyPatches;
use crate::sun::{remove_sun, SOLAR_DISK_SR};
use glam::DVec3;
use std::sync::Arc;

/// Puts the measured sky of `map` (its `terms`, read through `geometry`) around `world`, with
/// Reinhart `mf` patches; undo with [`remove_measured_sky`].
pub fn install_measured_sky(
    world: &mut World,
    map: &LuminanceMap,
    terms: &CaptureTerms,
    geometry: &GroupGeometry,
    mf: usize,
    state: &ModelState,
) {
    let without_sun = match &terms.sun {
        Some(s) => remove_sun(map, s),
        None => map.clone(),
    };
    let patches = SkyPatches::reinhart(mf);
    let sky = patches.aggregate(
        &without_sun,
        &geometry.direction,
        &geometry.solid_angle_sr,
        MIN_COVERAGE,
    );
    // A Lambertian ground of reflectance ρ under the outdoor horizontal illuminance E has
    // luminance ρ E / π.
    let ground_cd_m2 =
        state.ground_reflectance * terms.outdoor_horizontal_lux / std::f64::consts::PI;
    let efficacy = WHITE_EFFICACY_LM_PER_W;
    let luminance = sky.luminance_cd_m2;
    world.set_environment(Some(Arc::new(move |d: DVec3| {
        let l = if d.z < 0.0 {
            ground_cd_m2
        } else {
            patches
                .patch_of(d)
                .and_then(|p| luminance.get(p).copied())
                .filter(|l| l.is_finite())
                .unwrap_or(0.0)
        };
        DVec3::splat(l / efficacy)
    })));
    if let Some(s) = &terms.sun {
        if s.direct_normal_illuminance_lux > 0.0 {
            world.add_distant(DistantEmitter::sun(
                s.direction,
                SOLAR_DISK_SR,
                s.direct_normal_illuminance_lux / (efficacy * SOLAR_DISK_SR),
            ));
        }
    }
}

/// Takes the sky and the sun off `world` again (the room alone, as its coefficients need it).
pub fn remove_measured_sky(world: &mut World) {
    world.clear_distant();
    world.set_environment(None);
}
