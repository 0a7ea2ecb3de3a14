// Sections 1-6 and the raw rows of docs/benchmarks.md (bench:report; section 7 is dragging.ts).
// Each section checks its targets through `verdicts`, which collects what was missed.
import type { ReferenceRow } from '../reference_csv.js';
import type { Row } from '../metrics.js';
import { heapGrowthText } from './heap_growth.js';
import { pct, table, us } from './markdown.js';
import { PEER_SAMPLES, type Measurements, type ScaleRow } from './measure.js';
import type { Verdicts } from './verdicts.js';

/** Targets of section 1, the default method in WebAssembly: medians and p99, seconds. */
const RANDOM_MEDIAN_S = 3e-4;
const RANDOM_P99_S = 1e-2;
const INCREMENTAL_MEDIAN_S = 3e-5;
/** Section 2: the least speed-up over the original program. */
const LEAST_SPEED_UP = 100;
/** Section 3: the largest WebAssembly / native time ratio of the solver core. */
const LARGEST_WASM_RATIO = 1.5;

/** `x` to three significant digits, without trailing zeros: 0.3, 30, 99.6. */
const short = (x: number): number => Number(x.toPrecision(3));

/** The A7 rigs' names, in the report's order. */
type A7Names = readonly string[];

/** 1. The default method on every rig, WebAssembly. */
export function defaultSection(m: Measurements, verdicts: Verdicts): string[] {
  const rows = m.defaults
    .filter((r) => r.engine === 'wasm')
    .map((r) => {
      const random = r.experiment === 'random';
      const fast = random
        ? r.t_median_s <= RANDOM_MEDIAN_S && r.t_p99_s <= RANDOM_P99_S
        : r.t_median_s <= INCREMENTAL_MEDIAN_S;
      const why =
        r.success_rate < 1
          ? `success ${pct(r.success_rate)}, not 100%`
          : random
            ? `median ${us(r.t_median_s)} us (at most ${short(RANDOM_MEDIAN_S * 1e6)}), p99 ${us(r.t_p99_s)} us (at most ${short(RANDOM_P99_S * 1e6)})`
            : `median ${us(r.t_median_s)} us, over ${short(INCREMENTAL_MEDIAN_S * 1e6)}`;
      const met = verdicts.mark(r.success_rate === 1 && fast, `1. ${r.rig} ${r.experiment}: ${why}`);
      return [
        r.rig,
        r.experiment,
        pct(r.success_rate),
        us(r.t_median_s),
        us(r.t_p99_s),
        us(r.t_max_s),
        r.iter_avg.toFixed(2),
        r.E_max.toPrecision(3),
        met,
      ];
    });
  return [
    '## 1. The default method: `lm` with restarts',
    '',
    `Targets: success 100% (random and incremental); in WebAssembly, random median <= ${short(RANDOM_MEDIAN_S * 1e3)} ms and p99 <= ${short(RANDOM_P99_S * 1e3)} ms, incremental median <= ${short(INCREMENTAL_MEDIAN_S * 1e6)} us.`,
    '',
    table(['rig', 'experiment', 'success', 'median (us)', 'p99 (us)', 'max (us)', 'iter avg', 'max E', 'met'], rows),
    '',
  ];
}

/** 2. gd, bfgs, gn against the original program's re-measured times (`reference`, from `referenceName`). */
export function originalSection(
  m: Measurements,
  reference: readonly ReferenceRow[],
  referenceName: string,
  verdicts: Verdicts,
): string[] {
  const rows = m.classic.map((r) => {
    const ref = reference.find(
      (x) => x.rig === r.rig && x.experiment === r.experiment && x.method.toLowerCase() === r.method,
    );
    const theirs = m.paper.find(
      (x) => x.rig === r.rig && x.experiment === r.experiment && x.method === r.method && x.engine === r.engine,
    );
    const ratio = ref ? ref.t_avg_s / r.t_avg_s : NaN;
    const why = !ref
      ? `no row in ${referenceName}`
      : !theirs
        ? 'no --paper row'
        : ratio < LEAST_SPEED_UP
          ? `speed-up ${short(ratio)}x, under ${LEAST_SPEED_UP}x`
          : `success ${pct(r.success_rate)}, under the original's ${pct(theirs.success_rate)}`;
    const met = verdicts.mark(
      ratio >= LEAST_SPEED_UP && theirs !== undefined && r.success_rate >= theirs.success_rate,
      `2. ${r.rig} ${r.experiment} ${r.method}: ${why}`,
    );
    return [
      r.rig,
      r.experiment,
      r.method,
      r.t_avg_s.toPrecision(3),
      ref ? ref.t_avg_s.toPrecision(3) : '-',
      `${ratio.toFixed(0)}x`,
      pct(r.success_rate),
      theirs ? pct(theirs.success_rate) : '-',
      met,
      r.E_iqm.toPrecision(3),
      ref?.E_iqm?.toPrecision(3) ?? '-',
      r.E_max.toPrecision(3),
      ref?.E_max?.toPrecision(3) ?? '-',
    ];
  });
  return [
    '## 2. Against the original program',
    '',
    `\`gd\`, \`bfgs\`, \`gn\` in normal mode (analytic derivatives, WebAssembly) beside ${referenceName} (the original C++ re-run on a 2-core machine). Target: at least ${LEAST_SPEED_UP}x less mean time, with the same or better success rate. The original's CSV has no success rate: the original's is measured here by re-running its algorithms (\`--paper\`, finite differences and its line searches, on the same targets, with its sample counts: GD 50, the others 300). Its E_IQM and max E are shown beside ours.`,
    '',
    table(
      [
        'rig',
        'experiment',
        'method',
        't_avg ours (s)',
        't_avg original (s)',
        'speed-up',
        'success ours',
        'success original (--paper)',
        'met',
        'E_IQM ours',
        'E_IQM original',
        'max E ours',
        'max E original',
      ],
      rows,
    ),
    '',
  ];
}

/** 3. WebAssembly against native: the solver core alone, and the whole call. */
export function enginesSection(m: Measurements, a7Names: A7Names, verdicts: Verdicts): string[] {
  const rows: string[][] = [];
  for (const rig of a7Names)
    for (const experiment of ['incremental', 'random']) {
      const core = (engine: string): number =>
        m.core.find((c) => c.rig === rig && c.set === experiment && c.engine === engine)?.t_median_s ?? NaN;
      const n = core('native'),
        w = core('wasm');
      const api = (engine: string): Row | undefined =>
        m.defaults.find((r) => r.rig === rig && r.experiment === experiment && r.engine === engine);
      const apiN = api('native'),
        apiW = api('wasm');
      const ratio = apiN && apiW ? apiW.t_median_s / apiN.t_median_s : NaN;
      const met = verdicts.mark(
        w / n <= LARGEST_WASM_RATIO,
        `3. ${rig} ${experiment}: core WebAssembly / native ${(w / n).toFixed(2)}x, over ${LARGEST_WASM_RATIO}x`,
      );
      rows.push([
        rig,
        experiment,
        us(n),
        us(w),
        `${(w / n).toFixed(2)}x`,
        met,
        apiN ? us(apiN.t_median_s) : '-',
        apiW ? us(apiW.t_median_s) : '-',
        `${ratio.toFixed(2)}x`,
      ]);
    }
  return [
    '## 3. WebAssembly against native',
    '',
    `Target: at most ${LARGEST_WASM_RATIO}x. Two measurements: the solver core alone (wasm/tools/solver_speed.cpp, the same program built with g++ and with em++, median over the A7 target sets), and the whole call through the JavaScript API against the native driver (\`npm run bench -- --engine wasm,native\`), which adds the cost of crossing into WebAssembly and copying arrays.`,
    '',
    table(
      [
        'rig',
        'experiment',
        'core native (us)',
        'core wasm (us)',
        'core ratio',
        `<= ${LARGEST_WASM_RATIO}x`,
        'API native (us)',
        'API wasm (us)',
        'API ratio',
      ],
      rows,
    ),
    '',
  ];
}

/** The peers of section 4, the engine each runs on (JavaScript peers: 'js') and lm's beside it. */
const PEERS: readonly { method: string; engine: string; lmEngine: string }[] = [
  { method: 'three-ccd', engine: 'js', lmEngine: 'wasm' },
  { method: 'closed-chain-ik', engine: 'js', lmEngine: 'wasm' },
  { method: 'kdl', engine: 'native', lmEngine: 'native' },
];

/** "97.5%, 46 us (to success: 40 us, 100% within 1 ms)" of a row, or "-" when it is missing. */
function raceCell(r: Row | undefined): string {
  if (!r) return '-';
  const toSuccess =
    r.t_success_median_s === null ? 'none succeeded' : `${us(r.t_success_median_s)} us median to success`;
  return `${pct(r.success_rate)}; ${toSuccess}; ${pct(r.success_within_1ms)} / ${pct(r.success_within_10ms)} / ${pct(r.success_within_100ms)}`;
}

/** 4. lm against the peers on the A7 rigs, with and without restarts, time to success included. */
export function peersSection(m: Measurements, a7Names: A7Names, verdicts: Verdicts): string[] {
  const rows: string[][] = [];
  const find = (rig: string, experiment: string, method: string, engine: string, restarted: boolean) =>
    m.peers.find(
      (r) =>
        r.rig === rig &&
        r.experiment === experiment &&
        r.method === method &&
        r.engine === engine &&
        r.restarts > 0 === restarted,
    );
  for (const rig of a7Names)
    for (const experiment of ['random', 'incremental']) {
      if (!m.peers.some((r) => r.rig === rig && r.experiment === experiment && r.method === 'lm')) continue;
      for (const peer of PEERS) {
        const cells = [true, false].flatMap((restarted) => {
          const ours = find(rig, experiment, 'lm', peer.lmEngine, restarted);
          const them = find(rig, experiment, peer.method, peer.engine, restarted);
          return [raceCell(ours), raceCell(them)];
        });
        // The target: with restarts for both (the default), lm succeeds at least as often and its
        // median time to success is lower.
        const ours = find(rig, experiment, 'lm', peer.lmEngine, true),
          them = find(rig, experiment, peer.method, peer.engine, true);
        const wins =
          !!ours &&
          !!them &&
          ours.success_rate >= them.success_rate &&
          (them.t_success_median_s === null ||
            (ours.t_success_median_s !== null && ours.t_success_median_s < them.t_success_median_s));
        const met = verdicts.mark(
          wins,
          `4. ${rig} ${experiment}: lm does not beat ${peer.method} with restarts on both`,
        );
        rows.push([
          rig,
          experiment,
          `${peer.method} (${peer.engine === 'js' ? 'JavaScript' : peer.engine})`,
          ...cells,
          met,
        ]);
      }
    }
  return [
    '## 4. Against the peers',
    '',
    `lm against three.js CCDIKSolver and closed-chain-ik (both in Node, lm in WebAssembly) and Orocos KDL (native, lm native), on the same targets, tolerances and 1 s budget, and the same restart policy: the solvers' default (restarts from the same quasi-random points after the same stall rule, the best point kept; bench-node/peers/restarting.ts) or none. Peer settings: bench-node/README.md. At most ${PEER_SAMPLES} samples per rig and experiment. Each cell: success; the median time of the successful solves; the share of all targets solved within 1 / 10 / 100 ms.`,
    '',
    'Target: with restarts on both, lm succeeds at least as often as each peer and reaches its targets sooner (median time to success).',
    '',
    table(
      [
        'rig',
        'experiment',
        'peer',
        'lm, restarts',
        'peer, restarts',
        'lm, no restarts',
        'peer, no restarts',
        'lm beats it (restarts)',
      ],
      rows,
    ),
    '',
  ];
}

/** 5. Scale, 6. memory (the heap check's target goes to `verdicts`). */
export function scaleAndMemorySections(m: Measurements, verdicts: Verdicts): string[] {
  const scaleRows = (rows: ScaleRow[], engine: string): string[][] =>
    rows.map((r) => [
      engine,
      r.shape,
      String(r.bones),
      String(r.angles),
      String(r.effectors),
      r.us_per_iteration.toFixed(2),
      r.ns_per_angle_effector.toFixed(1),
      String(r.iterations_median),
      pct(r.success_rate),
    ]);
  const grew = m.heap.bytesAtEnd - m.heap.bytesAfterThousand;
  verdicts.mark(grew === 0, `6. the WebAssembly heap grew by ${grew} bytes after ${m.heap.solves} solves`);
  return [
    '## 5. Scale',
    '',
    'Synthetic chains (one effector) and trees (five branches, effectors at the leaves) of 10, 100 and 1000 bones, limits +-45 degrees, random reachable targets, `lm` from rest. Linear growth in (angles x effectors) shows as a flat last-but-two column.',
    '',
    table(
      [
        'engine',
        'shape',
        'bones',
        'angles',
        'effectors',
        'us / iteration',
        'ns / (angle x effector)',
        'iterations (median)',
        'success',
      ],
      [...scaleRows(m.scale.native, 'native'), ...scaleRows(m.scale.wasm, 'wasm')],
    ),
    '',
    '## 6. Memory',
    '',
    'Incremental solves on the project lamp through `IkSolver`, with a new rig and solver every 1000 solves (bench-node/report/heap_growth.ts). Target: the heap does not grow.',
    '',
    '```',
    heapGrowthText(m.heap),
    '```',
    '',
  ];
}

/** The raw rows of sets 1-3. */
export function allRowsSection(m: Measurements): string[] {
  const rows = [...m.defaults, ...m.classic, ...m.peers].map((r) => [
    r.rig,
    r.experiment,
    r.method,
    r.engine,
    String(r.samples),
    r.t_avg_s.toPrecision(3),
    r.t_median_s.toPrecision(3),
    r.t_p95_s.toPrecision(3),
    r.t_p99_s.toPrecision(3),
    r.t_max_s.toPrecision(3),
    r.iter_avg.toPrecision(4),
    r.E_avg.toPrecision(3),
    r.E_iqm.toPrecision(3),
    r.E_max.toPrecision(3),
    pct(r.success_rate),
  ]);
  return [
    '## All rows',
    '',
    'The raw rows of sets 1-3 (`npm run bench` columns).',
    '',
    table(
      [
        'rig',
        'experiment',
        'method',
        'engine',
        'samples',
        't_avg',
        't_median',
        't_p95',
        't_p99',
        't_max',
        'iter_avg',
        'E_avg',
        'E_IQM',
        'max E',
        'success',
      ],
      rows,
    ),
    '',
  ];
}
