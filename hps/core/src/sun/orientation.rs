//! The camera's orientation from the sun: image positions of the sun over a day against its
//! computed positions (NREL SPA), fitted as Wahba's problem with Davenport's q-method (the
//! optimal rotation is the eigenvector of the largest eigenvalue of the 4x4 matrix K; Markley
//! & Crassidis, "Fundamentals of Spacecraft Attitude Determination and Control", 2014, §5.5).
//! Unlike a polar decomposition it stays well posed when the directions are coplanar (a day
//! of sun at the equinox traces a great circle).

use crate::camera::{orientation_from_rotation, DeviceConfig, ImagePoint, OrientationConfig};
use glam::{DMat3, DVec3};

/// One sun sighting: where the sun's centroid is on the image, and where SPA puts it.
#[derive(Copy, Clone, Debug)]
pub struct SunObservation {
    pub image_point: ImagePoint,
    /// Unit vector towards the sun, world frame (+x east, +y north, +z up).
    pub sun_direction: DVec3,
}

/// The fitted orientation and how well it explains the sightings.
#[derive(Clone, Debug)]
pub struct OrientationFit {
    pub orientation: OrientationConfig,
    /// Angle between each sighting and the fitted model's prediction, degrees.
    pub residuals_deg: Vec<f64>,
    pub residual_rms_deg: f64,
    pub residual_max_deg: f64,
}

/// Why no orientation could be fitted.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OrientationError {
    #[error("{0} sightings: at least 2 in different directions are needed")]
    TooFew(usize),
    #[error("sighting {0}: image point ({1:.1}, {2:.1}) is outside the lens model")]
    OutsideLens(usize, f64, f64),
    #[error("sighting {0}: the sun direction is not a finite non-zero vector")]
    BadDirection(usize),
    #[error("the sightings are (nearly) parallel: the rotation about them is undetermined")]
    Degenerate,
}

/// Fits the orientation (the lens and principal point of `device` are held fixed).
pub fn fit_orientation(
    device: &DeviceConfig,
    sightings: &[SunObservation],
) -> Result<OrientationFit, OrientationError> {
    if sightings.len() < 2 {
        return Err(OrientationError::TooFew(sightings.len()));
    }
    let camera = crate::camera::CameraModel::new(device.clone());
    let mut pairs = Vec::with_capacity(sightings.len());
    for (i, s) in sightings.iter().enumerate() {
        let c =
            camera
                .unproject_camera_frame(s.image_point)
                .ok_or(OrientationError::OutsideLens(
                    i,
                    s.image_point.x_px,
                    s.image_point.y_px,
                ))?;
        let w = s.sun_direction;
        if !w.is_finite() || w.length() < 1e-12 {
            return Err(OrientationError::BadDirection(i));
        }
        pairs.push((c, w.normalize()));
    }
    let rotation = davenport(&pairs)?;
    let residuals_deg: Vec<f64> = pairs
        .iter()
        .map(|(c, w)| angle_deg(rotation * *w, *c))
        .collect();
    let rms =
        (residuals_deg.iter().map(|r| r * r).sum::<f64>() / residuals_deg.len() as f64).sqrt();
    let max = residuals_deg.iter().cloned().fold(0.0, f64::max);
    Ok(OrientationFit {
        orientation: orientation_from_rotation(rotation),
        residuals_deg,
        residual_rms_deg: rms,
        residual_max_deg: max,
    })
}

/// How far from the declared azimuth [`fit_azimuth`] searches, degrees: a compass read
/// beside a steel frame, or a mount turned on its bracket, is off by degrees, not by tens of
/// them (the battery's orientation errors are 2-10°, `sim/src/battery.rs`).
pub const AZIMUTH_SEARCH_DEG: f64 = 45.0;

/// Fits the camera's azimuth alone (its tilt and roll held as declared): a camera levelled on
/// its mount but turned about the vertical, the error a compass leaves. One sighting gives
/// two equations for this one unknown, so a day with the sun seen once or twice, or a few
/// sightings close together (where [`fit_orientation`]'s three angles are undetermined),
/// still fits it, and its residual tells whether a turn about the vertical explains them.
pub fn fit_azimuth(
    device: &DeviceConfig,
    sightings: &[SunObservation],
) -> Result<OrientationFit, OrientationError> {
    if sightings.is_empty() {
        return Err(OrientationError::TooFew(0));
    }
    for (i, s) in sightings.iter().enumerate() {
        if !s.sun_direction.is_finite() || s.sun_direction.length() < 1e-12 {
            return Err(OrientationError::BadDirection(i));
        }
    }
    let turned = |delta_deg: f64| {
        let mut d = device.clone();
        d.orientation.axis_azimuth_deg =
            (device.orientation.axis_azimuth_deg + delta_deg).rem_euclid(360.0);
        d
    };
    // The angle between each sighting, seen by the camera turned by `delta_deg`, and SPA.
    let residuals = |delta_deg: f64| -> Result<Vec<f64>, OrientationError> {
        let camera = crate::camera::CameraModel::new(turned(delta_deg));
        sightings
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let seen = camera
                    .unproject(s.image_point)
                    .ok_or(OrientationError::OutsideLens(
                        i,
                        s.image_point.x_px,
                        s.image_point.y_px,
                    ))?;
                Ok(angle_deg(seen, s.sun_direction.normalize()))
            })
            .collect()
    };
    let cost = |delta_deg: f64| -> Result<f64, OrientationError> {
        Ok(residuals(delta_deg)?.iter().map(|r| r * r).sum())
    };
    // A scan at 0.25° finds the basin (the cost is smooth, one minimum within the search for
    // sightings inside the lens), a golden-section search the minimum to 1e-6°.
    let step = 0.25;
    let mut best = (0.0, cost(0.0)?);
    let n = (AZIMUTH_SEARCH_DEG / step) as i32;
    for k in -n..=n {
        let delta = k as f64 * step;
        let c = cost(delta)?;
        if c < best.1 {
            best = (delta, c);
        }
    }
    let (mut a, mut b) = (best.0 - step, best.0 + step);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    while b - a > 1e-6 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if cost(x1)? < cost(x2)? {
            b = x2;
        } else {
            a = x1;
        }
    }
    let delta = 0.5 * (a + b);
    let residuals_deg = residuals(delta)?;
    let rms =
        (residuals_deg.iter().map(|r| r * r).sum::<f64>() / residuals_deg.len() as f64).sqrt();
    let max = residuals_deg.iter().cloned().fold(0.0, f64::max);
    Ok(OrientationFit {
        orientation: turned(delta).orientation,
        residuals_deg,
        residual_rms_deg: rms,
        residual_max_deg: max,
    })
}

fn angle_deg(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// The rotation A (world to camera) minimising Σ |c_i − A w_i|² (Wahba), by the q-method.
fn davenport(pairs: &[(DVec3, DVec3)]) -> Result<DMat3, OrientationError> {
    // B = Σ c w^T (attitude profile matrix), indexed b[row][col].
    let mut b = [[0.0f64; 3]; 3];
    for (c, w) in pairs {
        let (c, w) = (c.to_array(), w.to_array());
        for (i, row) in b.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v += c[i] * w[j];
            }
        }
    }
    let sigma = b[0][0] + b[1][1] + b[2][2];
    let z = [b[1][2] - b[2][1], b[2][0] - b[0][2], b[0][1] - b[1][0]];
    let mut k = [[0.0f64; 4]; 4];
    for i in 0..3 {
        for j in 0..3 {
            k[i][j] = b[i][j] + b[j][i] - if i == j { sigma } else { 0.0 };
        }
        k[i][3] = z[i];
        k[3][i] = z[i];
    }
    k[3][3] = sigma;
    let (values, vectors) = jacobi_eigen(k);
    let mut order = [0usize, 1, 2, 3];
    order.sort_by(|&a, &b| values[b].total_cmp(&values[a]));
    // A unique optimum needs a gap between the two largest eigenvalues.
    if values[order[0]] - values[order[1]] < 1e-9 * values[order[0]].abs().max(1e-300) {
        return Err(OrientationError::Degenerate);
    }
    let q: [f64; 4] = std::array::from_fn(|i| vectors[i][order[0]]);
    let (qv, q4) = (DVec3::new(q[0], q[1], q[2]), q[3]);
    // A(q) = (q4² − |qv|²) I + 2 qv qv^T − 2 q4 [qv×]  (Markley & Crassidis eq. 2.125).
    let cross = DMat3::from_cols(
        DVec3::new(0.0, qv.z, -qv.y),
        DVec3::new(-qv.z, 0.0, qv.x),
        DVec3::new(qv.y, -qv.x, 0.0),
    );
    let outer = DMat3::from_cols(qv * qv.x, qv * qv.y, qv * qv.z);
    Ok(DMat3::IDENTITY * (q4 * q4 - qv.length_squared()) + outer * 2.0 - cross * (2.0 * q4))
}

/// Eigenvalues and eigenvectors (columns) of a symmetric 4x4 matrix, by cyclic Jacobi rotations.
fn jacobi_eigen(mut a: [[f64; 4]; 4]) -> ([f64; 4], [[f64; 4]; 4]) {
    let mut v = [[0.0f64; 4]; 4];
    for (i, row) in v.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for _sweep in 0..64 {
        let off: f64 = (0..4)
            .flat_map(|i| (0..4).filter(move |&j| j != i).map(move |j| (i, j)))
            .map(|(i, j)| a[i][j] * a[i][j])
            .sum();
        if off < 1e-30 {
            break;
        }
        for p in 0..3 {
            for q in p + 1..4 {
                if a[p][q].abs() < 1e-300 {
                    continue;
                }
                let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
                let t = if theta == 0.0 { 1.0 } else { t };
                let c = 1.0 / (t * t + 1.0).sqrt();
                let s = t * c;
                for row in a.iter_mut() {
                    let (akp, akq) = (row[p], row[q]);
                    row[p] = c * akp - s * akq;
                    row[q] = s * akp + c * akq;
                }
                #[allow(clippy::needless_range_loop)] // rows p and q are updated together
                for k in 0..4 {
                    let (apk, aqk) = (a[p][k], a[q][k]);
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for row in v.iter_mut() {
                    let (vkp, vkq) = (row[p], row[q]);
                    row[p] = c * vkp - s * vkq;
                    row[q] = s * vkp + c * vkq;
                }
            }
        }
    }
    ([a[0][0], a[1][1], a[2][2], a[3][3]], v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::{direction_from_alt_az, CameraModel};

    /// Known orientations are recovered exactly from noiseless sightings, including from
    /// coplanar directions.
    #[test]
    fn recovers_known_orientations() {
        for (az, alt, roll) in [
            (0.0, 90.0, 0.0),
            (180.0, 16.0, 0.0),
            (37.0, 88.2, 3.0),
            (250.0, 45.0, -20.0),
            (90.0, 60.0, 170.0),
        ] {
            let device = DeviceConfig {
                orientation: OrientationConfig {
                    axis_azimuth_deg: az,
                    axis_altitude_deg: alt,
                    roll_deg: roll,
                },
                ..DeviceConfig::default()
            };
            let truth = CameraModel::new(device.clone());
            let axis = truth.axis();
            // Directions within 50° of the axis, some coplanar.
            let sightings: Vec<SunObservation> = (0..12)
                .filter_map(|k| {
                    let (a, b) = (k as f64 * 0.5, (k % 3) as f64 * 0.3 - 0.3);
                    let d = (axis
                        + truth.world_to_camera.row(0) * a.sin() * 0.6
                        + truth.world_to_camera.row(1) * b)
                        .normalize();
                    truth.project(d).map(|p| SunObservation {
                        image_point: p,
                        sun_direction: d,
                    })
                })
                .collect();
            let mut wrong = device.clone();
            wrong.orientation = OrientationConfig {
                axis_azimuth_deg: 0.0,
                axis_altitude_deg: 90.0,
                roll_deg: 0.0,
            };
            let fit = fit_orientation(&wrong, &sightings).unwrap();
            let fitted = CameraModel::new(DeviceConfig {
                orientation: fit.orientation.clone(),
                ..device.clone()
            });
            let err = angle_deg(fitted.axis(), axis).max(angle_deg(
                fitted.world_to_camera.row(0),
                truth.world_to_camera.row(0),
            ));
            assert!(
                err < 1e-9,
                "az {az} alt {alt} roll {roll}: {err} deg, fit {:?}",
                fit.orientation
            );
            assert!(fit.residual_max_deg < 1e-9);
        }
        let _ = direction_from_alt_az(0.0, 0.0);
    }

    /// A camera turned about the vertical is recovered from a single sighting, and a sighting
    /// no turn explains (the sun seen higher than SPA puts it) keeps a residual.
    #[test]
    fn one_sighting_fits_the_azimuth_of_a_levelled_camera() {
        for turn_deg in [-9.85, -3.0, 0.4, 6.41] {
            let truth = DeviceConfig {
                orientation: OrientationConfig {
                    axis_azimuth_deg: 195.0 + turn_deg,
                    axis_altitude_deg: 18.0,
                    roll_deg: 0.0,
                },
                ..DeviceConfig::default()
            };
            let mut declared = truth.clone();
            declared.orientation.axis_azimuth_deg = 195.0;
            let sun = direction_from_alt_az(22.7, 160.0);
            let p = CameraModel::new(truth.clone()).project(sun).unwrap();
            let one = [SunObservation {
                image_point: p,
                sun_direction: sun,
            }];
            let fit = fit_azimuth(&declared, &one).unwrap();
            let err = fit.orientation.axis_azimuth_deg - truth.orientation.axis_azimuth_deg;
            assert!(err.abs() < 1e-4, "turn {turn_deg}: fitted off by {err}°");
            assert!(fit.residual_max_deg < 1e-4, "{fit:?}");
            assert_eq!(fit.orientation.axis_altitude_deg, 18.0);
            // The same image point, but SPA's sun 5° higher: a turn cannot explain it.
            let higher = [SunObservation {
                image_point: p,
                sun_direction: direction_from_alt_az(27.7, 160.0),
            }];
            let fit = fit_azimuth(&declared, &higher).unwrap();
            assert!(fit.residual_rms_deg > 4.0, "{fit:?}");
        }
        assert_eq!(
            fit_azimuth(&DeviceConfig::default(), &[]).unwrap_err(),
            OrientationError::TooFew(0)
        );
    }

    #[test]
    fn refuses_what_cannot_be_fitted() {
        let d = DeviceConfig::default();
        let p = ImagePoint {
            x_px: 1296.0,
            y_px: 972.0,
        };
        assert_eq!(
            fit_orientation(&d, &[]).unwrap_err(),
            OrientationError::TooFew(0)
        );
        let same = SunObservation {
            image_point: p,
            sun_direction: DVec3::Z,
        };
        assert_eq!(
            fit_orientation(&d, &[same, same, same]).unwrap_err(),
            OrientationError::Degenerate
        );
        let nan = SunObservation {
            image_point: p,
            sun_direction: DVec3::NAN,
        };
        assert_eq!(
            fit_orientation(&d, &[same, nan]).unwrap_err(),
            OrientationError::BadDirection(1)
        );
    }
}
