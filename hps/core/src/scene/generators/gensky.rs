//! `gensky month day hour [options]` or `gensky -ang altitude azimuth [options]`: the CIE
//! skies RADIANCE's gensky.c writes (clear `+s`/`-s`, intermediate `+i`/`-i`, overcast `-c`,
//! uniform `-u`) as `skybr skybright.cal` with its sun, zenith brightness, ground and
//! normalisation computed as gensky computes them, numbers in its formats. The sun's place
//! comes from RADIANCE's sun.c, ported in [`crate::sky::perez`]. `-y` (Michalsky's
//! algorithm for a given year) is refused.

use super::args::number;
use crate::sky::perez::{c_exp, radiance_sun_at_solar_time, radiance_sun_position};
use glam::DVec3;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::path::Path;

const USAGE: &str = "gensky month day hour [options] | gensky -ang altitude azimuth [options]";

/// sun.c's default site: latitude 0.66 rad north, longitude 2.13 rad west, meridian 120° W.
pub(super) const DEFAULT_LATITUDE_DEG: f64 = 0.66 * 180.0 / PI;
pub(super) const DEFAULT_LONGITUDE_WEST_DEG: f64 = 2.13 * 180.0 / PI;
pub(super) const DEFAULT_MERIDIAN_WEST_DEG: f64 = 120.0;
/// gensky's luminous efficacies (RADIANCE color.h): SUNEFFICACY (illuminant B) and
/// SKYEFFICACY (= D65EFFICACY), lm/W.
const SUN_EFFICACY: f64 = 208.0;
const SKY_EFFICACY: f64 = 203.0;
/// gensky lowers the sun to this altitude (degrees) for the non-overcast skies.
const MAX_ALTITUDE_DEG: f64 = 87.0;

/// gensky's and gendaylit's time zones and their standard meridians (degrees west).
const TIME_ZONES: &[(&str, f64)] = &[
    ("YST", 135.0),
    ("YDT", 120.0),
    ("PST", 120.0),
    ("PDT", 105.0),
    ("MST", 105.0),
    ("MDT", 90.0),
    ("CST", 90.0),
    ("CDT", 75.0),
    ("EST", 75.0),
    ("EDT", 60.0),
    ("AST", 60.0),
    ("ADT", 45.0),
    ("NST", 52.5),
    ("NDT", 37.5),
    ("GMT", 0.0),
    ("BST", -15.0),
    ("CET", -15.0),
    ("CEST", -30.0),
    ("EET", -30.0),
    ("EEST", -45.0),
    ("AST", -45.0),
    ("ADT", -60.0),
    ("GST", -60.0),
    ("GDT", -75.0),
    ("IST", -82.5),
    ("IDT", -97.5),
    ("JST", -135.0),
    ("NDT", -150.0),
    ("NZST", -180.0),
    ("NZDT", -195.0),
];

/// A time as gensky reads it (`cvthour`): `10.5`, `10:30`, `+10:30` (solar), `10:30EDT`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Hour {
    pub hours: f64,
    pub solar: bool,
    /// The standard meridian (degrees west) a time-zone suffix names.
    pub meridian_west_deg: Option<f64>,
}

pub(super) fn parse_hour(text: &str) -> Result<Hour, String> {
    let bad = || format!("bad time `{text}`; expected H, H.H or H:MM, optionally a zone");
    let solar = text.starts_with('+');
    let body = text.trim_start_matches('+');
    let split = body
        .find(|c: char| c.is_ascii_alphabetic())
        .unwrap_or(body.len());
    let (clock, zone) = body.split_at(split);
    let hours = match clock.split_once(':') {
        Some((h, m)) => {
            let h: u32 = h.parse().map_err(|_| bad())?;
            let m: u32 = m.parse().map_err(|_| bad())?;
            f64::from(h) + f64::from(m) / 60.0
        }
        None => clock.parse::<f64>().map_err(|_| bad())?,
    };
    if !hours.is_finite() {
        return Err(bad());
    }
    let meridian_west_deg = if zone.is_empty() {
        None
    } else if solar {
        return Err(bad());
    } else {
        let upper = zone.to_ascii_uppercase();
        let found = TIME_ZONES.iter().find(|(z, _)| *z == upper);
        Some(
            found
                .map(|&(_, m)| m)
                .ok_or_else(|| format!("unknown time zone `{zone}`"))?,
        )
    };
    Ok(Hour {
        hours,
        solar,
        meridian_west_deg,
    })
}

/// Where the sun is: given, or from a date and time at a site (west-positive, as gensky).
pub(super) enum SunInput {
    Angles { altitude_deg: f64, azimuth_deg: f64 },
    Date { month: u32, day: u32, hour: Hour },
}

/// gendaylit 2.5's hour (the pyradiance wheel's): C `atof` of the word, so `10:30EDT` is 10 h
/// at the `-m` meridian; `+` marks solar time.
pub(super) fn parse_hour_as_number(text: &str) -> Result<Hour, String> {
    let body = text.strip_prefix('+').unwrap_or(text);
    let hours = (1..=body.len())
        .rev()
        .filter(|&n| body.is_char_boundary(n))
        .find_map(|n| body[..n].parse::<f64>().ok().filter(|v| v.is_finite()))
        .ok_or_else(|| format!("bad time `{text}`; expected a number of hours"))?;
    Ok(Hour {
        hours,
        solar: text.starts_with('+'),
        meridian_west_deg: None,
    })
}

/// The first three arguments as gensky and gendaylit read them; `hour` reads the time.
pub(super) fn parse_sun_input(
    args: &[String],
    usage: &str,
    hour: fn(&str) -> Result<Hour, String>,
) -> Result<SunInput, String> {
    if args.len() < 3 {
        return Err(format!("{} argument(s) given; usage: {usage}", args.len()));
    }
    if args[0] == "-ang" {
        return Ok(SunInput::Angles {
            altitude_deg: number(args, 1, "altitude")?,
            azimuth_deg: number(args, 2, "azimuth")?,
        });
    }
    let month = super::args::integer(args, 0, "month")?;
    let day = super::args::integer(args, 1, "day")?;
    if !(1..=12).contains(&month) || !(1..=31).contains(&day) {
        return Err(format!("bad date {month}/{day}"));
    }
    Ok(SunInput::Date {
        month: month as u32,
        day: day as u32,
        hour: hour(&args[2])?,
    })
}

/// A site in gensky's conventions: degrees, longitude and meridian west-positive.
#[derive(Clone, Copy, Debug)]
pub(super) struct Site {
    pub latitude_deg: f64,
    pub longitude_west_deg: f64,
    pub meridian_west_deg: f64,
}

impl Default for Site {
    fn default() -> Self {
        Site {
            latitude_deg: DEFAULT_LATITUDE_DEG,
            longitude_west_deg: DEFAULT_LONGITUDE_WEST_DEG,
            meridian_west_deg: DEFAULT_MERIDIAN_WEST_DEG,
        }
    }
}

/// The sun's altitude and azimuth (radians, azimuth west of south) and the solar time.
pub(super) fn sun_angles(input: &SunInput, site: &Site) -> Result<(f64, f64, Option<f64>), String> {
    let (direction, solar_time) = match *input {
        SunInput::Angles {
            altitude_deg,
            azimuth_deg,
        } => return Ok((altitude_deg.to_radians(), azimuth_deg.to_radians(), None)),
        SunInput::Date { month, day, hour } if hour.solar => (
            radiance_sun_at_solar_time(month, day, hour.hours, site.latitude_deg),
            hour.hours,
        ),
        SunInput::Date { month, day, hour } => {
            match radiance_sun_position(
                month,
                day,
                hour.hours,
                site.latitude_deg,
                -site.longitude_west_deg,
                -site.meridian_west_deg,
            ) {
                Some((d, st)) => (Some(d), st),
                None => (None, 0.0),
            }
        }
    };
    let d = direction.ok_or("the sun's position cannot be computed for this date and site")?;
    Ok((
        d.z.clamp(-1.0, 1.0).asin(),
        (-d.x).atan2(-d.y),
        Some(solar_time),
    ))
}

/// gensky's sun vector for an altitude and azimuth.
pub(super) fn sun_vector(altitude: f64, azimuth: f64) -> DVec3 {
    DVec3::new(
        -azimuth.sin() * altitude.cos(),
        -azimuth.cos() * altitude.cos(),
        altitude.sin(),
    )
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum SkyType {
    Clear = 1,
    Overcast = 2,
    Uniform = 3,
    Intermediate = 4,
}

/// A brightness given on the command line: as radiance (`-b`, `-r`) or irradiance (`-B`, `-R`).
#[derive(Clone, Copy, Debug)]
enum Given {
    Computed,
    Radiance(f64),
    Irradiance(f64),
}

struct Options {
    sky: SkyType,
    sun: bool,
    solar: Given,
    zenith: Given,
    turbidity: f64,
    ground_reflectance: f64,
    site: Site,
}

pub(super) fn generate(args: &[String], _dir: &Path) -> Result<String, String> {
    let input = parse_sun_input(args, USAGE, parse_hour)?;
    let zone = match &input {
        SunInput::Date { hour, .. } => hour.meridian_west_deg,
        SunInput::Angles { .. } => None,
    };
    let o = parse_options(&args[3..], zone)?;
    let (mut altitude, azimuth, _) = sun_angles(&input, &o.site)?;
    let overcast = matches!(o.sky, SkyType::Overcast | SkyType::Uniform);
    if !overcast && altitude > MAX_ALTITUDE_DEG.to_radians() {
        altitude = MAX_ALTITUDE_DEG.to_radians();
    }
    Ok(write_sky(&o, altitude, azimuth))
}

fn parse_options(args: &[String], zone_meridian: Option<f64>) -> Result<Options, String> {
    let mut o = Options {
        sky: SkyType::Clear,
        sun: true,
        solar: Given::Computed,
        zenith: Given::Computed,
        turbidity: 2.45,
        ground_reflectance: 0.2,
        site: Site::default(),
    };
    if let Some(m) = zone_meridian {
        o.site.meridian_west_deg = m;
    }
    let mut i = 0;
    while i < args.len() {
        let value = |what: &str| number(args, i + 1, what);
        match args[i].as_str() {
            s @ ("+s" | "-s") => (o.sky, o.sun) = (SkyType::Clear, s == "+s"),
            s @ ("+i" | "-i") => (o.sky, o.sun) = (SkyType::Intermediate, s == "+i"),
            "-c" => o.sky = SkyType::Overcast,
            "-u" => o.sky = SkyType::Uniform,
            "-r" => o.solar = Given::Radiance(value("-r solar radiance")?),
            "-R" => o.solar = Given::Irradiance(value("-R solar irradiance")?),
            "-b" => o.zenith = Given::Radiance(value("-b zenith radiance")?),
            "-B" => o.zenith = Given::Irradiance(value("-B horizontal irradiance")?),
            "-t" => o.turbidity = value("-t turbidity")?,
            "-g" => o.ground_reflectance = value("-g ground reflectance")?,
            "-a" => o.site.latitude_deg = value("-a latitude")?,
            "-o" => o.site.longitude_west_deg = value("-o longitude")?,
            "-m" => {
                let m = value("-m meridian")?;
                if zone_meridian.is_none() {
                    o.site.meridian_west_deg = m;
                }
            }
            "-y" => {
                return Err(
                    "`-y` (the sun for a given year, Michalsky's algorithm) is not \
                            implemented"
                        .into(),
                )
            }
            other => return Err(format!("unknown option `{other}`; usage: {USAGE}")),
        }
        i += if matches!(args[i].as_str(), "+s" | "-s" | "+i" | "-i" | "-c" | "-u") {
            1
        } else {
            2
        };
    }
    Ok(o)
}

/// gensky's `normsc`: the normalisation polynomial in the sun's altitude.
fn normsc(sky: SkyType, altitude: f64) -> f64 {
    const CLEAR: [f64; 5] = [2.766521, 0.547665, -0.369832, 0.009237, 0.059229];
    const INTERMEDIATE: [f64; 5] = [3.5556, -2.7152, -1.3081, 1.0660, 0.60227];
    let c = if sky == SkyType::Intermediate {
        INTERMEDIATE
    } else {
        CLEAR
    };
    let x = (altitude - PI / 4.0) / (PI / 4.0);
    c.iter().rev().fold(0.0, |acc, k| acc * x + k)
}

/// gensky's `computesky` and `printsky`.
fn write_sky(o: &Options, altitude: f64, azimuth: f64) -> String {
    let sun = sun_vector(altitude, azimuth);
    let overcast = matches!(o.sky, SkyType::Overcast | SkyType::Uniform);
    // Horizontal illuminance over zenith luminance, with the gradation F2 (CIE 1973 clear,
    // Matsuura's intermediate sky; gensky.c).
    let (normalisation, f2) = match o.sky {
        SkyType::Uniform => (1.0, 0.0),
        SkyType::Overcast => (0.777778, 0.0),
        SkyType::Clear => {
            let f2 =
                0.274 * (0.91 + 10.0 * (-3.0 * (PI / 2.0 - altitude)).exp() + 0.45 * sun.z * sun.z);
            (normsc(o.sky, altitude) / f2 / PI, f2)
        }
        SkyType::Intermediate => {
            let f2 = (2.739 + 0.9891 * (0.3119 + 2.6 * altitude).sin())
                * (-(PI / 2.0 - altitude) * (0.4441 + 1.48 * altitude)).exp();
            (normsc(o.sky, altitude) / f2 / PI, f2)
        }
    };
    let zenith = match o.zenith {
        Given::Irradiance(e) => e / (normalisation * PI),
        Given::Radiance(l) => l,
        Given::Computed => {
            let mut z = if overcast {
                8.6 * sun.z + 0.123
            } else {
                (1.376 * o.turbidity - 1.81) * altitude.tan() + 0.38
            };
            if o.sky == SkyType::Intermediate {
                z = (z + 8.6 * sun.z + 0.123) / 2.0;
            }
            if z < 0.0 {
                0.0
            } else {
                z * 1000.0 / SKY_EFFICACY
            }
        }
    };
    let mut ground = zenith * normalisation;
    let given_solar = match o.solar {
        Given::Computed => None,
        Given::Radiance(v) | Given::Irradiance(v) => Some(v),
    };
    let mut solar = 0.0;
    let mut with_sun = o.sun;
    if !overcast && sun.z > 0.0 && given_solar.is_none_or(|v| v > 0.0) {
        solar = match o.solar {
            Given::Irradiance(e) => e / (5.98e-5 * sun.z),
            Given::Radiance(l) => l,
            Given::Computed => {
                let b = 1.5e9 / SUN_EFFICACY * (1.147 - 0.147 / sun.z.max(0.16));
                if o.sky == SkyType::Intermediate {
                    b * 0.15
                } else {
                    b
                }
            }
        };
        ground += 6e-5 / PI * solar * sun.z;
    } else {
        with_sun = false;
    }
    ground *= o.ground_reflectance;
    let mut out = String::new();
    if with_sun {
        let s = c_exp(solar, 3);
        let _ = write!(
            out,
            "\nvoid light solar\n0\n0\n3 {s} {s} {s}\n\nsolar source sun\n0\n0\n\
             4 {:.6} {:.6} {:.6} 0.5\n",
            sun.x, sun.y, sun.z
        );
    }
    let _ = write!(out, "\nvoid brightfunc skyfunc\n2 skybr skybright.cal\n0\n");
    if overcast {
        let _ = writeln!(
            out,
            "3 {} {} {}",
            o.sky as u8,
            c_exp(zenith, 3),
            c_exp(ground, 3)
        );
    } else {
        let _ = writeln!(
            out,
            "7 {} {} {} {} {:.6} {:.6} {:.6}",
            o.sky as u8,
            c_exp(zenith, 3),
            c_exp(ground, 3),
            c_exp(f2, 3),
            sun.x,
            sun.y,
            sun.z
        );
    }
    out
}
