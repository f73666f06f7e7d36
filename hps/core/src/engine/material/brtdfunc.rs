//! RADIANCE's `BRTDfunc` (`src/rt/m_brdf.c` `m_brdf`, `dirbrdf`): a thin surface with
//! specular reflection and transmission whose colours are `.cal` expressions of the hit,
//! Lambertian reflection (front and back) and transmission given as reals, and a
//! directional-diffuse part, a function of the source direction, seen from light sources
//! only (RADIANCE samples no indirect light through it).

use super::scattering::{bright, choose_component, reflect, DiffuseLobe, Scatter};
use crate::engine::function::loader::CompiledFunction;
use crate::engine::function::ray::{FunctionRay, Perturbed};
use crate::engine::ray::FTINY;
use crate::engine::rng::Rng;
use crate::engine::sampling::cosine_direction;
use crate::scene::BrtdFunc;
use glam::DVec3;
use std::f64::consts::PI;
use std::sync::Arc;

/// String arguments of the directional-diffuse functions (`rbrtd gbrtd bbrtd`).
const DIRECTIONAL: std::ops::Range<usize> = 6..9;

/// A `BRTDfunc` with its expressions compiled.
#[derive(Clone, Debug)]
pub struct BrtdMaterial {
    pub arguments: BrtdFunc,
    pub function: Arc<CompiledFunction>,
}

/// A `BRTDfunc` evaluated at one hit (m_brdf's `BRDFDAT` and its two traced rays).
#[derive(Clone, Debug)]
pub struct BrtdShading {
    function: Arc<CompiledFunction>,
    /// The hit, kept for the directional functions of each source direction.
    ray: HitSnapshot,
    /// Ray direction (unit, towards the surface).
    rdir: DVec3,
    /// Perturbed normal turned towards the ray.
    pnorm: DVec3,
    /// The surface's own normal turned towards the ray: the diffuse hemisphere is sampled
    /// around it (RADIANCE's `samp_hemi` with -aa 0 ignores textures).
    ambient_normal: DVec3,
    specular_reflection_rgb: DVec3,
    specular_transmission_rgb: DVec3,
    diffuse_reflection_rgb: DVec3,
    diffuse_transmission_rgb: DVec3,
}

/// What [`FunctionRay`] needs, owned: kept by the shadings whose functions are called
/// again for each source direction.
#[derive(Clone, Copy, Debug)]
pub(super) struct HitSnapshot {
    pub direction: DVec3,
    /// The normal the functions see as `Nx Ny Nz`.
    pub normal: DVec3,
    pub point_m: DVec3,
    pub distance_m: f64,
    pub perturbed: Perturbed,
}

impl BrtdMaterial {
    /// m_brdf's set-up for a ray in unit `rdir` meeting, at `point_m` after `distance_m`, a
    /// surface of own normal `normal`, with shading normal `shading_normal` (perturbed by
    /// textures, on the same side as `normal`) and pattern colour `pattern_rgb`.
    pub fn shade(
        &self,
        rdir: DVec3,
        normal: DVec3,
        shading_normal: DVec3,
        point_m: DVec3,
        distance_m: f64,
        pattern_rgb: DVec3,
    ) -> BrtdShading {
        let front = rdir.dot(normal) < 0.0;
        let pnorm = if front {
            shading_normal
        } else {
            -shading_normal
        };
        let a = &self.arguments;
        let diffuse = if front {
            a.front_diffuse_rgb
        } else {
            a.back_diffuse_rgb
        };
        let ray = HitSnapshot {
            direction: rdir,
            normal,
            point_m,
            distance_m,
            perturbed: Perturbed {
                normal: pnorm,
                cos_incidence: -rdir.dot(pnorm),
                color_rgb: pattern_rgb,
            },
        };
        let context = self.function_ray(&ray);
        let [rr, rg, rb, tr, tg, tb] = self.function.values::<6>(0, &context);
        BrtdShading {
            function: self.function.clone(),
            ray,
            rdir,
            pnorm,
            ambient_normal: if front { normal } else { -normal },
            specular_reflection_rgb: DVec3::new(rr, rg, rb).max(DVec3::ZERO),
            specular_transmission_rgb: DVec3::new(tr, tg, tb).max(DVec3::ZERO),
            diffuse_reflection_rgb: diffuse * pattern_rgb,
            diffuse_transmission_rgb: a.diffuse_transmittance_rgb * pattern_rgb,
        }
    }

    fn function_ray<'a>(&'a self, hit: &HitSnapshot) -> FunctionRay<'a> {
        function_ray(&self.function, hit)
    }
}

/// The hit as `function`'s expressions see it.
pub(super) fn function_ray<'a>(
    function: &'a CompiledFunction,
    hit: &HitSnapshot,
) -> FunctionRay<'a> {
    FunctionRay {
        direction: hit.direction,
        normal: hit.normal,
        point_m: hit.point_m,
        distance_m: hit.distance_m,
        perturbed: Some(hit.perturbed),
        transform: &function.args.transform,
        real_args: &function.args.real_args,
    }
}

impl BrtdShading {
    /// The four components in [`choose_component`]'s order: specular reflection, specular
    /// transmission, diffuse reflection, diffuse transmission (the last two only with
    /// `allow_diffuse`).
    fn components(&self, allow_diffuse: bool) -> [DVec3; 4] {
        let keep = |c: DVec3| if allow_diffuse { c } else { DVec3::ZERO };
        [
            self.specular_reflection_rgb,
            self.specular_transmission_rgb,
            keep(self.diffuse_reflection_rgb),
            keep(self.diffuse_transmission_rgb),
        ]
    }

    /// The Lambertian parts as [`BrtdShading::sample`] samples them (see
    /// `NormalShading::diffuse_lobe`).
    pub fn diffuse_lobe(&self, allow_diffuse: bool) -> Option<DiffuseLobe> {
        DiffuseLobe::of_components(self.ambient_normal, &self.components(allow_diffuse))
    }

    /// A shadow ray goes on straight with the specular transmission (m_brdf traces the
    /// transmitted ray for shadow rays too).
    pub fn shadow_transmission(&self) -> DVec3 {
        self.specular_transmission_rgb
    }

    /// `dirbrdf`: Lambertian reflection or transmission of a source of solid angle `omega_sr`
    /// in unit direction `ldir`, plus the directional-diffuse functions of (lx, ly, lz, Ω) in
    /// the function's frame, times |cos| Ω.
    pub fn source_coefficient(&self, ldir: DVec3, omega_sr: f64) -> DVec3 {
        let ldot = self.pnorm.dot(ldir);
        if ldot.abs() <= FTINY {
            return DVec3::ZERO;
        }
        let diffuse = if ldot > 0.0 {
            self.diffuse_reflection_rgb
        } else {
            self.diffuse_transmission_rgb
        };
        let mut c = diffuse * (ldot.abs() * omega_sr / PI);
        let names = &self.function.args.expressions[DIRECTIONAL];
        if names.iter().all(|n| n == "0") {
            return c;
        }
        let context = function_ray(&self.function, &self.ray);
        let l = context.local_direction(ldir);
        let arguments = [l.x, l.y, l.z, omega_sr];
        let mut brtd = [0.0; 3];
        for (k, name) in names.iter().enumerate() {
            // m_brdf.c evaluates a name repeated from an earlier channel once.
            brtd[k] = match names[..k].iter().position(|n| n == name) {
                Some(j) => brtd[j],
                None => self.function.call(name, &arguments, &context),
            };
        }
        let brtd = DVec3::from_array(brtd);
        if bright(brtd) > FTINY {
            c += brtd * (ldot.abs() * omega_sr);
        }
        c
    }

    /// One of the four components, chosen in proportion to its brightness: the mirror ray,
    /// the straight transmitted ray, or a cosine-distributed diffuse ray on either side.
    pub fn sample(&self, allow_diffuse: bool, rng: &mut Rng) -> Scatter {
        let Some((pick, weight)) = choose_component(&self.components(allow_diffuse), rng) else {
            return Scatter::Absorbed;
        };
        match pick {
            0 => Scatter::Specular {
                direction: reflect(self.rdir, self.pnorm).normalize(),
                weight,
            },
            1 => Scatter::Specular {
                direction: self.rdir,
                weight,
            },
            2 => Scatter::Diffuse {
                direction: cosine_direction(self.ambient_normal, rng),
                weight,
            },
            _ => Scatter::Diffuse {
                direction: cosine_direction(-self.ambient_normal, rng),
                weight,
            },
        }
    }
}
