// Small row-major 4x4 affine-matrix helpers for the importers (no three.js; they run once per
// import, so they allocate freely). A matrix is 16 numbers, element (r, c) at 4 * r + c,
// the same layout as RigSpec.rest.

export type Mat4 = Float64Array;

/** A new 4x4 identity. */
export function identity(): Mat4 {
  return Float64Array.of(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
}

/** a * b (both affine or not; full 4x4 product). */
export function multiply(a: ArrayLike<number>, b: ArrayLike<number>): Mat4 {
  const out = new Float64Array(16);
  for (let r = 0; r < 4; r++)
    for (let c = 0; c < 4; c++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += a[4 * r + k] * b[4 * k + c];
      out[4 * r + c] = s;
    }
  return out;
}

/** The glTF column-major `matrix` array as a row-major matrix. */
export function fromColumnMajor(m: ArrayLike<number>): Mat4 {
  const out = new Float64Array(16);
  for (let r = 0; r < 4; r++) for (let c = 0; c < 4; c++) out[4 * r + c] = m[4 * c + r];
  return out;
}

/**
 * T * R * S from a translation, a quaternion (x, y, z, w) and a scale, with the same formula as
 * three.js Matrix4.compose (so a non-unit quaternion gives the same matrix in both).
 */
export function fromTRS(t: ArrayLike<number>, q: ArrayLike<number>, s: ArrayLike<number>): Mat4 {
  const [x, y, z, w] = [q[0], q[1], q[2], q[3]];
  const x2 = x + x,
    y2 = y + y,
    z2 = z + z;
  const xx = x * x2,
    xy = x * y2,
    xz = x * z2,
    yy = y * y2,
    yz = y * z2,
    zz = z * z2;
  const wx = w * x2,
    wy = w * y2,
    wz = w * z2;
  return Float64Array.of(
    (1 - (yy + zz)) * s[0],
    (xy - wz) * s[1],
    (xz + wy) * s[2],
    t[0],
    (xy + wz) * s[0],
    (1 - (xx + zz)) * s[1],
    (yz - wx) * s[2],
    t[1],
    (xz - wy) * s[0],
    (yz + wx) * s[1],
    (1 - (xx + yy)) * s[2],
    t[2],
    0,
    0,
    0,
    1,
  );
}

/** Determinant of the upper-left 3x3 block. */
export function det3(m: ArrayLike<number>): number {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
}

/** Inverse of an affine matrix (bottom row 0 0 0 1). Returns null when the 3x3 block is singular. */
export function invertAffine(m: ArrayLike<number>): Mat4 | null {
  const d = det3(m);
  const scale = Math.max(
    Math.abs(m[0]),
    Math.abs(m[1]),
    Math.abs(m[2]),
    Math.abs(m[4]),
    Math.abs(m[5]),
    Math.abs(m[6]),
    Math.abs(m[8]),
    Math.abs(m[9]),
    Math.abs(m[10]),
  );
  if (!Number.isFinite(d) || scale === 0 || Math.abs(d) <= 1e-12 * scale * scale * scale) return null;
  const inv = new Float64Array(16);
  inv[0] = (m[5] * m[10] - m[6] * m[9]) / d;
  inv[1] = (m[2] * m[9] - m[1] * m[10]) / d;
  inv[2] = (m[1] * m[6] - m[2] * m[5]) / d;
  inv[4] = (m[6] * m[8] - m[4] * m[10]) / d;
  inv[5] = (m[0] * m[10] - m[2] * m[8]) / d;
  inv[6] = (m[2] * m[4] - m[0] * m[6]) / d;
  inv[8] = (m[4] * m[9] - m[5] * m[8]) / d;
  inv[9] = (m[1] * m[8] - m[0] * m[9]) / d;
  inv[10] = (m[0] * m[5] - m[1] * m[4]) / d;
  for (let r = 0; r < 3; r++) inv[4 * r + 3] = -(inv[4 * r] * m[3] + inv[4 * r + 1] * m[7] + inv[4 * r + 2] * m[11]);
  inv[15] = 1;
  return inv;
}

/** m applied to the point p (3 numbers). */
export function transformPoint(m: ArrayLike<number>, p: ArrayLike<number>): [number, number, number] {
  return [0, 1, 2].map((r) => m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3]) as [
    number,
    number,
    number,
  ];
}

/** m's 3x3 block applied to the direction v (3 numbers). */
export function transformDirection(m: ArrayLike<number>, v: ArrayLike<number>): [number, number, number] {
  return [0, 1, 2].map((r) => m[4 * r] * v[0] + m[4 * r + 1] * v[1] + m[4 * r + 2] * v[2]) as [number, number, number];
}

/**
 * The rotation of the polar decomposition of m's 3x3 block (the orthogonal factor Q of Q * S with S
 * symmetric positive definite), as 9 row-major numbers. For T * R * S with a positive scale S this
 * is R exactly. Its determinant is -1 when m mirrors. m must be non-singular.
 */
export function polarRotation(m: ArrayLike<number>): Float64Array {
  const s = Math.cbrt(Math.abs(det3(m))) || 1; // pre-scaling makes the iteration start near Q
  let q = Float64Array.of(m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]).map((v) => v / s);
  for (let it = 0; it < 60; it++) {
    // Higham's iteration Q <- (Q + Q^-T) / 2 converges quadratically to the orthogonal factor.
    const [a, b, c, d, e, f, g, h, i] = q;
    const det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
    // Q^-T = cofactor(Q) / det
    const invT = Float64Array.of(
      (e * i - f * h) / det,
      -(d * i - f * g) / det,
      (d * h - e * g) / det,
      -(b * i - c * h) / det,
      (a * i - c * g) / det,
      -(a * h - b * g) / det,
      (b * f - c * e) / det,
      -(a * f - c * d) / det,
      (a * e - b * d) / det,
    );
    const next = q.map((v, k) => 0.5 * (v + invT[k]));
    let change = 0;
    for (let k = 0; k < 9; k++) change = Math.max(change, Math.abs(next[k] - q[k]));
    q = next;
    if (change < 1e-15) break;
  }
  return q;
}

/** True when every entry is a finite number. */
export function allFinite(m: ArrayLike<number>): boolean {
  for (let k = 0; k < m.length; k++) if (!Number.isFinite(m[k])) return false;
  return true;
}

/** The largest |v_k| (0 for an empty list). */
export function maxAbs(v: ArrayLike<number>): number {
  let m = 0;
  for (let k = 0; k < v.length; k++) m = Math.max(m, Math.abs(v[k]));
  return m;
}

/** The largest |a_k - b_k| over a's length. */
export function maxAbsDiff(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let m = 0;
  for (let k = 0; k < a.length; k++) m = Math.max(m, Math.abs(a[k] - b[k]));
  return m;
}
