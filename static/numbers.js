// Typed numbers, read one way on both pages (the form and the design study).
//
// The user chooses the decimal separator ("." or ","), stored with the other page
// settings; its default is the browser's locale. The other mark (and a space) may only
// group digits in threes: with "." as decimal separator "2,000" is 2000 and "2,5" is
// refused, with "," "2,5" is 2.5 and "2.000" or "2 000" is 2000. Nothing is guessed:
// what cannot be read under the setting is refused with a message saying why. Numbers
// travel to the API and into links in one canonical form (a point, no grouping), so a
// link means the same on every machine.

const KEY = "decimal-separator";

/** The decimal separator of the browser's locale: "," or ".". */
export function localeDecimal() {
  try {
    const part = new Intl.NumberFormat().formatToParts(1.5).find((p) => p.type === "decimal");
    return part && part.value === "," ? "," : ".";
  } catch {
    return ".";
  }
}

/** The decimal separator chosen on the page (or the locale's until one is chosen). */
export function decimalSeparator() {
  const saved = localStorage.getItem(KEY);
  return saved === "," || saved === "." ? saved : localeDecimal();
}

export function setDecimalSeparator(sep) {
  localStorage.setItem(KEY, sep === "," ? "," : ".");
}

// spaces that may group digits: space, no-break space, narrow no-break space, thin space
const SPACES = " \u00a0\u202f\u2009";

/**
 * A typed number read under the decimal separator ``dec``:
 * ``{ok: true, value, canonical, grouped}`` or ``{ok: false, error}``; ``{empty: true}``
 * for blank text. ``canonical`` is the number as the API reads it (a point, no grouping,
 * any exponent as typed); ``grouped`` says the text held grouping marks. For example
 * readNumber("2,000", ".") is 2000, readNumber("2,5", ".") is refused and
 * readNumber("2,5", ",") is 2.5 (tests/e2e/test_browser.py runs these in the browser).
 */
export function readNumber(text, dec = decimalSeparator()) {
  const s = String(text ?? "").trim();
  if (s === "") return { ok: false, empty: true, error: "" };
  const other = dec === "," ? "." : ",";
  const esc = (c) => c.replace(/[.\\]/g, "\\$&");
  const grp = `[${esc(other)}${SPACES}]`;
  const m = s.match(new RegExp(`^([+-]?)(\\d[\\d${esc(other)}${SPACES}]*|)(?:${esc(dec)}(\\d*))?([eE][+-]?\\d+)?$`));
  const sayWhy = () => {
    const want = dec === "," ? "2,5" : "2.5";
    const thousands = dec === "," ? "2.000" : "2,000";
    const name = dec === "," ? "comma" : "point";
    return `“${s}” is not a number with the decimal ${name} “${dec}”: write ${want}, or ${thousands} for two thousand (“decimal” at the top of the page)`;
  };
  if (!m) return { ok: false, error: sayWhy() };
  const [, sign, whole, frac, exp] = m;
  if (whole === "" && (frac === undefined || frac === "")) return { ok: false, error: sayWhy() };
  const grouped = new RegExp(grp).test(whole);
  if (grouped && !new RegExp(`^\\d{1,3}(?:${grp}\\d{3})+$`).test(whole)) return { ok: false, error: sayWhy() };
  const digits = whole.replace(new RegExp(grp, "g"), "");
  const canonical = `${sign}${digits || "0"}${frac !== undefined && frac !== "" ? "." + frac : ""}${exp ?? ""}`;
  const value = Number(canonical);
  if (!Number.isFinite(value)) return { ok: false, error: `“${s}” is too large a number` };
  return { ok: true, value, canonical, grouped };
}

/** The number of ``readNumber(text).value``, or NaN. */
export function parseNum(text, dec = decimalSeparator()) {
  const r = readNumber(text, dec);
  return r.ok ? r.value : NaN;
}

/**
 * A typed quantity: a number, or a number followed by a unit ("2,000 lbf", "45 mm"), the
 * number read under the setting. ``{ok, value, canonical, unit}`` (``unit`` "" for a bare
 * number), ``{ok: false, error}``, or ``{ok: false, text: true}`` when the text does not
 * start with a number (a designation, a word: left for the server to judge).
 */
export function readQuantity(text, dec = decimalSeparator()) {
  const s = String(text ?? "").trim();
  const bare = readNumber(s, dec);
  if (bare.ok || bare.empty) return { ...bare, unit: "" };
  const m = s.match(/^([+-]?[\d.,\u00a0\u202f\u2009 ]*\d(?:[eE][+-]?\d+)?|[+-]?[.,]\d+(?:[eE][+-]?\d+)?)\s*([^\d\s.,+-].*)$/);
  if (!m) return /^[+-]?[\d.,]/.test(s) ? { ok: false, error: bare.error } : { ok: false, text: true, error: "" };
  // "1 000 mm": the last space may end the number rather than group it
  const r = readNumber(m[1], dec);
  if (!r.ok) return { ok: false, error: readNumber(m[1].trim(), dec).error || r.error };
  return { ...r, unit: m[2].trim() };
}

/** A number written for the user: the canonical text ("12.5", "1.5e-7") with their decimal separator. */
export function localNumber(canonical, dec = decimalSeparator()) {
  return dec === "," ? String(canonical).replace(".", ",") : String(canonical);
}

/**
 * Plain text the user typed (digits, at most one decimal separator): nothing to echo.
 * Not plain: a decimal separator followed by exactly three digits ("1,500" under the
 * comma, "1.500" under the point), which reads as a thousands group in the other
 * convention; the value read (1.5) is then echoed so a misreading shows at once.
 */
export function isPlain(text, dec = decimalSeparator()) {
  const d = dec === "," ? "," : "\\.";
  const s = String(text ?? "").trim();
  if (new RegExp(`^[+-]?\\d{1,3}${d}\\d{3}$`).test(s)) return false;
  return new RegExp(`^[+-]?(\\d+(${d}\\d*)?|${d}\\d+)$`).test(s);
}

/**
 * The value read, written so it cannot be misread: no grouping marks below five digits,
 * narrow no-break spaces above, the user's decimal separator ("2000", "12 345,5").
 */
export function echoNumber(value, dec = decimalSeparator()) {
  let s = String(Number(value.toPrecision(12)));
  if (/e/.test(s)) return localNumber(s, dec);
  const [whole, frac] = s.split(".");
  const sign = whole.startsWith("-") ? "-" : "";
  const digits = whole.replace("-", "");
  const g = digits.length >= 5 ? digits.replace(/\B(?=(\d{3})+(?!\d))/g, "\u202f") : digits;
  s = sign + g + (frac ? (dec === "," ? "," : ".") + frac : "");
  return s;
}

/**
 * A pasted list of numbers (measured values, a CSV column) read under the decimal
 * separator ``dec``: ``{ok: true, values, canonical}`` or ``{ok: false, error, index}``
 * naming the first value that cannot be read (counted from 1 for the user); ``{empty:
 * true}`` for blank text. Values are separated by new lines, semicolons, tabs or spaces,
 * and by commas too when the decimal separator is the point; so no value may group its
 * digits. readSamples("1.5, 2\n3", ".") is [1.5, 2, 3]; readSamples("1,5; 2", ",") is
 * [1.5, 2]. A CSV with a header line: words are refused, so take the header off.
 */
export function readSamples(text, dec = decimalSeparator()) {
  const s = String(text ?? "").trim();
  if (s === "") return { ok: false, empty: true, error: "" };
  const split = dec === "," ? /[\s;]+/ : /[\s;,]+/;
  const tokens = s.split(split).filter((t) => t !== "");
  const values = [], canonical = [];
  for (let i = 0; i < tokens.length; i++) {
    const r = readNumber(tokens[i], dec);
    if (!r.ok || r.grouped) {
      const sep = dec === "," ? "new lines, semicolons or spaces" : "new lines, commas, semicolons or spaces";
      return { ok: false, index: i, error: `value ${i + 1}, “${tokens[i]}”, is not a number with the decimal ${dec === "," ? "comma" : "point"} “${dec}” (separate values by ${sep})` };
    }
    values.push(r.value);
    canonical.push(r.canonical);
  }
  return { ok: true, values, canonical };
}

// ---------------------------------------------------------------- numbers shown

/** The narrow no-break space that groups digits in what the pages show. */
export const GROUP = "\u202f";

/**
 * Digit grouping for integer parts of five digits or more, with a narrow no-break space
 * (readable under either decimal separator): group("12345.6") is "12 345.6", group("2000")
 * "2000". Text that is not a plain number (with a point) is returned as it is.
 */
export function group(s) {
  const m = String(s).match(/^([+-]?)(\d+)(\.\d+)?$/);
  if (!m || m[2].length < 5) return s;
  return m[1] + m[2].replace(/\B(?=(\d{3})+(?!\d))/g, GROUP) + (m[3] || "");
}

/**
 * A number as both pages show it: ``sig`` significant digits, the exponent form below
 * 0.001 and from a million ("1.5e-7", "2.35e6"), integer parts of five digits or more
 * grouped ("12 350"), the user's decimal separator. ``trim`` drops trailing zeros
 * (statistics, axis ticks, converted quantities); results keep them ("23.80"). For
 * example formatNumber(12345.6) is "12 350", formatNumber(0.5, 3) "0.500",
 * formatNumber(0.5, 3, {trim: true}) "0.5", formatNumber(2.5, 2, {dec: ","}) "2,5"
 * (tests/e2e/test_units_in_sentences.py runs these in the browser).
 */
export function formatNumber(x, sig = 4, { trim = false, dec = decimalSeparator() } = {}) {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return "0";
  const a = Math.abs(x);
  let s;
  if (a >= 1e6 || a < 1e-3) {
    s = x.toExponential(sig - 1).replace("e+", "e");
    if (trim) s = s.replace(/\.?0+e/, "e");
  } else {
    const p = x.toPrecision(sig);
    s = group(p.includes("e") || trim ? String(Number(p)) : p);
  }
  return dec === "," ? s.replace(".", ",") : s;
}

/** A count of things ("4000 designs", "12 000 designs"), grouped as formatNumber groups. */
export function formatCount(n) {
  return group(String(Math.round(n)));
}

/** Significant digits of a typed number ("2.50" 3, "0.012" 2, "1500" 4), at least 1. */
export function typedDigits(canonical) {
  const mantissa = String(canonical).replace(/^[+-]/, "").split(/[eE]/)[0];
  const digits = mantissa.replace(".", "").replace(/^0+/, "");
  return Math.max(1, digits.length);
}

// ---------------------------------------------------------------- units shown
//
// The unit a quantity is shown in, one way on both pages: the table is static/units.json
// (keyed by the model's SI unit), the system (metric or imperial) is the page setting
// "unit-system", shared by the form and the design study.

const SYSTEM_KEY = "unit-system";

/** True when the user chose imperial units (on either page). */
export function imperialChosen() {
  return localStorage.getItem(SYSTEM_KEY) === "imperial";
}

export function setImperial(imperial) {
  localStorage.setItem(SYSTEM_KEY, imperial ? "imperial" : "metric");
}

/** Unit expressions compared loosely: "N·m" == "N*m", "kg·m²" == "kg*m^2", "µm" == "um". */
export function norm(unit) {
  return String(unit ?? "")
    .replaceAll("·", "*").replaceAll("**", "^").replaceAll("²", "^2").replaceAll("³", "^3")
    .replaceAll("⁴", "^4").replaceAll("µ", "u").replaceAll("μ", "u").replace(/\s+/g, "");
}

/** Pretty SI unit for display: "kg*m^2" -> "kg·m²", "1" -> "". */
export function pretty(unit) {
  if (!unit || unit === "1") return "";
  return unit.replaceAll("*", "·").replaceAll("^2", "²").replaceAll("^3", "³").replaceAll("^4", "⁴")
    .replaceAll("^-1", "⁻¹");
}

/** units.json as the pages use it: normalised SI unit -> [[label, api, factor], ...]. */
export function unitTable(json) {
  const table = {};
  for (const [si, choices] of Object.entries(json)) if (!si.startsWith("_")) table[norm(si)] = choices;
  return table;
}

/**
 * The unit choices for an SI unit in ``table`` (unitTable), display unit first:
 * [{label, api, factor}]. Unknown SI units get one choice, the SI unit itself.
 */
export function unitChoices(table, si, display) {
  const row = table[norm(si)];
  let choices = row
    ? row.map(([label, api, factor]) => ({ label, api, factor }))
    : [{ label: pretty(si), api: "", factor: 1 }]; // unknown unit: plain SI numbers
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

/** Units the metric/imperial switch treats as imperial (offered after the metric ones in units.json). */
export const IMPERIAL = new Set(["in", "ft", "in²", "in³", "lb", "lbf", "kip", "lbf·ft", "lbf·in", "psi", "ksi", "hp",
  "ft·lbf", "lbf/in", "in/lbf", "lbf·ft/rad", "lb·in²", "ft/s", "in/s", "ft/s²"]);

/** Outputs that are ratios, shown in %: shares, utilisations, deviations, scatters, margins. */
export function isRatio(o) {
  return norm(o.unit) === "1" && o.kind === "float"
    && /share|utili[sz]ation|deviation|scatter|relative|margin|fraction|efficiency|change/.test(o.name);
}

export const PERCENT = { label: "%", api: "%", factor: 0.01 };

/**
 * The unit choices of an output (or input) ``o`` ({name, unit, display_unit, kind}), best
 * first: % for ratios; otherwise the system's (metric or imperial) choices, the model's
 * display unit first, then the one that shows ``v`` (an SI value, or a series' largest
 * magnitude) between 0.01 and 100 000 with the fewest digits. A value in SI is shown as
 * ``v / choice.factor``.
 */
export function outputChoices(table, o, v = null, imperial = imperialChosen()) {
  let choices = unitChoices(table, o.unit, o.display_unit);
  if (isRatio(o)) return [PERCENT, ...choices.filter((c) => c.api !== "%")];
  const inSystem = choices.filter((c) => IMPERIAL.has(c.label) === imperial);
  if (inSystem.length) choices = [...inSystem, ...choices.filter((c) => !inSystem.includes(c))];
  const a = typeof v === "number" ? Math.abs(v) : 0;
  if (a > 0 && Number.isFinite(a) && inSystem.length) {
    const fits = (c) => a / c.factor >= 0.01 && a / c.factor < 1e5;
    if (!fits(choices[0])) {
      const score = (c) => { const e = Math.log10(a / c.factor); return e < 0 ? -e + 1 : e > 3 ? e - 3 : 0; };
      const best = inSystem.reduce((b, c) => (score(c) < score(b) ? c : b), inSystem[0]);
      choices = [best, ...choices.filter((c) => c !== best)];
    }
  }
  return choices;
}

/**
 * The unit an input's value is written in: the model's display unit, or in imperial the
 * first imperial choice for it (units.json's order); {label, api, factor}.
 */
export function inputUnit(table, p, imperial = imperialChosen()) {
  const choices = unitChoices(table, p.unit, p.display_unit);
  return (imperial && choices.find((c) => IMPERIAL.has(c.label))) || choices[0];
}
