// Benchmark (not a test): how long a 10,000-point preview takes to
// regenerate in headless chromium, from the control change to the drawn
// preview (worker generation + transfer + drawing), per family; and the
// first-load transfer. Prints a table and writes build/web-shots/bench.json.
//   node tests/wasm/bench.mjs [runs]        (BUILD=build by default)
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, launch, waitDrawn, generation } from './browser.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const BUILD = path.resolve(ROOT, process.env.BUILD || 'build');
const OUT = path.join(BUILD, 'web-shots');
const RUNS = Number(process.argv[2] || 7);
const FAMILIES = (process.env.FAMILIES || 'stipple,vine,fill,branching,wanderer,pebbling').split(',');
// 8 in x 8 in at 1.6 mm Poisson spacing: about 10,000 points
const SPACING_IN = '0.063';

fs.mkdirSync(OUT, { recursive: true });
const server = await serve(path.join(BUILD, 'web'));
const context = await launch();
const page = context.pages()[0] || (await context.newPage());
await page.goto(server.url);
await waitDrawn(page, 0, 60000);
const firstLoad = server.sent.reduce((s, r) => s + r.bytes, 0);
const wasmBytes = fs.statSync(path.join(BUILD, 'web/quiltc.wasm')).size;

const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
const results = [];
for (const family of FAMILIES) {
  const g = await generation(page);
  await page.selectOption('#family', family);
  await page.fill('[data-param=spacing]', SPACING_IN);
  await waitDrawn(page, g, 120000);
  const runs = [];
  for (let i = 0; i <= RUNS; i++) {
    const r = await page.evaluate(() => new Promise((resolve, reject) => {
      const t0 = performance.now();
      document.addEventListener('quiltc:drawn', (e) => resolve({ ...e.detail, wall: performance.now() - t0 }), { once: true });
      document.addEventListener('quiltc:error', (e) => reject(new Error(e.detail)), { once: true });
      document.getElementById('family').dispatchEvent(new Event('change')); // regenerates at once
    }));
    if (i > 0) runs.push(r); // the first run warms up
  }
  const s = runs[0].stats;
  const row = {
    family,
    points: s.points,
    plan_points: s.plan_points,
    total_ms: median(runs.map((r) => r.wall)),
    total_min_ms: Math.min(...runs.map((r) => r.wall)),
    worker_ms: median(runs.map((r) => r.ms)),
    core_ms: median(runs.map((r) => r.stats.total_ms)),
    draw_ms: median(runs.map((r) => r.drawMs)),
    stages_ms: Object.fromEntries(Object.keys(s.stages_ms).map((k) => [k, median(runs.map((r) => r.stats.stages_ms[k] || 0))])),
  };
  results.push(row);
  console.log(`${family.padEnd(10)} ${String(row.points).padStart(6)} points ${String(row.plan_points).padStart(7)} plan points: ` +
    `regenerate ${row.total_ms.toFixed(0)} ms (best ${row.total_min_ms.toFixed(0)}; core ${row.core_ms.toFixed(0)}, worker ${row.worker_ms.toFixed(0)}, draw ${row.draw_ms.toFixed(0)}) ` +
    `stages ${Object.entries(row.stages_ms).map(([k, v]) => `${k} ${v.toFixed(0)}`).join(', ')}`);
}
console.log(`first load ${firstLoad} bytes; quiltc.wasm ${wasmBytes} bytes; median of ${RUNS} runs`);
fs.writeFileSync(path.join(OUT, 'bench.json'), JSON.stringify({ firstLoad, wasmBytes, runs: RUNS, results }, null, 1));
await context.close();
server.close();
