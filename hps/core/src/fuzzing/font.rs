//! RADIANCE font files (`.fnt`, read by `brighttext`, `colortext` and `mixtext`), and text
//! laid out in them.

use crate::engine::function::font::Font;
use crate::engine::function::text::{text_file_lines, TextLayout};
use glam::DVec3;
use std::sync::Arc;

/// Spacing arguments: absent, 0, proportional, squeezed, and past what a `short` holds.
const SPACINGS: [Option<f64>; 6] = [
    None,
    Some(0.0),
    Some(0.1),
    Some(-0.1),
    Some(1e9),
    Some(-1e9),
];

/// Parses the bytes as `fuzz.fnt`; a font read is tested glyph by glyph at the corners,
/// inside and outside its cell, then lays out lines (every character code, words with
/// spaces, the input itself split as text.c reads a text file) with every kind of spacing
/// and tests points over and around the text's box.
pub(super) fn fnt(bytes: &[u8]) {
    let font = match Font::parse("fuzz.fnt", bytes) {
        Ok(font) => Arc::new(font),
        Err(e) => return super::checks::assert_names(&e.to_string(), "fuzz.fnt"),
    };
    for c in 0..=255u8 {
        if let Some(glyph) = font.glyph(c) {
            for (x, y) in [
                (0.0, 0.0),
                (127.5, 127.5),
                (254.9, 255.0),
                (-1.0, 300.0),
                (f64::NAN, 1.0),
            ] {
                let _ = glyph.contains(x, y);
            }
        }
    }
    let mut lines = vec![b"SKY LUX   OK. ?".to_vec(), (0..=255u8).collect()];
    lines.extend(text_file_lines(bytes).into_iter().take(4));
    let (right, down) = (DVec3::X, DVec3::NEG_Y);
    for spacing in SPACINGS {
        let layout = TextLayout::new(
            font.clone(),
            lines.clone(),
            DVec3::ZERO,
            right,
            down,
            spacing,
        )
        .expect("orthogonal unit motion vectors span a plane");
        for j in -1..(lines.len() as i32 + 1) {
            for i in -2..64 {
                let point = DVec3::new(0.37 * f64::from(i), -0.41 - f64::from(j), 0.0);
                let _ = layout.is_foreground(point);
            }
        }
        let _ = layout.is_foreground(DVec3::new(1e300, -1e300, f64::NAN));
    }
}
