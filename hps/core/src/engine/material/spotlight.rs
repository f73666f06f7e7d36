//! RADIANCE's `spotlight` on a surface (src/rt/source.c `m_light` with srcsupp.c `spotout`):
//! a `light` whose light leaves only within a cone about its output direction.

use super::emitter::Emitter;
use glam::DVec3;

#[derive(Clone, Debug)]
pub struct SpotlightMaterial {
    pub emitter: Emitter,
    /// Unit output direction, the cone's axis.
    pub direction: DVec3,
    /// cos of half the full cone angle: spotout keeps directions whose solid-angle cap
    /// 2π(1 − cos θ) about the axis is within the spot's 2π(1 − cos(angle/2)).
    pub cos_half_angle: f64,
    /// Distance of the effective focus behind the source (the length of the given direction
    /// vector, manual §2.1.2 "Spotlight").
    pub focal_length_m: f64,
}

impl SpotlightMaterial {
    /// What a direct sample at `distance_m` from the lamp keeps of its radiance: source.c
    /// `srcray` shrinks the sample's solid angle to that of the lamp seen from its focus,
    /// d² / (d + focal length)².
    pub fn focus_factor(&self, distance_m: f64) -> f64 {
        let ratio = distance_m / (distance_m + self.focal_length_m);
        ratio * ratio
    }

    /// What a ray along unit `d` receives on meeting it: the emitter's light if `-d` lies in
    /// the cone, else nothing.
    pub fn seen(&self, d: DVec3, normal: DVec3, primary: bool) -> Option<DVec3> {
        if -d.dot(self.direction) < self.cos_half_angle {
            return None;
        }
        self.emitter.seen(d, normal, primary)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn light_leaves_inside_the_cone_only_and_falls_off_from_the_focus() {
        let spot = SpotlightMaterial {
            emitter: Emitter {
                radiance_w_sr_m2: DVec3::splat(10.0),
                patterns: Vec::new(),
                illuminates: true,
            },
            direction: -DVec3::Z,
            cos_half_angle: 30f64.to_radians().cos(),
            focal_length_m: 1.0,
        };
        let down = -DVec3::Z;
        // A ray coming up from 20° off the axis meets light, from 40° none.
        let at = |deg: f64| DVec3::new(deg.to_radians().sin(), 0.0, deg.to_radians().cos());
        assert_eq!(spot.seen(at(20.0), down, false), Some(DVec3::splat(10.0)));
        assert_eq!(spot.seen(at(40.0), down, false), None);
        // Its back is black, as for any light.
        assert_eq!(spot.seen(-at(0.0), down, false), None);
        // d² / (d + f)²: at 1 m from a lamp focused 1 m behind it, a quarter.
        assert!((spot.focus_factor(1.0) - 0.25).abs() < 1e-15);
    }
}
