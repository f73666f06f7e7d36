//! The measured sky in any direction: the map where the lens saw a valid group, the filled
//! sky patches elsewhere (outside the field of view, or over/under-range groups).

use super::{PatchSky, SkyPatches};
use crate::camera::CameraModel;
use crate::campaign::Readout;
use crate::hdr::{CaptureMap, MapFlag};
use glam::DVec3;

/// Luminance lookup over the whole upper hemisphere.
pub struct SkyLookup<'a> {
    pub camera: &'a CameraModel,
    pub merged: &'a CaptureMap,
    pub patches: SkyPatches,
    pub patch_sky: PatchSky,
}

impl<'a> SkyLookup<'a> {
    /// Builds the lookup with Reinhart MF `mf` patches for the fill (a patch counts as seen
    /// when half its solid angle is covered).
    pub fn new(camera: &'a CameraModel, merged: &'a CaptureMap, mf: usize) -> Self {
        let patches = SkyPatches::reinhart(mf);
        let patch_sky = patches.aggregate(
            &merged.map,
            &merged.geometry.direction,
            &merged.geometry.solid_angle_sr,
            0.5,
        );
        Self {
            camera,
            merged,
            patches,
            patch_sky,
        }
    }

    /// The group a direction falls on, if it is imaged inside the readout window.
    fn group(&self, d: DVec3) -> Option<usize> {
        let p = self.camera.project(d)?;
        let Readout {
            col_start,
            row_start,
            skip,
            ..
        } = self.merged.capture.readout;
        let step = 2.0 * skip as f64;
        let (gx, gy) = (
            (p.x_px - col_start as f64) / step,
            (p.y_px - row_start as f64) / step,
        );
        let map = &self.merged.map;
        if gx < 0.0 || gy < 0.0 || gx >= map.width as f64 || gy >= map.height as f64 {
            return None;
        }
        Some(gy as usize * map.width + gx as usize)
    }

    /// Luminance in a direction of the upper hemisphere, cd/m².
    pub fn luminance_cd_m2(&self, d: DVec3) -> f64 {
        if let Some(i) = self.group(d) {
            if self.merged.map.flags[i] == MapFlag::Valid {
                return self.merged.map.luminance_cd_m2[i] as f64;
            }
        }
        self.patches
            .patch_of(d)
            .map(|p| self.patch_sky.luminance_cd_m2[p])
            .filter(|l| l.is_finite())
            .unwrap_or(0.0)
    }
}
