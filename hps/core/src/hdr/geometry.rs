//! Per-group geometry of a readout: where each 2x2 Bayer group looks, its vignetting and its
//! solid angle. Computed once per camera and readout and reused for every capture, because
//! the inverse lens map is the expensive part of mapping.

use crate::camera::{CameraModel, ImagePoint};
use crate::campaign::Readout;
use glam::Vec3;

/// Geometry of every group of a `width` x `height`-group map.
#[derive(Clone, Debug)]
pub struct GroupGeometry {
    pub width: usize,
    pub height: usize,
    /// Unit direction (world frame) of each group's centre; NaN outside the lens model.
    pub direction: Vec<Vec3>,
    /// 1 / V(α) at each group's centre (0 outside the lens model).
    pub inverse_vignetting: Vec<f32>,
    /// Solid angle of each group, sr (0 outside the lens model).
    pub solid_angle_sr: Vec<f32>,
    /// The share of each group's cell its samples integrate: (bin / skip)². 1 when nothing
    /// falls between the read pixels; below 1, a source smaller than the cell can be missed
    /// or read as if it filled the cell (docs/readout.md).
    pub fill_factor: f64,
}

/// The geometry of the last readout asked for. The captures of a campaign share a readout,
/// so a pass over them computes the geometry once, not once per capture.
#[derive(Default)]
pub struct GeometryCache {
    last: Option<(ReadoutKey, GroupGeometry)>,
}

/// A readout and frame size: column start, row start, skip, raw width, raw height.
type ReadoutKey = (u32, u32, u32, u32, usize, usize);

impl GeometryCache {
    /// The geometry of `raw_width` x `raw_height` frames read out with `readout`.
    pub fn get(
        &mut self,
        camera: &CameraModel,
        readout: &Readout,
        raw_width: usize,
        raw_height: usize,
    ) -> &GroupGeometry {
        let key = (
            readout.col_start,
            readout.row_start,
            readout.skip,
            readout.bin,
            raw_width,
            raw_height,
        );
        if self.last.as_ref().map(|(k, _)| *k) != Some(key) {
            self.last = Some((
                key,
                GroupGeometry::new(camera, readout, raw_width, raw_height),
            ));
        }
        &self.last.as_ref().expect("just set").1
    }
}

impl GroupGeometry {
    /// Geometry of the groups of raw frames of `raw_width` x `raw_height` samples read out
    /// with `readout`.
    pub fn new(
        camera: &CameraModel,
        readout: &Readout,
        raw_width: usize,
        raw_height: usize,
    ) -> Self {
        let (width, height) = (raw_width / 2, raw_height / 2);
        let n = width * height;
        let mut direction = vec![Vec3::NAN; n];
        let mut inverse_vignetting = vec![0.0f32; n];
        let mut solid_angle_sr = vec![0.0f32; n];
        // A group's first raw column is adjacent in the full array to its second (campaign.md),
        // and with binning each sample averages `bin` same-colour pixels from there on, so
        // its sensitive area is the 2 bin pixels from its first column's left edge and its
        // centre `bin` pixels right of that edge (`Readout::group_centre`). Its share of the
        // sphere, for sums over the map, is its whole cell: (2 skip) x (2 skip) pixels.
        let footprint_px2 = (2.0 * readout.skip as f64).powi(2);
        for gy in 0..height {
            let y = Readout::group_centre(readout.row_start, readout.skip, readout.bin, gy as u32);
            for gx in 0..width {
                let x =
                    Readout::group_centre(readout.col_start, readout.skip, readout.bin, gx as u32);
                let p = ImagePoint { x_px: x, y_px: y };
                let i = gy * width + gx;
                if let (Some(d), Some(omega)) = (camera.unproject(p), camera.solid_angle_per_px2(p))
                {
                    let v = camera.vignetting(camera.off_axis_rad(d));
                    if v > 0.0 {
                        direction[i] = d.as_vec3();
                        inverse_vignetting[i] = (1.0 / v) as f32;
                        solid_angle_sr[i] = (omega * footprint_px2) as f32;
                    }
                }
            }
        }
        Self {
            width,
            height,
            direction,
            inverse_vignetting,
            solid_angle_sr,
            fill_factor: (f64::from(readout.bin.max(1)) / f64::from(readout.skip.max(1)))
                .min(1.0)
                .powi(2),
        }
    }
}
