// Shared by the browser tests and the benchmark: a tiny static server over
// build/web that counts the bytes it sends, and Debian's chromium driven by
// playwright-core (never a downloaded browser), with the flags this machine
// needs (no network: without them chromium stalls on its background
// services) and a fresh profile.
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.wasm': 'application/wasm', '.svg': 'image/svg+xml', '.png': 'image/png',
};

export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';

// Serves dir on 127.0.0.1 at a free port. server.sent: [{ url, bytes }] (headers + body).
export function serve(dir) {
  const sent = [];
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://x');
    const file = path.join(dir, decodeURIComponent(url.pathname === '/' ? '/index.html' : url.pathname));
    let body;
    let status = 200;
    if (!file.startsWith(dir) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      status = 404;
      body = Buffer.from('not found');
    } else {
      body = fs.readFileSync(file);
    }
    const headers = {
      'Content-Type': status === 200 ? TYPES[path.extname(file)] || 'application/octet-stream' : 'text/plain',
      'Content-Length': body.length,
      'Cache-Control': 'no-store',
    };
    res.writeHead(status, headers);
    res.end(body);
    const head = `HTTP/1.1 ${status} OK\r\n${Object.entries(headers).map(([k, v]) => `${k}: ${v}\r\n`).join('')}\r\n`;
    sent.push({ url: url.pathname, status, bytes: body.length + Buffer.byteLength(head) });
  });
  return new Promise((resolve) => {
    server.listen(0, '127.0.0.1', () => {
      server.url = `http://127.0.0.1:${server.address().port}/`;
      server.sent = sent;
      resolve(server);
    });
  });
}

// A persistent context in a fresh profile directory; close() removes the profile.
export async function launch(options = {}) {
  const { chromium } = await import('playwright-core');
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'qc-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    acceptDownloads: true,
    viewport: { width: 1200, height: 900 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    timeout: 60000,
    ...options,
  });
  const close = context.close.bind(context);
  context.close = async () => {
    await close();
    fs.rmSync(profile, { recursive: true, force: true });
  };
  return context;
}

// Waits until the page has drawn a generation newer than `after` and is idle.
export async function waitDrawn(page, after, timeout = 15000) {
  await page.waitForFunction((prev) => {
    const g = Number(document.getElementById('preview').dataset.generation || 0);
    return g > prev && document.body.dataset.state === 'ready';
  }, after, { timeout });
  await page.waitForTimeout(120); // a debounced follow-up, if any, starts within 50 ms
  await page.waitForFunction(() => document.body.dataset.state !== 'busy', null, { timeout });
  return generation(page);
}

export async function generation(page) {
  return page.evaluate(() => Number(document.getElementById('preview').dataset.generation || 0));
}

// The number of messages shown so far; waitError(page, count) waits for a newer one.
export async function errorCount(page) {
  return page.evaluate(() => Number(document.getElementById('error').dataset.count || 0));
}

export async function waitError(page, after, timeout = 15000) {
  await page.waitForFunction((prev) => {
    const e = document.getElementById('error');
    return !e.hidden && Number(e.dataset.count || 0) > prev;
  }, after, { timeout });
  return page.textContent('#error');
}
