// The command line as a function: options -> checks -> run -> tables and files, and every error
// as one line `bench: ...` (cli.ts is the entry point that calls it on process.argv).
import { spawnSync } from 'node:child_process';
import { closeSync, existsSync, openSync, unlinkSync } from 'node:fs';
import { availableParallelism, cpus } from 'node:os';
import { fileURLToPath } from 'node:url';

import { loadIkNode } from '#ik/node.js';
import { IkSolver } from '#ik/solver.js';
import { noGesturesNote, prepareRigs, runBench, totalSolves } from './bench.js';
import { compareTable, readReferenceCsv } from './reference_csv.js';
import { BenchError, errorLine } from './errors.js';
import type { Row } from './metrics.js';
import { parseOptions } from './options.js';
import { checkOutputs, csvTable, writeCsv, writeJson, writeMarkdown, writeText, type RunInfo } from './outputs.js';
import { makeProgress } from './progress.js';
import { resolveRigPaths } from './rigs.js';
import { engineRatioTable, groupRows, renderTable, resultsTable, timeToSuccessTable, type Table } from './table.js';
import { tracikCsvColumns, tracikTable, withPublished } from './tracik_table.js';
import { runTrackCommand } from './track_command.js';

/** Where the command writes: the tables (stdout), errors and notes (stderr). */
export interface CommandIo {
  out: (text: string) => void;
  err: (text: string) => void;
  /** Whether stderr is a terminal (the progress bar is drawn only there). */
  isTTY: boolean;
}

const processIo: CommandIo = {
  out: (text) => process.stdout.write(text),
  err: (text) => process.stderr.write(text),
  isTTY: process.stderr.isTTY === true,
};

const notes = [
  'Columns as in the report: t_avg (s), iter_avg, E_avg, E_IQM (mean of the middle half of the sorted final E), ' +
    'max E; plus success (final E < error tolerance), median, 95th percentile and max time per solve, and the stop reasons. ' +
    'Drag, reach and gestures: success means every tip within the tip tolerance of its target, over the reachable steps; ' +
    "unreachable steps (reach, gestures) are counted apart, wobble_unreach is the pinned effectors' wobble after them; " +
    'jumps counts steps where a joint moved more than 5% of the rig size while the dragged target moved less than 1%; ' +
    'flips counts steps where an elbow or knee bent against its anatomical direction or its bend plane turned more than 90 degrees; ' +
    'jump_max_deg is the largest change of one angle in one step (the shortest way round for an angle without limits). ' +
    'With --goals pose, E is over the tip positions and success also needs every orientation within 0.5 degrees; ' +
    "rot_err_avg_deg and rot_err_max_deg are the mean and max of each solve's largest orientation error. " +
    "tracik: TRAC-IK's protocol (pose within 1e-5 in position and 1e-5 rad in rotation angle, from the mid-limit seed, " +
    "5 ms per query; t_avg over all queries), with the TRAC-IK v1.4.6 README's KDL and TRAC-IK figures for the chains it lists. " +
    "Definitions, the drag and reach experiments and the peers' settings: bench-node/README.md.",
  'Times are per solve in seconds, measured on a machine that may be shared: a solve that is descheduled for ' +
    'milliseconds moves t_avg and t_max far more than t_median, so compare speeds by the medians. Wobble is in rig units.',
];

/** The checked-out commit, for the record; empty outside a git checkout. */
function gitCommit(): string {
  const r = spawnSync('git', ['rev-parse', '--short', 'HEAD'], {
    cwd: fileURLToPath(new URL('..', import.meta.url)),
    encoding: 'utf8',
  });
  return r.status === 0 ? r.stdout.trim() : '';
}

/**
 * Opens each output file for appending (which changes no byte of an existing file) and removes
 * the ones this made, so that a file the system will not let us create (/proc/x.json, a
 * read-only mount, where root passes every permission check) is a usage error before the run
 * rather than an error after it. Runs after checkOutputs(), which refuses FIFOs (opening one
 * would wait for a reader).
 */
function tryOutputs(outputs: ReadonlyArray<readonly [flag: string, file: string | undefined]>): void {
  for (const [flag, file] of outputs) {
    if (file === undefined) continue;
    const existed = existsSync(file);
    try {
      closeSync(openSync(file, 'a'));
    } catch (e) {
      throw new BenchError(`${flag} ${file}: cannot be written: ${errorLine(e)}`, 2);
    }
    if (!existed) unlinkSync(file);
  }
}

async function main(argv: string[], io: CommandIo): Promise<number> {
  // The core's methods are the ones --methods knows: its module comes first.
  const ik = await loadIkNode();
  const opts = parseOptions(argv, io.isTTY, IkSolver.methods(ik), io.err);
  if (!opts) return 0;
  const outputs = [
    ['--json', opts.json],
    ['--csv', opts.csv],
    ['--markdown', opts.markdown],
  ] as const;
  checkOutputs(outputs, [...resolveRigPaths(opts.rigs), ...(opts.compare ? [opts.compare] : [])]);
  tryOutputs(outputs);
  if (opts.track) {
    await runTrackCommand(opts, ik, io.out, `npm run bench -- ${argv.join(' ')}`);
    return 0;
  }
  const reference = opts.compare ? readReferenceCsv(opts.compare) : undefined;
  const rigs = await prepareRigs(opts, ik);
  if (opts.experiments.includes('gestures'))
    for (const rig of rigs) {
      const note = noGesturesNote(rig);
      if (note) io.err(`gestures: ${note}, left out\n`);
    }
  const progress = makeProgress(opts.progress, totalSolves(opts, rigs));
  let rows: Row[];
  try {
    rows = await runBench(rigs, { opts, ik, progress });
  } finally {
    progress.stop();
  }

  // tracik: each row with its chain and the published figures of that chain (tracik_table.ts).
  const chainOf = (rig: string): string | undefined => rigs.find((r) => r.name === rig)?.chain ?? undefined;
  const tracik = opts.experiments.includes('tracik') ? rows.map((r) => withPublished(r, chainOf(r.rig))) : undefined;
  const tables: Table[] = tracik ? groupRows(tracik).map(tracikTable) : groupRows(rows).map(resultsTable);
  const timed = timeToSuccessTable(rows);
  if (timed) tables.push(timed);
  const engineEntries = [...new Set(rows.map((r) => r.engine))].filter((e) => e !== 'js');
  const ratio = engineRatioTable(rows, engineEntries);
  if (ratio) tables.push(ratio);
  if (reference) {
    const compared = compareTable(rows, reference, opts.compare!);
    if (compared) tables.push(compared);
    else io.err(`compare: no row of ${opts.compare} matches this run's rigs, experiments and methods\n`);
  }
  io.out(tables.map((t) => renderTable(t, 'text')).join('\n'));

  const info: RunInfo = {
    command: `npm run bench -- ${argv.join(' ')}`,
    commit: gitCommit(),
    date: new Date().toISOString().slice(0, 10),
    node: process.versions.node,
    cpu: cpus()[0]?.model.trim() ?? 'unknown CPU',
    cores: availableParallelism(),
    workers: opts.workers,
    seed: opts.seed,
    timeBudgetSeconds: opts.timeBudgetSeconds,
    paper: opts.paper,
    goals: opts.goals,
    humanoidLimits: opts.humanoidLimits,
    rigs: rigs.map((r) => ({
      rig: r.name,
      path: r.path,
      chain: r.chain,
      bones: r.spec.parents.length,
      effectors: r.spec.effectors.length,
      size: r.size,
      gradientTolerance: r.gradientTolerance,
      errorTolerance: r.errorTolerance,
      dragGradientTolerance: r.drag.gradientTolerance,
      tipTolerance: r.drag.tipTolerance,
    })),
  };
  if (opts.json) writeJson(opts.json, tracik ?? rows, info);
  if (opts.csv && tracik) writeText(opts.csv, csvTable(tracik, tracikCsvColumns));
  else if (opts.csv) writeCsv(opts.csv, rows);
  if (opts.markdown) writeMarkdown(opts.markdown, tables, info, notes);
  return 0;
}

/** Control characters (line breaks) of a message escaped, so that it stays on one line. */
function oneLine(message: string): string {
  // eslint-disable-next-line no-control-regex -- the control characters are what it escapes
  return message.replace(/[\u0000-\u001f\u007f]/g, (c) => JSON.stringify(c).slice(1, -1));
}

/**
 * Runs the command line on `argv` (without node and the script) and returns its exit code. A
 * BenchError prints one line `bench: message` on `io.err` (exit code 2 for usage errors, 1
 * otherwise); anything else is a bug and prints its stack.
 */
export async function runCommand(argv: string[], io: CommandIo = processIo): Promise<number> {
  try {
    return await main(argv, io);
  } catch (e) {
    if (e instanceof BenchError) {
      io.err(`bench: ${oneLine(e.message)}\n`);
      return e.exitCode;
    }
    io.err(`bench: internal error: ${e instanceof Error ? (e.stack ?? e.message) : String(e)}\n`);
    return 1;
  }
}
