// Our solvers through the WebAssembly API (web/src/ik/solver.ts).
import type { IkCoreModule } from '../web/src/ik/module.js';
import type { RigSpec } from '../web/src/ik/rig_spec.js';
import type { SolveResult } from './metrics.js';
import type { Runner, RunSettings, SolveInput } from './runner.js';

export class WasmSolverRunner implements Runner {
  constructor(ik: IkCoreModule, spec: RigSpec, settings: RunSettings) {
    void ik;
    void spec;
    void settings;
    throw new Error('the WebAssembly solver API (web/src/ik/solver.ts) is not available yet');
  }

  solve(input: SolveInput): SolveResult {
    void input;
    throw new Error('unreachable');
  }

  dispose(): void {}
}
