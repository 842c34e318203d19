// Unity-style reporting for the Node tests, read by tests/run_tests.sh:
// one "file:line:name:PASS|FAIL: why|IGNORE: why" line per case and the
// summary "N Tests M Failures K Ignored" last.
export class Report {
  constructor(file) {
    this.file = file;
    this.n = 0;
    this.failed = 0;
    this.ignored = 0;
  }

  pass(name) { this.n++; console.log(`${this.file}:${this.n}:${name}:PASS`); }

  fail(name, why) {
    this.n++;
    this.failed++;
    console.log(`${this.file}:${this.n}:${name}:FAIL: ${String(why).replace(/\s+/g, ' ').slice(0, 400)}`);
  }

  ignore(name, why) {
    this.n++;
    this.ignored++;
    console.log(`${this.file}:${this.n}:${name}:IGNORE: ${why}`);
  }

  // Runs fn; a thrown Skip ignores the case, any other throw fails it.
  async run(name, fn) {
    try {
      await fn();
      this.pass(name);
    } catch (err) {
      if (err instanceof Skip) this.ignore(name, err.message);
      else this.fail(name, err && err.stack && process.env.QC_VERBOSE ? err.stack : err.message || err);
    }
  }

  finish() {
    console.log(`\n-----------------------\n${this.n} Tests ${this.failed} Failures ${this.ignored} Ignored`);
    console.log(this.failed ? 'FAIL' : 'OK');
    process.exitCode = this.failed ? 1 : 0;
  }
}

export class Skip extends Error {}

export function assert(cond, why) {
  if (!cond) throw new Error(why);
}

// First differing byte of two buffers, for messages.
export function firstDiff(a, b) {
  const n = Math.min(a.length, b.length);
  for (let i = 0; i < n; i++) if (a[i] !== b[i]) return i;
  return a.length === b.length ? -1 : n;
}

export function describeDiff(a, b) {
  const i = firstDiff(a, b);
  if (i < 0) return 'identical';
  const show = (x) => JSON.stringify(Buffer.from(x.subarray(Math.max(0, i - 20), i + 20)).toString('latin1'));
  return `${a.length} vs ${b.length} bytes, first difference at byte ${i}: ${show(a)} vs ${show(b)}`;
}
