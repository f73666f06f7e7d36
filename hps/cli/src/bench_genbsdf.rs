//! `skylux bench genbsdf`: `skylux genbsdf` against the pyradiance port of genBSDF on the
//! same device and sampling box at the same rays per patch, in one run: both times, their
//! ratio, and how far apart the two files' per-patch hemispherical R and T are.

use anyhow::Context;
use glam::DVec3;
use skylux_hps::bsdf::{bsdf_xml, AngleBasis, Bsdf, Scattering, Side};
use skylux_hps::engine::genbsdf::{generate_klems, GenBsdfSettings, SamplingBox};
use skylux_hps::engine::World;
use skylux_hps::scene;
use std::path::PathBuf;
use std::time::Instant;

/// The built-in device: a venetian blind of 25 mm slats at 45° (the tests' fixture).
const BLIND: &str = include_str!("../../core/tests/fixtures/genbsdf/blind45.rad");
const BLIND_BOX: [f64; 6] = [0.1, 0.9, 0.1, 0.9, -0.0176777, 0.0];

#[derive(clap::Args)]
pub struct GenbsdfBenchArgs {
    /// The device (default: the built-in 45° venetian blind).
    #[arg(long)]
    device: Option<PathBuf>,
    /// XMIN XMAX YMIN YMAX ZMIN ZMAX (default: the blind's middle 0.8 m square).
    #[arg(long, num_args = 6, allow_negative_numbers = true)]
    dim: Option<Vec<f64>>,
    /// Rays per incident patch for both.
    #[arg(long, default_value_t = 200)]
    samples: u32,
    #[arg(long)]
    json: bool,
}

pub fn run(args: &GenbsdfBenchArgs) -> anyhow::Result<()> {
    let work = tempfile::tempdir()?;
    let device = match &args.device {
        Some(p) => std::fs::canonicalize(p).with_context(|| format!("{}", p.display()))?,
        None => {
            let p = work.path().join("blind45.rad");
            std::fs::write(&p, BLIND)?;
            p
        }
    };
    let d = args.dim.clone().unwrap_or(BLIND_BOX.to_vec());
    let sampling = SamplingBox {
        min: DVec3::new(d[0], d[2], d[4]),
        max: DVec3::new(d[1], d[3], d[5]),
    };
    let world = World::new(&scene::load(&device)?)?;
    let basis = AngleBasis::builtin("LBNL/Klems Full").context("basis")?;
    let settings = GenBsdfSettings {
        samples_per_patch: args.samples,
        ..Default::default()
    };
    let start = Instant::now();
    let ours = generate_klems(&world, &sampling, &basis, &settings, &|_, _| {})?;
    let ours_s = start.elapsed().as_secs_f64();
    let our_path = work.path().join("ours.xml");
    let doc = ours.document("bench", "skylux bench genbsdf", "meter", &sampling);
    std::fs::write(&our_path, bsdf_xml(&doc).map_err(anyhow::Error::msg)?)?;

    let their_path = work.path().join("theirs.xml");
    let start = Instant::now();
    run_port(&device, work.path(), args.samples, &d, &their_path)?;
    let theirs_s = start.elapsed().as_secs_f64();
    let (worst, rms) = hemispherical_differences(&basis, &our_path, &their_path)?;
    let ratio = ours_s / theirs_s;
    if args.json {
        println!(
            "{{\"samples_per_patch\":{},\"ours_s\":{ours_s:.3},\"pyradiance_genbsdf_s\":{theirs_s:.3},\"ratio\":{ratio:.5},\"largest_hemispherical_difference\":{worst:.4},\"rms_hemispherical_difference\":{rms:.4}}}",
            args.samples
        );
    } else {
        println!(
            "device {} box {:?}, {} rays per patch, Klems full, both sides",
            device.display(),
            d,
            args.samples
        );
        println!("skylux genbsdf            {ours_s:9.3} s");
        println!("pyradiance genbsdf (2 procs) {theirs_s:6.3} s");
        println!("ratio                     {ratio:9.5}");
        println!("per-patch R and T apart: largest {worst:.4}, RMS {rms:.4} (both files' noise)");
    }
    Ok(())
}

/// The pyradiance port of genBSDF on `device` within `d`, `samples` rays per patch, its XML
/// written to `out`.
fn run_port(
    device: &std::path::Path,
    work: &std::path::Path,
    samples: u32,
    d: &[f64],
    out: &std::path::Path,
) -> anyhow::Result<()> {
    let script = "import sys\n\
        from pyradiance import genbsdf as g\n\
        d = [float(x) for x in sys.argv[4:10]]\n\
        res = g.generate_bsdf(sys.argv[1], nsamp=int(sys.argv[2]), nproc=2, \
        dim=g.SamplingBox(*d))\n\
        open(sys.argv[3], 'wb').write(g.generate_xml(vis_results=res, basis='kf'))\n";
    let status = std::process::Command::new("python3")
        .current_dir(device.parent().unwrap_or(work))
        .args(["-c", script])
        .arg(device)
        .arg(samples.to_string())
        .arg(out)
        .args([d[0], d[1], d[2], d[3], d[4], d[5]].map(|v| v.to_string()))
        .status()
        .context("python3 (pip install pyradiance)")?;
    anyhow::ensure!(status.success(), "pyradiance.genbsdf failed");
    Ok(())
}

/// The largest and the RMS difference of the two files' directional-hemispherical R and T
/// over the patch centres of every part.
fn hemispherical_differences(
    basis: &AngleBasis,
    ours: &std::path::Path,
    theirs: &std::path::Path,
) -> anyhow::Result<(f64, f64)> {
    let (mine, theirs) = (Bsdf::load(ours)?, Bsdf::load(theirs)?);
    let mut worst = 0.0f64;
    let mut sum_sq = (0.0, 0usize);
    for side in [
        Side::FrontReflection,
        Side::BackReflection,
        Side::FrontTransmission,
        Side::BackTransmission,
    ] {
        let kind = if side.is_transmission() {
            Scattering::Transmission
        } else {
            Scattering::Reflection
        };
        for p in 0..basis.len() {
            let v = side.incident_in_basis_frame(basis.direction_in_patch(p, [0.5, 0.5]));
            let diff = mine.hemispherical(v, kind) - theirs.hemispherical(v, kind);
            worst = worst.max(diff.abs());
            sum_sq = (sum_sq.0 + diff * diff, sum_sq.1 + 1);
        }
    }
    Ok((worst, (sum_sq.0 / sum_sq.1 as f64).sqrt()))
}
