//! The ray a `.cal` expression sees at a hit: RADIANCE's `chanvalue` (`src/rt/func.c`), with
//! the hit expressed in the function's own frame through the inverse of the modifier's
//! transform (`funcxf`).

use crate::cal::{CalContext, RayVariable};
use crate::scene::FunctionTransform;
use glam::DVec3;

/// What `BRTDfunc` adds for its expressions (`m_brdf.c` `setbrdfunc`): the perturbed normal
/// turned towards the ray, its cosine with the ray, and the pattern colour.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Perturbed {
    pub normal: DVec3,
    pub cos_incidence: f64,
    pub color_rgb: DVec3,
}

/// One hit as a function sees it.
#[derive(Clone, Copy, Debug)]
pub struct FunctionRay<'a> {
    /// Unit ray direction (towards the surface).
    pub direction: DVec3,
    /// The surface's own normal (not turned towards the ray).
    pub normal: DVec3,
    pub point_m: DVec3,
    /// Distance along this ray to the hit.
    pub distance_m: f64,
    pub perturbed: Option<Perturbed>,
    pub transform: &'a FunctionTransform,
    pub real_args: &'a [f64],
}

/// `v` (a row vector) times the upper 3x3 of `m`.
fn times(m: &[[f64; 4]; 4], v: DVec3) -> DVec3 {
    DVec3::new(
        v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0],
        v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
        v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2],
    )
}

impl FunctionRay<'_> {
    /// RADIANCE's `funcxf.sca`: the scale of the inverse transform.
    fn inverse_scale(&self) -> f64 {
        1.0 / self.transform.scale
    }

    /// A direction in the function's frame, unit length kept (`/ funcxf.sca`).
    pub fn local_direction(&self, v: DVec3) -> DVec3 {
        times(&self.transform.inverse, v) / self.inverse_scale()
    }

    fn local_point(&self) -> DVec3 {
        let m = &self.transform.inverse;
        times(m, self.point_m) + DVec3::new(m[3][0], m[3][1], m[3][2])
    }
}

impl CalContext for FunctionRay<'_> {
    fn ray_variable(&self, variable: RayVariable) -> f64 {
        use RayVariable as V;
        let m = &self.transform.inverse;
        let s = self.inverse_scale();
        let pick = |v: DVec3, axis: usize| v[axis];
        let perturbed = self.perturbed.unwrap_or(Perturbed {
            normal: self.normal,
            cos_incidence: -self.direction.dot(self.normal),
            color_rgb: DVec3::ONE,
        });
        match variable {
            V::Dx | V::Dy | V::Dz => pick(self.local_direction(self.direction), axis(variable)),
            V::Nx | V::Ny | V::Nz => pick(self.local_direction(self.normal), axis(variable)),
            V::Px | V::Py | V::Pz => pick(self.local_point(), axis(variable)),
            // Distance from this ray's origin (RADIANCE: from the primary ray's origin).
            V::T | V::Ts => self.distance_m * s,
            V::Rdot => (-self.direction.dot(self.normal)).clamp(-1.0, 1.0),
            V::S => s,
            V::Tx | V::Ty | V::Tz => m[3][axis(variable)],
            V::Ix | V::Iy | V::Iz => m[0][axis(variable)] / s,
            V::Jx | V::Jy | V::Jz => m[1][axis(variable)] / s,
            V::Kx | V::Ky | V::Kz => m[2][axis(variable)] / s,
            // Mesh coordinates: no meshes are traced.
            V::Lu | V::Lv => 0.0,
            V::NxP | V::NyP | V::NzP => {
                pick(self.local_direction(perturbed.normal), axis(variable))
            }
            V::RdotP => perturbed.cos_incidence.clamp(-1.0, 1.0),
            V::CrP => perturbed.color_rgb.x,
            V::CgP => perturbed.color_rgb.y,
            V::CbP => perturbed.color_rgb.z,
        }
    }

    fn real_arguments(&self) -> &[f64] {
        self.real_args
    }
}

/// 0, 1 or 2: the axis a ray variable names.
fn axis(variable: RayVariable) -> usize {
    use RayVariable as V;
    match variable {
        V::Dx | V::Nx | V::Px | V::Tx | V::Ix | V::Jx | V::Kx | V::NxP => 0,
        V::Dy | V::Ny | V::Py | V::Ty | V::Iy | V::Jy | V::Ky | V::NyP => 1,
        _ => 2,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A modifier moved by `-t 1 2 3 -s 2`: the function sees the hit moved back and scaled
    /// down, directions unchanged, `S` = 1/2 (func.c `chanvalue` with `invxf`).
    #[test]
    fn the_hit_is_seen_in_the_function_frame() {
        let words: Vec<String> = ["-s", "2", "-t", "1", "2", "3"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let scene = crate::scene::parse(
            "t.rad",
            format!("void colorfunc c 10 r g b . {}\n0\n0\n", words.join(" ")).as_bytes(),
        )
        .unwrap();
        let crate::scene::ModifierKind::Colorfunc(f) = &scene.modifiers()[0].kind else {
            panic!("a colorfunc")
        };
        let ray = FunctionRay {
            direction: DVec3::new(0.0, 0.6, -0.8),
            normal: DVec3::Z,
            point_m: DVec3::new(3.0, 4.0, 5.0),
            distance_m: 4.0,
            perturbed: None,
            transform: &f.transform,
            real_args: &[],
        };
        let v = |x| ray.ray_variable(x);
        assert!((v(RayVariable::Px) - 1.0).abs() < 1e-12);
        assert!((v(RayVariable::Py) - 1.0).abs() < 1e-12);
        assert!((v(RayVariable::Pz) - 1.0).abs() < 1e-12);
        assert!((v(RayVariable::Dy) - 0.6).abs() < 1e-12);
        assert!((v(RayVariable::S) - 0.5).abs() < 1e-12);
        assert!((v(RayVariable::T) - 2.0).abs() < 1e-12);
        assert!((v(RayVariable::Rdot) - 0.8).abs() < 1e-12);
    }
}
