// Stopping tolerances of a rig, shared by the page, the widget and the benchmark. The native tools
// and tests have the report tolerances and the rig size in C++ (wasm/native/protocol.h);
// tests/bench/protocol_agreement.test.ts checks both agree.
//
// Report tolerances (the benchmark's random and incremental experiments): the report's values
// for its five A7 rigs (beast: gradient 0.01, E 0.002; the others: 0.0001, 0.0002); for any other
// rig both scale with the square of the rig's size (the diagonal of the bounding box of every
// bone tip at the rest pose) relative to 1 rig unit, since E is a squared distance and
// grad E = J^T r scales the same way.
//
// Drag tolerances (the page, the widget, the benchmark's drag and reach experiments): a
// distance. Every end effector must lie within DRAG_TIP_SHARE of the rig size of its target,
// about one pixel with the rig framed in the view. The gradient test, which stops a solve at a
// closest point when the target is out of reach, is set far below the gradient an effector that
// far off its target makes: |grad E| ~ |r| * lever * pi/180 per degree, with the lever (the
// distance from a joint to the tip) up to the rig size.

export interface Tolerances {
  /** |grad E| threshold, rig units^2 per degree. */
  gradientTolerance: number;
  /** E threshold (and the success test), rig units^2. */
  errorTolerance: number;
}

/** The report's rigs and their tolerances (PROTOCOL.md). */
export const reportTolerances: Readonly<Record<string, Tolerances>> = {
  'ikea-lamp': { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
  'robot-arm': { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
  knight: { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
  'chimpanzee-hand': { gradientTolerance: 1e-4, errorTolerance: 2e-4 },
  beast: { gradientTolerance: 0.01, errorTolerance: 0.002 },
};

/** Reference size (rig units) at which an unknown rig gets the report's usual tolerances. */
export const REFERENCE_SIZE = 1;
const REFERENCE_TOL: Tolerances = { gradientTolerance: 1e-4, errorTolerance: 2e-4 };

/** Share of the rig size within which an end effector is on its target while dragging. */
export const DRAG_TIP_SHARE = 1e-3;
/** The drag gradient tolerance over the gradient of an effector one tip tolerance off with the whole rig as lever. */
export const DRAG_GRADIENT_SHARE = 1e-3;

/**
 * Share of the rig size that a joint may move in one frame while dragging beyond how far the
 * target moved (the solver option maxJointMove): with a target moved less than 1% this stays below
 * the 5% that makes a step a jump (bench-node/jumps.ts), so a change of branch shows as a quick
 * move over a few frames, never a one-frame snap.
 */
export const DRAG_JOINT_MOVE_SHARE = 0.04;

export interface DragTolerances {
  /** Largest tip-to-target distance that counts as on target, rig units. */
  tipTolerance: number;
  /** |grad E| threshold, rig units^2 per degree. */
  gradientTolerance: number;
  /** The farthest a joint moves in one frame (solver option maxJointMove), rig units. */
  maxJointMove: number;
}

/** The drag tolerances of a rig of size `size` (rig units, see rigSize). */
export function dragTolerances(size: number): DragTolerances {
  const tipTolerance = DRAG_TIP_SHARE * size;
  return {
    tipTolerance,
    gradientTolerance: DRAG_GRADIENT_SHARE * tipTolerance * size * (Math.PI / 180),
    maxJointMove: DRAG_JOINT_MOVE_SHARE * size,
  };
}

/** Rig size: the diagonal of the bounding box of the bone tips (3 numbers per bone), rig units. */
export function rigSize(boneTipsAtRest: ArrayLike<number>): number {
  if (boneTipsAtRest.length === 0) return REFERENCE_SIZE;
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < boneTipsAtRest.length; i++) {
    const axis = i % 3;
    lo[axis] = Math.min(lo[axis], boneTipsAtRest[i]);
    hi[axis] = Math.max(hi[axis], boneTipsAtRest[i]);
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

/** Height of a rig at rest: the vertical extent of its bone tips `boneTips` (3 per bone, rig units); rigSize when they are flat. */
export function restHeight(boneTips: ArrayLike<number>): number {
  let lo = Infinity,
    hi = -Infinity;
  for (let i = 1; i < boneTips.length; i += 3) {
    lo = Math.min(lo, boneTips[i]);
    hi = Math.max(hi, boneTips[i]);
  }
  return hi > lo ? hi - lo : rigSize(boneTips);
}

/** Default tolerances of the rig `name` (file base name); `a7` says it came from an A7 .json file. */
export function defaultTolerances(name: string, a7: boolean, size: number): Tolerances {
  const report = a7 && Object.hasOwn(reportTolerances, name) ? reportTolerances[name] : undefined;
  if (report) return { ...report };
  const scale = (size / REFERENCE_SIZE) ** 2;
  return {
    gradientTolerance: REFERENCE_TOL.gradientTolerance * scale,
    errorTolerance: REFERENCE_TOL.errorTolerance * scale,
  };
}
