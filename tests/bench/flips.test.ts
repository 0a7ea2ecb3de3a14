// Flips (flips.ts): a limb's bend plane reversed or turned past 90 degrees in one step, and a limb
// bent against its anatomical direction, on a hand-made chain; and on humanoids, that the
// importer's anatomical flexion is the direction flips.ts calls anatomical.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { bentAgainst, flipLimbs, isFlip, planeTurnDeg, type FlipLimb } from '../../bench-node/flips.js';
import { StepMeasurer } from '../../bench-node/step_measures.js';
import { randomAngles } from '../../bench-node/targets.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import type { HumanoidMap } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { seeded } from '../helpers/a7.js';
import { mixamoCharacterGlb } from '../helpers/limits_characters.js';
import { sketchRig } from '../../scripts/rig_files/rig_builder.js';

const ik = await loadIkNode();

// Three bones of length 1 along +x; the effector is bone 2's tip, so the limb is bone 1 (its
// parent): root (0,0,0), joint (1,0,0), tip (2,0,0) at rest.
const chain = sketchRig(
  [
    { parent: -1, at: [0, 0, 0], length: 1 },
    { parent: 0, at: [1, 0, 0], length: 1 },
    { parent: 1, at: [2, 0, 0], length: 1 },
  ],
  [2],
);
let rig: IkRig;
beforeAll(() => {
  rig = new IkRig(ik, chain);
});
afterAll(() => rig.dispose());

/** Poses of the chain with bone 0 at `upper` and bone 1 at `lower` (XZX degrees; the middle one bends about z). */
const poses = (lower: number[], upper = [0, 0, 0]): Float64Array => rig.poses([...upper, ...lower, 0, 0, 0]);

describe('a flip on a hand-made limb', () => {
  it('the limb of a rig without a humanoid is the effector bone parent, with no anatomy', () => {
    expect(flipLimbs(chain, null)).toEqual([{ bone: 1, hinge: null }]);
  });

  it('is a bend plane reversed, or turned by more than 90 degrees, in one step', () => {
    const [limb] = flipLimbs(chain, null);
    expect(planeTurnDeg(chain, limb, poses([0, 30, 0]), poses([0, -30, 0]))).toBeCloseTo(180, 9);
    expect(isFlip(chain, [limb], poses([0, 30, 0]), poses([0, -30, 0]))).toBe(true);
    // Bending further in the same plane turns nothing.
    expect(planeTurnDeg(chain, limb, poses([0, 30, 0]), poses([0, 60, 0]))).toBeCloseTo(0, 6);
    expect(isFlip(chain, [limb], poses([0, 30, 0]), poses([0, 60, 0]))).toBe(false);
    // Twisting the bent limb about the upper bone turns its plane by the twist.
    expect(planeTurnDeg(chain, limb, poses([0, 30, 0]), poses([100, 30, 0]))).toBeCloseTo(100, 9);
    expect(isFlip(chain, [limb], poses([0, 30, 0]), poses([100, 30, 0]))).toBe(true);
    expect(isFlip(chain, [limb], poses([0, 30, 0]), poses([80, 30, 0]))).toBe(false);
    // A limb within 5 degrees of straight has no plane: no flip through straight in small steps.
    expect(planeTurnDeg(chain, limb, poses([0, 30, 0]), poses([0, -4, 0]))).toBeNaN();
    expect(isFlip(chain, [limb], poses([0, 30, 0]), poses([0, -4, 0]))).toBe(false);
  });

  it('is a limb bent against its anatomical direction, the hinge carried by the upper bone', () => {
    const limb: FlipLimb = { bone: 1, hinge: [0, 0, 1] }; // anatomical: bending about +z
    expect(bentAgainst(chain, limb, poses([0, 30, 0]))).toBe(false);
    expect(bentAgainst(chain, limb, poses([0, -30, 0]))).toBe(true);
    expect(bentAgainst(chain, limb, poses([0, -4, 0]))).toBe(false); // too straight to tell
    // From straight (no plane to turn) to bent the wrong way: a flip all the same.
    expect(isFlip(chain, [limb], poses([0, 0, 0]), poses([0, -30, 0]))).toBe(true);
    expect(isFlip(chain, [limb], poses([0, 0, 0]), poses([0, 30, 0]))).toBe(false);
    // The whole limb turned over by its upper bone: the same bend is still the anatomical one.
    expect(bentAgainst(chain, limb, poses([0, 30, 0], [180, 0, 0]))).toBe(false);
    expect(bentAgainst(chain, limb, poses([0, -30, 0], [180, 0, 0]))).toBe(true);
    // The step measures count it.
    const measurer = new StepMeasurer(chain, rig, [limb]);
    expect(measurer.measure([0, 0, 0, 0, 0, 0, 0, 0, 0], [0, 0, 0, 0, -30, 0, 0, 0, 0]).flip).toBe(1);
    expect(measurer.measure([0, 0, 0, 0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 30, 0, 0, 0, 0]).flip).toBe(0);
  });
});

describe.each([
  ['the project character', async () => loadRigFromPath('web/public/models/character.glb')],
  [
    'a Mixamo character facing +X, hinges on local X',
    async () => loadRig(await mixamoCharacterGlb({ yawDeg: 90, hingeOnLocalX: true }), 'turned.glb'),
  ],
])('anatomical bends on %s', (_, load) => {
  let spec: RigSpec, humanoid: HumanoidMap, limbs: FlipLimb[], body: IkRig;
  beforeAll(async () => {
    const loaded = await load();
    spec = loaded.spec;
    humanoid = loaded.gltf!.humanoid!;
    limbs = flipLimbs(spec, humanoid);
    body = new IkRig(ik, spec);
  });
  afterAll(() => body.dispose());

  it('the limbs are the lower arms and legs, each with its hinge', () => {
    const roles = ['leftLowerArm', 'rightLowerArm', 'leftLowerLeg', 'rightLowerLeg'] as const;
    expect(limbs.map((l) => l.bone).sort()).toEqual(roles.map((r) => humanoid.bones[r]).sort());
    for (const l of limbs) expect(l.hinge).not.toBeNull();
  });

  it('no pose within the humanoid limits bends an elbow or knee against its direction; the flexion negated does', () => {
    const rand = seeded(7);
    let bentLimbs = 0;
    for (let n = 0; n < 200; n++) {
      const angles = randomAngles(spec, rand);
      const p = body.poses(angles);
      for (const limb of limbs) {
        expect(bentAgainst(spec, limb, p)).toBe(false);
        // The flexion: the limb's angle whose limits reach farthest from 0 (0..150 on these rigs).
        const k = [0, 1, 2].reduce(
          (best, i) =>
            Math.abs(spec.upper[3 * limb.bone + i]) > Math.abs(spec.upper[3 * limb.bone + best]) ? i : best,
          0,
        );
        const flexion = angles[3 * limb.bone + k];
        if (flexion < 10) continue;
        bentLimbs++;
        const reversed = angles.slice();
        reversed[3 * limb.bone + k] = -flexion;
        expect(bentAgainst(spec, limb, body.poses(reversed))).toBe(true);
      }
    }
    expect(bentLimbs).toBeGreaterThan(300); // about half the draws bend (flexion limits 0..150)
  });
});
