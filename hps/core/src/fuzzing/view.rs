//! RADIANCE view options and view files (`.vf`, `-vf`, a picture header's `VIEW=`).

use crate::engine::render::view::View;
use std::path::Path;

/// The bytes as a view file, then their first line as a view option string; every view
/// read is prepared and, when valid, sampled at the centre, the corners and outside.
pub(super) fn view(bytes: &[u8]) {
    let label = Path::new("fuzz.vf");
    let from_file = View::default().with_file_bytes(label, bytes);
    if let Err(e) = &from_file {
        super::checks::assert_names(&e.to_string(), "fuzz.vf");
    }
    let text = super::checks::text(bytes);
    let first_line = text.lines().next().unwrap_or("");
    for view in [from_file.ok(), View::parse(first_line).ok()]
        .into_iter()
        .flatten()
    {
        let _ = view.to_radiance_string();
        if let Ok(prepared) = view.prepare() {
            let (x, y) = prepared.fit_resolution(512, 512);
            assert!(x <= 512 && y <= 512, "{x} x {y} for 512 x 512");
            for (u, v) in [(0.5, 0.5), (0.0, 0.0), (1.0, 1.0), (-3.0, 7.0)] {
                if let Some(ray) = prepared.ray(u, v) {
                    assert!(ray.direction.is_finite(), "{ray:?} at ({u}, {v})");
                }
            }
        }
    }
}
