// Hand-written types for the Emscripten module built from wasm/bindings (3.1.6 cannot emit them).
// CMake copies this file beside the generated ik_core.mjs. The typed API is web/src/ik/.
// A failed call returns null ("", false, NaN, -1) and leaves its message for takeError(); the
// bindings expect typed arrays of the right length and plain option objects (web/src/ik/inputs.ts).

export interface RigSpecArrays {
  names?: string[];
  parents: Int32Array;
  rest: Float64Array;
  lengths: Float64Array;
  lower: Float64Array;
  upper: Float64Array;
  effectors: Int32Array;
  /** A floating root's bounds (x, y, z, rig units); both or neither. */
  rootLower?: Float64Array;
  rootUpper?: Float64Array;
}

export interface EmbindRig {
  readonly numBones: number;
  readonly numAngles: number;
  readonly numEffectors: number;
  effectors(): Int32Array;
  setEffectors(effectors: Int32Array): boolean;
  lower(): Float64Array;
  upper(): Float64Array;
  /** #angles | 16 numbers per bone; stale (length 0) after memory growth. */
  ioView(): Float64Array | null;
  /**
   * Poses the rig at the angles in ioView() and writes output `what` (its index in
   * Rig.forwardOutputs(): tips, boneTips, tipRotations as x, y, z, w per effector, poses) after
   * them; returns how many numbers it wrote, -1 on failure.
   */
  forwardIo(what: number): number;
  jacobian(angles: Float64Array): Float64Array | null;
  finiteDifferenceJacobian(angles: Float64Array, hDeg: number, clamp: boolean): Float64Array | null;
  objective(angles: Float64Array, target: Float64Array): number;
  gradient(angles: Float64Array, target: Float64Array): Float64Array | null;
  project(angles: Float64Array): Float64Array | null;
  restartStart(k: number, seed: number): Float64Array | null;
  delete(): void;
}

/**
 * Solver options by their camelCase names: the list is wasm/src/solvers/solver_options.def (read
 * by wasm/bindings/solver_options.h); web/src/ik/solver.ts's SolverOptions types and documents it,
 * and tests/ik/binding_tables.test.ts holds the two to the same names and defaults.
 */
export type EmbindSolverOptions = Record<string, number | boolean>;

/** wasm/bindings/solver_bindings.cpp: one method on one Rig (which must outlive it). */
export interface EmbindSolver {
  readonly method: string;
  readonly running: boolean;
  setOptions(options: EmbindSolverOptions): boolean;
  options(): EmbindSolverOptions;
  /** A buffer of `length` numbers for setGoalsIo() (stale, length 0, when the memory grows: ask again); null on failure. */
  goalsView(length: number): Float64Array | null;
  /**
   * Goals for the next start()/solveIo(), from goalsView()'s buffer: packedLength numbers, 7 per effector
   * [positionWeight, orientationWeight, qx, qy, qz, qw, yields] (the target gives positions), then polesLength,
   * 5 per bend hint [bone, x, y, z, weight], then stiffnessLength, one per bone or none.
   */
  setGoalsIo(packedLength: number, polesLength: number, stiffnessLength: number, lengthScale: number): boolean;
  clearGoals(): void;
  /** A buffer of #angles numbers for setPreferredIo() (stale, length 0, when the memory grows: ask again); null on failure. */
  preferredView(): Float64Array | null;
  /**
   * The next solve's preferred move from preferredView()'s buffer (degrees per angle, then a floating root's
   * translation in rig units): its first lm step adds it where the goals leave room. False (the message for
   * takeError()) for a wrong length or a value that is not finite.
   */
  setPreferredIo(): boolean;
  readonly hasGoals: boolean;
  start(angles: Float64Array, target: Float64Array): string;
  step(): boolean;
  /** Writes the solve so far into ioView() as solveIo() writes a solve (asked for the rig's current effectors); the stop reason's index, -1 on failure. */
  resultIo(): number;
  /** The current solve's message (invalid_input, numerical_failure); "" otherwise. */
  message(): string;
  /** Copies E's history (the start, then each iteration) into historyView(); returns its length, -1 on failure. */
  historyIo(): number;
  /** The history buffer; ask again when it is shorter than historyIo()'s count (it grew, or memory did). */
  historyView(): Float64Array;
  angles(): Float64Array;
  /** #angles | #residuals target | the result numbers Solver.ioStats() names (reached as 0/1); stale (length 0) after memory growth. */
  ioView(): Float64Array | null;
  /** Solves from the angles and target in ioView(); returns the stop reason's index in stopReasons(), -1 on failure. */
  solveIo(): number;
  delete(): void;
}

export interface EmbindSolverClass {
  create(rig: EmbindRig, method: string, options: EmbindSolverOptions): EmbindSolver | null;
  methods(): string[];
  defaultOptions(): EmbindSolverOptions;
  describe(method: string): string;
  label(method: string): string;
  stopReasons(): string[];
  /** The names of the result numbers solveIo() writes after the target, in order. */
  ioStats(): string[];
  /** Which of them are flags (written as 1 or 0). */
  ioFlags(): string[];
}

export interface IkCoreModule {
  Rig: {
    create(spec: RigSpecArrays): EmbindRig | null;
    /** The outputs forwardIo() writes, by index. */
    forwardOutputs(): string[];
  };
  /** The message of the last failed call, cleared by reading it ("" if none). */
  takeError(): string;
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
