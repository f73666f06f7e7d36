//! BSDF data of complex fenestration: WINDOW 6 / LBNL BSDF XML files (Klems matrices over
//! any angle basis, tensor trees), evaluated as RADIANCE's BSDF library does (`bsdf.c`,
//! `bsdf_m.c`, `bsdf_t.c`) so that a material built on them answers as RADIANCE's.
//!
//! Directions are unit vectors in the BSDF's own frame: the surface normal is +z ("front",
//! WINDOW's back) and both directions point away from the surface. Values are in 1/sr.

mod error;
mod klems;
mod klems_transmission;
mod part;
mod sample;
mod scattering_text;
mod shirley_chiu;
mod side;
mod tensor_tree;
mod through;
mod xml;
mod xml_writer;

pub use error::BsdfError;
pub use klems::AngleBasis;
pub use klems_transmission::KlemsTransmission;
pub use sample::{BsdfSample, OutgoingDistribution};
pub use shirley_chiu::{disk_to_square, square_to_disk};
pub use side::Side;
pub use through::Through;
pub use xml_writer::{bsdf_xml, BsdfDocument, DocumentData, DocumentPart};

use glam::DVec3;
use klems::KlemsMatrix;
use part::Part;
use std::f64::consts::PI;
use std::path::Path;
use tensor_tree::TensorTree;
use xml::{DataStructure, RawBsdf};

/// Which spectral band of the file to read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Band {
    /// Photopic (`Visible`): what RADIANCE renders with.
    Visible,
    /// `Solar`, for energy.
    Solar,
    /// `CIE-X` and `CIE-Z`, the other tristimulus values of colour matrices.
    CieX,
    CieZ,
}

impl Band {
    pub fn label(self) -> &'static str {
        match self {
            Band::Visible => "Visible",
            Band::Solar => "Solar",
            Band::CieX => "CIE-X",
            Band::CieZ => "CIE-Z",
        }
    }
}

/// Reflection or transmission, for hemispherical values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scattering {
    Reflection,
    Transmission,
}

/// The Lambertian share of each part, as hemispherical fractions (RADIANCE's `rLambFront`...).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Lambertian {
    pub reflectance_front: f64,
    pub reflectance_back: f64,
    pub transmittance_front: f64,
    pub transmittance_back: f64,
}

/// A loaded BSDF, one band.
#[derive(Debug, Clone)]
pub struct Bsdf {
    /// The file it came from, for messages.
    pub source: String,
    pub lambertian: Lambertian,
    /// Non-Lambertian parts, indexed by `side_index`.
    parts: [Option<Part>; 4],
    /// Incident-coordinate step of tree distributions: 1/256 or the smallest leaf if finer
    /// (RADIANCE `bsdf_t.c` `quantum`).
    quantum: f64,
}

fn side_index(side: Side) -> usize {
    match side {
        Side::FrontReflection => 0,
        Side::BackReflection => 1,
        Side::FrontTransmission => 2,
        Side::BackTransmission => 3,
    }
}

/// Parts whose largest hemispherical value is at most this are dropped (RADIANCE `SDloadFile`).
const NEGLIGIBLE_HEMISPHERICAL: f64 = 0.001;

impl Bsdf {
    /// Reads the visible band of a BSDF XML file.
    pub fn load(path: &Path) -> Result<Bsdf, BsdfError> {
        Self::load_band(path, Band::Visible)
    }

    pub fn load_band(path: &Path, band: Band) -> Result<Bsdf, BsdfError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| BsdfError::new(&file, 0, "file", format!("cannot read: {e}")))?;
        Self::from_xml(&text, &file, band)
    }

    /// Reads BSDF XML `text`; `file` names it in errors.
    pub fn from_xml(text: &str, file: &str, band: Band) -> Result<Bsdf, BsdfError> {
        let raw = xml::read_bsdf_xml(text, file)?;
        let mut parts = read_parts(&raw, band)?;
        let quantum = parts
            .iter()
            .flatten()
            .filter_map(|p| match p {
                Part::Tree(t) => Some(t.smallest_leaf()),
                Part::Klems(_) => None,
            })
            .fold(1.0 / 256.0, f64::min);
        let lambertian = separate_lambertian(&mut parts);
        Ok(Bsdf {
            source: file.to_string(),
            lambertian,
            parts,
            quantum,
        })
    }

    /// Whether any part is a tensor tree (data finer than a Klems basis).
    pub fn has_tensor_tree(&self) -> bool {
        self.parts
            .iter()
            .flatten()
            .any(|p| matches!(p, Part::Tree(_)))
    }

    pub fn part_present(&self, side: Side) -> bool {
        self.parts[side_index(side)].is_some()
    }

    fn part(&self, side: Side) -> Option<&Part> {
        self.parts[side_index(side)].as_ref()
    }

    /// The part answering for light in from `incident_front` and out to `outgoing_front`;
    /// transmission falls back on the other direction's data (RADIANCE `SDevalBSDF`).
    fn part_for(&self, incident_front: bool, outgoing_front: bool) -> Option<&Part> {
        let side = Side::of(incident_front, outgoing_front);
        let own = self.parts[side_index(side)].as_ref();
        if side.is_transmission() {
            own.or(self.parts[side_index(side.reversed())].as_ref())
        } else {
            own
        }
    }

    fn lambertian_of(&self, side: Side) -> f64 {
        let l = &self.lambertian;
        match side {
            Side::FrontReflection => l.reflectance_front,
            Side::BackReflection => l.reflectance_back,
            Side::FrontTransmission => l.transmittance_front,
            Side::BackTransmission => l.transmittance_back,
        }
    }

    /// f(ωi, ωo) in 1/sr, both directions pointing away from the surface.
    pub fn eval(&self, incident: DVec3, outgoing: DVec3) -> f64 {
        let (inf, outf) = (incident.z > 0.0, outgoing.z > 0.0);
        let diffuse = self.lambertian_of(Side::of(inf, outf)) / PI;
        diffuse
            + self
                .part_for(inf, outf)
                .map_or(0.0, |p| p.eval(incident, outgoing))
    }

    /// Directional-hemispherical reflectance or transmittance for light from `incident`
    /// (RADIANCE `SDdirectHemi`).
    pub fn hemispherical(&self, incident: DVec3, kind: Scattering) -> f64 {
        let inf = incident.z > 0.0;
        let outf = match kind {
            Scattering::Reflection => inf,
            Scattering::Transmission => !inf,
        };
        let diffuse = self.lambertian_of(Side::of(inf, outf));
        let part = self
            .part_for(inf, outf)
            .and_then(|p| p.distribution(incident, self.quantum))
            .map_or(0.0, |d| d.total());
        diffuse + part
    }
}

/// Reads every block of `band` into its part, refusing a second block for one part.
fn read_parts(raw: &RawBsdf, band: Band) -> Result<[Option<Part>; 4], BsdfError> {
    let file = raw.file.as_str();
    let bases = raw
        .angle_bases
        .iter()
        .map(|b| AngleBasis::from_raw(b, file))
        .collect::<Result<Vec<_>, _>>()?;
    let mut parts: [Option<Part>; 4] = Default::default();
    for block in raw
        .blocks
        .iter()
        .filter(|b| b.band.eq_ignore_ascii_case(band.label()))
    {
        let part = match raw.structure {
            DataStructure::Columns | DataStructure::Rows => {
                Part::Klems(KlemsMatrix::from_block(block, raw.structure, &bases, file)?)
            }
            DataStructure::TensorTree3 => Part::Tree(TensorTree::from_block(block, 3, file)?),
            DataStructure::TensorTree4 => Part::Tree(TensorTree::from_block(block, 4, file)?),
        };
        let slot = &mut parts[side_index(part.side())];
        if slot.is_some() {
            let message = format!("a second {} block for {:?}", band.label(), part.side());
            return Err(BsdfError::new(
                file,
                block.line,
                "WavelengthDataBlock",
                message,
            ));
        }
        *slot = Some(part);
    }
    if parts.iter().all(Option::is_none) {
        let message = format!("no <Wavelength>{}</Wavelength> data", band.label());
        return Err(BsdfError::new(
            file,
            raw.layer_line,
            "WavelengthData",
            message,
        ));
    }
    Ok(parts)
}

/// Moves each part's minimum into a Lambertian share, shares transmission between the two
/// directions when only one is given, and drops negligible parts (RADIANCE `SDloadMtx`,
/// `SDloadTre`, `SDloadFile`).
fn separate_lambertian(parts: &mut [Option<Part>; 4]) -> Lambertian {
    let mut diffuse = [0.0; 4];
    let mut max_hemi = [0.0; 4];
    for (k, part) in parts.iter_mut().enumerate() {
        if let Some(part) = part {
            max_hemi[k] = part.max_hemispherical();
            diffuse[k] = part.extract_diffuse();
            max_hemi[k] -= diffuse[k];
        }
    }
    let (front_t, back_t) = (
        side_index(Side::FrontTransmission),
        side_index(Side::BackTransmission),
    );
    if parts[back_t].is_some() && parts[front_t].is_none() {
        diffuse[front_t] = diffuse[back_t];
    } else if parts[front_t].is_some() && parts[back_t].is_none() {
        diffuse[back_t] = diffuse[front_t];
    }
    for (k, part) in parts.iter_mut().enumerate() {
        if max_hemi[k] <= NEGLIGIBLE_HEMISPHERICAL {
            *part = None;
        }
    }
    Lambertian {
        reflectance_front: diffuse[0],
        reflectance_back: diffuse[1],
        transmittance_front: diffuse[2],
        transmittance_back: diffuse[3],
    }
}
