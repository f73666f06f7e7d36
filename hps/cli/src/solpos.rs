//! `skylux solpos`: where the sun is for one time and place (NREL SPA, `skylux_hps::sun`).

use skylux_hps::sun::{parse_time_utc, solar_position, Atmosphere, Site, SunError};
use std::io::Write;

#[derive(clap::Args)]
#[command(after_help = "\
Output (CSV on stdout): a header line `zenith_deg,azimuth_deg`, then one line of values in \
degrees with 6 decimals. Azimuth is from north towards east (east = 90, south = 180). The zenith \
is apparent (refracted) unless --no-refraction is given. Delta T is estimated from the date as \
pvlib's calculate_deltat does.")]
pub struct SolposArgs {
    /// Latitude in degrees, north positive, within [-90, 90].
    #[arg(long, allow_negative_numbers = true)]
    lat: f64,
    /// Longitude in degrees, east positive, within [-180, 180].
    #[arg(long, allow_negative_numbers = true)]
    lon: f64,
    /// The instant, RFC 3339 with an explicit UTC offset, e.g. 2017-05-08T10:00:00+02:00.
    #[arg(long)]
    time: String,
    /// Height above sea level in metres.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    elevation: f64,
    /// Station pressure in hPa, for refraction [default: the standard atmosphere at --elevation].
    #[arg(long, allow_negative_numbers = true)]
    pressure: Option<f64>,
    /// Air temperature in °C, for refraction.
    #[arg(long, default_value_t = Atmosphere::DEFAULT_TEMPERATURE_C, allow_negative_numbers = true)]
    temp: f64,
    /// Give the geometric zenith, without atmospheric refraction.
    #[arg(long)]
    no_refraction: bool,
}

pub fn run(args: &SolposArgs) -> anyhow::Result<()> {
    let time = parse_time_utc(&args.time).map_err(|e| anyhow::anyhow!("--time: {e}"))?;
    let site = Site {
        latitude_deg: args.lat,
        longitude_deg: args.lon,
        elevation_m: args.elevation,
    };
    let air = Atmosphere {
        pressure_hpa: args
            .pressure
            .unwrap_or_else(|| Atmosphere::standard_at(args.elevation).pressure_hpa),
        temperature_c: args.temp,
    };
    let refraction = (!args.no_refraction).then_some(&air);
    let p = solar_position(time, &site, refraction).map_err(|e| {
        let option = match e {
            SunError::Latitude { .. } => "--lat",
            SunError::Longitude { .. } => "--lon",
            SunError::Elevation { .. } => "--elevation",
            SunError::Pressure { .. } => "--pressure",
            SunError::Temperature { .. } => "--temp",
            _ => "--time",
        };
        anyhow::anyhow!("{option}: {e}")
    })?;
    // Written, not println!-ed: a closed stdout is an error to report, not a panic.
    let mut out = std::io::stdout().lock();
    writeln!(out, "zenith_deg,azimuth_deg")?;
    writeln!(out, "{:.6},{:.6}", p.zenith_deg, p.azimuth_deg)?;
    Ok(())
}
