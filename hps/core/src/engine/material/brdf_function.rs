//! RADIANCE's `plasfunc`, `metfunc`, `transfunc` and their data forms `plasdata`,
//! `metdata`, `transdata` (`src/rt/m_brdf.c`: `m_brdf2`, `dirbrdf`): a normal material
//! whose specular part is a `.cal` function of the direction to a light source (or a data
//! file over such directions), seen from light sources only. Every other ray sees a
//! Lambertian surface of reflectance colour × (1 − trans) and transmittance colour × trans:
//! m_brdf2 traces no specular ray and sends the specular fraction to the ambient
//! calculation with the diffuse one.

use super::brtdfunc::{function_ray, HitSnapshot};
use super::scattering::{choose_component, DiffuseLobe, NormalSplit, Scatter};
use crate::engine::function::data::DataArray;
use crate::engine::function::loader::CompiledFunction;
use crate::engine::function::ray::Perturbed;
use crate::engine::ray::FTINY;
use crate::engine::rng::Rng;
use crate::engine::sampling::cosine_direction;
use crate::scene::{NormalFamily, NormalFractions};
use glam::DVec3;
use std::f64::consts::PI;
use std::sync::Arc;

/// A function material with its file compiled (and its data read).
#[derive(Clone, Debug)]
pub struct BrdfFunctionMaterial {
    pub fractions: NormalFractions,
    /// The function of the source direction (`func`).
    pub function_name: String,
    /// The function file; for the data forms its expressions are the coordinate
    /// functions' names.
    pub function: Arc<CompiledFunction>,
    /// The data forms' array.
    pub data: Option<Arc<DataArray>>,
}

/// A function material at one hit (m_brdf2's `BRDFDAT`).
#[derive(Clone, Debug)]
pub struct BrdfFunctionShading {
    material: Arc<BrdfFunctionMaterial>,
    /// The hit with the surface turned towards the ray (m_brdf2 calls `flipsurface`).
    ray: HitSnapshot,
    /// Perturbed normal turned towards the ray.
    pnorm: DVec3,
    /// The surface's own normal turned towards the ray: the ambient hemisphere's axis.
    ambient_normal: DVec3,
    mcolor: DVec3,
    split: NormalSplit,
}

impl BrdfFunctionMaterial {
    /// m_brdf2's set-up for a ray in unit `rdir` meeting, at `point_m` after `distance_m`,
    /// a surface of own normal `normal`, with shading normal `shading_normal` (textures) and
    /// pattern colour `pattern_rgb`.
    pub fn shade(
        self: &Arc<Self>,
        rdir: DVec3,
        normal: DVec3,
        shading_normal: DVec3,
        point_m: DVec3,
        distance_m: f64,
        pattern_rgb: DVec3,
    ) -> BrdfFunctionShading {
        let front = rdir.dot(normal) < 0.0;
        let side = if front { 1.0 } else { -1.0 };
        let (own, pnorm) = (normal * side, shading_normal * side);
        let f = &self.fractions;
        let mcolor = f.color_rgb * pattern_rgb;
        let ray = HitSnapshot {
            direction: rdir,
            normal: own,
            point_m,
            distance_m,
            perturbed: Perturbed {
                normal: pnorm,
                cos_incidence: -rdir.dot(pnorm),
                color_rgb: mcolor,
            },
        };
        BrdfFunctionShading {
            material: self.clone(),
            ray,
            pnorm,
            ambient_normal: own,
            mcolor,
            split: NormalSplit::new(f.specularity, f.transmissivity, f.transmitted_specularity),
        }
    }
}

impl BrdfFunctionShading {
    /// m_brdf2's ambient parts: colour × (1 − trans) reflected, colour × trans transmitted,
    /// in [`choose_component`]'s order (no specular component is traced).
    fn components(&self, allow_diffuse: bool) -> [DVec3; 4] {
        let t = self.split.trans;
        let reflected = if allow_diffuse && t < 1.0 - FTINY {
            self.mcolor * (1.0 - t)
        } else {
            DVec3::ZERO
        };
        let transmitted = if allow_diffuse && t > FTINY {
            self.mcolor * t
        } else {
            DVec3::ZERO
        };
        [DVec3::ZERO, DVec3::ZERO, reflected, transmitted]
    }

    /// The Lambertian parts as [`BrdfFunctionShading::sample`] samples them.
    pub fn diffuse_lobe(&self, allow_diffuse: bool) -> Option<DiffuseLobe> {
        DiffuseLobe::of_components(self.ambient_normal, &self.components(allow_diffuse))
    }

    /// One of the two Lambertian parts, chosen in proportion to its brightness.
    pub fn sample(&self, allow_diffuse: bool, rng: &mut Rng) -> Scatter {
        let Some((pick, weight)) = choose_component(&self.components(allow_diffuse), rng) else {
            return Scatter::Absorbed;
        };
        let side = if pick == 2 { 1.0 } else { -1.0 };
        Scatter::Diffuse {
            direction: cosine_direction(self.ambient_normal * side, rng),
            weight,
        }
    }

    /// `dirbrdf`: the Lambertian part of a source of solid angle `omega_sr` in unit
    /// direction `ldir`, plus the function's value times rspec (tspec behind) |cos| Ω,
    /// coloured by the material for `metfunc` reflection and `transfunc` transmission.
    pub fn source_coefficient(&self, ldir: DVec3, omega_sr: f64) -> DVec3 {
        let s = &self.split;
        let ldot = self.pnorm.dot(ldir);
        let wrong_side = if ldot < 0.0 {
            s.trans <= FTINY
        } else {
            s.trans >= 1.0 - FTINY
        };
        if ldot.abs() <= FTINY || wrong_side {
            return DVec3::ZERO;
        }
        let (diffuse, specular) = if ldot > 0.0 {
            (s.rdiff, s.rspec)
        } else {
            (s.tdiff, s.tspec)
        };
        let mut c = self.mcolor * (diffuse * ldot.abs() * omega_sr / PI);
        if specular <= FTINY {
            return c;
        }
        let value = self.directional(ldir, omega_sr);
        if value <= FTINY {
            return c;
        }
        let family = self.material.fractions.family;
        let coloured = if ldot > 0.0 {
            family == NormalFamily::Metal
        } else {
            family == NormalFamily::Trans
        };
        let colour = if coloured { self.mcolor } else { DVec3::ONE };
        c += colour * (value * ldot.abs() * omega_sr * specular);
        c
    }

    /// The function at (lx, ly, lz, Ω), the source direction in the function's frame; for
    /// the data forms, the function at (value, lx, ly, lz, Ω) with the data interpolated at
    /// the coordinate functions' values.
    fn directional(&self, ldir: DVec3, omega_sr: f64) -> f64 {
        let m = &self.material;
        let context = function_ray(&m.function, &self.ray);
        let l = context.local_direction(ldir);
        let arguments = [l.x, l.y, l.z, omega_sr];
        let Some(data) = &m.data else {
            return m.function.call(&m.function_name, &arguments, &context);
        };
        let point: Vec<f64> = m
            .function
            .args
            .expressions
            .iter()
            .map(|name| m.function.call(name, &arguments, &context))
            .collect();
        let value = data.value(&point);
        m.function.call(
            &m.function_name,
            &[value, l.x, l.y, l.z, omega_sr],
            &context,
        )
    }
}
