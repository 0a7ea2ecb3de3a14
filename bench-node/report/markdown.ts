// Number formats and Markdown tables of docs/benchmarks.md (bench:report).

/** Seconds as microseconds: two decimals below 10 us, one above. */
export const us = (s: number): string => (s * 1e6 < 10 ? (s * 1e6).toFixed(2) : (s * 1e6).toFixed(1));
/** A fraction as a percentage with one decimal. */
export const pct = (x: number): string => `${(100 * x).toFixed(1)}%`;
/** A Markdown table. */
export const table = (head: string[], rows: string[][]): string =>
  [
    `| ${head.join(' | ')} |`,
    `| ${head.map(() => '---').join(' | ')} |`,
    ...rows.map((r) => `| ${r.join(' | ')} |`),
  ].join('\n');
