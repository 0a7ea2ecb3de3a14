// `npm run bench -- [options]`: benchmarks the IK methods on the report's target sets and prints a
// table per rig and experiment. See bench-node/README.md for the options, metrics and peers.
import { spawnSync } from 'node:child_process';
import { availableParallelism, cpus } from 'node:os';
import { fileURLToPath } from 'node:url';

import { loadIkNode } from '../web/src/ik/node.js';
import { prepareRigs, runBench, totalSolves } from './bench.js';
import { compareTable, readReferenceCsv } from './compare.js';
import { BenchError } from './errors.js';
import type { Row } from './metrics.js';
import { parseOptions } from './options.js';
import { writeCsv, writeJson, writeMarkdown, type RunInfo } from './outputs.js';
import { makeProgress } from './progress.js';
import { engineRatioTable, groupRows, renderTable, resultsTable, type Table } from './table.js';

const notes = [
  'Columns as in the report: t_avg (s), iter_avg, E_avg, E_IQM (mean of the middle half of the sorted final E), ' +
    'max E; plus success (final E < ftol), median, 95th percentile and max time per solve, and the stop reasons. ' +
    'Drag and reach: success means every tip within the tip tolerance of its target, over the reachable steps; ' +
    'unreachable steps (reach) are counted apart; jump_max_deg is the largest change of one angle in one step. ' +
    'Definitions, the drag and reach experiments and the peers\' settings: bench-node/README.md.',
  'Times are per solve in seconds, measured on a machine that may be shared: a solve that is descheduled for ' +
    'milliseconds moves t_avg and t_max far more than t_median, so compare speeds by the medians. Wobble is in rig units.',
];

/** The checked-out commit, for the record; empty outside a git checkout. */
function gitCommit(): string {
  const r = spawnSync('git', ['rev-parse', '--short', 'HEAD'], { cwd: fileURLToPath(new URL('..', import.meta.url)), encoding: 'utf8' });
  return r.status === 0 ? r.stdout.trim() : '';
}

async function main(argv: string[]): Promise<number> {
  const opts = parseOptions(argv, process.stderr.isTTY === true);
  if (!opts) return 0;
  const reference = opts.compare ? readReferenceCsv(opts.compare) : undefined;
  const ik = await loadIkNode();
  const rigs = await prepareRigs(opts, ik);
  const progress = makeProgress(opts.progress, totalSolves(opts, rigs));
  let rows: Row[];
  try {
    rows = await runBench(rigs, { opts, ik, progress });
  } finally {
    progress.stop();
  }

  const tables: Table[] = groupRows(rows).map(resultsTable);
  const engineEntries = [...new Set(rows.map((r) => r.engine))].filter((e) => e !== 'js');
  const ratio = engineRatioTable(rows, engineEntries);
  if (ratio) tables.push(ratio);
  if (reference) {
    const compared = compareTable(rows, reference, opts.compare!);
    if (compared) tables.push(compared);
    else process.stderr.write(`compare: no row of ${opts.compare} matches this run's rigs, experiments and methods\n`);
  }
  process.stdout.write(tables.map((t) => renderTable(t, 'text')).join('\n'));

  const info: RunInfo = {
    command: `npm run bench -- ${argv.join(' ')}`,
    commit: gitCommit(),
    date: new Date().toISOString().slice(0, 10),
    node: process.versions.node,
    cpu: cpus()[0]?.model.trim() ?? 'unknown CPU',
    cores: availableParallelism(),
    workers: opts.workers,
    seed: opts.seed,
    timeoutSeconds: opts.timeoutSeconds,
    paper: opts.paper,
    rigs: rigs.map((r) => ({
      rig: r.name,
      path: r.path,
      bones: r.spec.parents.length,
      effectors: r.spec.effectors.length,
      size: r.size,
      gtol: r.gtol,
      ftol: r.ftol,
      dragGtol: r.drag.gtol,
      tipTolerance: r.drag.tipTolerance,
    })),
  };
  if (opts.json) writeJson(opts.json, rows, info);
  if (opts.csv) writeCsv(opts.csv, rows);
  if (opts.markdown) writeMarkdown(opts.markdown, tables, info, notes);
  return 0;
}

main(process.argv.slice(2)).then(
  (code) => {
    process.exitCode = code;
  },
  (e: unknown) => {
    if (e instanceof BenchError) {
      process.stderr.write(`bench: ${e.message}\n`);
      process.exitCode = e.exitCode;
    } else {
      process.stderr.write(`bench: internal error: ${e instanceof Error ? (e.stack ?? e.message) : String(e)}\n`);
      process.exitCode = 1;
    }
  },
);
