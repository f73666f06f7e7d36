//! Issue 19: bad input for the primitives added with it (inward surfaces, dielectric,
//! interface, spotlight, illum, antimatter, alias; instance and mesh, which Skylux does not
//! read) is a clear error naming the file, the line and the primitive, from the reader or,
//! for what it reads but does not trace (a spotlight as a distant source), from the engine.

use skylux_hps::engine::World;
use skylux_hps::scene;

const MATERIAL: &str = "void plastic m 0 0 5 .5 .5 .5 0 0\n";

/// The reader's error for `text` after a plastic `m` on line 1.
fn error(text: &str) -> String {
    scene::parse("bad.rad", format!("{MATERIAL}{text}").as_bytes())
        .unwrap_err()
        .to_string()
}

fn assert_names(message: &str, line: usize, fragments: &[&str]) {
    assert!(
        message.starts_with(&format!("bad.rad:{line}: ")),
        "{message}"
    );
    for f in fragments {
        assert!(message.contains(f), "`{f}` not in: {message}");
    }
}

#[test]
fn wrong_argument_counts_name_the_primitive_and_what_it_takes() {
    let cases: &[(&str, &[&str])] = &[
        (
            "void dielectric d 0 0 4 .9 .9 .9 1.5\n",
            &["dielectric `d`", "5 (rtn gtn btn n hc)"],
        ),
        (
            "void interface i 0 0 7 1 1 1 1.5 1 1 1\n",
            &["interface `i`", "8 (rtn1 gtn1 btn1 n1 rtn2 gtn2 btn2 n2)"],
        ),
        (
            "void spotlight s 0 0 6 1 1 1 30 0 0\n",
            &["spotlight `s`", "7 (red green blue angle xdir ydir zdir)"],
        ),
        (
            "void illum w 2 m m 0 3 1 1 1\n",
            &["illum `w`", "0 or 1 (optional alternate material)"],
        ),
        (
            "m bubble b 0 0 3 0 0 0\n",
            &["bubble `b`", "4 (xcent ycent zcent radius)"],
        ),
        (
            "m tube t 0 0 6 0 0 0 0 0 1\n",
            &["tube `t`", "7 (x0 y0 z0 x1 y1 z1 rad)"],
        ),
        (
            "m cup c 0 0 7 0 0 0 0 0 1 1\n",
            &["cup `c`", "8 (x0 y0 z0 x1 y1 z1 r0 r1)"],
        ),
        (
            "void antimatter a 0 0 0\n",
            &["antimatter `a`", "at least 1"],
        ),
        (
            "void antimatter a 1 m 0 1 2\n",
            &["antimatter `a`", "0 for antimatter"],
        ),
    ];
    for (text, fragments) in cases {
        assert_names(&error(&format!("# comment\n{text}")), 3, fragments);
    }
}

/// The text patterns: too few strings (no text file) or reals (no brightness, colour),
/// integers, and a `mixtext` naming an undefined modifier.
#[test]
fn text_patterns_with_wrong_arguments_name_what_they_take() {
    let place = "0 0 0 1 0 0 0 -1 0";
    let cases: &[(String, &[&str])] = &[
        (
            format!("void brighttext t 1 font.fnt\n0\n11 {place} 1 0\n"),
            &["brighttext `t`", "at least 2 (fontfile textfile"],
        ),
        (
            format!("void brighttext t 2 font.fnt a.txt\n0\n10 {place} 1\n"),
            &[
                "brighttext `t`",
                "at least 11 (Ax Ay Az",
                "foreground background [spacing]",
            ],
        ),
        (
            format!("void colortext t 3 font.fnt . hello\n0\n11 {place} 1 1\n"),
            &[
                "colortext `t`",
                "at least 15",
                "rback gback bback [spacing]",
            ],
        ),
        (
            format!("void colortext t 2 font.fnt a.txt\n1 3\n15 {place} 1 1 1 0 0 0\n"),
            &["colortext `t`", "integer"],
        ),
        (
            format!("void mixtext t 3 m m font.fnt\n0\n9 {place}\n"),
            &["mixtext `t`", "at least 4 (foreground background fontfile"],
        ),
        (
            format!("void mixtext t 4 m nothing font.fnt a.txt\n0\n9 {place}\n"),
            &["mixtext `t`", "background", "`nothing`"],
        ),
    ];
    for (text, fragments) in cases {
        assert_names(&error(text), 2, fragments);
    }
}

#[test]
fn out_of_range_values_are_refused() {
    assert_names(
        &error("void spotlight s 0 0 7 1 1 1 30 0 0 0\n"),
        2,
        &["direction", "a non-zero direction"],
    );
    assert_names(
        &error("void spotlight s 0 0 7 1 1 1 0 0 0 -1\n"),
        2,
        &["real argument 4 (angle)"],
    );
    assert_names(
        &error("void dielectric d 0 0 5 .9 .9 .9 0 0\n"),
        2,
        &["real argument 4 (n)", "a refractive index > 0"],
    );
    assert_names(
        &error("m bubble b 0 0 4 0 0 0 -1\n"),
        2,
        &["real argument 4 (radius)"],
    );
}

#[test]
fn references_to_nothing_are_errors_on_their_line() {
    assert_names(
        &error("void alias a nothing\n"),
        2,
        &["alias `a`", "`nothing`"],
    );
    assert_names(
        &error("m sphere ball 0 0 4 0 0 0 1\nvoid alias a ball\n"),
        3,
        &["surfaces cannot be aliased"],
    );
    assert_names(
        &error("nothing alias a m\n"),
        2,
        &["alias `a`", "modifier", "`nothing`"],
    );
    assert_names(
        &error("void antimatter a 2 m nothing 0 0\n"),
        2,
        &["antimatter `a`", "`nothing`"],
    );
    assert_names(
        &error("void illum w 1 nothing 0 3 1 1 1\n"),
        2,
        &["illum `w`", "alternate material", "`nothing`"],
    );
    // An alias is a modifier, not a surface: a primitive of type alias cannot follow `inherit`
    // as an ordinary primitive's modifier.
    assert_names(
        &error("inherit sphere s 0 0 4 0 0 0 1\n"),
        2,
        &["`inherit`"],
    );
}

#[test]
fn octree_instances_and_meshes_name_the_file_line_and_type() {
    for (text, kind) in [
        ("m instance chair 1 chair.oct 0 0\n", "`instance`"),
        ("m mesh table 1 table.rtm 0 0\n", "`mesh`"),
    ] {
        assert_names(
            &error(&format!("\n{text}")),
            3,
            &[kind, "outside the subset"],
        );
    }
}

#[test]
fn what_the_engine_does_not_trace_is_refused_with_its_location() {
    let scene = scene::parse(
        "spot.rad",
        b"void spotlight s 0 0 7 1 1 1 30 0 0 -1\ns source sun 0 0 4 0 0 1 0.5\n",
    )
    .unwrap();
    let err = World::new(&scene).unwrap_err().to_string();
    assert!(err.starts_with("spot.rad:"), "{err}");
    assert!(err.contains("spotlight"), "{err}");
}
