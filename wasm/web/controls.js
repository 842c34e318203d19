// One labelled control per parameter row of a family, from the library's
// table: used for the whole pattern and for a patch's own pattern. Visible
// label = accessible name (the label wraps its text and the control).
import { paramLabel, choiceLabel, unitLabel } from './labels.js';

export const HIDDEN_ROWS = new Set(['family', 'seed']);
export const MM_PER = { in: 25.4, mm: 1 };
export const fmt = (v, digits = 6) => String(+Number(v).toPrecision(digits));

// A label wrapping its text and a control; returns the label.
export function labelled(text, control, className) {
  const label = document.createElement('label');
  if (className) label.className = className;
  const span = document.createElement('span');
  span.className = 'label-text';
  span.textContent = text;
  label.append(span, control);
  return label;
}

// Fills box with the controls of family (a qc_family_info row) in units;
// data-ATTR holds the row name (attr in kebab case); values: the initial
// values (else the ones the box held); onChange(row) on every edit.
export function buildParamControls({ box, table, family, units, attr = 'param', values, onChange }) {
  const keep = values || {};
  if (!values) for (const el of box.querySelectorAll(`[data-${attr}]`)) keep[el.getAttribute(`data-${attr}`)] = el.value;
  box.innerHTML = '';
  for (const row of table) {
    if (HIDDEN_ROWS.has(row.name) || !(row.families & 2 ** family.id)) continue;
    let input;
    if (row.type === 'enum') {
      input = document.createElement('select');
      const choices = row.choices.split('|').filter((c) => c !== 'given');
      const def = family.defaults[row.name]; // this family's own default, as the library resolves it
      input.innerHTML = `<option value="">${def ? `default (${choiceLabel(row.name, def)})` : 'default'}</option>` +
        choices.map((c) => `<option value="${c}">${choiceLabel(row.name, c)}</option>`).join('');
    } else {
      input = document.createElement('input');
      input.type = 'number';
      input.inputMode = 'decimal';
      const scale = row.type === 'length' ? MM_PER[units] : 1;
      input.min = fmt(row.min / scale, 4);
      input.max = fmt(row.max / scale, 4);
      input.step = row.type === 'int' ? '1' : 'any';
      // a help text naming its own defaults ("default d/5; stipple d/3") is the better hint
      input.placeholder = /\(default/.test(row.help) ? 'default'
        : row.def_per_spacing ? `${row.def_per_spacing} × spacing` : fmt(row.def / scale, 4);
    }
    input.setAttribute(`data-${attr}`, row.name);
    if (keep[row.name] !== undefined) input.value = keep[row.name];
    input.addEventListener(row.type === 'enum' ? 'change' : 'input', () => onChange(row));
    const unit = unitLabel(row, units);
    const label = labelled(`${paramLabel(row)}${unit ? ` (${unit})` : ''}`, input, 'param');
    label.title = row.help;
    box.append(label);
  }
}

// The box's non-empty values: { name: text }; throws on a field that is not a number.
export function paramValues(box, attr = 'param') {
  const out = {};
  for (const el of box.querySelectorAll(`[data-${attr}]`)) {
    const name = el.getAttribute(`data-${attr}`);
    if (el.validity?.badInput) throw new Error(`${el.closest('label').textContent.trim()}: not a number`);
    if (el.value.trim() !== '') out[name] = el.value.trim();
  }
  return out;
}

// Empty controls show the value the library resolved for them.
export function showDefaults(box, table, resolved, units, attr = 'param') {
  for (const el of box.querySelectorAll(`[data-${attr}]`)) {
    const row = table.find((t) => t.name === el.getAttribute(`data-${attr}`));
    const v = resolved[row.name];
    if (v === undefined || v === null) continue;
    if (row.type === 'enum') el.options[0].textContent = `default (${choiceLabel(row.name, v)})`;
    else el.placeholder = fmt(row.type === 'length' ? v / MM_PER[units] : v, 4);
  }
}
