// A fuzz run: N cases spread over the kinds, run on a pool of workers with a watchdog, in a
// scratch folder that is removed afterwards.
import { CasePool } from './case_pool.js';
import type { CaseId, CaseReport, FuzzKind } from './case_id.js';
import { createFixture, removeFixture } from './fixture.js';

export interface FuzzOptions {
  seed: number;
  /** Cases in all, spread evenly over `kinds` (ignored with `only`). */
  cases: number;
  kinds: readonly FuzzKind[];
  /** Run only this case number of each kind (to replay it). */
  only?: number;
  workers: number;
  /** A case running longer than this is a hang. */
  hangSeconds: number;
  onReport?: (report: CaseReport) => void;
}

/** The cases of a run: kind by kind in turn (case 0 of each kind, then case 1...), numbered per kind. */
function caseIds(o: Pick<FuzzOptions, 'seed' | 'cases' | 'kinds' | 'only'>): CaseId[] {
  if (o.only !== undefined) return o.kinds.map((kind) => ({ kind, seed: o.seed, index: o.only! }));
  return Array.from({ length: o.cases }, (_, k) => ({
    kind: o.kinds[k % o.kinds.length],
    seed: o.seed,
    index: Math.floor(k / o.kinds.length),
  }));
}

/** Runs the cases of `o`; their reports in case order. */
export async function runFuzz(o: FuzzOptions): Promise<CaseReport[]> {
  const fixture = await createFixture();
  try {
    const pool = await CasePool.create(o.workers, fixture, o.hangSeconds);
    try {
      return await pool.runAll(caseIds(o), o.onReport ?? (() => undefined));
    } finally {
      await pool.close();
    }
  } finally {
    removeFixture(fixture);
  }
}
