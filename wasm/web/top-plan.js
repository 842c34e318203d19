// The page's plan for a quilt top, as quiltc quilt's plan file has it: ordered
// rules, the first that fits a patch chooses its pattern. The page keeps one
// rule per patch (by id) ahead of one rule per colour (by fill), and sends
// and downloads only the rules that choose for some patch (the library
// refuses a rule fitting no patch).

// qc_glob: '*' matches any run of characters.
export function glob(pattern, s) {
  const re = new RegExp(`^${pattern.split('*').map((p) => p.replace(/[.+?^${}()|[\]\\]/g, '\\$&')).join('.*')}$`, 's');
  return re.test(s);
}

// A colour as #rrggbb: #rgb, #rrggbb or rgb(r, g, b) (the page writes the
// library's #rrggbb; colour names are left as given).
export function colour(c) {
  const t = String(c).trim().toLowerCase();
  if (/^#[0-9a-f]{3}$/.test(t)) return `#${[...t.slice(1)].map((d) => d + d).join('')}`;
  const rgb = /^rgb\(\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*\)$/.exec(t);
  if (rgb) return `#${rgb.slice(1).map((v) => Math.min(255, Number(v)).toString(16).padStart(2, '0')).join('')}`;
  return t;
}

// qc_patch_matches: id, label by glob; class against any word of the patch's class; fill equal.
export function matches(m, p) {
  if (m.id !== undefined && !glob(m.id, p.id || '')) return false;
  if (m.label !== undefined && !glob(m.label, p.label || '')) return false;
  if (m.class !== undefined && !(p.class || '').split(/[ \t\n]+/).some((c) => c !== '' && glob(m.class, c))) return false;
  if (m.fill !== undefined && (!p.fill || colour(p.fill) !== colour(m.fill))) return false;
  return true;
}

// A plan value as the plan file writes it: plain numbers as numbers, the rest as typed.
const planValue = (v) => (/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(v) ? Number(v) : v);

export class TopPlan {
  constructor() { this.rules = []; } // { kind: 'patch' | 'colour', key, family, params }

  clear() { this.rules = []; }

  get(kind, key) { return this.rules.find((r) => r.kind === kind && r.key === key); }

  // Sets (or, with no family and no parameters, removes) the rule of a patch
  // id or a colour; a colour's rule replaces its patches' own rules.
  set(kind, key, family, params, patches) {
    this.rules = this.rules.filter((r) => !(r.kind === kind && r.key === key));
    if (kind === 'colour') {
      const ids = new Set(patches.filter((p) => (p.fill || '') === key).map((p) => p.id));
      this.rules = this.rules.filter((r) => !(r.kind === 'patch' && ids.has(r.key)));
    }
    if (family || Object.keys(params).length) this.rules.push({ kind, key, family, params: { ...params } });
  }

  // Lengths typed in one unit, rewritten in another (factor: new per old).
  rescale(lengthNames, factor, fmt) {
    for (const r of this.rules) {
      for (const [k, v] of Object.entries(r.params)) {
        if (lengthNames.has(k) && planValue(v) !== v) r.params[k] = fmt(Number(v) * factor);
      }
    }
  }

  // The rules as quiltc's plan file (and Quiltc.setPlan) takes them: patch
  // rules first, then colours; only those choosing for some patch.
  toPlan(patches) {
    const ordered = [...this.rules.filter((r) => r.kind === 'patch'), ...this.rules.filter((r) => r.kind === 'colour')]
      .map((r) => {
        const rule = { match: r.kind === 'patch' ? { id: r.key } : { fill: r.key } };
        if (r.family) rule.family = r.family;
        if (r.family !== 'none' && Object.keys(r.params).length) {
          rule.params = Object.fromEntries(Object.entries(r.params).map(([k, v]) => [k, planValue(v)]));
        }
        return rule;
      });
    const used = new Set();
    for (const p of patches) {
      const k = ordered.findIndex((rule) => matches(rule.match, p));
      if (k >= 0) used.add(k);
    }
    return ordered.filter((_, k) => used.has(k));
  }
}
