// The part of a rig a few bones hang from (web/src/avatar/sub_rig.ts), on the project's character:
// the part's bones are the tracked and planted ones and their ancestors only, its pose written
// into the whole rig's gives the same bone tips at every bone it kept (and the whole rig's other
// bones keep their angles), and the humanoid roles follow the renumbering.
import { resolve } from 'node:path';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { scatterAngles, subHumanoid, subRig } from '../../web/src/avatar/sub_rig.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { LoadedRig } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';

let ik: IkCoreModule;
let character: LoadedRig;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
  character = await loadRigFromPath(resolve(import.meta.dirname, '../../web/public/models/character.glb'));
});
afterAll(() => rigs.forEach((r) => r.dispose()));

describe('the part of a rig that moves a few bones', () => {
  it('keeps those bones and their ancestors, and poses them as the whole rig does', () => {
    const humanoid = character.gltf!.humanoid!;
    const moved = (['head', 'leftHand', 'rightHand', 'leftFoot', 'rightFoot'] as const).map((r) => humanoid.bones[r]!);
    const floatingRoot = { lower: [-1, -1, -1], upper: [1, 1, 1] };
    const spec = { ...character.spec, effectors: Int32Array.from(moved), floatingRoot };
    const part = subRig(spec, moved);
    const numBones = spec.parents.length;
    // Every bone kept is one moved or an ancestor of one; every ancestor of one is kept.
    const ancestors = new Set<number>();
    for (const b of moved) for (let a = b; a >= 0; a = spec.parents[a]) ancestors.add(a);
    expect(new Set(part.bones)).toEqual(ancestors);
    expect(part.bones.length).toBeLessThan(numBones / 2); // the character's fingers, toes and eyes are left out
    expect(Array.from(part.spec.effectors, (i) => part.bones[i])).toEqual(moved);

    const whole = new IkRig(ik, spec),
      sub = new IkRig(ik, part.spec);
    rigs.push(whole, sub);
    // A pose of the part: each angle somewhere in its range, the root moved.
    const subAngles = new Float64Array(sub.numAngles);
    for (let j = 0; j < subAngles.length; j++) subAngles[j] = 25 * Math.sin(1.7 * j + 0.3);
    subAngles.set([0.2, -0.1, 0.05], 3 * part.bones.length);
    sub.project(subAngles).forEach((v, j) => (subAngles[j] = v));
    const angles = whole.project(new Float64Array(whole.numAngles));
    const before = angles.slice();
    scatterAngles(part, subAngles, angles);
    const kept = new Set(part.bones);
    for (let b = 0; b < numBones; b++)
      if (!kept.has(b))
        expect(Array.from(angles.subarray(3 * b, 3 * b + 3))).toEqual(Array.from(before.subarray(3 * b, 3 * b + 3)));
    expect(Array.from(angles.subarray(3 * numBones))).toEqual([0.2, -0.1, 0.05]);
    const wholeTips = whole.boneTips(angles),
      subTips = sub.boneTips(subAngles);
    part.bones.forEach((b, i) => {
      for (let k = 0; k < 3; k++) expect(subTips[3 * i + k]).toBeCloseTo(wholeTips[3 * b + k], 12);
    });
    expect(Array.from(sub.tips(subAngles))).toEqual(Array.from(whole.tips(angles)));
  });

  it('renumbers the humanoid roles into the part, dropping the roles on bones left out', () => {
    const humanoid = character.gltf!.humanoid!;
    const moved = [humanoid.bones.leftHand!];
    const part = subRig(character.spec, moved);
    const renamed = subHumanoid(part, humanoid);
    expect(part.spec.names[renamed.bones.leftUpperArm!]).toBe(character.spec.names[humanoid.bones.leftUpperArm!]);
    expect(renamed.bones.rightHand).toBeUndefined();
    expect(renamed.bones.leftFoot).toBeUndefined();
  });
});
