// The core's 4x4 matrices are row-major (16 numbers); three.js stores column-major.
import type { Matrix4 } from 'three';

/** Copies the row-major 4x4 at `offset` of `src` into `out` (a three.js matrix); returns `out`. */
export function fromRowMajor(out: Matrix4, src: ArrayLike<number>, offset: number): Matrix4 {
  const o = offset;
  return out.set(
    src[o],
    src[o + 1],
    src[o + 2],
    src[o + 3],
    src[o + 4],
    src[o + 5],
    src[o + 6],
    src[o + 7],
    src[o + 8],
    src[o + 9],
    src[o + 10],
    src[o + 11],
    src[o + 12],
    src[o + 13],
    src[o + 14],
    src[o + 15],
  );
}
