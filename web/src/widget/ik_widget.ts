// <ik-widget src="models/lamp.glb" method="lm" effectors="head, 3" goals="head:pose"></ik-widget>
// One custom element: a rig, its targets and the solver running live, in a shadow root. A click
// or tap on a target gives it the gizmo; the status line says what the last solve reached. The
// `goals` attribute gives named effectors orientation goals (goal_kinds.ts): their targets start
// at the bone's current frame, and the bar's "turn" button switches the gizmo to rotating them
// (an orientation-only target always rotates). Unknown names in `effectors` or `goals` show in
// the status line. Loading problems (file, format, WebAssembly, WebGL) show as a message inside
// the widget and never throw into the host page. Names from files are shown as text, never as
// HTML. The frame loop, the solve and the gizmo are web/src/live/'s LiveController, as on the page.
import type { IkCoreModule } from '../ik/module.js';
import { errorText } from '../live/error_text.js';
import { FRAME_DEFAULTS } from '../live/live_solve.js';
import { LiveController, type FrameSettings } from '../view/live_controller.js';
import { LiveRig } from '../view/live_rig.js';
import { MethodList } from '../live/methods.js';
import { loadRigUrl } from '../view/rig_source.js';
import { widgetCore } from './core.js';
import { findBone, parseGoalKinds } from './goal_kinds.js';
import { widgetProbe, type WidgetProbe } from './probe.js';
import { StatusLine } from './status_line.js';

const STYLE = `
:host { display: block; position: relative; height: 320px; min-height: 160px; background: #20242b; color: #dfe4ea;
  font: 12px/1.4 system-ui, sans-serif; border-radius: 6px; overflow: hidden; contain: content; }
:host([hidden]) { display: none; }
.view { position: absolute; inset: 0; }
.bar { position: absolute; left: 0; right: 0; bottom: 0; display: flex; flex-wrap: wrap; gap: 2px 8px; align-items: center; padding: 4px 8px;
  background: #171a1fcc; font-variant-numeric: tabular-nums; }
.bar .name { color: #ffb454; overflow: hidden; text-overflow: ellipsis; white-space: nowrap; }
.bar .stats { margin-left: auto; text-align: right; }
.bar select, .bar button { font: inherit; background: #2a2f37; color: inherit; border: 1px solid #3a414c; border-radius: 3px; }
.bar button[aria-pressed='true'] { background: #3d4654; border-color: #ffb454; }
.message { position: absolute; inset: 0; display: grid; place-items: center; padding: 12px; text-align: center; }
.message[data-kind='error'] { color: #ffd9dc; background: #4a1f25; }
[hidden] { display: none !important; }
`;

export class IkWidget extends HTMLElement {
  static readonly observedAttributes = ['src', 'method', 'effectors', 'goals'];

  private readonly shadow: ShadowRoot;
  private readonly view: HTMLDivElement;
  private readonly bar: HTMLDivElement;
  private readonly nameEl: HTMLSpanElement;
  private readonly status: StatusLine;
  private readonly methodSelect: HTMLSelectElement;
  /** Switches the gizmo between moving and turning a target that has a pose goal. */
  private readonly turnButton: HTMLButtonElement;
  /** The gizmo turns pose targets (the turn button is pressed). */
  private turning = false;
  private readonly message: HTMLDivElement;
  /** The core's methods, once it has loaded. */
  private methods: MethodList | null = null;
  private controller: LiveController | null = null;
  /** The per-frame solve: the `method` attribute, the rig's drag tolerances, 50 iterations or 3 ms. */
  private readonly settings: FrameSettings = {
    method: '',
    gradientTolerance: 0,
    tipTolerance: 0,
    ...FRAME_DEFAULTS,
    paperMode: false,
  };
  private token = 0;

  constructor() {
    super();
    this.shadow = this.attachShadow({ mode: 'open' });
    const style = document.createElement('style');
    style.textContent = STYLE;
    this.view = document.createElement('div');
    this.view.className = 'view';
    this.bar = document.createElement('div');
    this.bar.className = 'bar';
    this.nameEl = document.createElement('span');
    this.nameEl.className = 'name';
    this.methodSelect = document.createElement('select');
    this.methodSelect.title = 'IK method';
    this.methodSelect.addEventListener('change', () => this.setAttribute('method', this.methodSelect.value));
    const reset = document.createElement('button');
    reset.type = 'button';
    reset.textContent = 'reset';
    reset.addEventListener('click', () => this.resetPose());
    this.turnButton = document.createElement('button');
    this.turnButton.type = 'button';
    this.turnButton.className = 'turn';
    this.turnButton.textContent = 'turn';
    this.turnButton.title = 'rotate the selected target: the bone turns to its orientation';
    this.turnButton.hidden = true;
    this.turnButton.setAttribute('aria-pressed', 'false');
    this.turnButton.addEventListener('click', () => {
      this.turning = !this.turning;
      this.useGizmo();
    });
    const stats = document.createElement('span');
    stats.className = 'stats';
    this.status = new StatusLine(stats);
    this.bar.append(this.nameEl, this.methodSelect, reset, this.turnButton, stats);
    this.bar.hidden = true;
    this.message = document.createElement('div');
    this.message.className = 'message';
    this.message.setAttribute('role', 'status');
    this.shadow.append(style, this.view, this.bar, this.message);
  }

  /**
   * The method solving every frame: the `method` attribute when the core registers it, else the
   * core's default (lm). Until the WebAssembly core has loaded, the attribute as written ('' if none).
   */
  get method(): string {
    const m = this.getAttribute('method');
    return this.methods ? this.methods.pick(m) : (m ?? '');
  }

  /** 'loading', 'ready' or 'error' (also the data-state attribute). */
  get state(): string {
    return this.dataset.state ?? 'loading';
  }

  /** For tests and tools: the selected target, targets, tips, the tolerance, the camera; null until ready. */
  get probe(): WidgetProbe | null {
    return this.controller ? widgetProbe(this.controller) : null;
  }

  connectedCallback(): void {
    void this.load();
  }

  disconnectedCallback(): void {
    this.token++;
    this.teardown();
  }

  attributeChangedCallback(name: string, before: string | null, after: string | null): void {
    if (!this.isConnected || before === after) return;
    if (name === 'src') void this.load();
    else if (name === 'method') this.useMethod();
    else if (name === 'effectors' || name === 'goals') this.applyTargets();
  }

  private async load(): Promise<void> {
    const token = ++this.token;
    this.teardown();
    this.dataset.state = 'loading';
    const src = this.getAttribute('src');
    if (!src) {
      this.fail('ik-widget: set the src attribute to a .glb, .gltf or A7 .json rig');
      return;
    }
    this.showMessage(`loading ${src}…`, 'info');
    let module: IkCoreModule;
    let live: LiveRig | null = null;
    try {
      module = await widgetCore();
      this.listMethods(module);
    } catch (e) {
      if (token === this.token) this.fail(`ik-widget: the WebAssembly solver could not start: ${errorText(e)}`);
      return;
    }
    try {
      const url = new URL(src, document.baseURI);
      const loaded = await loadRigUrl(url);
      if (token !== this.token) return;
      live = await LiveRig.create(module, loaded);
      if (token !== this.token) {
        live.dispose();
        return;
      }
      this.install(live);
    } catch (e) {
      if (live && live !== this.controller?.live) live.dispose();
      if (token !== this.token) return;
      this.teardown();
      this.fail(`ik-widget: could not load ${src}: ${errorText(e)}`);
    }
  }

  /** Fills the method menu from the core's registry (once). */
  private listMethods(module: IkCoreModule): void {
    if (this.methods) return;
    const methods = new MethodList(module);
    this.methods = methods;
    for (const m of methods.names) {
      const o = document.createElement('option');
      o.value = m;
      o.textContent = m;
      o.title = methods.describe(m);
      this.methodSelect.append(o);
    }
  }

  private install(live: LiveRig): void {
    const tolerances = live.tolerances();
    this.settings.tipTolerance = tolerances.tipTolerance;
    this.settings.gradientTolerance = tolerances.gradientTolerance;
    this.settings.maxJointMove = tolerances.maxJointMove;
    this.settings.method = this.methodSelect.value = this.method;
    const controller = new LiveController(this.view, this.settings, {
      solved: (outcome, ms) =>
        this.status.show(this.settings.method, outcome, ms, controller.live?.session.orientationErrorDeg() ?? NaN),
      failed: (message) => this.status.note(message, 'failed'),
      targetChanged: () => this.useGizmo(),
    });
    this.controller = controller;
    controller.show(live);
    this.applyTargets();
    this.nameEl.textContent = live.name;
    this.nameEl.title = `${live.name}: ${live.session.rig.numBones} bones`;
    this.bar.hidden = false;
    this.showMessage('', 'info');
    this.dataset.state = 'ready';
    this.dispatchEvent(new CustomEvent('ik-ready', { detail: { name: live.name } }));
  }

  private useMethod(): void {
    this.settings.method = this.methodSelect.value = this.method;
    this.controller?.invalidate();
  }

  /** The `effectors` and `goals` attributes, applied in that order; what could not be read shows in the status line. */
  private applyTargets(): void {
    let problems: string[];
    try {
      problems = [...this.applyEffectors(), ...this.applyGoals()];
    } catch (e) {
      problems = [`ik-widget: ${errorText(e)}`]; // e.g. more end effectors than the core takes
    }
    this.status.problem(problems.join('; '));
    this.useGizmo();
  }

  /** The `effectors` attribute: bone names or indices, separated by commas. Returns what could not be read. */
  private applyEffectors(): string[] {
    const controller = this.controller;
    const live = controller?.live;
    const attr = this.getAttribute('effectors');
    if (!controller || !live || !attr?.trim()) return [];
    const names = live.session.spec.names;
    const bones: number[] = [];
    const unknown: string[] = [];
    for (const raw of attr.split(',')) {
      const item = raw.trim();
      if (!item) continue;
      const i = findBone(names, item);
      if (i < 0) unknown.push(item);
      else if (!bones.includes(i)) bones.push(i);
    }
    if (bones.length) controller.setEffectors(bones);
    return unknown.length ? [`unknown effector ${unknown.join(', ')}`] : [];
  }

  /**
   * The `goals` attribute (goal_kinds.ts): a named bone that is not an end effector becomes one;
   * orientation goals start at the bone's current frame; effectors not named keep a position goal
   * only. Returns what could not be read.
   */
  private applyGoals(): string[] {
    const controller = this.controller;
    const live = controller?.live;
    if (!controller || !live) return [];
    const { goals, problems } = parseGoalKinds(this.getAttribute('goals') ?? '', live.session.spec.names);
    const effectors = Array.from(live.session.effectors());
    const missing = goals.map((g) => g.bone).filter((b) => !effectors.includes(b));
    if (missing.length) controller.setEffectors([...effectors, ...missing]);
    const list = Array.from(live.session.effectors());
    list.forEach((bone, k) => {
      const kind = goals.find((g) => g.bone === bone)?.kind ?? 'position';
      controller.setPositionGoal(k, kind !== 'orientation');
      controller.setOrientationGoal(k, kind !== 'position');
    });
    return problems;
  }

  /** The gizmo for the selected target: rotate for an orientation-only goal, the turn button's choice for a pose goal, else translate. */
  private useGizmo(): void {
    const controller = this.controller;
    const goals = controller?.live?.session.goals;
    const k = controller?.handles.selected ?? null;
    if (!controller || !goals) return;
    const turnable = k !== null && goals.orientation[k] === 1;
    const pose = turnable && goals.position[k] === 1;
    this.turnButton.hidden = !pose;
    this.turnButton.setAttribute('aria-pressed', String(this.turning));
    const mode = turnable && (!pose || this.turning) ? 'rotate' : 'translate';
    if (controller.handles.gizmoMode !== mode) controller.handles.setMode(mode);
  }

  private resetPose(): void {
    this.controller?.reset();
    this.status.note('');
    this.applyTargets(); // the attribute's goals again, at the rest pose
  }

  private teardown(): void {
    this.status.problem('');
    this.status.note('');
    this.controller?.dispose();
    this.controller = null;
    this.bar.hidden = true;
    this.turning = false;
  }

  private fail(text: string): void {
    this.dataset.state = 'error';
    this.showMessage(text, 'error');
  }

  private showMessage(text: string, kind: 'info' | 'error'): void {
    this.message.textContent = text;
    this.message.dataset.kind = kind;
    this.message.hidden = text === '';
  }
}

if (!customElements.get('ik-widget')) customElements.define('ik-widget', IkWidget);
