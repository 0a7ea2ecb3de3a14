// --compare: reads a results CSV of the report (its table, results.csv in the paper folder: rig,
// bones, experiment, method, ...) or of the re-measured original program (original-measured.csv:
// rig, experiment, method, samples, ...) and sets our rows beside it, with the speed ratio
// their t_avg / our t_avg (above 1: we are faster). Rows match on rig, experiment and method
// (case-insensitive: the CSVs say GD, BFGS, GN).
import { readFileSync, statSync } from 'node:fs';

import { BenchError, errorLine, quote } from './errors.js';
import type { Row } from './metrics.js';
import { formatNumber, formatPercent, type Table } from './table.js';

export interface ReferenceRow {
  rig: string;
  experiment: string;
  method: string;
  samples?: number;
  t_avg_s: number;
  iter_avg?: number;
  E_avg?: number;
  E_iqm?: number;
  E_max?: number;
}

const required = ['rig', 'experiment', 'method', 't_avg_s'] as const;
const optional = ['samples', 'iter_avg', 'E_avg', 'E_iqm', 'E_max'] as const;

/** Parses the CSV text; `file` names it in errors. Throws BenchError. */
export function parseReferenceCsv(text: string, file: string): ReferenceRow[] {
  const lines = text.split(/\r?\n/).filter((l) => l.trim().length > 0);
  if (lines.length === 0) throw new BenchError(`--compare ${file}: empty file`);
  const header = lines[0].split(',').map((h) => h.trim());
  for (const col of required)
    if (!header.includes(col))
      throw new BenchError(`--compare ${file}: no "${col}" column (expected ${required.join(', ')})`);
  const index = (col: string): number => header.indexOf(col);
  return lines.slice(1).map((line, i) => {
    const cells = line.split(',').map((c) => c.trim());
    if (cells.length !== header.length)
      throw new BenchError(`--compare ${file}: line ${i + 2} has ${cells.length} cells, the header ${header.length}`);
    const num = (col: string): number | undefined => {
      const k = index(col);
      if (k < 0) return undefined;
      const x = Number(cells[k]);
      if (cells[k] === '' || !Number.isFinite(x))
        throw new BenchError(`--compare ${file}: line ${i + 2}: ${col} ${quote(cells[k])} is not a number`);
      return x;
    };
    const row: ReferenceRow = {
      rig: cells[index('rig')],
      experiment: cells[index('experiment')].toLowerCase(),
      method: cells[index('method')].toLowerCase(),
      t_avg_s: num('t_avg_s')!,
    };
    for (const col of optional) {
      const v = num(col);
      if (v !== undefined) row[col] = v;
    }
    return row;
  });
}

/** Largest --compare file: the report's CSVs take a few KiB. */
const MAX_COMPARE_BYTES = 16 * 2 ** 20;

/**
 * Reads and parses a reference CSV. Throws BenchError `--compare FILE: problem` for a missing
 * file, a directory or device, a file over MAX_COMPARE_BYTES, an unreadable or malformed one.
 */
export function readReferenceCsv(file: string): ReferenceRow[] {
  const fail = (problem: string): BenchError => new BenchError(`--compare ${file}: ${problem}`);
  let text: string;
  try {
    const stat = statSync(file);
    if (stat.isDirectory()) throw fail('is a directory, not a CSV file');
    if (!stat.isFile()) throw fail('is not a regular file');
    if (stat.size > MAX_COMPARE_BYTES)
      throw fail(`is ${stat.size} bytes; a reference CSV has at most ${MAX_COMPARE_BYTES}`);
    text = readFileSync(file, 'utf8');
  } catch (e) {
    if (e instanceof BenchError) throw e;
    throw fail((e as NodeJS.ErrnoException).code === 'ENOENT' ? 'no such file' : errorLine(e));
  }
  return parseReferenceCsv(text, file);
}

export function findReference(
  reference: readonly ReferenceRow[],
  row: Pick<Row, 'rig' | 'experiment' | 'method'>,
): ReferenceRow | undefined {
  return reference.find(
    (r) => r.rig === row.rig && r.experiment === row.experiment && r.method === row.method.toLowerCase(),
  );
}

/** Ours beside theirs for every row of ours with a match; undefined when nothing matches. */
export function compareTable(
  rows: readonly Row[],
  reference: readonly ReferenceRow[],
  label: string,
): Table | undefined {
  const headers = [
    'rig',
    'experiment',
    'method',
    'engine',
    'samples ours',
    'samples theirs',
    't_avg ours',
    't_avg theirs',
    'speed ratio',
    'iter ours',
    'iter theirs',
    'E_IQM ours',
    'E_IQM theirs',
    'max E ours',
    'max E theirs',
    'success ours',
  ];
  const out: string[][] = [];
  for (const r of rows) {
    const ref = findReference(reference, r);
    if (!ref) continue;
    out.push([
      r.rig,
      r.experiment,
      r.method,
      r.engine,
      String(r.samples),
      ref.samples === undefined ? '-' : String(ref.samples),
      formatNumber(r.t_avg_s),
      formatNumber(ref.t_avg_s),
      `${formatNumber(ref.t_avg_s / r.t_avg_s)}x`,
      formatNumber(r.iter_avg),
      formatNumber(ref.iter_avg),
      formatNumber(r.E_iqm),
      formatNumber(ref.E_iqm),
      formatNumber(r.E_max),
      formatNumber(ref.E_max),
      formatPercent(r.success_rate),
    ]);
  }
  if (out.length === 0) return undefined;
  return {
    title: `ours beside ${label} (speed ratio = their t_avg / our t_avg; above 1: ours is faster)`,
    headers,
    numeric: headers.map((_, i) => i >= 4),
    rows: out,
  };
}
