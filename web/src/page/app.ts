// The page: a LiveController (web/src/live/) shows the rig and solves while targets move; around
// it the page's own parts: the panel, the solve report (stats and plot), compare, step mode, track
// mode, the selection, the keyboard, the URL and loading rigs. Each part is its own module; this
// one wires them together and loads rigs.
import type { IkCoreModule } from '../ik/module.js';
import { errorText } from '../live/error_text.js';
import { LiveController, type LiveEvents } from '../view/live_controller.js';
import { LiveRig } from '../view/live_rig.js';
import { MethodList } from '../live/methods.js';
import { readRig, type RigSource } from '../view/rig_source.js';
import { Throttle } from '../live/throttle.js';
import type { ViewClick } from '../view/picking.js';
import { bottomSheet } from './bottom_sheet.js';
import { Compare } from './compare_methods.js';
import { EditHistory } from './page_history.js';
import type { PathFile } from './dropped_files.js';
import { FileInput } from './file_input.js';
import { Keyboard } from './keyboard.js';
import { dismissNote, expandNotesOnClick, showMessage, type MessageKind } from './message_line.js';
import { initialSettings, type PageSettings } from './page_settings.js';
import { Panel, type PanelActions } from './panel.js';
import { pageShortcuts } from './page_shortcuts.js';
import { DEFAULT_RIG, FILE_CHOICE, loadProjectRig, loadUserFile, projectRig, rigMenu } from './project_rigs.js';
import { glbExportProblem, looksLikePoseFile } from './pose_files.js';
import { PoseFileActions } from './pose_file_actions.js';
import { rigNameText } from './rig_name.js';
import { showSelection, toggleEffector } from './selection.js';
import { SolveReport } from './solve_report.js';
import { TargetActions } from './target_actions.js';
import type { StatsPanel } from './stats.js';
import { StepMode, type StepHooks } from './step_mode.js';
import { TrackMode } from './track_mode.js';
import { TrackPanel } from './track_panel.js';
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

export class PageApp {
  readonly settings: PageSettings;
  private readonly methods: MethodList;
  readonly controller: LiveController;
  readonly report: SolveReport;
  private readonly compare: Compare;
  private readonly stepMode: StepMode;
  private readonly keyboard: Keyboard;
  private readonly panel: Panel;
  /** The avatar's track mode (the drag mode is put away while it is on). */
  readonly track: TrackMode;
  private readonly trackPanel: TrackPanel;
  /** The gizmo's mode, the target it holds, the target's orientation goal and the pole handles. */
  private readonly targets: TargetActions;
  private readonly files: FileInput;
  private readonly poseFiles: PoseFileActions;
  private readonly removeSheet: () => void;
  /** Undo and redo of edits and rig loads. */
  readonly history: EditHistory;
  /** The selection readout, rewritten a few times a second while the pose changes. */
  private readonly selectionText = new Throttle(() => this.showSelection());
  private rigKey: string | null = null;
  /** The URL's ?chain=: the chain of the URDF shown when not its longest, or the one the next .urdf opened is to show. */
  private chain: string | null;
  private loadToken = 0;
  /** Completed loads, successful or not (for tests and tools). */
  loads = 0;

  constructor(
    private readonly module: IkCoreModule,
    private readonly el: PageElements,
  ) {
    this.methods = new MethodList(module);
    const url = readUrlState();
    this.chain = url.chain;
    this.settings = initialSettings(
      url.rig && projectRig(url.rig) ? url.rig : DEFAULT_RIG,
      this.methods.pick(url.method),
    );

    this.controller = new LiveController(el.viewport, this.settings, this.controllerEvents());
    this.report = new SolveReport(el.side, this.methods, this.controller, this.settings);
    this.compare = new Compare(el.side, this.methods, this.report.plot);
    this.stepMode = new StepMode(el.stepInfo, this.settings, this.methods, this.controller, this.stepHooks());
    this.files = new FileInput(el.root, (f, others) => void this.loadFile(f, others));
    expandNotesOnClick(el.message);
    this.history = new EditHistory(
      this.controller,
      () => this.rigKey,
      (source, key) => this.load(async () => source, source.name, key, false),
      () => this.panel?.showUndo(this.history.canUndo, this.history.canRedo),
    );
    this.poseFiles = new PoseFileActions(
      el.root,
      this.controller,
      this.history,
      (text, kind) => this.showMessage(text, kind),
      () => this.showPoseChanged(),
    );

    const actions = this.panelActions(); // the keys do what the panel's buttons do
    this.panel = new Panel(el.side, this.settings, rigMenu(), this.methods, actions);
    this.track = new TrackMode(module, this.controller, (message) => this.showMessage(message, 'error'));
    this.targets = new TargetActions(this.settings, this.controller, this.track, this.panel, this.history);
    this.trackPanel = new TrackPanel(el.side, this.track);
    this.arrangeSide();
    this.removeSheet = bottomSheet(el.root, el.side);
    this.keyboard = new Keyboard(el.root, pageShortcuts(this.settings, actions, this.targets, this.track));
  }

  // ---- wiring --------------------------------------------------------------------------------

  /** What the page does when the live controller solves, fails, changes, is clicked or dragged. */
  private controllerEvents(): LiveEvents {
    const el = this.el;
    return {
      solved: (outcome, ms, tips) => this.report.solved(outcome, ms, tips),
      failed: (message) => this.showMessage(message, 'error'),
      changed: () => {
        this.track.leave(); // the drag mode's problem changed: it is shown again
        this.stepMode.restart();
      },
      clicked: (c) => this.click(c),
      dragging: (on) => {
        el.root.dataset.dragging = String(on);
        this.history.dragging(on);
        // A note goes once the user works; its line stays (empty), so the view does not move under the drag.
        if (on) dismissNote(el.message);
      },
      redrawn: () => {
        if (this.controller.live?.selectedBone != null) this.selectionText.request(); // its angles changed
      },
      tick: () => this.stepMode.tick(),
      targetChanged: () => this.targets?.showGoals(), // (made after the panel and track mode)
    };
  }

  /** What the page does with a step of step mode. */
  private stepHooks(): StepHooks {
    return {
      stepped: (outcome, ms) => this.report.stepped(outcome, ms),
      failed: (message) => this.showMessage(message, 'error'),
      switchedOn: () => this.panel.refresh(),
      pending: () => this.report.pending(),
    };
  }

  /** What the panel's menus, switches and buttons do. */
  private panelActions(): PanelActions {
    return {
      rigChanged: (key) => (key === FILE_CHOICE ? this.files.choose() : void this.loadProject(key)),
      openFile: () => this.files.choose(),
      chainChanged: (chain) => void this.loadChain(chain),
      limitsChanged: () => this.limitsChanged(),
      methodChanged: () => this.methodChanged(),
      settingsChanged: () => this.controller.invalidate(),
      displayChanged: () => this.applyDisplay(this.controller.live),
      gizmoChanged: () => this.targets.setGizmo(this.settings.gizmo),
      orientationGoalChanged: (on) => this.targets.setOrientationGoal(on),
      poleHandlesChanged: () => this.controller.setPoleHandles(this.settings.poleHandles),
      stepModeChanged: () => this.stepMode.switched(),
      resetPose: () => this.resetPose(),
      undo: () => void this.undo(false),
      redo: () => void this.undo(true),
      savePoseJson: () => this.poseFiles.saveJson(),
      loadPoseJson: () => this.poseFiles.choose(),
      savePosedGlb: () => void this.poseFiles.saveGlb(),
      step: () => this.stepMode.step(),
      compare: () => void this.compare.run(this.controller, this.settings),
      help: () => this.keyboard.toggle(),
    };
  }

  /** The side column's parts, top to bottom. */
  private arrangeSide(): void {
    const el = this.el;
    // The compare's results sit under the stats, in the side column (the bottom sheet on a phone), not over the view.
    el.side.replaceChildren(
      this.report.stats.element,
      el.stepInfo,
      this.compare.view.element,
      this.panel.gui.domElement,
      this.trackPanel.gui.domElement,
      el.selection,
      this.report.plot.element,
    );
  }

  /** Loads the rig named in the URL (or the default). */
  start(): Promise<void> {
    return this.loadProject(this.settings.rig);
  }

  /** The running window of per-frame solve times (ms). */
  get solveTimes(): StatsPanel['median'] {
    return this.report.stats.median;
  }

  async loadProject(key: string): Promise<void> {
    await this.load(() => loadProjectRig(key), projectRig(key)?.file ?? key, key);
  }

  /**
   * Loads a user's rig file (a URDF's chain: the URL's ?chain=, else its longest); a pose file
   * (ik-pose JSON) is applied to the rig shown instead.
   */
  async loadFile(file: File, others: PathFile[] = []): Promise<void> {
    if (/\.json$/i.test(file.name) && looksLikePoseFile(await file.slice(0, 200).text()))
      return this.loadPoseFile(file);
    await this.load(() => loadUserFile(file, { chain: this.chain ?? undefined }, others), file.name, null);
  }

  /** Shows chain `chain` ("BASE:TIP") of the URDF file shown (the panel's chain menu); a refused chain keeps the rig shown. */
  async loadChain(chain: string): Promise<void> {
    const urdf = this.controller.live?.source.urdf;
    if (!urdf || chain === urdf.chain) return;
    await this.load(
      () => readRig(urdf.bytes, urdf.fileName, urdf.readSibling, '', { chain }),
      `${urdf.fileName} (chain ${chain})`,
      null,
    );
  }

  /** Applies a pose file (ik-pose JSON) to the rig shown, as one undoable step; a bad file changes nothing and says why. */
  loadPoseFile(file: File): Promise<void> {
    return this.poseFiles.load(file);
  }

  /** Undoes (redo false) or redoes the last step; a step that cannot be shown says why. */
  async undo(redo: boolean): Promise<void> {
    try {
      if (!(await (redo ? this.history.redo() : this.history.undo()))) return;
    } catch (e) {
      this.showMessage(`Could not ${redo ? 'redo' : 'undo'}: ${errorText(e)}`, 'error');
      return;
    }
    this.showPoseChanged();
  }

  dispose(): void {
    this.loadToken++;
    this.selectionText.cancel();
    this.keyboard.dispose();
    this.removeSheet();
    this.files.dispose();
    this.poseFiles.dispose();
    this.trackPanel.dispose();
    this.track.dispose();
    this.panel.dispose();
    this.compare.dispose();
    this.report.dispose();
    this.controller.dispose();
  }

  // ---- loading -------------------------------------------------------------------------------

  /** Loads a rig and shows it; `undoable`: the rig shown before becomes an undo step. */
  private async load(read: () => Promise<RigSource>, what: string, key: string | null, undoable = true): Promise<void> {
    const token = ++this.loadToken;
    this.el.root.dataset.state = 'loading';
    this.showMessage(`loading ${what}…`, 'info');
    let live: LiveRig;
    try {
      live = await LiveRig.create(this.module, await read(), true, this.settings.humanoidLimits);
    } catch (e) {
      if (token !== this.loadToken) return;
      const shown = this.controller.live;
      this.showMessage(
        `Could not load ${what}: ${errorText(e)}${shown ? ` — still showing ${shown.name}` : ''}`,
        'error',
      );
      this.panel.showRig(this.rigKey ?? FILE_CHOICE);
      this.showChains(shown);
      this.el.root.dataset.state = shown ? 'ready' : 'error';
      this.loads++;
      return;
    }
    if (token !== this.loadToken) {
      live.dispose();
      return;
    }
    if (undoable) this.history.rigReplacing();
    this.install(live, key);
    const notes = live.source.warnings;
    this.showMessage(notes.length ? `${live.name}: ${notes.join('; ')}` : '', 'info');
    this.el.root.dataset.state = 'ready';
    this.loads++;
  }

  private install(live: LiveRig, key: string | null): void {
    this.applyDisplay(live); // before the camera frames the rig: a hidden mesh does not count
    this.track.leave(); // its avatar belongs to the rig shown until now
    this.controller.show(live);
    this.trackPanel.showRig();
    this.controller.handles.setMode(this.settings.gizmo);
    this.rigKey = key;
    this.panel.showRig(key ?? FILE_CHOICE);
    this.panel.showHumanoidLimits(live.hasHumanoidLimits);
    this.showChains(live);
    // The rig's drag tolerances, shown to 3 significant digits in the panel.
    const t = live.tolerances();
    this.settings.tipTolerance = Number(t.tipTolerance.toPrecision(3));
    this.settings.gradientTolerance = Number(t.gradientTolerance.toPrecision(3));
    this.settings.maxJointMove = t.maxJointMove;
    this.panel.refresh();
    const urdf = live.source.urdf;
    if (urdf) this.chain = urdf.chain !== urdf.defaultChain ? urdf.chain : null;
    writeUrlState({ rig: key, method: this.settings.method, chain: this.chain });
    this.showRigName();
    this.el.root.dataset.rig = live.name;
    this.report.reset();
    this.compare.view.hide();
    this.stepMode.restart();
    this.stepMode.clearInfo();
    this.showSelection();
    this.targets.showGoals();
    this.panel.showGlbExport(glbExportProblem(live));
  }

  // ---- panel, keyboard and click actions -----------------------------------------------------

  private methodChanged(): void {
    writeUrlState({ rig: this.rigKey, method: this.settings.method, chain: this.chain });
    this.controller.live?.session.endSteps();
    this.controller.invalidate();
    this.report.showIdle();
  }

  /** The humanoid-limits switch: the rig takes the other limits, keeping its targets, and solves into them. */
  private limitsChanged(): void {
    const live = this.controller.live;
    if (!live?.hasHumanoidLimits) return;
    this.track.leave();
    if (this.controller.paused) {
      // A compare is running on the current session: keep it.
      this.settings.humanoidLimits = !this.settings.humanoidLimits;
      this.panel.refresh();
      return;
    }
    try {
      live.useHumanoidLimits(this.settings.humanoidLimits);
    } catch (e) {
      this.showMessage(`could not switch the limits: ${errorText(e)}`, 'error');
      return;
    }
    this.report.showIdle();
    this.controller.invalidate();
    this.showSelection();
  }

  /** The panel's chain menu for `live`'s URDF file, hidden for other rigs. */
  private showChains(live: LiveRig | null): void {
    const urdf = live?.source.urdf;
    this.panel.showChains(urdf ? urdf.chains : null, urdf?.chain, urdf?.defaultChain);
  }

  private applyDisplay(live: LiveRig | null): void {
    if (!live) return;
    live.view.setMeshVisible(this.settings.showMesh);
    live.view.setBonesVisible(this.settings.showBones || !live.view.hasMesh);
  }

  private resetPose(): void {
    if (!this.controller.live || this.track.reset()) return;
    this.history.edit(() => this.controller.reset());
    this.report.showIdle();
    this.stepMode.clearInfo();
    this.showSelection();
  }

  /** A click that hit no target: the bone under it is selected, and (unless shift) toggled as an end effector. */
  private click(c: ViewClick): void {
    const live = this.controller.live;
    if (!live || this.track.click(c)) return;
    const bone = live.view.pick(c.raycaster, c.pixelSlope);
    live.selectedBone = bone;
    if (bone !== null && !c.shiftKey && this.settings.clickBone === 'toggle effector') {
      if (this.history.edit(() => toggleEffector(this.controller, bone))) {
        this.showRigName();
        this.report.showIdle();
      } else this.showMessage('a rig keeps at least one end effector', 'info');
    }
    this.controller.redraw();
    this.showSelection();
  }

  // ---- text ----------------------------------------------------------------------------------

  private showSelection(): void {
    this.selectionText.cancel();
    showSelection(this.el.selection, this.controller.live, this.settings.humanoidLimits);
  }

  private showRigName(): void {
    const live = this.controller.live;
    if (live) this.el.rigName.textContent = rigNameText(live);
  }

  /** The solve report, the step info, the rig line and the selection after an undo, a redo or a pose file. */
  private showPoseChanged(): void {
    this.report.showIdle();
    this.stepMode.clearInfo();
    this.showRigName();
    this.showSelection();
  }

  /** Shows `text` in the message line (message_line.ts). */
  private showMessage(text: string, kind: MessageKind): void {
    showMessage(this.el.message, text, kind);
  }
}
