//! The ray-box unit in its world: the cycle-accurate rust-hdl model of
//! `skylux_rtl::raybox::RayBoxUnit`, its Avalon-MM port wired to an [`AvalonMemory`] (SDRAM
//! with random waitrequest), and its configuration and status ports to a behavioural model of
//! the `raybox.*` registers, so HPS code reaches it through the bus traits
//! ([`SimRayBoxRegisters`], [`SimRayBoxMemory`]) as it will reach the board.
//!
//! The whole-core register file is wired in later; here the register semantics come from
//! [`RegisterFileModel`] (written from the map), and the unit's W1C pulses set its bits.

use crate::bus::avalon_memory::{AgentOutputs, AvalonMemory, AvalonMemoryConfig, HostCommand};
use crate::bus::RegisterFileModel;
use rust_hdl::prelude::*;
use skylux_bus::{check_access, BusError, DmaMemory, RegisterBus};
use skylux_regmap::{raybox, sys};
use skylux_rtl::drive::{DriveError, Driver};
use skylux_rtl::raybox::RayBoxUnit;
use std::sync::{Arc, Mutex};

/// Fabric cycles one register access takes in this model (the lightweight bridge's Avalon
/// transfer plus the HPS's L3 path; a round figure, only so polling advances time).
pub const CYCLES_PER_REGISTER_ACCESS: u64 = 8;

fn clock<const L: usize>(d: &mut RayBoxUnit<L>) -> &mut Signal<In, Clock> {
    &mut d.clock
}

/// The unit, its memory and its registers, advanced cycle by cycle.
pub struct RayBoxSystem<const LANES: usize> {
    pub driver: Driver<RayBoxUnit<LANES>>,
    pub memory: AvalonMemory,
    pub registers: RegisterFileModel,
    pending_start: bool,
    pending_abort: bool,
    cycles: u64,
    /// Cycles with a read or write command accepted.
    pub busy_port_cycles: u64,
}

impl<const LANES: usize> RayBoxSystem<LANES> {
    pub fn new(memory: AvalonMemoryConfig) -> Self {
        let mut driver = Driver::new(RayBoxUnit::<LANES>::default());
        driver.dut.ctrl_start.next = false;
        driver.dut.ctrl_abort.next = false;
        Self {
            driver,
            memory: AvalonMemory::new(memory),
            registers: RegisterFileModel::default(),
            pending_start: false,
            pending_abort: false,
            cycles: 0,
            busy_port_cycles: 0,
        }
    }

    /// Clock cycles run so far.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    fn field(&mut self, reg: skylux_regmap::Register, f: skylux_regmap::Field) -> u64 {
        // Read the stored value without the model's read side effects on pulses.
        let pulse = self.registers.last_pulse;
        let v = f.get(self.registers.read(reg.offset)) as u64;
        self.registers.last_pulse = pulse;
        v
    }

    /// One clock cycle.
    pub fn cycle(&mut self) -> Result<(), DriveError> {
        let AgentOutputs {
            waitrequest,
            readdatavalid,
            readdata,
        } = self.memory.begin_cycle();
        let work_base = self.field(raybox::work_base::REG, raybox::work_base::ADDR);
        let work_count = self.field(raybox::work_count::REG, raybox::work_count::ITEMS);
        let result_base = self.field(raybox::result_base::REG, raybox::result_base::ADDR);
        let window_base = self.field(raybox::window_base::REG, raybox::window_base::ADDR);
        let window_size = self.field(raybox::window_size::REG, raybox::window_size::BYTES);
        let timeout = self.field(raybox::bus_timeout::REG, raybox::bus_timeout::CYCLES);
        let d = &mut self.driver.dut;
        d.rbx_waitrequest.next = waitrequest;
        d.rbx_readdatavalid.next = readdatavalid;
        d.rbx_readdata.next = (readdata as u64).to_bits();
        d.ctrl_start.next = std::mem::take(&mut self.pending_start);
        d.ctrl_abort.next = std::mem::take(&mut self.pending_abort);
        d.work_base_addr.next = work_base.to_bits();
        d.work_count_items.next = work_count.to_bits();
        d.result_base_addr.next = result_base.to_bits();
        d.window_base_addr.next = window_base.to_bits();
        d.window_size_bytes.next = window_size.to_bits();
        d.bus_timeout_cycles.next = timeout.to_bits();
        self.driver.settle()?;
        let d = &self.driver.dut;
        let cmd = HostCommand {
            address: d.rbx_address.val().to_u64(),
            read: d.rbx_read.val(),
            write: d.rbx_write.val(),
            burstcount: d.rbx_burstcount.val().to_u64() as u32,
            writedata: d.rbx_writedata.val().to_u64() as u128,
            byteenable: d.rbx_byteenable.val().to_u64() as u32,
        };
        if (cmd.read || cmd.write) && !waitrequest {
            self.busy_port_cycles += 1;
        }
        // Status into the register model: W1C pulses, RO values.
        let status = raybox::status::REG.offset;
        let mut set = 0;
        for (pulse, f) in [
            (d.status_done_set.val(), raybox::status::DONE),
            (
                d.status_bad_descriptor_set.val(),
                raybox::status::BAD_DESCRIPTOR,
            ),
            (
                d.status_out_of_window_set.val(),
                raybox::status::OUT_OF_WINDOW,
            ),
            (d.status_bus_timeout_set.val(), raybox::status::BUS_TIMEOUT),
        ] {
            if pulse {
                set |= f.mask();
            }
        }
        if set != 0 {
            self.registers.set_bits(status, set);
        }
        if d.status_done_set.val() {
            self.registers.set_bits(
                sys::irq_status::REG.offset,
                sys::irq_status::RAYBOX_DONE.mask(),
            );
        }
        let busy = raybox::status::BUSY.word(d.status_busy.val() as u32);
        let tests = d.tests_done_count.val().to_u64() as u32;
        let lanes = raybox::info::LANES.word(d.info_lanes.val().to_u64() as u32);
        let inputs = &mut self.registers.fabric_inputs;
        inputs.insert(status, busy);
        inputs.insert(raybox::tests_done::REG.offset, tests);
        inputs.insert(raybox::info::REG.offset, lanes);
        self.memory.end_cycle(&cmd);
        self.driver.set_clock(clock::<LANES>, true)?;
        self.driver.set_clock(clock::<LANES>, false)?;
        self.cycles += 1;
        Ok(())
    }

    /// Runs `n` cycles.
    pub fn run(&mut self, n: u64) -> Result<(), DriveError> {
        (0..n).try_for_each(|_| self.cycle())
    }

    /// A register write as the HPS does it: W1P fields become one-cycle pulses.
    pub fn write_register(&mut self, offset: u32, value: u32) -> Result<(), DriveError> {
        self.run(CYCLES_PER_REGISTER_ACCESS)?;
        self.registers.write(offset, value, 0xF);
        if let Some((off, bits)) = self.registers.last_pulse.take() {
            if off == raybox::ctrl::REG.offset {
                self.pending_start |= bits & raybox::ctrl::START.mask() != 0;
                self.pending_abort |= bits & raybox::ctrl::ABORT.mask() != 0;
            }
        }
        Ok(())
    }

    /// A register read as the HPS does it.
    pub fn read_register(&mut self, offset: u32) -> Result<u32, DriveError> {
        self.run(CYCLES_PER_REGISTER_ACCESS)?;
        // The model refreshes RO inputs every cycle; read them as they are now.
        Ok(self.registers.read(offset))
    }
}

/// Shared handle to a [`RayBoxSystem`], for the two bus-trait views of it.
pub type SharedRayBox<const LANES: usize> = Arc<Mutex<RayBoxSystem<LANES>>>;

fn lock<const L: usize>(
    s: &SharedRayBox<L>,
) -> Result<std::sync::MutexGuard<'_, RayBoxSystem<L>>, BusError> {
    s.lock()
        .map_err(|_| BusError::Simulation("ray-box model poisoned by an earlier panic".into()))
}

/// The register window as the HPS sees it (`skylux_bus::RegisterBus`), offsets in the
/// lightweight bridge window; only the `raybox` and `sys` blocks are modelled.
pub struct SimRayBoxRegisters<const LANES: usize>(pub SharedRayBox<LANES>);

impl<const L: usize> RegisterBus for SimRayBoxRegisters<L> {
    fn read32(&mut self, offset: u32) -> Result<u32, BusError> {
        check_access(
            offset as u64,
            4,
            skylux_regmap::LW_BRIDGE_SPAN_BYTES as u64,
            4,
        )?;
        lock(&self.0)?
            .read_register(offset)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }
    fn write32(&mut self, offset: u32, value: u32) -> Result<(), BusError> {
        check_access(
            offset as u64,
            4,
            skylux_regmap::LW_BRIDGE_SPAN_BYTES as u64,
            4,
        )?;
        lock(&self.0)?
            .write_register(offset, value)
            .map_err(|e| BusError::Simulation(e.to_string()))
    }
}

/// The SDRAM buffer as the HPS sees it (`skylux_bus::DmaMemory`): the model's storage.
pub struct SimRayBoxMemory<const LANES: usize>(pub SharedRayBox<LANES>);

impl<const L: usize> DmaMemory for SimRayBoxMemory<L> {
    fn phys_base(&self) -> u64 {
        self.0.lock().map(|s| s.memory.phys_base()).unwrap_or(0)
    }
    fn len_bytes(&self) -> u64 {
        self.0.lock().map(|s| s.memory.len_bytes()).unwrap_or(0)
    }
    fn read_bytes(&mut self, offset: u64, buf: &mut [u8]) -> Result<(), BusError> {
        lock(&self.0)?.memory.read_bytes(offset, buf)
    }
    fn write_bytes(&mut self, offset: u64, data: &[u8]) -> Result<(), BusError> {
        lock(&self.0)?.memory.write_bytes(offset, data)
    }
}

/// A shared system and its two bus views.
pub fn sim_backend<const LANES: usize>(
    memory: AvalonMemoryConfig,
) -> (
    SharedRayBox<LANES>,
    SimRayBoxRegisters<LANES>,
    SimRayBoxMemory<LANES>,
) {
    let shared = Arc::new(Mutex::new(RayBoxSystem::<LANES>::new(memory)));
    (
        shared.clone(),
        SimRayBoxRegisters(shared.clone()),
        SimRayBoxMemory(shared),
    )
}

/// Random (ray, box) pairs for the conservativeness check, weighted towards the hard cases:
/// grazing rays, rays parallel to a slab (zero direction components, origins in a face
/// plane), zero-size and millimetre boxes, hits near `t_min`/`t_max`, over a 100 m scene.
pub mod pairs {
    use glam::DVec3;
    use rand::rngs::StdRng;
    use rand::{Rng, SeedableRng};
    use skylux_hps::engine::accel::{entry_m, quantise};
    use skylux_hps::engine::ray::{Ray, RayBoxQuery};
    use skylux_hps::engine::slab::{Aabb, SlabTest};
    use skylux_regmap::raybox_format::test as golden;

    /// What the golden model answered against the f64 slab test.
    #[derive(Clone, Debug, Default, PartialEq, Eq)]
    pub struct ConservativeReport {
        pub pairs: u64,
        /// Pairs the f64 slab test reports as hits.
        pub reference_hits: u64,
        /// Reference hits the unit would report as misses (must be 0).
        pub false_misses: u64,
        /// Reference hits whose unit entry distance is after the reference's (must be 0).
        pub late_entries: u64,
        /// Reference misses the unit reports as hits (allowed: the rounding margin).
        pub false_hits: u64,
        /// Pairs the format cannot hold (answered in software).
        pub fallbacks: u64,
        /// Pairs with a zero direction component, and with a zero-size box.
        pub parallel: u64,
        pub zero_size: u64,
    }

    fn unit_vector(rng: &mut StdRng) -> DVec3 {
        loop {
            let v = DVec3::new(
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
                rng.gen_range(-1.0..1.0),
            );
            let l = v.length();
            if l > 1e-3 && l <= 1.0 {
                return v / l;
            }
        }
    }

    /// One random pair.
    pub fn random_pair(rng: &mut StdRng) -> (RayBoxQuery, Aabb) {
        let origin = DVec3::new(
            rng.gen_range(-50.0..50.0),
            rng.gen_range(-50.0..50.0),
            rng.gen_range(-50.0..50.0),
        );
        let mut d = unit_vector(rng);
        match rng.gen_range(0..8) {
            // Parallel to one or two slabs.
            0 => d[rng.gen_range(0..3)] = 0.0,
            1 => {
                let k = rng.gen_range(0..3);
                d[k] = 0.0;
                d[(k + 1) % 3] = 0.0;
            }
            // Grazing: a tiny component.
            2 => d[rng.gen_range(0..3)] = rng.gen_range(-1e-6..1e-6),
            3 => d[rng.gen_range(0..3)] *= 1e-3,
            _ => {}
        }
        let d = if d.length() > 0.0 {
            d.normalize()
        } else {
            DVec3::X
        };
        let ray = Ray::new(origin, d);
        // A box around a point near the ray, sizes from 0 to tens of metres.
        let t_point = rng.gen_range(-5.0..150.0);
        let size = |rng: &mut StdRng| match rng.gen_range(0..5) {
            0 => 0.0,
            1 => 0.001,
            2 => rng.gen_range(0.0..0.01),
            3 => rng.gen_range(0.0..1.0),
            _ => rng.gen_range(0.0..30.0),
        };
        let half = DVec3::new(size(rng), size(rng), size(rng)) * 0.5;
        let miss_by = rng.gen_range(0.0..0.003) * (rng.gen_range(0..3) as f64);
        // Half the boxes hold the ray point; the others sit just beside it.
        let off_m = if rng.gen_bool(0.5) {
            0.0
        } else {
            half.length() + miss_by
        };
        let centre = ray.at(t_point) + unit_vector(rng) * off_m;
        let mut b = Aabb {
            min_m: centre - half,
            max_m: centre + half,
        };
        if rng.gen_range(0..6) == 0 {
            // A face exactly in the origin's plane on a parallel axis.
            let k = rng.gen_range(0..3);
            if rng.gen_bool(0.5) {
                b.min_m[k] = origin[k];
                b.max_m[k] = b.max_m[k].max(origin[k]);
            } else {
                b.max_m[k] = origin[k];
                b.min_m[k] = b.min_m[k].min(origin[k]);
            }
        }
        let (t_min, t_max) = match rng.gen_range(0..4) {
            0 => (0.0, f64::INFINITY),
            1 => (0.0, rng.gen_range(0.0..200.0)),
            2 => (rng.gen_range(0.0..50.0), rng.gen_range(50.0..200.0)),
            _ => (0.0, 1e9),
        };
        (RayBoxQuery::new(&ray, t_min, t_max), b)
    }

    /// A random pair as the work item the HPS would send (pairs the format cannot hold are
    /// drawn again).
    pub fn random_item(rng: &mut StdRng) -> skylux_regmap::raybox_format::WorkItem {
        loop {
            let (q, b) = random_pair(rng);
            if let Some(item) = quantise(&q, &b) {
                return item;
            }
        }
    }

    /// Checks `n` random pairs from `seed`.
    pub fn check(n: u64, seed: u64) -> ConservativeReport {
        let mut rng = StdRng::seed_from_u64(seed);
        let mut r = ConservativeReport::default();
        for _ in 0..n {
            let (q, b) = random_pair(&mut rng);
            r.pairs += 1;
            if (0..3).any(|a| q.inverse_direction[a].is_infinite()) {
                r.parallel += 1;
            }
            if (0..3).any(|a| b.min_m[a] == b.max_m[a]) {
                r.zero_size += 1;
            }
            let reference = SlabTest::entry(&q, &b);
            let Some(item) = quantise(&q, &b) else {
                r.fallbacks += 1;
                continue;
            };
            let unit = golden(&item);
            match (reference, unit.hit) {
                (Some(t), true) => {
                    r.reference_hits += 1;
                    if entry_m(&q, unit) > t {
                        r.late_entries += 1;
                    }
                }
                (Some(_), false) => {
                    r.reference_hits += 1;
                    r.false_misses += 1;
                }
                (None, true) => r.false_hits += 1,
                (None, false) => {}
            }
        }
        r
    }
}
