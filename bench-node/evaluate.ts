// E and the drag experiment's wobble from end-effector positions, the same for every method.

/** E = 1/2 |tips - target|^2 (tips and target: 3 per end effector). */
export function errorOf(tips: ArrayLike<number>, target: ArrayLike<number>): number {
  let s = 0;
  for (let i = 0; i < target.length; i++) {
    const d = tips[i] - target[i];
    s += d * d;
  }
  return 0.5 * s;
}

/**
 * The largest distance of a pinned end effector (every effector but `dragged`) from its target.
 * NaN when nothing is pinned (no drag, or a single end effector).
 */
export function pinnedDeviation(tips: ArrayLike<number>, target: ArrayLike<number>, dragged: number): number {
  const n = target.length / 3;
  if (dragged < 0 || n < 2) return NaN;
  let worst = 0;
  for (let e = 0; e < n; e++) {
    if (e === dragged) continue;
    const dx = tips[3 * e] - target[3 * e], dy = tips[3 * e + 1] - target[3 * e + 1], dz = tips[3 * e + 2] - target[3 * e + 2];
    worst = Math.max(worst, Math.hypot(dx, dy, dz));
  }
  return worst;
}
