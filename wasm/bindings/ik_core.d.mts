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
  initialE: number;
  gradNorm: number;
  tipDistance: number;
  reached: boolean;
  iterations: number;
  functionEvaluations: number;
  jacobianEvaluations: number;
  restarts: number;
  escapes: number;
  chainRestarts: number;
  stopReason: string;
  message: string;
  elapsedSeconds: number;
}

/** Solver options in camelCase (wasm/bindings/solver_options.h); every field optional. */
export interface EmbindSolverOptions {
  gradientTolerance?: number;
  errorTolerance?: number;
  maxIterations?: number;
  timeBudgetSeconds?: number;
  tipTolerance?: number;
  historyCapacity?: number;
  paperMode?: boolean;
  fdStepDeg?: number;
  gdInitialStep?: number;
  backtrackFactor?: number;
  armijoC1?: number;
  maxBacktracks?: number;
  gnSingularCutoff?: number;
  gnMaxStepDeg?: number;
  newtonMaxStepDeg?: number;
  lmInitialMu?: number;
  lmDampingFloor?: number;
  lmMaxRejections?: number;
  restarts?: number;
  stallIterations?: number;
  seed?: number;
  escapeSaddles?: boolean;
  chainRestarts?: number;
}

/** wasm/bindings/solver_bindings.cpp: one method on one Rig (which must outlive it). */
export interface EmbindSolver {
  readonly method: string;
  readonly running: boolean;
  setOptions(options: EmbindSolverOptions): void;
  options(): Required<EmbindSolverOptions>;
  start(angles: Numbers, target: Numbers): string;
  step(): boolean;
  solve(angles: Numbers, target: Numbers): EmbindSolverResult;
  result(): EmbindSolverResult;
  errorHistory(): Float64Array;
  angles(): Float64Array;
  /** n angles | m target | 12 result numbers (E, initialE, gradNorm, iterations, functionEvaluations, jacobianEvaluations, restarts, elapsedSeconds, tipDistance, reached (0/1), escapes, chainRestarts); stale (length 0) after memory growth. */
  ioView(n: number, m: number): Float64Array;
  /** Solves from the angles and target in ioView(); returns the stop reason's index in stopReasons(). */
  solveIo(): number;
  delete(): void;
}

export interface EmbindSolverClass {
  new (rig: EmbindRig, method: string, options: EmbindSolverOptions): EmbindSolver;
  methods(): string[];
  describe(method: string): string;
  stopReasons(): string[];
}

export interface IkCoreModule {
  Rig: new (spec: RigSpecArrays) => EmbindRig;
  Solver: EmbindSolverClass;
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
