//! Writes BSDF data as a WINDOW 6 / LBNL XML file that RADIANCE reads (`checkBSDF`, the
//! `BSDF` material, `bsdf2ttree`): the layout RADIANCE's own `wrapBSDF` writes, one
//! `WavelengthDataBlock` per part, values in 1/sr. Klems data as `Columns` (each row one
//! outgoing patch, each column one incident patch); a tensor tree as one full-resolution
//! grid (`{ v v ... }`, dimension 0 varying slowest: a tree of one leaf grid, which RADIANCE
//! reads as it reads a reduced one).

use super::klems::AngleBasis;
use super::side::Side;
use std::fmt::Write;

/// One part's data, 1/sr: for Klems `values[outgoing * n + incident]`; for a tree its grid.
pub struct DocumentPart<'a> {
    pub side: Side,
    pub values: &'a [f64],
}

/// How the data is organised.
#[derive(Clone, Copy)]
pub enum DocumentData<'a> {
    /// Klems matrices over this basis (incident and outgoing).
    Klems(&'a AngleBasis),
    /// A `TensorTree3` (dims 3, isotropic) or `TensorTree4` grid of 2^log2_res cells per
    /// dimension.
    TensorTree { dims: u32, log2_res: u32 },
}
/// What the file says about the device, and its data.
pub struct BsdfDocument<'a> {
    /// `<Name>`.
    pub name: &'a str,
    /// The command that made it, kept as an XML comment (as genBSDF does).
    pub created_by: &'a str,
    /// The geometry's unit as the file names it (`meter`, `millimeter`, ...) and the device's
    /// thickness, width and height in it.
    pub unit: &'a str,
    pub thickness: f64,
    pub width: f64,
    pub height: f64,
    pub data: DocumentData<'a>,
    pub parts: Vec<DocumentPart<'a>>,
}

/// The XML text of `doc`, visible band. Fails when a part's size does not fit the data's.
pub fn bsdf_xml(doc: &BsdfDocument) -> Result<String, String> {
    let (expected, row) = match doc.data {
        DocumentData::Klems(basis) => (basis.len() * basis.len(), basis.len()),
        DocumentData::TensorTree { dims, log2_res } => {
            if !(3..=4).contains(&dims) || log2_res == 0 || dims * log2_res > 24 {
                return Err(format!(
                    "a {dims}-D tree of 2^{log2_res} cells per dimension"
                ));
            }
            (1 << (dims * log2_res), 1 << log2_res)
        }
    };
    for part in &doc.parts {
        if part.values.len() != expected {
            return Err(format!(
                "{}: {} values where the data needs {expected}",
                part.side.window_label(),
                part.values.len()
            ));
        }
    }
    let mut s = String::new();
    let comment = doc.created_by.replace("--", "- -");
    let name = escape(doc.name);
    let unit = escape(doc.unit);
    // `write!` into a String cannot fail.
    let _ = write!(
        s,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <!-- Created by: {comment} -->\n\
         <WindowElement xmlns=\"http://windows.lbl.gov\" \
         xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" \
         xsi:schemaLocation=\"http://windows.lbl.gov/BSDF-v1.4.xsd\">\n\
         <WindowElementType>System</WindowElementType>\n\
         <FileType>BSDF</FileType>\n<Optical>\n<Layer>\n\t<Material>\n\
         \t\t<Name>{name}</Name>\n\t\t<Manufacturer>Skylux genbsdf</Manufacturer>\n\
         \t\t<DeviceType>Other</DeviceType>\n\
         \t\t<Thickness unit=\"{unit}\">{}</Thickness>\n\
         \t\t<Width unit=\"{unit}\">{}</Width>\n\
         \t\t<Height unit=\"{unit}\">{}</Height>\n\
         \t</Material>\n\t<Geometry></Geometry>\n\t<DataDefinition>\n",
        doc.thickness, doc.width, doc.height
    );
    let basis_line = match doc.data {
        DocumentData::Klems(basis) => {
            definition(&mut s, basis);
            let name = escape(&basis.name);
            format!(
                "\t\t\t<ColumnAngleBasis>{name}</ColumnAngleBasis>\n\
                 \t\t\t<RowAngleBasis>{name}</RowAngleBasis>\n"
            )
        }
        DocumentData::TensorTree { dims, .. } => {
            let _ = write!(
                s,
                "\t\t<IncidentDataStructure>TensorTree{dims}</IncidentDataStructure>\n\
                 \t</DataDefinition>\n"
            );
            "\t\t\t<AngleBasis>LBNL/Shirley-Chiu</AngleBasis>\n".to_string()
        }
    };
    for part in &doc.parts {
        let _ = write!(
            s,
            "\t<WavelengthData>\n\t\t<LayerNumber>System</LayerNumber>\n\
             \t\t<Wavelength unit=\"Integral\">Visible</Wavelength>\n\
             \t\t<SourceSpectrum>CIE Illuminant D65 1nm.ssp</SourceSpectrum>\n\
             \t\t<DetectorSpectrum>ASTM E308 1931 Y.dsp</DetectorSpectrum>\n\
             \t\t<WavelengthDataBlock>\n\
             \t\t\t<WavelengthDataDirection>{}</WavelengthDataDirection>\n\
             {basis_line}\
             \t\t\t<ScatteringDataType>BTDF</ScatteringDataType>\n\
             \t\t\t<ScatteringData>\n",
            part.side.window_label()
        );
        let tree = matches!(doc.data, DocumentData::TensorTree { .. });
        if tree {
            s.push_str("{\n");
        }
        for chunk in part.values.chunks(row) {
            for v in chunk {
                // Negative zero and noise below f32's range are written as 0.
                let v = if v.abs() < 1e-30 { 0.0 } else { *v };
                let _ = write!(s, "{v:.6e}\t");
            }
            s.push('\n');
        }
        if tree {
            s.push_str("}\n");
        }
        s.push_str("\t\t\t</ScatteringData>\n\t\t</WavelengthDataBlock>\n\t</WavelengthData>\n");
    }
    s.push_str("</Layer>\n</Optical>\n</WindowElement>\n");
    Ok(s)
}

/// The `IncidentDataStructure` and `AngleBasis` of Klems data.
fn definition(s: &mut String, basis: &AngleBasis) {
    let name = escape(&basis.name);
    let _ = write!(
        s,
        "\t\t<IncidentDataStructure>Columns</IncidentDataStructure>\n\
         \t\t<AngleBasis>\n\t\t\t<AngleBasisName>{name}</AngleBasisName>\n"
    );
    for (lower, upper, n_phis) in basis.rings() {
        let centre = if lower == 0.0 {
            0.0
        } else {
            0.5 * (lower + upper)
        };
        let _ = write!(
            s,
            "\t\t\t<AngleBasisBlock>\n\t\t\t\t<Theta>{centre}</Theta>\n\
             \t\t\t\t<nPhis>{n_phis}</nPhis>\n\t\t\t\t<ThetaBounds>\n\
             \t\t\t\t\t<LowerTheta>{lower}</LowerTheta>\n\
             \t\t\t\t\t<UpperTheta>{upper}</UpperTheta>\n\
             \t\t\t\t</ThetaBounds>\n\t\t\t</AngleBasisBlock>\n"
        );
    }
    s.push_str("\t\t</AngleBasis>\n\t</DataDefinition>\n");
}

/// `text` with XML's special characters escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
