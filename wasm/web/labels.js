// What the page calls the library's parameters and choices: quilters' words
// instead of the table's names (mst, tsp, r-seed, ...), which stay the values
// sent to the library and shown in the command line.
export const PARAM_LABELS = {
  points: 'Point layout',
  skeleton: 'Path through the points',
  mst: 'Tree links',
  tsp: 'Loop smoothing',
  edge: 'Pebbles at the edge',
  tile: 'Repeat as a tile',
  tip: 'Branch ends',
  spiral: 'Spiral kind',
  'echo-join': 'Echo lines joined as',
  spacing: 'Spacing',
  margin: 'Margin from the edge',
  size: 'Motif size',
  gap: 'Gap between motifs',
  angle: 'Motif angle',
  tangent: 'Curve roundness',
  'r-seed': 'First pebble size (× spacing)',
  width: 'Fill width',
  'tsp-time': 'Extra smoothing time',
  'repeat-cols': 'Tiles across',
  'repeat-rows': 'Tiles down',
  'start-x': 'Start near x',
  'start-y': 'Start near y',
  wiggle: 'Wiggle',
  'turn-radius': 'Tightest turn',
  iterations: 'Meander rounds',
  offset: 'Row offset (× tile width)',
};

export const CHOICE_LABELS = {
  points: { triangle: 'triangle grid', square: 'square grid', hex: 'hexagon grid', snub: 'snub grid', poisson: 'random, even' },
  skeleton: { mst: 'branching tree', tsp: 'one closed loop' },
  mst: { delaunay: 'nearby points', complete: 'every pair' },
  tsp: { greedy: 'quick', '2opt': 'untangled', oropt: 'refined', or3opt: 'most refined' },
  edge: { strict: 'kept inside', overgrow: 'trimmed at the edge' },
  tile: { none: 'no', 'edge-to-edge': 'edge to edge', 'all-over': 'all over' },
  tip: { none: 'plain', circle: 'small circles' },
  spiral: { archimedean: 'evenly spaced', fermat: 'sunflower (Fermat)' },
  'echo-join': { spiral: 'one spiral', rings: 'linked rings' },
};

export const paramLabel = (row) => PARAM_LABELS[row.name] || row.name.replace(/-/g, ' ');
export const choiceLabel = (name, choice) => CHOICE_LABELS[name]?.[choice] || choice;

// The unit shown after a label: lengths in the page's units.
export function unitLabel(row, units) {
  if (row.type === 'length') return units;
  if (row.unit === 'deg') return '°';
  return row.unit === 'count' || row.unit === 'ratio' ? '' : row.unit;
}
