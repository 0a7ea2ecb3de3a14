// A dragged goal that yields (the page's drag) reaches every target that the same goals reach as
// equals: on the project's hand, a finger dragged with the others pinned, along the bench's reach
// paths. Holding the pinned fingertips exactly leaves the dragged one short where letting them
// move within their tolerance meets every goal; the solver tries the goals as equals first.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { DragGoals } from '../../bench-node/drag_goals.js';
import { loadBenchRig } from '../../bench-node/rigs.js';
import { generateTargets } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';

let ik: IkCoreModule;
const owned: { dispose(): void }[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => owned.forEach((o) => o.dispose()));

describe('a yielding goal', () => {
  it('reaches, on the hand, every reach step that the goals as equals reach from the same start', async () => {
    const { spec } = await loadBenchRig('hand');
    const rig = new IkRig(ik, spec);
    owned.push(rig);
    const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
    const drag = dragTolerances(size);
    const options = {
      gradientTolerance: drag.gradientTolerance,
      tipTolerance: drag.tipTolerance,
      restarts: 0,
      timeBudgetSeconds: 0,
      maxJointMove: drag.maxJointMove,
    };
    const dragged = new IkSolver(rig, 'lm', options);
    const equals = new IkSolver(rig, 'lm', options);
    owned.push(dragged, equals);
    const set = generateTargets(spec, 'reach', 1e5, 1, (a) => rig.tips(a));
    const goals = new DragGoals(spec, Array.from(rig.effectors()), false);
    const r = set.numResiduals,
      m = set.numAngles;
    let current: Float64Array = new Float64Array(m),
      both = 0,
      equalsOnly = 0,
      partway = 0,
      resumes = false;
    // Paths 0-9: the first effector's, and the second's.
    for (let k = 0; k < 10 * 40; k++) {
      const start = set.chained[k] ? current : set.starts.slice(k * m, (k + 1) * m);
      const target = set.targets.subarray(k * r, (k + 1) * r);
      if (!set.chained[k]) goals.pin(rig.tipRotations(start), set.dragged[k]);
      const asEquals = equals.solve(start, target);
      const yielding = dragged.solve(start, goals.goals(target, set.dragged[k]));
      // A step the yielding solve ends partway to another branch (joint_speed: the joints may move
      // as far as the targets moved since the last frame, and 4% of the size more), and the step
      // after it (which resumes that move from the answer it was heading to, not from the start),
      // are the speed bound at work, not the priority: counted apart.
      if (asEquals.reached && (yielding.stopReason === 'joint_speed' || resumes)) partway++;
      else if (asEquals.reached && yielding.reached) both++;
      else if (asEquals.reached) equalsOnly++;
      resumes = yielding.stopReason === 'joint_speed';
      // Whatever it reached, the pinned tips stay within the tolerance.
      const tips = rig.tips(yielding.angles);
      for (let e = 0; e < r / 3; e++) {
        if (e === set.dragged[k]) continue;
        const off = Math.hypot(
          tips[3 * e] - target[3 * e],
          tips[3 * e + 1] - target[3 * e + 1],
          tips[3 * e + 2] - target[3 * e + 2],
        );
        expect(off, `step ${k}, effector ${e}`).toBeLessThanOrEqual(drag.tipTolerance);
      }
      current = yielding.angles;
    }
    expect(both).toBeGreaterThan(100);
    expect(equalsOnly, `reached by both ${both}`).toBe(0);
    expect(partway).toBeLessThanOrEqual(4);
  });
});
