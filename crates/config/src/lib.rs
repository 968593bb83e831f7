//! # ballscrew-config
//!
//! TOML screw specs: the file format with units in the key names, mapped to and from the core's
//! [`ScrewSpec`] (SI). A crate of its own because parsing a file needs `std` and allocation,
//! which the no_std core never does.
//!
//! ```toml
//! [geometry]
//! pitch_diameter_mm = 40.0
//! lead_mm = 12.0
//! ball_diameter_mm = 5.953
//! conformity_screw = 0.52
//! conformity_nut = 0.52
//! contact_angle_deg = 45.0
//! nuts = 2
//! preload = "double-nut"           # optional: "double-nut" | "offset-lead" | "oversize-ball" | "none"
//! circles_per_nut = 4
//! balls_per_circle = 19
//! [material]
//! youngs_modulus_gpa = 210.0
//! poisson_ratio = 0.3
//! [friction]
//! coefficient = 0.03              # optional, default 0.03 (Table 1): the dry model's
//! ball_ball_load_n = 0.0          # optional; absent, the loads follow from the ball train
//! standstill_speed_rpm = 0.1      # optional, default 0.1
//! creep_reduction = 1.0           # optional, default 1
//! seal_torque_per_nut_nm = 0.0    # optional, default 0: seal torque of each nut
//! [operating]                      # optional: the spec's operating point
//! speed_rpm = 100.0               # optional, default 100
//! preload_n = 2000.0              # required for a preloaded nut; default 0 for preload = "none"
//! axial_load_n = 0.0              # optional, default 0
//! [model]                          # optional; every key defaults to the decided reading
//! load_distribution = "geometric"  # "geometric" | "paper-literal" | "uniform"
//! creep_coefficients = "kalker-table" # "kalker-table" | "paper-fit"
//! torque = "energy"                # "energy" | "paper-eq27"
//! heathcote = true
//! spin_moment = "combined"         # "combined" | "separate"
//! contact_theory = "linear-saturated" # "linear-saturated" | "fastsim"
//! fastsim_grid = 20                # elements per axis of the ellipse (FASTSIM)
//! lubrication = "ehl"              # "ehl" (lubricated contacts) | "dry" (the paper's model)
//! [circulation]                    # optional: how the balls circulate
//! return = "internal"              # "internal" (deflector) | "external" (tube, end caps)
//! turns_per_circuit = 1            # optional: loaded turns per circuit
//! return_balls = 2                 # optional: balls in the return path
//! return_friction = 0.03           # optional: wall friction in the return
//! [lubricant]                      # optional; every key defaults to ISO VG 68 mineral oil at 40 C
//! iso_vg = 68.0                    # ISO 3448 grade, or both viscosities below (not both)
//! # viscosity_40c_mm2_s = 68.0
//! # viscosity_100c_mm2_s = 9.59
//! density_15c_kg_m3 = 870.0
//! density_temperature_coefficient_kg_m3_k = -0.6
//! pressure_viscosity_per_gpa = 22.0
//! thermal_conductivity_w_m_k = 0.134
//! temperature_c = 40.0             # oil temperature at the contacts
//! roughness_ball_rq_um = 0.025
//! roughness_raceway_rq_um = 0.16
//! boundary_friction = 0.15         # mu of asperity contact
//! full_film_traction = 0.03        # traction coefficient of a full film
//! asperity_load_b = 2.32           # asperity load share exp(-B Lambda^C)
//! asperity_load_c = 0.97
//! hysteresis_loss_factor = 0.002
//! # inlet_distance_ratio = 5.0     # starvation (absent: fully flooded)
//! [extensions.seal_drag]           # optional terms beyond the paper (`ballscrew_core::input::extensions`)
//! torque_nm = 0.02
//! ```
//!
//! Every key of every table (`[extensions.<name>]` included), with its unit, default, valid
//! values, meaning and source, is one row of the table of keys (`keys.rs`), from which the spec
//! reference `docs/spec-reference.md` is rendered ([`spec_reference`]); the crate's test
//! `tests/spec_reference.rs` requires the page to be that text and checks it against this parser
//! (the keys, each range end and option, each default).
//!
//! Under `lubrication = "ehl"` the raceway contacts' friction coefficient comes from each
//! contact's film (`[lubricant]`); `friction.coefficient` is the dry model's. The `[lubricant]`
//! table is read and its ranges checked under either model.
//!
//! Unknown keys and tables are rejected with their line and column. Values are checked by the
//! core's own validation ([`Model::new`]); its errors, which name SI fields, are mapped back to
//! the TOML key and unit by the same table of keys (`KEYS`).
//!
//! The source, a concern a file: `file_format.rs` (the tables and keys as serde reads and writes
//! them), `conversion.rs` (the file's units to the core's SI and back), `keys.rs` (the table of
//! keys: unit, default, range in the key's unit from the core's constants, meaning, source, core
//! field), `reference.rs` (the spec reference page rendered from that table), `error.rs`
//! ([`ConfigError`] and the rewording of parse and range errors with the line, the column and the
//! key); this file, the entry points.

mod conversion;
mod error;
mod file_format;
mod keys;
mod reference;

pub use error::ConfigError;
pub use keys::{MAX_ISO_VG, MIN_ISO_VG};
pub use reference::spec_reference;

use ballscrew_core::error::Error;
use ballscrew_core::input::ScrewSpec;
use ballscrew_core::screw::model::Model;
use error::{invalid, missing_preload, parse_error};
use file_format::RawSpec;
use std::path::Path;

/// The built-in spec: DKFZD4012 of Table 1 (`configs/dkfzd4012.toml`).
pub const DKFZD4012_TOML: &str = include_str!("../../../configs/dkfzd4012.toml");

/// Name of the built-in spec in messages and reports (command line and Python alike).
pub const BUILTIN_ORIGIN: &str = "built-in DKFZD4012 (configs/dkfzd4012.toml)";

/// Parses a TOML spec, converts it to SI and validates it (the core's [`Model::new`]).
///
/// `origin` names the text in error messages (a file name).
///
/// ```
/// use ballscrew_config::{ConfigError, DKFZD4012_TOML, spec_from_toml_str};
/// use ballscrew_core::ScrewSpec;
///
/// // The built-in file is the core's built-in spec, in SI.
/// assert_eq!(spec_from_toml_str(DKFZD4012_TOML, "dkfzd4012.toml")?, ScrewSpec::dkfzd4012());
/// // A value out of range: the key, the value as written and the range in the key's unit.
/// let bad = DKFZD4012_TOML.replace("lead_mm = 12.0", "lead_mm = -12.0");
/// let e = spec_from_toml_str(&bad, "bad.toml").unwrap_err();
/// assert!(matches!(&e, ConfigError::Invalid { field, value, .. } if field == "geometry.lead_mm" && *value == -12.0));
/// assert!(e.to_string().starts_with("invalid geometry.lead_mm: -12 mm (valid: "), "{e}");
/// // An unknown key: the origin, its line and column, and the key.
/// let line = DKFZD4012_TOML.lines().position(|l| l.starts_with("lead_mm")).unwrap() + 1;
/// let e = spec_from_toml_str(&DKFZD4012_TOML.replace("lead_mm", "lead_in"), "typo.toml").unwrap_err();
/// assert!(matches!(&e, ConfigError::Parse { line: l, column: 1, .. } if *l == line), "{e}");
/// assert!(e.to_string().starts_with(&format!("typo.toml:{line}:1: ")) && e.to_string().contains("lead_in"), "{e}");
/// # Ok::<(), ConfigError>(())
/// ```
pub fn spec_from_toml_str(text: &str, origin: &str) -> Result<ScrewSpec, ConfigError> {
    let raw: RawSpec = toml::from_str(text).map_err(|e| parse_error(text, origin, &e))?;
    if let Some(e) = missing_preload(text, origin, &raw) {
        return Err(e);
    }
    let spec = raw.to_spec()?;
    match Model::new(&spec) {
        Ok(_) => Ok(spec),
        Err(Error::Input(e)) => Err(invalid(&raw, &spec, &e)),
        Err(e) => Err(ConfigError::Model(e)),
    }
}

/// Reads and parses a TOML spec file (see [`spec_from_toml_str`]); errors name the path.
pub fn spec_from_toml_file(path: &Path) -> Result<ScrewSpec, ConfigError> {
    let origin = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| ConfigError::Io { path: origin.clone(), message: format!("cannot read spec file: {e}") })?;
    spec_from_toml_str(&text, &origin)
}

/// The built-in spec ([`DKFZD4012_TOML`], named [`BUILTIN_ORIGIN`]).
pub fn builtin_spec() -> Result<ScrewSpec, ConfigError> {
    spec_from_toml_str(DKFZD4012_TOML, BUILTIN_ORIGIN)
}

/// Writes a spec as TOML (units in the key names); [`spec_from_toml_str`] reads it back.
pub fn spec_to_toml(spec: &ScrewSpec) -> String {
    let body = toml::to_string(&RawSpec::from_spec(spec))
        .unwrap_or_else(|e| format!("# the spec could not be written: {e}\n"));
    format!("# ballscrew screw spec (units in the key names)\n\n{body}")
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::error::{header_name, key_of};
    use crate::keys::KEYS;
    use ballscrew_core::input::{LoadDistribution, Lubricant, Lubrication, ModelOptions, Preload, rpm_to_rad_s};

    const ORIGIN: &str = "dkfzd4012.toml";

    #[test]
    fn builtin_spec_is_dkfzd4012() {
        assert_eq!(builtin_spec().unwrap(), ScrewSpec::dkfzd4012());
    }

    fn close(a: f64, b: f64) -> bool {
        a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
    }

    fn assert_spec_close(a: &ScrewSpec, b: &ScrewSpec) {
        let (ga, gb) = (&a.geometry, &b.geometry);
        let pairs = [
            (ga.pitch_diameter_m, gb.pitch_diameter_m),
            (ga.lead_m, gb.lead_m),
            (ga.ball_diameter_m, gb.ball_diameter_m),
            (ga.conformity_screw, gb.conformity_screw),
            (ga.conformity_nut, gb.conformity_nut),
            (ga.contact_angle_rad, gb.contact_angle_rad),
            (a.material.youngs_modulus_pa, b.material.youngs_modulus_pa),
            (a.material.poisson_ratio, b.material.poisson_ratio),
            (a.friction.coefficient, b.friction.coefficient),
            (a.friction.ball_ball_load_n.unwrap_or(-1.0), b.friction.ball_ball_load_n.unwrap_or(-1.0)),
            (a.friction.standstill_speed_rad_s, b.friction.standstill_speed_rad_s),
            (a.operating.speed_rad_s, b.operating.speed_rad_s),
            (a.operating.preload_n, b.operating.preload_n),
            (a.operating.axial_load_n, b.operating.axial_load_n),
        ];
        for (i, (x, y)) in pairs.iter().enumerate() {
            assert!(close(*x, *y), "field {i}: {x} vs {y}");
        }
        assert_eq!(
            (ga.nuts, ga.preload, ga.circles_per_nut, ga.balls_per_circle),
            (gb.nuts, gb.preload, gb.circles_per_nut, gb.balls_per_circle)
        );
        assert_eq!(a.model, b.model);
        assert_eq!(a.circulation, b.circulation);
    }

    /// `geometry.preload` names the arrangement; absent, two nuts are a double nut and one nut
    /// is a nut without preload (which then takes no preload); an unknown name is refused with
    /// the names that are valid; a name that does not suit `nuts` is refused on `nuts`.
    #[test]
    fn preload_arrangement_key() {
        let base = DKFZD4012_TOML;
        assert_eq!(spec_from_toml_str(base, ORIGIN).unwrap().geometry.preload, Preload::DoubleNut);
        let absent = with_line("geometry", "preload", "");
        assert_eq!(spec_from_toml_str(&absent, ORIGIN).unwrap().geometry.preload, Preload::DoubleNut);
        let one = with_line("geometry", "nuts", "nuts = 1").replace("preload = \"double-nut\"", "");
        let (field, value, _) = invalid_err(&one);
        assert_eq!((field.as_str(), value), ("operating.preload_n", 2000.0), "no preload on a nut without one");
        let one = one.replace("preload_n = 2000.0", "preload_n = 0.0");
        assert_eq!(spec_from_toml_str(&one, ORIGIN).unwrap().geometry.preload, Preload::None);
        for p in Preload::ALL {
            let text = with_line("geometry", "preload", &format!("preload = \"{}\"", p.name()))
                .replace("nuts = 2", &format!("nuts = {}", p.nuts()));
            let text = if p == Preload::None { text.replace("preload_n = 2000.0", "preload_n = 0.0") } else { text };
            assert_eq!(spec_from_toml_str(&text, ORIGIN).unwrap_or_else(|e| panic!("{e}")).geometry.preload, p);
        }
        let (_, _, message) = parse_err(&with_line("geometry", "preload", "preload = \"spring\""));
        for name in ["double-nut", "offset-lead", "oversize-ball", "none"] {
            assert!(message.contains(name), "{message}");
        }
        let (field, value, valid) = invalid_err(&with_line("geometry", "preload", "preload = \"oversize-ball\""));
        assert_eq!((field.as_str(), value), ("geometry.nuts", 2.0), "{valid}");
    }

    /// The built-in file with `key = ...` (first occurrence, within `table`) replaced by `line`.
    /// The built-in file with `key` of `table` written as `line` (added under the table's
    /// header where the file leaves the optional key out).
    fn with_line(table: &str, key: &str, line: &str) -> String {
        let mut in_table = false;
        let mut out = Vec::new();
        let mut header = None;
        let mut replaced = false;
        for l in DKFZD4012_TOML.lines() {
            if let Some(t) = header_name(l) {
                in_table = t == table;
                if in_table {
                    header = Some(out.len());
                }
            }
            if in_table && key_of(l) == Some(key) {
                out.push(line.to_string());
                replaced = true;
            } else {
                out.push(l.to_string());
            }
        }
        if let (false, Some(h)) = (replaced, header) {
            out.insert(h + 1, line.to_string());
        }
        out.join("\n")
    }

    /// The 1-based line of `key` in `table` of the built-in file.
    fn line_of(table: &str, key: &str) -> usize {
        line_of_opt(table, key).unwrap_or_else(|| panic!("{table}.{key} not in the built-in file"))
    }

    /// The 1-based line of `key` in `table` of the built-in file, if it is there.
    fn line_of_opt(table: &str, key: &str) -> Option<usize> {
        let mut in_table = false;
        for (i, l) in DKFZD4012_TOML.lines().enumerate() {
            if let Some(t) = header_name(l) {
                in_table = t == table;
            }
            if in_table && key_of(l) == Some(key) {
                return Some(i + 1);
            }
        }
        None
    }

    fn parse_err(text: &str) -> (usize, usize, String) {
        match spec_from_toml_str(text, ORIGIN) {
            Err(ConfigError::Parse { line, column, message, origin }) => {
                assert_eq!(origin, ORIGIN);
                (line, column, message)
            }
            other => panic!("expected a parse error, got {other:?}"),
        }
    }

    fn invalid_err(text: &str) -> (String, f64, String) {
        match spec_from_toml_str(text, ORIGIN) {
            Err(ConfigError::Invalid { field, value, valid }) => (field, value, valid),
            other => panic!("expected an invalid-value error, got {other:?}"),
        }
    }

    #[test]
    fn embedded_file_is_dkfzd4012() {
        let spec = spec_from_toml_str(DKFZD4012_TOML, ORIGIN).unwrap();
        assert_spec_close(&spec, &ScrewSpec::dkfzd4012());
    }

    #[test]
    fn optional_tables_and_keys_default() {
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().replace("ball_ball_load_n = 0.0", "");
        let text = text.replace("standstill_speed_rpm = 0.1", "");
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_spec_close(&spec, &ScrewSpec::dkfzd4012());
    }

    /// The torque of `spec` at its own operating point.
    fn torque_at_own_point(spec: &ScrewSpec) -> f64 {
        let model = Model::new(spec).unwrap();
        let mut st = ballscrew_core::screw::model::SolverState::new();
        model.torque(&spec.operating, &mut st).unwrap()
    }

    /// `friction.coefficient` and the operating point's speed and axial load may be left out:
    /// they take 0.03, 100 rpm and 0 N, and the spec is the one with them written out.
    #[test]
    fn coefficient_speed_and_axial_load_default() {
        let text = with_line("friction", "coefficient", "");
        let text = text.replace("speed_rpm = 100.0", "").replace("axial_load_n = 0.0", "");
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_eq!(spec, builtin_spec().unwrap());
        // Written-out values other than the defaults act: the defaults are what was filled in.
        let other = with_line("friction", "coefficient", "coefficient = 0.05");
        assert_eq!(spec_from_toml_str(&other, ORIGIN).unwrap().friction.coefficient, 0.05);
        let dry = |t: &str| {
            let mut s = spec_from_toml_str(t, ORIGIN).unwrap();
            s.model.lubrication = Lubrication::Dry;
            torque_at_own_point(&s)
        };
        assert_ne!(dry(&other), dry(&text), "the dry model reads the coefficient");
        assert_eq!(dry(&text), dry(DKFZD4012_TOML));
        assert_eq!(torque_at_own_point(&spec), torque_at_own_point(&builtin_spec().unwrap()));
    }

    /// A nut without preload needs no `[operating]` table at all: the point is 100 rpm, 0 N
    /// preload, 0 N axial load, and the torques are those of the table written out.
    #[test]
    fn operating_table_optional_for_a_nut_without_preload() {
        let one =
            DKFZD4012_TOML.replace("nuts = 2 ", "nuts = 1 ").replace("preload = \"double-nut\"", "preload = \"none\"");
        let written =
            one.replace("preload_n = 2000.0", "preload_n = 0.0").replace("axial_load_n = 0.0", "axial_load_n = 500.0");
        let left_out = without_table(&with_line("friction", "coefficient", ""), "operating")
            .replace("nuts = 2 ", "nuts = 1 ")
            .replace("preload = \"double-nut\"", "preload = \"none\"");
        assert!(!left_out.contains("[operating]") && !left_out.contains("coefficient ="), "{left_out}");
        let spec = spec_from_toml_str(&left_out, ORIGIN).unwrap();
        let op = spec.operating;
        assert_eq!((op.speed_rad_s, op.preload_n, op.axial_load_n), (rpm_to_rad_s(100.0), 0.0, 0.0));
        assert_eq!(spec.friction.coefficient, 0.03);
        let explicit =
            spec_from_toml_str(&written.replace("axial_load_n = 500.0", "axial_load_n = 0.0"), ORIGIN).unwrap();
        assert_eq!(spec, explicit);
        // Under an axial load (the balls loaded, a torque to compare): the defaults' point with
        // the load set gives the torque of the file that writes it out.
        let loaded = spec_from_toml_str(&written, ORIGIN).unwrap();
        let mut from_defaults = spec;
        from_defaults.operating.axial_load_n = 500.0;
        let t = torque_at_own_point(&loaded);
        assert!(t > 0.0, "{t}");
        assert_eq!(torque_at_own_point(&from_defaults), t);
    }

    /// A preloaded nut's preload has no default: leaving it (or `[operating]`) out is refused
    /// as a missing key, naming the arrangement; the arrangement implied by two nuts counts.
    #[test]
    fn preload_required_for_a_preloaded_nut() {
        let no_key = with_line("operating", "preload_n", "");
        let no_table = without_table(DKFZD4012_TOML, "operating");
        let implied = with_line("geometry", "preload", "").replace("preload_n = 2000.0", "");
        for text in [&no_key, &no_table, &implied] {
            let (line, _, message) = parse_err(text);
            assert!(message.starts_with("missing key `operating.preload_n`"), "{message}");
            assert!(message.contains("\"double-nut\""), "{message}");
            let header = text.lines().position(|l| l == "[operating]").map_or(1, |i| i + 1);
            assert_eq!(line, header);
        }
        let offset = with_line("geometry", "preload", "preload = \"offset-lead\"").replace("nuts = 2 ", "nuts = 1 ");
        let (_, _, message) = parse_err(&offset.replace("preload_n = 2000.0", ""));
        assert!(message.contains("\"offset-lead\""), "{message}");
        assert!(spec_from_toml_str(&offset, ORIGIN).is_ok());
    }

    #[test]
    fn unknown_key_in_each_table_names_key_and_line() {
        for (table, key) in [
            ("geometry", "pitch_diameter_mm"),
            ("material", "poisson_ratio"),
            ("friction", "coefficient"),
            ("operating", "preload_n"),
            ("model", "torque"),
        ] {
            let bad = format!("{key}_typo");
            let value = if table == "model" { "\"energy\"" } else { "1.0" };
            let text = with_line(table, key, &format!("{bad} = {value}"));
            let (line, column, message) = parse_err(&text);
            assert_eq!(line, line_of(table, key), "{message}");
            assert_eq!(column, 1);
            assert!(message.contains(&format!("unknown field `{bad}`")), "{message}");
            assert!(message.contains(&format!("[{table}]")), "{message}");
            assert!(message.contains(&format!("`{key}`")), "the valid keys are listed: {message}");
            let shown = ConfigError::Parse { origin: ORIGIN.into(), line, column, message }.to_string();
            assert!(shown.starts_with(&format!("{ORIGIN}:{line}:1: unknown field")), "{shown}");
        }
    }

    #[test]
    fn unknown_table_rejected() {
        let text = format!("{DKFZD4012_TOML}\n[lubrication]\nviscosity = 1.0\n");
        let (line, _, message) = parse_err(&text);
        assert_eq!(line, DKFZD4012_TOML.lines().count() + 2);
        assert!(message.contains("unknown table `[lubrication]`"), "{message}");
        assert!(message.contains("`geometry`"), "{message}");
    }

    #[test]
    fn missing_required_key_named() {
        let text = with_line("geometry", "lead_mm", "");
        let (line, _, message) = parse_err(&text);
        assert_eq!(message, "missing key `geometry.lead_mm`");
        assert_eq!(line, DKFZD4012_TOML.lines().position(|l| l == "[geometry]").unwrap() + 1);

        let text = DKFZD4012_TOML.replace("[operating]", "[nothing]");
        let (_, _, message) = parse_err(&text);
        assert!(message.contains("[nothing]"), "{message}");

        let text: String = DKFZD4012_TOML.split("[material]").next().unwrap().to_string();
        let (_, _, message) = parse_err(&text);
        assert_eq!(message, "missing table `[material]`");
    }

    #[test]
    fn wrong_type_names_key() {
        let text = with_line("geometry", "lead_mm", "lead_mm = \"twelve\"");
        let (line, _, message) = parse_err(&text);
        assert_eq!(line, line_of("geometry", "lead_mm"));
        assert!(message.starts_with("geometry.lead_mm: "), "{message}");
    }

    #[test]
    fn wrong_type_says_number_or_whole_number() {
        let cases = [
            (
                "geometry",
                "lead_mm",
                "lead_mm = \"twelve\"",
                "geometry.lead_mm: invalid type: string \"twelve\", expected a number",
            ),
            (
                "material",
                "poisson_ratio",
                "poisson_ratio = true",
                "material.poisson_ratio: invalid type: boolean `true`, expected a number",
            ),
            (
                "geometry",
                "nuts",
                "nuts = \"two\"",
                "geometry.nuts: invalid type: string \"two\", expected a whole number",
            ),
            (
                "model",
                "fastsim_grid",
                "fastsim_grid = \"x\"",
                "model.fastsim_grid: invalid type: string \"x\", expected a whole number",
            ),
        ];
        for (table, key, line, message) in cases {
            let (at, _, m) = parse_err(&with_line(table, key, line));
            assert_eq!((at, m.as_str()), (line_of(table, key), message));
        }
        // A negative, fractional or huge grid is a range error, as for the other counts.
        for (line, value) in
            [("fastsim_grid = -1", -1.0), ("fastsim_grid = 2.5", 2.5), ("fastsim_grid = 99999999999", 99999999999.0)]
        {
            let (field, v, _) = invalid_err(&with_line("model", "fastsim_grid", line));
            assert_eq!((field.as_str(), v), ("model.fastsim_grid", value), "{line}");
        }
    }

    #[test]
    fn syntax_error_has_line_and_column() {
        let text = with_line("material", "poisson_ratio", "poisson_ratio = = 0.3");
        let (line, column, _) = parse_err(&text);
        assert_eq!(line, line_of("material", "poisson_ratio"));
        assert!(column > 1);
    }

    #[test]
    fn invalid_values_name_toml_key_value_and_range() {
        let cases = [
            (
                "geometry",
                "conformity_screw",
                "conformity_screw = 0.5",
                "geometry.conformity_screw",
                0.5,
                "[0.501, 0.6]",
            ),
            ("geometry", "contact_angle_deg", "contact_angle_deg = 90", "geometry.contact_angle_deg", 90.0, "[20, 70]"),
            (
                "geometry",
                "ball_diameter_mm",
                "ball_diameter_mm = 40.0",
                "geometry.ball_diameter_mm",
                40.0,
                "pitch diameter",
            ),
            ("geometry", "lead_mm", "lead_mm = -12.0", "geometry.lead_mm", -12.0, "[0.5, 200] mm"),
            (
                "geometry",
                "pitch_diameter_mm",
                "pitch_diameter_mm = 0",
                "geometry.pitch_diameter_mm",
                0.0,
                "[3, 300] mm",
            ),
            // Beyond the physical ranges (these once ended in "did not converge" or were accepted).
            ("geometry", "lead_mm", "lead_mm = 1e300", "geometry.lead_mm", 1e300, "[0.5, 200] mm"),
            (
                "geometry",
                "ball_diameter_mm",
                "ball_diameter_mm = 1e-9",
                "geometry.ball_diameter_mm",
                1e-9,
                "[0.5, 50] mm and below pitch diameter / 2",
            ),
            (
                "material",
                "youngs_modulus_gpa",
                "youngs_modulus_gpa = 1e-300",
                "material.youngs_modulus_gpa",
                1e-300,
                "[1, 1000] GPa",
            ),
            (
                "friction",
                "ball_ball_load_n",
                "ball_ball_load_n = 1e300",
                "friction.ball_ball_load_n",
                1e300,
                "[0, 1000] N",
            ),
            (
                "geometry",
                "conformity_nut",
                "conformity_nut = 0.5000001",
                "geometry.conformity_nut",
                0.5000001,
                "[0.501, 0.6]",
            ),
            (
                "geometry",
                "pitch_diameter_mm",
                "pitch_diameter_mm = 1e9",
                "geometry.pitch_diameter_mm",
                1e9,
                "[3, 300] mm",
            ),
            (
                "friction",
                "standstill_speed_rpm",
                "standstill_speed_rpm = 1e300",
                "friction.standstill_speed_rpm",
                1e300,
                "(0, 100] rpm",
            ),
            (
                "geometry",
                "pitch_diameter_mm",
                "pitch_diameter_mm = 11.0",
                "geometry.ball_diameter_mm",
                5.953,
                "pitch diameter / 2",
            ),
            ("operating", "speed_rpm", "speed_rpm = 1e9", "operating.speed_rpm", 1e9, "[-30000, 30000] rpm"),
            ("operating", "preload_n", "preload_n = -1", "operating.preload_n", -1.0, "[0, 1e7] N"),
            (
                "friction",
                "standstill_speed_rpm",
                "standstill_speed_rpm = 0",
                "friction.standstill_speed_rpm",
                0.0,
                "(0, 100] rpm",
            ),
            (
                "material",
                "youngs_modulus_gpa",
                "youngs_modulus_gpa = -inf",
                "material.youngs_modulus_gpa",
                f64::NEG_INFINITY,
                "[1, 1000] GPa",
            ),
        ];
        for (table, key, line, field, value, valid) in cases {
            let (f, v, r) = invalid_err(&with_line(table, key, line));
            assert_eq!(f, field, "{line}");
            assert_eq!(v, value, "{line}");
            assert!(r.contains(valid), "{line}: {r}");
        }
    }

    #[test]
    fn messages_show_huge_and_tiny_values_in_exponent_form() {
        let cases = [
            ("geometry", "lead_mm", "lead_mm = 1e300", "invalid geometry.lead_mm: 1e297 m (valid: [500 µm, 200 mm])"),
            (
                "material",
                "youngs_modulus_gpa",
                "youngs_modulus_gpa = 1e-300",
                "invalid material.youngs_modulus_gpa: 1e-291 Pa (valid: [1 GPa, 1 TPa])",
            ),
            (
                "operating",
                "preload_n",
                "preload_n = -2000",
                "invalid operating.preload_n: -2 kN (valid: finite, [0 N, 10 MN])",
            ),
        ];
        for (table, key, line, shown) in cases {
            let e = spec_from_toml_str(&with_line(table, key, line), ORIGIN).unwrap_err();
            assert_eq!(e.to_string(), shown);
        }
    }

    #[test]
    fn nan_rejected_naming_the_field() {
        for (table, key) in [("geometry", "lead_mm"), ("operating", "speed_rpm"), ("friction", "coefficient")] {
            let (field, value, _) = invalid_err(&with_line(table, key, &format!("{key} = nan")));
            assert_eq!(field, format!("{table}.{key}"));
            assert!(value.is_nan());
        }
        let e = spec_from_toml_str(&with_line("geometry", "lead_mm", "lead_mm = nan"), ORIGIN).unwrap_err();
        assert_eq!(e.to_string(), "invalid geometry.lead_mm: NaN (valid: [500 µm, 200 mm])");
    }

    #[test]
    fn counts_reject_negative_and_fractional() {
        for (line, value) in [("nuts = -2", -2.0), ("nuts = 1.5", 1.5), ("nuts = nan", f64::NAN)] {
            let (field, v, valid) = invalid_err(&with_line("geometry", "nuts", line));
            assert_eq!(field, "geometry.nuts");
            assert!(v == value || (v.is_nan() && value.is_nan()), "{line}");
            assert!(valid.contains("whole number"), "{valid}");
        }
        let (field, v, valid) = invalid_err(&with_line("geometry", "nuts", "nuts = 3"));
        assert_eq!((field.as_str(), v, valid.as_str()), ("geometry.nuts", 3.0, "1 or 2"));
        let (field, v, _) = invalid_err(&with_line("geometry", "balls_per_circle", "balls_per_circle = 5000000000"));
        assert_eq!((field.as_str(), v), ("geometry.balls_per_circle", 5.0e9));
        let (field, v, _) = invalid_err(&with_line("geometry", "circles_per_nut", "circles_per_nut = 0"));
        assert_eq!((field.as_str(), v), ("geometry.circles_per_nut", 0.0));
        // A whole float is a count.
        let spec = spec_from_toml_str(&with_line("geometry", "nuts", "nuts = 2.0"), ORIGIN).unwrap();
        assert_eq!(spec.geometry.nuts, 2);
    }

    #[test]
    fn model_options_parsed() {
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().to_string()
            + "[model]\nload_distribution = \"paper-literal\"\ncreep_coefficients = \"paper-fit\"\n\
               torque = \"paper-eq27\"\nheathcote = false\nspin_moment = \"separate\"\nlubrication = \"dry\"\n";
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_eq!(spec.model, ModelOptions { heathcote: false, ..ModelOptions::paper_literal() });
        let text =
            DKFZD4012_TOML.split("[model]").next().unwrap().to_string() + "[model]\nload_distribution = \"uniform\"\n";
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_eq!(
            spec.model,
            ModelOptions { load_distribution: LoadDistribution::Uniform, ..ModelOptions::default() }
        );
    }

    /// Each option's `name()` (what reports print) is the name a spec file takes and writes.
    #[test]
    fn option_names_are_the_spec_file_names() {
        use ballscrew_core::input::{ContactTheory, CreepCoefficientSource, LoadDistribution, SpinMoment, TorqueRoute};
        let mut specs = Vec::new();
        for d in [LoadDistribution::Geometric, LoadDistribution::PaperLiteral, LoadDistribution::Uniform] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.load_distribution = d;
            specs.push((s, "load_distribution", d.name()));
        }
        for c in [CreepCoefficientSource::KalkerTable, CreepCoefficientSource::PaperFit] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.creep_coefficients = c;
            specs.push((s, "creep_coefficients", c.name()));
        }
        for t in [TorqueRoute::Energy, TorqueRoute::PaperEq27] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.torque = t;
            specs.push((s, "torque", t.name()));
        }
        for m in [SpinMoment::Combined, SpinMoment::Separate] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.spin_moment = m;
            specs.push((s, "spin_moment", m.name()));
        }
        for c in [ContactTheory::LinearSaturated, ContactTheory::Fastsim] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.contact_theory = c;
            specs.push((s, "contact_theory", c.name()));
        }
        for (spec, key, name) in specs {
            let text = spec_to_toml(&spec);
            assert!(text.contains(&format!("{key} = \"{name}\"")), "{key} = {name} in:\n{text}");
            assert_eq!(spec_from_toml_str(&text, "test").unwrap().model, spec.model);
        }
    }

    #[test]
    fn bad_option_names_list_valid_ones() {
        let cases = [
            ("load_distribution", &["geometric", "paper-literal", "uniform"][..]),
            ("creep_coefficients", &["kalker-table", "paper-fit"][..]),
            ("torque", &["energy", "paper-eq27"][..]),
            ("spin_moment", &["combined", "separate"][..]),
        ];
        for (key, valid) in cases {
            let text = with_line("model", key, &format!("{key} = \"bogus\""));
            let (line, _, message) = parse_err(&text);
            assert_eq!(line, line_of("model", key));
            assert!(message.contains(&format!("model.{key}")), "{message}");
            assert!(message.contains("`bogus`"), "{message}");
            for v in valid {
                assert!(message.contains(&format!("`{v}`")), "{message}");
            }
        }
        let (_, _, message) = parse_err(&with_line("model", "heathcote", "heathcote = \"yes\""));
        assert!(message.contains("model.heathcote"), "{message}");
    }

    #[test]
    fn round_trip() {
        let mut specs = [ScrewSpec::dkfzd4012(); 3];
        specs[1].model = ModelOptions::paper_literal();
        specs[1].operating.speed_rad_s = -7.3;
        specs[1].friction.ball_ball_load_n = Some(12.5);
        specs[2].geometry.nuts = 1;
        specs[2].geometry.preload = Preload::OversizeBall;
        specs[2].geometry.contact_angle_rad = 0.7;
        specs[2].geometry.pitch_diameter_m = 0.0451;
        specs[2].material.youngs_modulus_pa = 2.07e11;
        for spec in &specs {
            let text = spec_to_toml(spec);
            let back = spec_from_toml_str(&text, "round-trip").unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_spec_close(&back, spec);
        }
        assert!(spec_to_toml(&specs[0]).contains("nuts = 2\n"));
    }

    #[test]
    fn missing_file_names_path() {
        let e = spec_from_toml_file(Path::new("/nonexistent/dir/spec.toml")).unwrap_err();
        assert!(matches!(e, ConfigError::Io { .. }));
        assert!(e.to_string().starts_with("/nonexistent/dir/spec.toml: "), "{e}");
    }

    #[test]
    fn every_core_field_is_mapped() {
        // Each spec value the core validates has one TOML key, and every key's core name is
        // what the core reports: break each value in turn and check the key that comes back.
        for k in KEYS.iter().filter(|k| k.core.is_some()) {
            let (table, key) = (k.table, k.key);
            // Counts of the [model] table are integers in TOML (nan does not parse): 2 is out of range.
            let bad = if table == "model" { "2" } else { "nan" };
            let text = if table == "lubricant" {
                let lub: Vec<String> = LUBRICANT_TOML
                    .lines()
                    .map(|l| if key_of(l) == Some(key) { format!("{key} = {bad}") } else { l.to_string() })
                    .collect();
                format!("{}\n{}", without_table(DKFZD4012_TOML, "lubricant"), lub.join("\n"))
            } else if line_of_opt(table, key).is_none() && !table.starts_with("extensions") {
                // An optional key the built-in file leaves out: added under its table's header.
                DKFZD4012_TOML.replacen(&format!("[{table}]\n"), &format!("[{table}]\n{key} = {bad}\n"), 1)
            } else if table.starts_with("extensions") {
                // The key is broken in every table that has it; only `table` is kept.
                let ext: Vec<String> = EXTENSIONS_TOML
                    .lines()
                    .map(|l| if key_of(l) == Some(key) { format!("{key} = {bad}") } else { l.to_string() })
                    .collect();
                format!("{DKFZD4012_TOML}\n{}", only_table(&ext.join("\n"), table))
            } else {
                with_line(table, key, &format!("{key} = {bad}"))
            };
            match spec_from_toml_str(&text, ORIGIN) {
                Err(ConfigError::Invalid { field, .. }) => assert_eq!(field, k.full()),
                other => panic!("{}: expected an invalid-value error, got {other:?}", k.full()),
            }
        }
    }

    /// A `[lubricant]` table with every key (valid values, the viscosities rather than a grade).
    const LUBRICANT_TOML: &str = "[lubricant]\nviscosity_40c_mm2_s = 100.0\nviscosity_100c_mm2_s = 11.0\n\
        density_15c_kg_m3 = 880.0\ndensity_temperature_coefficient_kg_m3_k = -0.65\n\
        pressure_viscosity_per_gpa = 20.0\nthermal_conductivity_w_m_k = 0.13\ntemperature_c = 55.0\n\
        roughness_ball_rq_um = 0.03\nroughness_raceway_rq_um = 0.2\nboundary_friction = 0.12\n\
        full_film_traction = 0.04\nasperity_load_b = 2.0\nasperity_load_c = 1.1\n\
        hysteresis_loss_factor = 0.003\ninlet_distance_ratio = 5.0\n";

    /// `text` without its `[table]` (header and keys), if it has one.
    fn without_table(text: &str, table: &str) -> String {
        let mut keep = true;
        let mut out = Vec::new();
        for l in text.lines() {
            if let Some(t) = header_name(l) {
                keep = t != table;
            }
            if keep {
                out.push(l);
            }
        }
        out.join("\n") + "\n"
    }

    /// The built-in file with its `[lubricant]` table replaced by `table`.
    fn with_lubricant(table: &str) -> String {
        format!("{}\n{table}", without_table(DKFZD4012_TOML, "lubricant"))
    }

    #[test]
    fn lubricant_table_read_written_and_read_back() {
        let spec = spec_from_toml_str(&with_lubricant(LUBRICANT_TOML), ORIGIN).unwrap();
        let l = &spec.lubricant;
        assert!(close(l.viscosity_40c_m2_s, 100.0e-6) && close(l.viscosity_100c_m2_s, 11.0e-6), "{l:?}");
        assert!(close(l.pressure_viscosity_per_pa, 2.0e-8) && close(l.roughness_raceway_rq_m, 0.2e-6), "{l:?}");
        assert_eq!((l.temperature_c, l.inlet_distance_ratio), (55.0, Some(5.0)));
        for spec in [spec, ScrewSpec::dkfzd4012()] {
            let text = spec_to_toml(&spec);
            assert!(text.contains("[lubricant]"), "{text}");
            let back = spec_from_toml_str(&text, ORIGIN).unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_lubricant_close(&back.lubricant, &spec.lubricant);
        }
        // No table: the default oil; a grade alone: that grade with the default slope.
        let spec = spec_from_toml_str(&without_table(DKFZD4012_TOML, "lubricant"), ORIGIN).unwrap();
        assert_eq!(spec.lubricant, Lubricant::default());
        let spec = spec_from_toml_str(&with_lubricant("[lubricant]\niso_vg = 32\n"), ORIGIN).unwrap();
        assert_eq!(spec.lubricant, Lubricant::iso_vg(32.0));
    }

    fn assert_lubricant_close(a: &Lubricant, b: &Lubricant) {
        let pairs = [
            (a.viscosity_40c_m2_s, b.viscosity_40c_m2_s),
            (a.viscosity_100c_m2_s, b.viscosity_100c_m2_s),
            (a.density_15c_kg_m3, b.density_15c_kg_m3),
            (a.density_temperature_coefficient_kg_m3_k, b.density_temperature_coefficient_kg_m3_k),
            (a.pressure_viscosity_per_pa, b.pressure_viscosity_per_pa),
            (a.thermal_conductivity_w_m_k, b.thermal_conductivity_w_m_k),
            (a.temperature_c, b.temperature_c),
            (a.roughness_ball_rq_m, b.roughness_ball_rq_m),
            (a.roughness_raceway_rq_m, b.roughness_raceway_rq_m),
            (a.boundary_friction, b.boundary_friction),
            (a.full_film_traction, b.full_film_traction),
            (a.asperity_load_b, b.asperity_load_b),
            (a.asperity_load_c, b.asperity_load_c),
            (a.hysteresis_loss_factor, b.hysteresis_loss_factor),
        ];
        for (i, (x, y)) in pairs.iter().enumerate() {
            assert!(close(*x, *y), "lubricant field {i}: {x} vs {y}");
        }
        assert_eq!(a.inlet_distance_ratio.is_some(), b.inlet_distance_ratio.is_some());
        if let (Some(x), Some(y)) = (a.inlet_distance_ratio, b.inlet_distance_ratio) {
            assert!(close(x, y));
        }
    }

    #[test]
    fn unknown_lubricant_key_names_line_and_column() {
        let text = with_lubricant("[lubricant]\ntemperature_c = 50.0\n  viscosity_40_mm2_s = 68.0\n");
        let (line, column, message) = parse_err(&text);
        assert_eq!(line, text.lines().position(|l| l.contains("viscosity_40_mm2_s")).unwrap() + 1);
        assert_eq!(column, 3);
        assert!(message.contains("unknown field `viscosity_40_mm2_s`") && message.contains("[lubricant]"), "{message}");
        assert!(message.contains("`viscosity_40c_mm2_s`"), "the valid keys are listed: {message}");
    }

    /// The grade range's ends are where the oil's viscosities leave theirs: the thinnest grade's
    /// oil is valid, a grade 1e-6 thinner is below 2 mm^2/s at 100 degrees C; the thickest
    /// grade's oil is valid.
    #[test]
    fn iso_vg_range_ends_are_the_oils_range_ends() {
        assert!(Lubricant::iso_vg(MIN_ISO_VG).validate().is_ok());
        let e = Lubricant::iso_vg(MIN_ISO_VG * (1.0 - 1e-6)).validate().unwrap_err();
        assert_eq!(e.field, "lubricant.viscosity_100c_mm2_s", "{e}");
        assert!(Lubricant::iso_vg(MAX_ISO_VG).validate().is_ok());
        let (field, value, valid) = invalid_err(&with_lubricant("[lubricant]\niso_vg = 5.3\n"));
        assert_eq!((field.as_str(), value), ("lubricant.iso_vg", 5.3));
        assert!(valid.starts_with("[5.362662, 5000]"), "{valid}");
    }

    #[test]
    fn iso_vg_with_viscosities_is_an_error_naming_the_key() {
        for extra in ["viscosity_40c_mm2_s = 68.0", "viscosity_100c_mm2_s = 9.0"] {
            let e = spec_from_toml_str(&with_lubricant(&format!("[lubricant]\niso_vg = 68\n{extra}\n")), ORIGIN)
                .unwrap_err();
            let shown = e.to_string();
            assert!(matches!(&e, ConfigError::Invalid { field, .. } if field == "lubricant.iso_vg"), "{e:?}");
            assert!(shown.contains("iso_vg") && shown.contains("viscosity_40c_mm2_s"), "{shown}");
        }
        // One viscosity alone names the missing one (not as a value of NaN).
        for (given, missing) in [("viscosity_40c_mm2_s = 68.0", "100c"), ("viscosity_100c_mm2_s = 9.0", "40c")] {
            let e = spec_from_toml_str(&with_lubricant(&format!("[lubricant]\n{given}\n")), ORIGIN).unwrap_err();
            let field = std::format!("lubricant.viscosity_{missing}_mm2_s");
            assert!(matches!(&e, ConfigError::Missing { field: f, .. } if *f == field), "{e:?}");
            assert_eq!(
                e.to_string(),
                std::format!("missing {field} (valid: both viscosities (40 and 100 C), or iso_vg alone)")
            );
        }
        // A grade too thin for the viscosity law is the grade's error.
        let (field, value, _) = invalid_err(&with_lubricant("[lubricant]\niso_vg = 2\n"));
        assert_eq!((field.as_str(), value), ("lubricant.iso_vg", 2.0));
    }

    #[test]
    fn bad_lubricant_value_names_key_value_and_range() {
        let cases = [
            ("temperature_c = 250.0", "invalid lubricant.temperature_c: 250 (valid: [-30, 200] degrees C)"),
            ("roughness_ball_rq_um = 7.0", "invalid lubricant.roughness_ball_rq_um: 7 µm (valid: [0 m, 5 µm])"),
            (
                "pressure_viscosity_per_gpa = 500.0",
                "invalid lubricant.pressure_viscosity_per_gpa: 500 (valid: [1, 100] 1/GPa)",
            ),
            ("viscosity_40c_mm2_s = 68.0\nviscosity_100c_mm2_s = 80.0", "invalid lubricant.viscosity_100c_mm2_s: 80"),
            ("iso_vg = 10000", "invalid lubricant.iso_vg: 10000 (valid: [5.362662, 5000]"),
            ("boundary_friction = 1.5", "invalid lubricant.boundary_friction: 1.5 (valid: [0, 1])"),
        ];
        for (line, shown) in cases {
            let e = spec_from_toml_str(&with_lubricant(&format!("[lubricant]\n{line}\n")), ORIGIN).unwrap_err();
            assert!(e.to_string().starts_with(shown), "{line}: {e}");
        }
    }

    #[test]
    fn lubrication_option_parsed_and_written() {
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().to_string() + "[model]\nlubrication = \"dry\"\n";
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_eq!(spec.model, ModelOptions { lubrication: Lubrication::Dry, ..ModelOptions::default() });
        assert!(spec_to_toml(&spec).contains("lubrication = \"dry\""));
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().to_string() + "[model]\nlubrication = \"wet\"\n";
        let (_, _, message) = parse_err(&text);
        assert!(message.contains("`ehl`") && message.contains("`dry`"), "{message}");
        assert_eq!(builtin_spec().unwrap().model.lubrication, Lubrication::Ehl);
    }

    /// Every extension table with valid values.
    const EXTENSIONS_TOML: &str = "[extensions.seal_drag]\ntorque_nm = 0.02\n\
        [extensions.viscous_drag]\ntorque_nm = 0.01\nexponent = 0.7\nreference_speed_rpm = 1000.0\n\
        [extensions.thermal_viscosity]\ntorque_nm = 0.01\nexponent = 0.7\nreference_speed_rpm = 500.0\n\
        viscosity_coefficient_per_k = 0.03\nreference_temperature_c = 40.0\n\
        [extensions.raceway_waviness]\nharmonic = 2\namplitude_nm = 0.005\nphase_deg = 30.0\n\
        [extensions.preload_loss]\nloss_per_1000_h = 0.3\n\
        [extensions.direction_asymmetry]\nreverse_factor = 1.2\n\
        [extensions.preload_law]\nexponent = -0.2\nreference_preload_n = 1500.0\n\
        [extensions.axial_load_loss]\ntorque_per_kn_nm = 0.3\n";

    /// The lines of one `[table]` of `text`.
    fn only_table(text: &str, table: &str) -> String {
        let mut keep = false;
        let mut out = Vec::new();
        for l in text.lines() {
            if let Some(t) = header_name(l) {
                keep = t == table;
            }
            if keep {
                out.push(l);
            }
        }
        out.join("\n")
    }

    #[test]
    fn extension_tables_round_trip_and_act_on_the_torque() {
        let text = format!("{DKFZD4012_TOML}\n{EXTENSIONS_TOML}");
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        let e = &spec.extensions;
        assert_eq!(e.raceway_waviness.unwrap().harmonic, 2);
        assert!((e.axial_load_loss.unwrap().torque_per_n_nm - 0.3e-3).abs() < 1e-15);
        assert!((e.thermal_viscosity.unwrap().drag.reference_speed_rad_s - rpm_to_rad_s(500.0)).abs() < 1e-12);
        let back = spec_from_toml_str(&spec_to_toml(&spec), ORIGIN).unwrap();
        assert_eq!(back.extensions.seal_drag, e.seal_drag);
        assert_eq!(back.extensions.preload_law, e.preload_law);
        assert!(
            (back.extensions.raceway_waviness.unwrap().phase_rad - e.raceway_waviness.unwrap().phase_rad).abs() < 1e-12
        );
        // The seal drag alone adds its torque to the model's at the spec's operating point.
        let seal = format!("{DKFZD4012_TOML}\n[extensions.seal_drag]\ntorque_nm = 0.02\n");
        let with = Model::new(&spec_from_toml_str(&seal, ORIGIN).unwrap()).unwrap();
        let without = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let op = ScrewSpec::dkfzd4012().operating;
        let mut st = ballscrew_core::screw::model::SolverState::new();
        let d = with.torque(&op, &mut st).unwrap() - without.torque(&op, &mut st).unwrap();
        assert!((d - 0.02).abs() < 1e-9, "{d}");
    }

    #[test]
    fn unknown_extension_table_or_key_is_rejected() {
        let (_, _, m) = parse_err(&format!("{DKFZD4012_TOML}\n[extensions.lubrication]\nviscosity = 1.0\n"));
        assert!(m.contains("lubrication") && m.contains("seal_drag"), "{m}");
        let (line, _, m) = parse_err(&format!("{DKFZD4012_TOML}\n[extensions.seal_drag]\ntorque = 1.0\n"));
        assert_eq!(line, DKFZD4012_TOML.lines().count() + 3);
        assert!(m.contains("unknown field `torque`") && m.contains("torque_nm"), "{m}");
    }

    #[test]
    fn creep_reduction_is_optional_and_checked() {
        let text = DKFZD4012_TOML.replace("coefficient = 0.03", "coefficient = 0.03\ncreep_reduction = 1.5");
        let (field, value, _) = invalid_err(&text);
        assert_eq!((field.as_str(), value), ("friction.creep_reduction", 1.5));
    }
}
