// The calculator page: the form, the TOML text and the sweep, over the model's WebAssembly
// module (crates/wasm). The module holds every rule and number; this script moves text in and
// out and draws. Its one call: a JSON request in, a JSON answer out (crates/wasm/src/calls.rs).
//
// A link can drive the page (the tests do): #spec=NAME&set=KEY:VALUE&FLAG_MEMBER=VALUE&run[=N]
// picks a spec to start from, sets form fields as typing would, fills the sweep's flags
// (preload_n, speed_rpm, ...) and presses "Run the sweep".
"use strict";

const engine = { exports: null, encoder: new TextEncoder(), decoder: new TextDecoder() };
const page = { specs: [], origin: "", name: "", edited: false, toml: "", loadMs: NaN, firstSweepMs: NaN };

/// Most points a sweep of this page draws (the command line takes 100000).
const MAX_POINTS = 5000;
const $ = (id) => document.getElementById(id);

/// Instantiates the module from the bytes engine.js carries (a file URL cannot fetch one).
async function loadEngine() {
  if (typeof BALLSCREW_WASM_BASE64 === "undefined") {
    throw new Error("The model's WebAssembly module is not built here: run `bash crates/wasm/build-page.sh` " +
      "from the repository's root, then reload this page.");
  }
  const t0 = performance.now();
  const bytes = Uint8Array.from(atob(BALLSCREW_WASM_BASE64), (c) => c.charCodeAt(0));
  const { instance } = await WebAssembly.instantiate(bytes, {});
  engine.exports = instance.exports;
  return performance.now() - t0;
}

/// One call of the module: the request's JSON in its buffer, the answer's JSON back.
function call(request) {
  const e = engine.exports;
  const bytes = engine.encoder.encode(JSON.stringify(request));
  const at = e.request_buffer(bytes.length);
  new Uint8Array(e.memory.buffer, at, bytes.length).set(bytes);
  const len = e.call();
  return JSON.parse(engine.decoder.decode(new Uint8Array(e.memory.buffer, e.answer(), len)));
}

function clearErrors() {
  document.querySelectorAll(".invalid").forEach((el) => el.classList.remove("invalid"));
  document.querySelectorAll(".field .error").forEach((el) => (el.textContent = ""));
  $("toml-error").textContent = "";
  $("sweep-error").textContent = "";
}

/// Empties the results: they belong to a spec and flags that are no longer the form's.
function clearResults() {
  $("table").textContent = "";
  $("plots").textContent = "";
  $("band-note").textContent = "";
  $("timing").textContent = "";
  delete $("results").dataset.state;
}

/// The spec as edited: from now on the page names it by the file it downloads as (messages and
/// the command line both).
function edited() {
  if (!page.edited) {
    page.edited = true;
    page.origin = page.name.split("/").pop();
  }
}

/// Shows a refusal at the field it names: a spec key's form field, a flag's input, else the
/// TOML text (a syntax error, with its line) or the sweep's own line.
function showError(error) {
  const field = error.field || "";
  const key = document.querySelector(`[data-key="${CSS.escape(field)}"]`);
  const flag = document.querySelector(`[data-flag="${CSS.escape(field)}"]`);
  if (key) {
    key.classList.add("invalid");
    key.closest(".field").querySelector(".error").textContent = error.message;
  } else if (flag) {
    flag.classList.add("invalid");
    $("sweep-error").textContent = error.message;
  } else if (error.line) {
    $("toml").classList.add("invalid");
    $("toml-error").textContent = error.message;
    $("toml-details").open = true;
  } else {
    $("sweep-error").textContent = error.message;
  }
}

/// The form from the TOML text: one field per key it holds, table by table.
function renderForm() {
  clearErrors();
  const a = call({ call: "fields", toml: page.toml, origin: page.origin });
  $("download").href = "data:application/toml;charset=utf-8," + encodeURIComponent(page.toml);
  if (!a.ok) {
    $("form").textContent = "";
    showError(a.error);
    return;
  }
  const form = $("form");
  form.textContent = "";
  const tables = new Map();
  for (const k of a.keys) {
    const [table, name] = [k.key.slice(0, k.key.indexOf(".")), k.key.slice(k.key.indexOf(".") + 1)];
    if (!tables.has(table)) {
      const fs = document.createElement("fieldset");
      const legend = document.createElement("legend");
      legend.textContent = `[${table}]`;
      fs.append(legend);
      form.append(fs);
      tables.set(table, fs);
    }
    const row = document.createElement("div");
    row.className = "field";
    const label = document.createElement("label");
    label.textContent = name;
    const input = document.createElement("input");
    input.dataset.key = k.key;
    input.value = k.value.replace(/^"(.*)"$/, "$1");
    input.id = "key-" + k.key;
    label.htmlFor = input.id;
    input.addEventListener("change", () => setKey(k.key, input.value));
    const hint = document.createElement("span");
    hint.className = "hint";
    hint.textContent = k.comment;
    const error = document.createElement("p");
    error.className = "error";
    row.append(label, input, hint, error);
    tables.get(table).append(row);
  }
  if (a.error) showError(a.error);
  updateCommand();
}

/// A form field typed in: that key of the TOML text set (its comment kept), the spec checked.
function setKey(key, value) {
  clearResults();
  edited();
  const a = call({ call: "set", toml: page.toml, key, value, origin: page.origin });
  if (!a.ok) {
    showError(a.error);
    return;
  }
  page.toml = a.toml;
  $("toml").value = page.toml;
  renderForm();
}

function flagInputs() {
  return [...document.querySelectorAll("[data-flag]")];
}

/// The flag of the swept quantity: the first range among the speed, the axial load and the oil
/// temperature (the command line's order), else the preload.
function sweptFlag(inputs) {
  const value = (flag) => inputs.find((i) => i.dataset.flag === flag);
  const ranged = ["--speed-rpm", "--axial-load-n", "--oil-temperature-c"].map(value).find((i) => i.value.includes(".."));
  return ranged || value("--preload-n");
}

/// The command line that runs the same sweep: each value flag given and the swept one's step
/// (the spec as edited is named by the file it downloads as).
function updateCommand() {
  const spec = page.origin.startsWith("built-in") ? "" : `--spec ${page.origin} `;
  const inputs = flagInputs();
  const swept = sweptFlag(inputs);
  const step = inputs.find((i) => i.dataset.flag === swept.dataset.flag.replace(/-(n|rpm|c)$/, "-step-$1"));
  const flags = inputs
    .filter((i) => (!i.dataset.flag.includes("-step-") && i.value.trim() !== "") || (i === step && i.value.trim() !== ""))
    .map((i) => `${i.dataset.flag} ${i.value.trim()}`);
  const note = page.edited ? `  (the spec as edited: download it as ${page.origin})` : "";
  $("command").textContent = `ballscrew ${spec}sweep ${flags.join(" ")}${note}`;
}

function formatNumber(x) {
  if (x === null) return "n/a";
  if (typeof x !== "number") return String(x);
  if (x === 0 || Number.isInteger(x)) return String(x);
  const a = Math.abs(x);
  return a >= 1e-3 && a < 1e6 ? String(Number(x.toPrecision(6))) : x.toExponential(4);
}

/// The sweep's table: the columns of `ballscrew sweep`, heading and unit, every value with its
/// exact number in data-value.
function renderTable(a) {
  const t = $("table");
  t.textContent = "";
  const head = t.createTHead();
  const names = head.insertRow();
  const units = head.insertRow();
  for (const c of a.columns) {
    const th = document.createElement("th");
    th.textContent = c.head;
    th.dataset.key = c.key;
    names.append(th);
    const tu = document.createElement("th");
    tu.textContent = `[${c.unit}]`;
    units.append(tu);
  }
  const body = t.createTBody();
  for (const r of a.rows) {
    const tr = body.insertRow();
    r.forEach((v, i) => {
      const td = tr.insertCell();
      td.textContent = formatNumber(v);
      td.dataset.key = a.columns[i].key;
      td.dataset.value = v === null ? "" : String(v);
    });
  }
}

const SVG = "http://www.w3.org/2000/svg";
function el(name, attrs, text) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

/// Ticks at round numbers (1, 2 or 5 times a power of ten) over lo..hi, about `n` of them.
function ticks(lo, hi, n) {
  if (!(hi > lo)) return [lo];
  const raw = (hi - lo) / n;
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((k) => k * p).find((s) => s >= raw);
  const out = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) out.push(Number(t.toPrecision(12)));
  return out;
}

/// Axes of a plot: x and y ranges mapped into a w x h box with margins; ticks and labels.
function axes(svg, xs, ys, xLabel, yLabel, w, h, right = 25) {
  const m = { l: 60, r: right, t: 25, b: 40 };
  const [x0, x1] = [Math.min(...xs), Math.max(...xs)];
  const [y0, y1] = [Math.min(0, ...ys), Math.max(...ys) * 1.05 || 1];
  const sx = (x) => m.l + (x1 === x0 ? 0.5 : (x - x0) / (x1 - x0)) * (w - m.l - m.r);
  const sy = (y) => h - m.b - ((y - y0) / (y1 - y0)) * (h - m.t - m.b);
  svg.append(el("line", { x1: m.l, y1: h - m.b, x2: w - m.r, y2: h - m.b, stroke: "#333" }));
  svg.append(el("line", { x1: m.l, y1: m.t, x2: m.l, y2: h - m.b, stroke: "#333" }));
  for (const x of ticks(x0, x1, 5)) {
    svg.append(el("text", { x: sx(x), y: h - m.b + 15, "text-anchor": "middle" }, formatNumber(x)));
  }
  for (const y of ticks(y0, y1, 5)) {
    svg.append(el("line", { x1: m.l - 4, y1: sy(y), x2: m.l, y2: sy(y), stroke: "#333" }));
    svg.append(el("text", { x: m.l - 6, y: sy(y) + 4, "text-anchor": "end" }, formatNumber(y)));
  }
  svg.append(el("text", { x: (m.l + w - m.r) / 2, y: h - 8, "text-anchor": "middle" }, xLabel));
  svg.append(el("text", { x: m.l, y: 15 }, yLabel));
  return { sx, sy };
}

/// The drag torque against the swept quantity with the catalog estimate and its band shaded,
/// as `ballscrew sweep --plot` draws it.
function plotTorque(a) {
  const col = (key) => a.columns.findIndex((c) => c.key === key);
  const [ix, id, ic, il, ih] = [0, col("drag_torque_nm"), col("catalog_nm"), col("catalog_low_nm"), col("catalog_high_nm")];
  const rows = a.rows.filter((r) => r[id] !== null);
  const xs = rows.map((r) => r[ix]);
  const ys = rows.flatMap((r) => [Math.abs(r[id]), r[ih] ?? 0]);
  const [w, h] = [460, 300];
  const svg = el("svg", { width: w, height: h, id: "plot-torque", role: "img" });
  const sw = a.columns[0];
  const { sx, sy } = axes(svg, xs, ys, `${sw.head} [${sw.unit}]`, "drag torque [N m]", w, h);
  const band = rows.map((r) => `${sx(r[ix])},${sy(r[ih])}`).concat(rows.slice().reverse().map((r) => `${sx(r[ix])},${sy(r[il])}`));
  svg.append(el("polygon", { points: band.join(" "), fill: "#f3d9a4", stroke: "none" }));
  const line = (k, color, dash) => el("polyline", {
    points: rows.map((r) => `${sx(r[ix])},${sy(Math.abs(r[k]))}`).join(" "),
    fill: "none", stroke: color, "stroke-width": 2, "stroke-dasharray": dash,
  });
  svg.append(line(ic, "#b07000", "6 4"), line(id, "#1f5fa8", ""));
  svg.append(el("text", { x: w - 200, y: 40, fill: "#1f5fa8" }, "model: drag torque"));
  svg.append(el("text", { x: w - 200, y: 56, fill: "#b07000" }, "catalog, band shaded"));
  return svg;
}

/// Each mechanism's share of the drag torque at each swept value, stacked.
function plotShares(a) {
  const m = a.mechanisms;
  const colors = ["#1f5fa8", "#e08a1e", "#6aa84f", "#b03060", "#7f6aa8", "#888"];
  const [w, h, legend] = [560, 300, 170];
  const svg = el("svg", { width: w, height: h, id: "plot-shares", role: "img" });
  const xs = a.rows.map((r) => r[0]);
  const sw = a.columns[0];
  const { sx, sy } = axes(svg, xs, [1 / 1.05], `${sw.head} [${sw.unit}]`, "share of the drag torque", w, h, legend);
  const n = a.rows.length;
  const bar = Math.max(2, ((w - 60 - legend) / Math.max(n, 1)) * 0.8);
  m.rows.forEach((parts, i) => {
    const total = parts.reduce((s, v) => s + Math.abs(v ?? 0), 0) || 1;
    let acc = 0;
    parts.forEach((v, k) => {
      const share = Math.abs(v ?? 0) / total;
      svg.append(el("rect", { x: sx(xs[i]) - bar / 2, y: sy(acc + share), width: bar, height: sy(acc) - sy(acc + share), fill: colors[k] }));
      acc += share;
    });
  });
  m.columns.forEach((c, k) => {
    svg.append(el("rect", { x: w - legend + 25, y: 40 + 18 * k, width: 10, height: 10, fill: colors[k] }));
    svg.append(el("text", { x: w - legend + 40, y: 49 + 18 * k }, c.label.trim().replace(/^of which /, "").replace(/ \(.*\)$/, "")));
  });
  return svg;
}

/// Runs the sweep of the form's spec and flags; the results, or the refusal at its field.
function runSweep() {
  clearErrors();
  clearResults();
  updateCommand();
  const request = { call: "sweep", toml: page.toml, origin: page.origin, max_points: MAX_POINTS };
  for (const i of flagInputs()) request[i.dataset.member] = i.value.trim();
  const t0 = performance.now();
  const a = call(request);
  const ms = performance.now() - t0;
  const results = $("results");
  if (!a.ok) {
    showError(a.error);
    results.dataset.state = "error";
    return;
  }
  $("band-note").textContent = a.band_note;
  renderTable(a);
  $("plots").replaceChildren(plotTorque(a), plotShares(a));
  const timing = $("timing");
  // The first sweep runs in the browser's baseline code, later ones in its optimised code.
  if (Number.isNaN(page.firstSweepMs)) page.firstSweepMs = ms;
  timing.dataset.loadMs = page.loadMs.toFixed(1);
  timing.dataset.firstSweepMs = page.firstSweepMs.toFixed(1);
  timing.dataset.sweepMs = ms.toFixed(1);
  timing.textContent = `Module loaded in ${page.loadMs.toFixed(0)} ms; ${a.rows.length} points in ` +
    `${ms.toFixed(1)} ms (the first sweep: ${page.firstSweepMs.toFixed(1)} ms).`;
  results.dataset.state = "done";
}

function startFrom(name) {
  const s = page.specs.find((x) => x.name === name) || page.specs[0];
  $("start").value = s.name;
  clearResults();
  page.name = s.name;
  page.origin = s.name;
  page.edited = false;
  page.toml = s.toml;
  $("toml").value = page.toml;
  $("download").download = s.name.split("/").pop();
  renderForm();
}

/// A link's instructions (see the top of this file).
function followLink() {
  const params = new URLSearchParams(location.hash.slice(1));
  if (params.has("spec")) startFrom(params.get("spec"));
  for (const s of params.getAll("set")) {
    const at = s.indexOf(":");
    const key = s.slice(0, at);
    const input = document.querySelector(`[data-key="${CSS.escape(key)}"]`);
    if (!input) {
      showError({ message: `the link sets ${key}, which this spec does not hold (add it in the TOML text)` });
      return;
    }
    input.value = s.slice(at + 1);
    input.dispatchEvent(new Event("change"));
  }
  for (const i of flagInputs()) {
    if (params.has(i.dataset.member)) i.value = params.get(i.dataset.member);
  }
  // run=N presses the button N times (the times of a first and of a later sweep).
  if (params.has("run")) {
    for (let k = 0; k < Math.max(1, Number(params.get("run")) || 1); k++) $("run").click();
  }
}

async function main() {
  try {
    page.loadMs = await loadEngine();
  } catch (e) {
    $("status").textContent = e.message;
    $("status").className = "error";
    return;
  }
  const a = call({ call: "start" });
  page.specs = a.specs.map((s) => ({ ...s }));
  if (typeof BALLSCREW_INIT_TEMPLATE !== "undefined") {
    page.specs.push({ name: "my_screw.toml", label: "ballscrew init (32 x 10 double nut, 6.35 mm balls)", toml: BALLSCREW_INIT_TEMPLATE });
  }
  for (const s of page.specs) {
    const o = document.createElement("option");
    o.value = s.name;
    o.textContent = s.label || s.name;
    $("start").append(o);
  }
  $("start").addEventListener("change", () => startFrom($("start").value));
  let typing;
  $("toml").addEventListener("input", () => {
    clearTimeout(typing);
    typing = setTimeout(() => {
      clearResults();
      edited();
      page.toml = $("toml").value;
      renderForm();
    }, 300);
  });
  flagInputs().forEach((i) =>
    i.addEventListener("change", () => {
      clearResults();
      updateCommand();
    }),
  );
  // The chapter that explains the page: the book's page, or the Markdown in a checkout.
  $("about").href = location.pathname.endsWith("/docs/calculator/index.html") ? "../calculator.md" : "../calculator.html";
  $("run").addEventListener("click", runSweep);
  startFrom(page.specs[0].name);
  $("status").textContent = `Model ${a.version} loaded in ${page.loadMs.toFixed(0)} ms.`;
  followLink();
  document.body.dataset.ready = "yes";
}

main();
