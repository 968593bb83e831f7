//! `modelDescription.xml` of an FMU of a spec: FMI 2.0, co-simulation, the variables of
//! [`crate::variables`] with their units, causality and variability, the spec's operating point
//! as the start values, and a GUID derived from the spec's text.

use crate::variables::{Causality, MODEL_IDENTIFIER, VARIABLES};
use ballscrew_core::{Evaluator, ScrewSpec};
use core::fmt::Write as _;

/// The GUID of an FMU of the spec in TOML text `spec_text`: 128 bits of two FNV-1a hashes of
/// the text, in GUID form. The library compares it with the GUID it is instantiated with, so a
/// `resources/spec.toml` edited after packaging is reported (a warning: the start values in
/// `modelDescription.xml` are then the old spec's).
pub fn guid(spec_text: &str) -> String {
    let fnv = |basis: u64| spec_text.bytes().fold(basis, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3));
    let (a, b) = (fnv(0xcbf2_9ce4_8422_2325), fnv(0x6c62_272e_07bb_0142));
    format!(
        "{{{:08x}-{:04x}-{:04x}-{:04x}-{:012x}}}",
        a >> 32,
        (a >> 16) & 0xffff,
        a & 0xffff,
        b >> 48,
        b & 0xffff_ffff_ffff
    )
}

/// `text` escaped for an XML attribute.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "&#{};", c as u32);
            }
            c => out.push(c),
        }
    }
    out
}

/// A start value as XML writes it: Rust's shortest round-trip form (`2000`, `0.5`).
fn number(x: f64) -> String {
    format!("{x:?}")
}

/// `modelDescription.xml` of the FMU of `spec` (TOML text `spec_text`), named `model_name`.
pub fn model_description(spec: &ScrewSpec, spec_text: &str, model_name: &str) -> String {
    let op = spec.operating;
    let solver = if Evaluator::<f64>::supports(spec).is_ok() { "control-loop evaluator" } else { "the model's solve" };
    let start = |vr: u32| match vr {
        crate::variables::SPEED_RAD_S => op.speed_rad_s,
        crate::variables::AXIAL_LOAD_N => op.axial_load_n,
        _ => op.preload_n,
    };
    let mut x = String::new();
    let _ = write!(
        x,
        r#"<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription
  fmiVersion="2.0"
  modelName="{name}"
  guid="{guid}"
  description="Friction (drag) torque of a preloaded ball screw by rolling-contact creep analysis ({solver}, f64), spec in resources/spec.toml"
  generationTool="ballscrew {version}"
  variableNamingConvention="flat"
  numberOfEventIndicators="0">
  <CoSimulation
    modelIdentifier="{id}"
    needsExecutionTool="false"
    canHandleVariableCommunicationStepSize="true"
    canInterpolateInputs="false"
    maxOutputDerivativeOrder="0"
    canRunAsynchronuously="false"
    canBeInstantiatedOnlyOncePerProcess="false"
    canNotUseMemoryManagementFunctions="true"
    canGetAndSetFMUstate="false"
    canSerializeFMUstate="false"
    providesDirectionalDerivative="false"/>
  <UnitDefinitions>
    <Unit name="rad/s"><BaseUnit s="-1" rad="1"/></Unit>
    <Unit name="N"><BaseUnit kg="1" m="1" s="-2"/></Unit>
    <Unit name="N.m"><BaseUnit kg="1" m="2" s="-2"/></Unit>
    <Unit name="W"><BaseUnit kg="1" m="2" s="-3"/></Unit>
  </UnitDefinitions>
  <LogCategories>
    <Category name="logStatusWarning" description="Warnings"/>
    <Category name="logStatusDiscard" description="Calls not carried out"/>
    <Category name="logStatusError" description="Errors: invalid inputs, points without solution, misuse"/>
    <Category name="logAll" description="Every message"/>
  </LogCategories>
  <DefaultExperiment startTime="0" stopTime="1" stepSize="0.001"/>
  <ModelVariables>
"#,
        name = escape(model_name),
        guid = guid(spec_text),
        version = env!("CARGO_PKG_VERSION"),
        id = MODEL_IDENTIFIER,
    );
    for v in &VARIABLES {
        let (causality, variability, start_attr) = match v.causality {
            Causality::Input => ("input", "continuous", format!(r#" start="{}""#, number(start(v.value_reference)))),
            Causality::TunableParameter => {
                ("parameter", "tunable", format!(r#" start="{}""#, number(start(v.value_reference))))
            }
            Causality::Output => ("output", "continuous", String::new()),
        };
        let initial = if v.causality == Causality::TunableParameter { r#" initial="exact""# } else { "" };
        let _ = writeln!(
            x,
            r#"    <!-- {index} --><ScalarVariable name="{name}" valueReference="{vr}" description="{desc}" causality="{causality}" variability="{variability}"{initial}>
      <Real quantity="{quantity}" unit="{unit}"{start_attr}/>
    </ScalarVariable>"#,
            index = v.value_reference + 1,
            name = v.name,
            vr = v.value_reference,
            desc = escape(v.description),
            quantity = v.quantity,
            unit = escape(v.unit),
        );
    }
    x.push_str("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n");
    // The load torque depends on the axial load alone; the others on the speed and the axial
    // load (the preload is a parameter, not listed).
    let outputs = VARIABLES.iter().filter(|v| v.causality == Causality::Output);
    for v in outputs.clone() {
        let index = v.value_reference + 1;
        let (deps, kinds) = if v.value_reference == crate::variables::LOAD_TORQUE_NM {
            (format!("{}", crate::variables::AXIAL_LOAD_N + 1), "dependent")
        } else {
            (
                format!("{} {}", crate::variables::SPEED_RAD_S + 1, crate::variables::AXIAL_LOAD_N + 1),
                "dependent dependent",
            )
        };
        let _ = writeln!(x, r#"      <Unknown index="{index}" dependencies="{deps}" dependenciesKind="{kinds}"/>"#);
    }
    x.push_str("    </Outputs>\n    <InitialUnknowns>\n");
    for v in outputs {
        let _ = writeln!(x, r#"      <Unknown index="{}"/>"#, v.value_reference + 1);
    }
    x.push_str("    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n");
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use ballscrew_config::{DKFZD4012_TOML, builtin_spec};

    #[test]
    fn guid_depends_on_the_text() {
        let g = guid(DKFZD4012_TOML);
        assert_eq!(g.len(), 38, "{g}");
        assert_eq!(g, guid(DKFZD4012_TOML));
        assert_ne!(g, guid(&format!("{DKFZD4012_TOML}\n")));
    }

    #[test]
    fn every_variable_with_its_unit_and_start() {
        let spec = builtin_spec().unwrap();
        let xml = model_description(&spec, DKFZD4012_TOML, "a<b");
        assert!(xml.contains(r#"modelName="a&lt;b""#));
        for v in &VARIABLES {
            assert!(
                xml.contains(&format!(r#"name="{}" valueReference="{}""#, v.name, v.value_reference)),
                "{}",
                v.name
            );
        }
        assert!(xml.contains(&format!(r#"unit="N" start="{:?}""#, spec.operating.preload_n)));
        assert_eq!(xml.matches("<ScalarVariable").count(), VARIABLES.len());
        assert_eq!(escape("&\"'\n"), "&amp;&quot;&apos;&#10;");
    }
}
