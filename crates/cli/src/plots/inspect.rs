//! The figure of `ballscrew inspect --plot FILE.svg`: one group of bars per circle (per nut, in
//! order), a bar per contact of its ball: (a) the normal load Q of the contact, N; (b) the
//! contact's share of the drive torque over all balls of the circle, N m.

use crate::error::CliError;
use crate::plots::figure::{
    Area, Chart, FONT, GREY, GRID_BOLD, legend, legend_size, page, plot_error, tick, with_legend,
};
use ballscrew_core::{BallReport, ContactKind, ContactReport, Evaluation};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const SIZE: (u32, u32) = (1300, 1000);
const HEADER: u32 = 90;
/// Most circles labelled in full (`nut 1, circle 2`); more are labelled `1.2` (nut.circle).
const FULL_LABELS: usize = 10;

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
         circle's balls"
            .to_string(),
    ];
    page(SIZE, HEADER, &lines, |_, body| {
        let panels = body.split_evenly((2, 1));
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
        )
    })
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
    let build = |a: f64, b: f64| -> Result<Chart<'_, '_>, CliError> {
        ChartBuilder::on(area)
            .caption(caption, (FONT, 19))
            .margin(16)
            .x_label_area_size(56)
            .y_label_area_size(90)
            .build_cartesian_2d(0.0..x1, a..b)
            .map_err(plot_error)
    };
    let (mut chart, corner) = with_legend(build, (y0, y1), size, &[], 0, &tops)?;
    chart
        .configure_mesh()
        .disable_x_mesh()
        .max_light_lines(0)
        .bold_line_style(GRID_BOLD)
        .x_labels(0)
        .y_labels(8)
        .y_label_formatter(&tick)
        .x_desc(x_desc)
        .y_desc(y_desc)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(plot_error)?;
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
    // The circles' names under their groups.
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
    let (_, ys) = chart.plotting_area().get_pixel_range();
    for (g, name) in names.iter().enumerate() {
        let (x, _) = chart.backend_coord(&(g as f64 + 0.5, y0));
        area.draw_text(name, &style, (x - area.get_base_pixel().0, ys.end - area.get_base_pixel().1 + 6))
            .map_err(plot_error)?;
    }
    legend(&mut chart, corner)
}
