//! What a `.cal` expression may read from the ray being shaded: RADIANCE's predefined ray
//! variables (`rayinit.cal`'s header lists them) and the modifier's real arguments `arg(n)`.

/// A ray variable RADIANCE defines before it reads `rayinit.cal`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RayVariable {
    Dx,
    Dy,
    Dz,
    Nx,
    Ny,
    Nz,
    Px,
    Py,
    Pz,
    /// Distance from the ray's start, in world units.
    T,
    /// Single (shadow) ray distance.
    Ts,
    /// Cosine between ray and surface normal.
    Rdot,
    /// World scale of the object's transform.
    S,
    Tx,
    Ty,
    Tz,
    Ix,
    Iy,
    Iz,
    Jx,
    Jy,
    Jz,
    Kx,
    Ky,
    Kz,
    /// Mesh local coordinates.
    Lu,
    Lv,
    /// Perturbed normal, ray dot product and material colour (`*func`, `*data` materials).
    NxP,
    NyP,
    NzP,
    RdotP,
    CrP,
    CgP,
    CbP,
}

impl RayVariable {
    /// Every ray variable, in declaration order (its index in [`RayValues`]).
    pub const ALL: [RayVariable; 34] = [
        Self::Dx,
        Self::Dy,
        Self::Dz,
        Self::Nx,
        Self::Ny,
        Self::Nz,
        Self::Px,
        Self::Py,
        Self::Pz,
        Self::T,
        Self::Ts,
        Self::Rdot,
        Self::S,
        Self::Tx,
        Self::Ty,
        Self::Tz,
        Self::Ix,
        Self::Iy,
        Self::Iz,
        Self::Jx,
        Self::Jy,
        Self::Jz,
        Self::Kx,
        Self::Ky,
        Self::Kz,
        Self::Lu,
        Self::Lv,
        Self::NxP,
        Self::NyP,
        Self::NzP,
        Self::RdotP,
        Self::CrP,
        Self::CgP,
        Self::CbP,
    ];

    /// The name a `.cal` file uses for it.
    pub fn name(self) -> &'static str {
        const NAMES: [&str; 34] = [
            "Dx", "Dy", "Dz", "Nx", "Ny", "Nz", "Px", "Py", "Pz", "T", "Ts", "Rdot", "S", "Tx",
            "Ty", "Tz", "Ix", "Iy", "Iz", "Jx", "Jy", "Jz", "Kx", "Ky", "Kz", "Lu", "Lv", "NxP",
            "NyP", "NzP", "RdotP", "CrP", "CgP", "CbP",
        ];
        NAMES[self as usize]
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|v| v.name() == name)
    }
}

/// The ray and modifier an evaluation reads from; the engine implements it per ray.
pub trait CalContext {
    fn ray_variable(&self, variable: RayVariable) -> f64;
    /// The modifier's real arguments (`arg(1)` is the first).
    fn real_arguments(&self) -> &[f64];
}

/// A plain set of ray values and real arguments.
#[derive(Debug, Clone, PartialEq)]
pub struct RayValues {
    /// Indexed by `RayVariable as usize`.
    pub values: [f64; RayVariable::ALL.len()],
    pub real_arguments: Vec<f64>,
}

impl Default for RayValues {
    /// Zero everywhere, with an identity world transform (`S` = 1, I J K the axes).
    fn default() -> Self {
        let mut values = [0.0; RayVariable::ALL.len()];
        for (v, x) in [
            (RayVariable::S, 1.0),
            (RayVariable::Ix, 1.0),
            (RayVariable::Jy, 1.0),
            (RayVariable::Kz, 1.0),
        ] {
            values[v as usize] = x;
        }
        Self {
            values,
            real_arguments: Vec::new(),
        }
    }
}

impl RayValues {
    pub fn set(&mut self, variable: RayVariable, value: f64) -> &mut Self {
        self.values[variable as usize] = value;
        self
    }
}

impl CalContext for RayValues {
    fn ray_variable(&self, variable: RayVariable) -> f64 {
        self.values[variable as usize]
    }
    fn real_arguments(&self) -> &[f64] {
        &self.real_arguments
    }
}
