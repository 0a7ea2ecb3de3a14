// The JavaScript API over the WebAssembly core. It knows nothing of three.js.
export { loadIk } from './module.js';
export type { IkCoreModule, IkCoreModuleOptions } from './module.js';
export { IkRig } from './rig.js';
export type { Numbers } from './rig.js';
export type { RigSpec } from './rig_arrays.js';
export { boneCount, restMatrix } from './rig_arrays.js';
export { IkSolver } from './solver.js';
export { orientationErrorsDeg } from './goals.js';
export type { EffectorGoal, Goals, PoleGoal } from './goals.js';
export type { SolverMethod, SolverOptions, SolverResult, StopReason } from './solver.js';
