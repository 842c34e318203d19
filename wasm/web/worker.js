// Generation off the page's thread, so the page never freezes while the core
// works. Messages: { type: 'generate', id, units, region, params, seed,
// motifs, tie } -> { type: 'result', id, rings, resolved, warnings, xy, flags, stats, ms }
// (warnings: what the SVG reader could not honour, one line each);
// a quilt top (msg.top, msg.plan) also gives patches and ditch;
// { type: 'export', id, format } -> { type: 'export', id, format, bytes }
// (refused after a failed generate: never the previous pattern);
// { type: 'probe', id, svg, name } -> { type: 'probe', id, patches } (the
// patches the SVG holds as a top, [] if the patch reader refuses it);
// any failure -> { type: 'error', id, message }.
import createQuiltc from './quiltc.mjs';
import { Quiltc } from './quiltc-api.js';

let api = null;
let current = false; // the module holds the result of the last generate
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
      current = false;
      const t0 = performance.now();
      const out = api.generate(msg);
      const ms = performance.now() - t0;
      postMessage({ type: 'result', id: msg.id, rings: api.regionRings(), resolved: api.resolved(),
        warnings: api.svgWarnings(), ...out, ms },
        [out.xy.buffer, out.flags.buffer]);
      current = true;
    } else if (msg.type === 'probe') {
      current = false;
      let patches = [];
      try { patches = api.topSvg(msg.svg, msg.name); } catch { patches = []; }
      postMessage({ type: 'probe', id: msg.id, patches });
    } else if (msg.type === 'export') {
      if (!current) throw new Error('nothing to download: the last settings gave no pattern');
      const bytes = api.export(msg.format);
      postMessage({ type: 'export', id: msg.id, format: msg.format, bytes }, [bytes.buffer]);
    }
  } catch (err) {
    postMessage({ type: 'error', id: msg.id, message: err.message || String(err) });
  }
};
