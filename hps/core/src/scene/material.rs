//! Materials and patterns: the modifiers a surface can carry.
//!
//! Argument meanings are those of the RADIANCE reference manual (ray.html), §2.1.2
//! "Materials" and §2.1.4 "Patterns". Colours are RADIANCE's radiometric RGB, one value per
//! channel, kept as a `DVec3` (x = red, y = green, z = blue) so the engine can do channel-wise
//! arithmetic on them.

use super::error::{ArgumentList, SceneError};
use super::function::{brtd, data_pattern, function_args, BrtdFunc, DataPattern, FunctionArgs};
use super::parse::{PrimitiveType, RawPrimitive};
use glam::DVec3;

/// Index of a modifier in `Scene::modifiers`. A modifier always refers to modifiers with a
/// smaller index, so walking a chain of modifiers always ends.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ModifierId(usize);

impl ModifierId {
    pub(super) fn new(index: usize) -> Self {
        Self(index)
    }

    pub fn index(self) -> usize {
        self.0
    }
}

/// What a primitive names as its modifier: RADIANCE's built-in `void`, or the definition of
/// that name most recent at that point in the files (reference manual §2.1: later definitions
/// apply to the primitives after them and do not relink earlier ones).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum ModifierRef {
    Void,
    Defined(ModifierId),
}

/// Refractive index RADIANCE's `glass` uses when no fourth real argument is given.
pub const GLASS_DEFAULT_REFRACTIVE_INDEX: f64 = 1.52;

/// What a modifier is, with its arguments.
#[derive(Clone, Debug, PartialEq)]
pub enum ModifierKind {
    Plastic(Plastic),
    Metal(Metal),
    Trans(Trans),
    Glass(Glass),
    Mirror(Mirror),
    Light(Light),
    Glow(Glow),
    Brightfunc(Brightfunc),
    Colorfunc(FunctionArgs),
    Brightdata(DataPattern),
    Colordata(DataPattern),
    Texfunc(FunctionArgs),
    Mixfunc(Mixfunc),
    BrtdFunc(BrtdFunc),
}

impl ModifierKind {
    /// The RADIANCE type name (`plastic`, `brightfunc`, ...).
    pub fn type_name(&self) -> &'static str {
        match self {
            ModifierKind::Plastic(_) => "plastic",
            ModifierKind::Metal(_) => "metal",
            ModifierKind::Trans(_) => "trans",
            ModifierKind::Glass(_) => "glass",
            ModifierKind::Mirror(_) => "mirror",
            ModifierKind::Light(_) => "light",
            ModifierKind::Glow(_) => "glow",
            ModifierKind::Brightfunc(_) => "brightfunc",
            ModifierKind::Colorfunc(_) => "colorfunc",
            ModifierKind::Brightdata(_) => "brightdata",
            ModifierKind::Colordata(_) => "colordata",
            ModifierKind::Texfunc(_) => "texfunc",
            ModifierKind::Mixfunc(_) => "mixfunc",
            ModifierKind::BrtdFunc(_) => "BRTDfunc",
        }
    }

    /// Materials decide how a surface scatters or emits light; patterns (`brightfunc`,
    /// `colorfunc`) scale and textures (`texfunc`) tilt the material they modify.
    pub fn is_material(&self) -> bool {
        !matches!(
            self,
            ModifierKind::Brightfunc(_)
                | ModifierKind::Colorfunc(_)
                | ModifierKind::Brightdata(_)
                | ModifierKind::Colordata(_)
                | ModifierKind::Texfunc(_)
        )
    }
}

/// `plastic`: diffuse reflection with uncoloured highlights (manual §2.1.2, "Plastic").
#[derive(Clone, Debug, PartialEq)]
pub struct Plastic {
    /// Diffuse reflectance per channel (`red green blue`).
    pub reflectance_rgb: DVec3,
    /// Fraction of reflection that is specular (`spec`), 0..=1.
    pub specularity: f64,
    /// RMS slope of the surface facets (`rough`); 0 is perfectly smooth.
    pub roughness: f64,
}

/// `metal`: as plastic, but highlights take the material colour (manual §2.1.2, "Metal").
#[derive(Clone, Debug, PartialEq)]
pub struct Metal {
    /// Reflectance per channel (`red green blue`), also colouring the specular part.
    pub reflectance_rgb: DVec3,
    /// Fraction of reflection that is specular (`spec`), 0..=1.
    pub specularity: f64,
    /// RMS slope of the surface facets (`rough`).
    pub roughness: f64,
}

/// `trans`: infinitely thin translucent material (manual §2.1.2, "Trans").
#[derive(Clone, Debug, PartialEq)]
pub struct Trans {
    /// Material colour (`red green blue`), applied to diffuse reflection and transmission.
    pub color_rgb: DVec3,
    /// Fraction of reflection that is specular (`spec`), 0..=1.
    pub specularity: f64,
    /// RMS slope of the surface facets (`rough`).
    pub roughness: f64,
    /// Fraction of penetrating light that travels all the way through (`trans`), 0..=1.
    pub transmissivity: f64,
    /// Fraction of transmitted light that is not diffusely scattered (`tspec`), 0..=1.
    pub transmitted_specularity: f64,
}

/// `glass`: thin glazing, one transmitted and one reflected ray (manual §2.1.2, "Glass").
#[derive(Clone, Debug, PartialEq)]
pub struct Glass {
    /// Transmissivity at normal incidence per channel (`rtn gtn btn`): light not absorbed in
    /// one traversal. Not the measured transmittance Tn; the manual gives the conversion.
    pub transmissivity_rgb: DVec3,
    /// Index of refraction (optional fourth real; [`GLASS_DEFAULT_REFRACTIVE_INDEX`] if absent).
    pub refractive_index: f64,
}

/// `mirror`: planar specular reflector that creates virtual sources (manual §2.1.2, "Mirror").
#[derive(Clone, Debug, PartialEq)]
pub struct Mirror {
    /// Reflectance per channel (`red green blue`).
    pub reflectance_rgb: DVec3,
    /// Optional material used to shade non-source rays (the one string argument); `void`
    /// makes the mirror invisible to them.
    pub alternate_material: Option<ModifierRef>,
}

/// `light`: self-luminous surface (manual §2.1.2, "Light").
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Radiance per channel in W/(sr·m²) (`red green blue`).
    pub radiance_w_sr_m2: DVec3,
}

/// `glow`: self-luminous surface with a limited effect (manual §2.1.2, "Glow"). gensky skies
/// use it for the sky and ground hemispheres.
#[derive(Clone, Debug, PartialEq)]
pub struct Glow {
    /// Radiance per channel in W/(sr·m²) (`red green blue`).
    pub radiance_w_sr_m2: DVec3,
    /// Maximum radius for shadow testing (`maxrad`): 0 means never tested for shadow (only
    /// seen through interreflection), negative means it never illuminates the scene.
    pub max_radius_m: f64,
}

/// `brightfunc`: a pattern scaling the modified material by a function (manual §2.1.4,
/// "Brightfunc"). Kept generic; the engine interprets `skyfunc` from `skybright.cal` and
/// `perezlum.cal`.
#[derive(Clone, Debug, PartialEq)]
pub struct Brightfunc {
    /// The function or variable to evaluate (`refname`), e.g. `skybright`.
    pub function_name: String,
    /// The function file (`funcfile`), e.g. `skybright.cal`; `.` means none.
    pub cal_file: String,
    /// Transform words after the file (`xform` syntax, e.g. `-rz 90`), unparsed.
    pub transform: Vec<String>,
    /// The real arguments `A1 .. An` made available to the function.
    pub real_args: Vec<f64>,
    /// The same, as the engine compiles it on a surface that is not a sky.
    pub function: FunctionArgs,
}

/// `mixfunc`: blends two modifiers by a coefficient (manual §2.1.6).
#[derive(Clone, Debug, PartialEq)]
pub struct Mixfunc {
    /// Used where the coefficient is 1 (`void`: nothing).
    pub foreground: ModifierRef,
    /// Used where the coefficient is 0.
    pub background: ModifierRef,
    /// One expression: the coefficient.
    pub function: FunctionArgs,
}

/// Interprets a modifier primitive. `resolve` looks up modifier names referenced in string
/// arguments (mirror's alternate material) as defined before this primitive.
pub(crate) fn build(
    raw: &RawPrimitive<'_>,
    resolve: &dyn Fn(&str) -> Option<ModifierRef>,
) -> Result<ModifierKind, SceneError> {
    let r = &raw.reals;
    let rgb = |i: usize| DVec3::new(r[i], r[i + 1], r[i + 2]);
    Ok(match raw.kind {
        PrimitiveType::Plastic | PrimitiveType::Metal => {
            raw.check_no_strings_or_integers()?;
            raw.check_real_count()?;
            non_negative(raw, 0..3, "a reflectance >= 0")?;
            unit_interval(raw, 3)?;
            non_negative(raw, 4..5, "a roughness >= 0")?;
            if raw.kind == PrimitiveType::Plastic {
                ModifierKind::Plastic(Plastic {
                    reflectance_rgb: rgb(0),
                    specularity: r[3],
                    roughness: r[4],
                })
            } else {
                ModifierKind::Metal(Metal {
                    reflectance_rgb: rgb(0),
                    specularity: r[3],
                    roughness: r[4],
                })
            }
        }
        PrimitiveType::Trans => {
            raw.check_no_strings_or_integers()?;
            raw.check_real_count()?;
            non_negative(raw, 0..3, "a colour component >= 0")?;
            unit_interval(raw, 3)?;
            non_negative(raw, 4..5, "a roughness >= 0")?;
            unit_interval(raw, 5)?;
            unit_interval(raw, 6)?;
            ModifierKind::Trans(Trans {
                color_rgb: rgb(0),
                specularity: r[3],
                roughness: r[4],
                transmissivity: r[5],
                transmitted_specularity: r[6],
            })
        }
        PrimitiveType::Glass => {
            raw.check_no_strings_or_integers()?;
            raw.check_count(
                ArgumentList::Real,
                r.len() == 3 || r.len() == 4,
                "3 or 4 (rtn gtn btn [n])",
            )?;
            non_negative(raw, 0..3, "a transmissivity >= 0")?;
            let refractive_index = match r.get(3) {
                Some(&n) if n > 0.0 => n,
                Some(_) => return Err(raw.invalid_real(3, "a refractive index > 0")),
                None => GLASS_DEFAULT_REFRACTIVE_INDEX,
            };
            ModifierKind::Glass(Glass {
                transmissivity_rgb: rgb(0),
                refractive_index,
            })
        }
        PrimitiveType::Mirror => {
            raw.check_count(
                ArgumentList::String,
                raw.strings.len() <= 1,
                "0 or 1 (optional alternate material)",
            )?;
            raw.check_no_integers()?;
            raw.check_real_count()?;
            non_negative(raw, 0..3, "a reflectance >= 0")?;
            let alternate_material = match raw.strings.first() {
                None => None,
                Some(name) => Some(resolve(name).ok_or_else(|| SceneError::UnknownModifier {
                    at: raw.at.clone(),
                    primitive: raw.describe(),
                    field: "string argument 1 (alternate material)",
                    modifier: name.to_string(),
                    hint: String::new(),
                })?),
            };
            ModifierKind::Mirror(Mirror {
                reflectance_rgb: rgb(0),
                alternate_material,
            })
        }
        PrimitiveType::Light => {
            raw.check_no_strings_or_integers()?;
            raw.check_real_count()?;
            ModifierKind::Light(Light {
                radiance_w_sr_m2: rgb(0),
            })
        }
        PrimitiveType::Glow => {
            raw.check_no_strings_or_integers()?;
            raw.check_real_count()?;
            ModifierKind::Glow(Glow {
                radiance_w_sr_m2: rgb(0),
                max_radius_m: r[3],
            })
        }
        PrimitiveType::Brightfunc => {
            raw.check_count(
                ArgumentList::String,
                raw.strings.len() >= 2,
                "at least 2 (refname funcfile [transform])",
            )?;
            let function = super::function::function_args(raw, 1, "refname funcfile [transform]")?;
            ModifierKind::Brightfunc(Brightfunc {
                function,
                function_name: raw.strings[0].to_string(),
                cal_file: raw.strings[1].to_string(),
                transform: raw.strings[2..].iter().map(|s| s.to_string()).collect(),
                real_args: r.clone(),
            })
        }
        PrimitiveType::Colorfunc
        | PrimitiveType::Brightdata
        | PrimitiveType::Colordata
        | PrimitiveType::Texfunc
        | PrimitiveType::Mixfunc
        | PrimitiveType::BrtdFunc => function_modifier(raw, resolve)?,
        PrimitiveType::Polygon
        | PrimitiveType::Sphere
        | PrimitiveType::Cylinder
        | PrimitiveType::Ring
        | PrimitiveType::Cone
        | PrimitiveType::Source => {
            return Err(raw.invalid(
                "type",
                raw.kind.name(),
                "a material or pattern (internal: surface passed to the material reader)",
            ))
        }
    })
}

/// `colorfunc`, `texfunc`, `mixfunc` or `BRTDfunc`, read from `raw`.
fn function_modifier(
    raw: &RawPrimitive<'_>,
    resolve: &dyn Fn(&str) -> Option<ModifierRef>,
) -> Result<ModifierKind, SceneError> {
    use super::parse::PrimitiveType as T;
    Ok(match raw.kind {
        T::Colorfunc => ModifierKind::Colorfunc(function_args(
            raw,
            3,
            "rvarname gvarname bvarname funcfile [transform]",
        )?),
        T::Texfunc => ModifierKind::Texfunc(function_args(
            raw,
            3,
            "xpert ypert zpert funcfile [transform]",
        )?),
        T::Mixfunc => {
            let function =
                function_args(raw, 3, "foreground background vname funcfile [transform]")?;
            let modifier = |i: usize, field: &'static str| {
                let name = &function.expressions[i];
                if name == "void" {
                    return Ok(ModifierRef::Void);
                }
                resolve(name).ok_or_else(|| SceneError::UnknownModifier {
                    at: raw.at.clone(),
                    primitive: raw.describe(),
                    field,
                    modifier: name.clone(),
                    hint: String::new(),
                })
            };
            let foreground = modifier(0, "string argument 1 (foreground)")?;
            let background = modifier(1, "string argument 2 (background)")?;
            ModifierKind::Mixfunc(Mixfunc {
                foreground,
                background,
                function: FunctionArgs {
                    expressions: vec![function.expressions[2].clone()],
                    ..function
                },
            })
        }
        T::BrtdFunc => ModifierKind::BrtdFunc(brtd(raw)?),
        T::Brightdata => ModifierKind::Brightdata(data_pattern(raw, 1)?),
        T::Colordata => ModifierKind::Colordata(data_pattern(raw, 3)?),
        _ => {
            return Err(raw.invalid(
                "type",
                raw.kind.name(),
                "a function modifier (internal: other type passed to the function reader)",
            ))
        }
    })
}

/// Reflectances and transmissivities below zero have no physical meaning (RADIANCE accepts
/// them silently; a Monte-Carlo estimator would turn them into negative path weights).
fn non_negative(
    raw: &RawPrimitive<'_>,
    indices: std::ops::Range<usize>,
    expected: &str,
) -> Result<(), SceneError> {
    for i in indices {
        if raw.reals[i] < 0.0 {
            return Err(raw.invalid_real(i, expected));
        }
    }
    Ok(())
}

/// Fractions (`spec`, `trans`, `tspec`) must lie in 0..=1.
fn unit_interval(raw: &RawPrimitive<'_>, index: usize) -> Result<(), SceneError> {
    if (0.0..=1.0).contains(&raw.reals[index]) {
        Ok(())
    } else {
        Err(raw.invalid_real(index, "a fraction between 0 and 1"))
    }
}
