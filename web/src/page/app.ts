// The page: composes the stage, the rig, the targets, the panel, the stats, the plots, compare,
// the keyboard and the URL. Each of those lives in its own module; this one wires them and owns
// the per-frame solve.
import { Vector3 } from 'three';

import type { IkCoreModule } from '../ik/module.js';
import { CompareView, compareMethods } from './compare.js';
import { FileInput } from './file_input.js';
import { Handles } from './handles.js';
import { Keyboard } from './keyboard.js';
import { showLimits } from './limits_view.js';
import { LiveRig } from './live_rig.js';
import { pinnedDrift, solveFrame, takeStep } from './live_solve.js';
import { Panel, type PageSettings } from './panel.js';
import { listenForClicks, type ViewClick } from './picking.js';
import { ConvergencePlot } from './plots.js';
import { DEFAULT_RIG, type LoadedRig, loadProjectRig, loadUserFile, PROJECT_RIGS } from './rig_source.js';
import { Stage } from './scene.js';
import { createSolver } from './solvers.js';
import type { SolveOutcome, SolveSettings } from './solver_port.js';
import { StatsPanel, type StatsValues } from './stats.js';
import { readUrlState, writeUrlState } from './url_state.js';

/** The page's DOM slots (see index.html). */
export interface PageElements {
  root: HTMLElement;
  viewport: HTMLElement;
  side: HTMLElement;
  rigName: HTMLElement;
  message: HTMLElement;
  stepInfo: HTMLElement;
  selection: HTMLElement;
}

const FILE_KEY = 'file';
const v = new Vector3();

export class PageApp {
  readonly settings: PageSettings;
  private readonly stage: Stage;
  private readonly handles: Handles;
  private readonly stats: StatsPanel;
  private readonly plot: ConvergencePlot;
  private readonly compareView: CompareView;
  private readonly keyboard: Keyboard;
  private readonly panel: Panel;
  private readonly files: FileInput;
  private readonly stopClicks: () => void;
  private live: LiveRig | null = null;
  private rigKey: string | null = null;
  private loadToken = 0;
  private needsSolve = false;
  private needsRedraw = false;
  private stepDirty = true;
  private lastTick = 0;
  private busy = false;
  private draggedEffector: number | null = null;
  /** Completed loads, successful or not (for tests and tools). */
  loads = 0;
  /** The slowest per-frame solve since the rig loaded: page ms, ms inside the solver, iterations, stop. */
  slowest: { ms: number; solverMs: number; iterations: number; stopReason: string } | null = null;

  constructor(private readonly module: IkCoreModule, private readonly el: PageElements) {
    const url = readUrlState();
    const rig = url.rig && PROJECT_RIGS[url.rig] ? url.rig : DEFAULT_RIG;
    this.settings = {
      rig,
      humanoidLimits: true,
      method: url.method ?? 'lm',
      gradientTolerance: 1e-7,
      tipTolerance: 1e-3,
      maxIterations: 50,
      timeBudgetMs: 3,
      restarts: 0,
      paperMode: false,
      compareTimeBudgetMs: 1000,
      compareMaxIterations: 100000,
      compareFrom: 'current pose',
      showMesh: true,
      showBones: true,
      gizmo: 'translate',
      clickBone: 'toggle effector',
      stepMode: false,
      autoStep: false,
      stepIntervalMs: 600,
    };

    this.stage = new Stage(el.viewport);
    this.handles = new Handles(this.stage); // before the orbit connects: the gizmo sees pointers first
    this.stage.connectOrbit();
    this.handles.onTargetMoved = (k, x, y, z) => this.moveTarget(k, x, y, z);
    this.handles.onDragging = (dragging) => {
      this.draggedEffector = dragging ? this.handles.selected : null;
      el.root.dataset.dragging = String(dragging);
    };

    this.stats = new StatsPanel(el.side);
    this.plot = new ConvergencePlot(el.side);
    this.compareView = new CompareView(el.root);
    this.files = new FileInput(el.root, (f) => void this.loadFile(f));

    const rigOptions: Record<string, string> = {};
    for (const [key, r] of Object.entries(PROJECT_RIGS)) rigOptions[r.label] = key;
    rigOptions['(a file)'] = FILE_KEY;
    this.panel = new Panel(el.side, this.settings, rigOptions, {
      rigChanged: (key) => (key === FILE_KEY ? this.files.choose() : void this.loadProject(key)),
      openFile: () => this.files.choose(),
      limitsChanged: () => this.limitsChanged(),
      methodChanged: () => this.methodChanged(),
      settingsChanged: () => this.invalidate(),
      displayChanged: () => this.applyDisplay(),
      gizmoChanged: () => this.handles.setMode(this.settings.gizmo),
      stepModeChanged: () => this.stepModeChanged(),
      resetPose: () => this.resetPose(),
      step: () => this.step(),
      compare: () => void this.compare(),
      help: () => this.keyboard.toggle(),
    });
    if (window.matchMedia('(max-width: 700px)').matches) this.panel.gui.close();
    el.side.replaceChildren(this.stats.element, el.stepInfo, el.selection, this.plot.element, this.panel.gui.domElement);

    this.keyboard = new Keyboard(el.root, [
      { keys: ['R'], label: 'reset the pose', run: () => this.resetPose() },
      { keys: ['W'], label: 'gizmo: translate the target', run: () => this.setGizmo('translate') },
      { keys: ['E'], label: 'gizmo: rotate the target about the root joint', run: () => this.setGizmo('rotate') },
      { keys: ['S'], label: 'step mode: one iteration', run: () => this.step() },
      { keys: ['C'], label: 'compare every method from the current pose', run: () => void this.compare() },
      { keys: ['?', 'H'], label: 'show or hide this help', run: () => this.keyboard.toggle() },
      { keys: ['Escape'], label: 'close this help', run: () => this.keyboard.toggle(false) },
    ]);

    this.stopClicks = listenForClicks(
      this.stage.canvas,
      this.stage.camera,
      () => this.handles.dragging || this.handles.hovering,
      (c) => this.click(c),
    );
    this.stage.onFrame(() => this.frame());
  }

  /** Loads the rig named in the URL (or the default). */
  start(): Promise<void> {
    return this.loadProject(this.settings.rig);
  }

  get current(): LiveRig | null {
    return this.live;
  }

  /** The running window of per-frame solve times (ms). */
  get solveTimes(): StatsPanel['median'] {
    return this.stats.median;
  }

  get renderer(): Stage['renderer'] {
    return this.stage.renderer;
  }

  get camera(): Stage['camera'] {
    return this.stage.camera;
  }

  get canvas(): HTMLCanvasElement {
    return this.stage.canvas;
  }

  /** Screen position (client pixels) of a world point, for tests and tools. */
  toScreen(p: Vector3): { x: number; y: number } {
    return this.stage.toScreen(p);
  }

  /** Screen pixels (CSS) per rig unit at world point `p`. */
  pixelsPerUnit(p: Vector3): number {
    return this.stage.pixelsPerUnit(p);
  }

  get selectedTarget(): number | null {
    return this.handles.selected;
  }

  async loadProject(key: string): Promise<void> {
    const entry = PROJECT_RIGS[key];
    await this.load(() => loadProjectRig(key), entry ? entry.file : key, key);
  }

  async loadFile(file: File): Promise<void> {
    await this.load(() => loadUserFile(file), file.name, null);
  }

  dispose(): void {
    this.loadToken++;
    this.live?.dispose();
    this.live = null;
    this.stopClicks();
    this.keyboard.dispose();
    this.files.dispose();
    this.panel.dispose();
    this.compareView.dispose();
    this.plot.dispose();
    this.handles.dispose();
    this.stage.dispose();
  }

  // ---- loading -------------------------------------------------------------------------------

  private async load(read: () => Promise<LoadedRig>, what: string, key: string | null): Promise<void> {
    const token = ++this.loadToken;
    this.el.root.dataset.state = 'loading';
    this.showMessage(`loading ${what}…`, 'info');
    let live: LiveRig | null = null;
    try {
      const loaded = await read();
      live = await LiveRig.create(this.module, loaded, createSolver, true, this.settings.humanoidLimits);
    } catch (e) {
      if (token !== this.loadToken) return;
      const msg = e instanceof Error ? e.message : String(e);
      this.showMessage(`Could not load ${what}: ${msg}${this.live ? ` — still showing ${this.live.name}` : ''}`, 'error');
      this.panel.showRig(this.rigKey ?? FILE_KEY);
      this.el.root.dataset.state = this.live ? 'ready' : 'error';
      this.loads++;
      return;
    }
    if (token !== this.loadToken) {
      live.dispose();
      return;
    }
    this.install(live, key);
    const notes = live.loaded.warnings;
    this.showMessage(notes.length ? `${live.name}: ${notes.join('; ')}` : '', 'info');
    this.el.root.dataset.state = 'ready';
    this.loads++;
  }

  private install(live: LiveRig, key: string | null): void {
    const old = this.live;
    if (old) {
      for (const o of old.objects) this.stage.scene.remove(o);
      old.dispose();
    }
    this.live = live;
    this.rigKey = key;
    this.stage.scene.add(...live.objects);
    this.panel.showRig(key ?? FILE_KEY);
    this.panel.showHumanoidLimits(live.hasHumanoidLimits);
    // The rig's drag tolerances, shown to 3 significant digits in the panel.
    const t = live.tolerances();
    this.settings.tipTolerance = Number(t.tipTolerance.toPrecision(3));
    this.settings.gradientTolerance = Number(t.gradientTolerance.toPrecision(3));
    this.panel.refresh();
    writeUrlState({ rig: key, method: this.settings.method });

    const s = live.session;
    this.handles.setRigSize(live.view.size);
    this.handles.select(null);
    this.handles.setTargets(s.targets);
    this.handles.setPivot(live.view.boneBase(0, v));
    this.handles.setMode(this.settings.gizmo);
    this.applyDisplay();
    this.stage.frame(live.view.bounds());

    const effectors = s.effectors().length;
    this.el.rigName.textContent = `${live.name} — ${live.loaded.format}, ${s.rig.numBones} bones, ${effectors} end effector${effectors === 1 ? '' : 's'}`;
    this.el.root.dataset.rig = live.name;
    this.stats.reset();
    this.slowest = null;
    this.stats.showIdle(this.settings.method, s.objective());
    this.plot.clear();
    this.compareView.hide();
    this.needsSolve = false;
    this.stepDirty = true;
    this.showSelection();
    this.showStepInfo('');
    this.needsRedraw = true;
  }

  // ---- per frame -----------------------------------------------------------------------------

  private frame(): void {
    const live = this.live;
    if (!live || this.busy) return;
    if (this.settings.stepMode) {
      const now = performance.now();
      if (this.settings.autoStep && now - this.lastTick >= this.settings.stepIntervalMs) {
        this.lastTick = now;
        this.step();
      }
    } else if (this.needsSolve || this.handles.dragging) {
      this.solveFrame(live);
    }
    if (this.needsRedraw) {
      this.needsRedraw = false;
      live.redraw();
      this.handles.sync(live.session.targets, live.session.tips());
      if (live.selectedBone !== null) this.showSelection();
    }
  }

  /** Per-frame solving: never restarts, bounded by the panel's iteration cap and time budget. */
  private frameSettings(): SolveSettings {
    const s = this.settings;
    return {
      gradientTolerance: s.gradientTolerance,
      tipTolerance: s.tipTolerance,
      maxIterations: s.maxIterations,
      timeBudgetMs: s.timeBudgetMs,
      restarts: 0,
      paperMode: s.paperMode,
    };
  }

  private solveFrame(live: LiveRig): void {
    const session = live.session;
    if (session.effectors().length === 0) {
      this.needsSolve = false;
      return;
    }
    try {
      const { outcome: out, ms, again } = solveFrame(session, this.settings.method, this.frameSettings());
      this.needsSolve = again;
      if (ms > (this.slowest?.ms ?? -1))
        this.slowest = { ms, solverMs: out.elapsedSeconds * 1000, iterations: out.iterations, stopReason: out.stopReason };
      if (out.iterations > 0) this.plot.record(this.settings.method, out.history);
      this.stats.show(this.statsOf(live, out, ms, this.draggedEffector));
      this.needsRedraw = true;
    } catch (e) {
      this.needsSolve = false;
      this.showMessage(`solver error: ${e instanceof Error ? e.message : String(e)}`, 'error');
    }
  }

  /** The stats of one solve: `except` is the dragged effector (not counted as pinned), or null. */
  private statsOf(live: LiveRig, out: SolveOutcome, ms: number, except: number | null): StatsValues {
    const session = live.session;
    const k = this.handles.selected ?? 0;
    return {
      method: this.settings.method,
      iterations: out.iterations,
      E: out.E,
      gradNorm: out.gradNorm,
      reached: out.reached,
      tipDistance: out.tipDistance,
      pixelsPerUnit: this.stage.pixelsPerUnit(v.fromArray(session.targets, 3 * Math.min(k, session.targets.length / 3 - 1))),
      stopReason: out.stopReason,
      paperMode: this.settings.paperMode,
      ms,
      pinnedDrift: pinnedDrift(session.tips(), session.targets, except),
    };
  }

  private moveTarget(k: number, x: number, y: number, z: number): void {
    const live = this.live;
    if (!live) return;
    const t = live.session.targets;
    t[3 * k] = x;
    t[3 * k + 1] = y;
    t[3 * k + 2] = z;
    this.invalidate();
  }

  /** Something the solve depends on changed: solve again (or restart the step-mode solve). */
  private invalidate(): void {
    this.needsSolve = true;
    this.stepDirty = true;
    this.needsRedraw = true;
    if (this.settings.stepMode) this.live?.showGhost(null);
  }

  // ---- panel and keyboard actions ------------------------------------------------------------

  private methodChanged(): void {
    writeUrlState({ rig: this.rigKey, method: this.settings.method });
    this.live?.session.endSteps();
    this.invalidate();
    if (this.live) this.stats.showIdle(this.settings.method, this.live.session.objective());
  }

  /** The humanoid-limits switch: the rig takes the other limits, keeping its targets, and solves into them. */
  private limitsChanged(): void {
    const live = this.live;
    if (!live?.hasHumanoidLimits) return;
    if (this.busy) {
      // A compare is running on the current session: keep it.
      this.settings.humanoidLimits = !this.settings.humanoidLimits;
      this.panel.refresh();
      return;
    }
    try {
      live.useHumanoidLimits(this.settings.humanoidLimits);
    } catch (e) {
      this.showMessage(`could not switch the limits: ${e instanceof Error ? e.message : String(e)}`, 'error');
      return;
    }
    this.stats.showIdle(this.settings.method, live.session.objective());
    this.invalidate();
    this.showSelection();
  }

  private setGizmo(mode: PageSettings['gizmo']): void {
    this.settings.gizmo = mode;
    this.handles.setMode(mode);
    this.panel.refresh();
  }

  private applyDisplay(): void {
    const live = this.live;
    if (!live) return;
    live.view.setMeshVisible(this.settings.showMesh);
    live.view.setBonesVisible(this.settings.showBones || !live.view.hasMesh);
  }

  private resetPose(): void {
    const live = this.live;
    if (!live) return;
    live.session.reset();
    live.showGhost(null);
    this.handles.setTargets(live.session.targets);
    this.needsSolve = false;
    this.stepDirty = true;
    this.needsRedraw = true;
    this.stats.showIdle(this.settings.method, live.session.objective());
    this.showStepInfo('');
    this.showSelection();
  }

  private stepModeChanged(): void {
    const live = this.live;
    this.stepDirty = true;
    if (!this.settings.stepMode) {
      live?.session.endSteps();
      live?.showGhost(null);
      this.showStepInfo('');
      this.needsSolve = true;
    } else {
      this.showStepInfo('step mode: press S (or “one iteration”) to take one iteration; drag a target to pose a new problem');
    }
  }

  /** One iteration of the current method; shows the previous iterate as a ghost and the step taken. */
  private step(): void {
    const live = this.live;
    if (!live || this.busy) return;
    if (!this.settings.stepMode) {
      this.settings.stepMode = true;
      this.panel.refresh();
    }
    const session = live.session;
    if (session.effectors().length === 0) return;
    const method = this.settings.method;
    try {
      const r = takeStep(session, method, { ...this.frameSettings(), maxIterations: this.settings.compareMaxIterations }, this.stepDirty);
      this.stepDirty = false;
      const out = r.outcome;
      live.showGhost(r.stepLength > 0 ? r.before : null);
      this.plot.record(method, out.history);
      this.stats.show(this.statsOf(live, out, r.ms, null), false);
      this.showStepInfo(r.text);
      this.el.stepInfo.dataset.iterations = String(out.iterations);
      this.needsRedraw = true;
    } catch (e) {
      this.showMessage(`solver error: ${e instanceof Error ? e.message : String(e)}`, 'error');
    }
  }

  private async compare(): Promise<void> {
    const live = this.live;
    if (!live || this.busy) return;
    this.busy = true;
    const s = this.settings;
    const settings: SolveSettings = {
      ...this.frameSettings(),
      maxIterations: s.compareMaxIterations,
      timeBudgetMs: s.compareTimeBudgetMs,
      restarts: s.restarts,
    };
    this.compareView.begin(`${live.name}, from the ${s.compareFrom} (budget ${s.compareTimeBudgetMs} ms, restarts ${s.restarts})`);
    try {
      await compareMethods(live.session, settings, s.compareFrom, (row) => {
        this.compareView.addRow(row, s.paperMode);
        if (row.outcome) this.plot.record(row.method, row.outcome.history);
      });
    } finally {
      this.compareView.end();
      this.busy = false;
    }
  }

  // ---- clicks --------------------------------------------------------------------------------

  private click(c: ViewClick): void {
    const live = this.live;
    if (!live) return;
    const target = this.handles.pick(c.raycaster);
    if (target !== null) {
      this.handles.select(target);
      return;
    }
    const bone = live.view.pick(c.raycaster);
    live.selectedBone = bone;
    if (bone !== null && !c.shiftKey && this.settings.clickBone === 'toggle effector') this.toggleEffector(bone);
    this.needsRedraw = true;
    this.showSelection();
  }

  private toggleEffector(bone: number): void {
    const live = this.live;
    if (!live) return;
    const list = Array.from(live.session.effectors());
    const at = list.indexOf(bone);
    if (at >= 0) {
      if (list.length === 1) {
        this.showMessage('a rig keeps at least one end effector', 'info');
        return;
      }
      list.splice(at, 1);
    } else {
      list.push(bone);
    }
    live.session.setEffectors(list);
    this.handles.setTargets(live.session.targets);
    if (at < 0) this.handles.select(list.length - 1);
    this.invalidate();
    const n = list.length;
    this.el.rigName.textContent = `${live.name} — ${live.loaded.format}, ${live.session.rig.numBones} bones, ${n} end effector${n === 1 ? '' : 's'}`;
    this.stats.showIdle(this.settings.method, live.session.objective());
  }

  // ---- text ----------------------------------------------------------------------------------

  private showSelection(): void {
    const live = this.live;
    const i = live?.selectedBone ?? null;
    if (!live || i === null) showLimits(this.el.selection, null);
    else
      showLimits(this.el.selection, {
        spec: live.session.spec,
        bone: i,
        angles: live.session.angles,
        isEffector: live.session.effectors().includes(i),
        limitSource: live.hasHumanoidLimits ? (this.settings.humanoidLimits ? 'humanoid (anatomical)' : 'the file’s (humanoid limits off)') : undefined,
      });
  }

  private showStepInfo(text: string): void {
    this.el.stepInfo.textContent = text;
    this.el.stepInfo.hidden = text === '';
  }

  private showMessage(text: string, kind: 'info' | 'error'): void {
    this.el.message.textContent = text;
    this.el.message.dataset.kind = kind;
    this.el.message.hidden = text === '';
  }
}
