// The Track panel (lil-gui, under the page's panel): track mode on or off (T), the clip to play and
// play / stop, "enter VR" where the browser offers immersive VR, and a status line: what the
// avatar's last solve reached, in words (the head and hands on their points), whether the feet
// stand where they are planted (or one steps), and the time per solve. It shows what TrackMode
// says and calls it; it changes nothing else.
import GUI, { type Controller } from 'lil-gui';

import { statusWords } from '../live/status_words.js';
import { Throttle } from '../live/throttle.js';
import { DRAG_TIP_SHARE } from '../rig/tolerances.js';
import { formatNumber } from './stats.js';
import type { TrackMode } from './track_mode.js';
import { immersiveVrSupported } from './xr_session.js';

/** The clip menu's value when the rig has no clips. */
const NO_CLIP = -1;

export class TrackPanel {
  readonly gui: GUI;
  private readonly state = { on: false, clip: NO_CLIP };
  private readonly onController: Controller;
  private clipController: Controller;
  private readonly playController: Controller;
  private readonly vrController: Controller;
  /** The status line (its data-* attributes carry the raw values for tests). */
  private readonly status: HTMLElement;
  private readonly statusText = new Throttle(() => this.showStatus());

  /**
   * The controls of `track`, in a panel of their own added to `container`; closed (its title
   * only) until opened or track mode goes on, so that what follows it in the side column stays in view.
   */
  constructor(
    container: HTMLElement,
    private readonly track: TrackMode,
  ) {
    const folder = (this.gui = new GUI({ container, title: 'Track (avatar)' }).close());
    this.onController = folder
      .add(this.state, 'on')
      .name('track mode (T)')
      .onChange((on: boolean) => {
        if (on) track.enter();
        else track.leave();
        this.refresh(); // also when track mode could not start: the box is cleared again
      });
    this.clipController = folder
      .add(this.state, 'clip', { '(no clips)': NO_CLIP })
      .name('clip')
      .onChange(() => {
        if (track.source === 'clip') void track.playClip(this.state.clip); // another clip while one plays: play that one
      });
    this.playController = folder.add({ play: () => this.playOrStop() }, 'play').name('play clip');
    this.playController.domElement.title =
      'the clip moves the head and hands (its own pose: the faint ghost beside); the avatar follows them';
    this.vrController = folder
      .add({ vr: () => void (track.inVr ? track.exitVr() : track.enterVr()) }, 'vr')
      .name('enter VR')
      .hide();
    this.vrController.domElement.title =
      'the headset moves the head, the controllers’ grips the hands; stand as the avatar stands to start (a squeeze calibrates again)';
    this.status = document.createElement('p');
    this.status.className = 'track-status';
    folder.$children.append(this.status);
    track.onChanged = () => this.refresh();
    track.onSolved = () => this.statusText.request();
    void immersiveVrSupported().then((yes) => this.vrController.show(yes));
    this.showRig();
  }

  /** Shows what the rig now shown offers: whether it can be tracked, and its clips. Call after a rig is shown. */
  showRig(): void {
    const names = this.track.clipNames();
    const menu: Record<string, number> = {};
    names.forEach((name, i) => (menu[name in menu ? `${name} (${i + 1})` : name] = i)); // two clips may share a name
    this.state.clip = names.length ? 0 : NO_CLIP;
    this.clipController = this.clipController.options(names.length ? menu : { '(no clips)': NO_CLIP });
    this.refresh();
  }

  /** Re-reads track mode's state into the controls and the status line. */
  refresh(): void {
    const track = this.track,
      problem = track.problem();
    this.state.on = track.active;
    if (track.active) this.gui.open();
    this.onController.enable(problem === null).updateDisplay();
    this.onController.domElement.title =
      problem ?? 'gizmos on the head and hands move the whole body (the feet stand, or step when the body leaves them)';
    const clips = problem === null && this.state.clip !== NO_CLIP;
    this.clipController.enable(clips).updateDisplay();
    this.playController.enable(clips).name(track.source === 'clip' ? 'stop clip' : 'play clip');
    this.vrController.enable(problem === null).name(track.inVr ? 'leave VR' : 'enter VR');
    this.statusText.now();
  }

  dispose(): void {
    this.statusText.cancel();
    this.gui.destroy();
  }

  private playOrStop(): void {
    if (this.track.source === 'clip') this.track.stopClip();
    else void this.track.playClip(this.state.clip);
  }

  private showStatus(): void {
    const track = this.track,
      s = this.status,
      avatar = track.avatar,
      outcome = track.outcome;
    s.dataset.active = String(track.active);
    s.dataset.source = track.source;
    if (!avatar || !outcome) {
      s.textContent = track.active ? '' : (track.problem() ?? 'off: the targets drag the rig');
      delete s.dataset.reached;
      return;
    }
    const words = statusWords(outcome, false);
    const feet = avatar.feet(),
      delta = DRAG_TIP_SHARE * avatar.standing.height;
    s.dataset.reached = String(outcome.reached);
    s.dataset.ms = String(avatar.ms);
    s.title = words.title;
    const driven =
      track.source === 'clip'
        ? 'the clip moves the head and hands'
        : track.source === 'vr'
          ? 'the headset moves the head and hands'
          : 'drag the head and hands';
    const feetText = feet.stepping
      ? 'a foot steps'
      : feet.drift <= delta
        ? 'feet planted'
        : `feet off by ${formatNumber(feet.drift)}`;
    s.textContent = `${driven} · ${words.text} · ${feetText} · ${formatNumber(avatar.ms)} ms/solve`;
  }
}
