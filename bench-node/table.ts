// Tables: the report's columns per rig and experiment, in plain text (aligned) or Markdown.
import type { Row } from './metrics.js';
import { isDragging } from './target_set.js';
import type { TimeToSuccess } from './time_to_success.js';

export type TableFormat = 'text' | 'markdown';

export interface Table {
  title: string;
  headers: string[];
  /** Columns whose cells are right-aligned (numbers). */
  numeric: boolean[];
  rows: string[][];
}

/** A number as the report prints it: 6 significant digits, exponent form below 1e-3. */
export function formatNumber(x: number | null | undefined): string {
  if (x === null || x === undefined || Number.isNaN(x)) return '-';
  if (!Number.isFinite(x)) return x > 0 ? 'inf' : '-inf';
  if (x === 0) return '0';
  if (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e7) {
    const [mantissa, exponent] = x.toExponential(5).split('e');
    const e = Number(exponent);
    const m = mantissa.includes('.') ? mantissa.replace(/0+$/, '').replace(/\.$/, '') : mantissa;
    return `${m}e${e < 0 ? '-' : '+'}${String(Math.abs(e)).padStart(2, '0')}`;
  }
  const s = x.toPrecision(6);
  return s.includes('.') ? s.replace(/0+$/, '').replace(/\.$/, '') : s;
}

export function formatPercent(x: number | null | undefined): string {
  if (x === null || x === undefined || !Number.isFinite(x)) return '-';
  return `${(100 * x).toFixed(1)}%`;
}

/** "converged_E 180, timeout 20", most frequent first. */
export function formatStopReasons(counts: Record<string, number>): string {
  return Object.entries(counts)
    .sort((a, b) => b[1] - a[1] || a[0].localeCompare(b[0]))
    .map(([reason, n]) => `${reason} ${n}`)
    .join(', ');
}

/** A count, or '-' when there is none (null: not measured). */
function formatCount(n: number | null): string {
  return n === null ? '-' : String(n);
}

/**
 * The results table of one rig and experiment. Drag, reach and gestures add the unreachable steps
 * (left out of success), the wobble (also over the unreachable steps), the jumps, the flips and
 * the largest angle jump; --goals pose the orientation errors (degrees).
 */
export function resultsTable(rows: readonly Row[]): Table {
  const first = rows[0];
  const drag = isDragging(first.experiment);
  const pose = first.goals === 'pose';
  const headers = [
    'method',
    'engine',
    'samples',
    'restarts',
    't_avg',
    'iter_avg',
    'E_avg',
    'E_IQM',
    'max E',
    'success',
    't_median',
    't_p95',
    't_max',
  ];
  if (pose) headers.push('rot_err_avg_deg', 'rot_err_max_deg');
  if (drag)
    headers.push(
      'unreachable',
      'wobble_during avg',
      'wobble_during max',
      'wobble_after avg',
      'wobble_after max',
      'wobble_unreach max',
      'jumps',
      'flips',
      'jump_max_deg',
    );
  headers.push('stop reasons');
  const numeric = headers.map((h) => !['method', 'engine', 'stop reasons'].includes(h));
  return {
    title: `${first.rig}, ${first.experiment} targets${pose ? ' (pose goals)' : ''}`,
    headers,
    numeric,
    rows: rows.map((r) => {
      const cells = [
        r.method,
        r.engine,
        String(r.samples),
        String(r.restarts),
        formatNumber(r.t_avg_s),
        formatNumber(r.iter_avg),
        formatNumber(r.E_avg),
        formatNumber(r.E_iqm),
        formatNumber(r.E_max),
        formatPercent(r.success_rate),
        formatNumber(r.t_median_s),
        formatNumber(r.t_p95_s),
        formatNumber(r.t_max_s),
      ];
      if (pose) cells.push(formatNumber(r.rot_err_avg_deg), formatNumber(r.rot_err_max_deg));
      if (drag)
        cells.push(
          String(r.unreachable),
          formatNumber(r.wobble_during_avg),
          formatNumber(r.wobble_during_max),
          formatNumber(r.wobble_after_avg),
          formatNumber(r.wobble_after_max),
          formatNumber(r.wobble_unreachable_max),
          formatCount(r.jumps),
          formatCount(r.flips),
          formatNumber(r.jump_max_deg),
        );
      cells.push(formatStopReasons(r.stop_reasons));
      return cells;
    }),
  };
}

/** Groups rows by (rig, experiment), keeping first-seen order. */
export function groupRows<R extends Row>(rows: readonly R[]): R[][] {
  const groups = new Map<string, R[]>();
  for (const r of rows) {
    const key = `${r.rig}\u0000${r.experiment}`;
    const g = groups.get(key);
    if (g) g.push(r);
    else groups.set(key, [r]);
  }
  return [...groups.values()];
}

/** Speed of each engine against the first one, per (rig, experiment, method): mean and median time. */
export function engineRatioTable(rows: readonly Row[], engines: readonly string[]): Table | undefined {
  if (engines.length < 2) return undefined;
  const [base, ...others] = engines;
  const headers = [
    'rig',
    'experiment',
    'method',
    ...engines.map((e) => `t_avg ${e}`),
    ...others.map((e) => `t_avg ${base} / ${e}`),
    ...engines.map((e) => `t_median ${e}`),
    ...others.map((e) => `t_median ${base} / ${e}`),
  ];
  const out: string[][] = [];
  const seen = new Set<string>();
  for (const r of rows) {
    const key = `${r.rig}\u0000${r.experiment}\u0000${r.method}`;
    if (seen.has(key)) continue;
    seen.add(key);
    const byEngine = engines.map((e) =>
      rows.find((x) => x.rig === r.rig && x.experiment === r.experiment && x.method === r.method && x.engine === e),
    );
    if (byEngine.some((x) => x === undefined)) continue;
    const cells = (t: number[]): string[] => [
      ...t.map(formatNumber),
      ...t.slice(1).map((x) => `${formatNumber(t[0] / x)}x`),
    ];
    out.push([
      r.rig,
      r.experiment,
      r.method,
      ...cells(byEngine.map((x) => x!.t_avg_s)),
      ...cells(byEngine.map((x) => x!.t_median_s)),
    ]);
  }
  if (out.length === 0) return undefined;
  return {
    title: `engines: time ${base} / time ${others.join(', ')} (above 1: ${base} is slower)`,
    headers,
    numeric: headers.map((_, i) => i >= 3),
    rows: out,
  };
}

export function renderTable(table: Table, format: TableFormat): string {
  if (format === 'markdown') {
    const esc = (s: string): string => s.replace(/\|/g, '\\|');
    const lines = [
      `| ${table.headers.map(esc).join(' | ')} |`,
      `| ${table.numeric.map((n) => (n ? '---:' : '---')).join(' | ')} |`,
      ...table.rows.map((row) => `| ${row.map(esc).join(' | ')} |`),
    ];
    return `### ${table.title}\n\n${lines.join('\n')}\n`;
  }
  const widths = table.headers.map((h, c) => Math.max(h.length, ...table.rows.map((row) => row[c].length)));
  const line = (cells: string[]): string =>
    cells
      .map((cell, c) => (table.numeric[c] ? cell.padStart(widths[c]) : cell.padEnd(widths[c])))
      .join('  ')
      .trimEnd();
  return (
    [table.title, line(table.headers), widths.map((w) => '-'.repeat(w)).join('  '), ...table.rows.map(line)].join(
      '\n',
    ) + '\n'
  );
}

/** A row as timeToSuccessTable() reads it. */
export interface TimedRow extends TimeToSuccess {
  rig: string;
  experiment: string;
  method: string;
  engine: string;
  success_rate: number;
}

/** One table of every row's time to success (after the results tables). */
export function timeToSuccessTable(rows: readonly TimedRow[]): Table | undefined {
  if (rows.length === 0) return undefined;
  const headers = [
    'rig',
    'experiment',
    'method',
    'engine',
    'success',
    't_success median',
    't_success p95',
    '≤ 1 ms',
    '≤ 10 ms',
    '≤ 100 ms',
  ];
  return {
    title: 'time to success (successful solves only; shares of all reachable samples)',
    headers,
    numeric: headers.map((_, i) => i >= 4),
    rows: rows.map((r) => [
      r.rig,
      r.experiment,
      r.method,
      r.engine,
      formatPercent(r.success_rate),
      formatNumber(r.t_success_median_s),
      formatNumber(r.t_success_p95_s),
      formatPercent(r.success_within_1ms),
      formatPercent(r.success_within_10ms),
      formatPercent(r.success_within_100ms),
    ]),
  };
}
