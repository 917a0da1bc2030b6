// The page's side of the tile cache (tile_cache_worker.js): registers the worker as soon as the
// page loads, hands it the budget from the address (`cache-max-size-mb=N`, the config file's
// [cache] max_size_mb; 0: keep no tiles), and shows how much it keeps beside the tile progress.
// app.js waits for `ready` before it fetches anything, so that the first visit's tiles and files
// go through the worker too. Service workers need a secure context (https, or http on localhost /
// 127.0.0.1): elsewhere the page works as before, without the cache.
'use strict';

window.trailrayTileCache = (() => {
  const OPTION = 'cache-max-size-mb';
  const CONTROL_WAIT_MS = 3000;  // a first visit: how long the page waits for the worker to take it
  const cache = { options: [OPTION], ready: null, error: null };

  function show(text, title = '') {
    const place = document.getElementById('tile-cache');
    if (place) { place.textContent = text; place.title = title; }
  }

  function megabytes(bytes) { return `${(bytes / 1048576).toFixed(bytes < 10485760 ? 1 : 0)} MB`; }

  // The budget in bytes from the query or the fragment (the fragment's last, as app.js reads
  // options), undefined when not given (the worker keeps the last one given, else 256 MB).
  function budgetFromAddress() {
    let value;
    for (const text of [location.search.slice(1), location.hash.slice(1)]) {
      const given = new URLSearchParams(text).get(OPTION);
      if (given !== null) value = given;
    }
    if (value === undefined) return undefined;
    const mb = Number(value);
    if (value.trim() === '' || !Number.isFinite(mb) || mb < 0) {
      cache.error = `${OPTION}=${value}: expected a size in MB (0: no tile cache)`;
      return undefined;
    }
    return Math.round(mb * 1048576);
  }

  // A message to the worker; its answer (the cache's summary), or null after a while.
  function ask(message) {
    const worker = navigator.serviceWorker.controller;
    if (!worker) return Promise.resolve(null);
    return new Promise((resolve) => {
      const channel = new MessageChannel();
      channel.port1.onmessage = (e) => resolve(e.data);
      worker.postMessage(message, [channel.port2]);
      setTimeout(() => resolve(null), 2000);
    });
  }

  cache.status = () => ask({ type: 'status' });

  function showStatus(s) {
    if (!s) return;
    if (!s.enabled) { show('', 'the tile cache is off'); return; }
    show(`cache ${megabytes(s.bytes)}`, `tiles and files kept by the browser: ${s.entries} (${s.tiles} tiles), ` +
      `${megabytes(s.bytes)} of ${megabytes(s.budget)} (${OPTION}); ${s.stale} answered from the cache ` +
      'because the network failed');
  }

  async function setUp() {
    const budget = budgetFromAddress();
    if (!navigator.serviceWorker) {
      show('no cache', 'tiles are not kept: the browser allows it only on https or localhost');
      return false;
    }
    try {
      await navigator.serviceWorker.register('tile_cache_worker.js', { updateViaCache: 'none' });
    } catch (e) {
      // Offline, the worker's update check fails; the worker already there still answers.
      if (!navigator.serviceWorker.controller) {
        show('no cache', `tiles are not kept: ${e.message}`);
        return false;
      }
    }
    if (!navigator.serviceWorker.controller) {
      await new Promise((resolve) => {
        navigator.serviceWorker.addEventListener('controllerchange', resolve, { once: true });
        setTimeout(resolve, CONTROL_WAIT_MS);
      });
    }
    if (!navigator.serviceWorker.controller) return false;
    showStatus(await ask({ type: 'hello', budget }));
    setInterval(async () => { if (!document.hidden) showStatus(await cache.status()); }, 2000);
    return true;
  }

  cache.ready = setUp().catch((e) => { console.warn(`tile cache: ${e}`); return false; }).then((on) => {
    if (cache.error && typeof showMessage === 'function') showMessage(cache.error);  // app.js's
    return on;
  });
  return cache;
})();
