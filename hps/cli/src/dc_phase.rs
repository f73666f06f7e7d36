//! `skylux dc --three-phase`: V, T and D of a room with one BSDF window, in RADIANCE's matrix
//! format (`dctimestep v.mtx t.xml d.mtx sky` reads them), and their product with a sky
//! vector.

use crate::dc::DcArgs;
use anyhow::Context;
use glam::DVec3;
use skylux_hps::bsdf::{Band, KlemsTransmission};
use skylux_hps::engine::phase::{daylight_matrix, three_phase, view_matrix, KlemsWindow};
use skylux_hps::engine::{Settings, World};
use skylux_hps::io::radiance_matrix::{MatrixFormat, RadianceMatrix};
use skylux_hps::scene;

pub fn run(args: &DcArgs) -> anyhow::Result<()> {
    let (Some(window_path), Some(bsdf_path)) = (&args.window, &args.bsdf) else {
        anyhow::bail!("--three-phase needs --window and --bsdf");
    };
    let options = scene::LoadOptions {
        allow_commands: args.allow_commands,
        ..Default::default()
    };
    let room = scene::load_files_with(&args.scenes, &options)?;
    let with_outside: Vec<_> = args.scenes.iter().chain(&args.outside).cloned().collect();
    let outside = scene::load_files_with(&with_outside, &options)?;
    let sensors = scene::load_sensors(&args.sensors)?;
    let room = World::new(&room)?;
    let outside = World::new(&outside)?;
    anyhow::ensure!(
        room.distant_sources().is_empty() && outside.distant_sources().is_empty(),
        "the scene holds a sky or sun (distant sources): the matrices need the room alone"
    );
    let t = KlemsTransmission::load(bsdf_path, Band::Visible)?;
    let up = DVec3::new(args.window_up[0], args.window_up[1], args.window_up[2]);
    let window = KlemsWindow::load(window_path, up, t.incident_basis.clone())?;
    let settings = Settings {
        ambient_bounces: args.ab,
        samples_per_sensor: args.ad,
        seed: args.seed,
        ..Default::default()
    };
    let bar = indicatif::ProgressBar::new(1);
    let progress = |d, n| {
        bar.set_length(n);
        bar.set_position(d);
    };
    let v = view_matrix(&room, &sensors, &window, &settings, &progress)?;
    let d_settings = Settings {
        ambient_bounces: args.d_ab,
        samples_per_sensor: args.d_samples,
        ..settings.clone()
    };
    let d = daylight_matrix(&outside, &window, args.mf, &d_settings, &progress)?;
    bar.finish_and_clear();
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    let write = |m: &RadianceMatrix, name: &str, what: String| -> anyhow::Result<()> {
        let path = args.out.join(name);
        // RGB (grey), as dctimestep expects of every factor.
        let rgb = m.with_components(3).context("a grey matrix")?;
        rgb.write(&path, MatrixFormat::Float, &[what])
            .with_context(|| format!("writing {}", path.display()))
    };
    write(
        &v,
        "v.mtx",
        format!(
            "skylux dc --three-phase: V, sensors x Klems patches of {}, W/m2 per W/m2/sr, {} paths, -ab {}",
            window_path.display(),
            args.ad,
            args.ab
        ),
    )?;
    write(
        &t.matrix,
        "t.mtx",
        format!("skylux dc --three-phase: T of {}", bsdf_path.display()),
    )?;
    write(
        &d,
        "d.mtx",
        format!(
            "skylux dc --three-phase: D, Klems patches x (ground + Reinhart MF{}), {} rays per patch, -ab {}",
            args.mf, args.d_samples, args.d_ab
        ),
    )?;
    println!(
        "V {}x{}, T {}x{}, D {}x{} -> {}",
        v.rows,
        v.cols,
        t.matrix.rows,
        t.matrix.cols,
        d.rows,
        d.cols,
        args.out.display()
    );
    if let Some(sky_path) = &args.sky {
        let sky = RadianceMatrix::read(sky_path)?;
        let result = three_phase(&v, &t.matrix, &d, &sky)?;
        let path = args.out.join("result.mtx");
        result
            .write(
                &path,
                MatrixFormat::Ascii,
                &[format!("skylux dc --three-phase: V T D {}", sky_path.display())],
            )
            .with_context(|| format!("writing {}", path.display()))?;
        let lux = result.brightness();
        for (s, sensor) in sensors.iter().enumerate() {
            let row: Vec<String> = (0..lux.cols)
                .map(|c| format!("{:.1}", 179.0 * lux.get(s, c, 0)))
                .collect();
            println!("{},{}", sensor.name, row.join(","));
        }
    }
    Ok(())
}
