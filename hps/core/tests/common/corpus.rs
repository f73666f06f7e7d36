//! Where the shared RADIANCE corpus is: shared/data beside the workspace, or
//! `$SKYLUX_DATA_DIR`.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The corpus folder; a clear failure when it is missing.
pub fn corpus() -> PathBuf {
    let root = std::env::var_os("SKYLUX_DATA_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data"));
    let corpus = root.join("radiance-corpus");
    assert!(
        corpus.join("README.md").is_file(),
        "the RADIANCE corpus is missing at {}; expected shared/data beside the workspace or \
         SKYLUX_DATA_DIR",
        corpus.display()
    );
    corpus
}

/// frads' office scene files as its `two_phase.cfg` lists them under `Objects/`, less
/// `deskleg.rad` and `chairs.rad` (absent from the snapshot), after its `materials.mat`.
pub const FRADS_OFFICE_SCENE: [&str; 13] = [
    "windowframe",
    "overhang",
    "ground",
    "extwalls",
    "floor",
    "desks",
    "horframe",
    "cubefabric",
    "ceiling",
    "cubeframe",
    "walls",
    "lower_glass",
    "upper_glass",
];
