//! The Perez baseline: the pyranometer's irradiance through gendaylit's sky model and the
//! same daylight coefficients, what the device model is compared against.

use super::sample::nearest_in_time;
use crate::campaign::Campaign;
use crate::engine::EngineError;
use crate::model::{CaptureData, Room};
use crate::sky::perez::{PerezConditions, PerezSky};
use chrono::{Datelike, TimeDelta};

/// The Perez baseline per capture: the pyranometer's irradiance through gendaylit's model,
/// the same daylight coefficients, the sun as a concentrated source, a ground of 0.2.
/// Also returns the outdoor horizontal illuminance the pyranometer implies (Perez 1990
/// luminous efficacy, as gendaylit converts), per capture.
#[allow(clippy::type_complexity)]
pub fn perez_predictions(
    campaign: &Campaign,
    room: &mut Room,
    captures: &[CaptureData],
    window: TimeDelta,
) -> Result<(Vec<Option<Vec<f64>>>, Vec<Option<f64>>), EngineError> {
    let Some(table) = &campaign.pyranometer else {
        return Ok((vec![None; captures.len()], vec![None; captures.len()]));
    };
    let mut outdoor = Vec::new();
    let patches = room.dc.patches();
    let n = patches.len();
    let mut out = Vec::new();
    for c in captures {
        let row = nearest_in_time(&table.rows, window, |r| r.time - c.time);
        let Some(row) = row else {
            out.push(None);
            outdoor.push(None);
            continue;
        };
        let Some(input) = row.perez_input() else {
            out.push(None);
            outdoor.push(None);
            continue;
        };
        let conditions = PerezConditions {
            day_of_year: c.time.ordinal() as u16,
            ..PerezConditions::gendaylit_ang(c.spa_sun)
        };
        let Ok(sky) = PerezSky::new(input, &conditions) else {
            out.push(None);
            outdoor.push(None);
            continue;
        };
        outdoor.push(Some(sky.global_horizontal_illuminance_lux()).filter(|l| l.is_finite()));
        let ground = 0.2 * sky.global_horizontal_illuminance_lux() / std::f64::consts::PI;
        let mut lum: Vec<f64> = (0..n)
            .map(|p| sky.luminance_cd_m2(patches.centre(p)))
            .collect();
        lum.extend(std::iter::repeat_n(ground, n));
        let mut e = room.dc.apply(&lum)?;
        let dn = sky.direct_normal_illuminance_lux();
        if dn > 0.0 && c.spa_sun.z > 0.0 {
            let k = room.sun_coefficients(c.spa_sun)?;
            for (ei, (ki, _)) in e.iter_mut().zip(k) {
                *ei += ki * dn;
            }
        }
        out.push(Some(e));
    }
    Ok((out, outdoor))
}
