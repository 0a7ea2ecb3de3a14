// Files from the user: a hidden file chooser and, optionally, drag-and-drop anywhere on the page.
export const RIG_FILE_TYPES = '.glb,.gltf,.json,.urdf';

export class FileInput {
  private readonly input: HTMLInputElement;
  private readonly cleanup: () => void;

  /** A chooser for `accept` (file types) with element id `id`; `acceptDrops`: files dropped on the page come here too. */
  constructor(root: HTMLElement, onFile: (file: File) => void, accept = RIG_FILE_TYPES, id = 'rig-file', acceptDrops = true) {
    this.input = document.createElement('input');
    this.input.type = 'file';
    this.input.accept = accept;
    this.input.hidden = true;
    this.input.id = id;
    this.input.addEventListener('change', () => {
      const f = this.input.files?.[0];
      this.input.value = '';
      if (f) onFile(f);
    });
    root.append(this.input);
    if (!acceptDrops) {
      this.cleanup = () => this.input.remove();
      return;
    }

    const over = (e: DragEvent): void => {
      if (!e.dataTransfer?.types.includes('Files')) return;
      e.preventDefault();
      e.dataTransfer.dropEffect = 'copy';
      root.classList.add('drop-target');
    };
    const leave = (e: DragEvent): void => {
      if (e.relatedTarget === null) root.classList.remove('drop-target');
    };
    const drop = (e: DragEvent): void => {
      root.classList.remove('drop-target');
      const f = e.dataTransfer?.files[0];
      if (!f) return;
      e.preventDefault();
      onFile(f);
    };
    window.addEventListener('dragover', over);
    window.addEventListener('dragleave', leave);
    window.addEventListener('drop', drop);
    this.cleanup = () => {
      window.removeEventListener('dragover', over);
      window.removeEventListener('dragleave', leave);
      window.removeEventListener('drop', drop);
      this.input.remove();
    };
  }

  choose(): void {
    this.input.click();
  }

  dispose(): void {
    this.cleanup();
  }
}
