//! RADIANCE's `illum` (src/rt/source.c `m_light`, `passillum`, `badcomponent`): a secondary
//! source. Rays that come for its light (rays arriving at its front from a scattering
//! vertex) receive its radiance; every other ray (rays from its back, eye rays, shadow rays
//! towards other sources) meets its alternate material instead, or passes when it has none.

use super::emitter::Emitter;
use super::Material;
use glam::DVec3;

#[derive(Clone, Debug)]
pub struct IllumMaterial {
    pub emitter: Emitter,
    /// What other rays see: a material, or [`Material::Invisible`] for `void` or none.
    pub alternate: Box<Material>,
}

impl IllumMaterial {
    /// Whether unit `d` meets the emitting side.
    pub fn is_front(d: DVec3, normal: DVec3) -> bool {
        d.dot(normal) < 0.0
    }
}
