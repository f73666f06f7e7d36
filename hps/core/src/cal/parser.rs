//! Statements and expressions of a `.cal` file, with calcomp's precedence (`calexpr.c`,
//! `getE1`..`getE5`): `+ -` left-associative, then `* /`, then `^` right-associative, then a
//! unary minus that binds to the primary only (so `-2^2` is 4, as calcomp computes it).

use super::ast::{BinaryOp, Definition, Expr};
use super::error::CalError;
use super::lexer::{tokenize, Located, Token};

/// Deepest nesting of parentheses and operators accepted: bounds the parser's and the
/// evaluator's stack on hostile input.
const MAX_NESTING: usize = 200;

/// Every definition in `text`, in order.
pub(super) fn parse_file(file: &str, text: &str) -> Result<Vec<Definition>, CalError> {
    let tokens = tokenize(file, text)?;
    let mut parser = Parser {
        file,
        tokens: &tokens,
        position: 0,
        depth: 0,
    };
    let mut definitions = Vec::new();
    while parser.position < tokens.len() {
        if parser.eat(';') {
            continue; // calcomp accepts empty statements
        }
        definitions.push(parser.statement()?);
        if parser.position < tokens.len() && !parser.eat(';') {
            return Err(parser.error("';' expected"));
        }
    }
    Ok(definitions)
}

struct Parser<'a> {
    file: &'a str,
    tokens: &'a [Located],
    position: usize,
    depth: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.position).map(|t| &t.token)
    }

    fn eat(&mut self, c: char) -> bool {
        if self.peek() == Some(&Token::Punct(c)) {
            self.position += 1;
            true
        } else {
            false
        }
    }

    fn line(&self) -> u32 {
        let last = self.tokens.last().map_or(1, |t| t.line);
        self.tokens.get(self.position).map_or(last, |t| t.line)
    }

    fn error(&self, message: &str) -> CalError {
        CalError::Syntax {
            file: self.file.to_string(),
            line: self.line(),
            message: message.to_string(),
        }
    }

    fn name(&mut self) -> Result<String, CalError> {
        match self.peek() {
            Some(Token::Name(n)) => {
                let n = n.clone();
                self.position += 1;
                Ok(n)
            }
            Some(Token::Channel(_)) => {
                Err(self.error("'$' channels belong to rcalc, not to a function file"))
            }
            _ => Err(self.error("name expected")),
        }
    }

    fn statement(&mut self) -> Result<Definition, CalError> {
        let line = self.line();
        let name = self.name()?;
        let parameters = if self.eat('(') {
            let mut names = vec![self.name()?];
            while self.eat(',') {
                names.push(self.name()?);
            }
            if !self.eat(')') {
                return Err(self.error("')' expected"));
            }
            Some(names)
        } else {
            None
        };
        let constant = if self.eat(':') {
            true
        } else if self.eat('=') {
            false
        } else {
            return Err(self.error("'=' or ':' expected"));
        };
        let body = self.sum()?;
        Ok(Definition {
            name,
            parameters,
            constant,
            body,
            line,
        })
    }

    fn nest(&mut self) -> Result<(), CalError> {
        self.depth += 1;
        if self.depth > MAX_NESTING {
            return Err(self.error(&format!("expression nested deeper than {MAX_NESTING}")));
        }
        Ok(())
    }

    /// E1: terms joined by `+` and `-`, left to right.
    fn sum(&mut self) -> Result<Expr, CalError> {
        self.nest()?;
        let mut left = self.product()?;
        loop {
            let op = if self.eat('+') {
                BinaryOp::Add
            } else if self.eat('-') {
                BinaryOp::Subtract
            } else {
                break;
            };
            left = Expr::Binary(op, Box::new(left), Box::new(self.product()?));
        }
        self.depth -= 1;
        Ok(left)
    }

    /// E2: factors joined by `*` and `/`, left to right.
    fn product(&mut self) -> Result<Expr, CalError> {
        let mut left = self.power()?;
        loop {
            let op = if self.eat('*') {
                BinaryOp::Multiply
            } else if self.eat('/') {
                BinaryOp::Divide
            } else {
                break;
            };
            left = Expr::Binary(op, Box::new(left), Box::new(self.power()?));
        }
        Ok(left)
    }

    /// E3: `E4 ^ E3`, right-associative.
    fn power(&mut self) -> Result<Expr, CalError> {
        self.nest()?;
        let base = self.unary()?;
        let result = if self.eat('^') {
            Expr::Binary(BinaryOp::Power, Box::new(base), Box::new(self.power()?))
        } else {
            base
        };
        self.depth -= 1;
        Ok(result)
    }

    /// E4: an optional sign before a primary.
    fn unary(&mut self) -> Result<Expr, CalError> {
        if self.eat('-') {
            return Ok(match self.primary()? {
                Expr::Number(v) => Expr::Number(-v),
                Expr::Negate(inner) => *inner,
                e => Expr::Negate(Box::new(e)),
            });
        }
        self.eat('+');
        self.primary()
    }

    /// E5: a parenthesised expression, a number, a name or a call.
    fn primary(&mut self) -> Result<Expr, CalError> {
        if self.eat('(') {
            let e = self.sum()?;
            if !self.eat(')') {
                return Err(self.error("')' expected"));
            }
            return Ok(e);
        }
        if let Some(Token::Number(v)) = self.peek() {
            let v = *v;
            self.position += 1;
            return Ok(Expr::Number(v));
        }
        let name = match self.peek() {
            Some(Token::Name(_)) | Some(Token::Channel(_)) => self.name()?,
            _ => return Err(self.error("unexpected character")),
        };
        if !self.eat('(') {
            return Ok(Expr::Name(name));
        }
        let mut args = vec![self.sum()?];
        while self.eat(',') {
            args.push(self.sum()?);
        }
        if !self.eat(')') {
            return Err(self.error("')' expected"));
        }
        Ok(Expr::Call(name, args))
    }
}
