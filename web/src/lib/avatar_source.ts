// What AvatarIK.attach() takes. These types are part of the package's public API, so this file
// names nothing but three.js and itself.
import type { Object3D } from 'three';

/** What a GLTFLoader result's parser gives: the file's JSON and the glTF node behind each object. */
export interface GltfParserLike {
  json: unknown;
  associations: Map<unknown, { nodes?: number } | undefined>;
}

/** A GLTFLoader result (`gltf`), or a loaded scene, group or SkinnedMesh. */
export type AvatarSource = Object3D | { scene: Object3D; parser?: GltfParserLike };
