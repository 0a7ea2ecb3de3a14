// The project's character as the track experiment takes it (bench-node/track.ts TrackRig: its
// file, spec, humanoid map and glTF nodes, loaded as the bench loads it), and an avatar of it.
import { resolve } from 'node:path';

import { afterAll, beforeAll } from 'vitest';

import { loadBenchRig } from '../../bench-node/rigs.js';
import type { TrackRig } from '../../bench-node/track.js';
import { AvatarSolver } from '../../web/src/avatar/avatar_solver.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';

/** web/public/models/character.glb as a TrackRig. */
export async function loadCharacterTrackRig(): Promise<TrackRig> {
  const loaded = await loadBenchRig(resolve(import.meta.dirname, '../../web/public/models/character.glb'));
  return {
    name: loaded.name,
    path: loaded.path,
    spec: loaded.spec,
    humanoid: loaded.humanoid!,
    boneNodes: loaded.boneNodes!,
  };
}

/** The WebAssembly, the character and an AvatarSolver of it, made before a file's tests (the fields are set then) and disposed after. */
export function useCharacterAvatar(): { ik: IkCoreModule; rig: TrackRig; avatar: AvatarSolver } {
  const made = {} as { ik: IkCoreModule; rig: TrackRig; avatar: AvatarSolver };
  beforeAll(async () => {
    made.ik = await loadIkNode();
    made.rig = await loadCharacterTrackRig();
    made.avatar = new AvatarSolver(made.ik, made.rig.spec, made.rig.humanoid);
  });
  afterAll(() => made.avatar?.dispose());
  return made;
}
