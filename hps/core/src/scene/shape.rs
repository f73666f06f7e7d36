//! Surfaces: the geometry rays hit, in metres in the world frame (+x east, +y north, +z up).
//!
//! Argument meanings are those of the RADIANCE reference manual (ray.html), §2.1.1
//! "Surfaces". Validation follows RADIANCE's own checks (src/common/cone.c, face.c), except
//! that what RADIANCE only warns about and then drops or silently inverts is an error here:
//! a scene that loads is a scene the engine traces as written.

use super::error::{ArgumentList, SceneError};
use super::parse::{PrimitiveType, RawPrimitive};
use glam::DVec3;

/// Smallest length or radius treated as non-zero, in metres: RADIANCE's `FTINY` (fvect.h).
pub const MIN_LENGTH_M: f64 = 1e-6;

/// Relative tolerances for degenerate polygons, against the polygon's extent: only vertices
/// collinear to rounding error, or an area that cancels to rounding error, are rejected, so
/// thin but real slivers from `obj2rad` meshes still load (RADIANCE itself only rejects an
/// area of exactly zero).
const COLLINEAR_TOLERANCE: f64 = 1e-10;
const ZERO_AREA_TOLERANCE: f64 = 1e-12;

/// The geometry of a surface.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    Polygon(Polygon),
    Sphere(Sphere),
    Cylinder(Cylinder),
    Cone(Cone),
    Ring(Ring),
    Source(DistantSource),
    /// `bubble`: a sphere whose normal points in (manual §2.1.1, "Bubble").
    Bubble(Sphere),
    /// `tube`: a cylinder whose normal points in (manual §2.1.1, "Tube").
    Tube(Cylinder),
    /// `cup`: a cone whose normal points in (manual §2.1.1, "Cup").
    Cup(Cone),
}

impl Shape {
    /// The RADIANCE type name (`polygon`, `source`, ...).
    pub fn type_name(&self) -> &'static str {
        match self {
            Shape::Polygon(_) => "polygon",
            Shape::Sphere(_) => "sphere",
            Shape::Cylinder(_) => "cylinder",
            Shape::Cone(_) => "cone",
            Shape::Ring(_) => "ring",
            Shape::Source(_) => "source",
            Shape::Bubble(_) => "bubble",
            Shape::Tube(_) => "tube",
            Shape::Cup(_) => "cup",
        }
    }
}

/// `polygon`: a planar polygon, vertices counter-clockwise seen from the front, the last one
/// joined to the first; holes are seams of coincident edges (manual §2.1.1, "Polygon").
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    /// The vertices as given, at least three.
    pub vertices_m: Vec<DVec3>,
    /// Unit front normal (right-hand rule over the vertex order, Newell's method).
    pub normal: DVec3,
    /// Area in m² (of the projection on the plane of `normal`).
    pub area_m2: f64,
}

/// `sphere`: given by centre and radius, normal pointing out (manual §2.1.1, "Sphere").
#[derive(Clone, Debug, PartialEq)]
pub struct Sphere {
    pub centre_m: DVec3,
    pub radius_m: f64,
}

/// `cylinder`: open tube between two axis end points, normal pointing out (manual §2.1.1,
/// "Cylinder"); the end caps are separate `ring`s if wanted.
#[derive(Clone, Debug, PartialEq)]
pub struct Cylinder {
    pub start_m: DVec3,
    pub end_m: DVec3,
    pub radius_m: f64,
}

/// `cone`: truncated cone between two axis end points; one radius may be zero, and equal
/// radii make it a cylinder (manual §2.1.1, "Cone").
#[derive(Clone, Debug, PartialEq)]
pub struct Cone {
    pub start_m: DVec3,
    pub end_m: DVec3,
    pub start_radius_m: f64,
    pub end_radius_m: f64,
}

/// `ring`: flat annulus (a disc when the inner radius is zero) (manual §2.1.1, "Ring").
/// As RADIANCE does (cone.c), radii given in decreasing order are swapped.
#[derive(Clone, Debug, PartialEq)]
pub struct Ring {
    pub centre_m: DVec3,
    /// Unit normal, the front side.
    pub normal: DVec3,
    pub inner_radius_m: f64,
    pub outer_radius_m: f64,
}

/// `source`: a disc at infinity seen under a given angle, used for the sun and for the sky
/// and ground hemispheres of gensky (manual §2.1.1, "Source").
#[derive(Clone, Debug, PartialEq)]
pub struct DistantSource {
    /// Unit direction from the scene towards the centre of the source.
    pub direction: DVec3,
    /// Full angle the source's disc subtends, in degrees (0.5 for the sun, 180 for a
    /// hemisphere, 360 for the whole sphere).
    pub angle_deg: f64,
}

impl DistantSource {
    /// Solid angle of the source: 2π(1 − cos(angle/2)).
    pub fn solid_angle_sr(&self) -> f64 {
        2.0 * std::f64::consts::PI * (1.0 - (0.5 * self.angle_deg.to_radians()).cos())
    }
}

/// `v` scaled to unit length, or `None` if it is zero (or overflows). Scaling by the largest
/// component first keeps `length()` from overflowing for huge but finite inputs.
pub(crate) fn unit_vector(v: DVec3) -> Option<DVec3> {
    let largest = v.abs().max_element();
    if !(largest > 0.0 && largest.is_finite()) {
        return None;
    }
    let scaled = v / largest;
    Some(scaled / scaled.length())
}

/// Interprets a surface primitive.
pub(crate) fn build(raw: &RawPrimitive<'_>) -> Result<Shape, SceneError> {
    raw.check_no_strings_or_integers()?;
    let r = &raw.reals;
    let point = |i: usize| DVec3::new(r[i], r[i + 1], r[i + 2]);
    Ok(match raw.kind {
        PrimitiveType::Polygon => Shape::Polygon(polygon(raw)?),
        PrimitiveType::Sphere => Shape::Sphere(sphere(raw)?),
        PrimitiveType::Bubble => Shape::Bubble(sphere(raw)?),
        PrimitiveType::Cylinder => Shape::Cylinder(cylinder(raw)?),
        PrimitiveType::Tube => Shape::Tube(cylinder(raw)?),
        PrimitiveType::Cone => Shape::Cone(cone(raw)?),
        PrimitiveType::Cup => Shape::Cup(cone(raw)?),
        PrimitiveType::Ring => {
            raw.check_real_count()?;
            let normal = unit_vector(point(3)).ok_or_else(|| {
                raw.invalid(
                    "normal (real arguments 4-6, xdir ydir zdir)",
                    format!("({} {} {})", r[3], r[4], r[5]),
                    "a non-zero direction",
                )
            })?;
            for i in [6, 7] {
                if r[i] < 0.0 {
                    return Err(raw.invalid_real(i, "a radius >= 0"));
                }
            }
            let (inner, outer) = if r[6] <= r[7] {
                (r[6], r[7])
            } else {
                (r[7], r[6])
            };
            if outer - inner < MIN_LENGTH_M {
                return Err(raw.invalid(
                    "radii r0 r1",
                    format!("{} {}", r[6], r[7]),
                    format!("an inner and an outer radius at least {MIN_LENGTH_M} m apart"),
                ));
            }
            Shape::Ring(Ring {
                centre_m: point(0),
                normal,
                inner_radius_m: inner,
                outer_radius_m: outer,
            })
        }
        PrimitiveType::Source => {
            raw.check_real_count()?;
            let direction = unit_vector(point(0)).ok_or_else(|| {
                raw.invalid(
                    "direction (real arguments 1-3, xdir ydir zdir)",
                    format!("({} {} {})", r[0], r[1], r[2]),
                    "a non-zero direction",
                )
            })?;
            if !(r[3] > 0.0 && r[3] <= 360.0) {
                return Err(raw.invalid_real(3, "an angle in degrees, > 0 and <= 360"));
            }
            Shape::Source(DistantSource {
                direction,
                angle_deg: r[3],
            })
        }
        PrimitiveType::Plastic
        | PrimitiveType::Metal
        | PrimitiveType::Trans
        | PrimitiveType::Glass
        | PrimitiveType::Mirror
        | PrimitiveType::Light
        | PrimitiveType::Glow
        | PrimitiveType::Brightfunc
        | PrimitiveType::Bsdf
        | PrimitiveType::ABsdf
        | PrimitiveType::Dielectric
        | PrimitiveType::Interface
        | PrimitiveType::Spotlight
        | PrimitiveType::Illum
        | PrimitiveType::Antimatter
        | PrimitiveType::Colorfunc
        | PrimitiveType::Brightdata
        | PrimitiveType::Colordata
        | PrimitiveType::Colorpict
        | PrimitiveType::Texfunc
        | PrimitiveType::Mixfunc
        | PrimitiveType::Texdata
        | PrimitiveType::Mixdata
        | PrimitiveType::Mixpict
        | PrimitiveType::Brighttext
        | PrimitiveType::Colortext
        | PrimitiveType::Mixtext
        | PrimitiveType::BrtdFunc
        | PrimitiveType::Plasfunc
        | PrimitiveType::Metfunc
        | PrimitiveType::Transfunc
        | PrimitiveType::Plasdata
        | PrimitiveType::Metdata
        | PrimitiveType::Transdata
        | PrimitiveType::Plastic2
        | PrimitiveType::Metal2
        | PrimitiveType::Trans2 => {
            return Err(raw.invalid(
                "type",
                raw.kind.name(),
                "a surface (internal: modifier passed to the surface reader)",
            ))
        }
    })
}

/// `sphere` or `bubble`: centre and radius. A negative radius is refused rather than
/// silently turned inside out, as RADIANCE does (sphere.c): the inward form is `bubble`.
fn sphere(raw: &RawPrimitive<'_>) -> Result<Sphere, SceneError> {
    raw.check_real_count()?;
    positive_radius(
        raw,
        3,
        "; an inward-facing sphere is written `bubble` with a positive radius",
    )?;
    let r = &raw.reals;
    Ok(Sphere {
        centre_m: DVec3::new(r[0], r[1], r[2]),
        radius_m: r[3],
    })
}

/// `cylinder` or `tube`: axis end points and radius.
fn cylinder(raw: &RawPrimitive<'_>) -> Result<Cylinder, SceneError> {
    raw.check_real_count()?;
    positive_radius(
        raw,
        6,
        "; an inward-facing cylinder is written `tube` with a positive radius",
    )?;
    let r = &raw.reals;
    let (start_m, end_m) = (DVec3::new(r[0], r[1], r[2]), DVec3::new(r[3], r[4], r[5]));
    axis_length(raw, start_m, end_m)?;
    Ok(Cylinder {
        start_m,
        end_m,
        radius_m: r[6],
    })
}

/// `cone` or `cup`: axis end points and the two radii, one of which may be zero.
fn cone(raw: &RawPrimitive<'_>) -> Result<Cone, SceneError> {
    raw.check_real_count()?;
    let r = &raw.reals;
    for i in [6, 7] {
        if r[i] < 0.0 {
            return Err(raw.invalid_real(
                i,
                "a radius >= 0; an inward-facing cone is written `cup` with positive radii",
            ));
        }
    }
    if r[6] < MIN_LENGTH_M && r[7] < MIN_LENGTH_M {
        return Err(raw.invalid(
            "radii r0 r1",
            format!("{} {}", r[6], r[7]),
            format!("at least one radius >= {MIN_LENGTH_M} m"),
        ));
    }
    let (start_m, end_m) = (DVec3::new(r[0], r[1], r[2]), DVec3::new(r[3], r[4], r[5]));
    axis_length(raw, start_m, end_m)?;
    Ok(Cone {
        start_m,
        end_m,
        start_radius_m: r[6],
        end_radius_m: r[7],
    })
}

fn positive_radius(
    raw: &RawPrimitive<'_>,
    index: usize,
    inverted_hint: &str,
) -> Result<(), SceneError> {
    let radius = raw.reals[index];
    if radius < 0.0 {
        Err(raw.invalid_real(index, format!("a radius > 0{inverted_hint}")))
    } else if radius < MIN_LENGTH_M {
        Err(raw.invalid_real(index, format!("a radius >= {MIN_LENGTH_M} m")))
    } else {
        Ok(())
    }
}

fn axis_length(raw: &RawPrimitive<'_>, start: DVec3, end: DVec3) -> Result<(), SceneError> {
    let length = (end - start).length();
    if length >= MIN_LENGTH_M && length.is_finite() {
        return Ok(());
    }
    Err(raw.invalid(
        "axis (real arguments 1-6, x0 y0 z0 x1 y1 z1)",
        format!("from {start} to {end}, length {length} m"),
        format!("end points between {MIN_LENGTH_M} m and a finite distance apart"),
    ))
}

fn polygon(raw: &RawPrimitive<'_>) -> Result<Polygon, SceneError> {
    let count = raw.reals.len();
    let coordinates = raw.reals.chunks_exact(3);
    raw.check_count(
        ArgumentList::Real,
        coordinates.remainder().is_empty(),
        "a multiple of 3 (x y z of each vertex)",
    )?;
    let degenerate = |reason: String| SceneError::DegeneratePolygon {
        at: raw.at.clone(),
        primitive: raw.describe(),
        reason,
    };
    let vertices_m: Vec<DVec3> = coordinates.map(|c| DVec3::new(c[0], c[1], c[2])).collect();
    let n = vertices_m.len();
    if n < 3 {
        return Err(degenerate(format!(
            "{n} vertices ({count} real arguments), fewer than 3"
        )));
    }
    // Work relative to the first vertex and in units of the polygon's extent, so that the
    // tolerances are scale-free and far-from-origin coordinates keep their precision.
    let origin = vertices_m[0];
    let (far_index, extent) = vertices_m
        .iter()
        .enumerate()
        .map(|(i, v)| (i, (*v - origin).length()))
        .fold(
            (0, 0.0_f64),
            |best, cur| if cur.1 > best.1 { cur } else { best },
        );
    if !extent.is_finite() {
        return Err(raw.invalid(
            "vertices",
            format!("spread over {extent} m"),
            "coordinates whose differences are finite",
        ));
    }
    if extent == 0.0 {
        return Err(degenerate(format!("all {n} vertices coincide")));
    }
    let relative: Vec<DVec3> = vertices_m.iter().map(|v| (*v - origin) / extent).collect();
    let axis = relative[far_index];
    let off_axis = relative
        .iter()
        .map(|w| (*w - axis * w.dot(axis)).length())
        .fold(0.0_f64, f64::max);
    if off_axis <= COLLINEAR_TOLERANCE {
        return Err(degenerate(format!("its {n} vertices are collinear")));
    }
    // Newell's method: twice the vector area, pointing along the right-hand normal.
    let mut twice_area = DVec3::ZERO;
    for (i, a) in relative.iter().enumerate() {
        let b = relative[(i + 1) % n];
        twice_area += a.cross(b);
    }
    let relative_area = 0.5 * twice_area.length();
    if relative_area <= ZERO_AREA_TOLERANCE {
        return Err(degenerate(format!(
            "its {n} vertices enclose zero area (the outline folds back on itself)"
        )));
    }
    Ok(Polygon {
        vertices_m,
        normal: twice_area / twice_area.length(),
        area_m2: relative_area * extent * extent,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::lexer::Lexer;
    use crate::scene::parse::{read_item, Item, RawPrimitive};
    use std::path::Path;
    use std::sync::Arc;

    fn shape(text: &str) -> Result<Shape, SceneError> {
        let mut lexer = Lexer::new(Arc::from(Path::new("s.rad")), text);
        let Some(Item::Primitive(p)) = read_item(&mut lexer).unwrap() else {
            panic!("no primitive in {text}")
        };
        build(&RawPrimitive::from_primitive(&p)?)
    }

    #[test]
    fn polygon_normal_and_area_follow_the_vertex_order() {
        let Shape::Polygon(p) = shape("m polygon f 0 0 12 0 0 0 2 0 0 2 3 0 0 3 0").unwrap() else {
            panic!("not a polygon")
        };
        assert_eq!(p.normal, DVec3::Z);
        assert!((p.area_m2 - 6.0).abs() < 1e-12);
        let Shape::Polygon(q) = shape("m polygon f 0 0 12 0 0 0 0 3 0 2 3 0 2 0 0").unwrap() else {
            panic!("not a polygon")
        };
        assert_eq!(q.normal, -DVec3::Z);
    }

    #[test]
    fn far_from_origin_polygon_keeps_its_area() {
        let Shape::Polygon(p) =
            shape("m polygon f 0 0 9 1e7 1e7 0 1e7 1e7 1 1e7 1.0000001e7 0").unwrap()
        else {
            panic!("not a polygon")
        };
        assert!((p.area_m2 - 0.5).abs() < 1e-6, "{}", p.area_m2);
    }

    #[test]
    fn degenerate_polygons_are_refused() {
        for (text, reason) in [
            ("m polygon f 0 0 6 0 0 0 1 0 0", "2 vertices"),
            ("m polygon f 0 0 9 1 1 1 1 1 1 1 1 1", "coincide"),
            ("m polygon f 0 0 9 0 0 0 1 1 1 3 3 3", "collinear"),
            (
                "m polygon f 0 0 9 0 0 0 0.1 0.2 0.3 0.3 0.6 0.9",
                "collinear",
            ),
            // Out and back along the same edges.
            ("m polygon f 0 0 12 0 0 0 1 0 0 1 1 0 1 0 0", "zero area"),
            // A bow tie: two opposite triangles whose areas cancel.
            ("m polygon f 0 0 12 0 0 0 1 1 0 1 0 0 0 1 0", "zero area"),
        ] {
            let err = shape(text).unwrap_err();
            assert!(
                matches!(err, SceneError::DegeneratePolygon { .. })
                    && err.to_string().contains(reason),
                "{text}: {err}"
            );
        }
    }

    #[test]
    fn thin_sliver_is_a_valid_polygon() {
        let Shape::Polygon(p) = shape("m polygon f 0 0 9 0 0 0 1 0.333333 0 3 1 0").unwrap() else {
            panic!("not a polygon")
        };
        assert!(p.area_m2 > 0.0 && p.area_m2 < 1e-5);
    }

    #[test]
    fn ring_radii_are_put_in_order_and_normal_normalised() {
        let Shape::Ring(r) = shape("m ring r 0 0 8 0 0 1 0 0 5 2 0.5").unwrap() else {
            panic!("not a ring")
        };
        assert_eq!((r.inner_radius_m, r.outer_radius_m), (0.5, 2.0));
        assert_eq!(r.normal, DVec3::Z);
    }

    #[test]
    fn radii_and_axes_are_checked() {
        for (text, field) in [
            ("m sphere s 0 0 4 0 0 0 -1", "(radius)"),
            ("m sphere s 0 0 4 0 0 0 0", "(radius)"),
            ("m cylinder c 0 0 7 0 0 0 0 0 1 -0.1", "(rad)"),
            ("m cylinder c 0 0 7 1 2 3 1 2 3 0.1", "axis"),
            ("m cone c 0 0 8 0 0 0 0 0 1 0.1 -0.1", "(r1)"),
            ("m cone c 0 0 8 0 0 0 0 0 1 0 0", "radii"),
            ("m cone c 0 0 8 0 0 0 0 0 0 0.1 0.2", "axis"),
            ("m ring r 0 0 8 0 0 0 0 0 0 0 1", "normal"),
            ("m ring r 0 0 8 0 0 0 0 0 1 1 1", "radii"),
            ("m ring r 0 0 8 0 0 0 0 0 1 -1 1", "(r0)"),
            ("m source s 0 0 4 0 0 0 0.5", "direction"),
            ("m source s 0 0 4 0 0 1 0", "(angle)"),
            ("m source s 0 0 4 0 0 1 361", "(angle)"),
        ] {
            let err = shape(text).unwrap_err();
            assert!(
                matches!(err, SceneError::InvalidValue { .. }) && err.to_string().contains(field),
                "{text}: {err}"
            );
        }
    }

    #[test]
    fn huge_finite_coordinates_do_not_produce_nan() {
        let err = shape("m polygon f 0 0 9 -1e308 0 0 1e308 0 0 0 1e308 0").unwrap_err();
        assert!(err.to_string().contains("finite"), "{err}");
        let Shape::Source(s) = shape("m source s 0 0 4 1e308 1e308 0 1").unwrap() else {
            panic!("not a source")
        };
        assert!((s.direction.length() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn sun_solid_angle() {
        let sun = DistantSource {
            direction: DVec3::Z,
            angle_deg: 0.533,
        };
        assert!((sun.solid_angle_sr() - 6.8e-5).abs() < 0.1e-5);
        let hemisphere = DistantSource {
            direction: DVec3::Z,
            angle_deg: 180.0,
        };
        assert!((hemisphere.solid_angle_sr() - 2.0 * std::f64::consts::PI).abs() < 1e-12);
    }
}
