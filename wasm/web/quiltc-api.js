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

  // What the last SVG read could not honour (a clip, text, ...): one line each.
  svgWarnings() {
    return this.json(this.m._qcw_svg_warnings_json(this.job));
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
    const rows = new Map(this.params().map((r) => [r.name, r]));
    this.m._qcw_params_reset(this.job, (settings.units || 'in') === 'in' ? 1 : 0);
    for (const [name, value] of Object.entries(settings.params || {})) {
      const row = rows.get(name);
      if (!row) throw new Error(`unknown parameter '${name}'`);
      if (row.type === 'seed') { this.seed(value); continue; }
      const v = paramValue(row, name, value, settings.units);
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
      const t = typeof value === 'string' ? value.trim() : value;
      if (typeof t === 'string' && !/^\d+$/.test(t)) throw new Error('not decimal'); // BigInt takes 0x10
      s = BigInt(t);
    } catch {
      throw new Error(`seed: '${value}' is not a whole number from 0 to 2^64-1`);
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

  // The whole composition for one settings object (what the worker does):
  // a block (settings.region), or a quilt top (settings.top, see quilt()).
  generate(settings) {
    if (settings.top) return this.quilt(settings);
    this.region(settings);
    this.setParams(settings);
    return this.run(settings.tie || 0);
  }

  // ---- quilt tops: quiltc quilt TOP.svg --plan PLAN.json ----
  // Reads the top's patches: [{ id, class, label, fill, element, line, rings }]
  // (rings in mm, the top's lower-left corner at the origin). Errors name the file.
  topSvg(text, name, units = 'in') {
    try {
      this.withString(units, (pu) => this.withString(text, (p, n) =>
        this.check(this.m._qcw_top_svg(this.job, p, n, unitScale(units), pu))));
    } catch (err) {
      throw new Error(`${name || 'quilt top'}: ${err.message}`);
    }
    return this.json(this.m._qcw_patches_json(this.job));
  }

  // plan: the rules of a quiltc plan file, [{ match: { id, class, label, fill },
  // family, params }] in order (the first that fits a patch chooses; params in
  // the settings' units, family "none" leaves the patches unquilted).
  setPlan(plan, units) {
    this.m._qcw_rules_clear(this.job);
    const rows = new Map(this.params().map((r) => [r.name, r]));
    plan.forEach((rule, i) => {
      const where = `plan: rules[${i}]`;
      const m = rule.match || {};
      for (const k of Object.keys(m)) {
        if (!['id', 'class', 'label', 'fill'].includes(k)) throw new Error(`${where}.match.${k}: unknown key`);
      }
      this.withString(m.id || '', (a) => this.withString(m.class || '', (b) => this.withString(m.label || '', (c) =>
        this.withString(m.fill || '', (d) => this.check(this.m._qcw_rule_add(this.job, a, b, c, d))))));
      if (rule.family === 'none') { this.check(this.m._qcw_rule_none(this.job)); return; }
      const params = { ...(rule.params || {}) };
      if (rule.family) params.family = rule.family;
      for (const [name, value] of Object.entries(params)) {
        const v = paramValue(rows.get(name), name, value, units);
        try {
          this.withString(name, (p) => this.check(this.m._qcw_rule_param(this.job, p, v)));
        } catch (err) {
          throw new Error(`${where}: ${err.message}`);
        }
      }
    });
  }

  // settings: { top: { svg, name }, plan: [...], units, params, seed, motifs, tie, join }
  // -> { xy, flags, stats (quiltc quilt --stats' figures), patches, ditch }.
  quilt(settings) {
    const patches = this.topSvg(settings.top.svg, settings.top.name, settings.units || 'in');
    this.setParams(settings);
    this.setPlan(settings.plan || [], settings.units);
    this.check(this.m._qcw_quilt(this.job, settings.join === 'jump' ? 1 : 0, settings.tie || 0));
    const n = this.m._qcw_points(this.job);
    const xy = new Float64Array(this.m.HEAPF64.buffer, this.m._qcw_xy(this.job), n * 2).slice();
    const flags = new Uint8Array(this.m.HEAPU8.buffer, this.m._qcw_flags(this.job), n).slice();
    const stats = this.json(this.m._qcw_quilt_stats_json(this.job));
    const ditch = this.json(this.m._qcw_ditch_json(this.job));
    return { xy, flags, stats, patches, ditch };
  }

  // The last result encoded as format ('pat', 'svg', ...): a Uint8Array.
  export(format) {
    this.withString(format, (p) => this.check(this.m._qcw_export(this.job, p)));
    const n = this.m._qcw_export_size(this.job);
    return new Uint8Array(this.m.HEAPU8.buffer, this.m._qcw_export_data(this.job), n).slice();
  }

  free() { this.m._qcw_free(this.job); this.job = 0; }
}

// A parameter's value as qcw_param takes it: lengths in mm (a bare number in
// units, or with its own mm, cm or in), enums as 1-based choices.
function paramValue(row, name, value, units) {
  if (!row || row.type === 'seed') throw new Error(`unknown parameter '${name}'`);
  if (row.type === 'enum') {
    const v = row.choices.split('|').indexOf(String(value)) + 1;
    if (v === 0) throw new Error(`${name}: unknown choice '${value}' (one of ${row.choices})`);
    return v;
  }
  let scale = row.type === 'length' ? unitScale(units) : 1;
  let text = value;
  const suffix = row.type === 'length' && typeof value === 'string' && /(mm|cm|in)\s*$/.exec(value);
  if (suffix) { // like the CLI: a length may carry its own unit
    scale = MM_PER_UNIT[suffix[1]];
    text = value.slice(0, suffix.index);
  }
  const v = typeof text === 'number' ? text : strictNumber(text);
  if (!Number.isFinite(v)) throw new Error(`${name}: '${value}' is not a ${row.type === 'length' ? 'length (a number, optionally with mm, cm or in)' : 'number'}`);
  return v * scale;
}

function unitScale(units) {
  const mm = MM_PER_UNIT[units || 'in'];
  if (mm === undefined) throw new Error(`unknown unit '${units}' (in, mm or cm)`);
  return mm;
}

// The whole string as a finite number, like the CLI's strict parser: plain
// decimals only (Number() also takes 0x10, 0b11, 0o17, which the CLI refuses).
function strictNumber(s) {
  const t = String(s).trim();
  return /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(t) ? Number(t) : NaN;
}
