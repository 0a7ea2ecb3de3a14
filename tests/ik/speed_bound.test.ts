// The speed bound with pinned goals: a solve that lands on another branch returns a pose partway
// there, and the few steps that bring the pinned tips back within their tolerance must not carry
// the joints past the bound. On the character's gesture "right hand pushed past its reach", as
// the page drags it (bench runSettings: the dragged hand yields, the others pinned with their
// frames, 4% of the height per step), one step moved a joint 8.2% of the height while the target
// moved 0.36%: no step may be a jump, and the pinned tips stay within the tolerance throughout.
import { describe, expect, it } from 'vitest';

import { prepareRigs, runSettings, targetSetsFor } from '../../bench-node/bench.js';
import { draggedTargetMoves, isJump } from '../../bench-node/jumps.js';
import { parseOptions } from '../../bench-node/options.js';
import { WasmSolverRunner } from '../../bench-node/solve_wasm.js';
import { StepMeasurer } from '../../bench-node/step_measures.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';

const PUSH_PAST_REACH = 7; // gesture path index: the right hand pushed past its reach

describe('the speed bound with pinned goals', () => {
  it('moves no joint by a jump while the character pushes a hand past its reach', async () => {
    const ik = await loadIkNode();
    const opts = parseOptions(
      ['--rig', 'character', '--experiment', 'gestures', '--methods', 'lm', '--no-progress'],
      false,
      IkSolver.methods(ik),
    )!;
    const [rig] = await prepareRigs(opts, ik);
    const set = targetSetsFor(rig, opts, ik).get('gestures')!;
    const settings = runSettings(rig, 'gestures', 'lm', opts);
    const core = new IkRig(ik, rig.spec);
    const runner = new WasmSolverRunner(ik, rig.spec, settings);
    try {
      const measurer = new StepMeasurer(rig.spec, core, rig.limbs);
      const moves = draggedTargetMoves(set, (a) => core.tips(a));
      const m = set.numAngles,
        r = set.numResiduals;
      const first = set.group.indexOf(PUSH_PAST_REACH);
      let previous = set.starts.slice(first * m, (first + 1) * m);
      let steps = 0,
        partway = 0;
      for (let k = first; k < set.count && set.group[k] === PUSH_PAST_REACH; k++, steps++) {
        const start = set.chained[k] && k > first ? null : set.starts.slice(k * m, (k + 1) * m);
        const from = start ?? previous;
        const result = runner.solve({
          start,
          target: set.targets.subarray(k * r, (k + 1) * r),
          dragged: set.dragged[k],
        });
        const to = result.angles!;
        const jointMove = measurer.measure(from, to).jointMove;
        expect(
          isJump(jointMove, moves[k], rig.size),
          `step ${k - first}: joints moved ${((100 * jointMove) / rig.size).toFixed(1)}% of the height`,
        ).toBe(false);
        expect(result.wobbleAfter, `step ${k - first}: the pinned tips`).toBeLessThan(settings.tipTolerance);
        if (result.stopReason === 'joint_speed') partway++;
        previous = to.slice();
      }
      expect(steps).toBeGreaterThan(100);
      expect(partway).toBeGreaterThan(0); // the path does cross to another branch
    } finally {
      runner.dispose();
      core.dispose();
    }
  });
});
