// The three.js stage: renderer, camera, OrbitControls, lights and a ground grid, sized to its
// container (ResizeObserver), with a render loop that calls the per-frame work (onFrame) first.
// The camera stays above the floor (the grid, at the framed rig's lowest point): it orbits no lower
// than level with the point it looks at, and a pan cannot take that point under the floor.
import {
  AmbientLight,
  Box3,
  Color,
  DirectionalLight,
  GridHelper,
  HemisphereLight,
  PerspectiveCamera,
  Scene,
  Sphere,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const viewPoint = new Vector3();

/** A point on screen, client (CSS) pixels. */
export interface ScreenPoint {
  x: number;
  y: number;
}

export type FrameCallback = (seconds: number) => void;

/**
 * After anything that may change the picture (input, invalidate()), every frame is drawn for this
 * long, ms (a drag's pointer moves keep it going).
 */
const ACTIVE_MS = 300;
/**
 * Otherwise a frame is drawn at most this often, ms: a still view costs the main thread next to
 * nothing (a character drawn in software took 50 ms a frame at every animation frame, 200-370 ms
 * with the cores busy, in the way of a compare's progress), and a change nobody announced still
 * shows within a second.
 */
const IDLE_FRAME_MS = 1000;
/** The input that may move something on screen for a while (a drag, an orbit, a zoom). */
const WAKING_EVENTS = ['pointerdown', 'pointermove', 'pointerup', 'wheel', 'touchstart', 'touchmove'] as const;
/** The input that may change the picture once (a shortcut): one frame is drawn. */
const ONE_FRAME_EVENTS = ['keydown'] as const;

export class Stage {
  readonly renderer: WebGLRenderer;
  readonly scene = new Scene();
  readonly camera = new PerspectiveCamera(45, 1, 0.01, 1000);
  /** Made unconnected: connect() it after every control that must see pointer events first. */
  readonly orbit: OrbitControls;
  private readonly grid: GridHelper;
  private readonly resizeObserver: ResizeObserver;
  private readonly callbacks: FrameCallback[] = [];
  private last = 0;
  /** Draw every frame until then (performance.now() ms). */
  private activeUntil = 0;
  private lastDraw = -Infinity;
  /** Draw the next frame whatever the timing says. */
  private drawNext = false;
  private readonly wake = (): void => this.invalidate();
  private readonly drawOnce = (): void => {
    this.drawNext = true;
  };
  /** Frames drawn (for tests and tools). */
  drawnFrames = 0;

  constructor(readonly container: HTMLElement) {
    this.renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: false });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    const canvas = this.renderer.domElement;
    canvas.style.display = 'block';
    canvas.style.width = '100%';
    canvas.style.height = '100%';
    canvas.style.touchAction = 'none'; // pointer events drive orbit and gizmo on touch screens
    container.append(canvas);

    this.scene.background = new Color(0x20242b);
    this.scene.add(new HemisphereLight(0xdde6ff, 0x30281e, 1.6));
    this.scene.add(new AmbientLight(0xffffff, 0.3));
    const sun = new DirectionalLight(0xffffff, 2.2);
    sun.position.set(3, 6, 4);
    this.scene.add(sun);
    this.grid = new GridHelper(10, 20, 0x56606e, 0x3a414c);
    this.scene.add(this.grid);

    this.camera.position.set(2, 1.5, 3);
    this.orbit = new OrbitControls(this.camera, null);
    this.orbit.enableDamping = false;
    this.orbit.maxPolarAngle = Math.PI / 2; // level with the target at most: never from below the floor
    this.orbit.addEventListener('change', () => this.keepAboveFloor());

    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.resize();
    for (const type of WAKING_EVENTS) window.addEventListener(type, this.wake, { passive: true });
    for (const type of ONE_FRAME_EVENTS) window.addEventListener(type, this.drawOnce, { passive: true });
    this.renderer.setAnimationLoop((t) => this.tick(t));
  }

  /** The picture may change: every frame is drawn for the next ACTIVE_MS (else one every IDLE_FRAME_MS). */
  invalidate(): void {
    this.activeUntil = performance.now() + ACTIVE_MS;
  }

  /** Where world point `p` is on screen now: client (CSS) pixels. */
  toScreen(p: Vector3): ScreenPoint {
    const rect = this.canvas.getBoundingClientRect();
    viewPoint.copy(p).project(this.camera);
    return { x: rect.left + ((viewPoint.x + 1) / 2) * rect.width, y: rect.top + ((1 - viewPoint.y) / 2) * rect.height };
  }

  /** Screen pixels (CSS) per world unit at world point `p`, seen by the camera now. */
  pixelsPerUnit(p: Vector3): number {
    const depth = viewPoint.copy(p).applyMatrix4(this.camera.matrixWorldInverse).z;
    const height = this.canvas.clientHeight;
    const fov = (this.camera.fov * Math.PI) / 180;
    return depth < 0 ? height / (2 * -depth * Math.tan(fov / 2)) : NaN;
  }

  get canvas(): HTMLCanvasElement {
    return this.renderer.domElement;
  }

  /** Connects the camera controls to the canvas; call after the gizmo is made. */
  connectOrbit(): void {
    this.orbit.connect(this.canvas);
  }

  onFrame(callback: FrameCallback): void {
    this.callbacks.push(callback);
  }

  /** Points the camera at `box` from the current viewing direction and scales the grid to it. */
  frame(box: Box3): void {
    if (box.isEmpty()) return;
    const sphere = box.getBoundingSphere(new Sphere());
    const r = Math.max(sphere.radius, 1e-3);
    const dir = new Vector3().subVectors(this.camera.position, this.orbit.target);
    if (dir.lengthSq() < 1e-12) dir.set(0.6, 0.45, 1);
    dir.normalize();
    const vfov = (this.camera.fov * Math.PI) / 180;
    const hfov = 2 * Math.atan(Math.tan(vfov / 2) * this.camera.aspect);
    const dist = (r / Math.sin(Math.min(vfov, hfov) / 2)) * 1.1;
    this.orbit.target.copy(sphere.center);
    this.camera.position.copy(sphere.center).addScaledVector(dir, dist);
    this.camera.near = dist / 100;
    this.camera.far = dist * 100;
    this.camera.updateProjectionMatrix();
    this.orbit.update();
    this.invalidate();
    const size = Math.pow(10, Math.ceil(Math.log10(r * 4)));
    this.grid.scale.setScalar(size / 10);
    this.grid.position.set(sphere.center.x, box.min.y, sphere.center.z);
  }

  /** Height of the floor (the grid), world units. */
  get floorY(): number {
    return this.grid.position.y;
  }

  /** Lifts the orbit's target (and the camera with it) back onto the floor after a pan took it below. */
  private keepAboveFloor(): void {
    const below = this.floorY - this.orbit.target.y;
    if (below <= 0) return;
    this.orbit.target.y += below;
    this.camera.position.y += below;
  }

  resize(): void {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.invalidate();
  }

  /** Stops the render loop and frees the renderer, its WebGL context and the grid. */
  dispose(): void {
    this.renderer.setAnimationLoop(null);
    for (const type of WAKING_EVENTS) window.removeEventListener(type, this.wake);
    for (const type of ONE_FRAME_EVENTS) window.removeEventListener(type, this.drawOnce);
    this.resizeObserver.disconnect();
    this.orbit.dispose();
    this.grid.geometry.dispose();
    const m = this.grid.material;
    (Array.isArray(m) ? m : [m]).forEach((x) => x.dispose());
    this.renderer.forceContextLoss(); // frees the WebGL context now: a page allows only about 16
    this.renderer.dispose();
    this.canvas.remove();
  }

  private tick(t: number): void {
    const dt = this.last ? Math.min((t - this.last) / 1000, 0.1) : 0;
    this.last = t;
    for (const cb of this.callbacks) cb(dt);
    const now = performance.now();
    if (
      !this.renderer.xr.isPresenting &&
      !this.drawNext &&
      now >= this.activeUntil &&
      now - this.lastDraw < IDLE_FRAME_MS
    ) {
      // Not drawn, but posed: clicks pick targets and bones by their world matrices, which a
      // draw would have brought up to date (the gizmo places its own on each pointer event).
      this.scene.updateMatrixWorld();
      this.camera.updateMatrixWorld();
      return;
    }
    this.lastDraw = now;
    this.drawNext = false;
    this.drawnFrames++;
    this.renderer.render(this.scene, this.camera);
  }
}
