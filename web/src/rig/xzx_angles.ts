// Reading a joint rotation back as XZX angles inside the joint's limits: how a pose from a peer
// that does not work in XZX angles (three.js CCD) is judged by the rig's own limits, how far a
// clip's pose leaves them (bench-node/clip_limits.ts), and a posed file's pose read as angles
// from its bind pose (bind_pose.ts). No three.js: a quaternion is any {x, y, z, w}.

/** A unit quaternion. */
export interface QuaternionLike {
  x: number;
  y: number;
  z: number;
  w: number;
}

const DEG = 180 / Math.PI;

/** Moves `x` by whole turns to the copy nearest the interval [lo, hi] (degrees). */
function nearestTurn(x: number, lo: number, hi: number): number {
  if (x >= lo && x <= hi) return x;
  if (!Number.isFinite(lo) || !Number.isFinite(hi) || hi - lo >= 360) {
    const mid = Number.isFinite(lo) && Number.isFinite(hi) ? (lo + hi) / 2 : 0;
    return x - 360 * Math.round((x - mid) / 360);
  }
  const below = x - 360 * Math.ceil((x - hi) / 360); // largest copy <= hi
  const above = below + 360;
  const dist = (y: number): number => (y < lo ? lo - y : y > hi ? y - hi : 0);
  return dist(below) <= dist(above) ? below : above;
}

/**
 * XZX angles (degrees) of the rotation `q`, as the decomposition nearest the limits [lo, hi] and
 * then clamped into them. Rx(a) Rz(b) Rx(c) has R00 = cos b, R10 = cos a sin b, R20 = sin a sin b,
 * R01 = -sin b cos c, R02 = sin b sin c; its two decompositions are (a, b, c) and
 * (a + 180, -b, c + 180). At b = 0 or 180 only a +- c is
 * defined; it is split so that both angles are inside their limits when possible.
 */
export function xzxWithinLimits(
  q: QuaternionLike,
  lo: ArrayLike<number>,
  hi: ArrayLike<number>,
  out: Float64Array,
  at = 0,
): void {
  const { x, y, z, w } = q;
  const r00 = 1 - 2 * (y * y + z * z);
  const r10 = 2 * (x * y + z * w);
  const r20 = 2 * (x * z - y * w);
  const r01 = 2 * (x * y - z * w);
  const r02 = 2 * (x * z + y * w);
  const r11 = 1 - 2 * (x * x + z * z);
  const r21 = 2 * (y * z + x * w);
  const sb = Math.hypot(r10, r20);
  const candidates: Array<[number, number, number]> = [];
  if (sb < 1e-9) {
    // At b = 0, R = Rx(a + c); at b = 180, R = Rx(a - c) Rz(180). Split the one defined sum so
    // that both a and c are inside their limits when that is possible.
    const b = r00 > 0 ? 0 : 180;
    const t = b === 0 ? Math.atan2(r21, r11) * DEG : Math.atan2(-r21, -r11) * DEG;
    const sign = b === 0 ? 1 : -1; // c = sign * (t - a)
    const turn = nearestTurn(t, b === 0 ? lo[0] + lo[2] : lo[0] - hi[2], b === 0 ? hi[0] + hi[2] : hi[0] - lo[2]);
    const cLo = b === 0 ? turn - hi[2] : turn + lo[2];
    const cHi = b === 0 ? turn - lo[2] : turn + hi[2];
    const aLo = Math.max(lo[0], cLo),
      aHi = Math.min(hi[0], cHi);
    const a = aLo <= aHi ? Math.min(aHi, Math.max(aLo, 0)) : Math.min(hi[0], Math.max(lo[0], turn));
    candidates.push([a, b, sign * (turn - a)]);
  } else {
    const a = Math.atan2(r20, r10) * DEG;
    const b = Math.atan2(sb, r00) * DEG;
    const c = Math.atan2(r02, -r01) * DEG;
    candidates.push([a, b, c], [a + 180, -b, c + 180]);
  }
  let best = Infinity;
  for (const cand of candidates) {
    let cost = 0;
    const clamped = cand.map((v, k) => {
      const near = nearestTurn(v, lo[k], hi[k]);
      const c = Math.min(hi[k], Math.max(lo[k], near));
      cost += (c - near) ** 2;
      return c;
    });
    if (cost < best) {
      best = cost;
      out.set(clamped, at);
    }
  }
}
