// Names from a URL or a file name never find an object's prototype: ?rig=constructor is an
// unknown rig (it used to fetch "<base>/undefined"), and an A7 file named constructor.json gets
// the usual tolerances. A glTF too deep for three.js's loader is shown as bones only; one without
// a scene has no model, and the error says so.
import { afterEach, describe, expect, it, vi } from 'vitest';

import { MAX_MODEL_TREE_DEPTH, readRig } from '../../web/src/view/rig_source.js';
import { loadProjectRig, PROJECT_RIGS, projectRig } from '../../web/src/page/project_rigs.js';
import { readUrlState } from '../../web/src/page/url_state.js';
import { defaultTolerances } from '../../web/src/rig/tolerances.js';
import { packGlb } from '../../scripts/rig_files/glb.js';
import { chainParents, treeGlb, treeGltf } from '../../scripts/rig_files/tree_rigs.js';

const PROTOTYPE_KEYS = ['constructor', '__proto__', 'toString', 'hasOwnProperty', 'valueOf'];

afterEach(() => vi.unstubAllGlobals());

describe('project rig names', () => {
  it('finds the project rigs and nothing else', () => {
    expect(projectRig('knight')?.file).toBe('models/knight.glb');
    for (const key of PROTOTYPE_KEYS) {
      expect(projectRig(key), key).toBeUndefined();
      expect(PROJECT_RIGS[key], key).toBeUndefined();
    }
  });

  it('treats ?rig=constructor as an unknown rig without fetching anything', async () => {
    const fetch = vi.fn();
    vi.stubGlobal('fetch', fetch);
    const { rig } = readUrlState({ search: '?rig=constructor' } as Location);
    expect(rig).toBe('constructor');
    expect(PROJECT_RIGS[rig!]).toBeUndefined(); // the page then loads its default rig
    await expect(loadProjectRig('constructor', 'http://example.test/')).rejects.toThrow(
      'unknown project rig "constructor"',
    );
    expect(fetch).not.toHaveBeenCalled();
  });

  it('gives an A7 rig named like a prototype key the usual tolerances', () => {
    for (const key of PROTOTYPE_KEYS)
      expect(defaultTolerances(key, true, 1), key).toEqual({ gradientTolerance: 1e-4, errorTolerance: 2e-4 });
  });
});

describe('glTF trees too deep for three.js', () => {
  it('are shown without the model, with a warning', async () => {
    const deep = await readRig(treeGlb(chainParents(MAX_MODEL_TREE_DEPTH + 1)), 'deep.glb');
    expect(deep.makeMesh).toBeNull();
    expect(deep.warnings.at(-1)).toBe(
      `the node tree is ${MAX_MODEL_TREE_DEPTH + 1} levels deep, more than three.js's glTF loader takes (${MAX_MODEL_TREE_DEPTH}): showing the bones without the model`,
    );
    const model = await (await readRig(treeGlb(chainParents(MAX_MODEL_TREE_DEPTH)), 'ok.glb')).makeMesh!();
    model.dispose();
  });

  it('a glTF without a scene has no model to show, said so naming the file', async () => {
    const json = treeGltf(chainParents(3));
    json.scenes = [];
    await expect((await readRig(packGlb(json), 'empty.glb')).makeMesh!()).rejects.toThrow(
      'empty.glb: three.js cannot build the model: the file has no scene (glTF "scenes" is empty or missing)',
    );
  });
});
