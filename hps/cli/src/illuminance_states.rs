//! `skylux illuminance --window W --state NAME=XML ...`: a window with several shading states
//! (blinds at several angles, a shade down, electrochromic tints), every state's illuminance
//! under the scene's sky from the room's matrices (`engine::phase::ShadedRoom`), traced once
//! and kept in `--matrices` for the next sky.

use anyhow::Context;
use glam::DVec3;
use skylux_hps::engine::phase::{
    sky_vector_of_world, ShadedRoom, ShadedRoomFiles, ShadedRoomSettings,
};
use skylux_hps::engine::{Settings, World};
use skylux_hps::scene;
use std::io::Write;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct StatesArgs {
    /// The window whose states are declared: its polygons, front normal into the room (as
    /// rfluxmtx's receiver). Surfaces of the scene in its plane and outline (its glazing) are
    /// left out: each state stands in for them.
    #[arg(long, requires = "states")]
    pub window: Option<PathBuf>,
    /// The up vector of the window's Klems frame and of its BSDFs.
    #[arg(long, num_args = 3, allow_negative_numbers = true, default_values_t = [0.0, 0.0, 1.0])]
    pub window_up: Vec<f64>,
    /// A state of the window, NAME=XML (a WINDOW / LBNL BSDF with Klems data; a tensor tree
    /// is refused: RADIANCE's bsdf2klems converts it);
    /// repeat for each, in the order of the output.
    #[arg(long = "state", requires = "window")]
    pub states: Vec<String>,
    /// Scene files outside the room (neighbours, overhangs) that the window sees.
    #[arg(long = "outside", requires = "window")]
    pub outside: Vec<PathBuf>,
    /// A folder for the room's matrices: read when they match the room, the sensors and the
    /// settings, traced and written otherwise.
    #[arg(long, requires = "window")]
    pub matrices: Option<PathBuf>,
    /// Reinhart multiplication factor of the sky patches.
    #[arg(long, default_value_t = 4)]
    pub mf: usize,
    /// Paths per sensor for V (many: a clear glazing puts the sun's beam into one Klems
    /// patch, whose interreflection then rests on one entry of V per sensor).
    #[arg(long, default_value_t = 262_144)]
    pub window_paths: u32,
    /// Rays per window patch for D.
    #[arg(long, default_value_t = 4096)]
    pub d_samples: u32,
}

pub fn run(
    scenes: &[PathBuf],
    allow_commands: bool,
    sensors_path: &Path,
    seed: u64,
    args: &StatesArgs,
) -> anyhow::Result<()> {
    let window = args.window.clone().context("--window")?;
    anyhow::ensure!((1..=8).contains(&args.mf), "--mf must be between 1 and 8");
    let states = args
        .states
        .iter()
        .map(|spec| parse_state(spec))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let load = scene::LoadOptions {
        allow_commands,
        ..Default::default()
    };
    let files = ShadedRoomFiles {
        scenes: scenes.to_vec(),
        outside: args.outside.clone(),
        window,
        up: DVec3::new(args.window_up[0], args.window_up[1], args.window_up[2]),
        states,
        load: load.clone(),
    };
    let defaults = ShadedRoomSettings::default();
    let settings = ShadedRoomSettings {
        mf: args.mf,
        view: Settings {
            samples_per_sensor: args.window_paths,
            seed,
            ..defaults.view
        },
        daylight: Settings {
            samples_per_sensor: args.d_samples,
            seed: seed.wrapping_add(1),
            ..defaults.daylight
        },
        ..defaults
    };
    let sensors = scene::load_sensors(sensors_path)?;
    let bar = indicatif::ProgressBar::new(1);
    let room = ShadedRoom::load(
        &files,
        &sensors,
        &settings,
        args.matrices.as_deref(),
        &|d, n| {
            bar.set_length(n);
            bar.set_position(d);
        },
    )?;
    bar.finish_and_clear();
    if let Some((folder, read)) = &room.cache {
        let how = if *read {
            "read from"
        } else {
            "traced and written to"
        };
        eprintln!("the room's matrices: {how} {}", folder.display());
    }
    if !room.removed_glazing.is_empty() {
        eprintln!(
            "the window's glazing, left out for its states: {}",
            room.removed_glazing.join(", ")
        );
    }
    // The sky: the scene's distant sources (gensky, gendaylit) and environment.
    let sky_world = World::new(&scene::load_files_with(scenes, &load)?)?;
    let (sky, suns) = sky_vector_of_world(&sky_world, args.mf);
    anyhow::ensure!(
        sky.iter().any(|&v| v > 0.0) || !suns.is_empty(),
        "the scene holds no sky (no glow source, environment or sun): give the sky's file \
         with --scene"
    );
    let lux = room.illuminance_lux(&sky, &suns)?;
    let mut out = std::io::stdout().lock();
    writeln!(out, "state,sensor,lux")?;
    for (name, values) in room.state_names().into_iter().zip(&lux) {
        for (sensor, value) in sensors.iter().zip(values) {
            writeln!(out, "{name},{},{value:.3}", sensor.name)?;
        }
    }
    Ok(())
}

/// A `--state NAME=XML`: the name (letters, digits, `-` and `_`: it names output columns and
/// files) and the XML's path.
pub fn parse_state(spec: &str) -> anyhow::Result<(String, PathBuf)> {
    let (name, path) = spec
        .split_once('=')
        .filter(|(n, p)| !n.is_empty() && !p.is_empty())
        .with_context(|| format!("--state {spec:?}: expected NAME=XML"))?;
    anyhow::ensure!(
        name.chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_'),
        "--state {spec:?}: the name may hold letters, digits, - and _ only"
    );
    Ok((name.to_string(), PathBuf::from(path)))
}
