// Undo and redo as stacks (web/src/page/undo_stacks.ts) and the key names shortcuts match
// (keyboard.ts): steps come back in reverse order, a new edit clears the redo, at least 100 steps
// are kept (the oldest dropped past the limit), and a step that could not be shown is put back.
import { describe, expect, it } from 'vitest';

import { UNDO_STEPS } from '../../web/src/page/page_history.js';
import { keyName } from '../../web/src/page/keyboard.js';
import { UndoHistory } from '../../web/src/page/undo_stacks.js';

describe('UndoHistory', () => {
  it('undoes and redoes in order; a new edit clears the redo', () => {
    const h = new UndoHistory<number>();
    expect(h.undo(0)).toBeNull();
    h.record(0); // 0 -> 1
    h.record(1); // 1 -> 2
    expect(h.undo(2)).toBe(1);
    expect(h.undo(1)).toBe(0);
    expect(h.undo(0)).toBeNull();
    expect(h.redo(0)).toBe(1);
    expect(h.redo(1)).toBe(2);
    expect(h.redo(2)).toBeNull();
    expect(h.undo(2)).toBe(1);
    h.record(1); // 1 -> 5: 2 can no longer be redone
    expect(h.canRedo).toBe(false);
    expect(h.undo(5)).toBe(1);
    expect(h.undo(1)).toBe(0);
  });

  it(`keeps ${UNDO_STEPS} steps (at least 100), dropping the oldest`, () => {
    expect(UNDO_STEPS).toBeGreaterThanOrEqual(100);
    const h = new UndoHistory<number>(UNDO_STEPS);
    for (let i = 0; i < UNDO_STEPS + 50; i++) h.record(i);
    expect(h.undoSteps).toBe(UNDO_STEPS);
    let state = UNDO_STEPS + 50;
    const seen: number[] = [];
    for (let s = h.undo(state); s !== null; s = h.undo(state)) seen.push((state = s));
    expect(seen.length).toBe(UNDO_STEPS);
    expect(seen[0]).toBe(UNDO_STEPS + 49);
    expect(seen.at(-1)).toBe(50);
  });

  it('puts back a step that could not be shown', () => {
    const h = new UndoHistory<string>();
    h.record('a');
    const back = h.undo('b');
    expect(back).toBe('a');
    h.putBack('a', true);
    expect(h.canRedo).toBe(false);
    expect(h.undo('b')).toBe('a');
    const again = h.redo('a');
    expect(again).toBe('b');
    h.putBack('b', false);
    expect(h.canUndo).toBe(false);
    expect(h.redo('a')).toBe('b');
  });
});

describe('keyName', () => {
  const key = (k: string, mods: { ctrl?: boolean; meta?: boolean; shift?: boolean } = {}) =>
    keyName({ key: k, ctrlKey: !!mods.ctrl, metaKey: !!mods.meta, shiftKey: !!mods.shift });
  it('names letters lower case, Shift only with Ctrl or Cmd', () => {
    expect(key('R')).toBe('r');
    expect(key('?', { shift: true })).toBe('?');
    expect(key('Escape')).toBe('escape');
    expect(key('z', { ctrl: true })).toBe('ctrl+z');
    expect(key('Z', { ctrl: true, shift: true })).toBe('ctrl+shift+z');
    expect(key('z', { meta: true })).toBe('ctrl+z');
  });
});
