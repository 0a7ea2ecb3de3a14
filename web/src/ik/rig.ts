// A rig living in WebAssembly: forward kinematics, tips, Jacobians and the objective.
// Angles are 3 numbers per bone in DEGREES (XZX); tips are 3 numbers per end effector.
// The object owns WebAssembly memory: call dispose() when done.
//
// Every method checks and copies its inputs first (inputs.ts) and throws an Error naming the
// problem; the core reports its own refusals through takeError() (see wasm/bindings/js_arrays.h).
import type { EmbindRig, IkCoreModule, RigSpecArrays } from './generated/ik_core.mjs';
import { SIZE_LIMITS } from './generated/size_limits.js';
import { checkedInteger, checkedNumbers, coreError, toFloat64, toInt32 } from './inputs.js';
import type { RigSpec } from './rig_arrays.js';

export type Numbers = ArrayLike<number>;

/** What the rig's forwardIo() writes (Rig.forwardOutputs()). */
type ForwardOutput = 'tips' | 'boneTips' | 'tipRotations' | 'poses';
const outputsCache = new WeakMap<IkCoreModule, Record<ForwardOutput, number>>();

/** forwardIo()'s index of each output, read once per module. */
function forwardOutputs(module: IkCoreModule): Record<ForwardOutput, number> {
  let index = outputsCache.get(module);
  if (!index) {
    index = Object.fromEntries(module.Rig.forwardOutputs().map((name, k) => [name, k])) as Record<
      ForwardOutput,
      number
    >;
    outputsCache.set(module, index);
  }
  return index;
}

/** The spec as the core takes it: typed arrays of the lengths its parents imply, string names. */
function specArrays(spec: RigSpec): RigSpecArrays {
  if (typeof spec !== 'object' || spec === null) throw new Error('rig spec must be an object');
  const parents = toInt32(spec.parents, 'parents');
  const n = parents.length;
  const names = spec.names === undefined ? [] : spec.names;
  if (!Array.isArray(names)) throw new Error('names must be an array of strings');
  return {
    names: names.slice(0, n).map((name, i) => {
      if (typeof name !== 'string') throw new Error(`names[${i}] is not a string`);
      return name;
    }),
    parents,
    rest: toFloat64(spec.rest, 'rest (16 row-major numbers per bone)', 16 * n, false),
    lengths: toFloat64(spec.lengths, 'lengths', n, false),
    lower: toFloat64(spec.lower, 'lower (3 limits per bone, degrees)', 3 * n, false),
    upper: toFloat64(spec.upper, 'upper (3 limits per bone, degrees)', 3 * n, false),
    effectors: toInt32(spec.effectors, 'effectors'),
    ...(spec.floatingRoot === undefined
      ? {}
      : {
          rootLower: toFloat64(spec.floatingRoot?.lower, 'floatingRoot.lower (x, y, z, rig units)', 3),
          rootUpper: toFloat64(spec.floatingRoot?.upper, 'floatingRoot.upper (x, y, z, rig units)', 3),
        }),
  };
}

export class IkRig {
  /** The embind object; other wrappers of the API (solvers) take it. */
  readonly handle: EmbindRig;
  readonly numBones: number;
  readonly numAngles: number;
  /** Lower and upper limits, 3 per bone, degrees; then a floating root's 3 bounds, rig units. */
  readonly lower: Float64Array;
  readonly upper: Float64Array;
  private disposed = false;
  /** forward()'s buffer in WebAssembly memory: angles | an output. */
  private io: Float64Array<ArrayBufferLike> = new Float64Array(0);
  /** Counts setEffectors() calls that changed the list: solvers hand their goals again after one. */
  effectorsVersion = 0;

  /** Builds the rig in WebAssembly. Throws an Error naming the bone and field of a bad spec. */
  constructor(
    readonly module: IkCoreModule,
    readonly spec: RigSpec,
  ) {
    const handle = module.Rig.create(specArrays(spec));
    if (!handle) throw coreError(module, 'building the rig');
    this.handle = handle;
    this.numBones = handle.numBones;
    this.numAngles = handle.numAngles;
    this.lower = handle.lower();
    this.upper = handle.upper();
  }

  get numEffectors(): number {
    return this.live().numEffectors;
  }

  /** Bone indices of the end effectors. */
  effectors(): Int32Array {
    return this.live().effectors();
  }

  /**
   * Replaces the end effectors (bone indices). Throws an Error naming the first bad entry: a
   * fraction, NaN or a number past 32 bits here (never truncated or wrapped to some bone), an
   * index that is no bone in the core, a bone listed twice, or more than the core takes. On
   * error the old list stays.
   */
  setEffectors(bones: Numbers): void {
    this.live();
    const list = toInt32(bones, 'effectors');
    if (!this.live().setEffectors(list)) throw coreError(this.module, 'setEffectors');
    this.effectorsVersion++;
  }

  /**
   * End-effector tips (3 per effector) at `angles`. `out` (optional, a Float64Array of 3 per
   * effector) receives them and is returned: no new array per call. So for the others below.
   */
  tips(angles: Numbers, out?: Float64Array): Float64Array {
    return this.forward('tips', angles, 3 * this.numEffectors, out);
  }

  /** Every bone's tip (3 per bone) at `angles`. */
  boneTips(angles: Numbers, out?: Float64Array): Float64Array {
    return this.forward('boneTips', angles, 3 * this.numBones, out);
  }

  /**
   * Each end effector's bone-frame rotation at `angles` as a unit quaternion [x, y, z, w], 4 per
   * effector in effector order: what an orientation goal (goals.ts) compares with.
   */
  tipRotations(angles: Numbers, out?: Float64Array): Float64Array {
    return this.forward('tipRotations', angles, 4 * this.numEffectors, out);
  }

  /** Every bone's pose transform T_i (16 per bone, row-major, rest space -> posed world). */
  poses(angles: Numbers, out?: Float64Array): Float64Array {
    return this.forward('poses', angles, 16 * this.numBones, out);
  }

  /** Analytic Jacobian d tips / d angles, row-major (3n rows x 3m columns), rig units per degree. */
  jacobian(angles: Numbers): Float64Array {
    this.live();
    const a = this.angles(angles);
    return this.checked(this.live().jacobian(a), 'jacobian');
  }

  /** Central-difference Jacobian with step hDeg degrees, clamped to the limits as the original did. */
  finiteDifferenceJacobian(angles: Numbers, hDeg = 1e-7, clampToLimits = true): Float64Array {
    this.live();
    const a = this.angles(angles);
    if (typeof hDeg !== 'number' || !(hDeg > 0) || !Number.isFinite(hDeg))
      throw new Error(`finite difference step is ${String(hDeg)}, not a number of degrees > 0`);
    return this.checked(
      this.live().finiteDifferenceJacobian(a, hDeg, clampToLimits === true),
      'finiteDifferenceJacobian',
    );
  }

  /** E = 1/2 |tips(angles) - target|^2. */
  objective(angles: Numbers, target: Numbers): number {
    this.live();
    const a = this.angles(angles),
      t = this.target(target);
    const E = this.live().objective(a, t);
    if (Number.isNaN(E)) throw coreError(this.module, 'objective');
    return E;
  }

  /** grad E = J^T (tips - target), 3 per bone, per degree. */
  gradient(angles: Numbers, target: Numbers): Float64Array {
    this.live();
    const a = this.angles(angles),
      t = this.target(target);
    return this.checked(this.live().gradient(a, t), 'gradient');
  }

  /** `angles` (degrees) clamped into the limits (a new array). Throws for a non-finite angle. */
  project(angles: Numbers): Float64Array {
    this.live();
    const a = this.angles(angles);
    return this.checked(this.live().project(a), 'project');
  }

  /**
   * The start of the solvers' k-th restart (k an integer in 1..2^31 - 1) for the option `seed` (an
   * integer in [0, 2^32), default 1, the solvers' default): degrees, inside the limits. The same point a solver restarts from,
   * for harnesses that restart other solvers alike. A new array.
   */
  restartStart(k: number, seed = 1): Float64Array {
    this.live();
    checkedInteger(k, 'restartStart: the restart index k', 1, SIZE_LIMITS.kMaxRestartIndex);
    checkedInteger(seed, 'restartStart: the seed', 0, 2 ** 32 - 1);
    return this.checked(this.live().restartStart(k, seed), 'restartStart');
  }

  /** True after dispose(). */
  get isDisposed(): boolean {
    return this.disposed;
  }

  /** Frees the WebAssembly object. Safe to call twice. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.handle.delete();
  }

  /**
   * Output `what` (`count` numbers) of the rig posed at `angles` (3 finite numbers per bone,
   * degrees), written into `out` when given, else into a new array. The numbers cross in the
   * rig's shared buffer (ioView / forwardIo): no JavaScript value crosses and, with `out`, nothing
   * is allocated.
   */
  private forward(what: ForwardOutput, angles: Numbers, count: number, out?: Float64Array): Float64Array {
    this.live();
    if (out !== undefined && !(out instanceof Float64Array && out.length === count))
      throw new Error(`${what}: out must be a Float64Array of ${count} numbers`);
    const n = this.numAngles;
    const a = checkedNumbers(angles, 'angles', n); // a getter or Proxy read here may dispose the rig: asked again below
    this.buffer().set(a);
    const written = this.live().forwardIo(forwardOutputs(this.module)[what]);
    if (written < 0) throw coreError(this.module, what);
    if (written !== count) throw new Error(`${what}: the end effectors changed while the angles were being read`);
    const io = this.buffer(); // asked anew if the memory grew
    const result = out ?? new Float64Array(count);
    for (let i = 0; i < count; i++) result[i] = io[n + i];
    return result;
  }

  /** The rig's shared buffer (#angles | 16 per bone), asked anew when the memory grew. */
  private buffer(): Float64Array<ArrayBufferLike> {
    if (this.io.length > 0) return this.io;
    const view = this.live().ioView();
    if (!view) throw coreError(this.module, 'the rig buffer');
    return (this.io = view);
  }

  /** `angles` checked (3 numbers per bone, degrees; the core refuses a non-finite one) and copied. */
  private angles(angles: Numbers): Float64Array {
    return toFloat64(angles, 'angles', this.numAngles, false);
  }

  /** `target` checked (3 numbers per current end effector; the core refuses a non-finite one) and copied. */
  private target(target: Numbers): Float64Array {
    return toFloat64(target, 'target', 3 * this.live().numEffectors, false);
  }

  /** A core result, or the core's error thrown. */
  private checked(result: Float64Array | null, what: string): Float64Array {
    if (result === null) throw coreError(this.module, what);
    return result;
  }

  private live(): EmbindRig {
    if (this.disposed) throw new Error('this rig was disposed');
    return this.handle;
  }
}
