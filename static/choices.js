// Readable names for the raw keys of choice inputs, on both pages (the form and the study).
//
// A model may declare its own names (``choice_labels`` in the catalogue, engine/core/spec.py);
// those come first. For keys declared without names, the few below are written out, and any
// other key of lowercase words joined by "_" is shown with spaces ("torque_wrench" →
// "torque wrench"). The value sent to the API is always the key.

const NAMES = {
  iso5393_hard: "ISO 5393 hard joint",
  iso5393_soft: "ISO 5393 soft joint",
  fixed_free: "fixed – free",
  hinged_hinged: "hinged – hinged",
  fixed_hinged: "fixed – hinged",
  fixed_fixed: "fixed – fixed",
  per_ball: "one spring per ball",
  common: "one common spring",
  bergstrasser: "Bergsträsser",
  wahl: "Wahl",
  symmetric_v: "symmetric V",
  vdi2230: "VDI 2230",
  approx: "approximate",
  before_heat_treatment: "rolled before heat treatment",
  after_heat_treatment: "rolled after heat treatment",
  nutrunner: "nut-runner",
  rare_impact: "rare-impact wrench",
  constant_power: "constant power",
};

/** The name shown for choice ``c`` of input ``p`` (a catalogue entry). */
export function choiceName(p, c) {
  const i = (p.choices || []).indexOf(c);
  const declared = p.choice_labels?.[i];
  if (declared) return declared;
  if (NAMES[c]) return NAMES[c];
  return /^[a-z][a-z0-9]*(_[a-z0-9]+)+$/.test(c) ? c.replaceAll("_", " ") : c;
}
