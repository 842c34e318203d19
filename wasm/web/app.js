// The page: controls built from the library's parameter table, generation in
// a Web Worker (worker.js), an SVG preview to scale with a ruler, a sew
// animation, and downloads byte-identical to `quiltc generate` with the same
// settings (the equivalent command line is shown under the stats). An SVG
// of several patches is a quilt top (top-view.js): sewn as `quiltc quilt`
// does with the page's plan, which downloads as plan.json.
// Test hooks: body[data-state] is loading | busy | ready | error;
// #preview[data-generation] counts drawn results; 'quiltc:drawn' and
// 'quiltc:error' events fire on document.
import { MM_PER, fmt, buildParamControls, paramValues, showDefaults as showDefaultsIn } from './controls.js';
import { plan, initTopView, loadTop, updatePatches, patchLayer, ditchLayer, topStats, showPatchDefaults, refreshEditor } from './top-view.js';

const $ = (id) => document.getElementById(id);
const FORMATS = [
  ['pat', 'pat', 'Innova AutoPilot'], ['qli', 'qli', 'Statler Stitcher'], ['bqm', 'bqm', 'Bernina Q-matic'],
  ['iqp', 'iqp', 'IntelliQuilter'], ['qcc', 'qcc', 'QuiltEZ'], ['plt', 'plt', 'HPGL plotters'],
  ['dxf', 'dxf', 'CAD / most long-arm software'], ['gcode', 'gcode', 'G-code (mm)'], ['svg', 'svg', 'drawing'],
];

const worker = new Worker(new URL('worker.js', import.meta.url), { type: 'module' });
let table = [];
let families = []; // the library's, with their needs and defaults (qc_family_info)
let regionSvg = null; // { name, text }
let top = null; // { name, text } of an SVG holding several patches (a quilt top)
let motifSvg = null; // { name, svg }
let latest = null;
let requestId = 0;
let busy = false;
let dirty = false;
let generation = 0;
const waiting = new Map();

function send(msg) {
  msg.id = ++requestId;
  worker.postMessage(msg);
  return new Promise((resolve, reject) => waiting.set(msg.id, { resolve, reject }));
}

worker.onmessage = (e) => {
  const m = e.data;
  if (m.type === 'ready') {
    table = m.params;
    families = m.families;
    $('version').textContent = `library ${m.version}`;
    buildFamilies();
    buildParams();
    buildMotifs(m.motifs);
    buildDownloads();
    regenerate();
    return;
  }
  if (m.type === 'fatal') {
    fail(m.message);
    return;
  }
  const w = waiting.get(m.id);
  if (!w) return;
  waiting.delete(m.id);
  if (m.type === 'error') w.reject(new Error(m.message)); else w.resolve(m);
};
worker.onerror = (e) => { e.preventDefault(); fail(`the generator stopped: ${e.message || 'worker error'}`); };
window.addEventListener('error', (e) => showError(`page error: ${e.message}`));
window.addEventListener('unhandledrejection', (e) => showError(`page error: ${e.reason?.message || e.reason}`));

const units = () => $('units').value;
const mmPerUnit = () => MM_PER[units()];
const familyRow = () => table.find((r) => r.name === 'family');
const family = () => families.find((f) => f.name === $('family').value);

function buildFamilies() {
  const def = familyRow().def;
  $('family').innerHTML = families
    .map((f) => `<option value="${f.name}" title="${f.summary}"${f.id === def ? ' selected' : ''}>${f.name}</option>`).join('');
}

// One control per parameter row of the chosen family: ranges and defaults in the page's units.
function buildParams() {
  buildParamControls({ box: $('params'), table, family: family(), units: units(), onChange: regenerateSoon });
  $('motifBox').hidden = !takesMotifs();
}

// The families that draw motifs (docs/motifs.md), as the library says (QC_FAMILY_NEEDS_MOTIFS).
const takesMotifs = () => family().motifs;

function buildMotifs(names) {
  $('motifList').innerHTML = names.map((n) =>
    `<label class="check"><input type="checkbox" value="${n}"> ${n}</label>`).join('');
  for (const c of $('motifList').querySelectorAll('input')) c.addEventListener('change', regenerateSoon);
}

function regionSpec() {
  const w = $('shapeW').value.trim();
  const shape = $('shape').value;
  return shape === 'rect' ? `rect:${w}x${$('shapeH').value.trim()}` : `${shape}:${w}`;
}

// The settings for the worker; throws on a field that is not a number.
function settings() {
  const params = { family: $('family').value, ...paramValues($('params')) };
  for (const id of ['shapeW', 'shapeH', 'tie']) {
    if ($(id).validity.badInput || $(id).value.trim() === '') {
      if (id !== 'tie' && (top || regionSvg)) continue; // an SVG has its own size
      if (id !== 'shapeH' || $('shape').value === 'rect') throw new Error(`${$(id).closest('label').textContent.trim()}: enter a number`);
    }
  }
  const motifs = [];
  if (takesMotifs()) { // other families ignore motifs: keep them off the command line
    motifs.push(...[...$('motifList').querySelectorAll('input:checked')].map((c) => c.value));
    if (motifSvg) motifs.push(motifSvg);
  }
  const tie = Number($('tie').value);
  if (!Number.isInteger(tie) || tie < 0 || tie > 100) throw new Error(`tie-off stitches: ${$('tie').value} is not a count from 0 to 100`);
  const s = { type: 'generate', units: units(), params, seed: $('seed').value.trim() || '0', motifs, tie };
  if (top) return { ...s, top: { svg: top.text, name: top.name }, plan: plan.toPlan(top.patches), join: $('join').value };
  return { ...s, region: regionSvg ? { svg: regionSvg.text, name: regionSvg.name } : { shape: regionSpec() } };
}

// The downloaded plan's file name, and the top's base name for the others.
const baseName = () => top.name.replace(/\.svg$/i, '');
const planName = () => `${baseName()}-plan.json`;

// The same settings as a quiltc command line.
function commandLine(s) {
  const q = (v) => (/^[\w.,:/+-]+$/.test(v) ? v : `'${v.replace(/'/g, "'\\''")}'`);
  const a = s.top ? ['quiltc', 'quilt', q(s.top.name)] : ['quiltc', 'generate', '--region', q(regionSvg ? regionSvg.name : s.region.shape)];
  if (s.top && s.plan.length) a.push('--plan', q(planName()));
  a.push('--units', s.units);
  for (const [k, v] of Object.entries(s.params)) a.push(`--${k}`, q(String(v)));
  a.push('--seed', s.seed);
  if (s.motifs.length) a.push('--motif', q(s.motifs.map((m) => (typeof m === 'string' ? m : m.name)).join(',')));
  if (s.tie || s.top) a.push('--tie', String(s.tie)); // quiltc quilt ties 3 unless told
  if (s.top) a.push('--join', s.join);
  a.push('-o', s.top ? 'quilt.pat' : 'pattern.pat');
  return a.join(' ');
}

function setState(state) { document.body.dataset.state = state; }

// Text from files (SVG names, library messages) may hold control
// characters, C1 (U+0080..U+009F) included: shown as \uXXXX, as the CLI does.
const visible = (m) => String(m).replace(/[\u0000-\u001f\u007f-\u009f]/g,
  (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, '0')}`);

function showError(message) {
  message = message && visible(message);
  $('error').hidden = !message;
  $('error').textContent = message || '';
  if (message) $('error').dataset.count = Number($('error').dataset.count || 0) + 1;
  if (message) document.dispatchEvent(new CustomEvent('quiltc:error', { detail: message }));
}

// The SVG reader's warnings (a clip it cannot apply, text, ...): shown, never
// a silent misread.
function showWarnings(lines) {
  const list = $('svgWarnings');
  list.replaceChildren(...(lines || []).map((w) => {
    const li = document.createElement('li');
    li.textContent = `warning: ${w}`;
    return li;
  }));
  list.hidden = !(lines && lines.length);
}

function fail(message) {
  setState('error');
  showError(message);
}

let timer = null;
function regenerateSoon() { clearTimeout(timer); timer = setTimeout(regenerate, 50); }

// One generation in flight; changes made meanwhile trigger one more when it ends.
async function regenerate() {
  if (!table.length) return;
  if (busy) {
    dirty = true;
    return;
  }
  let s;
  try {
    s = settings();
  } catch (err) {
    fail(err.message);
    return;
  }
  busy = true;
  dirty = false;
  setState('busy');
  const t0 = performance.now();
  try {
    const r = await send(s);
    r.settings = s;
    const t1 = performance.now();
    draw(r);
    latest = r;
    r.drawMs = performance.now() - t1;
    r.totalMs = performance.now() - t0;
    showStats(r);
    showWarnings(r.warnings);
    showDefaultsIn($('params'), table, r.resolved, units());
    if (r.patches) showPatchDefaults(r.resolved);
    $('cli').textContent = commandLine(s);
    showError('');
    setState('ready');
    document.dispatchEvent(new CustomEvent('quiltc:drawn', { detail: { ms: r.ms, drawMs: r.drawMs, totalMs: r.totalMs, stats: r.stats } }));
  } catch (err) {
    fail(err.message); // the last good preview stays on screen under the message
  } finally {
    busy = false;
    if (dirty) regenerate();
  }
}

function pathData(xy, flags) {
  const n = flags.length;
  const parts = new Array(n);
  for (let i = 0; i < n; i++) {
    parts[i] = `${flags[i] & 1 ? 'M' : 'L'}${xy[2 * i].toFixed(2)} ${xy[2 * i + 1].toFixed(2)}`;
  }
  return parts.join('');
}

// Ticks every inch (quarters) or every 10 mm (5 mm) along the bottom and left edges.
function ruler(w, h, size) {
  const mm = mmPerUnit();
  const major = units() === 'mm' ? 10 : 25.4;
  const minor = units() === 'mm' ? 5 : 6.35;
  const every = Math.max(1, Math.ceil((size / major) / 12)); // at most ~12 labels
  const t = size / 60;
  const fs = size / 38;
  let g = '';
  const label = (x, y, text, anchor) =>
    `<text transform="translate(${x.toFixed(2)} ${y.toFixed(2)}) scale(1 -1)" text-anchor="${anchor}">${text}</text>`;
  for (let k = 0; k * minor <= w + 1e-6; k++) {
    const x = k * minor;
    const isMajor = Math.abs(x / major - Math.round(x / major)) < 1e-9;
    g += `<line x1="${x.toFixed(2)}" y1="0" x2="${x.toFixed(2)}" y2="${-(isMajor ? 2 : 1) * t}"/>`;
    if (isMajor && Math.round(x / major) % every === 0) g += label(x, -2 * t - fs, fmt(x / mm, 4), 'middle');
  }
  for (let k = 0; k * minor <= h + 1e-6; k++) {
    const y = k * minor;
    const isMajor = Math.abs(y / major - Math.round(y / major)) < 1e-9;
    g += `<line x1="0" y1="${y.toFixed(2)}" x2="${-(isMajor ? 2 : 1) * t}" y2="${y.toFixed(2)}"/>`;
    if (isMajor && Math.round(y / major) % every === 0 && y > 0) g += label(-2.4 * t, y - fs / 3, fmt(y / mm, 4), 'end');
  }
  g += label(-2.4 * t, -2 * t - fs, units(), 'end');
  return `<g class="ruler" font-size="${fs.toFixed(2)}">${g}</g>`;
}

function draw(r) {
  let w = 0;
  let h = 0;
  for (const ring of r.rings) for (const [x, y] of ring) { w = Math.max(w, x); h = Math.max(h, y); }
  const size = Math.max(w, h, 1);
  const padL = size * 0.09;
  const pad = size * 0.03;
  const svg = $('preview');
  svg.setAttribute('viewBox', `${(-padL).toFixed(2)} ${(-pad).toFixed(2)} ${(w + padL + pad).toFixed(2)} ${(h + padL + pad).toFixed(2)}`);
  const regionD = r.rings.map((ring) => `M${ring.map(([x, y]) => `${x.toFixed(2)} ${y.toFixed(2)}`).join('L')}Z`).join('');
  const d = pathData(r.xy, r.flags);
  if (r.patches) updatePatches(r.patches);
  svg.classList.toggle('top', !!r.patches);
  svg.innerHTML = `<g transform="translate(0 ${h.toFixed(2)}) scale(1 -1)">${ruler(w, h, size)}
    <path id="regionPath" d="${regionD}" fill-rule="evenodd"/>${r.patches ? patchLayer(r.patches) : ''}
    <path id="stitchPath" d="${d}"/>${r.ditch ? ditchLayer(r.ditch) : ''}
    <path id="sewPath" d="${d}" stroke-width="${(size / 300).toFixed(3)}" visibility="hidden"/>
    <circle id="needle" r="${(size / 120).toFixed(2)}" visibility="hidden"/></g>`;
  svg.dataset.points = r.flags.length;
  svg.dataset.generation = ++generation;
  stopSew();
  prepareSew(r);
}

function showStats(r) {
  const s = r.stats;
  $('patchStats').innerHTML = '';
  if (r.patches) {
    const t = topStats(r, units());
    $('stats').innerHTML = t.rows.map(([k, v]) => `<div><dt>${k}</dt><dd data-stat="${k}">${v}</dd></div>`).join('');
    $('patchStats').innerHTML = t.table;
    return;
  }
  const inch = units() === 'in';
  const len = inch ? `${(s.path_length_mm / 25.4).toFixed(1)} in` : `${(s.path_length_mm / 1000).toFixed(2)} m`;
  const thread = inch ? `${(s.thread_mm / 914.4).toFixed(1)} yd` : `${(s.thread_mm / 1000).toFixed(1)} m`;
  const min = Math.floor(s.sew_seconds / 60);
  const rows = [
    ['points', s.points], ['path length', len], ['stitches (12 per inch)', s.stitches.toLocaleString('en')],
    ['thread', thread], ['sewing time', `${min} min ${Math.round(s.sew_seconds - 60 * min)} s`],
    ['pieces', s.pieces], ['generation', `${r.ms.toFixed(0)} ms`],
  ];
  if (s.motifs_placed) rows.push(['motifs placed', s.motifs_placed]);
  if (s.pebbles) rows.push(['pebbles', s.pebbles]);
  if (s.farthest_fabric_mm) rows.push(['farthest fabric from a stitch', inch ? `${(s.farthest_fabric_mm / 25.4).toFixed(2)} in` : `${s.farthest_fabric_mm.toFixed(1)} mm`]);
  if (s.farthest_fabric_mm) rows.push(['seam farther than 1/4 in', `${(100 * s.seam_bare).toFixed(0)}%`]);
  if (s.largest_gap_mm) rows.push(['largest gap', inch ? `${(s.largest_gap_mm / 25.4).toFixed(2)} in` : `${s.largest_gap_mm.toFixed(1)} mm`]);
  $('stats').innerHTML = rows.map(([k, v]) => `<div><dt>${k}</dt><dd data-stat="${k}">${v}</dd></div>`).join('');
}

function buildDownloads() {
  $('downloads').innerHTML = FORMATS.map(([f, ext, what]) =>
    `<button type="button" data-format="${f}" data-ext="${ext}" title="${what}">.${ext}</button>`).join('') +
    '<button type="button" id="planDownload" data-format="plan" title="the patches\' patterns, for quiltc quilt --plan" hidden>plan.json</button>';
  for (const b of $('downloads').querySelectorAll('button')) b.addEventListener('click', () => download(b));
}

function save(name, bytes, type = 'application/octet-stream') {
  const url = URL.createObjectURL(new Blob([bytes], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

async function download(button) {
  try {
    if (busy || dirty) throw new Error('the preview is still being generated; try again in a moment');
    if (!latest) throw new Error('nothing to download yet');
    const f = button.dataset.format;
    const r = await send({ type: 'export', format: f === 'plan' ? 'pat' : f }); // the worker refuses a stale pattern
    const s = latest.settings;
    if (f === 'plan') { // the plan that gave the pattern on screen
      if (!s.top || !s.plan.length) throw new Error('no patch has its own pattern: nothing to put in a plan');
      save(planName(), `${JSON.stringify(s.plan, null, 1)}\n`, 'application/json');
      return;
    }
    save(s.top ? `${baseName()}-quilt.${button.dataset.ext}` : `quiltc-${s.params.family}-${s.seed}.${button.dataset.ext}`, r.bytes);
  } catch (err) {
    showError(err.message);
  }
}

// ---- sew: the path traced in stitching order at a chosen multiple of real sewing speed ----
let sew = null;

function prepareSew(r) {
  const n = r.flags.length;
  const cum = new Float64Array(n);
  for (let i = 1; i < n; i++) {
    const d = r.flags[i] & 1 ? 0 : Math.hypot(r.xy[2 * i] - r.xy[2 * i - 2], r.xy[2 * i + 1] - r.xy[2 * i - 1]);
    cum[i] = cum[i - 1] + d;
  }
  const total = cum[n - 1] || 1;
  const p = $('sewPath');
  p.setAttribute('pathLength', total.toFixed(3));
  p.setAttribute('stroke-dasharray', `${total.toFixed(3)} ${total.toFixed(3)}`);
  sew = { r, cum, total, sewn: 0, frame: 0, last: 0 };
}

const speedFactor = () => 10 ** ($('sewSpeed').value / 25); // 1x .. 10000x real time
function showSpeed() { $('sewSpeedLabel').textContent = `×${fmt(speedFactor(), 2)}`; }

function stopSew() {
  if (sew && sew.frame) cancelAnimationFrame(sew.frame);
  if (sew) sew.frame = 0;
  $('sewBtn').textContent = 'Sew';
}

function sewFrame(now) {
  const dt = Math.min(0.1, (now - sew.last) / 1000);
  sew.last = now;
  sew.sewn = Math.min(sew.total, sew.sewn + dt * 25.4 * speedFactor());
  showSewn();
  if (sew.sewn < sew.total) {
    sew.frame = requestAnimationFrame(sewFrame);
  } else {
    sew.frame = 0;
    $('sewBtn').textContent = 'Sew';
    $('sewBtn').dataset.done = '1';
  }
}

function showSewn() {
  const { r, cum, total, sewn } = sew;
  $('sewPath').setAttribute('stroke-dashoffset', (total - sewn).toFixed(3));
  let lo = 0;
  let hi = cum.length - 1;
  while (lo < hi) { const mid = (lo + hi + 1) >> 1; if (cum[mid] <= sewn) lo = mid; else hi = mid - 1; }
  const i = lo;
  const j = Math.min(i + 1, cum.length - 1);
  const f = cum[j] > cum[i] ? (sewn - cum[i]) / (cum[j] - cum[i]) : 0;
  const needle = $('needle');
  needle.setAttribute('cx', (r.xy[2 * i] + f * (r.xy[2 * j] - r.xy[2 * i])).toFixed(2));
  needle.setAttribute('cy', (r.xy[2 * i + 1] + f * (r.xy[2 * j + 1] - r.xy[2 * i + 1])).toFixed(2));
  $('sewBtn').dataset.progress = (sewn / total).toFixed(4);
}

$('sewBtn').addEventListener('click', () => {
  if (!sew) return;
  if (sew.frame) { stopSew(); return; }
  if (sew.sewn >= sew.total) sew.sewn = 0;
  delete $('sewBtn').dataset.done;
  $('sewPath').setAttribute('visibility', 'visible');
  $('needle').setAttribute('visibility', 'visible');
  $('sewBtn').textContent = 'Stop';
  sew.last = performance.now();
  sew.frame = requestAnimationFrame(sewFrame);
});
$('sewSpeed').addEventListener('input', showSpeed);
showSpeed();

// ---- region and motif files ----
// An SVG of several patches is a quilt top; one shape (or an SVG the patch
// reader refuses) is a block outline, as before.
async function readRegionFile(file) {
  const text = await file.text();
  let patches = [];
  try {
    patches = (await send({ type: 'probe', svg: text, name: file.name })).patches;
  } catch {
    patches = [];
  }
  if (patches.length > 1) {
    top = { name: file.name, text, patches };
    regionSvg = null;
    loadTop(patches);
  } else {
    top = null;
    regionSvg = { name: file.name, text };
  }
  $('shape').querySelector('[value=svg]').disabled = false;
  $('shape').value = 'svg';
  shapeFields();
  regenerate();
}

function shapeFields() {
  const shape = $('shape').value;
  $('sizeW').hidden = shape === 'svg';
  $('sizeH').hidden = shape !== 'rect';
  $('sizeW').querySelector('.label-text').textContent = shape === 'rect' ? 'Width' : 'Size';
  $('regionName').textContent = shape === 'svg' ? (regionSvg || top)?.name || '' : '';
  $('topBox').hidden = !(top && shape === 'svg');
  if ($('planDownload')) $('planDownload').hidden = !(top && shape === 'svg');
  if (top && shape === 'svg') $('topName').textContent = `${top.name}: ${top.patches.length} patches`;
}

$('regionFile').addEventListener('change', (e) => {
  const f = e.target.files[0];
  e.target.value = ''; // choosing the same file again (fixed, say) reloads it; its name shows below
  if (f) readRegionFile(f);
});
$('motifFile').addEventListener('change', async (e) => {
  const f = e.target.files[0];
  motifSvg = f ? { name: f.name, svg: await f.text() } : null;
  $('motifName').textContent = motifSvg ? motifSvg.name : '';
  regenerate();
});
const drop = $('drop');
drop.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
drop.addEventListener('dragleave', () => drop.classList.remove('over'));
drop.addEventListener('drop', (e) => {
  e.preventDefault();
  drop.classList.remove('over');
  const f = e.dataTransfer.files[0];
  if (f) readRegionFile(f);
});
$('shape').addEventListener('change', () => {
  if ($('shape').value !== 'svg') {
    regionSvg = null;
    top = null;
    $('regionFile').value = ''; // choosing the same file again reloads it
  }
  shapeFields();
  regenerate();
});
for (const id of ['shapeW', 'shapeH', 'seed', 'tie']) $(id).addEventListener('input', regenerateSoon);
$('units').addEventListener('change', () => {
  const f = units() === 'mm' ? 25.4 : 1 / 25.4;
  for (const id of ['shapeW', 'shapeH']) if ($(id).value !== '') $(id).value = fmt($(id).value * f);
  const lengths = new Set(table.filter((r) => r.type === 'length').map((r) => r.name));
  for (const el of $('params').querySelectorAll('[data-param]')) {
    if (lengths.has(el.dataset.param) && el.value !== '') el.value = fmt(el.value * f);
  }
  plan.rescale(lengths, f, fmt);
  buildParams();
  refreshEditor();
  regenerate();
});
$('family').addEventListener('change', () => { buildParams(); refreshEditor(); regenerate(); });
$('join').addEventListener('change', regenerate);
initTopView({
  table: () => table,
  families: () => families,
  units,
  globalFamily: () => $('family').value,
  changed: regenerateSoon,
  fail,
});
$('shuffle').addEventListener('click', () => {
  $('seed').value = String(Math.floor(Math.random() * 2 ** 32));
  regenerate();
});
shapeFields();
