// Undo and redo as two stacks of states. Before an edit the caller records the state it had;
// undo() takes the current state and gives back the one before it, redo() the other way. A new
// edit clears what could be redone. The oldest states are dropped past `limit`.
export class UndoHistory<T> {
  private readonly past: T[] = [];
  private readonly future: T[] = [];

  /** Keeps at most `limit` states to undo (and as many to redo). */
  constructor(readonly limit = 200) {}

  get canUndo(): boolean {
    return this.past.length > 0;
  }

  get canRedo(): boolean {
    return this.future.length > 0;
  }

  /** Steps that can be undone now. */
  get undoSteps(): number {
    return this.past.length;
  }

  /** An edit is about to change `before` (the state now): it can be undone from now on. */
  record(before: T): void {
    this.past.push(before);
    if (this.past.length > this.limit) this.past.shift();
    this.future.length = 0;
  }

  /** The state before the last edit, or null; `current` becomes redoable. */
  undo(current: T): T | null {
    const before = this.past.pop();
    if (before === undefined) return null;
    this.future.push(current);
    return before;
  }

  /** The state the last undo left, or null; `current` becomes undoable again. */
  redo(current: T): T | null {
    const after = this.future.pop();
    if (after === undefined) return null;
    this.past.push(current);
    return after;
  }

  /** Puts back a state undo() or redo() gave when it could not be shown (the step is not lost). */
  putBack(state: T, undone: boolean): void {
    const [from, to] = undone ? [this.future, this.past] : [this.past, this.future];
    from.pop();
    to.push(state);
  }

  clear(): void {
    this.past.length = 0;
    this.future.length = 0;
  }
}
