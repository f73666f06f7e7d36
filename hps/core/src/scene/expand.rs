//! Inline commands replaced by the primitives they write, as `oconv` would read them: `xform`
//! natively (nested, arrays, several files), RADIANCE's generators natively, pipes into
//! `xform`, and, only with [`LoadOptions::allow_commands`], anything else through `/bin/sh`.
//!
//! A command runs in the directory of the file that holds it (xform changes into each file's
//! directory before reading it), so relative names are relative to that file. Includes are
//! followed with their chain kept, so a cycle, a chain deeper than [`MAX_INCLUDE_DEPTH`], a
//! missing file or an expansion beyond [`MAX_PRIMITIVES`] is an error naming the command's
//! file and line, never a hang.

use super::command::{program_name, split_pipeline};
use super::error::{utf8, SceneError, SourceLocation};
use super::files::{read_regular_file, resolve};
use super::generators;
use super::lexer::Lexer;
use super::parse::{read_item, Item};
use super::primitive::Primitive;
use super::xform::{parse_xform, Xform};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Deepest chain of files including files that is followed.
pub const MAX_INCLUDE_DEPTH: usize = 32;
/// Most primitives a scene may expand to (a few hundred MB of geometry).
pub const MAX_PRIMITIVES: usize = 2_000_000;

/// How scene files are read.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LoadOptions {
    /// Run inline commands Skylux does not implement through `/bin/sh`, as `oconv` would. A
    /// scene file can then run any program with the user's rights: only for files you trust.
    /// The daemon never sets it.
    pub allow_commands: bool,
    /// Where RADIANCE would run (`oconv`, `rtrace`): the "." its file search starts from
    /// for files a scene names by a path (`BSDF` XML files). None: the process's directory.
    pub working_directory: Option<std::path::PathBuf>,
}

/// Expands scene text into primitives, following commands.
pub(crate) struct Expander<'o> {
    options: &'o LoadOptions,
    /// Files being read, outermost first, each with the command that included it.
    chain: Vec<(PathBuf, Option<SourceLocation>)>,
    /// Primitives produced so far, against [`MAX_PRIMITIVES`].
    produced: usize,
}

/// The directory a file's commands run in.
fn directory_of(file: &Path) -> PathBuf {
    match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// A file's identity for cycle detection: its canonical path when it exists.
fn identity(file: &Path) -> PathBuf {
    std::fs::canonicalize(file).unwrap_or_else(|_| file.to_path_buf())
}

impl<'o> Expander<'o> {
    pub fn new(options: &'o LoadOptions) -> Self {
        Expander {
            options,
            chain: Vec::new(),
            produced: 0,
        }
    }

    /// The primitives of top-level scene text labelled `label` (its file name).
    pub fn top_text(&mut self, label: Arc<Path>, text: &str) -> Result<Vec<Primitive>, SceneError> {
        self.chain.push((identity(&label), None));
        let dir = directory_of(&label);
        let result = self.text(label, text, &dir);
        self.chain.pop();
        result
    }

    /// Scene text: its primitives and what its commands write, in file order.
    fn text(
        &mut self,
        label: Arc<Path>,
        text: &str,
        dir: &Path,
    ) -> Result<Vec<Primitive>, SceneError> {
        let mut lexer = Lexer::new(label, text);
        let mut out = Vec::new();
        while let Some(item) = read_item(&mut lexer)? {
            match item {
                Item::Primitive(p) => {
                    self.count(1, &p.origin, "")?;
                    out.push(p);
                }
                Item::Command { line, text } => {
                    let at = lexer.at(line);
                    out.extend(self.command(&at, &text, dir)?);
                }
            }
        }
        Ok(out)
    }

    fn count(&mut self, n: usize, at: &SourceLocation, command: &str) -> Result<(), SceneError> {
        self.produced = self.produced.saturating_add(n);
        if self.produced > MAX_PRIMITIVES {
            return Err(SceneError::TooManyPrimitives {
                at: at.clone(),
                command: command.to_string(),
                limit: MAX_PRIMITIVES,
            });
        }
        Ok(())
    }

    /// One `!command` (without its `!`) at `at`, run in `dir`.
    fn command(
        &mut self,
        at: &SourceLocation,
        text: &str,
        dir: &Path,
    ) -> Result<Vec<Primitive>, SceneError> {
        let fail = |message: String| SceneError::Command {
            at: at.clone(),
            command: text.trim().to_string(),
            message,
        };
        let pipeline = match split_pipeline(text) {
            Ok(p) => p,
            Err(reason) => return self.through_shell(at, text, dir, &reason),
        };
        let first = &pipeline.stages[0];
        let program = program_name(first);
        let mut primitives = if program == "xform" {
            let runs = parse_xform(&first[1..]).map_err(fail)?;
            if runs[0].files.is_empty() {
                return Err(fail(
                    "xform with no file reads standard input, which a scene file does not have"
                        .into(),
                ));
            }
            let files = self.read_includes(at, text, &runs[0].files, dir)?;
            self.apply_runs(at, text, &runs, &files)?
        } else if let Some(generate) = generators::generator(program) {
            let written =
                generate(&first[1..], dir).map_err(|why| fail(format!("{program}: {why}")))?;
            self.generated(at, text, &written)?
        } else {
            return self.through_shell(
                at,
                text,
                dir,
                &format!("`{program}` is not a command Skylux implements"),
            );
        };
        for stage in &pipeline.stages[1..] {
            let runs = match program_name(stage) {
                "xform" => parse_xform(&stage[1..]).map_err(fail)?,
                other => {
                    let why = format!("`{other}` after a pipe is not a command Skylux implements");
                    return self.through_shell(at, text, dir, &why);
                }
            };
            if !runs[0].files.is_empty() {
                return Err(fail(
                    "an xform after a pipe must read the pipe, not files".into(),
                ));
            }
            primitives = self.apply_runs(at, text, &runs, &primitives)?;
        }
        Ok(primitives)
    }

    /// The expanded primitives of each file an xform names, in order.
    fn read_includes(
        &mut self,
        at: &SourceLocation,
        command: &str,
        files: &[String],
        dir: &Path,
    ) -> Result<Vec<Primitive>, SceneError> {
        let mut out = Vec::new();
        for name in files {
            let path = resolve(dir, name);
            out.extend(self.included_file(at, command, &path)?);
        }
        Ok(out)
    }

    fn included_file(
        &mut self,
        at: &SourceLocation,
        command: &str,
        path: &Path,
    ) -> Result<Vec<Primitive>, SceneError> {
        let id = identity(path);
        let chain = |extra: &Path| {
            let mut links: Vec<String> = self
                .chain
                .iter()
                .skip(1)
                .filter_map(|(_, by)| by.as_ref().map(ToString::to_string))
                .collect();
            links.push(at.to_string());
            format!("{} -> {}", links.join(" -> "), extra.display())
        };
        if self.chain.iter().any(|(f, _)| *f == id) {
            return Err(SceneError::IncludeCycle {
                at: at.clone(),
                command: command.trim().to_string(),
                chain: chain(path),
            });
        }
        if self.chain.len() >= MAX_INCLUDE_DEPTH {
            return Err(SceneError::IncludeDepth {
                at: at.clone(),
                command: command.trim().to_string(),
                limit: MAX_INCLUDE_DEPTH,
                chain: chain(path),
            });
        }
        let bytes = read_regular_file(path).map_err(|source| SceneError::MissingInclude {
            at: at.clone(),
            command: command.trim().to_string(),
            path: path.to_path_buf(),
            source,
        })?;
        let label: Arc<Path> = Arc::from(path);
        let text = utf8(&label, &bytes)?;
        self.chain.push((id, Some(at.clone())));
        let result = self.text(label, text, &directory_of(path));
        self.chain.pop();
        result
    }

    /// Every run of an xform command applied to `input`, runs in order.
    fn apply_runs(
        &mut self,
        at: &SourceLocation,
        command: &str,
        runs: &[Xform],
        input: &[Primitive],
    ) -> Result<Vec<Primitive>, SceneError> {
        self.count(runs.len().saturating_mul(input.len()), at, command)?;
        let mut out = Vec::with_capacity(runs.len() * input.len());
        for run in runs {
            let moved = run.apply(input).map_err(|message| SceneError::Command {
                at: at.clone(),
                command: command.trim().to_string(),
                message,
            })?;
            out.extend(moved);
        }
        Ok(out)
    }

    /// Text a generator wrote, read as a scene; its primitives are placed at the command.
    fn generated(
        &mut self,
        at: &SourceLocation,
        command: &str,
        written: &str,
    ) -> Result<Vec<Primitive>, SceneError> {
        let mut lexer = Lexer::new(at.file.clone(), written);
        let mut out = Vec::new();
        while let Some(item) = read_item(&mut lexer).map_err(|e| SceneError::Command {
            at: at.clone(),
            command: command.trim().to_string(),
            message: format!("its output does not read as a scene: {e}"),
        })? {
            if let Item::Primitive(mut p) = item {
                p.origin = at.clone();
                out.push(p);
            }
        }
        self.count(out.len(), at, command)?;
        Ok(out)
    }

    /// A command Skylux does not implement: an error, or with `allow_commands` its output
    /// through `/bin/sh` in `dir`.
    fn through_shell(
        &mut self,
        at: &SourceLocation,
        text: &str,
        dir: &Path,
        reason: &str,
    ) -> Result<Vec<Primitive>, SceneError> {
        let command = format!("!{}", text.trim());
        if !self.options.allow_commands {
            return Err(SceneError::UnsupportedCommand {
                at: at.clone(),
                command,
                reason: format!(
                    "{reason}; Skylux runs xform, genbox, gensky, gendaylit, genblinds, genprism, \
                     genrev, genworm and gensurf itself, and runs other commands only with \
                     --allow-commands"
                ),
            });
        }
        let output = std::process::Command::new("/bin/sh")
            .arg("-c")
            .arg(text)
            .current_dir(dir)
            .stdin(std::process::Stdio::null())
            .output()
            .map_err(|e| SceneError::Command {
                at: at.clone(),
                command: command.clone(),
                message: format!("cannot run /bin/sh: {e}"),
            })?;
        if !output.status.success() {
            return Err(SceneError::Command {
                at: at.clone(),
                command,
                message: format!(
                    "the shell reports {}: {}",
                    output.status,
                    String::from_utf8_lossy(&output.stderr).trim()
                ),
            });
        }
        let label: Arc<Path> = Arc::from(Path::new(&format!("{at} (output of {command})")));
        let text = utf8(&label, &output.stdout)?.to_string();
        self.text(label, &text, dir)
    }
}
