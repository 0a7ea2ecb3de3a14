// The references between the parts of a glTF document, checked in one linear pass before anything
// follows them, so that neither the rig importer nor three.js's GLTFLoader (which builds the page's
// mesh from the same bytes) meets a dangling index, a null where an object belongs or a name that
// is no string. Byte ranges are gltf_ranges.ts; the node tree and skins are gltf_nodes.ts.
import { failIn } from '../rig_format_error.js';
import { asIndex, asObject, asObjectList, type JsonObject } from './gltf_json.js';

const LISTS = [
  'accessors',
  'animations',
  'buffers',
  'bufferViews',
  'cameras',
  'images',
  'materials',
  'meshes',
  'nodes',
  'samplers',
  'scenes',
  'skins',
  'textures',
] as const;

type ListName = (typeof LISTS)[number];

/** The top-level lists of a glTF document, each checked to be a list of objects (missing = empty). */
export type GltfLists = Record<ListName, JsonObject[]>;

/** The top-level lists of `json`. Throws RigFormatError for a list that is not a list of objects. */
export function readLists(json: JsonObject, file: string): GltfLists {
  const lists = {} as GltfLists;
  for (const key of LISTS) lists[key] = asObjectList(json[key], key, file);
  return lists;
}

/**
 * Checks every name and every index a glTF document holds outside the node tree and the skins'
 * joints: scenes, node meshes, skins and cameras, mesh primitives, materials' textures, textures,
 * images, animations, accessors' and buffer views' targets. Throws RigFormatError naming the field.
 */
export function checkReferences(json: JsonObject, lists: GltfLists, file: string): void {
  const ref = refChecker(lists, file);
  checkNames(lists, file);
  ref(json.scene, 'scenes', 'scene');
  lists.scenes.forEach((s, i) => checkRefList(s.nodes, 'nodes', `scenes[${i}].nodes`, ref, file));
  checkNodesAndSkins(lists, ref);
  lists.meshes.forEach((m, i) => checkPrimitives(m, `meshes[${i}]`, ref, file));
  lists.materials.forEach((m, i) => checkMaterialTextures(m, `materials[${i}]`, lists.textures.length, file));
  checkTexturesAndImages(lists, ref, file);
  lists.animations.forEach((a, i) => checkAnimation(a, `animations[${i}]`, lists.accessors.length, ref, file));
  lists.accessors.forEach((a, i) => ref(a.bufferView, 'bufferViews', `accessors[${i}].bufferView`));
  lists.bufferViews.forEach((v, i) => asIndex(v.buffer, lists.buffers.length, `bufferViews[${i}].buffer`, file));
}

/** Checks that `v`, where given, is an index into the list `list`; throws RigFormatError naming `where`. */
type RefCheck = (v: unknown, list: ListName, where: string) => void;

/** The RefCheck for the lists `lists` of a document read from `file`. */
function refChecker(lists: GltfLists, file: string): RefCheck {
  return (v, list, where) => {
    if (v !== undefined) asIndex(v, lists[list].length, where, file);
  };
}

/** Checks that `v`, where given, is an array of indices into `list` (`ref` checks each). */
function checkRefList(v: unknown, list: ListName, where: string, ref: RefCheck, file: string): void {
  if (v === undefined) return;
  if (!Array.isArray(v)) failIn(file, `${where} is not an array`);
  v.forEach((x, k) => ref(x, list, `${where}[${k}]`));
}

/** Checks that every object of every list has a string for a name, or none. */
function checkNames(lists: GltfLists, file: string): void {
  for (const key of LISTS)
    lists[key].forEach((o, i) => {
      if (o.name !== undefined && typeof o.name !== 'string') failIn(file, `${key}[${i}].name is not a string`);
    });
}

/** Checks the nodes' meshes, skins and cameras, then the skins' skeletons and inverse bind matrices. */
function checkNodesAndSkins(lists: GltfLists, ref: RefCheck): void {
  lists.nodes.forEach((n, i) => {
    ref(n.mesh, 'meshes', `nodes[${i}].mesh`);
    ref(n.skin, 'skins', `nodes[${i}].skin`);
    ref(n.camera, 'cameras', `nodes[${i}].camera`);
  });
  lists.skins.forEach((s, i) => {
    ref(s.skeleton, 'nodes', `skins[${i}].skeleton`);
    ref(s.inverseBindMatrices, 'accessors', `skins[${i}].inverseBindMatrices`);
  });
}

/** Checks that mesh `m` (`where` names it) has primitives, and their attributes', indices', material's and targets' indices. */
function checkPrimitives(m: JsonObject, where: string, ref: RefCheck, file: string): void {
  const primitives = m.primitives;
  if (!Array.isArray(primitives) || primitives.length === 0) failIn(file, `${where}.primitives is missing or empty`);
  primitives.forEach((raw, j) => {
    const at = `${where}.primitives[${j}]`;
    const p = asObject(raw, at, file);
    for (const [name, v] of Object.entries(asObject(p.attributes, `${at}.attributes`, file)))
      ref(v, 'accessors', `${at}.attributes.${name}`);
    ref(p.indices, 'accessors', `${at}.indices`);
    ref(p.material, 'materials', `${at}.material`);
    asObjectList(p.targets, `${at}.targets`, file).forEach((t, k) => {
      for (const [name, v] of Object.entries(t)) ref(v, 'accessors', `${at}.targets[${k}].${name}`);
    });
  });
}

/** `v` as a JSON object, or undefined when not given; throws RigFormatError naming `where` for anything else. */
function optionalObject(v: unknown, where: string, file: string): JsonObject | undefined {
  return v === undefined ? undefined : asObject(v, where, file);
}

/**
 * Checks that the texture slots of material `m` (`where` names it), where given, are objects
 * whose index is one of the document's `textureCount` textures.
 */
function checkMaterialTextures(m: JsonObject, where: string, textureCount: number, file: string): void {
  const pbr = optionalObject(m.pbrMetallicRoughness, `${where}.pbrMetallicRoughness`, file);
  const slots: [unknown, string][] = [
    [pbr?.baseColorTexture, 'pbrMetallicRoughness.baseColorTexture'],
    [pbr?.metallicRoughnessTexture, 'pbrMetallicRoughness.metallicRoughnessTexture'],
    [m.normalTexture, 'normalTexture'],
    [m.occlusionTexture, 'occlusionTexture'],
    [m.emissiveTexture, 'emissiveTexture'],
  ];
  for (const [v, slot] of slots) {
    const info = optionalObject(v, `${where}.${slot}`, file);
    if (info) asIndex(info.index, textureCount, `${where}.${slot}.index`, file);
  }
}

/** Checks the textures' images and samplers, then the images' buffer views and uris. */
function checkTexturesAndImages(lists: GltfLists, ref: RefCheck, file: string): void {
  lists.textures.forEach((t, i) => {
    ref(t.source, 'images', `textures[${i}].source`);
    ref(t.sampler, 'samplers', `textures[${i}].sampler`);
  });
  lists.images.forEach((img, i) => {
    ref(img.bufferView, 'bufferViews', `images[${i}].bufferView`);
    if (img.uri !== undefined && typeof img.uri !== 'string') failIn(file, `images[${i}].uri is not a string`);
  });
}

/**
 * Checks animation `a` (`where` names it): its samplers' input and output accessors (indices
 * below `accessorCount`), then its channels' samplers and target nodes.
 */
function checkAnimation(a: JsonObject, where: string, accessorCount: number, ref: RefCheck, file: string): void {
  const samplers = asObjectList(a.samplers, `${where}.samplers`, file);
  samplers.forEach((s, k) => {
    asIndex(s.input, accessorCount, `${where}.samplers[${k}].input`, file);
    asIndex(s.output, accessorCount, `${where}.samplers[${k}].output`, file);
  });
  asObjectList(a.channels, `${where}.channels`, file).forEach((c, k) => {
    const at = `${where}.channels[${k}]`;
    asIndex(c.sampler, samplers.length, `${at}.sampler`, file);
    ref(asObject(c.target, `${at}.target`, file).node, 'nodes', `${at}.target.node`);
  });
}
