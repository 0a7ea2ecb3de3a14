// Where rigs come from: the project models under web/public/models/, or a file the user drops
// or chooses. Reading bytes and naming errors lives here; parsing is the importers' job.
import type { RigSpec } from '../ik/rig_spec.js';
import { parseA7Rig } from '../rig/a7_rig.js';
import type { MeshBinding } from './rig_view.js';

/** The project rigs, keyed as the URL names them (?rig=knight). */
export const PROJECT_RIGS: Record<string, { file: string; label: string }> = {
  lamp: { file: 'models/lamp.glb', label: 'lamp' },
  'robot-arm': { file: 'models/robot-arm.glb', label: 'robot arm' },
  knight: { file: 'models/knight.glb', label: 'knight' },
  hand: { file: 'models/hand.glb', label: 'hand' },
  beast: { file: 'models/beast.glb', label: 'beast' },
  character: { file: 'models/character.glb', label: 'character (60+ joints)' },
};

export const DEFAULT_RIG = 'lamp';

/** A rig ready for a session: its spec, names, and (for glTF) a factory for the posed mesh. */
export interface LoadedRig {
  /** Display name (shown as text). */
  name: string;
  format: string;
  spec: RigSpec;
  /** Builds the skinned mesh bound to the spec's angles; null for bones-only formats. */
  makeMesh: (() => Promise<MeshBinding>) | null;
}

/** Reads the bytes of `url`; `what` names it in the error. */
export async function fetchBytes(url: string | URL, what: string): Promise<Uint8Array> {
  let res: Response;
  try {
    res = await fetch(url);
  } catch (e) {
    throw new Error(`${what}: could not fetch (${e instanceof Error ? e.message : String(e)})`);
  }
  if (!res.ok) throw new Error(`${what}: HTTP ${res.status} ${res.statusText}`);
  return new Uint8Array(await res.arrayBuffer());
}

export type SiblingReader = (uri: string) => Promise<Uint8Array>;

/** Parses a rig file of any supported format. Throws an Error whose message names the file. */
export async function readRig(bytes: Uint8Array, fileName: string, readSibling?: SiblingReader): Promise<LoadedRig> {
  const lower = fileName.toLowerCase();
  if (lower.endsWith('.json')) {
    const spec = parseA7Rig(new TextDecoder().decode(bytes), fileName);
    return { name: fileName.replace(/\.json$/i, ''), format: 'A7 JSON', spec, makeMesh: null };
  }
  if (lower.endsWith('.glb') || lower.endsWith('.gltf')) {
    void readSibling;
    throw new Error(`${fileName}: the glTF importer (web/src/rig/load_rig.ts) is not available yet`);
  }
  throw new Error(`${fileName}: not a rig file (expected .glb, .gltf or an A7 .json)`);
}

/** Loads a project rig by key from the page's models folder, relative to `base`. */
export async function loadProjectRig(key: string, base: string | URL = document.baseURI): Promise<LoadedRig> {
  const entry = PROJECT_RIGS[key];
  if (!entry) throw new Error(`unknown project rig "${key}"`);
  const url = new URL(entry.file, base);
  const bytes = await fetchBytes(url, entry.file);
  return readRig(bytes, entry.file.split('/').pop() ?? entry.file, (uri) => fetchBytes(new URL(uri, url), uri));
}

/** Loads a user's file; a .gltf's side files cannot be reached and must be embedded. */
export async function loadUserFile(file: File): Promise<LoadedRig> {
  const bytes = new Uint8Array(await file.arrayBuffer());
  return readRig(bytes, file.name, async (uri) => {
    throw new Error(`${file.name} refers to "${uri}": choose a .glb or a .gltf with embedded buffers`);
  });
}
