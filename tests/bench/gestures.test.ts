// The gestures experiment (gestures.ts): its paths on humanoids (count, step sizes, starts at the
// rest tips, the others pinned, where they end), and the command line: its columns on the
// character, the refusal for a rig without a humanoid and the note when one of several has none.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { runCommand } from '../../bench-node/command.js';
import {
  CROUCH_SHARE,
  GESTURE_STEP_SHARE,
  gesturePaths,
  gestureSteps,
  PUSH_REACH,
  walk,
  type GesturePath,
} from '../../bench-node/gestures.js';
import { jointPositions } from '../../bench-node/jumps.js';
import { independentRanges, project, type TargetSet } from '../../bench-node/target_set.js';
import { generateTargets } from '../../bench-node/targets.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import type { HumanoidMap } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { loadRig, type LoadedRig } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { mixamoCharacterGlb } from '../helpers/limits_characters.js';

const ik = await loadIkNode();
const dir = mkdtempSync(join(tmpdir(), 'bench-gestures-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

const distance = (a: ArrayLike<number>, b: ArrayLike<number>): number =>
  Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

const GESTURES = [
  'left hand across the chest',
  'left hand over the head',
  'left hand behind the back',
  'left hand pushed past its reach',
  'right hand across the chest',
  'right hand over the head',
  'right hand behind the back',
  'right hand pushed past its reach',
  'left foot lifted forward',
  'right foot lifted forward',
  'head lowered (crouch)',
];

describe('walk', () => {
  it('goes through every waypoint in equal steps of at most the step length', () => {
    const steps = walk(
      [0, 0, 0],
      [
        [1, 0, 0],
        [1, 0.25, 0],
      ],
      0.3,
    );
    expect(steps.map((p) => p.map((x) => +x.toFixed(12)))).toEqual([
      [1 / 4, 0, 0],
      [1 / 2, 0, 0],
      [3 / 4, 0, 0],
      [1, 0, 0],
      [1, 0.25, 0],
    ]);
  });
});

describe.each([
  ['the project character', async () => loadRigFromPath('web/public/models/character.glb')],
  ['a Mixamo character facing +X', async () => loadRig(await mixamoCharacterGlb({ yawDeg: 90 }), 'turned.glb')],
])('gestures of %s', (_, load) => {
  let loaded: LoadedRig, spec: RigSpec, humanoid: HumanoidMap, body: IkRig;
  let rest: Float64Array, restTips: Float64Array, paths: GesturePath[], set: TargetSet, height: number;
  beforeAll(async () => {
    loaded = await load();
    spec = loaded.spec;
    humanoid = loaded.gltf!.humanoid!;
    body = new IkRig(ik, spec);
    rest = project(spec, new Float64Array(body.numAngles));
    restTips = body.tips(rest);
    const gestureBody = { humanoid, poses: (a: Float64Array) => body.poses(a) };
    paths = gesturePaths(spec, gestureBody, rest, restTips);
    set = generateTargets(spec, 'gestures', 100000, 1, (a) => body.tips(a), gestureBody);
    const joints = jointPositions(spec, body.poses(rest));
    const ys = Array.from({ length: joints.length / 3 }, (_, j) => joints[3 * j + 1]); // both stand along +Y
    height = Math.max(...ys) - Math.min(...ys);
  });
  afterAll(() => body.dispose());

  const effectorOf = (role: 'head' | 'leftHand' | 'rightHand' | 'leftFoot' | 'rightFoot'): number =>
    spec.effectors.indexOf(humanoid.bones[role]!);
  const path = (name: string): GesturePath => paths.find((p) => p.name === name)!;

  it('has every gesture, for both hands and both feet, on the right effector', () => {
    expect(paths.map((p) => p.name)).toEqual(GESTURES);
    for (const p of paths) {
      const role = p.name.startsWith('head')
        ? 'head'
        : p.name.replace(
            /^(left|right) (hand|foot).*$/,
            (_m, s: string, part: string) => `${s}${part === 'hand' ? 'Hand' : 'Foot'}`,
          );
      expect(p.effector, p.name).toBe(effectorOf(role as 'head'));
    }
  });

  it('moves the target in steps of at most 0.5% of the height, from the rest tip', () => {
    expect(height).toBeGreaterThan(1.7); // 1.8 m tall, and not lying down
    for (const p of paths) {
      let from = restTips.subarray(3 * p.effector, 3 * p.effector + 3);
      for (const point of p.steps) {
        expect(distance(from, point), p.name).toBeLessThanOrEqual(GESTURE_STEP_SHARE * height * (1 + 1e-9));
        from = Float64Array.from(point);
      }
      expect(p.steps.length, p.name).toBeGreaterThan(40);
    }
  });

  it('ends where each gesture goes', () => {
    const shoulder = (side: 'left' | 'right'): Float64Array =>
      jointPositions(spec, body.poses(rest)).subarray(
        6 * humanoid.bones[`${side}UpperArm`]!,
        6 * humanoid.bones[`${side}UpperArm`]! + 3,
      );
    const end = (name: string): number[] => path(name).steps.at(-1)!;
    const tip = (e: number): Float64Array => restTips.subarray(3 * e, 3 * e + 3);
    // The crouch: straight down by 30% of the height.
    const head = tip(effectorOf('head'));
    expect(distance(end('head lowered (crouch)'), [head[0], head[1] - CROUCH_SHARE * height, head[2]])).toBeLessThan(
      1e-9,
    );
    for (const side of ['left', 'right'] as const) {
      const other = side === 'left' ? 'right' : 'left';
      const arm = distance(tip(effectorOf(`${side}Hand`)), shoulder(side));
      // Pushed past its reach: 1.5 arm lengths from the shoulder.
      expect(distance(end(`${side} hand pushed past its reach`), shoulder(side))).toBeCloseTo(PUSH_REACH * arm, 9);
      // Across the chest: nearer the other shoulder than its own.
      const across = end(`${side} hand across the chest`);
      expect(distance(across, shoulder(other))).toBeLessThan(0.5 * distance(across, shoulder(side)));
      // Over the head: above the head's tip.
      expect(end(`${side} hand over the head`)[1]).toBeGreaterThan(head[1]);
      // The foot: lifted.
      expect(end(`${side} foot lifted forward`)[1]).toBeGreaterThan(tip(effectorOf(`${side}Foot`))[1] + 0.1 * height);
    }
  });

  it('makes the set: whole paths chained from P(0), every other effector pinned at its rest tip', () => {
    expect(set.count).toBe(gestureSteps(paths));
    expect(independentRanges(set).map(([b, e]) => e - b)).toEqual(paths.map((p) => p.steps.length));
    const m = set.numAngles,
      r = set.numResiduals;
    let k = 0;
    for (const p of paths)
      p.steps.forEach((point, t) => {
        expect(set.chained[k]).toBe(t > 0 ? 1 : 0);
        expect(set.dragged[k]).toBe(p.effector);
        expect(Array.from(set.starts.subarray(k * m, (k + 1) * m))).toEqual(Array.from(rest));
        const target = Array.from(set.targets.subarray(k * r, (k + 1) * r));
        const expected = Array.from(restTips);
        expected.splice(3 * p.effector, 3, ...point);
        expect(target).toEqual(expected);
        k++;
      });
    // A prefix of the set is its first steps.
    expect(
      generateTargets(spec, 'gestures', 30, 1, (a) => body.tips(a), { humanoid, poses: (a) => body.poses(a) }).count,
    ).toBe(30);
  });
});

/** The command run in this process, its output captured. */
async function benchHere(...args: string[]): Promise<{ code: number; stdout: string; stderr: string }> {
  const out = { stdout: '', stderr: '' };
  const code = await runCommand(args, { out: (t) => (out.stdout += t), err: (t) => (out.stderr += t), isTTY: false });
  return { code, ...out };
}

describe('the command line', () => {
  it('runs gestures on the character with the columns: success, unreachable, wobble, jumps, flips', async () => {
    const file = join(dir, 'gestures.json');
    const r = await benchHere(
      '--rig',
      'character',
      '--experiment',
      'gestures',
      '--methods',
      'lm',
      '--samples',
      '30',
      '--warm-up',
      '0',
      '--workers',
      '1',
      '--json',
      file,
    );
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/character, gestures targets/);
    expect(r.stdout).toMatch(/success .* unreachable .* wobble_unreach max {2}jumps {2}flips {2}jump_max_deg/);
    const [row] = (JSON.parse(readFileSync(file, 'utf8')) as { rows: Record<string, unknown>[] }).rows;
    expect(row).toMatchObject({
      rig: 'character',
      experiment: 'gestures',
      method: 'lm',
      samples: 30,
      restarts: 0,
      jumps: 0,
      flips: 0,
    });
    expect(row.success_rate).toBe(1); // the left hand's first steps forward are easy
    expect(typeof row.jump_max_deg).toBe('number');
  });

  it('refuses a rig without a humanoid in one line', async () => {
    const r = await benchHere('--rig', 'lamp', '--experiment', 'gestures');
    expect(r.stdout).toBe('');
    expect(r.stderr).toMatch(/^bench: lamp: the gestures experiment needs a humanoid the importer recognises.*\n$/);
    expect(r.code).toBe(1);
  });

  it('leaves out the rigs without one, with a note, when another has one', async () => {
    const file = join(dir, 'mixed.json');
    const r = await benchHere(
      '--rig',
      'lamp,character',
      '--experiment',
      'drag,gestures',
      '--methods',
      'lm',
      '--samples',
      '3',
      '--warm-up',
      '0',
      '--workers',
      '1',
      '--json',
      file,
    );
    expect(r.code).toBe(0);
    expect(r.stderr).toBe('gestures: lamp: no gestures (the importer recognised no humanoid), left out\n');
    const rows = (JSON.parse(readFileSync(file, 'utf8')) as { rows: Record<string, unknown>[] }).rows;
    expect(rows.map((row) => `${row.rig} ${row.experiment}`)).toEqual([
      'lamp drag',
      'character drag',
      'character gestures',
    ]);
  });
});
