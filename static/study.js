// The design-study page: builds a study from the catalogue (GET /api/v1/models), submits it
// (POST <model path>/study → 202 and a job), polls the job for progress, cancels it, and draws
// the summary: histogram with reference lines, grid map with the feasible region, sensitivity bars.
// Plain ES module, no build step, nothing fetched but this server.

import { choiceName } from "./choices.js";
import {
  decimalSeparator, echoNumber, formatCount, formatNumber, imperialChosen, inputUnit, isPlain, localNumber, outputChoices, pretty, readQuantity, readSamples,
  setDecimalSeparator, setImperial, unitChoices, unitTable,
} from "./numbers.js";

const $ = (sel) => document.querySelector(sel);
const API = "api/v1";
let catalogue = [];
let model = null;
let job = null;
let timer = null;
let summary = null;
let lastJob = null;
let units = {}; // units.json, as numbers.js's unitTable gives it

function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === "text") node.textContent = v;
    else if (v !== undefined && v !== null && v !== false) node.setAttribute(k, v === true ? "" : v);
  }
  for (const c of children) node.append(c);
  return node;
}

/** A value for the reader, as the form writes one (numbers.js's formatNumber), trailing zeros dropped. */
function fmt(v, digits = 4) {
  if (v === null || v === undefined || Number.isNaN(v)) return "–";
  if (typeof v === "boolean") return v ? "yes" : "no";
  return formatNumber(v, digits, { trim: true });
}

/**
 * The unit an output (or input) of the study is shown in: the form's choice for it in the
 * unit system chosen (numbers.js's outputChoices), ``v`` a typical SI value of it;
 * {label, factor}, a value in SI shown as ``v / factor``.
 */
function shownUnit(name, v = null) {
  const o = model.outputs.find((q) => q.name === name) ?? model.inputs.find((q) => q.name === name)
    ?? { name, unit: summary?.units?.[name] ?? "1", kind: "float" };
  return outputChoices(units, o, v)[0];
}

/** The largest magnitude among numbers (null if none): what picks a unit for a column or an axis. */
function typical(...values) {
  const a = values.filter((v) => typeof v === "number" && Number.isFinite(v)).map(Math.abs);
  return a.length ? Math.max(...a) : null;
}

/** " [lbf·ft]" after an axis name, nothing for a pure number. */
function bracket(u) {
  return u.label ? ` [${u.label}]` : "";
}

/**
 * An input's SI value as its field shows it: the number in the input's unit in the system
 * chosen, with that unit ("12 mm", "0.4724 in"), or the bare SI number when that unit is
 * SI. The field keeps the exact SI value it was written from (data-si) and sends it until
 * it is edited, so a value rounded for reading is never what runs.
 */
function writeSI(input, p, si) {
  const u = inputUnit(units, p);
  const bare = u.factor === 1 && (u.label === "" || u.api === p.unit);
  const text = bare ? localNumber(String(Number(si.toPrecision(6))))
    : `${localNumber(String(Number((si / u.factor).toPrecision(5))))} ${u.label}`;
  input.value = text;
  input.dataset.si = String(si);
  input.dataset.shown = text;
}

/** The exact SI value a field was written from, while it shows it unedited; else undefined. */
function exactSI(input) {
  return input.dataset.si !== undefined && input.dataset.shown === input.value ? Number(input.dataset.si) : undefined;
}

/** A unit typed as the pages write it ("lbf·ft", "µm") in the form the API reads ("lbf*ft", "um"). */
function apiUnit(p, typed) {
  const c = p ? unitChoices(units, p.unit, p.display_unit).find((x) => x.label === typed) : null;
  return c && c.api ? c.api : typed;
}

function label(p) {
  return p.label || p.name.replaceAll("_", " ");
}

async function loadCatalogue() {
  const [r, u] = await Promise.all([fetch(`${API}/models`), fetch("units.json")]);
  catalogue = (await r.json()).models;
  units = unitTable(await u.json());
  const sel = $("#study-model");
  for (const m of catalogue) sel.append(el("option", { value: m.name, text: `${m.title}` }));
  const wanted = new URLSearchParams(location.search).get("model");
  if (wanted && catalogue.some((m) => m.name === wanted)) sel.value = wanted;
  sel.addEventListener("change", () => pickModel(sel.value));
  const carried = fromForm(sel.value);
  pickModel(sel.value, carried);
  if (carried) {
    $("#study-status").textContent = "Base design carried from the form: checking it…";
    checkBase();
  }
}

/**
 * The design the form's "Study this design" carried here (sessionStorage, the inputs as
 * the form's link holds them: numbers with their unit, "12 mm"), or null.
 */
function fromForm(name) {
  if (new URLSearchParams(location.search).get("from") !== "form") return null;
  try {
    const carried = JSON.parse(sessionStorage.getItem("study-base") ?? "null");
    return carried && carried.model === name && carried.base ? carried.base : null;
  } catch {
    return null;
  }
}

/** A carried value as the study's field shows it: the number with the user's decimal separator, its unit kept. */
function carriedText(value) {
  const s = String(value);
  const m = s.match(/^([+-]?[\d.]+(?:[eE][+-]?\d+)?)(\s.*)?$/);
  return m ? localNumber(m[1]) + (m[2] ?? "") : s;
}

function lawCell(p, value) {
  const cell = el("div", { class: "law" });
  const law = el("select", { "aria-label": `${label(p)}: law`, "data-part": "distribution" });
  for (const d of ["uniform", "normal", "lognormal", "triangular"]) law.append(el("option", { value: d, text: d }));
  const num = typeof value === "number" ? value : Number(p.default) || 1;
  const spread = Math.abs(num) * 0.1 || 0.1;
  const lo = p.minimum !== null ? Math.max(p.minimum, num - spread) : num - spread;
  const hi = p.maximum !== null ? Math.min(p.maximum, num + spread) : num + spread;
  const field = (part, v, title) => {
    const input = el("input", { "data-part": part, "aria-label": `${label(p)}: ${title}`, title });
    if (part === "num") input.value = String(v);
    else writeSI(input, p, v);
    return input;
  };
  cell.append(
    law,
    field("low", lo, "low"),
    field("high", hi, "high"),
    field("mean", num, "mean"),
    field("sd", spread / 2, "standard deviation"),
    field("mode", num, "mode"),
    field("num", 11, "grid points"),
  );
  const update = () => {
    const method = $("#study-method").value;
    const d = law.value;
    for (const input of cell.querySelectorAll("input")) {
      const part = input.dataset.part;
      const show =
        method === "grid"
          ? ["low", "high", "num"].includes(part)
          : part === "num"
            ? false
            : d === "uniform"
              ? ["low", "high"].includes(part)
              : d === "normal" || d === "lognormal"
                ? ["mean", "sd"].includes(part)
                : ["low", "high", "mode"].includes(part);
      input.hidden = !show;
    }
    law.hidden = method === "grid";
  };
  law.addEventListener("change", update);
  $("#study-method").addEventListener("change", update);
  update();
  return cell;
}

function pickModel(name, carried = null) {
  model = catalogue.find((m) => m.name === name);
  $("#study-model-hint").textContent = model.summary;
  const example = (model.examples && model.examples[0]) || {};
  const rows = $("#study-rows");
  rows.replaceChildren();
  for (const p of model.inputs) {
    // a design carried from the form is taken as it stands: what it leaves empty stays empty
    const value = carried ? carried[p.name] : example[p.name] ?? p.default;
    const id = `in-${p.name}`;
    let control;
    if (p.kind === "choice") {
      control = el("select", { id, "data-name": p.name });
      if (carried && !p.required) control.append(el("option", { value: "", text: "—" }));
      for (const c of p.choices) control.append(el("option", { value: c, text: choiceName(p, c) }));
      if (value !== null && value !== undefined) control.value = value;
      else if (carried && !p.required) control.value = "";
    } else if (p.kind === "bool") {
      control = el("input", { id, type: "checkbox", "data-name": p.name });
      control.checked = value === "true" || value === true;
    } else if (p.kind === "samples") {
      // a list of measured values in SI, held fixed (a study cannot vary a list)
      control = el("textarea", { id, "data-name": p.name, "data-kind": "samples", rows: 3, placeholder: `values in ${p.unit}, ${p.required ? "required" : "optional"}`, "aria-describedby": `${id}-range` });
      if (Array.isArray(value)) control.value = value.map((v) => localNumber(String(v))).join("\n");
      else if (typeof value === "string") control.value = value.split(/\s+/).filter((t) => t !== p.unit).map(carriedText).join("\n");
    } else {
      control = el("input", {
        id,
        "data-name": p.name,
        value: value === null || value === undefined ? "" : typeof value === "number" ? localNumber(String(value)) : carried ? carriedText(value) : String(value),
        placeholder: p.required ? "required" : "optional",
        "aria-describedby": `${id}-range`,
      });
      if (typeof value === "number" && p.kind === "float") writeSI(control, p, value);
    }
    const vary = el("input", { type: "checkbox", "aria-label": `vary ${label(p)}` });
    vary.disabled = !(p.kind === "float" || p.kind === "int");
    const read = el("output", { class: "read-as" });
    const valueCell = el("td", {}, control, read);
    const law = vary.disabled ? null : lawCell(p, typeof value === "number" ? value : Number(p.default));
    vary.addEventListener("change", () => {
      valueCell.replaceChildren(vary.checked ? law : control, read);
      echo(tr);
      refreshPairs();
    });
    const tr = el(
      "tr",
      { "data-name": p.name },
      el("td", {}, vary),
      el("td", { class: "name" }, el("label", { for: id, text: label(p) }), el("div", { class: "hint", id: `${id}-range`, text: p.range })),
      valueCell,
      el("td", { class: "unit", text: pretty(p.unit) }),
    );
    tr.read = read;
    tr.unit = p.unit;
    tr.vary = vary;
    tr.control = control;
    tr.law = law;
    rows.append(tr);
  }
  const fid = $("#study-fidelity");
  fid.replaceChildren(el("option", { value: "", text: `default (${model.default_fidelity})` }), el("option", { value: "auto", text: "auto" }));
  for (const r of model.rungs) fid.append(el("option", { value: r.name, text: r.name }));
  const feas = $("#study-feasible");
  feas.replaceChildren(el("option", { value: "", text: "every reported requirement passes" }));
  for (const o of model.outputs.filter((o) => o.kind === "bool" && !o.series)) feas.append(el("option", { value: o.name, text: label(o) }));
  $("#study-pairs").replaceChildren();
  refreshPairs();
}

/**
 * The rank correlations between varied inputs (Monte Carlo and Latin hypercube only: the
 * API joins them by a Gaussian copula). Built here, after the inputs' fieldset: each pair
 * is two selects of the varied inputs and Spearman's ρ_S, −0.99…0.99.
 */
function correlationBox() {
  // a fieldset is laid out as a grid by the stylesheet, which `hidden` would not undo: the
  // box around it is what hides
  const box = el(
    "div",
    { id: "study-correlations" },
    el(
      "fieldset",
      { class: "study-settings" },
      el("legend", { text: "Correlated inputs (Monte Carlo, Latin hypercube)" }),
      el("ul", { id: "study-pairs", class: "pairs" }),
      el("div", {}, el("button", { type: "button", id: "study-add-pair", text: "add a correlation" })),
      el("p", { class: "hint", text: "Spearman rank correlation ρ_S of two varied inputs, −0.99…0.99: the inputs are drawn through a Gaussian copula, each keeping its own law." }),
    ),
  );
  $("#study-inputs").after(box);
  $("#study-add-pair").addEventListener("click", addPair);
  $("#study-method").addEventListener("change", refreshPairs);
}

function varied() {
  return [...$("#study-rows").children].filter((tr) => tr.vary.checked).map((tr) => tr.dataset.name);
}

function addPair() {
  const names = varied();
  const pick = (which, i) => {
    const sel = el("select", { "data-part": which, "aria-label": `correlation: ${which === "a" ? "first" : "second"} input` });
    sel.dataset.want = names[i] ?? "";
    return sel;
  };
  const rho = el("input", { "data-part": "rank_correlation", value: localNumber("0.5"), inputmode: "decimal", "aria-label": "correlation: ρ_S", title: "Spearman's ρ_S, −0.99…0.99" });
  const remove = el("button", { type: "button", text: "remove", "aria-label": "remove this correlation" });
  const li = el("li", {}, pick("a", 0), el("span", { text: " and " }), pick("b", 1), el("span", { text: " ρ_S " }), rho, remove);
  remove.addEventListener("click", () => { li.remove(); refreshPairs(); });
  $("#study-pairs").append(li);
  refreshPairs();
}

/** Each pair's selects offer the inputs varied now (a choice that stays varied is kept); the box shows for the methods that take correlations. */
function refreshPairs() {
  const box = $("#study-correlations");
  if (!box) return;
  const names = varied();
  for (const sel of box.querySelectorAll("select")) {
    const keep = sel.value || sel.dataset.want;
    sel.replaceChildren(...names.map((n) => el("option", { value: n, text: label(model.inputs.find((p) => p.name === n)) })));
    if (names.includes(keep)) sel.value = keep;
    delete sel.dataset.want;
  }
  box.hidden = !["monte_carlo", "lhs"].includes($("#study-method").value);
  $("#study-add-pair").disabled = names.length < 2;
}

/** The correlations to send: each complete pair (a, b, ρ_S read under the decimal setting). */
function correlations(errors) {
  const box = $("#study-correlations");
  if (!box || box.hidden) return [];
  return [...box.querySelectorAll("#study-pairs li")].map((li) => {
    const [a, b] = [...li.querySelectorAll("select")].map((s) => s.value);
    const rho = number(li.querySelector("input").value, "correlation ρ_S", errors);
    return { a, b, rank_correlation: typeof rho === "number" ? rho : NaN };
  }).filter((c) => {
    if (Number.isNaN(c.rank_correlation)) errors.push(`correlation of ${c.a} and ${c.b}: ρ_S must be a number −0.99…0.99`);
    return c.a && c.b && !Number.isNaN(c.rank_correlation);
  });
}

/**
 * A typed value read under the decimal-separator setting: a number, "2000 mm" (a unit
 * typed with it, sent in canonical form), or text (a designation) as typed. A number the
 * setting cannot read ("2,5" with a decimal point) is collected in ``errors``, never sent.
 */
function number(text, what = "", errors = [], p = null) {
  const t = String(text).trim();
  const q = readQuantity(t);
  if (q.ok) return q.unit ? `${q.canonical} ${apiUnit(p, q.unit)}` : q.value;
  if (!q.text && !q.empty) errors.push(`${what}: ${q.error}`);
  return t;
}

/** What an input's field sends: its exact SI value while unedited, else what is typed (number()). */
function fieldValue(input, name, errors, part = "") {
  const exact = exactSI(input);
  if (exact !== undefined) return exact;
  const p = model.inputs.find((q) => q.name === name);
  return number(input.value, label(p) + part, errors, p);
}

/** The value read beside a row whose typed numbers differ from it ("= 2000 mm"), or why it cannot be read. */
function echo(tr) {
  const fields = tr.vary.checked ? [...tr.law.querySelectorAll("input:not([hidden])")] : tr.control.tagName === "INPUT" && tr.control.type !== "checkbox" ? [tr.control] : [];
  const parts = [];
  let bad = false;
  for (const f of fields) {
    const q = readQuantity(f.value);
    const name = tr.vary.checked ? `${f.dataset.part} ` : "";
    if (!q.ok && !q.empty && !q.text) { parts.push(`${name}${q.error}`); bad = true; continue; }
    const typed = q.unit ? f.value.trim().slice(0, -q.unit.length) : f.value;
    const unit = q.unit || (tr.unit === "1" ? "" : tr.unit);
    if (q.ok && !isPlain(typed)) parts.push(`${name}= ${echoNumber(q.value)}${unit ? " " + unit : ""}`);
  }
  tr.read.textContent = parts.join("; ");
  tr.read.classList.toggle("error", bad);
}

/** Every input as set in its field, varied or not: the base design the single check computes. */
function design(errors = []) {
  const base = {};
  for (const tr of $("#study-rows").children) {
    const name = tr.dataset.name;
    if (tr.control.type === "checkbox") base[name] = tr.control.checked;
    else if (tr.control.dataset.kind === "samples" && tr.control.value.trim() !== "") {
      const r = readSamples(tr.control.value);
      if (r.ok) base[name] = r.values;
      else errors.push(`${label(model.inputs.find((p) => p.name === name))}: ${r.error}`);
    } else if (tr.control.value.trim() !== "") {
      base[name] = tr.control.tagName === "SELECT" ? tr.control.value : fieldValue(tr.control, name, errors);
    }
  }
  return base;
}

/**
 * One run of the model on the base design (POST the model's endpoint once), before any
 * point of a study runs: a design the model refuses is said at once, naming the field,
 * not after thousands of points. Returns true when the model computes it.
 */
async function checkBase() {
  const errors = [];
  const base = design(errors);
  if (errors.length) { showError(errors.join("; ")); return false; }
  const r = await fetch(`${API}${model.path}`, {
    method: "POST",
    headers: { "content-type": "application/json" },
    body: JSON.stringify(base),
  });
  let reply = {};
  try { reply = await r.json(); } catch { /* no body */ }
  if (!r.ok) {
    $("#study-status").textContent = "";
    showError(`The base design is refused by the model: ${detailText(reply.detail ?? r.statusText)}`);
    document.body.dataset.baseCheck = "refused";
    return false;
  }
  $("#study-status").textContent = "Base design checked: the model computes it.";
  document.body.dataset.baseCheck = "ok";
  return true;
}

function detailText(detail) {
  const items = Array.isArray(detail) ? detail : [{ msg: String(detail) }];
  const field = (d) => d.field ?? (Array.isArray(d.loc) && d.loc.length > 1 ? d.loc[d.loc.length - 1] : "");
  return items.map((d) => (field(d) ? `${field(d)}: ${d.msg}` : d.msg)).join("; ");
}

function body(errors = []) {
  const base = {};
  const variables = [];
  for (const tr of $("#study-rows").children) {
    const name = tr.dataset.name;
    if (tr.vary.checked) {
      const v = { name, distribution: tr.law.querySelector("select").value };
      for (const input of tr.law.querySelectorAll("input")) {
        if (input.hidden || input.value.trim() === "") continue;
        v[input.dataset.part] = input.dataset.part === "num" ? parseInt(input.value, 10) : fieldValue(input, name, errors, ` (${input.dataset.part})`);
      }
      variables.push(v);
    } else if (tr.control.type === "checkbox") {
      base[name] = tr.control.checked;
    } else if (tr.control.dataset.kind === "samples" && tr.control.value.trim() !== "") {
      const r = readSamples(tr.control.value);
      if (r.ok) base[name] = r.values;
      else errors.push(`${label(model.inputs.find((p) => p.name === name))}: ${r.error}`);
    } else if (tr.control.value.trim() !== "") {
      base[name] = tr.control.tagName === "SELECT" ? tr.control.value : fieldValue(tr.control, name, errors);
    }
  }
  const out = {
    base,
    variables,
    method: $("#study-method").value,
    samples: parseInt(String(number($("#study-samples").value, "designs", errors)), 10) || 1000,
    seed: parseInt($("#study-seed").value, 10) || 0,
    keep_points: $("#study-keep").checked,
  };
  if ($("#study-fidelity").value) out.fidelity = $("#study-fidelity").value;
  if ($("#study-tolerance").value.trim()) out.tolerance = Number(number($("#study-tolerance").value, "tolerance", errors));
  if ($("#study-feasible").value) out.feasible_when = $("#study-feasible").value;
  const pairs = correlations(errors);
  if (pairs.length) out.correlations = pairs;
  return out;
}

function showError(detail) {
  $("#study-error").textContent = detailText(detail);
}

async function run(event) {
  event.preventDefault();
  $("#study-error").textContent = "";
  const errors = [];
  const b = body(errors);
  if (errors.length) return showError(errors.join("; "));
  if (!b.variables.length) return showError("tick at least one input to vary");
  $("#study-run").disabled = true;
  delete document.body.dataset.baseCheck;
  if (!(await checkBase())) {
    $("#study-run").disabled = false;
    return;
  }
  const r = await fetch(`${API}${model.path}/study`, {
    method: "POST",
    headers: { "content-type": "application/json" },
    body: JSON.stringify(b),
  });
  const reply = await r.json();
  if (r.status !== 202) {
    $("#study-run").disabled = false;
    return showError(reply.detail);
  }
  job = reply.job;
  $("#study-cancel").disabled = false;
  $("#study-result").hidden = true;
  poll();
}

async function poll() {
  const r = await fetch(`${API}/jobs/${job}`);
  const j = await r.json();
  const p = j.progress;
  $("#study-progress").value = p.fraction;
  const rate = p.rate_per_s ? `${fmt(p.rate_per_s, 3)} designs/s` : "";
  const eta = p.eta_s !== null && p.eta_s !== undefined ? `, ${fmt(p.eta_s, 2)} s left` : "";
  const phase = j.state === "running" && j.phase ? ` (${j.phase})` : "";
  $("#study-status").textContent = `${j.state}${phase}: ${formatCount(p.done)} of ${formatCount(p.total)} designs ${rate}${eta}`;
  if (j.state === "queued" || j.state === "running") {
    timer = setTimeout(poll, 300);
    return;
  }
  $("#study-run").disabled = false;
  $("#study-cancel").disabled = true;
  if (j.state === "done") render(j);
  else if (j.error) showError(j.error.msg);
}

async function cancel() {
  if (!job) return;
  clearTimeout(timer);
  await fetch(`${API}/jobs/${job}`, { method: "DELETE" });
  poll();
}

function render(j) {
  lastJob = j;
  summary = j.result;
  $("#study-result").hidden = false;
  const feas = summary.feasible.fraction;
  $("#study-meta").textContent =
    `${formatCount(summary.points)} designs (${summary.method.replace("_", " ")}), ` +
    `${summary.refused} refused; feasible (${summary.feasible.criterion}): ` +
    `${feas === null ? "not known" : (100 * feas).toFixed(1) + " %"}; ` +
    `method of the model: ${Object.entries(summary.rungs).map(([k, v]) => `${k} ×${v}`).join(", ")}; ` +
    `${fmt(summary.elapsed_s, 3)} s.`;
  const names = Object.keys(summary.outputs);
  const sel = $("#study-output");
  sel.replaceChildren(...names.map((n) => el("option", { value: n, text: n.replaceAll("_", " ") })));
  const lines = $("#study-lines");
  lines.replaceChildren(...names.map((n) => el("option", { value: n, text: n.replaceAll("_", " ") })));
  const preferred = ["required_preload", "yield_preload", "permissible_preload"];
  for (const o of lines.options) o.selected = preferred.includes(o.value);
  const first = names.find((n) => summary.outputs[n].count && summary.outputs[n].max !== summary.outputs[n].min) || names[0];
  sel.value = names.includes(sel.dataset.keep) ? sel.dataset.keep : first; // a redraw (units switched) keeps the output
  sel.onchange = () => { sel.dataset.keep = sel.value; draw(); };
  lines.onchange = draw;
  // statistics table
  const head = el("tr", {}, ...["output", "unit", "mean", "sd", "1 %", "50 %", "99 %", "min", "max"].map((h) => el("th", { scope: "col", text: h })));
  const rows = names.map((n) => {
    const s = summary.outputs[n];
    const q = s.quantiles || {};
    // each row in its output's unit in the system chosen, as the form shows the output
    const u = shownUnit(n, typical(s.min, s.max, s.mean));
    const shown = (v) => (typeof v === "number" ? v / u.factor : v);
    return el(
      "tr",
      { "data-name": n },
      el("th", { scope: "row", text: n.replaceAll("_", " ") }),
      el("td", { class: "unit", text: u.label }),
      ...[s.mean, s.std, q["0.01"], q["0.5"], q["0.99"], s.min, s.max].map((v) => el("td", { class: "num", text: fmt(shown(v)) })),
    );
  });
  $("#study-stats").replaceChildren(el("thead", {}, head), el("tbody", {}, ...rows));
  renderChecks();
  $("#study-notes").replaceChildren(...summary.notes.map((n) => el("li", { text: n })),
    ...Object.entries(summary.refusals || {}).map(([k, v]) => el("li", { text: `${v} refused: ${k}` })));
  const blob = new Blob([JSON.stringify(summary, null, 1)], { type: "application/json" });
  $("#study-json").href = URL.createObjectURL(blob);
  for (const [id, link] of [["#study-csv", j.links.points_csv], ["#study-parquet", j.links.points_parquet]]) {
    const a = $(id);
    a.hidden = !link;
    if (link) a.href = link.replace(/^\//, "");
  }
  draw();
}

function passBar(fraction) {
  const bar = el("span", { class: "pass-bar", "aria-hidden": "true" }, el("span"));
  bar.firstChild.style.width = `${fraction === null ? 0 : Math.round(1000 * fraction) / 10}%`;
  return bar;
}

// The share of designs passing each check, and all of them (the feasible share), as the
// array path or the single runs reported them: refused designs are "not evaluated".
function renderChecks() {
  const list = $("#study-checks");
  const pct = (f) => (f === null ? "not evaluated" : `${(100 * f).toFixed(1)} % pass`);
  const item = (name, fraction, detail, passed, failed) => {
    const cls = fraction === null ? "unknown" : failed === 0 ? "ok" : passed === 0 ? "fail" : "part";
    const mark = { ok: "✓", fail: "✗", part: "◐", unknown: "–" }[cls];
    return el("li", { class: cls }, el("span", { class: "mark", text: `${mark} ` }), passBar(fraction),
      el("span", { text: `${name}: ${pct(fraction)} ` }), el("span", { class: "hint", text: detail }));
  };
  const rows = Object.entries(summary.checks).map(([name, c]) => {
    const unknown = c.unknown ? `, ${formatCount(c.unknown)} not evaluated` : "";
    const label = name.replaceAll("_", " ") + (c.level === "advice" ? " (advice, not counted)" : "");
    return item(label, c.pass_fraction,
      `(${formatCount(c.passed)} pass, ${formatCount(c.failed)} fail${unknown})`, c.passed, c.failed);
  });
  const f = summary.feasible;
  if (rows.length || f.fraction !== null) {
    const every = f.criterion === "every reported requirement passes";
    const ok = f.fraction === null ? 0 : Math.round(f.fraction * f.known);
    const rest = summary.points - f.known;
    rows.push(item(every ? "all requirements" : `feasible (${f.criterion.replaceAll("_", " ")})`, f.fraction,
      `(${formatCount(ok)} of ${formatCount(f.known)} designs${rest ? `, ${formatCount(rest)} not known` : ""})`,
      ok, f.known - ok));
    rows[rows.length - 1].classList.add("all");
  }
  if (!Object.keys(summary.checks).length)
    rows.unshift(el("li", { class: "unknown", text: "no checks reported (the model's array path gives none); see notes" }));
  list.replaceChildren(...rows);
}

function draw() {
  const name = $("#study-output").value;
  drawHistogram(name);
  drawMap(name);
  drawSensitivity(name);
}

function axes(ctx, w, h, pad, xlo, xhi, ylo, yhi, xlabel, ylabel) {
  ctx.strokeStyle = "#5b6670";
  ctx.fillStyle = "#1d2630";
  ctx.font = "12px system-ui, sans-serif";
  ctx.beginPath();
  ctx.moveTo(pad.l, pad.t);
  ctx.lineTo(pad.l, h - pad.b);
  ctx.lineTo(w - pad.r, h - pad.b);
  ctx.stroke();
  ctx.textAlign = "center";
  for (let i = 0; i <= 4; i++) {
    const x = pad.l + ((w - pad.l - pad.r) * i) / 4;
    ctx.textAlign = i === 4 ? "right" : "center"; // the last tick label stays on the canvas
    ctx.fillText(fmt(xlo + ((xhi - xlo) * i) / 4, 3), i === 4 ? w - 2 : x, h - pad.b + 14);
  }
  ctx.textAlign = "center";
  ctx.fillText(xlabel, (w + pad.l - pad.r) / 2, h - 4);
  ctx.textAlign = "right";
  for (let i = 0; i <= 4; i++) {
    const y = h - pad.b - ((h - pad.t - pad.b) * i) / 4;
    ctx.fillText(fmt(ylo + ((yhi - ylo) * i) / 4, 3), pad.l - 4, y + 4);
  }
  ctx.save();
  ctx.translate(12, (h - pad.b + pad.t) / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center";
  ctx.fillText(ylabel, 0, 0);
  ctx.restore();
}

function drawHistogram(name) {
  const canvas = $("#study-hist");
  const ctx = canvas.getContext("2d");
  const w = canvas.width, h = canvas.height;
  ctx.clearRect(0, 0, w, h);
  const s = summary.outputs[name];
  if (!s || !s.histogram) return;
  // the axis in the output's unit in the system chosen; reference lines of another SI unit
  // cannot share the axis and are left out
  const u = shownUnit(name, typical(s.min, s.max, s.mean));
  const edges = s.histogram.edges.map((v) => v / u.factor);
  const { counts } = s.histogram;
  const unit = bracket(u);
  const refs = [...$("#study-lines").selectedOptions].map((o) => o.value).filter((n) => n !== name && summary.outputs[n] && typeof summary.outputs[n].mean === "number"
    && summary.units[n] === summary.units[name]);
  const refMean = (r) => summary.outputs[r].mean / u.factor;
  let xlo = edges[0], xhi = edges[edges.length - 1];
  for (const r of refs) {
    xlo = Math.min(xlo, refMean(r));
    xhi = Math.max(xhi, refMean(r));
  }
  if (xhi === xlo) xhi = xlo + 1;
  const pad = { l: 68, r: 12, t: 12, b: 36 }; // room for "0.00925" beside the rotated label
  const ymax = Math.max(...counts, 1);
  axes(ctx, w, h, pad, xlo, xhi, 0, ymax, name.replaceAll("_", " ") + unit, "designs");
  canvas.setAttribute("aria-label", `histogram of ${name.replaceAll("_", " ")}${unit}`);
  const X = (v) => pad.l + ((v - xlo) / (xhi - xlo)) * (w - pad.l - pad.r);
  const Y = (c) => h - pad.b - (c / ymax) * (h - pad.t - pad.b);
  ctx.fillStyle = "#1f5f99";
  counts.forEach((c, i) => {
    // full-width bins: each bar spans its two edges
    ctx.fillRect(X(edges[i]), Y(c), Math.max(1, X(edges[i + 1]) - X(edges[i]) - 0.5), h - pad.b - Y(c));
  });
  ctx.setLineDash([5, 4]);
  ctx.lineWidth = 2;
  const colours = ["#b3261e", "#1e7b34", "#8a5a00"];
  refs.forEach((r, i) => {
    const x = X(refMean(r));
    ctx.strokeStyle = colours[i % colours.length];
    ctx.beginPath();
    ctx.moveTo(x, pad.t);
    ctx.lineTo(x, h - pad.b);
    ctx.stroke();
    ctx.fillStyle = ctx.strokeStyle;
    ctx.textAlign = "left";
    ctx.fillText(r.replaceAll("_", " "), x + 3, pad.t + 12 + 14 * i);
  });
  ctx.setLineDash([]);
  ctx.lineWidth = 1;
}

function colour(t) {
  // a perceptually ordered blue → yellow ramp (viridis endpoints)
  const a = [68, 1, 84], b = [33, 145, 140], c = [0xfd, 0xe7, 0x25];
  const mix = (p, q, u) => p.map((v, i) => Math.round(v + (q[i] - v) * u));
  const rgb = t < 0.5 ? mix(a, b, t * 2) : mix(b, c, (t - 0.5) * 2);
  return `rgb(${rgb.join(",")})`;
}

function drawMap(name) {
  const fig = $("#study-map-fig");
  const grid = summary.grid;
  fig.hidden = !grid;
  if (!grid) return;
  const canvas = $("#study-map");
  const ctx = canvas.getContext("2d");
  const w = canvas.width, h = canvas.height;
  ctx.clearRect(0, 0, w, h);
  const axesNames = Object.keys(grid.axes);
  // axes in their inputs' units and the output in its own, in the system chosen
  const axisUnit = (a) => shownUnit(a, typical(...grid.axes[a]));
  const axis = (a) => grid.axes[a].map((v) => v / axisUnit(a).factor);
  const axisLabel = (a) => a.replaceAll("_", " ") + bracket(axisUnit(a));
  const ou = shownUnit(name, typical(...grid.maps[name].flat(2)));
  let values = grid.maps[name].map(function scale(v) { return Array.isArray(v) ? v.map(scale) : v === null ? null : v / ou.factor; });
  let feasible = grid.feasible;
  if (axesNames.length === 3) {
    const k = Math.floor(grid.shape[2] / 2);
    values = values.map((row) => row.map((col) => col[k]));
    feasible = feasible.map((row) => row.map((col) => col[k]));
  }
  const pad = { l: 68, r: 12, t: 12, b: 36 }; // room for "0.00925" beside the rotated label
  if (axesNames.length === 1) {
    const xs = axis(axesNames[0]);
    const ys = values.filter((v) => v !== null);
    const ylo = Math.min(...ys), yhi = Math.max(...ys) === ylo ? ylo + 1 : Math.max(...ys);
    axes(ctx, w, h, pad, xs[0], xs[xs.length - 1], ylo, yhi, axisLabel(axesNames[0]), name.replaceAll("_", " ") + bracket(ou));
    ctx.strokeStyle = "#1f5f99";
    ctx.beginPath();
    xs.forEach((x, i) => {
      if (values[i] === null) return;
      const px = pad.l + ((x - xs[0]) / (xs[xs.length - 1] - xs[0])) * (w - pad.l - pad.r);
      const py = h - pad.b - ((values[i] - ylo) / (yhi - ylo)) * (h - pad.t - pad.b);
      i ? ctx.lineTo(px, py) : ctx.moveTo(px, py);
    });
    ctx.stroke();
    return;
  }
  const xs = axis(axesNames[0]), ys = axis(axesNames[1]);
  const flat = values.flat().filter((v) => v !== null);
  const lo = Math.min(...flat), hi = Math.max(...flat);
  axes(ctx, w, h, pad, xs[0], xs[xs.length - 1], ys[0], ys[ys.length - 1], axisLabel(axesNames[0]), axisLabel(axesNames[1]));
  const cw = (w - pad.l - pad.r) / xs.length, ch = (h - pad.t - pad.b) / ys.length;
  for (let i = 0; i < xs.length; i++) {
    for (let j = 0; j < ys.length; j++) {
      const v = values[i][j];
      const x = pad.l + i * cw, y = h - pad.b - (j + 1) * ch;
      ctx.fillStyle = v === null ? "#d5dbe1" : colour(hi > lo ? (v - lo) / (hi - lo) : 0.5);
      ctx.fillRect(x, y, cw + 0.5, ch + 0.5);
      if (feasible[i][j] === 0) {
        ctx.strokeStyle = "rgba(255,255,255,0.7)";
        ctx.beginPath();
        ctx.moveTo(x, y + ch);
        ctx.lineTo(x + cw, y);
        ctx.stroke();
      }
    }
  }
  // outline of the feasible region: edges between a feasible and a non-feasible cell
  ctx.strokeStyle = "#b3261e";
  ctx.lineWidth = 2;
  ctx.beginPath();
  const ok = (i, j) => i >= 0 && j >= 0 && i < xs.length && j < ys.length && feasible[i][j] === 1;
  for (let i = 0; i < xs.length; i++) {
    for (let j = 0; j < ys.length; j++) {
      if (!ok(i, j)) continue;
      const x = pad.l + i * cw, y = h - pad.b - (j + 1) * ch;
      if (!ok(i - 1, j)) { ctx.moveTo(x, y); ctx.lineTo(x, y + ch); }
      if (!ok(i + 1, j)) { ctx.moveTo(x + cw, y); ctx.lineTo(x + cw, y + ch); }
      if (!ok(i, j - 1)) { ctx.moveTo(x, y + ch); ctx.lineTo(x + cw, y + ch); }
      if (!ok(i, j + 1)) { ctx.moveTo(x, y); ctx.lineTo(x + cw, y); }
    }
  }
  ctx.stroke();
  ctx.lineWidth = 1;
  ctx.textAlign = "left";
  const sliced = axesNames.length === 3 ? axesNames[2] : null;
  const slice = sliced ? ` (slice ${sliced.replaceAll("_", " ")} = ${fmt(axis(sliced)[Math.floor(grid.shape[2] / 2)], 3)}${axisUnit(sliced).label ? " " + axisUnit(sliced).label : ""})` : "";
  const legend = `${name.replaceAll("_", " ")}: ${fmt(lo, 3)} … ${fmt(hi, 3)}${ou.label ? " " + ou.label : ""}${slice}`;
  ctx.fillStyle = "rgba(255,255,255,0.85)"; // readable over the dark end of the colour ramp
  ctx.fillRect(pad.l + 1, pad.t + 1, ctx.measureText(legend).width + 6, 16);
  ctx.fillStyle = "#1d2630";
  ctx.fillText(legend, pad.l + 4, pad.t + 12);
}

function drawSensitivity(name) {
  const box = $("#study-sens");
  const sens = summary.sensitivity;
  $("#study-sens-fig").hidden = !sens;
  if (!sens) return;
  const rows = sens.indices[name] || {};
  const sobol = sens.method.startsWith("sobol");
  $("#study-sens-cap").textContent = sobol
    ? "Sobol' indices: dark bar first order, light bar total (Saltelli 2010, Jansen 1999)."
    : "Spearman rank correlation of the output with each input (sign: direction).";
  box.replaceChildren(el("h4", { text: `Which input drives ${name.replaceAll("_", " ")}` }));
  for (const [input, v] of Object.entries(rows)) {
    const value = sobol ? v.first : v;
    const bar = el("div", { class: "bar" + (value !== null && value < 0 ? " neg" : "") });
    bar.style.width = `${Math.min(100, Math.abs(value ?? 0) * 100)}%`;
    const track = el("div", {}, bar);
    if (sobol) {
      const total = el("div", { class: "bar total" });
      total.style.width = `${Math.min(100, Math.abs(v.total) * 100)}%`;
      track.append(total);
    }
    box.append(el("div", { class: "bar-row" }, el("span", { text: input.replaceAll("_", " ") }), track,
      el("span", { class: "num", text: sobol ? `${fmt(v.first, 2)} / ${fmt(v.total, 2)}` : fmt(value, 2) })));
  }
}

$("#study-form").addEventListener("submit", run);
$("#study-rows").addEventListener("input", (e) => { const tr = e.target.closest("tr"); if (tr?.read) echo(tr); });
{
  // the decimal separator, shared with the form's page: a change rewrites the numbers, same values
  const sep = $("#decimal-sep");
  sep.value = decimalSeparator();
  sep.addEventListener("change", () => {
    const old = decimalSeparator();
    setDecimalSeparator(sep.value);
    for (const f of document.querySelectorAll("#study-form input:not([type=checkbox])")) {
      if (f.dataset.part === "num" || f.id === "study-samples" || f.id === "study-seed") continue;
      const q = readQuantity(f.value, old);
      if (!q.ok) continue;
      const text = localNumber(q.canonical) + (q.unit ? " " + q.unit : "");
      if (f.dataset.shown === f.value) f.dataset.shown = text; // still the value written: still exact
      f.value = text;
    }
    for (const tr of $("#study-rows").children) echo(tr);
  });
}
{
  // the unit system, shared with the form's page: a change redraws the results, same values
  const system = $("#unit-system");
  system.value = imperialChosen() ? "imperial" : "metric";
  system.addEventListener("change", () => {
    setImperial(system.value === "imperial");
    for (const f of document.querySelectorAll("#study-rows input[data-si]")) {
      const p = model.inputs.find((q) => q.name === f.closest("tr").dataset.name);
      if (exactSI(f) !== undefined) writeSI(f, p, exactSI(f));
    }
    if (lastJob) render(lastJob);
  });
}
$("#study-cancel").addEventListener("click", cancel);
correlationBox();
loadCatalogue();
