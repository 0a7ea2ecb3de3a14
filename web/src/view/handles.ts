// End-effector targets and their gizmo. Each effector has a target sphere (draggable with a
// TransformControls gizmo), a small marker on its tip, and a line from tip to target. While the
// gizmo is dragged the orbit camera is disabled. Targets not being dragged never move.
// Translate mode moves the selected target; rotate mode swings it about the rig's root joint.
import {
  BufferGeometry,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Object3D,
  Quaternion,
  type Raycaster,
  SphereGeometry,
  Vector3,
} from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';

import type { Stage } from './stage.js';

export type GizmoMode = 'translate' | 'rotate';

const q = new Quaternion();

export class Handles {
  readonly root = new Group();
  readonly gizmo: TransformControls;
  /** Index (in effector order) of the target the gizmo holds, or null. */
  selected: number | null = null;
  dragging = false;
  /** Called with the effector index whenever the user moves that target. */
  onTargetMoved: (k: number, x: number, y: number, z: number) => void = () => {};
  /** Called when dragging starts (true) and stops (false). */
  onDragging: (dragging: boolean) => void = () => {};

  private readonly targetGeo = new SphereGeometry(1, 20, 14);
  private readonly tipGeo = new SphereGeometry(1, 12, 8);
  private readonly targetMat = new MeshStandardMaterial({ color: 0xff4d6d, roughness: 0.35, emissive: 0x400010 });
  private readonly targetSelMat = new MeshStandardMaterial({ color: 0xffd166, roughness: 0.35, emissive: 0x403000 });
  private readonly tipMat = new MeshBasicMaterial({ color: 0xff9a3c, depthTest: false, transparent: true });
  private readonly lineMat = new LineBasicMaterial({ color: 0xff4d6d, depthTest: false, transparent: true, opacity: 0.8 });
  private readonly lines: LineSegments;
  private targets: Mesh[] = [];
  private tips: Mesh[] = [];
  private readonly pivot = new Object3D();
  private mode: GizmoMode = 'translate';
  private readonly swingFrom = new Vector3();
  private readonly pivotStart = new Quaternion();
  private readonly disposeGizmoListeners: () => void;

  private size = 1;

  constructor(stage: Stage) {
    this.gizmo = new TransformControls(stage.camera, stage.canvas);
    this.gizmo.setSize(0.9);
    const helper = this.gizmo.getHelper();
    stage.scene.add(helper);
    const lineGeo = new BufferGeometry();
    lineGeo.setAttribute('position', new Float32BufferAttribute(new Float32Array(0), 3));
    this.lines = new LineSegments(lineGeo, this.lineMat);
    this.lines.frustumCulled = false;
    this.lines.renderOrder = 12;
    this.root.add(this.lines, this.pivot);
    stage.scene.add(this.root);

    const onDragging = (e: { value: unknown }): void => {
      this.dragging = e.value === true;
      stage.orbit.enabled = !this.dragging;
      if (this.dragging && this.mode === 'rotate' && this.selected !== null) {
        this.swingFrom.copy(this.targets[this.selected].position);
        this.pivotStart.copy(this.pivot.quaternion);
      }
      this.onDragging(this.dragging);
    };
    const onChange = (): void => {
      const k = this.selected;
      if (k === null || !this.dragging) return;
      const t = this.targets[k];
      if (this.mode === 'rotate') {
        q.copy(this.pivotStart).invert().premultiply(this.pivot.quaternion);
        t.position.copy(this.swingFrom).sub(this.pivot.position).applyQuaternion(q).add(this.pivot.position);
      }
      this.onTargetMoved(k, t.position.x, t.position.y, t.position.z);
    };
    this.gizmo.addEventListener('dragging-changed', onDragging);
    this.gizmo.addEventListener('objectChange', onChange);
    this.disposeGizmoListeners = () => {
      this.gizmo.removeEventListener('dragging-changed', onDragging);
      this.gizmo.removeEventListener('objectChange', onChange);
      helper.removeFromParent();
    };
  }

  /** Marker size follows the rig's size. */
  setRigSize(size: number): void {
    this.size = size;
  }

  /** Rebuilds the markers for `targets` (3 numbers per effector); keeps the selection if it still exists. */
  setTargets(targets: Float64Array): void {
    const count = targets.length / 3;
    for (const m of [...this.targets, ...this.tips]) m.removeFromParent();
    this.targets = [];
    this.tips = [];
    const r = this.size * 0.018;
    for (let k = 0; k < count; k++) {
      const t = new Mesh(this.targetGeo, this.targetMat);
      t.name = `target ${k}`;
      t.scale.setScalar(r);
      t.position.fromArray(targets, 3 * k);
      const tip = new Mesh(this.tipGeo, this.tipMat);
      tip.scale.setScalar(r * 0.55);
      tip.renderOrder = 13;
      this.targets.push(t);
      this.tips.push(tip);
      this.root.add(t, tip);
    }
    this.lines.geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(6 * count), 3));
    const keep = this.selected !== null && this.selected < count ? this.selected : count > 0 ? 0 : null;
    this.selected = null;
    this.select(keep);
  }

  get count(): number {
    return this.targets.length;
  }

  /** Puts the gizmo on target k (null detaches it). */
  select(k: number | null): void {
    if (this.selected !== null && this.targets[this.selected]) this.targets[this.selected].material = this.targetMat;
    this.selected = k;
    if (k === null || !this.targets[k]) {
      this.selected = null;
      this.gizmo.detach();
      return;
    }
    this.targets[k].material = this.targetSelMat;
    this.attach();
  }

  setMode(mode: GizmoMode): void {
    this.mode = mode;
    this.gizmo.setMode(mode);
    this.attach();
  }

  get gizmoMode(): GizmoMode {
    return this.mode;
  }

  /** Where rotate mode swings targets about (the root joint). */
  setPivot(at: Vector3): void {
    this.pivot.position.copy(at);
  }

  /** Moves markers: targets (unless one is being dragged) and tips, 3 numbers per effector. */
  sync(targets: Float64Array, tips: Float64Array): void {
    const pos = this.lines.geometry.getAttribute('position') as Float32BufferAttribute;
    for (let k = 0; k < this.targets.length; k++) {
      const t = this.targets[k];
      if (!(this.dragging && k === this.selected)) t.position.fromArray(targets, 3 * k);
      this.tips[k].position.fromArray(tips, 3 * k);
      pos.setXYZ(2 * k, tips[3 * k], tips[3 * k + 1], tips[3 * k + 2]);
      pos.setXYZ(2 * k + 1, t.position.x, t.position.y, t.position.z);
    }
    pos.needsUpdate = true;
    if (this.mode === 'rotate' && !this.dragging) this.pivot.quaternion.identity();
  }

  /** The target under the ray (effector index), or null. */
  pick(raycaster: Raycaster): number | null {
    const hits = raycaster.intersectObjects(this.targets, false);
    return hits.length ? this.targets.indexOf(hits[0].object as Mesh) : null;
  }

  /** True while the pointer is over a gizmo handle (so a click is not a pick). */
  get hovering(): boolean {
    return this.gizmo.axis !== null;
  }

  /** World position of target k. */
  targetPosition(k: number, out: Vector3): Vector3 {
    return out.copy(this.targets[k].position);
  }

  dispose(): void {
    this.gizmo.detach();
    this.disposeGizmoListeners();
    this.gizmo.dispose();
    this.root.removeFromParent();
    this.root.clear();
    for (const x of [this.targetGeo, this.tipGeo, this.lines.geometry]) x.dispose();
    for (const x of [this.targetMat, this.targetSelMat, this.tipMat, this.lineMat]) x.dispose();
  }

  private attach(): void {
    const k = this.selected;
    if (k === null) return;
    if (this.mode === 'rotate') {
      this.pivot.quaternion.identity();
      this.gizmo.attach(this.pivot);
    } else {
      this.gizmo.attach(this.targets[k]);
    }
  }
}
