// Files from the user: a hidden file chooser and, optionally, drag-and-drop anywhere on the page.
// Several files (chosen together, or a folder dropped) come as the rig file and the files beside it
// (dropped_files.ts).
import { chosenFiles, droppedFiles, type PathFile, pickRigFile } from './dropped_files.js';

export const RIG_FILE_TYPES = '.glb,.gltf,.json,.urdf';
/** The files a rig file may refer to, chosen with it: a URDF's meshes, a .gltf's buffers and images. */
const SIDE_FILE_TYPES = '.stl,.dae,.bin,.png,.jpg,.jpeg,.webp,.ktx2';

/** What the user gave: a file, and the other files given with it (a URDF's meshes; none for one file). */
export type OnFile = (file: File, others: PathFile[]) => void;

export class FileInput {
  private readonly input: HTMLInputElement;
  private readonly cleanup: () => void;

  /**
   * A chooser for `accept` (file types) with element id `id`; `acceptDrops`: files and folders
   * dropped on the page come here too, and the chooser takes several files (the rig file is picked
   * among them, pickRigFile).
   */
  constructor(root: HTMLElement, onFile: OnFile, accept = RIG_FILE_TYPES, id = 'rig-file', acceptDrops = true) {
    this.input = document.createElement('input');
    this.input.type = 'file';
    this.input.accept = acceptDrops ? `${accept},${SIDE_FILE_TYPES}` : accept;
    this.input.multiple = acceptDrops;
    this.input.hidden = true;
    this.input.id = id;
    const give = (files: PathFile[]): void => {
      const { rig, others } = acceptDrops ? pickRigFile(files) : { rig: files[0], others: [] };
      // Nothing of a rig type among several files: the first, so the page says what it is not.
      const main = rig ?? files[0];
      if (main) onFile(main.file, rig ? others : files.slice(1));
    };
    this.input.addEventListener('change', () => {
      const files = this.input.files ? chosenFiles(this.input.files) : [];
      this.input.value = '';
      give(files);
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
      const data = e.dataTransfer;
      if (!data || data.files.length === 0) return;
      e.preventDefault();
      void droppedFiles(data).then(give);
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
