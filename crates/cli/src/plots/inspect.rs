//! The figure of `ballscrew inspect --plot FILE.svg`: one group of bars per circle (per nut, in
//! order), a bar per contact of its ball: (a) the normal load Q of the contact, N; (b) the
//! contact's share of the drive torque over all balls of the circle, N m; (c) the chain force
//! along the ball train, N: over each circle, from the contact behind its first ball to the one
//! ahead of its last, in the direction the balls travel (a line per nut).

use crate::error::CliError;
use crate::plots::figure::{
    Area, Chart, FONT, GREY, GRID_BOLD, legend, legend_size, page, plot_error, tick, with_legend,
};
use ballscrew_core::{BallReport, ContactKind, ContactReport, Evaluation};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const SIZE: (u32, u32) = (1300, 1450);
const HEADER: u32 = 90;
/// Most circles labelled in full (`nut 1, circle 2`); more are labelled `1.2` (nut.circle).
const FULL_LABELS: usize = 10;

/// The colour of a nut's chain force (panel c), by nut index.
pub fn nut_colour(nut: usize) -> RGBColor {
    if nut == 0 { RGBColor(148, 103, 189) } else { RGBColor(214, 39, 40) }
}

/// The colour of a contact's bars.
pub fn colour(kind: ContactKind) -> RGBColor {
    match kind {
        ContactKind::Nut => RGBColor(31, 119, 180),
        ContactKind::Screw => RGBColor(255, 127, 14),
        ContactKind::BallBall => RGBColor(44, 160, 44),
    }
}

/// The balls of the evaluation (one per nut and circle), in order.
fn balls(ev: &Evaluation) -> Vec<&BallReport> {
    ev.balls.iter().take(ev.nuts).flat_map(|nut| nut.iter().take(ev.circles)).collect()
}

/// The figure; `title` says what was run.
pub fn svg(title: &str, ev: &Evaluation) -> Result<String, CliError> {
    let balls = balls(ev);
    let full = balls.len() <= FULL_LABELS;
    let names: Vec<String> = balls
        .iter()
        .map(|b| {
            if full {
                format!("{}, circle {}", ev.preload.group_label(b.nut), b.circle + 1)
            } else {
                format!("{}.{}", b.nut + 1, b.circle + 1)
            }
        })
        .collect();
    let x_desc = if full { "circle (one ball stands for each)" } else { "circle, as nut.circle" };
    let lines = [
        title.to_string(),
        "a bar per contact of the circle's ball: (a) its normal load; (b) its share of the drive torque over the \
         circle's balls; (c) the chain force between the balls along each circle, in the direction they travel"
            .to_string(),
    ];
    let forwards = ev.summary.operating.speed_rad_s >= 0.0;
    page(SIZE, HEADER, &lines, |_, body| {
        let panels = body.split_evenly((3, 1));
        bars(&panels[0], "(a) Normal load of each contact", "normal load Q, N", &balls, &names, x_desc, |c| {
            c.normal_load_n
        })?;
        bars(
            &panels[1],
            "(b) Torque share of each contact (all balls of the circle)",
            "torque share, N m",
            &balls,
            &names,
            x_desc,
            |c| c.torque_share_nm,
        )?;
        chain(&panels[2], ev, &balls, &names, x_desc, forwards)
    })
}

/// A circle's line of chain force: its nut, and the points it runs from and to.
type Line = (usize, (f64, f64), (f64, f64));

/// Panel (c): the chain force over each circle, a straight line (every ball of the circle
/// pushed alike) from the contact behind its first ball to the one ahead of its last, drawn in
/// the direction its balls travel: from the circle's left edge to its right where the balls go
/// from a nut's first circle to its last (flank +1 turning forwards, flank -1 backwards), the
/// other way otherwise. A line per nut; zero where the train's gap is.
fn chain(
    area: &Area<'_>,
    ev: &Evaluation,
    balls: &[&BallReport],
    names: &[String],
    x_desc: &str,
    forwards: bool,
) -> Result<(), CliError> {
    // (nut, from, to) of each circle's line.
    let lines: Vec<Line> = balls
        .iter()
        .enumerate()
        .map(|(g, b)| {
            let (left, right) = (g as f64 + 0.05, g as f64 + 0.95);
            let ascending = forwards == (b.flank > 0.0);
            let (start, end) = if ascending { (left, right) } else { (right, left) };
            (b.nut, (start, b.chain_in_n), (end, b.chain_out_n))
        })
        .collect();
    let hi = lines.iter().flat_map(|l| [l.1.1, l.2.1]).filter(|v| v.is_finite()).fold(0.0_f64, f64::max);
    let (y0, y1) = (0.0, if hi > 0.0 { 1.05 * hi } else { 1.0 });
    let x1 = balls.len().max(1) as f64;
    let nuts: Vec<usize> = (0..ev.nuts).collect();
    let labels: Vec<String> = nuts.iter().map(|&n| ev.preload.group_label(n).to_string()).collect();
    let size = legend_size(&labels.iter().map(String::as_str).collect::<Vec<_>>())?;
    let points: Vec<(f64, f64)> = lines.iter().flat_map(|l| [l.1, l.2]).collect();
    let caption = "(c) Chain force between the balls along each circle, in the direction they travel";
    let panel = Panel { caption, x_desc, y_desc: "chain force, N", circles: x1, span: (y0, y1) };
    let (mut chart, corner) = panel_chart(area, &panel, size, &points)?;
    for (&nut, label) in nuts.iter().zip(&labels) {
        let c = nut_colour(nut);
        let mut first = true;
        for l in lines.iter().filter(|l| l.0 == nut && l.1.1.is_finite() && l.2.1.is_finite()) {
            let series = chart.draw_series(LineSeries::new([l.1, l.2], c.stroke_width(3))).map_err(plot_error)?;
            if first {
                series
                    .label(label.as_str())
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], c.stroke_width(3)));
                first = false;
            }
        }
    }
    name_groups(area, &chart, names, y0)?;
    legend(&mut chart, corner)
}

/// One panel of bars: `value` of each contact of each ball.
fn bars(
    area: &Area<'_>,
    caption: &str,
    y_desc: &str,
    balls: &[&BallReport],
    names: &[String],
    x_desc: &str,
    value: fn(&ContactReport) -> f64,
) -> Result<(), CliError> {
    let kinds: Vec<ContactKind> =
        balls.first().map(|b| b.contacts.iter().map(|c| c.kind).collect()).unwrap_or_default();
    let width = 0.8 / kinds.len().max(1) as f64;
    // (kind, left, right, value) of every bar.
    let mut rects = Vec::new();
    for (g, b) in balls.iter().enumerate() {
        for (k, c) in b.contacts.iter().enumerate() {
            let left = g as f64 + 0.1 + k as f64 * width;
            rects.push((c.kind, left, left + width, value(c)));
        }
    }
    let finite = rects.iter().map(|r| r.3).filter(|v| v.is_finite());
    let (lo, hi) = finite.fold((0.0_f64, 0.0_f64), |(a, b), v| (a.min(v), b.max(v)));
    let span = if hi > lo { hi - lo } else { 1.0 };
    let (y0, y1) = (lo - if lo < 0.0 { 0.05 * span } else { 0.0 }, hi + 0.05 * span);
    let x1 = balls.len().max(1) as f64;
    let labels: Vec<String> = kinds.iter().map(|k| format!("{} contact", k.name())).collect();
    let size = legend_size(&labels.iter().map(String::as_str).collect::<Vec<_>>())?;
    let tops: Vec<(f64, f64)> = rects.iter().flat_map(|r| [(r.1, r.3), (r.2, r.3), (0.5 * (r.1 + r.2), r.3)]).collect();
    let panel = Panel { caption, x_desc, y_desc, circles: x1, span: (y0, y1) };
    let (mut chart, corner) = panel_chart(area, &panel, size, &tops)?;
    for (i, kind) in kinds.iter().enumerate() {
        let c = colour(*kind);
        chart
            .draw_series(
                rects
                    .iter()
                    .filter(|r| r.0 == *kind && r.3.is_finite())
                    .map(|r| Rectangle::new([(r.1, 0.0_f64.clamp(y0, y1)), (r.2, r.3)], c.filled())),
            )
            .map_err(plot_error)?
            .label(labels[i].as_str())
            .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], c.filled()));
    }
    chart.draw_series(LineSeries::new([(0.0, 0.0), (x1, 0.0)], GREY.stroke_width(1))).map_err(plot_error)?;
    name_groups(area, &chart, names, y0)?;
    legend(&mut chart, corner)
}

/// The circles' `names` under their groups of `chart` on `area` (bottom `y0`).
fn name_groups(area: &Area<'_>, chart: &Chart<'_, '_>, names: &[String], y0: f64) -> Result<(), CliError> {
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
    let (_, ys) = chart.plotting_area().get_pixel_range();
    for (g, name) in names.iter().enumerate() {
        let (x, _) = chart.backend_coord(&(g as f64 + 0.5, y0));
        area.draw_text(name, &style, (x - area.get_base_pixel().0, ys.end - area.get_base_pixel().1 + 6))
            .map_err(plot_error)?;
    }
    Ok(())
}

/// What a panel is: its caption, its axes' descriptions, its width in circles and the span
/// of its values.
struct Panel<'t> {
    caption: &'t str,
    x_desc: &'t str,
    y_desc: &'t str,
    circles: f64,
    span: (f64, f64),
}

/// The chart of `panel` on `area` with room for a legend of `size` clear of `points`, its
/// grid and axes drawn; with the legend's corner.
fn panel_chart<'a, 'b>(
    area: &'a Area<'b>,
    panel: &Panel<'_>,
    size: (i32, i32),
    points: &[(f64, f64)],
) -> Result<(Chart<'a, 'b>, SeriesLabelPosition), CliError> {
    let build = |a: f64, b: f64| -> Result<Chart<'a, 'b>, CliError> {
        ChartBuilder::on(area)
            .caption(panel.caption, (FONT, 19))
            .margin(16)
            .x_label_area_size(56)
            .y_label_area_size(90)
            .build_cartesian_2d(0.0..panel.circles, a..b)
            .map_err(plot_error)
    };
    let (mut chart, corner) = with_legend(build, panel.span, size, &[], 0, points)?;
    chart
        .configure_mesh()
        .disable_x_mesh()
        .max_light_lines(0)
        .bold_line_style(GRID_BOLD)
        .x_labels(0)
        .y_labels(8)
        .y_label_formatter(&tick)
        .x_desc(panel.x_desc)
        .y_desc(panel.y_desc)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(plot_error)?;
    Ok((chart, corner))
}
