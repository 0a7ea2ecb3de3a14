// Size bombs in a glTF's JSON: cheap to write, costly to walk or to materialise. Node-count bombs
// (very many empty nodes: a few bytes each, but a loader builds a world matrix and more per node)
// and accessor-sum bombs (many accessors without a bufferView, each of a size a real file may
// have, whose zeros together run to tens of GiB for a reader such as three.js that builds every
// accessor). A file past what any rig needs must be refused, and quickly (the hang limit).
import type { Json } from '../rig_files/glb.js';
import type { Rand } from './random.js';

export interface Bomb {
  description: string;
  /** Set when a successful load is wrong: the file is past any sane cap. */
  mustFail?: string;
}

/** Nodes a loader must refuse: no rig has this many (the core takes 16,384 bones). */
const NODE_BOMB = 2_000_000;
/** Large counts a loader may take or refuse, that a run still loads in well under a second. */
const NODES_MODERATE = [50_000, 200_000];

/** Zero-filled accessor bytes in all past which a loader must refuse the file: far past any browser's memory. */
const ZERO_SUM_REFUSED = 16 * 2 ** 30;

/** [accessors, bytes each] of the accessor-sum bombs: 200 MiB in all (may load), then 19.5 GiB (many small, few large) and 97 GiB (must not). */
const ZERO_ACCESSORS: readonly [number, number][] = [
  [2, 100 * 2 ** 20],
  [10_000, 2 * 2 ** 20],
  [100, 200 * 2 ** 20],
  [99_000, 2 ** 20 + 1],
];

const [MAT4_FLOAT_BYTES, SCALAR_BYTE_BYTES] = [64, 1];

/** Appends `count` accessors without a bufferView of `bytes` bytes each; the sum's description. */
function zeroAccessors(json: Json, count: number, bytes: number): Bomb {
  if (!Array.isArray(json.accessors)) return { description: 'no accessor bomb (accessors is no array)' };
  const accessors = json.accessors as unknown[];
  const mat4 = bytes % MAT4_FLOAT_BYTES === 0;
  const element = mat4
    ? { componentType: 5126, type: 'MAT4', count: bytes / MAT4_FLOAT_BYTES }
    : { componentType: 5121, type: 'SCALAR', count: bytes / SCALAR_BYTE_BYTES };
  for (let k = 0; k < count; k++) accessors.push({ ...element });
  const sum = count * bytes;
  const description = `${count} accessors without a bufferView of ${element.count} ${element.type} each (${(sum / 2 ** 30).toFixed(1)} GiB of zeros)`;
  return {
    description,
    mustFail: sum > ZERO_SUM_REFUSED ? `its accessors without a bufferView add up to ${sum} bytes` : undefined,
  };
}

/** One bomb planted in `json`. */
export function plantBomb(r: Rand, json: Json): Bomb {
  return r.weighted<() => Bomb>([
    [
      2,
      () => {
        if (!Array.isArray(json.nodes)) return { description: 'no node bomb (nodes is no array)' };
        const count = r.pick([...NODES_MODERATE, NODE_BOMB]);
        for (let k = 0; k < count; k++) json.nodes.push({});
        const description = `${count} empty nodes appended`;
        return { description, mustFail: count >= NODE_BOMB ? `it has ${json.nodes.length} nodes` : undefined };
      },
    ],
    [3, () => zeroAccessors(json, ...r.pick(ZERO_ACCESSORS))],
  ])();
}
