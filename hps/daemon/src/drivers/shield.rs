//! The lens-shield stepper driven from the HPS through embedded-hal 1.0: step, direction and
//! enable outputs and a delay. (In the fabric the sequencer drives the same signals and
//! guards the shield-open ceiling in hardware; this driver is for a shield wired to HPS
//! GPIOs, and for moving the shield outside a sequence, e.g. closing it at shutdown.)
//!
//! One move: enable, set the direction, wait the driver's setup time, then per step a high
//! half-period and a low half-period on STEP, then disable. Enable and direction polarity
//! are configurable. If a pin fails, the driver still tries to disable the motor and returns
//! the first error.

use embedded_hal::delay::DelayNs;
use embedded_hal::digital::OutputPin;

/// Which way the shield moves.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Direction {
    Open,
    Close,
}

/// Wiring and timing.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct ShieldTiming {
    /// Full step period, ns (the STEP line is high for half of it).
    pub step_period_ns: u32,
    /// Between enable/direction and the first step edge, ns.
    pub setup_ns: u32,
    /// ENABLE is active low (as on A4988/DRV8825-type driver boards: /ENABLE).
    pub enable_active_low: bool,
    /// DIR high means "open".
    pub dir_high_opens: bool,
}

impl Default for ShieldTiming {
    /// 1 ms per step; 1 µs set-up (A4988 data sheet: 200 ns minimum set-up of DIR before
    /// STEP, with margin); active-low enable; DIR high opens.
    fn default() -> Self {
        Self {
            step_period_ns: 1_000_000,
            setup_ns: 1_000,
            enable_active_low: true,
            dir_high_opens: true,
        }
    }
}

/// Why a move failed.
#[derive(Debug, PartialEq, Eq)]
pub enum ShieldError<E> {
    /// A pin could not be driven.
    Pin(E),
    /// The step period is below 2 ns (each half-period must be at least 1 ns).
    StepPeriod(u32),
}

impl<E: core::fmt::Debug> core::fmt::Display for ShieldError<E> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Pin(e) => write!(f, "shield pin: {e:?}"),
            Self::StepPeriod(p) => write!(f, "step period {p} ns is below 2 ns"),
        }
    }
}

impl<E: core::fmt::Debug> std::error::Error for ShieldError<E> {}

/// The stepper.
pub struct ShieldStepper<S, D, EN, DL> {
    step: S,
    dir: D,
    enable: EN,
    delay: DL,
    timing: ShieldTiming,
}

impl<E, S, D, EN, DL> ShieldStepper<S, D, EN, DL>
where
    S: OutputPin<Error = E>,
    D: OutputPin<Error = E>,
    EN: OutputPin<Error = E>,
    DL: DelayNs,
{
    /// Takes the pins; the motor is disabled first.
    pub fn new(
        step: S,
        dir: D,
        enable: EN,
        delay: DL,
        timing: ShieldTiming,
    ) -> Result<Self, ShieldError<E>> {
        let mut s = Self {
            step,
            dir,
            enable,
            delay,
            timing,
        };
        s.set_enabled(false)?;
        s.step.set_low().map_err(ShieldError::Pin)?;
        Ok(s)
    }

    /// Opens the shield by `steps` steps.
    pub fn open(&mut self, steps: u32) -> Result<(), ShieldError<E>> {
        self.run(Direction::Open, steps)
    }

    /// Closes the shield by `steps` steps.
    pub fn close(&mut self, steps: u32) -> Result<(), ShieldError<E>> {
        self.run(Direction::Close, steps)
    }

    /// Moves `steps` steps in `direction`: enable before, disable after (also after an
    /// error, best effort; the first error is returned).
    pub fn run(&mut self, direction: Direction, steps: u32) -> Result<(), ShieldError<E>> {
        if self.timing.step_period_ns < 2 {
            return Err(ShieldError::StepPeriod(self.timing.step_period_ns));
        }
        let result = self.steps(direction, steps);
        let disabled = self.set_enabled(false);
        result.and(disabled)
    }

    fn steps(&mut self, direction: Direction, steps: u32) -> Result<(), ShieldError<E>> {
        self.set_enabled(true)?;
        let high = (direction == Direction::Open) == self.timing.dir_high_opens;
        if high {
            self.dir.set_high()
        } else {
            self.dir.set_low()
        }
        .map_err(ShieldError::Pin)?;
        self.delay.delay_ns(self.timing.setup_ns);
        let high_ns = self.timing.step_period_ns / 2;
        let low_ns = self.timing.step_period_ns - high_ns;
        for _ in 0..steps {
            self.step.set_high().map_err(ShieldError::Pin)?;
            self.delay.delay_ns(high_ns);
            self.step.set_low().map_err(ShieldError::Pin)?;
            self.delay.delay_ns(low_ns);
        }
        Ok(())
    }

    fn set_enabled(&mut self, on: bool) -> Result<(), ShieldError<E>> {
        if on != self.timing.enable_active_low {
            self.enable.set_high()
        } else {
            self.enable.set_low()
        }
        .map_err(ShieldError::Pin)
    }

    /// Gives the pins back.
    pub fn release(self) -> (S, D, EN, DL) {
        (self.step, self.dir, self.enable, self.delay)
    }
}

/// The Linux binding: GPIO character-device lines (`/dev/gpiochipN`) and the thread-sleep
/// delay of linux-embedded-hal.
#[cfg(target_os = "linux")]
pub mod linux {
    use super::{ShieldError, ShieldStepper, ShieldTiming};
    use linux_embedded_hal::gpio_cdev::{Chip, LineRequestFlags};
    use linux_embedded_hal::{CdevPin, CdevPinError, Delay};

    /// The stepper on lines `step`, `dir`, `enable` of `chip` (e.g. `/dev/gpiochip0`).
    pub type LinuxShield = ShieldStepper<CdevPin, CdevPin, CdevPin, Delay>;

    /// Why the lines could not be claimed.
    #[derive(Debug, thiserror::Error)]
    pub enum OpenError {
        #[error("{chip}: {source}")]
        Gpio {
            chip: String,
            source: linux_embedded_hal::gpio_cdev::Error,
        },
        #[error("{0}")]
        Shield(String),
    }

    /// Claims the three lines as outputs, labelled `skyluxd-shield`.
    pub fn open(
        chip: &str,
        step: u32,
        dir: u32,
        enable: u32,
        timing: ShieldTiming,
    ) -> Result<LinuxShield, OpenError> {
        let gpio = |source| OpenError::Gpio {
            chip: chip.to_string(),
            source,
        };
        let mut c = Chip::new(chip).map_err(gpio)?;
        let mut line = |n: u32, initial: u8| -> Result<CdevPin, OpenError> {
            let handle = c
                .get_line(n)
                .and_then(|l| l.request(LineRequestFlags::OUTPUT, initial, "skyluxd-shield"))
                .map_err(gpio)?;
            CdevPin::new(handle).map_err(gpio)
        };
        // Enable starts inactive.
        let enable_inactive = u8::from(timing.enable_active_low);
        let (s, d, e) = (
            line(step, 0)?,
            line(dir, 0)?,
            line(enable, enable_inactive)?,
        );
        ShieldStepper::new(s, d, e, Delay, timing)
            .map_err(|e: ShieldError<CdevPinError>| OpenError::Shield(e.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_hal_mock::eh1::delay::{CheckedDelay, Transaction as D};
    use embedded_hal_mock::eh1::digital::{Mock, State, Transaction as T};
    use embedded_hal_mock::eh1::MockError;
    use std::io::ErrorKind;

    fn timing() -> ShieldTiming {
        ShieldTiming {
            step_period_ns: 1000,
            setup_ns: 200,
            enable_active_low: true,
            dir_high_opens: true,
        }
    }

    #[test]
    fn open_is_enable_dir_steps_disable() {
        let mut step = Mock::new(&[
            T::set(State::Low),
            T::set(State::High),
            T::set(State::Low),
            T::set(State::High),
            T::set(State::Low),
        ]);
        let mut dir = Mock::new(&[T::set(State::High)]);
        // Active low: disabled = high; enabled = low; then disabled again.
        let mut enable = Mock::new(&[T::set(State::High), T::set(State::Low), T::set(State::High)]);
        let mut delay = CheckedDelay::new(&[
            D::delay_ns(200),
            D::delay_ns(500),
            D::delay_ns(500),
            D::delay_ns(500),
            D::delay_ns(500),
        ]);
        let mut s = ShieldStepper::new(
            step.clone(),
            dir.clone(),
            enable.clone(),
            delay.clone(),
            timing(),
        )
        .unwrap();
        s.open(2).unwrap();
        drop(s);
        step.done();
        dir.done();
        enable.done();
        delay.done();
    }

    #[test]
    fn close_with_odd_period_and_active_high_enable() {
        let t = ShieldTiming {
            step_period_ns: 1001,
            enable_active_low: false,
            ..timing()
        };
        let mut step = Mock::new(&[T::set(State::Low), T::set(State::High), T::set(State::Low)]);
        let mut dir = Mock::new(&[T::set(State::Low)]);
        let mut enable = Mock::new(&[T::set(State::Low), T::set(State::High), T::set(State::Low)]);
        let mut delay = CheckedDelay::new(&[D::delay_ns(200), D::delay_ns(500), D::delay_ns(501)]);
        let mut s = ShieldStepper::new(step.clone(), dir.clone(), enable.clone(), delay.clone(), t)
            .unwrap();
        s.close(1).unwrap();
        drop(s);
        step.done();
        dir.done();
        enable.done();
        delay.done();
    }

    #[test]
    fn a_failing_step_pin_still_disables_and_reports() {
        let mut step = Mock::new(&[
            T::set(State::Low),
            T::set(State::High).with_error(MockError::Io(ErrorKind::NotConnected)),
        ]);
        let mut dir = Mock::new(&[T::set(State::High)]);
        let mut enable = Mock::new(&[T::set(State::High), T::set(State::Low), T::set(State::High)]);
        let mut delay = CheckedDelay::new(&[D::delay_ns(200)]);
        let mut s = ShieldStepper::new(
            step.clone(),
            dir.clone(),
            enable.clone(),
            delay.clone(),
            timing(),
        )
        .unwrap();
        assert_eq!(
            s.open(3),
            Err(ShieldError::Pin(MockError::Io(ErrorKind::NotConnected)))
        );
        drop(s);
        step.done();
        dir.done();
        enable.done();
        delay.done();
    }

    #[test]
    fn zero_steps_only_toggles_enable_and_bad_period_is_refused() {
        let mut step = Mock::new(&[T::set(State::Low)]);
        let mut dir = Mock::new(&[T::set(State::Low)]);
        let mut enable = Mock::new(&[T::set(State::High), T::set(State::Low), T::set(State::High)]);
        let mut delay = CheckedDelay::new(&[D::delay_ns(200)]);
        let mut s = ShieldStepper::new(
            step.clone(),
            dir.clone(),
            enable.clone(),
            delay.clone(),
            timing(),
        )
        .unwrap();
        s.close(0).unwrap();
        drop(s);
        step.done();
        dir.done();
        enable.done();
        delay.done();

        let (mut a, mut b, mut c) = (
            Mock::new(&[T::set(State::Low)]),
            Mock::new(&[]),
            Mock::new(&[T::set(State::High)]),
        );
        let mut d = CheckedDelay::new(&[]);
        let mut s = ShieldStepper::new(
            a.clone(),
            b.clone(),
            c.clone(),
            d.clone(),
            ShieldTiming {
                step_period_ns: 1,
                ..timing()
            },
        )
        .unwrap();
        assert_eq!(s.open(5), Err(ShieldError::StepPeriod(1)));
        drop(s);
        a.done();
        b.done();
        c.done();
        d.done();
    }
}
