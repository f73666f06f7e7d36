//! Finding and running RADIANCE (from the pyradiance wheel, `SKYLUX_RADIANCE_BIN`, or PATH)
//! for the tests that compare with it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The folder holding rtrace, gensky and oconv, and the RAYPATH (its lib folder) if known.
pub fn radiance() -> Option<(PathBuf, Option<PathBuf>)> {
    let has = |dir: &Path| dir.join("rtrace").is_file() && dir.join("gensky").is_file();
    if let Some(dir) = std::env::var_os("SKYLUX_RADIANCE_BIN").map(PathBuf::from) {
        if has(&dir) {
            let lib = dir.parent().map(|p| p.join("lib")).filter(|l| l.is_dir());
            return Some((dir, lib));
        }
    }
    let out = Command::new("python3")
        .args([
            "-c",
            "import pyradiance, os; print(os.path.dirname(pyradiance.__file__))",
        ])
        .stderr(Stdio::null())
        .output()
        .ok()?;
    if out.status.success() {
        let root = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
        if has(&root.join("bin")) {
            return Some((root.join("bin"), Some(root.join("lib"))));
        }
    }
    std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .find(|d| has(d))
            .map(|d| (d, None))
    })
}

pub fn tool(bin: &Path, lib: &Option<PathBuf>, name: &str) -> Command {
    let mut c = Command::new(bin.join(name));
    // The folder first on PATH: a scene's inline commands (`!xform ...`) that oconv runs
    // must find the same programs, not fail and leave the scene empty.
    let mut path = std::ffi::OsString::from(bin);
    if let Some(old) = std::env::var_os("PATH") {
        path.push(":");
        path.push(old);
    }
    c.env("PATH", path);
    if let Some(lib) = lib {
        // "." first, as RADIANCE's default RAYPATH has it: function files beside the scene.
        let mut path = std::ffi::OsString::from(".:");
        path.push(lib);
        c.env("RAYPATH", path);
    }
    c
}

pub fn check_output(mut c: Command, input: Option<&[u8]>) -> Vec<u8> {
    use std::io::Write;
    c.stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let mut child = c.spawn().unwrap_or_else(|e| panic!("running {c:?}: {e}"));
    let mut stdin = child.stdin.take().unwrap();
    if let Some(input) = input {
        stdin.write_all(input).unwrap();
    }
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    assert!(
        out.status.success(),
        "{c:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

/// Luminance (cd/m², RADIANCE's 179 lm/W and its RGB weights) that `rtrace -ab 0` sees from
/// the origin along each of `directions` in the scene `text` (written, with its octree, into
/// `dir` under `name`). Rays go in through a file: piped while rtrace answers they would
/// fill both pipes; and as short numbers, since rtrace splits words longer than its buffer.
pub fn rtrace_luminance(
    bin: &Path,
    lib: &Option<PathBuf>,
    dir: &Path,
    name: &str,
    text: &str,
    directions: &[glam::DVec3],
) -> Vec<f64> {
    let rad = dir.join(format!("{name}.rad"));
    std::fs::write(&rad, text).unwrap();
    let mut oconv = tool(bin, lib, "oconv");
    oconv.current_dir(dir).arg(&rad);
    let oct = dir.join(format!("{name}.oct"));
    std::fs::write(&oct, check_output(oconv, None)).unwrap();
    let rays = dir.join(format!("{name}.rays"));
    let input: String = directions
        .iter()
        .map(|d| format!("0 0 0 {:.12e} {:.12e} {:.12e}\n", d.x, d.y, d.z))
        .collect();
    std::fs::write(&rays, input).unwrap();
    let mut rtrace = tool(bin, lib, "rtrace");
    rtrace
        .current_dir(dir)
        .args(["-h", "-w", "-ov", "-ab", "0"])
        .arg(&oct)
        .stdin(std::fs::File::open(&rays).unwrap());
    let run = rtrace.output().unwrap();
    assert!(
        run.status.success(),
        "rtrace: {}",
        String::from_utf8_lossy(&run.stderr)
    );
    let lum: Vec<f64> = String::from_utf8_lossy(&run.stdout)
        .lines()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|t| t.parse().unwrap()).collect();
            179.0 * (0.265 * v[0] + 0.670 * v[1] + 0.065 * v[2])
        })
        .collect();
    assert_eq!(lum.len(), directions.len(), "rtrace answered every ray");
    lum
}

/// RADIANCE found, or `None` after printing SKIPPED; panics when `SKYLUX_REQUIRE_RADIANCE` is
/// set (as CI sets it), so a missing RADIANCE can never pass there.
pub fn radiance_or_skip() -> Option<(PathBuf, Option<PathBuf>)> {
    let found = radiance();
    skylux_hps::prerequisite::available_or_skip(
        found.is_some(),
        skylux_hps::prerequisite::REQUIRE_RADIANCE,
        "RADIANCE (rtrace, gensky, oconv) not found (pip install pyradiance)",
    );
    found
}

/// Pure path tracing with rtrace (no ambient cache): the converged reference setting.
pub const RTRACE_PATH_TRACING: &[&str] = &[
    "-h", "-I", "-u+", "-ab", "8", "-aa", "0", "-ad", "4096", "-as", "0", "-lw", "1e-5", "-lr",
    "-16",
];

/// Illuminance (lux, RADIANCE's 179 lm/W and RGB weights) of an `rtrace -I` output line.
pub fn lux_of_line(line: &str) -> f64 {
    let v: Vec<f64> = line
        .split_whitespace()
        .map(|x| x.parse().expect("rtrace prints numbers"))
        .collect();
    179.0 * (0.265 * v[0] + 0.670 * v[1] + 0.065 * v[2])
}

/// Mean and standard error of rtrace's illuminance per sensor over `samples` independent
/// estimates, each with `args`, in `dir` (so relative file names in the scene resolve).
///
/// Each sensor is traced `samples` times: the points go in as `samples` copies, split over
/// two rtrace processes run at once (one per core). With `-u+` every copy draws fresh random
/// numbers, so the copies are independent estimates; and rtrace seeds its generator with the
/// wall clock in whole seconds (`srandom((long)time(0))` in RADIANCE's rtmain.c), so the two
/// processes start in different seconds. The standard error comes from the spread of the
/// copies: with 8 separate runs (the earlier design) the spread itself was so uncertain that
/// a 4-sigma band sometimes held half the real one. Identical copies fail the test rather
/// than pass with a spread of zero.
pub fn rtrace_lux_runs(
    bin: &Path,
    lib: &Option<PathBuf>,
    dir: &Path,
    octree: &Path,
    points: &[u8],
    args: &[&str],
    samples: usize,
) -> Vec<(f64, f64)> {
    const PROCESSES: usize = 2;
    assert!(samples >= 2 * PROCESSES, "at least two samples per process");
    let text = String::from_utf8_lossy(points);
    let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    let second = || {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_secs())
            .unwrap_or(0)
    };
    let mut last_start = 0;
    let copies_per_process = samples.div_ceil(PROCESSES);
    let children: Vec<std::thread::JoinHandle<Vec<f64>>> = (0..PROCESSES)
        .map(|_| {
            while second() == last_start {
                std::thread::sleep(std::time::Duration::from_millis(20));
            }
            last_start = second();
            let mut input = String::new();
            for _ in 0..copies_per_process {
                for l in &lines {
                    input.push_str(l);
                    input.push('\n');
                }
            }
            let mut c = tool(bin, lib, "rtrace");
            c.current_dir(dir).args(args).arg(octree);
            // Through a file: rtrace's answers would fill the pipe while we still write.
            let stem = octree.file_stem().unwrap_or_default().to_string_lossy();
            let input_path = dir.join(format!("{stem}-rtrace-input-{last_start}.pts"));
            std::fs::write(&input_path, input).unwrap();
            c.stdin(std::fs::File::open(&input_path).unwrap());
            std::thread::spawn(move || {
                let out = c.output().unwrap_or_else(|e| panic!("running rtrace: {e}"));
                assert!(
                    out.status.success(),
                    "rtrace failed: {}",
                    String::from_utf8_lossy(&out.stderr)
                );
                String::from_utf8(out.stdout)
                    .unwrap()
                    .lines()
                    .filter(|l| !l.trim().is_empty())
                    .map(lux_of_line)
                    .collect()
            })
        })
        .collect();
    let values: Vec<f64> = children
        .into_iter()
        .flat_map(|h| h.join().expect("rtrace thread"))
        .collect();
    let n_sensors = lines.len();
    assert_eq!(
        values.len(),
        n_sensors * copies_per_process * PROCESSES,
        "one rtrace answer per point copy"
    );
    (0..n_sensors)
        .map(|s| {
            let xs: Vec<f64> = values.iter().skip(s).step_by(n_sensors).copied().collect();
            assert!(
                xs.windows(2).any(|w| w[0] != w[1]),
                "every rtrace estimate of sensor {s} was the same: the samples were not independent"
            );
            let n = xs.len() as f64;
            let mean = xs.iter().sum::<f64>() / n;
            let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
            (mean, (var / n).sqrt())
        })
        .collect()
}

/// The per-comparison false-alarm rate the bands are set for: a CI run makes about sixty
/// comparison sets (some 600 sensors, natively and under qemu-arm), so a fixed 3σ band per
/// sensor would fail most runs by chance alone (600 × 0.27 %), while 10⁻⁴ per set for the
/// sensors and as much for the set's mean keeps a chance failure near one run in a hundred.
pub const FALSE_ALARM_PER_SET: f64 = 1e-4;

/// Complementary error function, Chebyshev fit with fractional error below 1.2e-7 everywhere
/// (Press et al., Numerical Recipes in C, 2nd ed., §6.2, `erfcc`).
fn erfc(x: f64) -> f64 {
    // The fit's coefficients, lowest power of t first (Horner's rule from the highest).
    const C: [f64; 10] = [
        -1.265_512_23,
        1.000_023_68,
        0.374_091_96,
        0.096_784_18,
        -0.186_288_06,
        0.278_868_07,
        -1.135_203_98,
        1.488_515_87,
        -0.822_152_23,
        0.170_872_77,
    ];
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = C.iter().rev().fold(0.0, |acc, c| acc * t + c);
    let r = t * (-z * z + poly).exp();
    if x >= 0.0 {
        r
    } else {
        2.0 - r
    }
}

/// The band in standard errors whose two-sided normal tail is `p`: P(|z| > k) = p.
pub fn two_sided_k(p: f64) -> f64 {
    let (mut lo, mut hi) = (0.0_f64, 40.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        // P(|z| > k) = erfc(k / √2).
        if erfc(mid / std::f64::consts::SQRT_2) > p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn the_bands_are_the_normal_quantiles() {
    // Two-sided normal tails: 4.55 % beyond 2 σ, 0.27 % beyond 3 σ, 10⁻⁴ beyond 3.8906 σ.
    for (p, k) in [(0.045_500_26, 2.0), (0.002_699_8, 3.0), (1e-4, 3.890_59)] {
        assert!((two_sided_k(p) - k).abs() < 1e-3, "{p}: {}", two_sided_k(p));
    }
}

/// Compares our illuminance with rtrace's per sensor and over the whole set; prints every
/// sensor and returns the failures.
///
/// rtrace's standard error at a sensor comes from a few independent runs, so it is itself
/// noisy (heavy-tailed where a run happens to miss a sunlit patch: its mean is then low *and*
/// its spread small). It is therefore moderated towards the set's median, giving the pooled
/// estimate the weight of the sensor's own (an empirical-Bayes shrinkage, as in Smyth 2004,
/// "Linear models and empirical Bayes methods", Stat. Appl. Genet. Mol. Biol. 3(1)): the
/// sensors of one room share their indirect paths, whose spread is what both sides estimate.
///
/// Per sensor |ours − rtrace| must be within max(2 % of rtrace, k × the combined error);
/// over the set, the mean of the per-sensor z scores times √n (sensors are traced
/// independently on both sides) must be within ±k too, which catches a bias of a fraction of
/// a per-sensor error that every sensor shares. k is `k_sigma` or, where larger, the band
/// that keeps the chance of a false alarm at [`FALSE_ALARM_PER_SET`] (per sensor Šidák's
/// correction for n sensors: 4.26 σ for 5 sensors, 4.65 σ for 30; 3.89 σ for the set).
pub fn agreement_failures(
    label: &str,
    ours: &[skylux_hps::engine::SensorIlluminance],
    reference: &[(f64, f64)],
    k_sigma: f64,
) -> Vec<String> {
    agreement_failures_within(label, ours, reference, k_sigma, None)
}

/// [`agreement_failures`] for two scenes that differ by design (the same device as two
/// independently sampled BSDFs): with `band`, each sensor within that fraction of rtrace or
/// k σ, and the mean relative difference within it, instead of 2 % and the shared-bias test.
pub fn agreement_failures_within(
    label: &str,
    ours: &[skylux_hps::engine::SensorIlluminance],
    reference: &[(f64, f64)],
    k_sigma: f64,
    band: Option<f64>,
) -> Vec<String> {
    assert_eq!(
        ours.len(),
        reference.len(),
        "{label}: one result per sensor"
    );
    assert!(!ours.is_empty(), "{label}: no sensors");
    let n = ours.len() as f64;
    let k_sensor = k_sigma.max(two_sided_k(FALSE_ALARM_PER_SET / n));
    let k_set = k_sigma.max(two_sided_k(FALSE_ALARM_PER_SET));
    let mut variances: Vec<f64> = reference.iter().map(|(_, se)| se * se).collect();
    variances.sort_by(f64::total_cmp);
    let pooled_variance = variances[variances.len() / 2];
    let mut failures = Vec::new();
    let (mut z_sum, mut relative_sum) = (0.0, 0.0);
    for (o, (r, r_se)) in ours.iter().zip(reference) {
        let diff = o.illuminance_lux - r;
        let rtrace_variance = 0.5 * (r_se * r_se + pooled_variance);
        let combined = (o.stderr_lux.powi(2) + rtrace_variance).sqrt();
        let allowed = (band.unwrap_or(0.02) * r).max(k_sensor * combined);
        z_sum += diff / combined;
        relative_sum += diff / r;
        println!(
            "  {label} {}: ours {:.1} ± {:.1} lux, rtrace {:.1} ± {:.1} lux (moderated ± {:.1}), diff {:+.2} % ({:+.2} σ)",
            o.name,
            o.illuminance_lux,
            o.stderr_lux,
            r,
            r_se,
            rtrace_variance.sqrt(),
            100.0 * diff / r,
            diff / combined
        );
        if diff.abs() > allowed {
            failures.push(format!(
                "{}: {:.1} vs {:.1} (allowed ±{allowed:.1})",
                o.name, o.illuminance_lux, r
            ));
        }
    }
    if let Some(band) = band {
        let mean = relative_sum / n;
        println!(
            "  {label}: mean difference {:+.2} % (allowed ±{:.1} %)",
            100.0 * mean,
            100.0 * band
        );
        if mean.abs() > band {
            failures.push(format!("the mean difference {:+.2} %", 100.0 * mean));
        }
        return failures;
    }
    let set_z = z_sum / n.sqrt();
    println!(
        "  {label}: per sensor within ±{k_sensor:.2} σ; mean z over {n} sensors × √n = {set_z:+.2} (allowed ±{k_set:.2})"
    );
    if set_z.abs() > k_set {
        failures.push(format!(
            "the set as a whole: mean z × √n = {set_z:+.2}, a shared bias (allowed ±{k_set:.2})"
        ));
    }
    failures
}

/// Whether python3 can import `pyradiance.bsdf` (RADIANCE's BSDF library); prints SKIPPED
/// and returns false when not, or panics when `SKYLUX_REQUIRE_RADIANCE` is set.
pub fn pyradiance_bsdf_or_skip() -> bool {
    let ok = Command::new("python3")
        .args(["-c", "import pyradiance.bsdf"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    skylux_hps::prerequisite::available_or_skip(
        ok,
        skylux_hps::prerequisite::REQUIRE_RADIANCE,
        "python3 cannot import pyradiance.bsdf (pip install pyradiance)",
    )
}
