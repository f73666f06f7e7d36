//! The glare indices from the sources and the field of view, in evalglare's forms (its
//! defaults: DGP coefficients of Wienold & Christoffersen, background luminance from the
//! vertical illuminance less the sources' direct part).

use std::f64::consts::PI;

/// What each index needs of a glare source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SourceTerms {
    pub luminance_cd_m2: f64,
    pub solid_angle_sr: f64,
    pub position_index: f64,
}

impl SourceTerms {
    /// L² ω / P², the sum shared by DGP, UGR and CGI.
    fn contrast(&self) -> f64 {
        (self.luminance_cd_m2 / self.position_index).powi(2) * self.solid_angle_sr
    }
}

/// Daylight glare probability (Wienold & Christoffersen, "Evaluation methods and development
/// of a new glare prediction model for daylight environments with the use of CCD cameras",
/// Energy and Buildings 38 (2006) 743-757, with evalglare's coefficients):
/// DGP = 5.87·10⁻⁵ Ev + 0.092 log10(1 + Σ L² ω / (Ev^1.87 P²)) + 0.159, at most 1.
pub fn dgp(ev_lux: f64, sources: &[SourceTerms]) -> f64 {
    let base = 5.87e-5 * ev_lux + 0.159;
    let dgp = if sources.is_empty() {
        base
    } else {
        let sum: f64 = sources.iter().map(SourceTerms::contrast).sum();
        base + 0.092 * (1.0 + sum / ev_lux.powf(1.87)).log10()
    };
    dgp.min(1.0)
}

/// Simplified daylight glare probability from the vertical eye illuminance alone (Wienold,
/// "Dynamic daylight glare evaluation", Building Simulation 2009, Glasgow, 944-951):
/// DGPs = 6.22·10⁻⁵ Ev + 0.184, at most 1. Valid where no direct sun or specular reflection
/// of it reaches the eye; the fallback when there is no time to render the view.
pub fn dgps(ev_lux: f64) -> f64 {
    (6.22e-5 * ev_lux + 0.184).min(1.0)
}

/// Below this vertical eye illuminance DGP needs its low-light correction (Wienold, "Dynamic
/// daylight glare evaluation", Building Simulation 2009): the uncorrected formula's floor of
/// 0.159 is not a glare probability there.
pub const LOW_LIGHT_LIMIT_LUX: f64 = 1000.0;

/// The low-light correction factor of DGP (Wienold, "Dynamic daylight glare evaluation",
/// Building Simulation 2009): e^(0.024 Ev − 4) / (1 + e^(0.024 Ev − 4)) below 1000 lx, else 1.
pub fn low_light_factor(ev_lux: f64) -> f64 {
    if ev_lux < LOW_LIGHT_LIMIT_LUX {
        let e = (0.024 * ev_lux - 4.0).exp();
        e / (1.0 + e)
    } else {
        1.0
    }
}

/// Daylight glare index (Hopkinson 1972; Chauvel et al., "Glare from windows: current views
/// of the problem", Lighting Research & Technology 14 (1982) 31-46), as evalglare sums it over
/// sources: DGI = 10 log10 Σ 0.478 L^1.6 (ω/P²)^0.8 / (Lb + 0.07 ω^0.5 L).
pub fn dgi(background_cd_m2: f64, sources: &[SourceTerms]) -> f64 {
    let sum: f64 = sources
        .iter()
        .map(|s| {
            let weighted_omega = s.solid_angle_sr / (s.position_index * s.position_index);
            0.478 * s.luminance_cd_m2.powf(1.6) * weighted_omega.powf(0.8)
                / (background_cd_m2 + 0.07 * s.solid_angle_sr.sqrt() * s.luminance_cd_m2)
        })
        .sum();
    10.0 * sum.log10()
}

/// Unified glare rating (CIE 117-1995): UGR = 8 log10(0.25 / Lb Σ L² ω / P²); None when the
/// background is dark (evalglare prints −99 then).
pub fn ugr(background_cd_m2: f64, sources: &[SourceTerms]) -> Option<f64> {
    if background_cd_m2 <= 0.0 {
        return None;
    }
    let sum: f64 = sources.iter().map(SourceTerms::contrast).sum();
    Some(if sum == 0.0 {
        0.0
    } else {
        8.0 * (0.25 / background_cd_m2 * sum).log10()
    })
}

/// CIE glare index (Einhorn, "Discomfort glare: a formula to bridge differences", Lighting
/// Research & Technology 11 (1979) 90-94): CGI = 8 log10(2 (1 + Ed/500) / Ev Σ L² ω / P²),
/// Ed the sources' direct vertical illuminance.
pub fn cgi(ev_lux: f64, ev_direct_lux: f64, sources: &[SourceTerms]) -> f64 {
    let sum: f64 = sources.iter().map(SourceTerms::contrast).sum();
    8.0 * (2.0 * (1.0 + ev_direct_lux / 500.0) / ev_lux * sum).log10()
}

/// Discomfort glare rating of the VCP method (Guth, "Computing visual comfort ratings for a
/// specific interior lighting installation", Illuminating Engineering 61 (1966) 634-642):
/// DGR = (Σ 0.5 L Q / (P F^0.44))^(n^−0.0914), Q = 20.4 ω + 1.52 ω^0.2 − 0.075, F the mean
/// luminance of the field of view.
pub fn dgr(average_cd_m2: f64, sources: &[SourceTerms]) -> f64 {
    let sum: f64 = sources
        .iter()
        .map(|s| {
            let q = 20.4 * s.solid_angle_sr + 1.52 * s.solid_angle_sr.powf(0.2) - 0.075;
            0.5 * s.luminance_cd_m2 * q / (s.position_index * average_cd_m2.powf(0.44))
        })
        .sum();
    sum.powf((sources.len() as f64).powf(-0.0914))
}

/// Visual comfort probability, % (IES, Guth 1966): 50 erf((6.374 − 1.3227 ln DGR) / √2) + 50,
/// 100 below DGR 20 and 0 above 750 as evalglare bounds it.
pub fn vcp(dgr: f64) -> f64 {
    if dgr > 750.0 {
        0.0
    } else if dgr < 20.0 {
        100.0
    } else {
        50.0 * libm::erf((6.374 - 1.3227 * dgr.ln()) / std::f64::consts::SQRT_2) + 50.0
    }
}

/// Background luminance as evalglare takes it by default: the vertical illuminance less the
/// sources' direct part, over π, cd/m².
pub fn background_luminance_cd_m2(ev_lux: f64, ev_direct_lux: f64) -> f64 {
    (ev_lux - ev_direct_lux) / PI
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dgps_is_wienolds_line_and_saturates() {
        // Wienold 2009: DGPs 0.35 (the "perceptible" class limit) at Ev = 0.166 / 6.22e-5.
        assert!((dgps(0.166 / 6.22e-5) - 0.35).abs() < 1e-12);
        assert!((dgps(0.0) - 0.184).abs() < 1e-12);
        assert_eq!(dgps(1e6), 1.0);
    }
}
