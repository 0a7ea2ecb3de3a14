// The side column as a bottom sheet on narrow screens (page.css, max-width 700px): below the view,
// a third of the screen high with the stats in sight, and a handle that expands it to most of the
// screen (the panel, the plots; it scrolls inside) or collapses it again. On wider screens the
// handle is hidden and the column is the usual side column. The state is root's data-sheet
// (collapsed or expanded), for the stylesheet and tests.

/** Adds the handle at the top of `side`; returns a function that removes it. */
export function bottomSheet(root: HTMLElement, side: HTMLElement): () => void {
  const handle = document.createElement('button');
  handle.type = 'button';
  handle.className = 'sheet-handle';
  handle.id = 'sheet-handle';
  handle.setAttribute('aria-controls', side.id);
  const show = (expanded: boolean): void => {
    root.dataset.sheet = expanded ? 'expanded' : 'collapsed';
    handle.setAttribute('aria-expanded', String(expanded));
    handle.textContent = expanded ? '▾ less: back to the view' : '▴ more: controls, plots';
    if (!expanded) side.scrollTop = 0;
  };
  handle.addEventListener('click', () => show(root.dataset.sheet !== 'expanded'));
  show(false);
  side.prepend(handle);
  return () => {
    handle.remove();
    delete root.dataset.sheet;
  };
}
