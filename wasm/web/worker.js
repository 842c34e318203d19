// Generation off the page's thread: the page never freezes while the core works.
import createQuiltc from './quiltc.mjs';
import { Quiltc } from './quiltc-api.js';

let api = null;
let table = null;
const ready = createQuiltc().then((m) => {
  api = new Quiltc(m);
  table = api.params();
  postMessage({ type: 'ready', version: api.version(), params: table });
});

onmessage = async (e) => {
  await ready;
  const msg = e.data;
  try {
    if (msg.type === 'generate') {
      const t0 = performance.now();
      if (msg.region.svg !== undefined) api.regionSvg(msg.region.svg);
      else api.regionShape(msg.region.shape, msg.units === 'mm' ? 1 : 25.4);
      api.setParams(msg, table);
      if (msg.motifSvg) api.motifSvg(msg.motifSvg.text, msg.motifSvg.name);
      const out = api.run(msg.tie || 0);
      const ms = performance.now() - t0;
      postMessage({ type: 'result', id: msg.id, rings: api.regionRings(), ...out, ms },
        [out.xy.buffer, out.flags.buffer]);
    } else if (msg.type === 'export') {
      const bytes = api.export(msg.format);
      postMessage({ type: 'export', id: msg.id, format: msg.format, bytes }, [bytes.buffer]);
    }
  } catch (err) {
    postMessage({ type: 'error', id: msg.id, message: err.message });
  }
};
