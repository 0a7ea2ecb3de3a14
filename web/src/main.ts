// Entry of the page (index.html): loads the WebAssembly core, then the rig named in the URL.
import './page/page.css';

import { loadIk } from './ik/module.js';
import { PageApp } from './page/app.js';

function slot(id: string): HTMLElement {
  const el = document.getElementById(id);
  if (!el) throw new Error(`index.html has no #${id}`);
  return el;
}

const root = slot('app');
const message = slot('message');
try {
  const module = await loadIk();
  const app = new PageApp(module, {
    root,
    viewport: slot('viewport'),
    side: slot('side'),
    rigName: slot('rig-name'),
    message,
    stepInfo: slot('step-info'),
    selection: slot('selection'),
  });
  // The test probes (window.ikPage, window.ikTrack) are a chunk of their own, fetched only under
  // automation (navigator.webdriver: the browser tests) or with ?probe in the URL.
  if (navigator.webdriver || new URLSearchParams(location.search).has('probe')) {
    const [{ makeProbe }, { makeTrackProbe }] = await Promise.all([
      import('./page/probe.js'),
      import('./page/track_probe.js'),
    ]);
    window.ikPage = makeProbe(app);
    window.ikTrack = makeTrackProbe(app);
  }
  await app.start();
} catch (e) {
  root.dataset.state = 'error';
  message.hidden = false;
  message.dataset.kind = 'error';
  message.textContent = `The page could not start: ${e instanceof Error ? e.message : String(e)}`;
}
