//! A window declared with several shading states (blinds at 0°, 45°, closed; a shade down;
//! electrochromic tints), each a BSDF: every state's illuminance for every sky from matrices
//! traced once. Per state k, the five-phase method with the sun's beam at its exact incident
//! patch:
//!
//! E_k = V T_k (D s + (D − D_d) s_sun + b_sun) − V_d T_k b_sun + C_k(sun) E_dn
//!
//! with s the sky without the sun, s_sun the sun as a sky vector (its light the outside
//! reflects: (D − D_d) s_sun), b_sun the beam as the radiance arriving in the sun's own Klems
//! patch (E_dn cos θ / Ω_patch over the lit share of the window; D s_sun would spread it over
//! the patches its sky patch overlaps, and a clear glazing sends each elsewhere: observed
//! +10 % at a sensor near the beam's landing), and C_k the beam's direct view at full
//! resolution.
//!
//! V, V_d, D and D_d belong to the room and are shared by every state; a state is only its
//! T_k and its data. A sky costs D (s + s_sun) and D_d s_sun once, then two (sensors ×
//! patches) products per state. The sun's direct term C_k is a product too: the sensors'
//! direct view of the window is integrated once over a grid of window points ([`SunView`]:
//! per sensor and point the solid angle times the cosines, where the room lets the sensor
//! see the point), and for each sky the points the sun reaches and the state's data at the
//! sun's exact incident direction give it, as RADIANCE's `BSDF` material takes the sun at a
//! window (m_bsdf.c `dir_bsdf`). States are Klems data (on another basis than the window's,
//! averaged over its patch pairs); a tensor tree is refused (convert it with `bsdf2klems`).
//!
//! The data is read as rtrace reads it, so that a state answers as rtrace does on the room
//! with that XML as its `BSDF` window: RADIANCE's material evaluates f with the ray from the
//! viewer (the room) as the incident direction and the light's as the outgoing one
//! (m_bsdf.c: `SDevalBSDF(&sv, vsrc, vray, sd)`), whereas `dctimestep` takes the file's
//! "Transmission Front" block (light from outside). For reciprocal data the two agree; where
//! a file's two transmission blocks do not (frads' Satine shade: front 1.34 × back), the
//! states follow rtrace, and T_k is not the file's front block.

use super::five_phase::sun_sky_vector;
use super::scene_sky::SunBeam;
use super::three_phase::WindowStates;
use super::window::KlemsWindow;
use super::{daylight_matrix, view_matrices};
use crate::bsdf::{Band, Bsdf, BsdfError, KlemsTransmission};
use crate::engine::error::EngineError;
use crate::engine::integrator::Settings;
use crate::engine::ray::Ray;
use crate::engine::world::World;
use crate::io::radiance_matrix::{MatrixFormat, RadianceMatrix};
use crate::scene::{Scene, Sensor, Shape};
use glam::DVec3;
use rayon::prelude::*;
use std::path::Path;

/// One declared state of the window.
#[derive(Debug, Clone)]
pub struct ShadingState {
    pub name: String,
    /// T_k on the window's Klems basis (rows outgoing into the room, columns incident),
    /// f times the incident patch's projected solid angle, as [`KlemsTransmission`].
    transmission: RadianceMatrix,
}

/// Incident and outgoing directions per Klems patch when data on another basis is averaged over the
/// patch pairs (3 × 3 strata each: 81 pairs per entry).
const OTHER_BASIS_STRATA: usize = 3;

impl ShadingState {
    /// The state `name` from its BSDF XML (visible band) on `window`'s Klems basis.
    pub fn load(name: &str, xml: &Path, window: &KlemsWindow) -> Result<Self, BsdfError> {
        let file = xml.display().to_string();
        let text = std::fs::read_to_string(xml)
            .map_err(|e| BsdfError::new(&file, 0, "file", format!("cannot read: {e}")))?;
        Self::from_xml(name, &text, &file, window)
    }

    /// As [`ShadingState::load`] from the XML's text; `file` names it in errors.
    pub fn from_xml(
        name: &str,
        text: &str,
        file: &str,
        window: &KlemsWindow,
    ) -> Result<Self, BsdfError> {
        let data = Bsdf::from_xml(text, file, Band::Visible)?;
        if data.has_tensor_tree() {
            // Averaged over 3 x 3 direction pairs per patch pair, the LBNL tutorial's blinds
            // (blindsT3.xml) read -19 % to +30 % against rtrace under overcast: a tree's peaks
            // need its own sampling per patch, as bsdf2klems does. Refused until then.
            return Err(BsdfError::new(
                file,
                0,
                "DataStructure",
                "a tensor tree: a window state needs Klems data (RADIANCE's bsdf2klems \
                 converts)",
            ));
        }
        // Klems data on the window's basis is constant over each patch pair: one direction
        // pair per entry gives it exactly.
        let on_basis = KlemsTransmission::from_xml(text, file, Band::Visible).is_ok_and(|t| {
            let n = window.basis.len();
            (t.matrix.rows, t.matrix.cols) == (n, n)
        });
        let transmission =
            klems_average(&data, window, if on_basis { 1 } else { OTHER_BASIS_STRATA });
        Ok(ShadingState {
            name: name.to_string(),
            transmission,
        })
    }

    /// A state of Klems data given as its T (f times the incident patch's projected solid
    /// angle, rows outgoing into the room, columns incident), without a file.
    pub fn from_transmission(name: &str, transmission: RadianceMatrix) -> Self {
        ShadingState {
            name: name.to_string(),
            transmission,
        }
    }

    /// T_k (rows outgoing into the room, columns incident from outside).
    pub fn transmission(&self) -> &RadianceMatrix {
        &self.transmission
    }
}

/// T of `data` on `window`'s basis as rtrace reads the data (the room's side incident):
/// f averaged over `strata`² direction pairs of each (incident, outgoing) patch pair, times
/// the incident patch's projected solid angle.
pub fn klems_average(data: &Bsdf, window: &KlemsWindow, strata: usize) -> RadianceMatrix {
    let basis = &window.basis;
    let n = basis.len();
    let per_axis = strata.max(1);
    let strata: Vec<[f64; 2]> = (0..per_axis * per_axis)
        .map(|k| {
            let cell = |c: usize| (c as f64 + 0.5) / per_axis as f64;
            [cell(k / per_axis), cell(k % per_axis)]
        })
        .collect();
    // Directions in the window's (and the BSDF's) frame: light arriving into the room along
    // a patch's direction travels in +z; the incident direction points back outside.
    let directions: Vec<Vec<DVec3>> = (0..n)
        .map(|p| {
            strata
                .iter()
                .map(|&u| basis.direction_in_patch(p, u))
                .collect()
        })
        .collect();
    let values: Vec<f64> = (0..n * n)
        .into_par_iter()
        .map(|k| {
            let (out, inc) = (k / n, k % n);
            let mut sum = 0.0;
            for i in &directions[inc] {
                for o in &directions[out] {
                    // Light from outside along i leaves into the room along o; rtrace
                    // evaluates it from the room's side: incident o, outgoing −i.
                    sum += data.eval(*o, -*i);
                }
            }
            sum / (strata.len() * strata.len()) as f64 * basis.projected_solid_angle_sr(inc)
        })
        .collect();
    RadianceMatrix {
        rows: n,
        cols: n,
        ncomp: 1,
        values,
    }
}

/// The room's matrices, shared by every state: V and D of the three-phase, V_d (`-ab 1`)
/// and D_d (`-ab 0`) of the five-phase's direct part.
#[derive(Debug, Clone)]
pub struct StateMatrices {
    pub v: RadianceMatrix,
    pub v_direct: RadianceMatrix,
    pub d: RadianceMatrix,
    pub d_direct: RadianceMatrix,
}

/// The files of [`StateMatrices::write`], in RADIANCE's matrix format.
const MATRIX_FILES: [&str; 4] = ["v.mtx", "vd.mtx", "d.mtx", "dd.mtx"];

impl StateMatrices {
    /// Traces the matrices: `room` the room without its glazing, `outside` the same with
    /// the outside geometry, `view` V's settings (V_d from the same paths' first segments),
    /// `daylight` D's (rays per window patch and bounces outside; D_d takes none).
    #[allow(clippy::too_many_arguments)]
    pub fn trace(
        room: &World,
        outside: &World,
        sensors: &[Sensor],
        window: &KlemsWindow,
        mf: usize,
        view: &Settings,
        daylight: &Settings,
        progress: &(dyn Fn(u64, u64) + Sync),
    ) -> Result<Self, EngineError> {
        let (v, v_direct) = view_matrices(room, sensors, window, view, progress)?;
        let d = daylight_matrix(outside, window, mf, daylight, progress)?;
        let d_direct = daylight_matrix(
            outside,
            window,
            mf,
            &Settings {
                ambient_bounces: 0,
                ..*daylight
            },
            &|_, _| {},
        )?;
        Ok(StateMatrices {
            v,
            v_direct,
            d,
            d_direct,
        })
    }

    fn all(&self) -> [&RadianceMatrix; 4] {
        [&self.v, &self.v_direct, &self.d, &self.d_direct]
    }

    /// Writes v.mtx, vd.mtx, d.mtx and dd.mtx into `dir` (binary float64, `header` in each).
    pub fn write(&self, dir: &Path, header: &str) -> Result<(), std::io::Error> {
        std::fs::create_dir_all(dir)?;
        for (m, name) in self.all().into_iter().zip(MATRIX_FILES) {
            m.write(&dir.join(name), MatrixFormat::Double, &[header.to_string()])?;
        }
        Ok(())
    }

    /// Reads what [`StateMatrices::write`] wrote.
    pub fn read(dir: &Path) -> Result<Self, String> {
        let read = |name: &str| {
            let path = dir.join(name);
            RadianceMatrix::read(&path).map_err(|e| format!("{}: {e}", path.display()))
        };
        Ok(StateMatrices {
            v: read(MATRIX_FILES[0])?,
            v_direct: read(MATRIX_FILES[1])?,
            d: read(MATRIX_FILES[2])?,
            d_direct: read(MATRIX_FILES[3])?,
        })
    }
}

/// Takes the window's glazing out of `scene` (the polygons [`KlemsWindow::holds`]): the
/// matrices see the window as their receiver, and the states stand in for the glazing.
/// Returns the names of the surfaces removed.
pub fn remove_glazing(scene: &mut Scene, window: &KlemsWindow) -> Vec<String> {
    let mut removed = Vec::new();
    scene.retain_surfaces(|s| match &s.shape {
        Shape::Polygon(p) if window.holds(p) => {
            removed.push(s.name.clone());
            false
        }
        _ => true,
    });
    removed
}

/// One sensor's view of one window point.
#[derive(Debug, Clone, Copy)]
struct PointView {
    point: u32,
    /// The Klems patch of the light from the point to the sensor.
    patch: u32,
    /// Irradiance at the sensor per unit radiance leaving the point towards it:
    /// (area / points) cos θ_window cos θ_sensor / r², sr.
    weight_sr: f64,
}

/// The sensors' direct view of the window over a grid of its points, for the sun's direct
/// term: computed once per room.
#[derive(Debug, Clone)]
pub struct SunView {
    points_m: Vec<DVec3>,
    sensor_positions_m: Vec<DVec3>,
    /// Entries of sensor s: `views[offsets[s]..offsets[s + 1]]`.
    offsets: Vec<usize>,
    views: Vec<PointView>,
}

/// How far outside the window's plane the sun's visibility ray starts, m.
const SUN_RAY_OFFSET_M: f64 = 1e-6;

impl SunView {
    /// The view of `sensors` through `room` (without its glazing) of `points_per_side`² points
    /// of `window`.
    pub fn new(
        room: &World,
        sensors: &[Sensor],
        window: &KlemsWindow,
        points_per_side: usize,
    ) -> Self {
        let points_m = window.grid_points(points_per_side.max(1));
        let area_per_point = window.area_m2() / points_m.len() as f64;
        let per_sensor: Vec<Vec<PointView>> = sensors
            .par_iter()
            .map(|sensor| {
                let mut views = Vec::new();
                for (k, &x) in points_m.iter().enumerate() {
                    let to_point = x - sensor.position_m;
                    let r2 = to_point.length_squared();
                    let d = to_point / r2.sqrt();
                    let (cos_sensor, cos_window) = (d.dot(sensor.direction), -d.dot(window.normal));
                    if cos_sensor <= 0.0 || cos_window <= 0.0 {
                        continue;
                    }
                    let blocked = room
                        .intersect(&Ray::new(sensor.position_m, d), None)
                        .is_some_and(|h| h.t_m < r2.sqrt() * (1.0 - 1e-9));
                    let Some(patch) = window.patch_of_arrival(-d) else {
                        continue;
                    };
                    if !blocked {
                        views.push(PointView {
                            point: k as u32,
                            patch: patch as u32,
                            weight_sr: area_per_point * cos_window * cos_sensor / r2,
                        });
                    }
                }
                views
            })
            .collect();
        let mut offsets = vec![0];
        let mut views = Vec::new();
        for v in per_sensor {
            views.extend(v);
            offsets.push(views.len());
        }
        SunView {
            points_m,
            sensor_positions_m: sensors.iter().map(|s| s.position_m).collect(),
            offsets,
            views,
        }
    }

    fn of_sensor(&self, s: usize) -> &[PointView] {
        &self.views[self.offsets[s]..self.offsets[s + 1]]
    }

    /// Per sensor and Klems patch, the solid-angle weight of the window points the sun
    /// reaches (`lit`): a direct view matrix at full spatial resolution.
    fn lit_patch_weights(&self, lit: &[bool], patches: usize) -> Vec<f64> {
        let sensors = self.sensor_positions_m.len();
        let mut w = vec![0.0; sensors * patches];
        for s in 0..sensors {
            for v in self.of_sensor(s) {
                if lit[v.point as usize] {
                    w[s * patches + v.patch as usize] += v.weight_sr;
                }
            }
        }
        w
    }
}

/// A window with its states, ready for every sky.
#[derive(Debug, Clone)]
pub struct ShadedWindow {
    window: KlemsWindow,
    mf: usize,
    states: Vec<ShadingState>,
    full: WindowStates,
    direct: WindowStates,
    sun_view: SunView,
}

fn setting_error(value: String) -> EngineError {
    EngineError::Setting {
        name: "window states",
        value,
        expected: "V, V_d with the sun view's sensors; D, D_d with 1 + Reinhart MF mf columns",
    }
}

impl ShadedWindow {
    /// Precomputes V T_k and V_d T_k for every state.
    pub fn new(
        window: KlemsWindow,
        mf: usize,
        states: Vec<ShadingState>,
        m: &StateMatrices,
        sun_view: SunView,
    ) -> Result<Self, EngineError> {
        let columns = 1 + crate::sky::SkyPatches::reinhart(mf).len();
        if m.d.cols != columns || m.d_direct.cols != columns {
            return Err(setting_error(format!(
                "D with {} and D_d with {} columns for MF{mf} ({columns})",
                m.d.cols, m.d_direct.cols
            )));
        }
        let sensors = sun_view.sensor_positions_m.len();
        if m.v.rows != sensors || m.v_direct.rows != sensors {
            return Err(setting_error(format!(
                "V with {} and V_d with {} rows for {sensors} sensors",
                m.v.rows, m.v_direct.rows
            )));
        }
        if states.is_empty() {
            return Err(setting_error("no state".into()));
        }
        let ts: Vec<RadianceMatrix> = states.iter().map(|s| s.transmission.clone()).collect();
        let full = WindowStates::new(&m.v, &ts, &m.d)?;
        let direct = WindowStates::new(&m.v_direct, &ts, &m.d_direct)?;
        Ok(ShadedWindow {
            window,
            mf,
            states,
            full,
            direct,
            sun_view,
        })
    }

    pub fn state_names(&self) -> Vec<&str> {
        self.states.iter().map(|s| s.name.as_str()).collect()
    }

    /// Irradiance per state and sensor, W/m² (times 179 lm/W for lux): `sky` the sky vector
    /// without the sun (ground, then the MF patches, radiance), `suns` the beams, `outside`
    /// the world the sun's light crosses to the window (the room without its glazing and the
    /// outside geometry, no sky).
    pub fn irradiance_w_m2(
        &self,
        sky: &[f64],
        suns: &[SunBeam],
        outside: &World,
    ) -> Result<Vec<Vec<f64>>, EngineError> {
        let mut sun_vector = vec![0.0; sky.len()];
        for sun in suns {
            if let Some(s) = sun_sky_vector(self.mf, sun.direction, sun.direct_normal_w_m2) {
                if s.len() != sky.len() {
                    return Err(setting_error(format!(
                        "a sky vector of {} for MF{} ({})",
                        sky.len(),
                        self.mf,
                        s.len()
                    )));
                }
                sun_vector.iter_mut().zip(s).for_each(|(a, b)| *a += b);
            }
        }
        // Radiance arriving per incident patch: the sky's, D s, and the sun's light the
        // outside reflects, (D − D_d) s_sun; the sun's own beam enters at its exact patch.
        let with_sun: Vec<f64> = sky.iter().zip(&sun_vector).map(|(a, b)| a + b).collect();
        let mut arriving = self.full.window_radiance(&with_sun)?;
        let reflected_sun = self.direct.window_radiance(&sun_vector)?;
        arriving
            .iter_mut()
            .zip(&reflected_sun)
            .for_each(|(a, b)| *a -= b);
        let sensors = self.full.sensors();
        let mut beam = vec![0.0; arriving.len()];
        let mut direct_sun = vec![vec![0.0; sensors]; self.states.len()];
        for sun in suns {
            self.add_sun(sun, outside, &mut beam, &mut direct_sun);
        }
        arriving.iter_mut().zip(&beam).for_each(|(a, b)| *a += b);
        let (mut a, mut b) = (vec![0.0; sensors], vec![0.0; sensors]);
        (0..self.states.len())
            .map(|k| {
                // V T_k over everything arriving, less the beam's direct view (V_d T_k),
                // which the sun term puts back at full resolution.
                self.full.apply_state(k, &arriving, &mut a)?;
                self.direct.apply_state(k, &beam, &mut b)?;
                Ok((0..sensors)
                    .map(|s| a[s] - b[s] + direct_sun[k][s])
                    .collect())
            })
            .collect()
    }

    /// Adds the sun's beam: into `beam`, the radiance its lit share of the window receives
    /// in the sun's exact incident patch (E_dn cos θ / Ω_patch); into `direct_sun`, per
    /// state and sensor, C_k(sun) E_dn: the beam through each state's data at its exact
    /// incident direction onto the window points it reaches, seen directly by the sensor.
    fn add_sun(
        &self,
        sun: &SunBeam,
        outside: &World,
        beam: &mut [f64],
        direct_sun: &mut [Vec<f64>],
    ) {
        let inward = -self.window.normal;
        let cos_incidence = sun.direction.dot(inward);
        let Some(incident_patch) = self.window.patch_of_arrival(-sun.direction) else {
            return;
        };
        if cos_incidence <= 0.0 || sun.direct_normal_w_m2 <= 0.0 {
            return;
        }
        let irradiance = sun.direct_normal_w_m2 * cos_incidence;
        let lit: Vec<bool> = self
            .sun_view
            .points_m
            .iter()
            .map(|&x| {
                let ray = Ray::new(x + inward * SUN_RAY_OFFSET_M, sun.direction);
                outside.intersect(&ray, None).is_none()
            })
            .collect();
        let lit_share = lit.iter().filter(|&&l| l).count() as f64 / lit.len().max(1) as f64;
        let omega_in = self.window.basis.projected_solid_angle_sr(incident_patch);
        beam[incident_patch] += irradiance * lit_share / omega_in;
        let patches = self.window.basis.len();
        let weights = self.sun_view.lit_patch_weights(&lit, patches);
        for (state, out) in self.states.iter().zip(direct_sun.iter_mut()) {
            let t = &state.transmission;
            for (s, o) in out.iter_mut().enumerate() {
                let through: f64 = (0..patches)
                    .map(|j| weights[s * patches + j] * t.get(j, incident_patch, 0))
                    .sum();
                *o += irradiance * through / omega_in;
            }
        }
    }
}
