//! Waiting for the fabric's DMA to finish frames: [`UioWait`] sleeps on the fabric's interrupt
//! through Linux UIO, [`PollWait`] reads `dma.frames_written` in a bounded loop. Both end with
//! [`WaitError::Timeout`] when the frames do not come, so a dead sensor or a stuck DMA is a
//! logged `dma_timeout`, never a hung daemon.
//!
//! The interrupt is the fabric's `sys.irq_status.FRAME_DONE`, a level raised while the cause
//! is set and enabled in `sys.irq_enable`, wired to f2h_irq0[0] (GIC SPI 40) and bound to
//! `uio_pdrv_genirq` (hardware-facts.md §3.5). The UIO protocol: the kernel masks the line in
//! its handler and counts the event; user space blocks in `read()` of the 4-byte count and
//! writes the 32-bit value 1 to unmask again. Because the line is a level, the cause is
//! cleared (W1C) before unmasking, and `frames_written` is read after clearing: a frame that
//! completes after that read sets the cause again, so no frame is ever missed between the
//! check and the sleep.

use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_hps::fpga::Fabric;
use skylux_regmap::sys;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Why a wait ended without the frames.
#[derive(Debug, thiserror::Error)]
pub enum WaitError {
    #[error("{received} of {expected} frames after {waited_ms} ms")]
    Timeout {
        received: u32,
        expected: u32,
        waited_ms: u64,
    },
    #[error("stop requested while waiting for frames ({received} of {expected} received)")]
    Stopped { received: u32, expected: u32 },
    #[error("register bus: {0}")]
    Bus(#[from] BusError),
    #[error("{path}: {what}: {source}")]
    Io {
        path: PathBuf,
        what: &'static str,
        source: std::io::Error,
    },
}

/// Something that waits until the DMA has written `expected` frames more than `start`
/// (`dma.frames_written` counts since power-up and wraps).
pub trait FrameWait {
    /// Returns the frames written since `start` (at least `expected`).
    fn wait_frames<B: RegisterBus>(
        &mut self,
        fabric: &mut Fabric<B>,
        start: u32,
        expected: u32,
        timeout: Duration,
        stop: &AtomicBool,
    ) -> Result<u32, WaitError>;

    /// A name for logs.
    fn name(&self) -> &'static str;
}

/// Polls `dma.frames_written`: at most `max_polls` reads, `pause` apart, within the timeout.
///
/// In the cycle-accurate simulation time only advances with register accesses, so the pause
/// is zero there and the bound is what ends a wait for frames that never come; on the board
/// (no UIO device) a pause of ~1 ms keeps the core free.
#[derive(Copy, Clone, Debug)]
pub struct PollWait {
    pub max_polls: u64,
    pub pause: Duration,
}

impl FrameWait for PollWait {
    fn wait_frames<B: RegisterBus>(
        &mut self,
        fabric: &mut Fabric<B>,
        start: u32,
        expected: u32,
        timeout: Duration,
        stop: &AtomicBool,
    ) -> Result<u32, WaitError> {
        let began = Instant::now();
        let mut received = 0;
        for _ in 0..self.max_polls {
            received = fabric.frames_written()?.wrapping_sub(start);
            if received >= expected {
                return Ok(received);
            }
            if stop.load(Ordering::Relaxed) {
                return Err(WaitError::Stopped { received, expected });
            }
            if began.elapsed() >= timeout {
                break;
            }
            if !self.pause.is_zero() {
                std::thread::sleep(self.pause);
            }
        }
        Err(WaitError::Timeout {
            received,
            expected,
            waited_ms: began.elapsed().as_millis() as u64,
        })
    }

    fn name(&self) -> &'static str {
        "poll"
    }
}

/// Longest single sleep in the interrupt wait: the stop flag is looked at this often.
const UIO_SLICE: Duration = Duration::from_millis(100);

/// The fabric's interrupt through `/dev/uioN`.
#[derive(Debug)]
pub struct UioWait {
    /// Where the event count is read (the UIO node).
    events: std::fs::File,
    /// Where the unmask word is written (the same node on the board).
    enable: std::fs::File,
    path: PathBuf,
    /// Interrupt events read so far.
    pub events_seen: u64,
}

impl UioWait {
    /// Opens the UIO node (read and write).
    pub fn open(path: &Path) -> Result<Self, WaitError> {
        let file = std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .open(path)
            .map_err(|source| WaitError::Io {
                path: path.into(),
                what: "cannot open the UIO device",
                source,
            })?;
        let enable = file.try_clone().map_err(|source| WaitError::Io {
            path: path.into(),
            what: "cannot duplicate the descriptor",
            source,
        })?;
        Ok(Self::from_files(file, enable, path))
    }

    /// A wait reading events from `events` and writing unmask words to `enable` (on the board
    /// both are the UIO node; tests use the two ends of pipes).
    pub fn from_files(events: std::fs::File, enable: std::fs::File, path: &Path) -> Self {
        Self {
            events,
            enable,
            path: path.into(),
            events_seen: 0,
        }
    }

    fn io(&self, what: &'static str) -> impl FnOnce(std::io::Error) -> WaitError + '_ {
        move |source| WaitError::Io {
            path: self.path.clone(),
            what,
            source,
        }
    }

    /// Unmasks the interrupt: the 32-bit value 1 (native order, as the kernel reads an s32).
    fn unmask(&mut self) -> Result<(), WaitError> {
        use std::io::Write;
        self.enable
            .write_all(&1u32.to_ne_bytes())
            .map_err(self.io("cannot re-enable the interrupt"))
    }

    /// Sleeps until an event or `limit`; `true` when an event was read.
    fn sleep_for_event(&mut self, limit: Duration) -> Result<bool, WaitError> {
        use std::io::Read;
        use std::os::fd::AsRawFd;
        let mut pfd = libc::pollfd {
            fd: self.events.as_raw_fd(),
            events: libc::POLLIN,
            revents: 0,
        };
        let ms = limit.as_millis().clamp(0, i32::MAX as u128) as libc::c_int;
        // SAFETY: one valid pollfd for the duration of the call.
        let n = unsafe { libc::poll(&mut pfd, 1, ms) };
        if n < 0 {
            let e = std::io::Error::last_os_error();
            if e.kind() == std::io::ErrorKind::Interrupted {
                return Ok(false);
            }
            return Err(self.io("poll")(e));
        }
        if n == 0 || pfd.revents & libc::POLLIN == 0 {
            if pfd.revents & (libc::POLLERR | libc::POLLHUP | libc::POLLNVAL) != 0 {
                return Err(self.io("poll")(std::io::Error::other(
                    "the device reported an error or hang-up",
                )));
            }
            return Ok(false);
        }
        let mut count = [0u8; 4];
        self.events
            .read_exact(&mut count)
            .map_err(self.io("cannot read the interrupt count"))?;
        self.events_seen += 1;
        Ok(true)
    }

    /// The wait itself, over any way of reading the frame counter and clearing the cause.
    pub fn wait_with(
        &mut self,
        frames_written: &mut dyn FnMut() -> Result<u32, BusError>,
        clear_cause: &mut dyn FnMut() -> Result<(), BusError>,
        start: u32,
        expected: u32,
        timeout: Duration,
        stop: &AtomicBool,
    ) -> Result<u32, WaitError> {
        let began = Instant::now();
        loop {
            clear_cause()?;
            self.unmask()?;
            let received = frames_written()?.wrapping_sub(start);
            if received >= expected {
                return Ok(received);
            }
            if stop.load(Ordering::Relaxed) {
                return Err(WaitError::Stopped { received, expected });
            }
            let left = timeout.saturating_sub(began.elapsed());
            if left.is_zero() {
                return Err(WaitError::Timeout {
                    received,
                    expected,
                    waited_ms: began.elapsed().as_millis() as u64,
                });
            }
            self.sleep_for_event(left.min(UIO_SLICE))?;
        }
    }
}

impl FrameWait for UioWait {
    fn wait_frames<B: RegisterBus>(
        &mut self,
        fabric: &mut Fabric<B>,
        start: u32,
        expected: u32,
        timeout: Duration,
        stop: &AtomicBool,
    ) -> Result<u32, WaitError> {
        fabric
            .bus()
            .write_reg(&sys::irq_enable::REG, 0, sys::irq_enable::FRAME_DONE.mask())?;
        let fabric = std::cell::RefCell::new(fabric);
        let result = self.wait_with(
            &mut || fabric.borrow_mut().frames_written(),
            &mut || {
                fabric.borrow_mut().bus().write_reg(
                    &sys::irq_status::REG,
                    0,
                    sys::irq_status::FRAME_DONE.mask(),
                )
            },
            start,
            expected,
            timeout,
            stop,
        );
        // Masked again at the source: nothing raises the line between captures.
        fabric
            .borrow_mut()
            .bus()
            .write_reg(&sys::irq_enable::REG, 0, 0)?;
        result
    }

    fn name(&self) -> &'static str {
        "uio"
    }
}

/// The wait chosen at start: the interrupt when a UIO node is configured, else polling.
#[derive(Debug)]
pub enum AnyWait {
    Uio(UioWait),
    Poll(PollWait),
}

impl FrameWait for AnyWait {
    fn wait_frames<B: RegisterBus>(
        &mut self,
        fabric: &mut Fabric<B>,
        start: u32,
        expected: u32,
        timeout: Duration,
        stop: &AtomicBool,
    ) -> Result<u32, WaitError> {
        match self {
            Self::Uio(w) => w.wait_frames(fabric, start, expected, timeout, stop),
            Self::Poll(w) => w.wait_frames(fabric, start, expected, timeout, stop),
        }
    }

    fn name(&self) -> &'static str {
        match self {
            Self::Uio(w) => w.name(),
            Self::Poll(w) => w.name(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Read, Write};
    use std::os::fd::FromRawFd;

    /// A pipe as (read end, write end).
    fn pipe() -> (std::fs::File, std::fs::File) {
        let mut fds = [0 as libc::c_int; 2];
        // SAFETY: a valid two-element array; the descriptors are owned by the Files below.
        assert_eq!(unsafe { libc::pipe(fds.as_mut_ptr()) }, 0);
        unsafe {
            (
                std::fs::File::from_raw_fd(fds[0]),
                std::fs::File::from_raw_fd(fds[1]),
            )
        }
    }

    /// The UIO protocol against pipes standing in for the device: the wait unmasks with the
    /// 32-bit value 1 before each sleep, sleeps in poll(2) until the "kernel" writes an event
    /// count, reads it, and returns once the frame counter reaches the target; with no event
    /// it times out after the timeout, not before.
    #[test]
    fn uio_wait_follows_the_protocol_and_times_out() {
        let (events_rx, mut events_tx) = pipe();
        let (mut enable_rx, enable_tx) = pipe();
        let mut w = UioWait::from_files(events_rx, enable_tx, Path::new("/dev/uio-test"));
        let stop = AtomicBool::new(false);
        let counter = std::sync::Arc::new(std::sync::atomic::AtomicU32::new(7));
        let kernel = {
            let counter = counter.clone();
            std::thread::spawn(move || {
                std::thread::sleep(Duration::from_millis(150));
                counter.store(9, Ordering::SeqCst); // two frames done
                events_tx.write_all(&1u32.to_ne_bytes()).unwrap();
                events_tx
            })
        };
        let mut clears = 0;
        let began = Instant::now();
        let got = w
            .wait_with(
                &mut || Ok(counter.load(Ordering::SeqCst)),
                &mut || {
                    clears += 1;
                    Ok(())
                },
                7,
                2,
                Duration::from_secs(10),
                &stop,
            )
            .unwrap();
        let waited = began.elapsed();
        let _tx = kernel.join().unwrap();
        assert_eq!(got, 2);
        assert_eq!(w.events_seen, 1);
        assert!(waited >= Duration::from_millis(140), "{waited:?}");
        assert!(waited < Duration::from_secs(5), "{waited:?}");
        // Cleared and unmasked before every check: the first, after each 100 ms slice, and
        // after the event; one unmask word per clear.
        assert!((2..=4).contains(&clears), "{clears}");
        let mut words = vec![0u8; 4 * clears];
        enable_rx.read_exact(&mut words).unwrap();
        assert!(words.chunks_exact(4).all(|w| w == 1u32.to_ne_bytes()));

        // No event: a timeout with the count, after the timeout.
        let began = Instant::now();
        match w.wait_with(
            &mut || Ok(counter.load(Ordering::SeqCst)),
            &mut || Ok(()),
            9,
            1,
            Duration::from_millis(250),
            &stop,
        ) {
            Err(WaitError::Timeout {
                received: 0,
                expected: 1,
                waited_ms,
            }) => assert!((250..5000).contains(&waited_ms), "{waited_ms}"),
            other => panic!("{other:?}"),
        }
        assert!(began.elapsed() >= Duration::from_millis(250));
        // A stop request ends the wait at the next slice.
        stop.store(true, Ordering::Relaxed);
        assert!(matches!(
            w.wait_with(
                &mut || Ok(9),
                &mut || Ok(()),
                9,
                1,
                Duration::from_secs(30),
                &stop
            ),
            Err(WaitError::Stopped { .. })
        ));
    }
}
