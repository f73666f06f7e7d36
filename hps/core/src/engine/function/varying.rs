//! Materials that change from hit to hit: a material under `brightfunc`/`colorfunc`/
//! `brightdata`/`colordata` patterns and `texfunc`/`texdata` textures, a `BRTDfunc`, a
//! function or anisotropic material, a `mixfunc` or `mixdata` of two modifiers. Each is
//! resolved at a hit into a plain [`Material`] and a shading normal, which the integrator
//! then uses as it uses any other; it never learns which kind it was.

use super::data::DataArray;
use super::loader::CompiledFunction;
use super::ray::FunctionRay;
use super::text::TextLayout;
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
    Data(DataLookup),
    /// `texdata`: three arrays and functions giving the perturbation.
    DataTexture(DataLookup),
    /// `brighttext` or `colortext`: multiplies the colour by one value inside the glyphs
    /// and another elsewhere (text.c `do_text`).
    Text {
        layout: Arc<TextLayout>,
        foreground_rgb: DVec3,
        background_rgb: DVec3,
    },
    /// A `mixfunc`, `mixdata`, `mixpict` or `mixtext` of two patterns (or `void`): their
    /// colours and perturbations blended by the coefficient, clamped to 0..1 (raytrace.c
    /// `raymixture`; a coefficient of 0 or 1 takes one side alone, as text.c does).
    Mixture {
        coefficient: MixCoefficient,
        /// The foreground's and the background's patterns and textures.
        sides: Box<[Vec<Modulation>; 2]>,
    },
}

/// Data files interpolated at coordinates given by expressions, then passed through
/// functions (p_data.c, t_data.c, mx_data.c).
#[derive(Clone, Debug)]
pub struct DataLookup {
    /// The coordinate expressions (one per dimension), with their file.
    pub coordinates: Arc<CompiledFunction>,
    /// The functions of the interpolated values (1 or 3).
    pub functions: Vec<String>,
    /// The data files (1 or 3), of as many dimensions as there are coordinates.
    pub arrays: Vec<Arc<DataArray>>,
}

/// What decides between a mixture's two sides.
#[derive(Clone, Debug)]
pub enum MixCoefficient {
    /// `mixfunc`: an expression.
    Function(Arc<CompiledFunction>),
    /// `mixdata`: a function of a data file's value.
    Data(DataLookup),
    /// `mixtext`: 1 inside the glyphs, 0 elsewhere.
    Text(Arc<TextLayout>),
}

impl MixCoefficient {
    /// The coefficient at `hit` (the foreground's share).
    fn at(&self, hit: &HitPoint) -> f64 {
        match self {
            MixCoefficient::Function(f) => f.value(0, &function_ray(f, hit)),
            MixCoefficient::Data(d) => d.evaluate(hit, false).first().copied().unwrap_or(0.0),
            MixCoefficient::Text(t) => f64::from(u8::from(t.is_foreground(hit.point_m))),
        }
    }
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
        coefficient: MixCoefficient,
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
                Material::Glass(g) if m.perturbation != DVec3::ZERO => {
                    Material::Glass(g.textured(m.perturbation, hit.direction, hit.normal))
                }
                Material::Mirror(mut mirror) if normal != hit.normal => {
                    mirror.surface_normal = Some(hit.normal);
                    Material::Mirror(mirror)
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
                let c = coefficient.at(hit);
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

    fn is_mirror(&self) -> bool {
        matches!(self.base, VaryingBase::Plain(Material::Mirror(_)))
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
                let c = coefficient.at(hit).clamp(0.0, 1.0);
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
        modulate(&self.modulations, hit)
    }
}

/// The modulations applied in turn to a neutral colour (1) and perturbation (0).
fn modulate(modulations: &[Modulation], hit: &HitPoint) -> Modulated {
    let mut m = Modulated {
        color_rgb: DVec3::ONE,
        perturbation: DVec3::ZERO,
    };
    for modulation in modulations {
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
                m.perturbation += to_scene_perturbation(local, f);
            }
            Modulation::Data(d) => m.color_rgb *= d.colour(hit),
            Modulation::DataTexture(d) => {
                if let [x, y, z] = d.evaluate(hit, true)[..] {
                    m.perturbation += to_scene_perturbation(DVec3::new(x, y, z), &d.coordinates);
                }
            }
            Modulation::Text {
                layout,
                foreground_rgb,
                background_rgb,
            } => {
                m.color_rgb *= if layout.is_foreground(hit.point_m) {
                    *foreground_rgb
                } else {
                    *background_rgb
                };
            }
            Modulation::Mixture { coefficient, sides } => {
                let c = coefficient.at(hit).clamp(0.0, 1.0);
                // A coefficient of 1 or 0 takes one side alone (the other is not evaluated).
                let blend = if c == 1.0 {
                    modulate(&sides[0], hit)
                } else if c == 0.0 {
                    modulate(&sides[1], hit)
                } else {
                    let (f, b) = (modulate(&sides[0], hit), modulate(&sides[1], hit));
                    Modulated {
                        color_rgb: c * f.color_rgb + (1.0 - c) * b.color_rgb,
                        perturbation: c * f.perturbation + (1.0 - c) * b.perturbation,
                    }
                };
                m.color_rgb *= blend.color_rgb;
                m.perturbation += blend.perturbation;
            }
        }
    }
    m
}

/// t_func.c, t_data.c: a perturbation in the function's frame taken to the scene's by the
/// forward transform and divided by its scale.
fn to_scene_perturbation(local: DVec3, f: &CompiledFunction) -> DVec3 {
    let t = &f.args.transform;
    let column = |j: usize| DVec3::new(t.forward[0][j], t.forward[1][j], t.forward[2][j]);
    DVec3::new(
        local.dot(column(0)),
        local.dot(column(1)),
        local.dot(column(2)),
    ) / t.scale
}

impl DataLookup {
    /// p_data.c, t_data.c, mx_data.c: the arrays interpolated at the coordinates, then each
    /// function of its channel's value, or of the three values if it takes three arguments
    /// or `texture` (t_data.c passes all three); one value per function.
    fn evaluate(&self, hit: &HitPoint, texture: bool) -> Vec<f64> {
        let ray = function_ray(&self.coordinates, hit);
        let point = self.coordinates.all_values(&ray);
        let values: Vec<f64> = self.arrays.iter().map(|a| a.value(&point)).collect();
        let all = |name: &str| {
            values.len() == 3
                && (texture || self.coordinates.parameter_count(name).unwrap_or(1) >= 3)
        };
        self.functions
            .iter()
            .enumerate()
            .map(|(k, name)| {
                if all(name) {
                    self.coordinates.call(name, &values, &ray)
                } else {
                    let own = &values[k.min(values.len() - 1)..][..1];
                    self.coordinates.call(name, own, &ray)
                }
            })
            .collect()
    }

    /// The colour of a `brightdata` (grey) or `colordata`.
    fn colour(&self, hit: &HitPoint) -> DVec3 {
        match self.evaluate(hit, false)[..] {
            [r, g, b] => DVec3::new(r, g, b),
            [v, ..] => DVec3::splat(v),
            [] => DVec3::ONE,
        }
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

/// A plain material with its colour scaled by a pattern: a normal material's colour, a
/// glass's transmitted part (glass.c: after the Fresnel terms; its reflection is not
/// patterned).
fn coloured(material: &Material, color_rgb: DVec3) -> Material {
    let mut m = material.clone();
    if color_rgb != DVec3::ONE {
        match &mut m {
            Material::Normal(n) => n.color_rgb *= color_rgb,
            Material::Glass(g) => g.pattern_rgb *= color_rgb,
            Material::Mirror(mirror) => mirror.reflectance_rgb *= color_rgb,
            // source.c m_light: the pattern scales the emitted radiance (an IES
            // distribution from ies2rad, say).
            Material::Emitter(e) => e.radiance_w_sr_m2 *= color_rgb,
            _ => {}
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
