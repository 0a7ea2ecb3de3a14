// npm run bench:report: runs the whole issue-6 measurement set and writes docs/benchmarks.md
// with its tables, ratios and two SVG charts (docs/benchmarks-time.svg, -success.svg).
// Every number comes from this run, on this machine. Sets:
//   1. the default method (lm, restarts on) on the five A7 rigs and every project rig,
//      random and incremental, WebAssembly and native (`npm run bench`);
//   2. gd, bfgs, gn in normal mode on the A7 rigs beside ../shared/paper/original-measured.csv;
//   3. the peers three-ccd and closed-chain-ik on the A7 rigs;
//   4. the solver core alone, native against WebAssembly (wasm/tools/solver_speed, one program);
//   5. time per iteration on synthetic chains and trees (wasm/tools/scale_bench);
//   6. the WebAssembly heap after 10^3 and 10^6 solves (bench-node/report/heap_growth.ts);
//   7. lm while a user drags: the drag and reach experiments on every rig (report/dragging.ts).
// Usage: npm run bench:report [-- --samples N]   (default 1000 per rig and experiment; gd 100)
import { spawnSync } from 'node:child_process';
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, tmpdir } from 'node:os';
import { join } from 'node:path';

import { parseReferenceCsv, type ReferenceRow } from '../compare.js';
import type { Row } from '../metrics.js';
import { draggingSection } from './dragging.js';
import { mark, pct, table, us } from './markdown.js';
import { barChartSvg } from './svg_chart.js';

const argAt = process.argv.indexOf('--samples');
const samples = argAt > 0 ? Number(process.argv[argAt + 1]) : 1000;
const gdSamples = Math.min(100, samples);
const a7Names = ['ikea-lamp', 'robot-arm', 'knight', 'chimpanzee-hand', 'beast'];
// The report's rigs and, beside them, its paper folder (scripts/bench-report.sh checks they exist).
const a7Dir = process.env.IK_A7_DIR || '../shared/rigs/a7';
const a7 = a7Names.map((n) => join(a7Dir, `${n}.json`));
const projectRigs = ['lamp', 'robot-arm', 'knight', 'hand', 'beast', 'character'];
const original = join(a7Dir, '../../paper/original-measured.csv');
const work = join(tmpdir(), `ik-bench-report-${process.pid}`);
mkdirSync(work, { recursive: true });
mkdirSync('docs', { recursive: true });

function run(command: string, args: string[]): string {
  process.stderr.write(`bench:report: ${command} ${args.join(' ')}\n`);
  const r = spawnSync(command, args, { encoding: 'utf8', maxBuffer: 1 << 28 });
  if (r.status !== 0) throw new Error(`${command} ${args.join(' ')} failed (${r.status}):\n${r.stderr}`);
  return r.stdout;
}

function bench(name: string, args: string[]): Row[] {
  const file = join(work, `${name}.json`);
  run('npx', ['tsx', 'bench-node/cli.ts', ...args, '--no-progress', '--json', file]);
  return (JSON.parse(readFileSync(file, 'utf8')) as { rows: Row[] }).rows;
}

// 1. The default method everywhere, both engines.
const defaults = bench('default', ['--rig', [...a7, ...projectRigs].join(','), '--methods', 'lm', '--samples', String(samples), '--engine', 'wasm,native']);
// 2. The report's methods (normal mode) on its rigs.
const classic = bench('classic', ['--rig', a7.join(','), '--methods', 'gd,bfgs,gn', '--samples', `${samples},gd=${gdSamples}`]);
// 2b. The original's success rate, which its CSV lacks: the original algorithms (--paper, the
// program reproduced) on the same targets, with the original's sample counts (GD 50, others 300).
const paper = bench('paper', ['--rig', a7.join(','), '--methods', 'gd,bfgs,gn', '--paper', '--samples', `${Math.min(samples, 300)},gd=${Math.min(samples, 50)}`]);
// 3. Peers.
const peers = bench('peers', ['--rig', a7.join(','), '--methods', 'three-ccd,closed-chain-ik', '--samples', String(samples)]);
// 4. The solver core, one C++ program built twice.
const coreRows: string[][] = [];
for (const path of a7) {
  for (const engine of ['native', 'wasm'] as const) {
    const out = engine === 'native'
      ? run('build/native/solver_speed', [path, '--methods', 'lm', '--samples', String(Math.min(samples, 500))])
      : run('node', ['build/wasm/solver_speed.cjs', path, '--methods', 'lm', '--samples', String(Math.min(samples, 500))]);
    for (const line of out.split('\n').filter((l) => /^(incremental|random)\s+lm/.test(l))) {
      const f = line.trim().split(/\s+/);
      coreRows.push([path.split('/').pop()!.replace('.json', ''), f[0], engine, f[5]]);
    }
  }
}
// 5. Scale, 6. memory.
const scaleNative = run('build/native/scale_bench', ['--csv']);
const scaleWasm = run('node', ['build/wasm/scale_bench.cjs', '--csv']);
const heap = run('npx', ['tsx', 'bench-node/report/heap_growth.ts', '--solves', String(samples * 1000)]);
// 7. Dragging; the A7 rigs and the project's share names, so the A7 ones are labelled.
const dragArgs = ['--experiment', 'drag,reach', '--methods', 'lm', '--samples', String(samples)];
const dragging = [
  ...bench('dragging-a7', ['--rig', a7.join(','), ...dragArgs]).map((r) => ({ ...r, rig: `${r.rig} (A7)` })),
  ...bench('dragging-project', ['--rig', projectRigs.join(','), ...dragArgs]),
];

// ---- the document
const md: string[] = [];
const when = new Date().toISOString().slice(0, 10);
md.push(`# Benchmarks`, '', `Made by \`npm run bench:report${samples !== 1000 ? ` -- --samples ${samples}` : ''}\` on ${when}: ${cpus()[0]?.model ?? 'unknown CPU'}, ${cpus().length} cores, Node ${process.version}. Target sets, tolerances and metrics as in ../shared/paper/PROTOCOL.md (beast 0.01 / 0.002, other A7 rigs 1e-4 / 2e-4, project rigs scaled by size, see bench-node/README.md); 1 s per solve; ${samples} samples per rig and experiment (gd ${gdSamples}). Times are per solve, measured around the call a user makes (WebAssembly: through \`IkSolver\` in Node).`, '');
md.push('![median time per solve](benchmarks-time.svg)', '', '![success rate](benchmarks-success.svg)', '');

md.push('## 1. The default method: `lm` with restarts', '', 'Targets: success 100% (random and incremental); in WebAssembly, random median <= 0.3 ms and p99 <= 10 ms, incremental median <= 30 us.', '');
const wasmDefault = defaults.filter((r) => r.engine === 'wasm');
md.push(table(['rig', 'experiment', 'success', 'median (us)', 'p99 (us)', 'max (us)', 'iter avg', 'max E', 'met'], wasmDefault.map((r) => {
  const ok = r.success_rate === 1 && (r.experiment === 'random' ? r.t_median_s <= 3e-4 && r.t_p99_s <= 1e-2 : r.t_median_s <= 3e-5);
  return [r.rig, r.experiment, pct(r.success_rate), us(r.t_median_s), us(r.t_p99_s), us(r.t_max_s), r.iter_avg.toFixed(2), r.E_max.toPrecision(3), mark(ok)];
})), '');

md.push('## 2. Against the original program', '', `\`gd\`, \`bfgs\`, \`gn\` in normal mode (analytic derivatives, WebAssembly) beside ${original} (the original C++ re-run on a 2-core machine). Target: at least 100x less mean time, with the same or better success rate. The original's CSV has no success rate: the original's is measured here by re-running its algorithms (\`--paper\`, finite differences and its line searches, on the same targets, with its sample counts: GD 50, the others 300). Its E_IQM and max E are shown beside ours.`, '');
const reference: ReferenceRow[] = parseReferenceCsv(readFileSync(original, 'utf8'), original);
md.push(table(['rig', 'experiment', 'method', 't_avg ours (s)', 't_avg original (s)', 'speed-up', 'success ours', 'success original (--paper)', 'met', 'E_IQM ours', 'E_IQM original', 'max E ours', 'max E original'], classic.map((r) => {
  const ref = reference.find((x) => x.rig === r.rig && x.experiment === r.experiment && x.method.toLowerCase() === r.method);
  const theirs = paper.find((x) => x.rig === r.rig && x.experiment === r.experiment && x.method === r.method && x.engine === r.engine);
  const ratio = ref ? ref.t_avg_s / r.t_avg_s : NaN;
  const ok = ratio >= 100 && theirs !== undefined && r.success_rate >= theirs.success_rate;
  return [r.rig, r.experiment, r.method, r.t_avg_s.toPrecision(3), ref ? ref.t_avg_s.toPrecision(3) : '-', `${ratio.toFixed(0)}x`, pct(r.success_rate), theirs ? pct(theirs.success_rate) : '-', mark(ok), r.E_iqm.toPrecision(3), ref?.E_iqm?.toPrecision(3) ?? '-', r.E_max.toPrecision(3), ref?.E_max?.toPrecision(3) ?? '-'];
})), '');

md.push('## 3. WebAssembly against native', '', 'Target: at most 1.5x. Two measurements: the solver core alone (wasm/tools/solver_speed.cpp, the same program built with g++ and with em++, median over the A7 target sets), and the whole call through the JavaScript API against the native driver (`npm run bench -- --engine wasm,native`), which adds the cost of crossing into WebAssembly and copying arrays.', '');
const coreTable: string[][] = [];
for (const rig of a7Names)
  for (const experiment of ['incremental', 'random']) {
    const n = Number(coreRows.find((c) => c[0] === rig && c[1] === experiment && c[2] === 'native')?.[3]);
    const w = Number(coreRows.find((c) => c[0] === rig && c[1] === experiment && c[2] === 'wasm')?.[3]);
    const e2eN = defaults.find((r) => r.rig === rig && r.experiment === experiment && r.engine === 'native');
    const e2eW = defaults.find((r) => r.rig === rig && r.experiment === experiment && r.engine === 'wasm');
    const e2e = e2eN && e2eW ? e2eW.t_median_s / e2eN.t_median_s : NaN;
    coreTable.push([rig, experiment, n.toFixed(2), w.toFixed(2), `${(w / n).toFixed(2)}x`, mark(w / n <= 1.5), e2eN ? us(e2eN.t_median_s) : '-', e2eW ? us(e2eW.t_median_s) : '-', `${e2e.toFixed(2)}x`]);
  }
md.push(table(['rig', 'experiment', 'core native (us)', 'core wasm (us)', 'core ratio', '<= 1.5x', 'API native (us)', 'API wasm (us)', 'API ratio'], coreTable), '');

md.push('## 4. Against the peers', '', 'Target: on every A7 rig, random and incremental, `lm` beats three.js CCDIKSolver and closed-chain-ik on both success rate and median time (settings: bench-node/README.md).', '');
const peerTable: string[][] = [];
for (const rig of a7Names)
  for (const experiment of ['random', 'incremental']) {
    const ours = wasmDefault.find((r) => r.rig === rig && r.experiment === experiment);
    const them = peers.filter((r) => r.rig === rig && r.experiment === experiment);
    if (!ours) continue;
    const beats = them.every((p) => ours.success_rate >= p.success_rate && ours.t_median_s < p.t_median_s);
    peerTable.push([rig, experiment, `${pct(ours.success_rate)}, ${us(ours.t_median_s)}`, ...them.map((p) => `${pct(p.success_rate)}, ${us(p.t_median_s)}`), mark(beats)]);
  }
md.push(table(['rig', 'experiment', 'lm (success, median us)', 'three-ccd', 'closed-chain-ik', 'lm beats both'], peerTable), '');

md.push('## 5. Scale', '', 'Synthetic chains (one effector) and trees (five branches, effectors at the leaves) of 10, 100 and 1000 bones, limits +-45 degrees, random reachable targets, `lm` from rest. Linear growth in (angles x effectors) shows as a flat last-but-two column.', '');
const scaleTable = (csv: string, engine: string): string[][] =>
  csv.trim().split('\n').slice(1).map((l) => l.split(',')).map((f) => [engine, f[0], f[1], f[2], f[3], Number(f[4]).toFixed(2), Number(f[5]).toFixed(1), f[6], pct(Number(f[7]))]);
md.push(table(['engine', 'shape', 'bones', 'angles', 'effectors', 'us / iteration', 'ns / (angle x effector)', 'iterations (median)', 'success'], [...scaleTable(scaleNative, 'native'), ...scaleTable(scaleWasm, 'wasm')]), '');

md.push('## 6. Memory', '', 'Incremental solves on the project lamp through `IkSolver`, with a new rig and solver every 1000 solves (bench-node/report/heap_growth.ts):', '', '```', heap.trim(), '```', '');

md.push(...draggingSection(dragging));

md.push('## All rows', '', 'The raw rows of sets 1-3 (`npm run bench` columns).', '');
md.push(table(['rig', 'experiment', 'method', 'engine', 'samples', 't_avg', 't_median', 't_p95', 't_p99', 't_max', 'iter_avg', 'E_avg', 'E_IQM', 'max E', 'success'], [...defaults, ...classic, ...peers].map((r) => [r.rig, r.experiment, r.method, r.engine, String(r.samples), r.t_avg_s.toPrecision(3), r.t_median_s.toPrecision(3), r.t_p95_s.toPrecision(3), r.t_p99_s.toPrecision(3), r.t_max_s.toPrecision(3), r.iter_avg.toPrecision(4), r.E_avg.toPrecision(3), r.E_iqm.toPrecision(3), r.E_max.toPrecision(3), pct(r.success_rate)])), '');
writeFileSync('docs/benchmarks.md', `${md.join('\n')}\n`);

// ---- charts: A7 rigs, random targets, WebAssembly
const colors: Record<string, string> = { lm: '#1b9e77', gn: '#d95f02', bfgs: '#7570b3', gd: '#e7298a', 'three-ccd': '#66a61e', 'closed-chain-ik': '#e6ab02' };
const methods = ['lm', 'gn', 'bfgs', 'gd', 'three-ccd', 'closed-chain-ik'];
const all = [...wasmDefault, ...classic, ...peers];
const pick = (m: string, f: (r: Row) => number): number[] => a7Names.map((rig) => {
  const r = all.find((x) => x.rig === rig && x.experiment === 'random' && x.method === m && x.engine !== 'native');
  return r ? f(r) : NaN;
});
writeFileSync('docs/benchmarks-time.svg', barChartSvg({
  title: 'Median time per solve, random targets (WebAssembly / JavaScript)', groups: a7Names, axis: 'seconds (log scale)', log: true, min: 1e-6, max: 1,
  format: (v) => (v >= 1e-3 ? `${v * 1e3} ms` : `${Math.round(v * 1e6)} us`),
  series: methods.map((m) => ({ name: m, color: colors[m], values: pick(m, (r) => r.t_median_s) })),
}));
writeFileSync('docs/benchmarks-success.svg', barChartSvg({
  title: 'Success rate (final E < ftol), random targets', groups: a7Names, axis: 'success', log: false, min: 0, max: 1,
  format: (v) => `${Math.round(v * 100)}%`,
  series: methods.map((m) => ({ name: m, color: colors[m], values: pick(m, (r) => r.success_rate) })),
}));
process.stderr.write('bench:report: wrote docs/benchmarks.md, docs/benchmarks-time.svg, docs/benchmarks-success.svg\n');
