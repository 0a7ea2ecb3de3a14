// Where rigs come from: the project models under web/public/models/, or a file the user drops
// or chooses. Parsing is web/src/rig/load_rig.ts; the mesh is three.js's GLTFLoader, posed by
// web/src/three/'s PoseWriter. This module only fetches bytes and joins the two.
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

import type { RigSpec } from '../ik/rig_spec.js';
import type { RigLimits } from '../rig/humanoid_limits.js';
import { loadRig, specWithFileLimits, type GltfRigInfo, type SiblingReader } from '../rig/load_rig.js';
import { bonesFromGltf } from '../three/find_bones.js';
import { PoseWriter } from '../three/pose_writer.js';
import { disposeObject3D } from './dispose_three.js';
import type { MeshBinding } from './rig_view.js';

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

/** A rig ready for a session: its spec, names, and (for glTF) a factory for the posed mesh. */
export interface LoadedRig {
  /** Display name (shown as text). */
  name: string;
  /** Format for display: "glb", "gltf" or "A7 JSON". */
  format: string;
  /** True for the A7 course format (bones only). */
  a7: boolean;
  spec: RigSpec;
  /**
   * Anatomical limits (3 per bone, degrees) when the importer recognised a humanoid; the spec
   * keeps the file's own (extras.ik or +-180). The panel's "humanoid limits" switches between them.
   */
  humanoidLimits?: RigLimits;
  /** Notes from the importer (defaults applied...), shown as text. */
  warnings: string[];
  /** Builds the skinned mesh bound to the rig; null for bones-only formats (A7) and too deep glTF trees. */
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

/**
 * The glTF scene of `bytes` through GLTFLoader, posed by a PoseWriter. The rig importer has checked
 * the file's structure; anything three.js still refuses is an Error naming the file.
 */
async function gltfMesh(bytes: Uint8Array, fileName: string, resourcePath: string, spec: RigSpec, info: GltfRigInfo): Promise<MeshBinding> {
  const loader = new GLTFLoader().setMeshoptDecoder(MeshoptDecoder);
  const data: ArrayBuffer | string = fileName.toLowerCase().endsWith('.gltf')
    ? new TextDecoder().decode(bytes)
    : (bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer);
  const failed = (e: unknown): Error => new Error(`${fileName}: three.js cannot build the model: ${e instanceof Error ? e.message : String(e)}`);
  const gltf = await loader.parseAsync(data, resourcePath).catch((e: unknown) => {
    throw failed(e);
  });
  if (!gltf.scene) throw failed(new Error('the file has no scene (glTF "scenes" is empty or missing)'));
  try {
    const writer = new PoseWriter(bonesFromGltf(gltf, info), spec, info);
    gltf.scene.traverse((o) => (o.frustumCulled = false)); // skinned bounds do not follow the pose
    return {
      object: gltf.scene,
      apply: (poses) => writer.write(poses),
      dispose: () => {
        writer.dispose();
        disposeObject3D(gltf.scene);
      },
    };
  } catch (e) {
    disposeObject3D(gltf.scene);
    throw failed(e);
  }
}

/**
 * Deepest glTF node tree whose model the page builds, levels. three.js's GLTFLoader walks the tree
 * recursively and runs out of stack near 2,000 levels; a deeper rig is shown as bones only.
 */
export const MAX_MODEL_TREE_DEPTH = 1000;

/**
 * Parses a rig file of any supported format. `resourcePath` is where a .gltf's relative files
 * live (for GLTFLoader). Throws an Error whose message names the file.
 */
export async function readRig(bytes: Uint8Array, fileName: string, readSibling?: SiblingReader, resourcePath = ''): Promise<LoadedRig> {
  const rig = await loadRig(bytes, fileName, readSibling);
  const info = rig.gltf;
  const tooDeep = info !== undefined && info.treeDepth > MAX_MODEL_TREE_DEPTH;
  return {
    name: rig.name,
    format: rig.format === 'a7' ? 'A7 JSON' : rig.format,
    a7: rig.format === 'a7',
    spec: specWithFileLimits(rig),
    humanoidLimits: info?.fileLimits ? { lower: rig.spec.lower, upper: rig.spec.upper } : undefined,
    warnings: tooDeep
      ? [...rig.warnings, `the node tree is ${info.treeDepth} levels deep, more than three.js's glTF loader takes (${MAX_MODEL_TREE_DEPTH}): showing the bones without the model`]
      : rig.warnings,
    makeMesh: info && !tooDeep ? () => gltfMesh(bytes, fileName, resourcePath, rig.spec, info) : null,
  };
}

/** Loads a rig file from a URL (a .gltf's side files are fetched next to it). */
export async function loadRigUrl(url: URL, what = url.pathname.split('/').pop() ?? url.href): Promise<LoadedRig> {
  const bytes = await fetchBytes(url, what);
  const fileName = decodeURIComponent(url.pathname.split('/').pop() ?? what);
  const base = new URL('.', url).href;
  return readRig(bytes, fileName, (uri) => fetchBytes(new URL(uri, url), uri), base);
}

/** Loads a project rig by key from the page's models folder, relative to `base`. */
export async function loadProjectRig(key: string, base: string | URL = document.baseURI): Promise<LoadedRig> {
  const entry = projectRig(key);
  if (!entry) throw new Error(`unknown project rig "${key}"`);
  return loadRigUrl(new URL(entry.file, base), entry.file);
}

/** Loads a user's file; a .gltf's side files cannot be reached and must be embedded. */
export async function loadUserFile(file: File): Promise<LoadedRig> {
  const bytes = new Uint8Array(await file.arrayBuffer());
  return readRig(bytes, file.name, async (uri) => {
    throw new Error(`${file.name} refers to "${uri}": choose a .glb, or a .gltf with embedded buffers`);
  });
}
