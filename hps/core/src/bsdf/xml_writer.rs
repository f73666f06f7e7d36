//! Writes Klems BSDF data as a WINDOW 6 / LBNL XML file that RADIANCE reads (`checkBSDF`,
//! the `BSDF` material, `bsdf2ttree`): the layout RADIANCE's own `wrapBSDF` writes, one
//! `WavelengthDataBlock` per part, `Columns` (each row one outgoing patch, each column one
//! incident patch), values in 1/sr.

use super::klems::AngleBasis;
use super::side::Side;
use std::fmt::Write;

/// One part's matrix over the document's basis: `values[outgoing * n + incident]`, 1/sr.
pub struct KlemsPart<'a> {
    pub side: Side,
    pub values: &'a [f64],
}

/// What the file says about the device besides its data.
pub struct KlemsDocument<'a> {
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
    pub basis: &'a AngleBasis,
    pub parts: Vec<KlemsPart<'a>>,
}

/// The XML text of `doc`, visible band. Fails when a part's size is not the basis's square.
pub fn klems_xml(doc: &KlemsDocument) -> Result<String, String> {
    let n = doc.basis.len();
    for part in &doc.parts {
        if part.values.len() != n * n {
            return Err(format!(
                "{}: {} values for a {n}-patch basis",
                part.side.window_label(),
                part.values.len()
            ));
        }
    }
    let mut s = String::new();
    let comment = doc.created_by.replace("--", "- -");
    let name = escape(doc.name);
    let basis = escape(&doc.basis.name);
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
         \t</Material>\n\t<Geometry></Geometry>\n\t<DataDefinition>\n\
         \t\t<IncidentDataStructure>Columns</IncidentDataStructure>\n\
         \t\t<AngleBasis>\n\t\t\t<AngleBasisName>{basis}</AngleBasisName>\n",
        doc.thickness, doc.width, doc.height
    );
    for (lower, upper, n_phis) in doc.basis.rings() {
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
    for part in &doc.parts {
        let _ = write!(
            s,
            "\t<WavelengthData>\n\t\t<LayerNumber>System</LayerNumber>\n\
             \t\t<Wavelength unit=\"Integral\">Visible</Wavelength>\n\
             \t\t<SourceSpectrum>CIE Illuminant D65 1nm.ssp</SourceSpectrum>\n\
             \t\t<DetectorSpectrum>ASTM E308 1931 Y.dsp</DetectorSpectrum>\n\
             \t\t<WavelengthDataBlock>\n\
             \t\t\t<WavelengthDataDirection>{}</WavelengthDataDirection>\n\
             \t\t\t<ColumnAngleBasis>{basis}</ColumnAngleBasis>\n\
             \t\t\t<RowAngleBasis>{basis}</RowAngleBasis>\n\
             \t\t\t<ScatteringDataType>BTDF</ScatteringDataType>\n\
             \t\t\t<ScatteringData>\n",
            part.side.window_label()
        );
        for row in part.values.chunks(n) {
            for v in row {
                // Negative zero and noise below f32's range are written as 0.
                let v = if v.abs() < 1e-30 { 0.0 } else { *v };
                let _ = write!(s, "{v:.6e}\t");
            }
            s.push('\n');
        }
        s.push_str("\t\t\t</ScatteringData>\n\t\t</WavelengthDataBlock>\n\t</WavelengthData>\n");
    }
    s.push_str("</Layer>\n</Optical>\n</WindowElement>\n");
    Ok(s)
}

/// `text` with XML's special characters escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
