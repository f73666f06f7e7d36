//! `[[views]]` and `[glare]`: the occupants' eyes whose glare each cycle reports (issue 21
//! item 3), and how their fisheye pictures are rendered within the cycle's time.

use super::{refuse, FieldError};
use glam::DVec3;
use serde::Deserialize;
use skylux_hps::engine::render::{View, ViewType};

/// `[[views]]`: one occupant's eye, as RADIANCE's `-vp`, `-vd`, `-vu` and a fisheye type.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ViewConfig {
    /// Names the view in the record and its picture's file (letters, digits, `-`, `_`).
    pub name: String,
    /// `-vp`: the eye, m, in the room's frame.
    pub position_m: [f64; 3],
    /// `-vd`: where the eye looks (any length but zero).
    pub direction: [f64; 3],
    /// `-vu`: up (default +z).
    #[serde(default = "default_up")]
    pub up: [f64; 3],
    /// `-vta` (angular fisheye, evalglare's usual input; the default) or `-vth`.
    #[serde(default = "default_view_type")]
    pub view_type: String,
    /// `-vh` and `-vv`, degrees: 180 (the field of view glare metrics integrate) by default.
    #[serde(default = "default_field_deg")]
    pub field_deg: f64,
}

fn default_up() -> [f64; 3] {
    [0.0, 0.0, 1.0]
}
fn default_view_type() -> String {
    "-vta".into()
}
fn default_field_deg() -> f64 {
    180.0
}

/// Longest view name (it becomes part of a file name).
const MAX_NAME_CHARS: usize = 64;

impl ViewConfig {
    /// The RADIANCE view of this eye.
    pub fn view(&self) -> View {
        View {
            kind: if self.view_type == "-vth" {
                ViewType::Hemispherical
            } else {
                ViewType::Angular
            },
            position_m: DVec3::from_array(self.position_m),
            direction: DVec3::from_array(self.direction),
            up: DVec3::from_array(self.up),
            horizontal_deg: self.field_deg,
            vertical_deg: self.field_deg,
            ..View::default()
        }
    }

    pub(super) fn check(&self) -> Result<(), FieldError> {
        let n = &self.name;
        let name_ok = !n.is_empty()
            && n.chars().count() <= MAX_NAME_CHARS
            && n.chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_');
        if !name_ok {
            return refuse(
                "name",
                format!(
                    "{n:?}: 1 to {MAX_NAME_CHARS} letters, digits, `-` or `_` (it names the \
                     view's picture file)"
                ),
            );
        }
        for (key, v) in [
            ("position_m", self.position_m),
            ("direction", self.direction),
            ("up", self.up),
        ] {
            if v.iter().any(|x| !x.is_finite() || x.abs() > 1e6) {
                return refuse(key, format!("{v:?}: three finite numbers, each within 1e6"));
            }
        }
        if !matches!(self.view_type.as_str(), "-vta" | "-vth") {
            return refuse(
                "view_type",
                format!(
                    "{:?}: a glare view is a fisheye, \"-vta\" (angular) or \"-vth\" \
                     (hemispherical)",
                    self.view_type
                ),
            );
        }
        let f = self.field_deg;
        if !(f.is_finite() && f > 0.0 && f <= 180.0) {
            return refuse("field_deg", format!("{f} is outside (0, 180] degrees"));
        }
        let (d, u) = (
            DVec3::from_array(self.direction),
            DVec3::from_array(self.up),
        );
        if d.length() < 1e-9 {
            return refuse("direction", "must not be zero");
        }
        if u.length() < 1e-9 || d.normalize().cross(u.normalize()).length() < 1e-6 {
            return refuse(
                "up",
                format!("{:?} must be non-zero and not along the direction", self.up),
            );
        }
        // What setview itself refuses is reported with the view's own words.
        self.view()
            .prepare()
            .map(|_| ())
            .or_else(|e| refuse("direction", e.to_string()))
    }
}

/// `[glare]`: the fisheye pictures of the views and the direct Ev sensor beside them.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct GlareConfig {
    /// Side of the square fisheye picture, pixels.
    #[serde(default = "default_resolution_px")]
    pub resolution_px: u32,
    /// Paths per pixel (at least 2: each pixel's standard error needs two).
    #[serde(default = "default_samples_per_pixel")]
    pub samples_per_pixel: u32,
    /// Paths of the direct Ev sensor at each eye (the DGPs fallback and the render's check).
    #[serde(default = "default_sensor_samples")]
    pub sensor_samples: u32,
    /// Share of `capture.period_s` a cycle may take in all: a view is rendered only if its
    /// estimated time still fits, else it reports DGPs.
    #[serde(default = "default_budget_fraction")]
    pub budget_fraction: f64,
}

/// 64 × 64 pixels (2.8° each) at 16 paths: three views take 1.7 s (overcast or no sun) to
/// 2.9 s (sun) of one core here per cycle (BENCHMARKS.md, "Glare views"). Their time on the A9
/// is not modelled; the cycle renders a view only when its own measured time per path says it
/// fits the budget, and reports DGPs otherwise.
fn default_resolution_px() -> u32 {
    64
}
fn default_samples_per_pixel() -> u32 {
    16
}
fn default_sensor_samples() -> u32 {
    4096
}
/// Three quarters of the period: 45 s of a 60 s period, of which the rest of the cycle takes
/// about 3.2 s on the A9 by the cost model (BENCHMARKS.md, "skyluxd cycle budget").
fn default_budget_fraction() -> f64 {
    0.75
}

impl Default for GlareConfig {
    fn default() -> Self {
        Self {
            resolution_px: default_resolution_px(),
            samples_per_pixel: default_samples_per_pixel(),
            sensor_samples: default_sensor_samples(),
            budget_fraction: default_budget_fraction(),
        }
    }
}

impl GlareConfig {
    pub(super) fn check(&self) -> Result<(), FieldError> {
        if !(8..=2048).contains(&self.resolution_px) {
            return refuse(
                "resolution_px",
                format!("{} is outside 8..=2048 pixels", self.resolution_px),
            );
        }
        if !(2..=65_536).contains(&self.samples_per_pixel) {
            return refuse(
                "samples_per_pixel",
                format!(
                    "{} is outside 2..=65536 (two at least: a pixel's standard error needs two)",
                    self.samples_per_pixel
                ),
            );
        }
        if !(1..=10_000_000).contains(&self.sensor_samples) {
            return refuse(
                "sensor_samples",
                format!("{} is outside 1..=10000000", self.sensor_samples),
            );
        }
        let b = self.budget_fraction;
        if !(b.is_finite() && b > 0.0 && b <= 1.0) {
            return refuse("budget_fraction", format!("{b} is outside (0, 1]"));
        }
        Ok(())
    }
}

/// Checks the views: each one, then that no two share a name. Returns the index of the view
/// refused with the error.
pub(super) fn check_views(views: &[ViewConfig]) -> Result<(), (usize, FieldError)> {
    for (i, v) in views.iter().enumerate() {
        v.check().map_err(|e| (i, e))?;
        if views[..i].iter().any(|o| o.name == v.name) {
            return Err((
                i,
                FieldError {
                    key: "name",
                    message: format!("{:?} names two views", v.name),
                },
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::tests::MINIMAL;
    use super::super::{Config, Overrides};
    use std::path::Path;

    const VIEW: &str = r#"
[[views]]
name = "desk"
position_m = [1.45, 4.7, 1.2]
direction = [0, -1, 0]
"#;

    fn parse(extra: &str) -> Result<Config, String> {
        let text = format!("{MINIMAL}{extra}");
        Config::parse(&text, Path::new("/etc/skyluxd.toml"), &Overrides::default())
            .map_err(|e| e.to_string())
    }

    /// The 1-based line of `key =` in the `nth` `[[views]]` table of MINIMAL + `extra`, or
    /// of that table's header without one.
    fn line_of(extra: &str, key: &str, nth: usize) -> usize {
        let text = format!("{MINIMAL}{extra}");
        let lines: Vec<&str> = text.lines().collect();
        let header = lines
            .iter()
            .enumerate()
            .filter(|(_, l)| l.trim() == "[[views]]")
            .nth(nth)
            .unwrap()
            .0;
        let table = lines[header + 1..]
            .iter()
            .take_while(|l| !l.trim_start().starts_with('['));
        let at = table
            .enumerate()
            .find(|(_, l)| l.starts_with(&format!("{key} =")))
            .map_or(0, |(k, _)| k + 1);
        header + 1 + at
    }

    #[test]
    fn a_view_takes_the_fisheye_defaults() {
        let c = parse(VIEW).unwrap();
        assert_eq!(c.views.len(), 1);
        let v = c.views[0].view();
        assert_eq!(v.kind, skylux_hps::engine::render::ViewType::Angular);
        assert_eq!((v.horizontal_deg, v.vertical_deg), (180.0, 180.0));
        assert_eq!(v.up, glam::DVec3::Z);
        assert_eq!(c.glare, super::GlareConfig::default());
        // No views: none evaluated.
        assert!(parse("").unwrap().views.is_empty());
    }

    #[test]
    fn each_refused_view_field_is_named_with_its_line() {
        let second =
            "\n[[views]]\nname = \"door\"\nposition_m = [1, 1, 1.2]\ndirection = [1, 0, 0]\n";
        let cases: [(&str, &str, &str, &str); 7] = [
            (
                "name = \"desk\"",
                "name = \"my desk\"",
                "views[0].name",
                "letters",
            ),
            (
                "direction = [0, -1, 0]",
                "direction = [0, 0, 0]",
                "views[0].direction",
                "zero",
            ),
            (
                "direction = [0, -1, 0]",
                "direction = [0, 0, 1]",
                "views[0].up",
                "along",
            ),
            (
                "position_m = [1.45, 4.7, 1.2]",
                "position_m = [1.45, nan, 1.2]",
                "views[0].position_m",
                "finite",
            ),
            (
                "direction = [0, -1, 0]",
                "direction = [0, -1, 0]\nview_type = \"-vtv\"",
                "views[0].view_type",
                "fisheye",
            ),
            (
                "direction = [0, -1, 0]",
                "direction = [0, -1, 0]\nfield_deg = 200",
                "views[0].field_deg",
                "(0, 180]",
            ),
            (
                "direction = [1, 0, 0]",
                "direction = [1, 0, 0]\nup = [2, 0, 0]",
                "views[1].up",
                "along",
            ),
        ];
        for (from, to, field, words) in cases {
            let extra = format!("{VIEW}{second}").replace(from, to);
            let e = parse(&extra).unwrap_err();
            assert!(e.contains(field) && e.contains(words), "{to}: {e}");
            // The line is the offending key's in the right [[views]] table, or that table's
            // header where the key was left to its default.
            let key = field.rsplit('.').next().unwrap();
            let nth = usize::from(field.starts_with("views[1]"));
            let line = line_of(&extra, key, nth);
            assert!(
                e.contains(&format!("skyluxd.toml:{line}:")),
                "{to}: {e} (line {line})"
            );
        }
    }

    #[test]
    fn two_views_may_not_share_a_name_and_a_missing_field_is_named() {
        let e = parse(&format!("{VIEW}{VIEW}")).unwrap_err();
        assert!(
            e.contains("views[1].name") && e.contains("names two views"),
            "{e}"
        );
        let e = parse("\n[[views]]\nname = \"a\"\nposition_m = [1, 1, 1]\n").unwrap_err();
        assert!(e.contains("direction"), "{e}");
        let e = parse(&format!("{VIEW}colour = 3\n")).unwrap_err();
        assert!(e.contains("colour"), "{e}");
    }

    #[test]
    fn glare_settings_are_checked() {
        for (text, field) in [
            ("resolution_px = 4", "glare.resolution_px"),
            ("samples_per_pixel = 1", "glare.samples_per_pixel"),
            ("sensor_samples = 0", "glare.sensor_samples"),
            ("budget_fraction = 1.5", "glare.budget_fraction"),
            ("budget_fraction = nan", "glare.budget_fraction"),
        ] {
            let e = parse(&format!("{VIEW}\n[glare]\n{text}\n")).unwrap_err();
            assert!(e.contains(field), "{text}: {e}");
        }
        let c = parse(&format!("{VIEW}\n[glare]\nresolution_px = 32\n")).unwrap();
        assert_eq!(c.glare.resolution_px, 32);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        /// A view table with any line replaced by anything: an error or a config, never a panic.
        #[test]
        fn mutated_views_never_panic(line in 0usize..6, junk in ".{0,60}") {
            let mut lines: Vec<String> = VIEW.lines().map(String::from).collect();
            let i = line % lines.len();
            lines[i] = junk;
            let _ = parse(&lines.join("\n"));
        }

        /// Any numbers in the vectors and the field.
        #[test]
        fn numbers_never_panic(v in proptest::num::f64::ANY, k in 0usize..4) {
            let text = match k {
                0 => VIEW.replace("1.45", &format!("{v:?}")),
                1 => VIEW.replace("-1, 0]", &format!("{v:?}, 0]")),
                2 => format!("{VIEW}up = [{v:?}, 0, 1]\n"),
                _ => format!("{VIEW}field_deg = {v:?}\n"),
            };
            let _ = parse(&text);
        }
    }
}
