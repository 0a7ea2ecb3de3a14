// What undo, redo and pose files keep of a live session (web/src/live/pose_state.ts): a captured
// state restored after edits gives back the exact pose, effectors, targets and goals; the copy is
// private (later edits do not reach it); angles are clamped into the limits in use; a state from a
// rig with another number of bones is refused and changes nothing.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { capturePose, restorePose, samePose } from '../../web/src/live/pose_state.js';
import { IkSession } from '../../web/src/live/session.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { sketchRig, straightLimb } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();
beforeAll(async () => {
  ik = await loadIkNode();
});

const threeBones = () =>
  sketchRig(
    [
      { parent: -1, at: [0, 0, 0], length: 1 },
      { parent: 0, at: [1, 0, 0], length: 1, lower: [-180, -90, -180], upper: [180, 90, 180] },
      { parent: 1, at: [2, 0, 0], length: 1 },
    ],
    [2],
  );

describe('pose states', () => {
  it('restores the pose, effectors, targets and goals exactly, from a private copy', () => {
    const s = keep(new IkSession(ik, threeBones()));
    s.angles.set([10, 20, 30, 0, 45, 0, 5, -5, 5]);
    s.targets[0] = 1.5;
    s.setOrientationGoal(0, true);
    const saved = capturePose(s);

    s.setEffectors([1, 2]);
    s.angles.fill(0);
    s.targets[1] = 9;
    s.goals.rotations[0] = 0.5;
    s.goals.setPoles([1], [0, 1, 0]);
    expect(samePose(saved, capturePose(s))).toBe(false);
    expect(saved.angles[0]).toBe(10);
    expect(saved.effectors).toEqual(Int32Array.from([2]));

    restorePose(s, saved);
    expect(samePose(saved, capturePose(s))).toBe(true);
    expect(Array.from(s.effectors())).toEqual([2]);
    expect(s.goals.orientation[0]).toBe(1);
    expect(s.goals.poleBones.length).toBe(0);
    s.targets[0] = 7; // the session's arrays are not the state's
    expect(saved.targets[0]).toBe(1.5);
  });

  it("clamps angles into the limits in use, and refuses another rig's state", () => {
    const s = keep(new IkSession(ik, threeBones()));
    const state = capturePose(s);
    state.angles[4] = 120; // bone 1's Z angle: limits [-90, 90]
    restorePose(s, state);
    expect(s.angles[4]).toBe(90);

    const other = keep(new IkSession(ik, straightLimb()));
    const before = capturePose(s);
    expect(() => restorePose(s, capturePose(other))).toThrow(/2 bones, the rig 3/);
    expect(samePose(before, capturePose(s))).toBe(true);
  });
});
