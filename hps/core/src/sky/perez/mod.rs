//! The Perez all-weather sky from measured irradiance, computed natively as RADIANCE's
//! `gendaylit` computes it, so that a sky built here and the sky `gendaylit` writes for the
//! same inputs are the same sky (`tests/perez_vs_gendaylit.rs`).
//!
//! The model: Perez, Seals & Michalsky, "All-weather model for sky luminance distribution:
//! preliminary configuration and validation", Solar Energy 50(3):235–245, 1993 (erratum
//! 51(5):423), with the luminous efficacies of Perez et al., "Modeling daylight availability
//! and irradiance components from direct and global irradiance", Solar Energy 44(5):271–289,
//! 1990. The port follows `gendaylit.c` v2.6 (NREL/Radiance, 2021, "gendaylit version 2.5
//! (2018/04/18)" in its usage text), the version the pyradiance wheel ships, step by step:
//! its clamps of ε and Δ, its "Perez correction" (Δ ≥ 0.2 for 1.065 < ε < 2.8), its
//! normalisation over the 145 Tregenza directions, its ground brightness, and its "error sky"
//! (all zeros) where it prints one. Departures: inputs gendaylit would misread (NaN, a zero
//! sun vector, a dew point outside [-40, 40] °C that gendaylit silently replaces) are errors.
//!
//! Units. The sky is a luminance in cd/m². What `gendaylit` writes depends on `-O`
//! ([`GendaylitUnits`]): `-O0` (the default) "W/m²/sr visible", i.e. luminance / 179 lm/W
//! (RADIANCE's `WHTEFFICACY`), the radiance RADIANCE turns back into luminance with the same
//! 179; `-O1` solar radiance in W/m²/sr (the irradiance-normalised sky, no efficacy); `-O2`
//! cd/m² directly (which RADIANCE would then multiply by 179 again when asked for luminance).

use super::cie::{hemisphere_integral, HemisphereGrid};
use crate::io::irradiance::PyranometerRow;
use crate::photometry::WHITE_EFFICACY_LM_PER_W;
use glam::DVec3;
use std::f64::consts::PI;
use tables::{
    CLEARNESS_BIN_UPPER, DIFFUSE_EFFICACY, DIRECT_EFFICACY, PEREZ_COEFFICIENTS, TREGENZA_BANDS,
};

mod gendaylit_text;
mod radiance_sun;
mod tables;

pub use gendaylit_text::c_exp;
pub use radiance_sun::{radiance_day_number, radiance_sun_at_solar_time, radiance_sun_position};

/// Solar constant, W/m² (`gendaylit.c` `solar_constant_e`).
pub const SOLAR_CONSTANT_W_M2: f64 = 1367.0;
/// Luminous solar constant, lux (`gendaylit.c` `solar_constant_l`): direct illuminance above
/// it is rejected as an error sky.
pub const SOLAR_CONSTANT_LUX: f64 = 127_500.0;
/// Half the angle of the sun `gendaylit` writes (`half_sun_angle`, degrees): the `source` is
/// 0.533° across, close to the sun's 0.5329° at 1 AU (hardware-facts.md §6).
pub const GENDAYLIT_HALF_SUN_ANGLE_DEG: f64 = 0.2665;
/// `gendaylit` lowers the sun to this altitude when it is higher (degrees).
pub const MAX_SUN_ALTITUDE_DEG: f64 = 87.0;
/// `gendaylit`'s default dew point, °C: it gives W = exp(0.07 Td − 0.075) = 2 cm, the
/// precipitable water Perez et al. 1990 assume when none is measured.
pub const DEFAULT_DEW_POINT_C: f64 = 10.97353115;

/// ε limits (`skyclearinf`, `skyclearsup`): ε above is set to 12.01 − 0.001.
const CLEARNESS_MIN: f64 = 1.0;
const CLEARNESS_SUP: f64 = 12.01;
/// Δ limits (`skybriginf`, `skybrigsup`).
const BRIGHTNESS_MIN: f64 = 0.01;
const BRIGHTNESS_MAX: f64 = 0.6;
/// 1.041 of the ε definition (Perez 1993 eq. 1; Z in radians).
const CLEARNESS_KAPPA: f64 = 1.041;
/// The sun's contribution to the ground brightness, `6.8e-5/π · solarradiance · sin(alt)`: the
/// solar solid angle gendaylit rounds to 6.8e-5 sr.
const GROUND_SUN_SOLID_ANGLE_SR: f64 = 6.8e-5;

/// What the sky is computed from, as the `gendaylit` option that takes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PerezInput {
    /// `-W`: direct normal and diffuse horizontal irradiance.
    DirectNormalDiffuse {
        direct_normal_w_m2: f64,
        diffuse_horizontal_w_m2: f64,
    },
    /// `-G` with direct horizontal = global − diffuse: DNI = (GHI − DHI) / sin(altitude).
    GlobalDiffuse {
        global_horizontal_w_m2: f64,
        diffuse_horizontal_w_m2: f64,
    },
    /// `-P`: the Perez parameters themselves, irradiances derived from them.
    ClearnessBrightness { clearness: f64, brightness: f64 },
}

impl PerezInput {
    /// A `pyranometer.csv` row as the model's input: DNI and DHI when both were measured (as
    /// gendaylit `-W`), else GHI and DHI (`-G`); `None` when neither pair is there.
    pub fn from_pyranometer(row: &PyranometerRow) -> Option<Self> {
        match (row.dni_wm2, row.dhi_wm2, row.ghi_wm2) {
            (Some(dni), Some(dhi), _) => Some(PerezInput::DirectNormalDiffuse {
                direct_normal_w_m2: dni,
                diffuse_horizontal_w_m2: dhi,
            }),
            (None, Some(dhi), Some(ghi)) => Some(PerezInput::GlobalDiffuse {
                global_horizontal_w_m2: ghi,
                diffuse_horizontal_w_m2: dhi,
            }),
            _ => None,
        }
    }
}

// Defined here, not beside the reader, so that `io` does not reach into the sky model.
impl PyranometerRow {
    /// [`PerezInput::from_pyranometer`].
    pub fn perez_input(&self) -> Option<PerezInput> {
        PerezInput::from_pyranometer(self)
    }
}

/// Everything that shapes a Perez sky besides the irradiance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PerezConditions {
    /// Unit vector towards the sun, world frame (+x east, +y north, +z up), as
    /// [`crate::sun::SolarPosition::direction`] gives it. gendaylit uses no refraction.
    pub sun_direction: DVec3,
    /// Day of the year for the eccentricity correction, 1..=366; 0 is what `gendaylit -ang`
    /// uses (its day number is never set in that mode). [`radiance_day_number`] gives
    /// gendaylit's count for a month and day.
    pub day_of_year: u16,
    /// Surface dew point, °C, for the precipitable water of the efficacy model
    /// (`gendaylit -d`); `None`: [`DEFAULT_DEW_POINT_C`] (W = 2 cm).
    pub dew_point_c: Option<f64>,
    /// Ground reflectance (`gendaylit -g`, default 0.2).
    pub ground_reflectance: f64,
    /// Local solar time written in the description's comment (gendaylit writes 0.00 with
    /// `-ang`); no effect on the sky.
    pub local_solar_time_h: Option<f64>,
}

impl PerezConditions {
    /// gendaylit's defaults for a sun direction: day 0 (as `-ang`), W = 2 cm, ground 0.2.
    pub fn gendaylit_ang(sun_direction: DVec3) -> Self {
        Self {
            sun_direction,
            day_of_year: 0,
            dew_point_c: None,
            ground_reflectance: 0.2,
            local_solar_time_h: None,
        }
    }
}

/// What gendaylit's `-O` selects for the numbers it writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GendaylitUnits {
    /// `-O0` (default): visible radiance, W/m²/sr = cd/m² / 179.
    VisibleRadiance,
    /// `-O1`: solar radiance, W/m²/sr, normalised to the irradiances.
    SolarRadiance,
    /// `-O2`: luminance, cd/m².
    Luminance,
}

/// Why gendaylit would print its "error sky" (zero sky, no sun) for these inputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorSky {
    /// Direct and diffuse both zero with the sun above the horizon.
    NoIrradiance,
    /// Direct normal irradiance above the solar constant (1367 W/m²).
    DirectAboveSolarConstant,
    /// ε undefined (0/0: no diffuse and no direct, sun at or below the horizon).
    UndefinedClearness,
    /// Direct and diffuse illuminance both zero with the sun above the horizon.
    NoIlluminance,
    /// Direct normal illuminance above the luminous solar constant (127 500 lx).
    DirectAboveLuminousSolarConstant,
    /// The Perez coefficient b came out positive (sky brighter towards the horizon without
    /// bound).
    PositiveGradation,
}

/// Inputs the model cannot take; each names the field.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum PerezError {
    #[error("{field} = {value} is not finite")]
    NotFinite { field: &'static str, value: f64 },
    #[error("sun_direction {value:?} is not a non-zero finite vector")]
    SunDirection { value: DVec3 },
    #[error("day_of_year {value} is outside 0..=366")]
    DayOfYear { value: u16 },
    #[error("dew_point_c {value} is outside [-40, 40] (gendaylit -d would ignore it)")]
    DewPoint { value: f64 },
    #[error("ground_reflectance {value} is outside [0, 1]")]
    GroundReflectance { value: f64 },
}

/// A Perez sky, in physical units, with what gendaylit would write for it.
#[derive(Clone, Debug, PartialEq)]
pub struct PerezSky {
    /// Towards the sun, after gendaylit's 87° limit.
    sun_direction: DVec3,
    /// Altitude after the 87° limit (radians; may be negative).
    altitude_rad: f64,
    /// Zenith angle used by the model: 90° − altitude, at most 90° (gendaylit's `air_mass`
    /// clamps it there before anything else uses it).
    zenith_rad: f64,
    precipitable_water_cm: f64,
    ground_reflectance: f64,
    local_solar_time_h: Option<f64>,
    clearness: f64,
    brightness: f64,
    direct_normal_w_m2: f64,
    diffuse_horizontal_w_m2: f64,
    direct_normal_lux: f64,
    diffuse_horizontal_lux: f64,
    coefficients: [f64; 5],
    /// gendaylit's `integ_lv`: Σ lv(θᵢ, γᵢ) cos θᵢ · 2π/145 over the Tregenza directions.
    tregenza_sum: f64,
    /// Ground brightness per unit of the normalisation: `zenith lv · normfactor`.
    ground_per_normalisation: f64,
    irradiance_error: Option<ErrorSky>,
    illuminance_error: Option<ErrorSky>,
}

/// Eccentricity correction (R0/R)² for a day number: Spencer's series as gendaylit's
/// `get_eccentricity` (day angle 2π(n − 1)/365).
pub fn eccentricity_factor(day_of_year: u16) -> f64 {
    let day_angle = 2.0 * PI * (f64::from(day_of_year) - 1.0) / 365.0;
    1.00011
        + 0.034221 * day_angle.cos()
        + 0.00128 * day_angle.sin()
        + 0.000719 * (2.0 * day_angle).cos()
        + 0.000077 * (2.0 * day_angle).sin()
}

/// Relative optical air mass at zenith angle `zenith_deg` (≤ 90°): Kasten 1966 as gendaylit's
/// `air_mass`, 1 / (cos Z + 0.15 (93.885 − Z)^−1.253).
pub fn air_mass(zenith_deg: f64) -> f64 {
    1.0 / (zenith_deg.to_radians().cos() + 0.15 * (93.885 - zenith_deg).powf(-1.253))
}

/// gendaylit's bin index 0..=7 for ε (`get_numlin`, which takes ε as a `float`).
fn coefficient_bin(clearness: f64) -> usize {
    let eps = f64::from(clearness as f32);
    CLEARNESS_BIN_UPPER[..7]
        .iter()
        .position(|&upper| eps < upper)
        .unwrap_or(7)
}

/// Bin of the efficacy tables: the first [lower, upper) containing ε, with the last upper
/// bound `last_upper` (12.01 diffuse, 12.1 direct); `None` outside (NaN included).
fn efficacy_bin(clearness: f64, last_upper: f64) -> Option<usize> {
    let mut lower = 1.0;
    for (i, &upper) in CLEARNESS_BIN_UPPER.iter().enumerate() {
        let upper = if i == 7 { last_upper } else { upper };
        if clearness >= lower && clearness < upper {
            return Some(i);
        }
        lower = upper;
    }
    None
}

/// The Perez coefficients a..e for zenith angle `z_rad`, ε and Δ, with RADIANCE's "Perez
/// correction" Δ ≥ 0.2 for 1.065 < ε < 2.8 (`coeff_lum_perez`).
pub fn perez_coefficients(z_rad: f64, clearness: f64, brightness: f64) -> [f64; 5] {
    let delta = if clearness > 1.065 && clearness < 2.8 {
        brightness.max(0.2)
    } else {
        brightness
    };
    let row = &PEREZ_COEFFICIENTS[coefficient_bin(clearness)];
    let x = |i: usize, j: usize| f64::from(row[4 * i + j]);
    let linear = |i: usize| x(i, 0) + x(i, 1) * z_rad + delta * (x(i, 2) + x(i, 3) * z_rad);
    if coefficient_bin(clearness) > 0 {
        [linear(0), linear(1), linear(2), linear(3), linear(4)]
    } else {
        [
            linear(0),
            linear(1),
            (delta * (x(2, 0) + x(2, 1) * z_rad)).powf(x(2, 2)).exp() - x(2, 3),
            -(delta * (x(3, 0) + x(3, 1) * z_rad)).exp() + x(3, 2) + delta * x(3, 3),
            linear(4),
        ]
    }
}

/// Perez relative luminance lv = (1 + a e^{b/cos ζ})(1 + c e^{dγ} + e cos²γ) at zenith
/// angle ζ and angle γ from the sun (radians).
pub fn perez_relative_luminance(coefficients: &[f64; 5], zeta_rad: f64, gamma_rad: f64) -> f64 {
    let [a, b, c, d, e] = *coefficients;
    let cos_gamma = gamma_rad.cos();
    (1.0 + a * (b / zeta_rad.cos()).exp())
        * (1.0 + c * (d * gamma_rad).exp() + e * cos_gamma * cos_gamma)
}

/// Precipitable water, cm, from a dew point, °C (Perez 1990 eq. 3, after Reitan):
/// W = exp(0.07 Td − 0.075).
pub fn precipitable_water_cm(dew_point_c: f64) -> f64 {
    (0.07 * dew_point_c - 0.075).exp()
}

fn finite(field: &'static str, value: f64) -> Result<f64, PerezError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(PerezError::NotFinite { field, value })
    }
}

impl PerezSky {
    /// Builds the sky as gendaylit does for `input` under `conditions`.
    pub fn new(input: PerezInput, conditions: &PerezConditions) -> Result<Self, PerezError> {
        let c = conditions;
        let dew_point_c = check_conditions(c)?;
        let sun = SunGeometry::lowered(c.sun_direction);
        let parameters = SkyParameters::from_input(input, &sun, c.day_of_year)?;
        let w = precipitable_water_cm(dew_point_c);
        let illuminance = Illuminances::perez_1990(&parameters, &sun, w);
        let shape = SkyShape::normalised(&parameters, &sun);
        Ok(Self {
            sun_direction: sun.direction,
            altitude_rad: sun.altitude_rad,
            zenith_rad: sun.zenith_rad,
            precipitable_water_cm: w,
            ground_reflectance: c.ground_reflectance,
            local_solar_time_h: c.local_solar_time_h,
            clearness: parameters.clearness,
            brightness: parameters.brightness,
            direct_normal_w_m2: parameters.direct_normal_w_m2,
            diffuse_horizontal_w_m2: parameters.diffuse_horizontal_w_m2,
            direct_normal_lux: illuminance.direct_normal_lux,
            diffuse_horizontal_lux: illuminance.diffuse_horizontal_lux,
            coefficients: shape.coefficients,
            tregenza_sum: shape.tregenza_sum,
            ground_per_normalisation: shape.ground_per_normalisation,
            irradiance_error: parameters.error,
            illuminance_error: illuminance.error,
        })
    }

    /// Why gendaylit would write its all-zero error sky in `units`, if it would: the
    /// illuminance checks only run for the visible outputs, and a positive b always fails.
    pub fn error_sky(&self, units: GendaylitUnits) -> Option<ErrorSky> {
        self.irradiance_error
            .or(match units {
                GendaylitUnits::SolarRadiance => None,
                _ => self.illuminance_error,
            })
            .or(if self.coefficients[1] > 0.0 {
                Some(ErrorSky::PositiveGradation)
            } else {
                None
            })
    }

    /// Sky clearness ε after gendaylit's limits (what it prints).
    pub fn clearness(&self) -> f64 {
        self.clearness
    }

    /// Sky brightness Δ after gendaylit's limits (what it prints; the coefficients use
    /// max(Δ, 0.2) for 1.065 < ε < 2.8).
    pub fn brightness(&self) -> f64 {
        self.brightness
    }

    /// Perez coefficients a, b, c, d, e (A3..A7 of `perezlum.cal`).
    pub fn coefficients(&self) -> [f64; 5] {
        self.coefficients
    }

    pub fn precipitable_water_cm(&self) -> f64 {
        self.precipitable_water_cm
    }

    /// Towards the sun (world frame), after gendaylit's 87° limit.
    pub fn sun_direction(&self) -> DVec3 {
        self.sun_direction
    }

    /// Solid angle of the sun gendaylit writes: 2π(1 − cos 0.2665°) = 6.797e-5 sr.
    pub fn sun_solid_angle_sr(&self) -> f64 {
        2.0 * PI * (1.0 - GENDAYLIT_HALF_SUN_ANGLE_DEG.to_radians().cos())
    }

    /// Direct normal irradiance after gendaylit's checks (derived for `-G` and `-P`).
    pub fn direct_normal_irradiance_w_m2(&self) -> f64 {
        self.direct_normal_w_m2
    }

    pub fn diffuse_horizontal_irradiance_w_m2(&self) -> f64 {
        self.diffuse_horizontal_w_m2
    }

    /// Direct normal illuminance: DNI × the Perez 1990 direct efficacy (0 for an error sky).
    pub fn direct_normal_illuminance_lux(&self) -> f64 {
        if self.error_sky(GendaylitUnits::Luminance).is_some() {
            0.0
        } else {
            self.direct_normal_lux
        }
    }

    /// Diffuse horizontal illuminance the sky is normalised to: DHI × the Perez 1990 diffuse
    /// efficacy (0 for an error sky). The sky's actual integral differs from it by the error
    /// of gendaylit's 145-point sum; see [`Self::sky_horizontal_illuminance_lux`].
    pub fn diffuse_horizontal_illuminance_lux(&self) -> f64 {
        if self.error_sky(GendaylitUnits::Luminance).is_some() {
            0.0
        } else {
            self.diffuse_horizontal_lux
        }
    }

    /// Diffuse horizontal plus direct normal × sin(altitude).
    pub fn global_horizontal_illuminance_lux(&self) -> f64 {
        self.diffuse_horizontal_illuminance_lux()
            + self.direct_normal_illuminance_lux() * self.sun_direction.z.max(0.0)
    }

    /// The normalisation A1, sun radiance and ground brightness A2 in `units`, zero for an
    /// error sky.
    fn radiometry(&self, units: GendaylitUnits) -> (f64, f64, f64) {
        self.radiometry_with(units, true)
    }

    /// [`Self::radiometry`]; without the sun (`gendaylit -s`) the ground has no sun term.
    fn radiometry_with(&self, units: GendaylitUnits, with_sun: bool) -> (f64, f64, f64) {
        if self.error_sky(units).is_some() {
            return (0.0, 0.0, 0.0);
        }
        let omega = self.sun_solid_angle_sr();
        let (normalisation, sun) = match units {
            GendaylitUnits::VisibleRadiance => (
                self.diffuse_horizontal_lux / self.tregenza_sum / WHITE_EFFICACY_LM_PER_W,
                self.direct_normal_lux / omega / WHITE_EFFICACY_LM_PER_W,
            ),
            GendaylitUnits::SolarRadiance => (
                self.diffuse_horizontal_w_m2 / self.tregenza_sum,
                self.direct_normal_w_m2 / omega,
            ),
            GendaylitUnits::Luminance => (
                self.diffuse_horizontal_lux / self.tregenza_sum,
                self.direct_normal_lux / omega,
            ),
        };
        let mut ground = normalisation * self.ground_per_normalisation;
        if with_sun && self.clearness > 1.0 {
            ground += GROUND_SUN_SOLID_ANGLE_SR / PI * sun * self.sun_direction.z;
        }
        (normalisation, sun, ground * self.ground_reflectance)
    }

    /// Luminance of the sun's disk, cd/m²: direct normal illuminance over the disk's solid
    /// angle (gendaylit's `light` radiance × 179). 0 for ε = 1, where gendaylit writes a
    /// zero `light` that RADIANCE drops (the sky then shows through the disk).
    pub fn sun_luminance_cd_m2(&self) -> f64 {
        if self.clearness > 1.0 {
            self.radiometry(GendaylitUnits::Luminance).1
        } else {
            0.0
        }
    }

    /// Luminance of the ground gendaylit writes (A2), cd/m².
    pub fn ground_luminance_cd_m2(&self) -> f64 {
        self.radiometry(GendaylitUnits::Luminance).2
    }

    /// The Perez model alone, cd/m², for a direction above the horizon (0 below): the
    /// normalised lv without `perezlum.cal`'s horizon treatment.
    pub fn model_luminance_cd_m2(&self, direction: DVec3) -> f64 {
        let d = direction.normalize_or_zero();
        if d.z <= 0.0 {
            return 0.0;
        }
        let (normalisation, _, _) = self.radiometry(GendaylitUnits::Luminance);
        let gamma = d.dot(self.sun_direction).clamp(-1.0, 1.0).acos();
        normalisation * perez_relative_luminance(&self.coefficients, d.z.acos(), gamma)
    }

    /// Sky luminance, cd/m², along `direction` exactly as RADIANCE evaluates gendaylit's
    /// description (`perezlum.cal`): the model with Dz floored at 0.01, blended with the
    /// ground brightness by weights (Dz + 1.01)^±10, so that below the horizon it is the
    /// ground. The sun's disk is not included ([`Self::sun_luminance_cd_m2`]).
    pub fn luminance_cd_m2(&self, direction: DVec3) -> f64 {
        let d = direction.normalize_or_zero();
        let (normalisation, _, ground) = self.radiometry(GendaylitUnits::Luminance);
        let [a, b, c, dd, e] = self.coefficients;
        let cos_gamma = d.dot(self.sun_direction);
        let gamma = cos_gamma.clamp(-1.0, 1.0).acos();
        let dz = if d.z - 0.01 > 0.0 { d.z } else { 0.01 };
        // rayinit.cal `Exp(x)`: 0 below −100.
        let exp = |x: f64| if -x - 100.0 > 0.0 { 0.0 } else { x.exp() };
        let sky = normalisation
            * (1.0 + a * exp(b / dz))
            * (1.0 + c * exp(dd * gamma) + e * cos_gamma * cos_gamma);
        let wa = (d.z + 1.01).powi(10);
        let wb = (d.z + 1.01).powi(-10);
        (wa * sky + wb * ground) / (wa + wb)
    }

    /// Horizontal illuminance of the sky as rendered ([`Self::luminance_cd_m2`] integrated
    /// over the upper hemisphere with cos θ), lux; the sun excluded.
    pub fn sky_horizontal_illuminance_lux(&self, grid: HemisphereGrid) -> f64 {
        hemisphere_integral(|d| self.luminance_cd_m2(d), grid)
    }
}

/// Checks what the model cannot take; returns the dew point to use.
fn check_conditions(c: &PerezConditions) -> Result<f64, PerezError> {
    let len = c.sun_direction.length();
    if !(len.is_finite() && len > 0.0) {
        return Err(PerezError::SunDirection {
            value: c.sun_direction,
        });
    }
    if c.day_of_year > 366 {
        return Err(PerezError::DayOfYear {
            value: c.day_of_year,
        });
    }
    let dew_point_c = match c.dew_point_c {
        None => DEFAULT_DEW_POINT_C,
        Some(td) if (-40.0..=40.0).contains(&td) => td,
        Some(td) => return Err(PerezError::DewPoint { value: td }),
    };
    if !(0.0..=1.0).contains(&c.ground_reflectance) {
        return Err(PerezError::GroundReflectance {
            value: c.ground_reflectance,
        });
    }
    if let Some(t) = c.local_solar_time_h {
        finite("local_solar_time_h", t)?;
    }
    Ok(dew_point_c)
}

/// The sun as the model sees it: altitude and azimuth as gendaylit derives its vector,
/// lowered to [`MAX_SUN_ALTITUDE_DEG`].
struct SunGeometry {
    direction: DVec3,
    /// Radians; may be negative.
    altitude_rad: f64,
    /// 90° − altitude, at most 90°.
    zenith_deg: f64,
    zenith_rad: f64,
}

impl SunGeometry {
    /// `sun_direction` must be a non-zero finite vector ([`check_conditions`]).
    fn lowered(sun_direction: DVec3) -> Self {
        let d = sun_direction / sun_direction.length();
        let mut altitude_rad = d.z.clamp(-1.0, 1.0).asin();
        let horizontal = (d.x * d.x + d.y * d.y).sqrt();
        let (east, north) = if horizontal > 0.0 {
            (d.x / horizontal, d.y / horizontal)
        } else {
            (0.0, -1.0) // exactly overhead: gendaylit's azimuth 0 (south)
        };
        if altitude_rad > MAX_SUN_ALTITUDE_DEG.to_radians() {
            altitude_rad = MAX_SUN_ALTITUDE_DEG.to_radians();
        }
        let direction = DVec3::new(
            east * altitude_rad.cos(),
            north * altitude_rad.cos(),
            altitude_rad.sin(),
        );
        let zenith_deg = (90.0 - altitude_rad.to_degrees()).min(90.0);
        Self {
            direction,
            altitude_rad,
            zenith_deg,
            zenith_rad: zenith_deg.to_radians(),
        }
    }
}

/// Irradiances and the Perez parameters ε, Δ after gendaylit's checks and clamps.
struct SkyParameters {
    direct_normal_w_m2: f64,
    diffuse_horizontal_w_m2: f64,
    clearness: f64,
    brightness: f64,
    error: Option<ErrorSky>,
}

impl SkyParameters {
    /// gendaylit `computesky`, inputs 0, 1 and 3.
    fn from_input(
        input: PerezInput,
        sun: &SunGeometry,
        day_of_year: u16,
    ) -> Result<Self, PerezError> {
        let altitude_rad = sun.altitude_rad;
        let m = air_mass(sun.zenith_deg);
        let e0 = eccentricity_factor(day_of_year);
        let z3 = CLEARNESS_KAPPA * sun.zenith_rad.powi(3);
        let extraterrestrial = SOLAR_CONSTANT_W_M2 * e0;
        let from_irradiances = |dni: f64, dhi: f64| {
            let (dni, dhi, error) = check_irradiances(dni, dhi, altitude_rad);
            let delta = dhi * m / extraterrestrial;
            let eps = ((dhi + dni) / dhi + z3) / (1.0 + z3);
            let (eps, delta) = clamp_parameters(eps, delta);
            (dni, dhi, eps, delta, error)
        };
        let (dni, dhi, clearness, brightness, error) = match input {
            PerezInput::DirectNormalDiffuse {
                direct_normal_w_m2,
                diffuse_horizontal_w_m2,
            } => from_irradiances(
                finite("direct_normal_w_m2", direct_normal_w_m2)?,
                finite("diffuse_horizontal_w_m2", diffuse_horizontal_w_m2)?,
            ),
            PerezInput::GlobalDiffuse {
                global_horizontal_w_m2,
                diffuse_horizontal_w_m2,
            } => {
                let ghi = finite("global_horizontal_w_m2", global_horizontal_w_m2)?;
                let dhi = finite("diffuse_horizontal_w_m2", diffuse_horizontal_w_m2)?;
                if altitude_rad <= 0.0 {
                    from_irradiances(0.0, 0.0)
                } else {
                    from_irradiances((ghi - dhi) / altitude_rad.sin(), dhi)
                }
            }
            PerezInput::ClearnessBrightness {
                clearness,
                brightness,
            } => {
                let (eps, delta) = clamp_parameters(
                    finite("clearness", clearness)?,
                    finite("brightness", brightness)?,
                );
                let dhi = delta / m * extraterrestrial;
                let dni = dhi * ((eps - 1.0) * (1.0 + z3));
                let (dni, dhi, error) = check_irradiances(dni, dhi, altitude_rad);
                (dni, dhi, eps, delta, error)
            }
        };
        let error = error.or(if clearness.is_nan() {
            Some(ErrorSky::UndefinedClearness)
        } else {
            None
        });
        Ok(Self {
            direct_normal_w_m2: dni,
            diffuse_horizontal_w_m2: dhi,
            clearness,
            brightness,
            error,
        })
    }
}

/// Negative irradiances count as zero; gendaylit's error skies for none at all with the sun
/// up, and for a direct beam above the solar constant.
fn check_irradiances(dni: f64, dhi: f64, altitude_rad: f64) -> (f64, f64, Option<ErrorSky>) {
    let (dni, dhi) = (dni.max(0.0), dhi.max(0.0));
    let error = if dni + dhi == 0.0 && altitude_rad > 0.0 {
        Some(ErrorSky::NoIrradiance)
    } else if dni > SOLAR_CONSTANT_W_M2 {
        Some(ErrorSky::DirectAboveSolarConstant)
    } else {
        None
    };
    (dni, dhi, error)
}

/// ε and Δ within gendaylit's limits.
fn clamp_parameters(eps: f64, delta: f64) -> (f64, f64) {
    // NaN passes through, as in gendaylit (its comparisons are all false).
    let eps = if eps < CLEARNESS_MIN {
        CLEARNESS_MIN
    } else if eps > CLEARNESS_SUP {
        CLEARNESS_SUP - 0.001
    } else {
        eps
    };
    // f64::clamp keeps NaN, as gendaylit's comparisons do.
    let delta = delta.clamp(BRIGHTNESS_MIN, BRIGHTNESS_MAX);
    (eps, delta)
}

/// Direct normal and diffuse horizontal illuminance from the Perez 1990 luminous efficacies,
/// then gendaylit's `check_illuminances`.
struct Illuminances {
    direct_normal_lux: f64,
    diffuse_horizontal_lux: f64,
    error: Option<ErrorSky>,
}

impl Illuminances {
    fn perez_1990(p: &SkyParameters, sun: &SunGeometry, precipitable_water_cm: f64) -> Self {
        let (clearness, brightness, w) = (p.clearness, p.brightness, precipitable_water_cm);
        let zenith_rad = sun.zenith_rad;
        let (mut diffuse_lux, mut direct_lux) = (0.0, 0.0);
        if let Some(bin) = efficacy_bin(clearness, CLEARNESS_SUP) {
            let [a, b, cc, dd] = DIFFUSE_EFFICACY[bin];
            diffuse_lux = p.diffuse_horizontal_w_m2
                * (a + b * w + cc * zenith_rad.cos() + dd * brightness.ln());
        }
        if let Some(bin) = efficacy_bin(clearness, 12.1) {
            let [a, b, cc, dd] = DIRECT_EFFICACY[bin];
            let efficacy = a + b * w + cc * (5.73 * zenith_rad - 5.0).exp() + dd * brightness;
            direct_lux = p.direct_normal_w_m2 * efficacy.max(0.0);
        }
        let (diffuse_lux, direct_lux) = (diffuse_lux.max(0.0), direct_lux.max(0.0));
        let error = if direct_lux + diffuse_lux == 0.0 && sun.altitude_rad > 0.0 {
            Some(ErrorSky::NoIlluminance)
        } else if direct_lux > SOLAR_CONSTANT_LUX {
            Some(ErrorSky::DirectAboveLuminousSolarConstant)
        } else {
            None
        };
        Self {
            direct_normal_lux: direct_lux,
            diffuse_horizontal_lux: diffuse_lux,
            error,
        }
    }
}

/// The sky's relative shape and gendaylit's normalisation of it.
struct SkyShape {
    coefficients: [f64; 5],
    /// gendaylit's `integ_lv` over the Tregenza directions.
    tregenza_sum: f64,
    /// Ground brightness per unit of the normalisation.
    ground_per_normalisation: f64,
}

impl SkyShape {
    fn normalised(p: &SkyParameters, sun: &SunGeometry) -> Self {
        let (clearness, zenith_rad, altitude_rad) = (p.clearness, sun.zenith_rad, sun.altitude_rad);
        if clearness.is_nan() {
            return Self {
                coefficients: [0.0; 5],
                tregenza_sum: f64::NAN,
                ground_per_normalisation: 0.0,
            };
        }
        let coefficients = perez_coefficients(zenith_rad, clearness, p.brightness);
        // integ_lv: 145 directions, azimuth measured from the sun, lv stored as float.
        let mut sum = 0.0;
        for (theta_deg, count) in TREGENZA_BANDS {
            let theta = theta_deg.to_radians();
            for k in 0..count {
                let phi = (360.0 / count as f64 * k as f64).to_radians();
                let cos_gamma =
                    zenith_rad.cos() * theta.cos() + zenith_rad.sin() * theta.sin() * phi.cos();
                let gamma = if cos_gamma > 1.0 {
                    0.0
                } else {
                    cos_gamma.acos()
                };
                let lv = perez_relative_luminance(&coefficients, theta, gamma) as f32;
                sum += f64::from(lv) * theta.cos();
            }
        }
        let tregenza_sum = sum * (2.0 * PI / 145.0);
        // Ground: zenith lv times gendaylit's horizontal-to-zenith factor by ε class.
        let zenith_lv = perez_relative_luminance(&coefficients, 0.0, zenith_rad);
        let normfactor = if clearness == 1.0 {
            0.777778
        } else if clearness >= 6.0 {
            let f2 = 0.274
                * (0.91
                    + 10.0 * (-3.0 * (PI / 2.0 - altitude_rad)).exp()
                    + 0.45 * sun.direction.z * sun.direction.z);
            normsc(altitude_rad, false) / f2 / PI
        } else {
            let f2 = (2.739 + 0.9891 * (0.3119 + 2.6 * altitude_rad).sin())
                * (-(PI / 2.0 - altitude_rad) * (0.4441 + 1.48 * altitude_rad)).exp();
            normsc(altitude_rad, true) / f2 / PI
        };
        Self {
            coefficients,
            tregenza_sum,
            ground_per_normalisation: zenith_lv * normfactor,
        }
    }
}

/// gendaylit's `normsc`: a polynomial in x = (alt − π/4)/(π/4) approximating E0·F2/L0 for the
/// clear (CIE) or intermediate sky (the same table as gensky).
fn normsc(altitude_rad: f64, intermediate: bool) -> f64 {
    const NFC: [[f64; 5]; 2] = [
        [2.766521, 0.547665, -0.369832, 0.009237, 0.059229],
        [3.5556, -2.7152, -1.3081, 1.0660, 0.60227],
    ];
    let nf = &NFC[usize::from(intermediate)];
    let x = (altitude_rad - PI / 4.0) / (PI / 4.0);
    nf.iter().rev().fold(0.0, |acc, &c| acc * x + c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sun::sun_direction;

    fn sky(dni: f64, dhi: f64, zenith_deg: f64) -> PerezSky {
        PerezSky::new(
            PerezInput::DirectNormalDiffuse {
                direct_normal_w_m2: dni,
                diffuse_horizontal_w_m2: dhi,
            },
            &PerezConditions::gendaylit_ang(sun_direction(zenith_deg, 160.0)),
        )
        .unwrap()
    }

    /// ε from its definition: with no direct light ε = 1 (overcast), more direct light → clearer.
    #[test]
    fn clearness_and_brightness_follow_their_definitions() {
        let s = sky(0.0, 100.0, 40.0);
        assert_eq!(s.clearness(), 1.0);
        let z = 40f64.to_radians();
        let k = 1.041 * z.powi(3);
        let s = sky(500.0, 100.0, 40.0);
        assert!((s.clearness() - (6.0 + k) / (1.0 + k)).abs() < 1e-12);
        let delta = 100.0 * air_mass(40.0) / (1367.0 * eccentricity_factor(0));
        assert!((s.brightness() - delta).abs() < 1e-12);
        // Clamps: Δ at least 0.01, ε at most 12.009.
        let s = sky(1300.0, 1.0, 10.0);
        assert_eq!(s.brightness(), 0.01);
        assert!((s.clearness() - 12.009).abs() < 1e-12);
    }

    #[test]
    fn the_sun_is_lowered_to_87_degrees() {
        let s = sky(800.0, 100.0, 1.0);
        assert!((s.sun_direction().z - 87f64.to_radians().sin()).abs() < 1e-12);
        assert!((s.sun_direction().length() - 1.0).abs() < 1e-12);
        let overhead = PerezSky::new(
            PerezInput::DirectNormalDiffuse {
                direct_normal_w_m2: 800.0,
                diffuse_horizontal_w_m2: 100.0,
            },
            &PerezConditions::gendaylit_ang(DVec3::Z),
        )
        .unwrap();
        assert!(overhead.sun_direction().y < 0.0, "azimuth 0 = south");
    }

    /// The normalisation reproduces the diffuse illuminance through gendaylit's own sum.
    #[test]
    fn tregenza_sum_normalises_to_the_diffuse_illuminance() {
        let s = sky(600.0, 150.0, 50.0);
        let mut sum = 0.0;
        for (theta_deg, count) in TREGENZA_BANDS {
            for k in 0..count {
                let az = 160.0 + 360.0 / count as f64 * k as f64;
                let d = sun_direction(theta_deg, az);
                sum += s.model_luminance_cd_m2(d) * d.z;
            }
        }
        let e = sum * 2.0 * PI / 145.0;
        assert!((e / s.diffuse_horizontal_illuminance_lux() - 1.0).abs() < 1e-6);
        let ghi = s.diffuse_horizontal_illuminance_lux()
            + s.direct_normal_illuminance_lux() * 40f64.to_radians().sin();
        assert!((s.global_horizontal_illuminance_lux() - ghi).abs() < 1e-9 * ghi);
        let sun = s.sun_luminance_cd_m2() * s.sun_solid_angle_sr();
        assert!((sun / s.direct_normal_illuminance_lux() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn error_skies_and_bad_inputs() {
        assert_eq!(
            sky(0.0, 0.0, 40.0).error_sky(GendaylitUnits::VisibleRadiance),
            Some(ErrorSky::NoIrradiance)
        );
        assert_eq!(
            sky(1400.0, 50.0, 40.0).error_sky(GendaylitUnits::SolarRadiance),
            Some(ErrorSky::DirectAboveSolarConstant)
        );
        let below = sky(0.0, 0.0, 95.0);
        assert_eq!(
            below.error_sky(GendaylitUnits::VisibleRadiance),
            Some(ErrorSky::UndefinedClearness)
        );
        assert_eq!(below.luminance_cd_m2(DVec3::Z), 0.0);
        assert!(below
            .gendaylit_text(GendaylitUnits::VisibleRadiance)
            .contains("10 0.00 0.00"));
        let bad = |input, c: PerezConditions| PerezSky::new(input, &c).unwrap_err();
        let ok = PerezConditions::gendaylit_ang(DVec3::new(0.0, -0.6, 0.8));
        let w = |dni, dhi| PerezInput::DirectNormalDiffuse {
            direct_normal_w_m2: dni,
            diffuse_horizontal_w_m2: dhi,
        };
        assert!(matches!(
            bad(w(f64::NAN, 1.0), ok),
            PerezError::NotFinite {
                field: "direct_normal_w_m2",
                ..
            }
        ));
        assert!(matches!(
            bad(
                w(1.0, 1.0),
                PerezConditions {
                    sun_direction: DVec3::ZERO,
                    ..ok
                }
            ),
            PerezError::SunDirection { .. }
        ));
        assert!(matches!(
            bad(
                w(1.0, 1.0),
                PerezConditions {
                    day_of_year: 367,
                    ..ok
                }
            ),
            PerezError::DayOfYear { value: 367 }
        ));
        assert!(matches!(
            bad(
                w(1.0, 1.0),
                PerezConditions {
                    dew_point_c: Some(55.0),
                    ..ok
                }
            ),
            PerezError::DewPoint { .. }
        ));
        assert!(matches!(
            bad(
                w(1.0, 1.0),
                PerezConditions {
                    ground_reflectance: f64::NAN,
                    ..ok
                }
            ),
            PerezError::GroundReflectance { .. }
        ));
    }

    #[test]
    fn day_numbers() {
        assert_eq!(radiance_day_number(1, 1), Some(1));
        assert_eq!(radiance_day_number(12, 31), Some(365));
        assert_eq!(radiance_day_number(13, 1), None);
        // Perihelion in early January: E0 > 1; aphelion in early July: E0 < 1.
        assert!(eccentricity_factor(3) > 1.03 && eccentricity_factor(185) < 0.97);
    }
}
