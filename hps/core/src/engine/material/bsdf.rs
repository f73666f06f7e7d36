//! RADIANCE's `BSDF` material (src/rt/m_bsdf.c `m_bsdf`): scattering from a WINDOW / LBNL XML
//! file ([`crate::bsdf::Bsdf`]), in the frame the surface normal and the up vector give it
//! (`SDcompXform`), with optional extra Lambertian reflectance and transmittance.
//!
//! Direct light (the sun, local lights) is evaluated through the data at each hit, as
//! m_bsdf.c's `dir_bsdf` does; the sky arrives by the continuation drawn from the data's own
//! distribution. Lambertian lobes continue as diffuse (ambient) bounces, the file's
//! directional parts as specular events, as RADIANCE counts them against `-ab`.
//!
//! A non-zero thickness makes the surface a proxy for detailed geometry behind it: shadow
//! rays, view (camera) rays and rays meeting its hidden side pass through it, as m_bsdf.c
//! decides (`raytrans`); light transmitted through it (the sun's next-event estimate and
//! the sampled continuation) is traced from the hit moved by the thickness against the
//! front normal, past the detailed geometry (m_bsdf.c: `-thick` times `ron`).
//!
//! `aBSDF` is a thin `BSDF` whose strong "through" component ([`crate::bsdf::Through`],
//! found around the straight continuation of each ray as m_bsdf.c's `compute_through` finds
//! it) passes rays straight on. A shadow ray towards a light source (the sun) crosses it
//! keeping the through transmittance, so the sun reaches what lies behind an `aBSDF` window by
//! next-event estimation; the sun's estimate at the window itself then takes the BTDF around
//! the peak instead of the peak for a source within the peak's cone of the ray's through
//! direction, so that the peak is not counted twice (`direct_specular_OK`). Paths that meet it
//! after a bounce sample its whole data, peak included, as RADIANCE's ambient and specular
//! rays do. A view (camera) ray goes on straight with the through transmittance, still a view
//! ray, and the rest of its scattering is sampled with the transmitted samples that fall in
//! the peak (within the side of the view's smallest data cell of the straight continuation)
//! dropped (m_bsdf.c `sample_sdf`, `sample_sdcomp`). Shadow rays for the sky's next-event estimate do not cross it (the sky is no
//! light source in RADIANCE: its light through the peak is the sampled continuation's).

use super::scattering::{bright, Scatter};
use crate::bsdf::Bsdf;
use crate::bsdf::Through;
use crate::engine::ray::FTINY;
use crate::engine::rng::Rng;
use crate::engine::sampling::cosine_direction;
use crate::scene::{BsdfModifier, BsdfType};
use glam::DVec3;
use std::f64::consts::PI;
use std::sync::Arc;

/// A `BSDF` surface's material.
#[derive(Clone, Debug)]
pub struct BsdfMaterial {
    pub data: Arc<Bsdf>,
    /// Signed proxy thickness (0: thin).
    pub thickness_m: f64,
    pub up: DVec3,
    pub extra_reflectance_front_rgb: DVec3,
    pub extra_reflectance_back_rgb: DVec3,
    pub extra_transmittance_rgb: DVec3,
    /// `aBSDF`: straight rays pass with the through component.
    pub through: bool,
}

impl BsdfMaterial {
    pub fn new(args: &BsdfModifier, data: Arc<Bsdf>) -> Self {
        Self {
            data,
            thickness_m: args.thickness_m,
            up: args.up,
            extra_reflectance_front_rgb: args.extra_reflectance_front_rgb,
            extra_reflectance_back_rgb: args.extra_reflectance_back_rgb,
            extra_transmittance_rgb: args.extra_transmittance_rgb,
            through: args.kind == BsdfType::ABsdf,
        }
    }

    /// What a straight ray along unit `d` keeps crossing a surface of front normal `normal`
    /// of this material: an `aBSDF`'s through transmittance for that ray (m_bsdf.c passes
    /// shadow rays with `cthru`), 0 for a `BSDF` or where there is no through component.
    pub fn through_transmittance(&self, d: DVec3, normal: DVec3) -> f64 {
        if !self.through {
            return 0.0;
        }
        Frame::new(normal, self.up)
            .and_then(|frame| self.data.through(frame.to_local(-d)))
            .map_or(0.0, |t| t.transmittance)
    }

    /// Whether a ray along `d` meeting a surface of front normal `normal` passes this proxy
    /// unscattered (m_bsdf.c: view rays, and rays on the side a positive thickness hides,
    /// or the front for a negative one). Thin surfaces never let rays pass.
    pub fn passes(&self, d: DVec3, normal: DVec3, primary: bool) -> bool {
        let hit_front = d.dot(normal) < 0.0;
        self.thickness_m != 0.0 && (primary || (self.thickness_m > 0.0) != hit_front)
    }

    /// Shadow rays pass a proxy and are blocked by a thin `BSDF` (m_bsdf.c, the early shadow
    /// checks).
    pub fn shadow_passes(&self) -> bool {
        self.thickness_m != 0.0
    }

    /// The BSDF's frame (x, y, z) on a surface of front normal `normal`; None when the up
    /// vector is parallel to it.
    pub fn frame_axes(&self, normal: DVec3) -> Option<[DVec3; 3]> {
        Frame::new(normal, self.up).map(|f| [f.x, f.y, f.z])
    }

    /// f per steradian, the extra Lambertian parts included, of light from `source_local`
    /// leaving towards `view_local` (both unit, in the BSDF's frame; the brightness of the
    /// extra colours), as [`BsdfShading::source_coefficient`] weights a source without the
    /// `aBSDF` peak's exception: what `engine::window_sun` tabulates for the sun.
    pub fn sun_radiance_factor(&self, view_local: DVec3, source_local: DVec3) -> f64 {
        let reflected = (view_local.z > 0.0) == (source_local.z > 0.0);
        let extra = match (reflected, view_local.z > 0.0) {
            (true, true) => self.extra_reflectance_front_rgb,
            (true, false) => self.extra_reflectance_back_rgb,
            (false, _) => self.extra_transmittance_rgb,
        };
        self.data.eval(view_local, source_local) + bright(extra) / PI
    }

    /// The shading of a ray along unit `d` hitting a surface of front normal `normal`; None
    /// when the up vector is parallel to the normal (RADIANCE: "Illegal orientation vector",
    /// the ray gets nothing).
    pub fn shade(&self, d: DVec3, normal: DVec3) -> Option<BsdfShading> {
        self.shade_as(d, normal, false)
    }

    /// [`BsdfMaterial::shade`] for a ray that is a view (camera) ray if `view`: at an `aBSDF`
    /// its through component is then left out of the sampled transmission.
    pub fn shade_as(&self, d: DVec3, normal: DVec3, view: bool) -> Option<BsdfShading> {
        let frame = Frame::new(normal, self.up)?;
        let hit_front = d.dot(normal) < 0.0;
        let extra_reflectance_rgb = if hit_front {
            self.extra_reflectance_front_rgb
        } else {
            self.extra_reflectance_back_rgb
        };
        let view_local = frame.to_local(-d);
        let through = if self.through {
            self.data.through(view_local)
        } else {
            None
        };
        let peak_radius_squared = match through {
            Some(_) if view => Some(
                self.data
                    .pair_projected_solid_angle(view_local, -view_local),
            ),
            _ => None,
        };
        Some(BsdfShading {
            data: self.data.clone(),
            frame,
            view_local,
            through,
            peak_radius_squared,
            pnorm: if hit_front { normal } else { -normal },
            transmitted_offset_m: -self.thickness_m * normal.normalize(),
            extra_reflectance_rgb,
            extra_transmittance_rgb: self.extra_transmittance_rgb,
        })
    }
}

/// The BSDF's frame on the surface: z the front normal, x = up × z, y = z × x (RADIANCE
/// bsdf.c `SDcompXform`).
#[derive(Clone, Copy, Debug)]
struct Frame {
    x: DVec3,
    y: DVec3,
    z: DVec3,
}

impl Frame {
    fn new(normal: DVec3, up: DVec3) -> Option<Frame> {
        let z = normal.normalize();
        let x = up.cross(z);
        if x.length_squared() <= FTINY * FTINY * up.length_squared() {
            return None;
        }
        let x = x.normalize();
        Some(Frame {
            x,
            y: z.cross(x),
            z,
        })
    }

    fn to_local(self, v: DVec3) -> DVec3 {
        DVec3::new(v.dot(self.x), v.dot(self.y), v.dot(self.z))
    }

    fn to_world(self, v: DVec3) -> DVec3 {
        self.x * v.x + self.y * v.y + self.z * v.z
    }
}

/// m_bsdf.c's `BSDFDAT` at one hit.
#[derive(Clone, Debug)]
pub struct BsdfShading {
    data: Arc<Bsdf>,
    frame: Frame,
    /// The direction back to the viewer, in the BSDF's frame (`vray`).
    view_local: DVec3,
    /// Surface normal turned towards the viewer.
    pnorm: DVec3,
    extra_reflectance_rgb: DVec3,
    extra_transmittance_rgb: DVec3,
    /// Where transmitted light is traced from, relative to the hit (zero when thin).
    transmitted_offset_m: DVec3,
    /// An `aBSDF`'s through component for this ray (None for `BSDF`).
    through: Option<Through>,
    /// For a view ray through an `aBSDF`: transmitted samples whose projection lies within
    /// √ of this of the straight continuation's are the through component's, dropped.
    peak_radius_squared: Option<f64>,
}

impl BsdfShading {
    /// The hit `p_m`, moved by the thickness when `dir` is on the far side (transmission).
    pub fn origin_towards(&self, p_m: DVec3, dir: DVec3) -> DVec3 {
        if self.pnorm.dot(dir) < 0.0 {
            p_m + self.transmitted_offset_m
        } else {
            p_m
        }
    }

    /// m_bsdf.c `dir_bsdf`: f |cos| Ω, with the extra Lambertian parts (ρ/π |cos| Ω on their
    /// side). RADIANCE traces backwards and queries `SDevalBSDF(outVec = view, inVec =
    /// source)`: the view direction is the data's first direction, as it is for sampling
    /// (`SDsampComponent` from the view), so a file whose front and back transmissions are
    /// not reciprocal answers here as in rtrace (Satine: 30 % apart).
    pub fn source_coefficient(&self, ldir: DVec3, omega_sr: f64) -> DVec3 {
        let ldot = self.pnorm.dot(ldir);
        if ldot.abs() <= FTINY {
            return DVec3::ZERO;
        }
        let l_local = self.frame.to_local(ldir);
        let f_per_sr = match &self.through {
            // The peak's light is the shadow ray's through the window: the surround instead,
            // with the data's Lambertian transmission.
            Some(t) if t.covers(self.view_local, l_local, omega_sr) => {
                let l = &self.data.lambertian;
                let lambertian = if self.view_local.z > 0.0 {
                    l.transmittance_front
                } else {
                    l.transmittance_back
                };
                t.surround_per_sr + lambertian / PI
            }
            _ => self.data.eval(self.view_local, l_local),
        };
        let extra = if ldot > 0.0 {
            self.extra_reflectance_rgb
        } else {
            self.extra_transmittance_rgb
        };
        (DVec3::splat(f_per_sr) + extra / PI) * (ldot.abs() * omega_sr)
    }

    /// The continuation: the file's lobes by its own distribution, or an extra Lambertian
    /// lobe, each chosen in proportion to its hemispherical value and weighted by the inverse
    /// of that choice (one-sample lobe selection). Lambertian lobes are diffuse bounces,
    /// taken only if `allow_diffuse`; directional parts are specular events.
    pub fn sample(&self, allow_diffuse: bool, rng: &mut Rng) -> Scatter {
        let distribution = self.data.distribution(self.view_local);
        let data_total = distribution.total().max(0.0);
        let (extra_r, extra_t) = if allow_diffuse {
            (
                bright(self.extra_reflectance_rgb),
                bright(self.extra_transmittance_rgb),
            )
        } else {
            (0.0, 0.0)
        };
        let total = data_total + extra_r + extra_t;
        if total.partial_cmp(&FTINY) != Some(std::cmp::Ordering::Greater) {
            return Scatter::Absorbed;
        }
        let u = [rng.uniform(), rng.uniform(), rng.uniform()];
        let pick = rng.uniform() * total;
        if pick < data_total {
            return self.sample_data(&distribution, total / data_total, allow_diffuse, u);
        }
        let (rgb, side, probability) = if pick < data_total + extra_r {
            (self.extra_reflectance_rgb, self.pnorm, extra_r / total)
        } else {
            (self.extra_transmittance_rgb, -self.pnorm, extra_t / total)
        };
        Scatter::Diffuse {
            direction: cosine_direction(side, rng),
            weight: rgb / probability,
        }
    }

    /// One direction from the file's distribution, weighted by `1 / probability of choosing
    /// the file` (`inverse_choice`).
    fn sample_data(
        &self,
        distribution: &crate::bsdf::OutgoingDistribution<'_>,
        inverse_choice: f64,
        allow_diffuse: bool,
        u: [f64; 3],
    ) -> Scatter {
        let Some(s) = distribution.sample(u) else {
            return Scatter::Absorbed;
        };
        if (s.lambertian && !allow_diffuse)
            || s.lobe_pdf_per_sr.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater)
        {
            return Scatter::Absorbed;
        }
        let weight = DVec3::splat(
            s.lobe_value_per_sr * s.direction.z.abs() / s.lobe_pdf_per_sr * inverse_choice,
        );
        if let Some(r2) = self.peak_radius_squared {
            let (dx, dy) = (
                s.direction.x + self.view_local.x,
                s.direction.y + self.view_local.y,
            );
            let transmitted = (s.direction.z > 0.0) != (self.view_local.z > 0.0);
            if transmitted && !s.lambertian && dx * dx + dy * dy <= r2 {
                return Scatter::Absorbed;
            }
        }
        let direction = self.frame.to_world(s.direction).normalize();
        if s.lambertian {
            Scatter::Diffuse { direction, weight }
        } else {
            Scatter::Specular { direction, weight }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsdf::Scattering;

    fn satine(extra_reflectance_front: f64) -> BsdfMaterial {
        let xml = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../../shared/data/radiance-corpus/bsdf/frads/2011-SA1.xml");
        let data = Bsdf::load(&xml).expect("the corpus's Satine XML (shared/data)");
        let args = BsdfModifier {
            kind: BsdfType::Bsdf,
            thickness_m: 0.0,
            xml_name: "2011-SA1.xml".into(),
            xml_path: xml,
            up: DVec3::Z,
            extra_reflectance_front_rgb: DVec3::splat(extra_reflectance_front),
            extra_reflectance_back_rgb: DVec3::ZERO,
            extra_transmittance_rgb: DVec3::ZERO,
        };
        BsdfMaterial::new(&args, Arc::new(data))
    }

    /// Satine as an `aBSDF`.
    fn satine_absdf() -> BsdfMaterial {
        let mut m = satine(0.0);
        m.through = true;
        m
    }

    /// An `aBSDF` view ray's sampled continuation leaves the through component out: its
    /// weights average to R + T less the through transmittance (the straight ray carries that),
    /// while any other ray's average to R + T; shadow rays towards sources keep the through
    /// transmittance.
    #[test]
    fn a_view_ray_samples_all_but_the_through_component() {
        let m = satine_absdf();
        let normal = DVec3::new(0.0, 1.0, 0.0);
        let d = DVec3::new(0.2, -0.95, -0.1).normalize();
        let mean_weight = |view: bool| {
            let s = m.shade_as(d, normal, view).unwrap();
            let mut rng = Rng::for_stream(5, u64::from(view));
            let n = 400_000;
            let mut sum = 0.0;
            for _ in 0..n {
                if let Scatter::Diffuse { weight, .. } | Scatter::Specular { weight, .. } =
                    s.sample(true, &mut rng)
                {
                    sum += weight.x;
                }
            }
            sum / n as f64
        };
        let s = m.shade(d, normal).unwrap();
        let r = m.data.hemispherical(s.view_local, Scattering::Reflection);
        let t = m.data.hemispherical(s.view_local, Scattering::Transmission);
        let through = m.through_transmittance(d, normal);
        assert!(through > 0.01, "Satine's openness: {through}");
        let (all, view) = (mean_weight(false), mean_weight(true));
        assert!((all - (r + t)).abs() < 0.005, "{all} vs R + T {}", r + t);
        assert!(
            (view - (r + t - through)).abs() < 0.005,
            "{view} vs R + T - through {}",
            r + t - through
        );
        assert_eq!(satine(0.0).through_transmittance(d, normal), 0.0);
    }

    /// The sampled continuation's weights average to the data's R + T for the view direction
    /// (RADIANCE `SDdirectHemi`), plus the extra reflectance: the lobe selection is unbiased.
    #[test]
    fn sampling_weights_average_to_the_hemispherical_values() {
        let m = satine(0.1);
        let normal = DVec3::new(0.0, 1.0, 0.0);
        let d = DVec3::new(0.3, -0.8, -0.2).normalize();
        let s = m.shade(d, normal).unwrap();
        let r = m.data.hemispherical(s.view_local, Scattering::Reflection);
        let t = m.data.hemispherical(s.view_local, Scattering::Transmission);
        let mut rng = Rng::for_stream(3, 0);
        let n = 200_000;
        let mut sum = DVec3::ZERO;
        for _ in 0..n {
            if let Scatter::Diffuse { weight, .. } | Scatter::Specular { weight, .. } =
                s.sample(true, &mut rng)
            {
                sum += weight;
            }
        }
        let mean = sum.x / n as f64;
        let expect = r + t + 0.1;
        assert!(
            (mean - expect).abs() < 0.005,
            "{mean} vs {expect} (R {r}, T {t})"
        );
    }

    /// Integrated over all source directions, the direct coefficient is the data's R + T for
    /// the view (reciprocity of the whole, f queried view first as RADIANCE does).
    #[test]
    fn source_coefficients_integrate_to_the_hemispherical_values() {
        let m = satine(0.0);
        let normal = DVec3::new(0.0, 1.0, 0.0);
        let d = DVec3::new(-0.2, -0.9, 0.1).normalize();
        let s = m.shade(d, normal).unwrap();
        let expect = m.data.hemispherical(s.view_local, Scattering::Reflection)
            + m.data.hemispherical(s.view_local, Scattering::Transmission);
        // Uniform directions on the sphere, weight 4π.
        let mut rng = Rng::for_stream(9, 0);
        let n = 400_000;
        let mut sum = 0.0;
        for _ in 0..n {
            let z = 2.0 * rng.uniform() - 1.0;
            let phi = 2.0 * PI * rng.uniform();
            let r = (1.0 - z * z).sqrt();
            let l = DVec3::new(r * phi.cos(), r * phi.sin(), z);
            sum += s.source_coefficient(l, 1.0).x * 4.0 * PI;
        }
        let mean = sum / n as f64;
        assert!((mean - expect).abs() < 0.01, "{mean} vs {expect}");
    }

    /// SDcompXform on a wall facing -y with up +z: right-handed, y along up, invertible.
    #[test]
    fn frame_is_right_handed_and_up_projects_on_y() {
        let f = Frame::new(DVec3::new(0.0, -1.0, 0.0), DVec3::Z).unwrap();
        assert!((f.x.cross(f.y) - f.z).length() < 1e-12);
        assert!((f.y - DVec3::Z).length() < 1e-12, "{:?}", f.y);
        let v = DVec3::new(0.3, -0.5, 0.8).normalize();
        assert!((f.to_world(f.to_local(v)) - v).length() < 1e-12);
        assert!(Frame::new(DVec3::Z, DVec3::Z).is_none());
    }
}
