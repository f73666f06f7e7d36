//! `skylux scene check FILE... [--json] [--allow-commands]`: loads scene files as the engine
//! would (inline commands expanded) and reports what they hold: primitives and modifiers per
//! type, bounds, a units hint, referenced files that are missing, modifiers never used, and
//! whether the engine's subset can load them (or the error that stops it).

use serde_json::json;
use skylux_hps::engine::World;
use skylux_hps::scene::{self, LoadOptions, Primitive};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct SceneArgs {
    #[command(subcommand)]
    command: SceneCommand,
}

#[derive(clap::Subcommand)]
enum SceneCommand {
    /// Loads scene files in order (as oconv would) and reports counts, bounds, a units hint,
    /// missing files, unused modifiers and whether Skylux's engine can load them.
    Check(CheckArgs),
}

#[derive(clap::Args)]
struct CheckArgs {
    /// RADIANCE scene files, read in order into one scene.
    #[arg(required = true)]
    files: Vec<PathBuf>,
    /// Print the report as JSON.
    #[arg(long)]
    json: bool,
    /// Run inline commands Skylux does not implement through /bin/sh (trusted files only).
    #[arg(long)]
    allow_commands: bool,
}

pub fn run(args: &SceneArgs) -> anyhow::Result<()> {
    match &args.command {
        SceneCommand::Check(check) => run_check(check),
    }
}

/// Extensions of files a primitive's string arguments may name.
const FILE_EXTENSIONS: &[&str] = &[
    "cal", "dat", "xml", "hdr", "pic", "oct", "rtm", "tif", "tiff", "fnt", "ies",
];

/// What `scene check` finds.
struct Report {
    surfaces: BTreeMap<String, usize>,
    modifiers: BTreeMap<String, usize>,
    bounds: Option<([f64; 3], [f64; 3])>,
    missing_files: Vec<String>,
    unused_modifiers: Vec<String>,
    engine: Result<(), String>,
}

fn run_check(args: &CheckArgs) -> anyhow::Result<()> {
    let options = LoadOptions {
        allow_commands: args.allow_commands,
        ..Default::default()
    };
    let primitives = scene::expand_files(&args.files, &options)?;
    let report = Report {
        surfaces: count_types(&primitives, true),
        modifiers: count_types(&primitives, false),
        bounds: bounds(&primitives),
        missing_files: missing_files(&primitives),
        unused_modifiers: unused_modifiers(&primitives),
        engine: engine_loads(&args.files, &options),
    };
    if args.json {
        println!("{}", serde_json::to_string_pretty(&to_json(&report))?);
    } else {
        print_text(&report);
    }
    Ok(())
}

/// Whether the scene loads into the engine: the subset's reader, then the engine's world.
fn engine_loads(files: &[PathBuf], options: &LoadOptions) -> Result<(), String> {
    let scene = scene::load_files_with(files, options).map_err(|e| e.to_string())?;
    World::new(&scene).map_err(|e| e.to_string())?;
    Ok(())
}

fn count_types(primitives: &[Primitive], surfaces: bool) -> BTreeMap<String, usize> {
    let mut counts = BTreeMap::new();
    for p in primitives.iter().filter(|p| p.is_surface() == surfaces) {
        *counts.entry(p.type_name.clone()).or_insert(0) += 1;
    }
    counts
}

/// Points that bound a surface (centres pushed out by radii), distant sources excluded.
fn extent_points(p: &Primitive) -> Vec<[f64; 3]> {
    let r = &p.reals;
    let at = |i: usize| [r[i], r[i + 1], r[i + 2]];
    let ball = |c: [f64; 3], radius: f64| {
        let a = radius.abs();
        vec![c.map(|v| v - a), c.map(|v| v + a)]
    };
    match (p.type_name.as_str(), r.len()) {
        ("polygon", n) if n % 3 == 0 => r.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect(),
        ("sphere" | "bubble", 4) => ball(at(0), r[3]),
        ("cylinder" | "tube", 7) => [ball(at(0), r[6]), ball(at(3), r[6])].concat(),
        ("cone" | "cup", 8) => [ball(at(0), r[6]), ball(at(3), r[7])].concat(),
        ("ring", 8) => ball(at(0), r[7]),
        _ => Vec::new(),
    }
}

fn bounds(primitives: &[Primitive]) -> Option<([f64; 3], [f64; 3])> {
    primitives
        .iter()
        .flat_map(extent_points)
        .fold(None, |acc: Option<([f64; 3], [f64; 3])>, p| {
            Some(match acc {
                None => (p, p),
                Some((lo, hi)) => (
                    std::array::from_fn(|k| lo[k].min(p[k])),
                    std::array::from_fn(|k| hi[k].max(p[k])),
                ),
            })
        })
}

/// Feet or metres, from the height the geometry spans (a storey is 2.4-4 m, 8-13 ft).
fn units_hint(bounds: Option<([f64; 3], [f64; 3])>) -> &'static str {
    let Some((lo, hi)) = bounds else {
        return "no geometry";
    };
    let height = hi[2] - lo[2];
    match height {
        h if (2.0..=6.0).contains(&h) => "metres (a storey-high scene)",
        h if (6.5..=20.0).contains(&h) => {
            "feet likely (about one storey if in feet); Skylux works in metres"
        }
        h if h > 500.0 => "millimetres or inches likely; Skylux works in metres",
        _ => "unclear from the height; Skylux works in metres",
    }
}

/// Files named in string arguments that exist neither beside the file that names them nor
/// on RAYPATH.
fn missing_files(primitives: &[Primitive]) -> Vec<String> {
    let raypath: Vec<PathBuf> = std::env::var_os("RAYPATH")
        .map(|p| std::env::split_paths(&p).collect())
        .unwrap_or_default();
    let mut missing = BTreeSet::new();
    for p in primitives {
        let dir = p.origin.file.parent().unwrap_or(Path::new("."));
        for s in &p.strings {
            let named = Path::new(s);
            let is_file = named
                .extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| FILE_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()));
            let found = dir.join(named).exists() || raypath.iter().any(|r| r.join(named).exists());
            if is_file && !found {
                missing.insert(format!(
                    "{s} (named by {} `{}` at {})",
                    p.type_name, p.identifier, p.origin
                ));
            }
        }
    }
    missing.into_iter().collect()
}

fn unused_modifiers(primitives: &[Primitive]) -> Vec<String> {
    let used: BTreeSet<&str> = primitives
        .iter()
        .map(|p| p.modifier.as_str())
        .chain(
            primitives
                .iter()
                .flat_map(|p| p.strings.iter().map(String::as_str)),
        )
        .collect();
    primitives
        .iter()
        .filter(|p| !p.is_surface() && !used.contains(p.identifier.as_str()))
        .map(|p| format!("{} `{}` ({})", p.type_name, p.identifier, p.origin))
        .collect()
}

fn to_json(r: &Report) -> serde_json::Value {
    json!({
        "surfaces": r.surfaces,
        "modifiers": r.modifiers,
        "bounds": r.bounds.map(|(lo, hi)| json!({"min": lo, "max": hi})),
        "units_hint": units_hint(r.bounds),
        "missing_files": r.missing_files,
        "unused_modifiers": r.unused_modifiers,
        "engine_loads": r.engine.is_ok(),
        "engine_error": r.engine.as_ref().err(),
    })
}

fn print_text(r: &Report) {
    let list = |counts: &BTreeMap<String, usize>| {
        counts
            .iter()
            .map(|(t, n)| format!("{n} {t}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    println!("surfaces: {}", list(&r.surfaces));
    println!("modifiers: {}", list(&r.modifiers));
    match r.bounds {
        Some((lo, hi)) => println!(
            "bounds: x {:.3} .. {:.3}, y {:.3} .. {:.3}, z {:.3} .. {:.3}",
            lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]
        ),
        None => println!("bounds: no geometry"),
    }
    println!("units: {}", units_hint(r.bounds));
    println!("missing files: {}", r.missing_files.len());
    for m in &r.missing_files {
        println!("  {m}");
    }
    println!(
        "modifiers defined and not used: {}",
        r.unused_modifiers.len()
    );
    for m in &r.unused_modifiers {
        println!("  {m}");
    }
    match &r.engine {
        Ok(()) => println!("engine: loads"),
        Err(e) => println!("engine: does not load: {e}"),
    }
}
