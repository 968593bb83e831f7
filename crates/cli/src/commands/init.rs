//! `ballscrew init`: a commented spec file for the user's screw from its dimensions. Every value
//! the flags give is marked `# given`; every other is an assumption, written with `# assumed:`
//! and why, for the user to replace with the screw maker's data. The text is read back by the
//! spec parser (`ballscrew_config::spec_from_toml_str`) before anything is written: a spec the
//! parser refuses is refused here, naming the flag, and nothing is written.

use crate::error::CliError;
use ballscrew_config::{ConfigError, spec_from_toml_str};
use ballscrew_core::input::geometry::max_balls_per_circle;
use ballscrew_core::input::{Geometry, Preload, ScrewSpec};
use clap::ValueEnum;
use std::path::Path;

/// Table 1's conformity of both grooves, the usual gothic-arch value.
const CONFORMITY: f64 = 0.52;
/// The usual gothic-arch contact angle, deg.
const CONTACT_ANGLE_DEG: f64 = 45.0;
/// Table 1's circles per nut.
const CIRCLES_PER_NUT: u32 = 4;

/// How the nut is preloaded (the spec's `geometry.preload`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Arrangement {
    /// Two nuts pressed apart (nuts = 2)
    DoubleNut,
    /// One nut with a lead offset between its halves
    OffsetLead,
    /// One nut with oversize balls (four-point contact)
    OversizeBall,
    /// One nut without preload
    None,
}

impl Arrangement {
    fn core(self) -> Preload {
        match self {
            Arrangement::DoubleNut => Preload::DoubleNut,
            Arrangement::OffsetLead => Preload::OffsetLead,
            Arrangement::OversizeBall => Preload::OversizeBall,
            Arrangement::None => Preload::None,
        }
    }
}

/// How the balls return (the spec's `circulation.return`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ReturnKind {
    /// A deflector in the nut: one loaded turn per circuit
    Internal,
    /// A tube outside the nut or end caps
    External,
}

impl ReturnKind {
    fn name(self) -> &'static str {
        match self {
            ReturnKind::Internal => "internal",
            ReturnKind::External => "external",
        }
    }
}

/// Flags of `ballscrew init`.
#[derive(Debug, Clone, clap::Args)]
pub struct InitArgs {
    /// Pitch diameter d_m: diameter of the helix through the ball centres, mm
    #[arg(long, value_name = "MM", allow_negative_numbers = true)]
    pub pitch_diameter_mm: f64,
    /// Lead L: axial advance of the nut per screw revolution, mm
    #[arg(long, value_name = "MM", allow_negative_numbers = true)]
    pub lead_mm: f64,
    /// Ball diameter D_w, mm
    #[arg(long, value_name = "MM", allow_negative_numbers = true)]
    pub ball_diameter_mm: f64,
    /// Number of nuts (1 or 2) [default: 2 for --preload-arrangement double-nut, else 1]
    #[arg(long, value_name = "N")]
    pub nuts: Option<u32>,
    /// How the nut is preloaded [default: double-nut for --nuts 2, else none]
    #[arg(long, value_enum, value_name = "ARRANGEMENT")]
    pub preload_arrangement: Option<Arrangement>,
    /// Preload F_p, N: needed for every arrangement but none (the screw maker's catalog gives it)
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub preload_n: Option<f64>,
    /// Load-carrying circles (turns of balls) of each nut [default: 4, assumed]
    #[arg(long, value_name = "N")]
    pub circles_per_nut: Option<u32>,
    /// Balls in each circle [default: as many as fit one turn less the return's room (2 for an
    /// internal return, 1 for an external one), assumed]
    #[arg(long, value_name = "N")]
    pub balls_per_circle: Option<u32>,
    /// Nominal contact angle, deg [default: 45, assumed]
    #[arg(long, value_name = "DEG", allow_negative_numbers = true)]
    pub contact_angle_deg: Option<f64>,
    /// Conformity of the screw groove: groove radius / ball diameter [default: 0.52, assumed]
    #[arg(long, value_name = "F", allow_negative_numbers = true)]
    pub conformity_screw: Option<f64>,
    /// Conformity of the nut groove: groove radius / ball diameter [default: 0.52, assumed]
    #[arg(long, value_name = "F", allow_negative_numbers = true)]
    pub conformity_nut: Option<f64>,
    /// How the balls return [default: internal, assumed]
    #[arg(long = "return", value_enum, value_name = "RETURN")]
    pub return_kind: Option<ReturnKind>,
    /// Replace an existing file named by --out (without it, an existing file is refused)
    #[arg(long)]
    pub force: bool,
}

/// One `key = value  # note` line, the notes aligned.
fn line(key: &str, value: &str, note: &str) -> String {
    format!("{:<30}# {note}\n", format!("{key} = {value}"))
}

/// A real value as TOML writes it (`40.0`, `5.953`).
fn real(v: f64) -> String {
    format!("{v:?}")
}

/// `given`, or `assumed: why`.
fn note(given: bool, why: &str) -> String {
    if given { "given".to_string() } else { format!("assumed: {why}") }
}

/// The flag that sets a spec key, for the parser's errors.
fn flag_of(field: &str) -> String {
    match field {
        "geometry.preload" => "--preload-arrangement".to_string(),
        "operating.preload_n" => "--preload-n".to_string(),
        "circulation.return" => "--return".to_string(),
        _ => format!("--{}", field.rsplit('.').next().unwrap_or(field).replace('_', "-")),
    }
}

/// The spec text for `args`, not yet checked.
fn spec_text(args: &InitArgs) -> Result<String, CliError> {
    for (flag, v) in [
        ("--pitch-diameter-mm", Some(args.pitch_diameter_mm)),
        ("--lead-mm", Some(args.lead_mm)),
        ("--ball-diameter-mm", Some(args.ball_diameter_mm)),
        ("--preload-n", args.preload_n),
        ("--contact-angle-deg", args.contact_angle_deg),
        ("--conformity-screw", args.conformity_screw),
        ("--conformity-nut", args.conformity_nut),
    ] {
        if let Some(v) = v.filter(|v| !v.is_finite()) {
            return Err(CliError::Input(format!("invalid {flag}: {v} (valid: a finite number)")));
        }
    }
    if let Some(n) = args.nuts.filter(|n| !(1..=2).contains(n)) {
        return Err(CliError::Input(format!("invalid --nuts: {n} (valid: 1 or 2)")));
    }
    let (nuts, arrangement) = match (args.nuts, args.preload_arrangement) {
        (Some(n), Some(a)) => (n, a.core()),
        (Some(n), None) => (n, Preload::default_for_nuts(n)),
        (None, Some(a)) => (a.core().nuts(), a.core()),
        (None, None) => (1, Preload::None),
    };
    let preload_n = match (args.preload_n, arrangement) {
        (Some(p), _) => p,
        (None, Preload::None) => 0.0,
        (None, a) => {
            return Err(CliError::Input(format!(
                "--preload-n is needed for a nut preloaded by {} (the screw maker's catalog gives the preload, \
                 in N; without it, --preload-arrangement none)",
                a.name()
            )));
        }
    };
    let return_kind = args.return_kind.unwrap_or(ReturnKind::Internal);
    let return_room = match return_kind {
        ReturnKind::Internal => 2,
        ReturnKind::External => 1,
    };
    let geometry = Geometry {
        pitch_diameter_m: args.pitch_diameter_mm / 1e3,
        lead_m: args.lead_mm / 1e3,
        ball_diameter_m: args.ball_diameter_mm / 1e3,
        ..ScrewSpec::dkfzd4012().geometry
    };
    let fit = max_balls_per_circle(&geometry);
    let balls = args.balls_per_circle.unwrap_or_else(|| fit.saturating_sub(return_room).max(1));
    let arrangement_given = args.preload_arrangement.is_some();
    let nuts_why = if arrangement_given {
        format!("the nuts of a {} arrangement", arrangement.name())
    } else {
        "one nut without preload; a preloaded nut: --nuts or --preload-arrangement, and --preload-n".to_string()
    };
    let arrangement_why = if args.nuts.is_some() {
        format!("the usual arrangement of {nuts} nut{}", if nuts == 1 { "" } else { "s" })
    } else {
        "no preload (one nut)".to_string()
    };
    let mut t = String::new();
    t.push_str(
        "# Ball screw spec written by `ballscrew init` (units in the key names). `# given` marks a value\n\
         # from the command line, `# assumed:` one the screw maker's data should replace. Every key,\n\
         # its default and its range: docs/spec-reference.md. Check it: `ballscrew torque --spec FILE`.\n",
    );
    t.push_str("\n[geometry]\n");
    t.push_str(&line("pitch_diameter_mm", &real(args.pitch_diameter_mm), "given"));
    t.push_str(&line("lead_mm", &real(args.lead_mm), "given"));
    t.push_str(&line("ball_diameter_mm", &real(args.ball_diameter_mm), "given"));
    let groove = "the usual gothic-arch groove (Table 1's 0.52)";
    t.push_str(&line(
        "conformity_screw",
        &real(args.conformity_screw.unwrap_or(CONFORMITY)),
        &note(args.conformity_screw.is_some(), groove),
    ));
    t.push_str(&line(
        "conformity_nut",
        &real(args.conformity_nut.unwrap_or(CONFORMITY)),
        &note(args.conformity_nut.is_some(), groove),
    ));
    t.push_str(&line(
        "contact_angle_deg",
        &real(args.contact_angle_deg.unwrap_or(CONTACT_ANGLE_DEG)),
        &note(args.contact_angle_deg.is_some(), "the usual gothic-arch contact angle"),
    ));
    t.push_str(&line("nuts", &nuts.to_string(), &note(args.nuts.is_some(), &nuts_why)));
    let circles = args.circles_per_nut.unwrap_or(CIRCLES_PER_NUT);
    t.push_str(&line("preload", &format!("\"{}\"", arrangement.name()), &note(arrangement_given, &arrangement_why)));
    t.push_str(&line(
        "circles_per_nut",
        &circles.to_string(),
        &note(args.circles_per_nut.is_some(), "Table 1's nut; the catalog gives the circles (turns)"),
    ));
    t.push_str(&line(
        "balls_per_circle",
        &balls.to_string(),
        &note(
            args.balls_per_circle.is_some(),
            &format!("{fit} fit one turn, less {return_room} for the {} return", return_kind.name()),
        ),
    ));
    t.push_str("\n[material]\n");
    t.push_str(&line("youngs_modulus_gpa", "210.0", "assumed: bearing steel (Table 1)"));
    t.push_str(&line("poisson_ratio", "0.3", "assumed: bearing steel (Table 1)"));
    t.push_str("\n[friction]\n");
    t.push_str(&line(
        "coefficient",
        "0.03",
        "assumed: Table 1's; lubrication = \"dry\" reads it, \"ehl\" takes the oil's",
    ));
    t.push_str("\n# The point `ballscrew torque` evaluates by default; --speed-rpm, --preload-n and\n");
    t.push_str("# --axial-load-n override it.\n[operating]\n");
    t.push_str(&line("speed_rpm", "100.0", "assumed: Table 1's speed"));
    let preload_why = "a nut without preload takes none";
    t.push_str(&line("preload_n", &real(preload_n), &note(args.preload_n.is_some(), preload_why)));
    t.push_str(&line("axial_load_n", "0.0", "assumed: no external load"));
    t.push_str("\n[circulation]\n");
    t.push_str(&line(
        "return",
        &format!("\"{}\"", return_kind.name()),
        &note(args.return_kind.is_some(), "a deflector in the nut, the usual return"),
    ));
    if return_kind == ReturnKind::External {
        // The train of a circuit of several turns is solved for two-point balls only.
        let (turns, why) = if arrangement == Preload::OversizeBall {
            (1, "assumed: one loaded turn per circuit (several are not solved for oversize balls)")
        } else {
            (circles, "assumed: every circle of the nut in one circuit (a tube or end caps over the nut)")
        };
        t.push_str(&line("turns_per_circuit", &turns.to_string(), why));
    }
    if arrangement != Preload::OversizeBall {
        t.push_str(
            "# lead_deviation_um left out: assumed the nominal lead; ISO 3408-3 allows 23 um over\n\
             # 300 mm for class 5 (12 for class 3), about that share between the first and last circle\n\
             # load_ramp_balls left out: assumed no load ramp at the returns (the nut's drawing shows\n\
             # the raceway's relief at a deflector or tube)\n\
             # spacer_balls left out: assumed the load balls touch (no spacer balls between them)\n",
        );
    }
    t.push_str(
        "\n# [lubricant] left out: assumed ISO VG 68 mineral oil at 40 degrees C with ground raceways\n\
         # (the lubricated model's defaults); give the maker's oil and its temperature, e.g.\n\
         # [lubricant]\n\
         # iso_vg = 68.0\n\
         # temperature_c = 40.0\n",
    );
    Ok(t)
}

/// The spec for `args`, checked by the spec parser; refused naming the flag otherwise. An
/// existing regular file at `out` is refused without `--force`.
pub fn run(args: &InitArgs, out: Option<&Path>) -> Result<String, CliError> {
    if let Some(path) = out
        && !args.force
        && std::fs::metadata(path).is_ok_and(|m| m.is_file())
    {
        return Err(CliError::Input(format!("--out {}: the file exists (--force replaces it)", path.display())));
    }
    let text = spec_text(args)?;
    match spec_from_toml_str(&text, "ballscrew init") {
        Ok(_) => Ok(text),
        Err(ConfigError::Invalid { field, value, valid }) => Err(CliError::Input(format!(
            "invalid {}: {} (valid: {}; the spec's {field})",
            flag_of(&field),
            ballscrew_core::error::Measured { value, field: &field, valid: &valid },
            ballscrew_core::error::ValidRange(&valid)
        ))),
        Err(e) => Err(CliError::Input(format!("the spec does not read back: {e}"))),
    }
}
