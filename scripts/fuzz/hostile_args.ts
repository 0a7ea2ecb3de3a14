// Array arguments for the rig and solver calls: the right numbers, or careless and hostile
// versions of them (wrong lengths, NaN, array-likes that lie, typed arrays of other kinds,
// detached buffers, and elements whose valueOf disposes the rig or re-enters the API).
import { IkRig } from '#ik/rig.js';
import { sketchRig } from '../rig_files/rig_builder.js';
import { FUZZ_THROW } from './classify_error.js';
import { changeEffectors, type ApiState } from './api_state.js';
import type { Rand } from './random.js';

/** Should a correct API accept the argument? 'either' when the outcome depends on a side effect. */
export type Acceptance = 'must' | 'mustNot' | 'either';

export interface Arg {
  value: unknown;
  /** Short description for the case's line. */
  text: string;
  accept: Acceptance;
  /** For 'must': the numbers a correct API computes with. */
  numbers?: Float64Array;
  /** Reading it runs the caller's code (a valueOf, a getter, a Proxy trap), whose time is no part of the call's own. */
  sideEffect?: boolean;
}

/** An argument a correct API accepts; `numbers` is copied, since the call may write into `value` (solve's `out`). */
const must = (value: unknown, text: string, numbers: Float64Array): Arg => ({
  value,
  text,
  accept: 'must',
  numbers: numbers.slice(),
});
const mustNot = (value: unknown, text: string): Arg => ({ value, text, accept: 'mustNot' });

/** Side effects an element's valueOf can have in the middle of a call; `harmless` ones leave the numbers' meaning intact. */
function tricks(s: ApiState): [string, () => void, boolean][] {
  return [
    ['disposes the rig', () => s.rig.dispose(), false],
    ['disposes the solver', () => s.solver.dispose(), false],
    ['sets the effectors to [0]', () => changeEffectors(s, [0]), false],
    [
      'throws',
      () => {
        throw new Error(FUZZ_THROW);
      },
      false,
    ],
    ['calls rig.tips at zero re-entrantly', () => s.rig.tips(new Float64Array(s.rig.numAngles)), true],
    [
      'runs a solve re-entrantly',
      () => s.solver.solve(new Float64Array(s.rig.numAngles), new Float64Array(3 * s.rig.numEffectors)),
      true,
    ],
    ['grows the WebAssembly memory', () => growMemory(s), true],
  ];
}

/** Effectors of the rig growMemory() builds: its Jacobian buffer has 3 * 256 rows. */
const GROW_EFFECTORS = 256;

/**
 * Makes the WebAssembly memory grow while the heap is under 64 MiB: builds and frees a chain
 * whose Jacobian buffer alone is as large as the heap. A refusal of that rig is ignored (the
 * point is the growth, not the rig).
 */
function growMemory(s: ApiState): void {
  const bytes = s.ik.HEAPU8.length;
  if (bytes > 64 * 2 ** 20) return;
  const bones = Math.max(GROW_EFFECTORS, Math.ceil(bytes / (8 * 3 * GROW_EFFECTORS * 3)));
  const spec = sketchRig(
    Array.from({ length: bones }, (_, i) => ({ parent: i - 1, at: [i, 0, 0], length: 1 })),
    [...Array(GROW_EFFECTORS).keys()],
  );
  try {
    new IkRig(s.ik, spec).dispose();
  } catch {
    // Refused (too large): the memory may not have grown, which only makes this trick weaker.
  }
}

/** An argument with a side effect: harmless ones must be accepted, a throwing one must throw, the rest may do either. */
function tricked(value: unknown, text: string, what: string, harmless: boolean, valid: Float64Array): Arg {
  const accept: Acceptance = harmless ? 'must' : what === 'throws' ? 'mustNot' : 'either';
  return { value, text, accept, numbers: harmless ? valid.slice() : undefined, sideEffect: true };
}

/** `valid` (the right numbers for this call) as is, or a careless or hostile variant. */
export function numbersArg(r: Rand, s: ApiState, valid: Float64Array, name: string): Arg {
  const n = valid.length;
  const withEntry = (k: number, v: number): Float64Array => {
    const a = valid.slice();
    a[k] = v;
    return a;
  };
  return r.weighted<() => Arg>([
    [12, () => must(valid, name, valid)],
    [3, () => must(Array.from(valid), `${name} as an Array`, valid)],
    [
      1,
      () => {
        const f = Float32Array.from(valid);
        return must(f, `${name} as a Float32Array`, Float64Array.from(f));
      },
    ],
    [1, () => ({ value: Array.from(valid, String), text: `${name} as numeric strings`, accept: 'either' })],
    [
      1,
      () => ({
        value: Array.from(valid, (v) => ({ valueOf: () => v })),
        text: `${name} as objects with valueOf`,
        accept: 'either',
      }),
    ],
    [
      1,
      () => {
        const shared = new Float64Array(new SharedArrayBuffer(8 * n));
        shared.set(valid);
        return must(shared, `${name} on a SharedArrayBuffer`, valid);
      },
    ],
    [
      1,
      () => ({
        value: '0'.repeat(n),
        text: `${name} as the string "${'0'.repeat(Math.min(n, 6))}..."`,
        accept: 'either',
      }),
    ],
    [
      3,
      () => {
        const length = r.pick([0, 1, n - 1, n + 1, 2 * n, 1_000_000].filter((l) => l >= 0 && l !== n));
        return mustNot(new Float64Array(length), `${name} of length ${length} (expected ${n})`);
      },
    ],
    [
      4,
      () => {
        const k = r.int(n),
          v = r.pick([NaN, Infinity, -Infinity]);
        return mustNot(withEntry(k, v), `${name}[${k}] = ${v}`);
      },
    ],
    [
      2,
      () => {
        // Angles may be as large as doubles go (sin and cos stay finite); targets stay where E = |tips - target|^2 / 2 does not overflow.
        const k = r.int(n),
          v = r.pick(
            name === 'angles'
              ? [1e300, -1e308, 5e-324, -0, 2 ** 53 + 2, 1e150]
              : [-1e150, 1e150, 5e-324, -0, 2 ** 53 + 2],
          );
        return must(withEntry(k, v), `${name}[${k}] = ${v}`, withEntry(k, v));
      },
    ],
    [
      2,
      () => {
        const v = r.pick<unknown>([null, undefined, 42, 'abc', {}, true, () => 0, Symbol('x')]);
        return mustNot(v, `${name} = ${String(v)}`);
      },
    ],
    [
      2,
      () => {
        const length = r.pick<unknown>([n, -1, 2 ** 32, 2 ** 53, NaN, String(n), Infinity]);
        return mustNot({ length }, `${name} = {length: ${String(length)}} (no elements)`);
      },
    ],
    [
      1,
      () => {
        const a: number[] = Array.from(valid);
        delete a[r.int(n)];
        return mustNot(a, `${name} with a hole`);
      },
    ],
    [1, () => mustNot(new BigInt64Array(n), `${name} as a BigInt64Array`)],
    [
      1,
      () => {
        const a = Float64Array.from(valid);
        structuredClone(a.buffer, { transfer: [a.buffer] });
        return mustNot(a, `${name} on a detached ArrayBuffer`);
      },
    ],
    [
      1,
      () => {
        const i8 = Int8Array.from(valid, (v) => Math.max(-128, Math.min(127, Math.round(v))));
        return must(i8, `${name} as an Int8Array`, Float64Array.from(i8));
      },
    ],
    [
      4,
      () => {
        const [what, effect, harmless] = r.pick(tricks(s));
        const k = r.int(n);
        const a: unknown[] = Array.from(valid);
        a[k] = { valueOf: () => (effect(), valid[k]) };
        return tricked(a, `${name}[${k}].valueOf ${what}`, what, harmless, valid);
      },
    ],
    [
      1,
      () => {
        const [what, effect, harmless] = r.pick(tricks(s));
        const like = Object.defineProperty({ ...Array.from(valid) }, 'length', { get: () => (effect(), n) });
        return tricked(like, `${name} as an array-like whose length getter ${what}`, what, harmless, valid);
      },
    ],
    [
      1,
      () => {
        const [what, effect, harmless] = r.pick(tricks(s));
        const k = r.int(n);
        const proxy = new Proxy(Array.from(valid), {
          get: (t, p, rcv) => (p === String(k) && effect(), Reflect.get(t, p, rcv)),
        });
        return tricked(proxy, `${name} as a Proxy whose element ${k} ${what}`, what, harmless, valid);
      },
    ],
  ])();
}
