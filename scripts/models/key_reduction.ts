// Keyframe reduction for a clip's channel sampled at every frame: the frames to keep so that
// interpolation between kept ones (LINEAR: slerp for rotations, as glTF players do) rebuilds every
// frame within a tolerance. Greedy: from the last kept frame, the run extends while every frame in
// it is rebuilt well; the first and last frames are always kept.

/** Quaternion [x, y, z, w] number `k` of `values`. */
function quat(values: Float32Array, k: number): number[] {
  return Array.from(values.subarray(4 * k, 4 * k + 4));
}

/** The angle between rotations `a` and `b` (unit quaternions), degrees; from the chord, exact for near ones. */
function angleDeg(a: number[], b: number[]): number {
  const sign = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] < 0 ? -1 : 1;
  const minus = Math.hypot(...a.map((x, i) => x - sign * b[i])),
    plus = Math.hypot(...a.map((x, i) => x + sign * b[i]));
  return (4 * Math.atan2(minus, plus) * 180) / Math.PI;
}

/** Spherical interpolation from unit quaternion `a` (u = 0) to `b` (u = 1), the shorter way. */
function slerp(a: number[], b: number[], u: number): number[] {
  let d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const sign = d < 0 ? -1 : 1;
  d *= sign;
  const theta = Math.acos(Math.min(1, d));
  if (theta < 1e-9) return a;
  const wa = Math.sin((1 - u) * theta) / Math.sin(theta),
    wb = (sign * Math.sin(u * theta)) / Math.sin(theta);
  return a.map((x, i) => wa * x + wb * b[i]);
}

/**
 * The frames of a channel to keep: `values` holds `stride` numbers per frame (4: a rotation
 * quaternion, `tolerance` in degrees; 3: a translation, `tolerance` in its units).
 */
export function keptFrames(values: Float32Array, stride: 3 | 4, tolerance: number): number[] {
  const count = values.length / stride;
  const error = (a: number, b: number, k: number): number => {
    const u = (k - a) / (b - a);
    if (stride === 4) return angleDeg(slerp(quat(values, a), quat(values, b), u), quat(values, k));
    let sum = 0;
    for (let i = 0; i < 3; i++) {
      const x = values[3 * a + i] + u * (values[3 * b + i] - values[3 * a + i]);
      sum += (x - values[3 * k + i]) ** 2;
    }
    return Math.sqrt(sum);
  };
  const kept = [0];
  for (let b = 2; b < count; b++) {
    const a = kept[kept.length - 1];
    for (let k = a + 1; k < b; k++)
      if (error(a, b, k) > tolerance) {
        kept.push(b - 1);
        break;
      }
  }
  if (count > 1) kept.push(count - 1);
  return kept;
}
