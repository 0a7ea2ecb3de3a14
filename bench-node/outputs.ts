// The files a run can write: --json, --csv and --markdown.
import { writeFileSync } from 'node:fs';

import { BenchError } from './errors.js';
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
  timeoutSeconds: number;
  paper: boolean;
  /** Per rig: size and the tolerances used (dragGtol, tipTolerance: drag and reach's; tipTolerance 0: E < ftol). */
  rigs: Array<{
    rig: string;
    path: string;
    bones: number;
    effectors: number;
    size: number;
    gtol: number;
    ftol: number;
    dragGtol: number;
    tipTolerance: number;
  }>;
}

function write(file: string, text: string): void {
  try {
    writeFileSync(file, text);
  } catch (e) {
    throw new BenchError(`cannot write ${file}: ${(e as Error).message.split('\n')[0]}`);
  }
}

export function writeJson(file: string, rows: readonly Row[], info: RunInfo): void {
  write(file, `${JSON.stringify({ rows, run: info }, (_, v: unknown) => (typeof v === 'number' && !Number.isFinite(v) ? null : v), 2)}\n`);
}

const csvColumns = [
  'rig', 'experiment', 'method', 'engine', 'samples', 't_avg_s', 't_median_s', 't_p95_s', 't_max_s',
  'iter_avg', 'E_avg', 'E_iqm', 'E_max', 'success_rate', 'unreachable',
  'wobble_during_avg', 'wobble_during_max', 'wobble_after_avg', 'wobble_after_max', 'jump_max_deg', 'stop_reasons',
] as const;

export function csvText(rows: readonly Row[]): string {
  const cell = (v: unknown): string => {
    if (v === null || v === undefined || (typeof v === 'number' && !Number.isFinite(v))) return '';
    const s = typeof v === 'object' ? formatStopReasons(v as Record<string, number>).replace(/, /g, ';') : String(v);
    return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
  };
  return [csvColumns.join(','), ...rows.map((r) => csvColumns.map((c) => cell(r[c])).join(','))].join('\n') + '\n';
}

export function writeCsv(file: string, rows: readonly Row[]): void {
  write(file, csvText(rows));
}

export function markdownText(tables: readonly Table[], info: RunInfo, notes: readonly string[]): string {
  const rigLines = info.rigs.map(
    (r) =>
      `| ${r.rig} | ${r.bones} | ${r.effectors} | ${r.size.toPrecision(4)} | ${r.gtol} | ${r.ftol} | ` +
      `${r.dragGtol.toPrecision(3)} | ${r.tipTolerance ? r.tipTolerance.toPrecision(3) : '- (E < ftol)'} |`,
  );
  return [
    '# Benchmark results',
    '',
    `Made by \`${info.command}\` on ${info.date}${info.commit ? ` at commit ${info.commit}` : ''}.`,
    '',
    `Machine: ${info.cpu}, ${info.cores} cores; Node ${info.node}; ${info.workers} workers. Seed ${info.seed}, ` +
      `time budget ${info.timeoutSeconds} s per solve${info.paper ? ', paper mode (the original algorithms)' : ''}.`,
    '',
    '| rig | bones | end effectors | size | gtol | ftol | drag gtol | drag tip tolerance |',
    '| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |',
    ...rigLines,
    '',
    ...notes.flatMap((n) => [n, '']),
    ...tables.map((t) => renderTable(t, 'markdown')),
  ].join('\n');
}

export function writeMarkdown(file: string, tables: readonly Table[], info: RunInfo, notes: readonly string[]): void {
  write(file, markdownText(tables, info, notes));
}
