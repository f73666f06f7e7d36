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
