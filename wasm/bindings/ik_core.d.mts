// Hand-written types for the Emscripten module built from wasm/bindings (3.1.6 cannot emit them).
// CMake copies this file beside the generated ik_core.mjs. The typed API is web/src/ik/.

export interface RigSpecArrays {
  names?: string[];
  parents: Int32Array;
  rest: Float64Array;
  lengths: Float64Array;
  lower: Float64Array;
  upper: Float64Array;
  effectors: Int32Array;
}

type Numbers = ArrayLike<number>;

export interface EmbindRig {
  readonly numBones: number;
  readonly numAngles: number;
  readonly numEffectors: number;
  effectors(): Int32Array;
  setEffectors(effectors: Int32Array): void;
  lower(): Float64Array;
  upper(): Float64Array;
  tips(angles: Numbers): Float64Array;
  boneTips(angles: Numbers): Float64Array;
  poses(angles: Numbers): Float64Array;
  jacobian(angles: Numbers): Float64Array;
  finiteDifferenceJacobian(angles: Numbers, hDeg: number, clamp: boolean): Float64Array;
  objective(angles: Numbers, target: Numbers): number;
  gradient(angles: Numbers, target: Numbers): Float64Array;
  project(angles: Numbers): Float64Array;
  delete(): void;
}

export interface EmbindSolverResult {
  angles: Float64Array;
  E: number;
  gradNorm: number;
  iterations: number;
  functionEvaluations: number;
  jacobianEvaluations: number;
  stopReason: string;
  elapsedSeconds: number;
}

export interface IkCoreModule {
  Rig: new (spec: RigSpecArrays) => EmbindRig;
  // Solver bindings (wasm/bindings/solver_bindings.cpp) extend this interface.
  [key: string]: unknown;
  HEAPU8: Uint8Array;
}

export interface IkCoreModuleOptions {
  wasmBinary?: ArrayBuffer | Uint8Array;
  instantiateWasm?: (
    imports: WebAssembly.Imports,
    done: (instance: WebAssembly.Instance, module?: WebAssembly.Module) => void,
  ) => WebAssembly.Exports | Record<string, never>;
  locateFile?: (path: string, prefix: string) => string;
}

export default function createIkModule(options?: IkCoreModuleOptions): Promise<IkCoreModule>;
