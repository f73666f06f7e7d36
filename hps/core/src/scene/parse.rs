//! The generic primitive syntax of a RADIANCE scene file, before any meaning is given to the
//! arguments.
//!
//! RADIANCE reference manual (ray.html), §2.1 "Scene Description": a primitive is
//! `modifier type identifier`, then a string argument count and the strings, an integer
//! argument count and the integers, a real argument count and the reals. A line starting with
//! `!` is a command whose output RADIANCE reads in its place (`expand.rs` runs it).

use super::error::{ArgumentList, SceneError, SourceLocation};
use super::lexer::{Lexer, Token};
use super::primitive::Primitive;

/// Every other primitive type RADIANCE 5 knows, so a message can say whether an unsupported
/// type is a RADIANCE type outside the subset or a typo.
pub(crate) const OTHER_RADIANCE_TYPES: &[&str] = &[
    "instance", "mesh", "prism1", "prism2", "mist", "ashik2", "WGMDfunc", "spectrum", "specfile",
    "specfunc", "specdata", "specpict", "alias",
];

/// The primitive types of the supported subset.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum PrimitiveType {
    Plastic,
    Metal,
    Trans,
    Glass,
    Mirror,
    Light,
    Glow,
    Brightfunc,
    Bsdf,
    ABsdf,
    Dielectric,
    Interface,
    Spotlight,
    Illum,
    Antimatter,
    Colorfunc,
    Brightdata,
    Colordata,
    Colorpict,
    Texfunc,
    Mixfunc,
    Texdata,
    Mixdata,
    Mixpict,
    Brighttext,
    Colortext,
    Mixtext,
    BrtdFunc,
    Plasfunc,
    Metfunc,
    Transfunc,
    Plasdata,
    Metdata,
    Transdata,
    Plastic2,
    Metal2,
    Trans2,
    Polygon,
    Sphere,
    Cylinder,
    Ring,
    Cone,
    Source,
    Bubble,
    Tube,
    Cup,
}

impl PrimitiveType {
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "plastic" => Self::Plastic,
            "metal" => Self::Metal,
            "trans" => Self::Trans,
            "glass" => Self::Glass,
            "mirror" => Self::Mirror,
            "light" => Self::Light,
            "glow" => Self::Glow,
            "brightfunc" => Self::Brightfunc,
            "BSDF" => Self::Bsdf,
            "aBSDF" => Self::ABsdf,
            "dielectric" => Self::Dielectric,
            "interface" => Self::Interface,
            "spotlight" => Self::Spotlight,
            "illum" => Self::Illum,
            "antimatter" => Self::Antimatter,
            "bubble" => Self::Bubble,
            "tube" => Self::Tube,
            "cup" => Self::Cup,
            "colorfunc" => Self::Colorfunc,
            "brightdata" => Self::Brightdata,
            "colordata" => Self::Colordata,
            "colorpict" => Self::Colorpict,
            "texfunc" => Self::Texfunc,
            "mixfunc" => Self::Mixfunc,
            "texdata" => Self::Texdata,
            "mixdata" => Self::Mixdata,
            "mixpict" => Self::Mixpict,
            "brighttext" => Self::Brighttext,
            "colortext" => Self::Colortext,
            "mixtext" => Self::Mixtext,
            "BRTDfunc" => Self::BrtdFunc,
            "plasfunc" => Self::Plasfunc,
            "metfunc" => Self::Metfunc,
            "transfunc" => Self::Transfunc,
            "plasdata" => Self::Plasdata,
            "metdata" => Self::Metdata,
            "transdata" => Self::Transdata,
            "plastic2" => Self::Plastic2,
            "metal2" => Self::Metal2,
            "trans2" => Self::Trans2,
            "polygon" => Self::Polygon,
            "sphere" => Self::Sphere,
            "cylinder" => Self::Cylinder,
            "ring" => Self::Ring,
            "cone" => Self::Cone,
            "source" => Self::Source,
            _ => return None,
        })
    }

    pub fn name(self) -> &'static str {
        match self {
            Self::Plastic => "plastic",
            Self::Metal => "metal",
            Self::Trans => "trans",
            Self::Glass => "glass",
            Self::Mirror => "mirror",
            Self::Light => "light",
            Self::Glow => "glow",
            Self::Brightfunc => "brightfunc",
            Self::Bsdf => "BSDF",
            Self::ABsdf => "aBSDF",
            Self::Dielectric => "dielectric",
            Self::Interface => "interface",
            Self::Spotlight => "spotlight",
            Self::Illum => "illum",
            Self::Antimatter => "antimatter",
            Self::Bubble => "bubble",
            Self::Tube => "tube",
            Self::Cup => "cup",
            Self::Colorfunc => "colorfunc",
            Self::Brightdata => "brightdata",
            Self::Colordata => "colordata",
            Self::Colorpict => "colorpict",
            Self::Texfunc => "texfunc",
            Self::Mixfunc => "mixfunc",
            Self::Texdata => "texdata",
            Self::Mixdata => "mixdata",
            Self::Mixpict => "mixpict",
            Self::Brighttext => "brighttext",
            Self::Colortext => "colortext",
            Self::Mixtext => "mixtext",
            Self::BrtdFunc => "BRTDfunc",
            Self::Plasfunc => "plasfunc",
            Self::Metfunc => "metfunc",
            Self::Transfunc => "transfunc",
            Self::Plasdata => "plasdata",
            Self::Metdata => "metdata",
            Self::Transdata => "transdata",
            Self::Plastic2 => "plastic2",
            Self::Metal2 => "metal2",
            Self::Trans2 => "trans2",
            Self::Polygon => "polygon",
            Self::Sphere => "sphere",
            Self::Cylinder => "cylinder",
            Self::Ring => "ring",
            Self::Cone => "cone",
            Self::Source => "source",
        }
    }

    /// Modifiers (materials and patterns) can be named as the modifier of later primitives;
    /// surfaces cannot (RADIANCE `ismodifier`).
    pub fn is_modifier(self) -> bool {
        !matches!(
            self,
            Self::Polygon
                | Self::Sphere
                | Self::Cylinder
                | Self::Ring
                | Self::Cone
                | Self::Source
                | Self::Bubble
                | Self::Tube
                | Self::Cup
        )
    }

    /// Names of the real arguments, from the reference manual's synopsis of each type.
    pub fn real_names(self) -> &'static [&'static str] {
        match self {
            Self::Plastic | Self::Metal => &["red", "green", "blue", "spec", "rough"],
            Self::Trans => &["red", "green", "blue", "spec", "rough", "trans", "tspec"],
            Self::Glass => &["rtn", "gtn", "btn", "n"],
            Self::Mirror | Self::Light | Self::Illum => &["red", "green", "blue"],
            Self::Dielectric => &["rtn", "gtn", "btn", "n", "hc"],
            Self::Interface => &["rtn1", "gtn1", "btn1", "n1", "rtn2", "gtn2", "btn2", "n2"],
            Self::Spotlight => &["red", "green", "blue", "angle", "xdir", "ydir", "zdir"],
            Self::Glow => &["red", "green", "blue", "maxrad"],
            Self::Plastic2 | Self::Metal2 => &["red", "green", "blue", "spec", "urough", "vrough"],
            Self::Trans2 => &[
                "red", "green", "blue", "rspec", "urough", "vrough", "trans", "tspec",
            ],
            Self::Plasfunc | Self::Metfunc | Self::Plasdata | Self::Metdata => {
                &["red", "green", "blue", "spec"]
            }
            Self::Transfunc | Self::Transdata => {
                &["red", "green", "blue", "rspec", "trans", "tspec"]
            }
            Self::Source => &["xdir", "ydir", "zdir", "angle"],
            Self::Brighttext => &[
                "Ax",
                "Ay",
                "Az",
                "Rx",
                "Ry",
                "Rz",
                "Dx",
                "Dy",
                "Dz",
                "foreground",
                "background",
            ],
            Self::Colortext => &[
                "Ax", "Ay", "Az", "Rx", "Ry", "Rz", "Dx", "Dy", "Dz", "rfore", "gfore", "bfore",
                "rback", "gback", "bback",
            ],
            Self::Mixtext => &["Ax", "Ay", "Az", "Rx", "Ry", "Rz", "Dx", "Dy", "Dz"],
            Self::Sphere | Self::Bubble => &["xcent", "ycent", "zcent", "radius"],
            Self::Cylinder | Self::Tube => &["x0", "y0", "z0", "x1", "y1", "z1", "rad"],
            Self::Cone | Self::Cup => &["x0", "y0", "z0", "x1", "y1", "z1", "r0", "r1"],
            Self::Ring => &[
                "xcent", "ycent", "zcent", "xdir", "ydir", "zdir", "r0", "r1",
            ],
            Self::Brightfunc
            | Self::Colorfunc
            | Self::Brightdata
            | Self::Colordata
            | Self::Colorpict
            | Self::Texfunc
            | Self::Mixfunc
            | Self::Texdata
            | Self::Mixdata
            | Self::Mixpict
            | Self::BrtdFunc
            | Self::Polygon
            | Self::Antimatter => &[],
            Self::Bsdf | Self::ABsdf => &[
                "rdf", "gdf", "bdf", "rdb", "gdb", "bdb", "rdt", "gdt", "bdt",
            ],
        }
    }

    /// How an error message names real argument `index` (0-based) of this type.
    pub fn real_field(self, index: usize) -> String {
        let number = index + 1;
        match self {
            Self::Polygon => format!(
                "real argument {number} (vertex {} {})",
                index / 3 + 1,
                ["x", "y", "z"][index % 3]
            ),
            Self::Brightfunc
            | Self::Colorfunc
            | Self::Brightdata
            | Self::Colordata
            | Self::Colorpict
            | Self::Texfunc
            | Self::Mixfunc
            | Self::Texdata
            | Self::Mixdata
            | Self::Mixpict => {
                format!("real argument {number} (A{number})")
            }
            Self::BrtdFunc => match index {
                0..=8 => format!(
                    "real argument {number} ({})",
                    ["rdf", "gdf", "bdf", "rdb", "gdb", "bdb", "rdt", "gdt", "bdt"][index]
                ),
                _ => format!("real argument {number} (A{number})"),
            },
            // The named reals, then A5 .. (A7 .. for the trans family) for the function.
            Self::Plasfunc
            | Self::Metfunc
            | Self::Transfunc
            | Self::Plasdata
            | Self::Metdata
            | Self::Transdata => match self.real_names().get(index) {
                Some(name) => format!("real argument {number} ({name})"),
                None => format!("real argument {number} (A{number})"),
            },
            _ => match self.real_names().get(index) {
                Some(name) => format!("real argument {number} ({name})"),
                None => format!("real argument {number}"),
            },
        }
    }
}

/// One primitive with its arguments read but not yet interpreted.
#[derive(Debug)]
pub(crate) struct RawPrimitive<'a> {
    /// File and line of the modifier word, where the primitive starts.
    pub at: SourceLocation,
    pub modifier: &'a str,
    pub kind: PrimitiveType,
    pub identifier: &'a str,
    pub strings: Vec<&'a str>,
    pub integers: Vec<i64>,
    pub reals: Vec<f64>,
}

impl<'a> RawPrimitive<'a> {
    /// A read primitive as one of the subset's types; any other RADIANCE type is an error
    /// naming it.
    pub fn from_primitive(p: &'a Primitive) -> Result<Self, SceneError> {
        let Some(kind) = PrimitiveType::from_name(&p.type_name) else {
            return Err(SceneError::UnsupportedType {
                at: p.origin.clone(),
                type_name: p.type_name.clone(),
                identifier: p.identifier.clone(),
                reason: "a RADIANCE type outside the subset Skylux reads",
            });
        };
        Ok(RawPrimitive {
            at: p.origin.clone(),
            modifier: &p.modifier,
            kind,
            identifier: &p.identifier,
            strings: p.strings.iter().map(String::as_str).collect(),
            integers: p.integers.clone(),
            reals: p.reals.clone(),
        })
    }

    /// ``type `identifier` ``, as error messages name a primitive.
    pub fn describe(&self) -> String {
        describe(self.kind.name(), self.identifier)
    }

    /// Fails unless the number of arguments in `list` is acceptable.
    pub fn check_count(
        &self,
        list: ArgumentList,
        acceptable: bool,
        expected: impl Into<String>,
    ) -> Result<(), SceneError> {
        if acceptable {
            return Ok(());
        }
        let found = match list {
            ArgumentList::String => self.strings.len(),
            ArgumentList::Integer => self.integers.len(),
            ArgumentList::Real => self.reals.len(),
        };
        Err(SceneError::ArgumentCount {
            at: self.at.clone(),
            primitive: self.describe(),
            list,
            found,
            expected: expected.into(),
        })
    }

    /// No string and no integer arguments, as for every type but `brightfunc` and `mirror`.
    pub fn check_no_strings_or_integers(&self) -> Result<(), SceneError> {
        self.check_count(
            ArgumentList::String,
            self.strings.is_empty(),
            format!("0 for {}", self.kind.name()),
        )?;
        self.check_no_integers()
    }

    /// RADIANCE has no primitive with integer arguments (reference manual §2.1).
    pub fn check_no_integers(&self) -> Result<(), SceneError> {
        self.check_count(
            ArgumentList::Integer,
            self.integers.is_empty(),
            "0 (no RADIANCE primitive takes integer arguments)",
        )
    }

    /// Exactly the real arguments the manual's synopsis names.
    pub fn check_real_count(&self) -> Result<(), SceneError> {
        let names = self.kind.real_names();
        self.check_count(
            ArgumentList::Real,
            self.reals.len() == names.len(),
            format!("{} ({})", names.len(), names.join(" ")),
        )
    }

    /// An out-of-range real argument.
    pub fn invalid_real(&self, index: usize, expected: impl Into<String>) -> SceneError {
        self.invalid(
            self.kind.real_field(index),
            self.reals
                .get(index)
                .map_or_else(String::new, f64::to_string),
            expected,
        )
    }

    /// A field (possibly made of several arguments) whose value is not acceptable.
    pub fn invalid(
        &self,
        field: impl Into<String>,
        value: impl Into<String>,
        expected: impl Into<String>,
    ) -> SceneError {
        SceneError::InvalidValue {
            at: self.at.clone(),
            primitive: self.describe(),
            field: field.into(),
            value: value.into(),
            expected: expected.into(),
        }
    }
}

fn describe(type_name: &str, identifier: &str) -> String {
    format!("{type_name} `{identifier}`")
}

/// What a scene file holds at the top level: a primitive or an inline command.
#[derive(Debug)]
pub(crate) enum Item {
    Primitive(Primitive),
    /// A `!command` line (continuation lines joined), without its `!`, and its first line.
    Command {
        line: usize,
        text: String,
    },
}

/// Reads the next primitive or command, or `None` at the end of the file. Every RADIANCE type
/// is read (so `xform` can carry it); [`RawPrimitive::from_primitive`] then refuses those
/// outside the subset.
pub(crate) fn read_item(lexer: &mut Lexer<'_>) -> Result<Option<Item>, SceneError> {
    let Some(modifier) = lexer.next_token()? else {
        return Ok(None);
    };
    let line = modifier.line;
    if !modifier.quoted && modifier.text.starts_with('!') {
        let text = format!("{}{}", &modifier.text[1..], lexer.command_tail());
        return Ok(Some(Item::Command { line, text }));
    }
    let type_token = expect(lexer, || {
        (
            format!("after modifier `{}` (line {line})", modifier.text),
            "a primitive type".to_string(),
        )
    })?;
    let kind = PrimitiveType::from_name(type_token.text);
    if kind.is_none() && !OTHER_RADIANCE_TYPES.contains(&type_token.text) {
        let identifier = lexer
            .next_token()
            .ok()
            .flatten()
            .map_or_else(|| "(none)".to_string(), |t| t.text.to_string());
        return Err(SceneError::UnsupportedType {
            at: lexer.at(type_token.line),
            type_name: type_token.text.to_string(),
            identifier,
            reason: "not a RADIANCE primitive type",
        });
    }
    let type_name = type_token.text;
    let identifier = expect(lexer, || {
        (
            format!("after `{} {type_name}` (line {line})", modifier.text),
            "an identifier".to_string(),
        )
    })?
    .text;
    let mut primitive = Primitive {
        modifier: modifier.text.to_string(),
        type_name: type_name.to_string(),
        identifier: identifier.to_string(),
        strings: Vec::new(),
        integers: Vec::new(),
        reals: Vec::new(),
        origin: lexer.at(line),
    };
    if type_name == "alias" {
        // `mod alias new old`: one word, no argument lists (RADIANCE 5 readobj).
        let target = expect(lexer, || {
            (
                format!("after `{} alias {identifier}` (line {line})", modifier.text),
                "the aliased modifier".to_string(),
            )
        })?;
        primitive.strings.push(target.text.to_string());
        return Ok(Some(Item::Primitive(primitive)));
    }
    read_arguments(lexer, &mut primitive, kind)?;
    Ok(Some(Item::Primitive(primitive)))
}

/// The three argument lists of `p`, named after `kind`'s synopsis when it is known.
fn read_arguments(
    lexer: &mut Lexer<'_>,
    p: &mut Primitive,
    kind: Option<PrimitiveType>,
) -> Result<(), SceneError> {
    let line = p.origin.line;
    let type_name = p.type_name.clone();
    let identifier = p.identifier.clone();
    // Messages are only formatted on the error path: this loop runs for every word of a
    // 10,000-polygon scene.
    let primitive = || describe(&type_name, &identifier);
    let real_field = |i: usize| match kind {
        Some(k) => k.real_field(i),
        None => format!("real argument {}", i + 1),
    };
    let inside = |list: ArgumentList| {
        format!(
            "inside the {list} arguments of {} (which starts on line {line})",
            primitive()
        )
    };

    let string_count = read_count(lexer, &primitive, line, ArgumentList::String)?;
    p.strings.reserve(string_count.min(16));
    for i in 0..string_count {
        let token = expect(lexer, || {
            (
                inside(ArgumentList::String),
                format!("string argument {} of {string_count}", i + 1),
            )
        })?;
        p.strings.push(token.text.to_string());
    }

    let integer_count = read_count(lexer, &primitive, line, ArgumentList::Integer)?;
    p.integers.reserve(integer_count.min(16));
    for i in 0..integer_count {
        let token = expect(lexer, || {
            (
                inside(ArgumentList::Integer),
                format!("integer argument {} of {integer_count}", i + 1),
            )
        })?;
        let value = token
            .text
            .parse::<i64>()
            .map_err(|_| SceneError::BadInteger {
                at: lexer.at(token.line),
                primitive: primitive(),
                index: i + 1,
                token: token.text.to_string(),
            })?;
        p.integers.push(value);
    }

    let real_count = read_count(lexer, &primitive, line, ArgumentList::Real)?;
    p.reals.reserve(real_count.min(1024));
    for i in 0..real_count {
        let token = expect(lexer, || {
            (
                inside(ArgumentList::Real),
                format!("{} of {real_count}", real_field(i)),
            )
        })?;
        let value = token.text.parse::<f64>().map_err(|_| SceneError::BadReal {
            at: lexer.at(token.line),
            primitive: primitive(),
            field: real_field(i),
            token: token.text.to_string(),
        })?;
        // Rust also parses `nan`, `inf` and overflowing exponents, which RADIANCE's `atof`
        // would turn into values no surface can have.
        if !value.is_finite() {
            return Err(SceneError::NonFiniteReal {
                at: lexer.at(token.line),
                primitive: primitive(),
                field: real_field(i),
                token: token.text.to_string(),
            });
        }
        p.reals.push(value);
    }
    Ok(())
}

/// The next word; at the end of the file, an error built from `describe()`'s (where, what
/// was expected).
fn expect<'a>(
    lexer: &mut Lexer<'a>,
    describe: impl FnOnce() -> (String, String),
) -> Result<Token<'a>, SceneError> {
    match lexer.next_token()? {
        Some(token) => Ok(token),
        None => {
            let (context, expected) = describe();
            Err(SceneError::UnexpectedEnd {
                at: lexer.last_word(),
                context,
                expected,
            })
        }
    }
}

fn read_count(
    lexer: &mut Lexer<'_>,
    primitive: &dyn Fn() -> String,
    line: usize,
    list: ArgumentList,
) -> Result<usize, SceneError> {
    let token = expect(lexer, || {
        (
            format!("inside {} (which starts on line {line})", primitive()),
            format!("the {list} argument count"),
        )
    })?;
    token
        .text
        .parse::<u64>()
        .ok()
        .and_then(|n| usize::try_from(n).ok())
        .ok_or_else(|| SceneError::BadCount {
            at: lexer.at(token.line),
            primitive: primitive(),
            list,
            token: token.text.to_string(),
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;
    use std::sync::Arc;

    fn read_all(text: &str) -> Result<Vec<Primitive>, SceneError> {
        let mut lexer = Lexer::new(Arc::from(Path::new("p.rad")), text);
        let mut out = Vec::new();
        while let Some(item) = read_item(&mut lexer)? {
            match item {
                Item::Primitive(p) => {
                    RawPrimitive::from_primitive(&p)?;
                    out.push(p);
                }
                Item::Command { text, .. } => panic!("command {text}"),
            }
        }
        Ok(out)
    }

    #[test]
    fn layout_does_not_matter() {
        let a = read_all("void plastic red\n0\n0\n5 .5 .4 .3 0 0\n").unwrap();
        let b = read_all("void plastic red 0 0 5 .5 .4 .3 0 0").unwrap();
        assert_eq!(a[0].reals, b[0].reals);
        assert_eq!(a[0].reals, [0.5, 0.4, 0.3, 0.0, 0.0]);
        assert_eq!(a[0].identifier, "red");
        assert_eq!(a[0].type_name, "plastic");
    }

    #[test]
    fn strings_and_integers_are_kept_in_order() {
        let p = read_all("void brightfunc f 3 skybright skybright.cal -rz 2 7 -3 1 2.5")
            .unwrap()
            .remove(0);
        assert_eq!(p.strings, ["skybright", "skybright.cal", "-rz"]);
        assert_eq!(p.integers, [7, -3]);
        assert_eq!(p.reals, [2.5]);
    }

    #[test]
    fn primitive_line_is_the_modifier_line() {
        let ps =
            read_all("# c\n\nvoid light l\n0 0 3 1 1 1\n\nl source s 0 0 4 0 0 1 0.5").unwrap();
        assert_eq!(ps[0].origin.line, 3);
        assert_eq!(ps[1].origin.line, 6);
    }

    /// The list of other RADIANCE types holds none that Skylux reads (`alias` is read apart).
    #[test]
    fn other_types_are_not_supported_ones() {
        for name in OTHER_RADIANCE_TYPES {
            assert!(
                PrimitiveType::from_name(name).is_none(),
                "{name} is supported"
            );
        }
    }

    #[test]
    fn real_fields_are_named_after_the_manual() {
        assert_eq!(
            PrimitiveType::Plastic.real_field(3),
            "real argument 4 (spec)"
        );
        assert_eq!(
            PrimitiveType::Polygon.real_field(7),
            "real argument 8 (vertex 3 y)"
        );
        assert_eq!(PrimitiveType::Sphere.real_field(9), "real argument 10");
    }

    #[test]
    fn huge_counts_do_not_allocate_up_front() {
        let err = read_all("void plastic x 0 0 4000000000 1 2").unwrap_err();
        assert!(matches!(err, SceneError::UnexpectedEnd { .. }), "{err}");
    }

    #[test]
    fn known_and_unknown_types_are_told_apart() {
        let known = read_all("void prism1 c 0 0 0").unwrap_err();
        assert!(known.to_string().contains("outside the subset"), "{known}");
        let typo = read_all("void plastik c 0 0 5 1 1 1 0 0").unwrap_err();
        assert!(
            typo.to_string().contains("not a RADIANCE primitive type"),
            "{typo}"
        );
    }
}
