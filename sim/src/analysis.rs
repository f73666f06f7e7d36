//! Truth-side analysis: what an ideal instrument could achieve, derived from the noise model
//! and the true scene, never from the product's own estimates.

use skylux_hps::camera::DeviceConfig;

/// The noise-limited relative standard deviation of an inverse-variance merge of the
/// exposures `exposures_s` (unity gain) for a group whose true black-subtracted weighted
/// signal rate is `rate_dn_per_s` (`L V / cg`), under the device's noise model: each sample
/// has shot noise `K x` and a floor `σ_r² + 1/12` (read noise and quantisation); a grey
/// group's signal `S = Σ w'_c x_c` has variance `q (K x + floor)` with `q = Σ w'_c²`. Only
/// exposures whose expected sample lies in the valid range count.
pub fn hdr_relative_sigma_bound(
    device: &DeviceConfig,
    exposures_s: &[f64],
    rate_dn_per_s: f64,
) -> Option<f64> {
    let [wr, wg, wb] = device.response.weights;
    let weight_sum = wr + wg + wb;
    let q = wr * wr + 2.0 * (wg / 2.0).powi(2) + wb * wb;
    let floor = device.noise.read_noise_dn.powi(2) + 1.0 / 12.0;
    let black = device.sensor.black_level_dn;
    let mut information = 0.0;
    for &t in exposures_s {
        let x = rate_dn_per_s * t / weight_sum;
        if x + black >= device.sensor.valid_min_dn && x + black <= device.sensor.valid_max_dn {
            let var_s = q * (device.noise.conversion_dn_per_e * x + floor);
            information += t * t / var_s;
        }
    }
    (information > 0.0).then(|| (1.0 / information).sqrt() / rate_dn_per_s)
}
