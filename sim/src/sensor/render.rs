//! Rendering raw frames from a known luminance field.
//!
//! Each 2x2 Bayer group images the field in the direction of its centre (the camera model's
//! inverse map), so the truth of a group is one number. A spectrally grey scene gives every
//! channel the black-subtracted mean signal `x = L t g V(α) / (cg Σw)`, which makes the
//! device's response `L = cg (w · RGB) / (t g V)` exact; another spectrum scales each
//! channel by its response (`spectral.rs`, `render_scene_spectral`). Noise per sample: Poisson shot noise
//! on `x / (K g)` electrons (times bin² for a binned sample, then averaged) (K: DN per electron at unity gain), Gaussian read noise, then the
//! black level, rounding to whole DN and clipping to 12 bits.

use super::spectral::ChannelResponse;
use glam::DVec3;
use rand_distr::{Distribution, Normal, Poisson};
use rayon::prelude::*;
use skylux_hps::camera::{CameraModel, ImagePoint};
use skylux_hps::campaign::{BayerPattern, RawFrame, Readout, MAX_SAMPLE_DN};
use skylux_hps::hdr::Samples;

/// Which noise to add.
#[derive(Copy, Clone, Debug, PartialEq)]
pub enum Noise {
    /// Shot noise, read noise and quantisation, from the device's `[noise]` model.
    Sensor { seed: u64 },
    /// None at all: samples are the exact expected values (see [`AnalogFrame`]).
    None,
}

/// A frame of unquantised, noiseless samples (DN as real numbers, black level included,
/// unclipped): what an ideal ADC would read.
#[derive(Clone, Debug)]
pub struct AnalogFrame {
    pub width: usize,
    pub height: usize,
    pub samples_dn: Vec<f64>,
}

impl Samples for AnalogFrame {
    type Sample = f64;
    fn width(&self) -> usize {
        self.width
    }
    fn height(&self) -> usize {
        self.height
    }
    fn row(&self, y: usize) -> &[f64] {
        &self.samples_dn[y * self.width..(y + 1) * self.width]
    }
}

/// How a group integrates the field over its footprint.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum Footprint {
    /// The field at the group's centre: the group's truth is one exact number (HDR tests).
    #[default]
    Centre,
    /// The mean of the field over the group's whole cell (2 skip x 2 skip pixels), as an
    /// ideal integrating readout would: what binning with bin = skip reads, and an
    /// idealisation for a readout that skips without binning (the campaign simulations):
    /// where the field bends by more than 1 % across the neighbouring groups' centres (an
    /// edge such as the solar limb) the footprint is averaged on a 16 x 16 grid.
    Integrated,
    /// The mean of the field over the pixels the readout reads (the MT9P031's binning: each
    /// sample averages bin x bin same-colour pixels, so a group integrates 2 bin x 2 bin
    /// pixels from its cell's start): binning keeps the light that falls on its pixels,
    /// skipping loses what falls between them. Edges are found as for `Integrated`.
    AsRead,
}

/// A source that may be smaller than a group and fall between the groups' centres (the solar
/// disk in groups of binned pixels): the groups within its reach are probed every 2 pixels
/// and, where it is, integrated on a quarter-pixel grid.
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct SmallSource {
    pub direction: DVec3,
    pub radius_rad: f64,
}

/// Renders frames of one readout window through one camera.
pub struct FrameRenderer<'a> {
    pub camera: &'a CameraModel,
    pub readout: Readout,
    pub raw_width: usize,
    pub raw_height: usize,
    pub footprint: Footprint,
    /// Where the field has sources smaller than a group (see [`SmallSource`]).
    pub small_sources: Vec<SmallSource>,
}

impl FrameRenderer<'_> {
    /// Mean black-subtracted sample of each group (grey scene), before noise; 0 where the lens
    /// images nothing.
    /// The scene as the groups see it, independent of the exposure: per group, luminance ×
    /// vignetting V(α) (cd/m²), 0 where the lens images nothing. With
    /// [`Footprint::Integrated`], groups where the field bends by more than 1 % across their
    /// neighbours' centres (an edge such as the solar limb) are averaged over their footprint.
    pub fn scene(&self, luminance_cd_m2: &(dyn Fn(DVec3) -> f64 + Sync)) -> Vec<f64> {
        let (gw, gh) = (self.raw_width / 2, self.raw_height / 2);
        let centre = |i: usize| {
            let (gx, gy) = (i % gw, i / gw);
            let r = &self.readout;
            (
                Readout::group_centre(r.col_start, r.skip, r.bin, gx as u32),
                Readout::group_centre(r.row_start, r.skip, r.bin, gy as u32),
            )
        };
        // Centre luminance and vignetting of every group.
        let at_centre: Vec<Option<(f64, f64)>> = (0..gw * gh)
            .into_par_iter()
            .map(|i| {
                let (x, y) = centre(i);
                let dir = self.camera.unproject(ImagePoint { x_px: x, y_px: y })?;
                Some((
                    luminance_cd_m2(dir),
                    self.camera.vignetting(self.camera.off_axis_rad(dir)),
                ))
            })
            .collect();
        (0..gw * gh)
            .into_par_iter()
            .map(|i| {
                let Some((l, v)) = at_centre[i] else {
                    return 0.0;
                };
                if self.footprint == Footprint::Centre {
                    return l * v;
                }
                let (gx, gy) = ((i % gw) as i64, (i / gw) as i64);
                let at = |dx: i64, dy: i64| {
                    let (nx, ny) = (gx + dx, gy + dy);
                    if nx < 0 || ny < 0 || nx >= gw as i64 || ny >= gh as i64 {
                        return None;
                    }
                    at_centre[ny as usize * gw + nx as usize].map(|(ln, _)| ln)
                };
                // The second difference along each axis and diagonal through the centre: a
                // field linear across the footprint has the centre as its mean, and a smooth
                // one differs from it by an twenty-fourth of this difference (the midpoint
                // rule's error), so only a kink or a jump (the solar limb, a cloud's edge)
                // needs the footprint integrated.
                let bends = [(1, 0), (0, 1), (1, 1), (1, -1)].iter().any(|&(dx, dy)| {
                    match (at(-dx, -dy), at(dx, dy)) {
                        (Some(a), Some(b)) => (a + b - 2.0 * l).abs() > 0.01 * l.abs().max(1e-300),
                        // At the rim of the image circle: the one-sided difference.
                        (Some(n), None) | (None, Some(n)) => {
                            (n - l).abs() > 0.01 * l.abs().max(1e-300)
                        }
                        (None, None) => false,
                    }
                });
                let (x, y) = centre(i);
                let near_small = self.near_a_small_source(x, y);
                let half_px = f64::from(match self.footprint {
                    Footprint::AsRead => self.readout.bin.max(1),
                    _ => self.readout.skip,
                });
                // Near a small source the integration grid is fine enough (1/4 px) that a
                // solar disk a few pixels wide is integrated to within about 1 % (its limb's
                // grid-counting error).
                let grid = if near_small {
                    ((8.0 * half_px).ceil() as usize).max(16)
                } else {
                    16
                };
                // A source smaller than the spacing of the groups (the solar disk in a
                // group of binned pixels) can lie between all the centres: the groups
                // within its reach are also probed every 2 pixels, which no disk of more
                // than 1.5 px radius escapes.
                let hidden = near_small && self.differs_inside(luminance_cd_m2, x, y, half_px, l);
                if bends || hidden {
                    self.footprint_mean(luminance_cd_m2, x, y, half_px, grid, l) * v
                } else {
                    l * v
                }
            })
            .collect()
    }

    /// Mean black-subtracted sample of each group (grey scene) for an exposure, before noise.
    fn mean_signal_dn(&self, scene: &[f64], exposure_s: f64, gain: f64) -> Vec<f64> {
        let d = &self.camera.config;
        let weight_sum: f64 = d.response.weights.iter().sum();
        let k = exposure_s * gain / (d.response.cg * weight_sum);
        scene.iter().map(|lv| lv * k).collect()
    }

    /// Whether a [`SmallSource`] reaches within two group pitches of the group centred at
    /// (x, y).
    fn near_a_small_source(&self, x: f64, y: f64) -> bool {
        let p = ImagePoint { x_px: x, y_px: y };
        let (Some(d), Some(omega_px2)) =
            (self.camera.unproject(p), self.camera.solid_angle_per_px2(p))
        else {
            return false;
        };
        let pitch_rad = 2.0 * f64::from(self.readout.skip) * omega_px2.sqrt();
        self.small_sources
            .iter()
            .any(|s| d.angle_between(s.direction) < s.radius_rad + 2.0 * pitch_rad)
    }

    /// Whether the field differs by more than 1 % from `centre` anywhere on a lattice of at
    /// most 2-pixel spacing over the square of half-width `half` pixels centred at (x, y).
    fn differs_inside(
        &self,
        field: &(dyn Fn(DVec3) -> f64 + Sync),
        x: f64,
        y: f64,
        half: f64,
        centre: f64,
    ) -> bool {
        let n = (half.ceil() as usize).max(1);
        (0..n * n).any(|k| {
            let px = x - half + 2.0 * half * ((k % n) as f64 + 0.5) / n as f64;
            let py = y - half + 2.0 * half * ((k / n) as f64 + 0.5) / n as f64;
            self.camera
                .unproject(ImagePoint { x_px: px, y_px: py })
                .map(field)
                .is_some_and(|v| (v - centre).abs() > 0.01 * centre.abs().max(1e-300))
        })
    }

    /// Mean luminance over the square of half-width `half` pixels centred at (x, y), on an
    /// `n` x `n` grid.
    fn footprint_mean(
        &self,
        field: &(dyn Fn(DVec3) -> f64 + Sync),
        x: f64,
        y: f64,
        half: f64,
        n: usize,
        centre: f64,
    ) -> f64 {
        let at = |px: f64, py: f64| {
            self.camera
                .unproject(ImagePoint { x_px: px, y_px: py })
                .map(field)
        };
        let (mut sum, mut count) = (0.0, 0usize);
        for j in 0..n {
            for i in 0..n {
                let px = x - half + 2.0 * half * (i as f64 + 0.5) / n as f64;
                let py = y - half + 2.0 * half * (j as f64 + 0.5) / n as f64;
                if let Some(v) = at(px, py) {
                    sum += v;
                    count += 1;
                }
            }
        }
        if count == 0 {
            centre
        } else {
            sum / count as f64
        }
    }

    /// An ideal frame: exact expected samples, no noise, no rounding, no clipping.
    pub fn render_analog(
        &self,
        luminance_cd_m2: &(dyn Fn(DVec3) -> f64 + Sync),
        exposure_s: f64,
        gain: f64,
    ) -> AnalogFrame {
        let mean = self.mean_signal_dn(&self.scene(luminance_cd_m2), exposure_s, gain);
        let black = self.camera.config.sensor.black_level_dn;
        let gw = self.raw_width / 2;
        let samples_dn = (0..self.raw_width * self.raw_height)
            .map(|i| {
                let (x, y) = (i % self.raw_width, i / self.raw_width);
                black + mean[(y / 2) * gw + x / 2]
            })
            .collect();
        AnalogFrame {
            width: self.raw_width,
            height: self.raw_height,
            samples_dn,
        }
    }

    /// A 12-bit raw frame with the sensor's noise.
    pub fn render(
        &self,
        luminance_cd_m2: &(dyn Fn(DVec3) -> f64 + Sync),
        exposure_s: f64,
        gain: f64,
        noise: Noise,
    ) -> RawFrame {
        self.render_scene(&self.scene(luminance_cd_m2), exposure_s, gain, noise)
    }

    /// A 12-bit raw frame of a scene computed once by [`Self::scene`] (an HDR set renders
    /// the same scene at several exposures).
    pub fn render_scene(
        &self,
        scene: &[f64],
        exposure_s: f64,
        gain: f64,
        noise: Noise,
    ) -> RawFrame {
        self.render_scene_spectral(
            scene,
            exposure_s,
            gain,
            noise,
            &ChannelResponse::GREY,
            BayerPattern::GRBG,
        )
    }

    /// As [`Self::render_scene`], with each sample scaled by its channel's response to the
    /// scene's spectrum (`pattern`: the colours of the frame's first 2x2 block).
    pub fn render_scene_spectral(
        &self,
        scene: &[f64],
        exposure_s: f64,
        gain: f64,
        noise: Noise,
        response: &ChannelResponse,
        pattern: BayerPattern,
    ) -> RawFrame {
        let mean = self.mean_signal_dn(scene, exposure_s, gain);
        let gw = self.raw_width / 2;
        self.render_samples(gain, noise, &|x, y| {
            mean[(y / 2) * gw + x / 2] * response.sample_gain(pattern, x, y)
        })
    }

    /// A 12-bit raw frame of a scene whose every channel has its own scene (R, G, B: the
    /// luminance times the channel's response, as [`Self::scene`] computes them): the sky's
    /// colour changes from direction to direction (`pattern`: the colours of the frame's first
    /// 2x2 block).
    pub fn render_scene_channels(
        &self,
        scenes: &[Vec<f64>; 3],
        exposure_s: f64,
        gain: f64,
        noise: Noise,
        pattern: BayerPattern,
    ) -> RawFrame {
        let means = scenes
            .each_ref()
            .map(|scene| self.mean_signal_dn(scene, exposure_s, gain));
        let gw = self.raw_width / 2;
        self.render_samples(gain, noise, &|x, y| {
            let c = match pattern.channel(x & 1, y & 1) {
                skylux_hps::campaign::Channel::Red => 0,
                skylux_hps::campaign::Channel::Green => 1,
                skylux_hps::campaign::Channel::Blue => 2,
            };
            means[c][(y / 2) * gw + x / 2]
        })
    }

    /// The frame from each sample's mean black-subtracted signal `mean_at(x, y)` (DN): shot
    /// noise, read noise, black level, rounding and clipping.
    fn render_samples(
        &self,
        gain: f64,
        noise: Noise,
        mean_at: &(dyn Fn(usize, usize) -> f64 + Sync),
    ) -> RawFrame {
        let d = &self.camera.config;
        let black = d.sensor.black_level_dn;
        let k = d.noise.conversion_dn_per_e * gain;
        // A binned sample averages bin² pixels' charge: its shot noise is that of bin² times
        // the electrons, divided back (the read noise stays one sample's).
        let pixels = f64::from(self.readout.bin.max(1).pow(2));
        let read = Normal::new(0.0, d.noise.read_noise_dn.max(0.0)).expect("finite read noise");
        let seed = match noise {
            Noise::Sensor { seed } => seed,
            Noise::None => 0,
        };
        // One RNG stream per row, seeded from (seed, row): deterministic and parallel.
        let rows: Vec<Vec<u16>> = (0..self.raw_height)
            .into_par_iter()
            .map(|y| {
                let mut rng = <rand::rngs::StdRng as rand::SeedableRng>::seed_from_u64(
                    seed ^ (y as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15),
                );
                (0..self.raw_width)
                    .map(|x| {
                        let m = mean_at(x, y).max(0.0);
                        let dn = match noise {
                            Noise::None => black + m,
                            Noise::Sensor { .. } => {
                                let electrons = m / k * pixels;
                                let shot = if electrons > 0.0 {
                                    Poisson::new(electrons)
                                        .map(|p| p.sample(&mut rng))
                                        .unwrap_or(electrons)
                                        / pixels
                                } else {
                                    0.0
                                };
                                black + shot * k + read.sample(&mut rng)
                            }
                        };
                        dn.round().clamp(0.0, MAX_SAMPLE_DN as f64) as u16
                    })
                    .collect()
            })
            .collect();
        RawFrame {
            width: self.raw_width,
            height: self.raw_height,
            samples_dn: rows.concat(),
        }
    }
}
