// A quilt top on the page: its patches drawn in their colours and picked by
// a click (or the patch list), the picked patch's pattern set for it alone or
// for every patch of its colour (a TopPlan rule), the seam travel drawn in
// its own colour, and quiltc quilt --stats' figures per patch.
import { buildParamControls, paramValues, showDefaults } from './controls.js';
import { TopPlan } from './top-plan.js';

const $ = (id) => document.getElementById(id);

export const plan = new TopPlan();
let ctx = null; // { table(), families(), units(), globalFamily(), changed(), fail(message) }
let patches = []; // the loaded top's, from the last result
let picked = -1;

export const patchName = (p) => p.id || p.label || `shape ${p.element}`;

export function initTopView(context) {
  ctx = context;
  $('patchPick').addEventListener('change', () => pick(Number($('patchPick').value)));
  $('patchScope').addEventListener('change', showEditor);
  $('patchFamily').addEventListener('change', () => { buildPatchParams({}); saveRule(); });
  $('preview').addEventListener('click', (e) => {
    const el = e.target.closest?.('[data-patch]');
    if (el) pick(Number(el.dataset.patch));
  });
}

// A new top: its patches listed, its plan empty, nothing picked.
export function loadTop(list) {
  patches = list;
  plan.clear();
  picked = -1;
  $('patchPick').innerHTML = '<option value="-1">none (click a patch)</option>' + list.map((p, i) =>
    `<option value="${i}">${escape(patchName(p))}${p.label && p.id ? ` (${escape(p.label)})` : ''}</option>`).join('');
  showEditor();
}

// The result's patches (the same top, moved as sewn).
export function updatePatches(list) { patches = list; }

export function pick(i) {
  picked = i >= 0 && i < patches.length ? i : -1;
  $('patchPick').value = String(picked);
  for (const el of document.querySelectorAll('#preview [data-patch]')) el.classList.toggle('picked', Number(el.dataset.patch) === picked);
  showEditor();
}

const escape = (s) => String(s).replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);

// The scope's key: the patch's id or its colour ('' when the plan cannot name it).
function scopeKey(p, scope) { return scope === 'patch' ? p.id || '' : p.fill || ''; }

// Rebuilds the editor (after the units or the whole top's family changed).
export function refreshEditor() { if (ctx && patches.length) showEditor(); }

function showEditor() {
  const p = patches[picked];
  $('patchEdit').hidden = !p;
  if (!p) return;
  const scope = $('patchScope');
  scope.options[0].disabled = !p.id;
  scope.options[1].disabled = !p.fill;
  if (scope.selectedOptions[0]?.disabled) scope.value = p.id ? 'patch' : 'colour';
  $('patchSwatch').style.background = p.fill || 'transparent';
  $('patchSwatch').title = p.fill || 'no colour';
  const key = scopeKey(p, scope.value);
  $('patchNoName').hidden = key !== '';
  $('patchFamily').disabled = key === '';
  const rule = key ? plan.get(scope.value, key) : null;
  const fams = ctx.families();
  // what the patch gets without a rule of this scope: its colour's rule, else the whole top's pattern
  const byColour = scope.value === 'patch' && p.fill ? plan.get('colour', p.fill) : null;
  const inherited = byColour ? `as its colour (${byColour.family === 'none' ? 'unquilted' : byColour.family || ctx.globalFamily()})`
    : `same as the rest (${ctx.globalFamily()})`;
  $('patchFamily').innerHTML = `<option value="">${inherited}</option>` +
    '<option value="none">leave unquilted</option>' +
    fams.map((f) => `<option value="${f.name}" title="${escape(f.summary)}">${f.name}</option>`).join('');
  $('patchFamily').value = rule?.family || '';
  buildPatchParams(rule?.params || {});
}

function buildPatchParams(values) {
  const name = $('patchFamily').value;
  const box = $('patchParams');
  if (name === 'none') {
    box.innerHTML = '';
    return;
  }
  const family = ctx.families().find((f) => f.name === (name || ctx.globalFamily()));
  buildParamControls({ box, table: ctx.table(), family, units: ctx.units(), attr: 'patch-param', values, onChange: saveRule });
}

// The editor's values as the rule of the chosen scope.
function saveRule() {
  const p = patches[picked];
  if (!p) return;
  const scope = $('patchScope').value;
  const key = scopeKey(p, scope);
  if (!key) return;
  let params;
  try {
    params = paramValues($('patchParams'), 'patch-param');
  } catch (err) {
    ctx.fail(err.message);
    return;
  }
  plan.set(scope, key, $('patchFamily').value, params, patches);
  ctx.changed();
}

// SVG of the patches (fills, clickable) and of the seam travel, y up, in mm.
export function patchLayer(list) {
  return `<g id="patches">${list.map((p, i) => `<path data-patch="${i}" class="patch${i === picked ? ' picked' : ''}" ` +
    `fill="${p.fill || '#ffffff'}" d="${p.rings.map((r) => `M${ringPoints(r)}Z`).join('')}" fill-rule="evenodd">` +
    `<title>${escape(patchName(p))}</title></path>`).join('')}</g>`;
}

function ringPoints(xy) {
  const out = [];
  for (let k = 0; k + 1 < xy.length; k += 2) out.push(`${xy[k].toFixed(2)} ${xy[k + 1].toFixed(2)}`);
  return out.join('L');
}

export function ditchLayer(pieces) {
  return `<path id="ditchPath" d="${pieces.map((xy) => `M${ringPoints(xy)}`).join('')}"/>`;
}

// Empty patch controls show what the library resolves for the whole top.
export function showPatchDefaults(resolved) {
  if (ctx) showDefaults($('patchParams'), ctx.table(), resolved, ctx.units(), 'patch-param');
}

// quiltc quilt --stats' totals as the stats rows, and a row per patch.
export function topStats(r, units) {
  const s = r.stats;
  const inch = units === 'in';
  const len = (mm) => (inch ? `${(mm / 25.4).toFixed(1)} in` : `${(mm / 1000).toFixed(2)} m`);
  const min = Math.floor(s.sew_seconds / 60);
  const rows = [
    ['patches', `${s.quilted} quilted${s.unquilted ? `, ${s.unquilted} left` : ''}`],
    ['pieces', s.pieces], ['jumps', s.jumps],
    ['pattern length', len(s.pattern_mm)], ['ditch length', len(s.ditch_mm)],
    ['stitches (12 per inch)', s.stitches.toLocaleString('en')],
    ['thread', inch ? `${(s.thread_mm / 914.4).toFixed(1)} yd` : `${(s.thread_mm / 1000).toFixed(1)} m`],
    ['sewing time', `${min} min ${Math.round(s.sew_seconds - 60 * min)} s`],
    ['generation', `${r.ms.toFixed(0)} ms`],
  ];
  const table = `<table><caption>Per patch</caption><thead><tr><th scope="col">patch</th><th scope="col">pattern</th>` +
    `<th scope="col">order</th><th scope="col">length</th></tr></thead><tbody>${s.patches.map((p, i) =>
      `<tr data-patch-row="${i}"><td>${escape(patchName(r.patches[i]))}</td><td data-patch-family="${escape(p.id)}">${p.family === 'none' ? 'unquilted' : p.ditch_only ? `${p.family}: too small, in the ditch only` : p.family}</td>` +
      `<td>${p.order ?? ''}</td><td>${p.length_mm === undefined ? '' : len(p.length_mm)}</td></tr>`).join('')}</tbody></table>`;
  return { rows, table };
}

