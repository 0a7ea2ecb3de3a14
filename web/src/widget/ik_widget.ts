// <ik-widget src="models/lamp.glb" method="lm" effectors="head, 3"></ik-widget>
// One custom element: a rig, its targets and the solver running live, in a shadow root. A click
// or tap on a target gives it the gizmo; the status line says what the last solve reached. Loading
// problems (file, format, WebAssembly, WebGL) show as a message inside the widget and never
// throw into the host page. Names from files are shown as text, never as HTML.
import type { IkCoreModule } from '../ik/module.js';
import { Handles } from '../page/handles.js';
import { LiveRig } from '../page/live_rig.js';
import { solveFrame } from '../page/live_solve.js';
import { listenForClicks, type ViewClick } from '../page/picking.js';
import { loadRigUrl } from '../page/rig_source.js';
import { Stage } from '../page/scene.js';
import { createSolver } from '../page/solvers.js';
import { isMethod, METHOD_LABELS, METHODS, type Method, type SolveSettings } from '../page/solver_port.js';
import type { DragTolerances } from '../rig/tolerances.js';
import { widgetCore } from './core.js';
import { widgetProbe, type WidgetProbe } from './probe.js';
import { showNote, showSolve } from './status_line.js';

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
.message { position: absolute; inset: 0; display: grid; place-items: center; padding: 12px; text-align: center; }
.message[data-kind='error'] { color: #ffd9dc; background: #4a1f25; }
[hidden] { display: none !important; }
`;

function errorText(e: unknown): string {
  return e instanceof Error ? e.message : String(e);
}

export class IkWidget extends HTMLElement {
  static readonly observedAttributes = ['src', 'method', 'effectors'];

  private readonly shadow: ShadowRoot;
  private readonly view: HTMLDivElement;
  private readonly bar: HTMLDivElement;
  private readonly nameEl: HTMLSpanElement;
  private readonly statsEl: HTMLSpanElement;
  private readonly methodSelect: HTMLSelectElement;
  private readonly message: HTMLDivElement;
  private stage: Stage | null = null;
  private handles: Handles | null = null;
  private live: LiveRig | null = null;
  /** The rig's drag tolerances (tip distance and gradient), set with the rig. */
  private tolerances: DragTolerances | null = null;
  private stopClicks: (() => void) | null = null;
  private token = 0;
  private needsSolve = false;
  private needsRedraw = false;

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
    for (const m of METHODS) {
      const o = document.createElement('option');
      o.value = m;
      o.textContent = m;
      o.title = METHOD_LABELS[m];
      this.methodSelect.append(o);
    }
    this.methodSelect.addEventListener('change', () => this.setAttribute('method', this.methodSelect.value));
    const reset = document.createElement('button');
    reset.type = 'button';
    reset.textContent = 'reset';
    reset.addEventListener('click', () => this.resetPose());
    this.statsEl = document.createElement('span');
    this.statsEl.className = 'stats';
    this.bar.append(this.nameEl, this.methodSelect, reset, this.statsEl);
    this.bar.hidden = true;
    this.message = document.createElement('div');
    this.message.className = 'message';
    this.message.setAttribute('role', 'status');
    this.shadow.append(style, this.view, this.bar, this.message);
  }

  /** The method solving every frame (the `method` attribute; lm when absent or unknown). */
  get method(): Method {
    const m = this.getAttribute('method');
    return isMethod(m) ? m : 'lm';
  }

  /** 'loading', 'ready' or 'error' (also the data-state attribute). */
  get state(): string {
    return this.dataset.state ?? 'loading';
  }

  /** For tests and tools: the selected target, targets, tips, the tolerance, the camera; null until ready. */
  get probe(): WidgetProbe | null {
    const { live, handles, stage, tolerances } = this;
    return live && handles && stage && tolerances ? widgetProbe(live, handles, stage, tolerances.tipTolerance) : null;
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
    else if (name === 'method') {
      this.methodSelect.value = this.method;
      this.needsSolve = true;
    } else if (name === 'effectors' && this.live) this.applyEffectors(this.live);
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
    } catch (e) {
      if (token === this.token) this.fail(`ik-widget: the WebAssembly solver could not start: ${errorText(e)}`);
      return;
    }
    try {
      const url = new URL(src, document.baseURI);
      const loaded = await loadRigUrl(url);
      if (token !== this.token) return;
      live = await LiveRig.create(module, loaded, createSolver);
      if (token !== this.token) {
        live.dispose();
        return;
      }
      this.install(live);
    } catch (e) {
      if (live && live !== this.live) live.dispose();
      if (token !== this.token) return;
      this.teardown();
      this.fail(`ik-widget: could not load ${src}: ${errorText(e)}`);
    }
  }

  private install(live: LiveRig): void {
    const stage = new Stage(this.view);
    this.stage = stage;
    const handles = new Handles(stage);
    this.handles = handles;
    stage.connectOrbit(); // after the gizmo: a drag on the gizmo must not orbit
    this.stopClicks = listenForClicks(stage.canvas, stage.camera, () => handles.dragging || handles.hovering, (c) => this.pickTarget(c));
    this.live = live;
    this.tolerances = live.tolerances();
    stage.scene.add(...live.objects);
    live.ghost.root.visible = false;
    handles.setRigSize(live.view.size);
    handles.onTargetMoved = (k, x, y, z) => {
      live.session.targets.set([x, y, z], 3 * k);
      this.needsSolve = true;
      this.needsRedraw = true;
    };
    this.applyEffectors(live);
    stage.frame(live.view.bounds());
    stage.onFrame(() => this.frame());
    this.methodSelect.value = this.method;
    this.nameEl.textContent = live.name;
    this.nameEl.title = `${live.name}: ${live.session.rig.numBones} bones`;
    this.bar.hidden = false;
    this.showMessage('', 'info');
    this.dataset.state = 'ready';
    this.dispatchEvent(new CustomEvent('ik-ready', { detail: { name: live.name } }));
  }

  /** The `effectors` attribute: bone names or indices, separated by commas. */
  private applyEffectors(live: LiveRig): void {
    const attr = this.getAttribute('effectors');
    const unknown: string[] = [];
    if (attr && attr.trim()) {
      const names = live.session.spec.names;
      const bones: number[] = [];
      for (const raw of attr.split(',')) {
        const item = raw.trim();
        if (!item) continue;
        let i = /^\d+$/.test(item) ? Number(item) : names.indexOf(item);
        if (i < 0) i = names.findIndex((n) => n.toLowerCase() === item.toLowerCase());
        if (i >= 0 && i < names.length) {
          if (!bones.includes(i)) bones.push(i);
        } else unknown.push(item);
      }
      if (bones.length) live.session.setEffectors(bones);
    }
    showNote(this.statsEl, unknown.length ? `unknown effector ${unknown.join(', ')}` : '');
    this.handles?.setTargets(live.session.targets);
    this.needsSolve = false;
    this.needsRedraw = true;
  }

  private resetPose(): void {
    const live = this.live;
    if (!live) return;
    live.session.reset();
    this.handles?.setTargets(live.session.targets);
    showNote(this.statsEl, '');
    this.needsSolve = false;
    this.needsRedraw = true;
  }

  /** A click or tap on the view: the target under it, if any, takes the gizmo (and shows as selected). */
  private pickTarget(c: ViewClick): void {
    const k = this.handles?.pick(c.raycaster) ?? null;
    if (k !== null) this.handles?.select(k);
  }

  private frame(): void {
    const { live, handles, tolerances } = this;
    if (!live || !handles || !tolerances) return;
    if (this.needsSolve || handles.dragging) {
      const settings: SolveSettings = {
        tipTolerance: tolerances.tipTolerance,
        gradientTolerance: tolerances.gradientTolerance,
        maxIterations: 50,
        timeBudgetMs: 3,
        restarts: 0,
        paperMode: false,
      };
      try {
        const { outcome: out, ms, again } = solveFrame(live.session, this.method, settings);
        this.needsSolve = again;
        showSolve(this.statsEl, this.method, out, ms);
      } catch (e) {
        this.needsSolve = false;
        showNote(this.statsEl, `solver error: ${errorText(e)}`, 'failed');
      }
      this.needsRedraw = true;
    }
    if (this.needsRedraw) {
      this.needsRedraw = false;
      live.redraw();
      handles.sync(live.session.targets, live.session.tips());
    }
  }

  private teardown(): void {
    this.stopClicks?.();
    this.stopClicks = null;
    this.tolerances = null;
    if (this.live) {
      for (const o of this.live.objects) o.removeFromParent();
      this.live.dispose();
      this.live = null;
    }
    this.handles?.dispose();
    this.handles = null;
    if (this.stage) {
      this.stage.renderer.forceContextLoss();
      this.stage.dispose();
      this.stage = null;
    }
    this.bar.hidden = true;
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
