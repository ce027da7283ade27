// The calculator page, generated from GET /api/v1/models: no per-model HTML.
//
// Values travel to the API as unit strings ("45 mm", "1450 rpm"), which the
// server parses exactly; the unit table (units.json) is used only to convert a
// field when its unit selector changes, to check ranges before submitting, and
// to show results in each output's display unit. Everything the page knows
// about a model comes from the catalogue entry, so a newly registered model
// appears here without any change to this file.

const API = "api/v1";
const uPlot = window.uPlot;

const state = {
  models: [], // catalogue entries
  units: {}, // normalised SI unit -> [[label, api, factor], ...]
  model: null, // the catalogue entry shown
  lastRequest: null, // body of the last evaluation POST
  lastResponse: null, // its JSON answer (status 200 only)
  lastSweep: null, // {request, response}
  charts: [], // uPlot instances to destroy on re-render
  example: "0", // the example (or "defaults") the form was loaded with
  sweepParams: null, // the last sweep's settings, kept in the address bar
  seq: 0, // answers to an older request than the latest are dropped
  sweepSeq: 0,
};
window.calcState = state; // for the browser test and for curious users in the console

// ---------------------------------------------------------------- helpers

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === null || v === undefined || v === false) continue;
    if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v === true ? "" : v);
  }
  for (const c of children.flat()) if (c !== null && c !== undefined) e.append(c);
  return e;
}

/** Unit expressions compared loosely: "N·m" == "N*m", "kg·m²" == "kg*m^2", "µm" == "um". */
function norm(unit) {
  return String(unit ?? "")
    .replaceAll("·", "*").replaceAll("**", "^").replaceAll("²", "^2").replaceAll("³", "^3")
    .replaceAll("⁴", "^4").replaceAll("µ", "u").replaceAll("μ", "u").replace(/\s+/g, "");
}

/** Pretty SI unit for display: "kg*m^2" -> "kg·m²", "1" -> "". */
function pretty(unit) {
  if (!unit || unit === "1") return "";
  return unit.replaceAll("*", "·").replaceAll("^2", "²").replaceAll("^3", "³").replaceAll("^4", "⁴")
    .replaceAll("^-1", "⁻¹");
}

/**
 * The unit choices for an SI unit, display unit first: [{label, api, factor}].
 * Unknown SI units get one choice, the SI unit itself (the API still parses it).
 */
function unitChoices(si, display) {
  const table = state.units[norm(si)];
  let choices = table
    ? table.map(([label, api, factor]) => ({ label, api, factor }))
    : [{ label: pretty(si), api: "", factor: 1 }]; // unknown unit: send plain SI numbers
  if (norm(si) === "1" && norm(display) !== "%") choices = choices.filter((c) => c.api !== "%");
  const want = norm(display || si);
  const i = choices.findIndex((c) => norm(c.label) === want || norm(c.api) === want);
  if (i > 0) choices = [choices[i], ...choices.slice(0, i), ...choices.slice(i + 1)];
  else if (i < 0) {
    // display unit unknown to the table: fall back to SI (exact, if less friendly)
    const s = choices.findIndex((c) => c.factor === 1);
    if (s > 0) choices = [choices[s], ...choices.slice(0, s), ...choices.slice(s + 1)];
  }
  return choices;
}

/**
 * A number written into a text field. Loaded values (sent as their exact SI
 * value until edited) show 7 significant figures; a typed value converted to
 * another unit keeps 10, enough to give the same answer.
 */
function fieldNumber(x, sig = 10) {
  if (!Number.isFinite(x)) return "";
  return String(Number(x.toPrecision(sig)));
}

/** Significant figures a result deserves, from its relative error estimate. */
function sigFigs(err) {
  if (err === null || err === undefined || !(err > 0)) return 4;
  return Math.min(6, Math.max(3, Math.ceil(-Math.log10(err)) + 1));
}

function fmt(x, sig = 4) {
  if (x === null || x === undefined) return "—";
  if (typeof x === "boolean") return x ? "yes" : "no";
  if (typeof x !== "number") return String(x);
  if (x === 0) return "0";
  const a = Math.abs(x);
  if (a >= 1e6 || a < 1e-3) return x.toExponential(sig - 1).replace("e+", "e");
  const p = x.toPrecision(sig);
  return p.includes("e") ? String(Number(p)) : p;
}

/** A limit or default in words: a few significant figures, no trailing zeros. */
function short(x, sig = 6) {
  if (x === 0) return "0";
  const a = Math.abs(x);
  if (a >= 1e6 || a < 1e-4) return x.toExponential(sig - 1).replace(/\.?0+e/, "e").replace("e+", "e");
  return String(Number(x.toPrecision(sig)));
}

function fmtError(err) {
  if (err === null || err === undefined) return "not known";
  const pct = err * 100;
  if (pct < 1e-4) return "< 0.0001 %";
  return "±" + short(pct, 2) + " %";
}

function fmtTime(s) {
  if (s < 1e-3) return fmt(s * 1e6, 3) + " µs";
  if (s < 1) return fmt(s * 1e3, 3) + " ms";
  return fmt(s, 3) + " s";
}

// ---------------------------------------------------------------- start-up

async function init() {
  const [models, units] = await Promise.all([
    fetch(API + "/models").then((r) => r.json()),
    fetch("units.json").then((r) => r.json()),
  ]);
  state.models = models.models;
  for (const [si, choices] of Object.entries(units)) if (!si.startsWith("_")) state.units[norm(si)] = choices;
  renderNav();
  window.addEventListener("hashchange", () => route());
  await route();
  document.body.dataset.ready = "1";
}

function renderNav() {
  const nav = document.getElementById("models");
  const families = new Map();
  for (const m of state.models) {
    if (!families.has(m.family)) families.set(m.family, []);
    families.get(m.family).push(m);
  }
  nav.replaceChildren();
  if (!state.models.length) nav.append(el("p", { class: "muted" }, "No models are registered."));
  for (const [family, ms] of families) {
    nav.append(el("h2", {}, family));
    for (const m of ms) {
      nav.append(el("a", { href: "#m=" + encodeURIComponent(m.name), "data-model": m.name, title: m.summary }, m.title));
    }
  }
}

/** Show what the URL hash asks for: a model, its inputs, fidelity; compute if inputs are given. */
async function route() {
  const params = new URLSearchParams(location.hash.slice(1));
  const name = params.get("m");
  const m = state.models.find((x) => x.name === name);
  if (!m) return renderHome();
  if (state.model !== m || params.size > 1) showModel(m, params);
  if (params.has("ex") || [...params.keys()].some((k) => m.inputs.some((p) => p.name === k))) await compute();
  if (params.has("sv") && document.getElementById("sweep-vary")) {
    // a shared sweep: its input, output, range, points and scale
    const set = (id, key) => { if (params.has(key)) document.getElementById(id).value = params.get(key); };
    set("sweep-vary", "sv");
    sweepDefaults(m);
    for (const [id, key] of [["sweep-output", "so"], ["sweep-start", "s0"], ["sweep-stop", "s1"], ["sweep-num", "sn"], ["sweep-scale", "ss"]]) set(id, key);
    await runSweep(m);
  }
}

function renderHome() {
  state.model = null;
  const sec = document.getElementById("model");
  sec.replaceChildren(el("h2", {}, "Choose a model"));
  for (const a of document.querySelectorAll("nav a")) a.classList.remove("active");
  const list = el("div", { class: "cards" });
  for (const m of state.models) {
    list.append(el("a", { class: "card", href: "#m=" + encodeURIComponent(m.name) },
      el("strong", {}, m.title), el("span", { class: "family" }, m.family), el("p", {}, m.summary)));
  }
  sec.append(list);
}

// ---------------------------------------------------------------- the form

function showModel(m, params = new URLSearchParams()) {
  state.model = m;
  state.lastResponse = null;
  state.sweepParams = null;
  destroyCharts();
  for (const a of document.querySelectorAll("nav a")) a.classList.toggle("active", a.dataset.model === m.name);
  const sec = document.getElementById("model");
  sec.replaceChildren(
    el("h2", { id: "model-title" }, m.title),
    el("p", { class: "summary" }, m.summary),
    el("p", { class: "source" }, el("strong", {}, "Source: "), m.source),
    rungTable(m),
  );

  const form = el("form", { id: "form", novalidate: true, autocomplete: "off" });
  const groups = new Map();
  for (const p of m.inputs) {
    const g = p.group || "Inputs";
    if (!groups.has(g)) groups.set(g, []);
    groups.get(g).push(p);
  }
  for (const [g, ps] of groups) {
    form.append(el("fieldset", {}, el("legend", {}, g), ...ps.map(fieldRow)));
  }
  form.append(fidelityRow(m));
  const examples = el("select", { id: "example", "aria-label": "load a worked example" },
    el("option", { value: "" }, "Load…"),
    el("option", { value: "defaults" }, "source defaults"),
    ...m.examples.map((_, i) => el("option", { value: String(i) }, `example ${i + 1}${i === 0 ? " (the model's reference case)" : ""}`)));
  examples.addEventListener("change", () => {
    if (examples.value !== "") fillForm(m, examples.value);
    examples.value = "";
  });
  form.append(el("div", { class: "actions" },
    el("button", { type: "submit", id: "compute" }, "Compute"), examples,
    el("button", { type: "button", id: "copy-link", onclick: copyLink }, "Copy link")));
  form.addEventListener("submit", (e) => { e.preventDefault(); compute(); });
  sec.append(form, el("div", { id: "error-box", role: "alert" }), el("div", { id: "result" }), sweepPanel(m));

  fillForm(m, params.get("ex") ?? (m.examples.length ? "0" : "defaults"));
  applyParams(m, params);
}

function rungTable(m) {
  return el("details", { class: "rungs" }, el("summary", {}, `Methods (${m.rungs.length} rung${m.rungs.length > 1 ? "s" : ""}, cheapest first)`),
    el("table", {}, el("tr", {}, el("th", {}, "rung"), el("th", {}, "method"), el("th", {}, "typical error"), el("th", {}, "typical time")),
      ...m.rungs.map((r) => el("tr", {}, el("td", {}, el("code", {}, r.name)), el("td", {}, r.description),
        el("td", {}, r.typical_error || "—"), el("td", {}, r.typical_time || "—")))));
}

function fieldRow(p) {
  const id = "in-" + p.name;
  let input, unitSel = null;
  if (p.kind === "choice") {
    input = el("select", { id, name: p.name }, ...(p.required ? [] : [el("option", { value: "" }, "—")]),
      ...p.choices.map((c) => el("option", { value: c }, c)));
  } else if (p.kind === "bool") {
    input = el("input", { id, name: p.name, type: "checkbox" });
  } else {
    input = el("input", { id, name: p.name, type: "text", inputmode: "decimal", size: 12 });
    const choices = unitChoices(p.unit, p.display_unit);
    if (choices.length > 1) {
      unitSel = el("select", { id: "unit-" + p.name, name: "unit-" + p.name, "aria-label": `${p.label} unit` },
        ...choices.map((c) => el("option", { value: c.api, "data-factor": c.factor }, c.label)));
      unitSel.dataset.prev = unitSel.value;
      unitSel.addEventListener("change", () => changeUnit(p, input, unitSel));
    } else {
      unitSel = el("span", { class: "unit", id: "unit-" + p.name, "data-api": choices[0].api, "data-factor": choices[0].factor }, choices[0].label);
    }
    input.addEventListener("input", () => checkField(p));
    input.addEventListener("change", () => checkField(p));
  }
  const label = el("label", { for: id, title: p.description },
    p.label, p.symbol ? el("span", { class: "symbol" }, ` ${p.symbol}`) : null, p.required ? el("span", { class: "req", title: "required" }, " *") : null);
  return el("div", { class: "field", "data-field": p.name },
    label, el("div", { class: "control" }, input, unitSel),
    p.description ? el("div", { class: "desc", title: p.description }, p.description) : null,
    el("div", { class: "hint", id: "hint-" + p.name }, hintText(p)),
    el("div", { class: "error", id: "err-" + p.name, role: "alert" }));
}

/** The unit currently chosen for a numeric input: {api, factor, label}. */
function currentUnit(p) {
  const u = document.getElementById("unit-" + p.name);
  if (!u) return { api: "", factor: 1, label: "" };
  if (u.tagName === "SELECT") {
    const o = u.selectedOptions[0];
    return { api: o.value, factor: Number(o.dataset.factor), label: o.textContent };
  }
  return { api: u.dataset.api, factor: Number(u.dataset.factor), label: u.textContent };
}

function inUnit(si, unit) {
  return si / unit.factor;
}

/** "default 100 rpm · allowed > 0 and ≤ 1e4 mm · recommended …", in the unit chosen. */
function hintText(p) {
  const parts = [];
  if (p.kind === "choice" || p.kind === "bool") {
    if (p.default !== null && p.default !== undefined) parts.push(`default ${p.default}`);
    if (p.kind === "choice") parts.push(`one of ${p.choices.join(", ")}`);
    return parts.join(" · ");
  }
  const u = document.getElementById("unit-" + p.name) ? currentUnit(p) : unitChoices(p.unit, p.display_unit)[0];
  const sp = u.label ? " " + u.label : "";
  if (p.default !== null && p.default !== undefined) parts.push(`default ${short(inUnit(p.default, u))}${sp}`);
  else if (!p.required) parts.push("optional");
  parts.push("allowed: " + rangeText(p, u));
  if (p.recommended) parts.push(`recommended ${short(inUnit(p.recommended[0], u))}…${short(inUnit(p.recommended[1], u))}${sp}`);
  return parts.join(" · ");
}

function rangeText(p, u) {
  const sp = u.label ? " " + u.label : "";
  const parts = [];
  if (p.minimum !== null && p.minimum !== undefined) parts.push(`${p.exclusive_minimum ? ">" : "≥"} ${short(inUnit(p.minimum, u))}${sp}`);
  if (p.maximum !== null && p.maximum !== undefined) parts.push(`${p.exclusive_maximum ? "<" : "≤"} ${short(inUnit(p.maximum, u))}${sp}`);
  const what = p.kind === "int" ? "an integer" : "a number";
  return parts.length ? `${what} ${parts.join(" and ")}` : `any ${p.kind === "int" ? "integer" : "finite number"}`;
}

function changeUnit(p, input, sel) {
  const prev = Number(sel.querySelector(`option[value="${CSS.escape(sel.dataset.prev)}"]`).dataset.factor);
  const next = Number(sel.selectedOptions[0].dataset.factor);
  const v = input.value.trim();
  if (!touched(input) && input.dataset.si !== undefined) {
    // still the loaded value: convert from its exact SI value, and keep it untouched
    input.value = input.dataset.shown = fieldNumber(Number(input.dataset.si) / next, 7);
  } else if (v !== "" && Number.isFinite(Number(v))) input.value = fieldNumber((Number(v) * prev) / next);
  sel.dataset.prev = sel.value;
  document.getElementById("hint-" + p.name).textContent = hintText(p);
  checkField(p);
}

/**
 * Load a worked example ("0", "1", …) or the source defaults ("defaults") into the
 * form, in each field's unit. A field keeps the exact SI value it was loaded with
 * until the user edits it (then its text and unit are sent as typed), so a
 * rounded display never changes a result; links name the example and carry only
 * the fields the user changed.
 */
function fillForm(m, key) {
  const values = key === "defaults" ? {} : m.examples[Number(key)] || {};
  state.example = key === "defaults" || m.examples[Number(key)] ? key : "defaults";
  for (const p of m.inputs) {
    const input = document.getElementById("in-" + p.name);
    const v = p.name in values ? values[p.name] : p.default;
    if (p.kind === "bool") input.checked = Boolean(v);
    else if (p.kind === "choice") input.value = v ?? "";
    else if (typeof v === "string") {
      input.value = v; // a unit string ("45 mm"): sent as written
      delete input.dataset.si;
    } else {
      input.value = v === null || v === undefined ? "" : fieldNumber(inUnit(v, currentUnit(p)), 7);
      if (v === null || v === undefined) delete input.dataset.si;
      else input.dataset.si = String(v);
    }
    input.dataset.shown = shownValue(input);
    setError(p.name, "");
  }
}

function shownValue(input) {
  return input.type === "checkbox" ? String(input.checked) : input.value;
}

/** Edited by the user since the example or defaults were loaded. */
function touched(input) {
  return shownValue(input) !== input.dataset.shown;
}

/** Inputs from the URL: name=“45 mm” (unit strings), fidelity, tol (%). */
function applyParams(m, params) {
  for (const p of m.inputs) {
    if (!params.has(p.name)) continue;
    const raw = params.get(p.name);
    const input = document.getElementById("in-" + p.name);
    if (p.kind === "bool") { input.checked = raw === "true"; continue; }
    if (p.kind === "choice") { input.value = raw; continue; }
    const match = raw.match(/^\s*(\S+)\s*(.*)$/);
    const sel = document.getElementById("unit-" + p.name);
    if (match && sel && sel.tagName === "SELECT" && match[2]) {
      const opt = [...sel.options].find((o) => norm(o.value) === norm(match[2]) || norm(o.textContent) === norm(match[2]));
      if (opt) {
        sel.value = opt.value; sel.dataset.prev = opt.value; input.value = match[1];
        if (input.dataset.si !== undefined) input.dataset.shown = fieldNumber(Number(input.dataset.si) / Number(opt.dataset.factor), 7);
      }
      else input.value = raw; // the API will parse it, or say why not
    } else input.value = match && (!match[2] || sel?.dataset.api === match[2]) ? match[1] : raw;
    document.getElementById("hint-" + p.name).textContent = hintText(p);
  }
  if (params.has("fidelity")) document.getElementById("fidelity").value = params.get("fidelity");
  if (params.has("tol")) document.getElementById("tolerance").value = params.get("tol");
  syncTolerance();
}

function fidelityRow(m) {
  const sel = el("select", { id: "fidelity", name: "fidelity" },
    el("option", { value: "auto" }, "auto: cheapest method within the tolerance"),
    ...m.rungs.map((r) => {
      const err = r.typical_error.length > 48 ? r.typical_error.slice(0, 47) + "…" : r.typical_error;
      return el("option", { value: r.name, title: `${r.description}; typical error ${r.typical_error || "not stated"}` }, `${r.name}${err ? " (" + err + ")" : ""}`);
    }));
  sel.value = m.default_fidelity;
  sel.addEventListener("change", syncTolerance);
  const tol = el("input", { id: "tolerance", name: "tolerance", type: "text", inputmode: "decimal", size: 5, value: "1" });
  return el("fieldset", { class: "fidelity" }, el("legend", {}, "Fidelity"),
    el("div", { class: "control" }, el("label", { for: "fidelity" }, "method "), sel,
      el("label", { for: "tolerance", id: "tol-label" }, " tolerance "), tol, el("span", { class: "unit" }, "%")),
    el("div", { class: "error", id: "err-tolerance" }));
}

function syncTolerance() {
  const auto = document.getElementById("fidelity").value === "auto";
  document.getElementById("tolerance").disabled = !auto;
}

// ---------------------------------------------------------------- validation

function setError(name, msg) {
  const slot = document.getElementById("err-" + name);
  if (!slot) return false;
  slot.textContent = msg;
  slot.closest(".field")?.classList.toggle("invalid", Boolean(msg));
  const input = document.getElementById("in-" + name);
  if (input) {
    if (msg) input.setAttribute("aria-invalid", "true");
    else input.removeAttribute("aria-invalid");
  }
  return true;
}

/** Range check from the catalogue, before anything is sent. Returns the message or "". */
function checkField(p) {
  const input = document.getElementById("in-" + p.name);
  const raw = input.value.trim();
  let msg = "";
  if (raw === "") {
    if (p.required) msg = `${p.label} is required`;
  } else if (!Number.isFinite(Number(raw))) {
    // a typed unit string ("45 mm") is left to the server, which parses units exactly
    if (!/^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?\s*\S+/i.test(raw)) msg = `“${raw}” is not a number`;
  } else {
    const u = currentUnit(p);
    const si = Number(raw) * u.factor;
    const lo = p.minimum, hi = p.maximum;
    const bad = (lo !== null && lo !== undefined && (p.exclusive_minimum ? si <= lo : si < lo))
      || (hi !== null && hi !== undefined && (p.exclusive_maximum ? si >= hi : si > hi))
      || (p.kind === "int" && !Number.isInteger(si));
    if (bad) msg = `${p.name} = ${raw}${u.label ? " " + u.label : ""} is not allowed: must be ${rangeText(p, u)}`;
  }
  setError(p.name, msg);
  return msg;
}

// ---------------------------------------------------------------- evaluate

/** The request body the form describes: unit strings for numbers, as typed. */
function requestBody(m, { skip = null } = {}) {
  const body = {};
  for (const p of m.inputs) {
    if (p.name === skip) continue;
    const input = document.getElementById("in-" + p.name);
    if (p.kind === "bool") { body[p.name] = input.checked; continue; }
    const raw = input.value.trim();
    if (raw === "") continue;
    if (p.kind === "choice") { body[p.name] = raw; continue; }
    const u = currentUnit(p);
    if (!touched(input) && input.dataset.si !== undefined) body[p.name] = Number(input.dataset.si);
    else if (Number.isFinite(Number(raw))) body[p.name] = u.api ? `${raw} ${u.api}` : Number(raw);
    else body[p.name] = raw;
  }
  return body;
}

function fidelityBody() {
  const fidelity = document.getElementById("fidelity").value;
  const out = { fidelity };
  if (fidelity === "auto") {
    const t = Number(document.getElementById("tolerance").value);
    setError("tolerance", Number.isFinite(t) && t > 0 && t < 100 ? "" : "tolerance must be between 0 and 100 %");
    if (Number.isFinite(t) && t > 0 && t < 100) out.tolerance = t / 100;
  }
  return out;
}

async function post(path, body) {
  const res = await fetch(API + path, {
    method: "POST", headers: { "content-type": "application/json" }, body: JSON.stringify(body),
  });
  let data;
  try { data = await res.json(); } catch { data = { detail: [{ msg: `HTTP ${res.status}` }] }; }
  return { ok: res.ok, status: res.status, data };
}

/** Server errors at their fields; the rest in the error box. */
function showErrors(data, box) {
  const general = [], marked = new Set();
  for (const d of data.detail || []) {
    if (d.field && marked.has(d.field)) continue; // the first message per field is shown
    if (d.field && setError(d.field, d.msg)) marked.add(d.field);
    else general.push(d.msg);
  }
  if (marked.size) {
    general.unshift(`Not computed: ${[...marked].join(", ")} ${marked.size > 1 ? "were" : "was"} refused; see the marked field${marked.size > 1 ? "s" : ""}.`);
    const first = document.querySelector(".field.invalid input, .field.invalid select");
    if (first) { first.scrollIntoView({ block: "center" }); first.focus({ preventScroll: true }); }
  }
  box.replaceChildren(...general.map((g) => el("p", { class: "error" }, g)));
}

async function compute() {
  const m = state.model;
  if (!m) return;
  for (const p of m.inputs) if (p.kind === "float" || p.kind === "int") checkField(p);
  const body = { ...requestBody(m), ...fidelityBody() };
  if (m.outputs.some((o) => o.series)) body.series = true; // the form plots them; the API sends none unasked
  state.lastRequest = body;
  updateHash(m, body);
  const out = document.getElementById("result");
  const box = document.getElementById("error-box");
  out.classList.add("busy");
  const seq = ++state.seq;
  const { ok, data } = await post(m.path, body);
  if (seq !== state.seq || state.model !== m) return; // a newer request or another model
  out.classList.remove("busy");
  for (const p of m.inputs) setError(p.name, "");
  box.replaceChildren();
  if (!ok) {
    state.lastResponse = null;
    destroyCharts("series");
    out.replaceChildren();
    showErrors(data, box);
    document.body.dataset.result = "error";
    return;
  }
  state.lastResponse = data;
  renderResult(m, data);
  document.body.dataset.result = "ok";
}

/** The address bar: model, the example loaded, the fields the user changed (as typed, with units), fidelity. */
function updateHash(m, body) {
  const params = new URLSearchParams({ m: m.name, ex: state.example });
  for (const p of m.inputs) {
    const input = document.getElementById("in-" + p.name);
    if (!touched(input)) continue;
    if (p.kind === "bool") params.set(p.name, String(input.checked));
    else if (p.kind === "choice" || !Number.isFinite(Number(input.value.trim())) || input.value.trim() === "") {
      params.set(p.name, input.value.trim());
    } else {
      const u = currentUnit(p);
      params.set(p.name, u.api ? `${input.value.trim()} ${u.api}` : input.value.trim());
    }
  }
  params.set("fidelity", body.fidelity);
  if ("tolerance" in body) params.set("tol", fieldNumber(body.tolerance * 100));
  for (const [k, v] of Object.entries(state.sweepParams || {})) params.set(k, v);
  history.replaceState(null, "", "#" + params.toString());
}

async function copyLink() {
  const m = state.model;
  updateHash(m, { ...requestBody(m), ...fidelityBody() });
  try { await navigator.clipboard.writeText(location.href); } catch { /* no clipboard: the address bar has it */ }
  document.getElementById("copy-link").textContent = "Link copied (and in the address bar)";
}

// ---------------------------------------------------------------- results

function outputUnit(o) {
  return unitChoices(o.unit, o.display_unit)[0];
}

function renderResult(m, data) {
  const out = document.getElementById("result");
  const sig = sigFigs(data.error_estimate);
  const rows = [];
  for (const o of m.outputs) {
    if (o.series || !(o.name in data.results)) continue;
    const v = data.results[o.name];
    const choices = unitChoices(o.unit, o.display_unit);
    const u = choices[0];
    const digits = o.kind === "int" ? 12 : sig;
    const shown = typeof v === "number" ? fmt(v / u.factor, digits) : fmt(v);
    const cell = el("td", { class: "num", "data-si": v === null ? "null" : String(v), "data-factor": u.factor }, shown);
    let unitCell = typeof v === "number" ? u.label : "";
    if (typeof v === "number" && choices.length > 1 && o.kind !== "int") {
      // another unit for this result: the same SI value, converted
      unitCell = el("select", { class: "result-unit", "aria-label": `${o.label} unit` },
        ...choices.map((c, i) => el("option", { value: String(i) }, c.label)));
      unitCell.addEventListener("change", () => {
        const c = choices[Number(unitCell.value)];
        cell.dataset.factor = c.factor;
        cell.textContent = fmt(v / c.factor, digits);
      });
    }
    rows.push(el("tr", { "data-output": o.name },
      el("th", { scope: "row", title: o.description }, o.label),
      cell,
      el("td", { class: "unit" }, unitCell),
      el("td", { class: "desc" }, o.description)));
  }
  const rung = m.rungs.find((r) => r.name === data.rung);
  const meta = el("p", { class: "meta", id: "meta" },
    "Method ", el("code", { id: "rung" }, data.rung), rung ? ` (${rung.description})` : "",
    " · error estimate ", el("span", { id: "error-estimate" }, fmtError(data.error_estimate)),
    " · computed in ", el("span", { id: "elapsed" }, fmtTime(data.elapsed_s)),
    ` · shown to ${sig} significant figures`);
  const checks = data.checks.length
    ? el("ul", { class: "checks", id: "checks" }, ...data.checks.map((c) =>
      el("li", { class: c.ok ? "ok" : "fail" }, el("span", { class: "mark" }, c.ok ? "✓ pass " : "✗ fail "), el("strong", {}, c.name), ": ", c.detail)))
    : null;
  const warnings = data.warnings.length
    ? el("ul", { class: "warnings", id: "warnings" }, ...data.warnings.map((w) => el("li", {}, "⚠ ", w))) : null;
  const notes = data.notes.length
    ? el("ul", { class: "notes", id: "notes" }, ...data.notes.map((n) => el("li", {}, n))) : null;
  out.replaceChildren(...[
    el("h3", {}, "Results"), meta,
    el("table", { id: "results", class: "results" }, el("tbody", {}, ...rows)),
    checks ? el("h4", {}, "Checks") : null, checks,
    warnings ? el("h4", {}, "Warnings") : null, warnings,
    notes ? el("h4", {}, "Notes") : null, notes,
    el("div", { class: "downloads" },
      el("button", { type: "button", id: "download-json", onclick: () => downloadJSON(m, data) }, "Download JSON"),
      el("button", { type: "button", id: "download-csv", onclick: () => downloadCSV(m, data) }, "Download CSV")),
    Object.values(data.series).some((v) => v.length) ? el("p", { class: "muted" }, "Drag across a plot to zoom in; double-click to zoom out.") : null,
    el("div", { id: "series-plots", class: "plots" })].filter(Boolean));
  renderSeries(m, data);
}

function download(name, type, text) {
  const a = el("a", { href: URL.createObjectURL(new Blob([text], { type })), download: name });
  document.body.append(a);
  a.click();
  a.remove();
}

function downloadJSON(m, data) {
  download(`${m.name}.json`, "application/json",
    JSON.stringify({ model: m.name, link: location.href, request: state.lastRequest, response: data }, null, 2));
}

function csvCell(v) {
  const s = v === null || v === undefined ? "" : String(v);
  return /[",\n]/.test(s) ? `"${s.replaceAll('"', '""')}"` : s;
}

/** Results (SI and display unit), then inputs (SI), then the series as columns. */
function downloadCSV(m, data) {
  const lines = [["quantity", "name", "value_si", "unit_si", "value_shown", "unit_shown"].join(",")];
  for (const o of m.outputs) {
    if (o.series || !(o.name in data.results)) continue;
    const v = data.results[o.name];
    const u = outputUnit(o);
    const shown = typeof v === "number" ? v / u.factor : v;
    lines.push(["result", o.name, v, data.units[o.name] ?? o.unit, shown, u.label].map(csvCell).join(","));
  }
  for (const [k, v] of Object.entries(data.inputs)) {
    const p = m.inputs.find((x) => x.name === k);
    lines.push(["input", k, v, p && p.unit !== "1" ? p.unit : "", "", ""].map(csvCell).join(","));
  }
  lines.push(["meta", "rung", data.rung, "", "", ""].join(","));
  lines.push(["meta", "error_estimate", data.error_estimate ?? "", "1", "", ""].join(","));
  lines.push(["meta", "elapsed_s", data.elapsed_s, "s", "", ""].join(","));
  const names = Object.keys(data.series);
  if (names.length) {
    lines.push("");
    lines.push(names.map((n) => csvCell(`${n} [${data.units[n] ?? ""}]`)).join(","));
    const n = Math.max(...names.map((k) => data.series[k].length));
    for (let i = 0; i < n; i++) lines.push(names.map((k) => csvCell(data.series[k][i])).join(","));
  }
  download(`${m.name}.csv`, "text/csv", lines.join("\n") + "\n");
}

// ---------------------------------------------------------------- plots

function destroyCharts(kind = null) {
  state.charts = state.charts.filter((c) => {
    if (kind && c.kind !== kind) return true;
    c.chart.destroy();
    return false;
  });
}

function chartWidth(container) {
  return Math.max(320, Math.min(760, container.clientWidth || 640));
}

/**
 * Shaded windows on a chart drawn against the x series ``xo``: the spans its
 * ``plot.windows`` declare, each between two scalar results in the x unit
 * (e.g. the striker's engagement window).
 */
function windows(xo, data) {
  const out = [];
  for (const w of (xo.plot && xo.plot.windows) || []) {
    const from = data.results[w.start], to = data.results[w.end];
    if (typeof from !== "number" || typeof to !== "number") continue;
    if (norm(data.units[w.start]) !== norm(xo.unit)) continue;
    out.push({ label: w.label, from, to });
  }
  return out;
}

function makeChart(container, kind, { title, xLabel, yLabel, x, ys, bars = false, bands = [], marks = [], xRange = null, xLog = false }) {
  const colors = ["#1f5f99", "#c0392b", "#2e8b57", "#8e44ad"];
  const opts = {
    title,
    width: chartWidth(container),
    height: 280,
    scales: { x: { time: false, ...(xLog ? { distr: 3 } : {}), ...(xRange ? { range: xRange } : {}) } },
    axes: [{ label: xLabel }, { label: yLabel, size: 70 }],
    series: [{ label: xLabel }, ...ys.map((s, i) => ({
      label: s.label,
      stroke: colors[i % colors.length],
      width: 2,
      ...(bars ? { fill: "rgba(31,95,153,0.35)", paths: uPlot.paths.bars({ size: [0.95, Infinity] }), points: { show: false } } : {}),
    }))],
    legend: { show: true },
    hooks: {
      drawClear: [(u) => {
        const ctx = u.ctx;
        for (const b of bands) {
          const x0 = u.valToPos(b.from, "x", true), x1 = u.valToPos(b.to, "x", true);
          ctx.save();
          ctx.fillStyle = "rgba(255, 193, 7, 0.25)";
          ctx.fillRect(Math.min(x0, x1), u.bbox.top, Math.abs(x1 - x0), u.bbox.height);
          ctx.fillStyle = "#8a6d00";
          ctx.font = `${12 * devicePixelRatio}px system-ui`;
          ctx.fillText(b.label, Math.min(x0, x1) + 4, u.bbox.top + 14 * devicePixelRatio);
          ctx.restore();
        }
        for (const mk of marks) {
          const px = u.valToPos(mk.at, "x", true);
          if (!(px >= u.bbox.left && px <= u.bbox.left + u.bbox.width)) continue;
          ctx.save();
          ctx.strokeStyle = "#888";
          ctx.setLineDash([6 * devicePixelRatio, 4 * devicePixelRatio]);
          ctx.beginPath(); ctx.moveTo(px, u.bbox.top); ctx.lineTo(px, u.bbox.top + u.bbox.height); ctx.stroke();
          ctx.fillStyle = "#555";
          ctx.font = `${12 * devicePixelRatio}px system-ui`;
          ctx.fillText(mk.label, px + 4, u.bbox.top + 14 * devicePixelRatio);
          ctx.restore();
        }
      }],
    },
  };
  const box = el("div", { class: "chart", "data-kind": kind });
  container.append(box);
  const chart = new uPlot(opts, [x, ...ys.map((s) => s.data)], box);
  state.charts.push({ kind, chart });
  return chart;
}

/**
 * Every series output against its declared x series. Curves sharing an x series
 * and a unit share a chart (e.g. the travel of each part against time); a
 * series whose x holds bin edges (one longer) or that declares ``plot.bars``
 * draws as a histogram.
 */
function renderSeries(m, data) {
  destroyCharts("series");
  const box = document.getElementById("series-plots");
  const byName = Object.fromEntries(m.outputs.map((o) => [o.name, o]));
  const usedAsX = new Set(m.outputs.filter((o) => o.series && o.x).map((o) => o.x));
  const charts = new Map(); // key -> chart spec, in the order the model lists its outputs
  for (const o of m.outputs) {
    const ys = data.series[o.name];
    if (!o.series || !ys || !ys.length) continue;
    if (!o.x && usedAsX.has(o.name)) continue; // an axis, not a curve
    const yu = outputUnit(o);
    const y = ys.map((v) => (v === null ? null : v / yu.factor));
    let xs = o.x ? data.series[o.x] : null;
    const xo = o.x && xs ? byName[o.x] : null;
    const xu = xo ? outputUnit(xo) : { factor: 1, label: "" };
    const xLabel = xo ? `${xo.label}${xu.label ? " [" + xu.label + "]" : ""}` : "sample";
    let bars = false, xRange = null;
    if (!xs) xs = ys.map((_, i) => i);
    else if (xs.length === ys.length + 1) {
      // bin edges: draw bars at the bin centres, spanning the edges
      bars = true;
      xRange = [xs[0] / xu.factor, xs[xs.length - 1] / xu.factor];
      xs = ys.map((_, i) => (xs[i] + xs[i + 1]) / 2);
    } else if (xs.length !== ys.length) continue;
    else if (o.plot && o.plot.bars) bars = true;
    const key = bars ? "bars:" + o.name : `${xo ? o.x : "index:" + ys.length}|${norm(o.unit)}`;
    if (!charts.has(key)) {
      const x = xs.map((v) => v / xu.factor);
      const bands = xo && !bars ? windows(xo, data).map((b) => ({ ...b, from: b.from / xu.factor, to: b.to / xu.factor })) : [];
      charts.set(key, { xLabel, unit: yu.label, x, ys: [], bars, bands, xRange });
    }
    charts.get(key).ys.push({ label: o.label, data: y });
  }
  for (const c of charts.values()) {
    const names = c.ys.map((s) => s.label).join(", ");
    makeChart(box, "series", {
      title: names + (c.bars ? " (histogram)" : ""),
      xLabel: c.xLabel, yLabel: `${names.length <= 40 ? names : c.ys[0].label + ", …"}${c.unit ? " [" + c.unit + "]" : ""}`,
      x: c.x, ys: c.ys, bars: c.bars, bands: c.bands, xRange: c.xRange,
    });
  }
}

// ---------------------------------------------------------------- sweep

function sweepPanel(m) {
  const numeric = m.inputs.filter((p) => p.kind === "float" || p.kind === "int");
  const scalars = m.outputs.filter((o) => !o.series && (o.kind === "float" || o.kind === "int"));
  if (!numeric.length || !scalars.length) return el("div");
  const vary = el("select", { id: "sweep-vary" }, ...numeric.map((p) => el("option", { value: p.name }, p.label)));
  const output = el("select", { id: "sweep-output" }, ...scalars.map((o) => el("option", { value: o.name }, o.label)));
  const start = el("input", { id: "sweep-start", size: 9, inputmode: "decimal" });
  const stop = el("input", { id: "sweep-stop", size: 9, inputmode: "decimal" });
  const unit = el("span", { class: "unit", id: "sweep-unit" });
  const num = el("input", { id: "sweep-num", size: 4, value: "40", inputmode: "numeric" });
  const scale = el("select", { id: "sweep-scale" }, el("option", { value: "linear" }, "linear"), el("option", { value: "log" }, "log"));
  vary.addEventListener("change", () => sweepDefaults(m));
  const panel = el("section", { class: "sweep", id: "sweep" },
    el("h3", {}, "Sweep one input"),
    el("p", { class: "muted" }, "The other inputs stay as in the form; a point the model refuses is left out of the curve."),
    el("div", { class: "control" }, el("label", { for: "sweep-output" }, "plot "), output,
      el("label", { for: "sweep-vary" }, " against "), vary,
      el("label", { for: "sweep-start" }, " from "), start, el("label", { for: "sweep-stop" }, " to "), stop, " ", unit,
      el("label", { for: "sweep-num" }, " points "), num, " ", scale, " ",
      el("button", { type: "button", id: "sweep-run", onclick: () => runSweep(m) }, "Sweep")),
    el("div", { class: "error", id: "sweep-error", role: "alert" }),
    el("div", { id: "sweep-notes", class: "notes" }),
    el("div", { id: "sweep-plot", class: "plots" }));
  queueMicrotask(() => sweepDefaults(m));
  return panel;
}

/** A dashed line at the design in the form (its varied input's current value). */
function designMark(m, p, u) {
  const input = document.getElementById("in-" + p.name);
  const si = !touched(input) && input.dataset.si !== undefined ? Number(input.dataset.si) : Number(input.value) * u.factor;
  return Number.isFinite(si) ? [{ at: si / u.factor, label: "this design" }] : [];
}

/** A range around the current value of the varied input, inside its allowed range. */
function sweepDefaults(m) {
  const p = m.inputs.find((x) => x.name === document.getElementById("sweep-vary").value);
  const u = currentUnit(p);
  const raw = Number(document.getElementById("in-" + p.name).value);
  let v = Number.isFinite(raw) ? raw * u.factor : (p.default ?? 1);
  let lo = v > 0 ? v * 0.5 : v < 0 ? v * 1.5 : 0;
  let hi = v > 0 ? v * 1.5 : v < 0 ? v * 0.5 : 1;
  if (p.minimum !== null && p.minimum !== undefined && lo <= p.minimum) lo = p.exclusive_minimum ? p.minimum + (v - p.minimum) * 0.1 : p.minimum;
  if (p.maximum !== null && p.maximum !== undefined && hi >= p.maximum) hi = p.exclusive_maximum ? p.maximum - (p.maximum - v) * 0.1 : p.maximum;
  if (p.kind === "int") { lo = Math.ceil(lo); hi = Math.max(lo + 1, Math.floor(hi)); }
  if (p.kind === "int") document.getElementById("sweep-num").value = String(Math.min(hi - lo + 1, 200));
  document.getElementById("sweep-start").value = fieldNumber(lo / u.factor);
  document.getElementById("sweep-stop").value = fieldNumber(hi / u.factor);
  document.getElementById("sweep-unit").textContent = u.label;
}

async function runSweep(m) {
  const vary = document.getElementById("sweep-vary").value;
  const p = m.inputs.find((x) => x.name === vary);
  const output = document.getElementById("sweep-output").value;
  const u = currentUnit(p);
  const end = (id) => {
    const raw = document.getElementById(id).value.trim();
    return u.api && Number.isFinite(Number(raw)) ? `${raw} ${u.api}` : Number.isFinite(Number(raw)) ? Number(raw) : raw;
  };
  let num = Number(document.getElementById("sweep-num").value) || 40;
  if (p.kind === "int") {
    // an integer input is swept over whole numbers only: one point per integer
    const a = Number(document.getElementById("sweep-start").value), b = Number(document.getElementById("sweep-stop").value);
    if (Number.isInteger(a) && Number.isInteger(b) && b > a) num = Math.min(b - a + 1, 2000);
    document.getElementById("sweep-num").value = String(num);
  }
  const req = {
    base: requestBody(m, { skip: vary }), vary, start: end("sweep-start"), stop: end("sweep-stop"),
    num,
    scale: document.getElementById("sweep-scale").value, outputs: [output], ...fidelityBody(),
  };
  const errBox = document.getElementById("sweep-error");
  errBox.textContent = "";
  for (const p2 of m.inputs) setError(p2.name, "");
  const seq = ++state.sweepSeq;
  const { ok, data } = await post(m.path + "/sweep", req);
  if (seq !== state.sweepSeq || state.model !== m) return;
  destroyCharts("sweep");
  const plot = document.getElementById("sweep-plot");
  plot.replaceChildren();
  document.getElementById("sweep-notes").replaceChildren();
  if (!ok) {
    // base inputs are marked at their fields; the box repeats every message
    const msgs = [];
    for (const d of data.detail || []) {
      const field = (d.loc || []).filter((x) => x !== "body" && x !== "base").join(".") || d.field;
      if (field && field !== vary) setError(field, d.msg);
      msgs.push(d.msg);
    }
    errBox.textContent = "Sweep refused: " + (msgs.join(" ") || `HTTP error`);
    state.lastSweep = { request: req, response: null };
    document.body.dataset.sweep = "error";
    return;
  }
  state.lastSweep = { request: req, response: data };
  state.sweepParams = {
    sv: vary, so: output, s0: document.getElementById("sweep-start").value.trim(),
    s1: document.getElementById("sweep-stop").value.trim(), sn: String(num), ss: req.scale,
  };
  updateHash(m, { ...requestBody(m), ...fidelityBody() });
  if (!Array.isArray(data.results[output])) {
    errBox.textContent = `The sweep returned no values of ${output} (method ${data.rung}); try another output or method.`;
    document.body.dataset.sweep = "empty";
    return;
  }
  const o = m.outputs.find((x) => x.name === output);
  const ou = outputUnit(o);
  const x = data.values.map((v) => v / u.factor);
  const y = data.results[output].map((v) => (v === null ? null : v / ou.factor));
  makeChart(plot, "sweep", {
    title: `${o.label} against ${p.label} (method ${data.rung}, ${fmtTime(data.elapsed_s)})`,
    xLabel: `${p.label}${u.label ? " [" + u.label + "]" : ""}`,
    yLabel: `${o.label}${ou.label ? " [" + ou.label + "]" : ""}`,
    x, ys: [{ label: o.label, data: y }], xLog: req.scale === "log", marks: designMark(m, p, u),
  });
  const msgs = [...data.warnings.map((w) => "⚠ " + w), ...data.notes];
  document.getElementById("sweep-notes").replaceChildren(...msgs.slice(0, 6).map((n) => el("p", {}, n)),
    ...(msgs.length > 6 ? [el("p", { class: "muted" }, `… and ${msgs.length - 6} more`)] : []));
  document.body.dataset.sweep = "ok";
}

let resizeTimer = null;
window.addEventListener("resize", () => {
  clearTimeout(resizeTimer);
  resizeTimer = setTimeout(() => {
    for (const c of state.charts) c.chart.setSize({ width: chartWidth(c.chart.root.parentElement.parentElement), height: 280 });
  }, 150);
});

init().catch((e) => {
  document.getElementById("model").replaceChildren(el("p", { class: "error" }, "Could not load the model catalogue: " + e));
});
