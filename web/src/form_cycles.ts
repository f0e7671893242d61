// The cycles of the "New program" page and their fields. Ranges, units,
// defaults and choices are the server's (GET /api/forms, made from the
// very reading that checks a form: src/dnc/form_cycles.cpp); the page
// adds only its words (titles and labels). The page checks a field as the
// user types only to say so at once; the server checks it again and
// decides (POST /api/forms/{cycle}/preview, docs/dnc-server.md "Forms for
// cycles").

export interface FieldDef {
  name: string; // the field of the request body
  label: string;
  what?: string; // how a message names it, when not "the " + the label
  unit: string;
  min: number;
  max: number;
  minIncluded: boolean;
  whole?: boolean;
  value?: number; // the server's default; none: required
  text?: boolean; // a string, not a number
  textValue?: string;
  file?: boolean; // a file's text (a drawing), chosen by the user
  choices?: string[]; // one of these strings
}

export interface CycleDef {
  name: string; // the route's {cycle}
  title: string;
  fields: FieldDef[];
}

// A field as GET /api/forms describes it.
export interface FieldSpec {
  name: string;
  what: string;
  kind: 'number' | 'whole' | 'text';
  unit: string;
  min: number;
  max: number;
  min_included: boolean;
  default?: number | string;
  choices?: string[];
}

export interface FormSpecs {
  cycles: { name: string; fields: FieldSpec[] }[];
}

const TITLES: Record<string, string> = {
  ellipse_pocket: 'Elliptical pocket (seed 002)',
  rect_pocket: 'Rectangular pocket',
  circle_pocket: 'Circular pocket',
  drill_grid: 'Drilling: a grid of holes',
  bolt_circle: 'Drilling: a bolt circle',
  engrave: 'Engraving text',
  profile_dxf: 'Profile from a DXF drawing',
  pocket_dxf: 'Pocket with islands from a DXF drawing',
};

// The page's words for a field, by its name (the same in every cycle).
const LABELS: Record<string, string> = {
  center_x: 'Centre X',
  center_y: 'Centre Y',
  rx: 'Radius along X',
  ry: 'Radius along Y',
  depth: 'Depth',
  stepover: 'Stepover',
  step_down: 'Step down',
  finish_allowance: 'Finish allowance',
  floor_allowance: 'Floor allowance',
  resolution: 'Resolution (DDA increment)',
  width: 'Width',
  height: 'Height',
  corner_radius: 'Corner radius',
  radius: 'Radius',
  x0: 'First hole X',
  y0: 'First hole Y',
  nx: 'Holes along X',
  ny: 'Holes along Y',
  dx: 'Spacing along X',
  dy: 'Spacing along Y',
  retract: 'Retract height (R plane)',
  peck: 'Peck (0: none)',
  count: 'Holes',
  start_angle: 'Start angle (from +X, counter-clockwise)',
  text: 'Text (printable ASCII)',
  at_x: 'Baseline start X',
  at_y: 'Baseline start Y',
  font: 'Font (Hershey)',
  dxf: 'Drawing (DXF)',
  layer: 'Layer (optional)',
  side: 'Side',
  lead_radius: 'Lead arc radius (0: none)',
  tabs: 'Tabs (0: none)',
  tab_width: 'Tab width',
  tab_height: 'Tab height',
  tool: 'Tool number',
  tool_diameter: 'Tool diameter',
  feed: 'Feed',
  plunge_feed: 'Plunge feed',
  rpm: 'Spindle speed',
  safe_z: 'Safe Z',
};

// Fields the page leaves at the server's default: the bound on the work
// and the drawing's spline tolerance are for `usina gen` users.
const LEFT_OUT = new Set(['max_moves', 'spline_tolerance']);

// Per cycle, a label that says more than the field's name does.
const CYCLE_LABELS: Record<string, Record<string, string>> = {
  engrave: { height: 'Height of a capital' },
};

function fieldOf(cycle: string, s: FieldSpec): FieldDef {
  const text = s.kind === 'text';
  return {
    name: s.name,
    label: CYCLE_LABELS[cycle]?.[s.name] ?? LABELS[s.name] ?? s.name,
    what: s.what,
    unit: text ? '' : s.unit,
    min: s.min,
    max: s.max,
    minIncluded: s.min_included,
    whole: s.kind === 'whole' || undefined,
    value: typeof s.default === 'number' ? s.default : undefined,
    text: text || undefined,
    textValue: typeof s.default === 'string' ? s.default : undefined,
    file: s.name === 'dxf' || undefined,
    choices: s.choices,
  };
}

// The page's cycles from the server's description, in its order.
export function cyclesOf(specs: FormSpecs): CycleDef[] {
  return specs.cycles.map((c) => ({
    name: c.name,
    title: TITLES[c.name] ?? c.name,
    fields: c.fields.filter((f) => !LEFT_OUT.has(f.name)).map((f) => fieldOf(c.name, f)),
  }));
}

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
