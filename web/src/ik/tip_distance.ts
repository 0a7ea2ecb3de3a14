// How far end effectors are from their targets, measured from the tips the core returns: the
// page's "pinned drift" and the benchmark's tip distance and wobble share this one loop.

/**
 * The largest distance (rig units) of an end effector's tip from its target, over every end
 * effector but `skip` (an effector index; -1, the default: none). `tips` and `targets` hold 3
 * numbers per end effector (rig units). 0 when no effector is measured.
 */
export function largestTipDistance(tips: ArrayLike<number>, targets: ArrayLike<number>, skip = -1): number {
  let worst = 0;
  for (let e = 0; e < targets.length / 3; e++) {
    if (e === skip) continue;
    const dx = tips[3 * e] - targets[3 * e],
      dy = tips[3 * e + 1] - targets[3 * e + 1],
      dz = tips[3 * e + 2] - targets[3 * e + 2];
    worst = Math.max(worst, Math.hypot(dx, dy, dz));
  }
  return worst;
}
