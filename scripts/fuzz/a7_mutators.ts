// Mutations specific to A7 rigs (PROTOCOL.md): parent cycles and bad indices, non-rigid or
// malformed rest matrices, inverted or absurd limits, bad end-effector lists, bad lengths.
import { INFINITY_MARK } from './json_text.js';
import type { Rand } from './random.js';

type Bone = Record<string, unknown>;
export type A7Doc = { bones: Bone[]; ik_constraints?: unknown };

function restRows(b: Bone): number[][] | undefined {
  const rows = b.rest_T;
  return Array.isArray(rows) && rows.every((row) => Array.isArray(row)) ? (rows as number[][]) : undefined;
}

/** One A7-specific mutation of `doc` (whose `bones` is a non-empty array); its description. */
export function mutateA7(r: Rand, doc: A7Doc): string {
  const n = doc.bones.length;
  const i = r.int(n),
    bone = doc.bones[i];
  const at = `bones[${i}]`;
  return r.weighted<() => string>([
    [
      2,
      () => {
        const p = bone.parent_id;
        if (
          Number.isInteger(p) &&
          (p as number) >= 0 &&
          (p as number) < n &&
          typeof doc.bones[p as number] === 'object'
        ) {
          doc.bones[p as number].parent_id = i;
          return `bones[${p}].parent_id = ${i} (a cycle with its child)`;
        }
        bone.parent_id = i;
        return `${at}.parent_id = ${i} (itself)`;
      },
    ],
    [
      2,
      () => {
        const v = r.pick<unknown>([n, -2, 0.5, 1e10, '0', 2 ** 32]);
        bone.parent_id = v;
        return `${at}.parent_id = ${JSON.stringify(v)}`;
      },
    ],
    [
      4,
      () => {
        const rows = restRows(bone);
        if (!rows) return `${at}.rest_T left as it is (not rows)`;
        return r.pick<() => string>([
          () => ((rows[0] = rows[0].map((x) => x * 1.5)), `${at}.rest_T row 0 scaled by 1.5 (not rigid)`),
          () => ((rows[0][0] *= 1 + 1e-7), `${at}.rest_T[0][0] *= 1 + 1e-7 (rigid within 1e-6)`),
          () => (rows.forEach((row) => (row[0] = -row[0])), `${at}.rest_T column 0 negated (a mirror)`),
          () => (rows.splice(3), `${at}.rest_T as 3x4`),
          () => (rows.push([0, 0, 0, 1]), `${at}.rest_T with a fifth row`),
          () => ((rows[3] = [0, 0, 0, 2]), `${at}.rest_T bottom row (0, 0, 0, 2)`),
          () => (((rows[r.int(3)] as unknown[])[r.int(4)] = INFINITY_MARK), `${at}.rest_T entry = 1e999`),
          () => {
            const v = r.pick([1e300, 1e308, -1e308]);
            rows[0][3] = v;
            return `${at}.rest_T translation x = ${v}`;
          },
          () => ((rows[1] = [0, 1, 0]), `${at}.rest_T row 1 has 3 numbers`),
        ])();
      },
    ],
    [
      3,
      () => {
        const key = r.pick(['xzx_min', 'xzx_max']);
        const v = r.pick<unknown>([
          [10, 10, 10],
          [-10, -10, -10],
          [1e10, 1e10, 1e10],
          [-1e10, -1e10, -1e10],
          [1e308, 0, 0],
          [null, 0, 0],
          [0, 0],
          ['0', '0', '0'],
          [1e300, 1e300, 1e300],
        ]);
        bone[key] = v;
        return `${at}.${key} = ${JSON.stringify(v)}`;
      },
    ],
    [
      1,
      () => {
        bone.xzx_min = [20, 20, 20];
        bone.xzx_max = [-20, -20, -20];
        return `${at} xzx_min above xzx_max`;
      },
    ],
    [
      3,
      () => {
        const v = r.pick<unknown>([
          [],
          -1,
          n,
          1.5,
          [0, 0],
          [[0]],
          'all',
          {},
          2 ** 32,
          [...Array(n).keys()],
          Array.from({ length: 300 }, (_, k) => k % n),
        ]);
        doc.ik_constraints = v;
        const text = JSON.stringify(v);
        return `ik_constraints = ${text.length > 30 ? `${text.slice(0, 27)}...` : text}`;
      },
    ],
    [
      2,
      () => {
        const v = r.pick<unknown>([-1, 1e308, INFINITY_MARK, '1', null, 1e-320]);
        bone.length = v;
        return `${at}.length = ${JSON.stringify(v)}`;
      },
    ],
    [
      1,
      () => {
        const v = r.pick<unknown>(['x'.repeat(1_000_000), 'a\u0000b', 42, '<img src=x onerror=alert(1)>']);
        bone.name = v;
        return `${at}.name = ${typeof v === 'string' ? `a ${v.length}-character string` : String(v)}`;
      },
    ],
  ])();
}
