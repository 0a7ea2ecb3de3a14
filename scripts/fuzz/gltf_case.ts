// glTF file cases: a base model as .glb, as .gltf with a side .bin, or with its buffer embedded
// as a data: uri; then glTF-specific and generic JSON mutations, a size bomb, byte damage, a
// buffer uri leading outside the folder or to a hostile side file, or a hostile path instead of
// the file.
import { packGlbText } from '../rig_files/glb.js';
import { mutateBytes } from './byte_mutators.js';
import { plantBomb } from './gltf_bombs.js';
import type { FileCase } from './file_case.js';
import type { Entry } from './folder.js';
import type { Fixture } from './fixture.js';
import { CHARACTER, type GltfBase } from './gltf_bases.js';
import { mutateGltf } from './gltf_mutators.js';
import { hostileMain } from './hostile_main.js';
import { jsonText } from './json_text.js';
import { mutateJson } from './json_mutators.js';
import type { Rand } from './random.js';
import { hostileSideFiles, uriEscapes, type SideFile } from './uri_escapes.js';

type Form = 'glb' | 'gltf' | 'embedded';

/** Sets (or, for undefined, deletes) buffers[0].uri; false when buffers[0] is no longer an object. */
function setBufferUri(json: GltfBase['json'], uri: string | undefined): boolean {
  const buffer = Array.isArray(json.buffers) ? (json.buffers[0] as Record<string, unknown>) : undefined;
  if (typeof buffer !== 'object' || buffer === null) return false;
  if (uri === undefined) delete buffer.uri;
  else buffer.uri = uri;
  return true;
}

/** One glTF case drawn from `r`. */
export function gltfCase(r: Rand, bases: readonly GltfBase[], fixture: Fixture): FileCase {
  const side = r.weighted<() => { file: SideFile; outside: boolean } | undefined>([
    [85, () => undefined],
    [12, () => ({ file: r.pick(uriEscapes(fixture)), outside: true })],
    [3, () => ({ file: r.pick(hostileSideFiles()), outside: false })],
  ])();
  const form: Form = side
    ? 'gltf'
    : r.weighted([
        [4, 'glb'],
        [4, 'gltf'],
        [1, 'embedded'],
      ] as const);
  const main = form === 'glb' ? r.pick(['rig.glb', 'rig.glb', 'Rig.GLB']) : 'rig.gltf';
  if (!side && r.chance(0.04)) {
    const h = hostileMain(r, main);
    return { description: h.description, entries: h.entries, main };
  }
  const base = side ? bases.find((b) => b.name === CHARACTER)! : r.pick(bases);
  const json = structuredClone(base.json);
  let bin: Uint8Array = base.bin;
  setBufferUri(
    json,
    form === 'glb'
      ? undefined
      : form === 'gltf'
        ? 'rig.bin'
        : `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}`,
  );

  const changes: string[] = [];
  // A uri case is mostly the untouched character: then only the uri stands between the load and the sentinel.
  const count =
    side && r.chance(0.7)
      ? 0
      : r.weighted([
          [1, 0],
          [5, 1],
          [2, 2],
          [1, 3],
        ]);
  for (let k = count; k > 0; k--) changes.push(...(r.chance(0.55) ? [mutateGltf(r, json)] : mutateJson(r, json, 1)));
  // Bombs only where no uri is on trial (a uri case must stand or fall by its uri); few, as a node bomb can cost a hang.
  const bomb = side ? undefined : r.chance(0.03) ? plantBomb(r, json) : undefined;
  if (bomb) changes.push(bomb.description);
  const sideSet = side !== undefined && setBufferUri(json, side.file.uri);
  if (side) changes.push(sideSet ? `buffers[0].uri = ${side.file.text}` : 'buffers[0] is no object: no uri set');
  let bytes: Uint8Array = form === 'glb' ? packGlbText(jsonText(json), bin) : new TextEncoder().encode(jsonText(json));
  if (r.chance(0.2)) {
    const onBin = form === 'gltf' && r.chance(0.4);
    const m = mutateBytes(r, onBin ? bin : bytes, onBin ? 'rig.bin' : main);
    if (onBin) bin = m.bytes;
    else bytes = m.bytes;
    changes.push(m.description);
  }
  const entries: Entry[] = [{ kind: 'file', name: main, bytes }, ...(side?.file.entries ?? [])];
  if (form === 'gltf') entries.push({ kind: 'file', name: 'rig.bin', bytes: bin });
  return {
    description: `${base.name} as ${form === 'embedded' ? '.gltf with a data: uri' : form === 'gltf' ? '.gltf + rig.bin' : '.glb'}${changes.length ? `; ${changes.join('; ')}` : ' (unchanged)'}`,
    entries,
    main,
    outsideUri: sideSet && side.outside ? side.file.uri : undefined,
    mustFail: sideSet && !side.outside ? `its buffer is ${side.file.text}` : bomb?.mustFail,
  };
}
