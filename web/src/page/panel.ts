// The method panel (lil-gui): rig choice (and a URDF file's chain), pose (undo, redo, files),
// method (the core's registered methods), tolerances, per-frame budget, display options and the
// teaching actions. It edits a PageSettings record and calls the page back; every label it shows
// is set as text by lil-gui.
// Its folders open one at a time (opening one closes the others), so the panel fits the screen
// and every folder's title is in view without scrolling.
import GUI, { type Controller } from 'lil-gui';

import type { MethodList } from '../live/methods.js';
import type { PageSettings } from './page_settings.js';

export interface PanelActions {
  rigChanged(key: string): void;
  openFile(): void;
  /** The URDF chain menu's choice, "BASE:TIP". */
  chainChanged(chain: string): void;
  limitsChanged(): void;
  methodChanged(): void;
  settingsChanged(): void;
  displayChanged(): void;
  gizmoChanged(): void;
  /** The selected target's "orientation goal" box was ticked (true) or cleared (false). */
  orientationGoalChanged(on: boolean): void;
  /** The "pole handles" box was ticked or cleared (settings.poleHandles says which). */
  poleHandlesChanged(): void;
  stepModeChanged(): void;
  resetPose(): void;
  undo(): void;
  redo(): void;
  savePoseJson(): void;
  loadPoseJson(): void;
  savePosedGlb(): void;
  step(): void;
  compare(): void;
  help(): void;
}

export class Panel {
  readonly gui: GUI;
  /** The top-level folders, opened one at a time. */
  private readonly folders: GUI[];
  private readonly rigController: Controller;
  private readonly humanoidController: Controller;
  /** The URDF file's chain ("BASE:TIP"), as the chain menu shows it. */
  private readonly urdf = { chain: '' };
  private readonly chainController: Controller;
  /** The selected target's goals, as the panel shows them. */
  private readonly target = { orientationGoal: false };
  private readonly orientationController: Controller;
  private readonly undoController: Controller;
  private readonly redoController: Controller;
  private readonly glbController: Controller;

  constructor(
    container: HTMLElement,
    readonly settings: PageSettings,
    rigs: Record<string, string>,
    methods: MethodList,
    actions: PanelActions,
  ) {
    this.gui = new GUI({ container, title: 'IK controls' });

    const rig = this.gui.addFolder('Rig');
    this.rigController = this.addRigChoice(rig, rigs, actions);
    this.chainController = this.addChainMenu(rig, actions);
    this.humanoidController = this.addHumanoidSwitch(rig, actions);
    this.addDisplaySwitches(rig, actions);
    this.orientationController = this.addEditTools(rig, actions);

    const pose = this.gui.addFolder('Pose');
    this.undoController = pose.add({ undo: () => actions.undo() }, 'undo').name('undo (Ctrl+Z)');
    this.redoController = pose.add({ redo: () => actions.redo() }, 'redo').name('redo (Ctrl+Shift+Z)');
    this.glbController = this.addPoseFiles(pose, actions);
    this.showUndo(false, false);

    const solver = this.gui.addFolder('Solver (every frame)');
    this.addSolverSettings(solver, methods, actions);
    this.addSolverSwitches(solver, actions);

    const teach = this.gui.addFolder('Teaching');
    this.addTeaching(teach, actions);

    this.folders = [rig, pose, solver, teach];
    this.openOneAtATime(rig);
  }

  // ---- the Rig folder ------------------------------------------------------------------------

  /** The project rig menu and the button that opens a file; returns the menu. */
  private addRigChoice(rig: GUI, rigs: Record<string, string>, actions: PanelActions): Controller {
    const menu = rig
      .add(this.settings, 'rig', rigs)
      .name('project rig')
      .onChange((v: string) => actions.rigChanged(v));
    rig.add({ open: () => actions.openFile() }, 'open').name('open .glb / .gltf / .json / .urdf…');
    return menu;
  }

  /** A URDF file's chain menu, hidden until a URDF rig is shown (showChains). */
  private addChainMenu(rig: GUI, actions: PanelActions): Controller {
    const menu = rig
      .add(this.urdf, 'chain', [])
      .name('chain')
      .onChange((v: string) => actions.chainChanged(v));
    menu.domElement.title =
      'the URDF robot’s serial chain shown, BASE:TIP (its tip is the end effector); ?chain=BASE:TIP in the URL picks it too';
    menu.hide();
    return menu;
  }

  /** The humanoid-limits switch, hidden until a rig that has them is shown (showHumanoidLimits). */
  private addHumanoidSwitch(rig: GUI, actions: PanelActions): Controller {
    const box = rig
      .add(this.settings, 'humanoidLimits')
      .name('humanoid limits')
      .onChange(() => actions.limitsChanged());
    box.hide();
    return box;
  }

  /** Whether the rig's mesh and its bones are drawn. */
  private addDisplaySwitches(rig: GUI, actions: PanelActions): void {
    rig
      .add(this.settings, 'showMesh')
      .name('show mesh')
      .onChange(() => actions.displayChanged());
    rig
      .add(this.settings, 'showBones')
      .name('show bones')
      .onChange(() => actions.displayChanged());
  }

  /**
   * How the pose is edited: a click on a bone, the gizmo's mode, the selected target's orientation
   * goal, the pole handles and the pose's reset; returns the orientation goal's box.
   */
  private addEditTools(rig: GUI, actions: PanelActions): Controller {
    const s = this.settings;
    rig.add(s, 'clickBone', ['toggle effector', 'select only']).name('click on a bone');
    rig
      .add(s, 'gizmo', ['translate', 'rotate', 'swing'])
      .name('gizmo (W / E / Q)')
      .onChange(() => actions.gizmoChanged());
    const orientation = rig
      .add(this.target, 'orientationGoal')
      .name('orientation goal (O)')
      .onChange((on: boolean) => actions.orientationGoalChanged(on));
    orientation.domElement.title =
      'the selected target also sets its effector bone’s orientation (turn it with the rotate gizmo, E)';
    rig
      .add(s, 'poleHandles')
      .name('pole handles (P)')
      .onChange(() => actions.poleHandlesChanged()).domElement.title =
      'a yellow handle per arm and leg: drag it to turn the elbow or knee towards it (the tips stay on their targets)';
    rig.add({ reset: () => actions.resetPose() }, 'reset').name('reset pose (R)');
    return orientation;
  }

  // ---- the Pose, Solver and Teaching folders -------------------------------------------------

  /** Saving and loading the pose (.json) and saving the posed model (.glb); returns the .glb button. */
  private addPoseFiles(pose: GUI, actions: PanelActions): Controller {
    pose.add({ save: () => actions.savePoseJson() }, 'save').name('save pose (.json)');
    pose.add({ load: () => actions.loadPoseJson() }, 'load').name('load pose (.json)…');
    return pose.add({ glb: () => actions.savePosedGlb() }, 'glb').name('save posed model (.glb)');
  }

  /** The method, its tolerances, its iterations and time per frame, and paper mode. */
  private addSolverSettings(solver: GUI, methods: MethodList, actions: PanelActions): void {
    const s = this.settings;
    solver
      .add(s, 'method', [...methods.names])
      .name('method')
      .onChange(() => actions.methodChanged());
    solver
      .add(s, 'tipTolerance')
      .name('on target within (distance)')
      .onChange(() => actions.settingsChanged());
    solver
      .add(s, 'gradientTolerance')
      .name('‖∇E‖ tolerance')
      .onChange(() => actions.settingsChanged());
    solver
      .add(s, 'maxIterations', 1, 1000, 1)
      .name('iterations / frame')
      .onChange(() => actions.settingsChanged());
    solver
      .add(s, 'timeBudgetMs', 0.25, 16, 0.25)
      .name('ms budget / frame')
      .onChange(() => actions.settingsChanged());
    solver
      .add(s, 'paperMode')
      .name('paper mode (the report’s algorithms)')
      .onChange(() => actions.settingsChanged());
  }

  /** What the other targets and the body keep while one target is dragged (each with its tooltip). */
  private addSolverSwitches(solver: GUI, actions: PanelActions): void {
    const s = this.settings;
    solver
      .add(s, 'strictPriority')
      .name('strict priority')
      .onChange(() => actions.settingsChanged())
      .domElement.setAttribute(
        'title',
        'on: targets that can be met stay met, the dragged one gives way; off: the least-squares point of all targets, which pulls the pinned ones off theirs (the report’s wobble)',
      );
    solver
      .add(s, 'pinOrientations')
      .name('pin orientations')
      .onChange(() => actions.settingsChanged())
      .domElement.setAttribute(
        'title',
        'on: while a target is dragged, the other end effectors keep their turn as well as their place (given up before the place when their chain cannot keep both); off: only their places are pinned',
      );
    solver
      .add(s, 'stillBody')
      .name('still body (no humanoid map)')
      .onChange(() => actions.settingsChanged())
      .domElement.setAttribute(
        'title',
        'on a rig not recognised as a humanoid: the bones the dragged target’s limb does not need alone keep their pose, so lifting a paw moves only its leg (the body still follows a target the limb cannot reach); off: the least change over the whole body',
      );
  }

  /** Step mode and its tick, compare and its settings, and the keyboard help. */
  private addTeaching(teach: GUI, actions: PanelActions): void {
    const s = this.settings;
    teach
      .add(s, 'stepMode')
      .name('step mode')
      .onChange(() => actions.stepModeChanged());
    teach.add({ step: () => actions.step() }, 'step').name('one iteration (S)');
    teach.add(s, 'autoStep').name('slow tick');
    teach.add(s, 'stepIntervalMs', 100, 3000, 50).name('tick (ms)');
    teach.add({ compare: () => actions.compare() }, 'compare').name('compare all methods (C)');
    teach.add(s, 'compareFrom', ['current pose', 'rest pose']).name('compare: start from');
    teach.add(s, 'compareTimeBudgetMs', 10, 5000, 10).name('compare: ms budget');
    teach.add(s, 'compareMaxIterations', 1, 100000, 1).name('compare: iterations');
    teach.add(s, 'restarts', 0, 20, 1).name('compare: restarts');
    teach.add({ help: () => actions.help() }, 'help').name('keyboard help (?)');
  }

  /** Leaves `first` the only folder open; from then on, opening a folder closes the others. */
  private openOneAtATime(first: GUI): void {
    for (const f of this.folders) if (f !== first) f.close();
    this.gui.onOpenClose((changed) => {
      if (changed._closed || !this.folders.includes(changed)) return;
      for (const f of this.folders) if (f !== changed) f.close();
    });
  }

  /** Re-reads every value (after keyboard shortcuts or URL changes). */
  refresh(): void {
    for (const c of this.gui.controllersRecursive()) c.updateDisplay();
  }

  /** Shows whether the selected target has an orientation goal; `selected` false: no target is selected (the box is disabled). */
  showOrientationGoal(on: boolean, selected: boolean): void {
    this.target.orientationGoal = on;
    this.orientationController.enable(selected);
    this.orientationController.updateDisplay();
  }

  /** Enables undo and redo as there are steps to take. */
  showUndo(canUndo: boolean, canRedo: boolean): void {
    this.undoController.enable(canUndo);
    this.redoController.enable(canRedo);
  }

  /** Enables "save posed model" when `problem` is null; else disables it with `problem` as its tooltip. */
  showGlbExport(problem: string | null): void {
    this.glbController.enable(problem === null);
    this.glbController.domElement.title =
      problem ?? 'the rig’s file with the solved joint rotations written into its nodes';
  }

  /** Shows the rig choice without calling back (e.g. a dropped file: no project rig selected). */
  showRig(key: string): void {
    this.settings.rig = key;
    this.rigController.updateDisplay();
  }

  /**
   * The chain menu: shown with `chains` ("BASE:TIP") and `chain` chosen for a URDF rig, the
   * importer's default chain (`longest`) marked; hidden for any other rig (null).
   */
  showChains(chains: readonly string[] | null, chain = '', longest: string | null = null): void {
    this.chainController.show(chains !== null);
    if (!chains) return;
    this.urdf.chain = chain;
    this.chainController.options(Object.fromEntries(chains.map((c) => [c === longest ? `${c} (longest)` : c, c])));
  }

  /** Shows the humanoid-limits switch only for a rig that has humanoid limits. */
  showHumanoidLimits(available: boolean): void {
    this.humanoidController.show(available);
  }

  dispose(): void {
    this.gui.destroy();
  }
}
