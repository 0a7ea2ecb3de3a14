// The A7 loader refuses, naming the file and the field, everything the core would refuse (whose
// messages name no file): a fractional or cyclic parent, a negative or huge length, a rest matrix
// that is not rigid, a repeated, fractional or missing end effector, a name that is no string.
// An unnamed bone gets the name '' so the core calls it `bone 3`, not `bone 3 "bone 3"`.
import { describe, expect, it } from 'vitest';

import { parseA7Rig } from '../../web/src/rig/a7/a7_rig.js';
import { chainParents, treeA7 } from '../../scripts/rig_files/tree_rigs.js';
import { loadError } from './synthetic_rigs.js';

const three = chainParents(3);
const rest = (rows: number[][]): Record<string, unknown> => ({ rest_T: rows });

describe('A7 checks', () => {
  it('leaves unnamed bones without a name and refuses a name that is not a string', async () => {
    expect(parseA7Rig(treeA7(three), 'a.json').names).toEqual(['', '', '']);
    expect(parseA7Rig(treeA7(three, { name: 'arm' }), 'a.json').names).toEqual(['arm', 'arm', 'arm']);
    expect(await loadError(treeA7(three, { name: 7 }), 'a.json')).toBe('a.json: bones[0].name is not a string');
  });

  it('refuses parents that are fractions, the bone itself or a cycle', async () => {
    const bad = (parents: number[]): Promise<string> => loadError(treeA7(parents), 'a.json');
    expect(await bad([-1, 0.5, 1])).toBe('a.json: bones[1].parent_id 0.5 is not -1 or a bone index (0..2)');
    expect(await bad([-1, 1, 1])).toBe('a.json: bones[1].parent_id is the bone itself');
    expect(await bad([-1, 2, 1])).toBe("a.json: the bones' parent_id form a cycle: bones[1] -> bones[2] -> bones[1]");
  });

  it('refuses negative and huge lengths and positions', async () => {
    expect(await loadError(treeA7(three, { length: -2 }), 'a.json')).toBe('a.json: bones[0].length -2 is negative');
    expect(await loadError(treeA7(three, { length: 1e300 }), 'a.json')).toBe(
      'a.json: bones[0].length = 1e+300 lies beyond +-1000000000 rig units',
    );
    expect(
      await loadError(
        treeA7(
          three,
          rest([
            [1, 0, 0, 2e9],
            [0, 1, 0, 0],
            [0, 0, 1, 0],
          ]),
        ),
        'a.json',
      ),
    ).toBe('a.json: bones[0].rest_T[0][3] = 2000000000 lies beyond +-1000000000 rig units');
  });

  it('refuses rest matrices that are not rigid', async () => {
    expect(
      await loadError(
        treeA7(
          three,
          rest([
            [2, 0, 0, 0],
            [0, 1, 0, 0],
            [0, 0, 1, 0],
          ]),
        ),
        'a.json',
      ),
    ).toBe('a.json: bones[0].rest_T is not rigid (its rotation part is not orthonormal)');
    expect(
      await loadError(
        treeA7(
          three,
          rest([
            [-1, 0, 0, 0],
            [0, 1, 0, 0],
            [0, 0, 1, 0],
          ]),
        ),
        'a.json',
      ),
    ).toBe('a.json: bones[0].rest_T is not rigid (it mirrors: determinant < 0)');
    expect(
      await loadError(
        treeA7(
          three,
          rest([
            [1, 0, 0, 0],
            [0, 1, 0, 0],
            [0, 0, 1, 0],
            [0, 0, 1, 1],
          ]),
        ),
        'a.json',
      ),
    ).toBe('a.json: bones[0].rest_T bottom row is not (0, 0, 0, 1)');
  });

  it('refuses end effectors that are fractions, repeated or none', async () => {
    const bad = (ik: unknown): Promise<string> => loadError(treeA7(three, {}, { ik_constraints: ik }), 'a.json');
    expect(await bad(2.5)).toBe('a.json: ik_constraints = 2.5 is not a bone (0..2)');
    expect(await bad([2, 1, 2])).toBe('a.json: ik_constraints[2] lists bone 2 a second time');
    expect(await bad([])).toBe('a.json: ik_constraints is empty: a rig needs an end effector');
    expect(await bad(['2'])).toBe('a.json: ik_constraints[0] is not a finite number');
  });

  it('reads a file that starts with a byte-order mark', () => {
    expect(parseA7Rig(`\ufeff${treeA7(three)}`, 'a.json').parents.length).toBe(3);
  });
});
