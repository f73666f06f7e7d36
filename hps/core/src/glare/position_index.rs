//! The position index P: how much less a source glares the farther it lies from the line of
//! sight, as evalglare computes it (its default `-P 0`).

use glam::DVec3;

/// evalglare's cap on the position index.
const MAX_POSITION_INDEX: f64 = 16.0;

/// Position index of a source seen in unit direction `direction`, for the unit view direction
/// and up vector.
///
/// Above the line of sight: Guth's index in the IES Lighting Handbook's closed form (Levin,
/// "Position index in VCP calculations", JIES 1975), with σ the angle from the line of sight
/// and τ the angle of the source's plane from vertical, both in degrees:
/// P = exp[(35.2 − 0.31889 τ − 1.22 e^(−2τ/9)) 10⁻³ σ + (21 + 0.26667 τ − 0.002963 τ²) 10⁻⁵ σ²].
/// Below it: Iwata's index (CIE 146/147:2002, in Kikuchi's coordinates as evalglare uses it):
/// β = atan(tan σ √(1 + 0.3225 cos² τ)), P = exp(6.49 10⁻³ β + 21 10⁻⁵ β²).
/// Both are capped at 16, as evalglare does.
pub fn position_index(direction: DVec3, view_direction: DVec3, view_up: DVec3) -> f64 {
    let cos_sigma = direction.dot(view_direction).clamp(-1.0, 1.0);
    let sigma_deg = cos_sigma.acos().to_degrees();
    // The source's direction projected on the plane normal to the line of sight.
    let across = (direction - cos_sigma * view_direction)
        .try_normalize()
        .unwrap_or(DVec3::ZERO);
    let tau_deg = view_up.dot(across).clamp(-1.0, 1.0).acos().to_degrees();
    // evalglare's `phi < 0`: the direction lies below the plane through the line of sight
    // and the horizontal image axis (vv = vdir × (vdir × vup) points down).
    let down = view_direction * view_direction.dot(view_up) - view_up;
    let index = if down.dot(direction) > 0.0 {
        let beta_deg = (sigma_deg.to_radians().tan()
            * (1.0 + 0.3225 * tau_deg.to_radians().cos().powi(2)).sqrt())
        .atan()
        .to_degrees();
        (6.49e-3 * beta_deg + 21.0e-5 * beta_deg * beta_deg).exp()
    } else {
        ((35.2 - 0.31889 * tau_deg - 1.22 * (-2.0 * tau_deg / 9.0).exp()) * 1e-3 * sigma_deg
            + (21.0 + 0.26667 * tau_deg - 0.002963 * tau_deg * tau_deg)
                * 1e-5
                * sigma_deg
                * sigma_deg)
            .exp()
    };
    index.min(MAX_POSITION_INDEX)
}
