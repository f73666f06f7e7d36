//! Replays the committed fuzz corpora of the library's readers (FUZZING.md): every file of
//! `fuzz/corpus/TARGET/` and `fuzz/regressions/TARGET/` through the harness the fuzzer ran,
//! without panicking. Building the instrumented fuzzers is not part of this test.

use skylux_hps::fuzzing::{replay, TARGETS};
use std::path::Path;
use std::time::Instant;

#[test]
fn every_corpus_file_replays_without_panic() {
    let repository = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    for (target, harness) in TARGETS {
        let started = Instant::now();
        let count = replay(&repository, target, *harness).unwrap_or_else(|e| panic!("{e}"));
        println!("{target}: {count} files in {:.2?}", started.elapsed());
    }
}

/// The `exr` fuzzer's finding (2026-11-27): 1,455 bytes whose header declares a layer of
/// billions of pixels made the exr crate try a 34 GB allocation and abort. Both readers now
/// refuse it from the header, naming the file.
/// The `exr` fuzzer's second finding (2026-11-27): 3,122 bytes declaring tiles of 64 x
/// 4,194,368 pixels over an 8 x 8 image, which made the exr crate allocate 1.8 GB and take
/// 1.7 s (a libFuzzer timeout on a loaded machine). Refused from the header now.
#[test]
fn an_exr_declaring_tiles_larger_than_its_image_is_refused_before_decoding() {
    let bytes = include_bytes!(
        "../../../fuzz/regressions/exr/timeout-dfdf7e8793853d534ee561a71f2d8c6224d53f49"
    );
    let path = Path::new("tiles.exr");
    let e = skylux_hps::picture::exr::parse_exr_luminance(path, bytes).unwrap_err();
    assert!(e.to_string().contains("tiles.exr"), "{e}");
    let e = skylux_hps::hdr::parse_exr(path, bytes)
        .unwrap_err()
        .to_string();
    assert!(e.contains("tiles.exr") && e.contains("tiles of"), "{e}");
    println!("{e}");
}

/// The `exr` fuzzer's third finding (2026-11-27): a map whose tile block contradicts its
/// header made the exr crate panic on an assertion (`line should have been filtered`). The
/// readers catch it and say the file is unreadable, naming it.
#[test]
fn an_exr_whose_blocks_contradict_its_header_is_an_error_not_a_panic() {
    let bytes = include_bytes!(
        "../../../fuzz/regressions/exr/crash-f91ab14ec2ba4f8169390b7e0e17efbf94361aca"
    );
    let path = Path::new("blocks.exr");
    let e = skylux_hps::picture::exr::parse_exr_luminance(path, bytes).unwrap_err();
    assert!(e.to_string().contains("blocks.exr"), "{e}");
    let e = skylux_hps::hdr::parse_exr(path, bytes)
        .unwrap_err()
        .to_string();
    assert!(e.contains("blocks.exr") && e.contains("contradict"), "{e}");
    println!("{e}");
}

#[test]
fn an_exr_declaring_billions_of_pixels_is_refused_before_decoding() {
    let bytes = include_bytes!(
        "../../../fuzz/regressions/exr/crash-9fbb764f89c8ecd314f2e2ee8d9439db4a0ee745"
    );
    let path = Path::new("huge.exr");
    let e = skylux_hps::picture::exr::parse_exr_luminance(path, bytes).unwrap_err();
    assert!(e.to_string().contains("huge.exr"), "{e}");
    let e = skylux_hps::hdr::parse_exr(path, bytes)
        .unwrap_err()
        .to_string();
    assert!(e.contains("huge.exr"), "{e}");
    println!("{e}");
}
