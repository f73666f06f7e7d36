//! The capture path (`capture.*`, `bayer.*`; `skylux_rtl::capture` and the ingest of
//! `skylux_rtl::dma`) per frame: at FRAME_VALID's rise the window, the mode and the
//! sequencer's tags are latched; at its fall the received lines are checked against the window
//! (`LINE_SHORT`, `LINE_LONG`, `FRAME_SHORT`, `FRAME_LONG`; extra pixels and lines dropped),
//! the words are formed (raw: two 12-bit samples per word, `skylux_regmap::words::raw`;
//! grouped: the RTL's golden model `skylux_rtl::bayer::golden`), words that find the FIFOs
//! full during a port stall are lost (`FIFO_OVERFLOW`), and the frame goes to the DMA with its
//! checksum; with `hdr.ctrl.ENABLE` in grouped mode it opens as a map frame (`super::dma`),
//! and armed for the sun accumulators it is summed as the ingest hands it over (`super::sun`).
//! Needed so the frames and the capture status the drivers read are the hardware's.

use super::{FabricModel, HardwareFault};
use skylux_hps::campaign::RawFrame;
use skylux_regmap::descriptor::flag;
use skylux_regmap::{bayer, capture, dma, hdr, sys};
use skylux_rtl::bayer::golden::{expected_words, BayerConfig, Frame, Phase};
use skylux_rtl::capture::fifo_entry::{DATA_FILL_LIMIT, END_MARKER_DELAY, FIFO_DEPTH};
use skylux_rtl::dma::BEAT_FIFO_ADDRESS_BITS;
use skylux_rtl::hdr::golden::HdrConfig;

/// Words the two FIFOs hold before a stalled port makes the capture drop words: the
/// clock-domain FIFO up to its data limit and the DMA's beat FIFO (two words a beat, less the
/// writer's margin of two beats), `skylux_rtl::capture::fifo_entry`, `skylux_rtl::dma`.
pub const STALL_CAPACITY_WORDS: u64 = DATA_FILL_LIMIT + 2 * ((1 << BEAT_FIFO_ADDRESS_BITS) - 2);

/// A frame being received.
#[derive(Clone, Debug)]
pub struct FrameRx {
    /// The samples as the sensor rendered them (its programmed window).
    pub samples: RawFrame,
    /// `capture.window`, latched at the frame's start.
    pub width: u32,
    pub height: u32,
    pub bayer: BayerConfig,
    /// The ingest takes the frame for the DMA (the engine was enabled at its start marker).
    pub dma_taken: bool,
    /// Taken as a map frame (`hdr.ctrl.ENABLE`, grouped mode).
    pub map: Option<super::dma::MapFrame>,
    /// The sun accumulators take the frame (`super::sun`).
    pub sun_armed: bool,
    pub tag_index: u32,
    pub tag_frame: u32,
    pub tag_time: u64,
}

/// The capture block's state.
#[derive(Clone, Debug, Default)]
pub struct CaptureBlock {
    pub current: Option<FrameRx>,
    /// `capture.frames`, `capture.last_frame`, `capture.fifo_high_water`.
    pub frames: u32,
    pub last_pixels: u32,
    pub last_lines: u32,
    pub high_water: u32,
}

fn saturate12(v: u64) -> u32 {
    v.min(0xFFF) as u32
}

impl FabricModel {
    fn bayer_config(&mut self, raw: bool) -> BayerConfig {
        let mode = self.stored(bayer::mode::REG.offset);
        let black = self.stored(bayer::black::REG.offset);
        let valid = self.stored(bayer::valid::REG.offset);
        let w = |m: &mut FabricModel, r: &skylux_regmap::Register, f: &skylux_regmap::Field| {
            f.get(m.stored(r.offset)) as u16
        };
        BayerConfig {
            phase: Phase::from_register(bayer::mode::PHASE.get(mode)),
            black: bayer::black::LEVEL.get(black) as u16,
            valid_min: bayer::valid::MIN.get(valid) as u16,
            valid_max: bayer::valid::MAX.get(valid) as u16,
            weight_r: w(self, &bayer::weight_r::REG, &bayer::weight_r::Q2_14),
            weight_g: w(self, &bayer::weight_g::REG, &bayer::weight_g::Q2_14),
            weight_b: w(self, &bayer::weight_b::REG, &bayer::weight_b::Q2_14),
            raw,
        }
    }

    /// FRAME_VALID rises: a frame starts if capture is enabled.
    pub(super) fn capture_frame_start(&mut self, samples: RawFrame) {
        let ctrl = self.stored(capture::ctrl::REG.offset);
        if capture::ctrl::ENABLE.get(ctrl) == 0 {
            self.capture.current = None;
            return;
        }
        let window = self.stored(capture::window::REG.offset);
        let raw = capture::ctrl::RAW.get(ctrl) != 0;
        let bayer = self.bayer_config(raw);
        let dma_enabled = dma::ctrl::ENABLE.get(self.stored(dma::ctrl::REG.offset)) != 0;
        // The ingest opens a map frame in grouped mode with `hdr.ctrl.ENABLE`, taking the
        // set's next place (skylux_rtl::dma::ingest).
        let map_enabled = hdr::ctrl::ENABLE.get(self.stored(hdr::ctrl::REG.offset)) != 0;
        let map = (dma_enabled && map_enabled && !raw).then(|| {
            let thresholds = HdrConfig {
                min_q11: hdr::min::Q11.get(self.stored(hdr::min::REG.offset)),
                max_q11: hdr::max::Q11.get(self.stored(hdr::max::REG.offset)),
            };
            self.dma.hdr.open(thresholds)
        });
        let sun_armed = dma_enabled && self.sun_armed(raw, self.seq.tag_index);
        let s = &self.seq;
        self.capture.current = Some(FrameRx {
            samples,
            width: capture::window::WIDTH.get(window),
            height: capture::window::HEIGHT.get(window),
            bayer,
            dma_taken: dma_enabled,
            map,
            sun_armed,
            tag_index: s.tag_index,
            tag_frame: s.tag_frame,
            tag_time: s.tag_time,
        });
    }

    /// A reset of the sensor mid-frame: the frame is abandoned (not modelled further).
    pub(super) fn capture_abandon(&mut self) {
        self.capture.current = None;
    }

    /// FRAME_VALID falls after `lines` lines: check, form the words, hand over to the DMA.
    pub(super) fn capture_frame_end(&mut self, lines: u32, faults: &[HardwareFault]) {
        let Some(rx) = self.capture.current.take() else {
            return;
        };
        let sensor_w = rx.samples.width;
        // The lines on the bus: the sensor's, one longer or shorter by a fault, extra lines
        // (beyond its window) carrying zeros.
        let line_px = |y: u32| {
            let delta = faults
                .iter()
                .filter_map(|f| match *f {
                    HardwareFault::LineLength { line, delta_px } if line == y => Some(delta_px),
                    _ => None,
                })
                .sum::<i32>();
            (sensor_w as u32).saturating_add_signed(delta)
        };
        let (width, height) = (rx.width, rx.height);
        let mut flags = 0u32;
        let mut last_pixels = 0u32;
        let forwarded_lines = lines.min(height);
        let mut forwarded: Vec<Vec<u16>> = Vec::with_capacity(forwarded_lines as usize);
        for y in 0..lines {
            let n = line_px(y);
            last_pixels = n;
            if n < width {
                flags |= flag::LINE_SHORT;
            }
            if n > width {
                flags |= flag::LINE_LONG;
            }
            if y < height {
                let kept = n.min(width) as usize;
                let row = (0..kept)
                    .map(|x| {
                        let (yy, xx) = (y as usize, x);
                        if yy < rx.samples.height && xx < sensor_w {
                            rx.samples.samples_dn[yy * sensor_w + xx]
                        } else {
                            0
                        }
                    })
                    .collect();
                forwarded.push(row);
            }
        }
        if lines < height {
            flags |= flag::FRAME_SHORT;
        }
        if lines > height {
            flags |= flag::FRAME_LONG;
        }
        let mut words = self.words_of(&forwarded, width, &rx.bayer);
        // A stalled port: the FIFOs fill at the frame's mean word rate, then words are lost.
        let stall = faults
            .iter()
            .filter_map(|f| match *f {
                HardwareFault::PortStall { cycles } => Some(cycles),
                _ => None,
            })
            .max()
            .unwrap_or(0);
        let mut high_water = 2u64;
        if stall > 0 {
            let g = rx.samples.width as f64;
            let row_sys = self
                .pix_to_sys(
                    self.timeline
                        .frame
                        .as_ref()
                        .map(|f| f.settings.geometry.row_pixclk())
                        .unwrap_or(1),
                )
                .max(1) as f64;
            let per_row = if rx.bayer.raw { g / 2.0 } else { g / 4.0 };
            let arriving = (stall as f64 * per_row / row_sys) as u64;
            high_water = arriving.min(FIFO_DEPTH);
            let lost = arriving.saturating_sub(STALL_CAPACITY_WORDS) as usize;
            if lost > 0 {
                flags |= flag::FIFO_OVERFLOW;
                let from = (words.len() / 4).min(words.len());
                let to = (from + lost).min(words.len());
                words.drain(from..to);
            }
        }
        let bus_timeout =
            u64::from(dma::bus_timeout::CYCLES.get(self.stored(dma::bus_timeout::REG.offset)));
        let timed_out = stall > bus_timeout;
        self.capture.frames = self.capture.frames.wrapping_add(1);
        self.capture.last_pixels = saturate12(last_pixels.into());
        self.capture.last_lines = saturate12(lines.into());
        self.capture.high_water = high_water as u32;
        self.capture_status(flags);
        if rx.dma_taken {
            // The stall begins a quarter into the frame (where its words are lost); the last
            // beats leave once it has ended and the FIFOs have drained.
            let (rise, fall) = self
                .timeline
                .frame
                .as_ref()
                .map(|f| (f.rise_at, f.fall_at))
                .unwrap_or((self.now, self.now));
            let stall_end = rise + (fall.saturating_sub(rise)) / 4 + stall;
            let drained = if stall > 0 {
                stall_end + STALL_CAPACITY_WORDS / 2
            } else {
                0
            };
            let latency = self
                .pix_to_sys(END_MARKER_DELAY)
                .max(drained.saturating_sub(self.now));
            let corrupt = faults.iter().find_map(|f| match *f {
                HardwareFault::CorruptWord { word, xor } => Some((word, xor)),
                _ => None,
            });
            let swap = faults.contains(&HardwareFault::SwapSlots);
            self.dma_frame(super::dma::FrameOut {
                words,
                flags: flags | if timed_out { flag::BUS_TIMEOUT } else { 0 },
                last_pixels: saturate12(last_pixels.into()),
                lines: saturate12(lines.into()),
                raw: rx.bayer.raw,
                map: rx.map,
                sun_armed: rx.sun_armed,
                tag_index: rx.tag_index,
                tag_frame: rx.tag_frame,
                tag_time: rx.tag_time,
                ready_after: latency,
                corrupt,
                swap,
                bus_timeout: timed_out,
            });
        }
    }

    /// PIXCLK stopped during the frame after `lines` lines: the ingest's watchdog closes it
    /// with what arrived (no end marker: geometry 0, `PIXCLK_STOPPED`).
    pub(super) fn capture_pixclk_stopped(&mut self, lines: u32) {
        let Some(rx) = self.capture.current.take() else {
            self.capture_status(flag::PIXCLK_STOPPED);
            return;
        };
        let (w, h) = (rx.samples.width, rx.samples.height);
        let n = (lines as usize).min(h).min(rx.height as usize);
        let kept = w.min(rx.width as usize);
        let forwarded: Vec<Vec<u16>> = (0..n)
            .map(|y| {
                rx.samples
                    .samples_dn
                    .get(y * w..y * w + kept)
                    .map(<[u16]>::to_vec)
                    .unwrap_or_default()
            })
            .collect();
        let words = self.words_of(&forwarded, rx.width, &rx.bayer);
        self.capture_status(flag::PIXCLK_STOPPED);
        if rx.dma_taken {
            self.dma_frame(super::dma::FrameOut {
                words,
                flags: flag::PIXCLK_STOPPED,
                last_pixels: 0,
                lines: 0,
                raw: rx.bayer.raw,
                map: rx.map,
                sun_armed: rx.sun_armed,
                tag_index: rx.tag_index,
                tag_frame: rx.tag_frame,
                tag_time: rx.tag_time,
                ready_after: 0,
                corrupt: None,
                swap: false,
                bus_timeout: false,
            });
        }
    }

    /// The words of the forwarded lines: raw pairs per line (an odd last sample has no pair),
    /// or the grouper's words over the lines padded to the window width with zeros [U: the
    /// grouper's output for malformed lines is not specified].
    fn words_of(&self, lines: &[Vec<u16>], width: u32, config: &BayerConfig) -> Vec<u32> {
        if config.raw {
            lines
                .iter()
                .flat_map(|l| {
                    l.chunks_exact(2)
                        .map(|p| skylux_regmap::words::raw::pack(p[0], p[1]))
                })
                .collect()
        } else {
            let width = width as usize;
            if width == 0 || lines.is_empty() {
                return Vec::new();
            }
            let mut samples = Vec::with_capacity(width * lines.len());
            for l in lines {
                samples.extend(l.iter().copied().take(width));
                samples.extend(std::iter::repeat_n(0, width.saturating_sub(l.len())));
            }
            expected_words(
                &Frame {
                    width,
                    height: lines.len(),
                    samples,
                },
                config,
            )
        }
    }

    /// Sticky `capture.status` bits from the frame's flags (and `dma.status.OVERFLOW`).
    fn capture_status(&mut self, flags: u32) {
        use capture::status as cs;
        let map = [
            (flag::LINE_SHORT, cs::LINE_SHORT),
            (flag::LINE_LONG, cs::LINE_LONG),
            (flag::FRAME_SHORT, cs::FRAME_SHORT),
            (flag::FRAME_LONG, cs::FRAME_LONG),
            (flag::FIFO_OVERFLOW, cs::FIFO_OVERFLOW),
            (flag::PIXCLK_STOPPED, cs::PIXCLK_STOPPED),
        ];
        let bits = map
            .iter()
            .filter(|(f, _)| flags & f != 0)
            .fold(0, |m, (_, field)| m | field.mask());
        if bits != 0 {
            self.regs.set_bits(cs::REG.offset, bits);
            self.irq(&sys::irq_status::CAPTURE_ERROR);
        }
        if flags & flag::FIFO_OVERFLOW != 0 {
            self.regs
                .set_bits(dma::status::REG.offset, dma::status::OVERFLOW.mask());
            self.irq(&sys::irq_status::DMA_ERROR);
        }
    }

    pub(super) fn capture_inputs(&mut self) {
        let fv = self.timeline.frame_valid(self.now);
        let c = &self.capture;
        let inputs = [
            (
                capture::status::REG.offset,
                capture::status::FRAME_VALID.word(fv.into()),
            ),
            (
                capture::last_frame::REG.offset,
                capture::last_frame::PIXELS.word(c.last_pixels)
                    | capture::last_frame::LINES.word(c.last_lines),
            ),
            (
                capture::fifo_high_water::REG.offset,
                capture::fifo_high_water::WORDS.word(c.high_water.min(0xFFFF)),
            ),
            (capture::frames::REG.offset, c.frames),
        ];
        for (o, v) in inputs {
            self.regs.fabric_inputs.insert(o, v);
        }
    }
}
