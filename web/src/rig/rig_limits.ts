// The largest rig file the loaders read, the largest rig they hand to the core, and the largest
// coordinate they accept, so that a file past them gets an error naming the file before it is
// read whole or reaches WebAssembly. The counts are the core's (wasm/src/size_limits.h, written
// as web/src/ik/generated/size_limits.ts by the WebAssembly build).
import { SIZE_LIMITS } from '../ik/generated/size_limits.js';

/** The largest rig file (or .gltf side buffer) read, bytes (512 MiB): from disk and on the page, checked before reading. */
export const MAX_RIG_FILE_BYTES = 512 * 1024 * 1024;

/** Bones of one rig. */
export const MAX_BONES = SIZE_LIMITS.kMaxBones;

/** End effectors of one rig. */
export const MAX_EFFECTORS = SIZE_LIMITS.kMaxEffectors;

/** Entries of the Jacobian: (3 x effectors) rows times (3 x bones) columns. */
export const MAX_JACOBIAN_ENTRIES = SIZE_LIMITS.kMaxMatrixEntries;

/**
 * Largest magnitude of a bone length or joint position, rig units. Far past any real model in any
 * unit, and far below where squared distances (the objective) overflow.
 */
export const MAX_COORDINATE = SIZE_LIMITS.kMaxCoordinate;

/** The most end effectors a rig of `bones` bones may have (the effector and Jacobian caps). */
export function maxEffectors(bones: number): number {
  return Math.min(MAX_EFFECTORS, Math.floor(MAX_JACOBIAN_ENTRIES / (9 * Math.max(1, bones))));
}

/** Why `effectors` end effectors on `bones` bones are too many for the core, or undefined when they are not. */
export function effectorCountProblem(effectors: number, bones: number): string | undefined {
  if (effectors <= maxEffectors(bones)) return undefined;
  if (effectors > MAX_EFFECTORS) return `${effectors} end effectors; at most ${MAX_EFFECTORS}`;
  const entries = 9 * effectors * bones;
  return `${effectors} end effectors on ${bones} bones make a ${3 * effectors} x ${3 * bones} Jacobian (${entries} entries; at most ${MAX_JACOBIAN_ENTRIES}): at most ${maxEffectors(bones)} end effectors on this rig`;
}
