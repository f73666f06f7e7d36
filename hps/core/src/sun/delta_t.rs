//! ΔT = TT − UT1, the drift of the Earth's rotation against atomic time, estimated from the date.
//!
//! These are the polynomial expressions of Espenak & Meeus (NASA, "Polynomial expressions for
//! Delta T", eclipse.gsfc.nasa.gov/SEcat5/deltatpoly.html, 2006) exactly as pvlib 0.16.1
//! evaluates them in `pvlib.spa.calculate_deltat(year, month)`, so that our positions match
//! pvlib's `spa_python(delta_t=None)` row for row. `solar-positioning`'s own estimator uses
//! Espenak's 2014 update and newer fits from 2015 on; they differ from pvlib's by up to about
//! 80 s by 2100, which moves the sun by up to 0.001°, our whole budget against pvlib
//! (`tests/solar_position.rs` prints the figure). Beyond the present the values are
//! extrapolations (pvlib warns outside −1999..3000).

use super::SunError;

/// First and last year for which the estimate is offered (pvlib warns outside this range).
pub const DELTA_T_YEARS: (i32, i32) = (-1999, 3000);

/// ΔT in seconds for the middle of `month` (1..=12) of `year` (proleptic Gregorian, UTC date),
/// as `pvlib.spa.calculate_deltat`. The year is evaluated at `year + (month − 0.5) / 12`.
pub fn delta_t_s(year: i32, month: u32) -> Result<f64, SunError> {
    if !(1..=12).contains(&month) {
        return Err(SunError::Month { month });
    }
    if year < DELTA_T_YEARS.0 || year > DELTA_T_YEARS.1 {
        return Err(SunError::DeltaTYear { year });
    }
    let y = f64::from(year) + (f64::from(month) - 0.5) / 12.0;
    // The branch is chosen by the integer year, as pvlib does.
    let dt = match year {
        i32::MIN..=-501 => long_term_parabola(y),
        -500..=499 => {
            let u = y / 100.0;
            poly(
                u,
                &[
                    10583.6,
                    -1014.41,
                    33.78311,
                    -5.952053,
                    -0.1798452,
                    0.022174192,
                    0.0090316521,
                ],
            )
        }
        500..=1599 => {
            let u = (y - 1000.0) / 100.0;
            poly(
                u,
                &[
                    1574.2,
                    -556.01,
                    71.23472,
                    0.319781,
                    -0.8503463,
                    -0.005050998,
                    0.0083572073,
                ],
            )
        }
        1600..=1699 => poly(y - 1600.0, &[120.0, -0.9808, -0.01532, 1.0 / 7129.0]),
        1700..=1799 => poly(
            y - 1700.0,
            &[8.83, 0.1603, -0.0059285, 0.00013336, -1.0 / 1_174_000.0],
        ),
        1800..=1859 => poly(
            y - 1800.0,
            &[
                13.72,
                -0.332447,
                0.0068612,
                0.0041116,
                -0.00037436,
                0.0000121272,
                -0.0000001699,
                0.000000000875,
            ],
        ),
        1860..=1899 => poly(
            y - 1860.0,
            &[
                7.62,
                0.5737,
                -0.251754,
                0.01680668,
                -0.0004473624,
                1.0 / 233_174.0,
            ],
        ),
        1900..=1919 => poly(
            y - 1900.0,
            &[-2.79, 1.494119, -0.0598939, 0.0061966, -0.000197],
        ),
        1920..=1940 => poly(y - 1920.0, &[21.20, 0.84493, -0.076100, 0.0020936]),
        1941..=1960 => poly(y - 1950.0, &[29.07, 0.407, -1.0 / 233.0, 1.0 / 2547.0]),
        1961..=1985 => poly(y - 1975.0, &[45.45, 1.067, -1.0 / 260.0, -1.0 / 718.0]),
        1986..=2004 => poly(
            y - 2000.0,
            &[
                63.86,
                0.3345,
                -0.060374,
                0.0017275,
                0.000651814,
                0.00002373599,
            ],
        ),
        2005..=2049 => poly(y - 2000.0, &[62.92, 0.32217, 0.005589]),
        2050..=2149 => long_term_parabola(y) - 0.5628 * (2150.0 - y),
        2150..=i32::MAX => long_term_parabola(y),
    };
    Ok(dt)
}

/// Morrison & Stephenson (2004) long-term parabola, −20 + 32 u², u = (y − 1820) / 100.
fn long_term_parabola(y: f64) -> f64 {
    let u = (y - 1820.0) / 100.0;
    -20.0 + 32.0 * u * u
}

/// c[0] + c[1] t + c[2] t² + ... (Horner).
fn poly(t: f64, c: &[f64]) -> f64 {
    c.iter().rev().fold(0.0, |acc, &ci| acc * t + ci)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_month_and_far_years() {
        assert!(delta_t_s(2000, 0).is_err());
        assert!(delta_t_s(2000, 13).is_err());
        assert!(delta_t_s(3001, 1).is_err());
        assert!(delta_t_s(-2000, 1).is_err());
        assert!(delta_t_s(i32::MAX, 6).is_err());
    }

    /// Espenak & Meeus tabulate ΔT(2000.0) = 63.86 s at the 1986–2005 branch origin; mid-January
    /// 2000 lies 1/24 year later.
    #[test]
    fn branch_origin_value() {
        let dt = delta_t_s(2000, 1).unwrap();
        assert!((dt - 63.86).abs() < 0.02, "{dt}");
    }
}
