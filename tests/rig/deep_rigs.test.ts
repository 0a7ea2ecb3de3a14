// Big and deep rigs load in linear time without recursion: a 10,000-deep chain (glTF and A7), a
// cycle through 10,000 nodes. A rig with more leaves than end effectors the core takes keeps the
// deepest as defaults; more bones or listed end effectors than the core takes, and JSON nested or
// sized past its budget, are refused before anything big is built.
import { describe, expect, it } from 'vitest';

import { deepestBones } from '../../web/src/rig/gltf/effector_defaults.js';
import {
  jsonBudgetProblem,
  MAX_JSON_CONTAINERS,
  MAX_JSON_DEPTH,
  MAX_JSON_VALUES,
} from '../../web/src/rig/json_budget.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { effectorCountProblem, MAX_BONES, MAX_EFFECTORS, maxEffectors } from '../../web/src/rig/rig_limits.js';
import { packGlb } from '../../scripts/rig_files/glb.js';
import { chainParents, treeA7, treeGlb, treeGltf } from '../../scripts/rig_files/tree_rigs.js';
import { loadError } from './synthetic_rigs.js';

const N = 10_000;
const text = (s: string): Uint8Array => new TextEncoder().encode(s);

describe('deep and big rigs', () => {
  it('loads a 10,000-deep glTF chain', async () => {
    const rig = await loadRig(treeGlb(chainParents(N)), 'chain.glb');
    expect(rig.spec.parents.length).toBe(N);
    expect(Array.from(rig.spec.parents.subarray(0, 3))).toEqual([-1, 0, 1]);
    expect(rig.spec.parents[N - 1]).toBe(N - 2);
    expect(Array.from(rig.spec.effectors)).toEqual([N - 1]);
    expect(rig.gltf?.treeDepth).toBe(N);
  });

  it('loads a 10,000-bone A7 chain', async () => {
    const rig = await loadRig(text(treeA7(chainParents(N))), 'chain.json');
    expect(rig.spec.parents.length).toBe(N);
    expect(rig.spec.parents[N - 1]).toBe(N - 2);
    expect(Array.from(rig.spec.effectors)).toEqual([N - 1]);
  });

  it('reports a cycle through 10,000 nodes, shortened', async () => {
    const json = treeGltf(chainParents(N));
    json.nodes[N - 1].children = [0];
    const message = await loadError(packGlb(json), 'ring.glb');
    expect(message).toMatch(
      /^ring\.glb: node hierarchy has a cycle: node 0 "link 0" -> node 1 "link 1" -> .* -> node 7 "link 7" -> \.\.\. \(9992 more\) -> node 0 "link 0"$/,
    );
  });

  it('reports a cycle of A7 parents', async () => {
    const parents = chainParents(N);
    parents[0] = N - 1;
    expect(await loadError(treeA7(parents), 'ring.json')).toMatch(
      /^ring\.json: the bones' parent_id form a cycle: bones\[0\] -> bones\[1\] -> .* -> \.\.\. \(9992 more\) -> bones\[0\]$/,
    );
  });

  it('keeps the deepest leaves as default end effectors when every leaf would be too many', async () => {
    // A root with 100 children, the last 10 of which have a child of their own: 100 leaves.
    const parents = [-1, ...Array.from({ length: 100 }, () => 0), ...Array.from({ length: 10 }, (_, k) => 91 + k)];
    const rig = await loadRig(treeGlb(parents), 'wide.glb');
    const effectorNodes = Array.from(rig.spec.effectors, (b) => rig.gltf!.boneNodes[b]).sort((a, b) => a - b);
    // The 10 grandchildren (deepest), then the first 54 leaf children.
    expect(effectorNodes).toEqual([
      ...Array.from({ length: 54 }, (_, k) => 1 + k),
      ...Array.from({ length: 10 }, (_, k) => 101 + k),
    ]);
    expect(rig.warnings[0]).toMatch(
      /end effectors are the 64 leaf joints furthest from the root, of 100 \(the most this rig may have\) \(link 1, link 2, .*, link 12 and 52 more\)$/,
    );
  });

  it('picks the deepest bones in linear time, ties by index', () => {
    const depth = [0, 1, 3, 2, 3, 3];
    expect(deepestBones([1, 2, 3, 4, 5], depth, 2)).toEqual([2, 4]);
    expect(deepestBones([1, 3], depth, 2)).toEqual([1, 3]);
  });

  it('caps the end effectors by the Jacobian size on a big rig', () => {
    expect(maxEffectors(10)).toBe(MAX_EFFECTORS);
    expect(maxEffectors(N)).toBe(11); // 9 * 11 * 10,000 entries <= 2^20
    expect(effectorCountProblem(12, N)).toBe(
      '12 end effectors on 10000 bones make a 36 x 30000 Jacobian (1080000 entries; at most 1048576): at most 11 end effectors on this rig',
    );
    expect(effectorCountProblem(65, 10)).toBe('65 end effectors; at most 64');
    expect(effectorCountProblem(11, N)).toBeUndefined();
  });

  it('refuses JSON nested too deep or holding too many values before parsing it', async () => {
    const deep = `{"bones": ${'['.repeat(10_000)}${']'.repeat(10_000)}}`;
    expect(await loadError(deep, 'deep.json')).toBe(
      `deep.json: the JSON nests deeper than ${MAX_JSON_DEPTH} levels (at character 73)`,
    );
    expect(await loadError(deep.replace('"bones"', '"asset": {"version": "2.0"}, "nodes"'), 'deep.gltf')).toMatch(
      /^deep\.gltf: the JSON nests deeper than 64 levels/,
    );
    expect(jsonBudgetProblem(`[${'0,'.repeat(MAX_JSON_VALUES)}0]`)).toBe(
      `the JSON holds more than ${MAX_JSON_VALUES} values`,
    );
    expect(jsonBudgetProblem(`[${'[],'.repeat(MAX_JSON_CONTAINERS)}0]`)).toBe(
      `the JSON holds more than ${MAX_JSON_CONTAINERS} arrays and objects`,
    );
    expect(jsonBudgetProblem('{"a": "[[[[,,,,"}')).toBeUndefined(); // brackets and commas in strings do not count
  });

  it('refuses more bones than the core takes, naming the count', async () => {
    const many = MAX_BONES + 1;
    const joints = Array.from({ length: many }, (_, i) => i);
    const glb = packGlb({ asset: { version: '2.0' }, nodes: joints.map(() => ({})), skins: [{ joints }] });
    expect(await loadError(glb, 'huge.glb')).toBe(`huge.glb: ${many} joints; at most ${MAX_BONES} bones`);
    const a7 = JSON.stringify({ bones: joints.map(() => ({})) });
    expect(await loadError(a7, 'huge.json')).toBe(`huge.json: ${many} bones; at most ${MAX_BONES}`);
  });

  it('refuses more end effectors than the core takes', async () => {
    const parents = [-1, ...Array.from({ length: 100 }, () => 0)];
    expect(await loadError(treeA7(parents, {}, { ik_constraints: parents.map((_, i) => i) }), 'many.json')).toBe(
      'many.json: ik_constraints lists 101 end effectors; at most 64',
    );
    const json = treeGltf(parents);
    json.nodes.forEach((n) => (n.extras = { ik: { effector: true } }));
    expect(await loadError(packGlb(json), 'many.glb')).toBe(
      'many.glb: too many end effectors flagged in extras.ik: 101 end effectors; at most 64',
    );
  });
});
