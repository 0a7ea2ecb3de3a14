// Keyboard shortcuts and the help overlay that lists them (toggled with ?). Shortcuts work
// whatever has the focus except where keys are typed: a text or number field, a text area, a
// select (its letters pick options); a clicked checkbox or button keeps them working. Tab and
// Shift+Tab (focus keys) are shortcuts only while no control has the focus: on a control they
// move the focus, as everywhere.
export interface Shortcut {
  keys: string[];
  /** What the keys do; a function when it depends on a setting (read each time the help opens). */
  label: string | (() => string);
  run(): void;
  /**
   * A key browsers move the focus with (Tab, Shift+Tab): a shortcut only while no control has the
   * focus (the page itself or the view) and the help is closed; elsewhere the browser has it.
   */
  focusKey?: boolean;
}

/** Input types whose keys are not text: a shortcut pressed while one has the focus still runs. */
const NON_TEXT_INPUTS = new Set(['checkbox', 'radio', 'button', 'submit', 'reset', 'range', 'color', 'file', 'image']);

/** Whether keys pressed in `target` are typed into it (so they are no shortcuts). */
export function typingInto(target: EventTarget | null): boolean {
  if (target instanceof HTMLInputElement) return !NON_TEXT_INPUTS.has(target.type);
  if (target instanceof HTMLSelectElement || target instanceof HTMLTextAreaElement) return true;
  return target instanceof HTMLElement && target.isContentEditable;
}

/** Whether keys pressed in `target` go to a control (anything focused but the page itself and the view). */
export function controlFocused(target: EventTarget | null): boolean {
  return (
    target instanceof Element &&
    target !== document.body &&
    target !== document.documentElement &&
    !(target instanceof HTMLCanvasElement)
  );
}

/**
 * The key pressed, as shortcuts name keys, lower case: a letter or symbol ('z', '?'), a named key
 * ('escape', with Shift 'shift+tab'), and with Ctrl (or Cmd) held, 'ctrl+z' / 'ctrl+shift+z'
 * (Shift is named only with Ctrl or a named key: it is how '?' is typed).
 */
export function keyName(e: Pick<KeyboardEvent, 'key' | 'ctrlKey' | 'metaKey' | 'shiftKey'>): string {
  const key = e.key.toLowerCase();
  if (!e.ctrlKey && !e.metaKey) return e.shiftKey && key.length > 1 && key !== 'shift' ? `shift+${key}` : key;
  return `ctrl+${e.shiftKey ? 'shift+' : ''}${key}`;
}

export class Keyboard {
  readonly overlay: HTMLElement;
  private readonly table: HTMLTableElement;
  private readonly onKey: (e: KeyboardEvent) => void;

  constructor(
    parent: HTMLElement,
    private readonly shortcuts: Shortcut[],
  ) {
    this.overlay = document.createElement('div');
    this.overlay.className = 'help-overlay';
    this.overlay.id = 'help';
    this.overlay.hidden = true;
    this.overlay.setAttribute('role', 'dialog');
    this.overlay.setAttribute('aria-label', 'keyboard shortcuts');
    const box = document.createElement('div');
    box.className = 'help-box';
    const h = document.createElement('h2');
    h.textContent = 'Keyboard shortcuts';
    this.table = document.createElement('table');
    const more = document.createElement('p');
    more.textContent =
      'Mouse or touch: drag a target’s gizmo to move it (or, in rotate mode, to turn it: the effector’s bone turns to the target’s axes); drag elsewhere to orbit; click a bone to make its tip an effector or remove it (shift-click only selects it and shows its joint limits); click a target to put the gizmo on it, even one the gizmo’s handles reach over (a click there picks the target, a drag moves the gizmo); with pole handles on (P), click a yellow pole handle and drag it to turn that elbow or knee towards it. Drop a .glb, .gltf or A7 .json file anywhere to load it, or a saved pose (.json) to put that pose on the rig shown.';
    const close = document.createElement('button');
    close.type = 'button';
    close.textContent = 'close';
    close.addEventListener('click', () => this.toggle(false));
    box.append(h, this.table, more, close);
    this.overlay.append(box);
    this.overlay.addEventListener('click', (e) => {
      if (e.target === this.overlay) this.toggle(false);
    });
    parent.append(this.overlay);

    this.onKey = (e: KeyboardEvent) => {
      if (e.altKey) return;
      if (typingInto(e.target)) return;
      if (e.key === 'Escape' && !this.overlay.hidden) {
        this.toggle(false);
        return;
      }
      const key = keyName(e);
      const s = this.shortcuts.find((x) => x.keys.some((k) => k.toLowerCase() === key));
      if (!s || (s.focusKey && (controlFocused(e.target) || !this.overlay.hidden))) return;
      e.preventDefault();
      s.run();
    };
    // Capture: lil-gui stops every key event inside its controllers from bubbling (a clicked checkbox keeps the focus).
    window.addEventListener('keydown', this.onKey, true);
  }

  toggle(show = this.overlay.hidden): void {
    if (show) this.listShortcuts();
    this.overlay.hidden = !show;
  }

  dispose(): void {
    window.removeEventListener('keydown', this.onKey, true);
    this.overlay.remove();
  }

  private listShortcuts(): void {
    this.table.replaceChildren();
    for (const s of this.shortcuts) {
      const tr = this.table.insertRow();
      const k = tr.insertCell();
      s.keys.forEach((key, i) => {
        if (i) k.append(' / ');
        const kbd = document.createElement('kbd');
        kbd.textContent = key;
        k.append(kbd);
      });
      tr.insertCell().textContent = typeof s.label === 'function' ? s.label() : s.label;
    }
  }
}
