// What crosses into WebAssembly: inputs are checked and copied
// before C++ sees them, so user code cannot free a rig under C++ and no JavaScript error is raised
// inside a binding; the core's own refusals come back as Errors without leaking its stack; a
// solve whose workspace grows the memory still reports its result.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { IkSolver, type SolverOptions } from '../../web/src/ik/solver.js';
import { disposeAfterAll } from '../helpers/owned.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});

/** A straight chain of `n` unit bones along +x, +-90 degrees per angle, with `effectors`. */
function chain(n: number, effectors: number[]): RigSpec {
  const rest = new Float64Array(16 * n);
  for (let i = 0; i < n; i++) rest.set([1, 0, 0, i, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], 16 * i);
  return {
    names: [],
    parents: Int32Array.from({ length: n }, (_, i) => i - 1),
    rest,
    lengths: new Float64Array(n).fill(1),
    lower: new Float64Array(3 * n).fill(-90),
    upper: new Float64Array(3 * n).fill(90),
    effectors: Int32Array.from(effectors),
  };
}

describe('inputs are plain numbers before they reach C++', () => {
  it('a valueOf or getter that disposes the rig never runs inside a call', () => {
    const rig = new IkRig(ik, chain(3, [2]));
    let ran = false;
    const hostile = { valueOf: () => ((ran = true), rig.dispose(), 0) };
    const angles: unknown[] = Array.from({ length: rig.numAngles }, () => 0);
    angles[4] = hostile;
    for (const call of [
      () => rig.boneTips(angles as number[]),
      () => rig.poses(angles as number[]),
      () => rig.project(angles as number[]),
    ])
      expect(call).toThrow('angles[4] is an object, not a number');
    expect(ran).toBe(false);
    const withGetter = Array.from({ length: rig.numAngles }, () => 0);
    Object.defineProperty(withGetter, 5, { get: () => (rig.dispose(), 0) });
    expect(() => rig.tips(withGetter)).toThrow('this rig was disposed');
    expect(rig.isDisposed).toBe(true);
  });

  it('a huge or missing array is refused by its length before any copy', () => {
    const rig = keep(new IkRig(ik, chain(3, [2])));
    const solver = keep(new IkSolver(rig, 'lm'));
    expect(() => solver.solve({ length: 1e10 } as unknown as number[], [1, 1, 0])).toThrow(/angles must be an array/);
    expect(() => solver.solve(new Float64Array(9), null as unknown as number[])).toThrow(
      'target must be an array or a typed array of numbers, not null',
    );
    expect(() => rig.tips(undefined as unknown as number[])).toThrow(
      'angles must be an array or a typed array of numbers, not undefined',
    );
    expect(() => new IkRig(ik, { ...chain(3, [2]), rest: null } as unknown as RigSpec)).toThrow(/^rest .* not null$/);
    expect(solver.solve(new Float64Array(9), [1, 1, 0]).reached).toBe(true);
  });

  it('options must be a plain object of known names with number or boolean values', () => {
    const rig = keep(new IkRig(ik, chain(3, [2])));
    const bad: [unknown, RegExp][] = [
      [[1, 2], /solver option must be a plain object .* not an array/],
      [new Map([['maxIterations', 3]]), /solver option must be a plain object .* not an object/],
      [{ maxIterations: '3' }, /solver option maxIterations must be a number or a boolean/],
      [{ nope: 1 }, /unknown solver option "nope" \(known: gradientTolerance, /],
    ];
    for (const [options, message] of bad) {
      expect(() => new IkSolver(rig, 'lm', options as SolverOptions)).toThrow(message);
      const solver = keep(new IkSolver(rig, 'lm', { maxIterations: 7 }));
      expect(() => solver.setOptions(options as SolverOptions)).toThrow(message);
      expect(solver.options().maxIterations).toBe(7);
    }
    let reads = 0;
    const getter = Object.defineProperty({}, 'maxIterations', { enumerable: true, get: () => (++reads, 5) });
    expect(keep(new IkSolver(rig, 'lm', getter)).options().maxIterations).toBe(5);
    expect(reads).toBe(1);
  });
});

describe('the solve buffer', () => {
  it('a solve after dispose writes nothing into freed memory', () => {
    const rig = new IkRig(ik, chain(3, [2]));
    const solver = new IkSolver(rig, 'lm');
    solver.solve(new Float64Array(9), [1, 1, 0]);
    solver.dispose();
    expect(() => solver.solve(new Float64Array(9), [1, 1, 0])).toThrow('this solver was disposed');
    rig.dispose(); // trapped ("memory access out of bounds") when the solve wrote its inputs first
    const canary = keep(new IkRig(ik, chain(3, [2])));
    expect(keep(new IkSolver(canary, 'lm')).solve(new Float64Array(9), [1, 1, 0]).reached).toBe(true);
  });

  it('a Proxy that solves while its entries are read does not mix the two solves', () => {
    const rig = keep(new IkRig(ik, chain(2, [1])));
    const solver = keep(new IkSolver(rig, 'lm', { restarts: 0 }));
    const plain = [0, 90, 0, 0, 0, 0];
    const expected = solver.solve(plain, [0, 2, 0]).initialE;
    const proxy = new Proxy(plain, {
      get(t, p, r) {
        if (p === '4') solver.solve([0, 0, 0, 0, 0, 0], [2, 0, 0]);
        return Reflect.get(t, p, r) as unknown;
      },
    });
    expect(solver.solve(proxy, [0, 2, 0]).initialE).toBe(expected);
  });

  it('out must be a Float64Array of the angles: other arrays are refused, not rounded', () => {
    const rig = keep(new IkRig(ik, chain(2, [1])));
    const solver = keep(new IkSolver(rig, 'lm'));
    for (const out of [new Float32Array(6), new Int8Array(6), [0, 0, 0, 0, 0, 0], new Float64Array(5)])
      expect(() => solver.solve(new Float64Array(6), [0, 2, 0], out as Float64Array)).toThrow(
        'out must be a Float64Array of 6 numbers (the angles)',
      );
    const out = new Float64Array(6);
    expect(solver.solve(new Float64Array(6), [0, 2, 0], out).angles).toBe(out);
  });
});

describe("the core's refusals", () => {
  it('come back as Errors with the message, and the module keeps working', () => {
    const rig = keep(new IkRig(ik, chain(3, [2])));
    const solver = keep(new IkSolver(rig, 'lm', { errorTolerance: -1 }));
    const angles = new Float64Array(9);
    let thrown = 0;
    for (let i = 0; i < 1000; i++) {
      try {
        solver.solve(angles, [1, 1, 0]); // refused in C++ (an option out of range)
      } catch (e) {
        if ((e as Error).message.startsWith('solver option errorTolerance must be a number > 0')) thrown++;
      }
    }
    expect(thrown).toBe(1000); // tests/fuzz: 200,000 of them, and `npm run fuzz` a million
    expect(() => IkSolver.describe(ik, 'nope')).toThrow('unknown solver method "nope"');
    expect(() => new IkSolver(rig, 'nope')).toThrow(/unknown solver method "nope"/);
    expect(() => rig.setEffectors([-1])).toThrow('end effector 0 is bone -1, which is not a bone of the rig (0..2)');
    expect(ik.takeError()).toBe('');
    solver.setOptions({ tipTolerance: 1e-6 });
    const r = solver.solve(angles, [1, 1, 0]);
    expect(r.reached).toBe(true);
    expect(Math.hypot(...Array.from(rig.tips(r.angles)).map((x, k) => x - [1, 1, 0][k]))).toBeLessThan(1e-6);
  });

  it('a rig past the size limits is refused with the limit named', () => {
    const effectors = Array.from({ length: 60 }, (_, i) => 9999 - i);
    expect(() => new IkRig(ik, chain(10_000, effectors))).toThrow(
      '60 end effectors on 10000 bones make a Jacobian of 5400000 numbers; the core takes at most 1048576',
    );
    const rig = keep(new IkRig(ik, chain(300, [299])));
    expect(() => keep(new IkSolver(rig, 'newton')).solve(new Float64Array(900), [100, 100, 0])).toThrow(
      'newton takes rigs of at most 384 angles (128 bones); this one has 900: use lm or gd',
    );
    expect(() =>
      keep(new IkSolver(rig, 'lm', { historyCapacity: 1e8 })).solve(new Float64Array(900), [100, 100, 0]),
    ).toThrow('solver option historyCapacity must be in 1..1000000');
  });
});

describe('a big rig', () => {
  it('a solve that grows the WebAssembly memory still returns its result', () => {
    const rig = keep(new IkRig(ik, chain(10_000, [9999])));
    const solver = keep(new IkSolver(rig, 'lm', { restarts: 0, maxIterations: 3, timeBudgetSeconds: 0 }));
    const r = solver.solve(new Float64Array(rig.numAngles), [5000, 5000, 0]);
    expect(r.iterations).toBe(3);
    expect(r.stopReason).toBe('max_iterations');
    expect(r.E).toBeLessThan(r.initialE);
    const tip = rig.tips(r.angles);
    expect(0.5 * ((tip[0] - 5000) ** 2 + (tip[1] - 5000) ** 2 + tip[2] ** 2)).toBeCloseTo(r.E, 6);
  });
});

describe('results into arrays the caller keeps', () => {
  it('tips, boneTips, tipRotations and poses write into `out` what they return otherwise, and return `out`', () => {
    const rig = keep(new IkRig(ik, chain(5, [2, 4])));
    const a = Float64Array.from({ length: rig.numAngles }, (_, i) => 7 * Math.sin(i));
    const outputs = [
      ['tips', 6],
      ['boneTips', 15],
      ['tipRotations', 8],
      ['poses', 80],
    ] as const;
    for (const [what, count] of outputs) {
      const fresh = rig[what](a);
      expect(fresh.length, what).toBe(count);
      const out = new Float64Array(count).fill(NaN);
      expect(rig[what](a, out), what).toBe(out);
      expect(Array.from(out), what).toEqual(Array.from(fresh));
      // From a plain array too (checked and copied first).
      expect(Array.from(rig[what](Array.from(a), new Float64Array(count))), what).toEqual(Array.from(fresh));
      expect(() => rig[what](a, new Float64Array(count + 1)), what).toThrow(
        `${what}: out must be a Float64Array of ${count} numbers`,
      );
      expect(() => rig[what](a, new Float32Array(count) as unknown as Float64Array), what).toThrow(
        'out must be a Float64Array',
      );
    }
    const bad = a.slice();
    bad[3] = Infinity;
    expect(() => rig.tips(bad, new Float64Array(6))).toThrow('angles[3] is Infinity, not a finite number');
  });

  it('a rig asked again after the WebAssembly memory grew reads its new buffer', () => {
    const rig = keep(new IkRig(ik, chain(4, [3])));
    const a = new Float64Array(rig.numAngles).fill(10);
    const before = rig.poses(a);
    const heap = ik.HEAPU8.buffer;
    const big = keep(new IkRig(ik, chain(16_000, [15_999]))); // grows the memory: the first rig's view is left empty
    big.poses(new Float64Array(big.numAngles));
    expect(ik.HEAPU8.buffer).not.toBe(heap);
    expect(Array.from(rig.poses(a, new Float64Array(before.length)))).toEqual(Array.from(before));
    expect(Array.from(rig.tips(a))).toEqual(Array.from(rig.tips(Array.from(a))));
  });

  it("a solver's E history copies into `out` as far as it fits and says its whole length", () => {
    const rig = keep(new IkRig(ik, chain(6, [5])));
    const solver = keep(new IkSolver(rig, 'gd', { restarts: 0, maxIterations: 20, timeBudgetSeconds: 0 }));
    const r = solver.solve(new Float64Array(rig.numAngles), [3, 3, 0]);
    const history = solver.errorHistory();
    expect(history.length).toBe(r.iterations + 1);
    expect(history[0]).toBe(r.initialE);
    const whole = new Float64Array(history.length + 3).fill(-1);
    expect(solver.copyErrorHistory(whole)).toBe(history.length);
    expect(Array.from(whole.subarray(0, history.length))).toEqual(Array.from(history));
    expect(whole[history.length]).toBe(-1); // nothing written past it
    const short = new Float64Array(2);
    expect(solver.copyErrorHistory(short)).toBe(history.length);
    expect(Array.from(short)).toEqual(Array.from(history.subarray(0, 2)));
  });
});
