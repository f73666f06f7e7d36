//! The sun from the fabric's accumulators (issue 22 item 2): the HPS sets a threshold and a
//! search window around the predicted sun before the shortest exposure, and reads back a
//! handful of sums instead of scanning the map for the disk.
//!
//! The sums are of the grouped words (black-subtracted, weighted DN), so the calibration is
//! applied once, at the centroid: L = DN · c_g / (t g) / V (the HDR merge's own conversion,
//! `hdr::merge`), and the flux Σ L Ω is the sum of DN times that factor and the group's solid
//! angle there (both vary by well under 0.1 % across a disk a few groups wide). The
//! circumsolar background, which the fabric cannot subtract, comes from a ring of the map
//! around the box the fabric reports, as `extract_sun` takes it.

use super::extract::{ring_median_cd_m2, GroupBox, NoSun, SunFlag, SOLAR_DISK_SR};
use crate::camera::{CameraModel, ImagePoint};
use crate::campaign::Readout;
use crate::hdr::{GroupGeometry, LuminanceMap};
use glam::DVec3;
use skylux_regmap::sun_values::{SunConfig, SunSums};
use skylux_regmap::words::grouped;

/// Units of the grouped word's luminance field per DN (`words::grouped::LUMA_FRAC_BITS`).
const Q14_PER_DN: f64 = (1u32 << grouped::LUMA_FRAC_BITS) as f64;
/// Groups between the fabric's box and the background ring, and the ring's outer edge: the
/// blurred limb lies just outside the box (as `SunSearch::default().dilation_groups`).
const RING_INNER_GROUPS: usize = 2;
const RING_OUTER_GROUPS: usize = 5;

/// The frame the accumulators saw: its integration time and analog gain.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct SunExposure {
    pub exposure_s: f64,
    pub gain: f64,
}

/// How the HPS sets the accumulators up for one capture.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct FabricSunSearch {
    /// Groups at or above this luminance count (cd/m²; scaled as `SunSearch` scales it for
    /// groups larger than the disk).
    pub threshold_cd_m2: f64,
    /// Where the sun should be (solar position and camera orientation).
    pub predicted_direction: DVec3,
    /// Half the search window's side, groups.
    pub window_half_groups: u16,
}

/// The sun as the accumulators measured it.
#[derive(Clone, Debug, PartialEq)]
pub struct FabricSun {
    /// Unit vector towards the sun (world frame): the luminance-weighted centroid's direction.
    pub direction: DVec3,
    /// Mean luminance over the solar disk, cd/m²; NaN when saturated.
    pub disk_luminance_cd_m2: f64,
    /// Direct-normal illuminance the disk implies, lux; NaN when saturated.
    pub direct_normal_illuminance_lux: f64,
    /// Circumsolar background subtracted, cd/m².
    pub background_cd_m2: f64,
    /// Groups that counted.
    pub groups: u32,
    pub flags: Vec<SunFlag>,
}

/// The full-array position of a (fractional) group coordinate's centre: groups lie 2·skip
/// pixels apart and a group's centre is `bin` pixels right of (below) its first column (row),
/// as `GroupGeometry` places them (`Readout::group_centre`).
fn group_centre_px(readout: &Readout, gx: f64, gy: f64) -> ImagePoint {
    let step = 2.0 * readout.skip as f64;
    let offset = f64::from(readout.bin.max(1));
    ImagePoint {
        x_px: readout.col_start as f64 + step * gx + offset,
        y_px: readout.row_start as f64 + step * gy + offset,
    }
}

/// Luminance per DN and a group's solid angle where `p` lands, or `None` outside the lens.
fn calibration_at(
    camera: &CameraModel,
    readout: &Readout,
    exposure: &SunExposure,
    p: ImagePoint,
) -> Option<(DVec3, f64, f64)> {
    let direction = camera.unproject(p)?;
    let vignetting = camera.vignetting(camera.off_axis_rad(direction));
    let omega_px2 = camera.solid_angle_per_px2(p)?;
    let tg = exposure.exposure_s * exposure.gain;
    if !(vignetting > 0.0 && tg > 0.0) {
        return None;
    }
    let cd_m2_per_dn = camera.config.response.cg / tg / vignetting;
    let group_sr = omega_px2 * (2.0 * readout.skip as f64).powi(2);
    Some((direction, cd_m2_per_dn, group_sr))
}

impl FabricSunSearch {
    /// The accumulators' settings for frames of `groups` = (width, height) groups.
    pub fn config(
        &self,
        camera: &CameraModel,
        readout: &Readout,
        groups: (usize, usize),
        exposure: &SunExposure,
    ) -> Result<SunConfig, NoSun> {
        let (width, height) = groups;
        let p = camera
            .project(self.predicted_direction)
            .ok_or(NoSun::OutsideFieldOfView)?;
        let step = 2.0 * readout.skip as f64;
        let offset = f64::from(readout.bin.max(1));
        let gx = ((p.x_px - readout.col_start as f64 - offset) / step).round();
        let gy = ((p.y_px - readout.row_start as f64 - offset) / step).round();
        let half = f64::from(self.window_half_groups);
        let (w, h) = (width as f64, height as f64);
        if width == 0
            || height == 0
            || gx + half < 0.0
            || gy + half < 0.0
            || gx - half >= w
            || gy - half >= h
        {
            return Err(NoSun::OutsideFieldOfView);
        }
        let (_, cd_m2_per_dn, group_sr) =
            calibration_at(camera, readout, exposure, p).ok_or(NoSun::OutsideFieldOfView)?;
        let threshold_cd_m2 = self.threshold_cd_m2 * (SOLAR_DISK_SR / group_sr).min(1.0);
        let threshold_q14 = (threshold_cd_m2 / cd_m2_per_dn * Q14_PER_DN)
            .ceil()
            .clamp(1.0, grouped::LUMA_MAX_Q14 as f64) as u32;
        let clamp = |v: f64, n: f64| v.clamp(0.0, n - 1.0) as u16;
        Ok(SunConfig {
            groups_per_line: width.min(2047) as u16,
            threshold_q14,
            x_min: clamp(gx - half, w),
            x_max: clamp(gx + half, w),
            y_min: clamp(gy - half, h),
            y_max: clamp(gy + half, h),
        })
    }
}

/// The circumsolar background around the box the accumulators report: the median of a ring
/// of the map (2 to 5 groups outside it).
pub fn fabric_background_cd_m2(
    map: &LuminanceMap,
    geometry: &GroupGeometry,
    sums: &SunSums,
) -> f64 {
    let bbox = GroupBox {
        min_x: usize::from(sums.min_x),
        max_x: usize::from(sums.max_x),
        min_y: usize::from(sums.min_y),
        max_y: usize::from(sums.max_y),
    };
    ring_median_cd_m2(map, geometry, &bbox, RING_INNER_GROUPS, RING_OUTER_GROUPS)
}

/// The sun from the accumulators' sums, with the same flags as `extract_sun` where the sums
/// can tell (saturated, partly covered).
pub fn sun_from_fabric(
    sums: &SunSums,
    search: &FabricSunSearch,
    camera: &CameraModel,
    readout: &Readout,
    exposure: &SunExposure,
    background_cd_m2: f64,
) -> Result<FabricSun, NoSun> {
    let Some((cx, cy)) = sums.centroid().filter(|_| sums.count > 0) else {
        return Err(NoSun::BelowThreshold {
            threshold_cd_m2: search.threshold_cd_m2,
        });
    };
    let p = group_centre_px(readout, cx, cy);
    let (direction, cd_m2_per_dn, group_sr) =
        calibration_at(camera, readout, exposure, p).ok_or(NoSun::OutsideFieldOfView)?;
    let background = if background_cd_m2.is_finite() {
        background_cd_m2.max(0.0)
    } else {
        0.0
    };
    let sum_dn = sums.sum_l as f64 / Q14_PER_DN;
    let flux = (sum_dn * cd_m2_per_dn - background * f64::from(sums.count)) * group_sr;
    let peak = sums.max_l as f64 / Q14_PER_DN * cd_m2_per_dn - background;
    let mut flags = vec![];
    let saturated = sums.over_count > 0;
    if saturated {
        flags.push(SunFlag::Saturated);
    } else if peak > 0.0 && flux / peak < 0.6 * SOLAR_DISK_SR {
        // The rule and its reason are `extract_sun`'s.
        flags.push(SunFlag::PartlyCovered);
    }
    let (disk, dni) = if saturated {
        (f64::NAN, f64::NAN)
    } else {
        (flux / SOLAR_DISK_SR, flux)
    };
    Ok(FabricSun {
        direction,
        disk_luminance_cd_m2: disk,
        direct_normal_illuminance_lux: dni,
        background_cd_m2: background,
        groups: sums.count,
        flags,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::{direction_from_alt_az, DeviceConfig};

    fn setup() -> (CameraModel, Readout, SunExposure) {
        let camera = CameraModel::new(DeviceConfig::default());
        let readout = Readout {
            col_start: 0,
            row_start: 0,
            skip: 1,
            bin: 1,
        };
        let exposure = SunExposure {
            exposure_s: 1e-6,
            gain: 1.0,
        };
        (camera, readout, exposure)
    }

    #[test]
    fn the_window_is_centred_on_the_prediction_and_the_threshold_is_in_dn() {
        let (camera, readout, exposure) = setup();
        // The default camera faces south, 16° up: a sun there lands near the centre.
        let search = FabricSunSearch {
            threshold_cd_m2: 1e7,
            predicted_direction: direction_from_alt_az(16.0, 180.0),
            window_half_groups: 10,
        };
        let c = search
            .config(&camera, &readout, (1296, 972), &exposure)
            .unwrap();
        assert_eq!(c.groups_per_line, 1296);
        assert_eq!(c.x_max - c.x_min, 20);
        assert_eq!(c.y_max - c.y_min, 20);
        assert!((c.x_min + 10).abs_diff(648) <= 1 && (c.y_min + 10).abs_diff(486) <= 1);
        // 1e7 cd/m² at 1 µs, c_g 1, no vignetting: 10 DN.
        assert_eq!(c.threshold_q14, 10 * 16384);
    }

    #[test]
    fn a_prediction_outside_the_frame_or_the_lens_is_refused() {
        let (camera, readout, exposure) = setup();
        let mut search = FabricSunSearch {
            threshold_cd_m2: 1e7,
            predicted_direction: direction_from_alt_az(16.0, 180.0),
            window_half_groups: 10,
        };
        // A small window far from where the sun lands.
        assert_eq!(
            search.config(&camera, &readout, (100, 100), &exposure),
            Err(NoSun::OutsideFieldOfView)
        );
        search.predicted_direction = direction_from_alt_az(-30.0, 0.0);
        assert_eq!(
            search.config(&camera, &readout, (1296, 972), &exposure),
            Err(NoSun::OutsideFieldOfView)
        );
    }

    #[test]
    fn empty_and_saturated_sums_are_reported() {
        let (camera, readout, exposure) = setup();
        let search = FabricSunSearch {
            threshold_cd_m2: 1e7,
            predicted_direction: direction_from_alt_az(16.0, 180.0),
            window_half_groups: 10,
        };
        let none = sun_from_fabric(
            &SunSums::default(),
            &search,
            &camera,
            &readout,
            &exposure,
            0.0,
        );
        assert_eq!(
            none,
            Err(NoSun::BelowThreshold {
                threshold_cd_m2: 1e7
            })
        );
        let sums = SunSums {
            count: 9,
            over_count: 2,
            sum_l: 9 * 3000 * 16384,
            sum_xl: 9 * 3000 * 16384 * 648,
            sum_yl: 9 * 3000 * 16384 * 486,
            max_l: 3000 * 16384,
            min_x: 647,
            max_x: 649,
            min_y: 485,
            max_y: 487,
        };
        let s = sun_from_fabric(&sums, &search, &camera, &readout, &exposure, 0.0).unwrap();
        assert_eq!(s.flags, vec![SunFlag::Saturated]);
        assert!(s.disk_luminance_cd_m2.is_nan());
        assert!(
            s.direction
                .angle_between(search.predicted_direction)
                .to_degrees()
                < 0.2
        );
    }
}
