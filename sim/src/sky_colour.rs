//! The sky's real colour, for the spectral-mismatch effect of simulated campaigns
//! (`skylux sim campaign --effect spectral_mismatch=CCT_K`).
//!
//! Each direction's spectrum is a CIE daylight (CIE 15:2004 §3.1) at a correlated colour
//! temperature that depends on the sky:
//!
//! - a clear (or partly cloudy) sky is bluest away from the sun and whitest around it:
//!   measured clear skies run from some 6,000 K in the circumsolar region to 10,000-20,000 K
//!   and more at large angles from the sun (Hernández-Andrés, Romero, Lee, "Colorimetric and
//!   spectroradiometric characteristics of narrow-field-of-view clear skylight in Granada,
//!   Spain", JOSA A 18 (2001) 412-420; Chain, Dumortier, Fontoynont, "Consideration of
//!   daylight's colour", Energy and Buildings 33 (2001) 193-198). Here the reciprocal CCT
//!   (mired) goes from the circumsolar 6,000 K to the campaign's `CCT_K` with the angle γ
//!   from the sun as `exp(−γ / 25°)`;
//! - the sun's beam reddens with air mass (Rayleigh scattering): 5,700 K plus 20 mired per
//!   air mass above one (about 5,600 K at 60° altitude, 4,700 K at 20°), never below 4,000 K
//!   (reached below some 14°);
//! - an overcast sky is taken at D65 (overcast skies sit near 6,500 K; same sources), and so
//!   is the grey ground lit by the global daylight: both are the calibration spectrum.
//!
//! The camera's channels respond through the measured Nikon D5100 sensitivities
//! (`shared/data/spectral`, the stand-in for the MT9P031's) while `device.toml` keeps the
//! weights and `cg` calibrated under D65: each channel gives `rel_c` times its calibrated
//! signal ([`ChannelResponse`]), and the lux-meters (ideal V(λ)) see the true light.

use crate::capture::{CaptureSpec, WriteCaptureError};
use crate::sensor::spectral::{cie_daylight, ChannelResponse, SpectralData};
use crate::sensor::Noise;
use glam::DVec3;
use skylux_hps::camera::CameraModel;
use skylux_hps::campaign::{BayerPattern, CaptureConfig, RawFrame};
use skylux_hps::photometry::spectral::{load_d65, SpectralError};
use std::path::Path;

/// Circumsolar sky's colour temperature, K.
pub const CIRCUMSOLAR_CCT_K: f64 = 6000.0;
/// Angular scale of the sky's whitening towards the sun, degrees.
pub const CIRCUMSOLAR_SCALE_DEG: f64 = 25.0;
/// The sun's colour temperature at air mass 1, K.
pub const SUN_ZENITH_CCT_K: f64 = 5700.0;
/// The sun's reddening, mired per unit of air mass above one.
pub const SUN_MIRED_PER_AIR_MASS: f64 = 20.0;

/// Mired grid of the response table: 40 (25,000 K) to 250 (4,000 K).
const MIRED_RANGE: (f64, f64) = (40.0, 250.0);
const MIRED_STEP: f64 = 0.5;

/// The camera's channel responses to CIE daylights, tabulated in mired.
#[derive(Clone, Debug)]
pub struct DaylightResponses {
    table: Vec<ChannelResponse>,
}

impl DaylightResponses {
    /// The Nikon D5100 channels against CIE daylights, for a device calibrated under D65.
    pub fn load(data_dir: &Path) -> Result<Self, SpectralError> {
        let data = SpectralData::load(data_dir)?;
        let d65 = load_d65(data_dir)?;
        let n = ((MIRED_RANGE.1 - MIRED_RANGE.0) / MIRED_STEP).round() as usize;
        let table = (0..=n)
            .map(|i| {
                let mired = MIRED_RANGE.0 + MIRED_STEP * i as f64;
                ChannelResponse::of(
                    &data,
                    &cie_daylight(&data.daylight_basis, 1e6 / mired),
                    &d65,
                )
            })
            .collect();
        Ok(Self { table })
    }

    /// The response to CIE daylight at `cct_k` (clamped to 4,000-25,000 K), linear in mired.
    pub fn at(&self, cct_k: f64) -> ChannelResponse {
        let mired = (1e6 / cct_k).clamp(MIRED_RANGE.0, MIRED_RANGE.1);
        let u = (mired - MIRED_RANGE.0) / MIRED_STEP;
        let i = (u.floor() as usize).min(self.table.len() - 2);
        let f = u - i as f64;
        let (a, b) = (self.table[i].relative, self.table[i + 1].relative);
        ChannelResponse {
            relative: std::array::from_fn(|c| a[c] + f * (b[c] - a[c])),
        }
    }
}

/// The world's spectral mismatch as a straight line: the camera's relative luminance error
/// against its blue / red colour index (both relative to the D65 calibration), least squares
/// over CIE daylights of 5,000 to 20,000 K in 500 K steps (CIE 15:2004 §3.1), for a device
/// with channel `weights`. The truth the spectral-mismatch effect's fitted slope is judged
/// against, by the loop's tests and `skylux bench loop`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MismatchLine {
    /// d(error) / d(index).
    pub slope_per_index: f64,
    /// Mean colour index of the daylights.
    pub mean_index: f64,
    /// Mean relative luminance error at that index.
    pub mean_error: f64,
}

impl MismatchLine {
    pub fn of_daylights(data_dir: &Path, weights: [f64; 3]) -> Result<Self, SpectralError> {
        let data = SpectralData::load(data_dir)?;
        let d65 = load_d65(data_dir)?;
        let points: Vec<(f64, f64)> = (0..=30)
            .map(|i| {
                let daylight = cie_daylight(&data.daylight_basis, 5000.0 + 500.0 * i as f64);
                let r = ChannelResponse::of(&data, &daylight, &d65);
                (r.relative[2] / r.relative[0], r.luminance_error(weights))
            })
            .collect();
        let n = points.len() as f64;
        let (mx, my) = points
            .iter()
            .fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
        let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), p| {
            (a + (p.0 - mx) * (p.1 - my), b + (p.0 - mx).powi(2))
        });
        Ok(Self {
            slope_per_index: sxy / sxx,
            mean_index: mx,
            mean_error: my,
        })
    }

    /// The error the line gives at the calibration's own index, 1.
    pub fn error_at_calibration(&self) -> f64 {
        self.mean_error - self.slope_per_index * (self.mean_index - 1.0)
    }
}

/// The colour of one capture's sky.
#[derive(Clone, Copy, Debug)]
pub struct SkyColour {
    /// Clear-sky colour temperature far from the sun, K; `None`: an overcast sky (D65).
    pub clear_sky_cct_k: Option<f64>,
    pub sun_direction: DVec3,
    /// Cosine of the sun disk's angular radius.
    pub sun_cos_half: f64,
    /// Whether the sun disk is in the field (the direct beam is not blocked).
    pub sun_visible: bool,
}

impl SkyColour {
    /// The sun's colour temperature, K.
    pub fn sun_cct_k(&self) -> f64 {
        let air_mass = 1.0 / self.sun_direction.z.max(0.05);
        1e6 / (1e6 / SUN_ZENITH_CCT_K + SUN_MIRED_PER_AIR_MASS * (air_mass - 1.0)).min(250.0)
    }

    /// The colour temperature of direction `d`; `None` for the calibration spectrum (ground,
    /// overcast sky).
    pub fn cct_k(&self, d: DVec3) -> Option<f64> {
        if d.z < 0.0 {
            return None;
        }
        let clear = self.clear_sky_cct_k?;
        if self.sun_visible && d.dot(self.sun_direction) >= self.sun_cos_half {
            return Some(self.sun_cct_k());
        }
        let gamma_deg = d
            .dot(self.sun_direction)
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees();
        let near = (-gamma_deg / CIRCUMSOLAR_SCALE_DEG).exp();
        let mired = 1e6 / clear + (1e6 / CIRCUMSOLAR_CCT_K - 1e6 / clear) * near;
        Some(1e6 / mired)
    }
}

/// Renders one HDR capture of `field` whose colour is `colour`, each channel through
/// `responses`, and writes it to `dir`; every frame integrates its declared time plus
/// `overhead_us` while `capture.toml` declares the time alone.
pub fn simulate_capture_coloured(
    dir: &Path,
    camera: &CameraModel,
    field: &(dyn Fn(DVec3) -> f64 + Sync),
    colour: &SkyColour,
    responses: &DaylightResponses,
    spec: &CaptureSpec,
    overhead_us: f64,
) -> Result<CaptureConfig, WriteCaptureError> {
    let renderer = spec.renderer(camera);
    let gain_of = |d: DVec3, c: usize| match colour.cct_k(d) {
        Some(t) => responses.at(t).relative[c],
        None => 1.0,
    };
    let scenes: [Vec<f64>; 3] =
        std::array::from_fn(|c| renderer.scene(&|d: DVec3| field(d) * gain_of(d, c)));
    let frames: Vec<RawFrame> = spec
        .exposures_us
        .iter()
        .enumerate()
        .map(|(k, &t)| {
            renderer.render_scene_channels(
                &scenes,
                (t + overhead_us) * 1e-6,
                spec.gain_of(k),
                Noise::Sensor {
                    seed: spec.seed.wrapping_add(k as u64),
                },
                BayerPattern::GRBG,
            )
        })
        .collect();
    crate::capture::write_spec_capture(dir, spec, &frames)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The clear sky is bluest far from the sun, whiter near it; the sun is redder low down;
    /// the ground and an overcast sky are the calibration spectrum.
    #[test]
    fn colour_temperatures_follow_the_sky() {
        let sun = DVec3::new(0.0, -0.5, 0.866).normalize();
        let c = SkyColour {
            clear_sky_cct_k: Some(15_000.0),
            sun_direction: sun,
            sun_cos_half: (0.27f64).to_radians().cos(),
            sun_visible: true,
        };
        let far = c.cct_k(DVec3::new(0.0, 1.0, 0.1).normalize()).unwrap();
        let near = c
            .cct_k((sun + DVec3::new(0.05, 0.0, 0.0)).normalize())
            .unwrap();
        assert!(far > 12_000.0 && far < 15_000.0, "{far}");
        assert!(near > 6000.0 && near < 8000.0, "{near}");
        let disk = c.cct_k(sun).unwrap();
        assert!((5500.0..5700.0).contains(&disk), "{disk}");
        assert!(c.cct_k(DVec3::new(0.0, 1.0, -0.2)).is_none());
        let low = SkyColour {
            sun_direction: DVec3::new(0.0, -0.985, 0.174),
            ..c
        };
        assert!(low.sun_cct_k() < 4500.0, "{}", low.sun_cct_k());
        let overcast = SkyColour {
            clear_sky_cct_k: None,
            ..c
        };
        assert!(overcast.cct_k(DVec3::Z).is_none());
    }

    /// Three equal channel scenes render the grey frame sample for sample (same noise
    /// streams); a bluer blue scene raises the blue samples alone.
    #[test]
    fn channel_scenes_reduce_to_the_grey_frame() {
        let camera = CameraModel::new(skylux_hps::camera::DeviceConfig::default());
        let renderer = crate::sensor::FrameRenderer {
            camera: &camera,
            readout: skylux_hps::campaign::Readout {
                col_start: 1200,
                row_start: 900,
                skip: 1,
                bin: 1,
            },
            raw_width: 64,
            raw_height: 48,
            footprint: crate::sensor::Footprint::Centre,
            small_sources: vec![],
        };
        let scene = renderer.scene(&|d: DVec3| 2000.0 + 1000.0 * d.z);
        let noise = Noise::Sensor { seed: 7 };
        let grey = renderer.render_scene(&scene, 1e-3, 1.0, noise);
        let same = [scene.clone(), scene.clone(), scene.clone()];
        let channels = renderer.render_scene_channels(&same, 1e-3, 1.0, noise, BayerPattern::GRBG);
        assert_eq!(grey.samples_dn, channels.samples_dn);
        let blue = [
            scene.clone(),
            scene.clone(),
            scene.iter().map(|v| 1.5 * v).collect(),
        ];
        let plain = renderer.render_scene(&scene, 0.4, 1.0, Noise::None);
        let b = renderer.render_scene_channels(&blue, 0.4, 1.0, Noise::None, BayerPattern::GRBG);
        let black = camera.config.sensor.black_level_dn;
        for (i, (g, c)) in plain.samples_dn.iter().zip(&b.samples_dn).enumerate() {
            let (x, y) = (i % 64, i / 64);
            let (g, c) = (f64::from(*g) - black, f64::from(*c) - black);
            match BayerPattern::GRBG.channel(x & 1, y & 1) {
                skylux_hps::campaign::Channel::Blue => {
                    assert!((c / g - 1.5).abs() < 0.002, "{c} {g}")
                }
                _ => assert_eq!(c, g),
            }
        }
    }
}
