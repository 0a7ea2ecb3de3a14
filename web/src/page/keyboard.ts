// Keyboard shortcuts and the help overlay that lists them (toggled with ?).
export interface Shortcut {
  keys: string[];
  /** What the keys do; a function when it depends on a setting (read each time the help opens). */
  label: string | (() => string);
  run(): void;
}

export class Keyboard {
  readonly overlay: HTMLElement;
  private readonly table: HTMLTableElement;
  private readonly onKey: (e: KeyboardEvent) => void;

  constructor(parent: HTMLElement, private readonly shortcuts: Shortcut[]) {
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
      'Mouse or touch: drag a target’s gizmo to move it (or, in rotate mode, to turn it: the effector’s bone turns to the target’s axes); drag elsewhere to orbit; click a bone to make its tip an effector or remove it (shift-click only selects it and shows its joint limits); click a target to put the gizmo on it. Drop a .glb, .gltf or A7 .json file anywhere to load it.';
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
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      const t = e.target;
      if (t instanceof HTMLInputElement || t instanceof HTMLSelectElement || t instanceof HTMLTextAreaElement) return;
      if (e.key === 'Escape' && !this.overlay.hidden) {
        this.toggle(false);
        return;
      }
      const key = e.key.length === 1 ? e.key.toLowerCase() : e.key;
      const s = this.shortcuts.find((x) => x.keys.some((k) => k.toLowerCase() === key));
      if (!s) return;
      e.preventDefault();
      s.run();
    };
    window.addEventListener('keydown', this.onKey);
  }

  toggle(show = this.overlay.hidden): void {
    if (show) this.listShortcuts();
    this.overlay.hidden = !show;
  }

  dispose(): void {
    window.removeEventListener('keydown', this.onKey);
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
