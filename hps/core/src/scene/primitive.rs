//! A RADIANCE primitive of any type, read but not interpreted: what inline commands produce
//! and transform before the subset Skylux traces is built from it.

use super::error::SourceLocation;

/// One primitive, `modifier type identifier` and its three argument lists (reference manual
/// §2.1). `alias` keeps the aliased name as its one string.
#[derive(Clone, Debug, PartialEq)]
pub struct Primitive {
    pub modifier: String,
    pub type_name: String,
    pub identifier: String,
    pub strings: Vec<String>,
    pub integers: Vec<i64>,
    pub reals: Vec<f64>,
    /// Where it is defined: the file and line of its text, or of the command that made it.
    pub origin: SourceLocation,
}

/// RADIANCE's surface types (`T_S` in otypes.h); every other type is a modifier.
const SURFACE_TYPES: &[&str] = &[
    "polygon", "sphere", "bubble", "cone", "cup", "cylinder", "tube", "ring", "source", "instance",
    "mesh",
];

impl Primitive {
    /// Surfaces cannot modify other primitives; modifiers can (RADIANCE `ismodifier`).
    pub fn is_surface(&self) -> bool {
        SURFACE_TYPES.contains(&self.type_name.as_str())
    }
}
