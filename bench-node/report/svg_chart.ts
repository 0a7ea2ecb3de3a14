// A small grouped bar chart as SVG text, drawn by the project's own code (no chart library):
// one group per rig, one bar per method, a log-scaled value axis.

export interface ChartSeries {
  name: string;
  color: string;
  /** One value per group; NaN or missing draws no bar. */
  values: number[];
}

export interface ChartSpec {
  title: string;
  groups: string[];
  series: ChartSeries[];
  /** Axis label, e.g. "median time per solve (s)". */
  axis: string;
  log: boolean;
  /** Formats a tick value. */
  format: (v: number) => string;
  /** Value range; log axes need min > 0. */
  min: number;
  max: number;
}

const escape = (s: string): string => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

/** The chart as a standalone SVG document (width 760 px). */
export function barChartSvg(spec: ChartSpec): string {
  const width = 760,
    height = 300,
    left = 70,
    right = 10,
    top = 30,
    bottom = 70;
  const plotW = width - left - right,
    plotH = height - top - bottom;
  const toUnit = (v: number): number =>
    spec.log
      ? (Math.log10(v) - Math.log10(spec.min)) / (Math.log10(spec.max) - Math.log10(spec.min))
      : (v - spec.min) / (spec.max - spec.min);
  const y = (v: number): number => top + plotH * (1 - Math.min(1, Math.max(0, toUnit(v))));
  const out: string[] = [
    `<svg xmlns="http://www.w3.org/2000/svg" width="${width}" height="${height}" viewBox="0 0 ${width} ${height}" font-family="sans-serif" font-size="11">`,
    `<rect width="${width}" height="${height}" fill="white"/>`,
    `<text x="${width / 2}" y="18" text-anchor="middle" font-size="13">${escape(spec.title)}</text>`,
  ];
  const ticks: number[] = [];
  if (spec.log)
    for (let e = Math.ceil(Math.log10(spec.min)); e <= Math.floor(Math.log10(spec.max)); e++) ticks.push(10 ** e);
  else for (let k = 0; k <= 4; k++) ticks.push(spec.min + ((spec.max - spec.min) * k) / 4);
  for (const t of ticks) {
    out.push(`<line x1="${left}" x2="${width - right}" y1="${y(t)}" y2="${y(t)}" stroke="#ddd"/>`);
    out.push(`<text x="${left - 4}" y="${y(t) + 4}" text-anchor="end">${escape(spec.format(t))}</text>`);
  }
  out.push(
    `<text transform="translate(14 ${top + plotH / 2}) rotate(-90)" text-anchor="middle">${escape(spec.axis)}</text>`,
  );
  const groupW = plotW / spec.groups.length;
  const barW = (groupW * 0.8) / spec.series.length;
  spec.groups.forEach((g, gi) => {
    const x0 = left + gi * groupW + groupW * 0.1;
    spec.series.forEach((s, si) => {
      const v = s.values[gi];
      if (v === undefined || !Number.isFinite(v)) return;
      const yv = y(spec.log ? Math.max(v, spec.min) : v);
      out.push(
        `<rect x="${(x0 + si * barW).toFixed(1)}" y="${yv.toFixed(1)}" width="${(barW - 1).toFixed(1)}" height="${(top + plotH - yv).toFixed(1)}" fill="${s.color}"><title>${escape(`${s.name}, ${g}: ${spec.format(v)}`)}</title></rect>`,
      );
    });
    out.push(`<text x="${x0 + groupW * 0.4}" y="${top + plotH + 14}" text-anchor="middle">${escape(g)}</text>`);
  });
  spec.series.forEach((s, si) => {
    const x = left + (si % 5) * 135,
      yy = height - 30 + Math.floor(si / 5) * 14;
    out.push(
      `<rect x="${x}" y="${yy - 9}" width="10" height="10" fill="${s.color}"/><text x="${x + 14}" y="${yy}">${escape(s.name)}</text>`,
    );
  });
  out.push('</svg>');
  return `${out.join('\n')}\n`;
}
