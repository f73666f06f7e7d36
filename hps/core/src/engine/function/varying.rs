//! Materials that change from hit to hit: a material under `brightfunc`/`colorfunc`
//! patterns and `texfunc` textures, a `BRTDfunc`, a `mixfunc` of two modifiers. Each is
//! resolved at a hit into a plain [`Material`] and a shading normal, which the integrator
//! then uses as it uses any other; it never learns which kind it was.

use super::data::DataArray;
use super::loader::CompiledFunction;
use super::ray::FunctionRay;
use crate::engine::material::{
    AnisotropicMaterial, BrdfFunctionMaterial, BrtdMaterial, HitDependent, HitPoint, Material,
    Shading, ShadowCrossing,
};
use crate::engine::rng::Rng;
use glam::DVec3;
use std::sync::Arc;

/// A function modifier on a material's chain.
#[derive(Clone, Debug)]
pub enum Modulation {
    /// `brightfunc` (one expression) or `colorfunc` (three): multiplies the colour.
    Pattern(Arc<CompiledFunction>),
    /// `texfunc`: adds a perturbation to the normal.
    Texture(Arc<CompiledFunction>),
    /// `brightdata` (one function and array) or `colordata` (three).
    Data {
        coordinates: Arc<CompiledFunction>,
        functions: Vec<String>,
        arrays: Vec<Arc<DataArray>>,
    },
}

/// The material below the modulations.
#[derive(Clone, Debug)]
pub enum VaryingBase {
    /// A plain material (`plastic`, `metal`, `trans`) whose colour patterns scale.
    Plain(Material),
    Brtd(Box<BrtdMaterial>),
    /// `plasfunc`, `metfunc`, `transfunc` and their data forms.
    Function(Arc<BrdfFunctionMaterial>),
    /// `plastic2`, `metal2`, `trans2`.
    Anisotropic(Box<AnisotropicMaterial>),
    /// `mixfunc`: the foreground where the coefficient is 1, the background where 0.
    Mix {
        coefficient: Arc<CompiledFunction>,
        foreground: Box<Material>,
        background: Box<Material>,
    },
}

/// A material whose optics are functions of the hit.
#[derive(Clone, Debug)]
pub struct VaryingMaterial {
    pub modulations: Vec<Modulation>,
    pub base: VaryingBase,
}

/// Pattern colour and texture perturbation at a hit (`raytexture`'s `pcol` and `pert`).
struct Modulated {
    color_rgb: DVec3,
    perturbation: DVec3,
}

impl HitDependent for VaryingMaterial {
    /// The plain material and the shading normal at `hit`; `rng` picks one side of a
    /// `mixfunc` with the probability of its coefficient (RADIANCE traces both and weights
    /// them: the same mean).
    fn resolve(&self, hit: &HitPoint, rng: &mut Rng) -> (Material, DVec3) {
        let m = self.modulate(hit);
        let normal = shading_normal(hit, m.perturbation);
        let material = match &self.base {
            VaryingBase::Plain(material) => match coloured(material, m.color_rgb) {
                // Tilted for direct light and reflection, not for the ambient hemisphere.
                Material::Normal(n) if normal != hit.normal => {
                    Material::Shaded(Box::new(Shading::Normal(
                        n.shade(hit.direction, normal, hit.flat)
                            .with_ambient_normal(hit.normal),
                    )))
                }
                plain => plain,
            },
            VaryingBase::Brtd(b) => Material::Shaded(Box::new(Shading::Brtd(Box::new(b.shade(
                hit.direction,
                hit.normal,
                normal,
                hit.point_m,
                hit.distance_m,
                m.color_rgb,
            ))))),
            VaryingBase::Function(f) => {
                Material::Shaded(Box::new(Shading::Function(Box::new(f.shade(
                    hit.direction,
                    hit.normal,
                    normal,
                    hit.point_m,
                    hit.distance_m,
                    m.color_rgb,
                )))))
            }
            VaryingBase::Anisotropic(a) => {
                Material::Shaded(Box::new(Shading::Anisotropic(Box::new(a.shade(
                    hit.direction,
                    hit.normal,
                    normal,
                    hit.point_m,
                    hit.distance_m,
                    m.color_rgb,
                    hit.flat,
                )))))
            }
            VaryingBase::Mix {
                coefficient,
                foreground,
                background,
            } => {
                let c = coefficient.value(0, &function_ray(coefficient, hit));
                let chosen = if rng.uniform() < c {
                    foreground
                } else {
                    background
                };
                let (inner, inner_normal) = chosen.at_hit(hit, rng);
                return (coloured(&inner, m.color_rgb), inner_normal);
            }
        };
        (material, normal)
    }

    /// What a shadow ray does here: for a `mixfunc`, the coefficient's blend of what each
    /// side transmits (a shadow ray has no random choice).
    fn shadow_crossing(&self, hit: &HitPoint) -> ShadowCrossing {
        if let VaryingBase::Function(_) | VaryingBase::Anisotropic(_) = &self.base {
            // m_brdf2 and m_aniso end every shadow ray.
            return ShadowCrossing::Opaque;
        }
        let m = self.modulate(hit);
        let normal = shading_normal(hit, m.perturbation);
        match &self.base {
            VaryingBase::Plain(material) => {
                coloured(material, m.color_rgb).shadow_crossing(hit.direction, normal, hit.flat)
            }
            VaryingBase::Brtd(b) => ShadowCrossing::Transmits(
                b.shade(
                    hit.direction,
                    hit.normal,
                    normal,
                    hit.point_m,
                    hit.distance_m,
                    m.color_rgb,
                )
                .shadow_transmission(),
            ),
            VaryingBase::Function(_) | VaryingBase::Anisotropic(_) => ShadowCrossing::Opaque,
            VaryingBase::Mix {
                coefficient,
                foreground,
                background,
            } => {
                let c = coefficient
                    .value(0, &function_ray(coefficient, hit))
                    .clamp(0.0, 1.0);
                let kept = |m: &Material| match m.shadow_crossing_at(hit) {
                    ShadowCrossing::PassThrough => DVec3::ONE,
                    ShadowCrossing::Transmits(t) => t,
                    ShadowCrossing::Opaque => DVec3::ZERO,
                };
                ShadowCrossing::Transmits(
                    (kept(foreground) * c + kept(background) * (1.0 - c)) * m.color_rgb,
                )
            }
        }
    }
}

impl VaryingMaterial {
    /// The product of the patterns and the sum of the textures' perturbations (t_func.c:
    /// each in the function's frame, taken back to the scene's by the forward transform and
    /// divided by its scale).
    fn modulate(&self, hit: &HitPoint) -> Modulated {
        let mut m = Modulated {
            color_rgb: DVec3::ONE,
            perturbation: DVec3::ZERO,
        };
        for modulation in &self.modulations {
            match modulation {
                Modulation::Pattern(f) => {
                    let ray = function_ray(f, hit);
                    m.color_rgb *= if f.args.expressions.len() == 1 {
                        DVec3::splat(f.value(0, &ray))
                    } else {
                        DVec3::from_array(f.values::<3>(0, &ray))
                    };
                }
                Modulation::Texture(f) => {
                    let local = DVec3::from_array(f.values::<3>(0, &function_ray(f, hit)));
                    let t = &f.args.transform;
                    let scene = DVec3::new(
                        local.dot(DVec3::new(
                            t.forward[0][0],
                            t.forward[1][0],
                            t.forward[2][0],
                        )),
                        local.dot(DVec3::new(
                            t.forward[0][1],
                            t.forward[1][1],
                            t.forward[2][1],
                        )),
                        local.dot(DVec3::new(
                            t.forward[0][2],
                            t.forward[1][2],
                            t.forward[2][2],
                        )),
                    );
                    m.perturbation += scene / t.scale;
                }
                Modulation::Data {
                    coordinates,
                    functions,
                    arrays,
                } => m.color_rgb *= data_colour(coordinates, functions, arrays, hit),
            }
        }
        m
    }
}

/// p_data.c: the arrays interpolated at the coordinates, then each channel's function of
/// its value (or of the three values, if it takes three arguments).
fn data_colour(
    coordinates: &CompiledFunction,
    functions: &[String],
    arrays: &[Arc<DataArray>],
    hit: &HitPoint,
) -> DVec3 {
    let ray = function_ray(coordinates, hit);
    let point = coordinates.all_values(&ray);
    let values: Vec<f64> = arrays.iter().map(|a| a.value(&point)).collect();
    let channel = |k: usize| {
        let name = &functions[k];
        if coordinates.parameter_count(name).unwrap_or(1) >= 3 && values.len() == 3 {
            coordinates.call(name, &values, &ray)
        } else {
            coordinates.call(name, &values[k.min(values.len() - 1)..][..1], &ray)
        }
    };
    if functions.len() == 1 {
        DVec3::splat(channel(0))
    } else {
        DVec3::new(channel(0), channel(1), channel(2))
    }
}

fn function_ray<'a>(f: &'a CompiledFunction, hit: &HitPoint) -> FunctionRay<'a> {
    FunctionRay {
        direction: hit.direction,
        normal: hit.normal,
        point_m: hit.point_m,
        distance_m: hit.distance_m,
        perturbed: None,
        transform: &f.args.transform,
        real_args: &f.args.real_args,
    }
}

/// A plain material with its colour scaled by a pattern.
fn coloured(material: &Material, color_rgb: DVec3) -> Material {
    let mut m = material.clone();
    if color_rgb != DVec3::ONE {
        if let Material::Normal(n) = &mut m {
            n.color_rgb *= color_rgb;
        }
    }
    m
}

/// RADIANCE's `raynormal`: the normal plus the perturbation, normalised, and mirrored
/// about the plane across the ray if that put it on the other side of the ray than the
/// surface's own normal.
fn shading_normal(hit: &HitPoint, perturbation: DVec3) -> DVec3 {
    if perturbation == DVec3::ZERO {
        return hit.normal;
    }
    let mut n = (hit.normal + perturbation).normalize_or(hit.normal);
    let own = -hit.direction.dot(hit.normal);
    let new = -hit.direction.dot(n);
    if (new > 0.0) != (own > 0.0) {
        n += 2.0 * new * hit.direction;
    }
    n
}
