//! The transmission matrix T of the three-phase method, read from a Klems BSDF file as
//! `dctimestep` and `rmtxop` read it (RADIANCE `cmbsdf.c`): WINDOW's "Transmission Front"
//! block (light from the outside into the room), rows the outgoing patches on the room side,
//! columns the incident patches outside, each entry the file's f (1/sr) times the incident
//! patch's projected solid angle, so that T maps the radiance arriving per patch to the
//! radiance leaving per patch. The file's values as written: no Lambertian share taken out.

use super::error::BsdfError;
use super::klems::{AngleBasis, KlemsMatrix};
use super::xml::{self, DataStructure, WindowDirection};
use super::Band;
use crate::io::radiance_matrix::RadianceMatrix;
use std::path::Path;

/// T of a Klems BSDF, one band.
#[derive(Debug, Clone)]
pub struct KlemsTransmission {
    /// The file it came from, for messages and headers.
    pub source: String,
    /// The basis of the columns (incident, outside) and of the rows (outgoing, room side).
    pub incident_basis: AngleBasis,
    pub outgoing_basis: AngleBasis,
    /// Rows outgoing × columns incident, one component, dimensionless.
    pub matrix: RadianceMatrix,
}

impl KlemsTransmission {
    pub fn load(path: &Path, band: Band) -> Result<Self, BsdfError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| BsdfError::new(&file, 0, "file", format!("cannot read: {e}")))?;
        Self::from_xml(&text, &file, band)
    }

    /// Reads `text` (the contents of `file`, named in errors).
    pub fn from_xml(text: &str, file: &str, band: Band) -> Result<Self, BsdfError> {
        let raw = xml::read_bsdf_xml(text, file)?;
        if !matches!(raw.structure, DataStructure::Columns | DataStructure::Rows) {
            return Err(BsdfError::new(
                file,
                raw.layer_line,
                "DataStructure",
                "a tensor tree, not a Klems matrix: the three-phase T needs one \
                 (RADIANCE's bsdf2klems converts)",
            ));
        }
        let bases = raw
            .angle_bases
            .iter()
            .map(|b| AngleBasis::from_raw(b, file))
            .collect::<Result<Vec<_>, _>>()?;
        let block = raw
            .blocks
            .iter()
            .find(|b| {
                b.band.eq_ignore_ascii_case(band.label())
                    && b.direction == WindowDirection::TransmissionFront
            })
            .ok_or_else(|| {
                BsdfError::new(
                    file,
                    raw.layer_line,
                    "WavelengthDataDirection",
                    format!(
                        "no {} 'Transmission Front' block (light from outside into the room)",
                        band.label()
                    ),
                )
            })?;
        let klems = KlemsMatrix::from_block(block, raw.structure, &bases, file)?;
        let (incident_basis, outgoing_basis) = (
            klems.incident_basis().clone(),
            klems.outgoing_basis().clone(),
        );
        let (n_in, n_out) = (incident_basis.len(), outgoing_basis.len());
        let mut values = Vec::with_capacity(n_in * n_out);
        for o in 0..n_out {
            for i in 0..n_in {
                values.push(
                    f64::from(klems.value(o, i)) * incident_basis.projected_solid_angle_sr(i),
                );
            }
        }
        let matrix = RadianceMatrix::from_grey(n_out, n_in, values).ok_or_else(|| {
            BsdfError::new(file, block.line, "ScatteringData", "matrix size overflows")
        })?;
        Ok(KlemsTransmission {
            source: file.to_string(),
            incident_basis,
            outgoing_basis,
            matrix,
        })
    }
}
