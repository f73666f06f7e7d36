//! Writing primitives as RADIANCE scene text, as the generators print them.

/// One polygon in RADIANCE text.
pub(super) fn polygon(out: &mut String, modifier: &str, name: &str, vertices: &[[f64; 3]]) {
    use std::fmt::Write as _;
    let _ = write!(
        out,
        "\n{modifier} polygon {name}\n0\n0\n{}\n",
        vertices.len() * 3
    );
    for v in vertices {
        let _ = writeln!(out, "\t{} {} {}", v[0], v[1], v[2]);
    }
}

/// Any primitive with only real arguments, in RADIANCE text.
pub(super) fn reals_primitive(
    out: &mut String,
    modifier: &str,
    type_name: &str,
    name: &str,
    reals: &[f64],
) {
    use std::fmt::Write as _;
    let _ = write!(
        out,
        "\n{modifier} {type_name} {name}\n0\n0\n{}",
        reals.len()
    );
    for r in reals {
        let _ = write!(out, " {r}");
    }
    out.push('\n');
}
