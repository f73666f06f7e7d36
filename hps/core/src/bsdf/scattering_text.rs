//! The text of a `ScatteringData` element: numbers separated by white space or commas, and
//! for tensor trees the braces that nest them. Each token knows its line, for the errors.

use super::error::BsdfError;

/// `ScatteringData` text and the line it starts on.
#[derive(Debug, Clone)]
pub struct ScatteringText {
    pub text: String,
    pub line: u32,
}

/// One token of the scattering text.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Token {
    Open,
    Close,
    /// A BSDF value in 1/sr (never negative, always finite).
    Value(f32),
}

/// Tokens with their lines, read in one pass.
#[derive(Clone)]
pub struct Tokens<'a> {
    rest: &'a str,
    line: u32,
    file: &'a str,
}

impl ScatteringText {
    pub fn tokens<'a>(&'a self, file: &'a str) -> Tokens<'a> {
        Tokens {
            rest: &self.text,
            line: self.line,
            file,
        }
    }

    /// All values of a matrix, in file order (braces are not allowed).
    pub fn values(&self, file: &str) -> Result<Vec<f32>, BsdfError> {
        let mut tokens = self.tokens(file);
        let mut values = Vec::new();
        while let Some((token, line)) = tokens.next_token()? {
            match token {
                Token::Value(v) => values.push(v),
                _ => return Err(tokens.error(line, "a brace in matrix data")),
            }
        }
        Ok(values)
    }
}

impl<'a> Tokens<'a> {
    pub fn error(&self, line: u32, message: impl Into<String>) -> BsdfError {
        BsdfError::new(self.file, line, "ScatteringData", message)
    }

    /// The line of the next unread character.
    pub fn line(&self) -> u32 {
        self.line
    }

    fn skip_separators(&mut self) {
        let skipped = self
            .rest
            .find(|c: char| !(c.is_whitespace() || c == ','))
            .unwrap_or(self.rest.len());
        self.line += self.rest[..skipped].matches('\n').count() as u32;
        self.rest = &self.rest[skipped..];
    }

    /// The next token and its line, or None at the end of the text.
    pub fn next_token(&mut self) -> Result<Option<(Token, u32)>, BsdfError> {
        self.skip_separators();
        let line = self.line;
        let Some(first) = self.rest.chars().next() else {
            return Ok(None);
        };
        let (token, len) = match first {
            '{' => (Token::Open, 1),
            '}' => (Token::Close, 1),
            _ => {
                let len = self
                    .rest
                    .find(|c: char| c.is_whitespace() || c == ',' || c == '{' || c == '}')
                    .unwrap_or(self.rest.len());
                (Token::Value(self.value(&self.rest[..len], line)?), len)
            }
        };
        self.rest = &self.rest[len..];
        Ok(Some((token, line)))
    }

    fn value(&self, word: &str, line: u32) -> Result<f32, BsdfError> {
        let value = word
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| self.error(line, format!("'{word}' is not a number")))?;
        if value < 0.0 {
            return Err(self.error(line, format!("negative BSDF value {word}")));
        }
        // RADIANCE keeps BSDF values as C floats (bsdf_m.h, bsdf_t.h); so do we.
        let value = value as f32;
        if !value.is_finite() {
            return Err(self.error(line, format!("{word} is out of range")));
        }
        Ok(value)
    }
}
