//! Evaluation of a compiled program for one ray, with calcomp's semantics: function
//! arguments are evaluated only when the body asks for them, once per call (`calfunc.c`
//! `argument`), so `if` picks a branch and recursion ends; `:` constants are computed once;
//! a division by zero, an illegal power or a library domain error gives 0 and a warning.

use super::ast::BinaryOp;
use super::context::CalContext;
use super::error::{CalError, CalWarning};
use super::library::LibraryFunction;
use super::program::{CalProgram, Callee, Node, NodeId, SymbolId};

/// Deepest evaluation (expression levels and calls together): bounds the stack for runaway
/// recursion such as `f(x) = f(x)`, which calcomp would follow until it crashes.
const MAX_DEPTH: usize = 1500;
/// Most expression nodes one top-level evaluation may visit: bounds the time of a function
/// such as a Fibonacci without a reachable base case, which calcomp would run for ever.
const MAX_STEPS: u64 = 2_000_000;
/// Warnings kept per evaluator (the rest are counted).
const MAX_WARNINGS: usize = 64;

/// One function activation.
struct Frame {
    symbol: Option<SymbolId>,
    /// The call node's arguments, `None` for a call from Rust with given values.
    arguments: Option<(u32, u32)>,
    /// Start of this frame's cached argument values in `Evaluator::argument_values`.
    values_base: usize,
    count: usize,
    caller: usize,
}

/// Evaluates names of a [`CalProgram`]; holds caches, so keep one per thread and per ray.
pub struct Evaluator<'p> {
    program: &'p CalProgram,
    frames: Vec<Frame>,
    argument_values: Vec<Option<f64>>,
    /// Constants, computed once for the evaluator's life.
    constants: Vec<Option<f64>>,
    /// Variables, computed once per top-level evaluation (`generation`).
    variables: Vec<(u64, f64)>,
    generation: u64,
    depth: usize,
    steps: u64,
    warnings: Vec<CalWarning>,
    warning_count: usize,
}

impl<'p> Evaluator<'p> {
    pub fn new(program: &'p CalProgram) -> Self {
        let n = program.symbols.len();
        Self {
            program,
            frames: Vec::new(),
            argument_values: Vec::new(),
            constants: vec![None; n],
            variables: vec![(0, 0.0); n],
            generation: 0,
            depth: 0,
            steps: 0,
            warnings: Vec::new(),
            warning_count: 0,
        }
    }

    /// The first warnings raised, and how many there were in all.
    pub fn warnings(&self) -> (&[CalWarning], usize) {
        (&self.warnings, self.warning_count)
    }

    /// The value of the variable `name` for the ray in `context`.
    pub fn variable(&mut self, name: &str, context: &dyn CalContext) -> Result<f64, CalError> {
        let id = self
            .program
            .symbol(name)
            .ok_or_else(|| CalError::Undefined {
                name: name.to_string(),
                kind: "variable",
            })?;
        self.begin();
        self.variable_value(id, 0, context)
    }

    /// The value of the function `name` at `arguments` for the ray in `context`.
    pub fn call(
        &mut self,
        name: &str,
        arguments: &[f64],
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        let id = self
            .program
            .symbol(name)
            .ok_or_else(|| CalError::Undefined {
                name: name.to_string(),
                kind: "function",
            })?;
        self.begin();
        let base = self.argument_values.len();
        self.argument_values
            .extend(arguments.iter().map(|&a| Some(a)));
        self.frames.push(Frame {
            symbol: Some(id),
            arguments: None,
            values_base: base,
            count: arguments.len(),
            caller: 0,
        });
        let frame = self.frames.len() - 1;
        let result = self.invoke(id, frame, context);
        self.frames.truncate(frame);
        self.argument_values.truncate(base);
        result
    }

    /// Starts a top-level evaluation: variables are recomputed for the new ray.
    fn begin(&mut self) {
        self.generation += 1;
        self.depth = 0;
        self.steps = 0;
        self.frames.clear();
        self.argument_values.clear();
        // The root frame: no function, no arguments.
        self.frames.push(Frame {
            symbol: None,
            arguments: None,
            values_base: 0,
            count: 0,
            caller: 0,
        });
    }

    fn warn(&mut self, warning: CalWarning) {
        self.warning_count += 1;
        if self.warnings.len() < MAX_WARNINGS {
            self.warnings.push(warning);
        }
    }

    fn current_name(&self, frame: usize) -> String {
        self.frames[frame]
            .symbol
            .map_or_else(|| "(top)".to_string(), |s| self.program.name(s).to_string())
    }

    fn node(
        &mut self,
        node: NodeId,
        frame: usize,
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        self.steps += 1;
        if self.steps > MAX_STEPS {
            return Err(CalError::TooLong {
                name: self.current_name(frame),
                limit: MAX_STEPS,
            });
        }
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(CalError::TooDeep {
                name: self.current_name(frame),
                limit: MAX_DEPTH,
            });
        }
        let value = self.node_value(node, frame, context);
        self.depth -= 1;
        value
    }

    fn node_value(
        &mut self,
        node: NodeId,
        frame: usize,
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        match self.program.nodes[node as usize] {
            Node::Number(v) => Ok(v),
            Node::Variable(id) => self.variable_value(id, frame, context),
            Node::Parameter(i) => self.argument(frame, i as usize, context),
            Node::Negate(inner) => Ok(-self.node(inner, frame, context)?),
            Node::Binary(op, left, right) => self.binary(op, left, right, frame, context),
            Node::Call {
                callee,
                first,
                count,
            } => {
                let id = self.resolve_callee(callee, frame)?;
                let base = self.argument_values.len();
                self.argument_values.resize(base + count as usize, None);
                self.frames.push(Frame {
                    symbol: Some(id),
                    arguments: Some((first, count)),
                    values_base: base,
                    count: count as usize,
                    caller: frame,
                });
                let callee_frame = self.frames.len() - 1;
                let result = self.invoke(id, callee_frame, context);
                self.frames.truncate(callee_frame);
                self.argument_values.truncate(base);
                result
            }
        }
    }

    /// calcomp's `edivi` and `epow`: 0 and a warning where C would give ±∞ or NaN.
    fn binary(
        &mut self,
        op: BinaryOp,
        left: NodeId,
        right: NodeId,
        frame: usize,
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        if op == BinaryOp::Divide {
            let denominator = self.node(right, frame, context)?;
            if denominator == 0.0 {
                self.warn(CalWarning::DivisionByZero);
                return Ok(0.0);
            }
            return Ok(self.node(left, frame, context)? / denominator);
        }
        let a = self.node(left, frame, context)?;
        let b = self.node(right, frame, context)?;
        Ok(match op {
            BinaryOp::Add => a + b,
            BinaryOp::Subtract => a - b,
            BinaryOp::Multiply => a * b,
            BinaryOp::Power => {
                let p = a.powf(b);
                if !p.is_finite() {
                    self.warn(CalWarning::IllegalPower);
                    return Ok(0.0);
                }
                p
            }
            BinaryOp::Divide => unreachable!("handled above"),
        })
    }

    fn variable_value(
        &mut self,
        id: SymbolId,
        frame: usize,
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        let symbol = &self.program.symbols[id.0 as usize];
        let Some(definition) = &symbol.definition else {
            if let Some(v) = symbol.ray_variable {
                return Ok(context.ray_variable(v));
            }
            return Err(CalError::Undefined {
                name: symbol.name.clone(),
                kind: "variable",
            });
        };
        if definition.parameter_count.is_some() {
            return Err(CalError::Misuse {
                name: symbol.name.clone(),
                message: "a function used as a variable".to_string(),
            });
        }
        let (constant, body) = (definition.constant, definition.body);
        let slot = id.0 as usize;
        if constant {
            if let Some(v) = self.constants.get(slot).copied().flatten() {
                return Ok(v);
            }
        } else if let Some(&(generation, v)) = self.variables.get(slot) {
            if generation == self.generation {
                return Ok(v);
            }
        }
        let value = self.node(body, frame, context)?;
        if constant {
            if let Some(c) = self.constants.get_mut(slot) {
                *c = Some(value);
            }
        } else if let Some(v) = self.variables.get_mut(slot) {
            *v = (self.generation, value);
        }
        Ok(value)
    }

    /// The `i`-th argument of the call in `frame`, evaluated in its caller on first use.
    fn argument(
        &mut self,
        frame: usize,
        i: usize,
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        let f = &self.frames[frame];
        if i >= f.count {
            return Err(CalError::TooFewArguments {
                name: self.current_name(frame),
            });
        }
        if let Some(v) = self.argument_values[f.values_base + i] {
            return Ok(v);
        }
        let (first, _) = f.arguments.ok_or_else(|| CalError::TooFewArguments {
            name: self.current_name(frame),
        })?;
        let (caller, base) = (f.caller, f.values_base);
        let expr = self.program.call_arguments[first as usize + i];
        let value = self.node(expr, caller, context)?;
        self.argument_values[base + i] = Some(value);
        Ok(value)
    }

    /// The function a call names: a symbol, or the function name passed to a parameter
    /// (followed through the callers, as `calfunc.c` `eargf` does).
    fn resolve_callee(&self, callee: Callee, frame: usize) -> Result<SymbolId, CalError> {
        let (mut index, mut frame) = match callee {
            Callee::Symbol(id) => return Ok(id),
            Callee::Parameter(i) => (i as usize, frame),
        };
        loop {
            let f = &self.frames[frame];
            let not_function = || CalError::NotAFunction {
                name: self.current_name(frame),
            };
            let (first, count) = f.arguments.ok_or_else(not_function)?;
            if index >= count as usize {
                return Err(CalError::TooFewArguments {
                    name: self.current_name(frame),
                });
            }
            let expr = self.program.call_arguments[first as usize + index];
            match self.program.nodes[expr as usize] {
                Node::Variable(id) => return Ok(id),
                Node::Parameter(j) => {
                    index = j as usize;
                    frame = f.caller;
                }
                _ => return Err(not_function()),
            }
        }
    }

    /// Runs the function `id` in `frame` (its arguments already set up).
    fn invoke(
        &mut self,
        id: SymbolId,
        frame: usize,
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        let symbol = &self.program.symbols[id.0 as usize];
        if let Some(definition) = &symbol.definition {
            if definition.parameter_count.is_none() {
                return Err(CalError::Misuse {
                    name: symbol.name.clone(),
                    message: "a variable called as a function".to_string(),
                });
            }
            return self.node(definition.body, frame, context);
        }
        let Some(function) = symbol.library else {
            return Err(CalError::Undefined {
                name: symbol.name.clone(),
                kind: "function",
            });
        };
        let value = self.library(function, frame, context)?;
        if value.is_finite() {
            Ok(value)
        } else {
            // calcomp's `libfunc`: NaN (EDOM) or infinity (ERANGE) becomes 0 and a warning.
            self.warn(CalWarning::DomainError {
                function: function.name().to_string(),
            });
            Ok(0.0)
        }
    }

    /// A library function; a NaN result stands for calcomp's EDOM.
    fn library(
        &mut self,
        function: LibraryFunction,
        frame: usize,
        context: &dyn CalContext,
    ) -> Result<f64, CalError> {
        let count = self.frames[frame].count;
        match function {
            LibraryFunction::If => {
                let branch = if self.argument(frame, 0, context)? > 0.0 {
                    1
                } else {
                    2
                };
                self.argument(frame, branch, context)
            }
            LibraryFunction::Select => {
                // calfunc.c l_select: index rounded, 0 asks for the number of choices.
                let a1 = self.argument(frame, 0, context)?;
                let n = (a1 + 0.5) as i64;
                if a1 < -0.5 || n >= count as i64 || a1.is_nan() {
                    return Ok(f64::NAN);
                }
                if n == 0 {
                    return Ok((count - 1) as f64);
                }
                self.argument(frame, n as usize, context)
            }
            LibraryFunction::Min | LibraryFunction::Max => {
                let mut best = self.argument(frame, 0, context)?;
                for i in (1..count).rev() {
                    let v = self.argument(frame, i, context)?;
                    let better = if function == LibraryFunction::Min {
                        v < best
                    } else {
                        v > best
                    };
                    if better {
                        best = v;
                    }
                }
                Ok(best)
            }
            LibraryFunction::Atan2 => {
                let y = self.argument(frame, 0, context)?;
                let x = self.argument(frame, 1, context)?;
                Ok(y.atan2(x))
            }
            LibraryFunction::Arg => {
                // rtrace's l_arg: rounded index, 0 gives the count, out of range is EDOM.
                let a1 = self.argument(frame, 0, context)?;
                let arguments = context.real_arguments();
                let n = (a1 + 0.5).floor();
                if n == 0.0 {
                    return Ok(arguments.len() as f64);
                }
                if !(n >= 1.0 && n <= arguments.len() as f64) {
                    return Ok(f64::NAN);
                }
                Ok(arguments[n as usize - 1])
            }
            one => {
                let x = self.argument(frame, 0, context)?;
                Ok(one.of_one(x).unwrap_or(f64::NAN))
            }
        }
    }
}
