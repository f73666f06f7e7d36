//! `skylux bench render`: image quality at equal wall time, our renderer against `rpict`
//! (issue 21 item 2).
//!
//! For each view, a converged reference comes first: pure path tracing by `rtrace` (`-aa 0
//! -ad 1 -ab 12`) on `vwrays`' jittered rays, many per pixel, averaged with their standard
//! error; it is cached, keyed by the scene, sky, view, resolution and path count. Then
//! `rpict` renders the view with each configuration asked for, timed; our renderer gets the
//! same wall time (its paths per pixel chosen from a short calibration run), filtered and
//! unfiltered. Each picture is compared with the reference pixel by pixel: the RMS relative
//! error of the luminance, raw and with the reference's own variance taken out (the two are
//! independent, so their variances add), and Ev and DGP computed from the picture as
//! `skylux glare` computes them.
//!
//! `rpict` runs on one core (it has no threads); our renderer on all cores. Both are timed
//! from the call to the finished picture; neither includes building its scene (`oconv`,
//! [`World::new`]).

use anyhow::{bail, Context};
use serde_json::json;
use skylux_hps::engine::render::{self, PreparedView, RenderSettings, View, ViewType};
use skylux_hps::engine::{Settings, World};
use skylux_hps::glare::{self, GlareOptions, LuminanceImage};
use skylux_hps::picture::{falsecolour, rgbe, Picture};
use skylux_hps::scene;
use skylux_sim::radiance_tools::Radiance;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::Stdio;
use std::time::Instant;

use crate::bench_illuminance::{bench_cache_dir, fnv1a, next_second, tempfile_dir};

/// The default sky: NYC on 21 December at 10:30, clear (gendaylit from direct normal and
/// diffuse horizontal irradiance), low enough that the sun is seen through the tutorial
/// room's window from the fisheye view below.
const DEFAULT_SKY: &str = "!gendaylit 12 21 10.5 -a 40.7 -o 74 -m 75 -W 750 60
skyfunc glow skyglow 0 0 4 1 1 1 0
skyglow source sky 0 0 4 0 0 1 180
skyfunc glow groundglow 0 0 4 1 1 1 0
groundglow source ground 0 0 4 0 0 -1 180
";

/// Bounces of every program here: more change nothing in this room (BENCHMARKS.md, the
/// illuminance bench's reference).
const BOUNCES: u32 = 12;

#[derive(clap::Args)]
pub struct RenderBenchArgs {
    /// Print one JSON object instead of the table.
    #[arg(long)]
    json: bool,
    /// The room's folder (default: the LBNL matrix tutorial's room in the corpus).
    #[arg(long)]
    room: Option<PathBuf>,
    /// Scene files relative to --room, in oconv's order (inline commands run from --room).
    #[arg(long = "scene", num_args = 1.., default_values = ["materials.rad", "room.rad"])]
    scene: Vec<PathBuf>,
    /// Sky file (RADIANCE scene text); default: a clear winter morning in New York.
    #[arg(long)]
    sky: Option<PathBuf>,
    /// A view to compare, `NAME=OPTIONS` (rpict's -v options; `-vf FILE` relative to
    /// --room). Default: the tutorial's interior view and an occupant's fisheye towards the
    /// window with the sun in it.
    #[arg(long = "view")]
    views: Vec<String>,
    /// Largest image side in pixels (the view's aspect is kept, as rpict -pa 1 does).
    #[arg(long, default_value_t = 128)]
    size: u32,
    /// rpict configurations, each compared with ours at its time.
    #[arg(long = "rpict", default_values = [
        "-ab 3 -aa 0.1 -ad 1024 -as 512 -ar 256",
        "-ab 8 -aa 0.1 -ad 1024 -as 512 -ar 256 -lw 1e-4",
    ])]
    rpict: Vec<String>,
    /// rtrace paths per pixel of the reference.
    #[arg(long, default_value_t = 4096)]
    reference_paths: u32,
    /// Write each picture (.hdr and falsecolour .png) to this folder.
    #[arg(long)]
    images: Option<PathBuf>,
}

/// One view to compare.
struct Case {
    name: String,
    view: PreparedView,
    /// rpict/vwrays view options, with any `-vf` path absolute.
    options: Vec<String>,
    width_px: u32,
    height_px: u32,
    /// The -x and -y given to every program, which each fits to the view's aspect.
    max_px: u32,
}

/// Per-pixel mean luminance of the reference and the standard error of that mean.
struct Reference {
    luminance_cd_m2: Vec<f64>,
    stderr_cd_m2: Vec<f64>,
    seconds: f64,
    paths_per_pixel: u32,
}

/// One picture's quality against the reference.
struct Quality {
    rms_rel: f64,
    rms_rel_corrected: f64,
    ev_lux: Option<f64>,
    dgp: Option<f64>,
}

pub fn run(args: &RenderBenchArgs) -> anyhow::Result<()> {
    if args.size < 8 || args.size > 1024 {
        bail!("--size {}: expected 8 to 1024 pixels", args.size);
    }
    if args.reference_paths < 16 {
        bail!(
            "--reference-paths {}: expected at least 16",
            args.reference_paths
        );
    }
    let bench = Bench::prepare(args)?;
    let view_specs: Vec<String> = if args.views.is_empty() {
        vec![
            "interior=-vf views/in.vf".into(),
            "fisheye=-vta -vp 3.0 1.5 1.2 -vd 0 -1 0 -vu 0 0 1 -vh 180 -vv 180".into(),
        ]
    } else {
        args.views.clone()
    };
    let mut last_second = 0u64;
    let mut results = Vec::new();
    for spec in &view_specs {
        let case = Case::parse(spec, &bench.room_dir, args.size)?;
        results.push(bench.compare_view(args, &case, &mut last_second)?);
    }
    let out = json!({
        "machine_threads": rayon::current_num_threads(),
        "cases": results,
    });
    if args.json {
        println!("{}", serde_json::to_string_pretty(&out)?);
    } else {
        print_table(&out);
    }
    let _ = std::fs::remove_dir_all(&bench.work);
    Ok(())
}

/// The scene as both programs have it: RADIANCE's octree and our world.
struct Bench {
    radiance: Radiance,
    room_dir: PathBuf,
    cache: PathBuf,
    /// This run's folder (sky file, octree, rpict's pictures).
    work: PathBuf,
    octree: PathBuf,
    /// The scene files' text, the reference cache's key.
    scene_text: Vec<u8>,
    world: World,
}

impl Bench {
    fn prepare(args: &RenderBenchArgs) -> anyhow::Result<Self> {
        let radiance = Radiance::find()?;
        let room_dir = args.room.clone().unwrap_or_else(|| {
            PathBuf::from(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../../shared/data/radiance-corpus/sariths-matrix-tutorial/room"
            ))
        });
        let room_dir = std::fs::canonicalize(&room_dir)
            .with_context(|| format!("--room {}", room_dir.display()))?;
        let sky_text = match &args.sky {
            Some(p) => {
                std::fs::read_to_string(p).with_context(|| format!("--sky {}", p.display()))?
            }
            None => DEFAULT_SKY.to_string(),
        };
        let cache = bench_cache_dir("bench-render");
        std::fs::create_dir_all(&cache).with_context(|| format!("creating {}", cache.display()))?;
        let work = tempfile_dir(&cache)?;
        let sky_path = work.join("sky.rad");
        std::fs::write(&sky_path, &sky_text)?;
        let mut scene_paths: Vec<PathBuf> = args.scene.iter().map(|f| room_dir.join(f)).collect();
        scene_paths.push(sky_path);
        let mut scene_text = Vec::new();
        for path in &scene_paths {
            scene_text.extend(
                std::fs::read(path).with_context(|| format!("reading {}", path.display()))?,
            );
        }
        let octree = work.join("scene.oct");
        let oct = radiance.output({
            let mut c = radiance.tool("oconv");
            c.current_dir(&room_dir).arg("-f").args(&scene_paths);
            c
        })?;
        std::fs::write(&octree, &oct)?;
        let scene = scene::load_files_with(
            &scene_paths,
            &scene::LoadOptions {
                working_directory: Some(room_dir.clone()),
                ..Default::default()
            },
        )?;
        let world = World::new(&scene)?;
        Ok(Self {
            radiance,
            room_dir,
            cache,
            work,
            octree,
            scene_text,
            world,
        })
    }

    /// One view: its reference, then each rpict configuration and ours at its time.
    fn compare_view(
        &self,
        args: &RenderBenchArgs,
        case: &Case,
        last_second: &mut u64,
    ) -> anyhow::Result<serde_json::Value> {
        let log = |msg: String| {
            if !args.json {
                eprintln!("[{}] {msg}", case.name);
            }
        };
        // The scene's text, not the octree's: a frozen octree's header names its files.
        let key = fnv1a(&[
            &self.scene_text,
            case.options.join(" ").as_bytes(),
            &case.width_px.to_le_bytes(),
            &case.height_px.to_le_bytes(),
            &args.reference_paths.to_le_bytes(),
        ]);
        let reference = reference(
            &self.radiance,
            &self.octree,
            case,
            args,
            &self.cache,
            key,
            last_second,
            &log,
        )?;
        let mut ref_glare = glare_of(&case.luminance_image(reference.luminance_cd_m2.clone()));
        // Over a whole hemisphere the picture's Ev is the irradiance at the eye: rtrace -I
        // there is its converged value, free of the sun pixel's sampling noise.
        let eye_ev = if case.sees_hemisphere() {
            let ev = eye_illuminance(&self.radiance, &self.octree, case, last_second)?;
            log(format!(
                "Ev at the eye (rtrace -I): {:.1} ± {:.1} lx",
                ev.0, ev.1
            ));
            ref_glare.0 = Some(ev.0);
            Some(ev)
        } else {
            None
        };
        let mut runs = Vec::new();
        for options in &args.rpict {
            runs.push(self.rpict_and_ours(
                args,
                case,
                options,
                runs.len(),
                &reference,
                &ref_glare,
                &log,
            )?);
        }
        if let Some(dir) = &args.images {
            let stem = format!("{}-reference", case.name);
            write_images(dir, &stem, &case.picture(&reference.luminance_cd_m2))?;
        }
        Ok(json!({
            "view": case.name,
            "options": case.options.join(" "),
            "resolution": [case.width_px, case.height_px],
            "reference": {
                "program": format!("vwrays -pj 1 | rtrace -ab {BOUNCES} -aa 0 -ad 1 -as 0 -lw 1e-5 -lr -16 -u+"),
                "paths_per_pixel": reference.paths_per_pixel,
                "seconds": reference.seconds,
                "noise_rel": reference.noise_rel().sqrt(),
                "ev_lux": ref_glare.0,
                "ev_from": if eye_ev.is_some() { "rtrace -I at the eye" } else { "the reference picture" },
                "ev_stderr_lux": eye_ev.map(|e| e.1),
                "dgp": ref_glare.1,
            },
            "runs": runs,
        }))
    }

    /// rpict with `options`, then ours filtered and unfiltered at its wall time.
    #[allow(clippy::too_many_arguments)]
    fn rpict_and_ours(
        &self,
        args: &RenderBenchArgs,
        case: &Case,
        options: &str,
        run: usize,
        reference: &Reference,
        ref_glare: &(Option<f64>, Option<f64>),
        log: &dyn Fn(String),
    ) -> anyhow::Result<serde_json::Value> {
        let (rpict_image, rpict_s) =
            run_rpict(&self.radiance, &self.octree, case, options, &self.work)?;
        let rpict_q = quality(&rpict_image, reference);
        log(format!(
            "rpict {options}: {rpict_s:.2} s, RMS {:.1} %",
            100.0 * rpict_q.rms_rel_corrected
        ));
        if let Some(dir) = &args.images {
            let stem = format!("{}-{run}-rpict", case.name);
            write_images(dir, &stem, &case.picture(&rpict_image.luminance_cd_m2))?;
        }
        let mut ours = Vec::new();
        for filtered in [true, false] {
            let mode = if filtered { "filtered" } else { "unfiltered" };
            let (image, spp, seconds) = ours_at(&self.world, case, filtered, rpict_s)?;
            let q = quality(
                &case.luminance_image(image.luminance_cd_m2.clone()),
                reference,
            );
            log(format!(
                "skylux {mode} {spp} paths/pixel: {seconds:.2} s, RMS {:.1} %",
                100.0 * q.rms_rel_corrected
            ));
            if let Some(dir) = &args.images {
                write_images(dir, &format!("{}-{run}-skylux-{mode}", case.name), &image)?;
            }
            ours.push(json!({
                "mode": mode,
                "paths_per_pixel": spp,
                "seconds": seconds,
                "quality": q.to_json(ref_glare),
            }));
        }
        Ok(json!({
            "rpict": {"options": options, "seconds": rpict_s,
                      "quality": rpict_q.to_json(ref_glare)},
            "skylux": ours,
        }))
    }
}

impl Case {
    fn parse(spec: &str, room: &Path, size: u32) -> anyhow::Result<Self> {
        let (name, text) = spec
            .split_once('=')
            .with_context(|| format!("--view {spec:?}: expected NAME=OPTIONS"))?;
        let mut options: Vec<String> = text.split_whitespace().map(String::from).collect();
        let mut view = View::default();
        let mut i = 0;
        while i < options.len() {
            if options[i] == "-vf" {
                let file = options
                    .get(i + 1)
                    .with_context(|| format!("--view {name}: -vf without a file"))?;
                let path = room.join(file);
                view = view.with_file(&path)?;
                options[i + 1] = path.display().to_string();
                i += 2;
            } else {
                i += 1;
            }
        }
        // The options other than -vf and its file, applied over the file's view.
        let rest: Vec<&str> = options
            .iter()
            .enumerate()
            .filter(|(k, o)| *o != "-vf" && (*k == 0 || options[k - 1] != "-vf"))
            .map(|(_, o)| o.as_str())
            .collect();
        if !rest.is_empty() {
            view = view.with_options(&rest.join(" "))?;
        }
        let view = view.prepare()?;
        let (width_px, height_px) = view.fit_resolution(size, size);
        Ok(Self {
            name: name.to_string(),
            view,
            options,
            width_px,
            height_px,
            max_px: size,
        })
    }

    /// A fisheye of at least 180° each way: its picture holds the whole hemisphere.
    fn sees_hemisphere(&self) -> bool {
        let v = &self.view.view;
        v.kind != ViewType::Perspective && v.horizontal_deg >= 180.0 && v.vertical_deg >= 180.0
    }

    fn luminance_image(&self, luminance_cd_m2: Vec<f64>) -> LuminanceImage {
        LuminanceImage {
            width_px: self.width_px,
            height_px: self.height_px,
            view: self.view.view.clone(),
            luminance_cd_m2,
        }
    }

    /// A grey picture of `luminance_cd_m2` (for the image files).
    fn picture(&self, luminance_cd_m2: &[f64]) -> Picture {
        let n = luminance_cd_m2.len();
        Picture {
            width_px: self.width_px,
            height_px: self.height_px,
            view: self.view.view.to_radiance_string(),
            radiance_rgb: luminance_cd_m2
                .iter()
                .map(|l| glam::DVec3::splat(l / skylux_hps::engine::WHITE_EFFICACY_LM_PER_W))
                .collect(),
            luminance_cd_m2: luminance_cd_m2.to_vec(),
            luminance_stderr_cd_m2: vec![0.0; n],
            samples_per_pixel: 1,
        }
    }
}

impl Reference {
    /// Mean over the pixels of (standard error / value)²: the reference's own share of a
    /// measured mean squared relative error.
    fn noise_rel(&self) -> f64 {
        let (mut sum, mut n) = (0.0, 0usize);
        for (l, se) in self.luminance_cd_m2.iter().zip(&self.stderr_cd_m2) {
            if *l > 0.0 {
                sum += (se / l).powi(2);
                n += 1;
            }
        }
        sum / n.max(1) as f64
    }
}

impl Quality {
    fn to_json(&self, reference: &(Option<f64>, Option<f64>)) -> serde_json::Value {
        let ev_rel = match (self.ev_lux, reference.0) {
            (Some(a), Some(b)) if b > 0.0 => Some(a / b - 1.0),
            _ => None,
        };
        json!({
            "rms_rel": self.rms_rel,
            "rms_rel_corrected": self.rms_rel_corrected,
            "ev_lux": self.ev_lux,
            "ev_rel_err": ev_rel,
            "dgp": self.dgp,
            "dgp_err": match (self.dgp, reference.1) { (Some(a), Some(b)) => Some(a - b), _ => None },
        })
    }
}

/// Ev and DGP of a picture as `skylux glare` computes them (None where the view has no
/// meaning for them).
fn glare_of(image: &LuminanceImage) -> (Option<f64>, Option<f64>) {
    match glare::evaluate(image, &GlareOptions::default()) {
        Ok(r) => (Some(r.ev_lux), Some(r.dgp)),
        Err(_) => (None, None),
    }
}

fn quality(image: &LuminanceImage, reference: &Reference) -> Quality {
    let (mut sum, mut n) = (0.0, 0usize);
    for (o, r) in image.luminance_cd_m2.iter().zip(&reference.luminance_cd_m2) {
        if *r > 0.0 {
            sum += ((o - r) / r).powi(2);
            n += 1;
        }
    }
    let mse = sum / n.max(1) as f64;
    let (ev_lux, dgp) = glare_of(image);
    Quality {
        rms_rel: mse.sqrt(),
        rms_rel_corrected: (mse - reference.noise_rel()).max(0.0).sqrt(),
        ev_lux,
        dgp,
    }
}

/// The reference: rtrace on vwrays' jittered rays, `reference_paths` per pixel, in batches
/// of independent processes (rtrace `-u+` seeds by the second; each batch starts in its own
/// second), cached under `key`.
#[allow(clippy::too_many_arguments)]
fn reference(
    radiance: &Radiance,
    octree: &Path,
    case: &Case,
    args: &RenderBenchArgs,
    cache: &Path,
    key: u64,
    last_second: &mut u64,
    log: &dyn Fn(String),
) -> anyhow::Result<Reference> {
    let path = cache.join(format!("reference-{key:016x}.json"));
    log(format!("reference cache: {}", path.display()));
    if let Ok(text) = std::fs::read_to_string(&path) {
        if let Ok(v) = serde_json::from_str::<serde_json::Value>(&text) {
            let get = |k: &str| -> Option<Vec<f64>> {
                v[k].as_array()?.iter().map(|x| x.as_f64()).collect()
            };
            if let (Some(l), Some(se), Some(s)) =
                (get("luminance"), get("stderr"), v["seconds"].as_f64())
            {
                if l.len() == (case.width_px * case.height_px) as usize {
                    log(format!("reference from the cache ({})", path.display()));
                    return Ok(Reference {
                        luminance_cd_m2: l,
                        stderr_cd_m2: se,
                        seconds: s,
                        paths_per_pixel: args.reference_paths,
                    });
                }
            }
        }
    }
    let dims = radiance.output({
        let mut c = radiance.tool("vwrays");
        c.args(["-d", "-pa", "1", "-x", &case.max_px.to_string()])
            .args(["-y", &case.max_px.to_string()])
            .args(&case.options);
        c
    })?;
    let dims = String::from_utf8_lossy(&dims).trim().to_string();
    let want = format!("-x {} -y {}", case.width_px, case.height_px);
    if dims != want {
        bail!("vwrays fits the view to {dims:?}, ours to {want:?}");
    }
    let pixels = (case.width_px * case.height_px) as usize;
    let (mut sum, mut sum2) = (vec![0.0f64; pixels], vec![0.0f64; pixels]);
    let batch = 256u32.min(args.reference_paths);
    let batches = args.reference_paths.div_ceil(batch);
    let start = Instant::now();
    let mut done = 0u32;
    // Two processes at a time, one per core.
    while done < batches {
        let mut running = Vec::new();
        for _ in 0..2.min(batches - done) {
            next_second(last_second);
            running.push(spawn_reference_batch(radiance, octree, case, batch)?);
        }
        for child in running {
            let values = read_batch(child, pixels, batch)?;
            for (p, l) in values.iter().enumerate() {
                sum[p] += l.0;
                sum2[p] += l.1;
            }
            done += 1;
        }
        log(format!(
            "reference: {} of {} paths per pixel, {:.0} s",
            done * batch,
            batches * batch,
            start.elapsed().as_secs_f64()
        ));
    }
    let n = f64::from(done * batch);
    let luminance: Vec<f64> = sum.iter().map(|s| s / n).collect();
    let stderr: Vec<f64> = sum2
        .iter()
        .zip(&luminance)
        .map(|(s2, m)| ((s2 / n - m * m).max(0.0) * n / (n - 1.0) / n).sqrt())
        .collect();
    let seconds = start.elapsed().as_secs_f64();
    let _ = std::fs::write(
        &path,
        serde_json::to_string(
            &json!({"luminance": luminance, "stderr": stderr, "seconds": seconds}),
        )?,
    );
    Ok(Reference {
        luminance_cd_m2: luminance,
        stderr_cd_m2: stderr,
        seconds,
        paths_per_pixel: done * batch,
    })
}

fn spawn_reference_batch(
    radiance: &Radiance,
    octree: &Path,
    case: &Case,
    per_pixel: u32,
) -> anyhow::Result<std::process::Child> {
    let size = [
        "-x".to_string(),
        case.max_px.to_string(),
        "-y".to_string(),
        case.max_px.to_string(),
    ];
    let mut vwrays = radiance.tool("vwrays");
    vwrays
        .args(["-ff", "-pj", "1", "-pa", "1", "-c", &per_pixel.to_string()])
        .args(&size)
        .args(&case.options)
        .stdout(Stdio::piped())
        .stderr(Stdio::null());
    let mut rays = vwrays.spawn().context("starting vwrays")?;
    let input = rays.stdout.take().context("vwrays' output")?;
    let mut rtrace = radiance.tool("rtrace");
    rtrace
        .args(["-u+", "-h", "-fff", "-ab", &BOUNCES.to_string()])
        .args([
            "-aa", "0", "-ad", "1", "-as", "0", "-lw", "1e-5", "-lr", "-16",
        ])
        .arg(octree)
        .stdin(input)
        .stdout(Stdio::piped())
        .stderr(Stdio::null());
    rtrace.spawn().context("starting rtrace")
}

/// Sums of the luminance and of its square per pixel from one batch's float output.
fn read_batch(
    mut child: std::process::Child,
    pixels: usize,
    per_pixel: u32,
) -> anyhow::Result<Vec<(f64, f64)>> {
    let mut out = child.stdout.take().context("rtrace's output")?;
    let mut bytes = Vec::new();
    out.read_to_end(&mut bytes)?;
    let status = child.wait()?;
    let expected = pixels * per_pixel as usize * 12;
    if !status.success() || bytes.len() != expected {
        bail!(
            "rtrace for the reference: {} bytes for {expected} ({status})",
            bytes.len()
        );
    }
    let mut sums = vec![(0.0, 0.0); pixels];
    for (i, ray) in bytes.chunks_exact(12).enumerate() {
        let c = |k: usize| {
            f64::from(f32::from_le_bytes(
                ray[4 * k..4 * k + 4].try_into().unwrap_or([0; 4]),
            ))
        };
        let l = skylux_hps::engine::WHITE_EFFICACY_LM_PER_W
            * (0.265 * c(0) + 0.670 * c(1) + 0.065 * c(2));
        let s = &mut sums[i / per_pixel as usize];
        s.0 += l;
        s.1 += l * l;
    }
    Ok(sums)
}

/// The illuminance at the view point on a plane facing the view direction (lux) and its
/// standard error: 64 rtrace -I estimates of 2048 paths each, in two processes.
fn eye_illuminance(
    radiance: &Radiance,
    octree: &Path,
    case: &Case,
    last_second: &mut u64,
) -> anyhow::Result<(f64, f64)> {
    let v = &case.view.view;
    let (p, d) = (v.position_m, v.direction.normalize());
    let line = format!("{} {} {} {} {} {}\n", p.x, p.y, p.z, d.x, d.y, d.z);
    let mut values = Vec::new();
    for _ in 0..2 {
        next_second(last_second);
        let mut c = radiance.tool("rtrace");
        c.args(["-u+", "-h", "-I", "-ab", &BOUNCES.to_string()])
            .args([
                "-aa", "0", "-ad", "2048", "-as", "0", "-lw", "1e-5", "-lr", "-16", "-n", "2",
            ])
            .arg(octree)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null());
        let mut child = c.spawn().context("starting rtrace -I")?;
        {
            use std::io::Write;
            let mut input = child.stdin.take().context("rtrace's input")?;
            input.write_all(line.repeat(32).as_bytes())?;
        }
        let out = child.wait_with_output()?;
        for l in String::from_utf8_lossy(&out.stdout).lines() {
            let rgb: Vec<f64> = l
                .split_whitespace()
                .filter_map(|x| x.parse().ok())
                .collect();
            if rgb.len() == 3 {
                values.push(
                    skylux_hps::engine::WHITE_EFFICACY_LM_PER_W
                        * (0.265 * rgb[0] + 0.670 * rgb[1] + 0.065 * rgb[2]),
                );
            }
        }
    }
    if values.len() != 64 {
        bail!("rtrace -I at the eye gave {} values for 64", values.len());
    }
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    Ok((mean, (var / n).sqrt()))
}

/// rpict's picture of the view and its wall time.
fn run_rpict(
    radiance: &Radiance,
    octree: &Path,
    case: &Case,
    options: &str,
    work: &Path,
) -> anyhow::Result<(LuminanceImage, f64)> {
    let out = work.join("rpict.hdr");
    let mut c = radiance.tool("rpict");
    c.args([
        "-x",
        &case.width_px.to_string(),
        "-y",
        &case.height_px.to_string(),
    ])
    // The resolution vwrays and ours fitted, as it is: rpict's own fit can be a pixel less.
    .args(["-pa", "0"])
    .args(&case.options)
    .args(options.split_whitespace())
    .arg(octree)
    .stdout(std::fs::File::create(&out)?);
    let start = Instant::now();
    let status = c.stderr(Stdio::null()).status().context("starting rpict")?;
    let seconds = start.elapsed().as_secs_f64();
    if !status.success() {
        bail!("rpict {options}: {status}");
    }
    let mut image = glare::load_image(&out, None)?;
    if (image.width_px, image.height_px) != (case.width_px, case.height_px) {
        bail!(
            "rpict made {}x{}, vwrays {}x{}",
            image.width_px,
            image.height_px,
            case.width_px,
            case.height_px
        );
    }
    image.view = case.view.view.clone();
    Ok((image, seconds))
}

/// Our picture at about `seconds` of wall time: paths per pixel from a 4-path calibration.
fn ours_at(
    world: &World,
    case: &Case,
    filtered: bool,
    seconds: f64,
) -> anyhow::Result<(Picture, u32, f64)> {
    let settings = |spp: u32| RenderSettings {
        width_px: case.width_px,
        height_px: case.height_px,
        samples_per_pixel: spp,
        trace: Settings {
            ambient_bounces: BOUNCES,
            seed: 17,
            ..Settings::default()
        },
        filtered,
    };
    let timed = |spp: u32| -> anyhow::Result<(Picture, f64)> {
        let start = Instant::now();
        let p = render::render(world, &case.view, &settings(spp), &|_, _| {})?;
        Ok((p, start.elapsed().as_secs_f64()))
    };
    let (_, t4) = timed(4)?;
    let mut spp = ((4.0 * seconds / t4.max(1e-6)).floor() as u32).max(1);
    let (mut picture, mut t) = timed(spp)?;
    if t > 1.1 * seconds && spp > 1 {
        spp = ((f64::from(spp) * seconds / t).floor() as u32).max(1);
        (picture, t) = timed(spp)?;
    }
    Ok((picture, spp, t))
}

fn write_images(dir: &Path, stem: &str, picture: &Picture) -> anyhow::Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    rgbe::write_hdr(&dir.join(format!("{stem}.hdr")), picture, None)?;
    falsecolour::write_falsecolour_png(
        &dir.join(format!("{stem}.png")),
        picture,
        &falsecolour::FalsecolourOptions {
            unit: falsecolour::LegendUnit::Luminance,
            scale: falsecolour::ColourScale::Log { decades: 3.0 },
            maximum: None,
            minimum: None,
            divisions: 6,
        },
    )?;
    Ok(())
}

fn print_table(out: &serde_json::Value) {
    let pct = |v: &serde_json::Value| {
        v.as_f64()
            .map_or("-".to_string(), |x| format!("{:+.2} %", 100.0 * x))
    };
    for case in out["cases"].as_array().into_iter().flatten() {
        let r = &case["reference"];
        println!(
            "{} {}x{}: reference {} paths/pixel ({:.0} s, noise {:.1} %), Ev {:.1} lx, DGP {:.3}",
            case["view"].as_str().unwrap_or(""),
            case["resolution"][0],
            case["resolution"][1],
            r["paths_per_pixel"],
            r["seconds"].as_f64().unwrap_or(0.0),
            100.0 * r["noise_rel"].as_f64().unwrap_or(0.0),
            r["ev_lux"].as_f64().unwrap_or(f64::NAN),
            r["dgp"].as_f64().unwrap_or(f64::NAN),
        );
        println!("  program                          time s   RMS rel  (raw)    Ev err    DGP err");
        for run in case["runs"].as_array().into_iter().flatten() {
            let row = |label: String, s: &serde_json::Value, q: &serde_json::Value| {
                println!(
                    "  {label:<32} {:>6.2} {:>8.1} % {:>6.1} % {:>9} {:>9}",
                    s.as_f64().unwrap_or(0.0),
                    100.0 * q["rms_rel_corrected"].as_f64().unwrap_or(0.0),
                    100.0 * q["rms_rel"].as_f64().unwrap_or(0.0),
                    pct(&q["ev_rel_err"]),
                    q["dgp_err"]
                        .as_f64()
                        .map_or("-".to_string(), |x| format!("{x:+.4}")),
                );
            };
            let rp = &run["rpict"];
            row(
                format!("rpict {}", rp["options"].as_str().unwrap_or("")),
                &rp["seconds"],
                &rp["quality"],
            );
            for o in run["skylux"].as_array().into_iter().flatten() {
                row(
                    format!(
                        "  skylux {} {} spp",
                        o["mode"].as_str().unwrap_or(""),
                        o["paths_per_pixel"]
                    ),
                    &o["seconds"],
                    &o["quality"],
                );
            }
        }
    }
}
