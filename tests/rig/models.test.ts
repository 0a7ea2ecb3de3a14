// The project's own rigs in web/public/models/: reproducible from the generator, valid glTF,
// shaped like the report's five rigs plus a large character, and loadable in Node.
import { readdirSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { validateBytes } from 'gltf-validator';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { buildModels, modelsDir } from '../../scripts/generate-models.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';

let ik: IkCoreModule;
let generated: Map<string, Uint8Array>;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
  generated = await buildModels();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

const read = (name: string): Uint8Array => new Uint8Array(readFileSync(resolve(modelsDir, name)));

describe('project rigs', () => {
  it('the committed files are exactly what scripts/generate-models.ts makes (npm run models)', () => {
    expect([...generated.keys()]).toEqual([
      'lamp.glb',
      'robot-arm.glb',
      'knight.glb',
      'hand.glb',
      'beast.glb',
      'character.glb',
    ]);
    for (const [name, bytes] of generated) {
      expect(
        Buffer.from(read(name)).equals(Buffer.from(bytes)),
        `${name} differs from the generator's output: run npm run models`,
      ).toBe(true);
      // The character carries its animation clips (scripts/models/character_clips.ts): four of 6 s
      // with every frame at 30 fps (100 KB), then turn_in_place (7 s) and stress (21 s) with only the
      // frames interpolation cannot rebuild within 0.01 degrees (78 KB; their steps and big, fast
      // moves need most frames even at 0.1 degrees, 54 KB, where planted feet slide 3 mm).
      expect(bytes.byteLength, name).toBeLessThan((name === 'character.glb' ? 240 : 64) * 1024);
    }
  });

  it('pass the Khronos glTF validator without errors or warnings', async () => {
    for (const name of generated.keys()) {
      const report = await validateBytes(read(name));
      const issues = report.issues.messages.map(
        (m: { code: string; pointer?: string }) => `${m.code} ${m.pointer ?? ''}`,
      );
      expect(report.issues.numErrors, `${name}: ${issues.join(', ')}`).toBe(0);
      expect(report.issues.numWarnings, `${name}: ${issues.join(', ')}`).toBe(0);
    }
  });

  it.each([
    ['lamp', 5, 1, 4],
    ['robot-arm', 7, 1, 5],
    ['knight', 19, 5, undefined],
    ['hand', 21, 5, undefined],
    ['beast', 22, 5, undefined],
  ] as const)(
    '%s.glb has %i bones and %i end effectors like the report rig',
    async (name, bones, effectors, freeAngles) => {
      const { spec, warnings } = await loadRigFromPath(resolve(modelsDir, `${name}.glb`));
      expect(spec.parents.length).toBe(bones);
      expect(spec.effectors.length).toBe(effectors);
      if (freeAngles !== undefined)
        expect(Array.from(spec.lower).filter((v, i) => v !== spec.upper[i]).length).toBe(freeAngles);
      // Every joint carries IK extras; the knight's Blender names are recognised as a humanoid.
      expect(warnings).toEqual(name === 'knight' ? ['humanoid (rigify): 14 of 14 core roles'] : []);
    },
  );

  it('character.glb has 60+ joints with Mixamo names, and its hands, feet and head as end effectors', async () => {
    const { spec } = await loadRigFromPath(resolve(modelsDir, 'character.glb'));
    expect(spec.parents.length).toBeGreaterThanOrEqual(60);
    expect(spec.names.every((n) => n.startsWith('mixamorig:'))).toBe(true);
    expect(Array.from(spec.effectors, (b) => spec.names[b])).toEqual(
      ['Head', 'LeftHand', 'RightHand', 'LeftFoot', 'RightFoot'].map((n) => `mixamorig:${n}`),
    );
  });

  it('every file in web/public/models/ loads in Node and builds a WebAssembly rig', async () => {
    const files = readdirSync(modelsDir).filter((f) => /\.(glb|gltf|json)$/i.test(f));
    expect(files.length).toBeGreaterThanOrEqual(6);
    for (const f of files) {
      const loaded = await loadRigFromPath(resolve(modelsDir, f));
      const rig = new IkRig(ik, loaded.spec);
      rigs.push(rig);
      expect(rig.tips(new Float64Array(rig.numAngles)).every(Number.isFinite), f).toBe(true);
    }
  });
});
