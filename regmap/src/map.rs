//! The blocks of the map. Offsets are bytes from the start of the lightweight bridge window.
//!
//! Changing anything here changes the hardware/software contract: bump `sys::version::MINOR`
//! (compatible additions) or `MAJOR` (anything else), then regenerate the rendered copies with
//! `SKYLUX_BLESS=1 cargo test -p skylux-regmap`.

use crate::{register_block, Block};

/// Every block of the map, in address order.
pub const MAP: &[Block] = &[
    sys::BLOCK,
    i2c::BLOCK,
    seq::BLOCK,
    capture::BLOCK,
    bayer::BLOCK,
    dma::BLOCK,
    raybox::BLOCK,
    sun::BLOCK,
    hdr::BLOCK,
];

/// The value of `sys.id`: ASCII "SKYL". The HPS refuses to drive anything else.
pub const DESIGN_ID: u32 = 0x534B_594C;
/// Major version of the map: the HPS refuses a different major version.
pub const VERSION_MAJOR: u32 = 0;
/// Minor version: compatible additions. The HPS accepts a newer minor version.
pub const VERSION_MINOR: u32 = 4;

register_block! {
    /// Identification, scratch, time base, interrupts and bus errors.
    sys @ 0x0000 {
        /// Design identifier, checked by the HPS at start-up.
        id @ 0x000 {
            /// ASCII "SKYL".
            VALUE [0 +: 32] Const = crate::DESIGN_ID;
        }
        /// Register-map version, checked by the HPS at start-up.
        version @ 0x004 {
            /// Compatible additions.
            MINOR [0 +: 16] Const = crate::VERSION_MINOR;
            /// Incompatible changes.
            MAJOR [16 +: 16] Const = crate::VERSION_MAJOR;
        }
        /// Free for software: proves the bridge carries writes and reads.
        scratch @ 0x008 {
            /// Any value.
            VALUE [0 +: 32] RW = 0;
        }
        /// Accesses to addresses that hold no register.
        bus_status @ 0x00C {
            /// A read hit an unmapped address (it returned 0xDEADBEEF).
            UNMAPPED_READ [0 +: 1] W1C = 0;
            /// A write hit an unmapped address (it was ignored).
            UNMAPPED_WRITE [1 +: 1] W1C = 0;
        }
        /// Where the last unmapped access went.
        bus_error_addr @ 0x010 {
            /// Byte offset in the window of the last unmapped read or write.
            OFFSET [0 +: 21] RO = 0;
        }
        /// Frequency of the system clock that counts `time_lo`/`time_hi`.
        clock_hz @ 0x014 {
            /// Hertz.
            VALUE [0 +: 32] Const = crate::SYS_CLOCK_HZ;
        }
        /// Free-running system-clock counter, low word (timestamps frames).
        time_lo @ 0x018 {
            /// Cycles, low 32 bits.
            CYCLES [0 +: 32] RO = 0;
        }
        /// Free-running system-clock counter, high word. Read high, low, high.
        time_hi @ 0x01C {
            /// Cycles, high 32 bits.
            CYCLES [0 +: 32] RO = 0;
        }
        /// Interrupt causes; the interrupt line is high while any enabled cause is set.
        irq_status @ 0x020 {
            /// A frame and its descriptor are in memory.
            FRAME_DONE [0 +: 1] W1C = 0;
            /// The exposure sequence finished (shield closed).
            SEQUENCE_DONE [1 +: 1] W1C = 0;
            /// The DMA engine flagged an error (see `dma.status`).
            DMA_ERROR [2 +: 1] W1C = 0;
            /// The capture flagged a malformed frame (see `capture.status`).
            CAPTURE_ERROR [3 +: 1] W1C = 0;
            /// An I2C transaction finished (see `i2c.status`).
            I2C_DONE [4 +: 1] W1C = 0;
            /// The ray-box unit finished a batch or refused it (see `raybox.status`).
            RAYBOX_DONE [5 +: 1] W1C = 0;
        }
        /// Which interrupt causes raise the interrupt line.
        irq_enable @ 0x024 {
            /// Enables `irq_status.FRAME_DONE`.
            FRAME_DONE [0 +: 1] RW = 0;
            /// Enables `irq_status.SEQUENCE_DONE`.
            SEQUENCE_DONE [1 +: 1] RW = 0;
            /// Enables `irq_status.DMA_ERROR`.
            DMA_ERROR [2 +: 1] RW = 0;
            /// Enables `irq_status.CAPTURE_ERROR`.
            CAPTURE_ERROR [3 +: 1] RW = 0;
            /// Enables `irq_status.I2C_DONE`.
            I2C_DONE [4 +: 1] RW = 0;
            /// Enables `irq_status.RAYBOX_DONE`.
            RAYBOX_DONE [5 +: 1] RW = 0;
        }
    }
}

register_block! {
    /// Two-wire master for the image sensor's registers (MT9P031: 7-bit address 0x5D, 8-bit
    /// register address, 16-bit data MSB first; hardware-facts.md §1.3).
    i2c @ 0x1000 {
        /// Transaction control.
        ctrl @ 0x000 {
            /// Write 1 to start one register transaction.
            START [0 +: 1] W1P = 0;
            /// 1: read the register, 0: write it.
            READ [1 +: 1] RW = 0;
        }
        /// Target device.
        target @ 0x004 {
            /// 7-bit device address.
            ADDR7 [0 +: 7] RW = 0x5D;
        }
        /// Sensor register address.
        reg_addr @ 0x008 {
            /// 8-bit register address.
            ADDR [0 +: 8] RW = 0;
        }
        /// Data for a register write.
        write_data @ 0x00C {
            /// 16-bit value, sent MSB first.
            DATA [0 +: 16] RW = 0;
        }
        /// Data of the last register read.
        read_data @ 0x010 {
            /// 16-bit value.
            DATA [0 +: 16] RO = 0;
        }
        /// Transaction status.
        status @ 0x014 {
            /// A transaction is in progress.
            BUSY [0 +: 1] RO = 0;
            /// A transaction finished (with or without error).
            DONE [1 +: 1] W1C = 0;
            /// The target did not acknowledge.
            NACK [2 +: 1] W1C = 0;
            /// The transaction did not finish within `timeout` (SCL held low).
            TIMEOUT [3 +: 1] W1C = 0;
            /// SDA was low when the master released it (at START, or on a 1 bit it sent): a
            /// device holds the bus. The transaction was abandoned.
            BUS_STUCK [4 +: 1] W1C = 0;
            /// START was written while the exposure sequencer owned the master: nothing sent.
            REFUSED [5 +: 1] W1C = 0;
        }
        /// SCL timing.
        clock_div @ 0x018 {
            /// System clocks per half SCL period (500: 100 kHz at 100 MHz). The master works
            /// in quarter periods of `HALF_PERIOD / 2` clocks (at least 1).
            HALF_PERIOD [0 +: 16] RW = 500;
        }
        /// Transaction watchdog.
        timeout @ 0x01C {
            /// System clocks before a transaction is abandoned (10 ms at 100 MHz).
            CYCLES [0 +: 24] RW = 1_000_000;
        }
        /// The sensor's other control pins (hardware-facts.md §1.7, §1.8).
        sensor_pins @ 0x020 {
            /// Drives RESET_BAR: 0 holds the sensor in reset (the power-up state), 1 releases
            /// it. The HPS releases it once XCLKIN runs, then waits before the first I2C access.
            RESET_N [0 +: 1] RW = 0;
            /// STROBE (the sensor's exposure indicator), synchronised to the system clock.
            STROBE [1 +: 1] RO = 0;
        }
    }
}

register_block! {
    /// Exposure sequencer (snapshot mode) and the lens-shield actuator.
    seq @ 0x2000 {
        /// Sequence control.
        ctrl @ 0x000 {
            /// Write 1 to start a sequence.
            START [0 +: 1] W1P = 0;
            /// Write 1 to abort the sequence and close the shield.
            ABORT [1 +: 1] W1P = 0;
            /// 1: a rising edge on the external trigger input also starts a sequence.
            EXT_TRIGGER [2 +: 1] RW = 0;
        }
        /// Sequence length.
        count @ 0x004 {
            /// Exposures per sequence (1 to 8).
            EXPOSURES [0 +: 4] RW = 5;
        }
        /// Sequence state.
        status @ 0x008 {
            /// A sequence is running.
            BUSY [0 +: 1] RO = 0;
            /// Index of the current exposure.
            INDEX [4 +: 3] RO = 0;
            /// The shield is open.
            SHIELD_OPEN [8 +: 1] RO = 0;
            /// The sequence finished and the shield closed.
            DONE [16 +: 1] W1C = 0;
            /// The hardware closed the shield at `shield_limit` before the sequence ended.
            SHIELD_LIMIT_HIT [17 +: 1] W1C = 0;
            /// A sensor register write failed (NACK, timeout or stuck bus: see `i2c.status`);
            /// the sequence was abandoned and the shield closed.
            I2C_ERROR [18 +: 1] W1C = 0;
            /// START with `count.EXPOSURES` 0 or above 8, or while busy: nothing was done.
            REFUSED [19 +: 1] W1C = 0;
            /// The sequence was ended by `ctrl.ABORT`.
            ABORTED [20 +: 1] W1C = 0;
        }
        /// Longest time the shield may stay open per sequence. The hardware clamps the value
        /// to its reset value (0.55 s at 100 MHz): software may lower it, never raise it.
        shield_limit @ 0x00C {
            /// System clocks.
            CYCLES [0 +: 32] RW = 55_000_000;
        }
        /// Stepper steps from closed to open.
        shield_steps @ 0x010 {
            /// Steps.
            STEPS [0 +: 16] RW = 200;
        }
        /// Stepper step period.
        shield_step_period @ 0x014 {
            /// System clocks per step.
            CYCLES [0 +: 24] RW = 50_000;
        }
        /// Frames exposed since power-up.
        frame_number @ 0x018 {
            /// Count.
            VALUE [0 +: 32] RO = 0;
        }
        /// Width of the pulse on the sensor's TRIGGER pin (snapshot mode, hardware-facts.md
        /// §1.6).
        trigger_pulse @ 0x01C {
            /// System clocks (0 acts as 1).
            CYCLES [0 +: 16] RW = 100;
        }
        /// Shutter width per exposure (sensor R0x08/R0x09).
        exp_shutter_width[8] @ 0x040 {
            /// Rows (1 to 2^20 - 1).
            ROWS [0 +: 20] RW = 1;
        }
        /// Shutter delay per exposure (sensor R0x0C).
        exp_shutter_delay[8] @ 0x060 {
            /// Register value.
            VALUE [0 +: 13] RW = 0;
        }
        /// Gain per exposure (sensor R0x35 Global_Gain code; 8 is unity).
        exp_gain[8] @ 0x080 {
            /// Register code.
            CODE [0 +: 16] RW = 8;
        }
    }
}

register_block! {
    /// Pixel capture in the PIXCLK domain: window, frame checks, clock-domain FIFO.
    capture @ 0x3000 {
        /// Capture control.
        ctrl @ 0x000 {
            /// Accept frames from the sensor.
            ENABLE [0 +: 1] RW = 0;
            /// Store raw samples instead of grouped luminance words (calibration).
            RAW [1 +: 1] RW = 0;
        }
        /// Expected frame geometry.
        window @ 0x004 {
            /// Pixels per line.
            WIDTH [0 +: 12] RW = 2592;
            /// Lines per frame.
            HEIGHT [16 +: 12] RW = 1944;
        }
        /// Frame checks.
        status @ 0x008 {
            /// FRAME_VALID from the sensor, synchronised.
            FRAME_VALID [0 +: 1] RO = 0;
            /// A line ended before `window.WIDTH` pixels.
            LINE_SHORT [8 +: 1] W1C = 0;
            /// A line carried more than `window.WIDTH` pixels.
            LINE_LONG [9 +: 1] W1C = 0;
            /// A frame ended before `window.HEIGHT` lines.
            FRAME_SHORT [10 +: 1] W1C = 0;
            /// A frame carried more than `window.HEIGHT` lines.
            FRAME_LONG [11 +: 1] W1C = 0;
            /// The clock-domain FIFO overflowed: pixels were lost.
            FIFO_OVERFLOW [12 +: 1] W1C = 0;
            /// PIXCLK stopped during a frame.
            PIXCLK_STOPPED [13 +: 1] W1C = 0;
        }
        /// Geometry of the last frame as received.
        last_frame @ 0x00C {
            /// Pixels in its last line.
            PIXELS [0 +: 12] RO = 0;
            /// Lines.
            LINES [16 +: 12] RO = 0;
        }
        /// Deepest fill of the clock-domain FIFO during the last frame (as its read side saw it).
        fifo_high_water @ 0x010 {
            /// FIFO entries (32-bit words and frame markers).
            WORDS [0 +: 16] RO = 0;
        }
        /// Frames received since power-up.
        frames @ 0x014 {
            /// Count.
            COUNT [0 +: 32] RO = 0;
        }
    }
}

register_block! {
    /// Bayer 2x2 grouping into one luminance word per block.
    bayer @ 0x4000 {
        /// Grouping mode.
        mode @ 0x000 {
            /// Colour of the first sample: 0 GRBG, 1 RGGB, 2 BGGR, 3 GBRG.
            PHASE [0 +: 2] RW = 0;
        }
        /// Black level subtracted from every sample.
        black @ 0x004 {
            /// Digital numbers.
            LEVEL [0 +: 12] RW = 0;
        }
        /// Valid sample range (before black subtraction).
        valid @ 0x008 {
            /// Lowest valid sample.
            MIN [0 +: 12] RW = 0;
            /// Highest valid sample.
            MAX [16 +: 12] RW = 4095;
        }
        /// Red weight, unsigned Q2.14 (0x4000 is 1.0).
        weight_r @ 0x00C {
            /// Weight.
            Q2_14 [0 +: 16] RW = 0x1000;
        }
        /// Green weight, applied to (G1 + G2) / 2, unsigned Q2.14.
        weight_g @ 0x010 {
            /// Weight.
            Q2_14 [0 +: 16] RW = 0x2000;
        }
        /// Blue weight, unsigned Q2.14.
        weight_b @ 0x014 {
            /// Weight.
            Q2_14 [0 +: 16] RW = 0x1000;
        }
    }
}

register_block! {
    /// Frame DMA into HPS SDRAM through the FPGA-to-SDRAM port: a ring of buffers inside a
    /// window the HPS owns.
    dma @ 0x5000 {
        /// Engine control.
        ctrl @ 0x000 {
            /// Write frames.
            ENABLE [0 +: 1] RW = 0;
            /// Write 1 to restart the ring at slot 0.
            RESET [1 +: 1] W1P = 0;
        }
        /// Physical base of the window the engine may write.
        window_base @ 0x004 {
            /// Byte address, 8-byte aligned.
            ADDR [0 +: 32] RW = 0;
        }
        /// Size of the window.
        window_size @ 0x008 {
            /// Bytes.
            BYTES [0 +: 32] RW = 0;
        }
        /// Distance between ring slots.
        slot_stride @ 0x00C {
            /// Bytes, 8-byte aligned.
            BYTES [0 +: 32] RW = 0;
        }
        /// Ring length.
        slots @ 0x010 {
            /// Slots (1 to 255).
            COUNT [0 +: 8] RW = 4;
        }
        /// Engine state.
        status @ 0x014 {
            /// A frame is being written.
            BUSY [0 +: 1] RO = 0;
            /// Slot being written (or next to be written).
            SLOT [8 +: 8] RO = 0;
            /// A frame and its descriptor are complete.
            FRAME_DONE [16 +: 1] W1C = 0;
            /// A write would have left the window; it was not issued.
            OUT_OF_WINDOW [17 +: 1] W1C = 0;
            /// Frame data arrived faster than the port drained it: the frame is flagged.
            OVERFLOW [18 +: 1] W1C = 0;
            /// The port held waitrequest longer than `bus_timeout`.
            BUS_TIMEOUT [19 +: 1] W1C = 0;
        }
        /// Frames completed since power-up.
        frames_written @ 0x018 {
            /// Count.
            COUNT [0 +: 32] RO = 0;
        }
        /// Longest tolerated waitrequest stall.
        bus_timeout @ 0x01C {
            /// System clocks.
            CYCLES [0 +: 24] RW = 1_000_000;
        }
    }
}

register_block! {
    /// Ray-box (slab test) accelerator, fed with work items from SDRAM.
    raybox @ 0x6000 {
        /// Batch control.
        ctrl @ 0x000 {
            /// Write 1 to start the batch described below.
            START [0 +: 1] W1P = 0;
            /// Write 1 to abandon the batch.
            ABORT [1 +: 1] W1P = 0;
        }
        /// Physical address of the first work item.
        work_base @ 0x004 {
            /// Byte address, 8-byte aligned.
            ADDR [0 +: 32] RW = 0;
        }
        /// Number of work items.
        work_count @ 0x008 {
            /// Items.
            ITEMS [0 +: 24] RW = 0;
        }
        /// Physical address of the first result.
        result_base @ 0x00C {
            /// Byte address, 8-byte aligned.
            ADDR [0 +: 32] RW = 0;
        }
        /// Physical base of the window the unit may read and write.
        window_base @ 0x010 {
            /// Byte address.
            ADDR [0 +: 32] RW = 0;
        }
        /// Size of that window.
        window_size @ 0x014 {
            /// Bytes.
            BYTES [0 +: 32] RW = 0;
        }
        /// Batch state.
        status @ 0x018 {
            /// A batch is running.
            BUSY [0 +: 1] RO = 0;
            /// The batch finished (or was refused: see the error bits).
            DONE [16 +: 1] W1C = 0;
            /// A work item failed its check; the batch stopped there.
            BAD_DESCRIPTOR [17 +: 1] W1C = 0;
            /// The batch would read or write outside the window; nothing was accessed.
            OUT_OF_WINDOW [18 +: 1] W1C = 0;
            /// The port held waitrequest too long.
            BUS_TIMEOUT [19 +: 1] W1C = 0;
        }
        /// Tests completed since the batch started.
        tests_done @ 0x01C {
            /// Count.
            COUNT [0 +: 32] RO = 0;
        }
        /// What the unit is: the work-item format (`skylux_regmap::raybox_format`) and its
        /// parallelism.
        info @ 0x020 {
            /// Work-item and result format version.
            FORMAT [0 +: 8] Const = crate::raybox_format::FORMAT_VERSION;
            /// Slab-test lanes (tests per clock the datapath can take).
            LANES [8 +: 8] RO = 0;
        }
        /// Longest tolerated bus stall: waitrequest held, or read data awaited.
        bus_timeout @ 0x024 {
            /// System clocks (0 disables the watchdog).
            CYCLES [0 +: 24] RW = 1_000_000;
        }
    }
}

register_block! {
    /// The sun accumulators (`skylux_rtl::sun`; values in `crate::sun_values`): over the grouped
    /// words of the exposure named here, the groups at or above a threshold in a window.
    /// The sums hold until the next such frame begins; read them after its `FRAME_DONE`,
    /// `frames` before and after (the same count means one frame's sums).
    sun @ 0x7000 {
        /// Which frames to accumulate.
        ctrl @ 0x000 {
            /// Accumulate frames of `EXPOSURE_INDEX` (grouped mode only).
            ENABLE [0 +: 1] RW = 0;
            /// The exposure (its index in the sequence) that images the sun: the shortest.
            EXPOSURE_INDEX [4 +: 3] RW = 0;
        }
        /// A group counts at or above this luminance.
        threshold @ 0x004 {
            /// Grouped-word units (2^-14 DN).
            Q14 [0 +: 30] RW = 0x3FFF_FFFF;
        }
        /// The search window's columns, inclusive.
        window_x @ 0x008 {
            /// First group column.
            MIN [0 +: 11] RW = 0;
            /// Last group column.
            MAX [16 +: 11] RW = 2047;
        }
        /// The search window's rows, inclusive.
        window_y @ 0x00C {
            /// First group row.
            MIN [0 +: 11] RW = 0;
            /// Last group row.
            MAX [16 +: 11] RW = 2047;
        }
        /// Groups that counted.
        count @ 0x010 {
            /// Groups.
            GROUPS [0 +: 21] RO = 0;
        }
        /// Of those, groups with a sample above `bayer.valid.MAX`.
        over_count @ 0x014 {
            /// Groups.
            GROUPS [0 +: 21] RO = 0;
        }
        /// Σ L over the counted groups, low word.
        sum_l_lo @ 0x018 {
            /// Bits 0-31, grouped-word units.
            VALUE [0 +: 32] RO = 0;
        }
        /// Σ L, high word.
        sum_l_hi @ 0x01C {
            /// Bits 32-63.
            VALUE [0 +: 32] RO = 0;
        }
        /// Σ x·L (x: group column), low word.
        sum_xl_lo @ 0x020 {
            /// Bits 0-31.
            VALUE [0 +: 32] RO = 0;
        }
        /// Σ x·L, high word.
        sum_xl_hi @ 0x024 {
            /// Bits 32-63.
            VALUE [0 +: 32] RO = 0;
        }
        /// Σ y·L (y: group row), low word.
        sum_yl_lo @ 0x028 {
            /// Bits 0-31.
            VALUE [0 +: 32] RO = 0;
        }
        /// Σ y·L, high word.
        sum_yl_hi @ 0x02C {
            /// Bits 32-63.
            VALUE [0 +: 32] RO = 0;
        }
        /// The largest L counted.
        max_l @ 0x030 {
            /// Grouped-word units.
            Q14 [0 +: 30] RO = 0;
        }
        /// The counted groups' columns.
        box_x @ 0x034 {
            /// First.
            MIN [0 +: 11] RO = 0;
            /// Last.
            MAX [16 +: 11] RO = 0;
        }
        /// The counted groups' rows.
        box_y @ 0x038 {
            /// First.
            MIN [0 +: 11] RO = 0;
            /// Last.
            MAX [16 +: 11] RO = 0;
        }
        /// Accumulated frames begun since power-up.
        frames @ 0x03C {
            /// Count (wraps).
            COUNT [0 +: 16] RO = 0;
        }
    }
}

register_block! {
    /// HDR in the fabric (`skylux_rtl::hdr`; word format `crate::words::hdr_map`): the DMA
    /// writes the frames of a set, long to short, as one map into one ring slot (set
    /// `dma.slots` to 1), each group from the longest exposure in which it is usable, with
    /// byte enables masking the groups already written. Grouped mode only; read the map after
    /// the set's last `FRAME_DONE`. A set may span several sequences (shield openings).
    hdr @ 0x8000 {
        /// Map mode, and where a set begins.
        ctrl @ 0x000 {
            /// Write maps instead of frames (grouped mode only).
            ENABLE [0 +: 1] RW = 0;
            /// The next map frame begins a set (the longest exposure): it writes every group,
            /// whatever earlier sets left, and is the map words' exposure 0; each later frame
            /// counts one up (to 7).
            NEW_SET [1 +: 1] W1P = 0;
        }
        /// A group is usable at or above this luminance (and inside `bayer.valid`).
        min @ 0x004 {
            /// Map-word units (2^-11 DN): the grouped word's luminance without its last three
            /// bits, so the map word tells a usable group exactly.
            Q11 [0 +: 27] RW = 0;
        }
        /// ... and at or below this one.
        max @ 0x008 {
            /// Map-word units (2^-11 DN).
            Q11 [0 +: 27] RW = 0x7FF_FFFF;
        }
    }
}
