//! Which of the four scattering parts a block holds, in RADIANCE's frame: the surface normal
//! is +z and "front" is the +z side. WINDOW 6 calls that side "back" (RADIANCE `bsdf.h`,
//! `bsdf_m.c` `load_bsdf_data`), so its "Transmission Front" is our back transmission.

use super::xml::WindowDirection;

/// One scattering part, named by the side light arrives from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// In from +z, out to +z (WINDOW's "Reflection Back").
    FrontReflection,
    /// In from -z, out to -z (WINDOW's "Reflection Front").
    BackReflection,
    /// In from +z, out to -z (WINDOW's "Transmission Back").
    FrontTransmission,
    /// In from -z, out to +z (WINDOW's "Transmission Front").
    BackTransmission,
}

impl Side {
    pub fn from_window(direction: WindowDirection) -> Side {
        match direction {
            WindowDirection::ReflectionBack => Side::FrontReflection,
            WindowDirection::ReflectionFront => Side::BackReflection,
            WindowDirection::TransmissionBack => Side::FrontTransmission,
            WindowDirection::TransmissionFront => Side::BackTransmission,
        }
    }

    /// WINDOW's name of the part, as a file's `WavelengthDataDirection` gives it.
    pub fn window_label(self) -> &'static str {
        match self {
            Side::FrontReflection => "Reflection Back",
            Side::BackReflection => "Reflection Front",
            Side::FrontTransmission => "Transmission Back",
            Side::BackTransmission => "Transmission Front",
        }
    }

    /// The part light in from `incident_front` and out to `outgoing_front` goes through.
    pub fn of(incident_front: bool, outgoing_front: bool) -> Side {
        match (incident_front, outgoing_front) {
            (true, true) => Side::FrontReflection,
            (false, false) => Side::BackReflection,
            (true, false) => Side::FrontTransmission,
            (false, true) => Side::BackTransmission,
        }
    }

    /// Does light arrive from the +z side?
    pub fn incident_front(self) -> bool {
        matches!(self, Side::FrontReflection | Side::FrontTransmission)
    }

    /// Does light leave to the +z side?
    pub fn outgoing_front(self) -> bool {
        matches!(self, Side::FrontReflection | Side::BackTransmission)
    }

    pub fn is_transmission(self) -> bool {
        matches!(self, Side::FrontTransmission | Side::BackTransmission)
    }

    /// The same part seen with incident and outgoing exchanged (reciprocity).
    pub fn reversed(self) -> Side {
        match self {
            Side::FrontTransmission => Side::BackTransmission,
            Side::BackTransmission => Side::FrontTransmission,
            reflection => reflection,
        }
    }
}
