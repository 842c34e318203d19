// Browser tests of the preview page: build/web served by a tiny static
// server, driven in Debian's headless chromium by playwright-core. Load the
// page (first-load transfer < 500 KB), change family and parameters and see
// the preview change, out-of-range values and bad SVGs show a message while
// the last preview stays, upload and drop an SVG region, download machine
// files and compare them with the CLI's bytes, run the sew animation, fit a
// phone-sized screen. A pieced top (examples/sawtooth-star.svg): click a
// patch, give it a pattern, sew the top as one line, download the plan and
// the machine files and compare them with `quiltc quilt --plan`. After a
// failed SVG no download gives the previous pattern; labels are quilters'
// words and the controls' accessible names; no select cuts its choices
// off; on a phone the preview and the message stay in view.
// Screenshots go to build/web-shots/.
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { Report, Skip, assert, describeDiff } from './harness.mjs';
import { decodePng, countColour } from './png.mjs';
import { serve, launch, waitDrawn, waitError, errorCount, generation } from './browser.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const BUILD = path.resolve(ROOT, process.env.BUILD || 'build');
const WEB = path.join(BUILD, 'web');
const SHOTS = path.join(BUILD, 'web-shots');
const FIX = path.join(ROOT, 'tests/wasm/fixtures');
const FIRST_LOAD_LIMIT = 500 * 1024;
const report = new Report('tests/wasm/page.test.mjs');
fs.mkdirSync(SHOTS, { recursive: true });
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'qc-page-'));

// The reference for downloads: the CLI, or (until it generates) the native bindings.
const cli = path.join(BUILD, 'quiltc');
const cliReady = fs.existsSync(cli) && spawnSync(cli, ['generate', '--help']).status === 0;
const native = path.join(BUILD, 'tests/qcw_native');
function reference(args, out) {
  const [prog, pre] = cliReady ? [cli, ['generate']] : [native, []];
  const r = spawnSync(prog, [...pre, ...args, '-o', out], { encoding: 'utf8', timeout: 60000 });
  assert(r.status === 0, `${path.basename(prog)} ${args.join(' ')} failed (${r.error?.message || `exit ${r.status}`}): ${r.stderr}`);
  return fs.readFileSync(out);
}

const shot = (page, name) => page.screenshot({ path: path.join(SHOTS, `${name}.png`) });
const attr = (page, sel, name) => page.evaluate(([s, n]) => document.querySelector(s)?.getAttribute(n), [sel, name]);
const stat = (page, key) => page.textContent(`[data-stat="${key}"]`);

async function download(page, format) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click(`#downloads [data-format=${format}]`)]);
  const file = path.join(tmp, `page.${format}`);
  await dl.saveAs(file);
  return { name: dl.suggestedFilename(), bytes: fs.readFileSync(file) };
}

// Sets a control and waits for the redraw it causes.
async function change(page, fn) {
  const g = await generation(page);
  await fn();
  return waitDrawn(page, g);
}

const server = await serve(WEB);
const context = await launch();
const page = context.pages()[0] || (await context.newPage());
const consoleErrors = [];
page.on('pageerror', (e) => consoleErrors.push(`pageerror: ${e.message}`));
page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
let loaded = false;

await report.run('first_load_under_500KB', async () => {
  await page.goto(server.url);
  await waitDrawn(page, 0, 60000);
  loaded = true;
  const total = server.sent.reduce((s, r) => s + r.bytes, 0);
  const files = server.sent.map((r) => `${r.url} ${r.bytes}`).join(', ');
  console.log(`# first load: ${total} bytes in ${server.sent.length} requests (${files})`);
  fs.writeFileSync(path.join(SHOTS, 'first-load.json'), JSON.stringify({ total, requests: server.sent }, null, 1));
  assert(server.sent.some((r) => r.url.endsWith('.wasm')), 'the module was not fetched');
  assert(server.sent.every((r) => r.status === 200), `a request failed: ${files}`);
  assert(total < FIRST_LOAD_LIMIT, `first load transferred ${total} bytes (limit ${FIRST_LOAD_LIMIT})`);
});
if (!loaded) {
  await context.close();
  server.close();
  report.finish();
  process.exit();
}

await report.run('default_preview_drawn', async () => {
  const n = Number(await attr(page, '#preview', 'data-points'));
  assert(n > 100, `only ${n} points drawn`);
  assert((await attr(page, '#stitchPath', 'd')).length > 1000, 'empty stitch path');
  assert((await attr(page, '#regionPath', 'd')).startsWith('M'), 'no region outline');
  assert(Number(await stat(page, 'points')) > 50, 'no point count');
  assert(/ms$/.test(await stat(page, 'generation')), 'no generation time');
  assert(/yd$/.test(await stat(page, 'thread')), 'no thread estimate');
  const ruler = await page.$$eval('.ruler text', (t) => t.map((x) => x.textContent));
  assert(ruler.includes('8') && ruler.includes('in'), `ruler labels ${ruler.join(' ')}`);
  // empty controls show the library's resolved defaults, in inches
  assert(await attr(page, '[data-param=spacing]', 'placeholder') === '0.5', 'spacing default');
  assert(await attr(page, '[data-param=margin]', 'placeholder') === '0.15', 'margin default (0.3 d)');
  const points = await page.$eval('[data-param=points] option', (o) => o.textContent);
  assert(points === 'default (random, even)', `points default: ${points}`);
  await shot(page, '01-default');
});

await report.run('family_change_redraws', async () => {
  const before = await attr(page, '#stitchPath', 'd');
  await change(page, () => page.selectOption('#family', 'vine'));
  const after = await attr(page, '#stitchPath', 'd');
  assert(after !== before && after.length > 500, 'the preview did not change');
  assert(await page.isHidden('#motifBox'), 'vine shows the motif picker');
  assert(await page.$('[data-param=width]') === null, 'vine shows the fill width');
  await change(page, () => page.selectOption('#family', 'packing'));
  assert(await page.isVisible('#motifBox'), 'packing lacks the motif picker');
  await change(page, () => page.selectOption('#family', 'fill'));
  assert(await page.$('[data-param=width]') !== null, 'fill lacks its width control');
  await shot(page, '02-fill');
});

await report.run('parameter_change_redraws', async () => {
  const before = Number(await stat(page, 'points'));
  await change(page, () => page.fill('[data-param=spacing]', '0.3'));
  const after = Number(await stat(page, 'points'));
  assert(after > before * 1.5, `spacing 0.3 in: ${before} -> ${after} points`);
  await change(page, () => page.selectOption('[data-param=points]', 'hex'));
  await change(page, () => page.fill('#seed', '12345678901234567890'));
  assert(await page.isHidden('#error'), `error: ${await page.textContent('#error')}`);
});

await report.run('out_of_range_shows_message', async () => {
  const d = await attr(page, '#stitchPath', 'd');
  let e = await errorCount(page);
  await page.fill('[data-param=spacing]', '0.001');
  const msg = await waitError(page, e);
  assert(/spacing/.test(msg) && /range/.test(msg), `message: ${msg}`);
  assert(await attr(page, '#stitchPath', 'd') === d, 'the last preview was not kept');
  await shot(page, '03-out-of-range');
  await change(page, () => page.fill('[data-param=spacing]', '0.3'));
  assert(await page.isHidden('#error'), 'the message stayed after a good value');
  e = await errorCount(page);
  await page.fill('#shapeW', '0');
  const msg1 = await waitError(page, e);
  assert(/rect:0x8/.test(msg1) && /size/.test(msg1), `zero width message: ${msg1}`);
  await change(page, () => page.fill('#shapeW', '8'));
  e = await errorCount(page);
  await page.fill('#seed', 'abc');
  const msg2 = await waitError(page, e);
  assert(/seed/.test(msg2), `bad seed message: ${msg2}`);
  await change(page, () => page.fill('#seed', '5'));
  assert(await page.isHidden('#error'), 'the message stayed after a good value');
});

await report.run('units_mm', async () => {
  await change(page, () => page.selectOption('#units', 'mm'));
  assert(await page.inputValue('#shapeW') === '203.2', `width ${await page.inputValue('#shapeW')}`);
  assert(await page.inputValue('[data-param=spacing]') === '7.62', `spacing ${await page.inputValue('[data-param=spacing]')}`);
  const ruler = await page.$$eval('.ruler text', (t) => t.map((x) => x.textContent));
  assert(ruler.includes('mm') && ruler.includes('200'), `ruler labels ${ruler.join(' ')}`);
  await change(page, () => page.selectOption('#units', 'in'));
});

await report.run('motifs_from_library', async () => {
  await change(page, () => page.selectOption('#family', 'branching'));
  await page.fill('[data-param=spacing]', '');
  await page.fill('#seed', '1');
  await change(page, () => page.check('#motifList input[value=heart]'));
  assert(await page.isVisible('#motifBox'), 'no motif picker for branching');
  assert(Number(await stat(page, 'motifs placed')) > 0, 'no motif placed');
  assert((await page.textContent('#cli')).includes('--motif heart'), `command: ${await page.textContent('#cli')}`);
  await change(page, () => page.setInputFiles('#motifFile', path.join(FIX, 'tulip.svg')));
  assert((await page.textContent('#cli')).includes('--motif heart,tulip.svg'), `command: ${await page.textContent('#cli')}`);
  await shot(page, '04-branching-motifs');
  await change(page, () => page.uncheck('#motifList input[value=heart]'));
  await change(page, () => page.setInputFiles('#motifFile', []));
  assert(!(await page.textContent('#cli')).includes('--motif'), `command: ${await page.textContent('#cli')}`);
});

// The page's downloads against the CLI run with the command line the page shows.
async function compareDownloads(formats, fixArgs = (a) => a) {
  const line = (await page.textContent('#cli')).trim();
  const words = line.split(' ');
  assert(words[0] === 'quiltc' && words[1] === 'generate' && words.at(-2) === '-o', `command: ${line}`);
  const args = fixArgs(words.slice(2, -2));
  for (const f of formats) {
    const got = await download(page, f);
    const want = reference(args, path.join(tmp, `ref.${f}`));
    assert(got.name.endsWith(`.${f}`), `file name ${got.name}`);
    assert(Buffer.compare(got.bytes, want) === 0, `.${f} differs from ${cliReady ? 'quiltc' : 'qcw_native'} ${args.join(' ')}: ${describeDiff(want, got.bytes)}`);
  }
  return args;
}

await report.run('download_pat_matches_cli', async () => {
  await change(page, () => page.selectOption('#shape', 'heart'));
  await page.fill('#shapeW', '7');
  await page.selectOption('#family', 'stipple');
  await page.selectOption('[data-param=points]', '');
  await page.fill('#tie', '2');
  await page.fill('#seed', '7');
  await change(page, () => page.fill('[data-param=spacing]', '0.4'));
  const args = await compareDownloads(['pat', 'svg', 'qli', 'plt']);
  assert(args.join(' ') === '--region heart:7 --units in --family stipple --spacing 0.4 --seed 7 --tie 2', `args ${args.join(' ')}`);
  if (!cliReady) throw new Skip('compared with the native bindings: quiltc generate does not work yet');
});

let svgReader = true;
await report.run('svg_region_upload', async () => {
  const g = await generation(page);
  await page.setInputFiles('#regionFile', path.join(FIX, 'block-hole.svg'));
  await page.waitForFunction((prev) => document.body.dataset.state === 'error' ||
    Number(document.getElementById('preview').dataset.generation) > prev, g);
  const err = await page.isVisible('#error') ? await page.textContent('#error') : '';
  if (/not (built|supported)|unsupported/i.test(err)) {
    svgReader = false;
    throw new Skip(`the SVG reader is not in the library yet: ${err}`);
  }
  await waitDrawn(page, g);
  assert(await page.inputValue('#shape') === 'svg', 'shape is not svg');
  assert((await attr(page, '#regionPath', 'd')).split('M').length === 3, 'the window (hole) is missing');
  assert((await page.textContent('#regionName')) === 'block-hole.svg', 'file name not shown');
  await compareDownloads(['pat', 'dxf'], (a) => a.map((w) => (w === 'block-hole.svg' ? path.join(FIX, w) : w)));
  await shot(page, '05-svg-region');
});

// What the reader cannot honour is said on the page as the CLI says it.
await report.run('svg_warnings_shown_not_silent', async () => {
  if (!svgReader) throw new Skip('the SVG reader is not in the library yet');
  assert(await page.isHidden('#svgWarnings'), 'warnings shown for an SVG without any');
  const g = await generation(page);
  await page.setInputFiles('#regionFile', path.join(FIX, 'block-with-text.svg'));
  await waitDrawn(page, g);
  const lines = await page.$$eval('#svgWarnings li', (li) => li.map((x) => x.textContent));
  assert(lines.length === 1 && /^warning: svg line 3, <text id="label">: text is not read/.test(lines[0]),
    `warnings: ${JSON.stringify(lines)}`);
  assert(await page.isVisible('#svgWarnings'), 'the warning is not visible');
  const g2 = await generation(page);
  await page.setInputFiles('#regionFile', path.join(FIX, 'block-hole.svg'));
  await waitDrawn(page, g2);
  assert(await page.isHidden('#svgWarnings'), 'the last SVG\'s warnings stayed');
});

await report.run('malformed_svg_shows_message', async () => {
  if (!svgReader) throw new Skip('the SVG reader is not in the library yet');
  const d = await attr(page, '#stitchPath', 'd');
  const e = await errorCount(page);
  await page.setInputFiles('#regionFile', path.join(FIX, 'malformed.svg'));
  const msg = await waitError(page, e);
  assert(/^malformed\.svg: .*line \d+/.test(msg), `message: ${msg}`);
  assert(await attr(page, '#stitchPath', 'd') === d, 'the last preview was not kept');
  const dl = await page.evaluate(() => document.querySelector('#downloads [data-format=pat]') !== null);
  assert(dl, 'downloads gone');
  await shot(page, '06-malformed-svg');
});

await report.run('svg_region_drop', async () => {
  if (!svgReader) throw new Skip('the SVG reader is not in the library yet');
  const text = fs.readFileSync(path.join(FIX, 'block-hole.svg'), 'utf8');
  const g = await generation(page);
  await page.evaluate((svg) => {
    const dt = new DataTransfer();
    dt.items.add(new File([svg], 'dropped.svg', { type: 'image/svg+xml' }));
    document.getElementById('drop').dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, text);
  await waitDrawn(page, g);
  assert(await page.isHidden('#error'), `error after a good drop: ${await page.textContent('#error')}`);
  assert((await page.textContent('#regionName')) === 'dropped.svg', 'dropped file not used');
});

// ---- a pieced top ----
const STAR = path.join(ROOT, 'examples/sawtooth-star.svg');
const patchIndex = (page, id) => page.evaluate((want) => [...document.querySelectorAll('#preview [data-patch]')]
  .findIndex((el) => el.querySelector('title').textContent === want), id);

// A real click at the centroid of a patch's outline, as drawn on screen.
async function clickPatch(page, id) {
  const i = await patchIndex(page, id);
  assert(i >= 0, `no patch ${id} drawn`);
  const at = await page.evaluate((k) => {
    const el = document.querySelector(`#preview [data-patch="${k}"]`);
    el.scrollIntoView({ block: 'center', inline: 'center' }); // a click lands only in the viewport
    const pts = el.getAttribute('d').split('Z')[0].slice(1).split('L').map((xy) => xy.split(' ').map(Number));
    const c = pts.reduce(([x, y], [px, py]) => [x + px / pts.length, y + py / pts.length], [0, 0]);
    const p = new DOMPoint(c[0], c[1]).matrixTransform(el.getScreenCTM());
    return { x: p.x, y: p.y };
  }, i);
  await page.mouse.click(at.x, at.y);
  return i;
}

// A patch's sewn length as the per-patch table shows it.
const patchLength = (page, id) => page.evaluate((want) =>
  document.querySelector(`[data-patch-family="${want}"]`).parentElement.lastElementChild.textContent, id);

let topLoaded = false;
await report.run('top_click_patch_choose_family_sew', async () => {
  if (!svgReader) throw new Skip('the SVG reader is not in the library yet');
  await change(page, () => page.setInputFiles('#regionFile', STAR));
  assert(await page.isVisible('#topBox'), 'no quilt top controls');
  assert(await page.$$eval('#preview [data-patch]', (p) => p.length) === 17, 'not 17 patches drawn');
  assert((await attr(page, '#ditchPath', 'd') || '').length > 50, 'no ditch travel drawn');
  assert(await page.isVisible('#planDownload'), 'no plan.json download');
  topLoaded = true;
  const i = await clickPatch(page, 'point-top-a');
  assert(await page.inputValue('#patchPick') === String(i), `the click picked ${await page.inputValue('#patchPick')}, not ${i}`);
  assert(await attr(page, `#preview [data-patch="${i}"]`, 'class') === 'patch picked', 'the picked patch is not marked');
  assert(await page.inputValue('#patchScope') === 'patch', 'scope');
  await change(page, () => page.selectOption('#patchFamily', 'echo'));
  const echoLength = await patchLength(page, 'point-top-a');
  await change(page, () => page.fill('[data-patch-param=spacing]', '0.3'));
  assert(await patchLength(page, 'point-top-a') !== echoLength, `the patch's spacing changed nothing (${echoLength})`);
  assert(await stat(page, 'pieces') === '1', `pieces ${await stat(page, 'pieces')}`);
  assert(await stat(page, 'jumps') === '0', `jumps ${await stat(page, 'jumps')}`);
  assert(await page.textContent('[data-patch-family="point-top-a"]') === 'echo', 'the patch is not echo');
  assert(await page.textContent('[data-patch-family="point-top-b"]') === 'stipple', 'another star point changed');
  // every patch of the background colour at once
  await clickPatch(page, 'goose-left');
  await page.selectOption('#patchScope', 'colour');
  await change(page, () => page.selectOption('#patchFamily', 'spiral'));
  for (const id of ['goose-left', 'goose-top', 'corner-sw', 'corner-ne']) {
    assert(await page.textContent(`[data-patch-family="${id}"]`) === 'spiral', `${id} is not spiral`);
  }
  assert(await page.textContent('[data-patch-family="centre"]') === 'stipple', 'the centre changed');
  assert(await stat(page, 'pieces') === '1' && await stat(page, 'jumps') === '0', 'not one line');
  await shot(page, '09-top');
});

await report.run('top_downloads_match_cli_with_page_plan', async () => {
  if (!topLoaded) throw new Skip('no top loaded');
  if (!cliReady) throw new Skip('quiltc does not work yet');
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#planDownload')]);
  const planFile = path.join(tmp, 'page-plan.json');
  await dl.saveAs(planFile);
  assert(dl.suggestedFilename() === 'sawtooth-star-plan.json', `plan file name ${dl.suggestedFilename()}`);
  const plan = JSON.parse(fs.readFileSync(planFile, 'utf8'));
  assert(JSON.stringify(plan) === JSON.stringify([
    { match: { id: 'point-top-a' }, family: 'echo', params: { spacing: 0.3 } },
    { match: { fill: '#f5f0e1' }, family: 'spiral' }]), `plan ${JSON.stringify(plan)}`);
  const line = (await page.textContent('#cli')).trim();
  const words = line.split(' ');
  assert(words[0] === 'quiltc' && words[1] === 'quilt' && words.at(-2) === '-o', `command: ${line}`);
  const args = words.slice(2, -2).map((w) => (w === 'sawtooth-star.svg' ? STAR : w === 'sawtooth-star-plan.json' ? planFile : w));
  assert(args.includes(planFile), `the command does not use the plan: ${line}`);
  for (const f of ['pat', 'svg', 'dxf', 'qli']) {
    const got = await download(page, f);
    assert(got.name === `sawtooth-star-quilt.${f}`, `file name ${got.name}`);
    const out = path.join(tmp, `ref-top.${f}`);
    const r = spawnSync(cli, ['quilt', ...args, '-q', '-o', out], { encoding: 'utf8', timeout: 60000 });
    assert(r.status === 0, `quiltc quilt ${args.join(' ')}: ${r.stderr}`);
    const want = fs.readFileSync(out);
    assert(Buffer.compare(got.bytes, want) === 0, `.${f} differs from quiltc quilt ${args.join(' ')}: ${describeDiff(want, got.bytes)}`);
  }
});

// After a failed SVG the worker holds no pattern: a download gives a message, never the last top.
await report.run('no_stale_download_after_failed_svg', async () => {
  if (!topLoaded) throw new Skip('no top loaded');
  let e = await errorCount(page);
  await page.setInputFiles('#regionFile', path.join(FIX, 'malformed.svg'));
  await waitError(page, e);
  const downloads = [];
  page.on('download', (d) => downloads.push(d));
  for (const f of ['pat', 'svg']) {
    e = await errorCount(page);
    await page.click(`#downloads [data-format=${f}]`);
    const msg = await waitError(page, e);
    assert(/nothing to download/.test(msg), `.${f}: ${msg}`);
  }
  assert(downloads.length === 0, `${downloads.length} files downloaded after the failed SVG`);
  page.removeAllListeners('download');
});

// The visible text of every control's label and the name chromium gives it.
async function labelsAndNames(page, cdp) {
  const { root } = await cdp.send('DOM.getDocument', { depth: 0 });
  const { nodeIds } = await cdp.send('DOM.querySelectorAll', { nodeId: root.nodeId, selector: '#controls input, #controls select, #stage input, #stage select' });
  const out = [];
  for (const nodeId of nodeIds) {
    const { object } = await cdp.send('DOM.resolveNode', { nodeId });
    const { result } = await cdp.send('Runtime.callFunctionOn', { objectId: object.objectId, returnByValue: true, functionDeclaration: `function () {
      if (!this.getClientRects().length) return null; // not shown
      const label = this.closest('label');
      if (!label) return { id: this.id || this.outerHTML.slice(0, 60), visible: '' };
      const copy = label.cloneNode(true);
      for (const c of copy.querySelectorAll('input, select, button')) c.remove();
      return { id: this.id || this.dataset.param || this.dataset.patchParam || this.value, visible: copy.textContent.replace(/\\s+/g, ' ').trim() };
    }` });
    if (!result.value) continue;
    const { nodes } = await cdp.send('Accessibility.getPartialAXTree', { nodeId, fetchRelatives: false });
    out.push({ ...result.value, name: nodes[0]?.name?.value ?? '' });
  }
  return out;
}

const JARGON = /\b(mst|tsp|tsp-time|r-seed|tip|or3opt|oropt|2opt)\b/i;
await report.run('labels_quilters_words_and_accessible_names', async () => {
  if (!topLoaded) throw new Skip('no top loaded');
  // a top dropped on the preview, as one chosen with the file button
  const text = fs.readFileSync(STAR, 'utf8');
  await change(page, () => page.evaluate((svg) => {
    const dt = new DataTransfer();
    dt.items.add(new File([svg], 'dropped-star.svg', { type: 'image/svg+xml' }));
    document.getElementById('drop').dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, text));
  assert(await page.textContent('#topName') === 'dropped-star.svg: 17 patches', `top name: ${await page.textContent('#topName')}`);
  assert(await page.$$eval('#preview [data-patch]', (p) => p.length) === 17, 'the dropped top is not drawn as patches');
  await clickPatch(page, 'centre');
  const cdp = await context.newCDPSession(page);
  const checked = new Set();
  for (const fam of await page.$$eval('#family option', (o) => o.map((x) => x.value))) {
    await change(page, () => page.selectOption('#family', fam));
    await page.selectOption('#patchFamily', fam);
    for (const c of await labelsAndNames(page, cdp)) {
      assert(c.visible !== '', `${c.id} has no visible label`);
      assert(c.name === c.visible, `${c.id}: visible label '${c.visible}', accessible name '${c.name}'`);
      checked.add(c.id);
    }
    const shown = await page.evaluate(() => [...document.querySelectorAll('#controls .label-text, #controls option, #controls legend, #stats dt, #patchStats')]
      .filter((el) => el.closest('[hidden]') === null).map((el) => el.textContent).join(' | '));
    const m = JARGON.exec(shown);
    assert(m === null, `'${m && m[0]}' shown with ${fam}`);
  }
  await cdp.detach();
  for (const id of ['skeleton', 'mst', 'tsp', 'tsp-time', 'r-seed', 'tip', 'patchFamily', 'seed', 'tie']) {
    assert(checked.has(id), `the control ${id} was never checked`);
  }
});

// No select narrower than its longest choice (desktop and phone).
async function selectsCutOff(page) {
  return page.evaluate(() => {
    const ctx = document.createElement('canvas').getContext('2d');
    const bad = [];
    for (const s of document.querySelectorAll('select')) {
      if (!s.getClientRects().length || s.closest('[hidden]')) continue;
      const cs = getComputedStyle(s);
      ctx.font = cs.font;
      const widest = Math.max(...[...s.options].map((o) => ctx.measureText(o.textContent).width));
      const room = s.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight) - 12; // the arrow
      if (room < widest) bad.push(`${s.id || s.dataset.param || s.dataset.patchParam}: ${room.toFixed(0)} < ${widest.toFixed(0)} px`);
    }
    return bad;
  });
}

await report.run('selects_not_cut_off', async () => {
  if (!topLoaded) throw new Skip('no top loaded');
  await change(page, () => page.selectOption('#family', 'vine'));
  await page.selectOption('#patchFamily', 'pebbling');
  let bad = await selectsCutOff(page);
  assert(bad.length === 0, `cut off: ${bad.join(', ')}`);
  await page.setViewportSize({ width: 390, height: 844 });
  bad = await selectsCutOff(page);
  await page.setViewportSize({ width: 1200, height: 900 });
  assert(bad.length === 0, `cut off on a phone: ${bad.join(', ')}`);
});

// On a phone the preview and a message stay on screen while controls far below change.
const inView = (page, sel) => page.evaluate((s) => {
  const r = document.querySelector(s).getBoundingClientRect();
  const hit = document.elementFromPoint(r.left + r.width / 2, r.top + Math.min(r.height / 2, 20));
  return r.height > 0 && r.top >= -1 && r.bottom <= window.innerHeight + 1 && !!hit && document.querySelector(s).contains(hit);
}, sel);

await report.run('phone_preview_and_error_stay_in_view', async () => {
  await page.setViewportSize({ width: 390, height: 844 });
  try {
    await page.locator('#tie').scrollIntoViewIfNeeded();
    assert(await page.evaluate(() => window.scrollY) > 400, 'the page did not scroll: the test proves nothing');
    await change(page, () => page.fill('#tie', '1'));
    assert(await inView(page, '#tie'), 'the tie-off field is hidden under the preview');
    assert(await inView(page, '#preview'), 'the preview scrolled out of view');
    const e = await errorCount(page);
    await page.fill('#tie', '500');
    await waitError(page, e);
    assert(await inView(page, '#error'), 'the message is out of view on a phone');
    await change(page, () => page.fill('#tie', '0'));
    // a failed SVG chosen while scrolled far down: its message is on screen too
    await page.locator('#tie').scrollIntoViewIfNeeded();
    const e2 = await errorCount(page);
    await page.setInputFiles('#regionFile', path.join(FIX, 'malformed.svg'));
    const msg = await waitError(page, e2);
    assert(/^malformed\.svg: /.test(msg), `message: ${msg}`);
    assert(await page.evaluate(() => window.scrollY) > 400, 'the page scrolled back up: the test proves nothing');
    assert(await inView(page, '#error'), 'the SVG message is out of view on a phone');
    await shot(page, '10-phone-error');
  } finally {
    await page.setViewportSize({ width: 1200, height: 900 });
  }
});

const THREAD = [0xc1, 0x12, 0x1f];
const SEWN = [0x2a, 0x9d, 0x8f];
const previewPixels = async () => decodePng(await page.locator('#preview').screenshot());

await report.run('sew_animation', async () => {
  await change(page, () => page.selectOption('#shape', 'rect'));
  const before = await previewPixels();
  const red0 = countColour(before, THREAD);
  assert(red0 > 2000, `only ${red0} thread-coloured pixels in the preview`);
  assert(countColour(before, SEWN) < red0 / 50, 'sewn colour before sewing');
  await page.fill('#sewSpeed', '40');
  await page.click('#sewBtn');
  await page.waitForFunction(() => Number(document.getElementById('sewBtn').dataset.progress || 0) > 0.05);
  const p1 = Number(await attr(page, '#sewBtn', 'data-progress'));
  assert((await page.textContent('#sewBtn')) === 'Stop', 'button does not offer to stop');
  assert((await attr(page, '#needle', 'visibility')) === 'visible', 'no needle');
  await shot(page, '07-sewing');
  await page.fill('#sewSpeed', '100');
  await page.waitForFunction(() => document.getElementById('sewBtn').dataset.done === '1', null, { timeout: 30000 });
  assert(p1 < 1, `progress ${p1}`);
  assert(Number(await attr(page, '#sewBtn', 'data-progress')) === 1, 'did not finish');
  assert(Number(await attr(page, '#sewPath', 'stroke-dashoffset')) === 0, 'the sewn path is not whole');
  const after = await previewPixels();
  const red1 = countColour(after, THREAD);
  const green1 = countColour(after, SEWN);
  assert(red1 < red0 / 20, `${red1} of ${red0} thread pixels not covered by the sewn path`);
  assert(green1 > red0, `only ${green1} sewn pixels`);
});

await report.run('phone_screen', async () => {
  await page.setViewportSize({ width: 390, height: 844 });
  await page.waitForTimeout(200);
  const overflow = await page.evaluate(() => document.scrollingElement.scrollWidth - window.innerWidth);
  assert(overflow <= 0, `the page is ${overflow} px wider than the screen`);
  const box = await page.locator('#preview').boundingBox();
  assert(box.width > 300 && box.width <= 390, `preview ${box.width} px wide`);
  await shot(page, '08-phone');
  await page.setViewportSize({ width: 1200, height: 900 });
});

await report.run('python_http_server', async () => {
  const py = spawnSync('python3', ['--version']);
  if (py.status !== 0) throw new Skip('python3 not installed');
  const port = await new Promise((resolve) => {
    const s = net.createServer().listen(0, '127.0.0.1', () => { const p = s.address().port; s.close(() => resolve(p)); });
  });
  const child = spawn('python3', ['-m', 'http.server', String(port), '--bind', '127.0.0.1'], { cwd: WEB, stdio: 'ignore' });
  try {
    const p2 = await context.newPage();
    p2.on('pageerror', (e) => consoleErrors.push(`python server page: ${e.message}`));
    for (let i = 0; ; i++) { // until the server listens
      try {
        await p2.goto(`http://127.0.0.1:${port}/`);
        break;
      } catch (err) {
        if (i > 50) throw err;
        await p2.waitForTimeout(100);
      }
    }
    await waitDrawn(p2, 0, 60000);
    assert(Number(await p2.evaluate(() => document.getElementById('preview').dataset.points)) > 100, 'no preview');
    await p2.close();
  } finally {
    child.kill();
  }
});

await report.run('no_console_errors', async () => {
  assert(consoleErrors.length === 0, consoleErrors.join(' | '));
});

await context.close();
server.close();
fs.rmSync(tmp, { recursive: true, force: true });
report.finish();
