//! The RADIANCE picture reader (`picture::rgbe`): against RADIANCE's own tools (pvalue's
//! decoded values, pfilt's EXPOSURE, protate's and pflip's orientations against their
//! `-c` corrected copies), every scanline form by hand-made bytes, clear errors, and fuzzing.

mod common;

use common::radiance::{check_output, radiance_or_skip, tool};
use proptest::prelude::*;
use skylux_hps::picture::rgbe::{parse_hdr, read_hdr, HdrPicture, PixelFormat};
use std::path::{Path, PathBuf};

fn corpus_image() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(
        "../../../shared/data/radiance-corpus/glare-testimage/resources/evalglare/testimage.hdr",
    )
}

fn run(
    bin: &Path,
    lib: &Option<PathBuf>,
    dir: &Path,
    name: &str,
    args: &[&str],
    out: &str,
) -> PathBuf {
    let mut c = tool(bin, lib, name);
    c.current_dir(dir).args(args);
    let path = dir.join(out);
    std::fs::write(&path, check_output(c, None)).unwrap();
    path
}

/// Every pixel of `ours` equals pvalue's original value (`-o`, exposure undone) within its
/// printed precision, in pvalue's top-to-bottom order.
fn assert_matches_pvalue(bin: &Path, lib: &Option<PathBuf>, path: &Path, ours: &HdrPicture) {
    let mut c = tool(bin, lib, "pvalue");
    c.args(["-h", "-H", "-o", "-d"]).arg(path);
    let text = String::from_utf8(check_output(c, None)).unwrap();
    let values: Vec<[f64; 3]> = text
        .lines()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|t| t.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    assert_eq!(values.len(), ours.pixels.len(), "{}", path.display());
    for (i, (p, q)) in ours.pixels.iter().zip(&values).enumerate() {
        for k in 0..3 {
            let (a, b) = (f64::from(p[k]), q[k]);
            assert!(
                (a - b).abs() <= 1e-3 * b.abs() + 1e-30,
                "{} pixel {i} channel {k}: ours {a}, pvalue {b}",
                path.display()
            );
        }
    }
}

#[test]
fn matches_radiance_tools() {
    let Some((bin, lib)) = radiance_or_skip() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let corpus = read_hdr(&corpus_image()).unwrap();
    assert_eq!((corpus.width_px, corpus.height_px), (786, 786));
    assert_eq!(
        corpus.view.as_deref(),
        Some("-vta -vv 182 -vh 182 -vp 0 0 0 -vd 0 0 1 -vu 0 1 0")
    );
    assert_eq!(corpus.exposure, 1.0);
    assert_matches_pvalue(&bin, &lib, &corpus_image(), &corpus);

    let image = corpus_image();
    let image = image.to_str().unwrap();
    let exposed = run(
        &bin,
        &lib,
        dir.path(),
        "pfilt",
        &["-1", "-e", "3", "-x", "/4", "-y", "/4", image],
        "exp.hdr",
    );
    let picture = read_hdr(&exposed).unwrap();
    assert!(
        (picture.exposure - 3.0).abs() < 1e-9,
        "{}",
        picture.exposure
    );
    assert_matches_pvalue(&bin, &lib, &exposed, &picture);

    // Without -c, protate and pflip keep the picture and only reorder its scanlines (the
    // resolution line becomes +X +Y, +Y +X, +Y -X): it must read back as the same picture.
    // With -c they rotate or flip the picture itself, in the standard order.
    let e = exposed.to_str().unwrap();
    let (w, h) = (picture.width_px as usize, picture.height_px as usize);
    let at =
        |p: &HdrPicture, column: usize, row: usize| p.pixels[row * p.width_px as usize + column];
    let transforms: [(&str, &[&str], &PixelMap<'_>); 3] = [
        // Clockwise: output (column c, row r) shows input (column r, row h − 1 − c).
        ("protate", &[], &|c, r| (r, h - 1 - c)),
        ("pflip", &["-v"], &|c, r| (c, h - 1 - r)),
        ("pflip", &["-h", "-v"], &|c, r| (w - 1 - c, h - 1 - r)),
    ];
    for (name, args, source_of) in transforms {
        let plain_args: Vec<&str> = args.iter().copied().chain([e]).collect();
        let plain = run(&bin, &lib, dir.path(), name, &plain_args, "plain.hdr");
        let plain = read_hdr(&plain).unwrap();
        assert!(plain.pixels == picture.pixels, "{name} {args:?} without -c");
        let c_args: Vec<&str> = ["-c"]
            .into_iter()
            .chain(args.iter().copied())
            .chain([e])
            .collect();
        let turned = read_hdr(&run(&bin, &lib, dir.path(), name, &c_args, "turned.hdr")).unwrap();
        for row in 0..turned.height_px as usize {
            for column in 0..turned.width_px as usize {
                let (c, r) = source_of(column, row);
                assert_eq!(
                    at(&turned, column, row),
                    at(&picture, c, r),
                    "{name} -c {args:?}"
                );
            }
        }
    }
}

/// Which input pixel (column, row) an output pixel (column, row) shows.
type PixelMap<'a> = dyn Fn(usize, usize) -> (usize, usize) + 'a;

/// A header, resolution line and body as bytes.
fn file(header: &str, resolution: &str, body: &[u8]) -> Vec<u8> {
    let mut out = format!("#?RADIANCE\n{header}\n{resolution}\n").into_bytes();
    out.extend_from_slice(body);
    out
}

/// RGBE of (m, m, m) at exponent 128 + 8 + k: value (m + ½) 2^k.
fn grey(m: u8) -> [u8; 4] {
    [m, m, m, 136]
}

#[test]
fn reads_every_scanline_form_and_orientation() {
    let path = Path::new("hand.hdr");
    // Flat pixels (a 3-pixel scanline is below new-style RLE's minimum of 8).
    let body: Vec<u8> = (0..6u8).flat_map(|k| grey(10 * k)).collect();
    let p = parse_hdr(path, &file("FORMAT=32-bit_rle_rgbe\n", "-Y 2 +X 3", &body)).unwrap();
    let v: Vec<f32> = p.pixels.iter().map(|c| c[0]).collect();
    assert_eq!(v, [0.5, 10.5, 20.5, 30.5, 40.5, 50.5]);
    // +Y: the first scanline is the bottom row; -X: right to left.
    let p = parse_hdr(path, &file("", "+Y 2 -X 3", &body)).unwrap();
    let v: Vec<f32> = p.pixels.iter().map(|c| c[0]).collect();
    assert_eq!(v, [50.5, 40.5, 30.5, 20.5, 10.5, 0.5]);
    // Column-major: `-X 3 +Y 2`... scanlines are columns from the right, each from the bottom.
    let p = parse_hdr(path, &file("", "-X 3 +Y 2", &body)).unwrap();
    assert_eq!((p.width_px, p.height_px), (3, 2));
    let v: Vec<f32> = p.pixels.iter().map(|c| c[0]).collect();
    assert_eq!(v, [50.5, 30.5, 10.5, 40.5, 20.5, 0.5]);
    // Old-style RLE: 1 1 1 n repeats the previous pixel n times (n·256 for a second code).
    let mut body = grey(7).to_vec();
    body.extend_from_slice(&[1, 1, 1, 3]);
    body.extend_from_slice(&grey(9));
    let p = parse_hdr(path, &file("", "-Y 1 +X 5", &body)).unwrap();
    let v: Vec<f32> = p.pixels.iter().map(|c| c[0]).collect();
    assert_eq!(v, [7.5, 7.5, 7.5, 7.5, 9.5]);
    // New-style RLE, 10 pixels: per component a run of 6 and 4 literals.
    let mut body = vec![2, 2, 0, 10];
    for value in [5u8, 5, 5, 136] {
        body.extend_from_slice(&[128 + 6, value, 4, value, value + 1, value, value]);
    }
    let p = parse_hdr(
        path,
        &file(
            "EXPOSURE=2\nEXPOSURE=0.5\nVIEW= -vta\nVIEW= -vh 90\n",
            "-Y 1 +X 10",
            &body,
        ),
    )
    .unwrap();
    assert_eq!(p.view.as_deref(), Some("-vta -vh 90"));
    assert_eq!(p.exposure, 1.0);
    // Pixel 7: literal mantissa 6 and exponent 137, (6 + ½) × 2.
    assert_eq!(p.pixels[7][0], 13.0);
    assert_eq!(p.pixels[0][2], 5.5);
    assert_eq!(
        parse_hdr(
            path,
            &file("FORMAT=32-bit_rle_xyze\n", "-Y 1 +X 1", &grey(2))
        )
        .unwrap()
        .format,
        PixelFormat::Xyze
    );
}

fn error_of(bytes: &[u8]) -> String {
    parse_hdr(Path::new("bad.hdr"), bytes)
        .unwrap_err()
        .to_string()
}

#[test]
fn bad_files_get_clear_errors() {
    let good = std::fs::read(corpus_image()).unwrap();
    let truncated = error_of(&good[..good.len() / 2]);
    assert!(truncated.starts_with("bad.hdr: scanline "), "{truncated}");
    assert!(truncated.contains("truncated"), "{truncated}");
    let e = error_of(b"P6\n3 2\n255\n");
    assert!(e.contains("not a RADIANCE picture"), "{e}");
    let e = error_of(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n");
    assert!(
        e.contains("header line 3") && e.contains("ends inside the header"),
        "{e}"
    );
    let e = error_of(&file("SOFTWARE= x\nEXPOSURE=-2", "-Y 1 +X 1", &grey(1)));
    assert!(
        e.contains("header line 3") && e.contains("EXPOSURE `-2`"),
        "{e}"
    );
    let e = error_of(&file("FORMAT=ascii", "-Y 1 +X 1", &grey(1)));
    assert!(e.contains("FORMAT `ascii`"), "{e}");
    let e = error_of(&file("", "-Y 1 -Y 1", &grey(1)));
    assert!(
        e.contains("line 3") && e.contains("not a resolution line"),
        "{e}"
    );
    let e = error_of(&file("", "-Y 100000 +X 100000", &[]));
    assert!(e.contains("more than"), "{e}");
    let e = error_of(&file("", "-Y 1 +X 10", &[2, 2, 0, 9, 0]));
    assert!(e.contains("says 9 pixels, the picture 10"), "{e}");
    let e = error_of(&file("", "-Y 1 +X 2", &[1, 1, 1, 5]));
    assert!(e.contains("bad repeat code"), "{e}");
    let e = read_hdr(Path::new("/nonexistent/x.hdr"))
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("/nonexistent/x.hdr: "), "{e}");
}

/// A small valid run-length-encoded picture to mutate.
fn small_picture() -> Vec<u8> {
    let mut body = Vec::new();
    for row in 0..3u8 {
        body.extend_from_slice(&[2, 2, 0, 12]);
        for c in 0..4u8 {
            body.extend_from_slice(&[128 + 8, row * 10 + c, 4, 1, 2, 3, 4]);
        }
    }
    file(
        "FORMAT=32-bit_rle_rgbe\nVIEW= -vta -vh 180 -vv 180",
        "-Y 3 +X 12",
        &body,
    )
}

/// Reading never panics, ends quickly, and an error names the file.
fn check(bytes: &[u8]) -> Result<(), TestCaseError> {
    let start = std::time::Instant::now();
    let outcome = parse_hdr(Path::new("fuzz.hdr"), bytes);
    prop_assert!(start.elapsed().as_secs_f64() < 2.0);
    match outcome {
        Ok(p) => prop_assert_eq!(p.pixels.len(), (p.width_px * p.height_px) as usize),
        Err(e) => prop_assert!(e.to_string().starts_with("fuzz.hdr: "), "{}", e),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        check(&bytes)?;
        let mut with_magic = b"#?RADIANCE\n\n-Y 4 +X 9\n".to_vec();
        with_magic.extend_from_slice(&bytes);
        check(&with_magic)?;
    }

    #[test]
    fn mutated_pictures_never_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0..3u8), 1..8),
        cut in any::<prop::sample::Index>(),
    ) {
        let mut bytes = small_picture();
        for (at, value, kind) in edits {
            let i = at.index(bytes.len());
            match kind {
                0 => bytes[i] = value,
                1 => bytes.insert(i, value),
                _ => { bytes.remove(i); }
            }
        }
        check(&bytes)?;
        let end = cut.index(bytes.len() + 1);
        check(&bytes[..end])?;
    }
}
