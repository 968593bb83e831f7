//! `ballscrew sweep`: the torque over a range of one quantity, each point solved cold (its
//! canonical state, `ballscrew torque`'s numbers to the bit): the
//! preload (the default), the screw speed (`--speed-rpm A..B`), the axial load
//! (`--axial-load-n A..B`) or the oil temperature at the contacts (`--oil-temperature-c A..B`,
//! lubricated model only). The first column names the swept quantity; each row has the torque,
//! its drag and load parts, the catalog comparison (of the drag) and, under an axial load, the
//! forward and backdrive efficiency. With `--plot`, the torque against the swept quantity with
//! the catalog band ([`crate::plots::sweep`]).

use super::{Context, Format, FormatArg};
use crate::args::describe_point;
use crate::band::{self, BandArgs};
use crate::error::CliError;
use crate::output::{self, Named, Output, STDOUT};
use crate::plots;
use crate::progress::Bar;
use crate::report::{append_columns, cell, cells, csv, csv_line, horizontal_table_led, json_object, json_text, keys};
use crate::spec_and_flags::PointInput;
use crate::table::Cell;
use crate::table::format_short;
use ballscrew_batch::quantities::{BAND, EFFICIENCY, SWEEP, Swept};
use ballscrew_batch::sweep::{
    DEFAULT_SWEEP_FROM_N, DEFAULT_SWEEP_STEP_N, DEFAULT_SWEEP_TO_N, RangeText, RowError, SweepEnd, SweepFlags,
    SweepPoint, SweepRange, SweepRow, band_note, sweep,
};
use ballscrew_batch::uncertainty::{Band, BandError, BandSettings};
use ballscrew_batch::{BatchError, Errors, Never, threads_for};
use ballscrew_core::Model;
use ballscrew_core::input::{Lubrication, rad_s_to_rpm};
use ballscrew_core::screw::catalog::BAND_RELATIVE;
use clap::{Args, ValueEnum};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Default step of a speed sweep, rpm.
pub const DEFAULT_SPEED_STEP_RPM: f64 = 100.0;
/// Default step of an axial-load sweep, N.
pub const DEFAULT_AXIAL_LOAD_STEP_N: f64 = 500.0;
/// Default step of an oil-temperature sweep, degrees C.
pub const DEFAULT_OIL_TEMPERATURE_STEP_C: f64 = 5.0;

/// Flags of `ballscrew sweep`. One quantity is swept: the one given as a range `A..B`
/// (`--speed-rpm`, `--axial-load-n`, `--oil-temperature-c`), else the preload.
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    #[command(flatten)]
    pub output: FormatArg,
    /// Preload in N: a range `A..B` (both ends included) to sweep, or a single value
    /// [default: 500..3000, or the spec's when another quantity is swept]
    #[arg(long = "preload-n", visible_alias = "preload", value_name = "A..B", allow_hyphen_values = true)]
    pub preload: Option<RangeText>,
    /// Step of a preload sweep, N.
    #[arg(long = "preload-step-n", visible_aliases = ["step", "step-n"], value_name = "N", default_value_t = DEFAULT_SWEEP_STEP_N, allow_negative_numbers = true)]
    pub step: f64,
    /// Screw speed in rpm, negative for reverse rotation: a single value, or a range `A..B` to
    /// sweep the speed [default: the spec's]
    #[arg(long, value_name = "RPM|A..B", allow_hyphen_values = true)]
    pub speed_rpm: Option<RangeText>,
    /// Step of a speed sweep, rpm.
    #[arg(long, value_name = "RPM", default_value_t = DEFAULT_SPEED_STEP_RPM, allow_negative_numbers = true)]
    pub speed_step_rpm: f64,
    /// Oil temperature at the contacts (lubricant.temperature_c) in degrees C: a single value,
    /// or a range `A..B` to sweep it. Lubricated model only (lubrication = "ehl"): the dry model
    /// has no oil [default: the spec's]
    #[arg(long, value_name = "C|A..B", allow_hyphen_values = true)]
    pub oil_temperature_c: Option<RangeText>,
    /// Step of an oil-temperature sweep, degrees C.
    #[arg(long, value_name = "C", default_value_t = DEFAULT_OIL_TEMPERATURE_STEP_C, allow_negative_numbers = true)]
    pub oil_temperature_step_c: f64,
    /// External axial load on the nut in N: a single value, or a range `A..B` to sweep the
    /// axial load [default: the spec's]
    #[arg(long, value_name = "N|A..B", allow_hyphen_values = true)]
    pub axial_load_n: Option<RangeText>,
    /// Step of an axial-load sweep, N.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_AXIAL_LOAD_STEP_N, allow_negative_numbers = true)]
    pub axial_load_step_n: f64,
    /// Also draw the torque against the swept quantity to FILE as SVG (atomically): the spec's
    /// route with the catalog band shaded, the energy and moment routes as thinner lines, the
    /// drag and load torque under an axial load
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    /// With --plot, also draw Eq. 27 as printed in the paper (about ten times the model's torque:
    /// the y-axis then spans it)
    #[arg(long, requires = "plot")]
    pub plot_paper_eq27: bool,
    #[command(flatten)]
    pub band: BandArgs,
    /// What a point the model cannot evaluate does: `raise` stops the sweep with its error
    /// (exit 1); `nan` gives its row NaN (null in JSON, with its error) but for the operating
    /// point, computes the others and warns on stderr how many rows failed and why the first
    /// did (the plot and the band leave such rows out; CSV is then written at the end, not
    /// streamed)
    #[arg(long, value_enum, value_name = "raise|nan", default_value_t = OnError::Raise)]
    pub errors: OnError,
}

/// What a sweep does at a point the model cannot evaluate (`--errors`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OnError {
    /// Stop with the point's error.
    Raise,
    /// Give the point's row NaN and go on.
    Nan,
}

impl OnError {
    /// The batch's policy.
    fn errors(self) -> Errors {
        match self {
            OnError::Raise => Errors::Raise,
            OnError::Nan => Errors::Nan,
        }
    }
}

/// The file the flags name (`--plot`).
pub fn outputs(args: &SweepArgs) -> Named<'_> {
    Named { files: args.plot.iter().map(|p| ("--plot", p.as_path())).collect(), dirs: Vec::new() }
}

/// The summary of a row.
fn summary_of(r: &SweepRow) -> &ballscrew_core::Summary {
    &r.summary
}

/// The efficiency of a row.
fn efficiency_of(r: &SweepRow) -> &Option<ballscrew_core::Efficiency> {
    &r.efficiency
}

/// Runs the sweep and renders it (and its figure with `--plot`). CSV for stdout (`out` none or
/// `-`) with no figure is streamed: the rows written as they are computed, a block of
/// `SWEEP_BLOCK_POINTS` at a time (a table's
/// columns are as wide as their widest value of all rows, JSON is one object, and a run with a
/// file writes every output at its end, all or none).
pub fn run(ctx: &Context, args: &SweepArgs, out: Option<&Path>) -> Result<Output, CliError> {
    let settings = args.band.settings()?;
    let stream = ctx.format == Format::Csv
        && args.errors == OnError::Raise
        && args.plot.is_none()
        && settings.is_none()
        && out.is_none_or(|p| p == Path::new(STDOUT));
    let mut written = Ok(());
    let mut on_row = |swept: Swept, i: usize, row: &SweepRow| {
        if stream && written.is_ok() {
            let head = if i == 0 { csv_header(ctx, swept).join(",") + "\n" } else { String::new() };
            written = output::stream_stdout(&(head + &csv_line(&csv_cells(ctx, swept, row))));
        }
    };
    let (swept, rows, failures, bands) = evaluate(ctx, args, settings.as_ref(), &mut on_row)?;
    written?;
    ctx.warn_inertia(rows.iter().zip(&failures).filter(|(_, f)| f.is_none()).map(|(r, _)| r.summary.operating));
    let failed: Vec<bool> = failures.iter().map(Option::is_some).collect();
    let band = settings.as_ref().map(|s| (s, bands.as_slice()));
    // The plot of the computed rows (and their bands).
    let kept: Vec<SweepRow> = rows.iter().zip(&failed).filter(|(_, f)| !**f).map(|(r, _)| *r).collect();
    let kept_bands: Vec<Band> = bands.iter().zip(&failed).filter(|(_, f)| !**f).map(|(b, _)| *b).collect();
    if args.plot.is_some() && kept.is_empty() && !rows.is_empty() {
        return Err(CliError::Eval(format!(
            "--plot: no row of the sweep could be evaluated (--errors nan gave all {} rows NaN): nothing to plot",
            rows.len()
        )));
    }
    let plot = match (&args.plot, kept.first()) {
        (Some(path), Some(first)) => {
            let title = ctx.title("sweep", &fixed(ctx, swept, first));
            let mut lines = vec![title.trim_end().to_string(), band_note(&kept, swept.values())];
            let left: Vec<String> = rows
                .iter()
                .zip(&failed)
                .filter(|(_, f)| **f)
                .map(|(r, _)| format_short(swept_value(swept, r)))
                .collect();
            if !left.is_empty() {
                lines.push(format!(
                    "not evaluated, left out (the lines join across them): {} {} {}",
                    swept.quantity().label,
                    left.join(", "),
                    swept.quantity().unit
                ));
            }
            let model_band = settings
                .as_ref()
                .map(|s| (format!("model's band of the drag torque, {}", band::describe(s)), kept_bands.as_slice()));
            Some((path.clone(), plots::sweep::svg(&lines, swept.quantity(), &kept, args.plot_paper_eq27, model_band)?))
        }
        _ => None,
    };
    let rendered = Rendered { swept, rows: &rows, kept: &kept, failures: &failures, band };
    Ok(Output::with_plot((!stream).then(|| text(ctx, &rendered)), plot))
}

/// The sweep point a band's error is at (its index among the points the band ran over), where
/// it is one point's.
fn at_point(e: &BandError) -> Option<usize> {
    match e {
        BandError::Sample { point, .. } | BandError::End { point, .. } | BandError::Nominal { point, .. } => {
            Some(*point)
        }
        _ => None,
    }
}

/// The swept quantity's value of row `r`.
fn swept_value(swept: Swept, r: &SweepRow) -> f64 {
    match cell(swept.quantity(), r) {
        Cell::Num(x) => x,
        Cell::Int(n) => n as f64,
        Cell::Text(_) => f64::NAN,
    }
}

/// What [`evaluate`] gives: the swept quantity, each row, each row's error where it failed
/// (`--errors nan`), each row's band (`--band`).
type Evaluated = (Swept, Vec<SweepRow>, Vec<Option<String>>, Vec<Band>);

/// A sweep's rows to render: the swept quantity, each row (a failed one holding only its
/// operating point, [`SweepRow::failed`]), each row's error where it failed (`--errors nan`),
/// and the bands (`--band`; a failed row's NaN).
struct Rendered<'a> {
    swept: Swept,
    rows: &'a [SweepRow],
    /// The rows that were evaluated.
    kept: &'a [SweepRow],
    failures: &'a [Option<String>],
    band: Bands<'a>,
}

impl Rendered<'_> {
    /// Whether row `i` failed.
    fn failed(&self, i: usize) -> bool {
        self.failures.get(i).is_some_and(Option::is_some)
    }
}

/// A row's cells from `from` on (its computed columns) made `blank` where the row failed.
fn blank_failed(cells: &mut [Cell], from: usize, failed: bool, blank: &Cell) {
    if failed {
        for c in cells.iter_mut().skip(from) {
            *c = blank.clone();
        }
    }
}

/// The CSV header: the swept quantity, the ones held fixed, the torques, the efficiency.
fn csv_header(ctx: &Context, swept: Swept) -> Vec<&'static str> {
    let held = swept.held(ctx.spec.model.lubrication);
    [vec![swept.quantity().key], held.iter().map(|q| q.key).collect(), keys(SWEEP), keys(EFFICIENCY)].concat()
}

/// A row's CSV cells, in the order of [`csv_header`].
fn csv_cells(ctx: &Context, swept: Swept, r: &SweepRow) -> Vec<Cell> {
    let mut line = vec![cell(swept.quantity(), r)];
    line.extend(swept.held(ctx.spec.model.lubrication).iter().map(|q| cell(q, r)));
    line.extend(cells(SWEEP, &r.summary));
    line.extend(cells(EFFICIENCY, &r.efficiency));
    line
}

/// The band of each row, with how it was sampled (`--band`).
type Bands<'a> = Option<(&'a BandSettings, &'a [Band])>;

/// The sweep in the format asked for, with the band's columns after the others (`--band`).
fn text(ctx: &Context, r: &Rendered<'_>) -> String {
    match ctx.format {
        Format::Table => table(ctx, r),
        Format::Csv => {
            let swept = r.swept;
            let mut header = csv_header(ctx, swept);
            let from = 1 + swept.held(ctx.spec.model.lubrication).len();
            let mut lines: Vec<_> = r.rows.iter().map(|row| csv_cells(ctx, swept, row)).collect();
            if let Some((_, bands)) = r.band {
                header.extend(keys(BAND));
                for (line, b) in lines.iter_mut().zip(bands) {
                    line.extend(cells(BAND, b));
                }
            }
            for (i, line) in lines.iter_mut().enumerate() {
                blank_failed(line, from, r.failed(i), &Cell::Num(f64::NAN));
            }
            csv(&header, &lines)
        }
        Format::Json => json(ctx, r),
    }
}

/// Whether a flag's text is a range to sweep.
fn is_range(text: &Option<RangeText>) -> bool {
    text.as_ref().is_some_and(RangeText::is_range)
}

/// A single value of a flag (`None`: not given), or an error when it is not a finite number.
fn single(flag: &str, text: &Option<RangeText>, valid: &str) -> Result<Option<f64>, CliError> {
    Ok(text.as_ref().map(|t| t.ends(flag, true, |a, b| a == b, valid).map(|(a, _)| a)).transpose()?)
}

/// The points of a swept flag's range `text` in steps of `step`, checked (see
/// [`SweepRange::from_flags`]).
fn points(text: &RangeText, step: f64, flags: &SweepFlags<'_>) -> Result<Vec<f64>, CliError> {
    Ok(SweepRange::from_flags(text, step, flags)?.points())
}

/// Which quantity is swept, and over which values; every point validated, then each solved
/// cold over the threads by the sweep Python runs too ([`sweep`]), `on_row` called with each
/// row (and its index) in order as its block is done; a progress bar on stderr meanwhile
/// ([`Bar`]).
fn evaluate(
    ctx: &Context,
    args: &SweepArgs,
    settings: Option<&BandSettings>,
    on_row: &mut dyn FnMut(Swept, usize, &SweepRow),
) -> Result<Evaluated, CliError> {
    let ranges: Vec<&str> = [
        ("--preload-n", &args.preload),
        ("--speed-rpm", &args.speed_rpm),
        ("--axial-load-n", &args.axial_load_n),
        ("--oil-temperature-c", &args.oil_temperature_c),
    ]
    .iter()
    .filter(|(_, t)| is_range(t))
    .map(|(f, _)| *f)
    .collect();
    if ranges.len() > 1 {
        return Err(CliError::Input(format!(
            "one quantity at a time: {} are all ranges (give the others a single value)",
            ranges.join(" and ")
        )));
    }
    if args.oil_temperature_c.is_some() && ctx.spec.model.lubrication == Lubrication::Dry {
        return Err(CliError::Input(
            "--oil-temperature-c needs the lubricated model: the spec has lubrication = \"dry\", which has no oil \
             (set [model] lubrication = \"ehl\")"
                .to_string(),
        ));
    }
    let swept = if is_range(&args.speed_rpm) {
        Swept::Speed
    } else if is_range(&args.axial_load_n) {
        Swept::AxialLoad
    } else if is_range(&args.oil_temperature_c) {
        Swept::OilTemperature
    } else {
        Swept::Preload
    };
    let speed = single("--speed-rpm", &args.speed_rpm, "a number in rpm, or A..B with A <= B");
    let temperature =
        single("--oil-temperature-c", &args.oil_temperature_c, "a number in degrees C, or A..B with A <= B");
    let preload = single("--preload-n", &args.preload, "A..B with A <= B, or a single value, in N");
    let axial = single("--axial-load-n", &args.axial_load_n, "a number in N, or A..B with A <= B");
    let (values, speed, preload, axial, temperature) = match swept {
        Swept::Preload => {
            let default = || RangeText::from(format!("{DEFAULT_SWEEP_FROM_N}..{DEFAULT_SWEEP_TO_N}"));
            let text = args.preload.clone().unwrap_or_else(default);
            (points(&text, args.step, &Swept::Preload.flags())?, speed?, None, axial?, temperature?)
        }
        Swept::Speed => {
            let text = args.speed_rpm.clone().unwrap_or_default();
            let v = points(&text, args.speed_step_rpm, &Swept::Speed.flags())?;
            (v, None, preload?, axial?, temperature?)
        }
        Swept::AxialLoad => {
            let text = args.axial_load_n.clone().unwrap_or_default();
            let v = points(&text, args.axial_load_step_n, &Swept::AxialLoad.flags())?;
            (v, speed?, preload?, None, temperature?)
        }
        Swept::OilTemperature => {
            let text = args.oil_temperature_c.clone().unwrap_or_default();
            let v = points(&text, args.oil_temperature_step_c, &Swept::OilTemperature.flags())?;
            (v, speed?, preload?, axial?, None)
        }
    };
    // Each point: its operating point and, when the oil temperature is set, its own model.
    let mut ops = Vec::with_capacity(values.len());
    let mut models = Vec::with_capacity(values.len());
    for &x in &values {
        let input = PointInput {
            speed_rpm: if swept == Swept::Speed { Some(x) } else { speed },
            preload_n: if swept == Swept::Preload { Some(x) } else { preload },
            axial_load_n: if swept == Swept::AxialLoad { Some(x) } else { axial },
            preload_flag: "--preload-n",
        };
        ops.push(ctx.operating_point(&input)?);
        let t = if swept == Swept::OilTemperature { Some(x) } else { temperature };
        models.push(match t {
            Some(t) => Some(model_at(ctx, t)?),
            None => None,
        });
    }
    let points: Vec<SweepPoint<'_>> =
        ops.iter().zip(&models).map(|(&op, m)| SweepPoint { op, model: m.as_ref().unwrap_or(&ctx.model) }).collect();
    let bar = Bar::new("sweep", points.len());
    let context =
        |i: usize| format!("at {} {} {}", swept.quantity().label, format_short(values[i]), swept.quantity().unit);
    let results = sweep(&points, threads_for(points.len()), &Never, args.errors.errors(), &mut |i, row| {
        bar.suspend(|| on_row(swept, i, row));
        bar.step();
    })
    .map_err(|end| match end {
        SweepEnd::Point { index, error: RowError::Summary(e) } => CliError::eval(&context(index), &e),
        SweepEnd::Point { index, error: RowError::Efficiency(e) } => {
            CliError::eval(&format!("efficiency {}", context(index)), &e)
        }
        SweepEnd::Stopped => CliError::Eval("the sweep was stopped".to_string()),
        SweepEnd::OutOfMemory { bytes } => CliError::Eval(format!("sweep: {}", BatchError::OutOfMemory { bytes })),
        SweepEnd::Internal(m) => CliError::Eval(format!("sweep: {m}")),
    })?;
    // Under `--errors nan` a failed point's row holds its operating point, and its error is
    // kept (said once on stderr: how many, and the first).
    let mut rows = Vec::with_capacity(results.len());
    let mut failures = Vec::with_capacity(results.len());
    for (i, r) in results.into_iter().enumerate() {
        match r {
            Ok(row) => {
                rows.push(row);
                failures.push(None);
            }
            Err(e) => {
                rows.push(SweepRow::failed(&points[i]));
                failures.push(Some(e.error().to_string()));
            }
        }
    }
    // The band of each computed point (`--band`): each point's own, whatever the others.
    let kept: Vec<usize> = (0..rows.len()).filter(|&i| failures[i].is_none()).collect();
    let kept_points: Vec<SweepPoint<'_>> = kept.iter().map(|&i| points[i]).collect();
    let mut band_failures: Vec<(usize, String)> = Vec::new();
    let bands = match settings {
        // Under `--errors nan` each point's band alone: one that cannot be evaluated is NaN.
        Some(s) if args.errors == OnError::Nan => {
            let bar = Bar::new("band", ballscrew_batch::uncertainty::band_steps(&kept_points, s));
            let mut all = vec![Band::at(f64::NAN); rows.len()];
            for &i in &kept {
                match ballscrew_batch::uncertainty::band(&band::batch(s).stop(&bar), &points[i..=i], s) {
                    Ok(b) => all[i] = b[0],
                    Err(e) => match at_point(&e).map(|_| i) {
                        Some(i) => {
                            band_failures.push((i, band::error(&format!("band {}", context(i)), &e).to_string()))
                        }
                        None => return Err(band::error("band", &e)),
                    },
                }
            }
            all
        }
        Some(s) => {
            let bar = Bar::new("band", ballscrew_batch::uncertainty::band_steps(&kept_points, s));
            ballscrew_batch::uncertainty::band(&band::batch(s).stop(&bar), &kept_points, s)
                .map_err(|e| {
                    let at = at_point(&e).map(|k| context(kept[k])).unwrap_or_default();
                    band::error(format!("band {at}").trim_end(), &e)
                })
                .map(|computed| {
                    let mut all = vec![Band::at(f64::NAN); rows.len()];
                    for (&i, b) in kept.iter().zip(computed) {
                        all[i] = b;
                    }
                    all
                })?
        }
        None => Vec::new(),
    };
    let failed: Vec<usize> = (0..failures.len()).filter(|&i| failures[i].is_some()).collect();
    if let Some(&first) = failed.first() {
        let why = failures[first].as_deref().unwrap_or_default();
        eprintln!(
            "warning: {} of {} rows could not be evaluated and are NaN (--errors nan); the first, {}: {why}",
            failed.len(),
            rows.len(),
            context(first)
        );
    }
    if let Some((_, why)) = band_failures.first() {
        eprintln!(
            "warning: the band of {} of {} rows could not be evaluated and is NaN (--errors nan); the first: {why}",
            band_failures.len(),
            rows.len()
        );
    }
    Ok((swept, rows, failures, bands))
}

/// The spec's model with the oil at `temperature_c` at the contacts
/// ([`Context::model_at_oil_temperature`]).
fn model_at(ctx: &Context, temperature_c: f64) -> Result<Model, CliError> {
    ctx.model_at_oil_temperature(temperature_c)
}

/// What the sweep holds fixed, in words.
fn fixed(ctx: &Context, swept: Swept, first: &SweepRow) -> String {
    let op = first.summary.operating;
    let speed = (swept != Swept::Speed).then(|| rad_s_to_rpm(op.speed_rad_s));
    let preload = (swept != Swept::Preload).then_some(op.preload_n);
    let axial = (swept != Swept::AxialLoad).then_some(op.axial_load_n);
    let mut text = describe_point(speed, preload, axial);
    if swept != Swept::OilTemperature && ctx.spec.model.lubrication == Lubrication::Ehl {
        text.push_str(&format!(", oil {} C", format_short(first.oil_temperature_c)));
    }
    text
}

fn table(ctx: &Context, r: &Rendered<'_>) -> String {
    let (swept, rows, band) = (r.swept, r.rows, r.band);
    let Some(first) = rows.first() else { return String::new() };
    let mut out = ctx.title("sweep", &fixed(ctx, swept, first));
    out.push('\n');
    let mut t = horizontal_table_led(swept.quantity(), SWEEP, rows, summary_of);
    append_columns(&mut t, EFFICIENCY, rows, efficiency_of);
    if let Some((_, bands)) = band {
        append_columns(&mut t, BAND, bands, |b| b);
    }
    for (i, line) in t.rows.iter_mut().enumerate() {
        blank_failed(line, 1, r.failed(i), &Cell::Text("failed".to_string()));
    }
    out.push_str(&t.render(0));
    out.push('\n');
    if r.kept.is_empty() {
        out.push_str("No row was evaluated (--errors nan): nothing to compare with the catalog band.");
    } else {
        out.push_str(&band_note(r.kept, swept.values()));
    }
    out.push('\n');
    if let Some((s, _)) = band {
        out.push_str(&format!(
            "Band of the drag torque ({}): from the spread of the spec's [uncertainty]; `ballscrew sensitivity` ranks its inputs.\n",
            band::describe(s)
        ));
    }
    out
}

fn json(ctx: &Context, r: &Rendered<'_>) -> String {
    let (swept, rows, band) = (r.swept, r.rows, r.band);
    let mut head = ctx.json_head("sweep");
    head.insert("swept".into(), swept.quantity().key.into());
    if let Some(first) = rows.first() {
        let op = first.summary.operating;
        if swept != Swept::Speed {
            head.insert("speed_rpm".into(), rad_s_to_rpm(op.speed_rad_s).into());
        }
        if swept != Swept::Preload {
            head.insert("preload_n".into(), op.preload_n.into());
        }
        if swept != Swept::AxialLoad {
            head.insert("axial_load_n".into(), op.axial_load_n.into());
        }
        if swept != Swept::OilTemperature && ctx.spec.model.lubrication == Lubrication::Ehl {
            head.insert("oil_temperature_c".into(), first.oil_temperature_c.into());
        }
    }
    head.insert("catalog_band_relative".into(), BAND_RELATIVE.into());
    if let Some((s, _)) = band {
        head.insert("band".into(), band::json(s));
    }
    let lead = swept.quantity();
    let list: Vec<Value> = rows
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut o = json_object(core::slice::from_ref(lead), row);
            for q in swept.held(ctx.spec.model.lubrication) {
                o.extend(json_object(core::slice::from_ref(q), row));
            }
            let mut computed = json_object(SWEEP, &row.summary);
            computed.extend(json_object(EFFICIENCY, &row.efficiency));
            if let Some(b) = band.and_then(|(_, bands)| bands.get(i)) {
                computed.extend(json_object(BAND, b));
            }
            match r.failures.get(i).and_then(Option::as_ref) {
                Some(error) => {
                    o.extend(computed.into_iter().map(|(k, _)| (k, Value::Null)));
                    o.insert("error".into(), error.as_str().into());
                }
                None => o.extend(computed),
            }
            Value::Object(o)
        })
        .collect();
    head.insert("rows".into(), Value::Array(list));
    json_text(&Value::Object(head))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The preloads of `text` in steps of `step`, as `ballscrew sweep --preload-n` takes them.
    fn preload_points(text: &str, step: f64) -> Result<Vec<f64>, CliError> {
        points(&RangeText::from(text.to_string()), step, &Swept::Preload.flags())
    }

    #[test]
    fn bad_ranges_are_input_errors() {
        for (r, step, flag) in [
            ("3000..500", 100.0, "--preload-n"),
            ("abc", 100.0, "--preload-n"),
            ("1..nan", 100.0, "--preload-n"),
            ("500..3000", 0.0, "--preload-step-n"),
            ("500..3000", -5.0, "--preload-step-n"),
            ("500..3000", f64::NAN, "--preload-step-n"),
        ] {
            let e = preload_points(r, step).unwrap_err();
            assert_eq!(e.exit_code(), 2);
            assert!(e.to_string().starts_with(&format!("invalid {flag}: ")), "{e}");
        }
        assert!(preload_points("0..1e7", 1e-3).is_err());
    }

    #[test]
    fn the_default_sweep_is_the_default_preloads() {
        let text = RangeText::from(format!("{DEFAULT_SWEEP_FROM_N}..{DEFAULT_SWEEP_TO_N}"));
        let p = points(&text, DEFAULT_SWEEP_STEP_N, &Swept::Preload.flags()).unwrap();
        assert_eq!(p, ballscrew_batch::sweep::default_sweep_preloads_n());
        assert_eq!(preload_points("0..250", 100.0).unwrap(), [0.0, 100.0, 200.0, 250.0]);
    }
}
