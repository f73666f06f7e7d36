//! The exposure sequencer alone, against an ideal I2C master and sensor written here: the
//! register writes and triggers of a sequence, its tags, the shield's steps, and the
//! shield-open ceiling under random settings, aborts and missing frames.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rust_hdl::prelude::*;
use skylux_rtl::drive::Driver;
use skylux_rtl::sequencer::{ExposureSequencer, EXPOSURE_REGISTERS};

fn clock(d: &mut ExposureSequencer) -> &mut Signal<In, Clock> {
    &mut d.clock
}

#[derive(Clone, Debug)]
struct Exposure {
    sw: u32,
    sd: u32,
    gain: u32,
}

#[derive(Clone, Debug)]
struct Setup {
    exposures: Vec<Exposure>,
    steps: u32,
    period: u32,
    limit: u32,
    pulse: u32,
    /// Cycles an I2C write takes; `fail_at`: the n-th write fails.
    i2c_cycles: u32,
    fail_at: Option<usize>,
    /// Cycles from trigger to FV rise and FV high; `None`: the sensor never answers.
    frame: Option<(u32, u32)>,
    abort_at: Option<u64>,
}

#[derive(Debug, Default)]
struct Run {
    writes: Vec<(u8, u16)>,
    triggers: usize,
    trigger_widths: Vec<u32>,
    tags: Vec<(u32, u32, u64, u64)>,
    position: i64,
    max_position: i64,
    open_max: u64,
    dones: usize,
    limit_hits: usize,
    i2c_failed: usize,
    aborted: usize,
    refused: usize,
    cycles: u64,
}

fn run(setup: &Setup, max_cycles: u64) -> (Run, Driver<ExposureSequencer>) {
    let mut d = Driver::new(ExposureSequencer::default());
    {
        let s = &mut d.dut;
        s.exposures.next = (setup.exposures.len() as u64).into();
        s.shield_limit_cycles.next = u64::from(setup.limit).into();
        s.shield_steps.next = u64::from(setup.steps).into();
        s.step_period_cycles.next = u64::from(setup.period).into();
        s.trigger_pulse_cycles.next = u64::from(setup.pulse).into();
        for (i, e) in setup.exposures.iter().enumerate() {
            s.shutter_width[i].next = u64::from(e.sw).into();
            s.shutter_delay[i].next = u64::from(e.sd).into();
            s.gain[i].next = u64::from(e.gain).into();
        }
        s.start.next = true;
    }
    let mut r = Run::default();
    let (mut i2c_left, mut i2c_busy) = (0u32, false);
    let mut fv_timer: Option<u32> = None;
    let (mut prev_step, mut prev_trig, mut open_run, mut width) = (false, false, 0u64, 0u32);
    for cycle in 0..max_cycles {
        d.dut.time_cycles.next = (1_000_000 + cycle).into();
        d.dut.abort_request.next = setup.abort_at == Some(cycle);
        d.cycle(clock).unwrap();
        d.dut.start.next = false;
        r.cycles = cycle + 1;
        // Ideal I2C master.
        let (mut done, mut error) = (false, false);
        if i2c_busy {
            i2c_left -= 1;
            if i2c_left == 0 {
                i2c_busy = false;
                done = true;
                error = setup.fail_at == Some(r.writes.len() - 1);
            }
        } else if d.dut.i2c_start.val() {
            r.writes.push((
                d.dut.i2c_reg_addr.val().index() as u8,
                d.dut.i2c_write_data.val().index() as u16,
            ));
            i2c_busy = true;
            i2c_left = setup.i2c_cycles;
        }
        d.dut.i2c_done.next = done;
        d.dut.i2c_error.next = error;
        d.dut.i2c_busy.next = i2c_busy;
        // Ideal sensor: FV rises `frame.0` cycles after the trigger's rise, for `frame.1`.
        let s = &d.dut;
        let trig = s.trigger.val();
        if trig {
            width += 1;
        }
        if trig && !prev_trig {
            r.triggers += 1;
            r.tags.push((
                s.tag_exposure_index.val().index() as u32,
                s.tag_frame_number.val().index() as u32,
                s.tag_timestamp.val().to_u64(),
                1_000_000 + cycle,
            ));
            if setup.frame.is_some() {
                fv_timer = Some(0);
            }
        }
        if !trig && prev_trig {
            r.trigger_widths.push(width);
            width = 0;
        }
        prev_trig = trig;
        let mut fv = false;
        if let (Some(t), Some((delay, high))) = (fv_timer, setup.frame) {
            fv = t >= delay && t < delay + high;
            fv_timer = if t < delay + high { Some(t + 1) } else { None };
        }
        d.dut.frame_valid.next = fv;
        // Stepper driver.
        let s = &d.dut;
        let step = s.shield_step.val();
        if step && !prev_step && s.shield_enable.val() {
            r.position += if s.shield_dir.val() { 1 } else { -1 };
            r.max_position = r.max_position.max(r.position);
        }
        prev_step = step;
        if r.position != 0 {
            open_run += 1;
            r.open_max = r.open_max.max(open_run);
        } else {
            open_run = 0;
        }
        r.dones += usize::from(s.done.val());
        r.limit_hits += usize::from(s.shield_limit_hit.val());
        r.i2c_failed += usize::from(s.i2c_failed.val());
        r.aborted += usize::from(s.aborted.val());
        r.refused += usize::from(s.refused.val());
        if r.dones > 0 && !s.busy.val() && !i2c_busy {
            break;
        }
    }
    (r, d)
}

fn exposures(n: usize) -> Vec<Exposure> {
    (0..n)
        .map(|i| Exposure {
            sw: 0x1_0000 * (i as u32 % 2) + 100 * i as u32 + 1,
            sd: 7 * i as u32,
            gain: 8 + i as u32,
        })
        .collect()
}

fn nominal() -> Setup {
    Setup {
        exposures: exposures(3),
        steps: 5,
        period: 10,
        limit: 100_000,
        pulse: 3,
        i2c_cycles: 20,
        fail_at: None,
        frame: Some((30, 50)),
        abort_at: None,
    }
}

#[test]
fn a_sequence_writes_each_exposure_then_triggers_and_tags_it() {
    let setup = nominal();
    let (r, d) = run(&setup, 20_000);
    let expected: Vec<(u8, u16)> = setup
        .exposures
        .iter()
        .flat_map(|e| {
            let v = [(e.sw >> 16) as u16, e.sw as u16, e.sd as u16, e.gain as u16];
            EXPOSURE_REGISTERS.into_iter().zip(v)
        })
        .collect();
    assert_eq!(r.writes, expected);
    assert_eq!(r.triggers, 3);
    assert_eq!(r.trigger_widths, vec![3, 3, 3]);
    for (i, &(index, number, stamp, at)) in r.tags.iter().enumerate() {
        assert_eq!((index, number), (i as u32, i as u32));
        // The counter value at the edge that raised TRIGGER.
        assert_eq!(stamp, at, "tag {i}");
    }
    assert_eq!(
        (r.dones, r.limit_hits, r.i2c_failed, r.aborted, r.refused),
        (1, 0, 0, 0, 0)
    );
    assert_eq!((r.max_position, r.position), (5, 0));
    assert_eq!(d.dut.frame_number.val().index(), 3);
}

#[test]
fn bad_counts_and_a_second_start_are_refused() {
    for n in [0u64, 9, 15] {
        let mut d = Driver::new(ExposureSequencer::default());
        d.dut.exposures.next = n.into();
        d.dut.start.next = true;
        let mut refused = 0;
        for _ in 0..3 {
            d.cycle(clock).unwrap();
            d.dut.start.next = false;
            refused += usize::from(d.dut.refused.val());
        }
        assert_eq!(refused, 1, "count {n}");
        assert!(!d.dut.busy.val() && !d.dut.shield_enable.val(), "count {n}");
    }
    let mut d = Driver::new(ExposureSequencer::default());
    d.dut.exposures.next = 1.into();
    d.dut.shield_steps.next = 2.into();
    d.dut.step_period_cycles.next = 4.into();
    d.dut.shield_limit_cycles.next = 10_000.into();
    d.dut.start.next = true;
    d.cycle(clock).unwrap();
    assert!(d.dut.busy.val() && !d.dut.refused.val());
    // START held a second cycle: the sequencer is busy, so that one is refused.
    d.cycle(clock).unwrap();
    d.dut.start.next = false;
    assert!(d.dut.refused.val() && d.dut.busy.val());
}

#[test]
fn the_external_trigger_starts_a_sequence_only_when_enabled() {
    for enabled in [false, true] {
        let mut d = Driver::new(ExposureSequencer::default());
        d.dut.exposures.next = 1.into();
        d.dut.ext_trigger_enable.next = enabled;
        d.cycle(clock).unwrap();
        d.dut.ext_trigger.next = true;
        for _ in 0..5 {
            d.cycle(clock).unwrap();
        }
        assert_eq!(d.dut.busy.val(), enabled);
    }
}

#[test]
fn failures_and_aborts_close_the_shield_and_are_flagged() {
    let mut s = nominal();
    s.fail_at = Some(5);
    let (r, _) = run(&s, 20_000);
    assert_eq!((r.i2c_failed, r.dones, r.triggers), (1, 1, 1));
    assert_eq!(r.writes.len(), 6);
    assert_eq!(r.position, 0);

    let mut s = nominal();
    s.abort_at = Some(200);
    let (r, _) = run(&s, 20_000);
    assert_eq!((r.aborted, r.dones), (1, 1));
    assert_eq!(r.position, 0);
    assert!(r.triggers < 3);
}

#[test]
fn the_shield_is_never_open_longer_than_the_limit() {
    let mut rng = StdRng::seed_from_u64(31);
    let mut hits = 0;
    for case in 0..60 {
        let setup = Setup {
            exposures: exposures(rng.gen_range(1..=8)),
            steps: rng.gen_range(0..40),
            period: rng.gen_range(0..30),
            limit: rng.gen_range(1..6_000),
            pulse: rng.gen_range(0..5),
            i2c_cycles: rng.gen_range(1..40),
            fail_at: None,
            frame: if rng.gen_bool(0.2) {
                None
            } else {
                Some((rng.gen_range(1..200), rng.gen_range(1..300)))
            },
            abort_at: rng.gen_bool(0.2).then(|| rng.gen_range(0..3000)),
        };
        let (r, _) = run(&setup, 60_000);
        assert!(
            r.open_max <= u64::from(setup.limit),
            "case {case}: open {} > limit {}: {setup:?}",
            r.open_max,
            setup.limit
        );
        assert_eq!(r.position, 0, "case {case}: shield left open: {setup:?}");
        assert_eq!(r.dones, 1, "case {case}: {setup:?} {r:?}");
        hits += r.limit_hits;
    }
    assert!(hits > 5, "the limit was rarely exercised: {hits}");
}
