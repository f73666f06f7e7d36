//! The lux-meters' truth from RADIANCE instead of Skylux's own engine, so the loop's test bed
//! is independent of the model it tests (issue 18).
//!
//! One `rcontrib` run per campaign gives, per sensor, daylight coefficients: the illuminance
//! per unit radiance of (a) each Reinhart MF:4 sky patch (a `glow` of radiance 1 over the
//! upper hemisphere, binned by RADIANCE's own `reinhartb.cal`), (b) each bin of a uniform
//! ground (a `glow` below the horizon, binned by [`GroundBins`] so the glazing's angular
//! effect can weight it), and (c) each capture's sun (a `light` source of the sun's solid
//! angle at SPA's direction, its own modifier). A capture's illuminance is then the sum of
//! coefficient × luminance, the sky's luminance averaged over each patch by stratified
//! sub-sampling ([`PATCH_SUBSAMPLES`]), not read at the centre.
//!
//! Units: with `-I` rcontrib gives W/m² per W/(sr m²) of radiance; RADIANCE's luminous
//! efficacy (179 lm/W) converts both, so a coefficient is lux per cd/m² as it stands.
//!
//! Noise (pure Monte Carlo, [`RCONTRIB_ARGS`], 12 bounces): two runs on the reference room
//! (shared/scenes/test-module, five sensors 1 to 4.7 m from the façade) differ by 0.04-1.8 %
//! in the summed sky coefficients, 0.1-2.3 % in the ground's, and in the sun's by 0.01 % on
//! the sensor it shines on and up to 2.1 % on those it reaches by reflection only: about 1 %
//! standard deviation per run at the back of the room, fixed for a whole campaign (a
//! per-sensor bias of the truth, not noise between captures). One run: 6 s of one core.

use crate::radiance_tools::{Radiance, RadianceError};
use glam::DVec3;
use skylux_hps::scene::Sensor;
use skylux_hps::sky::SkyPatches;
use std::f64::consts::{FRAC_PI_2, TAU};
use std::fmt::Write as _;
use std::path::Path;

/// Reinhart subdivision of the sky's coefficients (MF:4, 2305 patches, as `reinhartb.cal`).
pub const SKY_MF: usize = 4;

/// Stratified sub-samples per side of a patch (so `PATCH_SUBSAMPLES²` directions per patch,
/// each the centre of an equal-solid-angle stratum).
pub const PATCH_SUBSAMPLES: usize = 5;

/// rcontrib's settings (the bounces apart): irradiance, pure Monte Carlo (rcontrib keeps no
/// ambient cache), Russian roulette below the weight limit so deep paths are not cut, 65536
/// first-bounce rays, and each sun's shadow ray aimed at its centre (`-dj 0`: rcontrib's
/// default jitter puts one ray anywhere on the disk, which moves a 20° sun's light on a
/// horizontal sensor by up to ±1.3 %).
pub const RCONTRIB_ARGS: &[&str] = &[
    "-h", "-I", "-faa", "-dj", "0", "-lr", "-16", "-ad", "65536", "-lw", "1e-6",
];

/// Diffuse bounces of a converged truth, as the loop's model uses them
/// ([`skylux_hps::engine::integrator::CONVERGED_AMBIENT_BOUNCES`]).
pub const CONVERGED_BOUNCES: u32 = skylux_hps::engine::integrator::CONVERGED_AMBIENT_BOUNCES;

/// RADIANCE's RGB to luminance weights (RADIANCE `color.h`, `bright()` for its primaries).
const LUMINANCE_WEIGHTS: [f64; 3] = [0.265, 0.670, 0.065];

/// Why the RADIANCE truth could not be computed.
#[derive(Debug, thiserror::Error)]
pub enum RadianceTruthError {
    #[error(transparent)]
    Radiance(#[from] RadianceError),
    #[error("{path}: {source}")]
    Io {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
    #[error("rcontrib output: {0}")]
    Output(String),
}

/// Bins of the ground (below the horizon): `ROWS` bands of depression angle, each of `COLS`
/// azimuth sectors from north towards east. The ground is uniform, so its bins only serve to
/// weight the glazing's angular transmittance by where its light really comes from.
pub struct GroundBins;

impl GroundBins {
    pub const ROWS: usize = 6;
    pub const COLS: usize = 12;

    pub const fn len() -> usize {
        Self::ROWS * Self::COLS
    }

    /// The same binning as a RADIANCE expression of the ray direction (Dx, Dy, Dz) for
    /// rcontrib's `-b`: `gbin`, −1 above the horizon.
    pub fn rcontrib_definitions() -> String {
        format!(
            "gdep = asin(if(-Dz-1, 1, -Dz)); grow0 = floor(gdep*{rows}/(PI/2)); \
             grow = if(grow0-{rmax}, {rmax}, grow0); gaz0 = atan2(Dx, Dy); \
             gaz = if(gaz0, gaz0, gaz0+2*PI); gcol0 = floor(gaz*{cols}/(2*PI)); \
             gcol = if(gcol0-{cmax}, {cmax}, gcol0); gbin = if(-Dz, grow*{cols}+gcol, -1);",
            rows = Self::ROWS,
            cols = Self::COLS,
            rmax = Self::ROWS - 1,
            cmax = Self::COLS - 1,
        )
    }

    /// The bin of a direction below the horizon.
    pub fn bin_of(d: DVec3) -> Option<usize> {
        let d = d.normalize();
        if d.z.is_nan() || d.z >= 0.0 {
            return None;
        }
        let depression = (-d.z).min(1.0).asin();
        let row = ((depression / FRAC_PI_2 * Self::ROWS as f64) as usize).min(Self::ROWS - 1);
        let az = d.x.atan2(d.y).rem_euclid(TAU);
        let col = ((az / TAU * Self::COLS as f64) as usize).min(Self::COLS - 1);
        Some(row * Self::COLS + col)
    }

    /// `n × n` directions, each the centre of an equal-solid-angle stratum of bin `b`.
    pub fn directions(b: usize, n: usize) -> Vec<DVec3> {
        let (row, col) = (b / Self::COLS, b % Self::COLS);
        let band = FRAC_PI_2 / Self::ROWS as f64;
        let sector = TAU / Self::COLS as f64;
        stratified(
            (band * row as f64).sin(),
            (band * (row + 1) as f64).sin(),
            sector * col as f64,
            sector * (col + 1) as f64,
            n,
        )
        .into_iter()
        .map(|d| DVec3::new(d.x, d.y, -d.z))
        .collect()
    }
}

/// `n × n` upper-hemisphere directions at the centres of equal-solid-angle strata of the
/// region sin(altitude) ∈ [s0, s1], azimuth (from north towards east) ∈ [a0, a1].
fn stratified(s0: f64, s1: f64, a0: f64, a1: f64, n: usize) -> Vec<DVec3> {
    let mut out = Vec::with_capacity(n * n);
    for i in 0..n {
        let s = s0 + (s1 - s0) * (i as f64 + 0.5) / n as f64;
        let c = (1.0 - s * s).max(0.0).sqrt();
        for j in 0..n {
            let a = a0 + (a1 - a0) * (j as f64 + 0.5) / n as f64;
            out.push(DVec3::new(a.sin() * c, a.cos() * c, s));
        }
    }
    out
}

/// `n × n` directions, each the centre of an equal-solid-angle stratum of Reinhart patch `p`
/// (the layout of [`SkyPatches::reinhart`], which is `reinhartb.cal`'s bin numbering: a
/// test checks it against RADIANCE).
pub fn patch_directions(patches: &SkyPatches, p: usize, n: usize) -> Vec<DVec3> {
    let alpha = patches.row_height_rad;
    if p == patches.len() - 1 {
        let top = alpha * patches.per_row.len() as f64;
        return stratified(top.sin(), 1.0, 0.0, TAU, n);
    }
    let (mut row, mut start) = (0, 0);
    while start + patches.per_row[row] <= p {
        start += patches.per_row[row];
        row += 1;
    }
    let width = TAU / patches.per_row[row] as f64;
    let centre = width * (p - start) as f64;
    stratified(
        (alpha * row as f64).sin(),
        (alpha * (row + 1) as f64).sin(),
        centre - width / 2.0,
        centre + width / 2.0,
        n,
    )
}

/// A sun for rcontrib: where it is and its disk's solid angle.
#[derive(Clone, Copy, Debug)]
pub struct SunSource {
    pub direction: DVec3,
    pub solid_angle_sr: f64,
}

/// Per sensor, illuminance per unit luminance (lux per cd/m²) of each sky patch, each ground
/// bin and each sun.
#[derive(Clone, Debug)]
pub struct DaylightCoefficients {
    /// `[sensor][patch]`, Reinhart MF:4.
    pub sky: Vec<Vec<f64>>,
    /// `[sensor][ground bin]` ([`GroundBins`]).
    pub ground: Vec<Vec<f64>>,
    /// `[sensor][sun]`, in the order of the suns given.
    pub sun: Vec<Vec<f64>>,
}

impl DaylightCoefficients {
    /// One rcontrib run on `scene` (a RADIANCE file; relative references resolve beside it)
    /// for `sensors` with `suns`, with `ambient_bounces` diffuse bounces.
    pub fn compute(
        radiance: &Radiance,
        scene: &Path,
        sensors: &[Sensor],
        suns: &[SunSource],
        ambient_bounces: u32,
    ) -> Result<Self, RadianceTruthError> {
        let tmp = tempfile::tempdir().map_err(|source| RadianceTruthError::Io {
            path: std::env::temp_dir(),
            source,
        })?;
        let write = |name: &str, text: &str| {
            let path = tmp.path().join(name);
            std::fs::write(&path, text).map_err(|source| RadianceTruthError::Io {
                path: path.clone(),
                source,
            })?;
            Ok::<_, RadianceTruthError>(path)
        };
        let sources = write("sources.rad", &sources_text(suns))?;
        let modifiers = write(
            "suns.txt",
            &(0..suns.len())
                .map(|k| format!("sun_{k}\n"))
                .collect::<String>(),
        )?;
        let rays = write(
            "sensors.rays",
            &sensors
                .iter()
                .map(|s| {
                    let (p, d) = (s.position_m, s.direction);
                    format!(
                        "{:.9} {:.9} {:.9} {:.12} {:.12} {:.12}\n",
                        p.x, p.y, p.z, d.x, d.y, d.z
                    )
                })
                .collect::<String>(),
        )?;
        let scene_dir = scene
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let octree = {
            let mut c = radiance.tool("oconv");
            c.current_dir(scene_dir)
                .arg(scene_abs(scene)?)
                .arg(&sources);
            radiance.output(c)?
        };
        let octree_path = tmp.path().join("truth.oct");
        std::fs::write(&octree_path, octree).map_err(|source| RadianceTruthError::Io {
            path: octree_path.clone(),
            source,
        })?;
        let mut c = radiance.tool("rcontrib");
        c.current_dir(scene_dir)
            .args(RCONTRIB_ARGS)
            .args(["-ab", &ambient_bounces.to_string()])
            .args(["-f", "reinhartb.cal", "-p"])
            .arg(format!("MF={SKY_MF}"))
            .args(["-b", "rbin", "-bn", "Nrbins", "-m", "skyglow"])
            .args(["-e", &GroundBins::rcontrib_definitions()])
            .args(["-b", "gbin", "-bn", &GroundBins::len().to_string()])
            .args(["-m", "groundglow", "-b", "0", "-bn", "1"]);
        if !suns.is_empty() {
            c.arg("-M").arg(&modifiers);
        }
        c.arg(&octree_path);
        let file = std::fs::File::open(&rays).map_err(|source| RadianceTruthError::Io {
            path: rays.clone(),
            source,
        })?;
        c.stdin(file);
        let out = radiance.output(c)?;
        Self::parse(&String::from_utf8_lossy(&out), sensors.len(), suns.len())
    }

    /// rcontrib's ASCII output: one line per sensor, the modifiers' bins in order, an RGB
    /// triple each.
    fn parse(text: &str, sensors: usize, suns: usize) -> Result<Self, RadianceTruthError> {
        let n_sky = SkyPatches::reinhart(SKY_MF).len();
        let n_ground = GroundBins::len();
        let per_line = n_sky + n_ground + suns;
        let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
        if lines.len() != sensors {
            return Err(RadianceTruthError::Output(format!(
                "{} lines for {sensors} sensors",
                lines.len()
            )));
        }
        let mut out = Self {
            sky: vec![],
            ground: vec![],
            sun: vec![],
        };
        for (s, line) in lines.iter().enumerate() {
            let v: Vec<f64> = line
                .split_whitespace()
                .map(|w| {
                    w.parse::<f64>().map_err(|_| {
                        RadianceTruthError::Output(format!(
                            "sensor {}: `{w}` is not a number",
                            s + 1
                        ))
                    })
                })
                .collect::<Result<_, _>>()?;
            if v.len() != 3 * per_line {
                return Err(RadianceTruthError::Output(format!(
                    "sensor {}: {} values, expected {} (3 × ({n_sky} sky + {n_ground} ground \
                     + {suns} suns))",
                    s + 1,
                    v.len(),
                    3 * per_line
                )));
            }
            let lum: Vec<f64> = v
                .chunks_exact(3)
                .map(|c| c.iter().zip(LUMINANCE_WEIGHTS).map(|(a, w)| a * w).sum())
                .collect();
            out.sky.push(lum[..n_sky].to_vec());
            out.ground.push(lum[n_sky..n_sky + n_ground].to_vec());
            out.sun.push(lum[n_sky + n_ground..].to_vec());
        }
        Ok(out)
    }
}

/// The scene's path made absolute (oconv runs beside it).
fn scene_abs(scene: &Path) -> Result<std::path::PathBuf, RadianceTruthError> {
    std::path::absolute(scene).map_err(|source| RadianceTruthError::Io {
        path: scene.to_path_buf(),
        source,
    })
}

/// The sky, ground and suns as rcontrib's modifiers: glows of radiance 1 over each
/// hemisphere (a `source` of 180° is a hemisphere), and a `light` of radiance 1 per sun, its
/// disk's full angle from the solid angle Ω = 2π (1 − cos(angle / 2)).
fn sources_text(suns: &[SunSource]) -> String {
    let mut t = String::from(
        "void glow skyglow\n0\n0\n4 1 1 1 0\nskyglow source skydome\n0\n0\n4 0 0 1 180\n\
         void glow groundglow\n0\n0\n4 1 1 1 0\ngroundglow source grounddome\n0\n0\n4 0 0 -1 180\n",
    );
    for (k, s) in suns.iter().enumerate() {
        let d = s.direction.normalize();
        let angle = 2.0 * (1.0 - s.solid_angle_sr / TAU).acos().to_degrees();
        let _ = write!(
            t,
            "void light sun_{k}\n0\n0\n3 1 1 1\nsun_{k} source sun_{k}_disk\n0\n0\n4 {:.12} {:.12} {:.12} {angle:.9}\n",
            d.x, d.y, d.z
        );
    }
    t
}

/// The campaign's truth from RADIANCE's coefficients: each capture's light from its sky,
/// ground and sun.
pub struct RadianceTruth {
    pub coefficients: DaylightCoefficients,
    /// Per sky patch, its stratified sub-sample directions.
    sky_directions: Vec<Vec<DVec3>>,
    /// Per ground bin, its stratified sub-sample directions.
    ground_directions: Vec<Vec<DVec3>>,
}

impl RadianceTruth {
    pub fn new(coefficients: DaylightCoefficients) -> Self {
        let patches = SkyPatches::reinhart(SKY_MF);
        Self {
            coefficients,
            sky_directions: (0..patches.len())
                .map(|p| patch_directions(&patches, p, PATCH_SUBSAMPLES))
                .collect(),
            ground_directions: (0..GroundBins::len())
                .map(|b| GroundBins::directions(b, PATCH_SUBSAMPLES))
                .collect(),
        }
    }

    /// Per sensor, lux from a sky of luminance `sky(d)` (cd/m², whatever reaches the room from
    /// d: glazing effects included), each patch's luminance averaged over its sub-samples.
    pub fn sky_lux(&self, sky: &(dyn Fn(DVec3) -> f64 + Sync)) -> Vec<f64> {
        let mean: Vec<f64> = self
            .sky_directions
            .iter()
            .map(|ds| ds.iter().map(|&d| sky(d)).sum::<f64>() / ds.len() as f64)
            .collect();
        dot_each(&self.coefficients.sky, &mean)
    }

    /// Per sensor, lux from a uniform ground of `ground_cd_m2` seen through a glazing of
    /// angular transmittance `iam(d)` (1: none), averaged over each ground bin.
    pub fn ground_lux(&self, ground_cd_m2: f64, iam: &dyn Fn(DVec3) -> f64) -> Vec<f64> {
        let mean: Vec<f64> = self
            .ground_directions
            .iter()
            .map(|ds| ground_cd_m2 * ds.iter().map(|&d| iam(d)).sum::<f64>() / ds.len() as f64)
            .collect();
        dot_each(&self.coefficients.ground, &mean)
    }

    /// Per sensor, lux from sun `k` of luminance `sun_cd_m2` (glazing effects included).
    pub fn sun_lux(&self, k: usize, sun_cd_m2: f64) -> Vec<f64> {
        self.coefficients
            .sun
            .iter()
            .map(|c| c[k] * sun_cd_m2)
            .collect()
    }
}

/// Per row of `m`, its dot product with `v`.
fn dot_each(m: &[Vec<f64>], v: &[f64]) -> Vec<f64> {
    m.iter()
        .map(|row| row.iter().zip(v).map(|(a, b)| a * b).sum())
        .collect()
}
