// Stub page: loads the WebAssembly core and prints a rig's end-effector tips at rest.
import { IkRig, loadIk } from './ik/index.js';
import { parseA7Rig } from './rig/a7_rig.js';

const out = document.querySelector<HTMLPreElement>('#out')!;
const input = document.querySelector<HTMLInputElement>('#file')!;

const ik = await loadIk();
out.textContent = 'WebAssembly core loaded.';

input.addEventListener('change', async () => {
  const file = input.files?.[0];
  if (!file) return;
  try {
    const rig = new IkRig(ik, parseA7Rig(await file.text(), file.name));
    const tips = rig.tips(new Float64Array(rig.numAngles));
    const lines = Array.from(rig.effectors(), (b, k) =>
      `${rig.spec.names[b]}: ${Array.from(tips.subarray(3 * k, 3 * k + 3), (v) => v.toFixed(4)).join(', ')}`,
    );
    out.textContent = `${file.name}: ${rig.numBones} bones\n${lines.join('\n')}`;
    rig.dispose();
  } catch (e) {
    out.textContent = `Could not load ${file.name}: ${(e as Error).message}`;
  }
});
