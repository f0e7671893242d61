// The cycles of the "New program" page and their fields, with the units,
// defaults and ranges of `usina gen` (docs/gen.md "Names" and "Ranges",
// src/cam/limits.hpp). The page checks them as the user types only to say
// so at once; the server checks them again and decides
// (POST /api/forms/{cycle}/preview, docs/dnc-server.md "Forms for cycles").

export interface FieldDef {
  name: string; // the field of the request body
  label: string;
  what?: string; // how a message names it, when not "the " + the label
  unit: string;
  min: number;
  max: number;
  minIncluded: boolean;
  whole?: boolean;
  value?: number; // docs/gen.md's default; none: required
  text?: boolean; // a string, not a number
  textValue?: string;
  file?: boolean; // a file's text (a drawing), chosen by the user
  choices?: string[]; // one of these strings (the first is the default)
}

export interface CycleDef {
  name: string; // the route's {cycle}
  title: string;
  fields: FieldDef[];
}

const M = 1e5; // ±100 m: coordinates and lengths (cam::kMaxCoordinate)
// The preview's bound on the work (src/dnc/form_cycles.hpp, kFormMaxMoves).
export const FORM_MAX_MOVES = 1_000_000;

const length = (name: string, label: string, value?: number): FieldDef => ({ name, label, unit: 'mm', min: 0, max: M, minIncluded: false, value });
const lengthOrZero = (name: string, label: string, value: number): FieldDef => ({ name, label, unit: 'mm', min: 0, max: M, minIncluded: true, value });
const coordinate = (name: string, label: string, what: string, value: number | undefined = 0): FieldDef => ({ name, label, what, unit: 'mm', min: -M, max: M, minIncluded: true, value });
const count = (name: string, label: string, value?: number): FieldDef => ({ name, label, unit: '', min: 1, max: 100000, minIncluded: true, whole: true, value });

const CUTTING: FieldDef[] = [
  { name: 'tool', label: 'Tool number', unit: '', min: 0, max: 99999, minIncluded: true, whole: true, value: 1 },
  { name: 'tool_diameter', label: 'Tool diameter', unit: 'mm', min: 0.001, max: 1000, minIncluded: true, value: 6 },
  { name: 'feed', label: 'Feed', unit: 'mm/min', min: 0, max: 1e6, minIncluded: false, value: 600 },
  { name: 'plunge_feed', label: 'Plunge feed', unit: 'mm/min', min: 0, max: 1e6, minIncluded: false, value: 200 },
  { name: 'rpm', label: 'Spindle speed', unit: 'rev/min', min: 0, max: 1e6, minIncluded: false, value: 10000 },
  length('safe_z', 'Safe Z', 5),
];

const POCKET: FieldDef[] = [
  length('depth', 'Depth'),
  length('stepover', 'Stepover'),
  length('step_down', 'Step down', 1),
  lengthOrZero('finish_allowance', 'Finish allowance', 0.2),
];

const DRILL: FieldDef[] = [length('depth', 'Depth'), lengthOrZero('retract', 'Retract height (R plane)', 1), lengthOrZero('peck', 'Peck (0: none)', 0)];

export const CYCLES: CycleDef[] = [
  {
    name: 'ellipse_pocket',
    title: 'Elliptical pocket (seed 002)',
    fields: [
      coordinate('center_x', 'Centre X', "the centre's X"),
      coordinate('center_y', 'Centre Y', "the centre's Y"),
      length('rx', 'Radius along X'),
      length('ry', 'Radius along Y'),
      ...POCKET,
      lengthOrZero('floor_allowance', 'Floor allowance', 0),
      { name: 'resolution', label: 'Resolution (DDA increment)', unit: 'mm', min: 0.0001, max: M, minIncluded: true, value: 0.1 },
      ...CUTTING,
    ],
  },
  {
    name: 'rect_pocket',
    title: 'Rectangular pocket',
    fields: [{ ...length('width', 'Width'), what: "the rectangle's width" }, { ...length('height', 'Height'), what: "the rectangle's height" }, lengthOrZero('corner_radius', 'Corner radius', 0), coordinate('center_x', 'Centre X', "the centre's X"), coordinate('center_y', 'Centre Y', "the centre's Y"), ...POCKET, ...CUTTING],
  },
  {
    name: 'circle_pocket',
    title: 'Circular pocket',
    fields: [{ ...length('radius', 'Radius'), what: "the circle's radius" }, coordinate('center_x', 'Centre X', "the centre's X"), coordinate('center_y', 'Centre Y', "the centre's Y"), ...POCKET, ...CUTTING],
  },
  {
    name: 'drill_grid',
    title: 'Drilling: a grid of holes',
    fields: [coordinate('x0', 'First hole X', "the first hole's X"), coordinate('y0', 'First hole Y', "the first hole's Y"), count('nx', 'Holes along X'), count('ny', 'Holes along Y'), coordinate('dx', 'Spacing along X', 'the spacing along X', undefined), coordinate('dy', 'Spacing along Y', 'the spacing along Y', undefined), ...DRILL, ...CUTTING],
  },
  {
    name: 'bolt_circle',
    title: 'Drilling: a bolt circle',
    fields: [
      coordinate('center_x', 'Centre X', "the centre's X"),
      coordinate('center_y', 'Centre Y', "the centre's Y"),
      { ...length('radius', 'Radius'), what: "the bolt circle's radius" },
      { ...count('count', 'Holes'), what: 'the count of holes' },
      { name: 'start_angle', label: 'Start angle (from +X, counter-clockwise)', unit: '°', min: -360, max: 360, minIncluded: true, value: 0 },
      ...DRILL,
      ...CUTTING,
    ],
  },
  {
    name: 'engrave',
    title: 'Engraving text',
    fields: [
      { name: 'text', label: 'Text (printable ASCII)', unit: '', min: 1, max: 10000, minIncluded: true, text: true },
      { ...length('height', 'Height of a capital'), what: 'the text height' },
      coordinate('at_x', 'Baseline start X', "the baseline's start's X"),
      coordinate('at_y', 'Baseline start Y', "the baseline's start's Y"),
      length('depth', 'Depth', 0.2),
      { name: 'font', label: 'Font (Hershey)', unit: '', min: 1, max: 40, minIncluded: true, text: true, textValue: 'rowmans' },
      ...CUTTING,
    ],
  },
  {
    name: 'profile_dxf',
    title: 'Profile from a DXF drawing',
    fields: [
      { name: 'dxf', label: 'Drawing (DXF)', unit: '', min: 1, max: 64 * 1024 * 1024, minIncluded: true, text: true, file: true },
      { name: 'layer', label: 'Layer (optional)', unit: '', min: 1, max: 255, minIncluded: true, text: true, textValue: '' },
      { name: 'side', label: 'Side', unit: '', min: 0, max: 0, minIncluded: true, text: true, choices: ['outside', 'inside', 'auto', 'left', 'right', 'on'], textValue: 'outside' },
      length('depth', 'Depth'),
      length('step_down', 'Step down', 1),
      { ...lengthOrZero('lead_radius', 'Lead arc radius (0: none)', 0), what: 'the lead radius' },
      { name: 'tabs', label: 'Tabs (0: none)', what: 'the tab count', unit: '', min: 0, max: 10000, minIncluded: true, whole: true, value: 0 },
      length('tab_width', 'Tab width', 3),
      length('tab_height', 'Tab height', 1),
      ...CUTTING,
    ],
  },
];

function numberText(v: number): string {
  return String(v);
}

// What is wrong with `raw` for `f` (as the server would say it), or ''.
// An empty field takes its default; one without a default is required.
export function checkField(f: FieldDef, raw: string): string {
  const bare = f.label.replace(/ \(.*\)$/, '');
  const what = f.what ?? `the ${bare.charAt(0).toLowerCase()}${bare.slice(1)}`;
  if (raw.trim() === '') return f.value === undefined && f.textValue === undefined ? `${what} is required` : '';
  if (f.choices) return f.choices.includes(raw) ? '' : `${what} is one of ${f.choices.join(', ')}`;
  if (f.file && raw.length > f.max) return `${what} is ${raw.length} bytes; at most ${f.max}`;
  if (f.text) {
    if (raw.length > f.max) return `${what} has ${raw.length} characters; give 1 to ${f.max}`;
    if (f.name === 'text' && /[^ -~]/.test(raw)) return 'printable ASCII only: the fonts have no other characters';
    return '';
  }
  const v = Number(raw);
  const unit = f.unit ? ` ${f.unit}` : '';
  const range = f.minIncluded ? `from ${numberText(f.min)} to ${numberText(f.max)}${unit}` : `above ${numberText(f.min)} and at most ${numberText(f.max)}${unit}`;
  if (!Number.isFinite(v)) return `${what} must be a number`;
  if ((f.minIncluded ? v < f.min : v <= f.min) || v > f.max) return `${what} is ${raw}${unit}; give a number ${range}`;
  if (f.whole && !Number.isInteger(v)) return `${what} is ${raw}; give a whole number`;
  return '';
}
