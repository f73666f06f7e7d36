//! The simulated world's own interior illuminance: the room traced directly under the world's
//! sky, ground and sun, as `skylux sim campaign` computes its lux-meters' truth. It shares no
//! step with the measurement it checks (no camera, HDR merge, sun extraction, sky patches or
//! daylight coefficients), so a test that compares the daemon's lux with it compares the
//! daemon with the world, not with itself.

use crate::config::SimSky;
use crate::source::{sim_outdoor_horizontal_lux, sim_sky, GROUND_REFLECTANCE};
use chrono::{DateTime, FixedOffset};
use glam::DVec3;
use skylux_hps::engine::sky::DistantEmitter;
use skylux_hps::engine::{self, Settings, World};
use skylux_hps::scene::Sensor;
use skylux_hps::sun::Site;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The room of the daemon's configuration, ready to be traced under the world.
pub struct InteriorTruth {
    world: World,
    sensors: Vec<Sensor>,
    settings: Settings,
}

impl InteriorTruth {
    /// The room of `config`, when `[sim] interior_truth_samples` asks for it.
    pub fn for_config(config: &crate::config::Config) -> Result<Option<Self>, String> {
        if config.sim.interior_truth_samples == 0 {
            return Ok(None);
        }
        Self::load(
            &config.room.scene,
            &config.room.sensors,
            config.sim.interior_truth_samples,
            config.sim.seed,
        )
        .map(Some)
        .map_err(|e| format!("the simulated world's room: {e}"))
    }

    /// Loads the room (`scene` files and `sensors` points) to trace with `samples` paths per
    /// sensor and the engine's converged bounce count.
    pub fn load(
        scene: &[PathBuf],
        sensors: &Path,
        samples: u32,
        seed: u64,
    ) -> Result<Self, String> {
        let scene = skylux_hps::scene::load_files(scene).map_err(|e| e.to_string())?;
        let sensors = skylux_hps::scene::load_sensors(sensors).map_err(|e| e.to_string())?;
        let mut world = World::new(&scene).map_err(|e| e.to_string())?;
        skylux_hps::engine::openings::add_openings(
            &mut world,
            &sensors.iter().map(|s| s.position_m).collect::<Vec<_>>(),
        );
        Ok(Self {
            world,
            sensors,
            settings: Settings {
                ambient_bounces: engine::integrator::CONVERGED_AMBIENT_BOUNCES,
                samples_per_sensor: samples,
                seed,
                ..Default::default()
            },
        })
    }

    /// Per sensor, the world's illuminance at `at`, lux: the Perez sky (without its disk) and
    /// the grey ground as the environment, the solar disk as a distant light of its own solid
    /// angle (reached by next-event estimation).
    pub fn illuminance_lux(
        &mut self,
        site: &Site,
        sky_kind: SimSky,
        at: DateTime<FixedOffset>,
    ) -> Result<Vec<f64>, String> {
        let (sky, sun_direction) = sim_sky(site, sky_kind, at)?;
        let Some((perez, with_sun)) = sky else {
            return Ok(vec![0.0; self.sensors.len()]);
        };
        // The world's ground, as `source::sim_world` renders it for the camera.
        let ground_cd_m2 = GROUND_REFLECTANCE * sim_outdoor_horizontal_lux(site, sky_kind, at)?
            / std::f64::consts::PI;
        let sun_cd_m2 = if with_sun {
            perez.sun_luminance_cd_m2()
        } else {
            0.0
        };
        let sun_sr = perez.sun_solid_angle_sr();
        let sky = Arc::new(perez);
        let environment = Arc::clone(&sky);
        self.world.set_environment(Some(Arc::new(move |d: DVec3| {
            let l = if d.z < 0.0 {
                ground_cd_m2
            } else {
                environment.luminance_cd_m2(d)
            };
            DVec3::splat(l / engine::WHITE_EFFICACY_LM_PER_W)
        })));
        if sun_cd_m2 > 0.0 {
            self.world.add_distant(DistantEmitter::sun(
                sun_direction,
                sun_sr,
                sun_cd_m2 / engine::WHITE_EFFICACY_LM_PER_W,
            ));
        }
        let traced = engine::illuminance(&self.world, &self.sensors, &self.settings, &|_, _| {});
        self.world.clear_distant();
        self.world.set_environment(None);
        Ok(traced
            .map_err(|e| e.to_string())?
            .iter()
            .map(|s| s.illuminance_lux)
            .collect())
    }
}
