//! The model options: every reading of the paper the model can take (load sharing, creep
//! coefficients, torque route, Heathcote slip, spin moment, contact theory). The default is the
//! decided reading; [`ModelOptions::paper_literal`] is the paper read literally.

/// How the load of a nut is shared over its circles (docs/model-notes.md item 8, Eq. 26).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum LoadDistribution {
    /// Decided reading: circle j of a nut carries a share proportional to (2/3)^(j-1),
    /// normalised over the nut's circles; the nuts are summed.
    #[default]
    Geometric,
    /// The paper's literal Eq. (26): every ball carries the same load, and each circle's
    /// friction is weighted by (2/3)^(j-1), unnormalised.
    PaperLiteral,
    /// Every ball carries the same load, no weights.
    Uniform,
}

/// Where the creep coefficients come from (docs/model-notes.md item 4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum CreepCoefficientSource {
    /// Kalker's table (E.3), interpolated in a/b and nu, a along rolling.
    #[default]
    KalkerTable,
    /// The paper's linear fits C1..C3 of Eq. (23), a along rolling.
    PaperFit,
}

/// Which torque the model reports as *the* torque (docs/model-notes.md item 9).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum TorqueRoute {
    /// T = F_a L / (2 pi) + D / omega: the energy balance of the whole screw.
    #[default]
    Energy,
    /// Eq. (27) as printed: friction magnitudes times (r_b - delta), weighted per circle.
    #[cfg_attr(feature = "serde", serde(rename = "paper-eq27"))]
    PaperEq27,
}

/// Whether a spin moment is carried by each raceway contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum SpinMoment {
    /// Kalker's linear spin moment, saturated together with the forces: the vector
    /// (F_e, F_f, M_z / l) is blended by Eq. (24), with l the full-slip spin-moment arm.
    #[default]
    Combined,
    /// Eq. (24) exactly as printed on the forces (F_e, F_f); the spin moment (which the paper
    /// omits, leaving the ball's spin about its contact line undetermined) is saturated on its
    /// own by the same blend with bound f Q l.
    Separate,
}

/// Which rolling-contact theory gives the creep forces of the raceway contacts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum ContactTheory {
    /// Kalker's linear theory saturated by Eq. (24) (the paper's model).
    #[default]
    LinearSaturated,
    /// Kalker's simplified theory by FASTSIM over the Hertz ellipse (ref. \[11\] of the paper),
    /// parabolic traction bound, `fastsim_grid` x `fastsim_grid` elements; the spin moment is
    /// FASTSIM's own.
    Fastsim,
}

/// Whether the raceway contacts are lubricated (docs/model-notes.md item 22).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum Lubrication {
    /// An elastohydrodynamic film of the spec's lubricant at every raceway contact: the bound
    /// of Eq. (24) is the mixed-lubrication friction coefficient of the contact's film
    /// parameter, and an EHL and an elastic-hysteresis rolling resistance act on the ball
    /// ([`crate::contact::ehl`]).
    #[default]
    Ehl,
    /// The paper's dry contacts: the bound of Eq. (24) is `friction.coefficient`, no rolling
    /// resistance.
    Dry,
}

impl Lubrication {
    /// The name of this option in a spec file (`model.{key}`) and in reports.
    pub fn name(&self) -> &'static str {
        match self {
            Lubrication::Ehl => "ehl",
            Lubrication::Dry => "dry",
        }
    }
}

impl LoadDistribution {
    /// The name of this option in a spec file (`model.{key}`) and in reports.
    pub fn name(&self) -> &'static str {
        match self {
            LoadDistribution::Geometric => "geometric",
            LoadDistribution::PaperLiteral => "paper-literal",
            LoadDistribution::Uniform => "uniform",
        }
    }
}

impl CreepCoefficientSource {
    /// The name of this option in a spec file (`model.{key}`) and in reports.
    pub fn name(&self) -> &'static str {
        match self {
            CreepCoefficientSource::KalkerTable => "kalker-table",
            CreepCoefficientSource::PaperFit => "paper-fit",
        }
    }
}

impl TorqueRoute {
    /// The name of this option in a spec file (`model.{key}`) and in reports.
    pub fn name(&self) -> &'static str {
        match self {
            TorqueRoute::Energy => "energy",
            TorqueRoute::PaperEq27 => "paper-eq27",
        }
    }
}

impl SpinMoment {
    /// The name of this option in a spec file (`model.{key}`) and in reports.
    pub fn name(&self) -> &'static str {
        match self {
            SpinMoment::Combined => "combined",
            SpinMoment::Separate => "separate",
        }
    }
}

impl ContactTheory {
    /// The name of this option in a spec file (`model.{key}`) and in reports.
    pub fn name(&self) -> &'static str {
        match self {
            ContactTheory::LinearSaturated => "linear-saturated",
            ContactTheory::Fastsim => "fastsim",
        }
    }
}

/// The model options of `docs/model-notes.md`; the default is the decided reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModelOptions {
    /// Load sharing over circles (Eq. 26).
    pub load_distribution: LoadDistribution,
    /// Creep coefficients (Eq. 23).
    pub creep_coefficients: CreepCoefficientSource,
    /// Reported torque (Eq. 27 or the energy balance).
    pub torque: TorqueRoute,
    /// Heathcote slip (Eqs. 10, 16, 22) on or off.
    pub heathcote: bool,
    /// Spin moment at the raceway contacts (linear-saturated theory).
    pub spin_moment: SpinMoment,
    /// Contact theory of the raceway contacts.
    pub contact_theory: ContactTheory,
    /// FASTSIM grid: elements per axis of the ellipse (`contact_theory = Fastsim`).
    pub fastsim_grid: u32,
    /// Lubricated (EHL film of the spec's lubricant) or dry raceway contacts.
    pub lubrication: Lubrication,
}

/// Default FASTSIM grid (elements per axis).
pub const DEFAULT_FASTSIM_GRID: u32 = 20;
/// Valid FASTSIM grids (elements per axis): [4, 200].
pub const FASTSIM_GRID_RANGE: (f64, f64) = (4.0, 200.0);

impl Default for ModelOptions {
    fn default() -> Self {
        Self {
            load_distribution: LoadDistribution::Geometric,
            creep_coefficients: CreepCoefficientSource::KalkerTable,
            torque: TorqueRoute::Energy,
            heathcote: true,
            spin_moment: SpinMoment::Combined,
            contact_theory: ContactTheory::LinearSaturated,
            fastsim_grid: DEFAULT_FASTSIM_GRID,
            lubrication: Lubrication::Ehl,
        }
    }
}

impl ModelOptions {
    /// The paper read literally where it is self-consistent: equal ball loads with unnormalised
    /// circle weights (Eq. 26), the paper's creep-coefficient fits, Eq. (24) on the forces alone,
    /// Eq. (27), dry contacts (the paper leaves the lubricant out, its section 3.1).
    pub fn paper_literal() -> Self {
        Self {
            load_distribution: LoadDistribution::PaperLiteral,
            creep_coefficients: CreepCoefficientSource::PaperFit,
            torque: TorqueRoute::PaperEq27,
            heathcote: true,
            spin_moment: SpinMoment::Separate,
            contact_theory: ContactTheory::LinearSaturated,
            fastsim_grid: DEFAULT_FASTSIM_GRID,
            lubrication: Lubrication::Dry,
        }
    }

    /// The decided reading with dry contacts: the model as it was before the lubricant
    /// (`lubrication = "dry"`).
    pub fn dry() -> Self {
        Self { lubrication: Lubrication::Dry, ..Self::default() }
    }
}
