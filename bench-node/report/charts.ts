// The two charts of docs/benchmarks.md (bench:report): median time and success rate per method
// on the A7 rigs, random targets, WebAssembly (the peers: JavaScript).
import type { Row } from '../metrics.js';
import { barChartSvg } from './svg_chart.js';

const colors: Record<string, string> = {
  lm: '#1b9e77',
  gn: '#d95f02',
  bfgs: '#7570b3',
  gd: '#e7298a',
  'three-ccd': '#66a61e',
  'closed-chain-ik': '#e6ab02',
};
const methods = Object.keys(colors);

/** The charts as SVG text: {time, success}; `rows` are any rows, `a7Names` the groups. */
export function charts(rows: readonly Row[], a7Names: readonly string[]): { time: string; success: string } {
  const pick = (method: string, value: (r: Row) => number): number[] =>
    a7Names.map((rig) => {
      const r = rows.find(
        (x) => x.rig === rig && x.experiment === 'random' && x.method === method && x.engine !== 'native',
      );
      return r ? value(r) : NaN;
    });
  const groups = [...a7Names];
  return {
    time: barChartSvg({
      title: 'Median time per solve, random targets (WebAssembly / JavaScript)',
      groups,
      axis: 'seconds (log scale)',
      log: true,
      min: 1e-6,
      max: 1,
      format: (v) => (v >= 1e-3 ? `${v * 1e3} ms` : `${Math.round(v * 1e6)} us`),
      series: methods.map((m) => ({ name: m, color: colors[m], values: pick(m, (r) => r.t_median_s) })),
    }),
    success: barChartSvg({
      title: 'Success rate (final E < error tolerance), random targets',
      groups,
      axis: 'success',
      log: false,
      min: 0,
      max: 1,
      format: (v) => `${Math.round(v * 100)}%`,
      series: methods.map((m) => ({ name: m, color: colors[m], values: pick(m, (r) => r.success_rate) })),
    }),
  };
}
