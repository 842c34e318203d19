// The page: controls built from the library's parameter table, generation in
// a Web Worker, an SVG preview to scale with a ruler, a sew animation and
// downloads that are byte-identical to the quiltc CLI's.
const $ = (id) => document.getElementById(id);
const FORMATS = ['pat', 'qli', 'dxf', 'plt', 'qcc', 'iqp', 'bqm', 'gcode', 'svg'];
const FAMILY_IGNORES = new Set(['family', 'seed', 'points', 'start-x', 'start-y', 'tsp-time']);
const worker = new Worker('worker.js', { type: 'module' });
let table = [];
let regionSvg = null;
let motifSvg = null;
let pending = 0;
let latest = null;
let requestId = 0;
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
    $('version').textContent = `library ${m.version}`;
    buildFamilies();
    buildParams();
    buildDownloads();
    regenerate();
    return;
  }
  const w = waiting.get(m.id);
  if (!w) return;
  waiting.delete(m.id);
  if (m.type === 'error') w.reject(new Error(m.message)); else w.resolve(m);
};

const units = () => $('units').value;
const mmPerUnit = () => (units() === 'mm' ? 1 : 25.4);

function buildFamilies() {
  const fam = table.find((r) => r.name === 'family');
  const names = fam.choices.split('|');
  $('family').innerHTML = names.map((n, i) => `<option value="${n}"${i + 1 === fam.def ? ' selected' : ''}>${n}</option>`).join('');
}

function familyBit() { return 1 << ($('family').selectedIndex + 1); }

// One control per parameter of the chosen family: ranges and defaults in the page's units.
function buildParams() {
  const box = $('params');
  const keep = {};
  for (const el of box.querySelectorAll('[data-param]')) keep[el.dataset.param] = el.value;
  box.innerHTML = '';
  for (const row of table) {
    if (FAMILY_IGNORES.has(row.name) && row.name !== 'points') continue;
    if (!(row.families & familyBit())) continue;
    const label = document.createElement('label');
    label.className = 'param';
    label.title = row.help;
    let input;
    if (row.type === 'enum') {
      input = document.createElement('select');
      const choices = row.choices.split('|').filter((c) => c !== 'given');
      input.innerHTML = `<option value="">default</option>` + choices.map((c) => `<option>${c}</option>`).join('');
    } else {
      input = document.createElement('input');
      input.type = 'number';
      const scale = row.type === 'length' ? mmPerUnit() : 1;
      input.min = +(row.min / scale).toPrecision(6);
      input.max = +(row.max / scale).toPrecision(6);
      input.step = row.type === 'int' ? 1 : 'any';
      input.placeholder = row.def_per_spacing ? `${row.def_per_spacing} x spacing` : +(row.def / scale).toPrecision(6);
    }
    input.dataset.param = row.name;
    if (keep[row.name] !== undefined) input.value = keep[row.name];
    input.addEventListener('input', regenerateSoon);
    label.append(`${row.name}${row.unit && row.type !== 'length' ? ` (${row.unit})` : row.type === 'length' ? ` (${units()})` : ''} `, input);
    box.append(label);
  }
}

function settings() {
  const params = { family: $('family').value };
  for (const el of $('params').querySelectorAll('[data-param]')) {
    if (el.value !== '') params[el.dataset.param] = el.tagName === 'SELECT' ? el.value : Number(el.value);
  }
  const region = regionSvg !== null ? { svg: regionSvg }
    : { shape: $('shape').value === 'rect' ? `rect:${$('shapeSize').value}x${$('shapeSize').value}` : `${$('shape').value}:${$('shapeSize').value}` };
  const s = { type: 'generate', units: units(), region, params, seed: $('seed').value || '0' };
  if ($('motifs').value.trim()) s.motifs = $('motifs').value.trim();
  if (motifSvg) s.motifSvg = motifSvg;
  return s;
}

function showError(message) {
  $('error').hidden = !message;
  $('error').textContent = message || '';
}

let timer = null;
function regenerateSoon() { clearTimeout(timer); timer = setTimeout(regenerate, 60); }

async function regenerate() {
  const mine = ++pending;
  try {
    const r = await send(settings());
    if (mine !== pending) return; // a newer request is on its way
    latest = r;
    showError('');
    draw(r);
    showStats(r);
  } catch (err) {
    if (mine === pending) showError(err.message);
  }
}

function pathData(xy, flags, count) {
  let d = '';
  for (let i = 0; i < count; i++) {
    d += `${flags[i] & 1 ? 'M' : 'L'}${xy[2 * i].toFixed(2)} ${xy[2 * i + 1].toFixed(2)}`;
  }
  return d;
}

function ruler(w, h) {
  const step = units() === 'mm' ? 10 : 25.4;
  let ticks = '';
  for (let x = 0, k = 0; x <= w + 1e-6; x += step, k++) {
    ticks += `<line x1="${x}" y1="0" x2="${x}" y2="${k % 5 ? -2 : -4}"/>`;
    if (units() === 'in' || k % 5 === 0) ticks += `<text x="${x}" y="-5" transform="scale(1 -1)" text-anchor="middle">${units() === 'mm' ? k * 10 : k}</text>`;
  }
  for (let y = 0, k = 0; y <= h + 1e-6; y += step, k++) ticks += `<line x1="0" y1="${y}" x2="${k % 5 ? -2 : -4}" y2="${y}"/>`;
  return `<g class="ruler" stroke="#888" stroke-width="0.3" font-size="3.5" fill="#666">${ticks}</g>`;
}

function draw(r) {
  let w = 0, h = 0;
  for (const ring of r.rings) for (const [x, y] of ring) { w = Math.max(w, x); h = Math.max(h, y); }
  const pad = Math.max(w, h) * 0.06 + 4;
  const svg = $('preview');
  svg.setAttribute('viewBox', `${-pad} ${-pad} ${w + 2 * pad} ${h + 2 * pad}`);
  const regionD = r.rings.map((ring) => 'M' + ring.map(([x, y]) => `${x.toFixed(2)} ${y.toFixed(2)}`).join('L') + 'Z').join('');
  const n = r.xy.length / 2;
  svg.innerHTML = `<g transform="translate(0 ${h}) scale(1 -1)">${ruler(w, h)}
    <path id="regionPath" d="${regionD}" fill="#fff" stroke="#1d3557" stroke-width="0.5" fill-rule="evenodd"/>
    <path id="stitchPath" d="${pathData(r.xy, r.flags, n)}" fill="none" stroke="#c1121f" stroke-width="0.35" stroke-linejoin="round"/>
    <path id="sewPath" d="" fill="none" stroke="#2a9d8f" stroke-width="0.6"/></g>`;
  svg.dataset.points = n;
}

function showStats(r) {
  const s = r.stats;
  const len = units() === 'mm' ? `${s.path_length_mm.toFixed(0)} mm` : `${(s.path_length_mm / 25.4).toFixed(1)} in`;
  const rows = [
    ['points', s.points], ['path length', len], ['stitches (12 SPI)', s.stitches],
    ['thread', `${(s.thread_mm / 914.4).toFixed(1)} yd`], ['sewing time', `${(s.sew_seconds / 60).toFixed(1)} min`],
    ['pieces', s.pieces], ['generation', `${r.ms.toFixed(1)} ms`],
  ];
  if (s.motifs_placed) rows.push(['motifs placed', s.motifs_placed]);
  if (s.pebbles) rows.push(['pebbles', s.pebbles]);
  $('stats').innerHTML = rows.map(([k, v]) => `<dt>${k}</dt><dd data-stat="${k}">${v}</dd>`).join('');
}

function buildDownloads() {
  $('downloads').innerHTML = FORMATS.map((f) => `<button type="button" data-format="${f}">.${f}</button>`).join('');
  for (const b of $('downloads').querySelectorAll('button')) {
    b.addEventListener('click', async () => {
      try {
        const r = await send({ type: 'export', format: b.dataset.format });
        const url = URL.createObjectURL(new Blob([r.bytes], { type: 'application/octet-stream' }));
        const a = document.createElement('a');
        a.href = url;
        a.download = `pattern.${r.format}`;
        document.body.append(a);
        a.click();
        a.remove();
        setTimeout(() => URL.revokeObjectURL(url), 1000);
      } catch (err) {
        showError(err.message);
      }
    });
  }
}

// Sew: trace the path in stitching order.
let sewing = null;
$('sewBtn').addEventListener('click', () => {
  if (!latest) return;
  cancelAnimationFrame(sewing);
  const n = latest.xy.length / 2;
  let shown = 0;
  const step = () => {
    shown = Math.min(n, shown + Math.max(1, Math.round(n * $('sewSpeed').value / 6000)));
    $('sewPath').setAttribute('d', pathData(latest.xy, latest.flags, shown));
    $('sewBtn').dataset.progress = shown;
    if (shown < n) sewing = requestAnimationFrame(step); else $('sewBtn').dataset.done = '1';
  };
  delete $('sewBtn').dataset.done;
  step();
});

async function readRegionFile(file) {
  regionSvg = await file.text();
  $('shape').querySelector('[value=svg]').disabled = false;
  $('shape').value = 'svg';
  regenerate();
}

$('regionFile').addEventListener('change', (e) => e.target.files[0] && readRegionFile(e.target.files[0]));
$('motifFile').addEventListener('change', async (e) => {
  const f = e.target.files[0];
  motifSvg = f ? { text: await f.text(), name: f.name } : null;
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
$('shape').addEventListener('change', () => { if ($('shape').value !== 'svg') regionSvg = null; regenerate(); });
$('shapeSize').addEventListener('input', regenerateSoon);
$('units').addEventListener('change', () => {
  const f = units() === 'mm' ? 25.4 : 1 / 25.4;
  $('shapeSize').value = +($('shapeSize').value * f).toPrecision(6);
  for (const el of $('params').querySelectorAll('[data-param]')) {
    const row = table.find((r) => r.name === el.dataset.param);
    if (row.type === 'length' && el.value !== '') el.value = +(el.value * f).toPrecision(6);
  }
  buildParams();
  regenerate();
});
$('family').addEventListener('change', () => { buildParams(); regenerate(); });
$('seed').addEventListener('input', regenerateSoon);
$('motifs').addEventListener('change', regenerate);
$('shuffle').addEventListener('click', () => { $('seed').value = Math.floor(Math.random() * 1e9); regenerate(); });
