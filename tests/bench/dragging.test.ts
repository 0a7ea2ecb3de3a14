// Drag and reach are solved and judged as a user's drag: the page's drag tolerances (a tip
// distance), no restarts, success when every tip is within the tip tolerance, for our solvers on
// both engines and for the peers alike; and each runner reports the tip distance and the jump
// (largest single-angle change, the shortest way round for an angle without limits) of the pose
// it returns.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { prepareRigs, runSettings } from '../../bench-node/bench.js';
import { isOnTarget, largestChange } from '../../bench-node/evaluate.js';
import { parseOptions } from '../../bench-node/options.js';
import { ClosedChainIkRunner } from '../../bench-node/peers/closed_chain_ik.js';
import { ThreeCcdRunner } from '../../bench-node/peers/three_ccd.js';
import { runNative } from '../../bench-node/run_native.js';
import type { Runner, RunSettings } from '../../bench-node/runner.js';
import { WasmSolverRunner } from '../../bench-node/solve_wasm.js';
import { independentRanges, prefix, type TargetSet } from '../../bench-node/target_set.js';
import { DRAG_PATH_STEPS, generateTargets } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { loadTestRig, rigsLike } from '../helpers/a7.js';

let ik: IkCoreModule;
beforeAll(async () => {
  ik = await loadIkNode();
});

describe('settings', () => {
  const settingsOf = async (...args: string[]): Promise<Record<string, RunSettings>> => {
    const opts = parseOptions(['--rig', 'lamp', ...args], false, IkSolver.methods(ik))!;
    const [lamp] = await prepareRigs(opts, ik);
    expect(lamp.size).toBeGreaterThan(0);
    return Object.fromEntries(
      (['random', 'incremental', 'drag', 'reach'] as const).map((e) => [e, runSettings(lamp, e, 'lm', opts)]),
    );
  };

  it('drag and reach: the drag tolerances and no restarts; random and incremental: the report tolerances', async () => {
    const s = await settingsOf();
    const size = s.drag.rigSize;
    for (const e of ['drag', 'reach']) {
      expect(s[e].tipTolerance).toBe(dragTolerances(size).tipTolerance);
      expect(s[e].gradientTolerance).toBe(dragTolerances(size).gradientTolerance);
      expect(s[e].restarts).toBe(0);
    }
    for (const e of ['random', 'incremental']) {
      expect(s[e].tipTolerance).toBe(0);
      expect(s[e].gradientTolerance).toBeCloseTo(1e-4 * size ** 2, 15);
      expect(s[e].errorTolerance).toBeCloseTo(2e-4 * size ** 2, 15);
      expect(s[e].restarts).toBeUndefined();
    }
  });

  it('--error-tolerance makes drag and reach use E < errorTolerance; --gradient-tolerance replaces their gradient tolerance', async () => {
    const f = await settingsOf('--error-tolerance', '1e-7');
    expect(f.reach.tipTolerance).toBe(0);
    expect(f.reach.errorTolerance).toBe(1e-7);
    expect(f.drag.gradientTolerance).toBe(dragTolerances(f.drag.rigSize).gradientTolerance);
    const g = await settingsOf('--gradient-tolerance', '1e-9');
    expect(g.drag.gradientTolerance).toBe(1e-9);
    expect(g.reach.gradientTolerance).toBe(1e-9);
    expect(g.reach.tipTolerance).toBe(dragTolerances(g.reach.rigSize).tipTolerance);
  });
});

/** Runs the samples [begin, end) of `set` through `runner`, chained as the workers chain them. */
function runAll(runner: Runner, set: TargetSet, [begin, end] = [0, set.count]): ReturnType<Runner['solve']>[] {
  const m = set.numAngles,
    r = set.numResiduals;
  return Array.from({ length: end - begin }, (_, i) => {
    const k = begin + i;
    return runner.solve({
      start: set.chained[k] ? null : set.starts.slice(k * m, (k + 1) * m),
      target: set.targets.subarray(k * r, (k + 1) * r),
      dragged: set.dragged[k],
    });
  });
}

describe.each(rigsLike('knight'))('the drag runners on $label', (knight) => {
  let spec: RigSpec;
  let rig: IkRig;
  let reach: TargetSet;
  let drag: RunSettings;
  beforeAll(() => {
    spec = loadTestRig(knight);
    rig = new IkRig(ik, spec);
    reach = generateTargets(spec, 'reach', 10000, 1, (a) => rig.tips(a));
    const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
    const { tipTolerance, gradientTolerance } = dragTolerances(size);
    drag = {
      method: 'lm',
      gradientTolerance: gradientTolerance,
      errorTolerance: 2e-4,
      tipTolerance,
      timeBudgetSeconds: 1,
      paper: false,
      rigSize: size,
      restarts: 0,
    };
  });
  afterAll(() => rig.dispose());

  describe('WebAssembly runner', () => {
    it('reports the tip distance and the jump of the returned pose, as the API computes them on a new solver', () => {
      const path = prefix(reach, 40);
      const runner = new WasmSolverRunner(ik, spec, drag);
      runAll(runner, prefix(reach, 3)); // what ran before changes nothing
      const results = runAll(runner, path);
      runner.dispose();
      // The same solves made directly through the API, each on a new solver.
      let pose: Float64Array = path.starts.slice(0, path.numAngles);
      let largest = 0,
        chainRestarts = 0;
      results.forEach((result, k) => {
        const target = path.targets.subarray(k * path.numResiduals, (k + 1) * path.numResiduals);
        const solver = new IkSolver(rig, 'lm', {
          gradientTolerance: drag.gradientTolerance,
          tipTolerance: drag.tipTolerance,
          restarts: 0,
        });
        const r = solver.solve(pose, target);
        solver.dispose();
        const jump = largestChange(pose, r.angles, spec.lower, spec.upper);
        expect(result.jumpDeg).toBe(jump);
        expect(result.tipDistance).toBeCloseTo(r.tipDistance, 12);
        expect(isOnTarget(drag, result.E, result.tipDistance)).toBe(r.reached);
        largest = Math.max(largest, jump);
        chainRestarts += r.chainRestarts;
        pose = r.angles;
      });
      expect(largest).toBeGreaterThan(0);
      // Some steps restart chains: on a reused solver they would draw other points.
      expect(chainRestarts).toBeGreaterThan(0);
    });
  });

  describe('native engine', () => {
    it('reports the same tip distances, jumps and verdicts as WebAssembly with --tip-tolerance', async () => {
      const set = generateTargets(spec, 'incremental', 12, 3, (a) => rig.tips(a));
      const settings = { ...drag, restarts: undefined };
      const runner = new WasmSolverRunner(ik, spec, settings);
      const wasm = runAll(runner, set);
      runner.dispose();
      const native = await runNative(spec, settings, set, 1, () => {});
      native.forEach((n, k) => {
        expect(n.stopReason).toBe(wasm[k].stopReason);
        expect(n.tipDistance).toBeCloseTo(wasm[k].tipDistance, 9);
        expect(n.jumpDeg).toBeCloseTo(wasm[k].jumpDeg, 6);
        expect(isOnTarget(settings, n.E, n.tipDistance)).toBe(isOnTarget(settings, wasm[k].E, wasm[k].tipDistance));
      });
      expect(native.filter((n) => n.stopReason === 'converged_E').length).toBeGreaterThan(6);
      expect(Math.max(...native.map((n) => n.jumpDeg))).toBeGreaterThan(0);
    });

    it('reports the same wobble as WebAssembly: the two replays agree', async () => {
      // Two drag paths, each step solved from its own start (not chained), so that rounding
      // differences between the engines cannot build up along a path. Even so the engines' solves
      // differ in the last digits, which near a straight limb can grow (the project knight's second
      // path ends up to 15% apart in E): the steps both solve alike (the same iterations, the same
      // tip distance to 0.1% of the tip tolerance), at least a path's worth, must show the same
      // wobble to that precision.
      const paths = generateTargets(spec, 'drag', 80, 2, (a) => rig.tips(a));
      const set = { ...paths, chained: new Uint8Array(paths.count) };
      const runner = new WasmSolverRunner(ik, spec, drag);
      const wasm = runAll(runner, set);
      runner.dispose();
      const native = await runNative(spec, drag, set, 1, () => {});
      const precision = 1e-3 * drag.tipTolerance;
      const alike = native.flatMap((n, k) =>
        n.iterations === wasm[k].iterations && Math.abs(n.tipDistance - wasm[k].tipDistance) <= precision ? [k] : [],
      );
      expect(alike.length).toBeGreaterThanOrEqual(DRAG_PATH_STEPS);
      for (const k of alike) {
        expect(Math.abs(native[k].wobbleDuring - wasm[k].wobbleDuring), `step ${k}`).toBeLessThanOrEqual(precision);
        expect(Math.abs(native[k].wobbleAfter - wasm[k].wobbleAfter), `step ${k}`).toBeLessThanOrEqual(precision);
      }
    });
  });

  describe.each(['three-ccd', 'closed-chain-ik'])('%s on reach paths', (method) => {
    it('stops on the tip test and reports the tip distance and jump of its pose', () => {
      const settings = { ...drag, method, timeBudgetSeconds: 0.05 };
      const runner =
        method === 'three-ccd' ? new ThreeCcdRunner(spec, settings) : new ClosedChainIkRunner(spec, settings);
      // The second draggable effector's paths, up to the first with a solve on target (CCD misses
      // whole paths; the first effector's are mostly out of the peers' reach on the project's knight).
      let onTarget = 0,
        largestJump = 0;
      for (const path of independentRanges(reach).slice(3, 6)) {
        for (const result of runAll(runner, reach, path)) {
          // E bounds the largest tip distance: max^2 <= 2E <= #effectors * max^2.
          expect(result.tipDistance ** 2).toBeLessThanOrEqual(2 * result.E * (1 + 1e-9));
          expect(2 * result.E).toBeLessThanOrEqual(spec.effectors.length * result.tipDistance ** 2 * (1 + 1e-9));
          // On target means the tip test, not E < errorTolerance (which allows tips 20 times farther off here).
          if (result.stopReason === 'converged_E') {
            expect(result.tipDistance).toBeLessThan(drag.tipTolerance);
            onTarget++;
          }
          expect(result.jumpDeg).toBeGreaterThanOrEqual(0);
          largestJump = Math.max(largestJump, result.jumpDeg);
        }
        if (onTarget > 0) break;
      }
      runner.dispose();
      expect(onTarget).toBeGreaterThan(0);
      expect(largestJump).toBeGreaterThan(0);
    });
  });
});
