//! The campaign's raw-frame (PGM) and capture.toml readers: exact round trips, clear errors
//! naming the file and field, and no panic on any input.

use proptest::prelude::*;
use skylux_hps::campaign::*;
use std::path::Path;

fn frame() -> RawFrame {
    let mut f = RawFrame::new(6, 4);
    for (i, v) in f.samples_dn.iter_mut().enumerate() {
        *v = (i as u16 * 173) % 4096;
    }
    f
}

#[test]
fn pgm_round_trips_and_is_big_endian() {
    let f = frame();
    let bytes = f.to_pgm();
    assert!(bytes.starts_with(b"P5\n6 4\n4095\n"));
    let first = f.samples_dn[1];
    assert_eq!(
        &bytes[14..16],
        &first.to_be_bytes(),
        "16-bit big-endian samples"
    );
    assert_eq!(RawFrame::parse(&bytes, Path::new("e0.pgm")).unwrap(), f);
    // Comments in the header are allowed by the PGM standard.
    let mut commented = b"P5\n# skylux\n6 4 # size\n4095\n".to_vec();
    commented.extend_from_slice(&bytes[12..]);
    assert_eq!(RawFrame::parse(&commented, Path::new("e0.pgm")).unwrap(), f);
}

#[test]
fn bad_frames_are_named_errors() {
    let good = frame().to_pgm();
    let cases: Vec<(Vec<u8>, &str)> = vec![
        (good.replacen(b"P5", b"P2"), "magic"),
        (good.replacen(b"4095", b"255 "), "maxval"),
        (good.replacen(b"6 4", b"5 4"), "even"),
        (good[..good.len() - 3].to_vec(), "truncated"),
        (b"P5\n6".to_vec(), "truncated"),
        (b"P5\n99999999999 4\n4095\n".to_vec(), "width"),
        (b"P5\n65536 65536\n4095\n".to_vec(), "too large"),
        (
            {
                let mut b = good.clone();
                let n = b.len();
                b[n - 2] = 0x10; // 4096 + x in the last sample
                b
            },
            "above maxval",
        ),
    ];
    for (bytes, needle) in cases {
        let e = RawFrame::parse(&bytes, Path::new("captures/a/e3.pgm"))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("captures/a/e3.pgm: ") && e.contains(needle),
            "{needle}: {e}"
        );
    }
}

trait Replacen {
    fn replacen(&self, from: &[u8], to: &[u8]) -> Vec<u8>;
}
impl Replacen for Vec<u8> {
    fn replacen(&self, from: &[u8], to: &[u8]) -> Vec<u8> {
        let at = self.windows(from.len()).position(|w| w == from).unwrap();
        [&self[..at], to, &self[at + from.len()..]].concat()
    }
}

const CAPTURE: &str = r#"
time = "2017-05-08T10:00:00+02:00"
bayer = "GRBG"
sensor_temperature_c = 24.0
[readout]
col_start = 0
row_start = 0
skip = 1
[[exposure]]
file = "e0.pgm"
exposure_us = 1.0
gain = 1.0
offset_ms = 0.0
[[exposure]]
file = "e1.pgm"
exposure_us = 500000.0
gain = 2.0
"#;

#[test]
fn capture_toml_reads_the_spec_example() {
    let c = CaptureConfig::parse(CAPTURE, Path::new("capture.toml")).unwrap();
    assert_eq!(c.bayer, BayerPattern::GRBG);
    assert_eq!(c.exposure.len(), 2);
    assert_eq!(c.exposure[1].offset_ms, 0.0, "offset_ms defaults to 0");
    assert_eq!(
        c.readout,
        Readout {
            col_start: 0,
            row_start: 0,
            skip: 1,
            bin: 1
        },
        "a file without readout.bin reads as bin = 1"
    );
    // The spec's skip mapping: raw column i -> col_start + (i / 2) * 2k + (i % 2).
    assert_eq!(Readout::active_coordinate(100, 3, 5), 100 + 2 * 6 + 1);
    // GRBG: green first, red right of it, blue below it.
    assert_eq!(
        BayerPattern::GRBG.offsets(),
        [(1, 0), (0, 0), (1, 1), (0, 1)]
    );
    assert_eq!(BayerPattern::BGGR.channel(1, 1), Channel::Red);
}

#[test]
fn bad_captures_name_the_field() {
    let cases = [
        (
            "exposure_us = 1.0",
            "exposure_us = -1.0",
            "exposure[0].exposure_us",
        ),
        (
            "exposure_us = 1.0",
            "exposure_us = nan",
            "exposure[0].exposure_us",
        ),
        ("gain = 2.0", "gain = 0.0", "exposure[1].gain"),
        (
            "file = \"e1.pgm\"",
            "file = \"../../etc/passwd\"",
            "exposure[1].file",
        ),
        ("skip = 1", "skip = 0", "readout"),
        ("col_start = 0", "col_start = 3", "readout"),
        ("bayer = \"GRBG\"", "bayer = \"RGBW\"", "line 3"),
    ];
    for (from, to, needle) in cases {
        let e = CaptureConfig::parse(&CAPTURE.replace(from, to), Path::new("c/capture.toml"))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("c/capture.toml: ") && e.contains(needle),
            "{to}: {e}"
        );
    }
}

proptest! {
    /// Neither reader panics on any input.
    #[test]
    fn readers_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..200), cut in 0usize..400, junk in "[\\[\\]=\"a-z0-9.\\n -]{0,30}") {
        let _ = RawFrame::parse(&bytes, Path::new("f.pgm"));
        let mut good = frame().to_pgm();
        let at = cut.min(good.len());
        good.truncate(at);
        let _ = RawFrame::parse(&good, Path::new("f.pgm"));
        let mut prefixed = b"P5\n6 4\n4095\n".to_vec();
        prefixed.extend_from_slice(&bytes);
        let _ = RawFrame::parse(&prefixed, Path::new("f.pgm"));
        let mut text = CAPTURE.to_string();
        text.insert_str(cut.min(text.len()), &junk);
        let _ = CaptureConfig::parse(&text, Path::new("capture.toml"));
    }
}
