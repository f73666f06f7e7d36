//! Inline commands expanded natively against the real programs from the pyradiance wheel, run
//! live: each command line is written into a scene file and expanded by Skylux, and run by
//! `/bin/sh` with RADIANCE on the PATH; the two primitive lists must be equal (names, types,
//! strings) with reals equal within the programs' printed precision.

mod common;

use common::primitives::{assert_same, theirs};
use common::radiance::radiance_or_skip;
use skylux_hps::scene::{self, LoadOptions, Primitive};
use std::path::Path;

/// What Skylux expands `!command` to, from a scene file in `dir`.
fn ours(dir: &Path, command: &str) -> Vec<Primitive> {
    let file = dir.join("case.rad");
    std::fs::write(&file, format!("!{command}\n")).unwrap();
    scene::expand_files(&[&file], &LoadOptions::default())
        .unwrap_or_else(|e| panic!("{command}: {e}"))
}

/// Geometry written with `%18.12g` or more digits.
const GEOMETRY: (f64, f64) = (1e-9, 1e-10);
/// Skies: `%.3e` and `%f`.
const SKY: (f64, f64) = (1.5e-6, 1e-3);

fn compare_all(commands: &[&str], tolerance: (f64, f64), setup: impl Fn(&Path)) -> usize {
    let Some((bin, lib)) = radiance_or_skip() else {
        return 0;
    };
    let dir = tempfile::tempdir().unwrap();
    setup(dir.path());
    for command in commands {
        let mine = ours(dir.path(), command);
        let reference = theirs(&bin, &lib, dir.path(), command);
        assert!(!reference.is_empty(), "{command}: RADIANCE wrote nothing");
        assert_same(command, &mine, &reference, tolerance.0, tolerance.1);
    }
    commands.len()
}

#[test]
fn genbox_as_radiance() {
    compare_all(
        &[
            "genbox wall w 1 2 3",
            "genbox wall w 6.1 0.2 3.06",
            "genbox m b 1 2 3 -i",
            "genbox m b 1 2 3 -b 0.1",
            "genbox m b 1 2 3 -i -b 0.2",
            "genbox m b 0.5 0.5 4 -r 0.1",
            "genbox m b 2 2 2 -r 0.5 -s",
            "genbox m b 1e-3 2e3 7",
            "genbox m b 1 1 1 -b 0.4",
        ],
        GEOMETRY,
        |_| {},
    );
}

#[test]
fn genblinds_as_radiance() {
    compare_all(
        &[
            "genblinds blind b 0.05 1.2 1.5 20 30",
            "genblinds blind b 0.05 1.2 1.5 20 -45",
            "genblinds blind b 0.025 0.8 1 5 0",
            "genblinds blind b 0.05 1.2 1.5 10 30 -r 0.1",
            "genblinds blind b 0.05 1.2 1.5 10 30 +r 0.1",
            "genblinds blind b 0.08 1 2 3 60 -r 0.5",
            "genblinds blind b 0.08 1 2 3 -20 +r 0.05",
            "genblinds blind b 0.1 1 1 1 90",
        ],
        GEOMETRY,
        |_| {},
    );
}

#[test]
fn genprism_as_radiance() {
    compare_all(
        &[
            "genprism m p 4 0 0 1 0 1 1 0 1",
            "genprism m p 3 0 0 2 0 1 1.5 -l 0 0 3",
            "genprism m p 4 0 0 1 0 1 1 0 1 -l 0.2 0.3 2 -e",
            "genprism m p 4 0 0 1 0 1 1 0 1 -c",
            "genprism m p 5 0 0 2 0 2 1 1 2 0 1 -l 0 0 -1",
            "genprism m p 4 0 0 1 0 1 1 0 1 -r 0.1",
            "genprism m p 5 0 0 2 0 2 1 1 2 0 1 -r 0.2 -l 0 0 1.5",
            "genprism m p 4 0 0 1 0 1 1 0 1 -r 0.1 -l 0 0 -1",
            "genprism m p verts.txt -l 0 0 2",
        ],
        GEOMETRY,
        |dir| std::fs::write(dir.join("verts.txt"), "0 0\n3 0\n3 2\n1.5 3\n0 2\n").unwrap(),
    );
}

#[test]
fn genrev_as_radiance() {
    compare_all(
        &[
            "genrev m vase 't' '0.5+0.2*sin(PI*t)' 8",
            "genrev m c 't*2' '1' 4",
            "genrev m disk '0' '1-t' 3",
            "genrev m cone 't' 't' 5",
            "genrev m bowl '1-cos(PI/2*t)' 'sin(PI/2*t)' 16",
            "genrev m down '1-t' '0.3+t^2' 6",
            "genrev m h 't' 'hermite(0.2,0.4,1,-1,t)' 7",
            "genrev m mixed 'floor(t*2)/2' '0.5+0.5*t' 4",
            "genrev m k 't' 'a+b*t' 5 -e 'a=0.2;b=0.3'",
            "genrev m f 'zf(t)' 'rf(t)' '2+3' -f prof.cal",
            "genrev m f2 'zf(t)' 'rf(t)' 6 -e 'k=2' -f prof.cal -s",
            "genrev m s 't' '0.5+0.2*sin(PI*t)' 8 -s",
            "genrev m sb '1-cos(PI/2*t)' 'sin(PI/2*t)' 5 -s",
            "genrev m sd '0' '1-t' 3 -s",
            "genrev m sr '1-t' '0.3+t^2' 2.7 -s",
        ],
        GEOMETRY,
        |dir| {
            std::fs::write(
                dir.join("prof.cal"),
                "{ a profile }\nk = 1;\nzf(t) = k*t;\nrf(t) = 0.4 + 0.1*cos(2*PI*t) + bezier(0,0.2,0.1,0,t);\n",
            )
            .unwrap()
        },
    );
}

#[test]
fn genworm_as_radiance() {
    compare_all(
        &[
            "genworm m w 't' '0' '0' '0.1' 2",
            "genworm m w 't' '0' '0' '0.1+t' 1",
            "genworm m helix 'cos(2*PI*t)' 'sin(2*PI*t)' 't' '0.05' 24",
            "genworm m taper 'cos(2*PI*t)' 'sin(2*PI*t)' 't' '0.1-0.05*t' 12",
            "genworm m blob 't' 't*t' '0' '0.2*(1+sin(6*t))' 9",
            "genworm m d 't' '0' '0' '1-t' 2",
            "genworm m h 'hermite(0,1,1,0,t)' 'bspline(0,1,0,1,t)' '0' '0.02' '3*2'",
            "genworm m f 'xf(t)' 'yf(t)' 't/2' 'r0*(1+t)' 7 -e 'r0=0.03' -f worm.cal",
        ],
        GEOMETRY,
        |dir| {
            std::fs::write(
                dir.join("worm.cal"),
                "xf(t) = 2*t;\nyf(t) = sq(t) - t;\nsq(x) : x*x;\n",
            )
            .unwrap()
        },
    );
}

#[test]
fn gensurf_as_radiance() {
    compare_all(
        &[
            "gensurf m s 't' 's' '0' 2 2",
            "gensurf m s 's' 't' 's*t' 3 4",
            "gensurf m i 's' 't' 's*t' 3 4 -i",
            "gensurf m sph 'sin(PI*s)*cos(2*PI*t)' 'sin(PI*s)*sin(2*PI*t)' 'cos(PI*s)' 6 8",
            "gensurf m sph 'sin(PI*s)*cos(2*PI*t)' 'sin(PI*s)*sin(2*PI*t)' 'cos(PI*s)' 6 8 -s",
            "gensurf m saddle '2*s-1' '2*t-1' '(2*s-1)^2-(2*t-1)^2' 5 5 -s",
            "gensurf m saddle '2*s-1' '2*t-1' '(2*s-1)^2-(2*t-1)^2' 5 5 -s -i",
            "gensurf m wave 's' 't' '0.1*sin(4*PI*s)' 7 3 -s",
            "gensurf m v 's' 't' 's+t' 4 4 -e 'valid(s,t)=0.9-s*t'",
            "gensurf m v 's' 't' 's*s+t' 4 4 -s -e 'valid(s,t)=1.2-s-t'",
            "gensurf m f 'xs(s,t)' 'ys(s,t)' 'h*s*t' '1+1' 3 -e 'h=2' -f surf1.cal",
            "gensurf m d 's' 't' height.dat 2 3",
            "gensurf m d 's' 't' height.dat 2 3 -s",
            "gensurf m c 's' 't' centres.dat 2 3",
            "gensurf m p points.dat points.dat points.dat 1 2",
        ],
        GEOMETRY,
        |dir| {
            std::fs::write(
                dir.join("surf1.cal"),
                "xs(s,t) = s + 0.1*t;\nys(s,t) = t;\n",
            )
            .unwrap();
            // 3 x 4 heights with the border, 2 x 3 without, 2 x 3 points of x y z.
            std::fs::write(
                dir.join("height.dat"),
                "0 0.1 0.2\n0.3 0.5 0.4\n0.2 0.3 0.6\n0.1 0 0.2\n",
            )
            .unwrap();
            std::fs::write(dir.join("centres.dat"), "0.1 0.2\n0.4 0.3\n0.5 0.1\n").unwrap();
            std::fs::write(
                dir.join("points.dat"),
                "0 0 0  1 0 0.1\n0 1 0.2  1 1 0.3\n0 2 0  1 2.2 0.5\n",
            )
            .unwrap();
        },
    );
}

#[test]
fn gensky_as_radiance() {
    compare_all(
        &[
            "gensky -ang 45 20 +s",
            "gensky -ang 45 20 -s",
            "gensky -ang 30 -60 +i",
            "gensky -ang 30 -60 -i",
            "gensky -ang 60 0 -c",
            "gensky -ang 60 0 -u",
            "gensky -ang 89 10 +s",
            "gensky -ang 10 120 +s -t 4.5 -g 0.3",
            "gensky -ang 45 20 -c -B 100",
            "gensky -ang 45 20 +s -R 600 -B 80",
            "gensky -ang 45 20 +s -r 1000 -b 20",
            "gensky 6 21 12",
            "gensky 3 21 10:30EST -a 40 -o 75 -m 90",
            "gensky 9 19 +14 -a 46.5 -o -6.6 -m -15 +i",
            "gensky 12 21 15.25 -a 51.5 -o 0.1 -m 0 -c",
            "gensky 7 4 9:15PDT",
        ],
        SKY,
        |_| {},
    );
}

#[test]
fn gendaylit_as_radiance() {
    compare_all(
        &[
            "gendaylit -ang 45 20 -W 700 120",
            "gendaylit -ang 30 -40 -W 300 200 -O 1",
            "gendaylit -ang 60 10 -G 500 100 -O 2",
            "gendaylit -ang 20 80 -P 3.2 0.2 -g 0.3",
            "gendaylit -ang 45 20 -W 700 120 -s",
            "gendaylit 9 19 10:30EDT -m 75 -o 73.96 -a 40.78 -W 706 162",
            "gendaylit 6 21 12 -a 46.5 -o -6.6 -m -15 -W 800 90 -d 15",
            "gendaylit 3 21 +14 -a 40 -o 75 -m 75 -W 400 150",
        ],
        SKY,
        |_| {},
    );
}

/// A file holding one primitive of each type xform treats apart.
const PARTS: &str = "\
void plastic white 0 0 5 .5 .5 .5 0 0
void brightfunc pat 2 skybr skybright.cal 0 3 1 2 3
void glow lamp 0 0 4 1 1 1 2.5
void spotlight spot 0 0 7 10 10 10 30 0 0 -1
void dielectric water 0 0 5 .9 .8 .7 1.33 0
void mist fog 1 src1>src2 0 3 .1 .2 .3
white polygon floor 0 0 12 0 0 0 4 0 0 4 3 0 0 3 0
white sphere ball 0 0 4 1 2 3 0.5
white cone c 0 0 8 0 0 0 0 0 1 0.5 0.25
white cup cu 0 0 8 0 0 0 0 0 1 0.5 0.25
white cylinder cyl 0 0 7 1 1 0 1 1 2 0.1
white tube tb 0 0 7 1 1 0 1 1 2 0.1
white ring r 0 0 8 2 2 1 0 0 1 0.1 0.3
lamp source s 0 0 4 0 1 1 5
white bubble bb 0 0 4 0 0 0 1
white instance inst 3 part.oct -rz 10 0 0
";

const NESTED: &str = "\
!genbox white box 1 1 1
!xform -n inner -rz 30 parts.rad
!genblinds white bl 0.05 1 1 4 30 | xform -rx 90 -t 0 0 1
";

#[test]
fn xform_as_radiance() {
    compare_all(
        &[
            "xform parts.rad",
            "xform -t 1 2 3 parts.rad",
            "xform -rx 30 parts.rad",
            "xform -ry -45 -t 1 0 0 parts.rad",
            "xform -rz 90 -s 2 parts.rad",
            "xform -mx parts.rad",
            "xform -my -mz parts.rad",
            "xform -s 0.3048 -rz 15 parts.rad",
            "xform -I parts.rad",
            "xform -I -mx parts.rad",
            "xform -m other -n pre parts.rad",
            "xform -n a -n b -t 1 1 1 parts.rad",
            "xform -e -a 3 -t 2 0 0 parts.rad",
            "xform -n row -a 2 -t 0 3 0 -a 3 -rz 20 parts.rad",
            "xform -t 1 0 0 -i 3 -rz 90 parts.rad",
            "xform -rz 45 parts.rad parts.rad",
            "xform -e nested.rad",
            "xform -e -rx 90 -t 5 5 0 nested.rad",
            "xform -e -a 2 -t 10 0 0 nested.rad",
            "xform -s 2 sub/inc.rad",
            "genbox white b 1 2 3 | xform -rz 30 | xform -s 2 -t 1 1 1",
            "genprism white p 3 0 0 1 0 0 1 | xform -e -a 4 -rz 90",
        ],
        GEOMETRY,
        |dir| {
            std::fs::write(dir.join("parts.rad"), PARTS).unwrap();
            std::fs::write(dir.join("nested.rad"), NESTED).unwrap();
            std::fs::create_dir(dir.join("sub")).unwrap();
            // Relative to its own directory, as xform reads it.
            std::fs::write(dir.join("sub/inc.rad"), "!xform -t 0 0 1 ../parts.rad\n").unwrap();
        },
    );
}
