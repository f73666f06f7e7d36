//! `gendaylit month day hour [options]` or `gendaylit -ang altitude azimuth [options]` with
//! `-W`, `-G` or `-P`: the Perez all-weather sky, through the project's port of gendaylit
//! ([`crate::sky::perez`]), written as gendaylit writes it. The options it takes besides
//! those are `-O`, `-g`, `-d`, `-s`/`+s`, `-a`, `-o`, `-m`; the rest (`-L`, `-E`, `-y`,
//! `-c`, ...) are refused by name. As gendaylit 2.5 (the pyradiance wheel's), the hour is
//! read as a number: `10:30EDT` is 10 h at the `-m` meridian (gensky reads minutes and zones).

use super::args::number;
use super::gensky::{
    parse_hour_as_number, parse_sun_input, sun_angles, sun_vector, Site, SunInput,
};
use crate::sky::perez::{
    radiance_day_number, GendaylitUnits, PerezConditions, PerezInput, PerezSky,
    MAX_SUN_ALTITUDE_DEG,
};
use std::path::Path;

const USAGE: &str = "gendaylit month day hour | -ang altitude azimuth, then -W dn df | -G dh df \
                     | -P epsilon delta, [-O 0|1|2] [-g rho] [-d dewpoint] [-s] [-a lat] \
                     [-o lon] [-m meridian]";

pub(super) fn generate(args: &[String], _dir: &Path) -> Result<String, String> {
    let input = parse_sun_input(args, USAGE, parse_hour_as_number)?;
    let mut site = Site::default();
    let mut perez = None;
    let mut units = GendaylitUnits::VisibleRadiance;
    let mut conditions = PerezConditions::gendaylit_ang(glam::DVec3::Z);
    let mut with_sun = true;
    let rest = &args[3..];
    let mut i = 0;
    while i < rest.len() {
        let value = |k: usize, what: &str| number(rest, i + k, what);
        let used = match rest[i].as_str() {
            "-W" => {
                perez = Some(PerezInput::DirectNormalDiffuse {
                    direct_normal_w_m2: value(1, "-W direct normal irradiance")?,
                    diffuse_horizontal_w_m2: value(2, "-W diffuse horizontal irradiance")?,
                });
                3
            }
            "-G" => {
                let direct = value(1, "-G direct horizontal irradiance")?;
                let diffuse = value(2, "-G diffuse horizontal irradiance")?;
                perez = Some(PerezInput::GlobalDiffuse {
                    global_horizontal_w_m2: direct + diffuse,
                    diffuse_horizontal_w_m2: diffuse,
                });
                3
            }
            "-P" => {
                perez = Some(PerezInput::ClearnessBrightness {
                    clearness: value(1, "-P epsilon")?,
                    brightness: value(2, "-P delta")?,
                });
                3
            }
            "-O" => {
                units = match value(1, "-O")? as i64 {
                    0 => GendaylitUnits::VisibleRadiance,
                    1 => GendaylitUnits::SolarRadiance,
                    2 => GendaylitUnits::Luminance,
                    other => return Err(format!("-O {other}: expected 0, 1 or 2")),
                };
                2
            }
            "-g" => {
                conditions.ground_reflectance = value(1, "-g ground reflectance")?;
                2
            }
            "-d" => {
                conditions.dew_point_c = Some(value(1, "-d dew point")?);
                2
            }
            "-a" => {
                site.latitude_deg = value(1, "-a latitude")?;
                2
            }
            "-o" => {
                site.longitude_west_deg = value(1, "-o longitude")?;
                2
            }
            "-m" => {
                site.meridian_west_deg = value(1, "-m meridian")?;
                2
            }
            s @ ("-s" | "+s") => {
                with_sun = s == "+s";
                1
            }
            other => {
                return Err(format!(
                    "option `{other}` is not implemented (Skylux reads -W, -G, -P, -O, -g, \
                     -d, -s, -a, -o, -m); usage: {USAGE}"
                ))
            }
        };
        i += used;
    }
    let perez = perez.ok_or("no sky given: expected -W, -G or -P")?;
    let (altitude, azimuth, solar_time) = sun_angles(&input, &site)?;
    let altitude = altitude.min(MAX_SUN_ALTITUDE_DEG.to_radians());
    conditions.sun_direction = sun_vector(altitude, azimuth);
    conditions.local_solar_time_h = solar_time;
    if let SunInput::Date { month, day, .. } = input {
        conditions.day_of_year = radiance_day_number(month, day).unwrap_or(0);
    }
    let sky = PerezSky::new(perez, &conditions).map_err(|e| e.to_string())?;
    Ok(sky.gendaylit_text_with(units, with_sun))
}
