// The rig as plain arrays: what every importer (A7 JSON, glTF) produces and the WebAssembly
// core consumes. Angles and limits are in DEGREES; lengths and positions in rig units.

export interface RigSpec {
  /** Display name per bone (never interpreted as HTML). */
  names: string[];
  /** Parent bone index per bone, -1 for a root. */
  parents: Int32Array;
  /** 16 numbers per bone: the row-major 4x4 rest transform, canonical bone -> rest bone (translation within +-1e9). */
  rest: Float64Array;
  /** Bone length per bone, 0..1e9: the canonical bone runs from (0,0,0) to (length,0,0). */
  lengths: Float64Array;
  /** 3 XZX lower limits per bone, degrees; -Infinity for unbounded. */
  lower: Float64Array;
  /** 3 XZX upper limits per bone, degrees; +Infinity for unbounded. */
  upper: Float64Array;
  /** Bone indices whose tips are end effectors. */
  effectors: Int32Array;
  /**
   * A floating root: the whole rig moves by a translation the solvers find, within these bounds
   * (world x, y, z, rig units, finite, lower <= upper), as three more unknowns after the angles
   * (IkRig.numAngles is 3 per bone + 3). Absent: the roots stay where their rest transforms put them.
   */
  floatingRoot?: { lower: ArrayLike<number>; upper: ArrayLike<number> };
}

/** Number of bones of a spec. */
export function boneCount(spec: RigSpec): number {
  return spec.parents.length;
}

/** The row-major 4x4 rest transform of bone `i`, as a new array of 16 numbers. */
export function restMatrix(spec: RigSpec, i: number): Float64Array {
  return spec.rest.slice(16 * i, 16 * i + 16);
}
