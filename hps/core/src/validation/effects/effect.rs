//! What an effect of the loop is: the [`LoopEffect`] interface, the stage it is fitted in,
//! and what a fit is given ([`FitContext`]) and gives back ([`Fitted`]).

use crate::camera::DeviceConfig;
use crate::campaign::Campaign;
use crate::model::{CaptureData, ModelError, Room};
use crate::validation::diagnostics::Variable;
use crate::validation::glazing::AngularGlazing;
use crate::validation::prediction::LoopState;
use crate::validation::sample::Sample;
use crate::validation::sky_colour::CaptureColour;
use crate::validation::sky_geometry::SkyGeometry;
use crate::validation::split::FitSet;
use crate::validation::terms::Terms;
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
#[derive(Clone)]
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
    /// What identified it, which decides where it ranks and how the hold-out set judges it.
    pub found: Found,
}

/// What identified a fitted candidate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Found {
    /// The lux-meters' residual on the fit set: ranked by fit-set error and tested on the
    /// hold-out set as a discovery.
    Residual,
    /// The logger's own series under a free common factor (the clock offset, a nuisance that
    /// changes which readings are compared): tried first, tested as a discovery.
    Series,
    /// The raw frames, without the lux-meters, its parameter then fitted on them (the
    /// spectral mismatch: the frames show the skies' colours, the lux-meters the slope):
    /// tried first, confirmed by a relevant fall
    /// ([`crate::validation::scoring::Verdict::confirming`]).
    FramesIdentified,
    /// The raw frames (and the pyranometer), parameter included (the shutter's overhead, the
    /// baffle's field, the seen ground's reflectance): tried first, confirmed unless the
    /// hold-out set contradicts it. Its false-discovery control is that evidence's own
    /// threshold; it needs no fit-set gain to be tried.
    FramesMeasured,
}

impl Found {
    /// Tried before the candidates ranked by fit-set error.
    pub fn apart(self) -> bool {
        self != Found::Residual
    }

    /// Identified without the lux-meters, so the hold-out set confirms it rather than tests
    /// it.
    pub fn without_luxmeters(self) -> bool {
        matches!(self, Found::FramesIdentified | Found::FramesMeasured)
    }
}
