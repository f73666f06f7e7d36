//! A scene's sky as the matrix methods take it (RADIANCE's `genskyvec`): the radiance of its
//! `glow` sources and environment averaged over the ground and over each Reinhart patch (D's
//! columns), and each `light` source (the sun) apart, as a beam for the five-phase's direct
//! term.

use crate::engine::material::bright;
use crate::engine::sky::DistantKind;
use crate::engine::world::World;
use crate::sky::SkyPatches;
use glam::DVec3;
use rayon::prelude::*;
use std::f64::consts::TAU;

/// A distant concentrated source: the sun.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SunBeam {
    /// Unit direction towards the sun.
    pub direction: DVec3,
    /// Direct-normal irradiance, W/m² (RADIANCE units: times 179 lm/W for lux).
    pub direct_normal_w_m2: f64,
}

/// Cells of the averaging grid per hemisphere: cos θ in `GRID_Z` equal steps, azimuth in
/// `GRID_PHI`, so every cell has the same solid angle (2π / (GRID_Z GRID_PHI) = 2.4e-5 sr,
/// a twentieth of the smallest patch, MF 8's zenith cap).
const GRID_Z: usize = 256;
const GRID_PHI: usize = 1024;

/// The sky vector of `world`'s distant sources and environment: ground first, then the
/// Reinhart MF `mf` patches, radiance in W/(m² sr) (grey: RADIANCE's brightness of the
/// colour), each the mean over its solid angle; and every `light` source as a beam. The
/// `light` sources are not in the vector (a ray that meets one sees nothing: RADIANCE counts
/// them by their own sampling only).
pub fn sky_vector_of_world(world: &World, mf: usize) -> (Vec<f64>, Vec<SunBeam>) {
    let patches = SkyPatches::reinhart(mf);
    let bins = 1 + patches.len();
    let direction = |row: usize, col: usize, upper: bool| {
        let z = (row as f64 + 0.5) / GRID_Z as f64;
        let phi = TAU * (col as f64 + 0.5) / GRID_PHI as f64;
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), if upper { z } else { -z })
    };
    let (sum, count) = (0..GRID_Z)
        .into_par_iter()
        .map(|row| {
            let mut sum = vec![0.0; bins];
            let mut count = vec![0u32; bins];
            for col in 0..GRID_PHI {
                for upper in [true, false] {
                    let d = direction(row, col, upper);
                    let bin = if upper {
                        patches.patch_of(d).map_or(0, |p| 1 + p)
                    } else {
                        0
                    };
                    sum[bin] += bright(world.escape_radiance(d));
                    count[bin] += 1;
                }
            }
            (sum, count)
        })
        .reduce(
            || (vec![0.0; bins], vec![0u32; bins]),
            |(mut s, mut c), (s2, c2)| {
                s.iter_mut().zip(s2).for_each(|(a, b)| *a += b);
                c.iter_mut().zip(c2).for_each(|(a, b)| *a += b);
                (s, c)
            },
        );
    let vector = (0..bins)
        .map(|b| match count[b] {
            0 => bright(world.escape_radiance(patches.centre(b - 1))),
            n => sum[b] / f64::from(n),
        })
        .collect();
    let suns = world
        .distant_sources()
        .iter()
        .filter(|s| s.kind == DistantKind::Light)
        .map(|s| SunBeam {
            direction: s.direction,
            direct_normal_w_m2: bright(s.radiance(s.direction)) * s.solid_angle_sr,
        })
        .collect();
    (vector, suns)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene;

    #[test]
    fn a_uniform_sky_and_ground_and_a_sun() {
        // A uniform sky of radiance 2, a ground of 0.5 and a sun of 1000 W/m² normal.
        let text = "void glow sky_glow 0 0 4 2 2 2 0\nsky_glow source sky 0 0 4 0 0 1 180\n\
                    void glow ground_glow 0 0 4 0.5 0.5 0.5 0\n\
                    ground_glow source ground 0 0 4 0 0 -1 180\n\
                    void light solar 0 0 3 1.5e7 1.5e7 1.5e7\n\
                    solar source sun 0 0 4 0 -0.6 0.8 0.533\n";
        let world = World::new(&scene::parse("sky.rad", text.as_bytes()).unwrap()).unwrap();
        let (v, suns) = sky_vector_of_world(&world, 1);
        assert_eq!(v.len(), 146);
        assert!((v[0] - 0.5).abs() < 1e-9, "ground {}", v[0]);
        // The sun is not in the vector; its disk hides the sky behind it, as a ray escaping
        // towards a `light` sees nothing: its patch reads a little under 2 (the disk is a
        // thousandth of a Tregenza patch; the grid resolves it to its cells).
        let sun_patch = 1 + SkyPatches::reinhart(1)
            .patch_of(DVec3::new(0.0, -0.6, 0.8))
            .unwrap();
        for (b, &x) in v.iter().enumerate().skip(1) {
            if b == sun_patch {
                assert!((1.99..2.0).contains(&x), "sun's patch {x}");
            } else {
                assert!((x - 2.0).abs() < 1e-9, "patch {b}: {x}");
            }
        }
        assert_eq!(suns.len(), 1);
        let omega = TAU * (1.0 - (0.5 * 0.533f64.to_radians()).cos());
        assert!((suns[0].direct_normal_w_m2 - 1.5e7 * omega).abs() < 1e-6 * 1.5e7 * omega);
        assert!((suns[0].direction - DVec3::new(0.0, -0.6, 0.8)).length() < 1e-12);
    }
}
