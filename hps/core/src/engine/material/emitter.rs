//! Self-luminous surfaces: `light` and `glow` on a surface (not a `source`), with their
//! `brightfunc` patterns (RADIANCE src/rt/source.c `m_light`).

use crate::engine::ray::FTINY;
use crate::engine::sky::SkyFunction;
use glam::DVec3;

/// A self-luminous surface (`light` or `glow` on a surface, not a `source`).
#[derive(Clone, Debug)]
pub struct Emitter {
    pub radiance_w_sr_m2: DVec3,
    pub patterns: Vec<SkyFunction>,
    /// A `glow` with negative `maxrad` never illuminates (RADIANCE source.c `distglow`,
    /// `badcomponent`): every ray the sensors trace descends from an ambient ray, so it
    /// counts as black.
    pub illuminates: bool,
}

impl Emitter {
    /// Whether a `glow` of radius `max_radius_m` illuminates other surfaces (negative: never,
    /// with RADIANCE's `FTINY` of tolerance).
    pub fn glow_illuminates(max_radius_m: f64) -> bool {
        max_radius_m >= -FTINY
    }

    pub fn radiance(&self, d: DVec3) -> DVec3 {
        self.patterns
            .iter()
            .fold(self.radiance_w_sr_m2, |l, p| l * p.value(d))
    }

    /// What a ray along unit `d` meeting the surface of normal `normal` receives: light leaves
    /// the front only (source.c m_light: `r->rod < 0` is black), and a `glow` that does not
    /// illuminate is seen by `primary` (eye) rays only. None: nothing.
    pub fn seen(&self, d: DVec3, normal: DVec3, primary: bool) -> Option<DVec3> {
        ((primary || self.illuminates) && d.dot(normal) < 0.0).then(|| self.radiance(d))
    }
}
