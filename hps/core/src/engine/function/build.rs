//! The material of a modifier chain that holds function modifiers: patterns and textures
//! compiled as [`Modulation`]s over a plain material, a `BRTDfunc` or a `mixfunc`.

use super::data::DataArray;
use super::loader::{CompiledFunction, FunctionLoader};
use super::varying::{DataLookup, MixCoefficient, Modulation, VaryingBase, VaryingMaterial};
use crate::engine::error::EngineError;
use crate::engine::material::{AnisotropicMaterial, BrdfFunctionMaterial, BrtdMaterial, Material};
use crate::engine::sky::SkyFunction;
use crate::scene::{
    Anisotropic, BrdfFunc, DataPattern, FunctionArgs, Modifier, ModifierKind, ModifierRef, Scene,
    Surface,
};
use std::sync::Arc;

/// The orientation vector's expressions of `plastic2`, `metal2`, `trans2` (`ux uy uz`).
const ORIENTATION_EXPRESSIONS: usize = 3;

/// BRTDfunc's expressions compiled as such (the specular colours); the next three name
/// functions of the source direction (`m_brdf.c`: `getfunc(m, 9, 0x3f, 0)`).
const BRTD_EXPRESSIONS: usize = 6;

/// The material of the chain starting at `start` for `surface`.
pub fn material_of(
    scene: &Scene,
    start: ModifierRef,
    surface: &Surface,
    loader: &mut FunctionLoader,
) -> Result<Material, EngineError> {
    material_under(scene, start, surface, loader, &[])
}

/// [`material_of`] under the patterns and textures `above` it: those on the chain above a
/// `mixfunc` of materials, which RADIANCE applies before the mixture chooses (`rayshade`
/// runs down the chain, `raytexture` accumulating colour and perturbation), so both sides
/// take them, after their own.
fn material_under(
    scene: &Scene,
    start: ModifierRef,
    surface: &Surface,
    loader: &mut FunctionLoader,
    above: &[Modulation],
) -> Result<Material, EngineError> {
    let chain = chain(scene, start);
    let material = chain.iter().copied().find(|m| m.kind.is_material());
    let emitter =
        material.is_some_and(|m| matches!(m.kind, ModifierKind::Light(_) | ModifierKind::Glow(_)));
    let functions = chain.iter().any(|m| is_function(&m.kind, emitter));
    if !functions && above.is_empty() {
        let (material, patterns) = resolve(scene, start)?;
        return Material::from_scene(scene, surface, material, patterns);
    }
    let Some(material) = material else {
        return Ok(Material::Invisible); // void: patterns on nothing
    };
    let mut modulations = above.to_vec();
    for m in chain.iter().filter(|m| !m.kind.is_material()) {
        modulations.push(modulation(scene, m, loader)?);
    }
    if let ModifierKind::Mixdata(_)
    | ModifierKind::Mixpict(_)
    | ModifierKind::Mixfunc(_)
    | ModifierKind::Mixtext(_) = material.kind
    {
        // The patterns above go down to the sides.
        let (coefficient, sides) = mix_parts(material, loader)?.expect("a mixture has two sides");
        return Ok(Material::Varying(Arc::new(VaryingMaterial {
            modulations: Vec::new(),
            base: mixture(scene, coefficient, sides, surface, loader, &modulations)?,
        })));
    }
    let base = base(scene, material, surface, loader)?;
    let refuse = |why: &str| {
        Err(EngineError::Unsupported {
            at: material.origin.clone(),
            what: format!(
                "{} `{}` under a pattern or texture: {why}",
                material.kind.type_name(),
                material.name
            ),
        })
    };
    match &base {
        VaryingBase::Plain(
            Material::Normal(_) | Material::Glass(_) | Material::Emitter(_) | Material::Mirror(_),
        )
        | VaryingBase::Brtd(_)
        | VaryingBase::Function(_)
        | VaryingBase::Anisotropic(_)
        | VaryingBase::Mix { .. } => {}
        _ if modulations.is_empty() => {}
        VaryingBase::Plain(_) => return refuse(
            "patterns are traced on plastic, metal, trans, glass, mirror, light, glow and BRTDfunc only",
        ),
    }
    Ok(Material::Varying(Arc::new(VaryingMaterial {
        modulations,
        base,
    })))
}

/// The modifiers from `start` down to `void`.
fn chain(scene: &Scene, start: ModifierRef) -> Vec<&Modifier> {
    let mut out = Vec::new();
    let mut next = start;
    while let ModifierRef::Defined(id) = next {
        let Some(m) = scene.modifier(id) else { break };
        out.push(m);
        next = m.modifier;
    }
    out
}

/// Whether `kind` makes the chain vary from hit to hit (a `brightfunc` on a `light` or
/// `glow` is a sky function, traced by `engine::sky`).
fn is_function(kind: &ModifierKind, emitter: bool) -> bool {
    match kind {
        ModifierKind::Brightfunc(_) => !emitter,
        other => other.is_evaluated(),
    }
}

fn modulation(
    scene: &Scene,
    m: &Modifier,
    loader: &mut FunctionLoader,
) -> Result<Modulation, EngineError> {
    Ok(match &m.kind {
        // A mixture of two patterns (its sides reach no material) is itself a pattern.
        kind if !kind.is_material()
            && matches!(
                kind,
                ModifierKind::Mixfunc(_)
                    | ModifierKind::Mixdata(_)
                    | ModifierKind::Mixpict(_)
                    | ModifierKind::Mixtext(_)
            ) =>
        {
            let (coefficient, [f, b]) = mix_parts(m, loader)?.expect("a mixture has two sides");
            Modulation::Mixture {
                coefficient,
                sides: Box::new([
                    side_modulations(scene, f, loader)?,
                    side_modulations(scene, b, loader)?,
                ]),
            }
        }
        ModifierKind::Brightfunc(b) => Modulation::Pattern(loader.compile(m, &b.function, 1)?),
        ModifierKind::Colorfunc(f) => Modulation::Pattern(loader.compile(m, f, 3)?),
        ModifierKind::Texfunc(f) => Modulation::Texture(loader.compile(m, f, 3)?),
        ModifierKind::Brightdata(d) | ModifierKind::Colordata(d) => {
            Modulation::Data(data_lookup(m, d, loader)?)
        }
        ModifierKind::Colorpict(d) => Modulation::Data(picture_lookup(m, d, loader)?),
        ModifierKind::Texdata(d) => Modulation::DataTexture(data_lookup(m, d, loader)?),
        ModifierKind::Brighttext(t) | ModifierKind::Colortext(t) => Modulation::Text {
            layout: loader.text(m, &t.text)?,
            foreground_rgb: t.foreground_rgb,
            background_rgb: t.background_rgb,
        },
        other => {
            return Err(EngineError::Unsupported {
                at: m.origin.clone(),
                what: format!("{} `{}` is not a pattern", other.type_name(), m.name),
            })
        }
    })
}

/// A mixture's coefficient and its two sides (foreground, background); `None` for any other
/// modifier.
fn mix_parts(
    m: &Modifier,
    loader: &mut FunctionLoader,
) -> Result<Option<(MixCoefficient, [ModifierRef; 2])>, EngineError> {
    Ok(Some(match &m.kind {
        ModifierKind::Mixfunc(x) => (
            MixCoefficient::Function(loader.compile(m, &x.function, 1)?),
            [x.foreground, x.background],
        ),
        ModifierKind::Mixdata(x) => (
            MixCoefficient::Data(data_lookup(m, &x.data, loader)?),
            [x.foreground, x.background],
        ),
        ModifierKind::Mixpict(x) => (
            MixCoefficient::Data(picture_lookup(m, &x.data, loader)?),
            [x.foreground, x.background],
        ),
        ModifierKind::Mixtext(x) => (
            MixCoefficient::Text(loader.text(m, &x.text)?),
            [x.foreground, x.background],
        ),
        _ => return Ok(None),
    }))
}

/// The patterns and textures of one side of a pattern mixture: its chain down to `void`
/// (no material there: [`crate::scene::Mixfunc::pattern`]).
fn side_modulations(
    scene: &Scene,
    side: ModifierRef,
    loader: &mut FunctionLoader,
) -> Result<Vec<Modulation>, EngineError> {
    chain(scene, side)
        .into_iter()
        .map(|m| modulation(scene, m, loader))
        .collect()
}

/// A data pattern, texture or mixture: its coordinates compiled, its arrays read, their
/// dimensions checked against the coordinates, its functions checked to exist.
fn data_lookup(
    m: &Modifier,
    d: &DataPattern,
    loader: &mut FunctionLoader,
) -> Result<DataLookup, EngineError> {
    let dimensions = d.function.expressions.len();
    let coordinates = loader.compile(m, &d.function, dimensions)?;
    let mut arrays = Vec::new();
    for name in &d.data_files {
        arrays.push(data_array(m, name, &d.function, dimensions, loader)?);
    }
    for name in &d.functions {
        defined(m, &coordinates, name)?;
    }
    Ok(DataLookup {
        coordinates,
        functions: d.functions.clone(),
        arrays,
    })
}

/// A `colorpict`: its two coordinates compiled, its picture read as three arrays, its
/// functions checked to exist.
fn picture_lookup(
    m: &Modifier,
    d: &DataPattern,
    loader: &mut FunctionLoader,
) -> Result<DataLookup, EngineError> {
    let coordinates = loader.compile(m, &d.function, 2)?;
    let arrays = loader.picture(m, &d.data_files[0], &d.function.scene_dir)?;
    for name in &d.functions {
        defined(m, &coordinates, name)?;
    }
    Ok(DataLookup {
        coordinates,
        functions: d.functions.clone(),
        arrays: arrays.to_vec(),
    })
}

/// The material under the modulations.
fn base(
    scene: &Scene,
    m: &Modifier,
    surface: &Surface,
    loader: &mut FunctionLoader,
) -> Result<VaryingBase, EngineError> {
    Ok(match &m.kind {
        ModifierKind::BrtdFunc(b) => VaryingBase::Brtd(Box::new(BrtdMaterial {
            arguments: b.clone(),
            function: loader.compile(m, &b.function, BRTD_EXPRESSIONS)?,
        })),
        ModifierKind::BrdfFunc(f) => VaryingBase::Function(Arc::new(brdf_function(m, f, loader)?)),
        ModifierKind::Anisotropic(a) => {
            VaryingBase::Anisotropic(Box::new(anisotropic(m, a, loader)?))
        }
        ModifierKind::Mixdata(_)
        | ModifierKind::Mixpict(_)
        | ModifierKind::Mixfunc(_)
        | ModifierKind::Mixtext(_) => {
            let (coefficient, sides) = mix_parts(m, loader)?.expect("a mixture has two sides");
            mixture(scene, coefficient, sides, surface, loader, &[])?
        }
        // Its patterns are the chain's modulations.
        _ => VaryingBase::Plain(Material::from_modifier(surface, Some(m), Vec::new())?),
    })
}

/// An error naming the modifier `m`, its scene file and line.
fn failure(m: &Modifier, what: String) -> EngineError {
    EngineError::Unsupported {
        at: m.origin.clone(),
        what: format!("{} `{}`: {what}", m.kind.type_name(), m.name),
    }
}

/// Fails unless `function`'s file or the library defines `name`.
fn defined(m: &Modifier, function: &CompiledFunction, name: &str) -> Result<(), EngineError> {
    match function.parameter_count(name) {
        Some(_) => Ok(()),
        None => Err(failure(
            m,
            format!(
                "function `{name}` is not defined in {} nor in the library",
                function.args.cal_file
            ),
        )),
    }
}

/// The data file `name` of `m`, read once, with `dimensions` dimensions (one per coordinate
/// the modifier gives).
fn data_array(
    m: &Modifier,
    name: &str,
    args: &FunctionArgs,
    dimensions: usize,
    loader: &mut FunctionLoader,
) -> Result<Arc<DataArray>, EngineError> {
    let array = loader.data(m, name, &args.scene_dir)?;
    if array.dimension_count() != dimensions {
        return Err(failure(
            m,
            format!(
                "data file {name} has {} dimension(s) but {dimensions} coordinate(s) are given",
                array.dimension_count()
            ),
        ));
    }
    Ok(array)
}

/// A function material: its file compiled, the function of the source direction and the
/// coordinate functions checked to exist, its data file read and its dimensions checked
/// against the coordinate functions.
fn brdf_function(
    m: &Modifier,
    f: &BrdfFunc,
    loader: &mut FunctionLoader,
) -> Result<BrdfFunctionMaterial, EngineError> {
    let function = loader.compile(m, &f.function, 0)?;
    defined(m, &function, &f.function_name)?;
    let data = match &f.data {
        None => None,
        Some(d) => Some(data_array(
            m,
            &d.data_file,
            &f.function,
            d.coordinate_functions.len(),
            loader,
        )?),
    };
    Ok(BrdfFunctionMaterial {
        fractions: f.fractions.clone(),
        function_name: f.function_name.clone(),
        function,
        data,
    })
}

/// An anisotropic material with its orientation expressions compiled.
fn anisotropic(
    m: &Modifier,
    a: &Anisotropic,
    loader: &mut FunctionLoader,
) -> Result<AnisotropicMaterial, EngineError> {
    Ok(AnisotropicMaterial {
        fractions: a.fractions.clone(),
        u_roughness: a.u_roughness,
        v_roughness: a.v_roughness,
        orientation: loader.compile(m, &a.orientation, ORIENTATION_EXPRESSIONS)?,
    })
}

/// A `mixfunc`, `mixdata`, `mixpict` or `mixtext` of the `sides` (foreground, background),
/// each under the modulations `above` the mixture.
fn mixture(
    scene: &Scene,
    coefficient: MixCoefficient,
    sides: [ModifierRef; 2],
    surface: &Surface,
    loader: &mut FunctionLoader,
    above: &[Modulation],
) -> Result<VaryingBase, EngineError> {
    Ok(VaryingBase::Mix {
        coefficient,
        foreground: Box::new(material_under(scene, sides[0], surface, loader, above)?),
        background: Box::new(material_under(scene, sides[1], surface, loader, above)?),
    })
}

/// Walks a surface's modifier chain from `start`: its material (None for void) and every
/// sky pattern on the chain, above and below the material (RADIANCE applies both:
/// `rayshade` and `raytexture`).
pub fn resolve(
    scene: &Scene,
    start: ModifierRef,
) -> Result<(Option<&Modifier>, Vec<SkyFunction>), EngineError> {
    let mut patterns = Vec::new();
    let mut material = None;
    let mut next = start;
    while let ModifierRef::Defined(id) = next {
        let Some(m) = scene.modifier(id) else { break };
        match &m.kind {
            ModifierKind::Brightfunc(b) => {
                patterns.push(SkyFunction::from_brightfunc(b, &m.origin)?)
            }
            _ if material.is_none() => material = Some(m),
            _ => {}
        }
        next = m.modifier;
    }
    Ok((material, patterns))
}
