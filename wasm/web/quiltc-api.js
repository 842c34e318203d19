// A small JS API over the qcw_* exports (wasm/quiltc_wasm.h), shared by the
// page's Web Worker and the Node tests. Every call checks its status and
// throws an Error carrying the library's one-line message. Lengths given to
// setParams are in the settings' units (in, mm or cm) and converted to mm
// exactly as the CLI converts its bare numbers.
export const MM_PER_UNIT = { in: 25.4, mm: 1, cm: 10 };

export class Quiltc {
  constructor(module) {
    this.m = module;
    this.job = module._qcw_new();
    if (!this.job) throw new Error('out of memory');
    this.table = null;
  }

  error() { return this.m.UTF8ToString(this.m._qcw_error(this.job)); }

  check(rc) {
    if (rc < 0) throw new Error(this.error() || `status ${rc}`);
    return rc;
  }

  // Copies a JS string (UTF-8) into the heap for one call: fn(pointer, byte length).
  withString(s, fn) {
    const n = this.m.lengthBytesUTF8(s) + 1;
    const p = this.m._malloc(n);
    if (!p) throw new Error('out of memory');
    try {
      this.m.stringToUTF8(s, p, n);
      return fn(p, n - 1);
    } finally {
      this.m._free(p);
    }
  }

  json(ptr) { return JSON.parse(this.m.UTF8ToString(ptr)); }

  version() { return this.m.UTF8ToString(this.m._qcw_version()); }

  params() {
    if (!this.table) this.table = this.json(this.m._qcw_params_json(this.job));
    return this.table;
  }

  motifNames() { return this.json(this.m._qcw_motifs_json(this.job)); }

  // The library's families (qc_family_info): [{ name, summary, id, points, tree, motifs, defaults }].
  families() { return this.json(this.m._qcw_families_json(this.job)); }

  // The parameters as the library resolves them (defaults filled in): { name: value },
  // lengths in mm, enums by choice name, the seed as a decimal string.
  resolved() {
    const p = this.m._qcw_resolved_json(this.job);
    if (!p) throw new Error(this.error());
    return this.json(p);
  }

  regionShape(spec, mmPerUnit) {
    this.withString(spec, (p) => this.check(this.m._qcw_region_shape(this.job, p, mmPerUnit)));
  }

  regionSvg(text) {
    this.withString(text, (p, n) => this.check(this.m._qcw_region_svg(this.job, p, n)));
  }

  // settings.region: { shape: 'rect:8x8' } in settings.units, or { svg: text, name }.
  // SVG errors name the file, as the CLI's do (the library's shape errors name the shape).
  region(settings) {
    const r = settings.region || { shape: 'rect:8x8' };
    if (r.svg === undefined) {
      this.regionShape(r.shape, unitScale(settings.units));
      return;
    }
    try {
      this.regionSvg(r.svg);
    } catch (err) {
      throw new Error(`${r.name || 'SVG outline'}: ${err.message}`);
    }
  }

  // The region's rings as arrays of [x, y] in mm (views are fresh: memory may have grown).
  regionRings() {
    const nv = this.m._qcw_region_vertices(this.job);
    const nr = this.m._qcw_region_rings(this.job);
    if (!nv) return [];
    const xy = new Float64Array(this.m.HEAPF64.buffer, this.m._qcw_region_xy(this.job), nv * 2).slice();
    const ends = new Uint32Array(this.m.HEAPU32.buffer, this.m._qcw_region_ring_ends(this.job), nr).slice();
    const rings = [];
    let start = 0;
    for (const end of ends) {
      rings.push(Array.from({ length: end - start }, (_, i) => [xy[2 * (start + i)], xy[2 * (start + i) + 1]]));
      start = end;
    }
    return rings;
  }

  // settings: { units: 'in'|'mm'|'cm', params: { name: value }, seed, motifs }
  // params: numbers in the settings' units (lengths) or choice names (enums);
  // seed: a decimal string or number (0 .. 2^64-1); motifs: a comma-separated
  // list of built-in names, or an array of names and { name, svg } objects.
  setParams(settings) {
    const mm = unitScale(settings.units);
    const rows = new Map(this.params().map((r) => [r.name, r]));
    this.m._qcw_params_reset(this.job, (settings.units || 'in') === 'in' ? 1 : 0);
    for (const [name, value] of Object.entries(settings.params || {})) {
      const row = rows.get(name);
      if (!row) throw new Error(`unknown parameter '${name}'`);
      if (row.type === 'seed') { this.seed(value); continue; }
      let v;
      if (row.type === 'enum') {
        v = row.choices.split('|').indexOf(String(value)) + 1;
        if (v === 0) throw new Error(`${name}: unknown choice '${value}' (one of ${row.choices})`);
      } else {
        let scale = row.type === 'length' ? mm : 1;
        let text = value;
        const suffix = row.type === 'length' && typeof value === 'string' && /(mm|cm|in)\s*$/.exec(value);
        if (suffix) { // like the CLI: a length may carry its own unit
          scale = MM_PER_UNIT[suffix[1]];
          text = value.slice(0, suffix.index);
        }
        v = typeof text === 'number' ? text : strictNumber(text);
        if (!Number.isFinite(v)) throw new Error(`${name}: '${value}' is not a ${row.type === 'length' ? 'length' : 'number'}`);
        v *= scale;
      }
      this.withString(name, (p) => this.check(this.m._qcw_param(this.job, p, v)));
    }
    if (settings.seed !== undefined && settings.seed !== '') this.seed(settings.seed);
    let motifs = settings.motifs || [];
    if (typeof motifs === 'string') motifs = motifs.split(',').map((s) => s.trim()).filter(Boolean);
    for (const m of motifs) {
      if (typeof m === 'string') this.withString(m, (p) => this.check(this.m._qcw_motifs(this.job, p)));
      else this.motifSvg(m.svg, m.name);
    }
  }

  seed(value) {
    let s;
    try {
      s = BigInt(typeof value === 'string' ? value.trim() : value);
    } catch {
      throw new Error(`seed: '${value}' is not a whole number`);
    }
    if (s < 0n || s >= 1n << 64n) throw new Error(`seed: '${value}' is not a whole number from 0 to 2^64-1`);
    this.check(this.m._qcw_seed(this.job, Number(s >> 32n), Number(s & 0xffffffffn)));
  }

  motifSvg(text, name) {
    try {
      this.withString(name, (pn) =>
        this.withString(text, (p, n) => this.check(this.m._qcw_motif_svg(this.job, p, n, pn))));
    } catch (err) {
      throw new Error(`motif ${name}: ${err.message}`);
    }
  }

  // Generates; returns { xy: Float64Array (mm, x,y pairs), flags: Uint8Array, stats }.
  run(tie = 0) {
    this.check(this.m._qcw_run(this.job, tie));
    const n = this.m._qcw_points(this.job);
    const xy = new Float64Array(this.m.HEAPF64.buffer, this.m._qcw_xy(this.job), n * 2).slice();
    const flags = new Uint8Array(this.m.HEAPU8.buffer, this.m._qcw_flags(this.job), n).slice();
    const stats = this.json(this.m._qcw_stats_json(this.job));
    return { xy, flags, stats };
  }

  // The whole composition for one settings object (what the worker does).
  generate(settings) {
    this.region(settings);
    this.setParams(settings);
    return this.run(settings.tie || 0);
  }

  // The last result encoded as format ('pat', 'svg', ...): a Uint8Array.
  export(format) {
    this.withString(format, (p) => this.check(this.m._qcw_export(this.job, p)));
    const n = this.m._qcw_export_size(this.job);
    return new Uint8Array(this.m.HEAPU8.buffer, this.m._qcw_export_data(this.job), n).slice();
  }

  free() { this.m._qcw_free(this.job); this.job = 0; }
}

function unitScale(units) {
  const mm = MM_PER_UNIT[units || 'in'];
  if (mm === undefined) throw new Error(`unknown unit '${units}' (in, mm or cm)`);
  return mm;
}

// The whole string as a finite number, like the CLI's strict parser.
function strictNumber(s) {
  const t = String(s).trim();
  return t === '' ? NaN : Number(t);
}
