//! `alias`: a modifier that takes its type and arguments from one defined before (reference
//! manual §2.1, "alias"; RADIANCE 5 readobj.c and m_alias.c).
//!
//! `mod alias id target` copies the most recent definition of `target` under the name `id`,
//! with `mod` as its modifier: `void` for none, another modifier's name, or the reserved
//! `inherit` to keep the target's own modifier. Surfaces cannot be aliased.

use super::error::SceneError;
use super::material::{ModifierKind, ModifierRef};
use super::primitive::Primitive;

/// The reserved modifier word of an alias that keeps its target's modifier.
pub const INHERIT: &str = "inherit";

/// What an alias needs to know of the definitions before it (the scene, in `mod.rs`).
pub(super) trait Definitions {
    /// The modifier a primitive read now would get for `name` (`void` included).
    fn resolve(&self, name: &str) -> Option<ModifierRef>;
    /// The kind and own modifier of the current definition of `name` (None: undefined).
    fn definition(&self, name: &str) -> Option<(ModifierKind, ModifierRef)>;
    /// Whether a surface has this name (for the message: surfaces cannot be aliased).
    fn is_surface(&self, name: &str) -> bool;
    /// The name and type of the material that shades a primitive with `modifier`, if any.
    fn material_of(&self, modifier: ModifierRef) -> Option<(String, &'static str)>;
}

/// The kind and modifier of the modifier an `alias` primitive defines.
pub(super) fn build(
    scene: &dyn Definitions,
    p: &Primitive,
) -> Result<(ModifierKind, ModifierRef), SceneError> {
    let describe = || format!("alias `{}`", p.identifier);
    let invalid = |field: &str, value: &str, expected: &str| SceneError::InvalidValue {
        at: p.origin.clone(),
        primitive: describe(),
        field: field.to_string(),
        value: value.to_string(),
        expected: expected.to_string(),
    };
    if p.identifier == "void" || p.identifier == INHERIT {
        return Err(invalid(
            "identifier",
            &p.identifier,
            "a name other than the reserved `void` and `inherit`",
        ));
    }
    let Some(target_name) = p.strings.first() else {
        return Err(invalid(
            "target",
            "(none)",
            "the name of a modifier defined before",
        ));
    };
    let (kind, target_modifier) = match scene.definition(target_name) {
        Some(found) => found,
        None => {
            let hint = if scene.is_surface(target_name) {
                format!(" (`{target_name}` is a surface, and surfaces cannot be aliased)")
            } else {
                String::new()
            };
            return Err(SceneError::UnknownModifier {
                at: p.origin.clone(),
                primitive: describe(),
                field: "target (the aliased modifier)",
                modifier: target_name.clone(),
                hint,
            });
        }
    };
    let modifier = if p.modifier == INHERIT {
        target_modifier
    } else {
        scene
            .resolve(&p.modifier)
            .ok_or_else(|| SceneError::UnknownModifier {
                at: p.origin.clone(),
                primitive: describe(),
                field: "modifier",
                modifier: p.modifier.clone(),
                hint: String::new(),
            })?
    };
    if kind.is_material() {
        if let Some((name, type_name)) = scene.material_of(modifier) {
            return Err(invalid(
                "modifier",
                &format!("`{name}`, a {type_name} material"),
                "`void`, `inherit` or a pattern (a material modified by another material is a \
                 conflicting material in RADIANCE)",
            ));
        }
    }
    Ok((kind, modifier))
}

#[cfg(test)]
mod tests {
    use crate::scene::{parse, ModifierKind, ModifierRef};

    #[test]
    fn an_alias_copies_its_target_under_a_new_name() {
        let scene = parse(
            "a.rad",
            b"void plastic red 0 0 5 .5 .1 .1 0 0\n\
              void brightfunc dim 2 skybright skybright.cal 0 0\n\
              void alias copy red\n\
              copy alias again red\n\
              void plastic red 0 0 5 .9 .9 .9 0 0\n\
              again polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n",
        )
        .unwrap_err();
        // `again` is a material modified by a material (`copy`): refused.
        assert!(err_has(&scene, "a.rad:4:"), "{scene}");
        let scene = parse(
            "b.rad",
            b"void plastic red 0 0 5 .5 .1 .1 0 0\n\
              void brightfunc dim 2 skybright skybright.cal 0 0\n\
              dim alias dimred red\n\
              inherit alias same dimred\n\
              void plastic red 0 0 5 .9 .9 .9 0 0\n\
              same polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n",
        )
        .unwrap();
        let surface = &scene.surfaces()[0];
        let material = scene.material(surface.modifier).unwrap();
        assert_eq!(material.name, "same");
        match &material.kind {
            ModifierKind::Plastic(p) => assert_eq!(p.reflectance_rgb.x, 0.5),
            other => panic!("{other:?}"),
        }
        // `inherit` kept `dimred`'s modifier, the pattern `dim`.
        let ModifierRef::Defined(id) = material.modifier else {
            panic!("no pattern")
        };
        assert_eq!(scene.modifiers()[id.index()].name, "dim");
    }

    fn err_has(err: &crate::scene::SceneError, text: &str) -> bool {
        err.to_string().contains(text)
    }

    #[test]
    fn an_alias_to_nothing_or_to_a_surface_is_an_error_with_its_line() {
        let err = parse("c.rad", b"# x\nvoid alias a nothing\n").unwrap_err();
        assert!(err.to_string().starts_with("c.rad:2:"), "{err}");
        assert!(err.to_string().contains("nothing"), "{err}");
        let err = parse(
            "d.rad",
            b"void plastic m 0 0 5 .5 .5 .5 0 0\nm sphere s 0 0 4 0 0 0 1\nvoid alias a s\n",
        )
        .unwrap_err();
        assert!(
            err.to_string().contains("surfaces cannot be aliased"),
            "{err}"
        );
        assert_eq!(err.location().unwrap().line, 3);
        let err = parse(
            "e.rad",
            b"void plastic m 0 0 5 .5 .5 .5 0 0\nvoid alias inherit m\n",
        )
        .unwrap_err();
        assert!(err.to_string().contains("reserved"), "{err}");
    }
}
