// The rest pose from the skins' bind pose (web/src/rig/gltf/bind_pose.ts): a file saved
// posed (its nodes turned, its inverse bind matrices still the unposed rest) imports with the same
// rest, limits and notes as the unposed file, and its pose comes as start angles
// (GltfRigInfo.startAngles) that put every joint where the file has it. A file saved in its bind
// pose imports as before, a skin without inverse bind matrices keeps the nodes' pose and says so,
// and a bind matrix that cannot be inverted is an error naming it.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import { rigReport } from '../../scripts/rig_inspect.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { readNodes, worldMatrices } from '../../web/src/rig/gltf/gltf_nodes.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { multiply } from '../../web/src/rig/mat4.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { posedGlb } from '../../web/src/view/pose_glb.js';
import { maxAbsDiff, randomAngles, seeded } from '../helpers/a7.js';
import { nodeIndex, packGlb, unpackGlb } from '../../scripts/rig_files/glb.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';
import { MIXAMO_NAMES } from '../helpers/limits_characters.js';
import { humanoidJoints } from '../helpers/named_humanoid.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { skeletonGlb } from '../helpers/skeleton_glb.js';
import { treeGlb } from '../../scripts/rig_files/tree_rigs.js';
import { loadError, turnedGlb } from './synthetic_rigs.js';

const modelsDir = resolve(import.meta.dirname, '../../web/public/models');
const expectedDir = resolve(import.meta.dirname, 'expected');

let ik: IkCoreModule;
const keep = disposeAfterAll();
beforeAll(async () => {
  ik = await loadIkNode();
});

const X: [number, number, number] = [1, 0, 0];
/** The small Mixamo-named humanoid (meters, T-pose, facing +Z, joints without rotation): a knee bends about +X, a thigh lifts forward about -X. */
const mixamoSkeleton = (): Promise<Uint8Array> => skeletonGlb(humanoidJoints({ roles: MIXAMO_NAMES }));
const BENT_KNEE = { 'mixamorig:LeftUpLeg': { axis: X, deg: -50 }, 'mixamorig:LeftLeg': { axis: X, deg: 80 } };

/** Rest size of a loaded rig: the diagonal of its bone tips' box. */
function restSize(rig: IkRig): number {
  return rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
}

/**
 * Largest difference of two rigs' limits, degrees (0 where both are unbounded). The bind matrices
 * are float32, so limits derived from the rest frames (humanoid_limits.ts) agree to about 1e-6
 * degrees: the `rig --json` rounding to 1e-6 may then differ in its last digit.
 */
function limitsDiff(a: LoadedRig, b: LoadedRig): number {
  let worst = 0;
  for (const k of ['lower', 'upper'] as const)
    a.spec[k].forEach((v, i) => (worst = Math.max(worst, v === b.spec[k][i] ? 0 : Math.abs(v - b.spec[k][i]))));
  return worst;
}

/**
 * The rig posed at its start angles (zero when it has none) against the file's own node world
 * matrices: each joint's posed world T_i * restWorld_i, positions to `tol` of the rig's size and
 * the linear parts to `tol` of their size. Returns the largest relative difference.
 */
function startPoseError(bytes: Uint8Array, loaded: LoadedRig): number {
  const info = loaded.gltf!;
  const rig = keep(new IkRig(ik, loaded.spec));
  const size = restSize(rig);
  const poses = rig.poses(info.startAngles ?? new Float64Array(rig.numAngles));
  const world = worldMatrices(readNodes(unpackGlb(bytes).json.nodes, 'x.glb'));
  let worst = 0;
  info.boneNodes.forEach((node, i) => {
    const posed = multiply(poses.subarray(16 * i, 16 * i + 16), info.restWorld.subarray(16 * i, 16 * i + 16));
    const want = world[node];
    const scale = Math.max(...[0, 1, 2, 4, 5, 6, 8, 9, 10].map((k) => Math.abs(want[k])));
    for (const k of [3, 7, 11]) worst = Math.max(worst, Math.abs(posed[k] - want[k]) / size);
    for (const k of [0, 1, 2, 4, 5, 6, 8, 9, 10]) worst = Math.max(worst, Math.abs(posed[k] - want[k]) / scale);
  });
  return worst;
}

describe('a file saved posed takes its rest from the bind pose', () => {
  it('a bent knee: the same rest, limits and notes as the unposed file, and start angles that pose it as saved', async () => {
    const straight = await mixamoSkeleton();
    const bent = turnedGlb(straight, BENT_KNEE);
    const [a, b] = [await loadRig(straight, 'straight.glb'), await loadRig(bent, 'bent.glb')];
    expect(a.gltf!.humanoid).not.toBeNull();
    expect(a.gltf!.startAngles).toBeNull();

    // The rest is the straight one: rest frames, lengths and limits as the unposed file's.
    const size = restSize(keep(new IkRig(ik, a.spec)));
    expect(maxAbsDiff(b.spec.rest, a.spec.rest)).toBeLessThan(1e-9 * size);
    expect(maxAbsDiff(b.spec.lengths, a.spec.lengths)).toBeLessThan(1e-9 * size);
    expect(maxAbsDiff(b.gltf!.restWorld, a.gltf!.restWorld)).toBeLessThan(1e-9 * size);
    expect(limitsDiff(b, a)).toBeLessThan(1e-5);
    expect(b.spec.effectors).toEqual(a.spec.effectors);

    // The notes: no "bent the other way", no "not in the bind pose"; the pose is named.
    expect(b.warnings.filter((w) => !w.startsWith("the file's pose"))).toEqual(a.warnings);
    expect(b.warnings.join('\n')).not.toMatch(/bent the other way|not in the bind pose/);
    expect(b.warnings).toContain(
      "the file's pose differs from the bind pose (2 joints: mixamorig:LeftUpLeg, mixamorig:LeftLeg): opened posed, the rest is the bind pose",
    );

    // The start angles pose the rig as the file's nodes stand: the knee bent 80 degrees within its limits.
    const start = b.gltf!.startAngles!;
    expect(start).not.toBeNull();
    expect(startPoseError(bent, b)).toBeLessThan(1e-6);
    const knee = b.spec.names.indexOf('mixamorig:LeftLeg');
    expect(start[3 * knee + 1]).toBeCloseTo(80, 6);
    for (let k = 0; k < start.length; k++) {
      expect(start[k]).toBeGreaterThanOrEqual(b.spec.lower[k]);
      expect(start[k]).toBeLessThanOrEqual(b.spec.upper[k]);
    }
    // Only the turned joints turn (relative to their parents); every other bone's motion is its parent's.
    const rig = keep(new IkRig(ik, b.spec));
    const poses = rig.poses(start);
    const turned = b.spec.names.filter((_, i) => {
      const p = b.spec.parents[i];
      const mine = poses.subarray(16 * i, 16 * i + 12),
        theirs = p < 0 ? [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0] : poses.subarray(16 * p, 16 * p + 12);
      return [0, 1, 2, 4, 5, 6, 8, 9, 10].some((k) => Math.abs(mine[k] - theirs[k]) > 1e-9);
    });
    expect(turned).toEqual(['mixamorig:LeftUpLeg', 'mixamorig:LeftLeg']);
  });

  it('a pose past the limits opens at the nearest angles within them, with a note', async () => {
    const bytes = turnedGlb(await mixamoSkeleton(), { 'mixamorig:LeftLeg': { axis: X, deg: -40 } }); // the knee bent forwards
    const rig = await loadRig(bytes, 'x.glb');
    expect(rig.warnings).toContain(
      'bone mixamorig:LeftLeg: posed past its limits in the file: opened at the nearest angles within them',
    );
    expect(rig.warnings.join('\n')).not.toMatch(/bent the other way/);
    const knee = rig.spec.names.indexOf('mixamorig:LeftLeg');
    expect(rig.gltf!.startAngles![3 * knee + 1]).toBe(0);
  });

  it('a file in its bind pose imports exactly as its nodes say, as the expectations have it', async () => {
    for (const name of ['character', 'knight']) {
      const loaded = await loadRig(new Uint8Array(readFileSync(resolve(modelsDir, `${name}.glb`))), `${name}.glb`);
      expect(loaded.gltf!.startAngles, name).toBeNull();
      expect(rigReport(loaded), name).toEqual(
        JSON.parse(readFileSync(resolve(expectedDir, `${name}.rig.json`), 'utf8')),
      );
      // Bit for bit: the rest world matrices are the nodes' own world matrices.
      const { json } = unpackGlb(readFileSync(resolve(modelsDir, `${name}.glb`)));
      const world = worldMatrices(readNodes(json.nodes, name));
      loaded.gltf!.boneNodes.forEach((node, i) =>
        expect(Array.from(loaded.gltf!.restWorld.subarray(16 * i, 16 * i + 16)), name).toEqual(Array.from(world[node])),
      );
    }
  });

  it('a whole file turned at its root keeps that turn in the rest (the bind pose is placed by the top joint)', async () => {
    const bytes = turnedGlb(await mixamoSkeleton(), { 'mixamorig:Hips': { axis: [0, 1, 0], deg: 30 } });
    const rig = await loadRig(bytes, 'x.glb');
    expect(rig.gltf!.startAngles).toBeNull();
    expect(startPoseError(bytes, rig)).toBeLessThan(1e-12);
  });
});

describe('which pose is the rest when the bind pose cannot give it', () => {
  it("a skin without inverse bind matrices: the nodes' pose, said in the notes", async () => {
    const rig = await loadRig(treeGlb([-1, 0, 1]), 'tree.glb');
    expect(rig.warnings).toContain("skin 0: no inverse bind matrices, so the nodes' pose is the rest");
    expect(rig.gltf!.startAngles).toBeNull();
    const { json } = unpackGlb(treeGlb([-1, 0, 1]));
    json.skins.push({ joints: [2] });
    expect((await loadRig(packGlb(json), 'two.glb')).warnings).toContain(
      "2 skins (0, 1): no inverse bind matrices, so the nodes' pose is the rest",
    );
  });

  it("bind matrices that are no turn of the nodes' skeleton (identities): the nodes' pose, as before", async () => {
    const rig = await loadRig(await skeletonGlb(humanoidJoints({ roles: MIXAMO_NAMES }), { bindPose: false }), 'x.glb');
    expect(rig.warnings).toContain(
      "skin 0: the nodes are not in the bind pose; the rig's rest pose is the nodes' pose",
    );
    expect(rig.gltf!.startAngles).toBeNull();
  });

  it("a bind matrix that is not invertible or not finite is an error naming the skin's inverseBindMatrices and the joint", async () => {
    const { json, bin } = unpackGlb(await mixamoSkeleton());
    const k = (json.skins[0].joints as number[]).indexOf(nodeIndex(json, 'mixamorig:LeftLeg'));
    const accessor = (json.accessors as { bufferView: number; byteOffset?: number }[])[
      json.skins[0].inverseBindMatrices as number
    ];
    const view = (json.bufferViews as { byteOffset?: number }[])[accessor.bufferView];
    const at = (view.byteOffset ?? 0) + (accessor.byteOffset ?? 0) + 64 * k;
    const singular = bin.slice();
    new DataView(singular.buffer).setFloat32(at + 4 * 5, 0, true); // scale y = 0
    expect(await loadError(packGlb(json, singular), 'x.glb')).toMatch(
      new RegExp(
        `^x\\.glb: skins\\[0\\]\\.inverseBindMatrices \\(accessor \\d+\\): matrix ${k}, of joint node \\d+ "mixamorig:LeftLeg", is not invertible`,
      ),
    );
    const notFinite = bin.slice();
    new DataView(notFinite.buffer).setFloat32(at + 4 * 12, NaN, true);
    expect(await loadError(packGlb(json, notFinite), 'x.glb')).toMatch(
      new RegExp(`skins\\[0\\]\\.inverseBindMatrices \\(accessor \\d+\\): matrix ${k} has a non-finite entry`),
    );
  });
});

describe('round trip: the character posed on the page, saved as .glb and opened again', () => {
  it('lifting the left foot by 30% of the height: the same limits, no "bent the other way", the foot where it was, and dragging it back down as if never saved', async () => {
    const bytes = new Uint8Array(readFileSync(resolve(modelsDir, 'character.glb')));
    const loaded = await loadRig(bytes, 'character.glb');
    const rig = keep(new IkRig(ik, loaded.spec));
    const zero = new Float64Array(rig.numAngles);
    const size = restSize(rig);
    const foot = Array.from(loaded.spec.effectors).indexOf(loaded.spec.names.indexOf('mixamorig:LeftFoot'));
    const tips0 = rig.boneTips(zero);
    const height = Math.max(...tips0.filter((_, k) => k % 3 === 1)) - Math.min(...tips0.filter((_, k) => k % 3 === 1));
    const rest = rig.tips(zero);
    /** Drags the left foot's target (the others staying on their rest tips) in 30 steps from where the pose puts it to height `y`. */
    const drag = (r: IkRig, from: Float64Array, y: number): Float64Array => {
      const solve = keep(
        new IkSolver(r, 'lm', { restarts: 0, ...dragTolerances(size), maxIterations: 1000, timeBudgetSeconds: 0 }),
      );
      let angles = from;
      const target = rest.slice();
      const y0 = r.tips(from)[3 * foot + 1];
      for (let s = 1; s <= 30; s++) {
        target[3 * foot + 1] = y0 + ((y - y0) * s) / 30;
        angles = solve.solve(angles, target).angles.slice();
      }
      expect(maxAbsDiff(r.tips(angles), target), 'on target').toBeLessThan(1e-3 * size);
      return angles;
    };
    const lifted = drag(rig, zero, rest[3 * foot + 1] + 0.3 * height);

    const saved = await posedGlb(bytes, 'character.glb', loaded.gltf!, loaded.spec, rig.poses(lifted));
    const again = await loadRig(saved, 'posed.glb');
    expect(limitsDiff(again, loaded)).toBeLessThan(1e-5);
    expect(again.warnings.join('\n')).not.toMatch(/bent the other way|not in the bind pose/);
    expect(again.warnings.filter((w) => !w.startsWith("the file's pose"))).toEqual(loaded.warnings);
    const rig2 = keep(new IkRig(ik, again.spec));
    // R (reset: angles 0) is the model's rest, not the saved pose.
    expect(maxAbsDiff(rig2.boneTips(zero), rig.boneTips(zero))).toBeLessThan(1e-6 * size);
    // It opens as saved: the foot (every bone tip) where it was, the knee bent as it was.
    const start = again.gltf!.startAngles!;
    expect(maxAbsDiff(rig2.boneTips(start), rig.boneTips(lifted))).toBeLessThan(1e-6 * size);
    expect(startPoseError(saved, again)).toBeLessThan(1e-6);
    const knee = again.spec.names.indexOf('mixamorig:LeftLeg');
    expect(start[3 * knee + 1]).toBeCloseTo(lifted[3 * knee + 1], 4);
    // Dragging the foot back down goes as it goes on the rig that was never saved.
    const down = drag(rig2, start, rest[3 * foot + 1]);
    expect(maxAbsDiff(rig2.boneTips(down), rig.boneTips(drag(rig, lifted, rest[3 * foot + 1])))).toBeLessThan(
      1e-5 * size,
    );
  });
});

describe('round trip at random angles', () => {
  it.each(['knight', 'the Blender-style character (two skins, Armature-space bind matrices under a moved World)'])(
    '%s: reopens at the same rest and pose',
    async (name) => {
      const bytes =
        name === 'knight' ? new Uint8Array(readFileSync(resolve(modelsDir, 'knight.glb'))) : await testCharacterGlb();
      const loaded = await loadRig(bytes, 'x.glb');
      const rig = keep(new IkRig(ik, loaded.spec));
      const size = restSize(rig);
      const rand = seeded(7);
      for (let s = 0; s < 3; s++) {
        const angles = randomAngles(loaded.spec, rand);
        const saved = await posedGlb(bytes, 'x.glb', loaded.gltf!, loaded.spec, rig.poses(angles));
        const again = await loadRig(saved, 'posed.glb');
        expect(maxAbsDiff(again.spec.rest, loaded.spec.rest)).toBeLessThan(1e-6 * size);
        expect(limitsDiff(again, loaded)).toBeLessThan(1e-5);
        expect(again.warnings.join('\n')).not.toMatch(/past its limits|not in the bind pose/);
        const rig2 = keep(new IkRig(ik, again.spec));
        expect(maxAbsDiff(rig2.boneTips(again.gltf!.startAngles!), rig.boneTips(angles))).toBeLessThan(1e-6 * size);
        expect(startPoseError(saved, again)).toBeLessThan(1e-6);
      }
    },
  );
});
