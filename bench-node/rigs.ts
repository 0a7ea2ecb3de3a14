// Finding and reading the rigs named by --rig, and their default tolerances.
//
// A rig is a path to a .glb, .gltf, A7 .json or .urdf file (with --chain BASE:TIP, the chain the
// URDF importer takes), or a bare name (`knight`) meaning the
// project rig web/public/models/NAME.glb. Its display name is the file's base name.
//
// Default tolerances: web/src/rig/tolerances.ts (shared with the page) has the values and the
// rule: the report's own for its five A7 rigs; for any other rig the usual ones scaled with the
// square of the rig's size (the diagonal of the bounding box of every bone's tip at the rest
// pose) relative to 1 rig unit. The four smaller A7 rigs measure 0.74 (robot-arm) to 1.73
// (chimpanzee-hand) by that rule, hence the reference of 1; beast measures 345 and keeps the
// report's own values.
import { existsSync, realpathSync } from 'node:fs';
import { extname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

import type { RigSpec } from '#ik/rig_arrays.js';
import type { HumanoidMap } from '#rig/humanoid/humanoid_roles.js';
import { specWithFileLimits, type RigFormat } from '#rig/load_rig.js';
import { loadRigFromPath } from '#rig/load_rig_node.js';
import { BenchError, errorLine, quote } from './errors.js';

export const projectModelsDir = fileURLToPath(new URL('../web/public/models/', import.meta.url));

/** The project's rigs (web/public/models/NAME.glb), by base name. */
export const projectRigNames = ['knight', 'lamp', 'robot-arm', 'hand', 'beast', 'character'] as const;

export { REFERENCE_SIZE, rigSize } from '#rig/tolerances.js';

export interface BenchRig {
  /** The file's base name without extension: "knight". */
  name: string;
  path: string;
  format: RigFormat;
  spec: RigSpec;
  /** The humanoid mapping the importer recognised (glTF; `npm run rig` shows it), or null. */
  humanoid: HumanoidMap | null;
  /** glTF: the node index of each bone (GltfRigInfo.boneNodes); null for an A7 rig. */
  boneNodes: Int32Array | null;
  /** URDF: the chain the importer took, BASE:TIP (--chain, else its default); null for the other formats. */
  chain: string | null;
}

/** Resolves a --rig entry to a file path; throws BenchError naming the entry when it does not exist. */
export function resolveRigPath(entry: string): string {
  const bare = !entry.includes('/') && !entry.includes('\\') && extname(entry) === '';
  const path = bare ? resolve(projectModelsDir, `${entry}.glb`) : resolve(entry);
  if (!existsSync(path)) throw new BenchError(bare ? `${entry}: no project rig ${path}` : `${entry}: no such file`);
  return path;
}

/** Resolves every --rig entry (resolveRigPath); one file named twice is a usage error. */
export function resolveRigPaths(entries: readonly string[]): string[] {
  const seen = new Map<string, string>();
  return entries.map((entry) => {
    const path = resolveRigPath(entry);
    const file = realpathSync(path);
    const other = seen.get(file);
    if (other === entry) throw new BenchError(`--rig: ${quote(entry)} given twice`, 2);
    if (other !== undefined) throw new BenchError(`--rig: ${quote(other)} and ${quote(entry)} are the same file`, 2);
    seen.set(file, entry);
    return path;
  });
}

/**
 * Reads a rig file (A7 .json, .glb, .gltf or .urdf). `humanoidLimits` false: a recognised
 * humanoid keeps the file's own limits; `chain` (BASE:TIP, URDF only; --chain) the chain the URDF
 * importer takes. Throws BenchError with one line naming the entry on failure.
 */
export async function loadBenchRig(entry: string, humanoidLimits = true, chain?: string): Promise<BenchRig> {
  const path = resolveRigPath(entry);
  const ext = extname(path).toLowerCase();
  if (!['.json', '.glb', '.gltf', '.urdf'].includes(ext))
    throw new BenchError(`${entry}: unknown rig format "${ext}" (expected .glb, .gltf, A7 .json or .urdf)`);
  try {
    const loaded = await loadRigFromPath(path, chain === undefined ? {} : { chain });
    const spec = humanoidLimits ? loaded.spec : specWithFileLimits(loaded);
    const urdf = loaded.urdf;
    return {
      name: loaded.name,
      path,
      format: loaded.format,
      spec,
      humanoid: loaded.gltf?.humanoid ?? null,
      boneNodes: loaded.gltf?.boneNodes ?? null,
      chain: urdf ? `${urdf.base}:${urdf.tip}` : null,
    };
  } catch (e) {
    const message = errorLine(e);
    throw new BenchError(`${entry}: ${message.startsWith(`${path}: `) ? message.slice(path.length + 2) : message}`);
  }
}
