//! The box room of the BSDF window tests: 4 m × 5 m × 3 m, one south window glazed with a
//! modifier named `window_bsdf`, shared by `bsdf_windows_vs_rtrace` and `shading_states`.
#![allow(dead_code)]

use std::path::Path;

/// A 4 m × 5 m × 3 m room, the window (x 1..3 m, z 0.9..2.1 m) in its south wall (y = 0)
/// with its normal into the room (RADIANCE's convention for WINDOW data), up +z.
pub fn box_room(xml: &Path) -> String {
    box_room_with(&format!(
        "void BSDF window_bsdf\n6 0 {} 0 0 1 .\n0\n0\n",
        xml.display()
    ))
}

/// [`box_room`] with the window's material `declaration` (a modifier named `window_bsdf`).
pub fn box_room_with(declaration: &str) -> String {
    let mut s = format!(
        "{declaration}\
         void plastic wall 0 0 5 0.5 0.5 0.5 0 0\n\
         void plastic floor 0 0 5 0.2 0.2 0.2 0 0\n\
         void plastic ceiling 0 0 5 0.7 0.7 0.7 0 0\n\
         window_bsdf polygon window 0 0 12 1 0 0.9 1 0 2.1 3 0 2.1 3 0 0.9\n"
    );
    let quads: [(&str, &str, [[f64; 3]; 4]); 9] = [
        (
            "floor",
            "floor",
            [[0., 0., 0.], [4., 0., 0.], [4., 5., 0.], [0., 5., 0.]],
        ),
        (
            "ceiling",
            "ceiling",
            [[0., 0., 3.], [0., 5., 3.], [4., 5., 3.], [4., 0., 3.]],
        ),
        (
            "wall",
            "east",
            [[4., 0., 0.], [4., 0., 3.], [4., 5., 3.], [4., 5., 0.]],
        ),
        (
            "wall",
            "west",
            [[0., 0., 0.], [0., 5., 0.], [0., 5., 3.], [0., 0., 3.]],
        ),
        (
            "wall",
            "north",
            [[0., 5., 0.], [4., 5., 0.], [4., 5., 3.], [0., 5., 3.]],
        ),
        (
            "wall",
            "south_low",
            [[0., 0., 0.], [0., 0., 0.9], [4., 0., 0.9], [4., 0., 0.]],
        ),
        (
            "wall",
            "south_high",
            [[0., 0., 2.1], [0., 0., 3.], [4., 0., 3.], [4., 0., 2.1]],
        ),
        (
            "wall",
            "south_west",
            [[0., 0., 0.9], [0., 0., 2.1], [1., 0., 2.1], [1., 0., 0.9]],
        ),
        (
            "wall",
            "south_east",
            [[3., 0., 0.9], [3., 0., 2.1], [4., 0., 2.1], [4., 0., 0.9]],
        ),
    ];
    for (material, name, corners) in quads {
        s.push_str(&format!("{material} polygon {name} 0 0 12"));
        for c in corners {
            s.push_str(&format!(" {} {} {}", c[0], c[1], c[2]));
        }
        s.push('\n');
    }
    s
}

/// Workplane sensors (0.8 m, facing up) from the window to the back, in and out of the
/// sun patches of the two sunny skies.
pub const BOX_SENSORS: &str = "\
1.5 0.8 0.8 0 0 1
2.5 1.5 0.8 0 0 1
2.0 2.5 0.8 0 0 1
1.0 3.5 0.8 0 0 1
3.0 4.2 0.8 0 0 1
2.0 1.0 0.8 0 0 1
";
