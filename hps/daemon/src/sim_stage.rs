//! The simulated world as the fabric sources' MT9P031 model images it: one scene shared
//! between the source (which sets the world's sky and sun before each capture) and the sensor
//! model (which renders it), and the world's own truth attached to each capture. The
//! cycle-accurate core (`fabric_source::SimFabricSource`) and the behavioural fabric
//! (`fabric_model_source::SimFabricModelSource`) both stage their world here.

use crate::config::{Config, SimSky};
use crate::interior_truth::InteriorTruth;
use crate::source::{
    sim_outdoor_horizontal_lux, sim_small_sources, sim_world, CaptureSet, SourceError,
};
use chrono::{DateTime, FixedOffset};
use skylux_hps::camera::{CameraModel, DeviceConfig};
use skylux_hps::campaign::RawFrame;
use skylux_sim::mt9p031::{FrameSettings, PixelSource, SceneSource};
use skylux_sim::sensor::ChannelResponse;
use std::sync::{Arc, Mutex, MutexGuard};

/// The world behind a simulated fabric: its scene, site and sky, and the room traced under it.
pub struct WorldStage {
    scene: Arc<Mutex<SceneSource>>,
    site: skylux_hps::sun::Site,
    sky: SimSky,
    interior: Option<InteriorTruth>,
}

impl WorldStage {
    /// The world of `config`'s site and `[sim]` sky, imaged through `device`, with the
    /// interior truth when `[sim] interior_truth_samples` asks for it.
    pub fn new(config: &Config, device: &DeviceConfig) -> Result<Self, SourceError> {
        Ok(Self {
            scene: Arc::new(Mutex::new(SceneSource {
                camera: CameraModel::new(device.clone()),
                luminance_cd_m2: Box::new(|_| 0.0),
                noise_seed: Some(config.sim.seed),
                channel_response: ChannelResponse::GREY,
                small_sources: vec![],
            })),
            site: skylux_hps::sun::Site {
                latitude_deg: config.site.latitude_deg,
                longitude_deg: config.site.longitude_deg,
                elevation_m: config.site.elevation_m,
            },
            sky: config.sim.sky,
            interior: InteriorTruth::for_config(config).map_err(SourceError::Other)?,
        })
    }

    /// What the MT9P031 model renders its frames from.
    pub fn pixel_source(&self) -> Box<dyn PixelSource + Send> {
        Box::new(SharedScene(Arc::clone(&self.scene)))
    }

    /// Sets the world of `at` (sky, ground and the solar disk as a small source) before a
    /// capture.
    pub fn stage(&self, at: DateTime<FixedOffset>) -> Result<(), SourceError> {
        let world = sim_world(&self.site, self.sky, at).map_err(SourceError::Other)?;
        let small_sources =
            sim_small_sources(&self.site, self.sky, at).map_err(SourceError::Other)?;
        let mut scene = lock(&self.scene);
        scene.luminance_cd_m2 = Box::new(world);
        scene.small_sources = small_sources;
        Ok(())
    }

    /// Writes the world's own outdoor and interior illuminance at `at` into `set`.
    pub fn attach_truth(
        &mut self,
        set: &mut CaptureSet,
        at: DateTime<FixedOffset>,
    ) -> Result<(), SourceError> {
        set.truth_outdoor_horizontal_lux =
            Some(sim_outdoor_horizontal_lux(&self.site, self.sky, at).map_err(SourceError::Other)?);
        if let Some(room) = &mut self.interior {
            set.truth_interior_lux = Some(
                room.illuminance_lux(&self.site, self.sky, at)
                    .map_err(SourceError::Other)?,
            );
        }
        Ok(())
    }
}

fn lock(scene: &Mutex<SceneSource>) -> MutexGuard<'_, SceneSource> {
    match scene.lock() {
        Ok(s) => s,
        Err(p) => p.into_inner(),
    }
}

/// The staged scene as the sensor model's pixel source.
struct SharedScene(Arc<Mutex<SceneSource>>);

impl PixelSource for SharedScene {
    fn frame(&mut self, settings: &FrameSettings, pixclk_hz: f64, frame_index: u64) -> RawFrame {
        lock(&self.0).frame(settings, pixclk_hz, frame_index)
    }
}
