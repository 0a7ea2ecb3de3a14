// The calls an API case strings together, each with careless or hostile arguments, and what a
// correct result of each must satisfy.
import type { Numbers } from '#ik/rig.js';
import { IkSolver, type SolverOptions, type SolverResult } from '#ik/solver.js';
import { changeEffectors, type ApiState } from './api_state.js';
import { attempt, both } from './attempt.js';
import { forwardKinematics } from './forward_kinematics.js';
import { goalsArg } from './hostile_goals.js';
import { numbersArg, type Acceptance, type Arg } from './hostile_args.js';
import { judgeSolve } from './judge_solve.js';
import { methodArg, optionsArg } from './hostile_options.js';
import { OK, worse, type Outcome } from './outcome.js';
import type { Rand } from './random.js';
import { randomAngles } from './random_rig.js';
import {
  clampToLimits,
  closeProblem,
  comparable,
  limitsProblem,
  numbersProblem,
  referenceTips,
  rigScale,
} from './result_checks.js';

/** One call: its description and how to run and judge it. */
export interface Step {
  text: string;
  run(): Outcome;
}

type Op = (r: Rand, s: ApiState) => Step;

function anglesArg(r: Rand, s: ApiState): Arg {
  return numbersArg(r, s, randomAngles(r, s.spec), 'angles');
}

/** Targets of effectors this far out: finite, and their squares still fit a double. */
const FAR_TARGET = 1e150;

function targetArg(r: Rand, s: ApiState): Arg {
  const reachable = referenceTips(s.spec, randomAngles(r, s.spec));
  const valid = r.weighted<() => Float64Array>([
    [16, () => reachable],
    [4, () => reachable.map(() => r.range(-5, 5))],
    [1, () => reachable.map(() => (r.chance(0.5) ? FAR_TARGET : -FAR_TARGET))],
  ])();
  return numbersArg(r, s, valid, 'target');
}

/** Known numbers of a 'must' argument small enough for the reference kinematics. */
function known(a: Arg): Float64Array | undefined {
  return a.accept === 'must' && a.numbers && comparable(a.numbers) ? a.numbers : undefined;
}

/** An array result: finite, of `length` numbers when the arguments were plain, equal to `reference` when given. */
function arrayProblem(
  name: string,
  v: unknown,
  length: number | undefined,
  reference: (() => Float64Array) | undefined,
  scale: number,
): string | undefined {
  const n = length ?? (v as ArrayLike<number> | null)?.length ?? 0;
  return (
    numbersProblem(name, v, n) ?? (reference ? closeProblem(name, v as Float64Array, reference(), scale) : undefined)
  );
}

/** A rig call taking angles and returning an array: its length per spec and its reference value, if there is one. */
function rigArrayOp(
  name: 'tips' | 'boneTips' | 'poses' | 'jacobian',
  length: (s: ApiState) => number,
  reference?: (s: ApiState, angles: Float64Array) => Float64Array,
): Op {
  return (r, s) => {
    const a = anglesArg(r, s);
    return {
      text: `rig.${name}(${a.text})`,
      run: () =>
        attempt(
          a.accept,
          () => s.rig[name](a.value as Numbers),
          (v) => {
            const k = known(a);
            return arrayProblem(
              name,
              v,
              a.accept === 'must' ? length(s) : undefined,
              k && reference ? () => reference(s, k) : undefined,
              rigScale(s.spec),
            );
          },
        ),
    };
  };
}

const tips = rigArrayOp(
  'tips',
  (s) => 3 * s.spec.effectors.length,
  (s, a) => referenceTips(s.spec, a),
);
const boneTips = rigArrayOp(
  'boneTips',
  (s) => 3 * s.spec.parents.length,
  (s, a) => forwardKinematics(s.spec, a).tips,
);
const poses = rigArrayOp(
  'poses',
  (s) => 16 * s.spec.parents.length,
  (s, a) => forwardKinematics(s.spec, a).poses,
);
const jacobian = rigArrayOp('jacobian', (s) => 9 * s.spec.effectors.length * s.spec.parents.length);

const finiteDifferenceJacobian: Op = (r, s) => {
  const a = anglesArg(r, s);
  const h = r.pick<unknown>([1e-7, 1e-3, 0, -1, NaN, Infinity, 1e300, 5e-324, '1e-3', undefined]);
  const clamp = r.pick<unknown>([true, false, 0, 'yes', undefined, null]);
  const hOk: Acceptance =
    typeof h === 'number' && h > 0 && Number.isFinite(h)
      ? 'must'
      : h === undefined || h === '1e-3'
        ? 'either'
        : 'mustNot';
  return {
    text: `rig.finiteDifferenceJacobian(${a.text}, ${String(h)}, ${String(clamp)})`,
    run: () =>
      attempt(
        both(a.accept, hOk),
        () => s.rig.finiteDifferenceJacobian(a.value as Numbers, h as number, clamp as boolean),
        (v) =>
          arrayProblem(
            'jacobian',
            v,
            a.accept === 'must' ? 9 * s.spec.effectors.length * s.spec.parents.length : undefined,
            undefined,
            1,
          ),
      ),
  };
};

const objective: Op = (r, s) => {
  const a = anglesArg(r, s),
    t = targetArg(r, s);
  return {
    text: `rig.objective(${a.text}, ${t.text})`,
    run: () =>
      attempt(
        both(a.accept, t.accept),
        () => s.rig.objective(a.value as Numbers, t.value as Numbers),
        (E) => {
          if (!Number.isFinite(E)) return `E is ${E}`;
          const ka = known(a),
            kt = known(t);
          if (!ka || !kt || both(a.accept, t.accept) !== 'must') return undefined;
          const tipsAt = referenceTips(s.spec, ka);
          const r2 = tipsAt.reduce((sum, x, i) => sum + (x - kt[i]) ** 2, 0);
          return closeProblem(
            'sqrt(2 E)',
            [Math.sqrt(2 * E)],
            [Math.sqrt(r2)],
            rigScale(s.spec) + Math.max(...Array.from(kt, Math.abs)),
          );
        },
      ),
  };
};

const gradient: Op = (r, s) => {
  const a = anglesArg(r, s),
    t = targetArg(r, s);
  const accept = both(a.accept, t.accept);
  return {
    text: `rig.gradient(${a.text}, ${t.text})`,
    run: () =>
      attempt(
        accept,
        () => s.rig.gradient(a.value as Numbers, t.value as Numbers),
        (v) => arrayProblem('gradient', v, accept === 'must' ? 3 * s.spec.parents.length : undefined, undefined, 1),
      ),
  };
};

const project: Op = (r, s) => {
  const a = anglesArg(r, s);
  return {
    text: `rig.project(${a.text})`,
    run: () =>
      attempt(
        a.accept,
        () => s.rig.project(a.value as Numbers),
        (v) => {
          const n = a.accept === 'must' ? 3 * s.spec.parents.length : undefined;
          const bad = arrayProblem('projected', v, n, undefined, 1) ?? limitsProblem('projected', v, s.spec);
          if (bad || a.accept !== 'must' || !a.numbers) return bad;
          return closeProblem('projected', v, clampToLimits(s.spec, a.numbers), 0);
        },
      ),
  };
};

const setEffectors: Op = (r, s) => {
  const n = s.spec.parents.length;
  const [text, value, accept] = r.weighted<() => [string, unknown, Acceptance]>([
    [
      4,
      () => {
        const list = [...Array(n).keys()].filter(() => r.chance(0.3)).slice(0, 8);
        return [`[${list}]`, list.length ? list : [n - 1], 'must'];
      },
    ],
    [1, () => ['an Int32Array [0]', Int32Array.of(0), 'must']],
    [1, () => ['[]', [], 'mustNot']],
    [
      4,
      () => {
        const bad = r.pick<unknown>([
          -1,
          n,
          1.5,
          NaN,
          Infinity,
          2 ** 32 + 1,
          -(2 ** 31),
          '0',
          null,
          0n,
          { valueOf: () => 0 },
        ]);
        return [`[0, ${String(bad)}]`, [0, bad], 'mustNot'];
      },
    ],
    [1, () => ['[0, 0] (repeated)', [0, 0], 'mustNot']],
    [
      1,
      () => {
        const count = r.pick([256, 257, 1000]);
        return [
          `${count} bones`,
          [...Array(Math.min(count, n)).keys()],
          count <= 256 ? 'either' : n >= count ? 'mustNot' : 'either',
        ];
      },
    ],
    [
      1,
      () => {
        const v = r.pick<unknown>([null, undefined, 'abc', 7, { length: 2 ** 31 }]);
        return [String(v), v, 'mustNot'];
      },
    ],
  ])();
  return {
    text: `rig.setEffectors(${text})`,
    run: () => {
      const before = Array.from(s.spec.effectors);
      const outcome = attempt(
        accept,
        () => changeEffectors(s, value as Numbers),
        () => undefined,
      );
      if (s.rig.isDisposed) return outcome;
      const now = Array.from(s.rig.effectors());
      const expected = outcome.kind === 'ok' ? Array.from(s.spec.effectors) : before;
      const same = now.length === expected.length && now.every((b, k) => b === expected[k]);
      return same
        ? outcome
        : worse(outcome, { kind: 'wrong', message: `effectors() is [${now}] afterwards, expected [${expected}]` });
    },
  };
};

const newSolver: Op = (r, s) => {
  const m = methodArg(r, IkSolver.methods(s.ik)),
    o = optionsArg(r, s);
  return {
    text: `new IkSolver(rig, ${m.text}, ${o.text})`,
    run: () =>
      attempt(
        both(m.accept, o.accept),
        () => new IkSolver(s.rig, m.value as string, o.value as SolverOptions),
        (solver) => {
          s.owned.push(solver);
          s.solver = solver;
          s.started = false;
          s.optionsOutOfRange = o.outOfRange === true;
          return undefined;
        },
      ),
  };
};

const setOptions: Op = (r, s) => {
  const o = optionsArg(r, s);
  return {
    text: `solver.setOptions(${o.text})`,
    run: () =>
      attempt(
        o.accept,
        () => s.solver.setOptions(o.value as SolverOptions),
        () => {
          s.optionsOutOfRange = o.outOfRange === true;
          return undefined;
        },
      ),
  };
};

/** The fields of SolverOptions (solver.ts): options() must give every one. */
const OPTION_FIELDS = 23;

const options: Op = (_, s) => ({
  text: 'solver.options()',
  run: () =>
    attempt(
      'either',
      () => s.solver.options(),
      (o) => {
        const entries = Object.entries(o);
        const bad = entries.find(([, v]) => typeof v !== 'boolean' && typeof v !== 'number');
        return entries.length < OPTION_FIELDS
          ? `options() has ${entries.length} fields`
          : bad
            ? `options().${bad[0]} is ${String(bad[1])}`
            : undefined;
      },
    ),
});

/** The time budget of the solve just finished (options() describes the current solve), undefined when it had none or the solver is gone. */
function solveBudget(s: ApiState): number | undefined {
  let budget: number;
  try {
    budget = s.solver.options().timeBudgetSeconds;
  } catch {
    return undefined;
  }
  return budget > 0 && Number.isFinite(budget) ? budget : undefined;
}

/** Records a finished solve against its time budget, unless the caller's code ran inside it. */
function recordBudget(s: ApiState, result: SolverResult, wallStart: number, callerCodeRan: boolean): void {
  const wallSeconds = (performance.now() - wallStart) / 1000;
  const budgetSeconds = solveBudget(s);
  if (budgetSeconds && !callerCodeRan)
    s.budgets.push({ budgetSeconds, elapsedSeconds: result.elapsedSeconds, wallSeconds });
}

const solve: Op = (r, s) => {
  const a = anglesArg(r, s),
    t = targetArg(r, s);
  const n = 3 * s.spec.parents.length;
  const [outText, out] = r.pick<[string, unknown]>([
    ['', undefined],
    ['', undefined],
    [', out', new Float64Array(n)],
    [', out = angles', a.value],
    [', out of the wrong length', new Float64Array(n + 1)],
    [', out = []', []],
    [', out = a Float32Array', new Float32Array(n)],
  ]);
  return {
    text: `solver.solve(${a.text}, ${t.text}${outText})`,
    run: () => {
      const accept = both(a.accept, t.accept, s.optionsOutOfRange ? 'mustNot' : 'must');
      let outcome: Outcome = OK;
      const wall = performance.now();
      const check = attempt(
        accept,
        () => s.solver.solve(a.value as Numbers, t.value as Numbers, out as Float64Array),
        (result) => {
          recordBudget(s, result, wall, a.sideEffect === true || t.sideEffect === true);
          s.started = true;
          const ka = known(a),
            kt = known(t);
          const given = ka && kt && accept === 'must' ? { start: ka, target: kt } : undefined;
          outcome = judgeSolve(result, s.spec, given);
          if (out instanceof Float64Array && out.length === n && result.angles !== out)
            return 'the result is not in `out`';
          return undefined;
        },
      );
      return worse(check, outcome);
    },
  };
};

/**
 * solve() with goals past sane (hostile_goals.ts), after setting their rest pull if they have one
 * (on top of the options of the current solve, which replace any out-of-range ones pending).
 */
const solveGoals: Op = (r, s) => {
  const angles = randomAngles(r, s.spec);
  const g = goalsArg(r, s);
  return {
    text: `solver.solve(angles, goals with ${g.text})`,
    run: () => {
      if (g.restWeight !== undefined) {
        const restWeight = g.restWeight;
        const set = attempt(
          'either',
          () => s.solver.setOptions({ ...s.solver.options(), restWeight }),
          () => undefined,
        );
        if (set.kind !== 'ok') return set;
        s.optionsOutOfRange = false;
      }
      let outcome: Outcome = OK;
      const wall = performance.now();
      const check = attempt(
        both(g.accept, s.optionsOutOfRange ? 'mustNot' : 'must'),
        () => s.solver.solve(angles, g.value),
        (result) => {
          recordBudget(s, result, wall, false);
          s.started = true;
          outcome = judgeSolve(result, s.spec);
          return undefined;
        },
      );
      return worse(check, outcome);
    },
  };
};

const startAndStep: Op = (r, s) => {
  const a = anglesArg(r, s),
    t = targetArg(r, s);
  const steps = r.pick([0, 1, 5, 50]);
  return {
    text: `solver.start(${a.text}, ${t.text}) then ${steps} step()s`,
    run: () =>
      attempt(
        both(a.accept, t.accept, s.optionsOutOfRange ? 'mustNot' : 'must'),
        () => {
          const reason = s.solver.start(a.value as Numbers, t.value as Numbers);
          s.started = true;
          let running = reason === 'running';
          for (let k = 0; k < steps && running; k++) running = s.solver.step();
          return reason;
        },
        (reason) =>
          ['running', 'converged_E', 'converged_grad', 'numerical_failure'].includes(reason)
            ? undefined
            : `start() returned "${reason}"`,
      ),
  };
};

const step: Op = (_, s) => ({
  text: 'solver.step()',
  run: () =>
    attempt(
      'either',
      () => s.solver.step(),
      (v) => (typeof v === 'boolean' ? undefined : `step() returned ${String(v)}`),
    ),
});

const result: Op = (_, s) => ({
  text: 'solver.result()',
  run: () =>
    attempt(
      'either',
      () => s.solver.result(),
      (res) => {
        if (!s.started) return undefined;
        return (
          numbersProblem('result().angles', res.angles, 3 * s.spec.parents.length) ??
          limitsProblem('result().angles', res.angles, s.spec)
        );
      },
    ),
});

const currentAngles: Op = (_, s) => ({
  text: 'solver.angles()',
  run: () =>
    attempt(
      'either',
      () => s.solver.angles(),
      (v) =>
        s.started
          ? (numbersProblem('angles()', v, 3 * s.spec.parents.length) ?? limitsProblem('angles()', v, s.spec))
          : undefined,
    ),
});

const errorHistory: Op = (_, s) => ({
  text: 'solver.errorHistory()',
  run: () =>
    attempt(
      'either',
      () => s.solver.errorHistory(),
      (v) => numbersProblem('errorHistory()', v, v.length),
    ),
});

const disposeRig: Op = (_, s) => ({
  text: 'rig.dispose() (its solver alive)',
  run: () =>
    attempt(
      'either',
      () => s.rig.dispose(),
      () => undefined,
    ),
});
const disposeSolver: Op = (_, s) => ({
  text: 'solver.dispose()',
  run: () =>
    attempt(
      'either',
      () => s.solver.dispose(),
      () => undefined,
    ),
});

const describe: Op = (r, s) => {
  const m = methodArg(r, IkSolver.methods(s.ik));
  return {
    text: `IkSolver.describe(${m.text})`,
    run: () =>
      attempt(
        m.accept,
        () => IkSolver.describe(s.ik, m.value as string),
        (d) => (typeof d === 'string' && d.length > 0 ? undefined : 'an empty description'),
      ),
  };
};

/** The calls with their weights. */
export const API_OPS: readonly (readonly [number, Op])[] = [
  [4, tips],
  [2, boneTips],
  [2, poses],
  [2, jacobian],
  [1, finiteDifferenceJacobian],
  [2, objective],
  [2, gradient],
  [3, project],
  [4, setEffectors],
  [4, newSolver],
  [3, setOptions],
  [1, options],
  [8, solve],
  [4, solveGoals],
  [3, startAndStep],
  [1, step],
  [1, result],
  [1, currentAngles],
  [1, errorHistory],
  [1, disposeRig],
  [1, disposeSolver],
  [1, describe],
];
