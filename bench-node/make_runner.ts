// Which Runner solves a method: the peers' adapters (with the solvers' restart policy applied by
// the harness, peers/restarting.ts), or our solvers through the WebAssembly API.
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import { ClosedChainIkRunner } from './peers/closed_chain_ik.js';
import { RestartingRunner } from './peers/restarting.js';
import { ThreeCcdRunner } from './peers/three_ccd.js';
import type { Runner, RunSettings } from './runner.js';
import { WasmSolverRunner } from './solve_wasm.js';

/** The restarts a run gives every method: the setting, else the solvers' default; none in paper mode. */
export function effectiveRestarts(ik: IkCoreModule, settings: RunSettings): number {
  if (settings.paper) return 0;
  return settings.restarts ?? Number(ik.Solver.defaultOptions().restarts);
}

export function makeRunner(ik: IkCoreModule, spec: RigSpec, settings: RunSettings): Runner {
  switch (settings.method) {
    case 'three-ccd':
      return withRestarts(ik, spec, settings, new ThreeCcdRunner(spec, settings));
    case 'closed-chain-ik':
      return withRestarts(ik, spec, settings, closedChainIk(ik, spec, settings));
    default:
      return new WasmSolverRunner(ik, spec, settings);
  }
}

/** closed-chain-ik; with pose goals given our forward kinematics to judge the orientations. */
function closedChainIk(ik: IkCoreModule, spec: RigSpec, settings: RunSettings): Runner {
  if (settings.goals !== 'pose') return new ClosedChainIkRunner(spec, settings);
  const rig = new IkRig(ik, spec);
  const runner = new ClosedChainIkRunner(spec, settings, (a) => rig.tipRotations(a));
  return { solve: (input) => runner.solve(input), dispose: () => (runner.dispose(), rig.dispose()) };
}

function withRestarts(ik: IkCoreModule, spec: RigSpec, settings: RunSettings, peer: Runner): Runner {
  const restarts = effectiveRestarts(ik, settings);
  if (restarts === 0) return peer;
  const rig = new IkRig(ik, spec);
  return new RestartingRunner(
    peer,
    (k) => rig.restartStart(k),
    settings,
    restarts,
    () => rig.dispose(),
  );
}
