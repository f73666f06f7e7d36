//! `skylux dc --three-phase`: V, T and D of a room with one BSDF window, in RADIANCE's matrix
//! format (`dctimestep v.mtx t.xml d.mtx sky` reads them), and their product with a sky
//! vector.

use crate::dc::DcArgs;
use anyhow::Context;
use glam::DVec3;
use skylux_hps::bsdf::{Band, KlemsTransmission};
use skylux_hps::engine::phase::{
    daylight_matrix, three_phase, view_matrices, KlemsWindow, WindowStates,
};
use skylux_hps::engine::{Settings, World};
use skylux_hps::io::radiance_matrix::{MatrixFormat, RadianceMatrix};
use skylux_hps::scene;
use std::path::Path;

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
    let states = load_states(args, &t)?;
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
    // V_d from V's own paths: the five-phase's difference V T D s_sun − V_d T D_d s_sun then
    // keeps no noise of the direct part.
    let (v, v_direct) = view_matrices(&room, &sensors, &window, &settings, &progress)?;
    let d_settings = Settings {
        ambient_bounces: args.d_ab,
        samples_per_sensor: args.d_samples,
        ..settings
    };
    let d = daylight_matrix(&outside, &window, args.mf, &d_settings, &progress)?;
    bar.finish_and_clear();
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    let write =
        |m: &RadianceMatrix, name: &str, what: String| write_matrix(&args.out, m, name, what);
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
    for ((name, matrix), spec) in states.iter().zip(&args.states) {
        write(
            matrix,
            &format!("t-{name}.mtx"),
            format!("skylux dc --three-phase: T of state {spec}"),
        )?;
    }
    write(
        &d,
        "d.mtx",
        format!(
            "skylux dc --three-phase: D, Klems patches x (ground + Reinhart MF{}), {} rays per patch, -ab {}",
            args.mf, args.d_samples, args.d_ab
        ),
    )?;
    if args.direct {
        write_direct_matrices(args, &outside, &window, &v_direct, d_settings)?;
    }
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
        write_product(args, sky_path, (&v, &t.matrix, &d), &states, &sensors)?;
    }
    Ok(())
}

/// The five-phase's direct matrices: vd.mtx (the sensors' direct view of the window, from
/// V's paths' first segments: `-ab 1`'s) and dd.mtx (D at -ab 0, the window's direct view
/// of the sky).
fn write_direct_matrices(
    args: &DcArgs,
    outside: &World,
    window: &KlemsWindow,
    v_direct: &RadianceMatrix,
    d_settings: Settings,
) -> anyhow::Result<()> {
    let write =
        |m: &RadianceMatrix, name: &str, what: String| write_matrix(&args.out, m, name, what);
    let d_direct = daylight_matrix(
        outside,
        window,
        args.mf,
        &Settings {
            ambient_bounces: 0,
            ..d_settings
        },
        &|_, _| {},
    )?;
    write(
        v_direct,
        "vd.mtx",
        format!(
            "skylux dc --three-phase --direct: V_d (-ab 1, V's first segments), {} paths",
            args.ad
        ),
    )?;
    write(
        &d_direct,
        "dd.mtx",
        format!(
            "skylux dc --three-phase --direct: D_d (-ab 0), {} rays per patch",
            args.d_samples
        ),
    )?;
    Ok(())
}

/// V T D s with the --sky vector: result.mtx, lux per sensor, and every window state's lux.
fn write_product(
    args: &DcArgs,
    sky_path: &Path,
    (v, t, d): (&RadianceMatrix, &RadianceMatrix, &RadianceMatrix),
    states: &[(String, RadianceMatrix)],
    sensors: &[scene::Sensor],
) -> anyhow::Result<()> {
    let sky = RadianceMatrix::read(sky_path)?;
    let result = three_phase(v, t, d, &sky)?;
    let path = args.out.join("result.mtx");
    result
        .write(
            &path,
            MatrixFormat::Ascii,
            &[format!(
                "skylux dc --three-phase: V T D {}",
                sky_path.display()
            )],
        )
        .with_context(|| format!("writing {}", path.display()))?;
    let lux = result.brightness();
    for (s, sensor) in sensors.iter().enumerate() {
        let row: Vec<String> = (0..lux.cols)
            .map(|c| format!("{:.1}", 179.0 * lux.get(s, c, 0)))
            .collect();
        println!("{},{}", sensor.name, row.join(","));
    }
    if !states.is_empty() {
        print_states(v, t, states, d, &sky, sensors)?;
    }
    Ok(())
}

/// Writes `m` as RGB (grey), float, as dctimestep expects of every factor.
fn write_matrix(out: &Path, m: &RadianceMatrix, name: &str, what: String) -> anyhow::Result<()> {
    let path = out.join(name);
    let rgb = m.with_components(3).context("a grey matrix")?;
    rgb.write(&path, MatrixFormat::Float, &[what])
        .with_context(|| format!("writing {}", path.display()))
}

/// The window's further states (`--state NAME=XML`), each T on the --bsdf's Klems basis.
fn load_states(
    args: &DcArgs,
    basis: &KlemsTransmission,
) -> anyhow::Result<Vec<(String, RadianceMatrix)>> {
    args.states
        .iter()
        .map(|spec| {
            let (name, path) = crate::illuminance_states::parse_state(spec)?;
            let path = path.display().to_string();
            let t = KlemsTransmission::load(Path::new(&path), Band::Visible)?;
            anyhow::ensure!(
                (t.matrix.rows, t.matrix.cols) == (basis.matrix.rows, basis.matrix.cols),
                "--state {name}: {path} is {}x{}, the --bsdf {}x{}: one window, one basis",
                t.matrix.rows,
                t.matrix.cols,
                basis.matrix.rows,
                basis.matrix.cols
            );
            Ok((name.to_string(), t.matrix))
        })
        .collect()
}

/// `sensor,state,lux` for the --bsdf ("bsdf") and every --state: D s once, then one product
/// per state ([`WindowStates`]).
fn print_states(
    v: &RadianceMatrix,
    t: &RadianceMatrix,
    states: &[(String, RadianceMatrix)],
    d: &RadianceMatrix,
    sky: &RadianceMatrix,
    sensors: &[scene::Sensor],
) -> anyhow::Result<()> {
    let grey = |m: &RadianceMatrix| {
        if m.ncomp == 1 {
            m.clone()
        } else {
            m.brightness()
        }
    };
    let mut ts = vec![grey(t)];
    ts.extend(states.iter().map(|(_, m)| grey(m)));
    let switch = WindowStates::new(&grey(v), &ts, &grey(d))?;
    let sky = grey(sky);
    anyhow::ensure!(sky.cols == 1, "--sky: one column (one sky) for the states");
    let window = switch.window_radiance(&sky.values)?;
    let names = std::iter::once("bsdf").chain(states.iter().map(|(n, _)| n.as_str()));
    println!("sensor,state,lux");
    let mut irradiance = vec![0.0; sensors.len()];
    for (k, name) in names.enumerate() {
        switch.apply_state(k, &window, &mut irradiance)?;
        for (sensor, e) in sensors.iter().zip(&irradiance) {
            println!("{},{name},{:.1}", sensor.name, 179.0 * e);
        }
    }
    Ok(())
}

/// `skylux bench states`: the per-capture cost of a window with several states, with
/// matrices of the real sizes (400 sensors, Klems full, Reinhart MF4 + ground, 5 states) and
/// arbitrary positive values (the time does not depend on them).
pub fn bench(json: bool, repeat: usize) -> anyhow::Result<()> {
    use skylux_hps::engine::phase::WindowStates;
    use skylux_hps::timing::median_ms;
    const SENSORS: usize = 400;
    const PATCHES: usize = 145;
    const STATES: usize = 5;
    let mf = 4;
    let bins = 1 + skylux_hps::sky::SkyPatches::reinhart(mf).len();
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut matrix = |rows: usize, cols: usize| {
        RadianceMatrix::from_grey(rows, cols, (0..rows * cols).map(|_| next()).collect())
            .context("matrix size")
    };
    let v = matrix(SENSORS, PATCHES)?;
    let d = matrix(PATCHES, bins)?;
    let t: Vec<RadianceMatrix> = (0..STATES)
        .map(|_| matrix(PATCHES, PATCHES))
        .collect::<anyhow::Result<_>>()?;
    let sky: Vec<f64> = (0..bins).map(|k| 1.0 + (k % 7) as f64).collect();
    let precompute = std::time::Instant::now();
    let states = WindowStates::new(&v, &t, &d)?;
    let precompute_ms = precompute.elapsed().as_secs_f64() * 1e3;
    let mut out = vec![0.0; SENSORS];
    let mut window = states.window_radiance(&sky)?;
    let mut failure = None;
    let d_ms = median_ms(repeat, || match states.window_radiance(&sky) {
        Ok(w) => window = w,
        Err(e) => failure = Some(e),
    });
    let switch_ms = median_ms(repeat, || {
        if let Err(e) = states.apply_state(STATES - 1, &window, &mut out) {
            failure = Some(e);
        }
    });
    let mut checksum = 0.0;
    let all_ms = median_ms(repeat, || {
        for k in 0..STATES {
            if let Err(e) = states.apply_state(k, &window, &mut out) {
                failure = Some(e);
            }
            checksum += out[0];
        }
    });
    if let Some(e) = failure {
        return Err(e.into());
    }
    checksum += window.iter().sum::<f64>();
    let (capture_with_sun_ms, sun_checksum) = capture_with_sun(&t, repeat)?;
    checksum += sun_checksum;
    if json {
        println!(
            "{}",
            serde_json::json!({
                "sensors": SENSORS,
                "klems_patches": PATCHES,
                "sky_bins": bins,
                "states": STATES,
                "precompute_ms": precompute_ms,
                "window_radiance_ms": d_ms,
                "state_switch_ms": switch_ms,
                "all_states_ms": all_ms,
                "capture_all_states_ms": d_ms + all_ms,
                "capture_all_states_with_sun_ms": capture_with_sun_ms,
                "budget_ms": 5.0,
                "checksum": checksum,
            })
        );
    } else {
        println!(
            "window states, {SENSORS} sensors x {PATCHES} Klems patches, MF{mf} sky ({bins} bins), \
             one core: D s {d_ms:.3} ms per capture, one state switch {switch_ms:.3} ms, all \
             {STATES} states {all_ms:.3} ms (capture with every state {:.3} ms; budget 5 ms); \
             precomputing V T_k {precompute_ms:.1} ms once; a whole capture with the sun \
             (its beam at its Klems patch, its direct view over 32 x 32 window points) \
             {capture_with_sun_ms:.3} ms",
            d_ms + all_ms
        );
    }
    Ok(())
}

/// A whole capture of a window with its states (`ShadedWindow::irradiance_w_m2`): the sky's
/// products, the sun's visibility over the window's 32 x 32 points, its beam and its direct
/// view, every state; on one core, for 400 sensors on the workplane of a 4 m x 5 m room with a
/// 2 m x 1.2 m south window, the sun at 60° through it. Matrices of the real sizes with
/// arbitrary positive values (the time does not depend on them). Returns the median ms and a
/// checksum.
fn capture_with_sun(ts: &[RadianceMatrix], repeat: usize) -> anyhow::Result<(f64, f64)> {
    use skylux_hps::engine::phase::{ShadedWindow, ShadingState, StateMatrices, SunBeam, SunView};
    let room_text = "void plastic wall 0 0 5 0.5 0.5 0.5 0 0\n\
                     wall polygon floor 0 0 12 0 0 0 4 0 0 4 5 0 0 5 0\n\
                     wall polygon back 0 0 12 0 5 0 4 5 0 4 5 3 0 5 3\n";
    let room = World::new(&scene::parse("bench-room.rad", room_text.as_bytes())?)?;
    let window_scene = scene::parse(
        "bench-window.rad",
        b"void glow g 0 0 4 1 1 1 0\ng polygon window 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9\n",
    )?;
    let polygons = window_scene
        .surfaces()
        .iter()
        .filter_map(|s| match &s.shape {
            scene::Shape::Polygon(p) => Some(p.clone()),
            _ => None,
        })
        .collect();
    let basis = skylux_hps::bsdf::AngleBasis::builtin("LBNL/Klems Full").context("basis")?;
    let window = KlemsWindow::new(polygons, DVec3::Z, basis, "bench-window.rad")?;
    let pts: String = (0..400)
        .map(|k| {
            format!(
                "{} {} 0.8 0 0 1\n",
                0.1 + 0.2 * (k % 20) as f64,
                0.1 + 0.24 * (k / 20) as f64
            )
        })
        .collect();
    let sensors = scene::parse_sensors("bench.pts", pts.as_bytes())?;
    let patches = window.basis.len();
    let mf = 4;
    let sky_bins = 1 + skylux_hps::sky::SkyPatches::reinhart(mf).len();
    let fill = |rows: usize, cols: usize, seed: usize| {
        RadianceMatrix::from_grey(
            rows,
            cols,
            (0..rows * cols)
                .map(|k| ((k * 2_654_435_761 + seed) % 1000) as f64 * 1e-6)
                .collect(),
        )
        .context("matrix size")
    };
    let m = StateMatrices {
        v: fill(sensors.len(), patches, 1)?,
        v_direct: fill(sensors.len(), patches, 2)?,
        d: fill(patches, sky_bins, 3)?,
        d_direct: fill(patches, sky_bins, 4)?,
    };
    let states = ts
        .iter()
        .enumerate()
        .map(|(k, t)| ShadingState::from_transmission(&format!("s{k}"), t.clone()))
        .collect();
    let sun_view = SunView::new(&room, &sensors, &window, 32);
    let shaded = ShadedWindow::new(window, mf, states, &m, sun_view)?;
    let sky: Vec<f64> = (0..sky_bins).map(|k| 1.0 + (k % 7) as f64).collect();
    let sun = SunBeam {
        direction: DVec3::new(0.0, -0.5, 0.75f64.sqrt()),
        direct_normal_w_m2: 500.0,
    };
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build()?;
    let mut checksum = 0.0;
    let mut failure = None;
    let ms = skylux_hps::timing::median_ms(repeat, || {
        match one.install(|| shaded.irradiance_w_m2(&sky, &[sun], &room)) {
            Ok(e) => checksum += e[0][0],
            Err(e) => failure = Some(e),
        }
    });
    if let Some(e) = failure {
        return Err(e.into());
    }
    Ok((ms, checksum))
}
