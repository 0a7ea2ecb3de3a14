// Goals beyond tip positions through the TypeScript API (web/src/ik/goals.ts): pose goals reached
// and checked against forward kinematics, orientation-only and weighted goals, the goal cache
// between solves, and every malformed goal refused with its field named.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { orientationErrorsDeg, type Goals } from '../../web/src/ik/goals.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { loadTestRig, randomAngles, seeded, testRigs } from '../helpers/a7.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { sketchRig, straightLimb } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
/** The methods the core registers (a new one is tested without a change here). */
const registered = IkSolver.methods(await loadIkNode());
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});

/** Row-major 3x3 rotation of a unit quaternion [x, y, z, w]. */
function quatToMatrix(q: ArrayLike<number>): number[] {
  const [x, y, z, w] = [q[0], q[1], q[2], q[3]];
  return [
    1 - 2 * (y * y + z * z),
    2 * (x * y - z * w),
    2 * (x * z + y * w),
    2 * (x * y + z * w),
    1 - 2 * (x * x + z * z),
    2 * (y * z - x * w),
    2 * (x * z - y * w),
    2 * (y * z + x * w),
    1 - 2 * (x * x + y * y),
  ];
}

/** Pose goals (position and orientation of every effector) that `angles` reaches exactly. */
function poseGoalsAt(rig: IkRig, angles: Float64Array): Goals {
  const tips = rig.tips(angles),
    q = rig.tipRotations(angles);
  return {
    effectors: Array.from(rig.effectors(), (bone, e) => ({
      bone,
      position: tips.subarray(3 * e, 3 * e + 3),
      orientation: q.subarray(4 * e, 4 * e + 4),
    })),
  };
}

describe('tipRotations', () => {
  it.each(testRigs.map((r) => [r.label, r] as const))('equals the pose times the rest rotation on %s', (_, testRig) => {
    const rig = keep(new IkRig(ik, loadTestRig(testRig)));
    const angles = randomAngles(rig.spec, seeded(3));
    const q = rig.tipRotations(angles),
      poses = rig.poses(angles);
    Array.from(rig.effectors()).forEach((bone, e) => {
      const quat = q.subarray(4 * e, 4 * e + 4);
      expect(Math.hypot(...quat)).toBeCloseTo(1, 12);
      const R = quatToMatrix(quat);
      for (let r = 0; r < 3; r++)
        for (let c = 0; c < 3; c++) {
          let expected = 0;
          for (let k = 0; k < 3; k++) expected += poses[16 * bone + 4 * r + k] * rig.spec.rest[16 * bone + 4 * k + c];
          expect(R[3 * r + c]).toBeCloseTo(expected, 10);
        }
    });
  });
});

describe('pose goals', () => {
  it.each(testRigs.map((r) => [r.label, r] as const))(
    'lm reaches reachable pose goals on %s, checked by forward kinematics',
    (_, testRig) => {
      const rig = keep(new IkRig(ik, loadTestRig(testRig)));
      const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
      const tipTolerance = 1e-3 * size;
      const solver = keep(
        new IkSolver(rig, 'lm', {
          tipTolerance,
          orientationToleranceDeg: 0.5,
          timeBudgetSeconds: 0,
          maxIterations: 20000,
        }),
      );
      const rng = seeded(17);
      let start = randomAngles(rig.spec, rng);
      for (let k = 0; k < 6; k++) {
        // Incremental: each target a small move away from where the last solve ended.
        const goalAngles = start.map((a, i) => Math.min(rig.upper[i], Math.max(rig.lower[i], a + 20 * (rng() - 0.5))));
        const goals = poseGoalsAt(rig, goalAngles);
        const result = solver.solve(start, goals);
        expect(result.stopReason).toBe('converged_E');
        const tips = rig.tips(result.angles);
        goals.effectors.forEach((g, e) => {
          const p = g.position!;
          expect(Math.hypot(tips[3 * e] - p[0], tips[3 * e + 1] - p[1], tips[3 * e + 2] - p[2])).toBeLessThan(
            tipTolerance,
          );
        });
        for (const err of orientationErrorsDeg(rig, result.angles, goals)) expect(err).toBeLessThan(0.5);
        expect(result.angles.every((x, i) => x >= rig.lower[i] && x <= rig.upper[i])).toBe(true);
        start = result.angles;
      }
    },
  );

  it('position goals of weight 1 solve exactly as the plain target array', () => {
    const rig = keep(new IkRig(ik, loadTestRig(testRigs.find((r) => r.name === 'knight')!)));
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0 }));
    const start = randomAngles(rig.spec, seeded(5));
    const target = rig.tips(randomAngles(rig.spec, seeded(6)));
    const plain = solver.solve(start, target);
    const goals: Goals = {
      effectors: Array.from(rig.effectors(), (bone, e) => ({ bone, position: target.subarray(3 * e, 3 * e + 3) })),
    };
    const viaGoals = solver.solve(start, goals);
    expect(Array.from(viaGoals.angles)).toEqual(Array.from(plain.angles));
    expect(viaGoals.iterations).toBe(plain.iterations);
    // And back to a plain target: the goals are cleared.
    expect(Array.from(solver.solve(start, target).angles)).toEqual(Array.from(plain.angles));
  });

  it('an orientation-only goal turns the tip frame and leaves its position free', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0 }));
    const zero = new Float64Array(rig.numAngles);
    // The tip frame turned 90 degrees about z: the last bone points along +y.
    const s = Math.SQRT1_2;
    const goals: Goals = { effectors: [{ bone: 'bone 1', orientation: [0, 0, s, s] }] };
    const result = solver.solve(zero, goals);
    expect(result.reached).toBe(true);
    expect(orientationErrorsDeg(rig, result.angles, goals)[0]).toBeLessThan(0.5);
    const R = quatToMatrix(rig.tipRotations(result.angles));
    expect(R[3]).toBeCloseTo(1, 2); // the frame's x axis (the bone) now along +y
  });

  it('the weights trade one goal against the other when both cannot be met', () => {
    // One bone of length 1: its tip cannot leave the unit sphere, so a position goal at distance 2
    // along +y and an orientation goal keeping the bone along +x conflict.
    const rig = keep(new IkRig(ik, sketchRig([{ parent: -1, at: [0, 0, 0], length: 1 }], [0])));
    // The weighted sum (strictPriority off); with strict priority the position wins whatever the weights (next test).
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0, restarts: 0, strictPriority: false }));
    const zero = new Float64Array(3);
    const error = (positionWeight: number) => {
      const goals: Goals = {
        effectors: [{ bone: 0, position: [0, 2, 0], orientation: [0, 0, 0, 1], positionWeight, orientationWeight: 1 }],
      };
      const r = solver.solve(zero, goals);
      return orientationErrorsDeg(rig, r.angles, goals)[0];
    };
    // A heavy position goal turns the bone towards +y (orientation error near 90 degrees); a light one barely.
    expect(error(100)).toBeGreaterThan(80);
    expect(error(0.01)).toBeLessThan(5);
  });

  it('yields: a dragged goal gives way to the pinned ones; a value other than true or false is refused by name', () => {
    const rig = keep(
      new IkRig(
        ik,
        sketchRig(
          [
            { parent: -1, at: [0, 0, 0], length: 1 },
            { parent: 0, at: [1, 0, 0], length: 1 },
            { parent: 0, at: [1, 0, 0], length: 1 },
          ],
          [1, 2],
        ),
      ),
    );
    const start = new Float64Array(rig.numAngles);
    const tips = rig.tips(start);
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0, restarts: 0, tipTolerance: 1e-3 }));
    // Bone 1's target far beyond reach: it yields, bone 2 stays on its target although they share bone 0.
    const goals: Goals = {
      effectors: [
        { bone: 1, position: [10, 5, 0], yields: true },
        { bone: 2, position: tips.subarray(3, 6) },
      ],
    };
    const r = solver.solve(start, goals);
    const end = rig.tips(r.angles);
    expect(Math.hypot(end[3] - tips[3], end[4] - tips[4], end[5] - tips[5])).toBeLessThan(1e-3);
    expect(r.outOfReach).toBe(true);
    expect(r.goalsGivenUp).toBe(1);
    expect(() =>
      solver.solve(start, { effectors: [{ bone: 1, position: [1, 1, 0], yields: 1 as unknown as boolean }] }),
    ).toThrow('goals.effectors[0].yields must be true or false');
  });

  it('with strict priority (the default) the position holds as far as it can and the orientation gives way, whatever the weights', () => {
    const rig = keep(new IkRig(ik, sketchRig([{ parent: -1, at: [0, 0, 0], length: 1 }], [0])));
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0, restarts: 0, tipTolerance: 1e-3 }));
    for (const positionWeight of [0.01, 1, 100]) {
      // Within reach (0.8 along +y) but against the orientation goal (the bone along +x).
      const goals: Goals = {
        effectors: [
          { bone: 0, position: [0, 0.8, 0.6], orientation: [0, 0, 0, 1], positionWeight, orientationWeight: 1 },
        ],
      };
      const r = solver.solve(new Float64Array(3), goals);
      const tip = rig.tips(r.angles);
      expect(Math.hypot(tip[0], tip[1] - 0.8, tip[2] - 0.6), `weight ${positionWeight}`).toBeLessThan(1e-3);
      expect(r.reached).toBe(false);
      expect(r.orientationOutOfReach).toBe(true);
      expect(r.outOfReach).toBe(false);
      expect(orientationErrorsDeg(rig, r.angles, goals)[0]).toBeGreaterThan(80);
    }
  });

  it('start and step take goals too, and a change of goals between solves takes effect', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0 }));
    const zero = new Float64Array(rig.numAngles);
    const s = Math.SQRT1_2;
    const up: Goals = { effectors: [{ bone: 1, orientation: [0, 0, s, s] }] };
    const down: Goals = { effectors: [{ bone: 1, orientation: [0, 0, -s, s] }] };
    expect(solver.start(zero, up)).toBe('running');
    while (solver.step());
    const a = solver.result();
    expect(a.reached).toBe(true);
    const b = solver.solve(zero, down);
    expect(b.reached).toBe(true);
    expect(orientationErrorsDeg(rig, b.angles, down)[0]).toBeLessThan(0.5);
    expect(orientationErrorsDeg(rig, b.angles, up)[0]).toBeGreaterThan(170);
  });

  it('goals follow a change of end effectors', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0 }));
    const zero = new Float64Array(rig.numAngles);
    const goals: Goals = { effectors: [{ bone: 1, position: [0, 2, 0] }] };
    expect(solver.solve(zero, goals).reached).toBe(true);
    rig.setEffectors([0, 1]);
    const both: Goals = {
      effectors: [
        { bone: 0, position: [0, 1, 0] },
        { bone: 1, position: [1, 1, 0] },
      ],
    };
    const r = solver.solve(zero, both);
    expect(r.reached).toBe(true);
    const tips = rig.tips(r.angles);
    expect(tips[1]).toBeCloseTo(1, 2);
    expect(tips[3]).toBeCloseTo(1, 2);
  });

  it('paper mode refuses orientation goals with a message', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, 'gd', { paperMode: true }));
    expect(() => solver.solve(new Float64Array(6), { effectors: [{ bone: 1, orientation: [0, 0, 0, 1] }] })).toThrow(
      /paper mode/,
    );
  });
});

describe('bend hints, rest pull and stiffness', () => {
  /** The straight limb's elbow (bone 1's head) at `angles`. */
  const elbow = (rig: IkRig, angles: Float64Array) => rig.boneTips(angles).subarray(0, 3);

  // The page's drag tolerances (web/src/rig/tolerances.ts): a tip within 0.1% of the rig's size, a
  // gradient test scaled to it. (With the report's gradient tolerance, 1e-4, a run stops at
  // |grad E| < 1e-4 a few 1e-3 off a 1e-4 tip tolerance, and the solve falls back to the plain
  // solve from the start: on target, but unflipped.)
  const swivels: [string, string, number][] = [
    // gd stays put for the half turn: there the pole's pull on the elbow has no gradient (the elbow
    // ends pointing away, cos -1), and a first-order method has nothing else to go on.
    ...registered.filter((m) => m !== 'gd').map((m): [string, string, number] => [m, 'mirrored through the axis', 180]),
    ...registered.map((m): [string, string, number] => [m, 'a quarter turn away', 90]),
  ];
  it.each(swivels)(
    '%s: a pole %s turns a bent limb to its side without moving the tip (restarts 0)',
    (method, _, turn) => {
      const rig = keep(new IkRig(ik, straightLimb()));
      const { tipTolerance, gradientTolerance } = dragTolerances(
        rigSize(rig.boneTips(new Float64Array(rig.numAngles))),
      );
      const solver = keep(
        new IkSolver(rig, method, { timeBudgetSeconds: 0, tipTolerance, gradientTolerance, restarts: 0 }),
      );
      // Bent 90 degrees at the elbow, the bend plane turned -30 degrees about the limb's axis (x).
      const bent = new Float64Array([-30, 45, 0, 0, -90, 0]);
      const [, y, z] = elbow(rig, bent);
      const c = Math.cos((turn * Math.PI) / 180),
        s = Math.sin((turn * Math.PI) / 180);
      const pole = [0.7, 3 * (c * y - s * z), 3 * (s * y + c * z)]; // the bend direction turned about x
      const tip = rig.tips(bent);
      const result = solver.solve(bent, {
        effectors: [{ bone: 1, position: tip }],
        poles: [{ bone: 'bone 1', point: pole }],
      });
      expect(result.reached).toBe(true);
      const after = elbow(rig, result.angles);
      const cos =
        (after[1] * pole[1] + after[2] * pole[2]) / Math.hypot(after[1], after[2]) / Math.hypot(pole[1], pole[2]);
      expect(cos).toBeGreaterThan(0.99); // the elbow points at the pole
      const end = rig.tips(result.angles);
      expect(Math.hypot(end[0] - tip[0], end[1] - tip[1], end[2] - tip[2])).toBeLessThan(tipTolerance);
    },
  );

  it('a pole bends a straight limb towards it when the target comes nearer', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, 'lm', { timeBudgetSeconds: 0 }));
    for (const side of [1, -1]) {
      const result = solver.solve(new Float64Array(6), {
        effectors: [{ bone: 1, position: [1.5, 0, 0] }],
        poles: [{ bone: 1, point: [0.7, 0, 3 * side] }],
      });
      expect(result.reached).toBe(true);
      expect(elbow(rig, result.angles)[2] * side).toBeGreaterThan(0.3);
    }
  });

  it('restWeight keeps angles nearer rest at equal success, and stiffness keeps a bone still', () => {
    const limb = sketchRig(
      [0, 1, 2, 3].map((i) => ({ parent: i - 1, at: [i, 0, 0] as [number, number, number], length: 1 })),
      [3],
    );
    const rig = keep(new IkRig(ik, limb));
    const rng = seeded(11);
    const distance = (options: { restWeight: number }, stiffness?: Record<string, number>) => {
      const solver = new IkSolver(rig, 'lm', { timeBudgetSeconds: 0, ...options });
      let reached = 0,
        sum = 0,
        first = 0;
      for (let k = 0; k < 20; k++) {
        const goal = randomAngles(rig.spec, seeded(100 + k)).map((a) => a / 4);
        const r = solver.solve(new Float64Array(rig.numAngles), {
          effectors: [{ bone: 3, position: rig.tips(goal) }],
          stiffness,
        });
        if (r.reached) reached++;
        sum += r.angles.reduce((s, a) => s + Math.abs(a), 0) / rig.numAngles;
        first += Math.abs(r.angles[0]) + Math.abs(r.angles[1]) + Math.abs(r.angles[2]);
      }
      solver.dispose();
      return { reached, mean: sum / 20, first };
    };
    void rng;
    const free = distance({ restWeight: 0 });
    const pulled = distance({ restWeight: 0.05 });
    const stiff = distance({ restWeight: 0.05 }, { 'bone 0': 20 });
    expect(pulled.reached).toBe(free.reached);
    expect(stiff.reached).toBe(free.reached);
    expect(pulled.mean).toBeLessThan(free.mean);
    expect(stiff.first).toBeLessThan(pulled.first);
  });

  it('paper mode refuses poles and the rest pull', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const zero = new Float64Array(6);
    const paper = keep(new IkSolver(rig, 'gn', { paperMode: true }));
    expect(() =>
      paper.solve(zero, { effectors: [{ bone: 1, position: [1, 1, 0] }], poles: [{ bone: 1, point: [0, 1, 0] }] }),
    ).toThrow(/paper mode/);
    paper.setOptions({ paperMode: true, restWeight: 1 });
    expect(() => paper.solve(zero, [1, 1, 0])).toThrow(/paper mode/);
  });
});

describe('malformed goals are refused, naming the field', () => {
  const cases: [string, unknown, RegExp][] = [
    ['not an object', [1, 2, 3, 4], /target has 4 values/],
    ['no effectors array', { effector: [] }, /unknown goals field "effector"/],
    [
      'an unknown bone name',
      { effectors: [{ bone: 'hand', position: [0, 0, 0] }] },
      /goals\.effectors\[0\]\.bone "hand" is not a bone/,
    ],
    [
      'a bone that is no effector',
      { effectors: [{ bone: 0, position: [0, 0, 0] }] },
      /"bone 0" is not an end effector \(the end effectors are bone 1/,
    ],
    ['a bone index out of range', { effectors: [{ bone: 7, position: [0, 0, 0] }] }, /bone is 7, not a bone index/],
    [
      'a bone named twice',
      {
        effectors: [
          { bone: 1, position: [0, 0, 0] },
          { bone: 'bone 1', position: [0, 0, 0] },
        ],
      },
      /has a goal already/,
    ],
    [
      'a short position',
      { effectors: [{ bone: 1, position: [0, 0] }] },
      /effectors\[0\]\.position has 2 values, expected 3/,
    ],
    ['a NaN position', { effectors: [{ bone: 1, position: [0, NaN, 0] }] }, /position\[1\] is NaN/],
    ['a zero quaternion', { effectors: [{ bone: 1, orientation: [0, 0, 0, 0] }] }, /zero quaternion/],
    [
      'a quaternion of 3 numbers',
      { effectors: [{ bone: 1, orientation: [0, 0, 1] }] },
      /orientation \(a quaternion x, y, z, w\) has 3 values/,
    ],
    [
      'a negative weight',
      { effectors: [{ bone: 1, position: [0, 0, 0], weight: -1 }] },
      /weight must be a finite number >= 0/,
    ],
    [
      'an infinite orientation weight',
      { effectors: [{ bone: 1, orientation: [0, 0, 0, 1], orientationWeight: Infinity }] },
      /orientationWeight must be a finite/,
    ],
    [
      'a misspelt field',
      { effectors: [{ bone: 1, orientaton: [0, 0, 0, 1] }] },
      /unknown field goals\.effectors\[0\]\.orientaton/,
    ],
    [
      'a weight without its goal',
      { effectors: [{ bone: 1, positionWeight: 2 }] },
      /positionWeight is given without a position/,
    ],
    ['no goal at all', { effectors: [] }, /no goal/],
    ['only goals of weight 0', { effectors: [{ bone: 1, position: [0, 0, 0], weight: 0 }] }, /no goal/],
    [
      'a pole on a root bone',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], poles: [{ bone: 0, point: [0, 1, 0] }] },
      /poles\[0\]\.bone "bone 0" has no parent/,
    ],
    [
      'a pole without a point',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], poles: [{ bone: 1 }] },
      /poles\[0\]\.point must be an array/,
    ],
    [
      'a pole with a NaN point',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], poles: [{ bone: 1, point: [0, NaN, 0] }] },
      /poles\[0\]\.point\[1\] is NaN/,
    ],
    [
      'a pole with a misspelt field',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], poles: [{ bone: 1, pont: [0, 1, 0] }] },
      /unknown field goals\.poles\[0\]\.pont/,
    ],
    [
      'poles not an array',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], poles: { bone: 1 } },
      /goals\.poles must be an array/,
    ],
    [
      'stiffness of an unknown bone',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], stiffness: { elbow: 2 } },
      /stiffness key "elbow" is not a bone/,
    ],
    [
      'a negative stiffness',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], stiffness: { 'bone 0': -1 } },
      /stiffness\["bone 0"\] must be a finite number >= 0/,
    ],
    [
      'a negative length scale',
      { effectors: [{ bone: 1, position: [0, 0, 0] }], lengthScale: -2 },
      /lengthScale must be a finite number >= 0/,
    ],
  ];
  it.each(cases)('%s', (_, goals, message) => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, 'lm'));
    const zero = new Float64Array(rig.numAngles);
    expect(() => solver.solve(zero, goals as Goals)).toThrow(message);
    expect(() => solver.start(zero, goals as Goals)).toThrow(message);
    // The solver still works afterwards.
    expect(solver.solve(zero, [0, 2, 0]).reached).toBe(true);
  });
});
