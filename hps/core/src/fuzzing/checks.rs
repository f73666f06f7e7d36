//! What every harness checks of a reader's answer.

/// Bytes as the text readers see them: invalid UTF-8 replaced, as `from_utf8_lossy` does.
pub(super) fn text(bytes: &[u8]) -> std::borrow::Cow<'_, str> {
    String::from_utf8_lossy(bytes)
}

/// Asserts that an error message names the input, as every reader's errors must.
pub(super) fn assert_names(message: &str, label: &str) {
    assert!(
        message.contains(label),
        "the error does not name `{label}`: {message}"
    );
}
