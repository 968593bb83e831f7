//! The FMU's variables: name, value reference, causality, unit and meaning. The names carry
//! their units as everywhere in the project; `modelDescription.xml` declares the units too
//! (`rad/s`, `N`, `N.m`, `W`), so importers convert and check them.

/// The FMU's model identifier: the name of its shared library in the archive
/// (`binaries/linux64/ballscrew.so`).
pub const MODEL_IDENTIFIER: &str = "ballscrew";

/// Value reference of the screw speed input, rad/s (signed: the direction of rotation).
pub const SPEED_RAD_S: u32 = 0;
/// Value reference of the external axial load input, N.
pub const AXIAL_LOAD_N: u32 = 1;
/// Value reference of the preload (a tunable parameter), N.
pub const PRELOAD_N: u32 = 2;
/// Value reference of the drive torque output (drag plus load torque), N m.
pub const TORQUE_NM: u32 = 3;
/// Value reference of the drag (friction) torque output, N m.
pub const DRAG_TORQUE_NM: u32 = 4;
/// Value reference of the load torque output F_a L / (2 pi), N m.
pub const LOAD_TORQUE_NM: u32 = 5;
/// Value reference of the dissipated power output (drag torque times speed), W.
pub const DISSIPATED_POWER_W: u32 = 6;

/// What a variable is to the importer (FMI's causality and variability).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// A continuous input, set by the importer before each step.
    Input,
    /// A tunable parameter: set before initialization or between steps.
    TunableParameter,
    /// A continuous output, computed from the inputs and the parameter.
    Output,
}

/// One variable of the FMU.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Variable {
    /// Its name, unit included.
    pub name: &'static str,
    /// Its value reference.
    pub value_reference: u32,
    /// Its causality (and variability).
    pub causality: Causality,
    /// Its unit, as declared in `modelDescription.xml`.
    pub unit: &'static str,
    /// Its physical quantity, as declared in `modelDescription.xml`.
    pub quantity: &'static str,
    /// What it is.
    pub description: &'static str,
}

/// Every variable, in value-reference order (the index of `modelDescription.xml`'s
/// `ModelVariables` is the value reference plus one).
pub const VARIABLES: [Variable; 7] = [
    Variable {
        name: "speed_rad_s",
        value_reference: SPEED_RAD_S,
        causality: Causality::Input,
        unit: "rad/s",
        quantity: "AngularVelocity",
        description: "Screw speed, rad/s; the sign is the direction of rotation",
    },
    Variable {
        name: "axial_load_n",
        value_reference: AXIAL_LOAD_N,
        causality: Causality::Input,
        unit: "N",
        quantity: "Force",
        description: "External axial load on the nut, N: positive when it opposes the nut's travel under positive rotation",
    },
    Variable {
        name: "preload_n",
        value_reference: PRELOAD_N,
        causality: Causality::TunableParameter,
        unit: "N",
        quantity: "Force",
        description: "Preload, N",
    },
    Variable {
        name: "torque_nm",
        value_reference: TORQUE_NM,
        causality: Causality::Output,
        unit: "N.m",
        quantity: "Torque",
        description: "Drive torque, N m: the drag torque plus the load torque",
    },
    Variable {
        name: "drag_torque_nm",
        value_reference: DRAG_TORQUE_NM,
        causality: Causality::Output,
        unit: "N.m",
        quantity: "Torque",
        description: "Drag (friction) torque, N m, signed with the rotation",
    },
    Variable {
        name: "load_torque_nm",
        value_reference: LOAD_TORQUE_NM,
        causality: Causality::Output,
        unit: "N.m",
        quantity: "Torque",
        description: "Load torque F_a L / (2 pi) of the axial load, N m",
    },
    Variable {
        name: "dissipated_power_w",
        value_reference: DISSIPATED_POWER_W,
        causality: Causality::Output,
        unit: "W",
        quantity: "Power",
        description: "Power dissipated by friction, W: the drag torque times the speed",
    },
];

/// The variable of value reference `value_reference`, if there is one.
pub fn variable(value_reference: u32) -> Option<&'static Variable> {
    VARIABLES.get(usize::try_from(value_reference).ok()?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_references_are_the_indices() {
        for (i, v) in VARIABLES.iter().enumerate() {
            assert_eq!(v.value_reference as usize, i, "{v:?}");
            assert_eq!(variable(v.value_reference), Some(v));
        }
        assert_eq!(variable(VARIABLES.len() as u32), None);
        assert_eq!(variable(u32::MAX), None);
    }
}
