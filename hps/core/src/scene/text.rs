//! The text patterns `brighttext`, `colortext` and the mixture `mixtext`: letters of a
//! polygonal font drawn on a surface (reference manual ray.html §2.1.4 "Brighttext",
//! "Colortext", §2.1.6 "Mixtext"; `src/rt/text.c`).
//!
//! Strings: `fontfile textfile`, or `fontfile . word ..` for one line of words (text.c
//! takes the words after the second string whatever that string is); `mixtext` names its
//! foreground and background modifiers first (`material::Mixtext`, beside the other
//! mixtures). Reals: the upper-left anchor `Ax Ay Az`, the right and down motion vectors
//! (one character cell each), then for `brighttext` the foreground and background
//! brightness, for `colortext` the two colours, and last an optional character spacing. The engine reads the font and the text file
//! (`engine::function::text`); here the arguments are only split and counted.

use super::error::{ArgumentList, SceneError};
use super::parse::{PrimitiveType, RawPrimitive};
use glam::DVec3;
use std::path::PathBuf;

/// Reals before the pattern's own: the anchor, the right and the down vectors.
const PLACEMENT_REALS: usize = 9;

/// Where a text pattern's characters come from.
#[derive(Clone, Debug, PartialEq)]
pub enum TextSource {
    /// One line: the words of the string arguments joined by single spaces.
    Inline(String),
    /// A text file, found through RAYPATH as the font is; one line of text per line.
    File(String),
}

/// What every text pattern carries: the font, the text and where the text lies.
#[derive(Clone, Debug, PartialEq)]
pub struct TextArgs {
    /// The font file as written, found through RAYPATH by the engine.
    pub font_file: String,
    pub text: TextSource,
    /// The upper-left corner of the first line (`Ax Ay Az`), scene coordinates.
    pub anchor_m: DVec3,
    /// One character cell to the right (`Rx Ry Rz`).
    pub right_m: DVec3,
    /// One line down (`Dx Dy Dz`).
    pub down_m: DVec3,
    /// The optional last real: 0 or absent for uniform cells, > 0 for proportional
    /// spacing with that gap, < 0 for squeezed text (in cell widths).
    pub spacing: Option<f64>,
    /// The directory of the scene file that names the files (searched after RAYPATH).
    pub scene_dir: PathBuf,
}

/// `brighttext` (grey values) and `colortext`: the colour inside the glyphs and outside.
#[derive(Clone, Debug, PartialEq)]
pub struct TextPattern {
    pub text: TextArgs,
    /// Multiplies the colour inside a glyph.
    pub foreground_rgb: DVec3,
    /// Multiplies it elsewhere, outside the text's box included.
    pub background_rgb: DVec3,
}

/// The font, text and placement of a text pattern whose font is string argument
/// `font_index` (0, or 2 for `mixtext`).
pub(crate) fn text_args(raw: &RawPrimitive<'_>, font_index: usize) -> Result<TextArgs, SceneError> {
    let synopsis = match raw.kind {
        PrimitiveType::Mixtext => {
            "foreground background fontfile textfile | foreground \
                                   background fontfile . word .."
        }
        _ => "fontfile textfile | fontfile . word ..",
    };
    raw.check_count(
        ArgumentList::String,
        raw.strings.len() >= font_index + 2,
        format!("at least {} ({synopsis})", font_index + 2),
    )?;
    raw.check_no_integers()?;
    let own = match raw.kind {
        PrimitiveType::Brighttext => 2,
        PrimitiveType::Colortext => 6,
        _ => 0,
    };
    let required = PLACEMENT_REALS + own;
    raw.check_count(
        ArgumentList::Real,
        raw.reals.len() >= required,
        format!(
            "at least {required} ({} [spacing])",
            raw.kind.real_names().join(" ")
        ),
    )?;
    let r = &raw.reals;
    let vector = |i: usize| DVec3::new(r[i], r[i + 1], r[i + 2]);
    let text = if raw.strings.len() > font_index + 2 {
        TextSource::Inline(raw.strings[font_index + 2..].join(" "))
    } else {
        TextSource::File(raw.strings[font_index + 1].to_string())
    };
    Ok(TextArgs {
        font_file: raw.strings[font_index].to_string(),
        text,
        anchor_m: vector(0),
        right_m: vector(3),
        down_m: vector(6),
        spacing: r.get(required).copied(),
        scene_dir: raw.at.file.parent().map(PathBuf::from).unwrap_or_default(),
    })
}

/// `brighttext` or `colortext`.
pub(crate) fn text_pattern(raw: &RawPrimitive<'_>) -> Result<TextPattern, SceneError> {
    let text = text_args(raw, 0)?;
    let r = &raw.reals[PLACEMENT_REALS..];
    let (foreground_rgb, background_rgb) = if raw.kind == PrimitiveType::Colortext {
        (DVec3::new(r[0], r[1], r[2]), DVec3::new(r[3], r[4], r[5]))
    } else {
        (DVec3::splat(r[0]), DVec3::splat(r[1]))
    };
    Ok(TextPattern {
        text,
        foreground_rgb,
        background_rgb,
    })
}
