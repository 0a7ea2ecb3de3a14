// Run by tests/browser/package.test.ts in a folder where the packed ik-web-avatar and three are
// installed, as an app uses the package in Node: GLTFLoader parses the character (argument: the
// .glb) twice, both copies standing moved, turned and scaled in the world. AvatarIK attaches to
// one; the other takes a pose over 30 frames (arms lowered 40 degrees, elbows bent 30, the spine
// bent 10), and each frame its head's and hands' world poses are the targets, as a tracker would
// give them; then 10 frames more. Prints one JSON line: the height, how far each hand's target
// moved and how far each tracked bone ended from its target (world units), whether the last
// update() was on target, the humanoid's source, and after dispose() how far the hand bones are
// from where they stood at attach time and what update() throws.
import { readFile } from 'node:fs/promises';

import { Quaternion, Vector3 } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { AvatarIK } from 'ik-web-avatar';

const bytes = await readFile(process.argv[2]);
async function placedCopy() {
  const gltf = await new GLTFLoader().parseAsync(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), '');
  gltf.scene.position.set(1.5, 0.2, -2);
  gltf.scene.rotation.y = 0.7;
  gltf.scene.scale.setScalar(1.4);
  gltf.scene.updateMatrixWorld(true);
  return gltf;
}
const gltf = await placedCopy();
const mover = await placedCopy();

const avatar = await AvatarIK.attach(gltf);
const worldOf = (o) => o.getWorldPosition(new Vector3());
const restHands = [worldOf(avatar.bones.leftHand), worldOf(avatar.bones.rightHand)];
const startTargets = [worldOf(avatar.leftHand), worldOf(avatar.rightHand)];

// The mover's turns: bone name (as GLTFLoader names it), world axis, degrees at the end.
const forward = new Vector3(0, 0, 1).applyQuaternion(mover.scene.quaternion);
const side = new Vector3(1, 0, 0).applyQuaternion(mover.scene.quaternion);
const up = new Vector3(0, 1, 0);
const turns = [
  ['mixamorigSpine1', side, 10],
  ['mixamorigLeftArm', forward, -40],
  ['mixamorigRightArm', forward, 40],
  ['mixamorigLeftForeArm', up, -30],
  ['mixamorigRightForeArm', up, 30],
].map(([name, axis, degrees]) => {
  const bone = mover.scene.getObjectByName(name);
  if (!bone) throw new Error(`no bone ${name} in the character`);
  return { bone, axis, degrees, rest: bone.quaternion.clone() };
});
const parentTurn = new Quaternion(), turn = new Quaternion(), scale = new Vector3();

let onTarget = false;
for (let f = 1; f <= 40; f++) {
  const share = Math.min(1, f / 30);
  // Each bone turned about a world axis: local = parent⁻¹ turn parent rest.
  for (const { bone, axis, degrees, rest } of turns) {
    bone.parent.getWorldQuaternion(parentTurn);
    turn.setFromAxisAngle(axis, (degrees * share * Math.PI) / 180);
    bone.quaternion.copy(rest).premultiply(parentTurn.clone().invert().multiply(turn).multiply(parentTurn));
    bone.updateMatrixWorld(true);
  }
  for (const role of ['head', 'leftHand', 'rightHand']) {
    const tracked = mover.scene.getObjectByName(avatar.bones[role].name);
    tracked.matrixWorld.decompose(avatar[role].position, avatar[role].quaternion, scale);
  }
  onTarget = avatar.update();
}

const miss = (role) => worldOf(avatar.bones[role]).distanceTo(worldOf(avatar[role]));
const result = {
  height: avatar.height,
  humanoid: avatar.humanoid,
  moved: [worldOf(avatar.leftHand).distanceTo(startTargets[0]), worldOf(avatar.rightHand).distanceTo(startTargets[1])],
  miss: { head: miss('head'), leftHand: miss('leftHand'), rightHand: miss('rightHand') },
  onTarget,
};
avatar.dispose();
result.restoredOff = [worldOf(avatar.bones.leftHand).distanceTo(restHands[0]), worldOf(avatar.bones.rightHand).distanceTo(restHands[1])];
try {
  avatar.update();
} catch (e) {
  result.afterDispose = e.message;
}
console.log(JSON.stringify(result));
