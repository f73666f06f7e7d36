//! Splits `.cal` text into tokens, each with its line; `{ ... }` comments (nested, as
//! calcomp's scanner skips them) and white space are dropped.

use super::error::CalError;

#[derive(Debug, Clone, PartialEq)]
pub(super) enum Token {
    Number(f64),
    Name(String),
    /// `$n`: an input channel (rcalc); accepted only to report it clearly.
    Channel(u32),
    /// One of `+ - * / ^ ( ) , ; = :`.
    Punct(char),
}

#[derive(Debug, Clone, PartialEq)]
pub(super) struct Located {
    pub token: Token,
    pub line: u32,
}

/// calcomp's identifier characters (`calcomp.h` `isid`): letters, digits, `_`, `.` and the
/// context mark `` ` ``; a name starts with a letter or the context mark.
fn is_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '.' || c == '`'
}

/// Tokens of `text`; `file` names it in errors.
pub(super) fn tokenize(file: &str, text: &str) -> Result<Vec<Located>, CalError> {
    let chars: Vec<char> = text.chars().collect();
    let mut tokens = Vec::new();
    let mut i = 0;
    let mut line: u32 = 1;
    let error = |line: u32, message: &str| CalError::Syntax {
        file: file.to_string(),
        line,
        message: message.to_string(),
    };
    while i < chars.len() {
        let c = chars[i];
        if c == '\n' {
            line += 1;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if c == '{' {
            let opened = line;
            i = skip_comment(&chars, i, &mut line)
                .ok_or_else(|| error(opened, "'}' expected for the comment opened here"))?;
        } else if c.is_ascii_digit() || c == '.' {
            let (value, next) = scan_number(&chars, i).map_err(|m| error(line, m))?;
            tokens.push(Located {
                token: Token::Number(value),
                line,
            });
            i = next;
        } else if c.is_ascii_alphabetic() || c == '`' {
            let start = i;
            while i < chars.len() && is_name_char(chars[i]) {
                i += 1;
            }
            let name: String = chars[start..i].iter().collect();
            tokens.push(Located {
                token: Token::Name(name),
                line,
            });
        } else if c == '$' {
            let start = i + 1;
            i = start;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            let digits: String = chars[start..i].iter().collect();
            let n = digits.parse().map_err(|_| error(line, "bad channel '$'"))?;
            tokens.push(Located {
                token: Token::Channel(n),
                line,
            });
        } else if "+-*/^(),;=:".contains(c) {
            tokens.push(Located {
                token: Token::Punct(c),
                line,
            });
            i += 1;
        } else {
            return Err(error(line, &format!("unexpected character '{c}'")));
        }
    }
    Ok(tokens)
}

/// Index after the comment opening at `start` (comments nest), or `None` when unclosed.
fn skip_comment(chars: &[char], start: usize, line: &mut u32) -> Option<usize> {
    let mut depth = 0usize;
    for (i, &c) in chars.iter().enumerate().skip(start) {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            '\n' => *line += 1,
            _ => {}
        }
    }
    None
}

/// A number as calcomp's `getnum` reads it: digits, an optional fraction, an optional
/// exponent; a lone `.` and an exponent without digits are errors.
fn scan_number(chars: &[char], start: usize) -> Result<(f64, usize), &'static str> {
    let digits_from = |mut i: usize| {
        while i < chars.len() && chars[i].is_ascii_digit() {
            i += 1;
        }
        i
    };
    let mut i = digits_from(start);
    if i < chars.len() && chars[i] == '.' {
        let after = digits_from(i + 1);
        if i == start && after == i + 1 {
            return Err("badly formed number");
        }
        i = after;
    }
    if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
        let mut j = i + 1;
        if j < chars.len() && (chars[j] == '+' || chars[j] == '-') {
            j += 1;
        }
        let end = digits_from(j);
        if end == j {
            return Err("missing exponent");
        }
        i = end;
    }
    let text: String = chars[start..i].iter().collect();
    let value = text.parse::<f64>().map_err(|_| "badly formed number")?;
    Ok((value, i))
}
