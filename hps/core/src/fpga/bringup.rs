//! Bring-up: prove the bridge works and the fabric is the design this software was built for,
//! before anything else is touched.

use skylux_bus::{BusError, RegisterAccess, RegisterBus};
use skylux_regmap::{sys, DESIGN_ID, UNMAPPED_READ_VALUE, VERSION_MAJOR};

/// What the fabric reported at bring-up.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FabricInfo {
    pub version_major: u32,
    pub version_minor: u32,
    pub sys_clock_hz: u32,
}

/// Why bring-up refused the fabric.
#[derive(Debug, thiserror::Error)]
pub enum BringUpError {
    #[error("register bus: {0}")]
    Bus(#[from] BusError),
    #[error("sys.id reads {found:#010x}, expected {DESIGN_ID:#010x} (\"SKYL\"): {hint}")]
    WrongId { found: u32, hint: &'static str },
    #[error("register map v{found_major}.{found_minor} in the fabric, this software speaks v{VERSION_MAJOR}.x: load the matching bitstream")]
    WrongVersion { found_major: u32, found_minor: u32 },
    #[error("sys.scratch does not hold what was written ({wrote:#010x} written, {read:#010x} read): the bridge does not carry writes")]
    ScratchMismatch { wrote: u32, read: u32 },
}

/// The fabric, brought up and checked.
pub struct Fabric<B: RegisterBus> {
    bus: B,
    info: FabricInfo,
}

fn id_hint(found: u32) -> &'static str {
    match found {
        0 | 0xFFFF_FFFF => "the bridge is disabled or the FPGA is not configured (enable the bridges in U-Boot: see bitstream/README.md)",
        UNMAPPED_READ_VALUE => "the address is unmapped: wrong register window base",
        _ => "another design is loaded",
    }
}

impl<B: RegisterBus> Fabric<B> {
    /// Checks `sys.id`, the major version and a scratch write/read round trip.
    pub fn bring_up(mut bus: B) -> Result<Self, BringUpError> {
        let id = bus.read_reg(&sys::id::REG, 0)?;
        if id != DESIGN_ID {
            return Err(BringUpError::WrongId {
                found: id,
                hint: id_hint(id),
            });
        }
        let version = bus.read_reg(&sys::version::REG, 0)?;
        let (major, minor) = (
            sys::version::MAJOR.get(version),
            sys::version::MINOR.get(version),
        );
        if major != VERSION_MAJOR {
            return Err(BringUpError::WrongVersion {
                found_major: major,
                found_minor: minor,
            });
        }
        for pattern in [0xA5A5_5A5A, 0x5A5A_A5A5] {
            bus.write_reg(&sys::scratch::REG, 0, pattern)?;
            let read = bus.read_reg(&sys::scratch::REG, 0)?;
            if read != pattern {
                return Err(BringUpError::ScratchMismatch {
                    wrote: pattern,
                    read,
                });
            }
        }
        let sys_clock_hz = bus.read_field(&sys::clock_hz::REG, 0, &sys::clock_hz::VALUE)?;
        Ok(Self {
            bus,
            info: FabricInfo {
                version_major: major,
                version_minor: minor,
                sys_clock_hz,
            },
        })
    }

    /// What bring-up found.
    pub fn info(&self) -> &FabricInfo {
        &self.info
    }

    /// The underlying bus, for drivers of individual blocks.
    pub fn bus(&mut self) -> &mut B {
        &mut self.bus
    }

    /// Gives the bus back.
    pub fn into_bus(self) -> B {
        self.bus
    }
}
