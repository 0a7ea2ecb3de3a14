// The page's rigs: the project models under web/public/models/ (the rig menu and ?rig=), or a
// file the user drops or chooses. Reading a file is web/src/view/rig_source.ts.
import { loadRigUrl, readRig, type RigSource } from '../view/rig_source.js';
import { RigFormatError, type LoadRigOptions } from '../rig/load_rig.js';
import { MAX_RIG_FILE_BYTES } from '../rig/rig_limits.js';
import { findSibling, type PathFile } from './dropped_files.js';

export interface ProjectRig {
  /** Path relative to the page. */
  file: string;
  /** Name in the rig menu. */
  label: string;
}

/**
 * The project rigs, keyed as the URL names them (?rig=knight). The object has no prototype, so a
 * key from a URL such as "constructor" or "__proto__" finds nothing; projectRig() looks keys up.
 */
export const PROJECT_RIGS: Readonly<Record<string, ProjectRig>> = Object.freeze(
  Object.assign(Object.create(null) as Record<string, ProjectRig>, {
    lamp: { file: 'models/lamp.glb', label: 'lamp' },
    'robot-arm': { file: 'models/robot-arm.glb', label: 'robot arm' },
    knight: { file: 'models/knight.glb', label: 'knight' },
    hand: { file: 'models/hand.glb', label: 'hand' },
    beast: { file: 'models/beast.glb', label: 'beast' },
    character: { file: 'models/character.glb', label: 'character (60+ joints)' },
  }),
);

/** The project rig called `key` (a URL's ?rig= value), or undefined for any other string. */
export function projectRig(key: string): ProjectRig | undefined {
  return Object.hasOwn(PROJECT_RIGS, key) ? PROJECT_RIGS[key] : undefined;
}

export const DEFAULT_RIG = 'lamp';

/** The rig menu's value for "a file" (not a project rig). */
export const FILE_CHOICE = 'file';

/** The rig menu: label -> key for every project rig, then "(a file)" -> FILE_CHOICE. */
export function rigMenu(): Record<string, string> {
  const menu: Record<string, string> = {};
  for (const [key, r] of Object.entries(PROJECT_RIGS)) menu[r.label] = key;
  menu['(a file)'] = FILE_CHOICE;
  return menu;
}

/** Loads a project rig by key from the page's models folder, relative to `base`. */
export async function loadProjectRig(key: string, base: string | URL = document.baseURI): Promise<RigSource> {
  const entry = projectRig(key);
  if (!entry) throw new Error(`unknown project rig "${key}"`);
  return loadRigUrl(new URL(entry.file, base), entry.file);
}

/**
 * Loads a user's file; a URDF's meshes are taken from `others`, the files given with it
 * (dropped_files.ts findSibling); a .gltf's side files cannot be reached and must be embedded. A file over
 * MAX_RIG_FILE_BYTES is refused before it is read; the importer's caps (web/src/rig/gltf/gltf_budget.ts)
 * refuse the rest before three.js's GLTFLoader sees the file. `options.chain` picks a URDF's chain.
 * Throws an Error naming the file.
 */
export async function loadUserFile(
  file: File,
  options: LoadRigOptions = {},
  others: readonly PathFile[] = [],
): Promise<RigSource> {
  if (file.size > MAX_RIG_FILE_BYTES)
    throw new RigFormatError(
      `${file.name}: ${file.size} bytes, more than the ${MAX_RIG_FILE_BYTES} (512 MiB) a rig file may have`,
    );
  const bytes = new Uint8Array(await file.arrayBuffer());
  return readRig(
    bytes,
    file.name,
    async (uri) => {
      // A URDF's meshes come from the files given with it; a .gltf must embed what it refers to
      // (three.js's loader, which draws it, would fetch its files from the page's address).
      const sibling = /\.urdf$/i.test(file.name) ? findSibling(uri, others) : undefined;
      if (!sibling) throw new Error(`${file.name} refers to "${uri}": choose a .glb, or a .gltf with embedded buffers`);
      if (sibling.size > MAX_RIG_FILE_BYTES)
        throw new Error(
          `${sibling.name}: ${sibling.size} bytes, more than the ${MAX_RIG_FILE_BYTES} (512 MiB) a file beside a rig may have`,
        );
      return new Uint8Array(await sibling.arrayBuffer());
    },
    '',
    options,
  );
}
