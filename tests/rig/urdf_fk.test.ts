// Forward kinematics of imported URDF chains checked against an independent implementation
// (tests/helpers/urdf_reference.ts, written from the URDF specification): at 1000 random
// configurations within the limits, the rig's end-effector tip (through the WebAssembly core)
// is the TIP link's origin and its bone frame (tipRotations) the TIP link's frame, to 1e-9 of
// the robot's size. On the small robots of urdf_samples.ts, and on every shared robot
// (../shared/robots: skipped without it, failed under CI).
import { readFileSync } from 'node:fs';

import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { seeded } from '../helpers/a7.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { needsRobots, robotPath, sharedRobots } from '../helpers/robots.js';
import { quaternionMatrix, ReferenceChain } from '../helpers/urdf_reference.js';
import { sampleRobots, urdfText } from './urdf_samples.js';

let ik: IkCoreModule;
beforeAll(async () => {
  ik = await loadIkNode();
});
const keep = disposeAfterAll();

const CONFIGURATIONS = 1000;

/** The largest position and rotation-entry differences between the rig and the reference over CONFIGURATIONS random configurations. */
async function fkAgreement(
  text: string,
  file: string,
  chain: string,
): Promise<{ position: number; rotation: number; size: number; dof: number }> {
  const loaded = await loadRig(new TextEncoder().encode(text), file, undefined, { chain });
  const ref = new ReferenceChain(text, chain);
  const moving = ref.moving;
  // Bone k is moving joint k, then the TIP link's bone.
  expect(loaded.spec.names.slice(0, -1)).toEqual(moving.map((j) => j.name));
  const rig = keep(new IkRig(ik, loaded.spec));
  const rand = seeded(31);
  const angles = new Float64Array(rig.numAngles);
  let position = 0,
    rotation = 0;
  for (let s = 0; s < CONFIGURATIONS; s++) {
    const q = moving.map((j) => j.lower + (j.upper - j.lower) * rand());
    q.forEach((v, k) => (angles[3 * k] = (v * 180) / Math.PI));
    const T = ref.tipFrame(q);
    const tip = rig.tips(angles);
    const R = quaternionMatrix(rig.tipRotations(angles));
    for (let r = 0; r < 3; r++) {
      position = Math.max(position, Math.abs(tip[r] - T[4 * r + 3]));
      for (let c = 0; c < 3; c++) rotation = Math.max(rotation, Math.abs(R[3 * r + c] - T[4 * r + c]));
    }
  }
  return { position, rotation, size: ref.size, dof: moving.length };
}

describe.each(sampleRobots)('URDF forward kinematics on $label', (robot) => {
  it(`agrees with the reference at ${CONFIGURATIONS} configurations`, async () => {
    const r = await fkAgreement(urdfText(robot.joints), 'sample.urdf', robot.chain);
    expect(r.dof).toBe(robot.dof);
    expect(r.position).toBeLessThanOrEqual(1e-9 * r.size);
    expect(r.rotation).toBeLessThanOrEqual(1e-9);
  });
});

describe.each(sharedRobots)('URDF forward kinematics on the shared robot $name ($chain)', needsRobots, (robot) => {
  it(`agrees with the reference at ${CONFIGURATIONS} configurations`, async () => {
    const r = await fkAgreement(readFileSync(robotPath(robot.name), 'utf8'), robotPath(robot.name), robot.chain);
    expect(r.dof).toBe(robot.dof);
    expect(r.position).toBeLessThanOrEqual(1e-9 * r.size);
    expect(r.rotation).toBeLessThanOrEqual(1e-9);
  });
});
