//! The `.cal` evaluator against RADIANCE's `rcalc`, run live on the same files and the same
//! random inputs: rayinit.cal's functions, skybright.cal, perezlum.cal, winxmit.cal and a
//! hand-written file using every operator, `if`, `select`, `rand`, recursion, functions
//! passed as arguments and constants. rcalc gets the ray variables as input columns
//! (`Dx=$1;...`) and `arg(n)` as a `select` over further columns; it answers in binary
//! doubles (`-od`), so the comparison sees every digit. Without RADIANCE the tests print
//! SKIPPED and pass, unless `SKYLUX_REQUIRE_RADIANCE` is set.

mod common;

use std::path::{Path, PathBuf};

use common::radiance::{check_output, radiance_or_skip, tool};
use rand::{rngs::StdRng, Rng, SeedableRng};
use skylux_hps::cal::{CalProgram, Evaluator, RayValues, RayVariable};

/// Largest relative difference accepted; the absolute floor covers results that cancel to
/// about zero (their rounding then differs only in the last bits of the operands).
const RELATIVE_TOLERANCE: f64 = 1e-9;
const ABSOLUTE_FLOOR: f64 = 1e-12;
const ROWS: usize = 400;

fn radiance_lib(lib: &Option<PathBuf>) -> PathBuf {
    lib.clone()
        .expect("RADIANCE's lib folder (RAYPATH) is needed for its .cal files")
}

fn examples_lib() -> PathBuf {
    let data = std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data"));
    data.join("radiance-corpus/radiance-examples/lib")
}

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/cal")
        .join(name)
}

fn unit_vector(rng: &mut StdRng) -> [f64; 3] {
    loop {
        let v: [f64; 3] = std::array::from_fn(|_| rng.gen_range(-1.0..1.0));
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if n > 0.1 && n <= 1.0 {
            return v.map(|x| x / n);
        }
    }
}

/// A random ray: unit directions and normals, points in a 10-unit box, a distance up to 50.
fn random_ray(rng: &mut StdRng, real_arguments: Vec<f64>) -> RayValues {
    use RayVariable as V;
    let mut ray = RayValues::default();
    for v in RayVariable::ALL {
        ray.set(v, rng.gen_range(-5.0..5.0));
    }
    for group in [
        [V::Dx, V::Dy, V::Dz],
        [V::Nx, V::Ny, V::Nz],
        [V::NxP, V::NyP, V::NzP],
    ] {
        let u = unit_vector(rng);
        for (v, x) in group.into_iter().zip(u) {
            ray.set(v, x);
        }
    }
    for v in [V::Rdot, V::RdotP] {
        ray.set(v, rng.gen_range(-1.0..1.0));
    }
    for v in [V::T, V::Ts, V::S] {
        ray.set(v, rng.gen_range(0.0..50.0));
    }
    ray.real_arguments = real_arguments;
    ray
}

/// One comparison: files loaded in order, expressions evaluated on random rays.
struct Case<'a> {
    files: Vec<PathBuf>,
    expressions: &'a [&'a str],
    real_arguments: &'a dyn Fn(&mut StdRng) -> Vec<f64>,
}

/// The rcalc definitions that feed it one ray per input line.
fn rcalc_inputs(argument_count: usize) -> String {
    let mut defs: String = RayVariable::ALL
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{}=${};", v.name(), i + 1))
        .collect();
    let first = RayVariable::ALL.len() + 1;
    let columns: String = (0..argument_count)
        .map(|i| format!(",${}", first + i))
        .collect();
    defs.push_str(&format!("arg(n)=select(n+1,{argument_count}{columns});"));
    defs
}

fn rcalc_values(bin: &Path, lib: &Option<PathBuf>, case: &Case, rays: &[RayValues]) -> Vec<f64> {
    let argument_count = rays[0].real_arguments.len();
    let mut command = tool(bin, lib, "rcalc");
    command
        .arg("-od")
        .arg("-e")
        .arg(rcalc_inputs(argument_count));
    for f in &case.files {
        command.arg("-f").arg(f);
    }
    let outputs: String = case
        .expressions
        .iter()
        .enumerate()
        .map(|(i, e)| format!("${}=({e});", i + 1))
        .collect();
    command.arg("-e").arg(outputs);
    let input: String = rays
        .iter()
        .map(|r| {
            let fields: Vec<String> = r
                .values
                .iter()
                .chain(&r.real_arguments)
                .map(|x| format!("{x:e}"))
                .collect();
            fields.join(" ") + "\n"
        })
        .collect();
    // Through a file: piped while rcalc answers, input and output would fill both pipes.
    let dir = tempfile::tempdir().unwrap();
    let rows = dir.path().join("rays.txt");
    std::fs::write(&rows, input).unwrap();
    command.arg(&rows);
    let out = check_output(command, None);
    assert_eq!(
        out.len(),
        rays.len() * case.expressions.len() * 8,
        "rcalc's output size"
    );
    out.chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
        .collect()
}

fn our_values(case: &Case, rays: &[RayValues]) -> Vec<f64> {
    let mut program = CalProgram::new();
    for f in &case.files {
        program.load_file(f).unwrap_or_else(|e| panic!("{e}"));
    }
    let checks: String = case
        .expressions
        .iter()
        .enumerate()
        .map(|(i, e)| format!("check.{i} = {e};\n"))
        .collect();
    program.load_str("checks", &checks).unwrap();
    let mut evaluator = Evaluator::new(&program);
    let mut values = Vec::new();
    for ray in rays {
        for (i, e) in case.expressions.iter().enumerate() {
            let v = evaluator
                .variable(&format!("check.{i}"), ray)
                .unwrap_or_else(|err| panic!("{e}: {err}"));
            values.push(v);
        }
    }
    values
}

/// Evaluates `case` on random rays both ways; returns the largest relative difference.
fn compare(case: &Case, seed: u64) -> Option<f64> {
    let (bin, lib) = radiance_or_skip()?;
    let mut rng = StdRng::seed_from_u64(seed);
    let rays: Vec<RayValues> = (0..ROWS)
        .map(|_| {
            let args = (case.real_arguments)(&mut rng);
            random_ray(&mut rng, args)
        })
        .collect();
    let theirs = rcalc_values(&bin, &lib, case, &rays);
    let ours = our_values(case, &rays);
    let mut worst: f64 = 0.0;
    for (k, (a, b)) in ours.iter().zip(&theirs).enumerate() {
        let expression = case.expressions[k % case.expressions.len()];
        let scale = a.abs().max(b.abs());
        let difference = (a - b).abs();
        assert!(
            difference <= RELATIVE_TOLERANCE * scale + ABSOLUTE_FLOOR,
            "{expression} on ray {}: ours {a:e}, rcalc {b:e}",
            k / case.expressions.len()
        );
        if scale > 0.0 {
            worst = worst.max(difference / scale);
        }
    }
    println!(
        "{} expressions x {ROWS} rays of {:?}: worst relative difference {worst:.2e}",
        case.expressions.len(),
        case.files
            .iter()
            .map(|f| f.file_name().unwrap())
            .collect::<Vec<_>>()
    );
    Some(worst)
}

fn no_arguments(_: &mut StdRng) -> Vec<f64> {
    Vec::new()
}

#[test]
fn rayinit_functions_match_rcalc() {
    let Some((_, lib)) = radiance_or_skip() else {
        return;
    };
    let expressions = [
        "bound(Px, Py, Pz)",
        "Acos(Dx * 1.2)",
        "Asin(Dy * 1.1)",
        "Atan2(Dy, Dx)",
        "Exp(Px * 30)",
        "Sqrt(Px)",
        "and(Px, Py)",
        "or(Px, Py)",
        "not(Px)",
        "xor(Px, Py)",
        "abs(Px)",
        "sgn(Py)",
        "sq(Pz)",
        "inside(Px, Py, Pz)",
        "frac(Px)",
        "mod(Px, Py)",
        "tri(Px, Py)",
        "linterp(Dx, Px, Py)",
        "noop(Pz)",
        "clip(Px)",
        "noneg(Py)",
        "red(Px, Py, Pz)",
        "green(Px, Py, Pz)",
        "blue(Px, Py, Pz)",
        "grey(Px, Py, Pz)",
        "clip_r(Px, Py, Pz)",
        "clip_g(Px, Py, Pz)",
        "clip_b(Px, Py, Pz)",
        "clipgrey(Px, Py, Pz)",
        "dot(D, N)",
        "cross(1, D, N)",
        "cross(2, D, N)",
        "cross(3, D, N)",
        "fade(Px, Py, T)",
        "hermite(Px, Py, Pz, Dx, Dy)",
        "bezier(Px, Py, Pz, T, Dz)",
        "bspline(Px, Py, Pz, T, Dz)",
        "AC",
        "A1",
        "A2",
        "A5",
        "D(2)",
        "N(3)",
        "P(1)",
        "PI",
        "DEGREE",
        "FTINY",
        "rand(Px)",
        "nrand(Px)",
        "unif2norm(Dx * 0.5 + 0.5)",
        "U",
        "V",
        "Idx",
        "Idy",
        "Idz",
        "Ldx(Dx, Dy, Dz)",
        "min(Px, Py, Pz)",
        "max(Px, Py, Pz, T)",
    ];
    let case = Case {
        files: vec![radiance_lib(&lib).join("rayinit.cal")],
        expressions: &expressions,
        real_arguments: &|rng: &mut StdRng| (0..5).map(|_| rng.gen_range(-3.0..3.0)).collect(),
    };
    assert!(compare(&case, 19).is_some());
}

#[test]
fn skybright_matches_rcalc() {
    let Some((_, lib)) = radiance_or_skip() else {
        return;
    };
    let lib = radiance_lib(&lib);
    // gensky's arguments: sky type 1..4, zenith and ground brightness, normalisation, sun.
    let sky_arguments = |rng: &mut StdRng| {
        let sun = loop {
            let s = unit_vector(rng);
            if s[2] > 0.05 {
                break s;
            }
        };
        let mut a = vec![
            rng.gen_range(1..=4) as f64,
            rng.gen_range(100.0..5000.0),
            rng.gen_range(0.0..100.0),
            rng.gen_range(0.5..3.0),
        ];
        a.extend(sun);
        a
    };
    let expressions = [
        "skybr",
        "sunnysky",
        "cloudysky",
        "unifsky",
        "intersky",
        "gamma",
        "zt",
        "eta",
        "wmean(Px, Py, Pz, T)",
    ];
    let case = Case {
        files: vec![lib.join("rayinit.cal"), lib.join("skybright.cal")],
        expressions: &expressions,
        real_arguments: &sky_arguments,
    };
    assert!(compare(&case, 20).is_some());
}

#[test]
fn perezlum_matches_rcalc() {
    let Some((_, lib)) = radiance_or_skip() else {
        return;
    };
    let lib = radiance_lib(&lib);
    // gendaylit's arguments: diffuse normalisation, ground brightness, Perez a..e, sun.
    let perez_arguments = |rng: &mut StdRng| {
        let sun = loop {
            let s = unit_vector(rng);
            if s[2] > 0.02 {
                break s;
            }
        };
        let mut a = vec![
            rng.gen_range(1.0..50.0),
            rng.gen_range(0.0..30.0),
            rng.gen_range(-1.5..1.5),
            rng.gen_range(-1.0..-0.05),
            rng.gen_range(0.0..10.0),
            rng.gen_range(-3.0..0.0),
            rng.gen_range(0.0..1.0),
        ];
        a.extend(sun);
        a
    };
    let expressions = ["skybright", "intersky", "cosgamma", "gamma", "zt", "eta"];
    let case = Case {
        files: vec![lib.join("rayinit.cal"), lib.join("perezlum.cal")],
        expressions: &expressions,
        real_arguments: &perez_arguments,
    };
    assert!(compare(&case, 21).is_some());
}

#[test]
fn winxmit_matches_rcalc() {
    let Some((_, lib)) = radiance_or_skip() else {
        return;
    };
    let case = Case {
        files: vec![
            radiance_lib(&lib).join("rayinit.cal"),
            examples_lib().join("winxmit.cal"),
        ],
        expressions: &["winxmit"],
        real_arguments: &no_arguments,
    };
    assert!(compare(&case, 22).is_some());
}

#[test]
fn every_operator_matches_rcalc() {
    let expressions = [
        "neg.pow",
        "pow.right",
        "sub.left",
        "div.left",
        "mixed",
        "unary.plus",
        "sci",
        "div.zero",
        "HALF",
        "QUARTER",
        "scaled",
        "sign.of(Px)",
        "branch",
        "pick",
        "count",
        "lo",
        "hi",
        "fact.T",
        "fib.T",
        "passed",
        "lib.sum",
        "hash",
    ];
    let case = Case {
        files: vec![fixture("every_operator.cal")],
        expressions: &expressions,
        real_arguments: &no_arguments,
    };
    compare(&case, 23);
}

#[test]
fn later_files_override_earlier_ones_as_in_rcalc() {
    let case = Case {
        files: vec![
            fixture("override_first.cal"),
            fixture("override_second.cal"),
        ],
        // `user` keeps the first K (calcomp folds a constant when it reads it), the new g.
        expressions: &["user", "base", "K", "g(Py)"],
        real_arguments: &no_arguments,
    };
    compare(&case, 24);
}

// Malformed files and hostile input: a clear error naming file and line, never a panic or
// a hang. (Here rather than in a file of their own to share this test binary's build.)

fn load_error(text: &str) -> String {
    let mut program = CalProgram::new();
    match program.load_str("bad.cal", text) {
        Ok(()) => panic!("{text:?} was accepted"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn malformed_files_name_file_and_line() {
    let cases = [
        ("a = 1;\nb = (2 + 3;\n", "bad.cal, line 2: ')' expected"),
        (
            "a = 1;\n\n{ open comment\n",
            "bad.cal, line 3: '}' expected",
        ),
        ("a = 1;\nb 2;\n", "bad.cal, line 2: '=' or ':' expected"),
        ("a = 1 b = 2;", "bad.cal, line 1: ';' expected"),
        ("a = 3 # 4;", "bad.cal, line 1: unexpected character '#'"),
        ("a = 1e+;", "bad.cal, line 1: missing exponent"),
        ("a = .;", "bad.cal, line 1: badly formed number"),
        ("a = --b;", "bad.cal, line 1: unexpected character"),
        ("f(x,) = x;", "bad.cal, line 1: name expected"),
        ("a = $1;", "bad.cal, line 1: '$' channels belong to rcalc"),
    ];
    for (text, expected) in cases {
        let message = load_error(text);
        assert!(message.starts_with(expected), "{text:?}: {message}");
    }
    let deep = format!("a = {}1{};", "(".repeat(5000), ")".repeat(5000));
    assert!(load_error(&deep).contains("nested deeper"));
    let missing = Path::new("/nonexistent/skylux.cal");
    let err = CalProgram::new()
        .load_file(missing)
        .unwrap_err()
        .to_string();
    assert!(err.starts_with("/nonexistent/skylux.cal: "), "{err}");
}

#[test]
fn evaluation_errors_and_warnings_follow_calcomp() {
    let mut program = CalProgram::new();
    let text = "loop(x) = loop(x) + 1; u = nothing + 1; h(x) = x(2); v = h(3);\n\
                few = if(-1, 2); z = 1 / (Px - Px); s = select(9, 1, 2); q = sqrt(-1);\n\
                p = (-8) ^ 0.5; a2 = arg(2); a0 = arg(0); ff = fact; fact(n) = n;\n\
                fibs(n) = if(n + 60, fibs(n - 1) + fibs(n - 2), 1);";
    program.load_str("t.cal", text).unwrap();
    let mut ev = Evaluator::new(&program);
    let ray = RayValues {
        real_arguments: vec![4.0, 9.0],
        ..Default::default()
    };
    let err = |ev: &mut Evaluator, name: &str| ev.variable(name, &ray).unwrap_err().to_string();
    assert!(err(&mut ev, "u").contains("nothing: undefined variable"));
    assert!(err(&mut ev, "v").contains("argument not a function"));
    assert!(err(&mut ev, "few").contains("if(): too few arguments"));
    assert!(err(&mut ev, "ff").contains("fact: a function used as a variable"));
    let deep = ev.call("loop", &[1.0], &ray).unwrap_err().to_string();
    assert!(deep.contains("loop(): recursion deeper than"), "{deep}");
    let long = ev.call("fibs", &[5.0], &ray).unwrap_err().to_string();
    assert!(long.contains("evaluation longer than"), "{long}");
    // calcomp answers 0 with a warning for these.
    for name in ["z", "s", "q", "p"] {
        assert_eq!(ev.variable(name, &ray).unwrap(), 0.0, "{name}");
    }
    assert_eq!(ev.warnings().1, 4);
    assert_eq!(ev.variable("a2", &ray).unwrap(), 9.0);
    assert_eq!(ev.variable("a0", &ray).unwrap(), 2.0);
}

mod fuzz {
    use super::*;
    use proptest::prelude::*;
    use std::time::{Duration, Instant};

    const ALPHABET: &[&str] = &[
        "a", "b", "f", "x", "(", ")", ",", ";", "=", ":", "+", "-", "*", "/", "^", "1", "2.5",
        "1e3", "{", "}", "\n", " ", "if", "select", "rand", "f(x)", "x", "Dx", "arg", "$1", ".",
        "e", "`", "é",
    ];

    fn evaluate_everything(program: &CalProgram) {
        let mut ev = Evaluator::new(program);
        let ray = RayValues::default();
        for name in ["a", "b", "x", "Dx"] {
            let _ = ev.variable(name, &ray);
        }
        for name in ["f", "if", "select", "rand", "a"] {
            let _ = ev.call(name, &[0.5, 2.0], &ray);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        /// Token soup: parse errors or a program; evaluating it never panics nor hangs.
        #[test]
        fn token_soup_never_panics(tokens in prop::collection::vec(prop::sample::select(ALPHABET), 0..80)) {
            let text: String = tokens.concat();
            let start = Instant::now();
            let mut program = CalProgram::new();
            if program.load_str("fuzz.cal", &text).is_ok() {
                evaluate_everything(&program);
            }
            prop_assert!(start.elapsed() < Duration::from_secs(2));
        }

        /// A real library file with bytes changed, cut or inserted.
        #[test]
        fn mutated_library_files_never_panic(
            position in 0usize..4000, length in 0usize..40, insert in ".{0,12}", file in 0usize..3
        ) {
            let name = ["every_operator.cal", "override_first.cal", "override_second.cal"][file];
            let text = std::fs::read_to_string(fixture(name)).unwrap();
            let mut chars: Vec<char> = text.chars().collect();
            let at = position.min(chars.len());
            let end = (at + length).min(chars.len());
            chars.splice(at..end, insert.chars());
            let mutated: String = chars.into_iter().collect();
            let start = Instant::now();
            let mut program = CalProgram::new();
            if program.load_str(name, &mutated).is_ok() {
                evaluate_everything(&program);
                let mut ev = Evaluator::new(&program);
                for e in ["fact.T", "fib.T", "passed", "mixed", "hash"] {
                    let _ = ev.variable(e, &RayValues::default());
                }
            }
            prop_assert!(start.elapsed() < Duration::from_secs(2));
        }
    }
}

/// Every `.cal` file of RADIANCE's library and of its examples that rcalc reads, we read;
/// rcalc and pcomb scripts (they use `$n` channels) are not function files and are left out.
#[test]
fn every_library_file_rcalc_reads_loads() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let mut files: Vec<PathBuf> = [radiance_lib(&lib), examples_lib()]
        .iter()
        .flat_map(|dir| std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()))
        .filter(|p| p.extension().is_some_and(|e| e == "cal"))
        .collect();
    files.sort();
    let mut read_by_rcalc = 0;
    for file in &files {
        let mut rcalc = tool(&bin, &lib, "rcalc");
        rcalc.args(["-n", "-f"]).arg(file).args(["-e", "$1=0"]);
        let accepted = rcalc.output().is_ok_and(|o| o.status.success());
        let text = String::from_utf8_lossy(&std::fs::read(file).unwrap()).into_owned();
        let script = text
            .as_bytes()
            .windows(2)
            .any(|w| w[0] == b'$' && w[1].is_ascii_digit());
        if accepted && !script {
            read_by_rcalc += 1;
            let mut program = CalProgram::new();
            if let Err(e) = program.load_file(file) {
                panic!("rcalc reads {} but we do not: {e}", file.display());
            }
        }
    }
    println!(
        "{read_by_rcalc} of {} library files read by rcalc and by us",
        files.len()
    );
    assert!(read_by_rcalc > 50, "only {read_by_rcalc} files");
}
