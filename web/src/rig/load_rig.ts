// One entry point for every rig format, shared by the page and Node (no DOM, no node:fs):
// .json = A7 course format, .glb / .gltf = glTF 2.0 skinned character, .urdf = a robot's serial
// chain (docs/urdf.md).
import type { RigSpec } from '../ik/rig_arrays.js';
import { parseA7Rig } from './a7/a7_rig.js';
import { RigFormatError } from './rig_format_error.js';
import type { SiblingReader } from './gltf/gltf_file.js';
import { importGltfRig, type GltfRigInfo } from './gltf/gltf_rig.js';
import { parseUrdfModel } from './urdf/urdf_model.js';
import { urdfRigSpec, type UrdfRigInfo } from './urdf/urdf_rig.js';

export type { GltfRigInfo, SiblingReader, UrdfRigInfo };
export { RigFormatError };

export type RigFormat = 'a7' | 'glb' | 'gltf' | 'urdf';

/** Choices for formats that hold more than one rig. */
export interface LoadRigOptions {
  /** URDF: the chain "BASE:TIP" (link names); default the longest serial chain (a warning says which). */
  chain?: string;
}

export interface LoadedRig {
  /** The rig for the solver: angles and limits in degrees, lengths in the file's units. */
  spec: RigSpec;
  /** The file's base name without directory or extension ("knight" for "models/knight.glb"). */
  name: string;
  format: RigFormat;
  /** For glTF: bone -> node mapping and rest matrices for the write-back. */
  gltf?: GltfRigInfo;
  /** For URDF: the chain taken and its joints, bone k moving joint k. */
  urdf?: UrdfRigInfo;
  /** Notes for the user (defaults applied...); empty for A7. */
  warnings: string[];
}

/**
 * The rig's spec with the file's own limits (extras.ik, else +-180 degrees) where the importer gave
 * a recognised humanoid anatomical ones (GltfRigInfo.fileLimits); otherwise the spec itself.
 */
export function specWithFileLimits(rig: LoadedRig): RigSpec {
  const own = rig.gltf?.fileLimits;
  return own ? { ...rig.spec, lower: own.lower, upper: own.upper } : rig.spec;
}

/** The file name without directory and extension. */
export function rigBaseName(fileName: string): string {
  const base = fileName.split(/[\\/]/).pop() ?? fileName;
  const dot = base.lastIndexOf('.');
  return dot > 0 ? base.slice(0, dot) : base;
}

const FORMAT_NAMES = { json: 'A7 rig', glb: 'glTF', gltf: 'glTF', urdf: 'URDF' } as const;

/**
 * Loads a rig from the bytes of a file. The format comes from `fileName`'s extension (.json, .glb,
 * .gltf, .urdf; case-insensitive). `readSibling` reads the side files (buffers) a .gltf refers to by
 * relative URI (a URDF needs none). `options.chain` picks a URDF's chain. Throws RigFormatError
 * naming the file and the problem; never returns a partial rig.
 */
export async function loadRig(
  bytes: Uint8Array,
  fileName: string,
  readSibling?: SiblingReader,
  options: LoadRigOptions = {},
): Promise<LoadedRig> {
  const name = rigBaseName(fileName);
  const ext = fileName.toLowerCase().match(/\.([a-z0-9]+)$/)?.[1];
  if (ext !== 'json' && ext !== 'glb' && ext !== 'gltf' && ext !== 'urdf')
    throw new RigFormatError(`${fileName}: unknown rig format (expected .json for A7, .glb, .gltf or .urdf)`);
  if (options.chain !== undefined && ext !== 'urdf')
    throw new RigFormatError(`${fileName}: a chain can only be chosen in a URDF file`);
  try {
    if (ext === 'json')
      return { spec: parseA7Rig(new TextDecoder().decode(bytes), fileName), name, format: 'a7', warnings: [] };
    if (ext === 'urdf') {
      const { spec, urdf } = urdfRigSpec(parseUrdfModel(bytes, fileName), fileName, options.chain);
      return { spec, name, format: 'urdf', urdf, warnings: urdf.warnings };
    }
    const { spec, gltf } = await importGltfRig(bytes, fileName, readSibling);
    return { spec, name, format: ext, gltf, warnings: gltf.warnings };
  } catch (e) {
    if (e instanceof RigFormatError) throw e;
    // Anything unforeseen still names the file rather than escaping as a bare TypeError.
    throw new RigFormatError(`${fileName}: cannot read the ${FORMAT_NAMES[ext]}: ${(e as Error).message}`);
  }
}
