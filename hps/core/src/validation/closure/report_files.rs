//! The closure's report files: `report.json`, `report.md` and the PNG figures.

use super::model::ClosureModel;
use super::pyranometer_effects::Variable;
use super::{ClosureError, ClosureResult, LeaveOneOut};
use crate::output::plot::{self, BarGroup, Frame, Series};
use crate::output::write_atomic;
use crate::validation::report::Report;
use crate::validation::split::Score;
use chrono::{DateTime, Utc};
use std::fmt::Write as _;
use std::path::Path;

/// A figure written beside the report, and its caption in `report.md`.
struct FigureFile {
    name: String,
    caption: String,
}

impl FigureFile {
    fn new(name: impl Into<String>, caption: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            caption: caption.into(),
        }
    }
}

/// Writes `report.json`, `report.md` and the PNG plots into `dir` (created if missing);
/// returns the report as written.
pub fn write_outputs(result: &ClosureResult, dir: &Path) -> Result<Report, ClosureError> {
    std::fs::create_dir_all(dir).map_err(|source| ClosureError::Io {
        path: dir.into(),
        source,
    })?;
    let mut report = result.report.clone();
    let mut figures: Vec<FigureFile> = Vec::new();
    let (base, last) = (&result.base, &result.last);
    let n_after = last.model.effects.len();
    let after_label = format!(
        "after ({n_after} effect{})",
        if n_after == 1 { "" } else { "s" }
    );
    figures.extend(residual_vs_time(result, dir, &after_label)?);
    // The residual against the variable that revealed each effect, before and after it.
    for LeaveOneOut { effect, without } in &result.leave_one_out {
        let residual = ResidualScatter {
            variable: effect.revealing_variable(),
            before: &without.model,
            after: &last.model,
            what: effect.name(),
            before_label: &format!("without {}", effect.name()),
            after_label: &after_label,
        };
        let name = residual.write(result, dir)?;
        figures.push(FigureFile::new(
            name,
            format!("the residual that reveals {}", effect.name()),
        ));
    }
    let residual = ResidualScatter {
        variable: Variable::ZenithDeg,
        before: &base.model,
        after: &last.model,
        what: "all",
        before_label: "before",
        after_label: &after_label,
    };
    let name = residual.write(result, dir)?;
    figures.push(FigureFile::new(
        name,
        "the residual against zenith, before and after",
    ));
    figures.push(holdout_errors(result, dir, &after_label)?);

    report.figures = figures.iter().map(|f| f.name.clone()).collect();
    report.write_json(&dir.join("report.json"))?;
    write_atomic(
        &dir.join("report.md"),
        markdown(&report, result, &figures).as_bytes(),
    )?;
    Ok(report)
}

/// Residual against time of day, fit set, with a break at every gap; none without samples.
fn residual_vs_time(
    result: &ClosureResult,
    dir: &Path,
    after_label: &str,
) -> Result<Option<FigureFile>, ClosureError> {
    let day0 = result
        .fit_day
        .first()
        .and_then(|s| s.time_utc.date_naive().and_hms_opt(0, 0, 0))
        .map(|d| d.and_utc());
    let Some(day0) = day0 else {
        return Ok(None);
    };
    let gap = result.interval * 3 / 2;
    let series = |model: &ClosureModel, label: &str| {
        let mut points = Vec::new();
        let mut prev: Option<DateTime<Utc>> = None;
        for s in &result.fit_day {
            if prev.is_some_and(|p| s.time_utc - p > gap) {
                points.push((f64::NAN, f64::NAN));
            }
            prev = Some(s.time_utc);
            let h = (s.time_utc - day0).num_milliseconds() as f64 / 3.6e6;
            points.push((h, model.corrected_wm2(s)));
        }
        Series {
            label: label.into(),
            points,
        }
    };
    let name = "residual_vs_time.png";
    plot::lines_png(
        &dir.join(name),
        &Frame::new(
            "Closure residual GHI − (DNI cos Z + DHI), fit set",
            "hours UTC",
            "residual (W/m²)",
        ),
        &[
            series(&result.base.model, "before"),
            series(&result.last.model, after_label),
        ],
    )?;
    Ok(Some(FigureFile::new(
        name,
        "the residual against time, fit set",
    )))
}

/// The fit-set residual against one variable under two models.
struct ResidualScatter<'a> {
    variable: Variable,
    before: &'a ClosureModel,
    after: &'a ClosureModel,
    /// The file name's last part.
    what: &'a str,
    before_label: &'a str,
    after_label: &'a str,
}

impl ResidualScatter<'_> {
    /// Writes the plot into `dir`; returns its file name.
    fn write(&self, result: &ClosureResult, dir: &Path) -> Result<String, ClosureError> {
        let v = self.variable;
        let pts = |m: &ClosureModel| {
            result
                .fit_day
                .iter()
                .map(|s| (v.value(s), m.corrected_wm2(s)))
                .collect()
        };
        let name = format!("residual_vs_{}_{}.png", v.stem(), self.what);
        let frame = Frame::new(
            &format!(
                "Closure residual against {}, fit set",
                v.stem().replace('_', " ")
            ),
            v.label(),
            "residual (W/m²)",
        );
        plot::scatter_png(
            &dir.join(&name),
            &frame,
            &[
                Series {
                    label: self.before_label.into(),
                    points: pts(self.before),
                },
                Series {
                    label: self.after_label.into(),
                    points: pts(self.after),
                },
            ],
        )?;
        Ok(name)
    }
}

/// Hold-out figures before and after, as bars.
fn holdout_errors(
    result: &ClosureResult,
    dir: &Path,
    after_label: &str,
) -> Result<FigureFile, ClosureError> {
    let name = "holdout_errors.png";
    let group = |label: &str, f: fn(&Score) -> f64| BarGroup {
        label: label.into(),
        values: vec![Some(f(&result.base.holdout)), Some(f(&result.last.holdout))],
    };
    plot::grouped_bars_png(
        &dir.join(name),
        &Frame::new("Hold-out closure error", "", "W/m²"),
        &["before".to_string(), after_label.to_string()],
        &[
            group("mean |r|", |s| s.mean_abs),
            group("RMSE", |s| s.rmse),
            group("max |r|", |s| s.max_abs),
        ],
    )?;
    Ok(FigureFile::new(name, "hold-out errors before and after"))
}

fn markdown(report: &Report, result: &ClosureResult, figures: &[FigureFile]) -> String {
    let (b, a) = (&result.base.holdout, &result.last.holdout);
    let mut md = String::new();
    let _ = writeln!(md, "# Pyranometer closure\n");
    let _ = writeln!(
        md,
        "The error is the closure residual r = GHI − (DNI cos Z + DHI) in W/m², on daytime \
         hold-out samples only ({} samples). Effects are fitted on the fit set only.\n",
        b.n
    );
    let _ = writeln!(
        md,
        "| hold-out | mean \\|r\\| | RMSE | max \\|r\\| | bias |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|");
    for (label, s) in [("before", b), ("after", a)] {
        let _ = writeln!(
            md,
            "| {label} | {:.3} | {:.3} | {:.3} | {:+.3} |",
            s.mean_abs, s.rmse, s.max_abs, s.mean
        );
    }
    let _ = writeln!(md, "\n## Effects added\n");
    if report.effects.is_empty() {
        let _ = writeln!(md, "None.");
    }
    for e in &report.effects {
        let params: Vec<String> = e
            .parameters
            .iter()
            .map(|(k, v)| format!("`{k}` = {v:.5}"))
            .collect();
        let _ = writeln!(
            md,
            "- **{}** ({}); hold-out gain {:.3} W/m². {}",
            e.name,
            params.join(", "),
            e.gain,
            e.evidence
        );
    }
    if !report.rejected.is_empty() {
        let _ = writeln!(md, "\n## Not added\n");
        for r in &report.rejected {
            let _ = writeln!(md, "- {r}");
        }
    }
    let _ = writeln!(md, "\n## Notes\n");
    for n in &report.notes {
        let _ = writeln!(md, "- {n}");
    }
    let _ = writeln!(md, "\n## Plots\n");
    for f in figures {
        let _ = writeln!(md, "![{}]({})\n", f.caption, f.name);
    }
    md
}
