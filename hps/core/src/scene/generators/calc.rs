//! The expressions genrev takes for z(t) and r(t), in RADIANCE's `.cal` syntax (calcomp.c):
//! numbers, `t`, `PI`, `+ - * / ^` (unary minus binds tighter than `^`, `^` to the right),
//! parentheses, the usual functions and genrev's `hermite`, `bezier` and `bspline`. Files of
//! definitions (`-e`, `-f`) are not read.

/// Deepest nesting of parentheses and operators read (a guard for generated input).
const MAX_DEPTH: usize = 64;

/// A parsed expression.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Expr {
    Number(f64),
    Variable,
    Unary(Box<Expr>),
    Binary(char, Box<Expr>, Box<Expr>),
    Call(String, Vec<Expr>),
}

/// Parses `text`; the error names what is not understood.
pub(super) fn parse(text: &str) -> Result<Expr, String> {
    let mut p = Parser {
        chars: text.chars().filter(|c| !c.is_whitespace()).collect(),
        pos: 0,
        depth: 0,
    };
    let e = p.sum()?;
    match p.peek() {
        None => Ok(e),
        Some(c) => Err(format!("unexpected `{c}` in expression `{text}`")),
    }
}

struct Parser {
    chars: Vec<char>,
    pos: usize,
    depth: usize,
}

impl Parser {
    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).copied()
    }

    fn deeper(&mut self) -> Result<(), String> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(format!("expression nested deeper than {MAX_DEPTH}"));
        }
        Ok(())
    }

    fn sum(&mut self) -> Result<Expr, String> {
        self.deeper()?;
        let mut e = self.product()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.pos += 1;
            e = Expr::Binary(op, Box::new(e), Box::new(self.product()?));
        }
        self.depth -= 1;
        Ok(e)
    }

    fn product(&mut self) -> Result<Expr, String> {
        let mut e = self.power()?;
        while let Some(op @ ('*' | '/')) = self.peek() {
            self.pos += 1;
            e = Expr::Binary(op, Box::new(e), Box::new(self.power()?));
        }
        Ok(e)
    }

    fn power(&mut self) -> Result<Expr, String> {
        self.deeper()?;
        let base = self.unary()?;
        let e = if self.peek() == Some('^') {
            self.pos += 1;
            Expr::Binary('^', Box::new(base), Box::new(self.power()?))
        } else {
            base
        };
        self.depth -= 1;
        Ok(e)
    }

    fn unary(&mut self) -> Result<Expr, String> {
        match self.peek() {
            Some('-') => {
                self.pos += 1;
                self.deeper()?;
                let e = Expr::Unary(Box::new(self.unary()?));
                self.depth -= 1;
                Ok(e)
            }
            Some('+') => {
                self.pos += 1;
                self.unary()
            }
            _ => self.primary(),
        }
    }

    fn primary(&mut self) -> Result<Expr, String> {
        match self.peek() {
            Some('(') => {
                self.pos += 1;
                let e = self.sum()?;
                self.expect(')')?;
                Ok(e)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => self.number(),
            Some(c) if c.is_ascii_alphabetic() || c == '_' => self.name(),
            Some(c) => Err(format!("unexpected `{c}`")),
            None => Err("expression ends too soon".into()),
        }
    }

    fn expect(&mut self, c: char) -> Result<(), String> {
        if self.peek() == Some(c) {
            self.pos += 1;
            Ok(())
        } else {
            Err(format!("expected `{c}`"))
        }
    }

    fn number(&mut self) -> Result<Expr, String> {
        let start = self.pos;
        while matches!(self.peek(), Some(c) if c.is_ascii_digit() || c == '.') {
            self.pos += 1;
        }
        if matches!(self.peek(), Some('e' | 'E')) {
            let save = self.pos;
            self.pos += 1;
            if matches!(self.peek(), Some('+' | '-')) {
                self.pos += 1;
            }
            if !matches!(self.peek(), Some(c) if c.is_ascii_digit()) {
                self.pos = save;
            }
            while matches!(self.peek(), Some(c) if c.is_ascii_digit()) {
                self.pos += 1;
            }
        }
        let text: String = self.chars[start..self.pos].iter().collect();
        text.parse::<f64>()
            .map(Expr::Number)
            .map_err(|_| format!("`{text}` is not a number"))
    }

    fn name(&mut self) -> Result<Expr, String> {
        let start = self.pos;
        while matches!(self.peek(), Some(c) if c.is_ascii_alphanumeric() || c == '_' || c == '.') {
            self.pos += 1;
        }
        let name: String = self.chars[start..self.pos].iter().collect();
        if self.peek() != Some('(') {
            return match name.as_str() {
                "t" => Ok(Expr::Variable),
                "PI" => Ok(Expr::Number(std::f64::consts::PI)),
                _ => Err(format!(
                    "`{name}` is not defined (definitions from .cal files, -e and -f, are \
                     not read; expected t or PI)"
                )),
            };
        }
        self.pos += 1;
        let mut args = vec![self.sum()?];
        while self.peek() == Some(',') {
            self.pos += 1;
            args.push(self.sum()?);
        }
        self.expect(')')?;
        arity(&name, args.len())?;
        Ok(Expr::Call(name, args))
    }
}

/// Checks a function's name and argument count.
fn arity(name: &str, count: usize) -> Result<(), String> {
    let expected = match name {
        "sin" | "cos" | "tan" | "asin" | "acos" | "atan" | "exp" | "log" | "log10" | "sqrt"
        | "floor" | "ceil" => 1,
        "atan2" => 2,
        "hermite" | "bezier" | "bspline" => 5,
        _ => {
            return Err(format!(
                "function `{name}` is not known (.cal files are not read)"
            ))
        }
    };
    if count != expected {
        return Err(format!(
            "`{name}` takes {expected} argument(s), not {count}"
        ));
    }
    Ok(())
}

impl Expr {
    /// The value at parameter `t`.
    pub fn eval(&self, t: f64) -> f64 {
        match self {
            Expr::Number(v) => *v,
            Expr::Variable => t,
            Expr::Unary(e) => -e.eval(t),
            Expr::Binary(op, a, b) => {
                let (a, b) = (a.eval(t), b.eval(t));
                match op {
                    '+' => a + b,
                    '-' => a - b,
                    '*' => a * b,
                    '/' => a / b,
                    _ => a.powf(b),
                }
            }
            Expr::Call(name, args) => {
                let v: Vec<f64> = args.iter().map(|a| a.eval(t)).collect();
                call(name, &v)
            }
        }
    }
}

fn call(name: &str, v: &[f64]) -> f64 {
    match name {
        "sin" => v[0].sin(),
        "cos" => v[0].cos(),
        "tan" => v[0].tan(),
        "asin" => v[0].asin(),
        "acos" => v[0].acos(),
        "atan" => v[0].atan(),
        "exp" => v[0].exp(),
        "log" => v[0].ln(),
        "log10" => v[0].log10(),
        "sqrt" => v[0].sqrt(),
        "floor" => v[0].floor(),
        "ceil" => v[0].ceil(),
        "atan2" => v[0].atan2(v[1]),
        // genrev.c's l_hermite, l_bezier, l_bspline: cubic blends of four values at v[4].
        "hermite" => {
            let t = v[4];
            v[0] * ((2.0 * t - 3.0) * t * t + 1.0)
                + v[1] * (-2.0 * t + 3.0) * t * t
                + v[2] * ((t - 2.0) * t + 1.0) * t
                + v[3] * (t - 1.0) * t * t
        }
        "bezier" => {
            let t = v[4];
            v[0] * (1.0 + t * (-3.0 + t * (3.0 - t)))
                + v[1] * 3.0 * t * (1.0 + t * (-2.0 + t))
                + v[2] * 3.0 * t * t * (1.0 - t)
                + v[3] * t * t * t
        }
        _ => {
            let t = v[4];
            v[0] * (1.0 / 6.0 + t * (-0.5 + t * (0.5 - t / 6.0)))
                + v[1] * (2.0 / 3.0 + t * t * (-1.0 + 0.5 * t))
                + v[2] * (1.0 / 6.0 + t * (0.5 + t * (0.5 - 0.5 * t)))
                + v[3] * (t * t * t / 6.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn precedence_as_calcomp() {
        assert_eq!(parse("1+2*3^2").unwrap().eval(0.0), 19.0);
        assert_eq!(parse("-2^2").unwrap().eval(0.0), 4.0);
        assert_eq!(parse("2^3^2").unwrap().eval(0.0), 512.0);
        assert_eq!(parse("0.5 - t/2").unwrap().eval(1.0), 0.0);
        assert!((parse("sin(PI*t)").unwrap().eval(0.5) - 1.0).abs() < 1e-15);
        assert_eq!(parse("bezier(0,1,1,0,1)").unwrap().eval(0.0), 0.0);
    }

    #[test]
    fn unknown_names_and_bad_syntax_are_named() {
        assert!(parse("zz(t)").unwrap_err().contains("zz"));
        assert!(parse("k*t").unwrap_err().contains("`k`"));
        assert!(parse("(t").is_err());
        assert!(parse("t)").is_err());
        assert!(parse(&"(".repeat(500)).unwrap_err().contains("deeper"));
    }
}
