// Which Runner solves a method: the peers' adapters, or our solvers through the WebAssembly API.
import type { IkCoreModule } from '../web/src/ik/module.js';
import type { RigSpec } from '../web/src/ik/rig_spec.js';
import { ClosedChainIkRunner } from './peers/closed_chain_ik.js';
import { ThreeCcdRunner } from './peers/three_ccd.js';
import type { Runner, RunSettings } from './runner.js';
import { WasmSolverRunner } from './solve_wasm.js';

export function makeRunner(ik: IkCoreModule, spec: RigSpec, settings: RunSettings): Runner {
  switch (settings.method) {
    case 'three-ccd':
      return new ThreeCcdRunner(spec, settings);
    case 'closed-chain-ik':
      return new ClosedChainIkRunner(spec, settings);
    default:
      return new WasmSolverRunner(ik, spec, settings);
  }
}
