// A tool's trace export read into the form's trace fields through POST api/v1/trace/import.
//
// Wherever the form shows the angle and torque fields of a trace model (trace.analysis,
// trace.batch), a small block above them reads a file in any of the four formats the
// server reads (CSV with its columns and units, Open Protocol MID 0900, OPC UA
// StepTraceDataType, Rexroth result JSON). The server answers SI values; they are written
// into the fields in the unit each field shows. For trace.batch every file picked is
// appended as one more trace, with its length added to trace_lengths.
// No inline style or script: the CSV options are shown and hidden with the hidden attribute.

const FORMATS = [
  ["csv", "CSV (columns and units below)"],
  ["open_protocol", "Open Protocol MID 0900 (JSON)"],
  ["opc_ua", "OPC UA StepTraceDataType (JSON)"],
  ["rexroth", "Rexroth result (JSON)"],
];
const CSV_OPTIONS = [
  ["angle_column", "angle column", "Angle"],
  ["torque_column", "torque column", "Torque"],
  ["time_column", "time column (optional)", ""],
  ["angle_unit", "angle unit", "deg"],
  ["torque_unit", "torque unit", "N*m"],
  ["time_unit", "time unit", "s"],
];

function make(tag, attrs, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) node.setAttribute(k, v);
  for (const c of children) if (c !== null) node.append(c);
  return node;
}

function field(name) {
  return document.querySelector(`[data-field="${name}"] textarea`);
}

/** The factor from SI of the unit a samples field shows (its select or its unit label). */
function factorOf(name) {
  const u = document.getElementById("unit-" + name);
  if (!u) return 1;
  const f = u.tagName === "SELECT" ? u.selectedOptions[0].dataset.factor : u.dataset.factor;
  return Number(f) || 1;
}

/** SI values as the field's text: in its unit, one a line, with the page's decimal mark. */
function asText(values, name) {
  const factor = factorOf(name);
  const comma = (document.getElementById("decimal-sep") || {}).value === ",";
  return values
    .map((v) => String(Number((v / factor).toPrecision(10))))
    .map((s) => (comma ? s.replace(".", ",") : s))
    .join("\n");
}

function put(name, text, append) {
  const box = field(name);
  if (!box) return;
  box.value = append && box.value.trim() !== "" ? box.value.replace(/\s*$/, "") + "\n" + text : text;
  box.dispatchEvent(new Event("input", { bubbles: true }));
}

async function importOne(file, options) {
  const body = { format: options.format, content: await file.text() };
  if (options.format === "csv") {
    for (const [name] of CSV_OPTIONS) if (options[name] !== "") body[name] = options[name];
    body.decimal_comma = options.decimal_comma;
  }
  const r = await fetch("api/v1/trace/import", {
    method: "POST",
    headers: { "content-type": "application/json" },
    body: JSON.stringify(body),
  });
  const answer = await r.json().catch(() => ({}));
  if (!r.ok) {
    const d = (answer.detail || [])[0] || {};
    throw new Error(`${file.name}: ${d.field ? d.field + ": " : ""}${d.msg || "HTTP " + r.status}`);
  }
  return answer;
}

function block() {
  const batch = !!document.querySelector('[data-field="trace_lengths"]');
  const format = make("select", { id: "trace-import-format", name: "trace-import-format" },
    ...FORMATS.map(([v, label]) => make("option", { value: v }, label)));
  const csv = make("div", { id: "trace-import-csv", class: "trace-import-csv" });
  for (const [name, label, value] of CSV_OPTIONS) {
    const id = "trace-import-" + name;
    // each label with its box, so a line breaks between options, never inside one
    csv.append(make("span", { class: "trace-import-option" }, make("label", { for: id }, label + " "),
      make("input", { id, name: id, type: "text", value, size: "8", maxlength: name.endsWith("unit") ? "16" : "64" })), " ");
  }
  const comma = make("input", { id: "trace-import-decimal-comma", type: "checkbox" });
  csv.append(make("span", { class: "trace-import-option" }, make("label", { for: comma.id }, comma, " decimal comma (0,5)")));
  const file = make("input", {
    id: "trace-import-file", type: "file", accept: ".csv,.txt,.json,text/csv,application/json",
    "aria-label": "read a trace export",
  });
  if (batch) file.multiple = true;
  const status = make("output", { id: "trace-import-status", role: "status" });
  format.addEventListener("change", () => { csv.hidden = format.value !== "csv"; });
  file.addEventListener("change", async () => {
    const files = Array.from(file.files || []);
    if (!files.length) return;
    const options = { format: format.value, decimal_comma: comma.checked };
    for (const [name] of CSV_OPTIONS) options[name] = document.getElementById("trace-import-" + name).value.trim();
    status.textContent = "reading…";
    try {
      const read = [];
      for (const f of files) read.push(await importOne(f, options));
      const append = batch; // one trace replaces the fields; a batch's traces are appended
      const timed = read.every((a) => Array.isArray(a.inputs.time));
      put("angle", read.map((a) => asText(a.inputs.angle, "angle")).join("\n"), append);
      put("torque", read.map((a) => asText(a.inputs.torque, "torque")).join("\n"), append);
      if (timed) put("time", read.map((a) => asText(a.inputs.time, "time")).join("\n"), append);
      else put("time", "", false);
      if (batch) put("trace_lengths", read.map((a) => String(a.samples)).join("\n"), true);
      const n = read.reduce((s, a) => s + a.samples, 0);
      status.textContent = `read ${files.length} file${files.length > 1 ? "s" : ""}, ${n} samples` +
        (timed ? "" : " (no times)");
    } catch (err) {
      status.textContent = String(err.message || err);
    }
    file.value = "";
  });
  return make("fieldset", { id: "trace-import", class: "trace-import" },
    make("legend", {}, batch ? "Read traces from tool exports (each file one trace)" : "Read a trace from a tool export"),
    make("div", {}, make("label", { for: format.id }, "format "), format), csv,
    make("div", {}, make("label", { for: file.id }, batch ? "files " : "file "), file), status);
}

function place() {
  const angle = document.querySelector('[data-field="angle"]');
  if (!angle || !document.querySelector('[data-field="torque"] textarea')) return;
  if (document.getElementById("trace-import")) return;
  angle.before(block());
}

const root = document.getElementById("model") || document.body;
new MutationObserver(place).observe(root, { childList: true, subtree: true });
place();
