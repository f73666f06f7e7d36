//! Compiling a function modifier: its `.cal` file found through RAYPATH and read once per
//! file however many modifiers name it, RADIANCE's `rayinit.cal` before it when RAYPATH (or
//! the scene file's folder) has one (as `func.c` `initfunc` loads it first; RADIANCE's own
//! default RAYPATH holds its library), and the modifier's expressions compiled into
//! the program, so nothing is parsed per ray.

use super::data::DataArray;
use super::font::Font;
use super::text::{text_file_lines, TextLayout};
use crate::cal::{CalContext, CalError, CalProgram, Evaluator};
use crate::engine::error::EngineError;
use crate::scene::{FunctionArgs, Modifier, SourceLocation, TextArgs, TextSource};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// RADIANCE's initial definitions, read from RAYPATH before every function file.
const RAYINIT: &str = "rayinit.cal";
/// Where RADIANCE looks when RAYPATH is not set (rtmain's default is `.` and its library).
const DEFAULT_RAYPATH: &str = ".";
/// Prefix of the variables that hold a modifier's own expressions (dotted, as no RADIANCE
/// library name is).
const EXPRESSION_PREFIX: &str = "skylux.expression.";

/// Reads and caches function files for one scene.
#[derive(Default)]
pub struct FunctionLoader {
    /// Compiled `rayinit.cal` + file, by the file's resolved path (None: no file).
    programs: HashMap<Option<PathBuf>, Arc<CalProgram>>,
    /// Data files read, by resolved path.
    data: HashMap<PathBuf, Arc<DataArray>>,
    /// Pictures read as three arrays (red, green, blue), by resolved path.
    pictures: HashMap<PathBuf, [Arc<DataArray>; 3]>,
    /// Fonts read, by resolved path.
    fonts: HashMap<PathBuf, Arc<Font>>,
}

/// Most bytes of a font or text file read: a bound on memory for outside data (RADIANCE's
/// own font, helvet.fnt, is 60 KB).
pub const MAX_TEXT_FILE_BYTES: u64 = 16 << 20;

/// A modifier's expressions, compiled with its function file.
#[derive(Debug)]
pub struct CompiledFunction {
    program: CalProgram,
    /// The name of the variable holding each expression.
    expressions: Vec<String>,
    pub args: FunctionArgs,
    /// Where the modifier is defined, for messages.
    pub origin: SourceLocation,
    warnings: AtomicU64,
}

impl FunctionLoader {
    /// Compiles the first `compiled` expressions of `modifier`'s `args`; every other
    /// expression must name a function the file or the library defines (BRTDfunc's
    /// directional functions), or be `0`.
    pub fn compile(
        &mut self,
        modifier: &Modifier,
        args: &FunctionArgs,
        compiled: usize,
    ) -> Result<Arc<CompiledFunction>, EngineError> {
        let fail = |what: String| EngineError::Unsupported {
            at: modifier.origin.clone(),
            what: format!("{} `{}`: {what}", modifier.kind.type_name(), modifier.name),
        };
        let base = self.program_for(args).map_err(|e| fail(e.to_string()))?;
        let mut program = (*base).clone();
        let mut expressions = Vec::new();
        for (i, text) in args.expressions.iter().take(compiled).enumerate() {
            let name = format!("{EXPRESSION_PREFIX}{i}");
            program
                .load_str(
                    &format!("string argument {}", i + 1),
                    &format!("{name} = {text};"),
                )
                .map_err(|e| fail(e.to_string()))?;
            expressions.push(name);
        }
        for name in &args.expressions[compiled.min(args.expressions.len())..] {
            if name != "0" && !program.is_defined(name) {
                return Err(fail(format!(
                    "function `{name}` is not defined in {}",
                    args.cal_file
                )));
            }
        }
        let function = CompiledFunction {
            program,
            expressions,
            args: args.clone(),
            origin: modifier.origin.clone(),
            warnings: AtomicU64::new(0),
        };
        function.check_names().map_err(|e| fail(e.to_string()))?;
        Ok(Arc::new(function))
    }

    /// The data file `name` of `modifier`, found as function files are, read once.
    pub fn data(
        &mut self,
        modifier: &Modifier,
        name: &str,
        scene_dir: &Path,
    ) -> Result<Arc<DataArray>, EngineError> {
        let fail = |what: String| EngineError::Unsupported {
            at: modifier.origin.clone(),
            what: format!("{} `{}`: {what}", modifier.kind.type_name(), modifier.name),
        };
        let path = find(name, scene_dir).ok_or_else(|| {
            fail(format!(
                "data file {name} not found on RAYPATH ({}) nor beside the scene file",
                raypath().join(":")
            ))
        })?;
        if let Some(d) = self.data.get(&path) {
            return Ok(d.clone());
        }
        let text = std::fs::read_to_string(&path)
            .map_err(|e| fail(format!("data file {}: {e}", path.display())))?;
        let array = Arc::new(
            DataArray::parse(&path.display().to_string(), &text)
                .map_err(|e| fail(e.to_string()))?,
        );
        self.data.insert(path, array.clone());
        Ok(array)
    }

    /// The picture `name` of a `colorpict` (found as a data file is) as three arrays, read
    /// once per file: its stored values (the header's exposure not removed, as RADIANCE's
    /// getpict reads them). An XYZE picture is refused, as RADIANCE refuses it.
    pub fn picture(
        &mut self,
        modifier: &Modifier,
        name: &str,
        scene_dir: &Path,
    ) -> Result<[Arc<DataArray>; 3], EngineError> {
        let fail = |what: String| EngineError::Unsupported {
            at: modifier.origin.clone(),
            what: format!("{} `{}`: {what}", modifier.kind.type_name(), modifier.name),
        };
        let path = find(name, scene_dir).ok_or_else(|| {
            fail(format!(
                "picture file {name} not found on RAYPATH ({}) nor beside the scene file",
                raypath().join(":")
            ))
        })?;
        if let Some(p) = self.pictures.get(&path) {
            return Ok(p.clone());
        }
        let picture = crate::picture::rgbe::read_hdr(&path).map_err(|e| fail(e.to_string()))?;
        if picture.format != crate::picture::rgbe::PixelFormat::Rgbe {
            return Err(fail(format!(
                "picture file {}: XYZE pixels; RADIANCE reads only RGBE pictures here",
                path.display()
            )));
        }
        let exposure = picture.exposure as f32;
        let stored: Vec<[f32; 3]> = picture
            .pixels
            .iter()
            .map(|p| [p[0] * exposure, p[1] * exposure, p[2] * exposure])
            .collect();
        let arrays = DataArray::from_picture(
            &stored,
            picture.width_px as usize,
            picture.height_px as usize,
            picture.pixel_aspect,
        )
        .ok_or_else(|| {
            fail(format!(
                "picture file {}: {} x {} pixels; at least 2 x 2 needed",
                path.display(),
                picture.width_px,
                picture.height_px
            ))
        })?
        .map(Arc::new);
        self.pictures.insert(path, arrays.clone());
        Ok(arrays)
    }

    /// The text of a `brighttext`, `colortext` or `mixtext` laid out in its font: the font
    /// and the text file found as data files are (text.c and font.c look both up on
    /// RAYPATH), the font read once per file.
    pub fn text(
        &mut self,
        modifier: &Modifier,
        args: &TextArgs,
    ) -> Result<Arc<TextLayout>, EngineError> {
        let fail = |what: String| EngineError::Unsupported {
            at: modifier.origin.clone(),
            what: format!("{} `{}`: {what}", modifier.kind.type_name(), modifier.name),
        };
        let read = |what: &str, name: &str| -> Result<(PathBuf, Vec<u8>), EngineError> {
            let path = find(name, &args.scene_dir).ok_or_else(|| {
                fail(format!(
                    "{what} file {name} not found on RAYPATH ({}) nor beside the scene file",
                    raypath().join(":")
                ))
            })?;
            let size = std::fs::metadata(&path)
                .map_err(|e| fail(format!("{what} file {}: {e}", path.display())))?
                .len();
            if size > MAX_TEXT_FILE_BYTES {
                return Err(fail(format!(
                    "{what} file {}: {size} bytes, more than the {MAX_TEXT_FILE_BYTES} read",
                    path.display()
                )));
            }
            let bytes = std::fs::read(&path)
                .map_err(|e| fail(format!("{what} file {}: {e}", path.display())))?;
            Ok((path, bytes))
        };
        let font = match find(&args.font_file, &args.scene_dir).and_then(|p| self.fonts.get(&p)) {
            Some(font) => font.clone(),
            None => {
                let (path, bytes) = read("font", &args.font_file)?;
                let font = Arc::new(
                    Font::parse(&path.display().to_string(), &bytes)
                        .map_err(|e| fail(e.to_string()))?,
                );
                self.fonts.insert(path, font.clone());
                font
            }
        };
        let lines = match &args.text {
            TextSource::Inline(words) => vec![words.as_bytes().to_vec()],
            TextSource::File(name) => text_file_lines(&read("text", name)?.1),
        };
        TextLayout::new(
            font,
            lines,
            args.anchor_m,
            args.right_m,
            args.down_m,
            args.spacing,
        )
        .map(Arc::new)
        .map_err(fail)
    }

    /// `rayinit.cal` (if RAYPATH has it) and the modifier's file, compiled once per file.
    fn program_for(&mut self, args: &FunctionArgs) -> Result<Arc<CalProgram>, CalError> {
        let file = if args.cal_file == "." {
            None
        } else {
            Some(
                find(&args.cal_file, &args.scene_dir).ok_or_else(|| CalError::Io {
                    file: args.cal_file.clone(),
                    message: format!(
                        "function file not found on RAYPATH ({}) nor beside the scene file",
                        raypath().join(":")
                    ),
                })?,
            )
        };
        if let Some(p) = self.programs.get(&file) {
            return Ok(p.clone());
        }
        let mut program = CalProgram::new();
        // On RAYPATH, else beside the scene file as its function files are.
        if let Some(rayinit) = find(RAYINIT, &args.scene_dir) {
            program.load_file(&rayinit)?;
        }
        if let Some(f) = &file {
            program.load_file(f)?;
        }
        let program = Arc::new(program);
        self.programs.insert(file, program.clone());
        Ok(program)
    }
}

/// RAYPATH's folders (`RAYPATH` or `.`).
fn raypath() -> Vec<String> {
    std::env::var("RAYPATH")
        .unwrap_or_else(|_| DEFAULT_RAYPATH.to_string())
        .split(':')
        .filter(|s| !s.is_empty())
        .map(str::to_string)
        .collect()
}

/// `name` as RADIANCE's `getpath` finds it: as given if absolute, else in each RAYPATH
/// folder in turn; then, beyond RADIANCE, beside the scene file (`scene_dir`), so a scene
/// and its `.cal` files can be loaded from any working directory.
fn find(name: &str, scene_dir: &Path) -> Option<PathBuf> {
    let path = Path::new(name);
    if path.is_absolute() {
        return path.is_file().then(|| path.to_path_buf());
    }
    raypath()
        .iter()
        .map(|dir| Path::new(dir).join(path))
        .chain((!scene_dir.as_os_str().is_empty()).then(|| scene_dir.join(path)))
        .find(|p| p.is_file())
}

impl CompiledFunction {
    /// Evaluates expression `i` (0 on an evaluation error, counted as a warning).
    pub fn value(&self, i: usize, ray: &dyn CalContext) -> f64 {
        let mut evaluator = Evaluator::new(&self.program);
        self.checked(evaluator.variable(&self.expressions[i], ray), &evaluator)
    }

    /// Evaluates expressions `first..first + N` with one evaluator (shared variables are
    /// computed once).
    pub fn values<const N: usize>(&self, first: usize, ray: &dyn CalContext) -> [f64; N] {
        let mut evaluator = Evaluator::new(&self.program);
        std::array::from_fn(|k| {
            let v = evaluator.variable(&self.expressions[first + k], ray);
            self.checked(v, &evaluator)
        })
    }

    /// Every expression's value, in order, with one evaluator.
    pub fn all_values(&self, ray: &dyn CalContext) -> Vec<f64> {
        let mut evaluator = Evaluator::new(&self.program);
        (0..self.expressions.len())
            .map(|i| {
                let v = evaluator.variable(&self.expressions[i], ray);
                self.checked(v, &evaluator)
            })
            .collect()
    }

    /// How many arguments the function `name` takes (None: no such function).
    pub fn parameter_count(&self, name: &str) -> Option<usize> {
        self.program.parameter_count(name)
    }

    /// Calls the function `name` of the file at `arguments`; `0` is the constant 0.
    pub fn call(&self, name: &str, arguments: &[f64], ray: &dyn CalContext) -> f64 {
        if name == "0" {
            return 0.0;
        }
        let mut evaluator = Evaluator::new(&self.program);
        self.checked(evaluator.call(name, arguments, ray), &evaluator)
    }

    /// How many evaluations gave a warning or an error (their value taken as 0).
    pub fn warnings(&self) -> u64 {
        self.warnings.load(Ordering::Relaxed)
    }

    fn checked(&self, value: Result<f64, CalError>, evaluator: &Evaluator<'_>) -> f64 {
        let warned = evaluator.warnings().1 > 0;
        match value {
            Ok(v) if v.is_finite() && !warned => v,
            Ok(v) if v.is_finite() => {
                self.warnings.fetch_add(1, Ordering::Relaxed);
                v
            }
            _ => {
                self.warnings.fetch_add(1, Ordering::Relaxed);
                0.0
            }
        }
    }

    /// Evaluates every expression once on a ray at the origin, so an undefined name or a
    /// missing argument is an error at load time, not a silent 0 at every hit.
    fn check_names(&self) -> Result<(), CalError> {
        let probe = crate::cal::RayValues {
            real_arguments: self.args.real_args.clone(),
            ..Default::default()
        };
        for name in &self.expressions {
            let mut evaluator = Evaluator::new(&self.program);
            if let Err(e @ (CalError::Undefined { .. } | CalError::TooFewArguments { .. })) =
                evaluator.variable(name, &probe)
            {
                return Err(e);
            }
        }
        Ok(())
    }
}
