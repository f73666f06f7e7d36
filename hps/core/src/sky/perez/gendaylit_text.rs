//! The Perez sky written as RADIANCE scene text, line for line and number for number as
//! `gendaylit` writes it.

use super::{GendaylitUnits, PerezSky, GENDAYLIT_HALF_SUN_ANGLE_DEG};
use std::fmt::Write as _;

impl PerezSky {
    /// The sky description gendaylit writes on stdout for these inputs in `units`, after its
    /// first line (the command line echoed as a comment): the same lines and number formats,
    /// sun as `light`/`source`, sky as `brightfunc skyfunc` over `perezlum.cal`.
    pub fn gendaylit_text(&self, units: GendaylitUnits) -> String {
        self.gendaylit_text_with(units, true)
    }

    /// [`Self::gendaylit_text`], or without the sun and its share of the ground as
    /// `gendaylit -s` writes it (`with_sun` false).
    pub fn gendaylit_text_with(&self, units: GendaylitUnits, with_sun: bool) -> String {
        let mut out = String::new();
        let st = self.local_solar_time_h.unwrap_or(0.0);
        let azimuth_deg = (-self.sun_direction.x)
            .atan2(-self.sun_direction.y)
            .to_degrees();
        let _ = writeln!(out, "# Local solar time: {st:.2}");
        let _ = writeln!(
            out,
            "# Solar altitude and azimuth: {:.1} {:.1}",
            self.altitude_rad.to_degrees(),
            azimuth_deg
        );
        let s = self.sun_direction;
        if self.error_sky(units).is_some() {
            let _ = write!(
                out,
                "\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n\
                 10 0.00 0.00  0.000 0.000 0.000 0.000 0.000  {:.6} {:.6} {:.6} \n",
                s.x, s.y, s.z
            );
            return out;
        }
        let _ = writeln!(
            out,
            "# epsilon, delta, atmospheric precipitable water content : {:.4} {:.4} {:.4} ",
            self.clearness, self.brightness, self.precipitable_water_cm
        );
        let (normalisation, sun, ground) = self.radiometry_with(units, with_sun);
        let sun_text = if self.clearness > 1.0 {
            let r = c_exp(sun, 3);
            format!("{r} {r} {r}")
        } else {
            "0.0 0.0 0.0".to_string()
        };
        if with_sun {
            let _ = write!(
                out,
                "\nvoid light solar\n0\n0\n3 {sun_text}\n\nsolar source sun\n0\n0\n\
                 4 {:.6} {:.6} {:.6} {:.6}\n",
                s.x,
                s.y,
                s.z,
                2.0 * GENDAYLIT_HALF_SUN_ANGLE_DEG
            );
        }
        let [a, b, c, d, e] = self.coefficients;
        let _ = write!(
            out,
            "\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n\
             10 {} {} {a:.6} {b:.6} {c:.6} {d:.6} {e:.6} {:.6} {:.6} {:.6} \n",
            c_exp(normalisation, 3),
            c_exp(ground, 3),
            s.x,
            s.y,
            s.z
        );
        out
    }

    /// A complete RADIANCE sky in the default units: [`Self::gendaylit_text`] with the
    /// conventional glows that make `skyfunc` visible, the sky over the upper hemisphere and
    /// the ground (brightness A2, set by the ground reflectance) over the lower one.
    pub fn radiance_sky(&self) -> String {
        let mut out = self.gendaylit_text(GendaylitUnits::VisibleRadiance);
        out.push_str(
            "\nskyfunc glow sky_glow\n0\n0\n4 1 1 1 0\n\nsky_glow source sky\n0\n0\n4 0 0 1 180\n\
             \nskyfunc glow ground_glow\n0\n0\n4 1 1 1 0\n\n\
             ground_glow source ground\n0\n0\n4 0 0 -1 180\n",
        );
        out
    }
}

/// C's `%.{precision}e`: mantissa, `e`, sign and at least two exponent digits.
pub fn c_exp(value: f64, precision: usize) -> String {
    let text = format!("{value:.precision$e}");
    match text.split_once('e') {
        Some((mantissa, exponent)) => {
            let (sign, digits) = match exponent.strip_prefix('-') {
                Some(d) => ('-', d),
                None => ('+', exponent),
            };
            format!("{mantissa}e{sign}{digits:0>2}")
        }
        None => text, // inf, NaN
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn c_exponent_format() {
        assert_eq!(c_exp(4.872e6, 3), "4.872e+06");
        assert_eq!(c_exp(3.992e1, 3), "3.992e+01");
        assert_eq!(c_exp(0.0012345, 3), "1.234e-03");
        assert_eq!(c_exp(0.0, 3), "0.000e+00");
        assert_eq!(c_exp(1e123, 2), "1.00e+123");
    }
}
