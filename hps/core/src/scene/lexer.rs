//! Words of a RADIANCE scene file, with the line each starts on.
//!
//! As RADIANCE's `fgetword` (src/common/fgetword.c): words are separated by white space, and a
//! word that starts with `"` or `'` runs to the matching quote and may hold spaces. A `#` that
//! starts an unquoted word begins a comment to the end of the line. RADIANCE only recognises
//! comments between primitives; accepting them anywhere a word may start loses nothing, because
//! a `#` word inside an argument list would be an error there anyway.

use super::error::{SceneError, SourceLocation};
use std::path::Path;
use std::sync::Arc;

/// One word of the file.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) struct Token<'a> {
    /// The word, without its quotes if it was quoted.
    pub text: &'a str,
    /// 1-based line where the word starts.
    pub line: usize,
    /// Whether the word was quoted (a quoted `!` or `#` is an ordinary word).
    pub quoted: bool,
}

/// Streams the words of one file.
pub(crate) struct Lexer<'a> {
    file: Arc<Path>,
    text: &'a str,
    pos: usize,
    line: usize,
    /// Line of the last word returned: where "the file ends here" errors point.
    last_line: usize,
}

/// White space as C's `isspace` in the "C" locale, which RADIANCE uses.
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0b | 0x0c)
}

impl<'a> Lexer<'a> {
    pub fn new(file: Arc<Path>, text: &'a str) -> Self {
        // A byte-order mark written by some editors would otherwise stick to the first word.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        Lexer {
            file,
            text,
            pos: 0,
            line: 1,
            last_line: 1,
        }
    }

    /// Location of the last word read: once the file has ended, the last line with content.
    pub fn last_word(&self) -> SourceLocation {
        self.at(self.last_line)
    }

    pub fn at(&self, line: usize) -> SourceLocation {
        SourceLocation {
            file: self.file.clone(),
            line,
        }
    }

    /// The next word, or `None` at the end of the file.
    pub fn next_token(&mut self) -> Result<Option<Token<'a>>, SceneError> {
        let bytes = self.text.as_bytes();
        loop {
            while let Some(&b) = bytes.get(self.pos) {
                if !is_space(b) {
                    break;
                }
                if b == b'\n' {
                    self.line += 1;
                }
                self.pos += 1;
            }
            let Some(&first) = bytes.get(self.pos) else {
                return Ok(None);
            };
            let line = self.line;
            match first {
                b'#' => {
                    self.skip_to_end_of_line();
                }
                b'"' | b'\'' => {
                    let start = self.pos + 1;
                    let mut end = start;
                    while let Some(&b) = bytes.get(end) {
                        if b == first {
                            break;
                        }
                        if b == b'\n' {
                            self.line += 1;
                        }
                        end += 1;
                    }
                    if end >= bytes.len() {
                        return Err(SceneError::UnterminatedQuote {
                            at: self.at(line),
                            quote: char::from(first),
                        });
                    }
                    self.pos = end + 1;
                    self.last_line = line;
                    // Quotes are ASCII, so `start` and `end` are on character boundaries.
                    return Ok(Some(Token {
                        text: &self.text[start..end],
                        line,
                        quoted: true,
                    }));
                }
                _ => {
                    let start = self.pos;
                    while let Some(&b) = bytes.get(self.pos) {
                        if is_space(b) {
                            break;
                        }
                        self.pos += 1;
                    }
                    self.last_line = line;
                    // White space is ASCII, so the word ends on a character boundary.
                    return Ok(Some(Token {
                        text: &self.text[start..self.pos],
                        line,
                        quoted: false,
                    }));
                }
            }
        }
    }

    /// The rest of a `!command` line after the last word read, consumed. A line ending in a
    /// backslash continues on the next (RADIANCE's `fgetline` keeps both for the shell, which
    /// joins them); the lines it spans are counted.
    pub fn command_tail(&mut self) -> &'a str {
        let bytes = self.text.as_bytes();
        let start = self.pos;
        while let Some(&b) = bytes.get(self.pos) {
            if b == b'\n' {
                let mut end = self.pos;
                if end > 0 && bytes[end - 1] == b'\r' {
                    end -= 1;
                }
                if end > 0 && bytes[end - 1] == b'\\' {
                    self.line += 1;
                    self.pos += 1;
                    continue;
                }
                break;
            }
            self.pos += 1;
        }
        &self.text[start..self.pos]
    }

    fn skip_to_end_of_line(&mut self) {
        let bytes = self.text.as_bytes();
        while let Some(&b) = bytes.get(self.pos) {
            if b == b'\n' {
                break;
            }
            self.pos += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(text: &str) -> Vec<(String, usize, bool)> {
        let mut lexer = Lexer::new(Arc::from(Path::new("t.rad")), text);
        let mut out = Vec::new();
        while let Some(t) = lexer.next_token().unwrap() {
            out.push((t.text.to_string(), t.line, t.quoted));
        }
        out
    }

    #[test]
    fn words_carry_their_line_and_comments_are_skipped() {
        let got = words("# header\nvoid plastic  red # trailing\r\n0\n\t0\n5 .5 .5 .5 0 0\n");
        let texts: Vec<_> = got.iter().map(|(t, _, _)| t.as_str()).collect();
        assert_eq!(
            texts,
            ["void", "plastic", "red", "0", "0", "5", ".5", ".5", ".5", "0", "0"]
        );
        let lines: Vec<_> = got.iter().map(|(_, l, _)| *l).collect();
        assert_eq!(lines, [2, 2, 2, 3, 4, 5, 5, 5, 5, 5, 5]);
    }

    #[test]
    fn quoted_words_keep_spaces_and_are_not_comments() {
        let got = words("2 \"a b\" '#x'\n");
        assert_eq!(got[1], ("a b".to_string(), 1, true));
        assert_eq!(got[2], ("#x".to_string(), 1, true));
    }

    #[test]
    fn a_hash_inside_a_word_is_part_of_it() {
        assert_eq!(words("a#b")[0].0, "a#b");
    }

    #[test]
    fn byte_order_mark_is_dropped() {
        assert_eq!(words("\u{feff}void x")[0].0, "void");
    }

    #[test]
    fn unterminated_quote_names_its_opening_line() {
        let mut lexer = Lexer::new(Arc::from(Path::new("q.rad")), "a\n\"open\n\n");
        lexer.next_token().unwrap();
        let err = lexer.next_token().unwrap_err();
        assert!(err.to_string().starts_with("q.rad:2:"), "{err}");
    }

    #[test]
    fn command_tail_joins_continued_lines() {
        let mut lexer = Lexer::new(
            Arc::from(Path::new("c.rad")),
            "!xform -rz 90 \\\n  box.rad\nnext",
        );
        assert_eq!(lexer.next_token().unwrap().unwrap().text, "!xform");
        assert_eq!(lexer.command_tail(), " -rz 90 \\\n  box.rad");
        assert_eq!(lexer.next_token().unwrap().unwrap().line, 3);
    }
}
