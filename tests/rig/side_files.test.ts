// A .gltf loaded from disk reads its side buffers only from inside its own folder: "..", encoded
// "..", absolute, UNC and symbolic-link uris are refused before anything outside is read, and so
// are device files such as /dev/zero (which used to hang the load and eat memory). The messages
// name the uri as written, never the resolved path. A rig file that is not a regular file is
// refused too, a FIFO at once (opening one used to wait for a writer forever).
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { unpackGlb, type Json } from '../../scripts/rig_files/glb.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';

let json: Json;
let bin: Uint8Array;
let root: string; // holds model/ and, beside it, secret.bin
let model: string;

beforeAll(async () => {
  ({ json, bin } = unpackGlb(await testCharacterGlb()));
  root = mkdtempSync(join(tmpdir(), 'ik-side-'));
  model = join(root, 'model');
  mkdirSync(join(model, 'parts'), { recursive: true });
  writeFileSync(join(root, 'secret.bin'), bin); // a valid buffer, but outside the model's folder
  writeFileSync(join(model, 'parts', 'ok.bin'), bin);
  symlinkSync(join(root, 'secret.bin'), join(model, 'link.bin'));
});

/** Writes model/NAME.gltf whose buffer 0 has `uri`; returns its path. */
function gltfWithUri(name: string, uri: string): string {
  const side = structuredClone(json) as Json;
  (side.buffers as Record<string, unknown>[])[0].uri = uri;
  const path = join(model, `${name}.gltf`);
  writeFileSync(path, JSON.stringify(side));
  return path;
}

describe('side buffers stay inside the model folder', () => {
  it('reads a relative side file inside the folder', async () => {
    const rig = await loadRigFromPath(gltfWithUri('inside', 'parts/ok.bin'));
    expect(rig.spec.names.length).toBeGreaterThan(0);
  });

  it.each([
    ['a parent folder', '../secret.bin'],
    ['an encoded parent folder', '..%2Fsecret.bin'],
    ['a deeper way out', 'parts/../../secret.bin'],
    ['an absolute path', `${'/'}etc/passwd`],
    ['a UNC path', '//host/share/x.bin'],
    ['a Windows drive path', 'C:\\x.bin'],
    ['a symbolic link leading out', 'link.bin'],
  ])('refuses %s', async (_, uri) => {
    const path = gltfWithUri('out', uri);
    const error = await loadRigFromPath(path).then(
      () => null,
      (e: Error) => e,
    );
    expect(error?.message).toMatch(/outside the model's folder/);
    expect(error?.message).not.toContain(join(root, 'secret.bin')); // no resolved path in the message
    expect(error?.message).toContain('out.gltf');
  });

  it('refuses a device file without reading it (no hang, no memory)', async () => {
    const link = join(model, 'zero.bin');
    symlinkSync('/dev/zero', link);
    await expect(loadRigFromPath(gltfWithUri('zero', '../../../../../../dev/zero'))).rejects.toThrow(
      /outside the model's folder/,
    );
    // Through a link inside the folder, the real path is outside too.
    await expect(loadRigFromPath(gltfWithUri('zero-link', 'zero.bin'))).rejects.toThrow(/outside the model's folder/);
  });

  it('refuses a rig path that is not a regular file', async () => {
    await expect(loadRigFromPath('/dev/zero')).rejects.toThrow(/\/dev\/zero: cannot read the file: not a regular file/);
    await expect(loadRigFromPath(model)).rejects.toThrow(/cannot read the file: (not a regular file|EISDIR)/);
  });

  it.skipIf(process.platform === 'win32')('refuses a FIFO at once instead of waiting for a writer', async () => {
    const fifo = join(model, 'pipe.json');
    execFileSync('mkfifo', [fifo]);
    await expect(loadRigFromPath(fifo)).rejects.toThrow(/pipe\.json: cannot read the file: not a regular file/);
    await expect(loadRigFromPath(gltfWithUri('fifo', 'pipe.json'))).rejects.toThrow(
      /buffer 0: cannot read the side file "pipe\.json" \(missing buffer\): not a regular file/,
    );
  });
});
