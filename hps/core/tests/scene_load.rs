//! The RADIANCE scene reader: the reference room and its sensors load with the facts that can
//! be read off the files, a gensky sky and the output of genbox, genrev and obj2rad load
//! unchanged, every error class names the file, the line and the field, and a 10,000-polygon
//! scene loads quickly.

use glam::DVec3;
use skylux_hps::scene::{
    self, load_sensors, ModifierKind, ModifierRef, Scene, SceneError, SensorsError, Shape,
};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The shared reference room, from the crate folder (`hps/core`) up to the workspace's parent.
fn test_module(file: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/scenes/test-module");
    assert!(
        dir.is_dir(),
        "the shared reference room is missing: expected the folder {} (the `shared` folder \
         beside the workspace, holding scenes/test-module/scene.rad, sensors.pts and grid400.pts)",
        dir.display()
    );
    dir.join(file)
}

fn polygon(scene: &Scene, name: &str) -> skylux_hps::scene::Polygon {
    let surface = scene
        .surfaces()
        .iter()
        .find(|s| s.name == name)
        .unwrap_or_else(|| panic!("no surface `{name}`"));
    match &surface.shape {
        Shape::Polygon(p) => p.clone(),
        other => panic!("`{name}` is a {}", other.type_name()),
    }
}

fn material_name<'a>(scene: &'a Scene, surface: &skylux_hps::scene::Surface) -> &'a str {
    &scene.material(surface.modifier).expect("a material").name
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-12
}

#[test]
fn reference_room_loads_with_the_facts_of_its_file() {
    let path = test_module("scene.rad");
    let scene = scene::load(&path).unwrap();

    // Six materials: five plastics and the glazing.
    let types: Vec<_> = scene
        .modifiers()
        .iter()
        .map(|m| m.kind.type_name())
        .collect();
    assert_eq!(
        types,
        ["plastic", "plastic", "plastic", "plastic", "plastic", "glass"]
    );
    let plastic_reflectance = |name: &str| match scene.modifier_named(name) {
        Some(ModifierRef::Defined(id)) => match &scene.modifier(id).unwrap().kind {
            ModifierKind::Plastic(p) => {
                assert_eq!((p.specularity, p.roughness), (0.0, 0.0), "{name}");
                p.reflectance_rgb
            }
            other => panic!("{name}: {other:?}"),
        },
        other => panic!("{name}: {other:?}"),
    };
    assert_eq!(plastic_reflectance("ceiling_mat"), DVec3::splat(0.8));
    assert_eq!(plastic_reflectance("wall_mat"), DVec3::splat(0.5));
    assert_eq!(plastic_reflectance("floor_mat"), DVec3::splat(0.2));
    assert_eq!(plastic_reflectance("frame_mat"), DVec3::splat(0.5));
    assert_eq!(plastic_reflectance("desk_mat"), DVec3::splat(0.4));
    let Some(ModifierRef::Defined(glazing)) = scene.modifier_named("glazing_mat") else {
        panic!("no glazing_mat")
    };
    match &scene.modifier(glazing).unwrap().kind {
        ModifierKind::Glass(g) => {
            assert_eq!(g.transmissivity_rgb, DVec3::splat(0.708456));
            assert_eq!(g.refractive_index, 1.52);
        }
        other => panic!("glazing_mat: {other:?}"),
    }

    // 44 polygons and nothing else; per material as the file assigns them.
    assert_eq!(scene.surfaces().len(), 44);
    assert!(scene
        .surfaces()
        .iter()
        .all(|s| matches!(s.shape, Shape::Polygon(_))));
    let count = |mat: &str| {
        scene
            .surfaces()
            .iter()
            .filter(|s| material_name(&scene, s) == mat)
            .count()
    };
    assert_eq!(count("floor_mat"), 1);
    assert_eq!(count("ceiling_mat"), 1);
    assert_eq!(count("wall_mat"), 7); // 3 walls, 4 façade pieces around the panes
    assert_eq!(count("frame_mat"), 9); // 4 frame sides, 2 mullions, 3 transoms
    assert_eq!(count("glazing_mat"), 6);
    assert_eq!(count("desk_mat"), 20); // 4 desks of 5 faces

    // A known vertex and the line the pane starts on.
    let pane1 = polygon(&scene, "pane1");
    assert_eq!(pane1.vertices_m.len(), 4);
    assert_eq!(pane1.vertices_m[2], DVec3::new(0.976667, 0.0, 1.4425));
    let text = std::fs::read_to_string(&path).unwrap();
    let pane1_line = 1 + text
        .lines()
        .position(|l| l == "glazing_mat polygon pane1")
        .unwrap();
    let pane1_surface = scene.surfaces().iter().find(|s| s.name == "pane1").unwrap();
    assert_eq!(pane1_surface.origin.line, pane1_line);
    assert_eq!(&*pane1_surface.origin.file, path.as_path());

    // Orientation and areas: the floor faces up, the ceiling down, the panes into the room;
    // the README's glazed area is 4.6748 m².
    assert!(close(polygon(&scene, "floor").normal, DVec3::Z));
    assert!(close(polygon(&scene, "ceiling").normal, -DVec3::Z));
    assert!((polygon(&scene, "floor").area_m2 - 2.9 * 6.4).abs() < 1e-9);
    let glazed_m2: f64 = (1..=6)
        .map(|i| {
            let pane = polygon(&scene, &format!("pane{i}"));
            assert!(close(pane.normal, DVec3::Y), "pane{i}: {}", pane.normal);
            pane.area_m2
        })
        .sum();
    assert!((glazed_m2 - 4.6748).abs() < 5e-4, "{glazed_m2}");
}

#[test]
fn reference_sensors_load_in_line_order() {
    let sensors = load_sensors(test_module("sensors.pts")).unwrap();
    assert_eq!(sensors.len(), 5);
    for (i, (s, y)) in sensors.iter().zip([1.0, 2.0, 3.0, 3.9, 4.7]).enumerate() {
        assert_eq!(s.name, format!("S{}", i + 1));
        assert_eq!(s.position_m, DVec3::new(1.45, y, 0.8));
        assert_eq!(s.direction, DVec3::Z);
        assert_eq!(s.origin.line, i + 1);
    }

    let grid = load_sensors(test_module("grid400.pts")).unwrap();
    assert_eq!(grid.len(), 400);
    assert_eq!(grid[399].name, "S400");
    // Row-major, y outer: x = (i + 0.5) 2.9/20, y = (j + 0.5) 6.4/20 (README).
    for (k, s) in grid.iter().enumerate() {
        let (i, j) = ((k % 20) as f64, (k / 20) as f64);
        let expected = DVec3::new((i + 0.5) * 2.9 / 20.0, (j + 0.5) * 6.4 / 20.0, 0.8);
        assert!(
            (s.position_m - expected).length() < 1e-9,
            "{}: {}",
            s.name,
            s.position_m
        );
        assert_eq!(s.direction, DVec3::Z);
    }
}

/// As `gensky 3 21 12 +s` prints it, followed by the usual sky and ground glow hemispheres.
const GENSKY: &str = "\
# gensky 3 21 12 +s
# Local solar time: 12.00
# Solar altitude and azimuth: 51.5 -0.0
# Ground ambient level: 17.4

void light solar
0
0
3 6.46e+06 6.46e+06 6.46e+06

solar source sun
0
0
4 0.000000 -0.622515 0.782608 0.5

void brightfunc skyfunc
2 skybright skybright.cal
0
7 1 1.34e+01 2.73e+01 2.00e-01 0.000000 -0.622515 0.782608

skyfunc glow skyglow
0
0
4 0.9 0.9 1.15 0

skyglow source sky
0
0
4 0 0 1 180

skyfunc glow groundglow
0
0
4 1.4 0.9 0.6 0

groundglow source ground
0
0
4 0 0 -1 180
";

#[test]
fn gensky_sky_loads_after_the_room() {
    let dir = tempfile::tempdir().unwrap();
    let sky_path = dir.path().join("sky.rad");
    std::fs::write(&sky_path, GENSKY).unwrap();
    let room = test_module("scene.rad");
    let scene = scene::load_files(&[room.as_path(), sky_path.as_path()]).unwrap();

    assert_eq!(scene.modifiers().len(), 6 + 4);
    assert_eq!(scene.surfaces().len(), 44 + 3);
    let sources: Vec<_> = scene
        .surfaces()
        .iter()
        .filter_map(|s| match &s.shape {
            Shape::Source(src) => Some((s, src)),
            _ => None,
        })
        .collect();
    let names: Vec<_> = sources.iter().map(|(s, _)| s.name.as_str()).collect();
    assert_eq!(names, ["sun", "sky", "ground"]);

    let (sun, sun_source) = sources[0];
    assert_eq!(sun.origin.line, 11);
    assert_eq!(&*sun.origin.file, sky_path.as_path());
    assert_eq!(sun_source.angle_deg, 0.5);
    assert!((sun_source.direction.length() - 1.0).abs() < 1e-12);
    let given = DVec3::new(0.0, -0.622515, 0.782608);
    assert!((sun_source.direction - given.normalize()).length() < 1e-12);
    match &scene.material(sun.modifier).unwrap().kind {
        ModifierKind::Light(l) => assert_eq!(l.radiance_w_sr_m2, DVec3::splat(6.46e6)),
        other => panic!("{other:?}"),
    }

    // The sky: a glow modified by the brightfunc pattern.
    let (sky, sky_source) = sources[1];
    assert_eq!(sky_source.direction, DVec3::Z);
    assert_eq!(sky_source.angle_deg, 180.0);
    let skyglow = scene.material(sky.modifier).unwrap();
    assert_eq!(skyglow.name, "skyglow");
    match &skyglow.kind {
        ModifierKind::Glow(g) => {
            assert_eq!(g.radiance_w_sr_m2, DVec3::new(0.9, 0.9, 1.15));
            assert_eq!(g.max_radius_m, 0.0);
        }
        other => panic!("{other:?}"),
    }
    let ModifierRef::Defined(skyfunc) = skyglow.modifier else {
        panic!("skyglow has no pattern")
    };
    match &scene.modifier(skyfunc).unwrap().kind {
        ModifierKind::Brightfunc(f) => {
            assert_eq!(f.function_name, "skybright");
            assert_eq!(f.cal_file, "skybright.cal");
            assert!(f.transform.is_empty());
            assert_eq!(
                f.real_args,
                [1.0, 13.4, 27.3, 0.2, 0.0, -0.622515, 0.782608]
            );
        }
        other => panic!("{other:?}"),
    }
    let (ground, ground_source) = sources[2];
    assert_eq!(ground_source.direction, -DVec3::Z);
    assert_eq!(scene.material(ground.modifier).unwrap().name, "groundglow");
}

#[test]
fn gendaylit_perez_sky_with_a_transform_loads() {
    let text = "\
void light solar 0 0 3 6.9e+06 6.9e+06 6.9e+06
solar source sun 0 0 4 0.1 -0.6 0.79 0.533
void brightfunc skyfunc
4 perezlum perezlum.cal -rz 90
0
10 2.1e+01 1.9e+01 -1.0 -0.32 10.1 -3.0 0.45 0.1 -0.6 0.79
skyfunc glow sky_glow 0 0 4 1 1 1 0
sky_glow source sky 0 0 4 0 0 1 180
";
    let scene = scene::parse("perez.rad", text.as_bytes()).unwrap();
    let ModifierKind::Brightfunc(f) = &scene.modifiers()[1].kind else {
        panic!("not a brightfunc")
    };
    assert_eq!(f.cal_file, "perezlum.cal");
    assert_eq!(f.transform, ["-rz", "90"]);
    assert_eq!(f.real_args.len(), 10);
    assert_eq!(scene.modifiers()[1].origin.line, 3);
}

/// What `genbox mat name x y z [-i] [-b bevel | -r round]` prints (RADIANCE src/gen/genbox.c).
fn genbox(mat: &str, name: &str, size: [f64; 3], bevel: f64, round: bool, reverse: bool) -> String {
    const LET: &[u8] = b"0123456789._ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
    // As genbox's vertex(): bit i picks the far side on axis i, and bit i + 3 says whether
    // that coordinate is pulled in by the bevel.
    let vertex = |mut v: usize| {
        let mut s = String::new();
        for axis_size in size {
            let value = match (v & 0o10 != 0, v & 1 != 0) {
                (true, true) => axis_size - bevel,
                (true, false) => bevel,
                (false, true) => axis_size,
                (false, false) => 0.0,
            };
            s += &format!("\t{value:>18}");
            v >>= 1;
        }
        s + "\n"
    };
    let face = |corners: &[usize]| {
        let mut s = format!("\n{mat} polygon {name}.");
        for &c in corners {
            s.push(char::from(LET[c]));
        }
        s += &format!("\n0\n0\n{}\n", 3 * corners.len());
        let mut order: Vec<usize> = corners.to_vec();
        if reverse {
            order.reverse();
        }
        for c in order {
            s += &vertex(c);
        }
        s
    };
    let mut out = format!(
        "# genbox {mat} {name} {} {} {}\n",
        size[0], size[1], size[2]
    );
    if bevel > 0.0 {
        for f in [
            [0o51, 0o55, 0o54, 0o50],
            [0o64, 0o66, 0o62, 0o60],
            [0o32, 0o33, 0o31, 0o30],
            [0o53, 0o52, 0o56, 0o57],
            [0o65, 0o61, 0o63, 0o67],
            [0o36, 0o34, 0o35, 0o37],
        ] {
            out += &face(&f);
        }
    }
    if bevel > 0.0 && !round {
        for f in [
            [0o31, 0o51, 0o50, 0o30],
            [0o60, 0o62, 0o32, 0o30],
            [0o50, 0o54, 0o64, 0o60],
            [0o34, 0o36, 0o66, 0o64],
            [0o37, 0o57, 0o56, 0o36],
            [0o52, 0o62, 0o66, 0o56],
            [0o52, 0o53, 0o33, 0o32],
            [0o57, 0o67, 0o63, 0o53],
            [0o61, 0o31, 0o33, 0o63],
            [0o65, 0o67, 0o37, 0o35],
            [0o55, 0o51, 0o61, 0o65],
            [0o34, 0o54, 0o55, 0o35],
        ] {
            out += &face(&f);
        }
        for c in [
            [0o30, 0o50, 0o60],
            [0o51, 0o31, 0o61],
            [0o32, 0o62, 0o52],
            [0o64, 0o54, 0o34],
            [0o36, 0o56, 0o66],
            [0o65, 0o35, 0o55],
            [0o53, 0o63, 0o33],
            [0o37, 0o67, 0o57],
        ] {
            out += &face(&c);
        }
    }
    if bevel > 0.0 && round {
        for (a, b) in [
            (0o70, 0o71),
            (0o70, 0o74),
            (0o70, 0o72),
            (0o73, 0o71),
            (0o73, 0o72),
            (0o73, 0o77),
            (0o75, 0o71),
            (0o75, 0o74),
            (0o75, 0o77),
            (0o76, 0o72),
            (0o76, 0o74),
            (0o76, 0o77),
        ] {
            out += &format!("\n{mat} cylinder {name}.{}{}\n0\n0\n7\n", a + 48, b + 48);
            out += &vertex(a);
            out += &vertex(b);
            out += &format!("\t{bevel:>18}\n");
        }
        for v in 0o70..=0o77 {
            out += &format!("\n{mat} sphere {name}.{}\n0\n0\n4\n", v + 48);
            out += &vertex(v);
            out += &format!("\t{bevel:>18}\n");
        }
    }
    if bevel == 0.0 {
        for f in [
            [1, 5, 4, 0],
            [4, 6, 2, 0],
            [2, 3, 1, 0],
            [3, 2, 6, 7],
            [5, 1, 3, 7],
            [6, 4, 5, 7],
        ] {
            out += &face(&f);
        }
    }
    out
}

const BOX_MATERIAL: &str = "void plastic box_mat 0 0 5 .5 .5 .5 0 0\n";

fn load_generated(generated: &str) -> Result<Scene, SceneError> {
    let mut scene = scene::parse("materials.rad", BOX_MATERIAL.as_bytes())?;
    scene.add_bytes("generated.rad", generated.as_bytes())?;
    Ok(scene)
}

/// How many polygons face away from `centre` (normal towards their own centroid's side).
fn outward_polygons(scene: &Scene, centre: DVec3) -> usize {
    scene
        .surfaces()
        .iter()
        .filter(|s| match &s.shape {
            Shape::Polygon(p) => {
                let c = p.vertices_m.iter().copied().sum::<DVec3>() / p.vertices_m.len() as f64;
                p.normal.dot(c - centre) > 0.0
            }
            _ => false,
        })
        .count()
}

#[test]
fn genbox_output_loads_with_outward_faces() {
    let size = [1.0, 2.0, 3.0];
    let centre = DVec3::new(0.5, 1.0, 1.5);

    let plain = load_generated(&genbox("box_mat", "box", size, 0.0, false, false)).unwrap();
    assert_eq!(plain.surfaces().len(), 6);
    assert_eq!(outward_polygons(&plain, centre), 6);
    let area: f64 = plain
        .surfaces()
        .iter()
        .map(|s| match &s.shape {
            Shape::Polygon(p) => p.area_m2,
            _ => 0.0,
        })
        .sum();
    assert!((area - 2.0 * (1.0 * 2.0 + 2.0 * 3.0 + 1.0 * 3.0)).abs() < 1e-12);
    assert_eq!(plain.surfaces()[0].name, "box.1540");
    assert_eq!(plain.surfaces()[0].origin.line, 3);

    let inverted = load_generated(&genbox("box_mat", "box", size, 0.0, false, true)).unwrap();
    assert_eq!(inverted.surfaces().len(), 6);
    assert_eq!(outward_polygons(&inverted, centre), 0);

    let bevelled = load_generated(&genbox("box_mat", "box", size, 0.1, false, false)).unwrap();
    assert_eq!(bevelled.surfaces().len(), 6 + 12 + 8);
    assert_eq!(outward_polygons(&bevelled, centre), 6 + 12 + 8);

    let rounded = load_generated(&genbox("box_mat", "box", size, 0.1, true, false)).unwrap();
    let kinds = |kind: &str| {
        rounded
            .surfaces()
            .iter()
            .filter(|s| s.shape.type_name() == kind)
            .count()
    };
    assert_eq!(
        (kinds("polygon"), kinds("cylinder"), kinds("sphere")),
        (6, 12, 8)
    );
}

#[test]
fn genrev_output_loads_with_its_inverted_pieces() {
    // `genrev box_mat lamp 'if(t-.5,...)' ... 3`: a disc, a cylinder and a cone to a point,
    // as genrev.c prints them (%15.9g fields).
    let lamp = "\
# genrev box_mat lamp z(t) r(t) 3

box_mat ring lamp.1
0
0
8
\t0\t0\t              0
\t0\t0\t             -1
\t              0\t            0.3

box_mat cylinder lamp.2
0
0
7
\t0\t0\t              0
\t0\t0\t            0.5
\t            0.3

box_mat cone lamp.3
0
0
8
\t0\t0\t            0.5
\t0\t0\t            0.8
\t            0.3\t              0
";
    let scene = load_generated(lamp).unwrap();
    let kinds: Vec<_> = scene
        .surfaces()
        .iter()
        .map(|s| s.shape.type_name())
        .collect();
    assert_eq!(kinds, ["ring", "cylinder", "cone"]);
    match &scene.surfaces()[0].shape {
        Shape::Ring(r) => {
            assert_eq!(r.normal, -DVec3::Z);
            assert_eq!((r.inner_radius_m, r.outer_radius_m), (0.0, 0.3));
        }
        other => panic!("{other:?}"),
    }
    match &scene.surfaces()[2].shape {
        Shape::Cone(c) => assert_eq!((c.start_radius_m, c.end_radius_m), (0.3, 0.0)),
        other => panic!("{other:?}"),
    }

    // With z decreasing genrev writes inward-facing `cup`s and `tube`s: read as such (issue 19).
    let inverted = lamp.replace("box_mat cone lamp.3", "box_mat cup lamp.3");
    let scene = load_generated(&inverted).unwrap();
    match &scene.surfaces()[2].shape {
        Shape::Cup(c) => assert_eq!((c.start_radius_m, c.end_radius_m), (0.3, 0.0)),
        other => panic!("{other:?}"),
    }
}

#[test]
fn obj2rad_output_loads_and_its_commands_are_refused() {
    let obj = "\
# Wavefront .OBJ file converted by obj2rad
# Object: part

box_mat polygon part.1
0
0
9
\t        0 \t        0 \t        0
\t        1 \t        0 \t        0
\t        0 \t        1 \t        0

box_mat polygon part.2
0
0
12
\t        1 \t        0 \t        0
\t        2 \t        0 \t        0
\t        2 \t        1 \t        0
\t        1 \t        1 \t        0
";
    let scene = load_generated(obj).unwrap();
    assert_eq!(scene.surfaces().len(), 2);
    assert_eq!(scene.surfaces()[1].origin.line, 12);

    // The command is expanded now (issue 19); the file it names is not there.
    let with_command = format!("{obj}\n!xform -rz 90 -t 1 0 0 part.rad\n");
    let err = load_generated(&with_command).unwrap_err();
    assert!(matches!(err, SceneError::MissingInclude { .. }), "{err}");
    let text = err.to_string();
    assert!(text.starts_with("generated.rad:21:"), "{text}");
    assert!(text.contains("!xform -rz 90 -t 1 0 0 part.rad"), "{text}");

    // Smoothed obj2rad output carries `texfunc` normals: read (issue 19), with its
    // expressions and function file for the engine to compile.
    let smoothed = format!(
        "void texfunc part.n\n4 dx dy dz tmesh.cal\n0\n0\n{}",
        obj.replace("box_mat polygon part.1", "part.n polygon part.1")
    );
    let scene = load_generated(&smoothed).unwrap();
    match &scene.modifiers()[1].kind {
        scene::ModifierKind::Texfunc(f) => {
            assert_eq!(f.expressions, ["dx", "dy", "dz"]);
            assert_eq!(f.cal_file, "tmesh.cal");
        }
        other => panic!("a texfunc, not {other:?}"),
    }
}

/// Parses `text` as `case.rad` and returns the error message, which must start with the file
/// and `line` and contain every fragment.
fn assert_error(text: &str, line: usize, fragments: &[&str]) {
    let err = match scene::parse("case.rad", text.as_bytes()) {
        Ok(_) => panic!("no error for:\n{text}"),
        Err(e) => e,
    };
    assert_eq!(err.location().map(|l| l.line), Some(line), "{err}");
    let message = err.to_string();
    assert!(
        message.starts_with(&format!("case.rad:{line}: ")),
        "{message}"
    );
    for fragment in fragments {
        assert!(message.contains(fragment), "`{fragment}` not in: {message}");
    }
}

const MAT: &str = "# material\nvoid plastic m 0 0 5 .5 .5 .5 0 0\n";

#[test]
fn commands_and_unsupported_types_are_errors_with_file_and_line() {
    assert_error(
        &format!("{MAT}\n!xform -rz 90 box.rad\n"),
        4,
        &["`!xform -rz 90 box.rad`", "cannot read box.rad"],
    );
    assert_error(
        &format!("{MAT}!genclock m w 0 0 t 0.1 8\n"),
        3,
        &[
            "`!genclock m w 0 0 t 0.1 8`",
            "`genclock` is not a command",
            "--allow-commands",
        ],
    );
    // The generators that read .cal text: a missing file, a bad count, a syntax error.
    assert_error(
        &format!("{MAT}!gensurf m s s t 0 2 2 -f missing.cal\n"),
        3,
        &["`!gensurf", "cannot find file `missing.cal`"],
    );
    assert_error(
        &format!("{MAT}!genworm m w t 0 0 0.1 0\n"),
        3,
        &["`!genworm", "nseg is `0`", "expected 1 to"],
    );
    assert_error(
        &format!("{MAT}!gensurf m s s t 'a+' 2 2\n"),
        3,
        &["`!gensurf", "z(s,t) `a+`"],
    );
    assert_error(
        &format!("{MAT}!gensurf m s s t 0 1000 1000\n"),
        3,
        &["`!gensurf", "1000 x 1000 cells: more than 250000"],
    );
    assert_error(
        &format!("{MAT}!genrev m r t 'u(t)' 4\n"),
        3,
        &["`!genrev", "u: undefined function"],
    );
    assert_error(
        &format!("{MAT}m prism1 b 0 0 4 0 0 0 1\n"),
        3,
        &["`prism1`", "`b`", "outside the subset"],
    );
    assert_error(
        &format!("{MAT}void alias m2 nothing\n"),
        3,
        &["alias `m2`", "`nothing`"],
    );
    assert_error(
        &format!("{MAT}\n\nm polgon p 0 0 9 0 0 0 1 0 0 0 1 0\n"),
        5,
        &["`polgon`", "not a RADIANCE primitive type"],
    );
}

#[test]
fn unknown_modifiers_are_errors_with_file_and_line() {
    assert_error(
        "void plastic m 0 0 5 .5 .5 .5 0 0\nn polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n",
        2,
        &[
            "polygon `p`: modifier `n` is not defined",
            "defined earlier",
        ],
    );
    // Defined after use: RADIANCE semantics, still unknown at the point of use.
    assert_error(
        "m polygon p 0 0 9 0 0 0 1 0 0 0 1 0\nvoid plastic m 0 0 5 .5 .5 .5 0 0\n",
        1,
        &["modifier `m` is not defined"],
    );
    assert_error(
        &format!("{MAT}void mirror mi 1 nothing 0 3 .9 .9 .9\n"),
        3,
        &["mirror `mi`: string argument 1 (alternate material) `nothing` is not defined"],
    );
}

#[test]
fn argument_count_errors_name_the_list_and_what_was_expected() {
    assert_error(
        "void plastic m 0 0 4 .5 .5 .5 0\n",
        1,
        &[
            "plastic `m`",
            "found 4 real arguments",
            "5 (red green blue spec rough)",
        ],
    );
    assert_error(
        "void plastic m 1 x 0 5 .5 .5 .5 0 0\n",
        1,
        &["found 1 string arguments", "expected 0"],
    );
    assert_error(
        "void plastic m 0 1 7 5 .5 .5 .5 0 0\n",
        1,
        &["found 1 integer arguments"],
    );
    assert_error(
        "void glass g 0 0 5 .9 .9 .9 1.5 0\n",
        1,
        &["glass `g`", "3 or 4 (rtn gtn btn [n])"],
    );
    assert_error(
        "void trans t 0 0 5 .5 .5 .5 0 0\n",
        1,
        &["7 (red green blue spec rough trans tspec)"],
    );
    assert_error(
        "void brightfunc f 1 skybright 0 0\n",
        1,
        &[
            "brightfunc `f`",
            "at least 2 (refname funcfile [transform])",
        ],
    );
    assert_error(
        &format!("{MAT}m sphere s 0 0 3 0 0 0\n"),
        3,
        &["sphere `s`", "4 (xcent ycent zcent radius)"],
    );
    assert_error(
        &format!("{MAT}m polygon p 0 0 10 0 0 0 1 0 0 0 1 0 5\n"),
        3,
        &["found 10 real arguments", "multiple of 3"],
    );
}

#[test]
fn malformed_numbers_are_errors_naming_the_field() {
    assert_error(
        "void plastic m\n0\n0\n5 .5 abc .5 0 0\n",
        4,
        &[
            "plastic `m`",
            "real argument 2 (green) is `abc`",
            "expected a number",
        ],
    );
    assert_error(
        &format!("{MAT}m polygon p\n0\n0\n9\n0 0 0\n1 NaN 0\n0 1 0\n"),
        8,
        &["real argument 5 (vertex 2 y) is `NaN`", "finite"],
    );
    assert_error(
        &format!("{MAT}m sphere s 0 0 4 0 0 inf 1\n"),
        3,
        &["(zcent) is `inf`", "finite"],
    );
    assert_error(
        &format!("{MAT}m sphere s 0 0 4 0 0 1e999 1\n"),
        3,
        &["`1e999`", "finite"],
    );
    assert_error(
        "void plastic m 0 0 five .5 .5 .5 0 0\n",
        1,
        &["real argument count is `five`", "non-negative integer"],
    );
    assert_error(
        "void plastic m -1 0 5 .5 .5 .5 0 0\n",
        1,
        &["string argument count is `-1`"],
    );
    assert_error(
        "void plastic m 0 1 2.5 5 .5 .5 .5 0 0\n",
        1,
        &["integer argument 1 is `2.5`"],
    );
}

#[test]
fn truncated_files_name_the_primitive_and_what_is_missing() {
    assert_error(
        "void plastic m\n0\n0\n5 .5 .5 .5\n\n",
        4,
        &[
            "file ends inside the real arguments of plastic `m` (which starts on line 1)",
            "real argument 4 (spec) of 5",
        ],
    );
    assert_error(
        "void plastic\n",
        1,
        &["after `void plastic`", "an identifier"],
    );
    assert_error(
        "void \"plastic m 0 0 5 1 1 1 0 0\n",
        1,
        &["never closed", "closing \""],
    );
}

#[test]
fn geometry_errors_name_the_field_and_what_was_expected() {
    assert_error(
        &format!("{MAT}m polygon p 0 0 6 0 0 0 1 0 0\n"),
        3,
        &["polygon `p`", "degenerate polygon", "2 vertices"],
    );
    assert_error(
        &format!("{MAT}m polygon p 0 0 9 0 0 0 1 1 0 2 2 0\n"),
        3,
        &["degenerate polygon", "collinear"],
    );
    assert_error(
        &format!("{MAT}m polygon p 0 0 12 0 0 0 1 1 0 1 0 0 0 1 0\n"),
        3,
        &["degenerate polygon", "zero area"],
    );
    assert_error(
        &format!("{MAT}m sphere s 0 0 4 0 0 0 -0.5\n"),
        3,
        &[
            "sphere `s`",
            "real argument 4 (radius) is -0.5",
            "radius > 0",
            "bubble",
        ],
    );
    assert_error(
        &format!("{MAT}m cylinder c 0 0 7 0 0 0 0 0 1 -0.1\n"),
        3,
        &["cylinder `c`", "(rad) is -0.1"],
    );
    assert_error(
        &format!("{MAT}m cylinder c 0 0 7 1 1 1 1 1 1 0.1\n"),
        3,
        &["cylinder `c`", "axis", "length 0 m"],
    );
    assert_error(
        &format!("{MAT}m cone c 0 0 8 0 0 0 0 0 1 -1 0.5\n"),
        3,
        &["cone `c`", "(r0) is -1"],
    );
    assert_error(
        &format!("{MAT}m cone c 0 0 8 2 2 2 2 2 2 1 0.5\n"),
        3,
        &["cone `c`", "axis"],
    );
    assert_error(
        &format!("{MAT}m ring r 0 0 8 0 0 0 0 0 1 0 -2\n"),
        3,
        &["ring `r`", "(r1) is -2"],
    );
    assert_error(
        &format!("{MAT}m source s 0 0 4 0 0 0 0.5\n"),
        3,
        &["source `s`", "direction", "non-zero"],
    );
}

#[test]
fn material_value_errors_name_the_field() {
    assert_error(
        "void plastic m 0 0 5 .5 -.5 .5 0 0\n",
        1,
        &["plastic `m`", "(green) is -0.5", "reflectance >= 0"],
    );
    assert_error(
        "void trans t 0 0 7 .5 .5 .5 0 0 0.5 1.5\n",
        1,
        &["trans `t`", "(tspec) is 1.5", "between 0 and 1"],
    );
    assert_error(
        "void glass g 0 0 4 .9 .9 .9 0\n",
        1,
        &["(n) is 0", "refractive index > 0"],
    );
}

#[test]
fn unreadable_input_names_the_file() {
    let missing = Path::new("/nonexistent/skylux/scene.rad");
    let err = scene::load(missing).unwrap_err();
    assert!(matches!(err, SceneError::Io { .. }));
    assert!(
        err.to_string().contains("/nonexistent/skylux/scene.rad"),
        "{err}"
    );

    let err = scene::parse("bin.rad", b"void plastic m 0 0 5 1 1 1 0 0\n\n\xff\xfe").unwrap_err();
    assert!(err.to_string().starts_with("bin.rad:3: not UTF-8"), "{err}");

    let err = load_sensors("/nonexistent/skylux/sensors.pts").unwrap_err();
    assert!(matches!(err, SensorsError::Io { .. }));
    assert!(
        err.to_string().contains("/nonexistent/skylux/sensors.pts"),
        "{err}"
    );
}

#[test]
fn sky_file_errors_name_the_sky_file() {
    let dir = tempfile::tempdir().unwrap();
    let sky_path = dir.path().join("bad_sky.rad");
    std::fs::write(&sky_path, GENSKY.replace("4 0 0 1 180", "4 0 0 1 0")).unwrap();
    let err = scene::load_files(&[test_module("scene.rad"), sky_path.clone()]).unwrap_err();
    let message = err.to_string();
    assert!(
        message.starts_with(&format!("{}:26: source `sky`", sky_path.display())),
        "{message}"
    );
    assert!(message.contains("(angle) is 0"), "{message}");
}

/// 10,000 quads (a 100 x 100 grid of tiles) with a material; also checks they all load.
fn many_polygons(count: usize) -> String {
    let mut text = String::from(MAT);
    let side = (count as f64).sqrt().ceil() as usize;
    for k in 0..count {
        let (x, y) = ((k % side) as f64 * 0.1, (k / side) as f64 * 0.1);
        text += &format!(
            "m polygon tile.{k}\n0\n0\n12\n\t{x:.4} {y:.4} 0\n\t{:.4} {y:.4} 0\n\t{:.4} {:.4} 0\n\t{x:.4} {:.4} 0\n\n",
            x + 0.1,
            x + 0.1,
            y + 0.1,
            y + 0.1
        );
    }
    text
}

#[test]
fn ten_thousand_polygons_load_quickly() {
    let text = many_polygons(10_000);
    let start = Instant::now();
    let scene = scene::parse("tiles.rad", text.as_bytes()).unwrap();
    let elapsed = start.elapsed();
    assert_eq!(scene.surfaces().len(), 10_000);
    let area: f64 = scene
        .surfaces()
        .iter()
        .map(|s| match &s.shape {
            Shape::Polygon(p) => p.area_m2,
            _ => 0.0,
        })
        .sum();
    assert!((area - 100.0).abs() < 1e-6, "{area}");
    eprintln!(
        "10,000 polygons ({} KiB) loaded in {:.1} ms",
        text.len() / 1024,
        elapsed.as_secs_f64() * 1e3
    );
    // Generous enough for an unoptimised build under qemu-arm; natively it is milliseconds.
    assert!(elapsed.as_secs_f64() < 5.0, "took {elapsed:?}");
}
