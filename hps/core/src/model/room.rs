//! The room as the device model sees it: its engine world (without sky), its sensors and its
//! daylight coefficients, computed once.

use super::error::ModelError;
use crate::campaign::Campaign;
use crate::engine::{self, DaylightCoefficients, EngineError, Settings, World};
use crate::scene::Sensor;
use glam::DVec3;

/// The room: its engine world (without sky) and daylight coefficients.
pub struct Room {
    pub world: World,
    pub sensors: Vec<Sensor>,
    pub dc: DaylightCoefficients,
    pub settings: Settings,
}

impl Room {
    /// Loads the campaign's room and computes its daylight coefficients (Reinhart `mf`).
    pub fn load(
        campaign: &Campaign,
        mf: usize,
        settings: Settings,
        progress: &(dyn Fn(u64, u64) + Sync),
    ) -> Result<Self, ModelError> {
        let scene = crate::scene::load(campaign.path(&campaign.config.files.scene))?;
        let sensors = crate::scene::load_sensors(campaign.path(&campaign.config.files.sensors))?;
        let mut world = World::new(&scene)?;
        engine::openings::add_openings(
            &mut world,
            &sensors.iter().map(|s| s.position_m).collect::<Vec<_>>(),
        );
        let dc = engine::daylight_coefficients(&world, &sensors, mf, &settings, progress)?;
        Ok(Self {
            world,
            sensors,
            dc,
            settings,
        })
    }

    /// Per sensor, lux per lux of direct-normal illuminance from a sun in unit direction
    /// `sun` (with standard errors), at the room's settings with 64 to 2048 paths per sensor
    /// (one direction needs fewer than the whole sky's coefficients).
    pub fn sun_coefficients(&mut self, sun: DVec3) -> Result<Vec<(f64, f64)>, EngineError> {
        let settings = Settings {
            samples_per_sensor: self.settings.samples_per_sensor.clamp(64, 2048),
            ..self.settings
        };
        engine::sun_coefficients(&mut self.world, &self.sensors, sun, &settings)
    }
}
