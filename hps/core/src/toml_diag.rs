//! TOML errors as users need them: with the line spelled out.

/// A TOML error with its line number spelled out (`line 12: invalid type ...`).
pub(crate) fn describe(text: &str, e: &toml::de::Error) -> String {
    let message = e.message().trim().to_string();
    match e.span() {
        Some(span) => {
            let line = text[..span.start.min(text.len())].matches('\n').count() + 1;
            format!("line {line}: {message}")
        }
        None => message,
    }
}
