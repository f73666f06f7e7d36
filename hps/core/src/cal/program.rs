//! The compiled form of one or more `.cal` files: a flat arena of expression nodes whose names
//! are resolved to symbol indices once, at load time, so evaluation looks nothing up by name.
//! Files load in order; a later definition of a name replaces the earlier one for every
//! expression that uses it, as in calcomp (names link to their definition, not its text).

use std::collections::HashMap;

use super::ast::{BinaryOp, Definition, Expr};
use super::context::RayVariable;
use super::library::LibraryFunction;

/// Index of a name in a [`CalProgram`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SymbolId(pub(super) u32);

/// Index of a node in the arena.
pub(super) type NodeId = u32;

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Node {
    Number(f64),
    Variable(SymbolId),
    /// The n-th (0-based) parameter of the function being evaluated.
    Parameter(u16),
    Negate(NodeId),
    Binary(BinaryOp, NodeId, NodeId),
    /// Arguments are `call_arguments[first..first + count]`.
    Call {
        callee: Callee,
        first: u32,
        count: u32,
    },
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Callee {
    Symbol(SymbolId),
    /// A parameter that names a function (rayinit.cal's `dot(v1, v2)`).
    Parameter(u16),
}

/// What a name is bound to.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Symbol {
    pub name: String,
    pub definition: Option<CompiledDefinition>,
    pub library: Option<LibraryFunction>,
    pub ray_variable: Option<RayVariable>,
}

#[derive(Debug, Clone, PartialEq)]
pub(super) struct CompiledDefinition {
    /// `None` for a variable, the parameter count for a function.
    pub parameter_count: Option<usize>,
    pub constant: bool,
    pub body: NodeId,
}

/// Definitions from `.cal` files, compiled.
#[derive(Debug, Clone, Default)]
pub struct CalProgram {
    pub(super) nodes: Vec<Node>,
    pub(super) call_arguments: Vec<NodeId>,
    pub(super) symbols: Vec<Symbol>,
    by_name: HashMap<String, SymbolId>,
}

impl CalProgram {
    pub fn new() -> Self {
        Self::default()
    }

    /// The symbol of `name`, if any file or the library uses or defines it.
    pub fn symbol(&self, name: &str) -> Option<SymbolId> {
        self.by_name.get(name).copied()
    }

    /// The symbol of `name`, created (bound to the library or a ray variable if it names
    /// one) on first use.
    pub(super) fn intern(&mut self, name: &str) -> SymbolId {
        if let Some(&id) = self.by_name.get(name) {
            return id;
        }
        let id = SymbolId(self.symbols.len() as u32);
        self.symbols.push(Symbol {
            name: name.to_string(),
            definition: None,
            library: LibraryFunction::lookup(name),
            ray_variable: RayVariable::from_name(name),
        });
        self.by_name.insert(name.to_string(), id);
        id
    }

    pub fn name(&self, id: SymbolId) -> &str {
        &self.symbols[id.0 as usize].name
    }

    /// Whether `name` has a definition from a file (not only a library binding).
    pub fn is_defined(&self, name: &str) -> bool {
        self.symbol(name)
            .is_some_and(|id| self.symbols[id.0 as usize].definition.is_some())
    }

    /// How many arguments the function `name` takes: its definition's parameters, or 1 for
    /// a library function; None if `name` is no function (RADIANCE's `fundefined`).
    pub fn parameter_count(&self, name: &str) -> Option<usize> {
        let symbol = &self.symbols[self.symbol(name)?.0 as usize];
        match &symbol.definition {
            Some(d) => d.parameter_count,
            None => symbol.library.map(|_| 1),
        }
    }

    /// Whether `name` is currently a variable defined with `:`.
    pub(super) fn is_constant_variable(&self, name: &str) -> bool {
        self.symbol(name)
            .and_then(|id| self.symbols[id.0 as usize].definition.as_ref())
            .is_some_and(|d| d.constant && d.parameter_count.is_none())
    }

    pub(super) fn define(&mut self, definition: &Definition) {
        let parameters = definition.parameters.as_deref().unwrap_or(&[]);
        let body = self.compile(&definition.body, parameters);
        let id = self.intern(&definition.name);
        self.symbols[id.0 as usize].definition = Some(CompiledDefinition {
            parameter_count: definition.parameters.as_ref().map(Vec::len),
            constant: definition.constant,
            body,
        });
    }

    fn push(&mut self, node: Node) -> NodeId {
        self.nodes.push(node);
        (self.nodes.len() - 1) as NodeId
    }

    /// Appends `expr` to the arena, parameters resolved to their positions.
    fn compile(&mut self, expr: &Expr, parameters: &[String]) -> NodeId {
        let parameter = |name: &str| parameters.iter().position(|p| p == name);
        match expr {
            Expr::Number(v) => self.push(Node::Number(*v)),
            Expr::Name(name) => match parameter(name) {
                Some(i) => self.push(Node::Parameter(i as u16)),
                None => {
                    let id = self.intern(name);
                    self.push(Node::Variable(id))
                }
            },
            Expr::Negate(inner) => {
                let inner = self.compile(inner, parameters);
                self.push(Node::Negate(inner))
            }
            Expr::Binary(op, left, right) => {
                let left = self.compile(left, parameters);
                let right = self.compile(right, parameters);
                self.push(Node::Binary(*op, left, right))
            }
            Expr::Call(name, args) => {
                let callee = match parameter(name) {
                    Some(i) => Callee::Parameter(i as u16),
                    None => Callee::Symbol(self.intern(name)),
                };
                let compiled: Vec<NodeId> =
                    args.iter().map(|a| self.compile(a, parameters)).collect();
                let first = self.call_arguments.len() as u32;
                self.call_arguments.extend(compiled);
                self.push(Node::Call {
                    callee,
                    first,
                    count: args.len() as u32,
                })
            }
        }
    }
}
