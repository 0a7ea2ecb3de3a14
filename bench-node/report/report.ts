// npm run bench:report: runs the whole measurement set and writes docs/benchmarks.md
// with its tables, ratios and two SVG charts (docs/benchmarks-time.svg, -success.svg).
// Every number comes from this run, on this machine (measure.ts). Sets:
//   1. the default method (lm, restarts on) on the five A7 rigs and every project rig,
//      random and incremental, WebAssembly and native (`npm run bench`);
//   2. gd, bfgs, gn in normal mode on the A7 rigs beside the original program's re-measured times
//      (original-measured.csv in the report's paper folder, beside the A7 rigs' folder);
//   3. the peers three-ccd and closed-chain-ik on the A7 rigs;
//   4. the solver core alone, native against WebAssembly (wasm/tools/solver_speed, one program);
//   5. time per iteration on synthetic chains and trees (wasm/tools/scale_bench);
//   6. the WebAssembly heap after 10^3 and 10^6 solves (bench-node/report/heap_growth.ts);
//   7. lm while a user drags: the drag and reach experiments on every rig (report/dragging.ts).
// Each table's "met" column checks a target. The document starts with what was missed; the
// command prints that too and exits 1 when anything was missed.
// Usage: npx tsx bench-node/report/report.ts --a7-dir DIR [--samples N] [--out DIR]
//   (scripts/bench-report.sh passes the A7 folder; default 1000 samples per rig and experiment,
//   gd 100; the files go to docs/)
import { mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { cpus, tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { Command, InvalidArgumentError } from 'commander';

import { reportTolerances } from '#rig/tolerances.js';
import { parseReferenceCsv } from '../reference_csv.js';
import { projectRigNames } from '../rigs.js';
import { charts } from './charts.js';
import { draggingSection } from './dragging.js';
import { measure, type Measurements } from './measure.js';
import {
  allRowsSection,
  defaultSection,
  enginesSection,
  originalSection,
  peersSection,
  scaleAndMemorySections,
} from './sections.js';
import { Verdicts } from './verdicts.js';

interface ReportOptions {
  a7Dir: string;
  samples: number;
  out: string;
}

function parseArgs(argv: string[]): ReportOptions {
  const count = (value: string): number => {
    const n = Number(value);
    if (!Number.isInteger(n) || n < 1) throw new InvalidArgumentError('not an integer >= 1');
    return n;
  };
  return new Command('bench:report')
    .description('Runs the benchmark set and writes docs/benchmarks.md and its charts.')
    .requiredOption(
      '--a7-dir <dir>',
      "the folder of the report's five A7 rigs (its paper folder is ../../paper from there)",
    )
    .option('--samples <n>', 'samples per rig and experiment (gd: at most 100)', count, 1000)
    .option('--out <dir>', 'where the document and the charts go', 'docs')
    .parse(argv, { from: 'user' })
    .opts<ReportOptions>();
}

/** The report's tolerances (gradient / E), rigs with the same ones together: "ikea-lamp, ...: 0.0001 / 0.0002; beast: 0.01 / 0.002". */
function tolerancesText(): string {
  const groups = new Map<string, string[]>();
  for (const [rig, t] of Object.entries(reportTolerances)) {
    const values = `${t.gradientTolerance} / ${t.errorTolerance}`;
    groups.set(values, [...(groups.get(values) ?? []), rig]);
  }
  return [...groups].map(([values, rigs]) => `${rigs.join(', ')}: ${values}`).join('; ');
}

/** The whole document. */
function document(m: Measurements, opts: ReportOptions, a7Names: readonly string[], verdicts: Verdicts): string[] {
  const gdSamples = Math.min(100, opts.samples);
  const originalFile = resolve(opts.a7Dir, '../../paper/original-measured.csv');
  const reference = parseReferenceCsv(readFileSync(originalFile, 'utf8'), originalFile);
  const body = [
    ...defaultSection(m, verdicts),
    ...originalSection(m, reference, 'original-measured.csv', verdicts),
    ...enginesSection(m, a7Names, verdicts),
    ...peersSection(m, a7Names, verdicts),
    ...scaleAndMemorySections(m, verdicts),
    ...draggingSection(m.dragging, verdicts),
    ...allRowsSection(m),
  ];
  const command = `npm run bench:report${opts.samples !== 1000 ? ` -- --samples ${opts.samples}` : ''}`;
  return [
    '# Benchmarks',
    '',
    `Made by \`${command}\` on ${new Date().toISOString().slice(0, 10)}: ${cpus()[0]?.model ?? 'unknown CPU'}, ${cpus().length} cores, Node ${process.version}. Target sets, tolerances and metrics as in the report's protocol (PROTOCOL.md; tolerances: ${tolerancesText()}; project rigs scaled by size, see bench-node/README.md); 1 s per solve; ${opts.samples} samples per rig and experiment (gd ${gdSamples}). Times are per solve, measured around the call a user makes (WebAssembly: through \`IkSolver\` in Node).`,
    '',
    ...verdicts.summary(),
    '',
    '![median time per solve](benchmarks-time.svg)',
    '',
    '![success rate](benchmarks-success.svg)',
    '',
    ...body,
  ];
}

const opts = parseArgs(process.argv.slice(2));
const a7Names = Object.keys(reportTolerances);
const work = join(tmpdir(), `ik-bench-report-${process.pid}`);
mkdirSync(work, { recursive: true });
mkdirSync(opts.out, { recursive: true });
try {
  const m = await measure({
    samples: opts.samples,
    gdSamples: Math.min(100, opts.samples),
    a7Rigs: a7Names.map((n) => join(opts.a7Dir, `${n}.json`)),
    projectRigs: projectRigNames,
    work,
  });
  const verdicts = new Verdicts();
  const md = document(m, opts, a7Names, verdicts);
  const { time, success } = charts(
    [...m.defaults.filter((r) => r.engine === 'wasm'), ...m.classic, ...m.peers],
    a7Names,
  );
  writeFileSync(join(opts.out, 'benchmarks.md'), `${md.join('\n')}\n`);
  writeFileSync(join(opts.out, 'benchmarks-time.svg'), time);
  writeFileSync(join(opts.out, 'benchmarks-success.svg'), success);
  process.stderr.write(
    `bench:report: wrote ${['benchmarks.md', 'benchmarks-time.svg', 'benchmarks-success.svg'].map((f) => join(opts.out, f)).join(', ')}\n`,
  );
  process.stderr.write(
    `bench:report: ${verdicts
      .summary()
      .filter((l) => l !== '')
      .join('\nbench:report: ')}\n`,
  );
  process.exitCode = verdicts.missed.length > 0 ? 1 : 0;
} finally {
  rmSync(work, { recursive: true, force: true });
}
