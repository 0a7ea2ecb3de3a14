// What a joint's name says about it, across common naming conventions: Mixamo
// ("mixamorig:LeftHand"), Blender ("hand.L", "DEF-forearm.R"), Unreal/Unity ("hand_l", "foot_r"),
// 3ds Max Biped ("Bip01 L Hand"). Names are split into lower-case tokens; nothing else is guessed.

export type Side = 'left' | 'right' | 'none';

/** Lower-case word tokens of a name: splits on punctuation, spaces, camelCase and digit runs. */
export function nameTokens(name: string): string[] {
  return name
    .replace(/([a-z])([A-Z])/g, '$1 $2')
    .replace(/([A-Z]+)([A-Z][a-z])/g, '$1 $2')
    .replace(/([A-Za-z])([0-9])/g, '$1 $2')
    .replace(/([0-9])([A-Za-z])/g, '$1 $2')
    .toLowerCase()
    .split(/[^a-z0-9]+/)
    .filter((t) => t.length > 0);
}

const LEFT = new Set(['left', 'l', 'lft']);
const RIGHT = new Set(['right', 'r', 'rt', 'rgt']);

/** The body side a name states ("hand.L", "LeftHand", "foot_r"), or 'none'. */
export function nameSide(tokens: string[]): Side {
  if (tokens.some((t) => LEFT.has(t))) return 'left';
  if (tokens.some((t) => RIGHT.has(t))) return 'right';
  return 'none';
}

/** True when a token is a side marker (left/right). */
export function isSideToken(t: string): boolean {
  return LEFT.has(t) || RIGHT.has(t);
}
