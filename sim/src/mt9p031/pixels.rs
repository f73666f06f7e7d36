//! Pixel values of the model's frames: the scene through the one camera model and sensor
//! noise model (`crate::sensor::FrameRenderer`), then the sensor's mirroring.

use super::frame::FrameSettings;
use crate::sensor::{ChannelResponse, Footprint, FrameRenderer, Noise};
use glam::DVec3;
use skylux_hps::camera::CameraModel;
use skylux_hps::campaign::{BayerPattern, RawFrame, Readout};

/// Where a frame's samples come from.
pub trait PixelSource {
    /// The samples of one frame in read-out order (mirroring applied), `frame_index` counting
    /// the frames the sensor has produced.
    fn frame(&mut self, settings: &FrameSettings, pixclk_hz: f64, frame_index: u64) -> RawFrame;
}

/// A frame flipped as the sensor reads it with Mirror_Row / Mirror_Column: the Bayer phase
/// follows (GRBG unmirrored; RGGB, BGGR, GBRG mirrored by column, row, both:
/// hardware-facts.md §1.1, S6), because the window has even width and height.
pub fn mirror(frame: &RawFrame, mirror_row: bool, mirror_column: bool) -> RawFrame {
    let (w, h) = (frame.width, frame.height);
    let samples_dn = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let sx = if mirror_column { w - 1 - x } else { x };
            let sy = if mirror_row { h - 1 - y } else { y };
            frame.samples_dn[sy * w + sx]
        })
        .collect();
    RawFrame {
        width: w,
        height: h,
        samples_dn,
    }
}

/// A luminance field imaged through a camera, with the sensor's noise.
pub struct SceneSource {
    pub camera: CameraModel,
    pub luminance_cd_m2: Box<dyn Fn(DVec3) -> f64 + Sync + Send>,
    /// Noise seed; each frame uses `seed + frame_index`. `None`: no noise.
    pub noise_seed: Option<u64>,
    /// Each channel's response to the scene's spectrum ([`ChannelResponse::GREY`]: a
    /// spectrally grey scene, or the device's calibration spectrum).
    pub channel_response: ChannelResponse,
    /// Sources smaller than a group (the solar disk) that binned groups must not miss
    /// (`crate::sensor::SmallSource`).
    pub small_sources: Vec<crate::sensor::SmallSource>,
}

impl PixelSource for SceneSource {
    fn frame(&mut self, settings: &FrameSettings, pixclk_hz: f64, frame_index: u64) -> RawFrame {
        let g = &settings.geometry;
        // Column_Bin 0, 1, 3: 1x, 2x, 4x (hardware-facts.md §1, register 0x23). A binned
        // sample is the mean of its bin x bin pixels; unbinned, the field at the group.
        let bin = g.col_bin + 1;
        let renderer = FrameRenderer {
            camera: &self.camera,
            readout: Readout {
                col_start: g.col_start,
                row_start: g.row_start,
                skip: g.col_skip,
                bin,
            },
            raw_width: g.width as usize,
            raw_height: g.height as usize,
            footprint: if bin > 1 {
                Footprint::AsRead
            } else {
                Footprint::Centre
            },
            small_sources: self.small_sources.clone(),
        };
        let noise = match self.noise_seed {
            Some(seed) => Noise::Sensor {
                seed: seed.wrapping_add(frame_index),
            },
            None => Noise::None,
        };
        let exposure_s = settings.exposure_pixclk as f64 / pixclk_hz;
        // Start addresses are even (the datasheet requires it, the driver refuses odd ones), so
        // the array reads GRBG (hardware-facts.md §1.1); mirroring below moves the phase.
        let raw = renderer.render_scene_spectral(
            &renderer.scene(&*self.luminance_cd_m2),
            exposure_s,
            settings.gain,
            noise,
            &self.channel_response,
            BayerPattern::GRBG,
        );
        mirror(&raw, settings.mirror_row, settings.mirror_column)
    }
}

/// A fixed test pattern (`x + 16 y` modulo 4096, per frame offset by the frame index): for
/// tests of the pixel path that need known values, not a scene.
pub struct RampSource;

impl PixelSource for RampSource {
    fn frame(&mut self, settings: &FrameSettings, _pixclk_hz: f64, frame_index: u64) -> RawFrame {
        let (w, h) = (
            settings.geometry.width as usize,
            settings.geometry.height as usize,
        );
        let raw = RawFrame {
            width: w,
            height: h,
            samples_dn: (0..w * h)
                .map(|i| ((i % w + 16 * (i / w) + frame_index as usize) % 4096) as u16)
                .collect(),
        };
        mirror(&raw, settings.mirror_row, settings.mirror_column)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Bayer phase after mirroring, from a 2x2 GRBG tile (hardware-facts.md §1.1).
    #[test]
    fn mirroring_moves_the_bayer_phase_as_the_sensor_does() {
        // 1 = Gr, 2 = R, 3 = B, 4 = Gb.
        let tile = RawFrame {
            width: 2,
            height: 2,
            samples_dn: vec![1, 2, 3, 4],
        };
        let cases = [
            (false, false, [1, 2, 3, 4]), // GRBG
            (false, true, [2, 1, 4, 3]),  // RGGB
            (true, false, [3, 4, 1, 2]),  // BGGR
            (true, true, [4, 3, 2, 1]),   // GBRG
        ];
        for (row, col, want) in cases {
            assert_eq!(
                mirror(&tile, row, col).samples_dn,
                want,
                "row {row} col {col}"
            );
        }
    }

    /// Binning (registers 0x22/0x23 = 0x0011: skip 2, bin 2) keeps the mean signal of a
    /// uniform scene and averages four pixels' shot noise: half the unbinned spread.
    #[test]
    fn binned_samples_keep_the_mean_and_average_the_shot_noise() {
        use skylux_hps::camera::DeviceConfig;
        let mut source = SceneSource {
            camera: CameraModel::new(DeviceConfig::default()),
            luminance_cd_m2: Box::new(|_| 1.0e6),
            noise_seed: Some(7),
            channel_response: ChannelResponse::GREY,
            small_sources: vec![],
        };
        let frame_with = |bin_field: u32| FrameSettings {
            geometry: super::super::timing::FrameGeometry {
                width: 200,
                height: 200,
                col_start: 1000,
                row_start: 800,
                col_skip: 2,
                row_skip: 2,
                row_bin: bin_field,
                col_bin: bin_field,
                hb: 500,
                vb: 9,
            },
            shutter_width_rows: 10,
            exposure_pixclk: 96_000, // 1 ms at 96 MHz: about 1000 DN
            gain: 1.0,
            mirror_row: false,
            mirror_column: false,
        };
        let stats = |f: &RawFrame| {
            let v: Vec<f64> = f.samples_dn.iter().map(|&d| f64::from(d)).collect();
            let mean = v.iter().sum::<f64>() / v.len() as f64;
            let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (v.len() - 1) as f64;
            (mean, var.sqrt())
        };
        let (m1, s1) = stats(&source.frame(&frame_with(0), 96e6, 0));
        let (m2, s2) = stats(&source.frame(&frame_with(1), 96e6, 0));
        assert!(m1 > 500.0 && m1 < 3000.0, "{m1}");
        assert!(
            (m2 / m1 - 1.0).abs() < 0.01,
            "mean {m1} unbinned, {m2} binned"
        );
        // Shot noise dominates the 2 DN read noise at these levels: the spread halves.
        let ratio = s2 / s1;
        assert!(
            (0.45..0.6).contains(&ratio),
            "spread {s1} unbinned, {s2} binned: {ratio}"
        );
    }
}
