//! `ballscrew contact`: one contact by FASTSIM (Kalker's simplified theory,
//! [`ballscrew_core::contact::fastsim`]) from its creepages, or from a screw operating point and a contact
//! name: the creep forces, the spin moment, the adhesion share and, with `--plot`, the traction
//! field over the contact ellipse (Fig. 10 of the paper). The model's own law, Kalker's linear
//! theory saturated by Eq. (24), is reported alongside for comparison. The contact and both laws
//! are the core's ([`ballscrew_core::contact::analysis`]); the contact's flags are shared with
//! `ballscrew creep-curves` ([`ContactArgs`]).
//!
//! The friction coefficient mu (the bound of both laws) is the model contact's own when the
//! contact comes from a screw point: under `lubrication = "ehl"` the mixed-film coefficient the
//! model found for that contact, under `"dry"` `friction.coefficient`. A contact given by the
//! flags alone has no film, and takes `friction.coefficient` (or `--friction`); the output names
//! the coefficient's source.

use super::{Context, Format, FormatArg};
use crate::args::{Bound, ContactArgs, ContactSetup, finite, resolve};
use crate::error::CliError;
use crate::output::{Named, Output};
use crate::plots;
use crate::report::{Quantity, cells, csv, json_object, json_text, keys, vertical_table};
use crate::spec_and_flags::checked;
use ballscrew_batch::quantities::{CONTACT_DATA, CREEPAGES, EQ24_EXTRA, FASTSIM_EXTRA, FORCES};
use ballscrew_core::Error;
use ballscrew_core::contact::analysis::{ContactRun, Creep};
use ballscrew_core::contact::fastsim::Element;
use ballscrew_core::contact::limits::CREEPAGE;
use clap::Args;
use serde_json::Value;
use std::path::PathBuf;

/// Creepage flags of `ballscrew contact`. Given any of them, the others are 0 and the contact's
/// own creepages are not used.
#[derive(Debug, Clone, Args)]
pub struct CreepArgs {
    /// Longitudinal creepage xi on the centre line y = 0 (the Heathcote term adds k_h y^2)
    /// [default: 0, or the contact's without creepage flags]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub xi: Option<f64>,
    /// Lateral creepage eta [default: 0, or the contact's]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub eta: Option<f64>,
    /// Spin creepage phi, 1/mm [default: 0, or the contact's]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub phi_per_mm: Option<f64>,
    /// Heathcote coefficient k_h, 1/mm^2: longitudinal creepage k_h y^2 at the lateral coordinate
    /// y, mean k_h b^2/5 over the ellipse [default: 0, or the contact's]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub heathcote_per_mm2: Option<f64>,
}

/// Flags of `ballscrew contact`.
#[derive(Debug, Clone, Args)]
pub struct ContactCmdArgs {
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub target: ContactArgs,
    #[command(flatten)]
    pub creep: CreepArgs,
    /// FASTSIM's traction bound
    #[arg(long, value_enum, default_value_t = Bound::Parabolic)]
    pub bound: Bound,
    /// Also draw the traction field over the ellipse (Fig. 10: arrows where the ball slips, the
    /// adhesion area shaded) to FILE as SVG (atomically)
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// The creepages of the flags, in SI units (`None` when no creepage flag is given), validated.
fn creep_of_flags(args: &CreepArgs) -> Result<Option<Creep>, CliError> {
    let flags = [
        ("--xi", args.xi, 1.0),
        ("--eta", args.eta, 1.0),
        ("--phi-per-mm", args.phi_per_mm, 1e3),
        ("--heathcote-per-mm2", args.heathcote_per_mm2, 1e6),
    ];
    if flags.iter().all(|(_, v, _)| v.is_none()) {
        return Ok(None);
    }
    let mut si = [0.0; 4];
    for (out, (flag, value, to_si)) in si.iter_mut().zip(flags) {
        let v = value.unwrap_or(0.0);
        checked(flag, v, CREEPAGE.contains(v), CREEPAGE.valid)?;
        *out = v * to_si;
    }
    Ok(Some(Creep { xi: si[0], eta: si[1], phi_per_m: si[2], heathcote_per_m2: si[3] }))
}

/// The file the flags name (`--plot`).
pub fn outputs(args: &ContactCmdArgs) -> Named<'_> {
    Named { files: args.plot.iter().map(|p| ("--plot", p.as_path())).collect(), dirs: Vec::new() }
}

/// Runs `ballscrew contact` and renders it.
pub fn run(ctx: &Context, args: &ContactCmdArgs) -> Result<Output, CliError> {
    let flags = creep_of_flags(&args.creep)?;
    let setup = resolve(&ctx.spec, &ctx.model, &args.target, flags.is_none())?;
    let creep = flags.or(setup.screw.map(|s| s.creep)).unwrap_or_default();
    let mut elements = vec![Element::default(); setup.grid * setup.grid];
    let run = ContactRun::new(setup.contact, creep, &setup.law, args.bound.traction(), setup.grid, Some(&mut elements))
        .map_err(|e| CliError::eval("contact", &Error::Input(e)))?;
    finite(&run.fastsim.forces, "FASTSIM")?;
    finite(&run.law.forces, "Eq. 24")?;
    let text = match ctx.format {
        Format::Table => table(ctx, &setup, &run),
        Format::Csv => csv_text(&run),
        Format::Json => json(ctx, &setup, &run),
    };
    let plot = match &args.plot {
        Some(path) => Some((path.clone(), plots::contact::svg(&run, &setup.source, &elements)?)),
        None => None,
    };
    Ok(Output::with_plot(Some(text), plot))
}

/// FASTSIM against Eq. 24, one column each.
const LAW_HEADS: [&str; 2] = ["FASTSIM", "Eq. 24"];

fn table(ctx: &Context, setup: &ContactSetup, run: &ContactRun) -> String {
    let mut out = format!(
        "ballscrew contact: {}; {}\nfriction coefficient mu: {}\n",
        ctx.origin, setup.source, setup.friction_source
    );
    let section = |out: &mut String, title: &str, body: String| {
        out.push('\n');
        out.push_str(title);
        out.push('\n');
        out.push_str(&body);
    };
    section(
        &mut out,
        "contact",
        vertical_table(CONTACT_DATA, core::slice::from_ref(&run.contact), &["value"]).render(2),
    );
    section(
        &mut out,
        "creepages of the ball over the raceway",
        vertical_table(CREEPAGES, core::slice::from_ref(run), &["value"]).render(2),
    );
    section(
        &mut out,
        "forces on the ball (contact frame: e rolling, f lateral)",
        vertical_table(FORCES, &[run.fastsim.forces, run.law.forces], &LAW_HEADS).render(2),
    );
    section(
        &mut out,
        "FASTSIM (Kalker's simplified theory), strips grid",
        vertical_table(FASTSIM_EXTRA, core::slice::from_ref(run), &["value"]).render(2),
    );
    section(
        &mut out,
        "Eq. 24 (Kalker's linear theory, saturated; the model's law)",
        vertical_table(EQ24_EXTRA, core::slice::from_ref(run), &["value"]).render(2),
    );
    out
}

/// `prefix` + each key.
fn prefixed<T>(prefix: &str, quantities: &[Quantity<T>]) -> Vec<String> {
    keys(quantities).iter().map(|k| format!("{prefix}{k}")).collect()
}

/// One row: contact, creepages, FASTSIM (`fastsim_*`), Eq. 24 (`eq24_*`).
fn csv_text(run: &ContactRun) -> String {
    let header: Vec<String> = [
        prefixed("", CONTACT_DATA),
        prefixed("", CREEPAGES),
        prefixed("fastsim_", FORCES),
        prefixed("fastsim_", FASTSIM_EXTRA),
        prefixed("eq24_", FORCES),
        prefixed("eq24_", EQ24_EXTRA),
    ]
    .concat();
    let row = [
        cells(CONTACT_DATA, &run.contact),
        cells(CREEPAGES, run),
        cells(FORCES, &run.fastsim.forces),
        cells(FASTSIM_EXTRA, run),
        cells(FORCES, &run.law.forces),
        cells(EQ24_EXTRA, run),
    ]
    .concat();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    csv(&header, &[row])
}

fn json(ctx: &Context, setup: &ContactSetup, run: &ContactRun) -> String {
    let mut head = ctx.json_head("contact");
    head.insert("source".into(), setup.source.as_str().into());
    head.insert("screw".into(), setup.screw_json());
    head.insert("friction_source".into(), setup.friction_source.as_str().into());
    head.insert("contact".into(), Value::Object(json_object(CONTACT_DATA, &run.contact)));
    head.insert("creepages".into(), Value::Object(json_object(CREEPAGES, run)));
    let mut f = json_object(FORCES, &run.fastsim.forces);
    f.extend(json_object(FASTSIM_EXTRA, run));
    head.insert("fastsim".into(), Value::Object(f));
    let mut l = json_object(FORCES, &run.law.forces);
    l.extend(json_object(EQ24_EXTRA, run));
    head.insert("eq24".into(), Value::Object(l));
    json_text(&Value::Object(head))
}
