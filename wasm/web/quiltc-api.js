// A small JS API over the qcw_* exports, shared by the Web Worker and the
// Node tests. Every call checks its status and throws an Error with the
// library's one-line message.
export class Quiltc {
  constructor(module) {
    this.m = module;
    this.job = module._qcw_new();
    if (!this.job) throw new Error('out of memory');
  }

  error() { return this.m.UTF8ToString(this.m._qcw_error(this.job)); }

  check(rc) {
    if (rc < 0) throw new Error(this.error() || `status ${rc}`);
    return rc;
  }

  // Copies a JS string (UTF-8) into the heap for one call.
  withString(s, fn) {
    const n = this.m.lengthBytesUTF8(s) + 1;
    const p = this.m._malloc(n);
    try {
      this.m.stringToUTF8(s, p, n);
      return fn(p, n - 1);
    } finally {
      this.m._free(p);
    }
  }

  version() { return this.m.UTF8ToString(this.m._qcw_version()); }

  params() { return JSON.parse(this.m.UTF8ToString(this.m._qcw_params_json(this.job))); }

  regionShape(spec, mmPerUnit) {
    this.withString(spec, (p) => this.check(this.m._qcw_region_shape(this.job, p, mmPerUnit)));
  }

  regionSvg(text) {
    this.withString(text, (p, n) => this.check(this.m._qcw_region_svg(this.job, p, n)));
  }

  // The region's rings as arrays of [x, y] in mm (fresh heap views: memory may have grown).
  regionRings() {
    const nv = this.m._qcw_region_vertices(this.job);
    const nr = this.m._qcw_region_rings(this.job);
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

  // settings: { units: 'in'|'mm', params: {name: value in user units}, seed, motifs }
  setParams(settings, table) {
    const mm = settings.units === 'mm' ? 1 : settings.units === 'cm' ? 10 : 25.4;
    this.m._qcw_params_reset(this.job, settings.units === 'in' ? 1 : 0);
    const rows = new Map(table.map((r) => [r.name, r]));
    for (const [name, value] of Object.entries(settings.params || {})) {
      const row = rows.get(name);
      if (!row) throw new Error(`unknown parameter '${name}'`);
      let v = value;
      if (row.type === 'enum' && typeof v === 'string') {
        v = row.choices.split('|').indexOf(v) + 1;
        if (v === 0) throw new Error(`invalid --${name} '${value}': choose one of ${row.choices}`);
      } else if (row.type === 'length') {
        v = Number(v) * mm;
      } else {
        v = Number(v);
      }
      if (!Number.isFinite(v)) throw new Error(`invalid --${name} '${value}': not a number`);
      this.withString(name, (p) => this.check(this.m._qcw_param(this.job, p, v)));
    }
    if (settings.seed !== undefined) {
      const s = BigInt(settings.seed);
      this.check(this.m._qcw_seed(this.job, Number(s >> 32n), Number(s & 0xffffffffn)));
    }
    if (settings.motifs) {
      this.withString(settings.motifs, (p) => this.check(this.m._qcw_motifs(this.job, p)));
    }
  }

  motifSvg(text, name) {
    this.withString(name, (pn) =>
      this.withString(text, (p, n) => this.check(this.m._qcw_motif_svg(this.job, p, n, pn))));
  }

  // Generates; returns { xy: Float64Array, flags: Uint8Array, stats }.
  run(tie = 0) {
    this.check(this.m._qcw_run(this.job, tie));
    const n = this.m._qcw_points(this.job);
    const xy = new Float64Array(this.m.HEAPF64.buffer, this.m._qcw_xy(this.job), n * 2).slice();
    const flags = new Uint8Array(this.m.HEAPU8.buffer, this.m._qcw_flags(this.job), n).slice();
    const stats = JSON.parse(this.m.UTF8ToString(this.m._qcw_stats_json(this.job)));
    return { xy, flags, stats };
  }

  // The last result encoded as format ('pat', 'svg', ...): a Uint8Array.
  export(format) {
    this.withString(format, (p) => this.check(this.m._qcw_export(this.job, p)));
    const n = this.m._qcw_export_size(this.job);
    return new Uint8Array(this.m.HEAPU8.buffer, this.m._qcw_export_data(this.job), n).slice();
  }

  free() { this.m._qcw_free(this.job); this.job = 0; }
}
