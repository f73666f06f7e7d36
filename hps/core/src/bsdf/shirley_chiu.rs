//! The Shirley–Chiu concentric map between the unit square and the unit disk (P. Shirley and
//! K. Chiu, "A low distortion map between disk and square", J. Graphics Tools 2(3), 1997).
//! It preserves area, so a uniform square is a uniform disk, that is a uniform projected
//! solid angle on the hemisphere: the "LBNL/Shirley-Chiu" basis of tensor-tree BSDFs.
//! The 0.9999999999999 factor is RADIANCE's (`disk2square.c`), kept so that cells agree.

use std::f64::consts::{FRAC_PI_4, PI};

const SHRINK: f64 = 0.9999999999999;

/// The point of the unit disk for `(sx, sy)` in [0,1]².
pub fn square_to_disk(sx: f64, sy: f64) -> [f64; 2] {
    let a = 2.0 * sx - 1.0;
    let b = 2.0 * sy - 1.0;
    let (r, phi) = if a > -b {
        if a > b {
            (a, FRAC_PI_4 * (b / a))
        } else {
            (b, FRAC_PI_4 * (2.0 - a / b))
        }
    } else if a < b {
        (-a, FRAC_PI_4 * (4.0 + b / a))
    } else if b != 0.0 {
        (-b, FRAC_PI_4 * (6.0 - a / b))
    } else {
        (-b, 0.0)
    };
    let r = r * SHRINK;
    [r * phi.cos(), r * phi.sin()]
}

/// The point of [0,1]² for `(x, y)` on the unit disk.
pub fn disk_to_square(x: f64, y: f64) -> [f64; 2] {
    let r = (x * x + y * y).sqrt();
    let mut phi = y.atan2(x);
    if phi < -FRAC_PI_4 {
        phi += 2.0 * PI;
    }
    let (a, b) = if phi < FRAC_PI_4 {
        (r, phi * r / FRAC_PI_4)
    } else if phi < 3.0 * FRAC_PI_4 {
        (-(phi - PI / 2.0) * r / FRAC_PI_4, r)
    } else if phi < 5.0 * FRAC_PI_4 {
        (-r, (phi - PI) * -r / FRAC_PI_4)
    } else {
        (-(phi - 3.0 * PI / 2.0) * -r / FRAC_PI_4, -r)
    };
    [a * (0.5 / SHRINK) + 0.5, b * (0.5 / SHRINK) + 0.5]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_area() {
        for i in 0..50 {
            for j in 0..50 {
                let (sx, sy) = ((i as f64 + 0.5) / 50.0, (j as f64 + 0.3) / 50.0);
                let [x, y] = square_to_disk(sx, sy);
                assert!(x * x + y * y <= 1.0);
                let [bx, by] = disk_to_square(x, y);
                assert!(
                    (bx - sx).abs() < 1e-9 && (by - sy).abs() < 1e-9,
                    "{sx},{sy} -> {bx},{by}"
                );
            }
        }
        // Equal areas: the inner half of the square's area is the disk of radius 1/√2.
        let [x, y] = square_to_disk(0.5 + 0.25 * 2f64.sqrt(), 0.5);
        assert!(((x * x + y * y).sqrt() - 0.5f64.sqrt()).abs() < 1e-9);
    }
}
