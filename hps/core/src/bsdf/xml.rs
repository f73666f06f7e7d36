//! Reading a WINDOW 6 / LBNL BSDF XML file into its blocks, as text and names: which
//! data structure, which angle bases, and per `WavelengthDataBlock` its direction, bases and
//! scattering text. No physics here; `klems.rs` and `tensor_tree.rs` give the numbers meaning.

use super::error::BsdfError;
use super::scattering_text::ScatteringText;
use roxmltree::{Document, Node};

/// How the file lays out its scattering data (`DataDefinition/IncidentDataStructure`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataStructure {
    /// A Klems-style matrix whose columns are the incident directions (rows outgoing).
    Columns,
    /// A Klems-style matrix whose rows are the incident directions.
    Rows,
    /// An isotropic variable-resolution tree (incident theta, outgoing square).
    TensorTree3,
    /// An anisotropic variable-resolution tree (incident square, outgoing square).
    TensorTree4,
}

/// `WavelengthDataDirection` in WINDOW's words. WINDOW's front faces the outside, which is
/// RADIANCE's back (RADIANCE `bsdf.h`): "Transmission Front" is light entering from the -z side.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WindowDirection {
    TransmissionFront,
    TransmissionBack,
    ReflectionFront,
    ReflectionBack,
}

/// A name read from an element's text, with the element's line.
#[derive(Debug, Clone)]
pub struct NamedAt {
    pub name: String,
    pub line: u32,
}

/// One ring of a custom `AngleBasis` (`AngleBasisBlock`).
#[derive(Debug, Clone)]
pub struct RawRing {
    pub lower_theta_deg: Option<f64>,
    pub upper_theta_deg: f64,
    pub n_phis: usize,
    pub line: u32,
}

/// An `AngleBasis` the file defines.
#[derive(Debug, Clone)]
pub struct RawAngleBasis {
    pub name: String,
    pub line: u32,
    pub rings: Vec<RawRing>,
}

/// One `WavelengthDataBlock` with the band (`Wavelength`) of its `WavelengthData`.
#[derive(Debug, Clone)]
pub struct RawBlock {
    /// `Visible`, `Solar`, `CIE-X`, ... as written.
    pub band: String,
    pub direction: WindowDirection,
    pub line: u32,
    pub column_basis: Option<NamedAt>,
    pub row_basis: Option<NamedAt>,
    pub angle_basis: Option<NamedAt>,
    pub data: ScatteringText,
}

/// The parts of a BSDF file that the evaluation needs.
#[derive(Debug, Clone)]
pub struct RawBsdf {
    pub file: String,
    pub structure: DataStructure,
    /// Line of the `Layer` element, for errors about what it lacks.
    pub layer_line: u32,
    pub angle_bases: Vec<RawAngleBasis>,
    pub blocks: Vec<RawBlock>,
}

/// Reads `text` (the contents of `file`, named in errors).
pub fn read_bsdf_xml(text: &str, file: &str) -> Result<RawBsdf, BsdfError> {
    let (body, skipped_lines) = skip_leading_text(text);
    let doc = Document::parse(body).map_err(|e| {
        // A truncated file: its last line is where it ends, more useful than the root's.
        let line = match e {
            roxmltree::Error::UnclosedRootNode => body.lines().count() as u32,
            _ => e.pos().row,
        } + skipped_lines;
        BsdfError::new(file, line, "xml", format!("not well-formed XML: {e}"))
    })?;
    let reader = Reader {
        doc: &doc,
        file,
        skipped_lines,
    };
    let layer = reader.layer()?;
    let definition = reader.required(layer, "DataDefinition")?;
    let structure = reader.data_structure(definition)?;
    let angle_bases = children(definition, "AngleBasis")
        .map(|b| reader.angle_basis(b))
        .collect::<Result<Vec<_>, _>>()?;
    let mut blocks = Vec::new();
    for data in children(layer, "WavelengthData") {
        let band = reader.required_text(data, "Wavelength")?;
        let mut any = false;
        for block in children(data, "WavelengthDataBlock") {
            blocks.push(reader.block(block, &band.name)?);
            any = true;
        }
        if !any {
            return Err(reader.error(data, "WavelengthData", "no WavelengthDataBlock"));
        }
    }
    if blocks.is_empty() {
        return Err(reader.error(layer, "Layer", "no WavelengthData block"));
    }
    Ok(RawBsdf {
        file: file.to_string(),
        structure,
        layer_line: reader.line(layer),
        angle_bases,
        blocks,
    })
}

/// genBSDF may leave a line such as "Recover using: ..." before the XML declaration;
/// RADIANCE's parser skips text before the first `<`, and so do we, counting its lines.
fn skip_leading_text(text: &str) -> (&str, u32) {
    let start = text.find('<').unwrap_or(0);
    let skipped = &text[..start];
    (&text[start..], skipped.matches('\n').count() as u32)
}

/// The element children of `node` named `name` (any namespace).
fn children<'a, 'i>(node: Node<'a, 'i>, name: &'static str) -> impl Iterator<Item = Node<'a, 'i>> {
    node.children()
        .filter(move |c| c.is_element() && c.tag_name().name() == name)
}

fn child<'a, 'i>(node: Node<'a, 'i>, name: &'static str) -> Option<Node<'a, 'i>> {
    children(node, name).next()
}

struct Reader<'d, 'i> {
    doc: &'d Document<'i>,
    file: &'d str,
    skipped_lines: u32,
}

impl<'d, 'i> Reader<'d, 'i> {
    fn line(&self, node: Node) -> u32 {
        self.line_at(node.range().start)
    }

    fn line_at(&self, offset: usize) -> u32 {
        self.doc.text_pos_at(offset).row + self.skipped_lines
    }

    fn error(&self, node: Node, element: &str, message: impl Into<String>) -> BsdfError {
        BsdfError::new(self.file, self.line(node), element, message)
    }

    fn required(
        &self,
        parent: Node<'d, 'i>,
        name: &'static str,
    ) -> Result<Node<'d, 'i>, BsdfError> {
        child(parent, name).ok_or_else(|| {
            let parent_name = parent.tag_name().name().to_string();
            self.error(parent, &parent_name, format!("missing <{name}>"))
        })
    }

    /// The trimmed text of a required child, refused when empty.
    fn required_text(
        &self,
        parent: Node<'d, 'i>,
        name: &'static str,
    ) -> Result<NamedAt, BsdfError> {
        let node = self.required(parent, name)?;
        self.optional_text(node)
            .ok_or_else(|| self.error(node, name, "empty"))
    }

    fn optional_text(&self, node: Node) -> Option<NamedAt> {
        let text = node.text().unwrap_or("").trim();
        (!text.is_empty()).then(|| NamedAt {
            name: text.to_string(),
            line: self.line(node),
        })
    }

    /// `WindowElement/Optical/Layer`, after the checks RADIANCE's `SDloadFile` makes.
    fn layer(&self) -> Result<Node<'d, 'i>, BsdfError> {
        let root = self.doc.root_element();
        if root.tag_name().name() != "WindowElement" {
            let name = root.tag_name().name().to_string();
            return Err(self.error(root, &name, "top-level element is not <WindowElement>"));
        }
        if let Some(kind) = child(root, "FileType") {
            let text = kind.text().unwrap_or("").trim();
            if text != "BSDF" {
                return Err(self.error(kind, "FileType", format!("'{text}', not 'BSDF'")));
            }
        }
        let optical = self.required(root, "Optical")?;
        self.required(optical, "Layer")
    }

    fn data_structure(&self, definition: Node) -> Result<DataStructure, BsdfError> {
        let kind = self.required_text(definition, "IncidentDataStructure")?;
        let structure = match kind.name.to_ascii_lowercase().as_str() {
            "columns" => DataStructure::Columns,
            "rows" => DataStructure::Rows,
            "tensortree3" => DataStructure::TensorTree3,
            "tensortree4" => DataStructure::TensorTree4,
            _ => {
                return Err(BsdfError::new(
                    self.file,
                    kind.line,
                    "IncidentDataStructure",
                    format!(
                        "unsupported '{}' (Columns, Rows, TensorTree3 or TensorTree4)",
                        kind.name
                    ),
                ))
            }
        };
        Ok(structure)
    }

    fn number(&self, parent: Node, name: &'static str) -> Result<f64, BsdfError> {
        let text = self.required_text(parent, name)?;
        text.name
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| {
                BsdfError::new(
                    self.file,
                    text.line,
                    name,
                    format!("'{}' is not a number", text.name),
                )
            })
    }

    fn angle_basis(&self, basis: Node) -> Result<RawAngleBasis, BsdfError> {
        let name = self.required_text(basis, "AngleBasisName")?;
        let mut rings = Vec::new();
        for block in children(basis, "AngleBasisBlock") {
            let bounds = self.required(block, "ThetaBounds")?;
            let lower_theta_deg = match child(bounds, "LowerTheta") {
                Some(_) => Some(self.number(bounds, "LowerTheta")?),
                None => None,
            };
            let upper_theta_deg = self.number(bounds, "UpperTheta")?;
            let n_phis = self.number(block, "nPhis")?;
            if !(1.0..=100_000.0).contains(&n_phis) || n_phis.fract() != 0.0 {
                return Err(self.error(block, "nPhis", format!("illegal phi count {n_phis}")));
            }
            rings.push(RawRing {
                lower_theta_deg,
                upper_theta_deg,
                n_phis: n_phis as usize,
                line: self.line(block),
            });
        }
        Ok(RawAngleBasis {
            name: name.name,
            line: self.line(basis),
            rings,
        })
    }

    fn block(&self, block: Node, band: &str) -> Result<RawBlock, BsdfError> {
        let direction = self.required_text(block, "WavelengthDataDirection")?;
        let direction = match direction.name.to_ascii_lowercase().as_str() {
            "transmission front" => WindowDirection::TransmissionFront,
            "transmission back" => WindowDirection::TransmissionBack,
            "reflection front" => WindowDirection::ReflectionFront,
            "reflection back" => WindowDirection::ReflectionBack,
            _ => {
                return Err(BsdfError::new(
                    self.file,
                    direction.line,
                    "WavelengthDataDirection",
                    format!("unknown direction '{}'", direction.name),
                ))
            }
        };
        let data_node = self.required(block, "ScatteringData")?;
        let text_start = data_node
            .first_child()
            .map(|t| t.range().start)
            .unwrap_or(data_node.range().start);
        let data = ScatteringText {
            text: data_node.text().unwrap_or("").to_string(),
            line: self.line_at(text_start),
        };
        let named = |name| child(block, name).and_then(|n| self.optional_text(n));
        Ok(RawBlock {
            band: band.to_string(),
            direction,
            line: self.line(block),
            column_basis: named("ColumnAngleBasis"),
            row_basis: named("RowAngleBasis"),
            angle_basis: named("AngleBasis"),
            data,
        })
    }
}
