//! The page's calls: a JSON request in, a JSON answer out (see the crate's documentation).
//!
//! Every answer is an object with `ok`; a refused request has `ok: false` and `error`:
//! `message` (the command line's text), `field` (the spec key or the flag it names, else
//! null), and for a TOML syntax error its `line` and `column`.

use ballscrew_batch::quantities::{EFFICIENCY, MECHANISMS, SWEEP, Swept};
use ballscrew_batch::sweep::{
    DEFAULT_SWEEP_FROM_N, DEFAULT_SWEEP_STEP_N, DEFAULT_SWEEP_TO_N, RangeText, RowError, SweepEnd, SweepPoint,
    SweepRange, SweepRow, band_note, sweep,
};
use ballscrew_batch::{Errors, Never, Value};
use ballscrew_config::{BUILTIN_ORIGIN, ConfigError, DKFZD4012_TOML, spec_from_toml_str};
use ballscrew_core::input::{Lubrication, rpm_to_rad_s};
use ballscrew_core::screw::catalog::BAND_RELATIVE;
use ballscrew_core::{Error, Invalid, Model, OperatingPoint, ScrewSpec, Short};
use serde_json::{Map, Value as Json, json};

/// The specs shipped in `configs/`, by file name, as the page offers them to start from.
pub const SHIPPED: [(&str, &str); 4] = [
    ("configs/dkfzd4012.toml", DKFZD4012_TOML),
    ("configs/dkfzd4012-dry.toml", include_str!("../../../configs/dkfzd4012-dry.toml")),
    ("configs/single-nut-16x5.toml", include_str!("../../../configs/single-nut-16x5.toml")),
    ("configs/xjtu-32x8.toml", include_str!("../../../configs/xjtu-32x8.toml")),
];

/// A refused request: the message as the command line prints it (without its `error: `), the key
/// or flag it names.
#[derive(Debug, Clone, PartialEq)]
pub struct Refusal {
    /// The message.
    pub message: String,
    /// The spec key (`geometry.lead_mm`) or the flag (`--speed-rpm`) the message is about.
    pub field: Option<String>,
    /// Line and column (1-based) of a TOML syntax or shape error.
    pub at: Option<(usize, usize)>,
}

impl Refusal {
    fn new(message: String, field: Option<&str>) -> Self {
        Self { message, field: field.map(str::to_string), at: None }
    }

    fn json(&self) -> Json {
        let mut e = Map::new();
        e.insert("message".into(), self.message.clone().into());
        e.insert("field".into(), self.field.clone().map_or(Json::Null, Json::from));
        if let Some((line, column)) = self.at {
            e.insert("line".into(), line.into());
            e.insert("column".into(), column.into());
        }
        json!({ "ok": false, "error": e })
    }
}

/// Answers one request (see the module docs); never panics on any text.
pub fn handle(request: &str) -> String {
    let answer = match serde_json::from_str::<Json>(request) {
        Ok(r) => match r.get("call").and_then(Json::as_str) {
            Some("start") => Ok(start()),
            Some("fields") => fields(text(&r, "toml").unwrap_or(DKFZD4012_TOML), origin(&r)),
            Some("set") => set(
                text(&r, "toml").unwrap_or(DKFZD4012_TOML),
                text(&r, "key").unwrap_or(""),
                text(&r, "value").unwrap_or(""),
                origin(&r),
            ),
            Some("sweep") => sweep_call(&r),
            other => Err(Refusal::new(
                format!("unknown call {other:?} (valid: \"start\", \"fields\", \"set\", \"sweep\")"),
                None,
            )),
        },
        Err(e) => Err(Refusal::new(format!("the request is not JSON: {e}"), None)),
    };
    answer.unwrap_or_else(|e| e.json()).to_string()
}

/// A string member of the request (absent, null or empty: `None`).
fn text<'a>(r: &'a Json, key: &str) -> Option<&'a str> {
    r.get(key).and_then(Json::as_str).filter(|s| !s.trim().is_empty())
}

/// Where the spec's text came from, for its messages (the command line names the file).
fn origin(r: &Json) -> &str {
    text(r, "origin").unwrap_or(BUILTIN_ORIGIN)
}

/// The specs to start from: the shipped ones.
fn start() -> Json {
    let specs: Vec<Json> = SHIPPED.iter().map(|(name, toml)| json!({ "name": name, "toml": toml })).collect();
    json!({ "ok": true, "specs": specs, "version": env!("CARGO_PKG_VERSION"), "catalog_band_relative": BAND_RELATIVE })
}

/// The spec of `toml`, validated as `ballscrew --spec` reads a file named `origin`.
pub fn spec(toml: &str, origin: &str) -> Result<ScrewSpec, Refusal> {
    spec_from_toml_str(toml, origin).map_err(|e| match &e {
        // A parse error names the file, its line and column already (as the command line prints it).
        // A wrong type or an unknown option is at the field of the key on that line, if any.
        ConfigError::Parse { line, column, .. } => {
            Refusal { message: e.to_string(), field: key_at(toml, *line), at: Some((*line, *column)) }
        }
        ConfigError::Invalid { field, .. } | ConfigError::Missing { field, .. } => {
            Refusal::new(format!("{origin}: {e}"), Some(field))
        }
        _ => Refusal::new(format!("{origin}: {e}"), None),
    })
}

/// The key (`table.key`) written on 1-based line `line` of `toml`, if that line holds one.
fn key_at(toml: &str, line: usize) -> Option<String> {
    let mut table = "";
    for (i, text) in toml.lines().enumerate() {
        let t = text.split('#').next().unwrap_or("").trim();
        if t.starts_with('[') && !t.starts_with("[[") {
            table = t.trim_start_matches('[').trim_end_matches(']').trim();
        }
        if i + 1 == line {
            let (key, _) = t.split_once('=')?;
            let key = key.trim().trim_matches('"');
            return (!key.is_empty() && !table.is_empty()).then(|| format!("{table}.{key}"));
        }
    }
    None
}

/// The error of a text that is not TOML, as the command line gives it (the file, the line and
/// the column), from the spec parser the command line uses.
fn syntax_error(toml: &str, origin: &str, e: &toml_edit::TomlError) -> Refusal {
    match spec(toml, origin) {
        Err(r) => r,
        // Not expected: the two parsers read the same TOML.
        Ok(_) => {
            let at = e.span().map(|s| line_column(toml, s.start));
            let (line, column) = at.unwrap_or((1, 1));
            Refusal { message: format!("{origin}:{line}:{column}: {}", e.message()), field: None, at }
        }
    }
}

/// The keys of `toml`, table by table (`table.key`, the value as written, its comment), and
/// whether the spec is valid (its error if not).
fn fields(toml: &str, origin: &str) -> Result<Json, Refusal> {
    let doc: toml_edit::DocumentMut = toml.parse().map_err(|e| syntax_error(toml, origin, &e))?;
    let mut keys = Vec::new();
    for (table, item) in doc.iter() {
        let Some(t) = item.as_table_like() else { continue };
        for (key, value) in t.iter() {
            let Some(v) = value.as_value() else { continue };
            let comment = v.decor().suffix().and_then(|s| s.as_str()).map_or("", str::trim);
            let comment = comment.trim_start_matches('#').trim();
            keys.push(json!({
                "key": format!("{table}.{key}"),
                "value": v.clone().decorated("", "").to_string(),
                "comment": comment,
            }));
        }
    }
    let error = spec(toml, origin).err().map_or(Json::Null, |e| e.json()["error"].clone());
    Ok(json!({ "ok": true, "keys": keys, "error": error }))
}

/// 1-based line and column (in characters) of byte `at` of `text`.
fn line_column(text: &str, at: usize) -> (usize, usize) {
    let before = text.get(..at).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// `toml` with `key` (`table.key`) set to `value` as typed: a TOML value (a number, `true`, a
/// quoted string), else the text as a string (an option's name); its comment and the rest of
/// the text kept.
fn set(toml: &str, key: &str, value: &str, origin: &str) -> Result<Json, Refusal> {
    let mut doc: toml_edit::DocumentMut = toml.parse().map_err(|e| syntax_error(toml, origin, &e))?;
    let Some((table, name)) = key.split_once('.') else {
        return Err(Refusal::new(format!("invalid key {key:?} (valid: table.key, e.g. geometry.lead_mm)"), None));
    };
    let typed = value.trim();
    let mut new: toml_edit::Value = typed.parse().unwrap_or_else(|_| toml_edit::Value::from(typed));
    if !doc.contains_key(table) {
        doc.insert(table, toml_edit::table());
    }
    let Some(t) = doc.get_mut(table).and_then(toml_edit::Item::as_table_like_mut) else {
        return Err(Refusal::new(format!("{table} is not a table"), Some(key)));
    };
    match t.get_mut(name).and_then(toml_edit::Item::as_value_mut) {
        Some(old) => {
            let decor = old.decor().clone();
            *new.decor_mut() = decor;
            *old = new;
        }
        None => {
            t.insert(name, toml_edit::value(new));
        }
    }
    Ok(json!({ "ok": true, "toml": doc.to_string() }))
}

/// A flag's text (`preload_n` for `--preload-n`), as the page's field holds it.
fn flag_text(r: &Json, member: &str) -> Option<RangeText> {
    match r.get(member) {
        Some(Json::String(s)) if !s.trim().is_empty() => Some(RangeText::from(s.clone())),
        Some(Json::Number(n)) => Some(RangeText::from(n.to_string())),
        _ => None,
    }
}

/// A step flag's value (absent: `default`).
fn step(r: &Json, member: &str, flag: &str, default: f64) -> Result<f64, Refusal> {
    match r.get(member) {
        None | Some(Json::Null) => Ok(default),
        Some(Json::Number(n)) => Ok(n.as_f64().unwrap_or(f64::NAN)),
        Some(Json::String(s)) if s.trim().is_empty() => Ok(default),
        Some(Json::String(s)) => s
            .trim()
            .parse()
            .map_err(|_| Refusal::new(format!("invalid value '{s}' for '{flag}': invalid float literal"), Some(flag))),
        Some(other) => Err(Refusal::new(format!("invalid value '{other}' for '{flag}'"), Some(flag))),
    }
}

/// A single value of a flag (`None`: not given), or its error.
fn single(flag: &str, t: &Option<RangeText>, valid: &str) -> Result<Option<f64>, Refusal> {
    t.as_ref()
        .map(|t| t.ends(flag, true, |a, b| a == b, valid).map(|(a, _)| a))
        .transpose()
        .map_err(|e| Refusal::new(e.to_string(), Some(flag)))
}

/// The sweep `ballscrew [--spec FILE] sweep` runs with the request's flags: the same checks in
/// the same order, the same points, [`sweep`] itself.
fn sweep_call(r: &Json) -> Result<Json, Refusal> {
    let origin = origin(r);
    let spec = match text(r, "toml") {
        Some(t) => spec(t, origin)?,
        None => spec(DKFZD4012_TOML, BUILTIN_ORIGIN)?,
    };
    let model = Model::new(&spec).map_err(|e| Refusal::new(format!("{origin}: {e}"), None))?;
    let preload = flag_text(r, "preload_n");
    let speed = flag_text(r, "speed_rpm");
    let axial = flag_text(r, "axial_load_n");
    let temperature = flag_text(r, "oil_temperature_c");
    let is_range = |t: &Option<RangeText>| t.as_ref().is_some_and(RangeText::is_range);
    let ranges: Vec<&str> = [
        ("--preload-n", &preload),
        ("--speed-rpm", &speed),
        ("--axial-load-n", &axial),
        ("--oil-temperature-c", &temperature),
    ]
    .iter()
    .filter(|(_, t)| is_range(t))
    .map(|(f, _)| *f)
    .collect();
    if ranges.len() > 1 {
        return Err(Refusal::new(
            format!("one quantity at a time: {} are all ranges (give the others a single value)", ranges.join(" and ")),
            Some(ranges[1]),
        ));
    }
    if temperature.is_some() && spec.model.lubrication == Lubrication::Dry {
        return Err(Refusal::new(
            "--oil-temperature-c needs the lubricated model: the spec has lubrication = \"dry\", which has no oil \
             (set [model] lubrication = \"ehl\")"
                .to_string(),
            Some("--oil-temperature-c"),
        ));
    }
    let swept = if is_range(&speed) {
        Swept::Speed
    } else if is_range(&axial) {
        Swept::AxialLoad
    } else if is_range(&temperature) {
        Swept::OilTemperature
    } else {
        Swept::Preload
    };
    let speed_v = single("--speed-rpm", &speed, "a number in rpm, or A..B with A <= B");
    let temperature_v = single("--oil-temperature-c", &temperature, "a number in degrees C, or A..B with A <= B");
    let preload_v = single("--preload-n", &preload, "A..B with A <= B, or a single value, in N");
    let axial_v = single("--axial-load-n", &axial, "a number in N, or A..B with A <= B");
    let flags = swept.flags();
    let (text, step) = match swept {
        Swept::Preload => (
            preload.clone().unwrap_or_else(|| RangeText::from(format!("{DEFAULT_SWEEP_FROM_N}..{DEFAULT_SWEEP_TO_N}"))),
            step(r, "preload_step_n", flags.step, DEFAULT_SWEEP_STEP_N)?,
        ),
        Swept::Speed => (speed.clone().unwrap_or_default(), step(r, "speed_step_rpm", flags.step, 100.0)?),
        Swept::AxialLoad => (axial.clone().unwrap_or_default(), step(r, "axial_load_step_n", flags.step, 500.0)?),
        Swept::OilTemperature => {
            (temperature.clone().unwrap_or_default(), step(r, "oil_temperature_step_c", flags.step, 5.0)?)
        }
    };
    // The checks in the command line's order: the swept range, then each single value.
    let range = SweepRange::from_flags(&text, step, &flags).map_err(|e| {
        let field = match &e {
            ballscrew_batch::SweepError::Invalid { flag, .. } => flag.clone(),
            ballscrew_batch::SweepError::TooManyPoints { .. } => flags.range.to_string(),
        };
        Refusal::new(e.to_string(), Some(&field))
    })?;
    let values = range.points();
    // The page's own limit (it draws every point): the request's `max_points`.
    if let Some(max) = r.get("max_points").and_then(Json::as_u64).map(|m| m as usize)
        && values.len() > max
    {
        return Err(Refusal::new(
            format!(
                "{} {} with {} {} gives {} points: this page draws at most {max} (use a larger step, or `ballscrew sweep`, \
                 which takes {})",
                flags.range,
                text,
                flags.step,
                Short(step),
                values.len(),
                ballscrew_batch::MAX_SWEEP_POINTS
            ),
            Some(flags.range),
        ));
    }
    let (speed_v, preload_v, axial_v, temperature_v) = match swept {
        Swept::Preload => (speed_v?, None, axial_v?, temperature_v?),
        Swept::Speed => (None, preload_v?, axial_v?, temperature_v?),
        Swept::AxialLoad => (speed_v?, preload_v?, None, temperature_v?),
        Swept::OilTemperature => (speed_v?, preload_v?, axial_v?, None),
    };
    let mut ops = Vec::with_capacity(values.len());
    let mut models = Vec::with_capacity(values.len());
    for &x in &values {
        let input = [
            ("speed_rad_s", "--speed-rpm", if swept == Swept::Speed { Some(x) } else { speed_v }),
            ("preload_n", "--preload-n", if swept == Swept::Preload { Some(x) } else { preload_v }),
            ("axial_load_n", "--axial-load-n", if swept == Swept::AxialLoad { Some(x) } else { axial_v }),
        ];
        let d = spec.operating;
        let op = OperatingPoint {
            speed_rad_s: input[0].2.map_or(d.speed_rad_s, rpm_to_rad_s),
            preload_n: input[1].2.unwrap_or(d.preload_n),
            axial_load_n: input[2].2.unwrap_or(d.axial_load_n),
        };
        op.validate().map_err(|e| match input.iter().find(|(field, _, _)| *field == e.field) {
            Some((_, flag, Some(v))) => {
                Refusal::new(Invalid { field: flag, value: *v, valid: e.valid }.to_string(), Some(flag))
            }
            _ => Refusal::new(e.to_string(), None),
        })?;
        ops.push(op);
        let t = if swept == Swept::OilTemperature { Some(x) } else { temperature_v };
        models.push(match t {
            Some(t) => Some(model_at(&spec, t, origin)?),
            None => None,
        });
    }
    let points: Vec<SweepPoint<'_>> =
        ops.iter().zip(&models).map(|(&op, m)| SweepPoint { op, model: m.as_ref().unwrap_or(&model) }).collect();
    let rows = sweep(&points, 1, &Never, Errors::Raise, &mut |_, _| {}).map_err(|end| {
        let at = |i: usize| format!("at {} {} {}", swept.quantity().label, Short(values[i]), swept.quantity().unit);
        match end {
            SweepEnd::Point { index, error: RowError::Summary(e) } => Refusal::new(eval_message(&at(index), &e), None),
            SweepEnd::Point { index, error: RowError::Efficiency(e) } => {
                Refusal::new(eval_message(&format!("efficiency {}", at(index)), &e), None)
            }
            SweepEnd::Stopped => Refusal::new("the sweep was stopped".to_string(), None),
            SweepEnd::OutOfMemory { bytes } => {
                Refusal::new(format!("sweep: {}", ballscrew_batch::BatchError::OutOfMemory { bytes }), None)
            }
            SweepEnd::Internal(m) => Refusal::new(format!("sweep: {m}"), None),
        }
    })?;
    let rows: Vec<SweepRow> = rows.into_iter().flatten().collect();
    Ok(table(swept, spec.model.lubrication, &rows))
}

/// The model of `spec` with the oil at `temperature_c` at the contacts, or the command line's
/// error for it.
fn model_at(spec: &ScrewSpec, temperature_c: f64, origin: &str) -> Result<Model, Refusal> {
    let mut s = *spec;
    s.lubricant.temperature_c = temperature_c;
    Model::new(&s).map_err(|e| match e {
        Error::Input(i) if i.field == "lubricant.temperature_c" => Refusal::new(
            Invalid { field: "--oil-temperature-c", value: temperature_c, valid: i.valid }.to_string(),
            Some("--oil-temperature-c"),
        ),
        e => Refusal::new(eval_message(origin, &e), None),
    })
}

/// The command line's message of an evaluation that failed `at` a point.
fn eval_message(at: &str, e: &Error) -> String {
    format!("{at}: {e}")
}

/// A reported value as JSON (a number that is not finite: null, as undefined).
fn value(v: Value) -> Json {
    match v {
        Value::Num(x) if x.is_finite() => json!(x),
        Value::Num(_) => Json::Null,
        Value::Int(n) => json!(n),
        Value::Text(t) => json!(t),
    }
}

/// The columns of `ballscrew sweep`'s CSV and JSON (the swept quantity, the ones held, the
/// torques, the efficiency), each with its heading and unit, and the rows.
fn table(swept: Swept, lubrication: Lubrication, rows: &[SweepRow]) -> Json {
    let held = swept.held(lubrication);
    let mut columns = Vec::new();
    let column = |q_key: &str, head: &str, unit: &str| json!({ "key": q_key, "head": head, "unit": unit });
    columns.push(column(swept.quantity().key, swept.quantity().head, swept.quantity().unit));
    columns.extend(held.iter().map(|q| column(q.key, q.head, q.unit)));
    columns.extend(SWEEP.iter().map(|q| column(q.key, q.head, q.unit)));
    columns.extend(EFFICIENCY.iter().map(|q| column(q.key, q.head, q.unit)));
    let body: Vec<Json> = rows
        .iter()
        .map(|r| {
            let mut line = vec![value((swept.quantity().get)(r))];
            line.extend(held.iter().map(|q| value((q.get)(r))));
            line.extend(SWEEP.iter().map(|q| value((q.get)(&r.summary))));
            line.extend(EFFICIENCY.iter().map(|q| value((q.get)(&r.efficiency))));
            Json::Array(line)
        })
        .collect();
    let shares: Vec<Json> =
        rows.iter().map(|r| Json::Array(MECHANISMS.iter().map(|q| value((q.get)(&r.summary))).collect())).collect();
    json!({
        "ok": true,
        "swept": swept.quantity().key,
        "columns": columns,
        "rows": body,
        "band_note": band_note(rows, swept.values()),
        "mechanisms": {
            "columns": MECHANISMS.iter().map(|q| json!({ "key": q.key, "label": q.label, "unit": q.unit })).collect::<Vec<_>>(),
            "rows": shares,
        },
        "catalog_band_relative": BAND_RELATIVE,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(request: Json) -> Json {
        serde_json::from_str(&handle(&request.to_string())).unwrap()
    }

    #[test]
    fn a_bad_key_is_refused_at_its_field_with_the_parsers_message() {
        let bad = DKFZD4012_TOML.replace("lead_mm = 12.0", "lead_mm = -12.0");
        let a = call(json!({ "call": "sweep", "toml": bad, "origin": "my.toml" }));
        assert_eq!(a["ok"], false);
        assert_eq!(a["error"]["field"], "geometry.lead_mm");
        let want = format!("my.toml: {}", spec_from_toml_str(&bad, "my.toml").unwrap_err());
        assert_eq!(a["error"]["message"], want.as_str());
    }

    /// A value of the wrong type, or an option that does not exist, is refused at its key.
    #[test]
    fn a_wrong_type_or_option_is_refused_at_its_key() {
        for (key, value) in [("geometry.lead_mm", "12abc"), ("model.lubrication", "wet")] {
            let set = call(json!({ "call": "set", "toml": DKFZD4012_TOML, "key": key, "value": value }));
            let a = call(json!({ "call": "sweep", "toml": set["toml"], "origin": "t.toml" }));
            assert_eq!(a["error"]["field"], key, "{a}");
            assert!(a["error"]["message"].as_str().unwrap().starts_with("t.toml:"), "{a}");
        }
    }

    /// The page's limit on the points it draws names the range flag.
    #[test]
    fn the_pages_limit_on_points_names_the_range() {
        let a = call(json!({ "call": "sweep", "preload_n": "0..10000", "preload_step_n": 1, "max_points": 5000 }));
        assert_eq!(a["error"]["field"], "--preload-n", "{a}");
        assert!(a["error"]["message"].as_str().unwrap().contains("gives 10001 points"), "{a}");
        let a = call(json!({ "call": "sweep", "preload_n": "500..1000", "preload_step_n": 500, "max_points": 5000 }));
        assert_eq!(a["ok"], true);
    }

    #[test]
    fn a_flag_out_of_range_is_refused_at_the_flag() {
        let a = call(json!({ "call": "sweep", "speed_rpm": "1e9" }));
        assert_eq!(a["error"]["field"], "--speed-rpm", "{a}");
        assert!(a["error"]["message"].as_str().unwrap().starts_with("invalid --speed-rpm: "), "{a}");
        let a = call(json!({ "call": "sweep", "preload_n": "3000..500" }));
        assert_eq!(a["error"]["field"], "--preload-n", "{a}");
        let a = call(json!({ "call": "sweep", "preload_n": "500..3000", "speed_rpm": "10..20" }));
        assert_eq!(a["ok"], false, "{a}");
    }

    /// Every mechanism of `ballscrew torque`'s "of which" rows is in the answer, and they add up
    /// to the dissipation less the seals' (which the summary gives apart).
    #[test]
    fn the_mechanisms_are_the_torque_summarys() {
        let a = call(json!({ "call": "sweep", "preload_n": "2000" }));
        let m = &a["mechanisms"];
        assert_eq!(m["columns"].as_array().unwrap().len(), MECHANISMS.len(), "{m}");
        assert_eq!(m["columns"][0]["key"], "creep_torque_nm");
        let parts: f64 = m["rows"][0].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).sum();
        let cols = a["columns"].as_array().unwrap();
        let drag = cols.iter().position(|c| c["key"] == "drag_torque_nm").unwrap();
        let drag = a["rows"][0][drag].as_f64().unwrap();
        assert!((parts - drag).abs() <= 1e-9 * drag, "{parts} against {drag}");
    }

    #[test]
    fn set_changes_one_key_and_keeps_the_comments() {
        let a = call(json!({ "call": "set", "toml": DKFZD4012_TOML, "key": "geometry.lead_mm", "value": "10" }));
        let toml = a["toml"].as_str().unwrap();
        assert!(toml.contains("lead_mm = 10 "), "{toml}");
        assert!(toml.contains("# Table 1: helical pitch (lead) L = 12 mm"), "{toml}");
        assert_eq!(spec_from_toml_str(toml, "t").unwrap().geometry.lead_m, 0.010);
        let a = call(json!({ "call": "set", "toml": DKFZD4012_TOML, "key": "model.lubrication", "value": "dry" }));
        let s = spec_from_toml_str(a["toml"].as_str().unwrap(), "t").unwrap();
        assert_eq!(s.model.lubrication, Lubrication::Dry);
    }

    #[test]
    fn fields_list_the_keys_with_their_values_and_comments() {
        let a = call(json!({ "call": "fields", "toml": DKFZD4012_TOML }));
        let keys = a["keys"].as_array().unwrap();
        let lead = keys.iter().find(|k| k["key"] == "geometry.lead_mm").unwrap();
        assert_eq!(lead["value"], "12.0");
        assert!(lead["comment"].as_str().unwrap().starts_with("Table 1"));
        assert!(a["error"].is_null());
        // A syntax error: the command line's message, with the file, line and column.
        let a = call(json!({ "call": "fields", "toml": "[geometry\nx = 1", "origin": "s.toml" }));
        assert_eq!(a["ok"], false);
        assert!(a["error"]["message"].as_str().unwrap().starts_with("s.toml:1:"), "{a}");
        let a = call(
            json!({ "call": "set", "toml": "[geometry\nx = 1", "origin": "s.toml", "key": "geometry.x", "value": "2" }),
        );
        assert!(a["error"]["message"].as_str().unwrap().starts_with("s.toml:1:"), "{a}");
        assert_eq!(a["error"]["line"], 1, "{a}");
    }

    #[test]
    fn the_start_offers_every_shipped_spec_and_each_is_valid() {
        let a = call(json!({ "call": "start" }));
        assert_eq!(a["specs"].as_array().unwrap().len(), SHIPPED.len());
        for (name, toml) in SHIPPED {
            assert!(spec_from_toml_str(toml, name).is_ok(), "{name}");
        }
        assert_eq!(call(json!({ "call": "nothing" }))["ok"], false);
        assert_eq!(serde_json::from_str::<Json>(&handle("not json")).unwrap()["ok"], false);
    }
}
