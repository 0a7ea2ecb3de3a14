// The limbs' pole handles: a yellow diamond per pole (a bend hint for the elbow or knee) and a thin
// line from the limb's joint to it, drawn through the model as the tip markers are. Only drawing
// and picking: Handles (handles.ts) gives a pole the translate gizmo, the LiveController turns the
// moves into pole goals. Scene coordinates are rig coordinates, rig units.
import {
  BufferGeometry,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  OctahedronGeometry,
  type Raycaster,
} from 'three';

/** A diamond's half-height, as a fraction of the rig's size (RigView.size). */
const DIAMOND_SIZE = 0.022;

export class PoleHandles {
  readonly root = new Group();
  private readonly geo = new OctahedronGeometry(1, 0);
  private readonly mat = new MeshBasicMaterial({ color: 0xffc400, depthTest: false, transparent: true, opacity: 0.9 });
  private readonly selMat = new MeshBasicMaterial({ color: 0xfff3a0, depthTest: false, transparent: true });
  private readonly lineMat = new LineBasicMaterial({
    color: 0xffc400,
    depthTest: false,
    transparent: true,
    opacity: 0.7,
  });
  private readonly lines: LineSegments;
  private handles: Mesh[] = [];
  private highlighted: number | null = null;

  constructor() {
    const lineGeo = new BufferGeometry();
    lineGeo.setAttribute('position', new Float32BufferAttribute(new Float32Array(0), 3));
    this.lines = new LineSegments(lineGeo, this.lineMat);
    this.lines.frustumCulled = false;
    this.lines.renderOrder = 15;
    this.root.add(this.lines);
  }

  /** Number of handles. */
  get count(): number {
    return this.handles.length;
  }

  /** Rebuilds `count` handles (0: none), sized for a rig of size `rigSize` (rig units); sync() places them. */
  rebuild(count: number, rigSize: number): void {
    for (const h of this.handles) h.removeFromParent();
    this.handles = [];
    this.highlighted = null;
    const r = rigSize * DIAMOND_SIZE;
    for (let j = 0; j < count; j++) {
      const h = new Mesh(this.geo, this.mat);
      h.name = `pole ${j}`;
      h.scale.set(r * 0.7, r, r * 0.7);
      h.renderOrder = 16;
      this.handles.push(h);
      this.root.add(h);
    }
    this.lines.geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(6 * count), 3));
  }

  /** Handle j's object (what the gizmo holds). */
  handle(j: number): Mesh | undefined {
    return this.handles[j];
  }

  /** Marks handle j as the selected one (null: none). */
  highlight(j: number | null): void {
    if (this.highlighted !== null && this.handles[this.highlighted]) this.handles[this.highlighted].material = this.mat;
    this.highlighted = j !== null && this.handles[j] ? j : null;
    if (this.highlighted !== null) this.handles[this.highlighted].material = this.selMat;
  }

  /**
   * Places the handles at `points` and their lines from `joints` (3 numbers per pole each, rig
   * units); handle `held` (being dragged) keeps where the gizmo put it. No allocation.
   */
  sync(points: ArrayLike<number>, joints: ArrayLike<number>, held: number | null): void {
    const pos = this.lines.geometry.getAttribute('position') as Float32BufferAttribute;
    for (let j = 0; j < this.handles.length; j++) {
      const h = this.handles[j];
      if (j !== held) h.position.set(points[3 * j], points[3 * j + 1], points[3 * j + 2]);
      pos.setXYZ(2 * j, joints[3 * j], joints[3 * j + 1], joints[3 * j + 2]);
      pos.setXYZ(2 * j + 1, h.position.x, h.position.y, h.position.z);
    }
    pos.needsUpdate = true;
  }

  /** The handle under the ray (pole index), or null. */
  pick(raycaster: Raycaster): number | null {
    const hits = raycaster.intersectObjects(this.handles, false);
    return hits.length ? this.handles.indexOf(hits[0].object as Mesh) : null;
  }

  dispose(): void {
    this.root.removeFromParent();
    this.root.clear();
    this.handles = [];
    for (const x of [this.geo, this.lines.geometry]) x.dispose();
    for (const x of [this.mat, this.selMat, this.lineMat]) x.dispose();
  }
}
