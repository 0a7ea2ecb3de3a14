// TEMPORARY stand-in until web/src/ik/solver.ts (the WebAssembly solvers) lands: a damped
// least-squares iteration in TypeScript over the WebAssembly Jacobian, whatever the method.
// solver_adapter.ts replaces it; nothing else imports this file.
import type { IkRig } from '../ik/rig.js';
import type { Method, MethodSolver, SolveOutcome, SolveSettings } from './solver_port.js';

interface Run {
  angles: Float64Array;
  target: Float64Array;
  settings: SolveSettings;
  lambda: number;
  history: number[];
  iterations: number;
  stopReason: string;
  stepLength: number | null;
  t0: number;
}

export function createInterimSolver(rig: IkRig, method: Method): MethodSolver {
  let run: Run | null = null;
  const residual = (a: Float64Array, target: Float64Array): Float64Array => {
    const tips = rig.tips(a);
    for (let k = 0; k < tips.length; k++) tips[k] -= target[k];
    return tips;
  };
  const energy = (r: Float64Array): number => {
    let s = 0;
    for (let k = 0; k < r.length; k++) s += r[k] * r[k];
    return s / 2;
  };
  const outcome = (r: Run): SolveOutcome => {
    const res = residual(r.angles, r.target);
    const g = rig.gradient(r.angles, r.target);
    let gn = 0;
    for (let k = 0; k < g.length; k++) gn += g[k] * g[k];
    return {
      angles: r.angles.slice(),
      E: energy(res),
      gradNorm: Math.sqrt(gn),
      iterations: r.iterations,
      stopReason: r.stopReason,
      elapsedSeconds: (performance.now() - r.t0) / 1000,
      stepLength: r.stepLength,
      history: Float64Array.from(r.history),
    };
  };
  const begin = (start: Float64Array, target: Float64Array, settings: SolveSettings): Run => {
    const angles = rig.project(start);
    return {
      angles, target: target.slice(), settings, lambda: 1e-2, iterations: 0, stopReason: '', stepLength: null,
      history: [energy(residual(angles, target))], t0: performance.now(),
    };
  };
  const iterate = (r: Run): void => {
    const m = r.target.length, n = rig.numAngles;
    const res = residual(r.angles, r.target);
    const E0 = energy(res);
    if (E0 < r.settings.errorTolerance) { r.stopReason = 'converged_E'; return; }
    const J = rig.jacobian(r.angles);
    const g = new Float64Array(n);
    for (let i = 0; i < m; i++) for (let j = 0; j < n; j++) g[j] += J[i * n + j] * res[i];
    let gn = 0;
    for (let j = 0; j < n; j++) gn += g[j] * g[j];
    if (Math.sqrt(gn) < r.settings.gradientTolerance) { r.stopReason = 'converged_grad'; return; }
    for (let attempt = 0; attempt < 20; attempt++) {
      // (J J^T + lambda I) y = res, step = -J^T y.
      const A = new Float64Array(m * m);
      for (let i = 0; i < m; i++)
        for (let k = 0; k < m; k++) {
          let s = 0;
          for (let j = 0; j < n; j++) s += J[i * n + j] * J[k * n + j];
          A[i * m + k] = s + (i === k ? r.lambda : 0);
        }
      const y = solveDense(A, res.slice(), m);
      const next = new Float64Array(n);
      for (let j = 0; j < n; j++) {
        let s = 0;
        for (let i = 0; i < m; i++) s += J[i * n + j] * y[i];
        next[j] = r.angles[j] - s;
      }
      const projected = rig.project(next);
      const E1 = energy(residual(projected, r.target));
      if (E1 < E0) {
        let len = 0;
        for (let j = 0; j < n; j++) len += (projected[j] - r.angles[j]) ** 2;
        r.stepLength = Math.sqrt(len);
        r.angles = projected;
        r.lambda = Math.max(r.lambda / 3, 1e-9);
        r.iterations++;
        r.history.push(E1);
        return;
      }
      r.lambda *= 4;
    }
    r.stopReason = 'zero_step';
  };
  const finish = (r: Run): void => {
    if (r.stopReason) return;
    const E = r.history[r.history.length - 1];
    if (E < r.settings.errorTolerance) r.stopReason = 'converged_E';
    else if (r.iterations >= r.settings.maxIterations) r.stopReason = 'max_iterations';
    else if (performance.now() - r.t0 > r.settings.timeBudgetMs) r.stopReason = 'timeout';
  };
  return {
    method,
    solve(start, target, settings) {
      const r = begin(start, target, settings);
      for (;;) {
        finish(r);
        if (r.stopReason) break;
        iterate(r);
      }
      return outcome(r);
    },
    start(start, target, settings) {
      run = begin(start, target, settings);
      return outcome(run);
    },
    step() {
      if (!run) throw new Error('step() before start()');
      finish(run);
      if (!run.stopReason) {
        iterate(run);
        finish(run);
      }
      return outcome(run);
    },
    dispose() {
      run = null;
    },
  };
}

function solveDense(A: Float64Array, b: Float64Array, m: number): Float64Array {
  for (let c = 0; c < m; c++) {
    let p = c;
    for (let r = c + 1; r < m; r++) if (Math.abs(A[r * m + c]) > Math.abs(A[p * m + c])) p = r;
    if (p !== c) {
      for (let k = 0; k < m; k++) [A[c * m + k], A[p * m + k]] = [A[p * m + k], A[c * m + k]];
      [b[c], b[p]] = [b[p], b[c]];
    }
    const d = A[c * m + c] || 1e-300;
    for (let r = c + 1; r < m; r++) {
      const f = A[r * m + c] / d;
      for (let k = c; k < m; k++) A[r * m + k] -= f * A[c * m + k];
      b[r] -= f * b[c];
    }
  }
  for (let c = m - 1; c >= 0; c--) {
    let s = b[c];
    for (let k = c + 1; k < m; k++) s -= A[c * m + k] * b[k];
    b[c] = s / (A[c * m + c] || 1e-300);
  }
  return b;
}
