// XZX joint-limit values read from rig files, in degrees, by the rule the core applies (README
// "Limits", kMaxLimitDeg in wasm/src/rig.h): a limit past +-MAX_LIMIT_DEG (100 turns) in its own
// direction means unbounded, as -1e10 does in the A7 files; a lower limit above +MAX_LIMIT_DEG or
// an upper limit below -MAX_LIMIT_DEG leaves no angle and is refused, naming the field. Refused,
// not clamped: it is a typo or a hostile value, and no clamp can tell what was meant.
// So xzx_min = xzx_max = [1e9, 0, 0] is an error. It used to be read as "unbounded" by magnitude
// alone and became a lower limit of +Infinity, and every solve ended in numerical_failure.

/** Largest magnitude of a bounded limit, degrees (100 turns); farther out in its own direction a limit means none. */
export const MAX_LIMIT_DEG = 36000;

export type LimitSide = 'min' | 'max';

/** True when `deg` as a `side` limit means unbounded: below -MAX_LIMIT_DEG for min, above +MAX_LIMIT_DEG for max. */
export function isUnbounded(deg: number, side: LimitSide): boolean {
  return side === 'min' ? deg < -MAX_LIMIT_DEG : deg > MAX_LIMIT_DEG;
}

/** Why `deg` is no valid `side` limit (a phrase following the field's name), or undefined when it is one. */
export function limitProblem(deg: number, side: LimitSide): string | undefined {
  if (side === 'min' ? deg <= MAX_LIMIT_DEG : deg >= -MAX_LIMIT_DEG) return undefined;
  const [bound, unbounded] =
    side === 'min' ? ['a lower', `below -${MAX_LIMIT_DEG}`] : ['an upper', `above ${MAX_LIMIT_DEG}`];
  return `= ${deg} degrees leaves no angle within +-${MAX_LIMIT_DEG} degrees: ${bound} limit ${unbounded} means unbounded`;
}
