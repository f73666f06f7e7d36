//! The room and its sky, read from RADIANCE scene files, and the virtual sensors from `.pts`.
//!
//! The subset read is listed in shared/spec/campaign.md ("Scene subset") and in
//! [`SUPPORTED_TYPES`]: anything outside it is an error naming the file and line, never
//! silently dropped. Inline commands (`!xform`, `!genbox`, `!gensky`, ...) are expanded
//! natively (`expand.rs`); others run only with [`LoadOptions::allow_commands`]. See
//! docs/radiance-compatibility.md. Geometry is in metres in the
//! campaign world frame (+x east, +y north, +z up), in `f64` (`glam::DVec3`) so the
//! Monte-Carlo engine can trace on it directly.
//!
//! ```no_run
//! let scene = skylux_hps::scene::load_files(&["room/scene.rad", "sky.rad"])?;
//! for surface in scene.surfaces() {
//!     let material = scene.material(surface.modifier);
//!     # let _ = material;
//! }
//! # Ok::<(), skylux_hps::scene::SceneError>(())
//! ```

mod alias;
mod brdf_material;
mod bsdf_modifier;
mod command;
mod error;
mod expand;
mod files;
mod function;
mod generators;
mod lexer;
mod material;
mod parse;
mod primitive;
mod sensors;
mod shape;
mod text;
mod xform;

pub use brdf_material::{Anisotropic, BrdfData, BrdfFunc, NormalFamily, NormalFractions};
pub use bsdf_modifier::{BsdfModifier, BsdfType};
pub use error::{ArgumentList, SceneError, SourceLocation, SUPPORTED_TYPES};
pub use expand::{LoadOptions, MAX_INCLUDE_DEPTH, MAX_PRIMITIVES};
pub use function::{BrtdFunc, DataPattern, FunctionArgs, FunctionTransform};
pub use material::{
    Antimatter, Brightfunc, Dielectric, Glass, Glow, Illum, Light, Medium, Metal, Mirror, Mixdata,
    Mixfunc, Mixtext, ModifierId, ModifierKind, ModifierRef, Plastic, Spotlight, Trans,
    GLASS_DEFAULT_REFRACTIVE_INDEX, HARTMANN_MEAN_WAVELENGTH_NM,
};
pub use primitive::Primitive;
pub use sensors::{load_sensors, parse_sensors, Sensor, SensorsError};
pub use shape::{Cone, Cylinder, DistantSource, Polygon, Ring, Shape, Sphere, MIN_LENGTH_M};
pub use text::{TextArgs, TextPattern, TextSource};
pub use xform::MAX_ARRAY_COPIES;

use error::utf8;
use expand::Expander;
use parse::RawPrimitive;
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

/// A material or pattern definition.
#[derive(Clone, Debug, PartialEq)]
pub struct Modifier {
    /// Its identifier.
    pub name: String,
    /// Its own modifier: `void`, or a pattern applied to it (a `glow` modified by a sky
    /// `brightfunc`).
    pub modifier: ModifierRef,
    pub kind: ModifierKind,
    /// Where it is defined.
    pub origin: SourceLocation,
}

/// A surface of the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// Its identifier (not necessarily unique).
    pub name: String,
    /// Its modifier, normally its material.
    pub modifier: ModifierRef,
    pub shape: Shape,
    /// Where it is defined.
    pub origin: SourceLocation,
}

/// A scene: modifiers and surfaces in file order, from one or more files.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    modifiers: Vec<Modifier>,
    surfaces: Vec<Surface>,
    /// The current definition of each modifier name, as the next primitive read would see it.
    current: HashMap<String, ModifierId>,
}

/// Loads one scene file.
pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
    load_files(&[path])
}

/// Loads scene files in order into one scene, as `oconv room.rad sky.rad` would: modifiers
/// defined in an earlier file can be used in a later one.
pub fn load_files<P: AsRef<Path>>(paths: &[P]) -> Result<Scene, SceneError> {
    load_files_with(paths, &LoadOptions::default())
}

/// [`load_files`] with options (running other commands through the shell).
pub fn load_files_with<P: AsRef<Path>>(
    paths: &[P],
    options: &LoadOptions,
) -> Result<Scene, SceneError> {
    let mut scene = Scene::new();
    for path in paths {
        scene.add_file_with(path, options)?;
    }
    Ok(scene)
}

/// The primitives of scene files after every inline command is expanded, of any RADIANCE
/// type, in order: what `xform -e` would write for each file, before Skylux interprets them.
pub fn expand_files<P: AsRef<Path>>(
    paths: &[P],
    options: &LoadOptions,
) -> Result<Vec<Primitive>, SceneError> {
    let mut out = Vec::new();
    for path in paths {
        let path = path.as_ref();
        let bytes = read_file(path)?;
        let label: Arc<Path> = Arc::from(path);
        let text = utf8(&label, &bytes)?;
        out.extend(Expander::new(options).top_text(label.clone(), text)?);
    }
    Ok(out)
}

/// Primitives of RADIANCE scene text without commands (a program's output), of any type.
pub fn parse_primitives(label: impl AsRef<Path>, text: &str) -> Result<Vec<Primitive>, SceneError> {
    let label: Arc<Path> = Arc::from(label.as_ref());
    let mut lexer = lexer::Lexer::new(label, text);
    let mut out = Vec::new();
    while let Some(item) = parse::read_item(&mut lexer)? {
        match item {
            parse::Item::Primitive(p) => out.push(p),
            parse::Item::Command { line, text } => {
                return Err(SceneError::UnsupportedCommand {
                    at: lexer.at(line),
                    command: format!("!{text}"),
                    reason: "commands are not run here".into(),
                })
            }
        }
    }
    Ok(out)
}

fn read_file(path: &Path) -> Result<Vec<u8>, SceneError> {
    std::fs::read(path).map_err(|source| SceneError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Reads a scene from bytes in memory; `label` names it in errors and origins.
pub fn parse(label: impl AsRef<Path>, bytes: &[u8]) -> Result<Scene, SceneError> {
    let mut scene = Scene::new();
    scene.add_bytes(label, bytes)?;
    Ok(scene)
}

impl Scene {
    /// An empty scene.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends the primitives of a scene file. On error the scene is left as it was.
    pub fn add_file(&mut self, path: impl AsRef<Path>) -> Result<(), SceneError> {
        self.add_file_with(path, &LoadOptions::default())
    }

    /// [`Scene::add_file`] with options.
    pub fn add_file_with(
        &mut self,
        path: impl AsRef<Path>,
        options: &LoadOptions,
    ) -> Result<(), SceneError> {
        let path = path.as_ref();
        let bytes = read_file(path)?;
        self.add_bytes_with(path, &bytes, options)
    }

    /// Appends the primitives of scene text in memory; `label` names it in errors and origins,
    /// and its directory is where its commands run. On error the scene is left as it was.
    pub fn add_bytes(&mut self, label: impl AsRef<Path>, bytes: &[u8]) -> Result<(), SceneError> {
        self.add_bytes_with(label, bytes, &LoadOptions::default())
    }

    /// [`Scene::add_bytes`] with options.
    pub fn add_bytes_with(
        &mut self,
        label: impl AsRef<Path>,
        bytes: &[u8],
        options: &LoadOptions,
    ) -> Result<(), SceneError> {
        let modifier_count = self.modifiers.len();
        let surface_count = self.surfaces.len();
        let mut replaced: Vec<(String, Option<ModifierId>)> = Vec::new();
        let result = self.read(Arc::from(label.as_ref()), bytes, options, &mut replaced);
        if result.is_err() {
            self.modifiers.truncate(modifier_count);
            self.surfaces.truncate(surface_count);
            for (name, previous) in replaced.into_iter().rev() {
                match previous {
                    Some(id) => self.current.insert(name, id),
                    None => self.current.remove(&name),
                };
            }
        }
        result
    }

    /// Materials and patterns, in definition order; [`ModifierId`] indexes this.
    pub fn modifiers(&self) -> &[Modifier] {
        &self.modifiers
    }

    /// Surfaces (including distant `source`s), in file order.
    pub fn surfaces(&self) -> &[Surface] {
        &self.surfaces
    }

    /// Keeps the surfaces for which `keep` holds (the matrix methods take a window's glazing
    /// out of the room: the window is their receiver).
    pub fn retain_surfaces(&mut self, keep: impl FnMut(&Surface) -> bool) {
        self.surfaces.retain(keep);
    }

    /// The modifier an id refers to (`None` only for an id from another scene).
    pub fn modifier(&self, id: ModifierId) -> Option<&Modifier> {
        self.modifiers.get(id.index())
    }

    /// Whether the chain from `start` down to `void` holds a material.
    fn reaches_material(&self, start: ModifierRef) -> bool {
        let mut next = start;
        let mut steps = 0;
        while let ModifierRef::Defined(id) = next {
            let Some(m) = self.modifier(id) else { break };
            if m.kind.is_material() {
                return true;
            }
            next = m.modifier;
            steps += 1;
            if steps > self.modifiers.len() {
                break; // a chain is acyclic by construction; a guard all the same
            }
        }
        false
    }

    /// The definition a primitive appended now would get for `name`.
    pub fn modifier_named(&self, name: &str) -> Option<ModifierRef> {
        if name == "void" {
            return Some(ModifierRef::Void);
        }
        self.current.get(name).map(|&id| ModifierRef::Defined(id))
    }

    /// The material that shades a primitive with this modifier: the first material on the
    /// modifier chain, patterns before it being applied to it (as RADIANCE's `rayshade`
    /// walks it). `None` if the chain reaches `void` first: RADIANCE then lets rays pass.
    pub fn material(&self, modifier: ModifierRef) -> Option<&Modifier> {
        let mut next = modifier;
        while let ModifierRef::Defined(id) = next {
            let m = self.modifiers.get(id.index())?;
            if m.kind.is_material() {
                return Some(m);
            }
            next = m.modifier;
        }
        None
    }

    fn read(
        &mut self,
        file: Arc<Path>,
        bytes: &[u8],
        options: &LoadOptions,
        replaced: &mut Vec<(String, Option<ModifierId>)>,
    ) -> Result<(), SceneError> {
        let text = utf8(&file, bytes)?;
        let primitives = Expander::new(options).top_text(file.clone(), text)?;
        for primitive in &primitives {
            if primitive.type_name == "alias" {
                let (kind, modifier) = alias::build(self, primitive)?;
                let definition = Modifier {
                    name: primitive.identifier.clone(),
                    modifier,
                    kind,
                    origin: primitive.origin.clone(),
                };
                self.define(definition, replaced);
                continue;
            }
            let raw = RawPrimitive::from_primitive(primitive)?;
            let modifier = self.modifier_named(raw.modifier).ok_or_else(|| {
                let hint = if self.surfaces.iter().any(|s| s.name == raw.modifier) {
                    format!(
                        " (`{}` is a surface, and a surface cannot modify other primitives)",
                        raw.modifier
                    )
                } else {
                    String::new()
                };
                SceneError::UnknownModifier {
                    at: raw.at.clone(),
                    primitive: raw.describe(),
                    field: "modifier",
                    modifier: raw.modifier.to_string(),
                    hint,
                }
            })?;
            if raw.kind.is_modifier() {
                let mut kind = material::build(
                    &raw,
                    &|name| self.modifier_named(name),
                    &file,
                    options.working_directory.as_deref(),
                )?;
                kind.settle_mixture(|side| self.reaches_material(side));
                if kind.is_material() {
                    self.check_no_material_below(&raw, modifier)?;
                }
                let definition = Modifier {
                    name: raw.identifier.to_string(),
                    modifier,
                    kind,
                    origin: raw.at.clone(),
                };
                self.define(definition, replaced);
            } else {
                let shape = shape::build(&raw)?;
                self.surfaces.push(Surface {
                    name: raw.identifier.to_string(),
                    modifier,
                    shape,
                    origin: raw.at,
                });
            }
        }
        Ok(())
    }

    /// Appends a modifier and makes it the current definition of its name, remembering the
    /// previous one so a failed file can be undone.
    fn define(&mut self, modifier: Modifier, replaced: &mut Vec<(String, Option<ModifierId>)>) {
        let id = ModifierId::new(self.modifiers.len());
        let name = modifier.name.clone();
        self.modifiers.push(modifier);
        let previous = self.current.insert(name.clone(), id);
        replaced.push((name, previous));
    }

    /// A material's modifier chain may hold only patterns: RADIANCE stops with "conflicting
    /// material" when it meets a second material while shading (raytexture in raytrace.c).
    fn check_no_material_below(
        &self,
        raw: &parse::RawPrimitive<'_>,
        modifier: ModifierRef,
    ) -> Result<(), SceneError> {
        match self.material(modifier) {
            None => Ok(()),
            Some(other) => Err(raw.invalid(
                "modifier",
                format!("`{}`, a {} material", other.name, other.kind.type_name()),
                "`void` or a pattern (a material modified by another material is a \
                 conflicting material in RADIANCE)",
            )),
        }
    }
}

impl alias::Definitions for Scene {
    fn resolve(&self, name: &str) -> Option<ModifierRef> {
        self.modifier_named(name)
    }

    fn definition(&self, name: &str) -> Option<(ModifierKind, ModifierRef)> {
        let id = *self.current.get(name)?;
        let m = self.modifiers.get(id.index())?;
        Some((m.kind.clone(), m.modifier))
    }

    fn is_surface(&self, name: &str) -> bool {
        self.surfaces.iter().any(|s| s.name == name)
    }

    fn material_of(&self, modifier: ModifierRef) -> Option<(String, &'static str)> {
        self.material(modifier)
            .map(|m| (m.name.clone(), m.kind.type_name()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn later_definitions_shadow_earlier_ones_for_later_primitives_only() {
        let scene = parse(
            "m.rad",
            b"void plastic m 0 0 5 .1 .1 .1 0 0\n\
              m polygon a 0 0 9 0 0 0 1 0 0 0 1 0\n\
              void plastic m 0 0 5 .9 .9 .9 0 0\n\
              m polygon b 0 0 9 0 0 0 1 0 0 0 1 0\n",
        )
        .unwrap();
        let reflectance = |s: &Surface| match &scene.material(s.modifier).unwrap().kind {
            ModifierKind::Plastic(p) => p.reflectance_rgb.x,
            other => panic!("{other:?}"),
        };
        assert_eq!(reflectance(&scene.surfaces()[0]), 0.1);
        assert_eq!(reflectance(&scene.surfaces()[1]), 0.9);
        assert_eq!(
            scene.modifier_named("m"),
            Some(ModifierRef::Defined(ModifierId::new(1)))
        );
    }

    #[test]
    fn a_failed_file_leaves_the_scene_unchanged() {
        let mut scene = parse("a.rad", b"void plastic m 0 0 5 .1 .1 .1 0 0\n").unwrap();
        let before = scene.clone();
        let err = scene
            .add_bytes(
                "b.rad",
                b"void plastic m 0 0 5 .5 .5 .5 0 0\nvoid plastic n 0 0 5 1 1 1 0 0\n\
                  m polygon p 0 0 9 0 0 0 1 0 0 0 1 0\nm bogus x 0 0 0\n",
            )
            .unwrap_err();
        assert!(err.to_string().starts_with("b.rad:4:"), "{err}");
        assert_eq!(scene, before);
    }

    #[test]
    fn material_walks_patterns_to_the_material() {
        let scene = parse(
            "c.rad",
            b"void brightfunc f 2 skybright skybright.cal 0 0\n\
              f glow g 0 0 4 1 1 1 0\n\
              g source s 0 0 4 0 0 1 180\n\
              f source bare 0 0 4 0 0 1 180\n",
        )
        .unwrap();
        let sky = &scene.surfaces()[0];
        assert_eq!(scene.material(sky.modifier).unwrap().name, "g");
        assert!(scene.material(scene.surfaces()[1].modifier).is_none());
    }

    #[test]
    fn a_material_modified_by_a_material_is_refused() {
        let err = parse(
            "d.rad",
            b"void plastic a 0 0 5 .5 .5 .5 0 0\na plastic b 0 0 5 .5 .5 .5 0 0\n",
        )
        .unwrap_err();
        let text = err.to_string();
        assert!(
            text.starts_with("d.rad:2: plastic `b`: modifier is `a`"),
            "{text}"
        );
    }

    #[test]
    fn a_surface_name_is_not_a_modifier() {
        let err = parse(
            "e.rad",
            b"void plastic a 0 0 5 .5 .5 .5 0 0\na polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n\
              p polygon q 0 0 9 0 0 0 1 0 0 0 1 0\n",
        )
        .unwrap_err();
        assert!(err.to_string().contains("`p` is a surface"), "{err}");
        assert_eq!(err.location().unwrap().line, 3);
    }
}
