// The panel's pose files (its Pose folder): a pose file (ik-pose JSON) chosen or dropped is applied
// to the rig shown as one undoable step; the pose is saved as JSON and the posed model as .glb
// (pose_files.ts reads and writes them). A file that cannot be read or written changes nothing and
// the message line says why.
import { errorText } from '../live/error_text.js';
import type { LiveController } from '../view/live_controller.js';
import type { EditHistory } from './page_history.js';
import { FileInput } from './file_input.js';
import type { MessageKind } from './message_line.js';
import { download, fileStem, posedGlbBytes, poseJsonText, readPoseFile } from './pose_files.js';

export class PoseFileActions {
  /** The hidden chooser of "load pose (.json)…". */
  private readonly chooser: FileInput;

  /** `say` shows a message; `poseLoaded` shows the page anew after a pose file was applied. */
  constructor(
    root: HTMLElement,
    private readonly controller: LiveController,
    private readonly history: EditHistory,
    private readonly say: (text: string, kind: MessageKind) => void,
    private readonly poseLoaded: () => void,
  ) {
    this.chooser = new FileInput(root, (f) => void this.load(f), '.json', 'pose-file', false);
  }

  /** Opens the chooser of a pose file. */
  choose(): void {
    this.chooser.choose();
  }

  /** Applies a pose file to the rig shown, as one undoable step; a bad file changes nothing and says why. */
  async load(file: File): Promise<void> {
    const live = this.controller.live;
    if (!live) return this.say(`Could not load ${file.name}: no rig is loaded`, 'error');
    try {
      const { state, warnings } = await readPoseFile(file, live);
      this.history.edit(() => this.controller.restore(state));
      this.poseLoaded();
      this.say(`${file.name}: pose loaded${warnings.length ? ` (${warnings.join('; ')})` : ''}`, 'info');
    } catch (e) {
      this.say(`Could not load ${file.name}: ${errorText(e)}`, 'error');
    }
  }

  /** Downloads the pose of the rig shown as a pose file (ik-pose JSON). */
  saveJson(): void {
    const live = this.controller.live;
    if (!live) return;
    try {
      download(poseJsonText(live), `${fileStem(live.name)}-pose.json`, 'application/json');
    } catch (e) {
      this.say(`Could not save the pose: ${errorText(e)}`, 'error');
    }
  }

  /** Downloads the rig shown as its glTF file posed (.glb). */
  async saveGlb(): Promise<void> {
    const live = this.controller.live;
    if (!live) return;
    try {
      download(await posedGlbBytes(live), `${fileStem(live.name)}-posed.glb`, 'model/gltf-binary');
    } catch (e) {
      this.say(`Could not save the posed model: ${errorText(e)}`, 'error');
    }
  }

  /** Removes the chooser. */
  dispose(): void {
    this.chooser.dispose();
  }
}
