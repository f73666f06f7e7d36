//! Every declared shading state of the room's window, every cycle (`[room.window]`): the
//! illuminance per sensor and, for each occupant view, the eye's vertical illuminance and
//! the simplified DGP (Wienold 2009) under each state, from the room's matrices traced once
//! (`skylux_hps::engine::phase::ShadedRoom`). The capture's sky is the measured one: the
//! map's patches with the sun's disk removed, the ground from the model's reflectance, and
//! the extracted sun as a beam through each state at its exact direction. A state switch
//! costs products, not a simulation: the cycle reports what each state would give, which is
//! what a blind controller chooses by.

use crate::config::{Config, StateConfig, ViewConfig};
use crate::cycle::{SensorLux, SetupError};
use crate::views::ViewGlare;
use serde::{Deserialize, Serialize};
use skylux_hps::bsdf::AngleBasis;
use skylux_hps::engine::phase::{
    remove_glazing, sky_vector_from_luminance, KlemsWindow, ShadedRoom, ShadedRoomFiles,
    ShadedRoomSettings, SunBeam,
};
use skylux_hps::engine::{Settings, World, WHITE_EFFICACY_LM_PER_W};
use skylux_hps::glare::metrics::{dgps, LOW_LIGHT_LIMIT_LUX};
use skylux_hps::model::CaptureTerms;
use skylux_hps::scene::{self, Sensor, Shape, SourceLocation};
use skylux_hps::sky::SkyPatches;
use std::path::Path;
use std::sync::Arc;

/// One state of the window in a cycle's record.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct WindowStateRecord {
    pub state: String,
    /// Illuminance per sensor under this state, lux.
    pub illuminance: Vec<SensorLux>,
    /// Per declared view (`[[views]]`), in their order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub views: Vec<StateViewGlare>,
}

/// An occupant view under one state.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct StateViewGlare {
    pub view: String,
    /// Vertical illuminance at the eye, facing the view direction, lux.
    pub ev_lux: f64,
    /// Simplified DGP from `ev_lux` (Wienold 2009).
    pub dgps: f64,
    /// `ev_lux` is below DGP's low-light limit (1000 lx): `dgps` is the formula's floor.
    pub low_light: bool,
    /// The view's fisheye under this state and the measured sky, as `views` has it for the
    /// room as built: the DGP of the picture, or DGPs from the eye's sensor and why when the
    /// cycle had no time left to render.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rendered: Option<ViewGlare>,
}

/// The room's window with its states, its sensors followed by one eye sensor per view.
pub struct WindowStates {
    room: ShadedRoom,
    /// Per state, the room with the state's BSDF as its glazing, for the views' renders
    /// (only when views are declared).
    pub worlds: Vec<World>,
    sensor_names: Vec<String>,
    view_names: Vec<String>,
    mf: usize,
}

impl WindowStates {
    /// None when the room declares no window states; the matrices are read from (or traced
    /// into) `config.cache_dir()`.
    pub fn load(
        config: &Config,
        sensors: &[Sensor],
        progress: &(dyn Fn(u64, u64) + Sync),
    ) -> Result<Option<Self>, SetupError> {
        let Some(w) = &config.room.window else {
            return Ok(None);
        };
        let files = ShadedRoomFiles {
            scenes: config.room.scene.clone(),
            outside: w.outside.clone(),
            window: w.polygons.clone(),
            up: glam::DVec3::from_array(w.up),
            states: w
                .states
                .iter()
                .map(|s| (s.name.clone(), s.bsdf.clone()))
                .collect(),
            load: Default::default(),
        };
        let defaults = ShadedRoomSettings::default();
        let settings = ShadedRoomSettings {
            mf: config.room.mf,
            view: Settings {
                ambient_bounces: config.room.ambient_bounces,
                samples_per_sensor: w.view_paths,
                seed: config.room.seed,
                ..defaults.view
            },
            daylight: Settings {
                samples_per_sensor: w.daylight_rays,
                seed: config.room.seed.wrapping_add(1),
                ..defaults.daylight
            },
            ..defaults
        };
        let mut all = sensors.to_vec();
        all.extend(eye_sensors(&config.views));
        let cache = config.cache_dir();
        let room =
            ShadedRoom::load(&files, &all, &settings, Some(&cache), progress).map_err(|e| {
                SetupError::Cache {
                    path: w.polygons.clone(),
                    message: format!("window states: {e}"),
                }
            })?;
        if let Some((folder, read)) = &room.cache {
            tracing::info!(
                path = %folder.display(),
                read_from_cache = read,
                glazing_left_out = ?room.removed_glazing,
                "window states ready"
            );
        }
        let worlds = if config.views.is_empty() {
            vec![]
        } else {
            w.states
                .iter()
                .map(|s| state_world(config, s))
                .collect::<Result<_, _>>()?
        };
        Ok(Some(WindowStates {
            room,
            worlds,
            sensor_names: sensors.iter().map(|s| s.name.clone()).collect(),
            view_names: config.views.iter().map(|v| v.name.clone()).collect(),
            mf: config.room.mf,
        }))
    }

    /// Every state under the capture's measured sky; an error names what is missing.
    pub fn evaluate(
        &self,
        terms: &CaptureTerms,
        ground_reflectance: f64,
    ) -> Result<Vec<WindowStateRecord>, String> {
        let patches = SkyPatches::reinhart(self.mf).len();
        let measured = terms
            .bins_without_sun_cd_m2
            .get(..patches)
            .ok_or("the capture's sky has fewer patches than the window's matrices")?;
        let ground_cd_m2 = ground_reflectance * terms.outdoor_horizontal_lux / std::f64::consts::PI;
        let sky = sky_vector_from_luminance(measured, ground_cd_m2);
        if !sky.iter().all(|v| v.is_finite()) {
            return Err("the capture's sky holds values that are not finite".into());
        }
        let suns: Vec<SunBeam> = terms
            .sun
            .iter()
            .map(|s| SunBeam {
                direction: s.direction,
                direct_normal_w_m2: s.direct_normal_illuminance_lux / WHITE_EFFICACY_LM_PER_W,
            })
            .collect();
        let lux = self
            .room
            .illuminance_lux(&sky, &suns)
            .map_err(|e| e.to_string())?;
        let n = self.sensor_names.len();
        Ok(self
            .room
            .state_names()
            .into_iter()
            .zip(lux)
            .map(|(state, values)| WindowStateRecord {
                state: state.to_string(),
                illuminance: self
                    .sensor_names
                    .iter()
                    .zip(&values[..n])
                    .map(|(name, &lux)| SensorLux {
                        sensor: name.clone(),
                        lux,
                        stderr_lux: None,
                    })
                    .collect(),
                views: self
                    .view_names
                    .iter()
                    .zip(&values[n..])
                    .map(|(view, &ev_lux)| StateViewGlare {
                        view: view.clone(),
                        ev_lux,
                        dgps: dgps(ev_lux),
                        low_light: ev_lux < LOW_LIGHT_LIMIT_LUX,
                        rendered: None,
                    })
                    .collect(),
            })
            .collect())
    }
}

/// The room with `state`'s BSDF in place of its glazing: the room's scene less what lies in
/// the window's polygons, and those polygons with a `BSDF` of the state's XML (thin, the
/// window's up vector), as RADIANCE would read the room so glazed.
fn state_world(config: &Config, state: &StateConfig) -> Result<World, SetupError> {
    let Some(w) = &config.room.window else {
        return Err(SetupError::Cache {
            path: config.path.clone(),
            message: "no [room.window]".into(),
        });
    };
    let refuse = |message: String| SetupError::Cache {
        path: state.bsdf.clone(),
        message,
    };
    let basis = AngleBasis::builtin("LBNL/Klems Full").ok_or_else(|| refuse("no basis".into()))?;
    let window = KlemsWindow::load(&w.polygons, glam::DVec3::from_array(w.up), basis)
        .map_err(|e| refuse(format!("window: {e}")))?;
    let mut scene = scene::load_files(&config.room.scene)?;
    remove_glazing(&mut scene, &window);
    let xml = state.bsdf.display().to_string();
    if xml.chars().any(char::is_whitespace) {
        return Err(refuse(
            "a BSDF path with white space cannot be written into a RADIANCE scene".into(),
        ));
    }
    let [ux, uy, uz] = w.up;
    let mut text = format!(
        "void BSDF skylux_state
6 0 {xml} {ux} {uy} {uz} .
0
0
"
    );
    for (k, s) in scene::load(&w.polygons)?.surfaces().iter().enumerate() {
        if let Shape::Polygon(p) = &s.shape {
            text.push_str(&format!(
                "skylux_state polygon skylux_state_pane{k}
0
0
{}",
                3 * p.vertices_m.len()
            ));
            for v in &p.vertices_m {
                text.push_str(&format!(" {} {} {}", v.x, v.y, v.z));
            }
            text.push('\n');
        }
    }
    scene.add_bytes(
        format!("[[room.window.states]] {}", state.name),
        text.as_bytes(),
    )?;
    Ok(World::new(&scene)?)
}

/// One sensor per view, at the eye facing the view direction: a 180° view's Ev.
fn eye_sensors(views: &[ViewConfig]) -> Vec<Sensor> {
    let origin = SourceLocation {
        file: Arc::from(Path::new("[[views]]")),
        line: 0,
    };
    views
        .iter()
        .map(|v| {
            let view = v.view();
            Sensor {
                name: format!("eye:{}", v.name),
                position_m: view.position_m,
                direction: view.direction.normalize(),
                origin: origin.clone(),
            }
        })
        .collect()
}
