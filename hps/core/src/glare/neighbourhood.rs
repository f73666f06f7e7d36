//! The two neighbourhood walks evalglare uses to find glare-source pixels near a pixel
//! (`find_near_pgs` and `find_split`). Both walk outwards row by row from the pixel and stop a
//! row where the angular distance passes the radius; which neighbour they meet first decides
//! which source a pixel joins, so the order is kept.
//!
//! Distances are evalglare's: twice the angle between pixel directions against the radius, so
//! the default radius 0.2 reaches 0.1 rad (5.7°) away.

use super::pixels::PixelGrid;

/// Whether pixel `other` lies within `radius_rad` (evalglare's doubled angle) of `centre`.
fn within(grid: &PixelGrid, centre: usize, other: usize, cos_half_radius: f64) -> bool {
    grid.direction[centre].dot(grid.direction[other]) >= cos_half_radius
}

/// evalglare's `find_near_pgs` walk around pixel (`x`, `y`): down from its row, then up from
/// the row above, each row from the middle of the previous row's span leftwards and then
/// rightwards, columns up to `x_max`. `inside` sees each pixel within the radius and returns
/// true to end the walk in that direction (the other vertical direction is still walked).
pub fn walk_near(
    grid: &PixelGrid,
    (x, y): (usize, usize),
    radius_rad: f64,
    x_max: usize,
    mut inside: impl FnMut(usize) -> bool,
) {
    let cos_half = (radius_rad / 2.0).cos();
    let centre = grid.index(x, y);
    let (x, y) = (x as i64, y as i64);
    let (x_max, y_max) = (x_max as i64, grid.height_px as i64 - 1);
    for dy in [-1i64, 1] {
        let mut iy = if dy < 0 { y } else { y + 1 };
        let mut span = [x, x];
        let mut stop = false;
        while (0..=y_max).contains(&iy) && !stop {
            for (side, dx) in [(0usize, -1i64), (1, 1)] {
                let mut ix = (span[0] + span[1]) / 2;
                while (0..=x_max).contains(&ix) && !stop {
                    let other = grid.index(ix as usize, iy as usize);
                    if !within(grid, centre, other, cos_half) {
                        span[side] = ix - dx;
                        break;
                    }
                    stop = inside(other);
                    ix += dx;
                }
            }
            iy += dy;
        }
    }
}

/// evalglare's `find_split` walk around pixel (`x`, `y`): rows down and then up, each row
/// leftwards from the pixel's column and rightwards from the next, until a row has no pixel
/// within the radius. `inside` sees every pixel within the radius.
pub fn walk_split(
    grid: &PixelGrid,
    (x, y): (usize, usize),
    radius_rad: f64,
    mut inside: impl FnMut(usize),
) {
    let cos_half = (radius_rad / 2.0).cos();
    let centre = grid.index(x, y);
    let (x, y) = (x as i64, y as i64);
    let (x_max, y_max) = (grid.width_px as i64 - 1, grid.height_px as i64 - 1);
    for dy in [-1i64, 1] {
        let mut iy = if dy < 0 { y } else { y + 1 };
        while (0..=y_max).contains(&iy) {
            let mut any = false;
            for dx in [-1i64, 1] {
                let mut ix = if dx < 0 { x } else { x + 1 };
                while (0..=x_max).contains(&ix) {
                    let other = grid.index(ix as usize, iy as usize);
                    if !within(grid, centre, other, cos_half) {
                        break;
                    }
                    any = true;
                    inside(other);
                    ix += dx;
                }
            }
            if !any {
                break;
            }
            iy += dy;
        }
    }
}
