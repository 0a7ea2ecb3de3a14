import { describe, expect, it } from 'vitest';

import { parseA7Rig } from '../../web/src/rig/a7/a7_rig.js';
import { a7Names, loadA7, needsA7 } from '../helpers/a7.js';

const rest3x4 = '[[1,0,0,0],[0,1,0,0],[0,0,1,0]]';

describe('A7 JSON import', () => {
  it("reads the report's five rigs with their bones and end effectors", needsA7, () => {
    const counts = a7Names.map((n) => [loadA7(n).parents.length, loadA7(n).effectors.length]);
    expect(counts).toEqual([
      [5, 1],
      [7, 1],
      [19, 5],
      [21, 5],
      [22, 5],
    ]);
    expect(Array.from(loadA7('robot-arm').effectors)).toEqual([6]); // no ik_constraints
  });

  it('takes the last bone as end effector when ik_constraints is missing', () => {
    const spec = parseA7Rig(
      `{"bones":[{"parent_id":-1,"rest_T":${rest3x4}},{"parent_id":0,"rest_T":${rest3x4}}]}`,
      'x.json',
    );
    expect(Array.from(spec.effectors)).toEqual([1]);
  });

  it('reads 3x4 rest matrices, and missing limits as unbounded', () => {
    const spec = parseA7Rig(`{"bones":[{"parent_id":-1,"length":2,"rest_T":${rest3x4}}]}`, 'x.json');
    expect(Array.from(spec.rest.subarray(12))).toEqual([0, 0, 0, 1]);
    expect(Array.from(spec.lower)).toEqual([-Infinity, -Infinity, -Infinity]);
    expect(Array.from(spec.upper)).toEqual([Infinity, Infinity, Infinity]);
    expect(spec.lengths[0]).toBe(2);
  });

  it('names the file and field of each problem', () => {
    const bad = (text: string) => () => parseA7Rig(text, 'rig.json');
    expect(bad('{ nope')).toThrow(/^rig\.json: bad JSON/);
    expect(bad('{}')).toThrow('rig.json: no "bones" array');
    expect(bad(`{"bones":[{"rest_T":${rest3x4}}]}`)).toThrow('rig.json: bones[0].parent_id is missing');
    expect(bad(`{"bones":[{"parent_id":3,"rest_T":${rest3x4}}]}`)).toThrow('bones[0].parent_id 3 is not -1 or a bone');
    expect(bad(`{"bones":[{"parent_id":-1,"rest_T":[[1,0,0],[0,1,0,0],[0,0,1,0]]}]}`)).toThrow(
      'bones[0].rest_T row 0 must have 4 numbers',
    );
    expect(bad(`{"bones":[{"parent_id":-1,"length":"long","rest_T":${rest3x4}}]}`)).toThrow(
      'bones[0].length is not a finite number',
    );
    expect(bad(`{"bones":[{"parent_id":-1,"xzx_min":[0,0],"rest_T":${rest3x4}}]}`)).toThrow(
      'bones[0].xzx_min must be 3 numbers',
    );
    expect(bad(`{"ik_constraints":[0,4],"bones":[{"parent_id":-1,"rest_T":${rest3x4}}]}`)).toThrow(
      'ik_constraints[1] = 4 is not a bone',
    );
  });
});
