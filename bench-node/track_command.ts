// `npm run bench -- --rig FILE --experiment track [--clips NAME,...|all] [--points 3|6] [--noise SHARE]`: every
// rig's clips through the avatar solver (track.ts), a table on stdout, the rows as JSON and CSV.
import type { IkCoreModule } from '#ik/module.js';
import { BenchError } from './errors.js';
import type { BenchOptions } from './options.js';
import { csvTable, writeJson, writeText } from './outputs.js';
import { loadBenchRig } from './rigs.js';
import { formatNumber, renderTable, type Table } from './table.js';
import { runTrack, type TrackRow } from './track.js';

/** The CSV's columns, in order (the JSON rows carry the same fields). */
const columns: ReadonlyArray<keyof TrackRow & string> = [
  'rig',
  'experiment',
  'method',
  'clip',
  'frames',
  'points',
  'noise',
  'success_rate',
  'reachable',
  'success_reachable',
  'mpjpe',
  'mpjpe_upper',
  'jitter_ratio',
  'flips',
  'foot_slide',
  'median_us',
  'p99_us',
];

/** Runs the track experiment of `opts` (opts.track set); returns the rows after printing and writing them. */
export async function runTrackCommand(
  opts: BenchOptions,
  ik: IkCoreModule,
  out: (text: string) => void,
  command: string,
): Promise<TrackRow[]> {
  const track = opts.track!;
  const rows: TrackRow[] = [];
  for (const entry of opts.rigs) {
    const rig = await loadBenchRig(entry, opts.humanoidLimits);
    if (!rig.humanoid || !rig.boneNodes)
      throw new BenchError(
        `${entry}: the track experiment needs a glTF humanoid the importer recognises (npm run rig -- FILE shows the mapping)`,
        2,
      );
    try {
      rows.push(
        ...(await runTrack(
          ik,
          { name: rig.name, path: rig.path, spec: rig.spec, humanoid: rig.humanoid, boneNodes: rig.boneNodes },
          track.clips,
          { points: track.points, noise: track.noise, seed: opts.seed },
        )),
      );
    } catch (e) {
      if (e instanceof BenchError) throw e;
      throw new BenchError(`${entry}: ${e instanceof Error ? e.message.split('\n')[0] : String(e)}`);
    }
  }
  out(renderTable(trackTable(rows), 'text'));
  const run = { command, date: new Date().toISOString().slice(0, 10), node: process.versions.node };
  if (opts.json) writeJson(opts.json, rows, run);
  if (opts.csv) writeText(opts.csv, csvTable(rows, columns));
  return rows;
}

function trackTable(rows: readonly TrackRow[]): Table {
  const percent = (x: number): string => `${(100 * x).toFixed(1)}%`;
  return {
    title:
      'track: the tracked points (3: head and hands; 6: and hips and feet) drive the avatar; errors as shares of the height',
    headers: [
      'rig',
      'clip',
      'frames',
      'points',
      'noise',
      'success',
      'reachable',
      'success_reachable',
      'mpjpe',
      'mpjpe_upper',
      'jitter_ratio',
      'flips',
      'foot_slide',
      'median_us',
      'p99_us',
    ],
    numeric: [false, false, true, true, true, true, true, true, true, true, true, true, true, true, true],
    rows: rows.map((r) => [
      r.rig,
      r.clip,
      String(r.frames),
      String(r.points),
      percent(r.noise),
      percent(r.success_rate),
      percent(r.reachable),
      r.success_reachable === null ? '-' : percent(r.success_reachable),
      percent(r.mpjpe),
      percent(r.mpjpe_upper),
      formatNumber(r.jitter_ratio),
      String(r.flips),
      percent(r.foot_slide),
      r.median_us.toFixed(1),
      r.p99_us.toFixed(1),
    ]),
  };
}
