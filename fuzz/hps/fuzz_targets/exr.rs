#![no_main]
//! libFuzzer target `exr`: the harness of the same name in `skylux_hps::fuzzing`.
//!
//! The readers catch the exr crate's own panics (`picture::exr::read_first_layer`: the crate
//! asserts on some blocks that contradict their header) and return an error: such an input
//! is handled, not a crash. libfuzzer-sys (0.4.13, fuzz/Cargo.lock) cannot tell: its
//! `initialize`, run from `LLVMFuzzerInitialize`, installs a panic hook that calls
//! `std::process::abort()` on every panic, caught or not, so the fuzzer stopped on that
//! handled case. The `init` below runs after `initialize` and replaces that hook with one
//! that only remembers the message.
//!
//! An uncaught panic is still a crash. The body catches what the readers did not, prints the
//! remembered message (the hook no longer does) and calls `std::process::abort()`, as the
//! replaced hook did: libFuzzer reports a deadly signal and saves the input as
//! `crash-<sha1>`. The body does not lean on libfuzzer-sys for it, though libfuzzer-sys
//! would end the process too: `LLVMFuzzerTestOneInput` (`test_input_wrap`) runs each input
//! in `catch_unwind` and aborts when it caught a panic, and before that the unwinding meets
//! the `extern "C"` boundary of the macro's `rust_fuzzer_test_input`, where Rust aborts
//! ("panic in a function that cannot unwind": seen when this body re-raised the panic with
//! `resume_unwind`).
//! With `SKYLUX_FUZZ_UNCAUGHT_PANIC` set, every input panics outside the readers, so that
//! this path can be checked on the built binary (`scripts/fuzz panic-check`, FUZZING.md).

use std::cell::Cell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

/// The last panic's message and place, on any thread.
static LAST_PANIC: Mutex<Option<String>> = Mutex::new(None);

thread_local! {
    /// This thread is running the harness: its panics are caught by the readers or end in
    /// the body's report. On any other thread (the exr crate decompresses on a rayon pool,
    /// whose `spawn` aborts the process on a panic) the hook prints the message itself, or
    /// the crash would say nothing.
    static IN_HARNESS: Cell<bool> = const { Cell::new(false) };
}

/// `SKYLUX_FUZZ_UNCAUGHT_PANIC` was set: the self-check of the crash path.
static PANIC_ON_PURPOSE: AtomicBool = AtomicBool::new(false);

fn remember_panics_instead_of_aborting() {
    PANIC_ON_PURPOSE.store(
        std::env::var_os("SKYLUX_FUZZ_UNCAUGHT_PANIC").is_some(),
        Ordering::Relaxed,
    );
    std::panic::set_hook(Box::new(|info| {
        let message = info.to_string();
        if !IN_HARNESS.with(Cell::get) {
            eprintln!("exr harness: panic outside the fuzzing thread: {message}");
        }
        match LAST_PANIC.lock() {
            Ok(mut last) => *last = Some(message),
            Err(poisoned) => *poisoned.into_inner() = Some(message),
        }
    }));
}

libfuzzer_sys::fuzz_target!(init: remember_panics_instead_of_aborting(), |data: &[u8]| {
    let harness = skylux_hps::fuzzing::harness("exr").expect("a harness of that name");
    IN_HARNESS.with(|h| h.set(true));
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        harness(data);
        if PANIC_ON_PURPOSE.load(Ordering::Relaxed) {
            panic!("a deliberate uncaught panic (SKYLUX_FUZZ_UNCAUGHT_PANIC is set)");
        }
    }));
    IN_HARNESS.with(|h| h.set(false));
    if outcome.is_err() {
        let last = LAST_PANIC.lock().map(|l| l.clone()).unwrap_or_default();
        eprintln!(
            "exr harness: uncaught panic: {}",
            last.as_deref().unwrap_or("(no message)")
        );
        std::process::abort();
    }
});
