//! Bad input to function modifiers: a malformed `.cal` file, an unknown variable, a missing
//! `.cal` or data file, a malformed data file, a data file of the wrong dimension, a text
//! pattern's missing or malformed font or missing text file are each a
//! clear error naming the scene file and line and the `.cal`/`.dat` file, never a panic; and
//! the data-file reader, fuzzed with random and mutated files, never panics, always answers
//! quickly, and interpolates to finite values.

use proptest::prelude::*;
use skylux_hps::engine::function::data::DataArray;
use skylux_hps::engine::World;
use skylux_hps::scene;
use std::path::Path;

/// Loads `scene_text` written beside `files` (name, text) and returns the engine's error.
fn engine_error(scene_text: &str, files: &[(&str, &str)]) -> String {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    let path = dir.path().join("room.rad");
    std::fs::write(&path, scene_text).unwrap();
    let scene = scene::load_files(&[&path]).unwrap();
    World::new(&scene).unwrap_err().to_string()
}

const SURFACE: &str = "m polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n";

fn assert_names(err: &str, line: usize, fragments: &[&str]) {
    assert!(err.contains(&format!("room.rad:{line}:")), "{err}");
    for f in fragments {
        assert!(err.contains(f), "`{f}` not in: {err}");
    }
}

#[test]
fn a_malformed_cal_file_names_both_files_and_lines() {
    let scene = format!(
        "# a pattern\nvoid colorfunc c 4 r g b bad.cal\n0\n0\nc plastic m 0 0 5 .5 .5 .5 0 0\n{SURFACE}"
    );
    let err = engine_error(&scene, &[("bad.cal", "r = 1;\ng = (2 + ;\nb = 3;\n")]);
    assert_names(&err, 2, &["colorfunc `c`", "bad.cal", "line 2"]);
}

#[test]
fn an_unknown_variable_is_named() {
    let scene = format!(
        "void brightfunc b 2 nowhere ok.cal\n0\n0\nb plastic m 0 0 5 .5 .5 .5 0 0\n{SURFACE}"
    );
    let err = engine_error(&scene, &[("ok.cal", "x = 1;\n")]);
    assert_names(&err, 1, &["brightfunc `b`", "nowhere", "undefined"]);
}

#[test]
fn a_missing_cal_or_data_file_is_named() {
    let scene = format!(
        "void texfunc t 4 x y z absent.cal\n0\n0\nt plastic m 0 0 5 .5 .5 .5 0 0\n{SURFACE}"
    );
    let err = engine_error(&scene, &[]);
    assert_names(&err, 1, &["texfunc `t`", "absent.cal", "not found"]);
    let scene = format!(
        "void brightdata d 4 noneg absent.dat . Px\n0\n0\nd plastic m 0 0 5 .5 .5 .5 0 0\n{SURFACE}"
    );
    let err = engine_error(&scene, &[]);
    assert_names(&err, 1, &["brightdata `d`", "absent.dat", "not found"]);
}

#[test]
fn a_bad_data_file_is_named_with_its_line() {
    let scene = format!(
        "void brightdata d 4 same bad.dat f.cal Px\n0\n0\nd plastic m 0 0 5 .5 .5 .5 0 0\n{SURFACE}"
    );
    let cal = ("f.cal", "same(v) = v;\n");
    let err = engine_error(&scene, &[cal, ("bad.dat", "1\n0 1 3\n0.5 x 1\n")]);
    assert_names(&err, 1, &["brightdata `d`", "bad.dat", "line 3", "`x`"]);
    // Two dimensions in the file, one coordinate in the scene.
    let err = engine_error(&scene, &[cal, ("bad.dat", "2\n0 1 2\n0 1 2\n1 2 3 4\n")]);
    assert_names(&err, 1, &["bad.dat", "2 dimension(s)", "1 coordinate"]);
    // A function that does not exist.
    let scene = scene.replace("same bad.dat", "nofunc bad.dat");
    let err = engine_error(&scene, &[cal, ("bad.dat", "1\n0 1 2\n1 2\n")]);
    assert_names(&err, 1, &["nofunc", "not defined"]);
}

/// A text pattern whose font is missing or malformed, whose text file is missing, or whose
/// motion vectors span no plane: an error naming the scene file and line, the pattern, and
/// the font file with its line.
#[test]
fn text_pattern_files_and_vectors_are_named() {
    let pattern = |strings: &str, vectors: &str| {
        format!(
            "# text\nvoid brighttext t {strings}\n0\n11 0 0 0 {vectors} 1 0.2\n\
             t plastic m 0 0 5 .5 .5 .5 0 0\n{SURFACE}"
        )
    };
    let plane = "1 0 0 0 -1 0";
    let font = ("ok.fnt", "65 4 0 0 255 0 255 255 0 255\n32 0\n");
    let err = engine_error(&pattern("3 absent.fnt . A", plane), &[]);
    assert_names(
        &err,
        2,
        &["brighttext `t`", "font file absent.fnt", "not found"],
    );
    let bad = (
        "bad.fnt",
        "# two glyphs\n65 3 0 0 9 0 9 9\n66 3 0 0 300 0 9 9\n",
    );
    let err = engine_error(&pattern("3 bad.fnt . AB", plane), &[bad]);
    assert_names(
        &err,
        2,
        &[
            "brighttext `t`",
            "bad.fnt, line 3",
            "x of vertex 2 of character 66",
        ],
    );
    let err = engine_error(
        &pattern("3 bad.fnt . AB", plane),
        &[("bad.fnt", "65 2 0\n")],
    );
    assert_names(&err, 2, &["bad.fnt, line 1", "y of vertex 1"]);
    let err = engine_error(&pattern("2 ok.fnt absent.txt", plane), &[font]);
    assert_names(
        &err,
        2,
        &["brighttext `t`", "text file absent.txt", "not found"],
    );
    let err = engine_error(&pattern("3 ok.fnt . A", "1 0 0 2 0 0"), &[font]);
    assert_names(&err, 2, &["brighttext `t`", "illegal motion vectors"]);
    // The same font and text load.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join(font.0), font.1).unwrap();
    let path = dir.path().join("room.rad");
    std::fs::write(&path, pattern("3 ok.fnt . A", plane)).unwrap();
    World::new(&scene::load_files(&[&path]).unwrap()).unwrap();
}

#[test]
fn a_brtdfunc_with_too_few_arguments_is_a_scene_error() {
    let err = scene::parse(
        Path::new("room.rad"),
        b"void BRTDfunc s 10 0 0 0 0 0 0 0 0 0 .\n0\n6 .5 .5 .5 .5 .5 .5\n",
    )
    .unwrap_err()
    .to_string();
    assert!(
        err.starts_with("room.rad:1:") && err.contains("at least 9"),
        "{err}"
    );
}

/// A material's line, the files beside it (name, text), and fragments its error must hold.
type Case<'a> = (&'a str, &'a [(&'a str, &'a str)], &'a [&'a str]);

/// The function and anisotropic materials (`plasfunc` .. `transdata`, `plastic2` ..
/// `trans2`): a missing `.cal` or `.dat` file, an unknown function name, a data file of the
/// wrong dimension and an orientation naming an unknown variable are engine errors naming
/// the scene file, line and material.
#[test]
fn function_and_anisotropic_materials_name_what_is_missing() {
    let cal = (
        "f.cal",
        "lobe(lx, ly, lz, om) = 0.2;\nscale(v, lx, ly, lz, om) = v;\nup(lx, ly, lz, om) = lz;\n",
    );
    let dat = ("one.dat", "1\n0 1 3\n0.5 1 2\n");
    let surface = |m: &str| format!("# room\n{m}\n{}", SURFACE.replace("m polygon", "x polygon"));
    let cases: [Case; 6] = [
        (
            "void plasfunc x 2 lobe absent.cal\n0\n4 .5 .5 .5 .1",
            &[],
            &["plasfunc `x`", "absent.cal", "not found"],
        ),
        (
            "void metfunc x 2 nolobe f.cal\n0\n4 .5 .5 .5 .1",
            &[cal],
            &["metfunc `x`", "nolobe", "not defined"],
        ),
        (
            "void transdata x 4 scale absent.dat f.cal up\n0\n6 .5 .5 .5 .1 .5 .5",
            &[cal],
            &["transdata `x`", "absent.dat", "not found"],
        ),
        (
            "void plasdata x 4 noscale one.dat f.cal up\n0\n4 .5 .5 .5 .1",
            &[cal, dat],
            &["plasdata `x`", "noscale", "not defined"],
        ),
        (
            "void metdata x 5 scale one.dat f.cal up up\n0\n4 .5 .5 .5 .1",
            &[cal, dat],
            &["metdata `x`", "1 dimension(s)", "2 coordinate"],
        ),
        (
            "void plastic2 x 4 ux 0 0 f.cal\n0\n6 .5 .5 .5 .1 .1 .2",
            &[cal],
            &["plastic2 `x`", "ux"],
        ),
    ];
    for (material, files, fragments) in cases {
        let err = engine_error(&surface(material), files);
        assert_names(&err, 2, fragments);
    }
    // A texdata and a mixdata above a plastic: the texture's or the mixture's line is named.
    let plastic = "void plastic p 0 0 5 .5 .5 .5 0 0";
    let textured = format!("# room\n{plastic}\nvoid texdata x 8 first second third one.dat absent.dat one.dat f.cal up\n0 0\nx plastic m 0 0 5 .5 .5 .5 0 0\n{SURFACE}");
    let tex_cal = (
        "f.cal",
        "first(a, b, c) = a;\nsecond(a, b, c) = b;\nthird(a, b, c) = c;\nup = Pz;\n",
    );
    let err = engine_error(&textured, &[tex_cal, dat]);
    assert_names(&err, 3, &["texdata `x`", "absent.dat", "not found"]);
    let mixed = format!(
        "# room\n{plastic}\nvoid mixdata m 6 p void nofunc one.dat f.cal up\n0 0\n{SURFACE}"
    );
    let err = engine_error(&mixed, &[tex_cal, dat]);
    assert_names(&err, 3, &["mixdata `m`", "nofunc", "not defined"]);
}

/// A well-formed data file of `dims` dimensions with the given counts.
fn data_text(counts: &[usize], irregular: &[bool], values: &[f64]) -> String {
    let mut text = format!("{}\n", counts.len());
    for (k, &n) in counts.iter().enumerate() {
        if irregular[k] {
            let points: Vec<String> = (0..n).map(|j| format!("{}", j as f64 * 0.7)).collect();
            text.push_str(&format!("0 0 {n} {}\n", points.join(" ")));
        } else {
            text.push_str(&format!("-1 2 {n}\n"));
        }
    }
    let total: usize = counts.iter().product();
    for j in 0..total {
        text.push_str(&format!("{} ", values[j % values.len()]));
    }
    text
}

fn data_token() -> impl Strategy<Value = String> {
    prop_oneof![
        (0usize..6).prop_map(|n| n.to_string()),
        (-1e3f64..1e3).prop_map(|v| format!("{v}")),
        Just("0".to_string()),
        Just("nan".to_string()),
        Just("inf".to_string()),
        Just("99999999999".to_string()),
        Just("-2".to_string()),
        Just("\n".to_string()),
        "[a-z#.]{1,3}",
    ]
}

fn check_reader(text: &str) -> Result<(), TestCaseError> {
    let start = std::time::Instant::now();
    let lines = 1 + text.matches('\n').count();
    match DataArray::parse("fuzz.dat", text) {
        Ok(array) => {
            let n = array.dimension_count();
            for p in [-5.0, -0.3, 0.0, 0.4, 1.0, 3.7, 1e9, f64::NAN] {
                let v = array.value(&vec![p; n]);
                prop_assert!(v.is_finite() || p.is_nan(), "value {v} at {p}");
            }
        }
        Err(e) => {
            prop_assert_eq!(e.file.as_str(), "fuzz.dat");
            prop_assert!(
                e.line >= 1 && e.line <= lines,
                "line {} of {}",
                e.line,
                lines
            );
        }
    }
    prop_assert!(
        start.elapsed().as_secs_f64() < 2.0,
        "slow: {:?}",
        start.elapsed()
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn random_data_files_never_panic_or_hang(tokens in prop::collection::vec(data_token(), 0..40)) {
        check_reader(&tokens.join(" "))?;
    }

    #[test]
    fn mutated_data_files_never_panic_or_hang(
        counts in prop::collection::vec(2usize..5, 1..4),
        irregular in prop::collection::vec(any::<bool>(), 4),
        values in prop::collection::vec(-10.0f64..10.0, 1..8),
        cut in any::<prop::sample::Index>(),
        insert in data_token(),
    ) {
        let text = data_text(&counts, &irregular, &values);
        check_reader(&text)?;
        let at = cut.index(text.len() + 1);
        let mut mutated = text.clone();
        mutated.truncate(at);
        check_reader(&mutated)?;
        let mut spliced = text[..at].to_string();
        spliced.push(' ');
        spliced.push_str(&insert);
        spliced.push(' ');
        spliced.push_str(&text[at..]);
        check_reader(&spliced)?;
    }
}

fn font_token() -> impl Strategy<Value = String> {
    prop_oneof![
        (0i32..300).prop_map(|n| n.to_string()),
        Just("32 0".to_string()),
        Just("-1".to_string()),
        Just("99999999999".to_string()),
        Just("\n".to_string()),
        Just("#".to_string()),
        "[a-z.+-]{1,3}",
    ]
}

proptest! {
    /// Random font files, and the test font cut and spliced: the reader and the text laid out
    /// in it (the `fnt` fuzz harness) never panic, and an error names the file.
    #[test]
    fn random_and_mutated_font_files_never_panic(
        tokens in prop::collection::vec(font_token(), 0..60),
        cut in any::<prop::sample::Index>(),
        insert in font_token(),
    ) {
        let harness = skylux_hps::fuzzing::harness("fnt").unwrap();
        harness(tokens.join(" ").as_bytes());
        let font = include_str!("fixtures/text/block.fnt");
        let at = cut.index(font.len() + 1);
        let mut cut_short = font.as_bytes().to_vec();
        cut_short.truncate(at);
        harness(&cut_short);
        let spliced = format!("{} {insert} {}", &font[..at], &font[at..]);
        harness(spliced.as_bytes());
    }
}
