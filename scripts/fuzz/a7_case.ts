// A7 file cases: a generated rig (or one of the report's rigs, when ../shared is there) written
// as A7 JSON, then mutated at the JSON, A7 or byte level, or replaced by a hostile path.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';

import { writeA7Rig } from '#rig/a7/a7_writer.js';
import { MAX_BONES } from '#rig/rig_limits.js';
import { a7Dir } from '../a7_folder.js';
import { mutateA7, type A7Doc } from './a7_mutators.js';
import { mutateBytes } from './byte_mutators.js';
import type { FileCase } from './file_case.js';
import { hostileMain } from './hostile_main.js';
import { jsonText } from './json_text.js';
import { mutateJson } from './json_mutators.js';
import type { Rand } from './random.js';
import { randomRig } from './random_rig.js';

export interface A7Seed {
  name: string;
  text: string;
}

/** The report's A7 rigs (../shared/rigs/a7/*.json) as seeds, or none when that folder is absent. */
export function readA7Seeds(): A7Seed[] {
  if (!existsSync(a7Dir)) return [];
  return readdirSync(a7Dir)
    .filter((f) => f.endsWith('.json'))
    .map((f) => ({ name: f, text: readFileSync(join(a7Dir, f), 'utf8') }));
}

function baseDoc(r: Rand, seeds: readonly A7Seed[]): { doc: A7Doc; text: string } {
  const fromSeed = r.chance(0.25); // drawn even without seeds, so a case is the same with and without ../shared
  if (seeds.length > 0 && fromSeed) {
    const seed = r.pick(seeds);
    return { doc: JSON.parse(seed.text) as A7Doc, text: seed.name };
  }
  const bones = r.weighted<() => number>([
    [8, () => r.intIn(1, 12)],
    [2, () => r.intIn(20, 300)],
    [0.3, () => r.intIn(2000, 5000)],
    [0.1, () => r.pick([MAX_BONES, MAX_BONES + 1])],
  ])();
  const rotated = bones <= 5000;
  const spec = randomRig(r, bones, bones > 300 ? 20 : 4, rotated);
  return {
    doc: JSON.parse(writeA7Rig(spec)) as A7Doc,
    text: `a generated ${bones}-bone rig${rotated ? '' : ' (unrotated frames)'}`,
  };
}

/** One A7 case drawn from `r`. */
export function a7Case(r: Rand, seeds: readonly A7Seed[]): FileCase {
  const main = r.chance(0.9) ? 'rig.json' : r.pick(['Rig Ü.JSON', 'rig.gltf.json', '-rig.json']);
  if (r.chance(0.04)) {
    const h = hostileMain(r, main);
    return { description: h.description, entries: h.entries, main };
  }
  const base = baseDoc(r, seeds);
  const changes: string[] = [];
  let doc: unknown = base.doc;
  for (
    let k = r.weighted([
      [2, 0],
      [5, 1],
      [2, 2],
      [1, 3],
    ]);
    k > 0;
    k--
  ) {
    const d = doc as A7Doc;
    const kind = r.weighted([
      [5, 'a7'],
      [4, 'json'],
      [0.5, 'top'],
    ] as const);
    if (kind === 'top' || typeof d !== 'object' || d === null) {
      const v = r.pick<unknown>([[], null, 0, 'x', { bones: {} }, { bones: [] }, {}, { bones: [null] }]);
      doc = v;
      changes.push(`the document = ${JSON.stringify(v)}`);
    } else if (
      kind === 'a7' &&
      Array.isArray(d.bones) &&
      d.bones.length > 0 &&
      d.bones.every((b) => typeof b === 'object' && b !== null && !Array.isArray(b))
    ) {
      changes.push(mutateA7(r, d));
    } else {
      changes.push(...mutateJson(r, d, 1));
    }
  }
  let bytes: Uint8Array = new TextEncoder().encode(jsonText(doc));
  if (r.chance(0.15)) {
    const m = mutateBytes(r, bytes, main);
    bytes = m.bytes;
    changes.push(m.description);
  }
  return {
    description: `${base.text} as ${main}${changes.length ? `; ${changes.join('; ')}` : ' (unchanged)'}`,
    entries: [{ kind: 'file', name: main, bytes }],
    main,
  };
}
