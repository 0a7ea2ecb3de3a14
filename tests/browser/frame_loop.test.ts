// The page's frame loop allocates no array per frame: while a target is dragged, nothing called from
// LiveController.frame() (the solve, the tips, the poses, the bones and the skinned mesh posed, the
// gizmos placed, the hips target, the stats) makes a typed array or an Array. As the core's
// no-allocation test counts malloc calls during a solve, this counts constructions: a script run
// before the page's own puts a counting Proxy in place of every typed-array constructor and of
// Array (Array.from, new Array and the arrays map, filter, slice and concat make through it), and a
// construction counts when its stack passes through LiveController.frame. Array literals and
// spreads cannot be seen this way. Heap numbers and plain objects are not counted. Without the
// `out` buffers (tips, poses, the E history) the drag made 338 arrays in 138 frames.
import { describe, expect, it } from 'vitest';

import { openPage, nextFrame } from './harness.js';
import { effectorNamed, gotoRig, selectTarget, targetScreen, usePageServer } from './page_helpers.js';

const env = usePageServer();

/** What the counting script keeps on window. */
interface Counted {
  arraysCounting: boolean;
  /** Constructions inside frame() while counting: "constructor: stack" -> how many. */
  arraysMade: Map<string, number>;
}

/** Runs in the page before its scripts: counting constructors in place of the array ones. */
function countArrayConstructions(): void {
  const w = window as unknown as Counted;
  w.arraysCounting = false;
  w.arraysMade = new Map();
  Error.stackTraceLimit = 80; // frame() may sit deep below the construction (three.js calls)
  let inside = false; // the counting code makes arrays itself
  const names = [
    'Array',
    'Float64Array',
    'Float32Array',
    'Int32Array',
    'Uint32Array',
    'Int16Array',
    'Uint16Array',
    'Int8Array',
    'Uint8Array',
    'Uint8ClampedArray',
  ];
  const globals = globalThis as unknown as Record<string, new (...args: unknown[]) => object>;
  for (const name of names) {
    const original = globals[name];
    const counting: typeof original = new Proxy(original, {
      construct(target, args, newTarget) {
        if (w.arraysCounting && !inside) {
          inside = true;
          const stack = (new Error().stack ?? '').split('\n').slice(2);
          if (stack.some((line) => line.includes('LiveController.frame'))) {
            const where = `${name}: ${stack
              .slice(0, 4)
              .map((l) => l.trim())
              .join(' < ')}`;
            w.arraysMade.set(where, (w.arraysMade.get(where) ?? 0) + 1);
          }
          inside = false;
        }
        return Reflect.construct(target, args, newTarget === counting ? target : newTarget);
      },
    });
    // Through `constructor` the arrays' own methods (slice, map, subarray...) make their results.
    (original.prototype as { constructor: unknown }).constructor = counting;
    globals[name] = counting;
  }
}

describe('the frame loop', () => {
  // The character takes the longest path: the hips target, pinned frames, a skinned mesh.
  it("allocates no array per frame while the character's hand is dragged", async (ctx) => {
    const { page, errors } = await openPage(env.browser, ctx);
    await page.addInitScript(countArrayConstructions);
    await gotoRig(page, env.url, 'character');
    const k = await selectTarget(page, await effectorNamed(page, /LeftHand$/));
    const from = await targetScreen(page, k);
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    // The drag's first frames make what a drag keeps (pinned frames, buffers sized once).
    for (let i = 1; i <= 5; i++) {
      await page.mouse.move(from.x + 2 * i, from.y - 2 * i);
      await nextFrame(page);
    }
    await page.evaluate(() => ((window as unknown as Counted).arraysCounting = true));
    const solves0 = await page.evaluate(() => window.ikPage!.solveMs().total);
    for (let i = 1; i <= 20; i++) {
      await page.mouse.move(from.x + 10 + 2 * i, from.y - 10 - 2 * i);
      await nextFrame(page);
    }
    const made = await page.evaluate(() => {
      const w = window as unknown as Counted;
      w.arraysCounting = false;
      return [...w.arraysMade];
    });
    const solves = (await page.evaluate(() => window.ikPage!.solveMs().total)) - solves0;
    await page.mouse.up();
    const count = made.reduce((n, [, c]) => n + c, 0);
    console.log(`[frame loop] character: ${solves} per-frame solves while dragged, ${count} arrays made in frame()`);
    expect(solves).toBeGreaterThanOrEqual(20); // the frames counted did solve
    // None per frame: a buffer grown once (the WebAssembly memory growing, a longer history than
    // any before) may make one or two over the drag; a per-frame array makes one every solve.
    expect(made.filter(([, c]) => c > 2).map(([where, c]) => `${c} x ${where}`)).toEqual([]);
    expect(errors).toEqual([]);
  });
});
