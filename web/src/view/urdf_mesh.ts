// A URDF robot's meshes drawn on its rig: urdf-loader reads the file's visuals (meshes,
// boxes, cylinders, spheres, their origins and materials), the mesh files come from `files` (the
// folder the user dropped, already read), and each link's visuals then ride with the chain bone
// that moves the link: the nearest revolute joint of the chain above it (a camera on the upper arm
// rides with the upper arm; a link below the tip with the tip; a link above the chain's base, or in
// another branch, stays still as it is at the zero pose). No three.js hierarchy of the robot is kept: each link's
// visuals sit in a group whose world matrix is the bone's pose times the link's frame at rest.
import { Group, LoadingManager, Matrix4, type Object3D } from 'three';
import URDFLoader, { type URDFLink, type URDFRobot } from 'urdf-loader';

import { fromRowMajor } from './row_major.js';
import type { MeshBinding } from './rig_view.js';

/** What binds a URDF file's links to the rig of one of its chains. */
export interface UrdfChainLinks {
  /** The chain's base link: the rig's world is its frame. */
  base: string;
  /** The chain's revolute and continuous joints, bone k moving joint k. */
  joints: readonly string[];
  /** The turn from the URDF's frames to the page's (row-major 4x4; Z up to Y up), applied as the rig's rest frames were. */
  toPage: Float64Array;
}

/** The result: the binding, and the mesh files the visuals named that could not be drawn (not in `files`, not STL or Collada, or unreadable). */
export interface UrdfMesh {
  binding: MeshBinding;
  missing: string[];
}

/**
 * The visuals of the URDF `text` bound to `chain`'s rig; `files` maps each mesh file name as the
 * URDF writes it (package:// or relative) to its bytes, STL or Collada (URDF_MESH_FORMATS of
 * urdf_model.ts; absent: not found or not drawn, its visual is skipped).
 * Resolves once every mesh file has been parsed.
 */
export async function urdfMesh(
  text: string,
  chain: UrdfChainLinks,
  files: ReadonlyMap<string, Uint8Array>,
): Promise<UrdfMesh> {
  const urls = new Map<string, string>();
  for (const [name, bytes] of files) urls.set(name, URL.createObjectURL(new Blob([bytes as BlobPart])));
  const missing = new Set<string>();
  const manager = new LoadingManager();
  manager.setURLModifier((url) => urls.get(url) ?? url);
  let robot: URDFRobot;
  try {
    await new Promise<void>((resolve, reject) => {
      let pending = 0,
        parsed = false;
      const finish = (): void => {
        if (parsed && pending === 0) resolve();
      };
      const loader = new URDFLoader(manager);
      loader.parseCollision = false;
      loader.loadMeshCb = (path, m, material, done) => {
        const url = urls.get(path);
        if (!url) {
          missing.add(path);
          done(new Group());
          return;
        }
        pending++;
        // The default loader picks STL or Collada by the name; the manager turns it into the file's blob URL.
        loader.defaultMeshLoader(path, m, material, (mesh, err) => {
          if (err || !mesh) missing.add(path);
          done(mesh ?? new Group(), err);
          pending--;
          finish();
        });
      };
      // Mesh names stay as written: package://pkg/x.stl resolves to "package://pkg/x.stl".
      loader.packages = (pkg: string) => `package://${pkg}`;
      try {
        robot = loader.parse(text);
      } catch (e) {
        reject(e);
        return;
      }
      parsed = true;
      finish();
    });
  } finally {
    for (const url of urls.values()) URL.revokeObjectURL(url);
  }
  return { binding: bindLinks(robot!, chain), missing: [...missing] };
}

/** Each link's visuals in a group moved by its chain bone (see the file's header). */
function bindLinks(robot: URDFRobot, chain: UrdfChainLinks): MeshBinding {
  robot.updateMatrixWorld(true);
  const root = new Group();
  root.name = 'urdf-visuals';
  const baseLink = robot.links[chain.base];
  const toPage = fromRowMajor(new Matrix4(), chain.toPage, 0);
  const fromBase = new Matrix4().copy(baseLink.matrixWorld).invert();
  const boneOfJoint = new Map(chain.joints.map((j, k) => [j, k]));
  const parts: Array<{ group: Group; bone: number; rest: Matrix4 }> = [];
  for (const link of Object.values(robot.links) as URDFLink[]) {
    const visuals = link.children.filter((c) => (c as Object3D & { isURDFVisual?: boolean }).isURDFVisual);
    if (visuals.length === 0) continue;
    const bone = boneOf(link, chain, boneOfJoint);
    const group = new Group();
    group.name = link.name;
    group.matrixAutoUpdate = false;
    for (const v of visuals) group.add(v); // keeps each visual's origin within its link
    // The link's frame at rest in the page's coordinates: the base's frame is the rig's world.
    const rest = new Matrix4().multiplyMatrices(toPage, new Matrix4().multiplyMatrices(fromBase, link.matrixWorld));
    group.matrix.copy(rest);
    root.add(group);
    parts.push({ group, bone: bone ?? -1, rest });
  }
  const pose = new Matrix4();
  return {
    object: root,
    apply(poses: Float64Array): void {
      for (const { group, bone, rest } of parts) {
        if (bone < 0) continue;
        fromRowMajor(pose, poses, 16 * bone);
        group.matrix.multiplyMatrices(pose, rest);
        group.matrixWorldNeedsUpdate = true;
      }
    },
    dispose(): void {
      root.traverse((o) => {
        const mesh = o as Object3D & {
          geometry?: { dispose(): void };
          material?: { dispose(): void } | Array<{ dispose(): void }>;
        };
        mesh.geometry?.dispose();
        for (const m of Array.isArray(mesh.material) ? mesh.material : mesh.material ? [mesh.material] : [])
          m.dispose();
      });
      root.removeFromParent();
    },
  };
}

/** The chain bone that moves `link`: its nearest chain joint above it (below the tip, the last one's), or null (it does not move). */
function boneOf(link: URDFLink, chain: UrdfChainLinks, boneOfJoint: ReadonlyMap<string, number>): number | null {
  for (let o: Object3D | null = link; o; o = o.parent) {
    const joint = o as Object3D & { isURDFJoint?: boolean; name: string };
    if (joint.isURDFJoint && boneOfJoint.has(joint.name)) return boneOfJoint.get(joint.name)!;
    if ((o as URDFLink).isURDFLink && o.name === chain.base) return null;
  }
  return null;
}
