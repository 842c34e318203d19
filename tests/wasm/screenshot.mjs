// The README's picture of the page: node tests/wasm/screenshot.mjs [docs/preview.png]
// and of a quilt top on it: node tests/wasm/screenshot.mjs docs/top-page.png top
// (BUILD=build by default; needs `make wasm`, chromium and playwright-core).
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, launch, waitDrawn, generation } from './browser.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const BUILD = path.resolve(ROOT, process.env.BUILD || 'build');
const out = path.resolve(ROOT, process.argv[2] || 'docs/preview.png');

const server = await serve(path.join(BUILD, 'web'));
const context = await launch({ viewport: { width: 1280, height: 860 } });
const page = context.pages()[0] || (await context.newPage());
await page.goto(server.url);
let g = await waitDrawn(page, 0, 60000);
async function set(fn) {
  await fn();
  g = await waitDrawn(page, g, 60000);
}
if (process.argv[3] === 'top') {
  // the sawtooth star: echo in the star points, pebbles in the centre, spirals in the background
  await set(() => page.setInputFiles('#regionFile', path.join(ROOT, 'examples/sawtooth-star.svg')));
  const pick = async (id, scope, family) => {
    const i = await page.evaluate((want) => [...document.querySelectorAll('#preview [data-patch]')]
      .findIndex((el) => el.querySelector('title').textContent === want), id);
    await page.selectOption('#patchPick', String(i));
    await page.selectOption('#patchScope', scope);
    await set(() => page.selectOption('#patchFamily', family));
  };
  await pick('point-top-a', 'colour', 'echo');
  await pick('centre', 'patch', 'pebbling');
  await pick('goose-top', 'colour', 'spiral');
} else {
  await set(() => page.selectOption('#shape', 'heart'));
  await set(() => page.fill('#shapeW', '10'));
  await set(() => page.selectOption('#family', 'branching'));
  await set(() => page.fill('[data-param=spacing]', '0.7'));
  await set(() => page.check('#motifList input[value=leaf]'));
  await set(() => page.fill('#seed', '3'));
}
if (process.argv[3] !== 'top') {
  await page.fill('#sewSpeed', '62');
  await page.click('#sewBtn');
  await page.waitForFunction(() => Number(document.getElementById('sewBtn').dataset.progress || 0) > 0.55);
  await page.click('#sewBtn'); // stop part-way: the sewn part shows over the path
}
await page.evaluate(() => window.scrollTo(0, 0)); // checking a motif scrolls the controls
await page.screenshot({ path: out });
console.log(`wrote ${out} (generation ${await generation(page)})`);
await context.close();
server.close();
