//! Criterion benchmark of the HDR merge (issue 4): five 2592x1944 frames, 1 µs to 500 ms,
//! 150 dB, merged and mapped on one core and on all cores, next to the naive baseline's
//! shape (a per-group lens inversion) measured by `skylux bench hdr`. The case is
//! `skylux_sim::hdr_case`, the same one `skylux bench hdr` times.
//!
//! `cargo bench -p skylux-tests --bench hdr_merge`

use criterion::{criterion_group, criterion_main, Criterion};
use skylux_hps::campaign::BayerPattern;
use skylux_hps::hdr::merge;
use skylux_sim::hdr_case::HdrCase;
use std::hint::black_box;

fn hdr_merge(c: &mut Criterion) {
    let case = HdrCase::new();
    let exposures = case.exposures();
    let run = || {
        merge(
            black_box(&exposures),
            &case.device,
            BayerPattern::GRBG,
            &case.geometry,
        )
        .expect("the case merges")
    };
    let mut group = c.benchmark_group("hdr_merge_5x2592x1944");
    group.sample_size(20);
    let one_core = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    group.bench_function("one_core", |b| b.iter(|| one_core.install(run)));
    group.bench_function("all_cores", |b| b.iter(run));
    group.finish();
}

criterion_group!(benches, hdr_merge);
criterion_main!(benches);
