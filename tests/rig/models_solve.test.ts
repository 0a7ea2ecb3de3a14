// Every project model loads in Node and the default method (lm, restarts on) solves 100 random
// reachable targets on it: angles uniform in [-360, 360] clamped to the limits, start at rest,
// success when E < errorTolerance by the shared tolerance rule (web/src/rig/tolerances.ts). No clock: the
// solves have no time budget and an iteration cap (restarts included) far above what they take,
// so the result does not depend on the machine's speed or load.
import { readdirSync } from 'node:fs';
import { resolve } from 'node:path';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { defaultTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { randomAngles, seeded } from '../helpers/a7.js';

const modelsDir = resolve(import.meta.dirname, '../../web/public/models');
const models = readdirSync(modelsDir)
  .filter((f) => f.endsWith('.glb'))
  .sort();
/** Iterations of one solve, restarts included. The most any of these solves took: 3030 (hand.glb, 438 restarts). */
const MAX_ITERATIONS = 20000;
let ik: IkCoreModule;
const owned: { dispose(): void }[] = [];

beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => owned.reverse().forEach((o) => o.dispose()));

describe('the default method on the project models', () => {
  it('has the six models', () => {
    expect(models).toEqual(['beast.glb', 'character.glb', 'hand.glb', 'knight.glb', 'lamp.glb', 'robot-arm.glb']);
  });

  it.each(models)('%s: 100 random reachable targets, all solved, inside the limits', async (file) => {
    const loaded = await loadRigFromPath(resolve(modelsDir, file));
    const rig = new IkRig(ik, loaded.spec);
    owned.push(rig);
    const tol = defaultTolerances(loaded.name, false, rigSize(rig.boneTips(new Float64Array(rig.numAngles))));
    const solver = new IkSolver(rig, 'lm', {
      gradientTolerance: tol.gradientTolerance,
      errorTolerance: tol.errorTolerance,
      timeBudgetSeconds: 0,
      maxIterations: MAX_ITERATIONS,
    });
    owned.push(solver);
    const rand = seeded(404);
    const rest = new Float64Array(rig.numAngles);
    for (let s = 0; s < 100; s++) {
      const target = rig.tips(randomAngles(rig.spec, rand));
      const r = solver.solve(rest, target);
      expect(r.E, `${file} target ${s}: ${r.stopReason} after ${r.restarts} restarts`).toBeLessThan(tol.errorTolerance);
      for (let i = 0; i < r.angles.length; i++) {
        expect(r.angles[i]).toBeGreaterThanOrEqual(rig.lower[i]);
        expect(r.angles[i]).toBeLessThanOrEqual(rig.upper[i]);
      }
    }
  });
});
