//! The parse tree of a `.cal` file, before names are resolved.

/// An expression as written.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Expr {
    Number(f64),
    /// A variable, or a parameter of the function being defined.
    Name(String),
    Negate(Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// `name(args...)`: a defined or library function, or a parameter holding a function.
    Call(String, Vec<Expr>),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum BinaryOp {
    Add,
    Subtract,
    Multiply,
    Divide,
    Power,
}

/// One statement: `name = expr;`, `name : expr;` (constant) or `name(p1, p2) = expr;`.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Definition {
    pub name: String,
    /// `None` for a variable, the parameter names for a function.
    pub parameters: Option<Vec<String>>,
    /// Defined with `:`: its value never changes within a ray or between rays.
    pub constant: bool,
    pub body: Expr,
    pub line: u32,
}
