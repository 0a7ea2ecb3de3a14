// Budgets on the work a glTF file asks for (web/src/rig/gltf/gltf_budget.ts, json_budget.ts, the
// accessor-data cap in gltf_ranges.ts): small files that ask for millions of nodes or gigabytes of
// zero-filled accessors are refused before anything big is built, naming the file and the limit;
// `npm run rig` refuses the audit's two bombs within a bounded peak memory; the project's rigs sit
// far inside every limit.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { MAX_GLTF_LIST_LENGTHS, MAX_GLTF_NESTED_LENGTHS } from '../../web/src/rig/gltf/gltf_budget.js';
import { parseGltfContainer } from '../../web/src/rig/gltf/gltf_file.js';
import { MAX_ACCESSOR_BYTES } from '../../web/src/rig/gltf/gltf_ranges.js';
import { jsonBudgetProblem, MAX_JSON_CONTAINERS } from '../../web/src/rig/json_budget.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { MAX_BONES } from '../../web/src/rig/rig_limits.js';
import { packGlb } from '../../scripts/rig_files/glb.js';
import { manyNodesGltf, zeroAccessorGlb } from './hostile_rigs.js';
import { treeGltf } from '../../scripts/rig_files/tree_rigs.js';
import { loadError } from './synthetic_rigs.js';

const root = resolve(import.meta.dirname, '../..');
const modelsDir = resolve(root, 'web/public/models');
const dir = mkdtempSync(join(tmpdir(), 'gltf-budget-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** A two-joint rig with `extra` merged into its glTF JSON. */
function rigWith(extra: Record<string, unknown>): Uint8Array {
  return packGlb({ ...treeGltf([-1, 0]), ...extra });
}

describe('glTF work budgets', () => {
  it('refuses 4,000,000 empty nodes (12 MB) and 1,000,000 (3 MB) in the scan before parsing', async () => {
    for (const count of [4_000_000, 1_000_000])
      expect(await loadError(manyNodesGltf(count), 'nodes.gltf')).toBe(
        `nodes.gltf: the JSON holds more than ${MAX_JSON_CONTAINERS} arrays and objects`,
      );
  });

  it('refuses more nodes than the node limit, naming it', async () => {
    const most = MAX_GLTF_LIST_LENGTHS.nodes;
    expect(await loadError(manyNodesGltf(most + 1), 'wide.gltf')).toBe(
      `wide.gltf: ${most + 1} nodes; at most ${most} (the limit on glTF nodes)`,
    );
  });

  it('refuses long lists of meshes, accessors and materials, and nested lists summed over their parents', async () => {
    for (const list of ['meshes', 'accessors', 'materials']) {
      const most = MAX_GLTF_LIST_LENGTHS[list];
      const message = await loadError(rigWith({ [list]: Array.from({ length: most + 1 }, () => ({})) }), 'long.glb');
      expect(message).toBe(`long.glb: ${most + 1} ${list}; at most ${most} (the limit on glTF ${list})`);
    }
    // Joints of all skins together: three skins of MAX_BONES joints each.
    const joints = 3 * MAX_BONES;
    const [, , mostJoints] = MAX_GLTF_NESTED_LENGTHS.find(([p, c]) => p === 'skins' && c === 'joints')!;
    const skins = Array.from({ length: 3 }, () => ({ joints: Array.from({ length: MAX_BONES }, () => 0) }));
    expect(await loadError(rigWith({ skins }), 'skins.glb')).toBe(
      `skins.glb: ${joints} skins[].joints in all; at most ${mostJoints} (the limit on glTF skins' joints)`,
    );
  });

  it('refuses the 9 KB .glb of forty 512 MiB accessors without a bufferView', async () => {
    const bomb = zeroAccessorGlb(40);
    expect(bomb.byteLength).toBeLessThan(9 * 1024);
    expect(await loadError(bomb, 'zeros.glb')).toBe(
      `zeros.glb: 536870904 bytes of accessor data in accessors[0] (accessors[0]: 44739242 elements of 12 bytes without a bufferView, zeros to allocate); at most ${MAX_ACCESSOR_BYTES} bytes (256 MiB) in one file`,
    );
  });

  it('caps the sum of accessor bytes, each accessor under the cap', async () => {
    const count = Math.floor(MAX_ACCESSOR_BYTES / 3 / 12) + 1; // three of these are just over the cap
    const accessors = Array.from({ length: 3 }, () => ({ componentType: 5126, type: 'VEC3', count }));
    expect((await loadRig(rigWith({ accessors: accessors.slice(0, 2) }), 'two.glb')).spec.names).toHaveLength(2);
    expect(await loadError(rigWith({ accessors }), 'three.glb')).toMatch(
      new RegExp(
        `^three\\.glb: ${3 * count * 12} bytes of accessor data in accessors\\[0\\.\\.2\\] \\(accessors\\[2\\]: ${count} elements of 12 bytes without a bufferView, zeros to allocate\\); at most ${MAX_ACCESSOR_BYTES} bytes`,
      ),
    );
  });

  it('leaves the project rigs far inside every limit (under 1% of each)', async () => {
    for (const file of readdirSync(modelsDir).filter((f) => f.endsWith('.glb'))) {
      const bytes = new Uint8Array(readFileSync(join(modelsDir, file)));
      const json = parseGltfContainer(bytes, file).json;
      const text = JSON.stringify(json);
      expect(jsonBudgetProblem(text), file).toBeUndefined();
      expect((text.match(/[[{]/g) ?? []).length, `${file}: arrays and objects`).toBeLessThan(MAX_JSON_CONTAINERS / 100);
      for (const [list, most] of Object.entries(MAX_GLTF_LIST_LENGTHS)) {
        const n = Array.isArray(json[list]) ? (json[list] as unknown[]).length : 0;
        expect(n, `${file}: ${list}`).toBeLessThan(most / 100);
      }
      const accessorBytes = ((json.accessors ?? []) as { count: number }[]).reduce((sum, a) => sum + 64 * a.count, 0); // 64: a MAT4, the largest element
      expect(accessorBytes, `${file}: accessor bytes`).toBeLessThan(MAX_ACCESSOR_BYTES / 100);
      await loadRig(bytes, file);
    }
  });

  // The command on the two bombs, in a child process that reports its own peak memory (Linux).
  const linux = existsSync('/proc/self/status');
  it.skipIf(!linux)('npm run rig refuses both bombs with a peak memory under 300 MB', () => {
    const files: [string, Uint8Array][] = [
      ['nodes.gltf', manyNodesGltf(4_000_000)],
      ['zeros.glb', zeroAccessorGlb(40)],
    ];
    for (const [name, bytes] of files) {
      const path = join(dir, name);
      writeFileSync(path, bytes);
      const script = `
        import { readFileSync } from 'node:fs';
        import { runRigInspect } from ${JSON.stringify(resolve(root, 'scripts/rig_inspect.ts'))};
        let err = '';
        const code = await runRigInspect([${JSON.stringify(path)}], { out: () => {}, err: (t) => (err += t) });
        const peak = Number(/VmHWM:\\s+(\\d+) kB/.exec(readFileSync('/proc/self/status', 'utf8'))[1]) * 1024;
        console.log(JSON.stringify({ code, err, peak }));`;
      const out = execFileSync(process.execPath, ['--import', 'tsx', '--input-type=module', '-e', script], {
        cwd: root,
        encoding: 'utf8',
      });
      const { code, err, peak } = JSON.parse(out.trim().split('\n').pop()!) as {
        code: number;
        err: string;
        peak: number;
      };
      expect(code, err).toBe(1);
      expect(err).toMatch(
        new RegExp(`^rig: ${path.replace(/[.*+?^${}()|[\]\\/]/g, '\\$&')}: .*(arrays and objects|accessor data)`),
      );
      expect(peak, `${name}: peak memory`).toBeLessThan(300e6);
      rmSync(path);
    }
  });
});
