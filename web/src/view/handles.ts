// End-effector targets and their gizmo. Each effector has a target sphere (draggable with a
// TransformControls gizmo), a small marker on its tip, and a line from tip to target; a target
// with an orientation goal also shows that orientation as a red/green/blue axes triad (the
// effector bone frame's x, y, z). While the gizmo is dragged the orbit camera is disabled.
// Targets not being dragged never move. Modes: translate moves the selected target (keeping its
// orientation goal); rotate turns it, which sets its orientation goal (the gizmo starts at the
// effector's current frame, so nothing jumps until the user turns it); swing swings it (and its
// orientation goal, if any) rigidly about the rig's root joint. Scene coordinates are rig
// coordinates (rig_view.ts draws the poses unchanged), so the target's quaternion in the scene is
// the goal's quaternion in the rig, with no conversion. The gizmo may instead hold one of the
// limbs' pole handles (pole_handles.ts), always in translate mode: the gizmo holds one thing at a
// time, a target or a pole.
//
// Handles before the gizmo: a press on a target or pole handle the gizmo does not hold belongs to
// that handle, even where the gizmo's axes reach over it. Released without moving (a click), it
// gives the handle the gizmo; moved (a drag), it goes to the gizmo after all (or to the orbit, if
// no axis was under it), as if it had not been held (picking.ts, holdClickablePresses). A press on
// the handle the gizmo holds is the gizmo's, as always.
import {
  BufferGeometry,
  CylinderGeometry,
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

import { holdClickablePresses } from './picking.js';
import { PoleHandles } from './pole_handles.js';
import type { Stage } from './stage.js';

export type GizmoMode = 'translate' | 'rotate' | 'swing';

const q = new Quaternion();

/** Length of a target's axes triad, as a fraction of the rig's size (RigView.size). */
const AXES_LENGTH = 0.09;

export class Handles {
  readonly root = new Group();
  readonly gizmo: TransformControls;
  /** Index (in effector order) of the target the gizmo holds, or null. */
  selected: number | null = null;
  /** The limbs' pole handles (none until setPoles()). */
  readonly poles = new PoleHandles();
  /** Index of the pole handle the gizmo holds, or null. */
  selectedPole: number | null = null;
  /** Called with the pole index whenever the user moves that pole handle (rig units). */
  onPoleMoved: (j: number, x: number, y: number, z: number) => void = () => {};
  dragging = false;
  /** Called with the effector index whenever the user moves that target (rig units). */
  onTargetMoved: (k: number, x: number, y: number, z: number) => void = () => {};
  /**
   * Called with the effector index whenever the user turns that target (rotate mode, or swing
   * mode on a target with an orientation goal): its new orientation [x, y, z, w], rig coordinates.
   */
  onTargetTurned: (k: number, q: Quaternion) => void = () => {};
  /** Called when dragging starts (true) and stops (false). */
  onDragging: (dragging: boolean) => void = () => {};
  /** Called after the gizmo moved to another target (or none: k null, also when it took a pole). */
  onSelected: (k: number | null) => void = () => {};
  /** Writes effector k's current bone-frame rotation (rig coordinates) into `out`: where rotate mode starts. */
  currentRotation: (k: number, out: Quaternion) => void = (_k, out) => void out.identity();

  private readonly targetGeo = new SphereGeometry(1, 20, 14);
  private readonly tipGeo = new SphereGeometry(1, 12, 8);
  // Targets draw over the model (a lamp's target sits inside its shade) and under the gizmo.
  private readonly targetMat = new MeshStandardMaterial({
    color: 0xff4d6d,
    roughness: 0.35,
    emissive: 0x400010,
    depthTest: false,
    transparent: true,
  });
  private readonly targetSelMat = new MeshStandardMaterial({
    color: 0xffd166,
    roughness: 0.35,
    emissive: 0x403000,
    depthTest: false,
    transparent: true,
  });
  private readonly tipMat = new MeshBasicMaterial({ color: 0xff9a3c, depthTest: false, transparent: true });
  private readonly lineMat = new LineBasicMaterial({
    color: 0xff4d6d,
    depthTest: false,
    transparent: true,
    opacity: 0.8,
  });
  private readonly lines: LineSegments;
  private targets: Mesh[] = [];
  private tips: Mesh[] = [];
  /** One axes triad per target, a child of its sphere (so it turns with it); visible while its orientation goal is on. */
  private axes: Group[] = [];
  /** A unit-length rod along +Y from the origin, shared by every triad's three axes. */
  private readonly rodGeo = new CylinderGeometry(0.04, 0.04, 1, 6, 1).translate(0, 0.5, 0);
  private readonly axisMats = [0xff3b3b, 0x3bdc5a, 0x3b8bff].map(
    (color) => new MeshBasicMaterial({ color, depthTest: false, transparent: true }),
  );
  private readonly pivot = new Object3D();
  private mode: GizmoMode = 'translate';
  private readonly swingFrom = new Vector3();
  private readonly pivotStart = new Quaternion();
  private readonly turnFrom = new Quaternion();
  private readonly disposeGizmoListeners: () => void;
  private readonly stopHoldingPresses: () => void;

  private size = 1;

  constructor(stage: Stage) {
    this.gizmo = new TransformControls(stage.camera, stage.canvas);
    this.gizmo.setSize(0.9);
    // A capture listener: it sees a press before the gizmo, the orbit and the click listener do.
    this.stopHoldingPresses = holdClickablePresses(stage.canvas, stage.camera, (ray) => this.claimPress(ray));
    const helper = this.gizmo.getHelper();
    stage.scene.add(helper);
    // The gizmo picks against handles it places in updateMatrixWorld, which a drawn frame runs; a
    // still view draws seldom (Stage), so a pointer that reaches the canvas places them first (a
    // capture listener on the canvas runs before the gizmo's own).
    const placeGizmo = (): void => helper.updateMatrixWorld();
    for (const type of ['pointermove', 'pointerdown'] as const)
      stage.canvas.addEventListener(type, placeGizmo, { capture: true });
    const lineGeo = new BufferGeometry();
    lineGeo.setAttribute('position', new Float32BufferAttribute(new Float32Array(0), 3));
    this.lines = new LineSegments(lineGeo, this.lineMat);
    this.lines.frustumCulled = false;
    this.lines.renderOrder = 12;
    this.root.add(this.lines, this.pivot, this.poles.root);
    stage.scene.add(this.root);

    const onDragging = (e: { value: unknown }): void => {
      this.dragging = e.value === true;
      stage.orbit.enabled = !this.dragging;
      if (this.dragging && this.mode === 'swing' && this.selected !== null) {
        const t = this.targets[this.selected];
        this.swingFrom.copy(t.position);
        this.turnFrom.copy(t.quaternion);
        this.pivotStart.copy(this.pivot.quaternion);
      }
      this.onDragging(this.dragging);
    };
    const onChange = (): void => {
      const j = this.selectedPole;
      if (j !== null && this.dragging) {
        const p = this.poles.handle(j)?.position;
        if (p) this.onPoleMoved(j, p.x, p.y, p.z);
        return;
      }
      const k = this.selected;
      if (k === null || !this.dragging) return;
      const t = this.targets[k];
      if (this.mode === 'rotate') {
        this.onTargetTurned(k, t.quaternion);
        return;
      }
      if (this.mode === 'swing') {
        q.copy(this.pivotStart).invert().premultiply(this.pivot.quaternion);
        t.position.copy(this.swingFrom).sub(this.pivot.position).applyQuaternion(q).add(this.pivot.position);
        if (this.axes[k].visible) {
          t.quaternion.copy(this.turnFrom).premultiply(q);
          this.onTargetTurned(k, t.quaternion);
        }
      }
      this.onTargetMoved(k, t.position.x, t.position.y, t.position.z);
    };
    this.gizmo.addEventListener('dragging-changed', onDragging);
    this.gizmo.addEventListener('objectChange', onChange);
    this.disposeGizmoListeners = () => {
      this.gizmo.removeEventListener('dragging-changed', onDragging);
      this.gizmo.removeEventListener('objectChange', onChange);
      helper.removeFromParent();
      for (const type of ['pointermove', 'pointerdown'] as const)
        stage.canvas.removeEventListener(type, placeGizmo, { capture: true });
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
    this.axes = [];
    const r = this.size * 0.018;
    for (let k = 0; k < count; k++) {
      const t = new Mesh(this.targetGeo, this.targetMat);
      t.name = `target ${k}`;
      t.scale.setScalar(r);
      t.renderOrder = 12;
      t.position.fromArray(targets, 3 * k);
      const axes = this.makeAxes();
      axes.name = `target ${k} axes`;
      axes.scale.setScalar((AXES_LENGTH * this.size) / r); // inside the sphere's scale
      axes.visible = false;
      t.add(axes);
      this.axes.push(axes);
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

  /** Puts the gizmo on target k (null detaches it); a pole the gizmo held is let go. */
  select(k: number | null): void {
    this.selectedPole = null;
    this.poles.highlight(null);
    if (this.selected !== null && this.targets[this.selected]) this.targets[this.selected].material = this.targetMat;
    this.selected = k;
    if (k === null || !this.targets[k]) {
      this.selected = null;
      this.gizmo.detach();
      this.onSelected(null);
      return;
    }
    this.targets[k].material = this.targetSelMat;
    this.attach();
    this.onSelected(k);
  }

  /**
   * Puts the translate gizmo on pole handle j; the target it held is let go (onSelected(null)).
   * null, or a pole that does not exist: the first target takes the gizmo instead.
   */
  selectPole(j: number | null): void {
    if (j === null || !this.poles.handle(j)) {
      this.select(this.targets.length ? 0 : null);
      return;
    }
    if (this.selected !== null && this.targets[this.selected]) this.targets[this.selected].material = this.targetMat;
    this.selected = null;
    this.selectedPole = j;
    this.poles.highlight(j);
    this.attach();
    this.onSelected(null);
  }

  /**
   * Rebuilds the pole handles: `count` of them (0: none); sync() places them. A pole the gizmo held
   * keeps it if it still exists, else the first target takes it.
   */
  setPoles(count: number): void {
    const held = this.selectedPole;
    this.poles.rebuild(count, this.size);
    if (held === null) return;
    this.selectedPole = null;
    this.selectPole(held < count ? held : null);
  }

  /** Moves the pole handles to `points` and their lines' ends to `joints` (3 per pole each, rig units). */
  syncPoles(points: ArrayLike<number>, joints: ArrayLike<number>): void {
    this.poles.sync(points, joints, this.dragging ? this.selectedPole : null);
  }

  /** The pole handle under the ray (pole index), or null. */
  pickPole(raycaster: Raycaster): number | null {
    return this.poles.pick(raycaster);
  }

  /** Translate, rotate (turn the target: its orientation goal) or swing (about the root joint); a pole handle is always translated. */
  setMode(mode: GizmoMode): void {
    this.mode = mode;
    this.attach();
  }

  get gizmoMode(): GizmoMode {
    return this.mode;
  }

  /** Whether target k shows its orientation goal's axes. */
  axesShown(k: number): boolean {
    return this.axes[k]?.visible ?? false;
  }

  /** Where swing mode swings targets about (the root joint). */
  setPivot(at: Vector3): void {
    this.pivot.position.copy(at);
  }

  /**
   * Moves markers: targets (unless one is being dragged) and tips, 3 numbers per effector, rig
   * units. `turned[k]` is 1 where effector k has an orientation goal, `rotations` its orientation
   * (4 per effector [x, y, z, w], rig coordinates): the target turns to it and shows its axes.
   * The selected target in rotate mode without a goal follows its effector's current frame.
   */
  sync(targets: Float64Array, tips: Float64Array, turned?: Uint8Array, rotations?: Float64Array): void {
    const pos = this.lines.geometry.getAttribute('position') as Float32BufferAttribute;
    for (let k = 0; k < this.targets.length; k++) {
      const t = this.targets[k];
      const held = this.dragging && k === this.selected;
      const on = turned?.[k] === 1;
      this.axes[k].visible = on;
      if (!held) {
        t.position.fromArray(targets, 3 * k);
        if (on && rotations) t.quaternion.fromArray(rotations, 4 * k);
        else if (k === this.selected && this.mode === 'rotate') this.currentRotation(k, t.quaternion);
      }
      this.tips[k].position.fromArray(tips, 3 * k);
      pos.setXYZ(2 * k, tips[3 * k], tips[3 * k + 1], tips[3 * k + 2]);
      pos.setXYZ(2 * k + 1, t.position.x, t.position.y, t.position.z);
    }
    pos.needsUpdate = true;
    if (this.mode === 'swing' && !this.dragging) this.pivot.quaternion.identity();
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

  /**
   * What a click under `raycaster` does when it lands on a handle the gizmo does not hold while it
   * holds another (the nearest target first, else a pole handle): give that one the gizmo. Null
   * when the gizmo holds nothing (a click then picks as any click does) or the press is on what it
   * holds.
   */
  private claimPress(raycaster: Raycaster): (() => void) | null {
    if (this.dragging || !this.gizmo.enabled || (this.selected === null && this.selectedPole === null)) return null;
    const k = this.pick(raycaster);
    if (k !== null) {
      return k === this.selected
        ? null
        : () => {
            if (this.targets[k]) this.select(k);
          };
    }
    const j = this.pickPole(raycaster);
    if (j === null || j === this.selectedPole) return null;
    return () => {
      if (this.poles.handle(j)) this.selectPole(j);
    };
  }

  dispose(): void {
    this.stopHoldingPresses();
    this.gizmo.detach();
    this.disposeGizmoListeners();
    this.gizmo.dispose();
    this.poles.dispose();
    this.root.removeFromParent();
    this.root.clear();
    for (const x of [this.targetGeo, this.tipGeo, this.rodGeo, this.lines.geometry]) x.dispose();
    for (const x of [this.targetMat, this.targetSelMat, this.tipMat, this.lineMat, ...this.axisMats]) x.dispose();
  }

  /** A red/green/blue triad of unit rods along +x, +y, +z (seen through the model, as the tip markers are). */
  private makeAxes(): Group {
    const g = new Group();
    for (let i = 0; i < 3; i++) {
      const rod = new Mesh(this.rodGeo, this.axisMats[i]);
      if (i === 0) rod.rotation.z = -Math.PI / 2; // +y -> +x
      if (i === 2) rod.rotation.x = Math.PI / 2; // +y -> +z
      rod.renderOrder = 14;
      g.add(rod);
    }
    return g;
  }

  private attach(): void {
    const pole = this.selectedPole === null ? undefined : this.poles.handle(this.selectedPole);
    this.gizmo.setMode(pole || this.mode === 'translate' ? 'translate' : 'rotate');
    if (pole) {
      this.gizmo.attach(pole);
      return;
    }
    const k = this.selected;
    if (k === null) return;
    if (this.mode === 'swing') {
      this.pivot.quaternion.identity();
      this.gizmo.attach(this.pivot);
    } else {
      const t = this.targets[k];
      if (this.mode === 'rotate' && !this.axes[k].visible) this.currentRotation(k, t.quaternion);
      this.gizmo.attach(t);
    }
  }
}
