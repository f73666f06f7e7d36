//! The "through" component of an `aBSDF`: the part of the transmission that goes on
//! unscattered along the view direction, found in the data as RADIANCE finds it (m_bsdf.c,
//! `compute_through`, and the over-counting test of `direct_specular_OK`).
//!
//! The transmission is evaluated on a small square grid of directions around the straight
//! continuation of the view, spaced by fractions of the side of the data's smallest cell
//! (√ of its smallest projected solid angle). Values from the largest down that sit in cells
//! no bigger than 1.5 smallest cells, and that the peak found so far does not dwarf (8 times
//! the mean of the peak values), are the peak; the others are its surround. The peak's
//! transmittance is Σ f Ω_proj over the peak's cells, the surround's value the Ω_proj-weighted
//! mean of f over its cells, both less the data's Lambertian transmission. There is no
//! through component when the largest value is not itself a peak, when the surround covers
//! less than a fifth of the peak's projected solid angle, or when the peak transmits less
//! than 0.05 %.

use super::side::Side;
use super::{Bsdf, Part};
use glam::DVec3;
use std::f64::consts::PI;

/// RADIANCE's FTINY.
const FTINY: f64 = 1e-6;
/// Peak transmittance below which a BSDF has no through component (m_bsdf.c: 0.05 %).
const NEGLIGIBLE_THROUGH: f64 = 0.0005;

/// A view's through component.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Through {
    /// What passes straight through, as a transmittance (RADIANCE `cthru`).
    pub transmittance: f64,
    /// The BTDF around the peak without its Lambertian share, 1/sr (`cthru_surr`): what
    /// a light source seen near the through direction is lit through with instead of the
    /// peak, which shadow rays already carry.
    pub surround_per_sr: f64,
    /// The smallest projected solid angle the transmission data resolves (`minProjSA`).
    pub min_projected_solid_angle_sr: f64,
}

/// The grid around the straight continuation, in units of the smallest cell's side: its
/// centre, then three square rings of eight (axes first, then corners) at 0.6, 1.2 and 1.8,
/// then the four axis points at 2.4; RADIANCE's 29 directions in its order.
fn grid() -> impl Iterator<Item = [f64; 2]> {
    let ring = |r: f64, corners: bool| {
        let axes = [[-r, 0.0], [0.0, r], [0.0, -r], [r, 0.0]];
        let diagonals = [[-r, r], [-r, -r], [r, r], [r, -r]];
        axes.into_iter()
            .chain(diagonals.into_iter().filter(move |_| corners))
    };
    std::iter::once([0.0, 0.0])
        .chain(ring(0.6, true))
        .chain(ring(1.2, true))
        .chain(ring(1.8, true))
        .chain(ring(2.4, false))
}

impl Through {
    /// Whether a light source in unit direction `source` (BSDF frame) of solid angle
    /// `omega_sr` lies close enough to the through direction of the view `view` that its
    /// light through the peak is the shadow ray's, not the BTDF's (m_bsdf.c
    /// `direct_specular_OK`: within √(10/π) (√(Ω cos θ) + √Ω_min) of it, in the plane).
    pub fn covers(&self, view: DVec3, source: DVec3, omega_sr: f64) -> bool {
        if (source.z > 0.0) == (view.z > 0.0) || self.transmittance <= FTINY {
            return false;
        }
        let dx = source.x + view.x;
        let dy = source.y + view.y;
        let projected = omega_sr * source.z.abs();
        let m = self.min_projected_solid_angle_sr;
        dx * dx + dy * dy <= (2.5 * 4.0 / PI) * (projected + m + 2.0 * (projected * m).sqrt())
    }
}

impl Bsdf {
    /// The transmission part a view from the `front` (+z) side looks through, or the other
    /// direction's by reciprocity.
    fn transmission_part(&self, front: bool) -> Option<&Part> {
        let (own, other) = if front {
            (Side::FrontTransmission, Side::BackTransmission)
        } else {
            (Side::BackTransmission, Side::FrontTransmission)
        };
        self.part(own).or_else(|| self.part(other))
    }

    /// The smallest projected solid angle of the data's cells holding the direction pair
    /// (`v1`, `v2`), looked up in the part `v1`'s side and the pair's kind select (RADIANCE
    /// `SDsizeBSDF` with `SDqueryMin`): π when there is no such part (all Lambertian), 10
    /// when neither direction is in a cell.
    pub fn pair_projected_solid_angle(&self, v1: DVec3, v2: DVec3) -> f64 {
        let front = v1.z > 0.0;
        let part = if front != (v2.z > 0.0) {
            self.transmission_part(front)
        } else if front {
            self.part(Side::FrontReflection)
        } else {
            self.part(Side::BackReflection)
        };
        let Some(part) = part else {
            return PI;
        };
        part.pair_projected_solid_angles(v1, v2)
            .into_iter()
            .filter(|&psa| psa > 0.0)
            .fold(10.0, f64::min)
    }

    /// The through component for a view from unit direction `view` (BSDF frame, pointing
    /// away from the surface), or None when the data has none there.
    pub fn through(&self, view: DVec3) -> Option<Through> {
        let front = view.z > 0.0;
        let part = self.transmission_part(front)?;
        let min_psa = part.min_projected_solid_angle();
        let step = min_psa.sqrt();
        let mut samples: Vec<(f64, DVec3)> = grid()
            .map(|[x, y]| {
                let dir = DVec3::new(-view.x + x * step, -view.y + y * step, -view.z).normalize();
                (self.eval(view, dir), dir)
            })
            .collect();
        samples.sort_by(|a, b| b.0.total_cmp(&a.0));
        if samples[0].0 <= FTINY {
            return None;
        }
        let (mut peak, mut peak_psa, mut peak_values, mut peak_count) = (0.0, 0.0, 0.0, 0.0);
        let (mut surround, mut surround_psa) = (0.0, 0.0);
        for (i, &(value, dir)) in samples.iter().enumerate() {
            if i > 0 && value == samples[i - 1].0 {
                continue; // the same cell again
            }
            let psa = self.pair_projected_solid_angle(view, dir);
            if psa > 1.5 * min_psa || peak_values > 8.0 * value * peak_count {
                if i == 0 {
                    return None;
                }
                surround += value * psa;
                surround_psa += psa;
            } else {
                peak += value * psa;
                peak_psa += psa;
                peak_values += value;
                peak_count += 1.0;
            }
        }
        if surround_psa < 0.2 * peak_psa {
            return None;
        }
        let lambertian = self.lambertian_of(Side::of(front, !front)) / PI;
        let transmittance = (peak - peak_psa * lambertian).max(0.0);
        if transmittance < NEGLIGIBLE_THROUGH {
            return None;
        }
        Some(Through {
            transmittance,
            surround_per_sr: (surround / surround_psa - lambertian).max(0.0),
            min_projected_solid_angle_sr: min_psa,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsdf::Scattering;

    fn corpus_xml(name: &str) -> std::path::PathBuf {
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../../shared/data/radiance-corpus/bsdf")
            .join(name)
    }

    /// The first value of the first `<ScatteringData>` after `direction` in the file: the
    /// BTDF from Klems patch 0 to patch 0 (normal incidence, straight on), 1/sr.
    fn first_value_after(text: &str, direction: &str) -> f64 {
        let at = text.find(direction).expect("the direction's block");
        let data = &text[at..];
        let start = data.find("<ScatteringData>").unwrap() + "<ScatteringData>".len();
        data[start..]
            .split(|c: char| c == ',' || c.is_whitespace())
            .find(|w| !w.is_empty())
            .unwrap()
            .parse()
            .unwrap()
    }

    /// frads' electrochromic glazing (ec60, clear glass on a Klems full basis): seen at
    /// normal incidence from either side, its through component is the XML's own straight-on
    /// transmittance, f(0 → 0) times the centre patch's projected solid angle π sin² 5°
    /// (the file has no Lambertian share to take out), and most of the hemispherical
    /// transmittance; the surround around it is dark. Off normal it is still found.
    #[test]
    fn ec60_through_is_the_straight_on_transmittance() {
        let path = corpus_xml("frads/ec60.xml");
        let text = std::fs::read_to_string(&path).expect("the corpus's ec60.xml (shared/data)");
        let data = Bsdf::load(&path).unwrap();
        let centre_psa = PI * 5f64.to_radians().sin().powi(2);
        for (view, window_direction) in [
            (DVec3::Z, "Transmission Back"),
            (-DVec3::Z, "Transmission Front"),
        ] {
            let expect = first_value_after(&text, window_direction) * centre_psa;
            let t = data.through(view).expect("a through component");
            // RADIANCE's ±0.03 % perturbation of each Klems value is in the data's eval
            // (and not in its hemispherical sums).
            assert!(
                (t.transmittance - expect).abs() < 1e-3 * expect,
                "{view}: {} vs the XML's {expect}",
                t.transmittance
            );
            let hemispherical = data.hemispherical(view, Scattering::Transmission);
            assert!(
                t.transmittance > 0.95 * hemispherical && t.transmittance <= 1.001 * hemispherical,
                "{view}: {} of {hemispherical}",
                t.transmittance
            );
            assert!(t.surround_per_sr < 0.01 * t.transmittance / centre_psa);
            assert!((t.min_projected_solid_angle_sr - data_min_psa()).abs() < 1e-12);
        }
        let oblique = DVec3::new(0.3, -0.4, 0.0).with_z((1.0f64 - 0.25).sqrt());
        let t = data.through(oblique).expect("oblique through");
        let hemispherical = data.hemispherical(oblique, Scattering::Transmission);
        assert!(
            t.transmittance > 0.9 * hemispherical,
            "{t:?} of {hemispherical}"
        );
    }

    /// Klems full: the smallest patch is one of the twelve of the 75°-90° ring.
    fn data_min_psa() -> f64 {
        PI * 75f64.to_radians().cos().powi(2) / 12.0
    }

    /// Satine 5 % (frads `2011-SA1.xml`): its openness is a through component, a part of
    /// its transmittance; RADIANCE's own test BSDF (`testBSDF.xml`) has none.
    #[test]
    fn a_shade_passes_its_openness_and_a_diffuser_nothing() {
        let data = Bsdf::load(&corpus_xml("frads/2011-SA1.xml")).unwrap();
        for view in [DVec3::Z, -DVec3::Z] {
            let t = data.through(view).expect("Satine's openness");
            let hemispherical = data.hemispherical(view, Scattering::Transmission);
            println!("Satine {view}: through {t:?} of T {hemispherical}");
            assert!(
                t.transmittance > 0.0 && t.transmittance < hemispherical,
                "{view}: {t:?} of {hemispherical}"
            );
        }
        let data = Bsdf::load(&corpus_xml("radiance/test/util/ref/testBSDF.xml")).unwrap();
        for view in [DVec3::Z, -DVec3::Z, DVec3::new(0.5, 0.0, 0.75f64.sqrt())] {
            assert_eq!(data.through(view), None, "{view}");
        }
    }

    /// Near the through direction a source lights through the surround; away from it, or on
    /// the viewer's side, through the data.
    #[test]
    fn the_peak_cone_covers_the_through_direction_only() {
        let t = Through {
            transmittance: 0.5,
            surround_per_sr: 0.1,
            min_projected_solid_angle_sr: 0.0175,
        };
        let view = DVec3::new(0.2, 0.1, 0.97).normalize();
        let sun_sr = 6.8e-5;
        assert!(t.covers(view, -view, sun_sr));
        assert!(!t.covers(view, view, sun_sr));
        let away = DVec3::new(-0.6, -0.1, -0.79).normalize();
        assert!(!t.covers(view, away, sun_sr));
    }
}
