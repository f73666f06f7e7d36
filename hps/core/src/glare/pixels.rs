//! Where each pixel looks and how much of the sphere it covers, as evalglare's picture tool
//! (pictool.c) derives them from the view: the direction through the pixel's centre, and the
//! solid angle of the spherical quadrilateral through its four corner directions.
//!
//! Pixels are addressed as evalglare addresses them, `x` from the left and `y` from the
//! bottom, because its scans (and so which glare source a pixel joins) run in that order.

use crate::engine::render::{PreparedView, ViewType};
use glam::DVec3;
use std::f64::consts::PI;

/// The directions and solid angles of a picture's pixels.
pub struct PixelGrid {
    pub width_px: usize,
    pub height_px: usize,
    /// Unit direction through each pixel's centre, or zero where the view has no ray (outside
    /// a fisheye's circle). Indexed by [`PixelGrid::index`].
    pub direction: Vec<DVec3>,
    /// Solid angle of each pixel, sr; 0 where a corner has no ray.
    pub solid_angle_sr: Vec<f64>,
    /// Unit view direction and unit view up vector.
    pub view_direction: DVec3,
    pub view_up: DVec3,
    angular: bool,
}

impl PixelGrid {
    /// The grid of a `width_px` × `height_px` picture taken with `view`.
    pub fn new(view: &PreparedView, width_px: usize, height_px: usize) -> PixelGrid {
        let (w, h) = (width_px as f64, height_px as f64);
        let ray = |u: f64, v: f64| view.ray(u, v).map(|r| r.direction);
        // Corner (i, j) of the pixel lattice, i from the left and j from the bottom.
        let corners: Vec<Option<DVec3>> = (0..=height_px)
            .flat_map(|j| (0..=width_px).map(move |i| (i, j)))
            .map(|(i, j)| ray(i as f64 / w, j as f64 / h))
            .collect();
        let corner = |i: usize, j: usize| corners[j * (width_px + 1) + i];
        let mut direction = Vec::with_capacity(width_px * height_px);
        let mut solid_angle_sr = Vec::with_capacity(width_px * height_px);
        for y in 0..height_px {
            for x in 0..width_px {
                direction
                    .push(ray((x as f64 + 0.5) / w, (y as f64 + 0.5) / h).unwrap_or(DVec3::ZERO));
                let quad = [
                    corner(x, y),
                    corner(x, y + 1),
                    corner(x + 1, y + 1),
                    corner(x + 1, y),
                ];
                solid_angle_sr.push(quadrilateral_solid_angle_sr(quad));
            }
        }
        PixelGrid {
            width_px,
            height_px,
            direction,
            solid_angle_sr,
            view_direction: view.view.direction.normalize(),
            view_up: view.view.up.normalize(),
            angular: view.view.kind == ViewType::Angular,
        }
    }

    /// Index of pixel (`x` from the left, `y` from the bottom).
    pub fn index(&self, x: usize, y: usize) -> usize {
        y * self.width_px + x
    }

    /// Whether the view has a ray through the pixel's centre (evalglare's `pict_get_hangle`).
    pub fn has_ray(&self, i: usize) -> bool {
        self.direction[i] != DVec3::ZERO
    }

    /// Whether the pixel counts (pictool.h `pict_is_validpixel`): it has a ray, a positive
    /// solid angle and, in an angular fisheye, looks into the front hemisphere.
    pub fn is_valid(&self, i: usize) -> bool {
        self.has_ray(i)
            && self.solid_angle_sr[i] > 0.0
            && (!self.angular || self.direction[i].dot(self.view_direction) >= 0.0)
    }

    /// Twice the angle between the centre directions of two pixels, rad: the measure
    /// evalglare compares with its search radius (`acos(DOT(...)) * 2`). A pixel without a
    /// ray is a right angle from every direction.
    pub fn doubled_angle_rad(&self, a: usize, b: usize) -> f64 {
        2.0 * self.direction[a]
            .dot(self.direction[b])
            .clamp(-1.0, 1.0)
            .acos()
    }

    /// Row from the top of the picture of `y` (from the bottom).
    pub fn row_from_top(&self, y: f64) -> f64 {
        (self.height_px - 1) as f64 - y
    }
}

/// Solid angle of the spherical quadrilateral with great-circle edges through four unit
/// directions in order, sr: the sum of its interior angles less 2π (Girard's theorem), each
/// interior angle π less the angle between the normals of the planes of adjacent edges.
/// 0 if a corner is missing or the quadrilateral is degenerate.
fn quadrilateral_solid_angle_sr(corners: [Option<DVec3>; 4]) -> f64 {
    let mut c = [DVec3::ZERO; 4];
    for (slot, corner) in c.iter_mut().zip(corners) {
        match corner {
            Some(d) => *slot = d,
            None => return 0.0,
        }
    }
    let mut normals = [DVec3::ZERO; 4];
    for k in 0..4 {
        match c[k].cross(c[(k + 1) % 4]).try_normalize() {
            Some(n) => normals[k] = n,
            None => return 0.0,
        }
    }
    let interior: f64 = (0..4)
        .map(|k| PI - normals[k].dot(normals[(k + 1) % 4]).clamp(-1.0, 1.0).acos())
        .sum();
    let omega = interior - 2.0 * PI;
    if (0.0..=2.0 * PI).contains(&omega) {
        omega
    } else {
        0.0
    }
}
