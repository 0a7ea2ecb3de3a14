// The page's solver port over the WebAssembly solvers (web/src/ik/solver.ts). Options are sent
// to WebAssembly only when they change, so a per-frame solve is one call in and one result out,
// plus the E history for the plot.
import type { IkRig } from '../ik/rig.js';
import { IkSolver, type SolverOptions, type SolverResult } from '../ik/solver.js';
import type { Method, MethodSolver, SolveOutcome, SolveSettings } from './solver_port.js';

function toOptions(s: SolveSettings): SolverOptions {
  return {
    gradientTolerance: s.gradientTolerance,
    tipTolerance: s.tipTolerance,
    maxIterations: s.maxIterations,
    timeBudgetSeconds: s.timeBudgetMs / 1000,
    restarts: s.restarts,
    paperMode: s.paperMode,
  };
}

export function createWasmSolver(rig: IkRig, method: Method): MethodSolver {
  const solver = new IkSolver(rig, method);
  let sent: SolveSettings | null = null;
  const configure = (s: SolveSettings): void => {
    if (
      sent && sent.gradientTolerance === s.gradientTolerance && sent.tipTolerance === s.tipTolerance &&
      sent.maxIterations === s.maxIterations && sent.timeBudgetMs === s.timeBudgetMs &&
      sent.restarts === s.restarts && sent.paperMode === s.paperMode
    )
      return;
    solver.setOptions(toOptions(s));
    sent = { ...s };
  };
  const outcome = (r: SolverResult): SolveOutcome => ({
    angles: r.angles,
    E: r.E,
    gradNorm: r.gradNorm,
    tipDistance: r.tipDistance,
    reached: r.reached,
    iterations: r.iterations,
    stopReason: r.stopReason,
    elapsedSeconds: r.elapsedSeconds,
    stepLength: null,
    history: solver.errorHistory(),
  });
  return {
    method,
    solve(start, target, settings) {
      configure(settings);
      return outcome(solver.solve(start, target));
    },
    start(start, target, settings) {
      configure(settings);
      solver.start(start, target);
      return outcome(solver.result());
    },
    step() {
      if (solver.running) solver.step();
      return outcome(solver.result());
    },
    dispose() {
      solver.dispose();
    },
  };
}
