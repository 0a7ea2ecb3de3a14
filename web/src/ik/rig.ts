// A rig living in WebAssembly: forward kinematics, tips, Jacobians and the objective.
// Angles are 3 numbers per bone in DEGREES (XZX); tips are 3 numbers per end effector.
// The object owns WebAssembly memory: call dispose() when done.
import type { EmbindRig, IkCoreModule } from './generated/ik_core.mjs';
import type { RigSpec } from './rig_spec.js';

export type Numbers = ArrayLike<number>;

export class IkRig {
  /** The embind object; other wrappers of the API (solvers) take it. */
  readonly handle: EmbindRig;
  readonly numBones: number;
  readonly numAngles: number;
  /** Lower and upper limits, 3 per bone, degrees. */
  readonly lower: Float64Array;
  readonly upper: Float64Array;
  private disposed = false;

  /** Builds the rig in WebAssembly. Throws an Error naming the bone and field of a bad spec. */
  constructor(
    readonly module: IkCoreModule,
    readonly spec: RigSpec,
  ) {
    this.handle = new module.Rig(spec);
    this.numBones = this.handle.numBones;
    this.numAngles = this.handle.numAngles;
    this.lower = this.handle.lower();
    this.upper = this.handle.upper();
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
   * index that is no bone in the core. On error the old list stays.
   */
  setEffectors(bones: Numbers): void {
    const live = this.live();
    for (let k = 0; k < bones.length; k++) {
      const b = bones[k];
      if (!Number.isInteger(b) || Math.abs(b) > 0x7fffffff)
        throw new Error(`effectors[${k}] is ${String(b)}, not a bone index (an integer in 0..${this.numBones - 1})`);
    }
    live.setEffectors(Int32Array.from(bones));
  }

  /** End-effector tips (3 per effector) at `angles`. */
  tips(angles: Numbers): Float64Array {
    return this.live().tips(angles);
  }

  /** Every bone's tip (3 per bone) at `angles`. */
  boneTips(angles: Numbers): Float64Array {
    return this.live().boneTips(angles);
  }

  /** Every bone's pose transform T_i (16 per bone, row-major, rest space -> posed world). */
  poses(angles: Numbers): Float64Array {
    return this.live().poses(angles);
  }

  /** Analytic Jacobian d tips / d angles, row-major (3n rows x 3m columns), rig units per degree. */
  jacobian(angles: Numbers): Float64Array {
    return this.live().jacobian(angles);
  }

  /** Central-difference Jacobian with step hDeg degrees, clamped to the limits as the original did. */
  finiteDifferenceJacobian(angles: Numbers, hDeg = 1e-7, clampToLimits = true): Float64Array {
    return this.live().finiteDifferenceJacobian(angles, hDeg, clampToLimits);
  }

  /** E = 1/2 |tips(angles) - target|^2. */
  objective(angles: Numbers, target: Numbers): number {
    return this.live().objective(angles, target);
  }

  /** grad E = J^T (tips - target), 3 per bone, per degree. */
  gradient(angles: Numbers, target: Numbers): Float64Array {
    return this.live().gradient(angles, target);
  }

  /** `angles` (degrees) clamped into the limits (a new array). Throws for a non-finite angle. */
  project(angles: Numbers): Float64Array {
    for (let k = 0; k < angles.length; k++)
      if (!Number.isFinite(angles[k])) throw new Error(`angles[${k}] is ${String(angles[k])}, not a finite number of degrees`);
    return this.live().project(angles);
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

  private live(): EmbindRig {
    if (this.disposed) throw new Error('this rig was disposed');
    return this.handle;
  }
}
