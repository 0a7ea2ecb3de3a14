// IkRig.restartStart(k, seed) gives the point a solver restarts from, so a harness can restart
// other solvers (the bench's peers) from the same points.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { straightLimb } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});

describe('restart starts', () => {
  it("are where a solver's restart goes", () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    for (const seed of [1, 7]) {
      // The straight limb with its target straight behind it: a stationary start, so with no escape
      // start() moves on at once by a restart.
      const solver = keep(new IkSolver(rig, 'lm', { restarts: 1, escapeSaddles: false, timeBudgetSeconds: 0, seed }));
      solver.start(new Float64Array(rig.numAngles), [-2, 0, 0]);
      expect(solver.result().restarts).toBe(1);
      expect(Array.from(solver.angles())).toEqual(Array.from(rig.restartStart(1, seed)));
    }
  });

  it('lie inside the limits, follow k and the seed, and refuse bad indices', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const a = rig.restartStart(1),
      b = rig.restartStart(2),
      c = rig.restartStart(1, 2);
    for (const p of [a, b, c]) p.forEach((x, i) => expect(x >= rig.lower[i] && x <= rig.upper[i]).toBe(true));
    expect(Array.from(a)).toEqual(Array.from(rig.restartStart(1)));
    expect(Array.from(a)).not.toEqual(Array.from(b));
    expect(Array.from(a)).not.toEqual(Array.from(c));
    expect(() => rig.restartStart(0)).toThrow(/restart index/);
    expect(() => rig.restartStart(1.5)).toThrow(/restart index/);
    expect(() => rig.restartStart(1, -1)).toThrow(/seed/);
  });
});
