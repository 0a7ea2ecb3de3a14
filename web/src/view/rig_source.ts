// A rig file read for showing: its spec for the IK session and, for glTF, a factory for the posed
// mesh; for URDF, the chain shown and the file's other chains. Parsing is web/src/rig/load_rig.ts;
// the mesh is three.js's GLTFLoader, posed by web/src/view/'s PoseWriter. This module only
// fetches bytes and joins the two.
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

import type { RigSpec } from '../ik/rig_arrays.js';
import { followLimbEnds, limbEndFollowers } from '../rig/humanoid/control_follow.js';
import type { RigLimits } from '../rig/humanoid/humanoid_limits.js';
import type { HumanoidMap } from '../rig/humanoid/humanoid_roles.js';
import {
  loadRig,
  specWithFileLimits,
  type GltfRigInfo,
  type LoadRigOptions,
  type SiblingReader,
} from '../rig/load_rig.js';
import { multiply } from '../rig/mat4.js';
import { urdfChains } from '../rig/urdf/urdf_chains.js';
import { parseUrdfModel, URDF_MESH_FORMATS } from '../rig/urdf/urdf_model.js';
import { urdfRigSpec } from '../rig/urdf/urdf_rig.js';
import { bonesFromGltf } from './find_bones.js';
import { PoseWriter } from './pose_writer.js';
import { disposeObject3D } from './dispose_three.js';
import type { MeshBinding } from './rig_view.js';
import { errorText } from '../live/error_text.js';

/**
 * A rig file read and ready to show: its spec, names, and (for glTF) a factory for the posed mesh.
 * (web/src/rig/load_rig.ts's LoadedRig is the importer's result this is made from.)
 */
export interface RigSource {
  /** Display name (shown as text). */
  name: string;
  /** Format for display: "glb", "gltf", "A7 JSON" or "URDF". */
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
  /** The URDF file the rig was read from: the chain shown and the file's chains (the panel's chain menu). */
  urdf?: UrdfSource;
}

/** A URDF rig's file as read: the chain taken, the others to choose from, and the bytes to read it again. */
export interface UrdfSource {
  bytes: Uint8Array;
  fileName: string;
  /** The chain shown, "BASE:TIP". */
  chain: string;
  /** The importer's default chain (the longest serial one), or null when the file has none it takes. */
  defaultChain: string | null;
  /** The file's maximal importable chains (urdf_chains.ts), the default first; `chain` is among them. */
  chains: string[];
  /** The file's revolute and continuous joints in `chain`, bone k moving joint k. */
  joints: string[];
  /** Reads the files beside it (its meshes), as it was read; absent: none. */
  readSibling?: SiblingReader;
}

/** A glTF rig's file as read: what web/src/view/pose_glb.ts needs to write it posed. */
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
    throw new Error(`${what}: could not fetch (${errorText(e)})`, { cause: e });
  }
  if (!res.ok) throw new Error(`${what}: HTTP ${res.status} ${res.statusText}`);
  return new Uint8Array(await res.arrayBuffer());
}

/**
 * The glTF scene of `bytes` through GLTFLoader, posed by a PoseWriter. The rig importer has checked
 * the file's structure; anything three.js still refuses is an Error naming the file.
 */
async function gltfMesh(
  bytes: Uint8Array,
  fileName: string,
  resourcePath: string,
  spec: RigSpec,
  info: GltfRigInfo,
): Promise<MeshBinding> {
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
 * URDF's up (+z, ROS REP 103) turned to the page's (+y, three.js): a quarter turn about x, row-major.
 * Turning every rest frame by it turns the whole rig (T_i = T_parent rest_i R rest_i^-1 becomes W T_i
 * W^-1): the same angles, the same limits, the tips and tip frames turned by W.
 */
const Z_UP_TO_Y_UP = Float64Array.of(1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1);

/** `spec` with every rest frame turned by Z_UP_TO_Y_UP. */
function yUp(spec: RigSpec): RigSpec {
  const rest = new Float64Array(spec.rest.length);
  for (let i = 0; i < rest.length; i += 16) rest.set(multiply(Z_UP_TO_Y_UP, spec.rest.subarray(i, i + 16)), i);
  return { ...spec, rest };
}

/** Most chains in the panel's chain menu (the PR2 has 18, Baxter 19). */
const MAX_LISTED_CHAINS = 100;

/**
 * A URDF file's chain `wanted` ("BASE:TIP"; undefined: the importer's default) as a rig, turned so
 * that the robot's +z is the page's up. A `wanted` chain naming a link the file does not have
 * (a ?chain= left from another file) gives the default chain and a warning; any other refusal of
 * the importer (a prismatic joint in the chain, a chain that is not serial) is thrown.
 */
async function readUrdf(
  bytes: Uint8Array,
  fileName: string,
  wanted: string | undefined,
  readSibling?: SiblingReader,
): Promise<RigSource> {
  const model = parseUrdfModel(bytes, fileName);
  const notes: string[] = [];
  if (wanted !== undefined) {
    const missing = wanted.split(':').filter((link) => !model.links.includes(link));
    if (missing.length > 0) {
      notes.push(
        `the chain ${wanted} is not in this file (no link ${missing.map((l) => `"${l}"`).join(', ')}): took the file's longest chain`,
      );
      wanted = undefined;
    }
  }
  const rig = await loadRig(bytes, fileName, undefined, { chain: wanted });
  const urdf = rig.urdf!;
  const chain = `${urdf.base}:${urdf.tip}`;
  let defaultChain: string | null = chain;
  if (wanted !== undefined) {
    try {
      const d = urdfRigSpec(model, fileName).urdf;
      defaultChain = `${d.base}:${d.tip}`;
    } catch {
      defaultChain = null;
    }
  }
  const listed = urdfChains(model, MAX_LISTED_CHAINS).chains.map((c) => c.chain);
  const chains = [...new Set([chain, ...(defaultChain ? [defaultChain] : []), ...listed])];
  if (defaultChain) chains.sort((a, b) => Number(b === defaultChain) - Number(a === defaultChain));
  const moving = `${urdf.joints.length} moving joint${urdf.joints.length === 1 ? '' : 's'}`;
  notes.unshift(
    chain === defaultChain
      ? `chain ${chain} (${moving}, the longest; choose another in the panel's chain menu or with ?chain=BASE:TIP)`
      : `chain ${chain} (${moving})`,
  );
  // The importer's notes on the chain (it names the command line's --chain) and on package://
  // meshes are said here for the page.
  notes.push(...rig.warnings.filter((w) => !w.startsWith('no chain given') && !w.includes('package://')));
  // The mesh files, where they sit beside the file (a folder dropped): read now, drawn by makeMesh.
  const names = [...new Set(model.meshes)];
  const files = new Map<string, Uint8Array>();
  if (readSibling)
    for (const name of names)
      await readSibling(name).then(
        (b) => files.set(name, b),
        () => undefined,
      );
  const lacking = names.length - files.size;
  if (files.size === 0 && names.length > 0)
    notes.push(
      `${names.length} mesh file${names.length === 1 ? ' is' : 's are'} not beside it (drop the robot's folder to see them): the chain's links show as bones`,
    );
  else if (lacking > 0)
    notes.push(`${lacking} of ${names.length} mesh files are not beside it: their links are not drawn`);
  const drawn = new Map([...files].filter(([name]) => URDF_MESH_FORMATS.test(name)));
  const unread = files.size - drawn.size;
  if (unread > 0)
    notes.push(`${unread} mesh file${unread === 1 ? ' is' : 's are'} neither STL nor Collada (.dae): not drawn`);
  const text = new TextDecoder().decode(bytes);
  const links = { base: urdf.base, joints: urdf.joints, toPage: Z_UP_TO_Y_UP };
  return {
    name: rig.name,
    format: 'URDF',
    spec: yUp(rig.spec),
    warnings: notes,
    // urdf-loader and its Collada reader load with the first robot drawn, not with the page.
    makeMesh:
      drawn.size > 0 ? async () => (await (await import('./urdf_mesh.js')).urdfMesh(text, links, drawn)).binding : null,
    urdf: { bytes, fileName, chain, defaultChain, chains, joints: urdf.joints, readSibling },
  };
}

/**
 * Parses a rig file of any supported format. `resourcePath` is where a .gltf's relative files
 * live (for GLTFLoader); `options.chain` picks a URDF's chain (readUrdf). Throws an Error whose
 * message names the file.
 */
export async function readRig(
  bytes: Uint8Array,
  fileName: string,
  readSibling?: SiblingReader,
  resourcePath = '',
  options: LoadRigOptions = {},
): Promise<RigSource> {
  if (/\.urdf$/i.test(fileName)) return readUrdf(bytes, fileName, options.chain, readSibling);
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
      ? [
          ...rig.warnings,
          `the node tree is ${info.treeDepth} levels deep, more than three.js's glTF loader takes (${MAX_MODEL_TREE_DEPTH}): showing the bones without the model`,
        ]
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
