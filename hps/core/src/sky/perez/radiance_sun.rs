//! The sun where RADIANCE's `gendaylit` puts it for a date and time (`src/common/sun.c`).

use glam::DVec3;
use std::f64::consts::PI;

/// gendaylit's day number for a month (1..=12) and day: RADIANCE `sun.c` `jdate`, a
/// non-leap-year count.
pub fn radiance_day_number(month: u32, day: u32) -> Option<u16> {
    const BEFORE: [u16; 12] = [0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334];
    if !(1..=12).contains(&month) || !(1..=31).contains(&day) {
        return None;
    }
    Some(BEFORE[month as usize - 1] + day as u16)
}

/// The sun where `gendaylit month day hour -a lat -o lon -m mer` (no `-y`) puts it: RADIANCE
/// `src/common/sun.c` v2.7 (2019: `jdate`, `sdec` with its 365-day period, `stadj`, `salt`,
/// `sazi`), an approximation good to a few tenths of a degree. `standard_hour` is local standard time
/// at `meridian_east_deg`; longitudes here are east-positive (RADIANCE's are west-positive).
/// Returns the direction (world frame) and the local solar time in hours; `None` for an
/// invalid month or day. gendaylit's own sunrise/sunset test is not applied.
pub fn radiance_sun_position(
    month: u32,
    day: u32,
    standard_hour: f64,
    latitude_deg: f64,
    longitude_east_deg: f64,
    meridian_east_deg: f64,
) -> Option<(DVec3, f64)> {
    let jd = f64::from(radiance_day_number(month, day)?);
    let longitude_west = -longitude_east_deg * (PI / 180.0);
    let meridian_west = -meridian_east_deg * (PI / 180.0);
    let solar_time = standard_hour
        + (0.170 * ((4.0 * PI / 373.0) * (jd - 80.0)).sin()
            - 0.129 * ((2.0 * PI / 355.0) * (jd - 8.0)).sin()
            + (12.0 / PI) * (meridian_west - longitude_west));
    let direction = radiance_sun_at_solar_time(month, day, solar_time, latitude_deg)?;
    Some((direction, solar_time))
}

/// The sun where RADIANCE's `sun.c` puts it at local solar time `solar_hour` (gensky and
/// gendaylit with a `+hour`): declination `sdec`, altitude `salt`, azimuth `sazi`. `None` for an
/// invalid month or day, or a non-finite result.
pub fn radiance_sun_at_solar_time(
    month: u32,
    day: u32,
    solar_hour: f64,
    latitude_deg: f64,
) -> Option<DVec3> {
    let jd = f64::from(radiance_day_number(month, day)?);
    let latitude = latitude_deg * (PI / 180.0);
    let declination = 0.4093 * ((2.0 * PI / 365.0) * (jd - 81.0)).sin();
    let hour_angle = solar_hour * (PI / 12.0);
    let altitude = (latitude.sin() * declination.sin()
        - latitude.cos() * declination.cos() * hour_angle.cos())
    .asin();
    let azimuth = -(declination.cos() * hour_angle.sin()).atan2(
        -latitude.cos() * declination.sin() - latitude.sin() * declination.cos() * hour_angle.cos(),
    );
    let direction = DVec3::new(
        -azimuth.sin() * altitude.cos(),
        -azimuth.cos() * altitude.cos(),
        altitude.sin(),
    );
    direction.is_finite().then_some(direction)
}
