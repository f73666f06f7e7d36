//! Every cycle's outputs against physical bounds (`skylux_hps::model::plausibility`): a value no
//! sky can give is flagged in the record, counted in `/v1/metrics` and logged, never passed on
//! silently to a building that acts on it.

use crate::cycle::CycleRecord;
use skylux_hps::model::plausibility::{direct_normal_bound_lux, global_horizontal_bound_lux};

/// The flags a record can carry (stable names: records, the API and the metrics use them).
pub const OUTDOOR_ABOVE_BOUND: &str = "outdoor_above_clear_sky_bound";
pub const DIRECT_NORMAL_ABOVE_BOUND: &str = "direct_normal_above_extraterrestrial";
pub const INTERIOR_INVALID: &str = "interior_not_finite_or_negative";
pub const INTERIOR_ABOVE_BOUND: &str = "interior_above_outdoor_bound";
pub const OUTDOOR_INVALID: &str = "outdoor_not_finite_or_negative";

/// How far above its daylight-factor bound an interior value may read before it is flagged:
/// the Monte-Carlo values carry noise (a few standard errors of a few %).
pub const INTERIOR_BOUND_MARGIN: f64 = 1.1;

/// The flags of one record, for a site at `elevation_m` on day `day_of_year`; with the
/// room's bound per sensor (`skylux_hps::model::plausibility::interior_bound_lux`, in the
/// order of `record.illuminance`), each interior value is also held against it.
pub fn check(
    record: &CycleRecord,
    elevation_m: f64,
    day_of_year: u16,
    interior_bound_lux: Option<&[f64]>,
) -> Vec<&'static str> {
    let mut flags = vec![];
    let altitude_deg = record.sun.spa_altitude_deg;
    let outdoor = record.outdoor_horizontal_lux;
    if !(outdoor.is_finite() && outdoor >= 0.0) {
        flags.push(OUTDOOR_INVALID);
    } else if outdoor > global_horizontal_bound_lux(altitude_deg, elevation_m, day_of_year) {
        flags.push(OUTDOOR_ABOVE_BOUND);
    }
    if record
        .sun
        .direct_normal_lux
        .is_some_and(|dn| dn > direct_normal_bound_lux(day_of_year))
    {
        flags.push(DIRECT_NORMAL_ABOVE_BOUND);
    }
    let interior = record
        .illuminance
        .iter()
        .chain(record.monte_carlo.iter().flatten());
    // No sensor behind glazing receives more than a surface facing the sun outdoors: the
    // global bound with the sun at the zenith (beam and sky on a plane normal to the sun).
    let interior_bound = global_horizontal_bound_lux(90.0, elevation_m, day_of_year);
    let mut invalid = false;
    let mut above = false;
    for s in interior {
        invalid |= !(s.lux.is_finite() && s.lux >= 0.0);
        above |= s.lux > interior_bound;
    }
    // Each sensor against the most its room lets in under this outdoor light (sensor `k` of
    // `illuminance` and of `monte_carlo` alike).
    if let Some(bounds) = interior_bound_lux {
        let per_sensor = std::iter::once(&record.illuminance).chain(record.monte_carlo.iter());
        for values in per_sensor {
            for (s, bound) in values.iter().zip(bounds) {
                above |= s.lux > INTERIOR_BOUND_MARGIN * bound + 1.0;
            }
        }
    }
    if invalid {
        flags.push(INTERIOR_INVALID);
    }
    if above {
        flags.push(INTERIOR_ABOVE_BOUND);
    }
    flags
}
