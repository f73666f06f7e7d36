//! Glare evaluation against evalglare: the corpus's real fisheye photograph of an office
//! (RADIANCE's own evalglare test image, with the reference values of its PROVENANCE.txt)
//! and pictures of our own, each compared with evalglare run live from the pyradiance wheel.

mod common;

use common::radiance::{radiance_or_skip, tool};
use skylux_hps::glare::{self, GlareOptions, GlareReport};
use std::path::{Path, PathBuf};

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/radiance-corpus/glare-testimage")
}

fn evaluate_file(path: &Path, options: &GlareOptions) -> GlareReport {
    let image = glare::load_image(path, None).unwrap_or_else(|e| panic!("{e}"));
    glare::evaluate(&image, options).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn print_corpus() {
    let t = std::time::Instant::now();
    let r = evaluate_file(
        &corpus_dir().join("resources/evalglare/testimage.hdr"),
        &GlareOptions::default(),
    );
    let mut r2 = r.clone();
    r2.source_of_pixel.clear();
    println!("{:#?} {:?}", r2, t.elapsed());
}
