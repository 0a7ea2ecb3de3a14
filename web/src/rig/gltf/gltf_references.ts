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
  const ref = (v: unknown, list: ListName, where: string): void => {
    if (v !== undefined) asIndex(v, lists[list].length, where, file);
  };
  const refs = (v: unknown, list: ListName, where: string): void => {
    if (v === undefined) return;
    if (!Array.isArray(v)) failIn(file, `${where} is not an array`);
    v.forEach((x, k) => ref(x, list, `${where}[${k}]`));
  };
  const object = (v: unknown, where: string): JsonObject | undefined =>
    v === undefined ? undefined : asObject(v, where, file);

  for (const key of LISTS)
    lists[key].forEach((o, i) => {
      if (o.name !== undefined && typeof o.name !== 'string') failIn(file, `${key}[${i}].name is not a string`);
    });
  ref(json.scene, 'scenes', 'scene');
  lists.scenes.forEach((s, i) => refs(s.nodes, 'nodes', `scenes[${i}].nodes`));
  lists.nodes.forEach((n, i) => {
    ref(n.mesh, 'meshes', `nodes[${i}].mesh`);
    ref(n.skin, 'skins', `nodes[${i}].skin`);
    ref(n.camera, 'cameras', `nodes[${i}].camera`);
  });
  lists.skins.forEach((s, i) => {
    ref(s.skeleton, 'nodes', `skins[${i}].skeleton`);
    ref(s.inverseBindMatrices, 'accessors', `skins[${i}].inverseBindMatrices`);
  });
  lists.meshes.forEach((m, i) => {
    const primitives = m.primitives;
    if (!Array.isArray(primitives) || primitives.length === 0)
      failIn(file, `meshes[${i}].primitives is missing or empty`);
    primitives.forEach((raw, j) => {
      const where = `meshes[${i}].primitives[${j}]`;
      const p = asObject(raw, where, file);
      for (const [name, v] of Object.entries(asObject(p.attributes, `${where}.attributes`, file)))
        ref(v, 'accessors', `${where}.attributes.${name}`);
      ref(p.indices, 'accessors', `${where}.indices`);
      ref(p.material, 'materials', `${where}.material`);
      asObjectList(p.targets, `${where}.targets`, file).forEach((t, k) => {
        for (const [name, v] of Object.entries(t)) ref(v, 'accessors', `${where}.targets[${k}].${name}`);
      });
    });
  });
  lists.materials.forEach((m, i) => {
    const where = `materials[${i}]`;
    const pbr = object(m.pbrMetallicRoughness, `${where}.pbrMetallicRoughness`);
    const slots: [unknown, string][] = [
      [pbr?.baseColorTexture, 'pbrMetallicRoughness.baseColorTexture'],
      [pbr?.metallicRoughnessTexture, 'pbrMetallicRoughness.metallicRoughnessTexture'],
      [m.normalTexture, 'normalTexture'],
      [m.occlusionTexture, 'occlusionTexture'],
      [m.emissiveTexture, 'emissiveTexture'],
    ];
    for (const [v, slot] of slots) {
      const info = object(v, `${where}.${slot}`);
      if (info) asIndex(info.index, lists.textures.length, `${where}.${slot}.index`, file);
    }
  });
  lists.textures.forEach((t, i) => {
    ref(t.source, 'images', `textures[${i}].source`);
    ref(t.sampler, 'samplers', `textures[${i}].sampler`);
  });
  lists.images.forEach((img, i) => {
    ref(img.bufferView, 'bufferViews', `images[${i}].bufferView`);
    if (img.uri !== undefined && typeof img.uri !== 'string') failIn(file, `images[${i}].uri is not a string`);
  });
  lists.animations.forEach((a, i) => {
    const where = `animations[${i}]`;
    const samplers = asObjectList(a.samplers, `${where}.samplers`, file);
    samplers.forEach((s, k) => {
      asIndex(s.input, lists.accessors.length, `${where}.samplers[${k}].input`, file);
      asIndex(s.output, lists.accessors.length, `${where}.samplers[${k}].output`, file);
    });
    asObjectList(a.channels, `${where}.channels`, file).forEach((c, k) => {
      asIndex(c.sampler, samplers.length, `${where}.channels[${k}].sampler`, file);
      ref(
        asObject(c.target, `${where}.channels[${k}].target`, file).node,
        'nodes',
        `${where}.channels[${k}].target.node`,
      );
    });
  });
  lists.accessors.forEach((a, i) => ref(a.bufferView, 'bufferViews', `accessors[${i}].bufferView`));
  lists.bufferViews.forEach((v, i) => asIndex(v.buffer, lists.buffers.length, `bufferViews[${i}].buffer`, file));
}
