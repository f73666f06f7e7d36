//! `skylux genbsdf`: a Klems BSDF (WINDOW / LBNL XML that RADIANCE reads) from a detailed
//! RADIANCE model of a fenestration device, sampled by our own engine as genBSDF samples it
//! with rfluxmtx (`engine::genbsdf`; docs/bsdf.md "BSDFs from geometry").

use anyhow::Context;
use clap::{Args, ValueEnum};
use glam::DVec3;
use skylux_hps::bsdf::{bsdf_xml, AngleBasis, BsdfDocument, DocumentPart, Side};
use skylux_hps::engine::genbsdf::{
    generate_klems, generate_tensor_tree, Asymmetry, GenBsdfSettings, GeneratedBsdf, GeneratedPart,
    GeneratedTree, SamplingBox, TreeKind,
};
use skylux_hps::engine::World;
use skylux_hps::scene;
use std::path::PathBuf;

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Basis {
    /// LBNL/Klems Full, 145 patches.
    Kf,
    /// LBNL/Klems Half, 77 patches.
    Kh,
    /// LBNL/Klems Quarter, 41 patches.
    Kq,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Tree {
    /// TensorTree3: isotropic (the azimuthal average), res/2 incident cells.
    T3,
    /// TensorTree4: anisotropic, res² incident cells.
    T4,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum From {
    /// Light from both sides: all four parts.
    Both,
    /// Light from the room (+z) only: room-side reflection, transmission out.
    Room,
    /// Light from outside (−z) only: outside reflection, transmission in.
    Outside,
}

#[derive(Args)]
pub struct GenBsdfArgs {
    /// The device (RADIANCE scene files): behind the z = 0 plane, the room on +z, its up
    /// direction +y (genBSDF's convention).
    #[arg(required = true)]
    pub device: Vec<PathBuf>,
    /// The XML file to write.
    #[arg(long, short)]
    pub out: PathBuf,
    /// Rays per incident patch and side (genBSDF's -c).
    #[arg(long, default_value_t = 2000)]
    pub samples: u32,
    /// Most diffuse bounces in the device (genBSDF runs rfluxmtx -ab 5).
    #[arg(long, default_value_t = 5)]
    pub ab: u32,
    #[arg(long, value_enum, default_value_t = Basis::Kf)]
    pub basis: Basis,
    /// A tensor tree instead of Klems matrices (genBSDF's -t3 / -t4); --samples rays per
    /// incident cell.
    #[arg(long, value_enum)]
    pub tree: Option<Tree>,
    /// The tree's resolution: 2^N cells per dimension (genBSDF's -t4 N ... default 4).
    #[arg(long, default_value_t = 4)]
    pub tree_log2: u32,
    /// Which sides light comes from.
    #[arg(long, value_enum, default_value_t = From::Both)]
    pub from: From,
    /// The sampling box XMIN XMAX YMIN YMAX ZMIN ZMAX in the geometry's units (genBSDF's
    /// -dim); the device's bounding box by default.
    #[arg(long, num_args = 6, allow_negative_numbers = true)]
    pub dim: Option<Vec<f64>>,
    /// The geometry's unit, as the XML names it (genBSDF's -geom): meter, millimeter, foot...
    #[arg(long, default_value = "meter")]
    pub geom: String,
    /// The standard error of each element, written as a second XML of the same layout.
    #[arg(long)]
    pub errors: Option<PathBuf>,
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Run inline commands Skylux does not implement through /bin/sh, as oconv would (a
    /// scene file can then run any program with your rights).
    #[arg(long)]
    pub allow_commands: bool,
}

pub fn run(args: &GenBsdfArgs) -> anyhow::Result<()> {
    let scene = scene::load_files_with(
        &args.device,
        &scene::LoadOptions {
            allow_commands: args.allow_commands,
            ..Default::default()
        },
    )?;
    let world = World::new(&scene)?;
    anyhow::ensure!(
        world.distant_sources().is_empty() && !world.has_escape_radiance(),
        "the device files hold a sky or a sun: genbsdf needs the device alone"
    );
    let sampling = sampling_box(args, &world)?;
    sampling
        .check()
        .map_err(|e| anyhow::anyhow!("--dim: {e}"))?;
    for w in sampling.warnings() {
        eprintln!("warning: {w}");
    }
    let basis_name = match args.basis {
        Basis::Kf => "LBNL/Klems Full",
        Basis::Kh => "LBNL/Klems Half",
        Basis::Kq => "LBNL/Klems Quarter",
    };
    let basis = AngleBasis::builtin(basis_name).context("built-in basis")?;
    let settings = GenBsdfSettings {
        samples_per_patch: args.samples,
        ambient_bounces: args.ab,
        seed: args.seed,
        from_room: matches!(args.from, From::Both | From::Room),
        from_outside: matches!(args.from, From::Both | From::Outside),
    };
    let created_by = command_line();
    let name = args
        .device
        .first()
        .and_then(|p| p.file_stem())
        .map_or("device".into(), |s| s.to_string_lossy().into_owned());
    let bar = indicatif::ProgressBar::new(1);
    let progress = |d, n| {
        bar.set_length(n);
        bar.set_position(d);
    };
    if let Some(tree) = args.tree {
        let g = generate_tensor_tree(
            &world,
            &sampling,
            tree_kind(tree),
            args.tree_log2,
            &settings,
            &progress,
        )?;
        bar.finish_and_clear();
        return write_tree(args, &g, &sampling, &name, &created_by);
    }
    let generated = generate_klems(&world, &sampling, &basis, &settings, &progress)?;
    bar.finish_and_clear();
    let doc = generated.document(&name, &created_by, &args.geom, &sampling);
    let layout = |p: &GeneratedPart| p.standard_error.clone();
    write_documents(args, &doc, &generated.parts, &created_by, &layout)?;
    report(&generated, &doc, &sampling, args);
    Ok(())
}

fn tree_kind(tree: Tree) -> TreeKind {
    match tree {
        Tree::T3 => TreeKind::Isotropic,
        Tree::T4 => TreeKind::Anisotropic,
    }
}

/// Writes a sampled tree (and its errors) and prints its summary.
fn write_tree(
    args: &GenBsdfArgs,
    g: &GeneratedTree,
    sampling: &SamplingBox,
    name: &str,
    created_by: &str,
) -> anyhow::Result<()> {
    let grids = g.grids();
    let doc = g.document(&grids, name, created_by, &args.geom, sampling);
    // A tree's grid is incident-major: the errors are laid out as its values are.
    let layout = |p: &GeneratedPart| g.grid_of(p, &p.standard_error);
    write_documents(args, &doc, &g.parts, created_by, &layout)?;
    println!(
        "{}: TensorTree{} of {} cells per dimension ({}), {} rays per incident cell",
        args.out.display(),
        g.kind.dims(),
        1usize << g.log2_res,
        describe_box(sampling, &args.geom),
        g.samples_per_cell
    );
    let n_in = g.parts[0].n_incident;
    summary(&g.parts, &doc, n_in, |side, i| g.hemispherical(side, i));
    Ok(())
}

/// The BSDF and, with --errors, its standard errors in the same layout (`layout` turns a
/// part's standard errors into what the file holds for it).
fn write_documents(
    args: &GenBsdfArgs,
    doc: &BsdfDocument,
    parts: &[GeneratedPart],
    created_by: &str,
    layout: &dyn Fn(&GeneratedPart) -> Vec<f64>,
) -> anyhow::Result<()> {
    anyhow::ensure!(
        !doc.parts.is_empty(),
        "no ray left the device: the sampled BSDF is zero everywhere (is the box around it?)"
    );
    let text = bsdf_xml(doc).map_err(anyhow::Error::msg)?;
    std::fs::write(&args.out, text).with_context(|| format!("writing {}", args.out.display()))?;
    if let Some(path) = &args.errors {
        write_errors(path, parts, doc, created_by, layout)?;
    }
    Ok(())
}

fn sampling_box(args: &GenBsdfArgs, world: &World) -> anyhow::Result<SamplingBox> {
    match &args.dim {
        Some(d) => Ok(SamplingBox {
            min: DVec3::new(d[0], d[2], d[4]),
            max: DVec3::new(d[1], d[3], d[5]),
        }),
        None => SamplingBox::of_world(world).context("the device files hold no surface"),
    }
}

/// The standard errors in the layout of the BSDF itself, the same parts.
fn write_errors(
    path: &std::path::Path,
    parts: &[GeneratedPart],
    doc: &BsdfDocument,
    created_by: &str,
    layout: &dyn Fn(&GeneratedPart) -> Vec<f64>,
) -> anyhow::Result<()> {
    let name = format!("standard errors of {}", doc.name);
    let grids: Vec<(Side, Vec<f64>)> = doc
        .parts
        .iter()
        .filter_map(|d| parts.iter().find(|p| p.side == d.side))
        .map(|p| (p.side, layout(p)))
        .collect();
    let errors = BsdfDocument {
        name: &name,
        created_by,
        parts: grids
            .iter()
            .map(|(side, values)| DocumentPart {
                side: *side,
                values,
            })
            .collect(),
        ..*doc
    };
    let text = bsdf_xml(&errors).map_err(anyhow::Error::msg)?;
    std::fs::write(path, text).with_context(|| format!("writing {}", path.display()))
}

fn report(
    generated: &GeneratedBsdf,
    doc: &BsdfDocument,
    sampling: &SamplingBox,
    args: &GenBsdfArgs,
) {
    let n = generated.basis.len();
    println!(
        "{}: {} x {} {} ({}), {} rays per patch",
        args.out.display(),
        n,
        n,
        generated.basis.name,
        describe_box(sampling, &args.geom),
        generated.samples_per_patch
    );
    summary(&generated.parts, doc, n, |side, i| {
        Some((
            generated.hemispherical(side, i)?,
            generated.hemispherical_standard_error(side, i)?,
        ))
    });
    let r = generated.reciprocity();
    let show = |label: &str, a: Option<Asymmetry>| {
        if let Some(a) = a {
            println!(
                "reciprocity, {label}: {:.2} % apart, {:.2} standard errors RMS (1 for a reciprocal device)",
                100.0 * a.relative,
                a.rms_standard_errors
            );
        }
    };
    show("transmission", r.transmission);
    show("room-side reflection", r.room_reflection);
    show("outside reflection", r.outside_reflection);
}

/// Per part: R or T of the first incident cell (the normal for Klems and t3), the mean over
/// incident cells, and the largest standard error of one of them.
fn summary(
    parts: &[GeneratedPart],
    doc: &BsdfDocument,
    n_incident: usize,
    hemispherical: impl Fn(Side, usize) -> Option<(f64, f64)>,
) {
    println!("part                 first cell   mean over cells   largest standard error");
    for part in parts {
        let side = part.side;
        let hemi: Vec<(f64, f64)> = (0..n_incident)
            .filter_map(|i| hemispherical(side, i))
            .collect();
        let se = hemi.iter().map(|h| h.1).fold(0.0, f64::max);
        let written = doc.parts.iter().any(|p| p.side == side);
        println!(
            "{:20} {:10.4}   {:15.4}   {:22.4}{}",
            side.window_label(),
            hemi[0].0,
            hemi.iter().map(|h| h.0).sum::<f64>() / n_incident as f64,
            se,
            if written { "" } else { "   (zero: left out)" }
        );
    }
}

/// "box x A..B y C..D z E..F unit", to six decimals.
fn describe_box(b: &SamplingBox, unit: &str) -> String {
    let f = |v: f64| {
        let t = format!("{v:.6}");
        let t = t.trim_end_matches('0').trim_end_matches('.').to_string();
        if t == "-0" {
            "0".to_string()
        } else {
            t
        }
    };
    format!(
        "box x {}..{} y {}..{} z {}..{} {unit}",
        f(b.min.x),
        f(b.max.x),
        f(b.min.y),
        f(b.max.y),
        f(b.min.z),
        f(b.max.z)
    )
}

fn command_line() -> String {
    std::iter::once("skylux".to_string())
        .chain(std::env::args().skip(1))
        .collect::<Vec<_>>()
        .join(" ")
}
