// The widget's `goals` attribute: "hand.L:pose, foot.R:position", comma-separated bone:kind pairs.
// A bone is named as in the `effectors` attribute (its name, any case, or its index); the kind
// says what its target sets: its tip's position, its bone frame's orientation, or both (pose).

export type GoalKind = 'position' | 'orientation' | 'pose';

const KINDS: readonly GoalKind[] = ['position', 'orientation', 'pose'];

/** One bone's goal kind. */
export interface BoneGoalKind {
  /** Bone index. */
  bone: number;
  kind: GoalKind;
}

/** Bone `item` of a rig with bone `names`: a name (exact, then any case) or an index; -1 if none. */
export function findBone(names: readonly string[], item: string): number {
  let i = /^\d+$/.test(item) ? Number(item) : names.indexOf(item);
  if (i < 0) i = names.findIndex((n) => n.toLowerCase() === item.toLowerCase());
  return i >= 0 && i < names.length ? i : -1;
}

/**
 * The goals named by `attr` on a rig with bone `names`, and what could not be read: each problem
 * is a short text naming the item ("unknown goal bone "x"", "goal kind "y" of hand.L is not ...").
 * A bone named twice takes its last kind.
 */
export function parseGoalKinds(attr: string, names: readonly string[]): { goals: BoneGoalKind[]; problems: string[] } {
  const goals: BoneGoalKind[] = [];
  const problems: string[] = [];
  for (const raw of attr.split(',')) {
    const item = raw.trim();
    if (!item) continue;
    const colon = item.lastIndexOf(':');
    const name = (colon < 0 ? item : item.slice(0, colon)).trim();
    const kind =
      colon < 0
        ? ''
        : item
            .slice(colon + 1)
            .trim()
            .toLowerCase();
    const bone = findBone(names, name);
    if (bone < 0) {
      problems.push(`unknown goal bone "${name.slice(0, 60)}"`);
      continue;
    }
    if (!(KINDS as readonly string[]).includes(kind)) {
      problems.push(`goal kind "${kind.slice(0, 30)}" of ${name.slice(0, 60)} is not ${KINDS.join(', ')}`);
      continue;
    }
    const at = goals.findIndex((g) => g.bone === bone);
    if (at >= 0) goals.splice(at, 1);
    goals.push({ bone, kind: kind as GoalKind });
  }
  return { goals, problems };
}
