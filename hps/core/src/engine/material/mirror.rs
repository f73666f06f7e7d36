//! RADIANCE's `mirror` (src/rt/m_mirror.c): a pure specular reflector of the given colour,
//! black from the back. Plane mirrors also make virtual sources
//! ([`crate::engine::virtual_sources`]).

use super::scattering::{reflect, Scatter};
use crate::engine::ray::FTINY;
use glam::DVec3;

#[derive(Clone, Debug)]
pub struct MirrorMaterial {
    pub reflectance_rgb: DVec3,
    /// Under a texture, the surface's own normal: m_mirror reflects about the perturbed
    /// normal, and about this one where that reflection would go through the mirror.
    pub surface_normal: Option<DVec3>,
}

impl MirrorMaterial {
    /// Whether unit direction `d` meets the back of a mirror of normal `normal`, which m_mirror
    /// makes black (`r->rod < 0` returns no light).
    pub fn is_back(d: DVec3, normal: DVec3) -> bool {
        d.dot(normal) > 0.0
    }

    /// The mirror reflection of `d`, weighted by the reflectance.
    pub fn sample(&self, d: DVec3, normal: DVec3) -> Scatter {
        let mut direction = reflect(d, normal);
        if let Some(own) = self.surface_normal {
            let front = if d.dot(own) < 0.0 { own } else { -own };
            if direction.dot(front) <= FTINY {
                direction = reflect(d, own);
            }
        }
        Scatter::Specular {
            direction,
            weight: self.reflectance_rgb,
        }
    }
}
