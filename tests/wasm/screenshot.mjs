// The README's picture of the page: node tests/wasm/screenshot.mjs [docs/preview.png]
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
await set(() => page.selectOption('#shape', 'heart'));
await set(() => page.fill('#shapeW', '10'));
await set(() => page.selectOption('#family', 'branching'));
await set(() => page.fill('[data-param=spacing]', '0.7'));
await set(() => page.check('#motifList input[value=leaf]'));
await set(() => page.fill('#seed', '3'));
await page.fill('#sewSpeed', '62');
await page.click('#sewBtn');
await page.waitForFunction(() => Number(document.getElementById('sewBtn').dataset.progress || 0) > 0.55);
await page.click('#sewBtn'); // stop part-way: the sewn part shows over the path
await page.screenshot({ path: out });
console.log(`wrote ${out} (generation ${await generation(page)})`);
await context.close();
server.close();
