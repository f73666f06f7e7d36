//! A room whose window declares shading states, from its files: the room's scene (its glazing
//! taken out where the window file lies: the states stand in for it), the outside, the
//! window and each state's XML. The room's matrices are cached in a folder under a key of
//! the expanded scenes, the sensors and the settings, so that the next run (the next capture,
//! the next sky) costs the products only.

use super::scene_sky::SunBeam;
use super::shading_states::{remove_glazing, ShadedWindow, ShadingState, StateMatrices, SunView};
use super::window::{KlemsWindow, WindowError};
use crate::bsdf::{AngleBasis, BsdfError};
use crate::engine::error::EngineError;
use crate::engine::integrator::Settings;
use crate::engine::world::World;
use crate::engine::WHITE_EFFICACY_LM_PER_W;
use crate::numerics::fnv::{fnv1a, FNV1A_OFFSET};
use crate::scene::{self, LoadOptions, Scene, SceneError, Sensor, Shape};
use glam::DVec3;
use std::path::{Path, PathBuf};

/// Changes whenever the matrices' meaning or files change.
const CACHE_VERSION: &str = "skylux shading-state matrices 1";

/// What a shaded room is made of.
#[derive(Debug, Clone)]
pub struct ShadedRoomFiles {
    /// The room's scene files (its glazing may be in them: it is taken out).
    pub scenes: Vec<PathBuf>,
    /// Geometry outside the room (neighbours, overhangs) that D and the sun see.
    pub outside: Vec<PathBuf>,
    /// The window's polygons, front normal into the room (`rfluxmtx`'s receiver).
    pub window: PathBuf,
    /// The up vector of the window's Klems frame (and of its BSDFs).
    pub up: DVec3,
    /// Each state's name and BSDF XML, in the order results are given.
    pub states: Vec<(String, PathBuf)>,
    pub load: LoadOptions,
}

/// How the room's matrices are traced.
#[derive(Debug, Clone, Copy)]
pub struct ShadedRoomSettings {
    /// Reinhart multiplication factor of D's sky patches.
    pub mf: usize,
    /// V's paths per sensor and bounces (a clear glazing puts the sun's beam into one Klems
    /// patch: its interreflection then rests on one entry of V, which needs many paths).
    pub view: Settings,
    /// D's rays per window patch and bounces outside.
    pub daylight: Settings,
    /// The sun's direct view: points per side of the window's grid.
    pub sun_points_per_side: usize,
}

impl Default for ShadedRoomSettings {
    fn default() -> Self {
        ShadedRoomSettings {
            mf: 4,
            view: Settings {
                ambient_bounces: crate::engine::integrator::CONVERGED_AMBIENT_BOUNCES,
                samples_per_sensor: 262_144,
                seed: 1,
                ..Settings::default()
            },
            daylight: Settings {
                ambient_bounces: 2,
                samples_per_sensor: 4096,
                seed: 2,
                ..Settings::default()
            },
            sun_points_per_side: 32,
        }
    }
}

/// Why a shaded room cannot be built.
#[derive(Debug, thiserror::Error)]
pub enum ShadedRoomError {
    #[error("{0}")]
    Scene(#[from] SceneError),
    #[error("window: {0}")]
    Window(#[from] WindowError),
    #[error("state {state}: {source}")]
    State { state: String, source: BsdfError },
    #[error("{0}")]
    Engine(#[from] EngineError),
    #[error("{path}: {message}")]
    Cache { path: PathBuf, message: String },
    #[error("{0}")]
    Declaration(String),
}

/// The room, its window's states, and the world the sun crosses to the window.
#[derive(Debug)]
pub struct ShadedRoom {
    shaded: ShadedWindow,
    outside: World,
    /// The surfaces taken out of the room as the window's glazing.
    pub removed_glazing: Vec<String>,
    /// Where the matrices are cached, and whether they were read from there.
    pub cache: Option<(PathBuf, bool)>,
}

impl ShadedRoom {
    /// Loads the files, reads the matrices from `cache_dir` or traces (and caches) them.
    pub fn load(
        files: &ShadedRoomFiles,
        sensors: &[Sensor],
        settings: &ShadedRoomSettings,
        cache_dir: Option<&Path>,
        progress: &(dyn Fn(u64, u64) + Sync),
    ) -> Result<Self, ShadedRoomError> {
        check_states(&files.states)?;
        let basis = AngleBasis::builtin("LBNL/Klems Full")
            .ok_or_else(|| ShadedRoomError::Declaration("no Klems full basis".into()))?;
        let window = KlemsWindow::load(&files.window, files.up, basis)?;
        let mut room_scene = scene::load_files_with(&files.scenes, &files.load)?;
        let removed_glazing = remove_glazing(&mut room_scene, &window);
        let mut outside_scene = room_scene.clone();
        for f in &files.outside {
            outside_scene.add_file_with(f, &files.load)?;
        }
        let room = room_only(&room_scene)?;
        let outside = room_only(&outside_scene)?;
        let key = cache_key(&room_scene, &outside_scene, sensors, files, settings);
        let folder = cache_dir.map(|d| d.join(format!("states-{key:016x}")));
        let cached = folder.as_deref().and_then(|f| StateMatrices::read(f).ok());
        let from_cache = cached.is_some();
        let matrices = match cached {
            Some(m) => m,
            None => {
                let m = StateMatrices::trace(
                    &room,
                    &outside,
                    sensors,
                    &window,
                    settings.mf,
                    &settings.view,
                    &settings.daylight,
                    progress,
                )?;
                if let Some(f) = &folder {
                    write_cache(&m, f, files, settings)?;
                }
                m
            }
        };
        let states = files
            .states
            .iter()
            .map(|(name, xml)| {
                ShadingState::load(name, xml, &window).map_err(|source| ShadedRoomError::State {
                    state: name.clone(),
                    source,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        let sun_view = SunView::new(&room, sensors, &window, settings.sun_points_per_side);
        let shaded = ShadedWindow::new(window, settings.mf, states, &matrices, sun_view)?;
        Ok(ShadedRoom {
            shaded,
            outside,
            removed_glazing,
            cache: folder.map(|f| (f, from_cache)),
        })
    }

    pub fn state_names(&self) -> Vec<&str> {
        self.shaded.state_names()
    }

    /// Illuminance per state and sensor, lux, under the sky vector `sky` (ground, then the
    /// Reinhart patches, radiance W/(m² sr)) and the `suns`.
    pub fn illuminance_lux(
        &self,
        sky: &[f64],
        suns: &[SunBeam],
    ) -> Result<Vec<Vec<f64>>, EngineError> {
        Ok(self
            .shaded
            .irradiance_w_m2(sky, suns, &self.outside)?
            .into_iter()
            .map(|state| {
                state
                    .into_iter()
                    .map(|e| WHITE_EFFICACY_LM_PER_W * e)
                    .collect()
            })
            .collect())
    }
}

/// Names: one or more, each of letters, digits, `-` and `_` (they name output columns and
/// files), no two alike.
fn check_states(states: &[(String, PathBuf)]) -> Result<(), ShadedRoomError> {
    if states.is_empty() {
        return Err(ShadedRoomError::Declaration(
            "no shading state: declare at least one (name and BSDF XML)".into(),
        ));
    }
    for (k, (name, _)) in states.iter().enumerate() {
        let ok = !name.is_empty()
            && name.len() <= 64
            && name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if !ok {
            return Err(ShadedRoomError::Declaration(format!(
                "state name {name:?}: 1 to 64 letters, digits, `-` or `_`"
            )));
        }
        if states[..k].iter().any(|(n, _)| n == name) {
            return Err(ShadedRoomError::Declaration(format!(
                "state {name:?} declared twice"
            )));
        }
    }
    Ok(())
}

/// The world of `scene` without its sky, sun or environment.
fn room_only(scene: &Scene) -> Result<World, EngineError> {
    let mut world = World::new(scene)?;
    world.clear_distant();
    world.set_environment(None);
    Ok(world)
}

/// FNV-1a of what the matrices depend on: the expanded scenes' surfaces and their materials
/// (so that a file an `!xform` includes counts), the sensors, the window and the settings. The states do not enter:
/// changing one costs no retrace.
fn cache_key(
    room: &Scene,
    outside: &Scene,
    sensors: &[Sensor],
    files: &ShadedRoomFiles,
    settings: &ShadedRoomSettings,
) -> u64 {
    let mut h = FNV1A_OFFSET;
    fnv1a(&mut h, CACHE_VERSION.as_bytes());
    // The geometry and its materials, not the sky: a scene file may hold the sky too, and
    // another sky needs no retrace.
    for scene in [room, outside] {
        for s in scene.surfaces() {
            if !matches!(s.shape, Shape::Source(_)) {
                fnv1a(&mut h, format!("{s:?}").as_bytes());
                fnv1a(
                    &mut h,
                    format!("{:?}", scene.material(s.modifier)).as_bytes(),
                );
            }
        }
    }
    for s in sensors {
        for v in [s.position_m, s.direction] {
            v.to_array()
                .iter()
                .for_each(|x| fnv1a(&mut h, &x.to_le_bytes()));
        }
    }
    fnv1a(&mut h, &std::fs::read(&files.window).unwrap_or_default());
    for x in files.up.to_array() {
        fnv1a(&mut h, &x.to_le_bytes());
    }
    let (v, d) = (&settings.view, &settings.daylight);
    for x in [
        settings.mf as u64,
        u64::from(v.ambient_bounces),
        u64::from(v.samples_per_sensor),
        v.seed,
        u64::from(v.max_specular_events),
        u64::from(d.ambient_bounces),
        u64::from(d.samples_per_sensor),
        d.seed,
    ] {
        fnv1a(&mut h, &x.to_le_bytes());
    }
    h
}

/// Writes the matrices whole or not at all (a folder renamed into place).
fn write_cache(
    m: &StateMatrices,
    folder: &Path,
    files: &ShadedRoomFiles,
    settings: &ShadedRoomSettings,
) -> Result<(), ShadedRoomError> {
    let cache_error = |e: std::io::Error| ShadedRoomError::Cache {
        path: folder.to_path_buf(),
        message: e.to_string(),
    };
    let tmp = folder.with_extension("tmp");
    let _ = std::fs::remove_dir_all(&tmp);
    let header = format!(
        "skylux shading states: window {}, MF{}, V {} paths -ab {}, D {} rays -ab {}",
        files.window.display(),
        settings.mf,
        settings.view.samples_per_sensor,
        settings.view.ambient_bounces,
        settings.daylight.samples_per_sensor,
        settings.daylight.ambient_bounces
    );
    m.write(&tmp, &header).map_err(cache_error)?;
    let _ = std::fs::remove_dir_all(folder);
    std::fs::rename(&tmp, folder).map_err(cache_error)
}
