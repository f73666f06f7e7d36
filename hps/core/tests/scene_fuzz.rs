//! Fuzzing the scene and sensor readers: random bytes, random token streams and mutations of
//! the reference room never panic. They load, or fail with an error that names the file and a
//! line inside it; and whatever loads satisfies what the engine will rely on (unit normals,
//! positive areas and radii, modifier references that resolve to earlier definitions).

use proptest::prelude::*;
use skylux_hps::scene::{self, parse_sensors, ModifierRef, Scene, SceneError, Shape};
use std::path::Path;

const LABEL: &str = "fuzz.rad";

fn reference_room() -> String {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/scenes/test-module/scene.rad");
    std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "the shared reference room is missing: cannot read {} ({e}); expected the `shared` \
             folder beside the workspace",
            path.display()
        )
    })
}

/// Loads `bytes` and checks the outcome: an error that names `fuzz.rad` and a line that
/// exists, or a scene whose invariants hold.
fn check(bytes: &[u8]) -> Result<(), TestCaseError> {
    let lines = 1 + bytes.iter().filter(|&&b| b == b'\n').count();
    match scene::parse(LABEL, bytes) {
        Err(err) => check_error(&err, lines),
        Ok(scene) => check_scene(&scene),
    }
}

fn check_error(err: &SceneError, lines: usize) -> Result<(), TestCaseError> {
    let at = err.location().expect("errors from text carry a location");
    prop_assert_eq!(&*at.file, Path::new(LABEL));
    prop_assert!(
        at.line >= 1 && at.line <= lines,
        "line {} of {}",
        at.line,
        lines
    );
    let message = err.to_string();
    prop_assert!(
        message.starts_with(&format!("{LABEL}:{}: ", at.line)),
        "{}",
        message
    );
    Ok(())
}

fn check_scene(scene: &Scene) -> Result<(), TestCaseError> {
    let unit = |v: glam::DVec3| v.is_finite() && (v.length() - 1.0).abs() < 1e-9;
    for (index, m) in scene.modifiers().iter().enumerate() {
        if let ModifierRef::Defined(id) = m.modifier {
            prop_assert!(id.index() < index, "modifier {} refers forward", m.name);
        }
    }
    for s in scene.surfaces() {
        if let ModifierRef::Defined(id) = s.modifier {
            prop_assert!(scene.modifier(id).is_some());
        }
        match &s.shape {
            Shape::Polygon(p) => {
                prop_assert!(p.vertices_m.len() >= 3);
                prop_assert!(unit(p.normal), "{}: normal {}", s.name, p.normal);
                prop_assert!(p.area_m2 > 0.0 && p.area_m2.is_finite(), "{}", p.area_m2);
            }
            Shape::Sphere(sp) | Shape::Bubble(sp) => prop_assert!(sp.radius_m > 0.0),
            Shape::Cylinder(c) | Shape::Tube(c) => {
                prop_assert!(c.radius_m > 0.0 && (c.end_m - c.start_m).length() > 0.0)
            }
            Shape::Cone(c) | Shape::Cup(c) => prop_assert!(
                c.start_radius_m >= 0.0
                    && c.end_radius_m >= 0.0
                    && c.start_radius_m + c.end_radius_m > 0.0
            ),
            Shape::Ring(r) => {
                prop_assert!(unit(r.normal));
                prop_assert!(0.0 <= r.inner_radius_m && r.inner_radius_m < r.outer_radius_m);
            }
            Shape::Source(src) => {
                prop_assert!(unit(src.direction));
                prop_assert!(src.angle_deg > 0.0 && src.angle_deg <= 360.0);
            }
        }
    }
    Ok(())
}

/// Words a scene file is made of, including the troublesome ones.
fn word() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => prop::sample::select(vec![
            "void", "m", "n", "sky", "plastic", "metal", "trans", "glass", "mirror", "light",
            "glow", "brightfunc", "polygon", "sphere", "cylinder", "ring", "cone", "source",
            "bubble", "tube", "cup", "dielectric", "interface", "spotlight", "illum",
            "antimatter", "inherit", "alias", "texfunc", "!xform", "!", "#", "# c", "\"", "'", "\"a b\"",
            "skybright", "skybright.cal",
        ])
        .prop_map(str::to_string),
        6 => (0u32..14).prop_map(|n| n.to_string()),
        6 => prop::sample::select(vec![
            "0", "1", "-1", "0.5", ".5", "5.", "1e308", "-1e308", "1e-300", "nan", "inf", "-0",
            "1e999", "abc", "4294967296", "18446744073709551616", "+3",
        ])
        .prop_map(str::to_string),
        3 => (-1e3f64..1e3).prop_map(|v| v.to_string()),
    ]
}

fn separator() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![" ", " ", "\n", "\t", "\r\n", "  # note\n"])
}

/// A primitive shaped like the real thing: a supported type, usually with the argument counts
/// its type wants, and values that are often but not always valid, so that loads get deep into
/// the typed checks and some scenes load.
fn primitive() -> impl Strategy<Value = String> {
    let value = prop_oneof![
        6 => 0.0f64..1.0,
        3 => (-3i32..4).prop_map(f64::from),
        2 => -10.0f64..10.0,
        1 => prop::sample::select(vec![0.0, 1e-7, -1e-7, 1e300, -1e300, 180.0, 360.0, 361.0]),
    ];
    (
        prop::sample::select(vec![
            ("plastic", 5),
            ("metal", 5),
            ("trans", 7),
            ("glass", 3),
            ("glass", 4),
            ("mirror", 3),
            ("light", 3),
            ("glow", 4),
            ("brightfunc", 7),
            ("polygon", 9),
            ("polygon", 12),
            ("sphere", 4),
            ("cylinder", 7),
            ("ring", 8),
            ("cone", 8),
            ("source", 4),
            ("bubble", 4),
            ("tube", 7),
            ("cup", 8),
            ("dielectric", 5),
            ("interface", 8),
            ("spotlight", 7),
            ("illum", 3),
            ("antimatter", 0),
            ("alias", 0),
            ("plasfunc", 4),
            ("metdata", 4),
            ("transfunc", 6),
            ("transdata", 7),
            ("plastic2", 6),
            ("metal2", 6),
            ("trans2", 8),
            ("texdata", 0),
            ("mixdata", 0),
        ]),
        prop::sample::select(vec!["void", "void", "m", "m", "m", "sky", "x"]),
        prop::sample::select(vec!["m", "sky", "p"]),
        prop::bool::weighted(0.85),
        prop::collection::vec(value, 0..16),
    )
        .prop_map(|((kind, count), modifier, name, exact, mut reals)| {
            if exact {
                reals.resize(count, 0.5);
            }
            if kind == "alias" {
                return format!(
                    "{modifier} alias {name} {}\n",
                    ["m", "sky", "p", "void"][reals.len() % 4]
                );
            }
            let strings = match (kind, reals.len() % 3) {
                ("brightfunc", _) => "2 skybright skybright.cal",
                ("illum" | "mirror", 0) => "1 m",
                ("illum", 1) => "1 void",
                ("antimatter", 0) => "1 m",
                ("antimatter", 1) => "2 void m",
                ("plasfunc" | "transfunc", 0) => "2 lobe f.cal",
                ("plasfunc" | "transfunc", 1) => "3 lobe f.cal -rz",
                ("metdata" | "transdata", 0) => "4 f d.dat f.cal x",
                ("metdata" | "transdata", 1) => "6 f d.dat f.cal x y -s",
                ("plastic2" | "metal2" | "trans2", 0) => "4 1 0 0 .",
                ("plastic2" | "metal2" | "trans2", 1) => "4 ux uy uz f.cal -rx 30",
                ("texdata", 0) => "9 f g h x.dat y.dat z.dat f.cal Px Py",
                ("texdata", 1) => "8 f g h x.dat y.dat z.dat f.cal",
                ("mixdata", 0) => "6 m void f d.dat f.cal Px",
                ("mixdata", 1) => "8 nowhere m f d.dat f.cal Px -s 2",
                _ => "0",
            };
            let reals: Vec<String> = reals.iter().map(f64::to_string).collect();
            format!(
                "{modifier} {kind} {name}\n{strings}\n0\n{} {}\n",
                reals.len(),
                reals.join(" ")
            )
        })
}

/// Materials and surfaces that usually load, with random but valid arguments, so that whole
/// scenes of the issue-19 primitives reach the engine: every material kind is defined up
/// front (`scene_materials`), surfaces pick among them.
fn traceable_primitive() -> impl Strategy<Value = String> {
    let coordinate = -3.0f64..3.0;
    let radius = 0.05f64..2.0;
    let point = || (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0);
    (
        prop::sample::select(vec![
            "m",
            "crystal",
            "water",
            "spot",
            "window",
            "window_glass",
            "lamp",
            "copy",
            "brushed",
            "frosted",
            "void",
        ]),
        prop::sample::select(vec![
            "bubble", "tube", "cup", "sphere", "cylinder", "ring", "polygon",
        ]),
        point(),
        point(),
        radius.clone(),
        radius,
        coordinate,
    )
        .prop_map(|(modifier, kind, a, b, r0, r1, z)| {
            let reals = match kind {
                "bubble" | "sphere" => format!("4 {} {} {} {r0}", a.0, a.1, a.2),
                "tube" | "cylinder" => {
                    format!("7 {} {} {} {} {} {} {r0}", a.0, a.1, a.2, b.0, b.1, b.2)
                }
                "cup" => format!(
                    "8 {} {} {} {} {} {} {r0} {r1}",
                    a.0, a.1, a.2, b.0, b.1, b.2
                ),
                "ring" => format!("8 {} {} {} {} {} {} 0 {r0}", a.0, a.1, a.2, b.0, b.1, b.2),
                _ => format!(
                    "9 {} {} {z} {} {} {z} {} {} {z}",
                    a.0, a.1, b.0, b.1, a.2, b.2
                ),
            };
            format!("{modifier} {kind} s 0 0 {reals}\n")
        })
}

/// The materials [`traceable_primitive`]'s surfaces use.
const SCENE_MATERIALS: &str = "void dielectric crystal 0 0 5 .8 .8 .8 1.5 0\n\
    void interface water 0 0 8 .9 .9 .9 1.33 1 1 1 1.5\n\
    void spotlight spot 0 0 7 50 50 50 40 0 0 -2\n\
    void illum window 0 0 3 10 10 10\n\
    void glass pane 0 0 3 .9 .9 .9\n\
    void illum window_glass 1 pane 0 3 10 10 10\n\
    void glow lamp 0 0 4 5 5 5 0\n\
    inherit alias copy crystal\n\
    void antimatter hole 2 m crystal 0 0\n\
    void antimatter erase 1 void 0 0\n\
    void metal2 brushed 4 1 0 0 . 0 6 .8 .7 .6 .6 .04 .3\n\
    void trans2 frosted 4 0 1 0 . 0 8 .8 .8 .8 .05 .2 .05 .6 .4\n";

/// Words of inline command lines: programs, their options, numbers and shell syntax.
fn command_word() -> impl Strategy<Value = String> {
    prop_oneof![
        3 => prop::sample::select(vec![
            "xform", "genbox", "genblinds", "genprism", "genrev", "gensky", "gendaylit", "cat",
            "-e", "-n", "-m", "-a", "-i", "-t", "-rx", "-ry", "-rz", "-s", "-mx", "-my", "-mz",
            "-I", "-c", "-f", "-b", "-r", "+r", "-l", "-ang", "+s", "-u", "-W", "-G", "-P",
            "-O", "-g", "-d", "-o", "-y", "-B", "-R", "|", "\\\n", "'t'", "'1-t'", "\"a b\"",
            "'", "\"", ">", ";", "$X", "#", "m", "b", "10:30EDT", "+12", "sin(PI*t)", "-",
            "fuzz.rad", "-", "999999", "100000",
        ])
        .prop_map(str::to_string),
        3 => (-5i32..40).prop_map(|n| n.to_string()),
        1 => (-1e3f64..1e3).prop_map(|v| v.to_string()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_command_lines_never_panic_or_hang(
        lines in prop::collection::vec(prop::collection::vec(command_word(), 0..14), 1..4),
    ) {
        let mut text = String::from("void plastic m 0 0 5 .5 .5 .5 0 0\n");
        for words in &lines {
            text.push('!');
            text.push_str(&words.join(" "));
            text.push('\n');
        }
        let start = std::time::Instant::now();
        check(text.as_bytes())?;
        prop_assert!(start.elapsed().as_secs() < 20, "{:?} for {}", start.elapsed(), text);
    }

    #[test]
    fn generator_commands_with_random_numbers_never_panic(
        program in prop::sample::select(vec![
            "genbox m b", "genblinds m b", "genprism m p", "genrev m r t t", "gensky",
            "gendaylit", "xform -t", "xform -a",
        ]),
        numbers in prop::collection::vec(
            prop_oneof![
                (-100i32..100).prop_map(|n| n.to_string()),
                (-1e6f64..1e6).prop_map(|v| v.to_string()),
                prop::sample::select(vec!["0", "1e308", "-0", "nan", "inf", "4"])
                    .prop_map(str::to_string),
            ],
            0..12,
        ),
        tail in prop::sample::select(vec!["", " -W 500 100", " -r 0.1", " -i", " -c", " | xform -rz 9"]),
    ) {
        let text = format!(
            "void plastic m 0 0 5 .5 .5 .5 0 0\n!{program} {}{tail}\n",
            numbers.join(" ")
        );
        check(text.as_bytes())?;
    }

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..2048)) {
        check(&bytes)?;
    }

    #[test]
    fn random_ascii_text_never_panics(text in "[ -~\t\n]{0,1024}") {
        check(text.as_bytes())?;
    }

    #[test]
    fn random_token_streams_never_panic(
        words in prop::collection::vec((word(), separator()), 0..200),
    ) {
        let text: String = words.iter().flat_map(|(w, s)| [w.as_str(), *s]).collect();
        check(text.as_bytes())?;
    }

    #[test]
    fn random_primitives_never_panic(
        primitives in prop::collection::vec(primitive(), 1..12),
    ) {
        let text = format!("void plastic m 0 0 5 .5 .5 .5 0 0\n{}", primitives.concat());
        check(text.as_bytes())?;
    }

    /// Whatever loads also prepares for tracing or is refused with a located error, and a few
    /// paths through it stay finite and end: the engine side of the new primitives (inward
    /// shapes, dielectric, illum, spotlight, antimatter) under random arguments.
    #[test]
    fn random_primitives_trace_or_are_refused(
        primitives in prop::collection::vec(traceable_primitive(), 1..16),
    ) {
        let text = format!(
            "void plastic m 0 0 5 .5 .5 .5 0 0\nvoid light sun 0 0 3 1e5 1e5 1e5\n\
             sun source s 0 0 4 0.3 0.2 1 0.5\n{SCENE_MATERIALS}{}",
            primitives.concat()
        );
        let scene = match scene::parse(LABEL, text.as_bytes()) {
            Ok(scene) => scene,
            Err(err) => return check_error(&err, text.lines().count()),
        };
        let world = match skylux_hps::engine::World::new(&scene) {
            Ok(world) => world,
            Err(err) => {
                prop_assert!(err.to_string().starts_with(LABEL), "{}", err);
                return Ok(());
            }
        };
        let settings = skylux_hps::engine::Settings {
            samples_per_sensor: 8,
            ..Default::default()
        };
        let sensors = parse_sensors("fuzz.pts", b"0.1 0.2 0.3 0 0 1\n2 -1 0.5 1 0 0\n").unwrap();
        let start = std::time::Instant::now();
        let lux = skylux_hps::engine::illuminance(&world, &sensors, &settings, &|_, _| {}).unwrap();
        prop_assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
        for s in lux {
            prop_assert!(s.illuminance_lux.is_finite() && s.illuminance_lux >= 0.0, "{:?}", s);
        }
    }

    #[test]
    fn mutated_reference_room_never_panics(
        edits in prop::collection::vec((0usize..4, any::<prop::sample::Index>(), word()), 1..6),
    ) {
        let room = reference_room();
        let mut words: Vec<String> = room.split_inclusive(char::is_whitespace).map(str::to_string).collect();
        for (kind, at, replacement) in edits {
            if words.is_empty() {
                break;
            }
            let i = at.index(words.len());
            match kind {
                0 => { words.remove(i); }
                1 => words[i] = format!("{replacement} "),
                2 => words.insert(i, format!("{replacement}\n")),
                _ => {
                    let j = (i + 1) % words.len();
                    words.swap(i, j);
                }
            }
        }
        check(words.concat().as_bytes())?;
    }

    #[test]
    fn byte_flipped_reference_room_never_panics(
        flips in prop::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8),
    ) {
        let mut bytes = reference_room().into_bytes();
        for (at, value) in flips {
            let i = at.index(bytes.len());
            bytes[i] = value;
        }
        check(&bytes)?;
    }

    #[test]
    fn random_sensor_files_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..1024)) {
        if let Ok(sensors) = parse_sensors("fuzz.pts", &bytes) {
            for s in sensors {
                prop_assert!(s.position_m.is_finite());
                prop_assert!((s.direction.length() - 1.0).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn random_sensor_lines_never_panic(
        lines in prop::collection::vec(prop::collection::vec(word(), 0..8), 0..20),
    ) {
        let text: String = lines.iter().map(|l| l.join(" ") + "\n").collect();
        match parse_sensors("fuzz.pts", text.as_bytes()) {
            Ok(sensors) => {
                for (i, s) in sensors.iter().enumerate() {
                    prop_assert_eq!(&s.name, &format!("S{}", i + 1));
                    prop_assert!((s.direction.length() - 1.0).abs() < 1e-9);
                }
            }
            Err(err) => prop_assert!(err.to_string().starts_with("fuzz.pts"), "{}", err),
        }
    }
}

#[test]
fn the_unmutated_reference_room_passes_the_same_checks() {
    let room = reference_room();
    let scene = scene::parse(LABEL, room.as_bytes()).unwrap();
    assert_eq!(scene.surfaces().len(), 44);
    check(room.as_bytes()).unwrap();
}

/// A `BSDF`/`aBSDF` primitive with arguments often right and often not: thicknesses, XML
/// names (present, absent, a directory, a malformed file, an absolute path), up vectors
/// (parallel to the window, zero, not numbers), function files and transforms, reals.
fn bsdf_primitive() -> impl Strategy<Value = String> {
    let string = prop::sample::select(vec![
        "0",
        "0.05",
        "-0.05",
        "1e-9",
        "nan",
        "inf",
        "x",
        "good.xml",
        "./good.xml",
        "bad.xml",
        "absent.xml",
        ".",
        "sub",
        "/dev/null",
        "0",
        "1",
        "-1",
        "0",
        "0",
        "1",
        ".",
        "-rz",
        "90",
    ]);
    let real = prop_oneof![4 => 0.0f64..1.0, 1 => -1.0f64..2.0];
    (
        prop::sample::select(vec!["BSDF", "BSDF", "aBSDF"]),
        prop::bool::weighted(0.7),
        prop::collection::vec(string, 0..9),
        prop::collection::vec(real, 0..11),
    )
        .prop_map(|(kind, shaped, mut strings, mut reals)| {
            if shaped {
                let base = ["0", "good.xml", "0", "0", "1", "."];
                let skip = usize::from(kind == "aBSDF");
                for (i, w) in base.iter().skip(skip).enumerate() {
                    if strings.len() <= i {
                        strings.push(w);
                    }
                }
                reals.truncate(reals.len() / 3 * 3);
            }
            let reals: Vec<String> = reals.iter().map(f64::to_string).collect();
            format!(
                "void {kind} w\n{} {}\n0\n{} {}\nw polygon p 0 0 12 0 0 0 1 0 0 1 0 1 0 0 1\n",
                strings.len(),
                strings.join(" "),
                reals.len(),
                reals.join(" ")
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// BSDF materials load into the engine (the XML read, the frame built) or fail with an
    /// error naming the scene file and a line in it; never a panic.
    #[test]
    fn random_bsdf_materials_never_panic(text in bsdf_primitive()) {
        let dir = tempfile::tempdir().unwrap();
        let satine = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../../shared/data/radiance-corpus/bsdf/frads/2011-SA1.xml");
        std::fs::copy(&satine, dir.path().join("good.xml")).unwrap();
        std::fs::write(dir.path().join("bad.xml"), "<WindowElement><Optical>").unwrap();
        std::fs::create_dir(dir.path().join("sub")).unwrap();
        let file = dir.path().join("fuzz.rad");
        std::fs::write(&file, &text).unwrap();
        let options = scene::LoadOptions {
            working_directory: Some(dir.path().to_path_buf()),
            ..Default::default()
        };
        let started = std::time::Instant::now();
        match scene::load_files_with(&[&file], &options) {
            Err(err) => {
                let at = err.location().expect("errors from text carry a location");
                prop_assert_eq!(&*at.file, file.as_path());
                prop_assert!(at.line >= 1 && at.line <= 5, "line {}", at.line);
            }
            Ok(loaded) => {
                if let Err(err) = skylux_hps::engine::World::new(&loaded) {
                    let message = err.to_string();
                    prop_assert!(message.contains("fuzz.rad:1"), "{}", message);
                }
            }
        }
        prop_assert!(started.elapsed().as_secs_f64() < 5.0);
    }
}
