//! The campaign's captures as the device model reads them: each merged into a luminance map,
//! with the sun's position from SPA.

use super::error::ModelError;
use crate::camera::DeviceConfig;
use crate::campaign::Campaign;
use crate::hdr::{map_capture, CaptureMap, LuminanceMap};
use crate::sun::solar_position;
use chrono::{DateTime, FixedOffset, Utc};
use glam::DVec3;
use std::path::Path;

/// One capture as the model sees it: the merged map and the sun position from SPA.
#[derive(Clone)]
pub struct CaptureData {
    pub time: DateTime<FixedOffset>,
    pub map: LuminanceMap,
    pub readout: crate::campaign::Readout,
    pub raw_width: usize,
    pub raw_height: usize,
    /// The sun from SPA (geometric, as the engine's sun).
    pub spa_sun: DVec3,
    /// The sun measured without a scan of the map (the fabric's accumulators, issue 22
    /// item 2), taken as found; `None`: `extract_sun` searches the map for it.
    pub sun: Option<crate::sun::ExtractedSun>,
}

/// Reads and merges every capture of the campaign with the declared camera.
pub fn load_captures(
    campaign: &Campaign,
    device: &DeviceConfig,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CaptureData>, ModelError> {
    load_captures_with(campaign, &|dir| Ok(map_capture(dir, device)?), progress)
}

/// Reads every capture of the campaign, each folder merged by `merge` (the declared camera's
/// [`map_capture`] for the product; the loop's shutter effect merges with other exposure
/// times), with the SPA sun at its time.
pub fn load_captures_with(
    campaign: &Campaign,
    merge: &dyn Fn(&Path) -> Result<CaptureMap, ModelError>,
    progress: &dyn Fn(usize, usize),
) -> Result<Vec<CaptureData>, ModelError> {
    let site = crate::sun::Site {
        latitude_deg: campaign.config.site.latitude_deg,
        longitude_deg: campaign.config.site.longitude_deg,
        elevation_m: campaign.config.site.elevation_m,
    };
    let mut out = Vec::new();
    for (i, c) in campaign.captures.iter().enumerate() {
        progress(i, campaign.captures.len());
        let merged = merge(&c.dir)?;
        let spa = solar_position(c.time.with_timezone(&Utc), &site, None)
            .map_err(|e| ModelError::Sun(format!("{}: {e}", c.dir.display())))?;
        out.push(CaptureData {
            time: c.time,
            raw_width: 2 * merged.map.width,
            raw_height: 2 * merged.map.height,
            readout: merged.capture.readout,
            map: merged.map,
            spa_sun: spa.direction(),
            sun: None,
        });
    }
    Ok(out)
}
