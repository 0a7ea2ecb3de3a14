// ik-web-avatar: a humanoid three.js character driven by its head and hands (AvatarIK).
export { AvatarIK } from './avatar_ik.js';
export type { AvatarBone, HumanoidSource } from './avatar_ik.js';
export type { AvatarSource, GltfParserLike } from './avatar_source.js';
