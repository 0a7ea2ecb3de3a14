// The rig line in the page's header bar (index.html's rig-name slot): the rig shown, its file's format (a
// URDF file's chain too), its bones and its end effectors.
import type { LiveRig } from '../view/live_rig.js';

/** The rig line's text for `live`. */
export function rigNameText(live: LiveRig): string {
  const n = live.session.effectors().length;
  const urdf = live.source.urdf;
  const format = urdf ? `${live.source.format} chain ${urdf.chain}` : live.source.format;
  return `${live.name} — ${format}, ${live.session.rig.numBones} bones, ${n} end effector${n === 1 ? '' : 's'}`;
}
