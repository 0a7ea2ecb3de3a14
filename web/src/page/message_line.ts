// The page's message line (index.html's message slot). A note ('info') reads as one line, its
// details behind a click on it, and goes when a target is dragged (its line stays, empty: the view
// keeps its place); an error shows whole and stays until the next message. The state is the
// line's data-kind, data-expanded and data-dismissed, for the stylesheet and tests.

export type MessageKind = 'info' | 'error';

/** Shows `text` in the message line `line` (an empty text hides it). */
export function showMessage(line: HTMLElement, text: string, kind: MessageKind): void {
  line.textContent = text;
  line.dataset.kind = kind;
  line.dataset.expanded = 'false';
  line.dataset.dismissed = 'false';
  line.title = kind === 'info' && text ? 'click for the details (goes when you drag a target)' : '';
  line.hidden = text === '';
}

/** A click on a note shows or hides its details. */
export function expandNotesOnClick(line: HTMLElement): void {
  line.addEventListener('click', () => {
    if (line.dataset.kind === 'info') line.dataset.expanded = String(line.dataset.expanded !== 'true');
  });
}

/** A note goes once the user works (a drag starts); an error stays. */
export function dismissNote(line: HTMLElement): void {
  if (line.dataset.kind === 'info') line.dataset.dismissed = 'true';
}
