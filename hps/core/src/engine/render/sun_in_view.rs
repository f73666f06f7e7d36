//! The sun's disc in a picture, integrated over each pixel instead of hit by chance.
//!
//! The sun covers 6.8e-5 sr, a tenth of a pixel of a 128-pixel fisheye: a pixel's jittered
//! rays find it with a probability of about 0.1 each, so at a thousand paths per pixel the
//! pixel that holds it is still 10 % off, and Ev and DGP with the sun in view, which it
//! dominates, with it. Instead, camera rays that go straight to a small distant `light`
//! ([`super::super::radiance::SunDisc::Apart`]) see only what lies behind it, and its image
//! is added here: points of the disc, stratified in solid angle, are located in the image
//! ([`PreparedView::locate`]); each adds L T Ω / (n |J| A) to its pixel, with T the
//! transmission from the eye to the sun (glass, shadows), Ω the disc's solid angle, n the
//! points, J = ∂d/∂x × ∂d/∂y the solid angle per unit image area there and A one pixel's
//! image area. A pixel filled by the disc thus reads L T, and the disc's whole image sums to
//! its illuminance on the image, whatever the resolution.

use super::super::radiance::is_disc_apart;
use super::super::sky::DistantEmitter;
use super::super::world::World;
use super::view::PreparedView;
use glam::DVec3;

/// Points per disc side: 64 × 64 strata in (cos θ, φ) about the disc's centre.
const STRATA: u32 = 64;
/// Sub-pixel rays per side where pixels are smaller than the disc.
const SUBPIXELS: u32 = 16;
/// Image-coordinate step of the finite differences for J.
const STEP: f64 = 1e-5;

/// Adds the images of the world's small distant `light`s to `radiance_rgb` (row 0 at the
/// top, `width_px` × `height_px`). Where a pixel is larger than the disc, points of the
/// disc are splatted; where it is smaller (a narrow view of the sun), each pixel the disc
/// may touch is integrated on a 16 × 16 grid of sub-pixel rays instead.
pub fn add_discs(
    world: &World,
    view: &PreparedView,
    width_px: u32,
    height_px: u32,
    radiance_rgb: &mut [DVec3],
) {
    let image = Image {
        view,
        width_px,
        height_px,
        pixel_area: 1.0 / (f64::from(width_px) * f64::from(height_px)),
    };
    for source in world.distant_sources().iter().filter(|s| is_disc_apart(s)) {
        let points = disc_points(source, STRATA);
        let Some(pixel_sr) = points.iter().find_map(|&d| image.pixel_solid_angle_at(d)) else {
            continue; // nothing of the disc in the picture
        };
        if pixel_sr >= source.solid_angle_sr {
            image.splat(world, source, &points, radiance_rgb);
        } else {
            image.integrate(world, source, &points, radiance_rgb);
        }
    }
}

struct Image<'a> {
    view: &'a PreparedView,
    width_px: u32,
    height_px: u32,
    /// One pixel's area in image coordinates ([0, 1] each way).
    pixel_area: f64,
}

impl Image<'_> {
    /// The image position of unit direction `d` inside the picture, if it is.
    fn position(&self, d: DVec3) -> Option<(f64, f64)> {
        let (x, y) = self.view.locate(d)?;
        ((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y)).then_some((x, y))
    }

    fn index(&self, x: f64, y: f64) -> usize {
        let column = ((x * f64::from(self.width_px)) as u32).min(self.width_px - 1);
        let row =
            self.height_px - 1 - ((y * f64::from(self.height_px)) as u32).min(self.height_px - 1);
        (row * self.width_px + column) as usize
    }

    /// The solid angle of one pixel where `d` lands, if it lands in the picture.
    fn pixel_solid_angle_at(&self, d: DVec3) -> Option<f64> {
        let (x, y) = self.position(d)?;
        Some(solid_angle_per_area(self.view, x, y)? * self.pixel_area)
    }

    /// Each point adds L T Ω / (n |J| A) to the pixel it lands in.
    fn splat(
        &self,
        world: &World,
        source: &DistantEmitter,
        points: &[DVec3],
        radiance_rgb: &mut [DVec3],
    ) {
        let n = points.len() as f64;
        for &d in points {
            let Some((x, y)) = self.position(d) else {
                continue;
            };
            let (Some(ray), Some(jacobian_sr)) =
                (self.view.ray(x, y), solid_angle_per_area(self.view, x, y))
            else {
                continue;
            };
            let t = world.source_transmission(ray.origin_m, None, d);
            radiance_rgb[self.index(x, y)] += source.radiance(d)
                * t
                * (source.solid_angle_sr / n / (jacobian_sr * self.pixel_area));
        }
    }

    /// Every pixel of the box around the disc's points: the mean over sub-pixel rays of
    /// what each sees of the disc.
    fn integrate(
        &self,
        world: &World,
        source: &DistantEmitter,
        points: &[DVec3],
        radiance_rgb: &mut [DVec3],
    ) {
        let (w, h) = (f64::from(self.width_px), f64::from(self.height_px));
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for &d in points {
            if let Some((x, y)) = self.view.locate(d) {
                (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
            }
        }
        if x0 > x1 {
            return;
        }
        let columns = ((x0 * w).floor().max(0.0) as u32)..((x1 * w).ceil().min(w) as u32);
        let rows_up = ((y0 * h).floor().max(0.0) as u32)..((y1 * h).ceil().min(h) as u32);
        let k = f64::from(SUBPIXELS);
        for up in rows_up {
            for column in columns.clone() {
                let mut sum = DVec3::ZERO;
                for i in 0..SUBPIXELS {
                    for j in 0..SUBPIXELS {
                        let x = (f64::from(column) + (f64::from(i) + 0.5) / k) / w;
                        let y = (f64::from(up) + (f64::from(j) + 0.5) / k) / h;
                        let Some(ray) = self.view.ray(x, y) else {
                            continue;
                        };
                        let d = ray.direction;
                        if d.dot(source.direction) >= source.cos_half_angle {
                            sum += source.radiance(d)
                                * world.source_transmission(ray.origin_m, None, d);
                        }
                    }
                }
                let row = self.height_px - 1 - up;
                radiance_rgb[(row * self.width_px + column) as usize] += sum / (k * k);
            }
        }
    }
}

/// `strata`² directions spread evenly in solid angle over the disc (stratum centres in
/// cos θ and φ about its centre), the innermost ring first.
fn disc_points(source: &DistantEmitter, strata: u32) -> Vec<DVec3> {
    let (u, v) = super::super::sampling::basis(source.direction);
    let mut points = Vec::with_capacity((strata * strata) as usize);
    for i in 0..strata {
        for j in 0..strata {
            let c = 1.0 - (f64::from(i) + 0.5) / f64::from(strata) * (1.0 - source.cos_half_angle);
            let phi = std::f64::consts::TAU * (f64::from(j) + 0.5) / f64::from(strata);
            let s = (1.0 - c * c).max(0.0).sqrt();
            points.push(
                (u * (s * phi.cos()) + v * (s * phi.sin()) + source.direction * c).normalize(),
            );
        }
    }
    points
}

/// |∂d/∂x × ∂d/∂y| at image position (x, y): steradians per unit image area, by central
/// differences (one-sided at a fisheye's rim).
fn solid_angle_per_area(view: &PreparedView, x: f64, y: f64) -> Option<f64> {
    let dir = |x: f64, y: f64| view.ray(x, y).map(|r| r.direction);
    let centre = dir(x, y)?;
    let diff = |a: Option<DVec3>, b: Option<DVec3>| match (a, b) {
        (Some(a), Some(b)) => Some((a - b) / (2.0 * STEP)),
        (Some(a), None) => Some((a - centre) / STEP),
        (None, Some(b)) => Some((centre - b) / STEP),
        (None, None) => None,
    };
    let dx = diff(dir(x + STEP, y), dir(x - STEP, y))?;
    let dy = diff(dir(x, y + STEP), dir(x, y - STEP))?;
    let j = dx.cross(dy).length();
    (j > 0.0 && j.is_finite()).then_some(j)
}
