//! How surfaces scatter light, as RADIANCE shades them, so that our estimates converge to
//! what `rtrace` computes: one file per family ([`normal`]: `plastic`, `metal`, `trans`;
//! [`anisotropic`]: `plastic2`, `metal2`, `trans2`; [`brdf_function`]: `plasfunc` ..
//! `transdata`; [`brtdfunc`]; [`glass`]; [`mirror`]; [`emitter`]: `light` and `glow` on
//! surfaces), the optics they share in [`scattering`]; [`bsdf`]: `BSDF` and `aBSDF` from
//! WINDOW / LBNL XML data.
//!
//! The integrator, the per-ray radiance, shadow rays and virtual sources ask a [`Material`]
//! what happens at a hit ([`Material::interact`], [`Material::shading`],
//! [`Material::shadow_crossing`] and the properties below) and never look at its kind. A new
//! material (a WINDOW XML BSDF, `BRTDfunc`, `plastic2`, `dielectric`) is one more file here
//! and one more arm of [`Material`] (and of [`Shading`] if direct light is estimated at it),
//! converted in [`Material::from_modifier`]; the integrator does not change.
//!
//! Surfaces are two-sided (RADIANCE's default `-bv+`): hitting the back of a surface shades
//! it with the normal turned towards the ray (`flipsurface`).

pub mod anisotropic;
pub mod brdf_function;
pub mod brtdfunc;
pub mod bsdf;
pub mod dielectric;
pub mod emitter;
pub mod glass;
pub mod illum;
pub mod mirror;
pub mod normal;
pub mod scattering;
pub mod spotlight;

pub use anisotropic::{AnisotropicMaterial, AnisotropicShading};
pub use brdf_function::{BrdfFunctionMaterial, BrdfFunctionShading};
pub use brtdfunc::{BrtdMaterial, BrtdShading};
/// Where `validation::glazing` finds it; its home is [`crate::engine::sampling`].
pub use bsdf::{BsdfMaterial, BsdfShading};
pub use dielectric::DielectricMaterial;
pub use emitter::Emitter;
pub use glass::GlassMaterial;
pub use illum::IllumMaterial;
pub use mirror::MirrorMaterial;
pub use normal::{NormalKind, NormalMaterial, NormalShading};
pub use scattering::{bright, DiffuseLobe, Scatter};
pub use spotlight::SpotlightMaterial;

use super::error::EngineError;
use super::rng::Rng;
use super::sky::SkyFunction;
use crate::bsdf::Bsdf;
use crate::scene::{BsdfModifier, Modifier, ModifierKind, ModifierRef, Scene, Surface};
use glam::DVec3;
use std::sync::Arc;

/// A surface's material, ready for shading.
#[derive(Clone, Debug)]
pub enum Material {
    Normal(NormalMaterial),
    Glass(GlassMaterial),
    Mirror(MirrorMaterial),
    Emitter(Emitter),
    Bsdf(BsdfMaterial),
    Dielectric(DielectricMaterial),
    Spotlight(SpotlightMaterial),
    Illum(IllumMaterial),
    /// A material with function modifiers: resolved at each hit ([`Material::at_hit`])
    /// into one of the others; asked directly, it behaves as an opaque black surface.
    Varying(std::sync::Arc<dyn HitDependent>),
    /// A material as shaded at one hit (what [`Material::at_hit`] makes of a `BRTDfunc` or a
    /// textured material).
    Shaded(Box<Shading>),
    /// Modifier chain ends at `void` without a material: rays pass through.
    Invisible,
}

/// Where a ray meets a surface: what a material that varies from hit to hit is resolved
/// with.
#[derive(Clone, Copy, Debug)]
pub struct HitPoint {
    pub point_m: DVec3,
    /// Unit ray direction.
    pub direction: DVec3,
    /// The surface's own normal.
    pub normal: DVec3,
    pub distance_m: f64,
    pub flat: bool,
}

/// A mirror's reflectance for the sun it relays (m_mirror.c: the colour times its patterns).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VirtualSourceReflectance {
    Uniform(DVec3),
    /// Patterned: the material is resolved where the relayed ray meets it.
    AtEachPoint,
}

/// A material whose optics are functions of the hit (`engine::function`: patterns,
/// textures, `BRTDfunc`, `mixfunc`).
pub trait HitDependent: std::fmt::Debug + Send + Sync {
    /// The plain material at `hit` and the normal to shade it with.
    fn resolve(&self, hit: &HitPoint, rng: &mut Rng) -> (Material, DVec3);
    /// What a shadow ray does at `hit`.
    fn shadow_crossing(&self, hit: &HitPoint) -> ShadowCrossing;
    /// A `mirror` under patterns or textures: a plane of it relays the sun.
    fn is_mirror(&self) -> bool {
        false
    }
}

/// What happens to a ray at a hit ([`Material::interact`]).
#[derive(Clone, Debug)]
pub enum Interaction<'a> {
    /// No material: the ray goes on unchanged (not a scattering event).
    PassThrough,
    /// The path ends here and receives this radiance (W/sr/m² per RGB channel).
    Emits(DVec3),
    /// The path ends here with no light.
    Absorbed,
    /// A purely specular surface: one specular event, drawn by [`SpecularStep::sample`] once
    /// the caller has counted it against its limit.
    Specular(SpecularStep<'a>),
    /// A surface shaded as RADIANCE's normal.c does: the caller estimates direct light with
    /// the shading and continues the path by sampling it.
    Shaded(Shading),
}

/// A specular event not yet drawn: what [`Interaction::Specular`] carries.
#[derive(Clone, Debug)]
pub struct SpecularStep<'a> {
    material: &'a Material,
    direction: DVec3,
    normal: DVec3,
}

impl SpecularStep<'_> {
    /// The new direction and the throughput weight (the coefficient over the probability of
    /// the choice), or [`Scatter::Absorbed`].
    pub fn sample(&self, rng: &mut Rng) -> Scatter {
        match self.material {
            Material::Glass(g) => g.sample(self.direction, self.normal, rng),
            Material::Mirror(m) => m.sample(self.direction, self.normal),
            Material::Dielectric(m) => m.sample(self.direction, self.normal, rng),
            _ => Scatter::Absorbed,
        }
    }
}

/// A surface's scattering at one hit, for next-event estimation and for sampling the path's
/// continuation (pbrt's BSDF).
#[derive(Clone, Debug)]
pub enum Shading {
    Normal(NormalShading),
    Bsdf(BsdfShading),
    Brtd(Box<BrtdShading>),
    /// `plasfunc`, `metfunc`, `transfunc` and their data forms.
    Function(Box<BrdfFunctionShading>),
    /// `plastic2`, `metal2`, `trans2`.
    Anisotropic(Box<AnisotropicShading>),
}

impl Shading {
    /// The coefficient that turns the radiance of a source of solid angle `omega_sr` seen in
    /// unit direction `ldir` into radiance leaving towards the ray (normal.c `dirnorm`).
    pub fn source_coefficient(&self, ldir: DVec3, omega_sr: f64) -> DVec3 {
        match self {
            Shading::Normal(s) => s.source_coefficient(ldir, omega_sr),
            Shading::Bsdf(s) => s.source_coefficient(ldir, omega_sr),
            Shading::Brtd(s) => s.source_coefficient(ldir, omega_sr),
            Shading::Function(s) => s.source_coefficient(ldir, omega_sr),
            Shading::Anisotropic(s) => s.source_coefficient(ldir, omega_sr),
        }
    }

    /// The Lambertian part as [`Shading::sample`] samples it, for multiple importance
    /// sampling with next-event estimation; None when no diffuse component would be sampled.
    pub fn diffuse_lobe(&self, allow_diffuse: bool) -> Option<DiffuseLobe> {
        match self {
            Shading::Normal(s) => s.diffuse_lobe(allow_diffuse),
            // The sky reaches a BSDF vertex by its own sampling (as in RADIANCE, where the
            // sky is not a source): no next-event strategy to weigh against.
            Shading::Bsdf(_) => None,
            Shading::Brtd(s) => s.diffuse_lobe(allow_diffuse),
            Shading::Function(s) => s.diffuse_lobe(allow_diffuse),
            Shading::Anisotropic(s) => s.diffuse_lobe(allow_diffuse),
        }
    }

    /// Where light arriving from, or a path leaving towards, unit direction `dir` is traced
    /// from for a hit at `p_m`: `p_m` itself, except across a proxy (a `BSDF` with thickness),
    /// which hands transmitted light over beyond the detailed geometry it stands for
    /// (m_bsdf.c offsets those rays by the thickness).
    pub fn origin_towards(&self, p_m: DVec3, dir: DVec3) -> DVec3 {
        match self {
            Shading::Bsdf(s) => s.origin_towards(p_m, dir),
            Shading::Normal(_)
            | Shading::Brtd(_)
            | Shading::Function(_)
            | Shading::Anisotropic(_) => p_m,
        }
    }

    /// What a shadow ray keeps crossing this surface (straight); a BSDF's shading is not
    /// asked (its material answers for shadow rays) and blocks.
    pub fn shadow_transmission(&self) -> DVec3 {
        match self {
            Shading::Normal(s) => s.shadow_transmission(),
            Shading::Brtd(s) => s.shadow_transmission(),
            Shading::Anisotropic(s) => s.shadow_transmission(),
            // m_brdf2 is "always a shadow".
            Shading::Bsdf(_) | Shading::Function(_) => DVec3::ZERO,
        }
    }

    /// Samples the continuation; diffuse components only if `allow_diffuse` (ambient bounces
    /// left).
    pub fn sample(&self, allow_diffuse: bool, rng: &mut Rng) -> Scatter {
        match self {
            Shading::Normal(s) => s.sample(allow_diffuse, rng),
            Shading::Bsdf(s) => s.sample(allow_diffuse, rng),
            Shading::Brtd(s) => s.sample(allow_diffuse, rng),
            Shading::Function(s) => s.sample(allow_diffuse, rng),
            Shading::Anisotropic(s) => s.sample(allow_diffuse, rng),
        }
    }
}

/// What a shadow ray (towards a source, straight) does at a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadowCrossing {
    /// No material: not there for the shadow ray.
    PassThrough,
    /// Crossed, keeping this fraction per RGB channel (zero: blocked).
    Transmits(DVec3),
    /// Blocks the shadow ray.
    Opaque,
}

/// What a shadow ray towards a light source does at a surface ([`Material::source_crossing`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SourceCrossing {
    /// As any shadow ray does.
    Straight(ShadowCrossing),
    /// Turned into unit `direction`, keeping `factor` per RGB channel (a `dielectric`).
    Refracts { direction: DVec3, factor: DVec3 },
}

impl Material {
    /// This material at `hit`, and the normal to shade it with (the surface's own unless a
    /// texture tilts it): borrowed unless it varies from hit to hit.
    pub fn at_hit(&self, hit: &HitPoint, rng: &mut Rng) -> (std::borrow::Cow<'_, Material>, DVec3) {
        match self {
            Material::Varying(v) => {
                let (m, n) = v.resolve(hit, rng);
                (std::borrow::Cow::Owned(m), n)
            }
            _ => (std::borrow::Cow::Borrowed(self), hit.normal),
        }
    }

    /// What a shadow ray does at `hit` ([`Material::shadow_crossing`] for any material).
    pub fn shadow_crossing_at(&self, hit: &HitPoint) -> ShadowCrossing {
        match self {
            Material::Varying(v) => v.shadow_crossing(hit),
            _ => self.shadow_crossing(hit.direction, hit.normal, hit.flat),
        }
    }

    /// What a shadow ray towards a light source, straight, does at `hit`: as
    /// [`Material::shadow_crossing_at`], except that an `aBSDF` passes it with its through
    /// component (as [`Material::source_crossing`] does).
    pub fn light_crossing_at(&self, hit: &HitPoint) -> ShadowCrossing {
        match self {
            Material::Bsdf(m) if m.through => through_crossing(m, hit.direction, hit.normal),
            _ => self.shadow_crossing_at(hit),
        }
    }

    /// Whether [`Material::at_hit`] may give a shaded material (see [`Material::is_shaded`]).
    pub fn is_shaded_somewhere(&self) -> bool {
        matches!(self, Material::Varying(_)) || self.is_shaded()
    }

    /// What a ray in unit direction `d` does on meeting this material on a surface of front
    /// normal `normal` (`flat` for polygons and rings). `primary`: the ray descends from no
    /// ambient or specular ray (a camera ray), which sees a `glow` that does not illuminate.
    pub fn interact(&self, d: DVec3, normal: DVec3, flat: bool, primary: bool) -> Interaction<'_> {
        match self {
            Material::Invisible => Interaction::PassThrough,
            Material::Emitter(e) => match e.seen(d, normal, primary) {
                Some(l) => Interaction::Emits(l),
                None => Interaction::Absorbed,
            },
            Material::Spotlight(s) => match s.seen(d, normal, primary) {
                Some(l) => Interaction::Emits(l),
                None => Interaction::Absorbed,
            },
            Material::Illum(i) if IllumMaterial::is_front(d, normal) && !primary => {
                Interaction::Emits(i.emitter.radiance(d))
            }
            Material::Illum(i) => i.alternate.interact(d, normal, flat, primary),
            Material::Mirror(_) if MirrorMaterial::is_back(d, normal) => Interaction::Absorbed,
            Material::Mirror(_) | Material::Glass(_) | Material::Dielectric(_) => {
                Interaction::Specular(SpecularStep {
                    material: self,
                    direction: d,
                    normal,
                })
            }
            Material::Normal(m) => Interaction::Shaded(Shading::Normal(m.shade(d, normal, flat))),
            Material::Bsdf(m) if m.passes(d, normal, primary) => Interaction::PassThrough,
            Material::Bsdf(m) => match m.shade_as(d, normal, primary) {
                Some(s) => Interaction::Shaded(Shading::Bsdf(s)),
                None => Interaction::Absorbed,
            },
            Material::Shaded(s) => Interaction::Shaded((**s).clone()),
            Material::Varying(_) => Interaction::Absorbed,
        }
    }

    /// The shading of a ray in unit direction `rdir` at a surface of front normal `normal`,
    /// if this material is shaded with direct light (None for specular, emitting and
    /// invisible surfaces).
    pub fn shading(&self, rdir: DVec3, normal: DVec3, flat: bool) -> Option<Shading> {
        match self {
            Material::Normal(m) => Some(Shading::Normal(m.shade(rdir, normal, flat))),
            Material::Bsdf(m) if !m.passes(rdir, normal, false) => {
                m.shade(rdir, normal).map(Shading::Bsdf)
            }
            Material::Illum(i) if !IllumMaterial::is_front(rdir, normal) => {
                i.alternate.shading(rdir, normal, flat)
            }
            Material::Shaded(s) => Some((**s).clone()),
            _ => None,
        }
    }

    /// Whether [`Material::shading`] gives a shading (for an `illum`, from its back).
    pub fn is_shaded(&self) -> bool {
        match self {
            Material::Normal(_) | Material::Bsdf(_) | Material::Shaded(_) => true,
            Material::Illum(i) => i.alternate.is_shaded(),
            _ => false,
        }
    }

    /// What a shadow ray along unit `dir` does at a surface of front normal `normal`:
    /// RADIANCE traces shadow rays through `glass` and smooth `trans` (glass.c, normal.c).
    pub fn shadow_crossing(&self, dir: DVec3, normal: DVec3, flat: bool) -> ShadowCrossing {
        match self {
            Material::Invisible => ShadowCrossing::PassThrough,
            Material::Glass(g) => ShadowCrossing::Transmits(g.shadow_transmission(dir, normal)),
            Material::Normal(m) => {
                ShadowCrossing::Transmits(m.shade(dir, normal, flat).shadow_transmission())
            }
            Material::Bsdf(m) if m.shadow_passes() => ShadowCrossing::PassThrough,
            Material::Bsdf(_) => ShadowCrossing::Opaque,
            Material::Shaded(s) => ShadowCrossing::Transmits(s.shadow_transmission()),
            // Light reaching a point through an illum's front or a dielectric is what the
            // path's own continuation finds (an emitter hit, a refracted path), so no other
            // estimate may count it.
            Material::Illum(_) if IllumMaterial::is_front(dir, normal) => ShadowCrossing::Opaque,
            Material::Illum(i) => i.alternate.shadow_crossing(dir, normal, flat),
            Material::Mirror(_)
            | Material::Emitter(_)
            | Material::Spotlight(_)
            | Material::Dielectric(_)
            | Material::Varying(_) => ShadowCrossing::Opaque,
        }
    }

    /// What a view (camera) ray along unit `d` meeting a surface of front normal `normal` of
    /// this material goes on straight with besides its shading: an `aBSDF`'s through
    /// transmittance (m_bsdf.c traces it as a ray of its own), 0 elsewhere.
    pub fn view_through(&self, d: DVec3, normal: DVec3) -> f64 {
        match self {
            Material::Bsdf(m) => m.through_transmittance(d, normal),
            _ => 0.0,
        }
    }

    /// What a shadow ray towards a light source (the sun) does at a surface: an `illum` is
    /// its alternate material to it (source.c `passillum`), and a `dielectric` refracts it
    /// (dielectric.c traces shadow rays through), and an `aBSDF` passes it with its through
    /// component (m_bsdf.c).
    pub fn source_crossing(&self, dir: DVec3, normal: DVec3, flat: bool) -> SourceCrossing {
        match self {
            Material::Illum(i) => i.alternate.source_crossing(dir, normal, flat),
            // m_bsdf.c passes shadow rays through an aBSDF with its through component.
            Material::Bsdf(m) if m.through => {
                SourceCrossing::Straight(through_crossing(m, dir, normal))
            }
            Material::Dielectric(m) => match m.shadow_refraction(dir, normal) {
                Some((direction, factor)) => SourceCrossing::Refracts { direction, factor },
                None => SourceCrossing::Straight(ShadowCrossing::Opaque),
            },
            _ => SourceCrossing::Straight(self.shadow_crossing(dir, normal, flat)),
        }
    }

    /// Whether shadow rays towards light sources need [`Material::source_crossing`] rather
    /// than [`Material::shadow_crossing`].
    pub fn has_source_crossing(&self) -> bool {
        matches!(self, Material::Illum(_) | Material::Dielectric(_))
            || matches!(self, Material::Bsdf(m) if m.through)
    }

    /// The factor on the light a ray brings back from this surface after `distance_m` from
    /// its origin: absorption in the medium a `dielectric` is met from, and a `spotlight`'s
    /// fall-off from its focus for rays that are not `primary` (they stand for RADIANCE's
    /// direct samples); 1 elsewhere.
    pub fn arrival_factor(&self, d: DVec3, normal: DVec3, distance_m: f64, primary: bool) -> DVec3 {
        match self {
            Material::Dielectric(m) => m.arrival_attenuation(d, normal, distance_m),
            Material::Spotlight(s) if !primary => DVec3::splat(s.focus_factor(distance_m)),
            _ => DVec3::ONE,
        }
    }

    /// Purely diffuse and opaque: the radiance it sends is the same towards every viewer on
    /// one side, so one path's estimate of it can serve other sensors (path reuse).
    pub fn is_lambertian(&self) -> bool {
        matches!(self, Material::Normal(m) if m.is_lambertian())
    }

    /// Glass or no material: light crosses it without turning, so a polygon of it can be a
    /// portal, and the sun-patch strategy follows sunlight past it.
    pub fn is_clear(&self) -> bool {
        matches!(self, Material::Glass(_) | Material::Invisible)
    }

    /// The reflectance with which a plane surface of this material mirrors distant sources
    /// into virtual sources (RADIANCE virtuals.c), if it does.
    pub fn virtual_source_reflectance(&self) -> Option<VirtualSourceReflectance> {
        match self {
            Material::Mirror(m) => Some(VirtualSourceReflectance::Uniform(m.reflectance_rgb)),
            Material::Varying(v) if v.is_mirror() => Some(VirtualSourceReflectance::AtEachPoint),
            _ => None,
        }
    }

    /// [`Material::from_modifier`], with an `illum`'s alternate material looked up in `scene`.
    pub fn from_scene(
        scene: &Scene,
        surface: &Surface,
        modifier: Option<&Modifier>,
        patterns: Vec<SkyFunction>,
    ) -> Result<Material, EngineError> {
        let mut material = Self::from_modifier(surface, modifier, patterns)?;
        if let Some(ModifierKind::Antimatter(a)) = modifier.map(|m| &m.kind) {
            let first = a.subtracted.first().copied().unwrap_or(ModifierRef::Void);
            return Self::from_scene(scene, surface, scene.material(first), Vec::new());
        }
        if let (Material::Illum(i), Some(m)) = (&mut material, modifier) {
            if let ModifierKind::Illum(illum) = &m.kind {
                let alternate = match illum.alternate_material {
                    Some(ModifierRef::Defined(id)) => scene.material(ModifierRef::Defined(id)),
                    _ => None,
                };
                if alternate.is_some_and(|a| matches!(a.kind, ModifierKind::Illum(_))) {
                    return Err(EngineError::Unsupported {
                        at: m.origin.clone(),
                        what: format!("illum `{}` has another illum as its material", m.name),
                    });
                }
                *i.alternate = Self::from_scene(scene, surface, alternate, Vec::new())?;
            }
        }
        Ok(material)
    }

    /// The material of `surface` from the first material `modifier` on its chain (None:
    /// `void`, invisible) and the `brightfunc` `patterns` found on the chain.
    pub fn from_modifier(
        surface: &Surface,
        modifier: Option<&Modifier>,
        patterns: Vec<SkyFunction>,
    ) -> Result<Material, EngineError> {
        let Some(m) = modifier else {
            return Ok(Material::Invisible);
        };
        let emitter = matches!(
            m.kind,
            ModifierKind::Light(_)
                | ModifierKind::Glow(_)
                | ModifierKind::Spotlight(_)
                | ModifierKind::Illum(_)
        );
        if !patterns.is_empty() && !emitter {
            return Err(EngineError::Unsupported {
                at: surface.origin.clone(),
                what: format!(
                    "surface `{}`: a brightfunc pattern on a {} material; patterns are traced \
                     on light and glow only",
                    surface.name,
                    m.kind.type_name()
                ),
            });
        }
        Ok(match &m.kind {
            ModifierKind::Plastic(p) => Material::Normal(NormalMaterial::from(p)),
            ModifierKind::Metal(p) => Material::Normal(NormalMaterial::from(p)),
            ModifierKind::Trans(p) => Material::Normal(NormalMaterial::from(p)),
            ModifierKind::Glass(g) => Material::Glass(GlassMaterial::from(g)),
            ModifierKind::Mirror(mirror) => {
                if mirror.alternate_material.is_some() {
                    return Err(EngineError::Unsupported {
                        at: m.origin.clone(),
                        what: format!(
                            "mirror `{}` with an alternate material is not traced yet",
                            m.name
                        ),
                    });
                }
                Material::Mirror(MirrorMaterial {
                    reflectance_rgb: mirror.reflectance_rgb,
                    surface_normal: None,
                })
            }
            ModifierKind::Light(l) => Material::Emitter(Emitter {
                radiance_w_sr_m2: l.radiance_w_sr_m2,
                patterns,
                illuminates: true,
            }),
            ModifierKind::Glow(g) => Material::Emitter(Emitter {
                radiance_w_sr_m2: g.radiance_w_sr_m2,
                patterns,
                illuminates: Emitter::glow_illuminates(g.max_radius_m),
            }),
            ModifierKind::Bsdf(b) => Material::Bsdf(bsdf_material(m, b)?),
            ModifierKind::Dielectric(d) => Material::Dielectric(DielectricMaterial::from(d)),
            ModifierKind::Spotlight(s) => Material::Spotlight(SpotlightMaterial {
                emitter: Emitter {
                    radiance_w_sr_m2: s.radiance_w_sr_m2,
                    patterns,
                    illuminates: true,
                },
                direction: s.direction,
                cos_half_angle: (0.5 * s.cone_angle_deg.to_radians()).cos(),
                focal_length_m: s.focal_length_m,
            }),
            ModifierKind::Illum(i) => Material::Illum(IllumMaterial {
                emitter: Emitter {
                    radiance_w_sr_m2: i.radiance_w_sr_m2,
                    patterns,
                    illuminates: true,
                },
                alternate: Box::new(Material::Invisible),
            }),
            // Shaded as its first modifier's material, set by `from_scene`.
            ModifierKind::Antimatter(_) => Material::Invisible,
            ModifierKind::Brightfunc(_)
            | ModifierKind::Colorfunc(_)
            | ModifierKind::Brightdata(_)
            | ModifierKind::Colordata(_)
            | ModifierKind::Colorpict(_)
            | ModifierKind::Texfunc(_)
            | ModifierKind::Texdata(_)
            | ModifierKind::Mixfunc(_)
            | ModifierKind::Mixdata(_)
            | ModifierKind::Mixpict(_)
            | ModifierKind::BrtdFunc(_)
            | ModifierKind::BrdfFunc(_)
            | ModifierKind::Anisotropic(_)
            | ModifierKind::Brighttext(_)
            | ModifierKind::Colortext(_)
            | ModifierKind::Mixtext(_) => {
                return Err(EngineError::Unsupported {
                    at: m.origin.clone(),
                    what: format!(
                        "internal: {} `{}` is built by engine::function",
                        m.kind.type_name(),
                        m.name
                    ),
                })
            }
        })
    }
}

/// A shadow ray towards a light source along unit `dir` at an `aBSDF` of front normal
/// `normal`: crossed with the through transmittance, blocked where there is none.
fn through_crossing(m: &BsdfMaterial, dir: DVec3, normal: DVec3) -> ShadowCrossing {
    match m.through_transmittance(dir, normal) {
        t if t > 0.0 => ShadowCrossing::Transmits(DVec3::splat(t)),
        _ => ShadowCrossing::Opaque,
    }
}

/// A `BSDF` modifier's material with its XML data loaded; a file that cannot be read is an
/// error naming the scene file and line, the material and the XML file, element and line.
fn bsdf_material(m: &Modifier, b: &BsdfModifier) -> Result<BsdfMaterial, EngineError> {
    let data = Bsdf::load(&b.xml_path).map_err(|error| EngineError::BsdfFile {
        at: m.origin.clone(),
        material: m.name.clone(),
        error: Box::new(error),
    })?;
    Ok(BsdfMaterial::new(b, Arc::new(data)))
}
