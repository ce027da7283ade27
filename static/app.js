// Minimal form generated from GET /api/v1/models: no per-model HTML.
"use strict";
const api = "/api/v1";
let models = [];

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  for (const c of children) e.append(c);
  return e;
}

async function init() {
  const res = await fetch(api + "/models");
  models = (await res.json()).models;
  const nav = document.getElementById("models");
  for (const m of models) {
    const b = el("button", { type: "button", "data-model": m.name }, m.title);
    b.addEventListener("click", () => show(m));
    nav.append(b);
  }
}

function show(m) {
  const sec = document.getElementById("model");
  sec.replaceChildren(el("h2", {}, m.title), el("p", {}, m.summary));
  const form = el("form", { id: "form" });
  for (const p of m.inputs) {
    const id = "in-" + p.name;
    const input = p.kind === "choice"
      ? el("select", { id, name: p.name }, ...p.choices.map((c) => el("option", { value: c }, c)))
      : el("input", { id, name: p.name, value: p.default ?? "" });
    if (p.kind === "choice" && p.default) input.value = p.default;
    form.append(el("label", { class: "field", title: p.description },
      `${p.label} [${p.unit}] `, input, el("span", { class: "error", id: "err-" + p.name })));
  }
  form.append(el("button", { type: "submit" }, "Compute"));
  form.addEventListener("submit", (e) => { e.preventDefault(); compute(m, form); });
  sec.append(form, el("div", { id: "result" }));
}

async function compute(m, form) {
  const body = {};
  for (const p of m.inputs) {
    const v = form.elements[p.name].value.trim();
    if (v === "") continue;
    body[p.name] = p.kind === "choice" ? v : (isNaN(Number(v)) ? v : Number(v));
  }
  for (const e of form.querySelectorAll(".error")) e.textContent = "";
  const res = await fetch(api + m.path, {
    method: "POST", headers: { "content-type": "application/json" }, body: JSON.stringify(body),
  });
  const data = await res.json();
  const out = document.getElementById("result");
  if (!res.ok) {
    out.replaceChildren();
    for (const d of data.detail) {
      const slot = d.field && document.getElementById("err-" + d.field);
      if (slot) slot.textContent = d.msg; else out.append(el("p", { class: "error" }, d.msg));
    }
    return;
  }
  const rows = Object.entries(data.results).map(([k, v]) =>
    el("tr", {}, el("td", {}, k), el("td", {}, typeof v === "number" ? v.toPrecision(5) : String(v)),
      el("td", {}, data.units[k] || "")));
  out.replaceChildren(
    el("p", {}, `rung ${data.rung}, error estimate ${data.error_estimate ?? "n/a"}, ${(data.elapsed_s * 1e3).toFixed(2)} ms`),
    el("table", { id: "results" }, ...rows),
    el("ul", {}, ...data.checks.map((c) => el("li", { class: c.ok ? "ok" : "fail" }, `${c.ok ? "✓" : "✗"} ${c.name}: ${c.detail}`))),
    el("ul", {}, ...[...data.warnings, ...data.notes].map((n) => el("li", {}, n))),
  );
}

init();
