// The serial chains of a URDF robot that the importer (urdf_rig.ts) takes without a refusal, for a
// chooser such as the page's chain menu. Each runs as far as such joints reach at both ends: its
// BASE is the top of a subtree of revolute, continuous and fixed joints (no mimic), a link with no
// parent joint or one whose parent joint is of another type, and its TIP a leaf of that subtree;
// it has at least one revolute or continuous joint. Shorter chains inside one of these (a TIP
// higher up, "panda_link0:panda_link8") are importable too, and not listed.
import type { UrdfJoint, UrdfModel } from './urdf_model.js';

/** One importable chain. */
export interface UrdfChain {
  /** "BASE:TIP", as loadRig's options.chain takes it. */
  chain: string;
  base: string;
  tip: string;
  /** Revolute and continuous joints in the chain. */
  moving: number;
  /** All its joints, fixed ones included. */
  joints: number;
}

const isRevolute = (j: UrdfJoint): boolean => j.type === 'revolute' || j.type === 'continuous';
const importable = (j: UrdfJoint): boolean => (isRevolute(j) || j.type === 'fixed') && !j.mimic;

/**
 * The robot's maximal importable serial chains, the most moving joints first, then the most
 * joints, then in the file's link order (BASE, then TIP). At most `max` of them (the first by
 * that order); `more` counts those left out. Linear in the links and joints (no recursion).
 */
export function urdfChains(model: UrdfModel, max = 100): { chains: UrdfChain[]; more: number } {
  const found: { base: number; tip: number; moving: number; joints: number }[] = [];
  for (let base = 0; base < model.links.length; base++) {
    const up = model.parentJoint[base];
    if (up !== -1 && importable(model.joints[up])) continue; // not the top of its subtree
    const stack: [number, number, number][] = [[base, 0, 0]]; // link, moving joints and joints above it
    while (stack.length) {
      const [link, moving, joints] = stack.pop()!;
      let leaf = true;
      for (const j of model.childJoints[link]) {
        const joint = model.joints[j];
        if (!importable(joint)) continue;
        leaf = false;
        stack.push([joint.child, moving + (isRevolute(joint) ? 1 : 0), joints + 1]);
      }
      if (leaf && moving > 0) found.push({ base, tip: link, moving, joints });
    }
  }
  found.sort((a, b) => b.moving - a.moving || b.joints - a.joints || a.base - b.base || a.tip - b.tip);
  const chains = found.slice(0, max).map(({ base, tip, moving, joints }) => {
    const [b, t] = [model.links[base], model.links[tip]];
    return { chain: `${b}:${t}`, base: b, tip: t, moving, joints };
  });
  return { chains, more: found.length - chains.length };
}
