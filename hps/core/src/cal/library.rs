//! calcomp's library functions (`calfunc.c`), and `arg(n)` that rtrace adds.

/// A function no file needs to define.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum LibraryFunction {
    If,
    Select,
    Min,
    Max,
    Rand,
    Floor,
    Ceil,
    Sqrt,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Exp,
    Log,
    Log10,
    /// rtrace's `arg(n)`: the modifier's n-th real argument, `arg(0)` their count.
    Arg,
}

const TABLE: [(&str, LibraryFunction); 19] = [
    ("if", LibraryFunction::If),
    ("select", LibraryFunction::Select),
    ("min", LibraryFunction::Min),
    ("max", LibraryFunction::Max),
    ("rand", LibraryFunction::Rand),
    ("floor", LibraryFunction::Floor),
    ("ceil", LibraryFunction::Ceil),
    ("sqrt", LibraryFunction::Sqrt),
    ("sin", LibraryFunction::Sin),
    ("cos", LibraryFunction::Cos),
    ("tan", LibraryFunction::Tan),
    ("asin", LibraryFunction::Asin),
    ("acos", LibraryFunction::Acos),
    ("atan", LibraryFunction::Atan),
    ("atan2", LibraryFunction::Atan2),
    ("exp", LibraryFunction::Exp),
    ("log", LibraryFunction::Log),
    ("log10", LibraryFunction::Log10),
    ("arg", LibraryFunction::Arg),
];

impl LibraryFunction {
    pub fn lookup(name: &str) -> Option<Self> {
        TABLE.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
    }

    pub fn name(self) -> &'static str {
        TABLE
            .iter()
            .find(|(_, f)| *f == self)
            .map_or("?", |(n, _)| n)
    }

    /// The value of a one-argument function of `x`, or `None` for the others.
    pub fn of_one(self, x: f64) -> Option<f64> {
        Some(match self {
            Self::Rand => rand(x),
            Self::Floor => x.floor(),
            Self::Ceil => x.ceil(),
            Self::Sqrt => x.sqrt(),
            Self::Sin => x.sin(),
            Self::Cos => x.cos(),
            Self::Tan => x.tan(),
            Self::Asin => x.asin(),
            Self::Acos => x.acos(),
            Self::Atan => x.atan(),
            Self::Exp => x.exp(),
            Self::Log => x.ln(),
            Self::Log10 => x.log10(),
            _ => return None,
        })
    }
}

/// calcomp's `rand(x)`: a deterministic hash of `x` into [0, 1) (`calfunc.c` `l_rand`, with
/// its truncated e and π/4, whose last digits the hash amplifies), so a texture looks the same
/// in every run and as in RADIANCE.
pub(super) fn rand(x: f64) -> f64 {
    let mut x = x;
    #[allow(clippy::approx_constant)]
    let (e, quarter_pi) = (2.71828182845904, 0.785398163397447);
    x *= 1.0 / (1.0 + x * x) + e;
    x += quarter_pi - x.floor();
    x = 1e5 / x;
    x - x.floor()
}
