// A rig file read for showing: its spec for the IK session and, for glTF, a factory for the posed
// mesh. Parsing is web/src/rig/load_rig.ts; the mesh is three.js's GLTFLoader, posed by
// web/src/three/'s PoseWriter. This module only fetches bytes and joins the two.
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

import type { RigSpec } from '../ik/rig_spec.js';
import { followLimbEnds, limbEndFollowers } from '../rig/control_follow.js';
import type { RigLimits } from '../rig/humanoid_limits.js';
import type { HumanoidMap } from '../rig/humanoid_roles.js';
import { loadRig, specWithFileLimits, type GltfRigInfo, type SiblingReader } from '../rig/load_rig.js';
import { bonesFromGltf } from '../three/find_bones.js';
import { PoseWriter } from '../three/pose_writer.js';
import { disposeObject3D } from '../view/dispose_three.js';
import type { MeshBinding } from '../view/rig_view.js';
import { errorText } from './error_text.js';

/**
 * A rig file read and ready to show: its spec, names, and (for glTF) a factory for the posed mesh.
 * (web/src/rig/load_rig.ts's LoadedRig is the importer's result this is made from.)
 */
export interface RigSource {
  /** Display name (shown as text). */
  name: string;
  /** Format for display: "glb", "gltf" or "A7 JSON". */
  format: string;
  spec: RigSpec;
  /**
   * Anatomical limits (3 per bone, degrees) when the importer recognised a humanoid; the spec
   * keeps the file's own (extras.ik or +-180). The panel's "humanoid limits" switches between them.
   */
  humanoidLimits?: RigLimits;
  /** Which bone plays which humanoid role, when the importer recognised a humanoid (pole handles use its limbs). */
  humanoid?: HumanoidMap;
  /** Notes from the importer (defaults applied...), shown as text. */
  warnings: string[];
  /** Builds the skinned mesh bound to the rig; null for bones-only formats (A7) and too deep glTF trees. */
  makeMesh: (() => Promise<MeshBinding>) | null;
  /** The glTF file the rig was read from (the page writes posed copies of it); absent for A7 rigs. */
  gltf?: GltfSource;
}

/** A glTF rig's file as read: what web/src/three/pose_glb.ts needs to write it posed. */
export interface GltfSource {
  bytes: Uint8Array;
  fileName: string;
  info: GltfRigInfo;
  /** The importer's spec (the file's rest transforms). */
  spec: RigSpec;
  readSibling?: SiblingReader;
}

/** Reads the bytes of `url`; `what` names it in the error. */
export async function fetchBytes(url: string | URL, what: string): Promise<Uint8Array> {
  let res: Response;
  try {
    res = await fetch(url);
  } catch (e) {
    throw new Error(`${what}: could not fetch (${errorText(e)})`);
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
  const failed = (e: unknown): Error => new Error(`${fileName}: three.js cannot build the model: ${errorText(e)}`);
  const gltf = await loader.parseAsync(data, resourcePath).catch((e: unknown) => {
    throw failed(e);
  });
  if (!gltf.scene) throw failed(new Error('the file has no scene (glTF "scenes" is empty or missing)'));
  try {
    const writer = new PoseWriter(bonesFromGltf(gltf, info), spec, info);
    const followed = followLimbEnds(limbEndFollowers(spec.names, spec.parents)); // a foot control carries its leg's end's pose
    gltf.scene.traverse((o) => (o.frustumCulled = false)); // skinned bounds do not follow the pose
    return {
      object: gltf.scene,
      apply: (poses) => writer.write(followed(poses)),
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
 * Deepest glTF node tree whose model is built, levels. three.js's GLTFLoader walks the tree
 * recursively and runs out of stack near 2,000 levels; a deeper rig is shown as bones only.
 */
export const MAX_MODEL_TREE_DEPTH = 1000;

/**
 * Parses a rig file of any supported format. `resourcePath` is where a .gltf's relative files
 * live (for GLTFLoader). Throws an Error whose message names the file.
 */
export async function readRig(bytes: Uint8Array, fileName: string, readSibling?: SiblingReader, resourcePath = ''): Promise<RigSource> {
  const rig = await loadRig(bytes, fileName, readSibling);
  const info = rig.gltf;
  const tooDeep = info !== undefined && info.treeDepth > MAX_MODEL_TREE_DEPTH;
  return {
    name: rig.name,
    format: rig.format === 'a7' ? 'A7 JSON' : rig.format,
    spec: specWithFileLimits(rig),
    humanoidLimits: info?.fileLimits ? { lower: rig.spec.lower, upper: rig.spec.upper } : undefined,
    humanoid: info?.humanoid ?? undefined,
    warnings: tooDeep
      ? [...rig.warnings, `the node tree is ${info.treeDepth} levels deep, more than three.js's glTF loader takes (${MAX_MODEL_TREE_DEPTH}): showing the bones without the model`]
      : rig.warnings,
    makeMesh: info && !tooDeep ? () => gltfMesh(bytes, fileName, resourcePath, rig.spec, info) : null,
    gltf: info ? { bytes, fileName, info, spec: rig.spec, readSibling } : undefined,
  };
}

/** Loads a rig file from a URL (a .gltf's side files are fetched next to it). */
export async function loadRigUrl(url: URL, what = url.pathname.split('/').pop() ?? url.href): Promise<RigSource> {
  const bytes = await fetchBytes(url, what);
  const fileName = decodeURIComponent(url.pathname.split('/').pop() ?? what);
  const base = new URL('.', url).href;
  return readRig(bytes, fileName, (uri) => fetchBytes(new URL(uri, url), uri), base);
}
