// Several files at once (web/src/page/dropped_files.ts): the rig file picked among them, and the
// files a rig file names found by the tail of their path.
import { describe, expect, it } from 'vitest';

import { findSibling, type PathFile, pickRigFile } from '../../web/src/page/dropped_files.js';

const at = (path: string): PathFile => ({ path, file: new File(['x'], path.split('/').pop()!) });

describe('the rig file among several', () => {
  it('takes a .urdf before a .glb, .gltf or .json, and leaves the others beside it', () => {
    const files = [
      at('robot/meshes/base.stl'),
      at('robot/config.json'),
      at('robot/urdf/robot.urdf'),
      at('robot/model.glb'),
    ];
    const { rig, others } = pickRigFile(files);
    expect(rig?.path).toBe('robot/urdf/robot.urdf');
    expect(others.map((f) => f.path)).toEqual(['robot/meshes/base.stl', 'robot/config.json', 'robot/model.glb']);
    expect(pickRigFile([at('a.stl'), at('b.glb')]).rig?.path).toBe('b.glb');
    expect(pickRigFile([at('a.stl')]).rig).toBeUndefined();
  });
});

describe('a file named by the rig', () => {
  const others = [
    at('panda/meshes/visual/link0.dae'),
    at('panda/meshes/collision/link0.stl'),
    at('other/link0.dae'),
    at('link7.stl'),
    at('my arm/hand part.stl'),
  ];

  it('matches the longest tail of a package:// or relative path', () => {
    expect(findSibling('package://franka_description/meshes/visual/link0.dae', others)).toBe(others[0].file);
    expect(findSibling('package://franka_description/meshes/collision/link0.stl', others)).toBe(others[1].file);
    expect(findSibling('../meshes/visual/link0.dae', others)).toBe(others[0].file);
    expect(findSibling('package://x/meshes/link7.stl', others)).toBe(others[3].file);
    expect(findSibling('hand%20part.stl', others)).toBe(others[4].file);
  });

  it('finds nothing for a name no file ends with', () => {
    expect(findSibling('package://x/meshes/link8.stl', others)).toBeUndefined();
    expect(findSibling('package://', others)).toBeUndefined();
    expect(findSibling('k0.dae', others)).toBeUndefined(); // a tail is whole path segments
  });
});
