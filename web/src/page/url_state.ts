// The URL keeps the rig and the method, so a link reproduces the view: ?rig=knight&method=gn, and
// the chain of a URDF file (?chain=BASE:TIP: the chain the next .urdf opened shows, kept while it
// is shown). The values are read as written; the page checks them against its rigs, the core's
// methods and the file's links.

export interface UrlState {
  rig: string | null;
  method: string | null;
  /** A URDF chain "BASE:TIP" (absent: the file's longest). */
  chain: string | null;
}

export function readUrlState(location: Location = window.location): UrlState {
  const q = new URLSearchParams(location.search);
  return { rig: q.get('rig'), method: q.get('method'), chain: q.get('chain') };
}

/** Rewrites the query in place (no new history entry). A null rig removes it (a dropped file has no link). */
export function writeUrlState(state: UrlState): void {
  const url = new URL(window.location.href);
  if (state.rig) url.searchParams.set('rig', state.rig);
  else url.searchParams.delete('rig');
  if (state.method) url.searchParams.set('method', state.method);
  else url.searchParams.delete('method');
  if (state.chain) url.searchParams.set('chain', state.chain);
  else url.searchParams.delete('chain');
  if (url.href !== window.location.href) history.replaceState(null, '', url);
}
