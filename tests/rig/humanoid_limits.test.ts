// Anatomical limits of a humanoid (web/src/rig/humanoid/humanoid_limits.ts) on characters built in the
// tests without IK extras: which way each one faces, what is left alone, that the rest pose stays
// put, and by forward kinematics that each joint's main bend moves its bone the anatomical way in
// the character's own frame (as built, not as detected), whatever the joints' local axes.
import { resolve } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { bodyFrame } from '../../web/src/rig/anatomy/anatomy_frame.js';
import { jointOf, type Joint } from '../../web/src/rig/anatomy/anatomy_ranges.js';
import { humanoidLimits } from '../../web/src/rig/humanoid/humanoid_limits.js';
import { HUMANOID_ROLES, type HumanoidMap, type HumanoidRole } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import {
  blenderHumanoid,
  mapByNames,
  MIXAMO_NAMES,
  mixamoHumanoid,
  type TestHumanoid,
} from '../helpers/limits_characters.js';
import { disposeAfterAll } from '../helpers/owned.js';

type V = [number, number, number];
const sub = (a: V, b: V): V => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: V, b: V): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: V, b: V): V => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a: V): V => a.map((c) => c / Math.hypot(...a)) as V;
const at = (a: ArrayLike<number>, i: number): V => [a[3 * i], a[3 * i + 1], a[3 * i + 2]];
const noExtras = (spec: RigSpec): boolean[] => new Array<boolean>(spec.parents.length).fill(false);

let ik: IkCoreModule;
const keep = disposeAfterAll();
beforeAll(async () => {
  ik = await loadIkNode();
});

/** The spec with the humanoid limits in place of its own. */
function limited(h: TestHumanoid): RigSpec {
  const { lower, upper } = humanoidLimits(h.spec, h.map, noExtras(h.spec));
  return { ...h.spec, lower, upper };
}

const characters: [string, () => Promise<TestHumanoid>][] = [
  ['Mixamo, facing +Z', () => mixamoHumanoid()],
  ['Mixamo, facing -Z, knee hinges on local X', () => mixamoHumanoid({ yawDeg: 180, hingeOnLocalX: true })],
  ['Mixamo, facing +X', () => mixamoHumanoid({ yawDeg: 90 })],
  ['Mixamo, facing -X, knee hinges on local X', () => mixamoHumanoid({ yawDeg: -90, hingeOnLocalX: true })],
  ['Mixamo, knees bent forward at rest', () => mixamoHumanoid({ kneeForward: 4 })],
  ['Blender names, bent limbs, turned 30 degrees, tilted 10', () => blenderHumanoid()],
];

describe('which way the character faces', () => {
  it.each([
    [0, '+Z'],
    [180, '-Z'],
    [90, '+X'],
    [-90, '-X'],
  ])('turned %i degrees: faces %s, from the toes', async (yawDeg, axis) => {
    const h = await mixamoHumanoid({ yawDeg });
    const { notes } = humanoidLimits(h.spec, h.map, noExtras(h.spec));
    expect(notes[0]).toBe(`humanoid limits: the character faces ${axis} (from the toes)`);
    expect(dot(bodyFrame(h.spec, h.map).forward, h.forward)).toBeGreaterThan(0.9999);
  });

  it('a turned and tilted character: forward and up as built', async () => {
    const h = await blenderHumanoid();
    const frame = bodyFrame(h.spec, h.map);
    expect(dot(frame.up, h.up)).toBeGreaterThan(0.999);
    expect(dot(frame.forward, h.forward)).toBeGreaterThan(0.99);
    expect(dot(frame.left, cross(h.up, h.forward))).toBeGreaterThan(0.99);
  });

  it('without toes from the feet, then the sides, then glTF +Z', async () => {
    const h = await mixamoHumanoid({ yawDeg: 180 });
    const without = (...roles: HumanoidRole[]): HumanoidMap => ({
      ...h.map,
      bones: Object.fromEntries(Object.entries(h.map.bones).filter(([r]) => !roles.includes(r as HumanoidRole))),
    });
    const feet = ['leftToes', 'rightToes', 'leftFoot', 'rightFoot'] as const;
    const limbs = ['leftUpperLeg', 'rightUpperLeg', 'leftUpperArm', 'rightUpperArm'] as const;
    const facing = (map: HumanoidMap): [string, number] => {
      const f = bodyFrame(h.spec, map);
      return [f.facingFrom, Math.round(f.forward[2])];
    };
    expect(facing(without('leftToes', 'rightToes'))).toEqual(['feet', -1]);
    // The head stands straight up: no lean to read a facing from.
    expect(facing(without(...feet))).toEqual(['sides', -1]);
    expect(facing(without(...feet, ...limbs))).toEqual(['glTF +Z', 1]);
  });
});

describe('what the limits leave alone', () => {
  it('bones without a role and bones with extras.ik limits keep theirs; the hips bone is fixed', async () => {
    const h = await mixamoHumanoid();
    const n = h.spec.parents.length;
    const knee = h.map.bones.leftLowerLeg!,
      finger = h.spec.names.indexOf('mixamorig:LeftHandIndex2');
    const explicit = noExtras(h.spec);
    explicit[knee] = true;
    const { lower, upper, notes } = humanoidLimits(h.spec, h.map, explicit);
    const mapped = new Set(Object.values(h.map.bones));
    for (let i = 0; i < n; i++) {
      if (mapped.has(i) && i !== knee) continue;
      expect(Array.from(lower.slice(3 * i, 3 * i + 3))).toEqual(Array.from(h.spec.lower.slice(3 * i, 3 * i + 3)));
      expect(Array.from(upper.slice(3 * i, 3 * i + 3))).toEqual(Array.from(h.spec.upper.slice(3 * i, 3 * i + 3)));
    }
    expect(Array.from(upper.slice(3 * finger, 3 * finger + 3))).toEqual([180, 180, 180]);
    const hips = h.map.bones.hips!;
    expect(Array.from(lower.slice(3 * hips, 3 * hips + 3))).toEqual([0, 0, 0]);
    expect(Array.from(upper.slice(3 * hips, 3 * hips + 3))).toEqual([0, 0, 0]);
    expect(notes).toContain('extras.ik limits kept: mixamorig:LeftLeg');
    expect(h.spec.upper[3 * hips]).toBe(180); // the spec itself is not changed
  });

  it('the project character file (no IK extras): the importer gives its humanoid exactly these limits', async () => {
    const rig = await loadRigFromPath(resolve(import.meta.dirname, '../../web/public/models/character.glb'));
    const own = rig.gltf!.fileLimits!;
    expect(own.lower.every((v) => v === -180) && own.upper.every((v) => v === 180)).toBe(true);
    const spec = { ...rig.spec, lower: own.lower, upper: own.upper };
    const expected = humanoidLimits(spec, rig.gltf!.humanoid!, noExtras(spec));
    expect(rig.spec.lower).toEqual(expected.lower);
    expect(rig.spec.upper).toEqual(expected.upper);
    expect(rig.gltf!.humanoid!.bones).toEqual(mapByNames(spec, 'mixamo', MIXAMO_NAMES).bones);
  });
});

describe.each(characters)('%s', (_, make) => {
  let h: TestHumanoid;
  let rig: IkRig;
  beforeAll(async () => {
    h = await make();
    rig = keep(new IkRig(ik, limited(h)));
  });

  it('the rest pose clamped into the limits is the rest pose: the model does not move', () => {
    const rest = rig.poses(new Float64Array(rig.numAngles));
    const clamped = rig.poses(rig.project(new Float64Array(rig.numAngles)));
    for (let k = 0; k < rest.length; k++) expect(Math.abs(clamped[k] - rest[k])).toBeLessThan(1e-9);
  });

  /**
   * Where each joint's main bend moves its bone's tip, in the character's frame as built, and
   * whether the sign is known (a symmetric range only has a plane). The hips bone is fixed.
   */
  const towards = (joint: Exclude<Joint, 'hips'>): [V, boolean] => {
    const F = h.forward,
      U = h.up,
      back: V = [-F[0], -F[1], -F[2]],
      down: V = [-U[0], -U[1], -U[2]];
    const table: Record<Exclude<Joint, 'hips'>, [V, boolean]> = {
      spine: [F, true],
      neck: [F, false],
      head: [F, true],
      shoulder: [U, true],
      upperArm: [F, true],
      lowerArm: [F, true],
      hand: [U, false],
      upperLeg: [F, true],
      lowerLeg: [back, true],
      foot: [down, true],
      toes: [down, false],
    };
    return table[joint];
  };

  it('each joint bends the anatomical way: 15 degrees of its main bend move the tip as expected', () => {
    const rest = new Float64Array(rig.numAngles);
    const restTips = rig.boneTips(rest);
    for (const role of HUMANOID_ROLES) {
      const bone = h.map.bones[role];
      const joint = jointOf(role);
      if (bone === undefined || joint === 'hips') continue;
      const [expected, signed] = towards(joint);
      const lo = rig.lower,
        hi = rig.upper,
        b = 3 * bone;
      // The anatomical bend plane is the middle of the a0 and a2 ranges; the main bend, the longer side of a1.
      const a = rest.slice();
      a[b] = (lo[b] + hi[b]) / 2;
      a[b + 2] = (lo[b + 2] + hi[b + 2]) / 2;
      a[b + 1] = hi[b + 1] >= -lo[b + 1] ? 15 : -15;
      const moved = unit(sub(at(rig.boneTips(a), bone), at(restTips, bone)));
      const x: V = [h.spec.rest[16 * bone], h.spec.rest[16 * bone + 4], h.spec.rest[16 * bone + 8]];
      const across = unit(sub(expected, x.map((c) => c * dot(expected, x)) as V));
      const alignment = dot(moved, across);
      expect(
        signed ? alignment : Math.abs(alignment),
        `${role} moves along ${across.map((c) => c.toFixed(2))}`,
      ).toBeGreaterThan(0.95);
    }
  });
});

describe('a knee bent backward at rest (a reverse joint)', () => {
  it('bends further that way, and the notes say so', async () => {
    const h = await mixamoHumanoid({ kneeForward: -4 });
    const { lower, upper, notes } = humanoidLimits(h.spec, h.map, noExtras(h.spec));
    expect(notes).toContain(
      'bent the other way in the rest pose, so limited that way: mixamorig:LeftLeg, mixamorig:RightLeg',
    );
    const rig = keep(new IkRig(ik, { ...h.spec, lower, upper }));
    const knee = h.map.bones.leftLowerLeg!,
      b = 3 * knee;
    const a = new Float64Array(rig.numAngles);
    a[b] = (lower[b] + upper[b]) / 2;
    a[b + 2] = (lower[b + 2] + upper[b + 2]) / 2;
    a[b + 1] = upper[b + 1] >= -lower[b + 1] ? 30 : -30;
    const moved = sub(at(rig.boneTips(a), knee), at(rig.boneTips(new Float64Array(rig.numAngles)), knee));
    expect(dot(unit(moved), h.forward)).toBeGreaterThan(0.9); // the shin swings forward
  });
});
