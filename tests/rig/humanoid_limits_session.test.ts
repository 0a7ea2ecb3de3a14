// The page's "humanoid limits" switch below the DOM (LiveRig and IkSession): a rig the importer
// gave humanoid limits starts with them, and switching to the file's own limits and back keeps the
// end effectors and targets, clamps the pose into the new limits and frees the old session.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { LiveRig } from '../../web/src/view/live_rig.js';
import type { RigSource } from '../../web/src/view/rig_source.js';
import { IkSession } from '../../web/src/live/session.js';
import type { SolveSettings } from '../../web/src/live/method_solver.js';
import { humanoidLimits } from '../../web/src/rig/humanoid/humanoid_limits.js';
import { mixamoHumanoid } from '../helpers/limits_characters.js';
import { disposeAfterAll } from '../helpers/owned.js';

let ik: IkCoreModule;
let loaded: RigSource;
const keep = disposeAfterAll();
beforeAll(async () => {
  ik = await loadIkNode();
  const h = await mixamoHumanoid();
  const { lower, upper } = humanoidLimits(h.spec, h.map, new Array<boolean>(h.spec.parents.length).fill(false));
  loaded = {
    name: 'character',
    format: 'glb',
    spec: h.spec,
    warnings: [],
    makeMesh: null,
    humanoidLimits: { lower, upper },
  };
});

const within = (angles: Float64Array, lower: Float64Array, upper: Float64Array): boolean =>
  angles.every((a, k) => a >= lower[k] && a <= upper[k]);

async function liveRig(rig: RigSource, humanoid = true): Promise<LiveRig> {
  return keep(await LiveRig.create(ik, rig, false, humanoid));
}

describe('the humanoid limits switch', () => {
  it("starts with the humanoid limits, or the file's own when asked", async () => {
    const on = await liveRig(loaded);
    expect(on.hasHumanoidLimits).toBe(true);
    expect(on.session.spec.lower).toEqual(loaded.humanoidLimits!.lower);
    const off = await liveRig(loaded, false);
    expect(off.session.spec.upper).toEqual(loaded.spec.upper);
  });

  it('switching keeps effectors and targets, clamps the pose, and frees the old session', async () => {
    const live = await liveRig(loaded, false);
    const s0 = live.session;
    s0.setEffectors([s0.effectors()[0], s0.effectors()[1]]);
    s0.targets[0] += 0.05;
    // A pose outside the anatomical limits: every angle at 100 degrees.
    s0.angles.fill(100);
    const effectors = Array.from(s0.effectors()),
      targets = s0.targets.slice();
    const alive = IkSession.alive.sessions;

    live.useHumanoidLimits(true);
    const s1 = live.session;
    expect(s1).not.toBe(s0);
    expect(s0.rig.isDisposed).toBe(true);
    expect(IkSession.alive.sessions).toBe(alive);
    expect(Array.from(s1.effectors())).toEqual(effectors);
    expect(s1.targets).toEqual(targets);
    const { lower, upper } = loaded.humanoidLimits!;
    expect(s1.spec.lower).toEqual(lower);
    expect(within(s1.angles, lower, upper)).toBe(true);

    // Solving now stays inside the humanoid limits; switching back keeps that pose as it is.
    const settings: SolveSettings = {
      ...live.tolerances(),
      maxIterations: 1000,
      timeBudgetMs: 0,
      restarts: 0,
      paperMode: false,
    };
    const out = s1.solve('lm', settings);
    expect(within(out.angles, lower, upper)).toBe(true);
    live.useHumanoidLimits(false);
    expect(live.session.spec.upper).toEqual(loaded.spec.upper);
    expect(live.session.angles).toEqual(out.angles);
  });

  it('a rig without humanoid limits has none to switch to', async () => {
    const live = await liveRig({ ...loaded, humanoidLimits: undefined });
    expect(live.hasHumanoidLimits).toBe(false);
    expect(live.session.spec.upper).toEqual(loaded.spec.upper);
  });
});
