//! The loop's effect library: each effect is a parametric change to the device model, a fit
//! on the fit set only, and the residual signature that is its evidence. One effect, one file,
//! one line in [`registry::EFFECTS`]; the loop, the report and `skylux sim campaign --effect`
//! read that list.
//!
//! Fits minimise the squared relative residual (prediction / measurement − 1) over the fit
//! set; the linear effects (transmittance, leak, ground) have closed forms
//! ([`fit::fit_linear`]).

pub mod clock_offset;
pub mod fit;
pub mod glazing_angular;
pub mod glazing_transmittance;
pub mod ground_reflectance;
pub mod light_leak;
#[cfg(test)]
pub mod luxmeter_calibration;
pub mod orientation_error;
pub mod registry;
pub mod shutter_overhead;
pub mod sky_outside_fov;
pub mod spectral_mismatch;
pub mod sun_undersampling;
pub mod vignetting;

use super::diagnostics::Variable;
use super::glazing::AngularGlazing;
use super::prediction::LoopState;
use super::sample::Sample;
use super::sky_colour::CaptureColour;
use super::sky_geometry::SkyGeometry;
use super::split::FitSet;
use super::terms::Terms;
use crate::camera::DeviceConfig;
use crate::campaign::Campaign;
use crate::model::{CaptureData, ModelError, Room};
use std::collections::BTreeMap;

/// An effect of the library.
pub trait LoopEffect: Sync {
    /// The effect's one name: its file, its entry in `report.json`, and `--effect NAME=VALUE`
    /// of `skylux sim campaign`.
    fn name(&self) -> &'static str;

    /// Other spellings `skylux sim campaign --effect` accepts (the world parameter's older
    /// names).
    fn aliases(&self) -> &'static [&'static str] {
        &[]
    }

    /// When the loop tries the effect.
    fn stage(&self) -> Stage {
        Stage::Greedy
    }

    /// The effect's part in the joint linear fit, if it is one of the linear effects.
    fn linear(&self) -> Option<Linear> {
        None
    }

    /// The variable whose residual revealed the effect (its figure in the report: the
    /// residual against it, before and after), and how it is read from a diagnostic.
    fn revealing_variable(&self) -> Option<(&'static str, Variable)> {
        None
    }

    /// Fits the effect on the fit set from the loop's current model; `None` where its
    /// signature is absent or the fit leaves the model as it is.
    fn fit(&self, ctx: &mut FitContext<'_>) -> Result<Option<Fitted>, ModelError>;

    /// The effect's reported parameters after an effect added later refitted them (the linear
    /// effects are refitted jointly): read back from `state`.
    fn refresh(&self, _state: &LoopState, _parameters: &mut BTreeMap<String, f64>) {}
}

/// When the loop tries an effect.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// Before the others, judged on its own reference instrument (the sun sightings against
    /// SPA) rather than on the illuminance: the camera's geometry.
    Geometry,
    /// Ranked against the others by fit-set error, added while the hold-out error falls.
    Greedy,
}

/// The linear effects' parameters, fitted jointly ([`fit::fit_linear`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Linear {
    /// A factor on all light through the glazing.
    Glazing,
    /// The reflectance of the ground the lens does not see.
    Ground,
    /// Light proportional to the outdoor illuminance.
    Leak,
}

/// What an effect's fit may read: the loop's current model and data.
pub struct FitContext<'a> {
    pub campaign: &'a Campaign,
    /// Mutable: a fit that moves the sun or the camera traces new sun coefficients.
    pub room: &'a mut Room,
    /// The camera as the loop now holds it.
    pub device: &'a DeviceConfig,
    pub captures: &'a [CaptureData],
    pub state: &'a LoopState,
    /// The effects already added.
    pub accepted: &'a [&'static dyn LoopEffect],
    pub terms: &'a [Terms],
    /// The terms without the sky effects, and where each bin's light came from in the
    /// camera: what the sky effects rescale.
    pub sky_raw: &'a [Terms],
    pub sky_geometry: &'a SkyGeometry,
    pub fit: &'a FitSet<Sample>,
    /// Per capture, the pyranometer's outdoor horizontal illuminance, lux.
    pub reference_outdoor: &'a [Option<f64>],
    /// The glazing's angular model, where the glazing faces one way.
    pub angular: Option<&'a AngularGlazing>,
    /// Per capture, the sky's colour from the raw frames.
    pub colours: &'a [CaptureColour],
}

/// A fitted candidate: the model with the effect, its fit-set error, and what the effect
/// changed beyond the model's parameters.
pub struct Fitted {
    pub state: LoopState,
    pub parameters: BTreeMap<String, f64>,
    pub evidence: String,
    pub fit_error: f64,
    /// New terms, for an effect that acts on the terms.
    pub terms: Option<Vec<Terms>>,
    /// Re-merged captures, for an effect on the exposures.
    pub captures: Option<Vec<CaptureData>>,
    /// A new camera, for an effect on its geometry.
    pub device: Option<DeviceConfig>,
}
