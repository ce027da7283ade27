// The calculator page, generated from GET /api/v1/models: no per-model HTML.
//
// Values travel to the API as unit strings ("45 mm", "1450 rpm"), which the
// server parses exactly; the unit table (units.json) is used only to convert a
// field when its unit selector changes, to check ranges before submitting, and
// to show results in each output's display unit. Everything the page knows
// about a model comes from the catalogue entry, so a newly registered model
// appears here without any change to this file.

import { choiceName } from "./choices.js";
import {
  decimalSeparator, echoNumber, formatNumber, group, imperialChosen, IMPERIAL, inputUnit, isPlain, isRatio, localNumber, norm, outputChoices as sharedOutputChoices,
  parseNum, PERCENT, readNumber, readQuantity, readSamples, setDecimalSeparator, setImperial, typedDigits, unitChoices as sharedUnitChoices, unitTable,
} from "./numbers.js";

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
  imperial: false, // the metric/imperial switch (results, fields and sweeps)
  choiceNames: {}, // choice key -> readable name, from the spec and the API's catalogues
  fasteners: null, // GET /api/v1/fasteners when the service has it
  version: "", // the product's version and commit, for the report
  commit: "",
  lastSnapshot: null, // the inputs (SI) of the result shown, to mark it stale
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

/** The unit choices for an SI unit, display unit first (numbers.js's unitChoices over units.json). */
function unitChoices(si, display) {
  return sharedUnitChoices(state.units, si, display);
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
  return Math.min(6, Math.max(2, Math.ceil(-Math.log10(err)) + 1));
}

/** A value for the reader (numbers.js's formatNumber, shared with the study page). */
function fmt(x, sig = 4) {
  if (x === null || x === undefined) return "—";
  if (typeof x === "boolean") return x ? "yes" : "no";
  if (typeof x !== "number") return String(x);
  return formatNumber(x, sig);
}

/** A number for a text field, in the user's decimal separator (see fieldNumber). */
function fieldText(x, sig = 10) {
  return localNumber(fieldNumber(x, sig));
}

/**
 * Digits to show a loaded (SI) value of ``p`` with in another unit: two more than it has
 * in the model's display unit, 5 to 7 (0.012 m, "12 mm", reads "0.47244 in", not
 * "0.4724409 in"); the exact SI value is still what is sent until the field is edited.
 */
function loadedDigits(p, si) {
  const shown = si / unitChoices(p.unit, p.display_unit)[0].factor;
  if (!Number.isFinite(shown) || shown === 0) return 7;
  return Math.min(7, Math.max(5, typedDigits(String(Number(shown.toPrecision(7)))) + 2));
}

/** Digits to show a typed value with in another unit: two more than were typed, 4 to 10. */
function convertedDigits(canonical) {
  return Math.min(10, Math.max(4, typedDigits(canonical) + 2));
}

/**
 * A number from a link or a design file: canonical (a point, no grouping), or, in links
 * made before the decimal-separator setting, "12,5" with a decimal comma. Shown in the
 * user's separator; text that is no number is returned as it is.
 */
function linkNumber(raw) {
  const s = String(raw).trim();
  const legacy = /^[+-]?\d*,\d+(e[+-]?\d+)?$/i.test(s) ? s.replace(",", ".") : s;
  const r = readNumber(legacy, ".");
  return r.ok ? localNumber(r.canonical) : s;
}

/** A readable name: the spec's label, or its description when the label is only a code ("z1"). */
function labelOf(o) {
  const generic = o.label === o.name.replaceAll("_", " ");
  if (generic && o.name.length <= 3 && o.description) {
    const d = o.description.split(/[,;(]/)[0].trim();
    return d.length > 48 ? d.slice(0, 47) + "…" : d;
  }
  return o.label;
}

/** A choice or a list of choices ("torque_wrench, nut_angle") in readable names. */
function choiceText(v) {
  if (typeof v !== "string") return v;
  return v.split(/(,\s*)/).map((t) => state.choiceNames[t] ?? t).join("");
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

/** What a rung's error estimate promises: "bound", or "typical (exceeded in …)" with the
 * share of random designs that exceed it, as the catalogue states it (docs/accuracy.md). */
function estimateKindText(rung, kind = rung && rung.estimate_kind) {
  if (!kind) return "";
  if (kind !== "typical") return "bound";
  const share = rung && rung.typical_exceeded;
  return share ? `typical (exceeded in ${share})` : "typical (how often it is exceeded is not measured)";
}

function fmtTime(s) {
  if (s < 1e-3) return fmt(s * 1e6, 3) + " µs";
  if (s < 1) return fmt(s * 1e3, 3) + " ms";
  return fmt(s, 3) + " s";
}

/** The page's one live region: what Compute, a sweep or a refusal did, said once. */
function announce(text) {
  const region = document.getElementById("announce");
  if (region) region.textContent = text;
}

/** Skip links ("Skip to Compute", "Go to the result"): focus the target without touching the hash (the route). */
function skipTo(e) {
  e.preventDefault();
  const which = e.currentTarget.dataset.skip;
  // no result yet: the result link leads to Compute, which makes one
  const target = document.getElementById(which === "result" ? "result-heading" : "compute") ?? document.getElementById("compute");
  if (!target) return;
  if (!target.hasAttribute("tabindex") && target.tagName !== "BUTTON") target.setAttribute("tabindex", "-1");
  target.scrollIntoView({ block: which === "compute" ? "center" : "start" });
  target.focus({ preventScroll: true });
}

/** After Compute: the answer in view and focused (its heading), so the keyboard and a screen reader start there. */
function showAnswer() {
  const heading = document.getElementById("result-heading");
  if (!heading) return;
  heading.scrollIntoView({ block: "start" });
  heading.focus({ preventScroll: true });
}

// ---------------------------------------------------------------- start-up

async function init() {
  const [models, units] = await Promise.all([
    fetch(API + "/models").then((r) => r.json()),
    fetch("units.json").then((r) => r.json()),
  ]);
  state.models = models.models;
  state.units = unitTable(units);
  await loadCatalogues(models.service || {});
  state.imperial = imperialChosen();
  const system = document.getElementById("unit-system");
  system.value = state.imperial ? "imperial" : "metric";
  system.addEventListener("change", () => switchSystem(system.value === "imperial"));
  const decimal = document.getElementById("decimal-sep");
  decimal.value = decimalSeparator();
  decimal.addEventListener("change", () => switchDecimal(decimal.value));
  renderNav();
  for (const a of document.querySelectorAll("a[data-skip]")) a.addEventListener("click", skipTo);
  window.addEventListener("hashchange", () => route());
  await route();
  document.body.dataset.ready = "1";
}

/**
 * What the service offers beyond the models, as the catalogue names it (``service`` in
 * GET /api/v1/models: nothing else is fetched to learn it): its version and commit (for
 * the report), the preload-control methods with their scatter (readable method names),
 * and the fastener catalogue (thread and property-class pickers) where it exists.
 */
async function loadCatalogues(service = {}) {
  const get = (path) => fetch(path).then((r) => (r.ok ? r.json() : null)).catch(() => null);
  // only the catalogues the service names are asked for (no 404s in the console)
  const path = (key) => (service.catalogues?.[key] ?? "").replace(/^\//, "");
  const [methods, fasteners] = await Promise.all([
    path("preload_methods") ? get(path("preload_methods")) : null, path("fasteners") ? get(path("fasteners")) : null]);
  state.version = service.version ?? "";
  state.commit = service.commit ?? "";
  for (const m of state.models) {
    for (const p of m.inputs) {
      (p.choice_labels || []).forEach((label, i) => { state.choiceNames[p.choices[i]] = label; });
    }
  }
  for (const x of methods?.methods || []) {
    const scatter = typeof x.scatter === "number" ? ` (±${short(x.scatter * 100, 2)} %)` : "";
    state.choiceNames[x.key] ??= x.name + scatter;
  }
  if (fasteners && Array.isArray(fasteners.threads)) state.fasteners = fasteners;
  for (const pc of state.fasteners?.property_classes || []) {
    if (typeof pc.yield_strength === "number") {
      state.choiceNames[pc.name] ??= `${pc.name} (R_p0.2 ${short(pc.yield_strength / 1e6, 4)} MPa)`;
    }
  }
  // keys named by neither the spec nor the service's catalogues are shown readably too
  // ("iso5393_hard" → "ISO 5393 hard joint"); the hint still lists their keys
  state.namedChoices = new Set(Object.keys(state.choiceNames));
  for (const m of state.models) {
    for (const p of m.inputs) if (p.kind === "choice") for (const c of p.choices) state.choiceNames[c] ??= choiceName(p, c);
  }
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
  const fresh = state.model !== m;
  if (fresh || params.size > 1) showModel(m, params);
  // on a phone the menu sits above the form: go to the form
  if (fresh && window.matchMedia("(max-width: 800px)").matches) document.getElementById("model").scrollIntoView();
  if (params.has("ex") || [...params.keys()].some((k) => m.inputs.some((p) => p.name === k))) await compute();
  if (params.has("sv") && document.getElementById("sweep-vary")) {
    // a shared sweep: its input, unit, outputs, range, points, scale and axes
    const set = (id, key) => { if (params.has(key)) document.getElementById(id).value = params.get(key); };
    set("sweep-vary", "sv");
    sweepDefaults(m);
    if (params.has("su")) setSweepUnit(m, params.get("su"));
    const outs = (params.get("so") || "").split(",").filter(Boolean);
    if (outs.length) document.getElementById("sweep-output").value = outs[0];
    for (const box of document.querySelectorAll("#sweep-more input")) box.checked = outs.slice(1).includes(box.value);
    for (const [id, key] of [["sweep-start", "s0"], ["sweep-stop", "s1"], ["sweep-num", "sn"], ["sweep-scale", "ss"], ["sweep-axes", "sa"]]) set(id, key);
    await runSweep(m);
  }
  if (params.get("view") === "report") showView("report");
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
  state.lastSnapshot = null;
  state.lastSweep = null;
  state.compare = [];
  document.body.classList.remove("view-report", "view-compare");
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
    const picker = threadPicker(m, ps);
    form.append(el("fieldset", {}, el("legend", {}, g), picker, ...ps.map(fieldRow)));
  }
  form.append(fidelityRow(m));
  // a new design starts from the model's declared defaults; a worked example is one choice away
  const examples = el("select", { id: "example", "aria-describedby": "start-hint" },
    el("option", { value: "defaults" }, "new design: the model's defaults"),
    ...m.examples.map((_, i) => el("option", { value: String(i) }, `example ${i + 1}${i === 0 ? " (the model's reference case)" : ""}`)));
  examples.addEventListener("change", () => fillForm(m, examples.value));
  const required = m.inputs.filter((p) => p.required && (p.default === null || p.default === undefined));
  form.prepend(el("div", { class: "start" },
    el("label", { for: "example" }, "Start from "), examples,
    el("span", { class: "hint", id: "start-hint" }, "The defaults are the model's own: optional inputs empty, loads as declared",
      required.length ? `; to fill in: ${required.map((p) => p.label).join(", ")}` : "", ".")));
  const openOne = el("input", { type: "file", id: "open-design", accept: ".json,application/json", class: "file" });
  openOne.addEventListener("change", () => openDesign(openOne));
  const openMany = el("input", { type: "file", id: "compare-designs", accept: ".json,application/json", multiple: true, class: "file" });
  openMany.addEventListener("change", () => compareDesigns(m, openMany));
  // Compute stays in reach: the bar sticks to the bottom of the window while the form is on screen
  form.append(el("div", { class: "actions action-bar", id: "action-bar" },
    el("button", { type: "submit", id: "compute" }, "Compute"),
    el("a", { href: "#result", class: "to-result", id: "to-result", "data-skip": "result", onclick: skipTo, hidden: true }, "Go to the result"),
    el("button", { type: "button", id: "copy-link", onclick: copyLink }, "Copy link")),
  designNames(m, params),
  el("div", { class: "actions files" },
    el("button", { type: "button", id: "show-report", onclick: () => showView("report") }, "Calculation report"),
    el("button", { type: "button", id: "save-design", onclick: () => saveDesign(m) }, "Save design"),
    el("button", { type: "button", id: "study-design", onclick: () => studyDesign(m) }, "Study this design"),
    openOne, el("label", { class: "button", for: "open-design" }, "Open design…"),
    openMany, el("label", { class: "button", for: "compare-designs" }, "Compare designs…")));
  form.addEventListener("submit", (e) => { e.preventDefault(); compute(); });
  form.addEventListener("input", () => { syncUsage(m); markStale(); });
  form.addEventListener("change", () => { syncUsage(m); markStale(); });
  const stale = el("p", { id: "stale-note", class: "stale-note", hidden: true },
    "Inputs changed: compute again ", el("button", { type: "button", onclick: compute }, "Compute"));
  sec.append(form, el("div", { id: "error-box", tabindex: "-1" }), stale, el("div", { id: "result" }), sweepPanel(m),
    reportSection(m), el("section", { id: "compare", class: "compare", "aria-label": "comparison of designs" }));

  fillForm(m, params.get("ex") ?? "defaults");
  applyParams(m, params);
  syncUsage(m);
  // imperial chosen earlier: the fields the link does not set open in imperial units
  if (state.imperial) setFieldSystem(m, true, (p) => !params.has(p.name));
}

function rungTable(m) {
  return el("details", { class: "rungs" }, el("summary", {}, `Methods (${m.rungs.length} rung${m.rungs.length > 1 ? "s" : ""}, cheapest first)`),
    el("table", {}, el("tr", {}, el("th", {}, "rung"), el("th", {}, "method"), el("th", {}, "typical error"), el("th", {}, "error estimate"), el("th", {}, "typical time")),
      ...m.rungs.map((r) => el("tr", {}, el("td", {}, el("code", {}, r.name)), el("td", {}, r.description),
        el("td", {}, r.typical_error || "—"), el("td", { class: "estimate-kind" }, estimateKindText(r)), el("td", {}, r.typical_time || "—")))));
}

function fieldRow(p) {
  const id = "in-" + p.name;
  let input, unitSel = null;
  const numeric = p.kind === "float" || p.kind === "int";
  const described = ["desc-" + p.name, "hint-" + p.name, "err-" + p.name, ...(numeric ? ["read-" + p.name] : [])].join(" ");
  if (p.kind === "choice") {
    input = el("select", { id, name: p.name, "aria-describedby": described },
      ...(p.required ? [] : [el("option", { value: "" }, "—")]),
      ...p.choices.map((c) => el("option", { value: c }, state.choiceNames[c] ?? c)));
  } else if (p.kind === "bool") {
    input = el("input", { id, name: p.name, type: "checkbox", "aria-describedby": described });
  } else if (p.kind === "text") {
    // free text (a fastener designation such as "M12x1.25"); the choices are suggestions
    input = el("input", { id, name: p.name, type: "text", size: 22, maxlength: 64, list: "list-" + p.name, "aria-describedby": described });
    unitSel = el("datalist", { id: "list-" + p.name }, ...(p.choices || []).map((c) => el("option", { value: c })));
  } else if (p.kind === "samples") {
    return samplesRow(p, id, described);
  } else {
    input = el("input", { id, name: p.name, type: "text", inputmode: "decimal", size: 12, "aria-describedby": described });
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
    label, el("div", { class: "control" }, input, unitSel,
      // the value read, beside what was typed when the two differ ("2,000" → "= 2000 lbf")
      numeric ? el("output", { class: "read-as", id: "read-" + p.name, for: id }) : null),
    el("div", { class: "desc", id: "desc-" + p.name, title: p.description }, p.description || ""),
    el("div", { class: "hint", id: "hint-" + p.name }, hintText(p)),
    p.used_with ? el("div", { class: "unused", id: "unused-" + p.name, hidden: true }) : null,
    el("div", { class: "error", id: "err-" + p.name }));
}

/**
 * An input that changes nothing in the current mode is disabled, with the reason: the
 * model declares which input it takes effect with (``used_with``: the joint's μ_max and
 * torque tolerance act only with a torque specification; ``"name=value"``: only while that
 * choice is made, as a disc pack's inputs with spring kind "disc pack"). A disabled input
 * is not sent.
 */
function syncUsage(m) {
  for (const p of m.inputs) {
    if (!p.used_with) continue;
    const [otherName, wanted] = p.used_with.split("=");
    const input = document.getElementById("in-" + p.name);
    const other = document.getElementById("in-" + otherName);
    const reason = document.getElementById("unused-" + p.name);
    if (!input || !other || !reason) continue;
    const off = wanted !== undefined ? other.value !== wanted
      : other.type === "checkbox" ? !other.checked : other.value.trim() === "";
    const needs = m.inputs.find((x) => x.name === otherName);
    const label = needs ? needs.label : otherName;
    const was = input.disabled;
    input.disabled = off;
    if (was !== off && ["float", "int", "samples"].includes(p.kind)) checkField(p);
    for (const sel of document.querySelectorAll(`#unit-${p.name}`)) if (sel.tagName === "SELECT") sel.disabled = off;
    reason.hidden = !off;
    const choice = wanted === undefined ? "" : (state.choiceNames[wanted] || wanted);
    reason.textContent = !off ? ""
      : wanted !== undefined ? `Used only with ${label} “${choice}”: with another it changes nothing.`
      : `Used only with a ${label}: without one it changes nothing.`;
    input.closest(".field")?.classList.toggle("unused", off);
    const described = (input.getAttribute("aria-describedby") || "").split(" ").filter((x) => x && x !== reason.id);
    input.setAttribute("aria-describedby", [...described, ...(off ? [reason.id] : [])].join(" "));
  }
}

/** A list of measured values: pasted into a text area or read from a CSV file, in one unit. */
function samplesRow(p, id, described) {
  const input = el("textarea", { id, name: p.name, rows: 4, cols: 24, spellcheck: "false", "aria-describedby": described + " read-" + p.name,
    placeholder: "one value a line, or separated by spaces or semicolons" });
  const choices = unitChoices(p.unit, p.display_unit);
  const unitSel = choices.length > 1
    ? el("select", { id: "unit-" + p.name, name: "unit-" + p.name, "aria-label": `${p.label} unit` },
      ...choices.map((c) => el("option", { value: c.api, "data-factor": c.factor }, c.label)))
    : el("span", { class: "unit", id: "unit-" + p.name, "data-api": choices[0].api, "data-factor": choices[0].factor }, choices[0].label);
  if (unitSel.tagName === "SELECT") {
    unitSel.dataset.prev = unitSel.value;
    unitSel.addEventListener("change", () => changeUnit(p, input, unitSel));
  }
  const file = el("input", { id: "file-" + p.name, type: "file", accept: ".csv,.txt,text/csv,text/plain", "aria-label": `${p.label}: read a CSV file` });
  file.addEventListener("change", async () => {
    const f = file.files && file.files[0];
    if (!f) return;
    // a CSV file: one value a line (its first column), or values in a row; a header line is dropped
    const lines = (await f.text()).split(/\r?\n/).filter((l) => l.trim() !== "");
    const sep = decimalSeparator() === "," ? ";" : ",";
    const rows = lines.map((l) => l.split(lines.length > 1 ? sep : /\u0000/)[0].trim());
    if (rows.length > 1 && !readNumber(rows[0]).ok) rows.shift();
    input.value = rows.join("\n");
    checkField(p);
  });
  input.addEventListener("input", () => checkField(p));
  input.addEventListener("change", () => checkField(p));
  const label = el("label", { for: id, title: p.description },
    p.label, p.symbol ? el("span", { class: "symbol" }, ` ${p.symbol}`) : null, p.required ? el("span", { class: "req", title: "required" }, " *") : null);
  return el("div", { class: "field samples", "data-field": p.name },
    label, el("div", { class: "control" }, input, unitSel, file,
      el("output", { class: "read-as", id: "read-" + p.name, for: id })),
    el("div", { class: "desc", id: "desc-" + p.name, title: p.description }, p.description || ""),
    el("div", { class: "hint", id: "hint-" + p.name }, hintText(p)),
    el("div", { class: "error", id: "err-" + p.name }));
}

/** Values in SI written into a samples text area in ``unit``, one a line. */
function samplesText(values, unit) {
  return values.map((v) => localNumber(fieldNumber(v / unit.factor, 10))).join("\n");
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

/** A limit or default in a hint, in the user's decimal separator. */
function num(x) {
  return localNumber(short(x));
}

/** "default 100 rpm · allowed > 0 and ≤ 1e4 mm · recommended …", in the unit chosen. */
function hintText(p) {
  const parts = [];
  if (p.kind === "text") return (p.required ? "" : "optional · ") + (p.choices?.length ? `e.g. ${p.choices.slice(0, 3).join(", ")}` : "text");
  if (p.kind === "choice" || p.kind === "bool") {
    if (p.default !== null && p.default !== undefined) parts.push(`default ${state.choiceNames[p.default] ?? p.default}`);
    if (p.kind === "choice" && !p.choices.some((c) => state.namedChoices?.has(c))) parts.push(`one of ${p.choices.join(", ")}`);
    return parts.join(" · ");
  }
  const u = document.getElementById("unit-" + p.name) ? currentUnit(p) : unitChoices(p.unit, p.display_unit)[0];
  const sp = u.label ? " " + u.label : "";
  if (p.kind === "samples") {
    const seps = decimalSeparator() === "," ? "new lines, semicolons or spaces" : "new lines, commas, semicolons or spaces";
    return [p.required ? "" : "optional", `${p.min_length}–${p.max_length} values separated by ${seps}, or a CSV file`, "each " + rangeText(p, u)].filter(Boolean).join(" · ");
  }
  if (p.default !== null && p.default !== undefined) parts.push(`default ${num(inUnit(p.default, u))}${sp}`);
  else if (!p.required) parts.push("optional");
  parts.push("allowed: " + rangeText(p, u));
  if (p.recommended) parts.push(`recommended ${num(inUnit(p.recommended[0], u))}…${num(inUnit(p.recommended[1], u))}${sp}`);
  return parts.join(" · ");
}

function rangeText(p, u) {
  const sp = u.label ? " " + u.label : "";
  const parts = [];
  if (p.minimum !== null && p.minimum !== undefined) parts.push(`${p.exclusive_minimum ? ">" : "≥"} ${num(inUnit(p.minimum, u))}${sp}`);
  if (p.maximum !== null && p.maximum !== undefined) parts.push(`${p.exclusive_maximum ? "<" : "≤"} ${num(inUnit(p.maximum, u))}${sp}`);
  const what = p.kind === "int" ? "an integer" : "a number";
  return parts.length ? `${what} ${parts.join(" and ")}` : `any ${p.kind === "int" ? "integer" : "finite number"}`;
}

function changeUnit(p, input, sel) {
  const prev = Number(sel.querySelector(`option[value="${CSS.escape(sel.dataset.prev)}"]`).dataset.factor);
  const next = Number(sel.selectedOptions[0].dataset.factor);
  const v = input.value.trim();
  if (p.kind === "samples") {
    const r = readSamples(v);
    if (!touched(input) && input.dataset.si !== undefined) input.value = input.dataset.shown = samplesText(JSON.parse(input.dataset.si), { factor: next });
    else if (r.ok) input.value = samplesText(r.values.map((x) => x * prev), { factor: next });
  } else if (!touched(input) && input.dataset.si !== undefined) {
    // still the loaded value: convert from its exact SI value, and keep it untouched
    input.value = input.dataset.shown = fieldText(Number(input.dataset.si) / next, loadedDigits(p, Number(input.dataset.si)));
  } else if (v !== "" && Number.isFinite(parseNum(v))) {
    // a typed value: shown to the precision typed (two digits more), not 10 digits of
    // noise; its exact value is what is sent until the field is edited (exactSI)
    const kept = input.dataset.exact !== undefined && v === input.dataset.exactShown; // converted before
    const si = kept ? Number(input.dataset.exact) : parseNum(v) * prev;
    const digits = kept ? Number(input.dataset.digits) : convertedDigits(readNumber(v).canonical);
    input.value = fieldText(si / next, digits);
    Object.assign(input.dataset, { exact: String(si), exactShown: input.value, digits: String(digits) });
  }
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
    delete input.dataset.exact; // a converted typed value (changeUnit): replaced
    if (p.kind === "bool") input.checked = Boolean(v);
    else if (p.kind === "choice" || p.kind === "text") input.value = v ?? "";
    else if (p.kind === "samples") {
      input.value = Array.isArray(v) ? samplesText(v, currentUnit(p)) : "";
      if (Array.isArray(v)) input.dataset.si = JSON.stringify(v);
      else delete input.dataset.si;
    } else if (typeof v === "string") {
      input.value = v; // a unit string ("45 mm"): sent as written
      delete input.dataset.si;
    } else {
      input.value = v === null || v === undefined ? "" : fieldText(inUnit(v, currentUnit(p)), loadedDigits(p, v));
      if (v === null || v === undefined) delete input.dataset.si;
      else input.dataset.si = String(v);
    }
    input.dataset.shown = shownValue(input);
    setError(p.name, "");
    const read = document.getElementById("read-" + p.name);
    if (read) read.textContent = "";
  }
  const chooser = document.getElementById("example");
  if (chooser) chooser.value = state.example;
  syncUsage(m);
  markStale();
}

/**
 * The exact SI value a number field stands for, or undefined: a loaded value not edited
 * since, or a typed value converted to another unit and not edited since (shown rounded).
 */
function exactSI(input) {
  if (!touched(input) && input.dataset.si !== undefined) return Number(input.dataset.si);
  if (input.dataset.exact !== undefined && input.value === input.dataset.exactShown) return Number(input.dataset.exact);
  return undefined;
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
    if (p.kind === "choice" || p.kind === "text") { input.value = raw; continue; }
    if (p.kind === "samples") {
      // canonical numbers separated by spaces, the unit last ("10.1 9.9 10 N*m")
      const tokens = raw.trim().split(/\s+/);
      const sel = document.getElementById("unit-" + p.name);
      const last = tokens[tokens.length - 1];
      if (tokens.length > 1 && !readNumber(last, ".").ok && sel && sel.tagName === "SELECT") {
        const opt = [...sel.options].find((o) => norm(o.value) === norm(last) || norm(o.textContent) === norm(last));
        if (opt) { sel.value = opt.value; sel.dataset.prev = opt.value; tokens.pop(); }
      }
      input.value = tokens.map((t) => linkNumber(t)).join("\n");
      delete input.dataset.si;
      continue;
    }
    const match = raw.match(/^\s*(\S+)\s*(.*)$/);
    const sel = document.getElementById("unit-" + p.name);
    if (match && sel && sel.tagName === "SELECT" && match[2]) {
      const opt = [...sel.options].find((o) => norm(o.value) === norm(match[2]) || norm(o.textContent) === norm(match[2]));
      if (opt) {
        sel.value = opt.value; sel.dataset.prev = opt.value; input.value = linkNumber(match[1]);
        if (input.dataset.si !== undefined) {
          const si = Number(input.dataset.si), factor = Number(opt.dataset.factor);
          input.dataset.shown = fieldText(si / factor, loadedDigits(p, si));
          // the loaded value itself (a link holds it to 10 digits): shown rounded, sent exact
          const linked = readNumber(match[1], ".").value * factor;
          if (Math.abs(linked - si) <= 1e-9 * Math.abs(si)) input.value = input.dataset.shown;
        }
      }
      else input.value = raw; // the API will parse it, or say why not
    } else if (match && (!match[2] || sel?.dataset.api === match[2])) input.value = linkNumber(match[1]);
    else input.value = match && match[2] ? `${linkNumber(match[1])} ${match[2]}` : raw;
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
  if (p.kind === "samples") return checkSamples(p);
  const input = document.getElementById("in-" + p.name);
  const raw = input.value.trim();
  const q = readQuantity(raw);
  const u = currentUnit(p);
  let msg = "", echo = "", format = false;
  if (input.disabled) {
    // not sent in this mode (syncUsage): nothing to refuse
  } else if (raw === "") {
    if (p.required) msg = `${p.label} is required`;
  } else if (!q.ok) {
    format = true;
    msg = q.text
      ? `${p.label}: “${raw}” is not a number (write ${localNumber("12.5")}${u.label ? ", in " + u.label : ""})`
      : `${p.label}: ${q.error}`;
  } else if (q.unit) {
    // a typed unit string ("45 mm") is left to the server, which parses units exactly
    if (!isPlain(raw.slice(0, raw.length - q.unit.length))) echo = `= ${echoNumber(q.value)} ${q.unit}`;
  } else {
    if (!isPlain(raw)) echo = `= ${echoNumber(q.value)}${u.label ? " " + u.label : ""}`;
    const si = q.value * u.factor;
    const lo = p.minimum, hi = p.maximum;
    const bad = (lo !== null && lo !== undefined && (p.exclusive_minimum ? si <= lo : si < lo))
      || (hi !== null && hi !== undefined && (p.exclusive_maximum ? si >= hi : si > hi))
      || (p.kind === "int" && !Number.isInteger(si));
    if (bad) msg = `${p.label} = ${raw}${u.label ? " " + u.label : ""} is not allowed: must be ${rangeText(p, u)}`;
  }
  setError(p.name, msg);
  const read = document.getElementById("read-" + p.name);
  if (read) read.textContent = msg ? "" : echo;
  const slot = document.getElementById("err-" + p.name);
  if (slot) slot.dataset.format = format ? "1" : "";
  return msg;
}

/** A samples field read and range-checked value by value, as the server checks it. */
function checkSamples(p) {
  const input = document.getElementById("in-" + p.name);
  const raw = input.value.trim();
  const u = currentUnit(p);
  let msg = "", echo = "", format = false;
  if (raw === "") {
    if (p.required) msg = `${p.label} is required`;
  } else {
    const r = readSamples(raw);
    if (!r.ok) {
      format = true;
      msg = `${p.label}: ${r.error}`;
    } else if (r.values.length < p.min_length || r.values.length > p.max_length) {
      msg = `${p.label} has ${r.values.length} value${r.values.length === 1 ? "" : "s"}: give ${p.min_length} to ${p.max_length}`;
    } else {
      const lo = p.minimum, hi = p.maximum;
      const i = r.values.findIndex((v) => {
        const si = v * u.factor;
        return (lo !== null && lo !== undefined && (p.exclusive_minimum ? si <= lo : si < lo))
          || (hi !== null && hi !== undefined && (p.exclusive_maximum ? si >= hi : si > hi));
      });
      if (i >= 0) msg = `${p.label}: value ${i + 1} = ${localNumber(r.canonical[i])}${u.label ? " " + u.label : ""} is not allowed: each must be ${rangeText(p, u)}`;
      else echo = `${r.values.length} values read`;
    }
  }
  setError(p.name, msg);
  const read = document.getElementById("read-" + p.name);
  if (read) read.textContent = msg ? "" : echo;
  const slot = document.getElementById("err-" + p.name);
  if (slot) slot.dataset.format = format ? "1" : "";
  return msg;
}

// ---------------------------------------------------------------- evaluate

/** The request body the form describes: unit strings for numbers, as typed. */
function requestBody(m, { skip = null } = {}) {
  const body = {};
  for (const p of m.inputs) {
    if (p.name === skip) continue;
    const input = document.getElementById("in-" + p.name);
    if (input.disabled) continue; // no effect in this mode (syncUsage): not sent
    if (p.kind === "bool") { body[p.name] = input.checked; continue; }
    const raw = input.value.trim();
    if (raw === "") continue;
    if (p.kind === "choice" || p.kind === "text") { body[p.name] = raw; continue; }
    const u = currentUnit(p);
    if (p.kind === "samples") {
      const r = readSamples(raw);
      if (!touched(input) && input.dataset.si !== undefined) body[p.name] = JSON.parse(input.dataset.si);
      else if (!r.ok) body[p.name] = raw; // the form refuses it before sending; the server would too
      else body[p.name] = u.api ? { values: r.values, unit: u.api } : r.values;
      continue;
    }
    const q = readQuantity(raw);
    if (exactSI(input) !== undefined) body[p.name] = exactSI(input);
    else if (q.ok && !q.unit) body[p.name] = u.api ? `${q.canonical} ${u.api}` : q.value;
    else if (q.ok) body[p.name] = `${q.canonical} ${q.unit}`; // a unit typed with the number
    else body[p.name] = raw; // the form refuses it before sending; the server would too
  }
  return body;
}

function fidelityBody() {
  const fidelity = document.getElementById("fidelity").value;
  const out = { fidelity };
  if (fidelity === "auto") {
    const t = parseNum(document.getElementById("tolerance").value);
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
  const m = state.model;
  for (const d of data.detail || []) {
    if (d.field && marked.has(d.field)) continue; // the first message per field is shown
    const p = m?.inputs.find((x) => x.name === d.field);
    // in the user's unit and words when the form's own check says why; the server's words otherwise
    const own = p && (p.kind === "float" || p.kind === "int") ? checkField(p) : "";
    const msg = own || (p ? `${p.label}: ${d.msg}` : d.msg);
    if (d.field && setError(d.field, msg)) {
      marked.add(d.field);
      document.getElementById("err-" + d.field).dataset.server = d.msg;
    } else general.push(d.msg);
  }
  if (marked.size) {
    const names = [...marked].map((n) => m?.inputs.find((x) => x.name === n)?.label ?? n);
    general.unshift(`Not computed: ${names.join(", ")} ${marked.size > 1 ? "were" : "was"} refused; see the marked field${marked.size > 1 ? "s" : ""}.`);
    const first = document.querySelector(".field.invalid input, .field.invalid select");
    if (first) { first.scrollIntoView({ block: "center" }); first.focus({ preventScroll: true }); }
  }
  box.replaceChildren(...general.map((g) => el("p", { class: "error" }, g)));
}

async function compute() {
  const m = state.model;
  if (!m) return;
  for (const p of m.inputs) if (p.kind === "float" || p.kind === "int" || p.kind === "samples") checkField(p);
  const body = { ...requestBody(m), ...fidelityBody() };
  // a number the form cannot read under the decimal-separator setting is never sent
  const unread = m.inputs.filter((p) => document.getElementById("err-" + p.name)?.dataset.format === "1");
  if (unread.length) {
    state.lastRequest = body;
    const names = unread.map((p) => p.label).join(", ");
    const why = `Not computed: ${names} cannot be read as ${unread.length > 1 ? "numbers" : "a number"}; see the marked field${unread.length > 1 ? "s" : ""}.`;
    document.getElementById("error-box").replaceChildren(el("p", { class: "error" }, why));
    announce(why);
    const first = document.getElementById("in-" + unread[0].name);
    first.scrollIntoView({ block: "center" });
    first.focus({ preventScroll: true });
    document.body.dataset.result = "error";
    return;
  }
  if (m.outputs.some((o) => o.series)) body.series = true; // the form plots them; the API sends none unasked
  const snap = snapshot(m);
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
    state.lastSnapshot = null;
    destroyCharts("series");
    out.replaceChildren();
    document.getElementById("to-result").hidden = true;
    showErrors(data, box);
    announce(box.textContent);
    if (!document.querySelector(".field.invalid")) { box.scrollIntoView({ block: "center" }); box.focus({ preventScroll: true }); }
    // the report says why there is nothing to report
    document.getElementById("report-body")?.replaceChildren(el("p", { class: "error" }, "Not computed: "),
      el("ul", {}, ...(data.detail || []).map((d) => el("li", {}, d.msg))));
    markStale();
    document.body.dataset.result = "error";
    return;
  }
  state.lastResponse = data;
  state.lastSnapshot = snap;
  renderResult(m, data);
  markStale();
  // the report (its equations typeset) is built when it is asked for, not on every Compute
  if (document.body.classList.contains("view-report")) renderReport(m);
  const verdict = verdictText(m, data);
  announce(`Computed (method ${data.rung})${verdict ? `: ${verdict}` : ""}.`);
  document.getElementById("to-result").hidden = false;
  showAnswer();
  document.body.dataset.result = "ok";
}

/** The address bar: model, the example loaded, the fields the user changed (as typed, with units), fidelity. */
function updateHash(m, body) {
  const params = new URLSearchParams({ m: m.name, ex: state.example });
  for (const [k, v] of Object.entries(formInputs(m))) params.set(k, v);
  params.set("fidelity", body.fidelity);
  if ("tolerance" in body) params.set("tol", fieldNumber(body.tolerance * 100));
  for (const [k, v] of Object.entries(state.sweepParams || {})) params.set(k, v);
  for (const [k, id] of REPORT_NAMES) {
    const v = reportName(id);
    if (v) params.set(k, v);
  }
  if (document.body.classList.contains("view-report")) params.set("view", "report");
  history.replaceState(null, "", "#" + params.toString());
}

/**
 * Every input as the link and a design file hold it: numbers as shown with their
 * unit ("12 mm", "1450 rpm"), choices and switches as set; empty fields left out
 * (a field emptied by the user is kept, empty, so it stays empty when reopened).
 */
function formInputs(m) {
  const out = {};
  for (const p of m.inputs) {
    const input = document.getElementById("in-" + p.name);
    const raw = input.value.trim();
    if (p.kind === "bool") out[p.name] = String(input.checked);
    else if (raw === "") { if (touched(input)) out[p.name] = ""; }
    else if (p.kind === "samples") {
      // canonical numbers separated by spaces, the unit last: the link means the same everywhere
      const r = readSamples(raw), u = currentUnit(p);
      out[p.name] = r.ok ? [...r.canonical, ...(u.api ? [u.api] : [])].join(" ") : raw;
    } else if (p.kind === "choice" || p.kind === "text" || !readQuantity(raw).ok) out[p.name] = raw;
    else {
      // canonical numbers (a point, no grouping): the link means the same on every machine;
      // a value shown rounded (loaded, or converted) with its exact value to 10 digits
      const q = readQuantity(raw), u = currentUnit(p), exact = exactSI(input);
      const n = exact !== undefined && !q.unit ? fieldNumber(exact / u.factor, 10) : q.canonical;
      out[p.name] = q.unit ? `${n} ${q.unit}` : u.api ? `${n} ${u.api}` : n;
    }
  }
  return out;
}

/**
 * "Study this design": the study page opens with the form's design as its base, every
 * number with its unit as the link holds it (formInputs), carried in sessionStorage; the
 * study page checks that base with one run before any point of a study runs.
 */
function studyDesign(m) {
  sessionStorage.setItem("study-base", JSON.stringify({ model: m.name, base: formInputs(m) }));
  location.assign(`study.html?model=${encodeURIComponent(m.name)}&from=form`);
}

/** The inputs in SI (numbers typed with a unit left as typed) with the fidelity: what a result answers. */
function snapshot(m) {
  const snap = {};
  for (const p of m.inputs) {
    const input = document.getElementById("in-" + p.name);
    if (p.kind === "bool") { snap[p.name] = input.checked; continue; }
    const raw = input.value.trim();
    if (p.kind === "choice" || p.kind === "text") { snap[p.name] = raw; continue; }
    if (p.kind === "samples") { snap[p.name] = `${raw} ${currentUnit(p).api}`; continue; }
    if (exactSI(input) !== undefined) snap[p.name] = exactSI(input);
    else if (Number.isFinite(parseNum(raw))) snap[p.name] = parseNum(raw) * currentUnit(p).factor;
    else snap[p.name] = raw;
  }
  snap.fidelity = document.getElementById("fidelity").value;
  snap.tolerance = snap.fidelity === "auto" ? document.getElementById("tolerance").value.trim() : "";
  return snap;
}

function sameSnapshot(a, b) {
  if (!a || !b) return false;
  return Object.keys({ ...a, ...b }).every((k) => {
    const x = a[k], y = b[k];
    if (typeof x === "number" && typeof y === "number") return Math.abs(x - y) <= 1e-9 * Math.max(Math.abs(x), Math.abs(y));
    return x === y;
  });
}

/** Dim the result, and say so, the moment an input differs from the one it answers. */
function markStale() {
  const m = state.model;
  const note = document.getElementById("stale-note");
  if (!m || !note) return;
  const stale = Boolean(state.lastSnapshot) && !sameSnapshot(state.lastSnapshot, snapshot(m));
  note.hidden = !stale;
  document.getElementById("result").classList.toggle("stale", stale);
  // the sweep answers its own inputs (all but the one it varies)
  const sw = state.lastSweep;
  const plot = document.getElementById("sweep-plot");
  if (plot && sw?.snapshot) {
    const now = snapshot(m);
    delete now[sw.request.vary];
    const sweepStale = !sameSnapshot(sw.snapshot, now);
    plot.classList.toggle("stale", sweepStale);
    document.getElementById("sweep-stale").hidden = !sweepStale;
  }
  document.getElementById("report")?.classList.toggle("stale", stale);
  document.body.dataset.stale = stale ? "1" : "0";
}

async function copyLink() {
  const m = state.model;
  updateHash(m, { ...requestBody(m), ...fidelityBody() });
  try { await navigator.clipboard.writeText(location.href); } catch { /* no clipboard: the address bar has it */ }
  document.getElementById("copy-link").textContent = "Link copied (and in the address bar)";
}

// ---------------------------------------------------------------- results

/** The unit choices of an output, best first (numbers.js's outputChoices, in the system chosen). */
function outputChoices(o, v = null) {
  return sharedOutputChoices(state.units, o, v, state.imperial);
}

function outputUnit(o, v = null) {
  return outputChoices(o, v)[0];
}

/** A scatter is a ± band: "±30 %". */
function signOf(o) {
  return isRatio(o) && /scatter|relative/.test(o.name) ? "±" : "";
}

function renderResult(m, data) {
  const out = document.getElementById("result");
  out.replaceChildren(...resultParts(m, data, { interactive: true }));
  renderSeries(m, data);
}

/** The scalar results as table rows: readable name, value to the figures the error supports, unit. */
function resultRows(m, data, { interactive = false, withDesc = true } = {}) {
  const sig = sigFigs(data.error_estimate);
  const rows = [];
  for (const o of m.outputs) {
    if (o.series || !(o.name in data.results)) continue;
    const v = data.results[o.name];
    const choices = outputChoices(o, v);
    const u = choices[0];
    const digits = o.kind === "int" ? 12 : sig;
    const sign = typeof v === "number" && v > 0 ? signOf(o) : "";
    // a count reads as a whole number ("2 blows", not 2.00000000000)
    const shown = o.kind === "int" && Number.isInteger(v) ? group(String(v))
      : typeof v === "number" ? sign + fmt(v / u.factor, digits) : fmt(choiceText(v));
    const cell = el("td", { class: typeof v === "string" ? "num text" : "num", "data-si": v === null ? "null" : String(v), "data-factor": u.factor, "data-sig": digits }, shown);
    let unitCell = typeof v === "number" ? u.label : "";
    if (interactive && typeof v === "number" && choices.length > 1 && o.kind !== "int") {
      // another unit for this result: the same SI value, converted
      unitCell = el("select", { class: "result-unit", "aria-label": `${labelOf(o)} unit` },
        ...choices.map((c, i) => el("option", { value: String(i) }, c.label)));
      unitCell.addEventListener("change", () => {
        const c = choices[Number(unitCell.value)];
        cell.dataset.factor = c.factor;
        cell.textContent = sign + fmt(v / c.factor, digits);
      });
    }
    // the symbol and step the model declares for this result ("" for a count or a flag)
    const sym = o.symbol || "";
    rows.push(el("tr", { "data-output": o.name },
      el("th", { scope: "row", title: o.step ? `${o.description} (${o.step})` : o.description },
        labelOf(o), interactive && sym ? [" ", symbolNode(sym)] : null),
      interactive ? null : el("td", { class: "symbol" }, sym ? symbolNode(sym) : ""),
      cell,
      el("td", { class: "unit" }, unitCell),
      withDesc ? el("td", { class: "desc" }, o.description) : null,
      interactive ? null : el("td", { class: "step" }, o.step || "")));
  }
  return rows;
}

/** A symbol as the standard writes it: "F_M,min" -> F with "M,min" set below; each term of
 *  a ratio or difference ("τ_k2/τ_zul", "θ_y − θ_0") gets its own subscript. */
function symbolNode(sym) {
  const parts = String(sym).split(/(\s*[/+−()]\s*|\s+)/).filter((t) => t !== "").map((t) => {
    const i = t.indexOf("_");
    return i < 0 ? t : [t.slice(0, i), el("sub", {}, t.slice(i + 1))];
  });
  return el("var", { class: "sym" }, ...parts);
}

/** Checks split by level: requirements (a standard's: they fail) and advice (they warn). */
function checkLevels(data) {
  const req = data.checks.filter((c) => c.level !== "advice");
  const adv = data.checks.filter((c) => c.level === "advice");
  return { req, adv, failed: req.filter((c) => !c.ok), warned: adv.filter((c) => !c.ok) };
}

/** The verdict in words: "passes VDI 2230" or "2 of 6 requirements fail". */
function verdictText(m, data) {
  const { req, failed, warned } = checkLevels(data);
  const warn = warned.length ? `, ${warned.length} warning${warned.length > 1 ? "s" : ""}` : "";
  if (!req.length) return data.checks.length ? `no requirement checked${warn}` : "";
  if (!failed.length) return `passes ${m.requirements_of || `every requirement (${req.length})`}${warn}`;
  const of = m.requirements_of ? `${m.requirements_of} ` : "";
  return `${failed.length} of ${req.length} ${of}requirement${req.length > 1 ? "s" : ""} fail${failed.length > 1 ? "" : "s"}${warn}`;
}

function checkName(c) {
  return c.name.replaceAll("_", " ");
}

/**
 * A check's detail or a note in the unit system chosen. The API gives each sentence as
 * parts, texts and quantities (SI value, unit, the digits shown); in imperial each
 * quantity is converted as the results table converts a value of its unit, to the digits
 * the sentence showed ("F_M = 23.8 kN" reads "F_M = 5350 lbf"). Metric, and sentences
 * without parts, read as the model wrote them.
 */
function sentenceText(text, parts) {
  if (!state.imperial || !Array.isArray(parts) || parts.every((p) => typeof p === "string")) return text;
  return parts.map((p) => (typeof p === "string" ? p : quantityText(p))).join("");
}

function quantityText(q) {
  if (typeof q.value !== "number") return q.text;
  const u = outputUnit({ name: "", unit: q.unit, display_unit: q.display_unit, kind: "float" }, q.value);
  if (!IMPERIAL.has(u.label)) return q.text; // no imperial unit for it (°, %, s): as written
  const number = formatNumber(q.value / u.factor, q.digits || 3, { trim: true });
  return q.bare ? number : `${number} ${u.label}`; // bare: a range's first value
}

/** A check's sentence in the unit system chosen. */
function checkDetail(c) {
  return sentenceText(c.detail, c.detail_parts);
}

/** The notes of an answer in the unit system chosen, ``keep(note)`` only. */
function noteTexts(data, keep = () => true) {
  const parts = data.notes_parts || [];
  return data.notes.map((n, i) => [n, parts[i]]).filter(([n]) => keep(n)).map(([n, p]) => sentenceText(n, p));
}

/** The verdict banner (requirements counted) and, apart, the failing requirements named and
 *  the advice not followed listed as warnings. */
function checkSummary(m, data, interactive = true) {
  if (!data.checks.length) return [null, null];
  const id = (x) => (interactive ? x : null);
  const { failed, warned } = checkLevels(data);
  const item = (c) => el("li", {}, el("strong", {}, checkName(c)), ": ", checkDetail(c));
  const banner = el("div", { class: `check-summary ${failed.length ? "fail" : "ok"}`, id: id("check-summary") },
    el("strong", { class: "verdict", id: id("verdict") }, (failed.length ? "✗ " : "✓ ") + verdictText(m, data)));
  const details = failed.length || warned.length ? el("div", { class: "verdict-details" },
    failed.length ? el("ul", { class: "failed", id: id("failed") }, ...failed.map(item)) : null,
    warned.length ? el("p", { class: "advice-head" }, "⚠ Advice not followed (a rule of thumb or a recommendation: it does not fail the design):") : null,
    warned.length ? el("ul", { class: "advice", id: id("advice") }, ...warned.map(item)) : null) : null;
  return [banner, details];
}

/** A value of one output in its best unit, with the unit: "73.5 N·m". */
function valueText(m, data, name) {
  const o = m.outputs.find((x) => x.name === name);
  const v = data.results[name];
  if (!o || v === null || v === undefined) return "—";
  if (typeof v !== "number") return choiceText(String(v));
  const u = outputUnit(o, v);
  if (o.kind === "int" && Number.isInteger(v)) return group(String(v));
  const digits = sigFigs(data.error_estimate);
  return `${signOf(o) && v > 0 ? "±" : ""}${fmt(v / u.factor, digits)}${u.label ? " " + u.label : ""}`;
}

/** A required value declared as a number (SI), in the unit its output is shown in: "1.2". */
function boundText(o, bound, v) {
  const u = outputUnit(o, v);
  return `${short(bound / u.factor, 4)}${u.label ? " " + u.label : ""}`;
}

/**
 * The answer card: the numbers the model's question asks for (declared in its spec), each
 * with its symbol, its required value and the verdict of the check that judges it; the
 * verdict of the standard's requirements above them.
 */
function answerCard(m, data, { interactive = true } = {}) {
  // an answer the model does not give for this design (S_G without a transverse load) is left out
  const items = (m.answer || []).filter((a) => data.results[a.output] !== null && data.results[a.output] !== undefined);
  if (!items.length && !data.checks.length) return null;
  const byName = Object.fromEntries(data.checks.map((c) => [c.name, c]));
  const rows = items.map((a) => {
    const o = m.outputs.find((x) => x.name === a.output);
    const c = a.check ? byName[a.check] : null;
    const bound = a.bound === null || a.bound === undefined ? null
      : typeof a.bound === "string" ? valueText(m, data, a.bound)
        : boundText(o, a.bound, data.results[a.output]);
    const need = a.relation ? [` ${a.relation} `, a.bound_symbol ? [symbolNode(a.bound_symbol), " "] : null, bound] : null;
    return el("li", { "data-answer": a.output, class: c ? (c.ok ? "ok" : c.level === "advice" ? "warn" : "fail") : null },
      el("span", { class: "what" }, labelOf(o)), " ",
      symbolNode(a.symbol), " = ", el("strong", { class: "value" }, valueText(m, data, a.output)),
      need ? el("span", { class: "need" }, ...need.flat()) : null,
      c ? el("span", { class: "mark", title: checkDetail(c) }, c.ok ? " ✓" : c.level === "advice" ? " ⚠" : " ✗") : null);
  });
  const [banner, details] = checkSummary(m, data, interactive);
  return el("section", { class: "answer-card", id: interactive ? "answer-card" : null, "aria-label": "the answer" },
    banner, rows.length ? el("ul", { class: "answers" }, ...rows) : null, details);
}

/** When the method's error is large and a finer one exists, say which to pick. */
function methodHint(m, data) {
  const err = data.error_estimate;
  if (!(err > 0.05) || m.rungs.length < 2) return null;
  const finer = m.rungs.slice(m.rungs.findIndex((r) => r.name === data.rung) + 1);
  const names = finer.map((r) => r.name);
  return el("p", { class: "method-hint", id: "method-hint" },
    `The error estimate is ${fmtError(err)}: `,
    names.length ? `choose the method ${names.join(" or ")}, or ` : "",
    "auto with a tolerance (Fidelity above) for a tighter answer.");
}

function resultParts(m, data, { interactive = false } = {}) {
  const sig = sigFigs(data.error_estimate);
  const rung = m.rungs.find((r) => r.name === data.rung);
  const meta = el("p", { class: "meta", id: interactive ? "meta" : null },
    "Method ", el("code", { id: interactive ? "rung" : null }, data.rung), rung ? ` (${rung.description})` : "",
    " · error estimate ", el("span", { id: interactive ? "error-estimate" : null }, fmtError(data.error_estimate)),
    data.error_kind ? [" ", el("span", { id: interactive ? "error-kind" : null, class: "error-kind " + data.error_kind }, estimateKindText(rung, data.error_kind))] : null,
    " · computed in ", el("span", { id: interactive ? "elapsed" : null }, fmtTime(data.elapsed_s)),
    ` · shown to ${sig} significant figures`);
  const checks = data.checks.length
    ? el("ul", { class: "checks", id: interactive ? "checks" : null }, ...data.checks.map((c) =>
      el("li", { class: c.ok ? "ok" : c.level === "advice" ? "warn" : "fail", "data-level": c.level || "requirement" },
        el("span", { class: "mark" }, c.ok ? "✓ pass " : c.level === "advice" ? "⚠ advice " : "✗ fail "), el("strong", {}, c.name),
        c.level === "advice" ? el("span", { class: "muted" }, " (advice)") : null, ": ", checkDetail(c))))
    : null;
  const warnings = data.warnings.length
    ? el("ul", { class: "warnings", id: interactive ? "warnings" : null }, ...data.warnings.map((w) => el("li", {}, "⚠ ", w))) : null;
  // the report lists the model's assumptions once, under their own heading
  const noteList = interactive ? noteTexts(data) : noteTexts(data, (n) => !(m.assumptions || []).includes(n));
  const notes = noteList.length
    ? el("ul", { class: "notes", id: interactive ? "notes" : null }, ...noteList.map((n) => el("li", {}, n))) : null;
  const table = el("div", { class: "table-wrap" },
    el("table", { id: interactive ? "results" : null, class: "results" },
      interactive ? null : el("thead", {}, el("tr", {}, ...["result", "symbol", "value", "unit", "step, source"].map((h) => el("th", {}, h)))),
      el("tbody", {}, ...resultRows(m, data, { interactive, withDesc: interactive }))));
  if (!interactive) return [meta, table, checks ? el("h3", {}, "Checks") : null, checks, warnings ? el("h3", {}, "Warnings") : null, warnings, notes ? el("h3", {}, "Notes") : null, notes].filter(Boolean);
  return [
    el("h3", { id: "result-heading", tabindex: "-1" }, "Results"), answerCard(m, data), meta, methodHint(m, data),
    el("h4", {}, "Every result"), table,
    checks ? el("h4", {}, "Checks") : null, checks,
    warnings ? el("h4", {}, "Warnings") : null, warnings,
    notes ? el("h4", {}, "Notes") : null, notes,
    el("div", { class: "downloads" },
      el("button", { type: "button", id: "download-json", onclick: () => downloadJSON(m, data) }, "Download JSON"),
      el("button", { type: "button", id: "download-csv", onclick: () => downloadCSV(m, data) }, "Download CSV")),
    Object.values(data.series).some((v) => v.length) ? el("p", { class: "muted" }, "Drag across a plot to zoom in; double-click to zoom out.") : null,
    el("div", { id: "series-plots", class: "plots" })].filter(Boolean);
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
    const u = outputUnit(o, v);
    const shown = typeof v === "number" ? v / u.factor : v;
    lines.push(["result", o.name, v, data.units[o.name] ?? o.unit, shown, u.label].map(csvCell).join(","));
  }
  for (const [k, v] of Object.entries(data.inputs)) {
    const p = m.inputs.find((x) => x.name === k);
    // a list of samples in one cell, its values separated by spaces
    lines.push(["input", k, Array.isArray(v) ? v.join(" ") : v, p && p.unit !== "1" ? p.unit : "", "", ""].map(csvCell).join(","));
  }
  lines.push(["meta", "rung", data.rung, "", "", ""].join(","));
  lines.push(["meta", "error_estimate", data.error_estimate ?? "", "1", "", ""].join(","));
  lines.push(["meta", "error_kind", data.error_kind ?? "", "", "", ""].join(","));
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
  // within the screen on a phone, at most 760 px on a desktop
  const w = container.clientWidth || Math.min(640, window.innerWidth - 40);
  return Math.max(240, Math.min(760, w - 8));
}

function maxAbs(xs) {
  let a = 0;
  for (const v of xs || []) if (typeof v === "number" && Math.abs(v) > a) a = Math.abs(v);
  return a;
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

/**
 * Lines on a histogram at the limits the result table names in the same unit
 * as its x axis: the required (minimum) and the permissible / yield preload.
 */
function histogramMarks(m, data, xo) {
  const marks = [];
  for (const o of m.outputs) {
    const v = data.results[o.name];
    if (o.series || typeof v !== "number" || norm(o.unit) !== norm(xo.unit)) continue;
    if (/required/.test(o.name)) marks.push({ at: v, label: labelOf(o), color: "#1e7b34" });
    else if (/yield|permissible/.test(o.name)) marks.push({ at: v, label: labelOf(o), color: "#b3261e" });
  }
  return marks;
}

function makeChart(container, kind, { title, xLabel, yLabel, yLabel2 = null, x, ys, bars = false, bands = [], marks = [], segments = [], xRange = null, yRange = null, xLog = false }) {
  const colors = ["#1f5f99", "#c0392b", "#2e8b57", "#8e44ad", "#b8860b", "#555"];
  const twin = ys.some((s) => s.scale === "y2");
  // the report's plots are drawn at the size they print at (12 cm wide), their text legible on paper
  const paper = kind === "report";
  const axis = { size: 70, labelSize: 18, font: "12px system-ui", labelFont: "12px system-ui" };
  const opts = {
    title,
    width: paper ? 560 : chartWidth(container),
    height: paper ? 300 : 280,
    scales: { x: { time: false, ...(xLog ? { distr: 3 } : {}), ...(xRange ? { range: xRange } : {}) }, ...(bars ? { y: { range: (u, lo, hi) => [0, hi * 1.1 || 1] } } : {}), ...(yRange ? { y: { range: yRange } } : {}) },
    axes: [{ label: xLabel, font: axis.font, labelFont: axis.labelFont }, { ...axis, label: yLabel },
      ...(twin ? [{ ...axis, scale: "y2", side: 1, label: yLabel2, grid: { show: false } }] : [])],
    series: [{ label: xLabel }, ...ys.map((s, i) => ({
      label: s.label,
      scale: s.scale || "y",
      stroke: s.color || colors[i % colors.length],
      width: 2,
      ...(s.dash ? { dash: s.dash } : {}),
      ...(s.noPoints ? { points: { show: false } } : {}),
      ...(bars ? { fill: "rgba(31,95,153,0.35)", paths: uPlot.paths.stepped({ align: 1 }), points: { show: false } } : {}),
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
      }],
      draw: [(u) => {
        const ctx = u.ctx;
        marks.forEach((mk, i) => {
          const px = u.valToPos(mk.at, "x", true);
          if (!(px >= u.bbox.left && px <= u.bbox.left + u.bbox.width)) return;
          ctx.save();
          ctx.strokeStyle = mk.color || "#888";
          ctx.lineWidth = 2 * devicePixelRatio;
          ctx.setLineDash([6 * devicePixelRatio, 4 * devicePixelRatio]);
          ctx.beginPath(); ctx.moveTo(px, u.bbox.top); ctx.lineTo(px, u.bbox.top + u.bbox.height); ctx.stroke();
          ctx.fillStyle = mk.color || "#555";
          ctx.font = `${12 * devicePixelRatio}px system-ui`;
          const w = ctx.measureText(mk.label).width;
          const right = px + 4 + w > u.bbox.left + u.bbox.width;
          ctx.fillText(mk.label, right ? px - 4 - w : px + 4, u.bbox.top + (14 + 14 * i) * devicePixelRatio);
          ctx.restore();
        });
        // vertical segments between two values of y (the joint diagram's F_A, F_Z, F_KR), labelled
        for (const sg of segments) {
          const px = u.valToPos(sg.at, "x", true);
          const y0 = u.valToPos(sg.from, "y", true), y1 = u.valToPos(sg.to, "y", true);
          ctx.save();
          ctx.strokeStyle = sg.color || "#555";
          ctx.lineWidth = (sg.width || 2) * devicePixelRatio;
          ctx.setLineDash((sg.dash || []).map((d) => d * devicePixelRatio));
          ctx.textAlign = "left";
          ctx.textBaseline = "alphabetic";
          ctx.beginPath(); ctx.moveTo(px, y0); ctx.lineTo(px, y1); ctx.stroke();
          ctx.setLineDash([]);
          for (const yy of [y0, y1]) { ctx.beginPath(); ctx.moveTo(px - 5 * devicePixelRatio, yy); ctx.lineTo(px + 5 * devicePixelRatio, yy); ctx.stroke(); }
          ctx.fillStyle = sg.color || "#555";
          ctx.font = `bold ${13 * devicePixelRatio}px system-ui`;
          const w = ctx.measureText(sg.label).width;
          const left = sg.side === "left";
          const ty = sg.side === "top" ? Math.min(y0, y1) - 6 * devicePixelRatio : (y0 + y1) / 2 + 4 * devicePixelRatio;
          ctx.fillText(sg.label, left ? px - 6 * devicePixelRatio - w : sg.side === "top" ? px - w / 2 : px + 6 * devicePixelRatio, ty);
          ctx.restore();
        }
      }],
    },
  };
  const box = el("figure", { class: "chart", "data-kind": kind });
  container.append(box);
  const chart = new uPlot(opts, [x, ...ys.map((s) => s.data)], box);
  state.charts.push({ kind, chart });
  box.append(dataTable(title, xLabel, x, ys));
  if (segments.length) box.dataset.segments = JSON.stringify(Object.fromEntries(segments.map((sg) => [sg.key, [sg.at, sg.from, sg.to]])));
  return chart;
}

/**
 * The joint diagram as VDI 2230 draws it (Part 1, §3.2), from the joint model's series:
 * the bolt line rising from the origin to the preload F_M,min, the clamped-part line
 * falling from that point, and after embedding from F_V; F_A inserted at the working
 * point (the model's diagram_working_* pair, from F_KR up to F_S), F_Z as the drop from
 * F_M,min to F_V, F_KR from zero up, the separation point dashed. The points where the
 * lines meet are read off the series (the bolt line is straight through the origin), no
 * formula repeated here. Returns the names it drew, or an empty set when the model has
 * no such series.
 */
function jointDiagram(m, data, box, kind) {
  const S = data.series;
  const need = ["diagram_deformation", "diagram_bolt_line", "diagram_clamped_line", "diagram_preload_level", "diagram_working_deformation", "diagram_working_force"];
  if (!need.every((k) => S[k] && S[k].length)) return new Set();
  const byName = Object.fromEntries(m.outputs.map((o) => [o.name, o]));
  const drawn = new Set(m.outputs.filter((o) => o.name.startsWith("diagram_")).map((o) => o.name));
  const d = S.diagram_deformation, bolt = S.diagram_bolt_line, plate = S.diagram_clamped_line;
  const n = d.length;
  // deformation per force along the bolt line (δ_S), read at its first step (its top end is clipped)
  const slope = d[1] / bolt[1];
  if (!(Number.isFinite(slope) && slope > 0)) return new Set();
  const fm = S.diagram_preload_level[0];
  const fv = S.diagram_service_preload_level?.[0] ?? fm;
  const xm = fm * slope, xv = fv * slope;
  const [xw] = S.diagram_working_deformation, [fkr, fs] = S.diagram_working_force;
  const xo = S.diagram_opening_deformation?.[0];
  const embedded = S.diagram_embedded_clamped_line;
  // one x axis: the series' grid with the points where the lines meet
  const xs = [...new Set([...d, xm, xv, xw, ...(xo !== undefined ? [xo] : [])])].sort((a, b) => a - b);
  const at = (ys, x) => {
    // the series' value at x, linear between its grid points
    let i = d.findIndex((v) => v >= x);
    if (i <= 0) return ys[Math.max(i, 0)];
    const t = (x - d[i - 1]) / (d[i] - d[i - 1]);
    return ys[i - 1] + t * (ys[i] - ys[i - 1]);
  };
  const fu = outputUnit(byName.diagram_bolt_line, Math.max(fm, fs, ...bolt));
  const du = outputUnit(byName.diagram_deformation, d[n - 1]);
  const F = (v) => (v === null || v === undefined ? null : v / fu.factor);
  const boltY = xs.map((x) => (x <= xm ? F(x / slope) : null));
  // a clamped-part line from its start (x0, f0) down to zero force, not along the axis beyond
  const falling = (ys, x0, f0) => {
    let ended = false;
    return xs.map((x) => {
      if (x < x0 || ended) return null;
      const v = x === x0 ? f0 : at(ys, x);
      if (v <= 0) { ended = true; return 0; }
      return F(v);
    });
  };
  const line = { unit: fu.label, color: "#2e8b57", noPoints: true };
  const ys = [
    { label: "bolt", data: boltY, unit: fu.label, color: "#1f5f99", noPoints: true },
    { label: "clamped parts", data: falling(plate, xm, fm), ...line },
  ];
  if (embedded && fv < fm) ys.push({ label: "clamped parts after embedding", data: falling(embedded, xv, fv), ...line, dash: [6, 4] });
  const segments = [
    { key: "F_A", at: xw / du.factor, from: F(fkr), to: F(fs), label: "F_A", color: "#c0392b", width: 3, side: "left" },
    { key: "F_KR", at: xw / du.factor, from: 0, to: F(fkr), label: "F_KR", color: "#8e44ad", side: "left" },
  ];
  if (fv < fm) segments.push({ key: "F_Z", at: xm / du.factor, from: F(fv), to: F(fm), label: "F_Z", color: "#b8860b" });
  if (xo !== undefined && S.diagram_opening_force) {
    segments.push({ key: "opening", at: xo / du.factor, from: 0, to: F(S.diagram_opening_force[1]), label: "separation", color: "#888", dash: [4, 4], width: 1, side: "top" });
  }
  const top = Math.max(fm, fs, ...(S.diagram_opening_force ?? [0]));
  makeChart(box, kind, {
    title: "Joint diagram (VDI 2230): bolt and clamped parts, F_A at the working point",
    xLabel: `deformation f${du.label ? " [" + du.label + "]" : ""}`,
    yLabel: `force F${fu.label ? " [" + fu.label + "]" : ""}`,
    x: xs.map((x) => x / du.factor), ys, segments, yRange: [0, F(top) * 1.1],
  });
  return drawn;
}

/** The plotted values as a table (the plot's text alternative): at most 200 rows. */
function dataTable(title, xLabel, x, ys) {
  const step = Math.max(1, Math.ceil(x.length / 200));
  const rows = [];
  for (let i = 0; i < x.length; i += step) {
    rows.push(el("tr", {}, el("td", {}, fmt(x[i], 5)), ...ys.map((s) => el("td", {}, fmt(s.data[i], 5)))));
  }
  return el("details", { class: "data-table" },
    el("summary", {}, "Table of the plotted values" + (step > 1 ? ` (one point in ${step})` : "")),
    el("div", { class: "table-wrap" }, el("table", { "aria-label": title },
      el("thead", {}, el("tr", {}, el("th", {}, xLabel), ...ys.map((s) => el("th", {}, s.label + (s.unit ? ` [${s.unit}]` : ""))))),
      el("tbody", {}, ...rows))));
}

/**
 * Every series output against its declared x series. Curves sharing an x series
 * and a unit share a chart (e.g. the travel of each part against time); a
 * series that declares ``plot.bars`` (its x holds bin centres, or edges one
 * longer) draws as a histogram of full-width bins, with lines at the limits in
 * the same unit.
 */
function renderSeries(m, data, box = document.getElementById("series-plots"), kind = "series") {
  destroyCharts(kind);
  const byName = Object.fromEntries(m.outputs.map((o) => [o.name, o]));
  const usedAsX = new Set(m.outputs.filter((o) => o.series && o.x).map((o) => o.x));
  const charts = new Map(); // key -> chart spec, in the order the model lists its outputs
  const unitOf = new Map(); // one unit per output unit, so curves of a chart agree
  const diagram = jointDiagram(m, data, box, kind); // drawn as VDI draws it, not as plain curves
  for (const o of m.outputs) {
    const ys = data.series[o.name];
    if (!o.series || !ys || !ys.length || diagram.has(o.name)) continue;
    if (!o.x && usedAsX.has(o.name)) continue; // an axis, not a curve
    const ukey = norm(o.unit);
    if (!unitOf.has(ukey)) unitOf.set(ukey, outputUnit(o, maxAbs(m.outputs.filter((q) => q.series && norm(q.unit) === ukey).flatMap((q) => data.series[q.name] || []))));
    const yu = isRatio(o) ? PERCENT : unitOf.get(ukey);
    const y = ys.map((v) => (v === null ? null : v / yu.factor));
    let xs = o.x ? data.series[o.x] : null;
    const xo = o.x && xs ? byName[o.x] : null;
    const xu = xo ? outputUnit(xo, maxAbs(xs)) : { factor: 1, label: "" };
    const xLabel = xo ? `${labelOf(xo)}${xu.label ? " [" + xu.label + "]" : ""}` : "sample";
    let bars = false, xRange = null, marks = [];
    let yData = y;
    if (!xs) xs = ys.map((_, i) => i);
    else if (xs.length === ys.length + 1 || (xs.length === ys.length && o.plot?.bars)) {
      bars = true;
      let edges = xs;
      if (xs.length === ys.length) {
        // bin centres: the edges half a bin either side (equal bins)
        const w = xs.length > 1 ? (xs[xs.length - 1] - xs[0]) / (xs.length - 1) : Math.abs(xs[0]) * 0.1 || 1;
        edges = [...xs.map((c) => c - w / 2), xs[xs.length - 1] + w / 2];
      }
      xs = edges;
      yData = [...y, y[y.length - 1]]; // a step per bin, edge to edge
      marks = histogramMarks(m, data, xo).map((mk) => ({ ...mk, at: mk.at / xu.factor }));
      const lo = Math.min(edges[0] / xu.factor, ...marks.map((mk) => mk.at));
      const hi = Math.max(edges[edges.length - 1] / xu.factor, ...marks.map((mk) => mk.at));
      xRange = [lo - (hi - lo) * 0.03, hi + (hi - lo) * 0.03];
    } else if (xs.length !== ys.length) continue;
    const key = bars ? "bars:" + o.name : `${xo ? o.x : "index:" + ys.length}|${norm(o.unit)}`;
    if (!charts.has(key)) {
      const x = xs.map((v) => v / xu.factor);
      const bands = xo && !bars ? windows(xo, data).map((b) => ({ ...b, from: b.from / xu.factor, to: b.to / xu.factor })) : [];
      charts.set(key, { xLabel, unit: yu.label, x, ys: [], bars, bands, xRange, marks });
    }
    charts.get(key).ys.push({ label: labelOf(o), data: yData, unit: yu.label });
  }
  for (const c of charts.values()) {
    const names = c.ys.map((s) => s.label).join(", ");
    const title = names.length <= 60 ? names : `${c.ys[0].label} and ${c.ys.length - 1} more`;
    makeChart(box, kind, {
      title: title + (c.bars ? " (histogram)" : ""),
      xLabel: c.xLabel, yLabel: `${names.length <= 32 ? names : c.ys[0].label + ", …"}${c.unit ? " [" + c.unit + "]" : ""}`,
      x: c.x, ys: c.ys, bars: c.bars, bands: c.bands, xRange: c.xRange, marks: c.marks,
    });
  }
}

// ---------------------------------------------------------------- sweep

function sweepPanel(m) {
  const numeric = m.inputs.filter((p) => p.kind === "float" || p.kind === "int");
  const scalars = m.outputs.filter((o) => !o.series && (o.kind === "float" || o.kind === "int"));
  if (!numeric.length || !scalars.length) return el("div");
  const vary = el("select", { id: "sweep-vary" }, ...numeric.map((p) => el("option", { value: p.name }, p.label)));
  const output = el("select", { id: "sweep-output" }, ...scalars.map((o) => el("option", { value: o.name }, labelOf(o))));
  const more = el("details", { id: "sweep-more", class: "sweep-more" }, el("summary", {}, "more outputs"),
    el("div", { class: "more-list" }, ...scalars.map((o) => el("label", {},
      el("input", { type: "checkbox", value: o.name }), " ", labelOf(o)))));
  const start = el("input", { id: "sweep-start", size: 9, inputmode: "decimal" });
  const stop = el("input", { id: "sweep-stop", size: 9, inputmode: "decimal" });
  const unit = el("select", { id: "sweep-unit", "aria-label": "unit of the swept range" });
  unit.addEventListener("change", () => {
    const prev = Number(unit.dataset.factor), next = Number(unit.selectedOptions[0].dataset.factor);
    for (const f of [start, stop]) if (Number.isFinite(parseNum(f.value))) f.value = fieldText((parseNum(f.value) * prev) / next);
    unit.dataset.factor = String(next);
  });
  const read = el("output", { id: "sweep-read", class: "read-as", for: "sweep-start sweep-stop" });
  const echo = () => {
    const qs = [start, stop].map((f) => readQuantity(f.value));
    const bad = qs.find((q) => !q.ok && !q.empty);
    const differs = [start, stop].some((f, i) => qs[i].ok && !isPlain(qs[i].unit ? f.value.trim().slice(0, -qs[i].unit.length) : f.value));
    read.textContent = bad ? bad.error || "a number is needed"
      : differs && qs.every((q) => q.ok) ? `= ${echoNumber(qs[0].value)} … ${echoNumber(qs[1].value)} ${qs[0].unit || sweepUnit().label}` : "";
    read.classList.toggle("error", Boolean(bad));
  };
  for (const f of [start, stop]) f.addEventListener("input", echo);
  const num = el("input", { id: "sweep-num", size: 4, value: "40", inputmode: "numeric" });
  const scale = el("select", { id: "sweep-scale", "aria-label": "scale of the swept input" }, el("option", { value: "linear" }, "linear"), el("option", { value: "log" }, "log"));
  const axes = el("select", { id: "sweep-axes", "aria-label": "axes of several outputs" },
    el("option", { value: "auto" }, "axes: auto"), el("option", { value: "shared" }, "one shared axis"), el("option", { value: "twin" }, "twin axes"));
  vary.addEventListener("change", () => sweepDefaults(m));
  const panel = el("section", { class: "sweep", id: "sweep" },
    el("h3", {}, "Sweep one input"),
    el("p", { class: "muted" }, "The other inputs stay as in the form; a point the model refuses is left out of the curve."),
    el("div", { class: "control sweep-controls" },
      el("span", {}, el("label", { for: "sweep-output" }, "plot "), output), more,
      el("span", {}, el("label", { for: "sweep-vary" }, " against "), vary),
      el("span", {}, el("label", { for: "sweep-start" }, " from "), start), el("span", {}, el("label", { for: "sweep-stop" }, " to "), stop, " ", unit), read,
      el("span", {}, el("label", { for: "sweep-num" }, " points "), num), scale, axes,
      el("button", { type: "button", id: "sweep-run", onclick: () => runSweep(m) }, "Sweep")),
    el("div", { class: "error", id: "sweep-error" }),
    el("div", { id: "sweep-notes", class: "notes" }),
    el("p", { id: "sweep-stale", class: "stale-note", hidden: true }, "Inputs changed: sweep again"),
    el("div", { id: "sweep-plot", class: "plots" }),
    el("div", { class: "downloads", id: "sweep-downloads", hidden: true },
      el("button", { type: "button", id: "sweep-csv", onclick: () => downloadSweep(m, "csv") }, "Download sweep CSV"),
      el("button", { type: "button", id: "sweep-json", onclick: () => downloadSweep(m, "json") }, "Download sweep JSON")));
  queueMicrotask(() => sweepDefaults(m));
  return panel;
}

/** The unit the sweep's range is written in: {api, factor, label}. */
function sweepUnit() {
  const o = document.getElementById("sweep-unit").selectedOptions[0];
  return o ? { api: o.value, factor: Number(o.dataset.factor), label: o.textContent } : { api: "", factor: 1, label: "" };
}

/** Choose the sweep's unit (from a link) without converting the range. */
function setSweepUnit(m, api) {
  const sel = document.getElementById("sweep-unit");
  const opt = [...sel.options].find((o) => norm(o.value) === norm(api) || norm(o.textContent) === norm(api));
  if (opt) { sel.value = opt.value; sel.dataset.factor = opt.dataset.factor; }
}

/** A dashed line at the design in the form (its varied input's current value). */
function designMark(m, p, u) {
  const input = document.getElementById("in-" + p.name);
  const si = exactSI(input) ?? parseNum(input.value) * currentUnit(p).factor;
  return Number.isFinite(si) ? [{ at: si / u.factor, label: "this design" }] : [];
}

/** A range around the current value of the varied input, inside its allowed range, in the field's unit. */
function sweepDefaults(m) {
  const p = m.inputs.find((x) => x.name === document.getElementById("sweep-vary").value);
  const u = currentUnit(p);
  const sel = document.getElementById("sweep-unit");
  const choices = unitChoices(p.unit, p.display_unit);
  sel.replaceChildren(...choices.map((c) => el("option", { value: c.api, "data-factor": c.factor }, c.label)));
  setSweepUnit(m, u.api || u.label);
  sel.dataset.factor = sel.selectedOptions[0]?.dataset.factor ?? "1";
  sel.disabled = choices.length < 2;
  const raw = parseNum(document.getElementById("in-" + p.name).value);
  let v = Number.isFinite(raw) ? raw * u.factor : (p.default ?? 1);
  let lo = v > 0 ? v * 0.5 : v < 0 ? v * 1.5 : 0;
  let hi = v > 0 ? v * 1.5 : v < 0 ? v * 0.5 : 1;
  if (p.minimum !== null && p.minimum !== undefined && lo <= p.minimum) lo = p.exclusive_minimum ? p.minimum + (v - p.minimum) * 0.1 : p.minimum;
  if (p.maximum !== null && p.maximum !== undefined && hi >= p.maximum) hi = p.exclusive_maximum ? p.maximum - (p.maximum - v) * 0.1 : p.maximum;
  if (p.kind === "int") { lo = Math.ceil(lo); hi = Math.max(lo + 1, Math.floor(hi)); }
  if (p.kind === "int") document.getElementById("sweep-num").value = String(Math.min(hi - lo + 1, 200));
  const su = sweepUnit();
  document.getElementById("sweep-start").value = fieldText(lo / su.factor);
  document.getElementById("sweep-stop").value = fieldText(hi / su.factor);
}

function sweepOutputs() {
  const first = document.getElementById("sweep-output").value;
  const extra = [...document.querySelectorAll("#sweep-more input:checked")].map((b) => b.value);
  return [first, ...extra.filter((x) => x !== first)];
}

async function runSweep(m) {
  const vary = document.getElementById("sweep-vary").value;
  const p = m.inputs.find((x) => x.name === vary);
  const outputs = sweepOutputs();
  const u = sweepUnit();
  const end = (id) => {
    const raw = document.getElementById(id).value.trim();
    const q = readQuantity(raw);
    if (q.ok && q.unit) return `${q.canonical} ${q.unit}`;
    return u.api && q.ok ? `${q.canonical} ${u.api}` : q.ok ? q.value : raw;
  };
  const errBox = document.getElementById("sweep-error");
  const unread = ["sweep-start", "sweep-stop"].map((id) => [id, readQuantity(document.getElementById(id).value)])
    .filter(([, q]) => !q.ok);
  if (unread.length) {
    errBox.textContent = "Sweep not run: " + unread.map(([id, q]) =>
      `${id === "sweep-start" ? "from" : "to"}: ${q.error || "a number is needed"}`).join("; ");
    document.body.dataset.sweep = "error";
    return;
  }
  let num = Number(document.getElementById("sweep-num").value) || 40;
  if (p.kind === "int") {
    // an integer input is swept over whole numbers only: one point per integer
    const a = parseNum(document.getElementById("sweep-start").value), b = parseNum(document.getElementById("sweep-stop").value);
    if (Number.isInteger(a) && Number.isInteger(b) && b > a) num = Math.min(b - a + 1, 2000);
    document.getElementById("sweep-num").value = String(num);
  }
  const req = {
    base: requestBody(m, { skip: vary }), vary, start: end("sweep-start"), stop: end("sweep-stop"),
    num,
    scale: document.getElementById("sweep-scale").value, outputs, ...fidelityBody(),
  };
  errBox.textContent = "";
  for (const p2 of m.inputs) setError(p2.name, "");
  const seq = ++state.sweepSeq;
  const { ok, data } = await post(m.path + "/sweep", req);
  if (seq !== state.sweepSeq || state.model !== m) return;
  document.getElementById("sweep-downloads").hidden = !ok;
  if (!ok) {
    destroyCharts("sweep");
    document.getElementById("sweep-plot").replaceChildren();
    document.getElementById("sweep-notes").replaceChildren();
    // base inputs are marked at their fields; the box repeats every message
    const msgs = [];
    for (const d of data.detail || []) {
      const field = (d.loc || []).filter((x) => x !== "body" && x !== "base").join(".") || d.field;
      if (field && field !== vary) setError(field, d.msg);
      msgs.push(d.msg);
    }
    errBox.textContent = "Sweep refused: " + (msgs.join(" ") || `HTTP error`);
    announce(errBox.textContent);
    state.lastSweep = { request: req, response: null };
    document.body.dataset.sweep = "error";
    return;
  }
  const snap = snapshot(m);
  delete snap[vary];
  state.lastSweep = { request: req, response: data, unit: u, snapshot: snap };
  state.sweepParams = {
    sv: vary, su: u.api || u.label, so: outputs.join(","), s0: document.getElementById("sweep-start").value.trim(),
    s1: document.getElementById("sweep-stop").value.trim(), sn: String(num), ss: req.scale,
    sa: document.getElementById("sweep-axes").value,
  };
  updateHash(m, { ...requestBody(m), ...fidelityBody() });
  const got = outputs.filter((o) => Array.isArray(data.results[o]));
  if (!got.length) {
    destroyCharts("sweep");
    document.getElementById("sweep-plot").replaceChildren();
    errBox.textContent = `The sweep returned no values of ${outputs.join(", ")} (method ${data.rung}); try another output or method.`;
    document.body.dataset.sweep = "empty";
    return;
  }
  plotSweep(m);
  const msgs = [...data.warnings.map((w) => "⚠ " + w), ...data.notes];
  document.getElementById("sweep-notes").replaceChildren(...msgs.slice(0, 6).map((n) => el("p", {}, n)),
    ...(msgs.length > 6 ? [el("p", { class: "muted" }, `… and ${msgs.length - 6} more`)] : []));
  announce(`Sweep done: ${data.values.length} points.`);
  document.body.dataset.sweep = "ok";
}

/**
 * The last sweep: one curve per output. Outputs in one unit share the axis;
 * with two units (or "twin axes") the first unit is on the left, the rest on the right.
 */
function plotSweep(m, box = document.getElementById("sweep-plot"), kind = "sweep") {
  const sw = state.lastSweep;
  if (!sw?.response) return;
  const { request: req, response: data } = sw;
  destroyCharts(kind);
  box.replaceChildren();
  const p = m.inputs.find((x) => x.name === req.vary);
  const u = sw.unit;
  const outs = req.outputs.filter((o) => Array.isArray(data.results[o])).map((n) => m.outputs.find((x) => x.name === n));
  const mode = document.getElementById("sweep-axes")?.value ?? "auto";
  const units = [...new Set(outs.map((o) => norm(o.unit)))];
  const twin = outs.length > 1 && (mode === "twin" || (mode === "auto" && units.length > 1));
  const ys = outs.map((o) => {
    const ou = outputUnit(o, maxAbs(data.results[o.name]));
    const right = twin && (units.length > 1 ? norm(o.unit) !== units[0] : o !== outs[0]);
    return { label: labelOf(o), unit: ou.label, scale: right ? "y2" : "y", data: data.results[o.name].map((v) => (v === null ? null : v / ou.factor)) };
  });
  const axisLabel = (list) => {
    const names = list.map((s) => s.label).join(", ");
    const us = [...new Set(list.map((s) => s.unit).filter(Boolean))];
    return `${names.length <= 32 ? names : list[0].label + ", …"}${us.length ? " [" + us.join(", ") + "]" : ""}`;
  };
  makeChart(box, kind, {
    title: `${ys.map((s) => s.label).join(", ")} against ${p.label} (method ${data.rung}, ${fmtTime(data.elapsed_s)})`,
    xLabel: `${p.label}${u.label ? " [" + u.label + "]" : ""}`,
    yLabel: axisLabel(ys.filter((s) => s.scale === "y")), yLabel2: twin ? axisLabel(ys.filter((s) => s.scale === "y2")) : null,
    x: data.values.map((v) => v / u.factor), ys, xLog: req.scale === "log", marks: designMark(m, p, u),
  });
}

function downloadSweep(m, kind) {
  const sw = state.lastSweep;
  if (!sw?.response) return;
  const { request: req, response: data } = sw;
  if (kind === "json") {
    download(`${m.name}-sweep.json`, "application/json",
      JSON.stringify({ model: m.name, link: location.href, request: req, response: data }, null, 2));
    return;
  }
  const outs = req.outputs.filter((o) => Array.isArray(data.results[o]));
  const head = [`${req.vary} [${data.unit ?? m.inputs.find((x) => x.name === req.vary)?.unit ?? ""}]`,
    ...outs.map((o) => `${o} [${data.units?.[o] ?? m.outputs.find((x) => x.name === o)?.unit ?? ""}]`)];
  const lines = [head.map(csvCell).join(",")];
  data.values.forEach((v, i) => lines.push([v, ...outs.map((o) => data.results[o][i])].map(csvCell).join(",")));
  download(`${m.name}-sweep.csv`, "text/csv", lines.join("\n") + "\n");
}

// ---------------------------------------------------------------- report

/** The calculation report: a view on screen (view=report), and what the page prints. */
/** Project and part name: kept in the link, the design file and the report's header. */
/** The report's names, kept in the link: what it is for, who made and checked it, which revision. */
const REPORT_NAMES = [
  ["proj", "report-project", "Project", "project"],
  ["part", "report-part", "Part", "part / joint"],
  ["auth", "report-author", "Author", "calculated by"],
  ["chk", "report-checker", "Checker", "checked by"],
  ["rev", "report-revision", "Revision", "e.g. A"],
];

function designNames(m, params) {
  const row = el("div", { class: "actions names" });
  for (const [key, id, label, hint] of REPORT_NAMES) {
    const f = el("input", { id, type: "text", value: params.get(key) ?? "", placeholder: hint, class: key === "rev" ? "short" : null });
    f.addEventListener("change", () => updateHash(m, { ...requestBody(m), ...fidelityBody() }));
    row.append(el("span", { class: "name" }, el("label", { for: id }, label), " ", f));
  }
  return row;
}

function reportName(id) {
  return document.getElementById(id)?.value.trim() ?? "";
}

/** The fastener the result is for, as a designation: "M12 8.8", "M20×1.5 10.9", or "" (no bolt). */
function fastenerText(data) {
  const r = data.results || {}, x = data.inputs || {};
  if (typeof r.fastener === "string" && r.fastener) return r.fastener;
  if (typeof x.thread === "string" && x.thread) return [x.thread, x.grade || x.property_class].filter(Boolean).join(" ");
  if (typeof x.thread_diameter !== "number") return "";
  const pitch = typeof x.thread_pitch === "number" ? `×${short(x.thread_pitch * 1e3, 3)}` : "";
  const parts = [`M${short(x.thread_diameter * 1e3, 4)}${pitch}`, x.property_class, x.head_standard, x.washer && `washer ${x.washer}`, x.nut && `nut ${x.nut}`];
  return parts.filter(Boolean).join(" ");
}

function reportSection(m) {
  return el("section", { id: "report", class: "report", "aria-label": "calculation report" },
    el("div", { class: "report-bar no-print" },
      el("button", { type: "button", id: "print-report", onclick: () => window.print() }, "Print / save as PDF"),
      el("button", { type: "button", id: "close-report", onclick: () => showView(null) }, "Back to the form")),
    el("header", { class: "report-head" },
      el("h2", {}, "Calculation report: ", m.title),
      el("p", { class: "report-ids", id: "report-ids" }),
      el("p", { class: "report-meta", id: "report-meta" })),
    el("div", { id: "report-body" }, el("p", { class: "muted" }, "Compute to fill the report.")));
}

/** Show the report or the comparison over the form, or (null) the form again. */
function showView(view) {
  document.body.classList.toggle("view-report", view === "report");
  document.body.classList.toggle("view-compare", view === "compare");
  if (view === "report" && state.model) renderReport(state.model);
  if (state.model) updateHash(state.model, { ...requestBody(state.model), ...fidelityBody() });
  window.scrollTo(0, 0);
}

function equationNode(latex) {
  const box = el("div", { class: "eq" });
  try {
    // katex.render builds DOM nodes (styles through the CSSOM), which the page's CSP allows
    window.katex.render(latex, box, { displayMode: true, throwOnError: false, output: "html" });
  } catch {
    box.textContent = latex;
  }
  return box;
}

function inputsTable(m, data) {
  const rows = [];
  const example = state.example === "defaults" ? "source default" : `example ${Number(state.example) + 1}`;
  for (const p of m.inputs) {
    const v = data.inputs[p.name];
    if (v === null || v === undefined) continue;
    const input = document.getElementById("in-" + p.name);
    const given = input && touched(input) ? "entered" : (state.example !== "defaults" && p.name in (m.examples[Number(state.example)] || {})) ? example : "default";
    let shown, unit = "";
    if (typeof v === "number" && (p.kind === "float" || p.kind === "int")) {
      const u = p.kind === "int" ? { factor: 1, label: "" } : (currentUnit(p).factor ? currentUnit(p) : unitChoices(p.unit, p.display_unit)[0]);
      shown = p.kind === "int" ? String(v) : group(short(v / u.factor, 6));
      unit = u.label;
    } else if (Array.isArray(v)) {
      // a list of measured values: how many, and their range, in the field's unit
      const u = currentUnit(p).factor ? currentUnit(p) : unitChoices(p.unit, p.display_unit)[0];
      shown = `${v.length} values, ${group(short(Math.min(...v) / u.factor, 6))} … ${group(short(Math.max(...v) / u.factor, 6))}`;
      unit = u.label;
    } else shown = typeof v === "boolean" ? (v ? "yes" : "no") : choiceText(String(v));
    const cites = [...new Set((p.description || "").match(/\[\d{3}[^\]]*\]/g) || [])].join(" ");
    rows.push(el("tr", {}, el("th", { scope: "row" }, p.label, p.symbol ? el("span", { class: "symbol" }, " " + p.symbol) : null),
      el("td", { class: "num" }, shown), el("td", { class: "unit" }, unit), el("td", { class: "from" }, given, cites ? el("span", { class: "muted" }, " " + cites) : null)));
  }
  return el("table", { class: "results inputs", id: "report-inputs" },
    el("thead", {}, el("tr", {}, el("th", {}, "input"), el("th", {}, "value"), el("th", {}, "unit"), el("th", {}, "from, source"))),
    el("tbody", {}, ...rows));
}

function renderReport(m) {
  const body = document.getElementById("report-body");
  const data = state.lastResponse;
  if (!body || !data) return;
  destroyCharts("report");
  const now = new Date();
  const names = Object.fromEntries(REPORT_NAMES.map(([key, id]) => [key, reportName(id)]));
  const fastener = fastenerText(data);
  const ids = [["Project", names.proj], ["Part", names.part], ...(fastener ? [["Fastener", fastener]] : []),
    ["Author", names.auth], ["Checker", names.chk], ["Revision", names.rev]];
  document.getElementById("report-ids").replaceChildren(...ids.flatMap(([label, v], i) =>
    [i ? " · " : "", `${label} `, el("strong", { id: label === "Fastener" ? "report-fastener" : null }, v || "—")]));
  // the running header and footer of every printed page (CSS @page margin boxes read them)
  const root = document.documentElement.style;
  root.setProperty("--report-head", JSON.stringify(`Calculation report · ${m.title}${names.proj ? " · " + names.proj : ""}${names.part ? " · " + names.part : ""}`));
  root.setProperty("--report-foot", JSON.stringify(`tightening-calc ${state.version || "?"}${state.commit && state.commit !== "unknown" ? " (" + state.commit.slice(0, 12) + ")" : ""} · ${m.name}${names.rev ? " · revision " + names.rev : ""} · ${now.toISOString().slice(0, 10)}`));
  document.getElementById("report-meta").replaceChildren(
    `${now.toISOString().slice(0, 16).replace("T", " ")} UTC · tightening-calc ${state.version || "?"}`,
    ...(state.commit && state.commit !== "unknown" ? [" (commit ", el("code", { id: "report-commit" }, state.commit.slice(0, 12)), ")"] : []),
    " · model ",
    el("code", {}, m.name), " · ", el("a", { href: location.href, class: "report-link" }, "link to this calculation"));
  const sources = (m.sources || []).map((x) => el("li", {}, String(x.reference).startsWith("[") ? x.reference : `[${x.id}] ${x.reference}`));
  // the equations of the steps of the rung that produced this result (the model's all when
  // the rung declares none), in the order of its procedure
  const ran = (m.rungs || []).find((r) => r.name === data.rung);
  const eqs = ((ran && ran.equations) || m.equations || []).map((e) => el("div", { class: "eq-row" },
    el("p", { class: "eq-what" }, plainText(e.summary).replace(/\s*\[[^\]]*\]\.?$/, ""), e.source ? el("span", { class: "muted" }, ` ${e.source}`) : null),
    ...e.latex.map(equationNode)));
  const seriesBox = el("div", { class: "plots report-plots" });
  // results and checks beside the inputs; warnings and notes below both, full width
  const parts = resultParts(m, data);
  const cut = parts.findIndex((p) => p.tagName === "H3" && ["Warnings", "Notes"].includes(p.textContent));
  const beside = cut < 0 ? parts : parts.slice(0, cut);
  const below = cut < 0 ? [] : parts.slice(cut);
  body.replaceChildren(...[
    el("p", { class: "summary" }, m.summary),
    el("p", { class: "source" }, el("strong", {}, "Source: "), m.source),
    sources.length ? el("ul", { class: "sources" }, ...sources) : null,
    answerCard(m, data, { interactive: false }),
    (m.assumptions || []).length ? el("h3", {}, "Assumptions") : null,
    (m.assumptions || []).length ? el("ul", { class: "notes assumptions" }, ...m.assumptions.map((x) => el("li", {}, x))) : null,
    el("div", { class: "two-col" },
      el("div", {}, el("h3", {}, "Inputs"), el("div", { class: "table-wrap" }, inputsTable(m, data))),
      el("div", {}, el("h3", {}, "Results"), ...beside)),
    below.length ? el("div", { class: "report-notes" }, ...below) : null,
    eqs.length ? el("h3", {}, "Equations used") : null,
    eqs.length ? el("div", { class: "equations" }, ...eqs) : null,
    seriesBox,
    signOff(names)].filter(Boolean));
  if (Object.values(data.series).some((v) => v.length)) renderSeries(m, data, seriesBox, "report");
  if (state.lastSweep?.response) plotSweep(m, seriesBox.appendChild(el("div", {})), "report");
  markWideEquations(body);
}

/** Equations wider than half the printed page take the whole width (print CSS: .eq-row.wide)
 *  instead of being cut at their column's edge: a column of A4 holds about 28 em of KaTeX. */
function markWideEquations(root) {
  for (const row of root.querySelectorAll(".eq-row")) {
    let em = 0;
    for (const k of row.querySelectorAll(".katex-html")) {
      const range = document.createRange();
      range.selectNodeContents(k);
      const size = parseFloat(getComputedStyle(k).fontSize);
      if (size > 0) em = Math.max(em, range.getBoundingClientRect().width / size);
    }
    if (em > 0) row.classList.toggle("wide", em > 28);  // 0: not laid out (hidden), keep as is
  }
}
window.addEventListener("beforeprint", () => {
  const body = document.getElementById("report-body");
  if (body) markWideEquations(body);
});

/** A docstring's sentence without its markup: ``code`` and :role:`text` read as their text. */
function plainText(text) {
  return String(text ?? "").replace(/:[a-z]+:`~?([^`]*)`/g, "$1").replace(/``([^`]*)``/g, "$1");
}

/** Who calculated and who checked, with room to sign: the names from the form, the rest by hand. */
function signOff(names) {
  const row = (role, name) => el("tr", {}, el("th", { scope: "row" }, role), el("td", { class: "who" }, name || ""), el("td", { class: "sign" }, ""), el("td", { class: "sign" }, ""));
  return el("section", { class: "sign-off", id: "sign-off", "aria-label": "sign-off" },
    el("h3", {}, `Sign-off${names.rev ? ` · revision ${names.rev}` : ""}`),
    el("table", { class: "sign-table" },
      el("thead", {}, el("tr", {}, el("th", {}, ""), el("th", {}, "name"), el("th", {}, "date"), el("th", {}, "signature"))),
      el("tbody", {}, row("Calculated by", names.auth), row("Checked by", names.chk))));
}

// ---------------------------------------------------------------- designs as files

const DESIGN_KIND = "tightening-calculator/design";

function designOf(m) {
  const fid = fidelityBody();
  return {
    kind: DESIGN_KIND, version: 1, model: m.name, title: m.title,
    project: document.getElementById("report-project")?.value.trim() || "",
    part: document.getElementById("report-part")?.value.trim() || "",
    example: state.example, inputs: formInputs(m), fidelity: fid.fidelity,
    ...(fid.tolerance !== undefined ? { tolerance: fid.tolerance } : {}),
    saved: new Date().toISOString(), link: location.href,
  };
}

function saveDesign(m) {
  const d = designOf(m);
  const name = (d.part || d.project || m.name).replace(/[^\w.-]+/g, "_");
  download(`${name}.design.json`, "application/json", JSON.stringify(d, null, 2) + "\n");
}

async function readDesign(file) {
  const d = JSON.parse(await file.text());
  if (d.kind !== DESIGN_KIND || typeof d.inputs !== "object") throw new Error(`${file.name} is not a saved design`);
  if (!state.models.some((x) => x.name === d.model)) throw new Error(`${file.name}: unknown model ${d.model}`);
  return d;
}

function designHash(d) {
  const params = new URLSearchParams({ m: d.model, ex: d.example ?? "defaults" });
  for (const [k, v] of Object.entries(d.inputs)) params.set(k, v);
  params.set("fidelity", d.fidelity || "auto");
  if (typeof d.tolerance === "number") params.set("tol", fieldNumber(d.tolerance * 100));
  if (d.project) params.set("proj", d.project);
  if (d.part) params.set("part", d.part);
  return "#" + params.toString();
}

async function openDesign(fileInput) {
  const file = fileInput.files[0];
  fileInput.value = "";
  if (!file) return;
  try {
    const d = await readDesign(file);
    history.replaceState(null, "", designHash(d));
    state.model = null; // reload the form from the file
    await route();
  } catch (e) {
    document.getElementById("error-box").replaceChildren(el("p", { class: "error" }, String(e.message || e)));
  }
}

/** Compute each design and show them side by side; cells that differ from the first are marked. */
async function compareDesigns(m, fileInput) {
  const files = [...fileInput.files];
  fileInput.value = "";
  const box = document.getElementById("compare");
  const designs = [];
  try {
    for (const f of files) designs.push({ ...(await readDesign(f)), file: f.name });
  } catch (e) {
    box.replaceChildren(el("p", { class: "error" }, String(e.message || e)));
    return showView("compare");
  }
  const models = new Set(designs.map((d) => d.model));
  if (designs.length < 1 || models.size > 1) {
    box.replaceChildren(el("p", { class: "error" }, "Choose two or more designs of one model to compare."));
    return showView("compare");
  }
  const model = state.models.find((x) => x.name === designs[0].model);
  const answers = await Promise.all(designs.map((d) => {
    const body = { ...Object.fromEntries(Object.entries(d.inputs).filter(([k, v]) => v !== "" && model.inputs.some((p) => p.name === k))
      .map(([k, v]) => { const p = model.inputs.find((x) => x.name === k); return [k, p.kind === "bool" ? v === "true" : v]; })),
    fidelity: d.fidelity || "auto", ...(typeof d.tolerance === "number" ? { tolerance: d.tolerance } : {}) };
    return post(model.path, body);
  }));
  state.compare = designs.map((d, i) => ({ design: d, ...answers[i] }));
  renderCompare(model);
  showView("compare");
  document.body.dataset.compare = "ok";
}

function renderCompare(model) {
  const box = document.getElementById("compare");
  const cols = state.compare;
  const differs = (vals) => vals.some((v) => {
    const a = vals[0];
    if (typeof a === "number" && typeof v === "number") return Math.abs(a - v) > 1e-9 * Math.max(Math.abs(a), Math.abs(v));
    if (Array.isArray(a) && Array.isArray(v)) return a.length !== v.length || a.some((x, i) => x !== v[i]);
    return a !== v;
  });
  const row = (label, unit, vals, show) => {
    const diff = differs(vals);
    return el("tr", { class: diff ? "differs" : null },
      el("th", { scope: "row" }, label, unit ? el("span", { class: "muted" }, ` [${unit}]`) : null),
      ...vals.map((v, i) => el("td", { class: "num" + (diff && i > 0 && differs([vals[0], v]) ? " diff" : "") }, show(v))));
  };
  const first = cols.find((c) => c.ok)?.data;
  const rows = [el("tr", { class: "group" }, el("th", { colspan: cols.length + 1 }, "Inputs"))];
  for (const p of model.inputs) {
    const vals = cols.map((c) => (c.ok ? c.data.inputs[p.name] : undefined));
    if (vals.every((v) => v === null || v === undefined)) continue;
    const u = p.kind !== "float" ? { factor: 1, label: "" } : inputUnit(state.units, p, state.imperial);
    rows.push(row(p.label, u.label, vals, (v) => (typeof v === "number" ? group(short(v / u.factor, 6))
      : Array.isArray(v) ? `${v.length} values` : v === undefined || v === null ? "—" : choiceText(String(v)))));
  }
  rows.push(el("tr", { class: "group" }, el("th", { colspan: cols.length + 1 }, "Results")));
  for (const o of model.outputs) {
    if (o.series) continue;
    const vals = cols.map((c) => (c.ok ? c.data.results[o.name] : undefined));
    if (vals.every((v) => v === undefined)) continue;
    const u = outputUnit(o, first?.results[o.name]);
    const sign = signOf(o);
    rows.push(row(labelOf(o), u.label, vals, (v) => (typeof v === "number" ? (v > 0 ? sign : "") + fmt(v / u.factor, 4) : fmt(choiceText(v)))));
  }
  const failed = cols.map((c) => (c.ok ? c.data.checks.filter((k) => !k.ok).map((k) => k.name).join(", ") || "all pass" : "refused"));
  rows.push(row("Checks", "", failed, (v) => v));
  box.replaceChildren(
    el("div", { class: "report-bar no-print" }, el("button", { type: "button", id: "close-compare", onclick: () => showView(null) }, "Back to the form")),
    el("h2", {}, `Comparison: ${model.title}`),
    el("p", { class: "muted" }, "Cells that differ from the first design are marked; rows with any difference are shaded."),
    el("div", { class: "table-wrap" }, el("table", { class: "results compare-table", id: "compare-table" },
      el("thead", {}, el("tr", {}, el("th", {}, ""), ...cols.map((c, i) => el("th", { scope: "col" },
        c.design.part || c.design.project || c.design.file || `design ${i + 1}`,
        c.ok ? null : el("div", { class: "error" }, (c.data.detail || []).map((d) => d.msg).join(" ")))))),
      el("tbody", {}, ...rows))));
}

// ---------------------------------------------------------------- pickers and the unit system

/**
 * A thread picker for a fieldset holding thread_diameter and thread_pitch, fed by
 * GET /api/v1/fasteners when the service has it; without that catalogue the fields
 * are typed as before. A model that reads designations (a `thread` input) is sent
 * the designation, with the grade the catalogue pairs with an inch thread; the
 * numbers the designation sets (diameter, pitch, bearing face, hole) are cleared so
 * the catalogue's apply. A model that takes numbers only is sent the thread's
 * diameter and pitch and its default head's bearing face and clearance hole.
 */
function threadPicker(m, ps) {
  const threads = state.fasteners?.threads;
  const d = ps.find((p) => p.name === "thread_diameter"), pitch = ps.find((p) => p.name === "thread_pitch");
  if (!threads?.length || !d || !pitch) return null;
  const byName = (name) => m.inputs.find((p) => p.name === name);
  const designation = byName("thread"), grade = byName("grade");
  const numbers = [[d, "diameter"], [pitch, "pitch"], [byName("bearing_outer_diameter"), "bearing_diameter"],
    [byName("hole_diameter"), "hole_diameter"]].filter(([p]) => p);
  const sel = el("select", { id: "thread-picker", "aria-describedby": "thread-picker-hint" },
    el("option", { value: "" }, "— type diameter and pitch —"),
    ...threads.map((t, i) => el("option", { value: String(i) }, `${t.designation}${t.series ? " (" + t.series + ")" : ""}`)));
  const setText = (p, v) => {
    const input = document.getElementById("in-" + p.name);
    if (input) input.value = v;
  };
  const fill = (t) => {
    if (designation) {
      setText(designation, t.designation);
      for (const [p] of numbers) { setText(p, ""); checkField(p); }
      const now = grade ? document.getElementById("in-grade")?.value ?? "" : "";
      // an inch thread goes with its grade; a metric one drops an inch-only grade
      if (grade && t.grade) setText(grade, t.grade);
      else if (grade && !t.grade && /^(SAE|B7)/i.test(now)) setText(grade, "");
    } else {
      for (const [p, key] of numbers) {
        if (typeof t[key] !== "number") continue;
        setText(p, fieldText(t[key] / currentUnit(p).factor, 10));
        checkField(p);
      }
    }
    markStale();
  };
  sel.addEventListener("change", () => { if (threads[Number(sel.value)]) fill(threads[Number(sel.value)]); });
  // a designation typed into the diameter field ("M12", "M12x1.25") is read from the catalogue too
  queueMicrotask(() => document.getElementById("in-" + d.name)?.addEventListener("change", (e) => {
    const key = (s) => String(s).toUpperCase().replaceAll(" ", "").replaceAll("×", "X");
    const i = threads.findIndex((t) => key(t.designation) === key(e.target.value));
    if (i >= 0) { sel.value = String(i); fill(threads[i]); }
  }));
  const hint = designation
    ? "sends the designation (and an inch thread's grade); its diameter, pitch, bearing face and hole come from the catalogue"
    : "fills the thread diameter and pitch, and the default head's bearing face and clearance hole";
  return el("div", { class: "field picker" }, el("label", { for: "thread-picker" }, "Thread (designation)"),
    el("div", { class: "control" }, sel),
    el("div", { class: "hint", id: "thread-picker-hint" }, hint));
}

/** Each field's unit to its first imperial (or metric) choice; loaded values keep their exact SI value. */
function setFieldSystem(m, imperial, which = () => true) {
  for (const p of m.inputs) {
    const sel = document.getElementById("unit-" + p.name);
    if (!sel || sel.tagName !== "SELECT" || !which(p)) continue;
    const opts = [...sel.options];
    const want = imperial ? opts.find((o) => IMPERIAL.has(o.textContent)) : opts.find((o) => !IMPERIAL.has(o.textContent));
    if (!want || want.value === sel.value) continue;
    sel.value = want.value;
    sel.dispatchEvent(new Event("change"));
  }
}

/** Metric or imperial: every field, result, plot and sweep at once. */
function switchSystem(imperial) {
  state.imperial = imperial;
  setImperial(imperial);
  const m = state.model;
  if (!m) return;
  setFieldSystem(m, imperial);
  if (state.lastResponse) {
    renderResult(m, state.lastResponse);
    if (document.body.classList.contains("view-report")) renderReport(m);
  }
  if (state.lastSweep?.response) plotSweep(m);
  markStale();
}

/**
 * The decimal separator the user reads and types: every number in a field is rewritten
 * with the same value in the new separator (a setting never changes a value); text that
 * could not be read before is read again under the new setting.
 */
function switchDecimal(sep) {
  const old = decimalSeparator();
  setDecimalSeparator(sep);
  const now = decimalSeparator();
  const m = state.model;
  if (!m || old === now) return;
  const rewrite = (input) => {
    const q = readQuantity(input.value, old);
    if (!q.ok) return;
    const text = localNumber(q.canonical, now) + (q.unit ? " " + q.unit : "");
    if (input.dataset.shown === input.value) input.dataset.shown = text; // still the loaded value
    if (input.dataset.exactShown === input.value) input.dataset.exactShown = text; // still converted
    input.value = text;
  };
  for (const p of m.inputs) {
    if (p.kind !== "float" && p.kind !== "int") continue;
    rewrite(document.getElementById("in-" + p.name));
    document.getElementById("hint-" + p.name).textContent = hintText(p);
    checkField(p);
  }
  for (const id of ["tolerance", "sweep-start", "sweep-stop"]) {
    const f = document.getElementById(id);
    if (f) { rewrite(f); f.dispatchEvent(new Event("input")); }
  }
  if (state.lastResponse) renderResult(m, state.lastResponse); // its numbers in the new separator
  markStale();
}

let resizeTimer = null;
window.addEventListener("resize", () => {
  clearTimeout(resizeTimer);
  resizeTimer = setTimeout(() => {
    for (const c of state.charts) {
      if (c.kind === "report") continue;
      c.chart.setSize({ width: chartWidth(c.chart.root.parentElement.parentElement), height: 280 });
    }
  }, 150);
});

init().catch((e) => {
  document.getElementById("model").replaceChildren(el("p", { class: "error" }, "Could not load the model catalogue: " + e));
});
