//! The figures through the built binary: `sweep`, `map` and `inspect --plot`, the adhesion area
//! of `contact --plot`, the time figure and the legends of `diagnose --plots`, and the refusal of
//! a `--plot` that does not name an SVG file. Each figure is read back as SVG text: its title,
//! its axes with units, and its series, bars or marks counted from the elements plotters writes.

mod common;

use common::{XJTU_UPPER, fails, ok};
use std::path::Path;

/// The SVG of a run that writes `--plot FILE` (`FILE` appended to `args`).
fn figure(dir: &Path, name: &str, args: &[&str]) -> String {
    let path = dir.join(name);
    ok(&[args, &["--plot", path.to_str().unwrap()]].concat());
    let svg = std::fs::read_to_string(&path).unwrap();
    assert!(svg.trim_start().starts_with("<svg") && svg.trim_end().ends_with("</svg>"), "{name}: not SVG");
    svg
}

/// The text of every `<text>` element, unescaped as far as the figures need.
fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let body = &t[t.find('>')? + 1..t.find("</text>")?];
            Some(body.trim().replace("&apos;", "'").replace("&amp;", "&").replace("&lt;", "<").replace("&gt;", ">"))
        })
        .collect()
}

/// The opening tags of every `<name ...>` element.
fn elements<'a>(svg: &'a str, name: &str) -> Vec<&'a str> {
    let open = format!("<{name} ");
    svg.match_indices(&open).map(|(i, _)| &svg[i..i + svg[i..].find('>').unwrap()]).collect()
}

/// The value of attribute `name` of an opening tag.
fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = tag.find(&key)? + key.len();
    Some(&tag[start..start + tag[start..].find('"')?])
}

fn num(tag: &str, name: &str) -> f64 {
    attr(tag, name).unwrap_or_else(|| panic!("no {name} in {tag}")).parse().unwrap()
}

/// Elements `name` whose attribute `key` is `value`.
fn with<'a>(svg: &'a str, name: &str, key: &str, value: &str) -> Vec<&'a str> {
    elements(svg, name).into_iter().filter(|t| attr(t, key) == Some(value)).collect()
}

/// How many text elements are exactly `text`, or start with it when `prefix`.
fn count_texts(svg: &str, text: &str, prefix: bool) -> usize {
    texts(svg).iter().filter(|t| if prefix { t.starts_with(text) } else { t.as_str() == text }).count()
}

/// The legend's box (left, top, right, bottom): the rectangle with its grey border.
fn legend_boxes(svg: &str) -> Vec<(f64, f64, f64, f64)> {
    with(svg, "rect", "stroke", "#828282")
        .iter()
        .map(|r| {
            let (x, y) = (num(r, "x"), num(r, "y"));
            (x, y, x + num(r, "width"), y + num(r, "height"))
        })
        .collect()
}

/// The marks (rings) of the figures: (centre x, centre y, radius).
fn rings(svg: &str) -> Vec<(f64, f64, f64)> {
    with(svg, "circle", "stroke", "#E69F00").iter().map(|c| (num(c, "cx"), num(c, "cy"), num(c, "r"))).collect()
}

#[test]
fn sweep_plot_draws_the_torque_the_band_and_the_other_routes() {
    let dir = tempfile::tempdir().unwrap();
    let svg = figure(dir.path(), "sweep.svg", &["sweep"]);
    let t = texts(&svg);
    assert!(t[0].starts_with("ballscrew sweep: built-in DKFZD4012"), "{}", t[0]);
    assert!(t[0].contains("speed 100 rpm") && t[0].contains("torque route: energy"), "{}", t[0]);
    assert!(t.iter().any(|l| l.starts_with("Drag torque against the catalog band")), "the band's verdict");
    assert_eq!(count_texts(&svg, "preload F_p, N", false), 1);
    assert_eq!(count_texts(&svg, "torque, N m", false), 1);
    for label in [
        "catalog band, catalog × [0.5, 1.5]",
        "catalog estimate",
        "moment route (moment about the axis)",
        "energy route F_a L/2π + D/ω",
        "torque (the spec's route)",
    ] {
        assert_eq!(count_texts(&svg, label, false), 1, "{label}");
    }
    // No axial load: no drag or load line (the torque is the drag).
    assert_eq!(count_texts(&svg, "drag torque", true), 0);
    assert_eq!(count_texts(&svg, "load torque", true), 0);
    // The band: one polygon, its upper and lower edge a point per preload (26); a dot per point.
    let band = with(&svg, "polygon", "fill", "#FDAE61");
    assert_eq!(band.len(), 1);
    assert_eq!(attr(band[0], "points").unwrap().split_whitespace().count(), 2 * 26);
    assert_eq!(with(&svg, "circle", "fill", "#1F77B4").len(), 26);
    // The legend covers no dot of the torque.
    let legends = legend_boxes(&svg);
    assert_eq!(legends.len(), 1);
    let (l, top, r, b) = legends[0];
    for c in with(&svg, "circle", "fill", "#1F77B4") {
        let (x, y) = (num(c, "cx"), num(c, "cy"));
        assert!(!(x >= l && x <= r && y >= top && y <= b), "a torque point under the legend: {c}");
    }

    // An axial-load sweep: the drag and the load torque join; the x axis is the axial load.
    let svg = figure(dir.path(), "axial.svg", &["sweep", "--axial-load-n", "0..2000", "--axial-load-step-n", "500"]);
    assert_eq!(count_texts(&svg, "axial load F_a, N", false), 1);
    assert_eq!(count_texts(&svg, "drag torque (torque − F_a L/2π), against the band", false), 1);
    assert_eq!(count_texts(&svg, "load torque F_a L/2π", false), 1);
    assert_eq!(with(&svg, "circle", "fill", "#1F77B4").len(), 5);
    assert!(texts(&svg)[0].contains("preload 2000 N"), "the fixed preload in the title");
    // Speed and oil temperature as the swept quantity.
    let svg = figure(dir.path(), "speed.svg", &["sweep", "--speed-rpm", "100..500"]);
    assert_eq!(count_texts(&svg, "screw speed, rpm", false), 1);
    // Through reversal the band follows the sign of the speed: at -500 rpm it lies below zero,
    // as the torque does (SVG y grows downwards).
    let svg = figure(dir.path(), "reverse.svg", &["sweep", "--speed-rpm", "-500..500"]);
    assert_eq!(count_texts(&svg, "catalog band, catalog × [0.5, 1.5], signed as the speed", false), 1);
    let band = with(&svg, "polygon", "fill", "#FDAE61");
    let first: Vec<f64> = attr(band[0], "points")
        .unwrap()
        .split_whitespace()
        .next()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let dots = with(&svg, "circle", "fill", "#1F77B4");
    let zero = num(dots[dots.len() / 2], "cy");
    assert!(
        first[1] > zero && num(dots[0], "cy") > zero,
        "band {first:?} and torque at -500 rpm below zero at y {zero}"
    );
    let svg = figure(dir.path(), "oil.svg", &["sweep", "--oil-temperature-c", "20..60", "--preload", "2000"]);
    assert_eq!(count_texts(&svg, "oil temperature at the contacts, °C", false), 1);
    assert_eq!(with(&svg, "circle", "fill", "#1F77B4").len(), 9);
}

/// The largest number among the texts of a figure below `below` (the y-axis' tick labels, the
/// x-axis' being larger).
fn largest_tick(svg: &str, below: f64) -> f64 {
    texts(svg).iter().filter_map(|t| t.parse::<f64>().ok()).filter(|&v| v < below).fold(f64::NEG_INFINITY, f64::max)
}

/// The sweep's figure leaves Eq. 27 as printed out unless `--plot-paper-eq27` asks for it: the
/// y-axis spans the model's torque and the catalog band, not the printed equation's ten-fold
/// torque; asked for, the line is drawn and the axis spans it.
#[test]
fn sweep_plot_draws_eq27_as_printed_only_when_asked() {
    let dir = tempfile::tempdir().unwrap();
    // The preloads are 500 N and more: every number below is a torque tick.
    let (header, rows) = {
        let text = ok(&["sweep", "--format", "csv"]);
        let mut lines = text.lines();
        let header: Vec<String> = lines.next().unwrap().split(',').map(str::to_string).collect();
        let rows: Vec<Vec<f64>> =
            lines.map(|l| l.split(',').map(|f| f.parse().unwrap_or(f64::NAN)).collect()).collect();
        (header, rows)
    };
    let max = |key: &str| {
        let i = header.iter().position(|h| h == key).unwrap();
        rows.iter().map(|r| r[i]).fold(f64::NEG_INFINITY, f64::max)
    };
    let (model, high, eq27) = (max("torque_nm"), max("catalog_high_nm"), max("torque_eq27_nm"));
    assert!(eq27 > 2.0 * high.max(model) && high.max(model) < 100.0, "{model} {high} {eq27}");
    let svg = figure(dir.path(), "sweep.svg", &["sweep"]);
    assert_eq!(count_texts(&svg, "Eq. 27", true), 0);
    assert!(with(&svg, "polyline", "stroke", "#7F7F7F").is_empty(), "no grey Eq. 27 line");
    let top = largest_tick(&svg, 100.0);
    // (The legend may lift the top of the axis above the band to keep clear of the curves.)
    assert!(top >= 0.8 * high.max(model) && top <= 1.5 * high.max(model), "y ticks up to {top}: {model} {high}");
    assert!(top < 0.6 * eq27, "y ticks up to {top}: Eq. 27 up to {eq27}");

    let svg = figure(dir.path(), "eq27.svg", &["sweep", "--plot-paper-eq27"]);
    assert_eq!(count_texts(&svg, "Eq. 27 as printed", false), 1);
    let top = largest_tick(&svg, 100.0);
    assert!(top >= 0.8 * eq27 && top <= 1.1 * eq27, "y ticks up to {top}: Eq. 27 up to {eq27}");
    // The flag draws into a figure: without --plot it is refused, naming both.
    let e = fails(&["sweep", "--plot-paper-eq27"], 2);
    assert!(e.contains("--plot-paper-eq27") && e.contains("--plot <FILE.svg>"), "{e}");
}

#[test]
fn map_plot_draws_a_curve_per_preload_in_both_directions_and_rings_the_worst_point() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["map", "--preload-points", "5", "--speed-points", "8"];
    let svg = figure(dir.path(), "map.svg", &args);
    let t = texts(&svg);
    assert!(t[0].starts_with("ballscrew map: built-in DKFZD4012") && t[0].contains("axial load 0 N"), "{}", t[0]);
    assert!(t[1].starts_with("grid: preload 500..3000 N x 5 points"), "{}", t[1]);
    assert_eq!(count_texts(&svg, "speed magnitude, rpm (logarithmic)", false), 2);
    assert_eq!(count_texts(&svg, "torque, N m", false), 2);
    assert_eq!(count_texts(&svg, "(a) forward: speed > 0", false), 1);
    assert_eq!(count_texts(&svg, "(b) reverse: speed < 0, against its magnitude", false), 1);
    // A curve per preload (lines of width 2) in each panel, and a key entry per preload.
    assert_eq!(with(&svg, "polyline", "stroke-width", "2").len(), 2 * 5);
    assert_eq!(count_texts(&svg, "F_p = ", true), 5);
    for p in ["500", "1125", "1750", "2375", "3000"] {
        assert_eq!(count_texts(&svg, &format!("F_p = {p} N"), false), 1, "{p}");
    }
    // The worst check point: one ring, and its note with the error the table reports.
    assert_eq!(rings(&svg).len(), 1);
    let table = ok(&args);
    let percent = table.split("against the model: ").nth(1).unwrap().split(' ').next().unwrap();
    let note = t.iter().find(|l| l.starts_with("largest interpolation error")).expect("the worst point's note");
    let shown: f64 = note.split(' ').nth(3).unwrap().parse().unwrap();
    // The note rounds to two decimals.
    assert!((shown - percent.parse::<f64>().unwrap()).abs() <= 5e-3, "{note} against {percent} %");

    // More preloads than curves: every other one and the last, and the title says so.
    let svg = figure(
        dir.path(),
        "many.svg",
        &["map", "--preload-points", "30", "--speed-spacing", "uniform", "--speed-points", "4"],
    );
    assert_eq!(count_texts(&svg, "F_p = ", true), 16);
    assert_eq!(with(&svg, "polyline", "stroke-width", "2").len(), 2 * 16);
    assert!(texts(&svg).iter().any(|l| l.contains("(16 of the 30 preloads drawn)")));
    assert_eq!(count_texts(&svg, "speed magnitude, rpm", false), 2, "a uniform axis is linear");
    // The figure beside a C header: both written.
    let header = dir.path().join("map.h");
    let plot = dir.path().join("c.svg");
    ok(&[&args[..], &["--format", "c", "--out", header.to_str().unwrap(), "--plot", plot.to_str().unwrap()]].concat());
    assert!(std::fs::read_to_string(&header).unwrap().contains("#define"));
    assert_eq!(rings(&std::fs::read_to_string(&plot).unwrap()).len(), 1);
}

#[test]
fn inspect_plot_draws_a_bar_group_per_circle() {
    let dir = tempfile::tempdir().unwrap();
    let svg = figure(dir.path(), "inspect.svg", &["inspect", "--preload-n", "1500"]);
    let t = texts(&svg);
    assert!(t[0].starts_with("ballscrew inspect: built-in DKFZD4012") && t[0].contains("preload 1500 N"), "{}", t[0]);
    assert_eq!(count_texts(&svg, "normal load Q, N", false), 1);
    assert_eq!(count_texts(&svg, "torque share, N m", false), 1);
    assert_eq!(count_texts(&svg, "chain force, N", false), 1);
    // Panel (c): a line per circle in its nut's colour (and the legend's), each from the
    // contact behind the circle's first ball (the built-in internal return: the gap, zero) to
    // the one ahead of its last (the return's resistance), rising.
    for colour in ["#9467BD", "#D62728"] {
        let lines = with(&svg, "polyline", "stroke", colour);
        assert_eq!(lines.len(), 4 + 1, "{colour}");
        for l in &lines[..4] {
            let ys: Vec<f64> = attr(l, "points")
                .unwrap()
                .split_whitespace()
                .map(|p| p.split(',').nth(1).unwrap().parse().unwrap())
                .collect();
            assert!(ys.len() == 2 && ys[0] > ys[1], "{colour}: {ys:?} (pixels: larger is lower)");
        }
    }
    // The built-in double nut: 2 nuts x 4 circles, a group each in each panel.
    let json: serde_json::Value =
        serde_json::from_str(&ok(&["inspect", "--preload-n", "1500", "--format", "json"])).unwrap();
    let nuts = json["nuts"].as_array().unwrap();
    let circles: usize = nuts.iter().map(|n| n["circles"].as_array().unwrap().len()).sum();
    assert_eq!(circles, 8);
    for n in nuts {
        for c in n["circles"].as_array().unwrap() {
            let name = format!("{}, circle {}", n["group"].as_str().unwrap(), c["circle"]);
            assert_eq!(count_texts(&svg, &name, false), 3, "{name}: a group in each panel");
        }
    }
    // A bar per contact and circle in each panel, and the legend's swatch in each: nut, screw,
    // ball-ball.
    for (colour, label) in [("#1F77B4", "nut contact"), ("#FF7F0E", "screw contact"), ("#2CA02C", "ball-ball contact")]
    {
        assert_eq!(with(&svg, "rect", "fill", colour).len(), 2 * circles + 2, "{label}");
        assert_eq!(count_texts(&svg, label, false), 2, "{label}");
    }
    // The bars of panel (a) stand for the loads: the tallest nut bar is the largest load.
    let loads: Vec<f64> = nuts
        .iter()
        .flat_map(|n| n["circles"].as_array().unwrap().iter())
        .map(|c| {
            c["contacts"].as_array().unwrap().iter().find(|k| k["contact"] == "nut").unwrap()["normal_load_n"]
                .as_f64()
                .unwrap()
        })
        .collect();
    let bars: Vec<f64> = with(&svg, "rect", "fill", "#1F77B4").iter().take(circles).map(|r| num(r, "height")).collect();
    let scale = bars[0] / loads[0];
    for (bar, load) in bars.iter().zip(&loads) {
        assert!((bar - scale * load).abs() <= 1.5, "{bars:?} against {loads:?}: not proportional");
    }
}

#[test]
fn contact_plot_shades_the_adhesion_area() {
    let dir = tempfile::tempdir().unwrap();
    let shades = |svg: &str| with(svg, "rect", "fill", "#C6DBEF").len();
    let area = |svg: &str| -> f64 {
        with(svg, "rect", "fill", "#C6DBEF").iter().map(|r| num(r, "width") * num(r, "height")).sum()
    };
    let partial = figure(dir.path(), "partial.svg", &["contact", "--xi", "2e-4"]);
    assert!(texts(&partial)[0].contains("shaded where it adheres"));
    assert!(shades(&partial) > 40, "a run per strip at least");
    // All adhesion: the whole ellipse shaded; full slip: nothing.
    let still = figure(dir.path(), "still.svg", &["contact", "--xi", "0"]);
    assert!(area(&still) > 1.1 * area(&partial), "{} against {}", area(&still), area(&partial));
    let slip = figure(dir.path(), "slip.svg", &["contact", "--xi", "1"]);
    assert_eq!(shades(&slip), 0);
    // The shading stays within the axes' ellipse: within the outline's bounding box.
    let outline = elements(&partial, "polyline")
        .into_iter()
        .filter(|p| attr(p, "stroke-width") == Some("2"))
        .max_by_key(|p| attr(p, "points").unwrap().len())
        .unwrap();
    let pts: Vec<(f64, f64)> = attr(outline, "points")
        .unwrap()
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect();
    let (x0, x1) = pts.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let (y0, y1) = pts.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
    for r in with(&partial, "rect", "fill", "#C6DBEF") {
        let (x, y) = (num(r, "x"), num(r, "y"));
        assert!(x >= x0 - 1.0 && x + num(r, "width") <= x1 + 1.0, "{r} outside {x0}..{x1}");
        assert!(y >= y0 - 2.0 && y + num(r, "height") <= y1 + 2.0, "{r} outside {y0}..{y1}");
    }
}

/// Measured data with a torque periodic in the nut position at the lead (12 mm, harmonic 1):
/// the model's torque from `predict`, 10 % higher, plus 0.03 N m sin(2 pi x / 12 mm).
fn waviness_data(dir: &Path) -> String {
    let mut ops = String::from("preload_n,speed_rpm,position_mm\n");
    let rows: Vec<(f64, f64, f64)> = (0..240)
        .map(|i| (1000.0 + 500.0 * (i % 4) as f64, [100.0, 300.0, 600.0][i % 3], (i as f64 * 7.3) % 400.0))
        .collect();
    for (p, s, x) in &rows {
        ops.push_str(&format!("{p},{s},{x}\n"));
    }
    let ops_path = dir.join("ops.csv");
    std::fs::write(&ops_path, ops).unwrap();
    let predicted = ok(&["predict", "--data", ops_path.to_str().unwrap()]);
    let mut data = String::from("torque_nm,preload_n,speed_rpm,position_mm\n");
    for ((p, s, x), line) in rows.iter().zip(predicted.lines().skip(1)) {
        let t: f64 = line.rsplit(',').next().unwrap().parse().unwrap();
        let wave = 0.03 * (core::f64::consts::TAU * x / 12.0).sin();
        data.push_str(&format!("{},{p},{s},{x}\n", 1.1 * t + wave));
    }
    let path = dir.join("wavy.csv");
    std::fs::write(&path, data).unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn diagnose_rings_the_detected_harmonic_clear_of_the_legend_and_draws_time_only_with_time_h() {
    let dir = tempfile::tempdir().unwrap();
    let data = waviness_data(dir.path());
    let plots = dir.path().join("wavy");
    let text = ok(&["diagnose", "--data", &data, "--plots", plots.to_str().unwrap()]);
    assert!(text.contains("raceway_waviness") && text.contains("harmonic = 1,"), "{text}");
    let svg = std::fs::read_to_string(plots.join("periodogram_position.svg")).unwrap();
    assert_eq!(count_texts(&svg, "harmonic h of the lead", false), 1);
    assert_eq!(count_texts(&svg, "amplitude, N m", false), 1);
    assert_eq!(count_texts(&svg, "detected: h = 1, period 12 mm", false), 1);
    // The ring sits on the largest amplitude, top left, where the legend used to be; the
    // legend's box keeps clear of the ring.
    let ring = rings(&svg);
    assert_eq!(ring.len(), 1);
    let (cx, cy, r) = ring[0];
    let legends = legend_boxes(&svg);
    assert_eq!(legends.len(), 1);
    let (l, t, rt, b) = legends[0];
    let clear = cx + r < l || cx - r > rt || cy + r < t || cy - r > b;
    assert!(clear, "ring ({cx}, {cy}, r {r}) under the legend ({l}, {t}, {rt}, {b})");
    // No time column: no time figure.
    assert!(!plots.join("torque_vs_time.svg").exists());
    let mut names: Vec<String> =
        std::fs::read_dir(&plots).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert!(!names.iter().any(|n| n.contains("time")), "{names:?}");

    // The degradation data have time_h: the time figure, all three torques, units on the axes.
    let plots = dir.path().join("xjtu");
    ok(&[&XJTU_UPPER[..], &["--plots", plots.to_str().unwrap()]].concat());
    let svg = std::fs::read_to_string(plots.join("torque_vs_time.svg")).unwrap();
    assert!(texts(&svg)[0].starts_with("Torque against time"));
    assert_eq!(count_texts(&svg, "time, h", false), 1);
    assert_eq!(count_texts(&svg, "torque, N m", false), 1);
    for label in ["measured", "calibrated model", "extended model"] {
        assert_eq!(count_texts(&svg, label, false), 1, "{label}");
    }
    // A dot per row of each series (30 rows), and the legend clear of all of them.
    let dots: Vec<&str> = elements(&svg, "circle").into_iter().filter(|c| attr(c, "r") == Some("3")).collect();
    assert_eq!(dots.len(), 3 * 30);
    let (l, t, r, b) = legend_boxes(&svg)[0];
    for c in dots {
        let (x, y) = (num(c, "cx"), num(c, "cy"));
        assert!(!(x >= l && x <= r && y >= t && y <= b), "a point under the legend: {c}");
    }
}

#[test]
fn a_plot_not_named_svg_is_refused_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("x.png");
    let p = png.to_str().unwrap();
    for args in [
        &["sweep"][..],
        &["map"],
        &["inspect"],
        &["contact"],
        &["creep-curves"],
        &["reversal"],
        &["sweep", "--format", "csv", "--out"],
    ] {
        let mut all = args.to_vec();
        if all.last() == Some(&"--out") {
            all.push("-");
        }
        all.extend(["--plot", p]);
        let e = fails(&all, 2);
        assert_eq!(
            e.trim_end(),
            format!(
                "error: invalid --plot: {p} (the figure is SVG: valid is a file name ending in .svg, or a device or \
                 FIFO such as /dev/stdout)"
            ),
            "{args:?}"
        );
    }
    // No extension at all, and before the work: a map grid too long to tabulate is not reached.
    let bare = dir.path().join("figure");
    let e =
        fails(&["map", "--preload-points", "10000", "--speed-points", "10000", "--plot", bare.to_str().unwrap()], 2);
    assert!(e.starts_with("error: invalid --plot: "), "{e}");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "nothing written");
    // The extension in any case is accepted.
    let upper = dir.path().join("X.SVG");
    ok(&["sweep", "--preload", "1000..1500", "--plot", upper.to_str().unwrap()]);
    assert!(std::fs::read_to_string(&upper).unwrap().contains("<svg"));
}
