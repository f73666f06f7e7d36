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
