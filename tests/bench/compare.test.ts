// --compare reads both CSV layouts of the report's paper folder (results.csv, the report's own
// table; original-measured.csv, the original program re-run) and matches our rows.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { describe, expect, it } from 'vitest';

import { compareTable, findReference, parseReferenceCsv, readReferenceCsv } from '../../bench-node/reference_csv.js';
import type { Row } from '../../bench-node/metrics.js';
import { needsA7, paperDir } from '../helpers/a7.js';

const ours = (over: Partial<Row>): Row => ({
  rig: 'knight',
  experiment: 'random',
  method: 'gn',
  engine: 'wasm',
  goals: 'position',
  samples: 300,
  t_avg_s: 0.01,
  t_median_s: 0.01,
  t_p95_s: 0.02,
  t_p99_s: 0.025,
  t_max_s: 0.03,
  iter_avg: 16,
  E_avg: 0.06,
  E_iqm: 0.04,
  E_max: 0.4,
  success_rate: 0.3,
  unreachable: 0,
  stop_reasons: { converged_E: 90 },
  restarts: 0,
  wobble_during_avg: null,
  wobble_during_max: null,
  wobble_after_avg: null,
  wobble_after_max: null,
  jump_max_deg: null,
  wobble_unreachable_avg: null,
  wobble_unreachable_max: null,
  jumps: null,
  flips: null,
  rot_err_avg_deg: null,
  rot_err_max_deg: null,
  twist_rate: null,
  t_success_median_s: 0.008,
  t_success_p95_s: 0.015,
  success_within_1ms: 0,
  success_within_10ms: 0.2,
  success_within_100ms: 0.3,
  ...over,
});

describe('reference CSVs', () => {
  it('reads the report table (with a bones column) and the re-measured one (with samples)', needsA7, () => {
    const report = readReferenceCsv(resolve(paperDir, 'results.csv'));
    const measured = readReferenceCsv(resolve(paperDir, 'original-measured.csv'));
    expect(report).toHaveLength(30);
    expect(measured).toHaveLength(30);
    const a = findReference(report, { rig: 'knight', experiment: 'random', method: 'GN' })!;
    expect(a.t_avg_s).toBe(0.101948);
    expect(a.samples).toBeUndefined();
    const b = findReference(measured, { rig: 'knight', experiment: 'random', method: 'gn' })!;
    expect(b).toMatchObject({ samples: 300, t_avg_s: 0.0295832, iter_avg: 16.09, E_iqm: 0.0382201 });
  });

  it('prints their t_avg / our t_avg as the speed ratio', () => {
    const ref = parseReferenceCsv('rig,experiment,method,t_avg_s,E_iqm\nknight,random,GN,0.03,0.05\n', 'x.csv');
    const table = compareTable([ours({}), ours({ method: 'lm' })], ref, 'x.csv')!;
    expect(table.rows).toHaveLength(1);
    const cell = (name: string): string => table.rows[0][table.headers.indexOf(name)];
    expect(cell('speed ratio')).toBe('3x');
    expect(cell('t_avg theirs')).toBe('0.03');
    expect(cell('iter theirs')).toBe('-');
    expect(compareTable([ours({ rig: 'beast' })], ref, 'x.csv')).toBeUndefined();
  });

  it('rejects files without the needed columns or with bad numbers, in one line', () => {
    expect(() => parseReferenceCsv('rig,method,t_avg_s\nknight,GN,1\n', 'x.csv')).toThrow(/no "experiment" column/);
    expect(() => parseReferenceCsv('rig,experiment,method,t_avg_s\nknight,random,GN,fast\n', 'x.csv')).toThrow(
      /line 2: t_avg_s "fast"/,
    );
    const dir = mkdtempSync(join(tmpdir(), 'bench-compare-test-'));
    try {
      expect(() => readReferenceCsv(join(dir, 'missing.csv'))).toThrow(/missing\.csv: no such file/);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});
