// The files a run can write: --json, --csv and --markdown, and the check before a run that they
// can be written.
import { accessSync, constants, statSync, writeFileSync, type Stats } from 'node:fs';
import { dirname, resolve } from 'node:path';

import { BenchError, errorLine } from './errors.js';
import type { Row } from './metrics.js';
import { formatStopReasons, renderTable, type Table } from './table.js';

/** Facts about a run, written beside the rows so a file says how it was made. */
export interface RunInfo {
  command: string;
  /** Short hash of the checked-out commit ('' when unknown). */
  commit: string;
  date: string;
  node: string;
  cpu: string;
  cores: number;
  workers: number;
  seed: number;
  timeBudgetSeconds: number;
  paper: boolean;
  /** --goals: 'position' (the protocol's tip positions) or 'pose' (tip positions and frame orientations). */
  goals: string;
  /** Anatomical limits on recognised humanoids (false: --no-humanoid-limits). */
  humanoidLimits: boolean;
  /** Per rig: size and the tolerances used (dragGradientTolerance, tipTolerance: drag and reach's; tipTolerance 0: E < errorTolerance). */
  rigs: Array<{
    rig: string;
    path: string;
    /** URDF: the chain BASE:TIP the importer took; null for the other formats. */
    chain: string | null;
    bones: number;
    effectors: number;
    size: number;
    gradientTolerance: number;
    errorTolerance: number;
    dragGradientTolerance: number;
    tipTolerance: number;
  }>;
}

/** The stat of `path`, or undefined when nothing is there. */
function statOf(path: string): Stats | undefined {
  try {
    return statSync(path);
  } catch (e) {
    const code = (e as NodeJS.ErrnoException).code;
    if (code === 'ENOENT' || code === 'ENOTDIR') return undefined;
    throw e;
  }
}

function writable(path: string): boolean {
  try {
    accessSync(path, constants.W_OK);
    return true;
  } catch {
    return false;
  }
}

/** Why `file` cannot be written, or undefined when it can. */
function outputProblem(file: string): string | undefined {
  if (/[\\/]$/.test(file)) return 'names a folder, not a file';
  const stat = statOf(file);
  if (stat?.isDirectory()) return 'is a directory';
  if (stat && !stat.isFile() && !stat.isCharacterDevice()) return 'is not a regular file';
  if (stat) return writable(file) ? undefined : 'is not writable';
  const folder = dirname(resolve(file));
  const folderStat = statOf(folder);
  if (!folderStat) return `folder ${folder} does not exist`;
  if (!folderStat.isDirectory()) return `${folder} is not a folder`;
  return writable(folder) ? undefined : `folder ${folder} is not writable`;
}

/** What makes two paths the same file: device and inode when it exists, else the absolute path. */
function fileKey(path: string): string {
  try {
    const stat = statSync(path);
    return `${stat.dev}:${stat.ino}`;
  } catch {
    return resolve(path);
  }
}

/**
 * Who already has `file` in `taken` (an input, an earlier output), or undefined; then records it
 * as `flag`'s. Character devices (/dev/null) may be shared.
 */
function clash(file: string, flag: string, taken: Map<string, string>): string | undefined {
  if (statOf(file)?.isCharacterDevice()) return undefined;
  const key = fileKey(file);
  const owner = taken.get(key);
  taken.set(key, `the file of ${flag}`);
  return owner === undefined ? undefined : `is ${owner}`;
}

/**
 * Checks before a run that every output file can be written: its folder exists and is writable,
 * and it is no directory, FIFO or other special file (character devices such as /dev/null pass).
 * No two outputs may share a file, and none may overwrite an input (`inputs`: the rig and
 * --compare files). Throws BenchError (exit code 2) `FLAG FILE: problem`.
 */
export function checkOutputs(
  outputs: ReadonlyArray<readonly [flag: string, file: string | undefined]>,
  inputs: readonly string[],
): void {
  const taken = new Map(inputs.map((path) => [fileKey(path), 'an input of this run']));
  for (const [flag, file] of outputs) {
    if (file === undefined) continue;
    let problem: string | undefined;
    try {
      problem = outputProblem(file) ?? clash(file, flag, taken);
    } catch (e) {
      problem = errorLine(e);
    }
    if (problem) throw new BenchError(`${flag} ${file}: ${problem}`, 2);
  }
}

/** Writes `text` to `file`; throws BenchError naming the file when it cannot. */
export function writeText(file: string, text: string): void {
  try {
    writeFileSync(file, text);
  } catch (e) {
    throw new BenchError(`cannot write ${file}: ${(e as Error).message.split('\n')[0]}`);
  }
}

/** Writes `{ rows, run }` to `file` as JSON; a number that is not finite is written as null. */
export function writeJson(file: string, rows: readonly object[], run: object): void {
  writeText(
    file,
    `${JSON.stringify({ rows, run }, (_, v: unknown) => (typeof v === 'number' && !Number.isFinite(v) ? null : v), 2)}\n`,
  );
}

const csvColumns = [
  'rig',
  'experiment',
  'method',
  'engine',
  'samples',
  't_avg_s',
  't_median_s',
  't_p95_s',
  't_max_s',
  'iter_avg',
  'E_avg',
  'E_iqm',
  'E_max',
  'success_rate',
  'unreachable',
  'restarts',
  'goals',
  'rot_err_avg_deg',
  'rot_err_max_deg',
  't_success_median_s',
  't_success_p95_s',
  'success_within_1ms',
  'success_within_10ms',
  'success_within_100ms',
  'wobble_during_avg',
  'wobble_during_max',
  'wobble_after_avg',
  'wobble_after_max',
  'wobble_unreachable_avg',
  'wobble_unreachable_max',
  'jump_max_deg',
  'jumps',
  'flips',
  'stop_reasons',
] as const;

export function csvText(rows: readonly Row[]): string {
  return csvTable(rows, csvColumns);
}

/**
 * `rows` as CSV under `columns`: a header line, then a line per row. Empty for null, undefined and
 * numbers that are not finite; an object (stop reasons) as `reason: count;...`; quoted as needed.
 */
export function csvTable<R>(rows: readonly R[], columns: readonly (keyof R & string)[]): string {
  const cell = (v: unknown): string => {
    if (v === null || v === undefined || (typeof v === 'number' && !Number.isFinite(v))) return '';
    const s = typeof v === 'object' ? formatStopReasons(v as Record<string, number>).replace(/, /g, ';') : String(v);
    return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
  };
  return [columns.join(','), ...rows.map((r) => columns.map((c) => cell(r[c])).join(','))].join('\n') + '\n';
}

export function writeCsv(file: string, rows: readonly Row[]): void {
  writeText(file, csvText(rows));
}

export function markdownText(tables: readonly Table[], info: RunInfo, notes: readonly string[]): string {
  const rigLines = info.rigs.map(
    (r) =>
      `| ${r.rig} | ${r.bones} | ${r.effectors} | ${r.size.toPrecision(4)} | ${r.gradientTolerance} | ${r.errorTolerance} | ` +
      `${r.dragGradientTolerance.toPrecision(3)} | ${r.tipTolerance ? r.tipTolerance.toPrecision(3) : '- (E < error tolerance)'} |`,
  );
  return [
    '# Benchmark results',
    '',
    `Made by \`${info.command}\` on ${info.date}${info.commit ? ` at commit ${info.commit}` : ''}.`,
    '',
    `Machine: ${info.cpu}, ${info.cores} cores; Node ${info.node}; ${info.workers} workers. Seed ${info.seed}, ` +
      `time budget ${info.timeBudgetSeconds} s per solve${info.paper ? ', paper mode (the original algorithms)' : ''}` +
      `${info.goals === 'pose' ? ', pose goals (tip positions and orientations; on target also needs every orientation within 0.5 degrees)' : ''}.`,
    '',
    '| rig | bones | end effectors | size | gradient tolerance | error tolerance | drag gradient tolerance | drag tip tolerance |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
    ...rigLines,
    '',
    ...notes.flatMap((n) => [n, '']),
    ...tables.map((t) => renderTable(t, 'markdown')),
  ].join('\n');
}

export function writeMarkdown(file: string, tables: readonly Table[], info: RunInfo, notes: readonly string[]): void {
  writeText(file, markdownText(tables, info, notes));
}
