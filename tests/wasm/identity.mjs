// Byte identity: the WebAssembly module (build/web/quiltc.mjs, loaded in
// Node) against the native CLI (build/quiltc generate) and against the same
// binding code compiled natively (build/tests/qcw_native), for a corpus of
// settings across every family x shapes x seeds, in every output format;
// and quilt tops: qcw_quilt with a plan set as rules against
// `quiltc quilt TOP.svg --plan PLAN.json` (the sawtooth star and variants).
// A family the library does not build yet must fail the same way on every
// side; its cases are reported as ignored.
//   node tests/wasm/identity.mjs        (BUILD=build by default)
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { Report, Skip, assert, describeDiff } from './harness.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const BUILD = path.resolve(ROOT, process.env.BUILD || 'build');
const WEB = path.join(BUILD, 'web');
const FIX = path.join(ROOT, 'tests/wasm/fixtures');
const FORMATS = ['pat', 'qli', 'dxf', 'plt', 'qcc', 'iqp', 'bqm', 'gcode', 'svg'];
const report = new Report('tests/wasm/identity.mjs');

const { default: createQuiltc } = await import(path.join(WEB, 'quiltc.mjs'));
const { Quiltc } = await import(path.join(WEB, 'quiltc-api.js'));
const module = await createQuiltc({ wasmBinary: fs.readFileSync(path.join(WEB, 'quiltc.wasm')) });
const api = new Quiltc(module);

// The references: the CLI once `quiltc generate --help` works, and always the native bindings.
const cli = path.join(BUILD, 'quiltc');
const cliReady = fs.existsSync(cli) && spawnSync(cli, ['generate', '--help']).status === 0;
const native = path.join(BUILD, 'tests/qcw_native');
const nativeReady = fs.existsSync(native);

// ---- the corpus ----
const FAMILIES = api.families().map((f) => f.name); // the library's list (qc_family_info)
const SHAPES = [
  { region: 'rect:8x8', units: 'in' },
  { region: 'heart:180', units: 'mm' },
  { region: `${FIX}/block-hole.svg`, units: 'in' },
];
const SEEDS = ['1', '18446744073709551557']; // the second needs all 64 bits
const cases = [];
for (const family of FAMILIES) {
  for (const shape of SHAPES) {
    for (const seed of SEEDS) cases.push({ ...shape, seed, params: { family } });
  }
}
const extra = [
  { region: 'circle:6', params: { family: 'stipple', points: 'hex', spacing: '0.35', tip: 'circle', width: '0.1' } },
  { region: 'star:7', params: { family: 'fill', points: 'square', margin: '0.2' }, tie: 3 },
  { region: 'hexagon:6', params: { family: 'vine', points: 'triangle', mst: 'complete', 'start-x': '2', 'start-y': '3' } },
  { region: 'rect:6x4', params: { family: 'vine', points: 'snub', skeleton: 'tsp', tsp: '2opt' } },
  { region: 'rect:6x6', params: { family: 'vine', skeleton: 'tsp', tsp: 'greedy' }, seed: '99' },
  { region: 'rect:8x6', params: { family: 'branching', size: '0.3', angle: '30', gap: '0.1' }, motifs: ['heart', 'leaf'] },
  { region: 'circle:7', params: { family: 'branching' }, motifs: ['flower', `${FIX}/tulip.svg`] },
  { region: 'rect:7x7', params: { family: 'wanderer', tangent: '0.8' }, motifs: ['loop90', 'heart90'] },
  { region: 'rect:4x4', params: { family: 'stipple', tile: 'edge-to-edge', 'repeat-cols': '2', 'repeat-rows': '2' } },
  { region: 'rect:4x4', params: { family: 'fill', tile: 'all-over' } },
  { region: 'rect:8x8', params: { family: 'pebbling', edge: 'overgrow', 'r-seed': '0.8' } },
  { region: 'circle:8', params: { family: 'packing', points: 'poisson' }, motifs: ['star', 'circle'] },
  { region: 'rect:8x5', params: { family: 'echo', 'echo-join': 'spiral', spacing: '0.3' } },
  { region: 'rect:8x8', params: { family: 'spiral', spiral: 'fermat', spacing: '0.3' } },
  { region: 'heart:7', params: { family: 'meander', wiggle: '0.9', 'turn-radius': '0.12', iterations: '80', 'start-x': '1', 'start-y': '2' } },
  { region: 'rect:20x15', units: 'cm', params: { family: 'stipple', spacing: '1.2' }, seed: '3' },
  { region: 'heart:7', params: { family: 'stipple', spacing: '9mm', margin: '0.1in' } },
  { region: 'rect:8x8', params: { family: 'stipple', spacing: '0.12' }, seed: '4242' }, // ~3000 points
  // errors: both sides must refuse with the same message
  { region: 'rect:8x8', params: { family: 'stipple', spacing: '0.001' }, error: true },
  { region: 'rect:1x1', params: { family: 'vine', spacing: '0.5', margin: '2' }, error: true },
  // Number() and BigInt() take 0b11, 0o17, 0x10: the page must refuse them as
  // the CLI does (qcw_native's own parsing is lax: not a reference for text)
  { region: 'rect:8x8', params: { family: 'stipple', spacing: '0b11' }, error: true, cliOnly: true },
  { region: 'rect:8x8', params: { family: 'stipple', margin: '0x10' }, error: true, cliOnly: true },
  { region: 'rect:8x8', params: { family: 'stipple' }, seed: '0o17', error: true, cliOnly: true },
];
for (const c of extra) cases.push({ units: 'in', seed: '1', ...c });

function label(c) {
  const p = Object.entries(c.params).map(([k, v]) => (k === 'family' ? v : `${k}=${v}`)).join(',');
  return `${p}@${path.basename(c.region)}/${c.units}/seed${c.seed}${c.motifs ? '/' + c.motifs.map((m) => path.basename(m)).join('+') : ''}${c.tie ? '/tie' + c.tie : ''}`;
}

function cliArgs(c, dir) {
  const a = ['--region', c.region, '--units', c.units, '--seed', c.seed];
  for (const [k, v] of Object.entries(c.params)) a.push(`--${k}`, v);
  if (c.motifs) a.push('--motif', c.motifs.join(','));
  if (c.tie) a.push('--tie', String(c.tie));
  for (const f of FORMATS) a.push('-o', path.join(dir, `out.${f}`));
  return a;
}

// Runs a native program; { files: {fmt: Buffer} } or { error: stderr }.
function runNative(prog, args, dir) {
  const r = spawnSync(prog, args, { encoding: 'latin1', timeout: 120000 });
  if (r.status !== 0) return { error: (r.stderr || r.error?.message || `exit ${r.status}`).trim() };
  const files = {};
  for (const f of FORMATS) files[f] = fs.readFileSync(path.join(dir, `out.${f}`));
  return { files };
}

function runWasm(c) {
  const settings = {
    units: c.units,
    region: c.region.endsWith('.svg') ? { svg: fs.readFileSync(c.region, 'utf8') } : { shape: c.region },
    params: c.params,
    seed: c.seed,
    motifs: (c.motifs || []).map((m) => (m.endsWith('.svg') ? { name: m, svg: fs.readFileSync(m, 'utf8') } : m)),
    tie: c.tie || 0,
  };
  try {
    api.generate(settings);
  } catch (err) {
    return { error: err.message };
  }
  const files = {};
  try {
    for (const f of FORMATS) files[f] = api.export(f);
  } catch (err) {
    return { error: err.message };
  }
  return { files };
}

function compare(want, got, who) {
  if (want.error !== undefined || got.error !== undefined) {
    assert(want.error !== undefined, `${who} generated but the module failed: ${got.error}`);
    assert(got.error !== undefined, `the module generated but ${who} failed: ${want.error}`);
    // a range error: the CLI speaks --units, the module mm; both must name the parameter
    const range = /^(\S+) \S+ mm out of range/.exec(got.error);
    const same = want.error.endsWith(got.error) ||
      (range !== null && want.error.includes(`--${range[1]} `) && want.error.includes('out of range'));
    assert(same, `${who} said '${want.error}', the module '${got.error}'`);
    return;
  }
  for (const f of FORMATS) {
    const a = want.files[f];
    const b = got.files[f];
    assert(a.length > 0, `${who} wrote an empty .${f}`);
    assert(Buffer.compare(a, Buffer.from(b.buffer, b.byteOffset, b.length)) === 0,
      `.${f} differs from ${who}'s: ${describeDiff(a, b)}`);
  }
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'qc-identity-'));
if (!cliReady) report.ignore('cli_reference', `${cli} generate does not work yet: comparing with the native bindings only`);
if (!nativeReady) report.fail('native_reference', `${native} missing (make ${path.relative(ROOT, native)})`);
const formatsSeen = new Set();
let compared = 0;
for (const c of cases) {
  await report.run(label(c), () => {
    const wasm = runWasm(c);
    const refs = [];
    if (cliReady) refs.push(['quiltc', runNative(cli, ['generate', ...cliArgs(c, tmp)], tmp)]);
    if (nativeReady && !(c.cliOnly && cliReady)) refs.push(['qcw_native', runNative(native, cliArgs(c, tmp), tmp)]);
    assert(refs.length > 0, 'no native reference to compare with');
    for (const [who, ref] of refs) compare(ref, wasm, who);
    if (c.error) {
      assert(wasm.error !== undefined, 'expected an error');
      return;
    }
    // identical refusals (a family not built yet, a library limit) are identity, not bytes
    if (wasm.error !== undefined) throw new Skip(`every side refused: ${wasm.error}`);
    compared++;
    for (const f of FORMATS) formatsSeen.add(f);
  });
}
// ---- quilt tops: the module's qcw_quilt, its plan set via rules (Quiltc.setPlan,
// qcw_native --rule), against `quiltc quilt TOP.svg --plan PLAN.json` ----
const STAR = path.join(ROOT, 'examples/sawtooth-star.svg');
const STAR_PLAN = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples/sawtooth-star.json'), 'utf8'));
const quiltCases = [
  { name: 'sawtooth_star_plan', plan: STAR_PLAN, oneLine: true },
  { name: 'sawtooth_star_no_plan', params: { family: 'stipple', spacing: '0.5' }, seed: '9', oneLine: true },
  { name: 'sawtooth_star_fill_none_jump_mm', units: 'mm', join: 'jump', tie: 0, params: { family: 'echo', spacing: '8' },
    plan: [{ match: { fill: '#e67e22' }, family: 'none' }, { match: { class: 'background' }, family: 'meander', params: { spacing: '9mm' } }] },
  // star points too small for a 3 in stipple: sewn round in the ditch, alike everywhere
  { name: 'sawtooth_star_coarse_ditch_only', params: { family: 'stipple', spacing: '3' }, oneLine: true, ditchOnly: 8 },
  { name: 'sawtooth_star_rule_fits_no_patch', plan: [{ match: { id: 'nope' }, family: 'stipple' }], error: true },
];

function quiltGlobals(c) {
  const a = ['--units', c.units || 'in', '--seed', c.seed || '1', '--tie', String(c.tie ?? 3), '--join', c.join || 'ditch'];
  for (const [k, v] of Object.entries(c.params || {})) a.push(`--${k}`, v);
  return a;
}

// The plan as qcw_native's --rule / --rule-set arguments.
function ruleArgs(plan) {
  const a = [];
  for (const r of plan || []) {
    a.push('--rule', Object.entries(r.match || {}).map(([k, v]) => `${k}=${v}`).join(';'));
    if (r.family) a.push('--rule-set', `family=${r.family}`);
    for (const [k, v] of Object.entries(r.params || {})) a.push('--rule-set', `${k}=${v}`);
  }
  return a;
}

function runQuiltWasm(c) {
  try {
    const out = api.quilt({ top: { svg: fs.readFileSync(STAR, 'utf8'), name: STAR }, plan: c.plan || [],
      units: c.units || 'in', params: c.params || {}, seed: c.seed || '1', tie: c.tie ?? 3, join: c.join || 'ditch' });
    const files = {};
    for (const f of FORMATS) files[f] = api.export(f);
    return { files, stats: out.stats };
  } catch (err) {
    return { error: err.message };
  }
}

for (const c of quiltCases) {
  await report.run(`quilt_${c.name}`, () => {
    const wasm = runQuiltWasm(c);
    const outs = FORMATS.flatMap((f) => ['-o', path.join(tmp, `out.${f}`)]);
    const refs = [];
    if (cliReady) {
      const planFile = path.join(tmp, 'plan.json');
      fs.writeFileSync(planFile, JSON.stringify(c.plan || []));
      const plan = c.plan ? ['--plan', planFile] : [];
      refs.push(['quiltc quilt', runNative(cli, ['quilt', STAR, '-q', ...quiltGlobals(c), ...plan, ...outs], tmp)]);
    }
    if (nativeReady) refs.push(['qcw_native quilt', runNative(native, ['quilt', STAR, ...quiltGlobals(c), ...ruleArgs(c.plan), ...outs], tmp)]);
    assert(refs.length > 0, 'no native reference to compare with');
    for (const [who, ref] of refs) {
      if (c.error) { // the CLI adds "of TOP.svg" to the module's message
        assert(ref.error !== undefined && wasm.error !== undefined, `${who}: ${ref.error}, module: ${wasm.error}`);
        assert(ref.error.includes(wasm.error), `${who} said '${ref.error}', the module '${wasm.error}'`);
      } else {
        compare(ref, wasm, who);
      }
    }
    if (c.error) return;
    const s = wasm.stats;
    assert(s.patches.length === 17, `${s.patches.length} patches`);
    if (c.oneLine) assert(s.pieces === 1 && s.jumps === 0, `${s.pieces} pieces, ${s.jumps} jumps: not one line`);
    if (c.plan === STAR_PLAN) {
      const fam = Object.fromEntries(s.patches.map((p) => [p.id, p.family]));
      assert(fam.centre === 'pebbling' && fam['point-top-a'] === 'echo' && fam['goose-top'] === 'stipple' &&
        fam['corner-nw'] === 'spiral', `families ${JSON.stringify(fam)}`);
    }
    if (c.ditchOnly) {
      const ditch = s.patches.filter((p) => p.ditch_only).map((p) => p.id);
      assert(ditch.length === c.ditchOnly && ditch.every((id) => id.startsWith('point-')), `ditch only: ${ditch}`);
    }
    if (c.join === 'jump') assert(s.unquilted === 8 && s.ditch_mm === 0, `${s.unquilted} unquilted, ditch ${s.ditch_mm} mm`);
    compared++;
  });
}

// The page's own first-fit matching (top-plan.js, used to drop rules that fit
// no patch) must choose as the library does (qc_patch_matches).
await report.run('quilt_page_matching_equals_library', async () => {
  const { matches, TopPlan } = await import(path.join(WEB, 'top-plan.js'));
  const svg = fs.readFileSync(STAR, 'utf8');
  const patches = api.topSvg(svg, STAR);
  const plan = [
    { match: { id: 'point-*-b' }, family: 'echo' }, { match: { class: 'point' }, family: 'fill' },
    { match: { label: 'Sky*' }, family: 'meander' }, { match: { fill: '#F5F0E1' }, family: 'spiral' },
    { match: { class: 'cent*', fill: 'rgb(192, 57, 43)' }, family: 'none' }, { match: { id: 'nothing*' }, family: 'stipple' },
  ];
  const want = patches.map((p) => plan.findIndex((r) => matches(r.match, p)));
  const used = plan.filter((_, k) => want.includes(k));
  assert(used.length === plan.length - 1, `${used.length} rules used`);
  const { stats } = api.quilt({ top: { svg, name: STAR }, plan: used, units: 'in', params: {}, seed: '1', tie: 0 });
  const got = stats.patches.map((p) => (p.rule === 'default' ? -1 : plan.indexOf(used[Number(/\d+/.exec(p.rule)[0])])));
  assert(JSON.stringify(got) === JSON.stringify(want), `library ${got}, page ${want}`);
  // TopPlan: a colour's rule replaces its patches' own; rules fitting no patch are dropped
  const tp = new TopPlan();
  tp.set('patch', 'centre', 'echo', {}, patches);
  tp.set('patch', 'corner-sw', 'fill', { spacing: '0.3' }, patches);
  tp.set('colour', '#f5f0e1', 'pebbling', {}, patches);
  tp.set('patch', 'goose-top', '', {}, patches);
  assert(JSON.stringify(tp.toPlan(patches)) === JSON.stringify([{ match: { id: 'centre' }, family: 'echo' },
    { match: { fill: '#f5f0e1' }, family: 'pebbling' }]), `plan ${JSON.stringify(tp.toPlan(patches))}`);
});

await report.run('enough_bytes_compared', () => {
  assert(formatsSeen.size === FORMATS.length, `only ${[...formatsSeen].join(',')} were compared`);
  assert(compared >= 40, `only ${compared} cases produced bytes to compare`);
});
fs.rmSync(tmp, { recursive: true, force: true });
report.finish();
