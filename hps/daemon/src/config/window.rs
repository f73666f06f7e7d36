//! `[room.window]`: a window of the room whose shading states are declared (blinds at several
//! angles, a shade down, electrochromic tints), each a BSDF XML. Every cycle reports every
//! state's illuminance, and each view's Ev and DGPs under it, from the room's matrices
//! traced once (issue 20 item 5; `skylux_hps::engine::phase::ShadedRoom`).

use super::{refuse, FieldError};
use serde::Deserialize;
use std::path::PathBuf;

/// `[room.window]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct WindowConfig {
    /// The window's polygons, front normal into the room (`rfluxmtx`'s receiver). The room
    /// scene's surfaces in its plane and outline (its glazing) are left out of the matrices.
    pub polygons: PathBuf,
    /// The up vector of the window's Klems frame and of its BSDFs.
    #[serde(default = "default_up")]
    pub up: [f64; 3],
    /// Scene files outside the room (neighbours, overhangs) that the window sees.
    #[serde(default)]
    pub outside: Vec<PathBuf>,
    /// V's paths per sensor (a clear glazing puts the sun's beam into one Klems patch, whose
    /// interreflection then rests on one entry of V: it needs many).
    #[serde(default = "default_view_paths")]
    pub view_paths: u32,
    /// D's rays per window patch.
    #[serde(default = "default_daylight_rays")]
    pub daylight_rays: u32,
    /// The states, in the order of the record.
    pub states: Vec<StateConfig>,
}

/// `[[room.window.states]]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct StateConfig {
    /// Letters, digits, `-` or `_`.
    pub name: String,
    /// The state's BSDF (WINDOW / LBNL XML with Klems data; bsdf2klems converts a tree).
    pub bsdf: PathBuf,
}

fn default_up() -> [f64; 3] {
    [0.0, 0.0, 1.0]
}
fn default_view_paths() -> u32 {
    262_144
}
fn default_daylight_rays() -> u32 {
    4096
}

impl WindowConfig {
    pub(super) fn check(&self) -> Result<(), FieldError> {
        if self.polygons.as_os_str().is_empty() {
            return refuse("polygons", "name the window's polygon file");
        }
        if !self.up.iter().all(|x| x.is_finite()) || self.up.iter().all(|&x| x == 0.0) {
            return refuse(
                "up",
                format!("{:?}: a finite vector other than zero", self.up),
            );
        }
        if self.view_paths == 0 || self.daylight_rays == 0 {
            return refuse(
                "view_paths",
                "view_paths and daylight_rays must be at least 1",
            );
        }
        if self.states.is_empty() {
            return refuse(
                "states",
                "declare at least one state ([[room.window.states]])",
            );
        }
        for (k, s) in self.states.iter().enumerate() {
            let ok = !s.name.is_empty()
                && s.name.len() <= 64
                && s.name
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
            if !ok {
                return refuse(
                    "states",
                    format!(
                        "state name {:?}: 1 to 64 letters, digits, `-` or `_`",
                        s.name
                    ),
                );
            }
            if self.states[..k].iter().any(|o| o.name == s.name) {
                return refuse("states", format!("state {:?} declared twice", s.name));
            }
        }
        Ok(())
    }

    /// Paths relative to the configuration file's folder, through `resolve`.
    pub(super) fn resolve(&mut self, resolve: &dyn Fn(&mut PathBuf)) {
        resolve(&mut self.polygons);
        self.outside.iter_mut().for_each(resolve);
        self.states.iter_mut().for_each(|s| resolve(&mut s.bsdf));
    }
}
