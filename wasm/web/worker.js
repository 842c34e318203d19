// Generation off the page's thread, so the page never freezes while the core
// works. Messages: { type: 'generate', id, units, region, params, seed,
// motifs, tie } -> { type: 'result', id, rings, resolved, xy, flags, stats, ms };
// { type: 'export', id, format } -> { type: 'export', id, format, bytes };
// any failure -> { type: 'error', id, message }.
import createQuiltc from './quiltc.mjs';
import { Quiltc } from './quiltc-api.js';

let api = null;
const ready = createQuiltc().then(
  (m) => {
    api = new Quiltc(m);
    postMessage({ type: 'ready', version: api.version(), params: api.params(), families: api.families(),
      motifs: api.motifNames() });
  },
  (err) => postMessage({ type: 'fatal', message: `the WebAssembly module did not load: ${err.message || err}` }),
);

onmessage = async (e) => {
  await ready;
  const msg = e.data;
  try {
    if (!api) throw new Error('the WebAssembly module did not load');
    if (msg.type === 'generate') {
      const t0 = performance.now();
      const out = api.generate(msg);
      const ms = performance.now() - t0;
      postMessage({ type: 'result', id: msg.id, rings: api.regionRings(), resolved: api.resolved(), ...out, ms },
        [out.xy.buffer, out.flags.buffer]);
    } else if (msg.type === 'export') {
      const bytes = api.export(msg.format);
      postMessage({ type: 'export', id: msg.id, format: msg.format, bytes }, [bytes.buffer]);
    }
  } catch (err) {
    postMessage({ type: 'error', id: msg.id, message: err.message || String(err) });
  }
};
