//! The figure of `ballscrew map --plot FILE.svg`: the map's torque (its lookup, as firmware gets
//! it) against the speed magnitude, one curve per preload of the grid (at most
//! [`MAX_CURVES`]: every k-th of more, the last included), in two panels, forward and reverse;
//! the check point of the largest interpolation error marked by a ring and its numbers. A
//! geometric speed axis is drawn logarithmic, a uniform one linear. The preloads' key is beside
//! the panels.

use crate::error::CliError;
use crate::plots::figure::{Area, FONT, MARK, axes, num, page, plot_error};
use ballscrew_core::input::{rad_s_to_rpm, rpm_to_rad_s};
use ballscrew_core::realtime::map::{Spacing, Tabulated};
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const SIZE: (u32, u32) = (1500, 820);
const HEADER: u32 = 90;
/// Width of the preloads' key, pixels.
const KEY: u32 = 170;
/// Most curves drawn per panel.
pub const MAX_CURVES: usize = 24;
/// Points drawn per grid cell of a curve (the lookup between the nodes).
const PER_CELL: usize = 4;

/// Viridis-like colours from the first preload (dark) to the last (light).
fn colour(share: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] =
        [(68.0, 1.0, 84.0), (59.0, 82.0, 139.0), (33.0, 145.0, 140.0), (94.0, 201.0, 98.0), (253.0, 231.0, 37.0)];
    let t = share.clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |x: f64, y: f64| (x + (y - x) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The indices of the preloads drawn: all, or every k-th and the last.
fn shown(points: usize) -> Vec<usize> {
    let stride = points.div_ceil(MAX_CURVES).max(1);
    let mut k: Vec<usize> = (0..points).step_by(stride).collect();
    if k.last() != Some(&(points - 1)) {
        k.push(points - 1);
    }
    k
}

/// One curve: its colour and its points (speed magnitude rpm, torque N m).
type Curve = (RGBColor, Vec<(f64, f64)>);

/// The worst-error point: (speed magnitude rpm, map torque N m) and its note.
type Mark = ((f64, f64), String);

/// The figure; `title` says what was run and the grid.
pub fn svg(title: &[String], t: &Tabulated) -> Result<String, CliError> {
    let g = &t.grid;
    let map = t.map();
    let (p_worst, w_worst) = t.worst_point;
    let worst_rpm = rad_s_to_rpm(w_worst.abs());
    let nodes: Vec<f64> = (0..g.speed_points).map(|k| rad_s_to_rpm(f64::from(g.speed_rad_s(k)))).collect();
    let first = nodes.first().copied().unwrap_or(0.0);
    let last = nodes.last().copied().unwrap_or(1.0);
    let geometric = g.speed_spacing == Spacing::Geometric;
    // A logarithmic axis starts at the first node, or at the worst point below it.
    let lo = if geometric { if worst_rpm > 0.0 { first.min(worst_rpm) } else { first } } else { first };
    let mut speeds = Vec::new();
    if geometric && lo < first {
        speeds.extend((0..PER_CELL).map(|i| lo * (first / lo).powf(i as f64 / PER_CELL as f64)));
    }
    for pair in nodes.windows(2) {
        for i in 0..PER_CELL {
            let f = i as f64 / PER_CELL as f64;
            speeds.push(if geometric {
                pair[0] * (pair[1] / pair[0]).powf(f)
            } else {
                pair[0] + (pair[1] - pair[0]) * f
            });
        }
    }
    speeds.push(last);
    let indices = shown(g.preload_points as usize);
    let preloads: Vec<f64> = indices.iter().map(|&k| f64::from(g.preload_n(k as u32))).collect();
    let curves = |sign: f64| -> Vec<Curve> {
        preloads
            .iter()
            .enumerate()
            .map(|(i, &p)| {
                let share = if preloads.len() > 1 { i as f64 / (preloads.len() - 1) as f64 } else { 0.0 };
                let pts = speeds
                    .iter()
                    .map(|&s| (s, f64::from(map.torque_nm(p as f32, (sign * rpm_to_rad_s(s)) as f32))))
                    .collect();
                (colour(share), pts)
            })
            .collect()
    };
    let (forward, reverse) = (curves(1.0), curves(-1.0));
    let error = if t.max_relative_error.is_finite() {
        format!("{} %", num(100.0 * t.max_relative_error))
    } else {
        "n/a".to_string()
    };
    let worst_torque = f64::from(map.torque_nm(p_worst as f32, w_worst as f32));
    let note = format!(
        "largest interpolation error {error} ({} N m) at {} N, {} rpm",
        num(t.max_absolute_error_nm),
        num(p_worst),
        num(rad_s_to_rpm(w_worst))
    );
    let mark: Mark = ((worst_rpm, worst_torque), note);
    let x_desc = if geometric { "speed magnitude, rpm (logarithmic)" } else { "speed magnitude, rpm" };
    let mut lines = title.to_vec();
    lines.push(format!(
        "curve: the map's lookup torque at one preload{}; ring: the check point of the largest interpolation error",
        if preloads.len() < g.preload_points as usize {
            format!(" ({} of the {} preloads drawn)", preloads.len(), g.preload_points)
        } else {
            String::new()
        }
    ));
    page(SIZE, HEADER + 20, &lines, |_, body| {
        let (panels, key) = body.split_horizontally(SIZE.0 - KEY);
        let halves = panels.split_evenly((1, 2));
        let marks = |forward: bool| (forward == (w_worst >= 0.0)).then(|| mark.clone());
        let hi = last * 1.02;
        for (area, caption, set, fwd) in [
            (&halves[0], "(a) forward: speed > 0", &forward, true),
            (&halves[1], "(b) reverse: speed < 0, against its magnitude", &reverse, false),
        ] {
            if geometric {
                panel(area, caption, (lo / 1.15..hi).log_scale(), x_desc, set, marks(fwd))?;
            } else {
                panel(area, caption, lo..hi, x_desc, set, marks(fwd))?;
            }
        }
        draw_key(&key, &preloads, &forward)
    })
}

/// One panel: the curves of one direction, the mark if it lies in it.
fn panel<X>(
    area: &Area<'_>,
    caption: &str,
    x: X,
    x_desc: &str,
    curves: &[Curve],
    mark: Option<Mark>,
) -> Result<(), CliError>
where
    X: AsRangedCoord<Value = f64>,
    X::CoordDescType: ValueFormatter<f64>,
{
    let ys = curves.iter().flat_map(|c| c.1.iter().map(|p| p.1)).filter(|y| y.is_finite());
    let (y0, y1) = ys.fold((0.0_f64, 0.0_f64), |(a, b), y| (a.min(y), b.max(y)));
    let d = if y1 > y0 { 0.06 * (y1 - y0) } else { 1.0 };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 19))
        .margin(16)
        .x_label_area_size(56)
        .y_label_area_size(84)
        .build_cartesian_2d(x, y0 - d..y1 + d)
        .map_err(plot_error)?;
    axes(&mut chart, x_desc, "torque, N m")?;
    for (c, pts) in curves {
        chart.draw_series(LineSeries::new(pts.clone(), c.stroke_width(2))).map_err(plot_error)?;
    }
    if let Some((p, note)) = mark {
        chart.draw_series(core::iter::once(Circle::new(p, 9, MARK.stroke_width(3)))).map_err(plot_error)?;
        let (px, py) = chart.backend_coord(&p);
        let (xs, _) = chart.plotting_area().get_pixel_range();
        let base = area.get_base_pixel();
        let right = px < (xs.start + xs.end) / 2;
        let pos = if right { Pos::new(HPos::Left, VPos::Bottom) } else { Pos::new(HPos::Right, VPos::Bottom) };
        let style = TextStyle::from((FONT, 14).into_font()).color(&BLACK).pos(pos);
        let x = px - base.0 + if right { 12 } else { -12 };
        let y = py - base.1 - 12;
        // A white ground under the note, so the curves do not cross it.
        let (w, h) = area.estimate_text_size(&note, &style).map_err(plot_error)?;
        let (w, h) = (w as i32, h as i32);
        let left = if right { x } else { x - w };
        area.draw(&Rectangle::new([(left - 3, y - h - 3), (left + w + 3, y + 3)], WHITE.mix(0.85).filled()))
            .map_err(plot_error)?;
        area.draw_text(&note, &style, (x, y)).map_err(plot_error)?;
    }
    Ok(())
}

/// The key: a short line in each curve's colour and its preload.
fn draw_key(area: &Area<'_>, preloads: &[f64], curves: &[Curve]) -> Result<(), CliError> {
    let style = TextStyle::from((FONT, 14).into_font()).color(&BLACK);
    area.draw_text("preload F_p", &TextStyle::from((FONT, 16).into_font()).color(&BLACK), (10, 40))
        .map_err(plot_error)?;
    let step = ((area.dim_in_pixel().1 as i32 - 110) / preloads.len().max(1) as i32).clamp(8, 26);
    for (i, (&p, (c, _))) in preloads.iter().zip(curves).enumerate() {
        let y = 72 + step * i as i32;
        area.draw(&PathElement::new(vec![(10, y), (40, y)], c.stroke_width(3))).map_err(plot_error)?;
        area.draw_text(&format!("F_p = {} N", num(p)), &style, (48, y - 8)).map_err(plot_error)?;
    }
    Ok(())
}
