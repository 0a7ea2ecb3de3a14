// A pose file's angles clamped into the rig's limits (pose_json.ts reads them): every bone gets
// angles, 0 0 0 where the file gives none, and the bones whose given angles changed are noted.

/**
 * Every bone's XZX angles (3 per bone, degrees), those `given` or else 0 0 0, clamped into
 * `limits` (3 per bone, degrees). `clamped` has a line per given bone the clamping changed: its
 * key (from `keys`, rig order) and its angles before and after.
 */
export function clampAngles(
  given: readonly (number[] | undefined)[],
  keys: readonly string[],
  limits: { lower: ArrayLike<number>; upper: ArrayLike<number> },
): { angles: Float64Array; clamped: string[] } {
  const { lower, upper } = limits;
  const angles = new Float64Array(3 * given.length);
  const clamped: string[] = [];
  for (let i = 0; i < given.length; i++) {
    const a = given[i] ?? [0, 0, 0];
    for (let k = 0; k < 3; k++) angles[3 * i + k] = Math.min(Math.max(a[k], lower[3 * i + k]), upper[3 * i + k]);
    const now = Array.from(angles.subarray(3 * i, 3 * i + 3));
    if (given[i] && now.some((v, k) => v !== a[k]))
      clamped.push(`${JSON.stringify(keys[i])} [${a.join(', ')}] -> [${now.join(', ')}]`);
  }
  return { angles, clamped };
}
