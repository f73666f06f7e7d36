//! The glare sources drawn over a falsecolour picture: each source's edge in a colour of its
//! own, for `skylux glare`'s PNG.

/// Colours cycled over the sources: white, magenta, black, green, so that an edge shows on
/// every part of the Turbo scale.
const PALETTE: [[u8; 3]; 4] = [[255, 255, 255], [255, 0, 255], [0, 0, 0], [0, 255, 0]];

/// A mark per pixel (rows from the top) for the edge pixels of the sources in
/// `source_of_pixel` (0: no source): pixels of a source with a 4-neighbour outside it or on
/// the picture's border.
pub fn source_outlines(
    source_of_pixel: &[u32],
    width_px: usize,
    height_px: usize,
) -> Vec<Option<[u8; 3]>> {
    let at = |x: usize, y: usize| source_of_pixel[y * width_px + x];
    let mut marks = vec![None; source_of_pixel.len()];
    for y in 0..height_px {
        for x in 0..width_px {
            let s = at(x, y);
            if s == 0 {
                continue;
            }
            let edge = x == 0
                || y == 0
                || x + 1 == width_px
                || y + 1 == height_px
                || at(x - 1, y) != s
                || at(x + 1, y) != s
                || at(x, y - 1) != s
                || at(x, y + 1) != s;
            if edge {
                marks[y * width_px + x] = Some(PALETTE[(s as usize - 1) % PALETTE.len()]);
            }
        }
    }
    marks
}
