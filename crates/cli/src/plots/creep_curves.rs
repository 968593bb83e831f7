//! The figure of `ballscrew creep-curves --plot FILE.svg`: the friction of one contact against
//! each creep parameter, the other three zero (Fig. 9 of the paper), a panel each, a curve per
//! law.

use crate::curves::{Curve, Curves};
use crate::error::CliError;
use crate::plots::figure::{FONT, GREY, axes, num, page, plot_error, power_of_ten};
use ballscrew_core::contact::analysis::{Law, Parameter};
use ballscrew_core::contact::fastsim::TractionBound;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

/// Colour and dash of a law's curve.
fn law_style(law: Law) -> (RGBColor, bool) {
    match law {
        Law::Fastsim(TractionBound::Parabolic) => (RGBColor(31, 119, 180), false),
        Law::Fastsim(TractionBound::Elliptical) => (RGBColor(44, 160, 44), false),
        Law::Eq24 => (RGBColor(214, 39, 40), true),
    }
}

/// A law in words, for legends.
fn law_label(law: Law) -> &'static str {
    match law {
        Law::Fastsim(TractionBound::Parabolic) => "FASTSIM, parabolic bound",
        Law::Fastsim(TractionBound::Elliptical) => "FASTSIM, elliptical bound",
        Law::Eq24 => "Eq. 24 (the model's law)",
    }
}

/// Axis symbol of a parameter.
fn symbol(p: Parameter) -> &'static str {
    match p {
        Parameter::Xi => "ξ",
        Parameter::Eta => "η",
        Parameter::PhiC => "φ c",
        Parameter::KhB2 => "k_h b²",
    }
}

/// Words of a parameter, for panel captions.
fn caption(p: Parameter) -> &'static str {
    match p {
        Parameter::Xi => "longitudinal creepage ξ",
        Parameter::Eta => "lateral creepage η",
        Parameter::PhiC => "spin φ c",
        Parameter::KhB2 => "Heathcote k_h b²",
    }
}

/// Which component carries the force of a set of curves, e.g. `F along −e (F_f = 0)`.
fn direction_note(set: &[&Curve]) -> String {
    let (mut e, mut f) = (0.0_f64, 0.0_f64);
    let (mut e_sum, mut f_sum) = (0.0, 0.0);
    for p in set.iter().flat_map(|c| &c.points) {
        e = e.max(p.forces.force_e_n.abs());
        f = f.max(p.forces.force_f_n.abs());
        e_sum += p.forces.force_e_n;
        f_sum += p.forces.force_f_n;
    }
    let sign = |s: f64| if s < 0.0 { "−" } else { "+" };
    if f <= 1e-9 * e {
        format!("F along {}e, F_f = 0", sign(e_sum))
    } else if e <= 1e-9 * f {
        format!("F along {}f, F_e = 0", sign(f_sum))
    } else {
        "F in the e-f plane".to_string()
    }
}

/// The creep curves, Fig. 9 style: four panels (xi, eta, phi c, k_h b^2), |F|/(mu Q) against
/// the parameter under each law, with Kalker's linear theory as a thin grey line.
pub fn svg(curves: &Curves) -> Result<String, CliError> {
    const SIZE: (u32, u32) = (1300, 1080);
    const HEADER: u32 = 110;
    let (s, c) = (&curves.setup, &curves.setup.contact);
    let lines = [
        "Friction against each creep parameter, the other three zero (Fig. 9)".to_string(),
        format!(
            "a = {} mm, b = {} mm (a/b = {}), c = √(ab) = {} mm, Q = {} N, μ = {}; FASTSIM on {} × {} strips",
            num(c.semi_axis_rolling_m * 1e3),
            num(c.semi_axis_lateral_m * 1e3),
            num(c.a_over_b()),
            num(c.creep_length_m() * 1e3),
            num(c.normal_load_n),
            num(c.friction_coefficient),
            s.grid,
            s.grid
        ),
        s.source.clone(),
    ];
    page(SIZE, HEADER, &lines, |_, body| {
        for (parameter, panel) in Parameter::ALL.into_iter().zip(body.split_evenly((2, 2))) {
            let set: Vec<&Curve> = curves.of(parameter).collect();
            panel_chart(&panel, parameter, &set, curves.span)?;
        }
        Ok(())
    })
}

fn panel_chart(
    panel: &DrawingArea<SVGBackend<'_>, Shift>,
    parameter: Parameter,
    set: &[&Curve],
    span: f64,
) -> Result<(), CliError> {
    let Some(first) = set.first() else { return Ok(()) };
    let sat = first.saturation_value;
    let max = span * sat;
    // Axis numbers of order 1: the parameter times 10^-e.
    let e = if max > 0.0 { max.log10().floor() as i32 } else { 0 };
    let (unit, x_desc) = if (-1..=1).contains(&e) {
        (1.0, symbol(parameter).to_string())
    } else {
        (10f64.powi(e), format!("{} × {}", symbol(parameter), power_of_ten(-e)))
    };
    let y_top = set.iter().flat_map(|c| &c.points).map(|p| p.forces.force_ratio).fold(1.0, f64::max) * 1.08;
    let caption = format!("{} alone ({})", caption(parameter), direction_note(set));
    let mut chart = ChartBuilder::on(panel)
        .caption(caption, (FONT, 18))
        .margin(16)
        .x_label_area_size(52)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..max / unit, 0.0..y_top)
        .map_err(plot_error)?;
    axes(&mut chart, &x_desc, "|F| / (μQ)")?;
    // |F| = mu Q, and Kalker's linear theory up to the top of the panel.
    chart.draw_series(LineSeries::new([(0.0, 1.0), (max / unit, 1.0)], GREY.stroke_width(1))).map_err(plot_error)?;
    let x_end = (y_top * sat).min(max);
    chart
        .draw_series(LineSeries::new([(0.0, 0.0), (x_end / unit, x_end / sat)], GREY.stroke_width(1)))
        .map_err(plot_error)?
        .label("Kalker linear theory (Eq. 23)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], GREY.stroke_width(1)));
    for curve in set {
        let (colour, dashed) = law_style(curve.law);
        let style = colour.stroke_width(2);
        let pts: Vec<(f64, f64)> = curve.points.iter().map(|p| (p.value / unit, p.forces.force_ratio)).collect();
        if dashed {
            chart
                .draw_series(DashedLineSeries::new(pts, 8, 5, style))
                .map_err(plot_error)?
                .label(law_label(curve.law))
                .legend(move |(x, y)| DashedPathElement::new([(x, y), (x + 24, y)], 8, 5, style));
        } else {
            chart
                .draw_series(LineSeries::new(pts, style))
                .map_err(plot_error)?
                .label(law_label(curve.law))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
        }
    }
    // The legend where the curves are not: low curves (spin) leave the top free.
    let high = set.iter().flat_map(|c| &c.points).any(|p| p.forces.force_ratio > 0.5 * y_top);
    chart
        .configure_series_labels()
        .position(if high { SeriesLabelPosition::LowerRight } else { SeriesLabelPosition::UpperRight })
        .background_style(WHITE.mix(0.9))
        .border_style(GREY)
        .label_font((FONT, 14))
        .draw()
        .map_err(plot_error)?;
    Ok(())
}
