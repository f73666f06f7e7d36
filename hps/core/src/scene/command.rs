//! An inline command line split as `/bin/sh` would split it: words, quotes, backslashes and
//! pipes. Only the part of the shell language scene files use is read natively; anything
//! else (redirections, `;`, `&&`, variables, command substitution) is refused with the
//! construct named, so it can only run through the shell with `--allow-commands`.

/// The stages of a pipeline (`genblinds ... | xform -rz 90`), each a program and its words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Pipeline {
    pub stages: Vec<Vec<String>>,
}

/// Splits `text` (the command after its `!`) into pipeline stages; the error names the first
/// piece of shell syntax Skylux does not read itself.
pub(crate) fn split_pipeline(text: &str) -> Result<Pipeline, String> {
    let mut stages: Vec<Vec<String>> = vec![Vec::new()];
    let mut word: Option<String> = None;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => match chars.next() {
                Some('\n') | None => {}
                Some(next) => word.get_or_insert_with(String::new).push(next),
            },
            '\'' => {
                let w = word.get_or_insert_with(String::new);
                loop {
                    match chars.next() {
                        Some('\'') => break,
                        Some(ch) => w.push(ch),
                        None => return Err("a single quote is never closed".into()),
                    }
                }
            }
            '"' => {
                let w = word.get_or_insert_with(String::new);
                double_quoted(&mut chars, w)?;
            }
            '|' => {
                if chars.peek() == Some(&'|') {
                    return Err("shell syntax `||`".into());
                }
                end_word(&mut stages, &mut word);
                if stages.last().is_some_and(Vec::is_empty) {
                    return Err("a pipe `|` with no command before it".into());
                }
                stages.push(Vec::new());
            }
            '#' if word.is_none() => break,
            ';' | '&' | '<' | '>' | '`' | '$' | '(' | ')' | '*' | '?' | '[' | '~' | '{' => {
                return Err(format!("shell syntax `{c}`"));
            }
            c if c.is_whitespace() => end_word(&mut stages, &mut word),
            c => word.get_or_insert_with(String::new).push(c),
        }
    }
    end_word(&mut stages, &mut word);
    if stages.iter().any(Vec::is_empty) {
        return Err(if stages.len() == 1 {
            "an empty command".into()
        } else {
            "a pipe `|` with no command after it".into()
        });
    }
    Ok(Pipeline { stages })
}

/// The rest of a `"..."` word: backslash escapes only `$`, `` ` ``, `"`, `\` and newline.
fn double_quoted(
    chars: &mut std::iter::Peekable<std::str::Chars<'_>>,
    w: &mut String,
) -> Result<(), String> {
    loop {
        match chars.next() {
            Some('"') => return Ok(()),
            Some('\\') => match chars.next() {
                Some('\n') => {}
                Some(e @ ('$' | '`' | '"' | '\\')) => w.push(e),
                Some(other) => {
                    w.push('\\');
                    w.push(other);
                }
                None => return Err("a double quote is never closed".into()),
            },
            Some(ch @ ('$' | '`')) => return Err(format!("shell syntax `{ch}` inside quotes")),
            Some(ch) => w.push(ch),
            None => return Err("a double quote is never closed".into()),
        }
    }
}

fn end_word(stages: &mut [Vec<String>], word: &mut Option<String>) {
    if let (Some(w), Some(stage)) = (word.take(), stages.last_mut()) {
        stage.push(w);
    }
}

/// The program a stage runs, without its directory (`/usr/local/bin/xform` is `xform`).
pub(crate) fn program_name(stage: &[String]) -> &str {
    stage
        .first()
        .map_or("", |p| p.rsplit('/').next().unwrap_or(p))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stages(text: &str) -> Vec<Vec<String>> {
        split_pipeline(text).unwrap().stages
    }

    #[test]
    fn words_quotes_and_continuations() {
        assert_eq!(
            stages("genrev m n 'z t' \"1-t\" 8 \\\n -s"),
            [["genrev", "m", "n", "z t", "1-t", "8", "-s"]]
        );
        assert_eq!(stages("a b\\ c"), [["a", "b c"]]);
    }

    #[test]
    fn pipes_split_stages() {
        assert_eq!(
            stages("genblinds m b 1 2 3 4 5|xform -rz 90 | xform -t 1 0 0"),
            [
                vec!["genblinds", "m", "b", "1", "2", "3", "4", "5"],
                vec!["xform", "-rz", "90"],
                vec!["xform", "-t", "1", "0", "0"],
            ]
        );
    }

    #[test]
    fn other_shell_syntax_is_named() {
        for (text, needle) in [
            ("genbox m b 1 1 1 > out", "`>`"),
            ("a; b", "`;`"),
            ("a $HOME", "`$`"),
            ("a | ", "no command after"),
            ("| a", "no command before"),
            ("a 'open", "never closed"),
            ("", "empty"),
            ("a || b", "`||`"),
        ] {
            let err = split_pipeline(text).unwrap_err();
            assert!(err.contains(needle), "{text}: {err}");
        }
    }

    #[test]
    fn a_comment_ends_the_command() {
        assert_eq!(
            stages("genbox m b 1 1 1 # a box"),
            [["genbox", "m", "b", "1", "1", "1"]]
        );
        assert_eq!(program_name(&["/opt/r/bin/xform".into()]), "xform");
    }
}
