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

use super::extract::{
    ring_median_cd_m2, ExtractedSun, GroupBox, NoSun, SunFlag, SunSearch, SOLAR_DISK_SR,
    SUNSHINE_THRESHOLD_CD_M2,
};
use crate::camera::{CameraModel, ImagePoint};
use crate::campaign::Readout;
use crate::hdr::{GroupGeometry, LuminanceMap, MapFlag};
use glam::DVec3;
use skylux_regmap::sun_values::{SunConfig, SunSums};
use skylux_regmap::words::grouped;

/// Units of the grouped word's luminance field per DN (`words::grouped::LUMA_FRAC_BITS`).
const Q14_PER_DN: f64 = (1u32 << grouped::LUMA_FRAC_BITS) as f64;
/// Groups between the fabric's box and the background ring, and the ring's outer edge: the
/// blurred limb lies just outside the box (as `SunSearch::default().dilation_groups`).
const RING_INNER_GROUPS: usize = 2;
const RING_OUTER_GROUPS: usize = 5;

/// The accumulators' threshold for a device's captures, cd/m²: a tenth of the HPS search's
/// sunshine threshold. The HPS takes the blurred limb in by dilating its component over the
/// map; the fabric sums only the groups at the threshold, so it must reach down into the limb
/// (at 1e7 the sums agree with `extract_sun` within 0.05° and 1 %,
/// tests/tests/sun_extraction.rs), and still be far above the circumsolar sky (1e5 to 1e6).
pub const FABRIC_THRESHOLD_CD_M2: f64 = SUNSHINE_THRESHOLD_CD_M2 / 10.0;

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
    /// The search a device makes around `predicted_direction`: [`FABRIC_THRESHOLD_CD_M2`] and
    /// a window reaching `max_offset_deg` from the prediction (as `SunSearch::max_offset_deg`
    /// bounds the HPS's search), from the lens's scale where the prediction lands; `None`
    /// when it lands outside the lens.
    pub fn around(
        predicted_direction: DVec3,
        max_offset_deg: f64,
        camera: &CameraModel,
        readout: &Readout,
    ) -> Option<Self> {
        let p = camera.project(predicted_direction)?;
        let px_per_rad = 1.0 / camera.solid_angle_per_px2(p)?.sqrt();
        let groups = max_offset_deg.to_radians() * px_per_rad / (2.0 * readout.skip.max(1) as f64);
        groups.is_finite().then(|| FabricSunSearch {
            threshold_cd_m2: FABRIC_THRESHOLD_CD_M2,
            predicted_direction,
            window_half_groups: groups.ceil().clamp(1.0, 2047.0) as u16,
        })
    }

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

/// Why the sums read back cannot be one frame's sums under `config`: the invariants every
/// frame's sums keep (`skylux_rtl::sun::golden`), checked before they are believed, since a
/// register read that went wrong would otherwise move the sun.
pub fn check_sums(config: &SunConfig, sums: &SunSums) -> Result<(), String> {
    let s = sums;
    if s.count == 0 {
        let empty = SunSums::default();
        return if *s == empty {
            Ok(())
        } else {
            Err(format!(
                "no group counted, yet the sums are not zero: {s:?}"
            ))
        };
    }
    let in_window = config.x_min <= s.min_x
        && s.min_x <= s.max_x
        && s.max_x <= config.x_max
        && config.y_min <= s.min_y
        && s.min_y <= s.max_y
        && s.max_y <= config.y_max;
    if !in_window {
        return Err(format!(
            "box x {}..={}, y {}..={} outside the window x {}..={}, y {}..={}",
            s.min_x,
            s.max_x,
            s.min_y,
            s.max_y,
            config.x_min,
            config.x_max,
            config.y_min,
            config.y_max
        ));
    }
    let area = (u64::from(s.max_x - s.min_x) + 1) * (u64::from(s.max_y - s.min_y) + 1);
    if u64::from(s.count) > area || s.over_count > s.count {
        return Err(format!(
            "{} groups ({} over-range) in a box of {area}",
            s.count, s.over_count
        ));
    }
    let (n, l) = (u128::from(s.count), u128::from(s.sum_l));
    if s.max_l < config.threshold_q14
        || l < n * u128::from(config.threshold_q14)
        || l > n * u128::from(s.max_l)
    {
        return Err(format!(
            "Σ L {} over {} groups with the largest {} and the threshold {}",
            s.sum_l, s.count, s.max_l, config.threshold_q14
        ));
    }
    // The centroid lies inside the box.
    let within = |sum: u64, lo: u16, hi: u16| {
        (u128::from(lo) * l..=u128::from(hi) * l).contains(&u128::from(sum))
    };
    if !within(s.sum_xl, s.min_x, s.max_x) || !within(s.sum_yl, s.min_y, s.max_y) {
        return Err(format!(
            "centroid (Σ xL {}, Σ yL {} over Σ L {}) outside the box",
            s.sum_xl, s.sum_yl, s.sum_l
        ));
    }
    Ok(())
}

impl FabricSun {
    /// The sun with the blurred limb the accumulators leave out: the map's groups around their
    /// box, out to the dilation `extract_sun` applies to its component, above the background,
    /// added to the flux and to the direction's weights. The accumulators count only the
    /// groups at their threshold; a disk smaller than its groups (the example's readout, skip
    /// 4) leaves a percent or so of its light in neighbours below it, which the map holds, from
    /// a longer exposure. A walk of a few dozen groups, not a scan. A saturated sun (no flux)
    /// is returned as it is.
    pub fn with_limb(
        mut self,
        map: &LuminanceMap,
        geometry: &GroupGeometry,
        sums: &SunSums,
    ) -> Self {
        let (w, h) = (map.width, map.height);
        let core = self.direct_normal_illuminance_lux;
        if sums.count == 0 || w == 0 || h == 0 || !core.is_finite() {
            return self;
        }
        let d = SunSearch::default().dilation_groups;
        let (x0, x1) = (usize::from(sums.min_x), usize::from(sums.max_x));
        let (y0, y1) = (usize::from(sums.min_y), usize::from(sums.max_y));
        let (mut flux, mut weighted) = (0.0, DVec3::ZERO);
        for y in y0.saturating_sub(d)..=(y1 + d).min(h - 1) {
            for x in x0.saturating_sub(d)..=(x1 + d).min(w - 1) {
                let i = y * w + x;
                let inside = (x0..=x1).contains(&x) && (y0..=y1).contains(&y);
                let direction = geometry.direction[i];
                if inside || !direction.is_finite() || map.flags[i] != MapFlag::Valid {
                    continue;
                }
                let excess = f64::from(map.luminance_cd_m2[i]) - self.background_cd_m2;
                let f = excess.max(0.0) * f64::from(geometry.solid_angle_sr[i]);
                if f.is_finite() {
                    flux += f;
                    weighted += direction.as_dvec3() * f;
                }
            }
        }
        if flux > 0.0 {
            self.direction = (self.direction * core.max(0.0) + weighted).normalize();
            self.direct_normal_illuminance_lux = core + flux;
            self.disk_luminance_cd_m2 = self.direct_normal_illuminance_lux / SOLAR_DISK_SR;
        }
        self
    }

    /// The sun as the model takes an extracted one: the groups it removes from the map are
    /// the accumulators' box dilated as `extract_sun` dilates its component (`SunSearch`'s
    /// default), inside a `width` x `height` map.
    pub fn into_extracted(self, sums: &SunSums, width: usize, height: usize) -> ExtractedSun {
        let d = SunSearch::default().dilation_groups;
        let mut groups = vec![];
        if width > 0 && height > 0 && sums.count > 0 {
            let (x0, y0) = (usize::from(sums.min_x), usize::from(sums.min_y));
            let (x1, y1) = (usize::from(sums.max_x), usize::from(sums.max_y));
            for y in y0.saturating_sub(d)..=(y1 + d).min(height - 1) {
                for x in x0.saturating_sub(d)..=(x1 + d).min(width - 1) {
                    groups.push(y * width + x);
                }
            }
        }
        ExtractedSun {
            direction: self.direction,
            disk_luminance_cd_m2: self.disk_luminance_cd_m2,
            direct_normal_illuminance_lux: self.direct_normal_illuminance_lux,
            background_cd_m2: self.background_cd_m2,
            groups,
            flags: self.flags,
        }
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

    /// Sums of a 3 x 2 disk at (10..=12, 20..=21), worked out by hand: 2000 Q14 per group, one
    /// group 3000.
    fn disk() -> (SunConfig, SunSums) {
        let config = SunConfig {
            groups_per_line: 64,
            threshold_q14: 1000,
            x_min: 5,
            x_max: 20,
            y_min: 15,
            y_max: 30,
        };
        let mut sums = SunSums::default();
        for (i, (x, y)) in [(10, 20), (11, 20), (12, 20), (10, 21), (11, 21), (12, 21)]
            .into_iter()
            .enumerate()
        {
            let l: u64 = if i == 4 { 3000 } else { 2000 };
            sums.count += 1;
            sums.sum_l += l;
            sums.sum_xl += x * l;
            sums.sum_yl += y * l;
            sums.max_l = sums.max_l.max(l as u32);
        }
        (sums.min_x, sums.max_x, sums.min_y, sums.max_y) = (10, 12, 20, 21);
        (config, sums)
    }

    #[test]
    fn sums_a_frame_can_give_pass_and_garbage_is_named() {
        let (config, sums) = disk();
        assert_eq!(check_sums(&config, &sums), Ok(()));
        assert_eq!(check_sums(&config, &SunSums::default()), Ok(()));
        let bad = |f: &dyn Fn(&mut SunSums)| {
            let mut s = sums;
            f(&mut s);
            check_sums(&config, &s).unwrap_err()
        };
        // All ones, as a block that answers garbage reads.
        let garbage = SunSums {
            count: (1 << 21) - 1,
            over_count: (1 << 21) - 1,
            sum_l: u64::MAX,
            sum_xl: u64::MAX,
            sum_yl: u64::MAX,
            max_l: (1 << 30) - 1,
            min_x: 2047,
            max_x: 2047,
            min_y: 2047,
            max_y: 2047,
        };
        assert!(check_sums(&config, &garbage)
            .unwrap_err()
            .contains("outside the window"));
        assert!(bad(&|s| s.count = 7).contains("in a box of 6"));
        assert!(bad(&|s| s.over_count = 7).contains("7 over-range"));
        assert!(bad(&|s| s.max_l = 999).contains("the threshold 1000"));
        assert!(bad(&|s| s.sum_l = 5999).contains("Σ L 5999"));
        assert!(bad(&|s| s.sum_l = 6 * 3000 + 1).contains("Σ L"));
        assert!(bad(&|s| s.sum_xl = 9 * s.sum_l).contains("centroid"));
        assert!(bad(&|s| s.sum_yl = 22 * s.sum_l).contains("centroid"));
        assert!(bad(&|s| s.min_x = 13).contains("outside the window"));
        let none_but_sums = SunSums {
            sum_l: 5,
            ..SunSums::default()
        };
        assert!(check_sums(&config, &none_but_sums)
            .unwrap_err()
            .contains("no group counted"));
    }

    #[test]
    fn the_extracted_sun_removes_the_dilated_box_inside_the_map() {
        let (_, sums) = disk();
        let sun = FabricSun {
            direction: DVec3::Z,
            disk_luminance_cd_m2: 1e9,
            direct_normal_illuminance_lux: 1e9 * SOLAR_DISK_SR,
            background_cd_m2: 1e4,
            groups: sums.count,
            flags: vec![],
        };
        // Box 10..=12 x 20..=21 dilated by 2: 8..=14 x 18..=23, cut at the map's last row 22.
        let e = sun.clone().into_extracted(&sums, 64, 23);
        assert_eq!(e.groups.len(), 7 * 5);
        assert!(e.groups.contains(&(18 * 64 + 8)) && e.groups.contains(&(22 * 64 + 14)));
        assert!(e.groups.iter().all(|&i| i < 64 * 23));
        assert_eq!(
            (e.direction, e.background_cd_m2, e.flags),
            (sun.direction, sun.background_cd_m2, sun.flags.clone())
        );
        assert!(sun
            .into_extracted(&SunSums::default(), 64, 23)
            .groups
            .is_empty());
    }

    #[test]
    fn the_search_around_a_prediction_spans_its_offset_in_groups() {
        let (camera, readout, _) = setup();
        let predicted = direction_from_alt_az(16.0, 180.0);
        let s = FabricSunSearch::around(predicted, 12.0, &camera, &readout).unwrap();
        assert_eq!(s.threshold_cd_m2, FABRIC_THRESHOLD_CD_M2);
        // The default lens near its axis: focal_px pixels a radian, groups of 2 pixels.
        let expected = 12f64.to_radians() * camera.config.lens.focal_px / 2.0;
        assert!(
            (f64::from(s.window_half_groups) - expected).abs() <= 2.0,
            "{} vs {expected}",
            s.window_half_groups
        );
        let skipped = Readout { skip: 4, ..readout };
        let coarse = FabricSunSearch::around(predicted, 12.0, &camera, &skipped).unwrap();
        assert!(coarse.window_half_groups.abs_diff(s.window_half_groups / 4) <= 1);
        assert!(FabricSunSearch::around(-predicted, 12.0, &camera, &readout).is_none());
    }

    #[test]
    fn the_limb_around_the_box_is_added_from_the_map() {
        let (_, sums) = disk();
        // A 64 x 32 map looking straight up, groups of 1e-5 sr: the box (10..=12, 20..=21)
        // at 1e9, one limb group right of it at 1e7, one three groups out (beyond the
        // dilation) at 1e8, the sky at 1e4.
        let (w, h) = (64, 32);
        let direction: Vec<glam::Vec3> = (0..w * h)
            .map(|i| {
                glam::Vec3::new((i % w) as f32 - 32.0, (i / w) as f32 - 16.0, 300.0).normalize()
            })
            .collect();
        let geometry = GroupGeometry {
            width: w,
            height: h,
            direction,
            inverse_vignetting: vec![1.0; w * h],
            solid_angle_sr: vec![1e-5; w * h],
            fill_factor: 1.0,
        };
        let mut map = LuminanceMap {
            width: w,
            height: h,
            luminance_cd_m2: vec![1e4; w * h],
            flags: vec![MapFlag::Valid; w * h],
            relative_sigma: vec![0.01; w * h],
        };
        map.luminance_cd_m2[20 * w + 13] = 1e7;
        map.luminance_cd_m2[20 * w + 15] = 1e8;
        let sun = FabricSun {
            direction: geometry.direction[20 * w + 11].as_dvec3(),
            disk_luminance_cd_m2: 6.0 * 1e9 * 1e-5 / SOLAR_DISK_SR,
            direct_normal_illuminance_lux: 6.0 * 1e9 * 1e-5,
            background_cd_m2: 1e4,
            groups: sums.count,
            flags: vec![],
        };
        let with = sun.clone().with_limb(&map, &geometry, &sums);
        // The map's solid angles are f32.
        let limb = (1e7 - 1e4) * f64::from(1e-5f32);
        assert!(
            (with.direct_normal_illuminance_lux - (sun.direct_normal_illuminance_lux + limb)).abs()
                < 1e-9
        );
        assert!(
            (with.disk_luminance_cd_m2 * SOLAR_DISK_SR - with.direct_normal_illuminance_lux).abs()
                < 1e-9
        );
        // Towards the limb group, by its share of the flux.
        let towards = geometry.direction[20 * w + 13].as_dvec3();
        assert!(with.direction.angle_between(towards) < sun.direction.angle_between(towards));
        // A saturated sun has no flux to add to.
        let saturated = FabricSun {
            direct_normal_illuminance_lux: f64::NAN,
            disk_luminance_cd_m2: f64::NAN,
            flags: vec![SunFlag::Saturated],
            ..sun.clone()
        };
        let same = saturated.clone().with_limb(&map, &geometry, &sums);
        assert_eq!(same.direction, saturated.direction);
        assert!(same.direct_normal_illuminance_lux.is_nan());
    }
}
