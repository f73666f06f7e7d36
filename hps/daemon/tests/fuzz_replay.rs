//! Replays the committed fuzz corpora of the daemon's readers (`skyluxd.toml`, HTTP
//! requests) through the harnesses the fuzzer ran (FUZZING.md), without panicking.

use skylux_hps::fuzzing::replay;
use skyluxd::fuzzing::TARGETS;
use std::path::Path;

#[test]
fn every_corpus_file_replays_without_panic() {
    let repository = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    for (target, harness) in TARGETS {
        let count = replay(&repository, target, *harness).unwrap_or_else(|e| panic!("{e}"));
        println!("{target}: {count} files");
    }
}
