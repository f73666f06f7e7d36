//! The three-phase product V T D s, and a window with several states (shading positions,
//! each a BSDF): with V T_k precomputed for every state k, a capture's sky vector s costs one
//! D s, then one (sensors × patches) product per state; a state switch is one product, not a
//! new simulation.

use crate::engine::error::EngineError;
use crate::io::radiance_matrix::RadianceMatrix;

fn shapes_error(what: String) -> EngineError {
    EngineError::Setting {
        name: "matrix shapes",
        value: what,
        expected: "V columns = T rows, T columns = D rows, D columns = sky vector rows",
    }
}

/// V (T (D s)): per sensor and sky column, what `dctimestep V T D s` prints (irradiance,
/// W/m², per component of s; times 179 lm/W for lux).
pub fn three_phase(
    v: &RadianceMatrix,
    t: &RadianceMatrix,
    d: &RadianceMatrix,
    sky: &RadianceMatrix,
) -> Result<RadianceMatrix, EngineError> {
    let ds = d.multiply(sky).ok_or_else(|| {
        shapes_error(format!(
            "D {}x{}x{} and sky {}x{}x{}",
            d.rows, d.cols, d.ncomp, sky.rows, sky.cols, sky.ncomp
        ))
    })?;
    let tds = t.multiply(&ds).ok_or_else(|| {
        shapes_error(format!(
            "T {}x{} and D {}x{}",
            t.rows, t.cols, d.rows, d.cols
        ))
    })?;
    v.multiply(&tds).ok_or_else(|| {
        shapes_error(format!(
            "V {}x{} and T {}x{}",
            v.rows, v.cols, t.rows, t.cols
        ))
    })
}

/// A window's states, precomputed: V T_k per state and the shared D.
#[derive(Debug, Clone)]
pub struct WindowStates {
    /// sensors × patches, grey, row-major, one per state.
    view_transmission: Vec<RadianceMatrix>,
    daylight: RadianceMatrix,
}

impl WindowStates {
    /// From V, one T per state, and D (all one component).
    pub fn new(
        v: &RadianceMatrix,
        states: &[RadianceMatrix],
        d: &RadianceMatrix,
    ) -> Result<Self, EngineError> {
        let grey = |m: &RadianceMatrix| m.ncomp == 1;
        if !grey(v) || !grey(d) || !states.iter().all(grey) {
            return Err(shapes_error("a matrix with colour".into()));
        }
        let view_transmission = states
            .iter()
            .map(|t| {
                if t.rows != v.cols || t.cols != d.rows {
                    return Err(shapes_error(format!(
                        "V {}x{}, T {}x{}, D {}x{}",
                        v.rows, v.cols, t.rows, t.cols, d.rows, d.cols
                    )));
                }
                v.multiply(t)
                    .ok_or_else(|| shapes_error("V and T do not chain".into()))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(WindowStates {
            view_transmission,
            daylight: d.clone(),
        })
    }

    pub fn states(&self) -> usize {
        self.view_transmission.len()
    }

    pub fn sensors(&self) -> usize {
        self.view_transmission.first().map_or(0, |m| m.rows)
    }

    /// D s for a grey sky vector (one value per D column): the radiance arriving per window
    /// patch, shared by every state.
    pub fn window_radiance(&self, sky: &[f64]) -> Result<Vec<f64>, EngineError> {
        let d = &self.daylight;
        if sky.len() != d.cols {
            return Err(shapes_error(format!(
                "sky vector of {} for D's {} columns",
                sky.len(),
                d.cols
            )));
        }
        Ok(d.values
            .chunks_exact(d.cols)
            .map(|row| row.iter().zip(sky).map(|(a, b)| a * b).sum())
            .collect())
    }

    /// The state switch: irradiance per sensor under state `state` for window radiances
    /// `window` (from [`Self::window_radiance`]), into `out`.
    pub fn apply_state(
        &self,
        state: usize,
        window: &[f64],
        out: &mut [f64],
    ) -> Result<(), EngineError> {
        let m = self.view_transmission.get(state).ok_or_else(|| {
            shapes_error(format!("state {state} of {}", self.view_transmission.len()))
        })?;
        if window.len() != m.cols || out.len() != m.rows {
            return Err(shapes_error(format!(
                "{} window radiances and {} outputs for {}x{}",
                window.len(),
                out.len(),
                m.rows,
                m.cols
            )));
        }
        for (o, row) in out.iter_mut().zip(m.values.chunks_exact(m.cols)) {
            *o = row.iter().zip(window).map(|(a, b)| a * b).sum();
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matrix(rows: usize, cols: usize, seed: u64) -> RadianceMatrix {
        let values = (0..rows * cols)
            .map(|k| ((k as u64 * 2_654_435_761 + seed * 97) % 1000) as f64 / 1000.0)
            .collect();
        RadianceMatrix::from_grey(rows, cols, values).unwrap()
    }

    #[test]
    fn a_state_switch_equals_the_full_product() {
        let (v, d) = (matrix(7, 5, 1), matrix(5, 9, 2));
        let states = [matrix(5, 5, 3), matrix(5, 5, 4), matrix(5, 5, 5)];
        let sky = matrix(9, 1, 6);
        let w = WindowStates::new(&v, &states, &d).unwrap();
        assert_eq!((w.states(), w.sensors()), (3, 7));
        let window = w.window_radiance(&sky.values).unwrap();
        let mut out = vec![0.0; 7];
        for (k, t) in states.iter().enumerate() {
            w.apply_state(k, &window, &mut out).unwrap();
            let full = three_phase(&v, t, &d, &sky).unwrap();
            for (a, b) in out.iter().zip(&full.values) {
                assert!((a - b).abs() <= 1e-12 * b.abs(), "state {k}: {a} vs {b}");
            }
        }
        // Wrong sizes and an unknown state are errors, not panics.
        assert!(w.window_radiance(&sky.values[1..]).is_err());
        assert!(w.apply_state(3, &window, &mut out).is_err());
        assert!(w.apply_state(0, &window[1..], &mut out).is_err());
        assert!(WindowStates::new(&v, &[matrix(4, 5, 7)], &d).is_err());
        assert!(three_phase(&v, &states[0], &d, &matrix(8, 1, 8)).is_err());
    }
}
