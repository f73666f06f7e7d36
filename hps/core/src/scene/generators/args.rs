//! Reading a generator's arguments: numbers, counts and usage errors.

/// Argument `index` as a finite number; `what` names it in the error.
pub(super) fn number(args: &[String], index: usize, what: &str) -> Result<f64, String> {
    let word = args
        .get(index)
        .ok_or_else(|| format!("{what} is missing"))?;
    word.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("{what} is `{word}`; expected a number"))
}

/// Argument `index` as an integer.
pub(super) fn integer(args: &[String], index: usize, what: &str) -> Result<i64, String> {
    let word = args
        .get(index)
        .ok_or_else(|| format!("{what} is missing"))?;
    word.parse::<i64>()
        .map_err(|_| format!("{what} is `{word}`; expected an integer"))
}

/// Fails unless there are at least `count` arguments, with the program's usage.
pub(super) fn require(args: &[String], count: usize, usage: &str) -> Result<(), String> {
    if args.len() < count {
        return Err(format!("{} argument(s) given; usage: {usage}", args.len()));
    }
    Ok(())
}
