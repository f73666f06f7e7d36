//! The loop report (`report.json`), as `shared/spec/campaign.md` defines it, plus the
//! fields Skylux adds (the spec allows additions; readers ignore what they do not know).
//!
//! One type serves `skylux loop` (illuminance against lux-meters) and `skylux closure`
//! (the pyranometer closure GHI - (DNI cos Z + DHI)), so every tool reads one schema.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// An error figure over all sensors and per sensor (or per channel, for the closure).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ErrorSummary {
    pub all: f64,
    pub per_sensor: BTreeMap<String, f64>,
}

/// One effect the loop added, with its fitted parameters and the evidence that named it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EffectReport {
    pub name: String,
    pub parameters: BTreeMap<String, f64>,
    /// One sentence: the residual signature that revealed the effect.
    pub evidence: String,
    /// How much the hold-out error fell when the effect was added (in the metric's units).
    pub gain: f64,
    /// Skylux addition: the fit-set error before and after adding the effect.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fit_error_before: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fit_error_after: Option<f64>,
}

/// One row of the residual table: the relative residual (model / measured − 1) against one
/// explanatory variable, over one group of readings, before and after the effects.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ResidualRow {
    pub variable: String,
    /// `all` or a sensor name.
    pub group: String,
    pub n: usize,
    pub before_r: f64,
    /// Least-squares slope of the relative residual per unit of the variable.
    pub before_slope: f64,
    pub after_r: f64,
    pub after_slope: f64,
}

/// `report.json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// What `before`, `after` and the baseline measure, e.g. `mean_abs_rel_error`, or
    /// `rmse_wm2` for the closure.
    pub metric: String,
    pub fit_times: Vec<String>,
    pub holdout_times: Vec<String>,
    /// On the hold-out times only.
    pub before: ErrorSummary,
    /// On the hold-out times only.
    pub after: ErrorSummary,
    /// The Perez sky model from the pyranometer, on the hold-out times (absent for the
    /// closure, and for campaigns without `pyranometer.csv`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub baseline_perez: Option<ErrorSummary>,
    pub effects: Vec<EffectReport>,
    /// Skylux addition: a second metric per set (RMSE in the error's units), by name.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub secondary: BTreeMap<String, ErrorSummary>,
    /// Skylux addition: effects that were tried and rejected, and why.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub rejected: Vec<String>,
    /// Skylux addition: free-form findings (e.g. "no effect improved the hold-out error").
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    /// Skylux addition: plots written beside the report, relative to its folder.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub figures: Vec<String>,
}

impl From<crate::output::WriteError> for ReportError {
    fn from(e: crate::output::WriteError) -> Self {
        ReportError::Io {
            path: e.path,
            source: e.source,
        }
    }
}

impl Report {
    /// `report.md`: the before/after table per sensor, the baseline, each effect with its
    /// parameters and evidence, and the figures.
    pub fn markdown(&self, title: &str) -> String {
        use std::fmt::Write;
        let pct = |v: f64| {
            if v.is_finite() {
                format!("{:.1} %", 100.0 * v)
            } else {
                "n/a".into()
            }
        };
        let mut md = String::new();
        let _ = writeln!(md, "# {title}\n");
        let _ = writeln!(
            md,
            "Metric: `{}`, on the {} hold-out times (the fit used {} others; blocks of time \
             alternate between the sets).\n",
            self.metric,
            self.holdout_times.len(),
            self.fit_times.len()
        );
        let _ = write!(md, "| sensor | before | after |");
        if self.baseline_perez.is_some() {
            let _ = write!(md, " Perez baseline |");
        }
        let _ = write!(md, "\n|---|---|---|");
        if self.baseline_perez.is_some() {
            let _ = write!(md, "---|");
        }
        let _ = writeln!(md);
        let mut rows: Vec<(String, f64, f64, Option<f64>)> = self
            .before
            .per_sensor
            .iter()
            .map(|(k, b)| {
                (
                    k.clone(),
                    *b,
                    self.after.per_sensor.get(k).copied().unwrap_or(f64::NAN),
                    self.baseline_perez
                        .as_ref()
                        .map(|p| p.per_sensor.get(k).copied().unwrap_or(f64::NAN)),
                )
            })
            .collect();
        rows.sort_by_key(|r| sensor_order(&r.0));
        rows.push((
            "**all**".into(),
            self.before.all,
            self.after.all,
            self.baseline_perez.as_ref().map(|p| p.all),
        ));
        for (k, b, a, p) in rows {
            let _ = write!(md, "| {k} | {} | {} |", pct(b), pct(a));
            if let Some(p) = p {
                let _ = write!(md, " {} |", pct(p));
            }
            let _ = writeln!(md);
        }
        let _ = writeln!(md, "\n## Effects found\n");
        if self.effects.is_empty() {
            let _ = writeln!(md, "None.\n");
        }
        for e in &self.effects {
            let params: Vec<String> = e
                .parameters
                .iter()
                .map(|(k, v)| format!("{k} = {v:.4}"))
                .collect();
            let _ = writeln!(
                md,
                "- **{}** ({}): {}. Hold-out error fell by {}.",
                e.name,
                if params.is_empty() {
                    "no parameter".into()
                } else {
                    params.join(", ")
                },
                e.evidence,
                pct(e.gain)
            );
        }
        for (title, list) in [("Rejected", &self.rejected), ("Notes", &self.notes)] {
            if !list.is_empty() {
                let _ = writeln!(md, "\n## {title}\n");
                for n in list {
                    let _ = writeln!(md, "- {n}");
                }
            }
        }
        if !self.figures.is_empty() {
            let _ = writeln!(md, "\n## Figures\n");
            for f in &self.figures {
                let _ = writeln!(md, "![{f}]({f})\n");
            }
        }
        md
    }
}

/// The residual table of `report.md` (appended by `skylux loop`): the relative residual's
/// correlation and slope against each explanatory variable, over all readings and per sensor,
/// before and after the effects. Empty without rows.
pub fn residual_markdown(rows: &[ResidualRow]) -> String {
    use std::fmt::Write;
    let mut md = String::new();
    if rows.is_empty() {
        return md;
    }
    let _ = writeln!(
        md,
        "\n## Residual against the explanatory variables\n\nRelative residual \
         (model / measured − 1) of every reading (fit and hold-out): Pearson r and \
         least-squares slope per unit of the variable, before and after the effects.\n"
    );
    let _ = writeln!(
        md,
        "| variable | readings | r before | slope before | r after | slope after |\n\
         |---|---|---|---|---|---|"
    );
    let num = |v: f64, p: usize| {
        if v.is_finite() {
            format!("{v:.p$}")
        } else {
            "n/a".into()
        }
    };
    for r in rows.iter().filter(|r| r.group == "all") {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} |",
            r.variable,
            r.n,
            num(r.before_r, 2),
            num(r.before_slope, 4),
            num(r.after_r, 2),
            num(r.after_slope, 4)
        );
    }
    let mut groups: Vec<&str> = rows
        .iter()
        .map(|r| r.group.as_str())
        .filter(|g| *g != "all")
        .collect();
    groups.sort_by_key(|g| sensor_order(g));
    groups.dedup();
    if !groups.is_empty() {
        let _ = writeln!(
            md,
            "\nPer sensor, r before → after:\n\n| variable | {} |\n|---|{}",
            groups.join(" | "),
            "---|".repeat(groups.len())
        );
        let mut variables: Vec<&str> = Vec::new();
        for r in rows {
            if !variables.contains(&r.variable.as_str()) {
                variables.push(&r.variable);
            }
        }
        for v in variables {
            let cells: Vec<String> = groups
                .iter()
                .map(|g| {
                    rows.iter()
                        .find(|r| r.variable == v && r.group == *g)
                        .map_or("n/a".into(), |r| {
                            format!("{} → {}", num(r.before_r, 2), num(r.after_r, 2))
                        })
                })
                .collect();
            let _ = writeln!(md, "| {v} | {} |", cells.join(" | "));
        }
    }
    md
}

/// `S2` before `S10`.
fn sensor_order(name: &str) -> (String, u64) {
    let digits = name.trim_start_matches(|c: char| !c.is_ascii_digit());
    (
        name[..name.len() - digits.len()].to_string(),
        digits.parse().unwrap_or(u64::MAX),
    )
}

/// Why a report could not be written or read.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    #[error("{path}: {source}")]
    Io {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
    #[error("{path}: not a report: {message}")]
    Parse {
        path: std::path::PathBuf,
        message: String,
    },
}

impl Report {
    /// Writes `report.json` atomically (temporary file, then rename), so a reader never
    /// sees half a report.
    pub fn write_json(&self, path: &Path) -> Result<(), ReportError> {
        let text = serde_json::to_string_pretty(self).map_err(|e| ReportError::Parse {
            path: path.into(),
            message: e.to_string(),
        })?;
        crate::output::write_atomic(path, text.as_bytes())?;
        Ok(())
    }

    pub fn read_json(path: &Path) -> Result<Self, ReportError> {
        let text = std::fs::read_to_string(path).map_err(|source| ReportError::Io {
            path: path.into(),
            source,
        })?;
        serde_json::from_str(&text).map_err(|e| ReportError::Parse {
            path: path.into(),
            message: e.to_string(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The spec's example parses, and a written report reads back equal.
    #[test]
    fn spec_example_parses_and_round_trips() {
        let spec = r#"{
          "metric": "mean_abs_rel_error",
          "fit_times": ["..."],
          "holdout_times": ["..."],
          "before": {"all": 0.231, "per_sensor": {"S1": 0.25}},
          "after":  {"all": 0.061, "per_sensor": {"S1": 0.07}},
          "baseline_perez": {"all": 0.33, "per_sensor": {"S1": 0.37}},
          "effects": [
            {"name": "...", "parameters": {"...": 0.0}, "evidence": "one sentence", "gain": 0.12}
          ]
        }"#;
        let r: Report = serde_json::from_str(spec).unwrap();
        assert_eq!(r.before.per_sensor["S1"], 0.25);
        assert_eq!(r.effects[0].gain, 0.12);
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("report.json");
        r.write_json(&p).unwrap();
        assert_eq!(Report::read_json(&p).unwrap(), r);
        assert!(!crate::output::tmp_name(&p).exists());
    }
}
