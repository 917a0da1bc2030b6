// The page's service worker (registered by tile_cache.js; its scope is the web root): keeps what
// a reload needs so that the page starts and draws what was seen before without the network.
//   the app shell (index.html, the scripts, the style, trailray.wasm): network first (fresh when
//     the server answers), the kept copy when it cannot be reached; never evicted (about 4.5 MB).
//     This file is not among them: the browser keeps a registered worker itself;
//   tiles (a URL whose path ends in z/x/y, see isTile): cache first while fresh (Cache-Control,
//     else 7 days; "no data" answers a day), then the network, the stale copy when it fails;
//   any other GET (serve's api/config.json, track files): network first, the kept copy offline.
// Tiles and other files share one budget (the page's cache-max-size-mb, default 256 MB; 0: none
// kept), least recently used evicted beyond it. Each entry's size and last use live in a small
// IndexedDB index, so no body is read to account for the cache when the worker starts.
'use strict';

const SHELL_CACHE = 'trailray-shell-v1';
const TILE_CACHE = 'trailray-tiles-v1';
const SHELL_FILES = ['./', 'index.html', 'app.js', 'tile_cache.js', 'style.css', 'trailray.js', 'trailray.wasm'];
const DEFAULT_BUDGET_BYTES = 256 * 1024 * 1024;
const FRESH_MS = 7 * 24 * 3600 * 1000;        // as the desktop's disk cache
const NO_DATA_FRESH_MS = 24 * 3600 * 1000;
const SHELL_WAIT_MS = 5000;                    // a server slower than this to answer: the kept copy
const ENTRY_OVERHEAD_BYTES = 256;              // the URL, headers and index record of an entry
const STORED = 'x-trailray-stored', EXPIRES = 'x-trailray-expires', SIZE = 'x-trailray-size';

const scope = new URL(self.registration.scope);
const shellUrls = new Set(SHELL_FILES.map((f) => new URL(f, scope).href));

// --- the index: url -> { url, size, used } in IndexedDB, mirrored in memory -------------------

let database = null;
const index = new Map();
let totalBytes = 0;
let budgetBytes = DEFAULT_BUDGET_BYTES;
const counts = { hits: 0, misses: 0, stale: 0, stored: 0, evicted: 0, refused: 0 };

function request(r) {
  return new Promise((resolve, reject) => { r.onsuccess = () => resolve(r.result); r.onerror = () => reject(r.error); });
}

function openDatabase() {
  const opening = indexedDB.open('trailray-tile-cache', 1);
  opening.onupgradeneeded = () => {
    opening.result.createObjectStore('entries', { keyPath: 'url' });
    opening.result.createObjectStore('settings');
  };
  return request(opening);
}

function store(name, mode = 'readwrite') { return database.transaction(name, mode).objectStore(name); }

// Loads the index once per start of the worker and makes it agree with the Cache API (an entry
// written just before the worker stopped may lack its record, or the other way round).
const loaded = (async () => {
  try {
    database = await openDatabase();
    const budget = await request(store('settings', 'readonly').get('budget'));
    if (typeof budget === 'number') budgetBytes = budget;
    const records = await request(store('entries', 'readonly').getAll());
    const cache = await caches.open(TILE_CACHE);
    const keys = new Set((await cache.keys()).map((k) => k.url));
    for (const r of records) {
      if (keys.has(r.url)) { index.set(r.url, r); totalBytes += r.size; keys.delete(r.url); }
      else store('entries').delete(r.url);
    }
    for (const url of keys) {  // stored without a record: its size is in its headers
      const response = await cache.match(url);
      const size = Number(response && response.headers.get(SIZE));
      if (!size) { await cache.delete(url); continue; }
      const r = { url, size, used: Number(response.headers.get(STORED)) || 0 };
      index.set(url, r); totalBytes += size; store('entries').put(r);
    }
  } catch (e) {
    console.warn(`tile cache: no index (${e}); nothing is kept`);
    database = null;
  }
})();

// Changes of the cache run one at a time, so that eviction sees every entry's size.
let queue = Promise.resolve();
function serially(job) {
  const next = queue.then(job);
  queue = next.catch(() => {});
  return next;
}

function touch(url) {
  const r = index.get(url);
  if (!r || !database) return;
  r.used = Date.now();
  store('entries').put(r);
}

async function evict(limit) {
  if (totalBytes <= limit) return;
  const cache = await caches.open(TILE_CACHE);
  const oldest = [...index.values()].sort((a, b) => a.used - b.used);
  for (const r of oldest) {
    if (totalBytes <= limit) break;
    await cache.delete(r.url);
    store('entries').delete(r.url);
    index.delete(r.url);
    totalBytes -= r.size;
    counts.evicted += 1;
  }
}

// --- what may be kept ------------------------------------------------------------------------

// z/x/y (or z/y/x) at the end of the path, with an optional @2x and image suffix: the shape of
// every template the viewer takes ({z} {x} {y} {-y} in the path: the desktop's defaults, the
// page's ?terrain=/?imagery=, serve's /tiles/...). A tile template with its numbers in the query
// is not recognised: its tiles are kept network first like other files, and still work offline.
function isTile(url) {
  return /\/\d{1,2}\/\d{1,9}\/\d{1,9}(@[1-4]x)?(\.(png|pngraw|jpe?g|webp))?$/i.test(url.pathname);
}

// The decoders' formats, whole: PNG up to its IEND chunk, JPEG to its end marker, WebP to the
// length its RIFF header gives. An HTML error page answered with 200 (a captive portal), or a
// body cut short, is not a tile.
function isWholeImage(bytes) {
  const n = bytes.length;
  const at = (i, text) => [...text].every((c, k) => bytes[i + k] === c.charCodeAt(0));
  if (n > 20 && bytes[0] === 0x89 && at(1, 'PNG')) return at(n - 8, 'IEND');
  if (n > 4 && bytes[0] === 0xff && bytes[1] === 0xd8 && bytes[2] === 0xff) return bytes[n - 2] === 0xff && bytes[n - 1] === 0xd9;
  if (n > 12 && at(0, 'RIFF') && at(8, 'WEBP')) return (bytes[4] | (bytes[5] << 8) | (bytes[6] << 16) | (bytes[7] << 24)) + 8 === n;
  return false;
}

// When a response goes stale: Cache-Control max-age (no-cache: at once), else Expires, else
// `fallback` from now; null for no-store (not to be kept).
function expiryOf(headers, fallback) {
  const control = (headers.get('cache-control') || '').toLowerCase();
  if (/(^|[,\s])no-store/.test(control)) return null;
  if (/(^|[,\s])no-cache/.test(control)) return Date.now();
  const age = control.match(/(^|[,\s])max-age=(\d+)/);
  if (age) return Date.now() + Number(age[2]) * 1000;
  const expires = Date.parse(headers.get('expires') || '');
  return Number.isFinite(expires) ? expires : Date.now() + fallback;
}

// Keeps a response in the budgeted cache if it is whole and readable: 200 (for a tile, a whole
// image), or for a tile 404/204 ("no data here", what the viewer makes of them). Never an
// opaque response (a cross-origin one without CORS: its size and status are hidden), a partial
// one, a redirect, or an error.
async function keep(url, response, tile) {
  await loaded;
  if (!database || budgetBytes <= 0 || response.type === 'opaque' || response.type === 'opaqueredirect') return;
  const noData = tile && (response.status === 404 || response.status === 204);
  if (response.status !== 200 && !noData) return;
  const expires = expiryOf(response.headers, noData ? NO_DATA_FRESH_MS : FRESH_MS);
  if (expires === null) return;
  let bytes;
  try {
    bytes = new Uint8Array(await response.arrayBuffer());  // rejects when the body is cut short
  } catch (e) {
    return;
  }
  const length = response.headers.get('content-length');
  if (!noData && ((tile && !isWholeImage(bytes)) ||
                  (length !== null && !response.headers.has('content-encoding') && Number(length) !== bytes.length))) {
    counts.refused += 1;
    return;
  }
  const size = (noData ? 0 : bytes.length) + url.length + ENTRY_OVERHEAD_BYTES;
  if (size > budgetBytes) return;
  const headers = new Headers(response.headers);
  headers.set(STORED, String(Date.now()));
  headers.set(EXPIRES, String(expires));
  headers.set(SIZE, String(size));
  const copy = new Response(noData ? null : bytes, { status: response.status, statusText: response.statusText, headers });
  await serially(async () => {
    const cache = await caches.open(TILE_CACHE);
    const before = index.get(url);
    await evict(budgetBytes - size + (before ? before.size : 0));
    await cache.put(url, copy);
    const r = { url, size, used: Date.now() };
    if (index.has(url)) totalBytes -= index.get(url).size;
    index.set(url, r);
    totalBytes += size;
    store('entries').put(r);
    counts.stored += 1;
  });
}

// --- answers ---------------------------------------------------------------------------------

function withTimeout(promise, ms) {
  if (!ms) return promise;
  return Promise.race([promise, new Promise((_, reject) => setTimeout(() => reject(new Error('timeout')), ms))]);
}

async function tileAnswer(event) {
  await loaded;
  const url = event.request.url;
  const cache = await caches.open(TILE_CACHE);
  const kept = database && budgetBytes > 0 ? await cache.match(url) : undefined;
  if (kept && Number(kept.headers.get(EXPIRES)) > Date.now()) {
    counts.hits += 1;
    touch(url);
    return kept;
  }
  counts.misses += 1;
  try {
    const response = await fetch(event.request);
    if (kept && response.status >= 500) return staleAnswer(url, kept);
    event.waitUntil(keep(url, response.clone(), true));
    return response;
  } catch (e) {
    if (kept) return staleAnswer(url, kept);
    throw e;
  }
}

function staleAnswer(url, kept) {
  counts.stale += 1;
  touch(url);
  return kept;
}

// The shell and other files: the network's answer when it comes, else the kept copy.
async function networkFirst(event, shell) {
  await loaded;
  const url = new URL(event.request.url);
  const key = shell ? url.origin + url.pathname : url.href;
  const cache = await caches.open(shell ? SHELL_CACHE : TILE_CACHE);
  const kept = await cache.match(key);
  try {
    const response = await withTimeout(fetch(event.request), kept && shell ? SHELL_WAIT_MS : 0);
    if (kept && response.status >= 500) return kept;
    if (shell && response.status === 200 && response.type === 'basic' && !response.redirected)
      event.waitUntil(cache.put(key, response.clone()));
    else if (!shell) event.waitUntil(keep(key, response.clone(), false));
    if (!shell && kept) touch(key);
    return response;
  } catch (e) {
    if (!kept) throw e;
    if (!shell) staleAnswer(key, kept);
    return kept;
  }
}

self.addEventListener('fetch', (event) => {
  const r = event.request;
  if (r.method !== 'GET' || r.headers.has('range')) return;
  const url = new URL(r.url);
  if (url.protocol !== 'http:' && url.protocol !== 'https:') return;
  const inScope = url.href.startsWith(scope.href);
  if (r.mode === 'navigate') {
    // Only the page itself: another address in the scope (a served track opened as a page) goes
    // to the network as it would without this worker.
    if (shellUrls.has(url.origin + url.pathname)) event.respondWith(networkFirst(event, true));
    return;
  }
  if (inScope && shellUrls.has(url.origin + url.pathname)) event.respondWith(networkFirst(event, true));
  else if (isTile(url)) event.respondWith(tileAnswer(event));
  else event.respondWith(networkFirst(event, false));
});

// --- life and messages -----------------------------------------------------------------------

self.addEventListener('install', () => self.skipWaiting());

self.addEventListener('activate', (event) => {
  event.waitUntil((async () => {
    for (const name of await caches.keys())
      if (name.startsWith('trailray-') && name !== SHELL_CACHE && name !== TILE_CACHE) await caches.delete(name);
    await self.clients.claim();
  })());
});

// The shell files not kept yet (a first visit loaded them before this worker controlled the
// page), fetched once in the background.
async function keepShell() {
  const cache = await caches.open(SHELL_CACHE);
  for (const url of shellUrls) {
    if (await cache.match(url)) continue;
    try {
      const response = await fetch(url);
      if (response.status === 200 && !response.redirected) await cache.put(url, response);
    } catch (e) { /* offline: the next visit tries again */ }
  }
}

function summary() {
  let tiles = 0;
  for (const url of index.keys()) if (isTile(new URL(url))) tiles += 1;
  return { enabled: Boolean(database) && budgetBytes > 0, budget: budgetBytes, bytes: totalBytes,
    entries: index.size, tiles, ...counts };
}

// From tile_cache.js: {type: 'hello', budget?} once the page is controlled (the budget from its
// address, kept for later visits), {type: 'status'}; the answer goes back on the message's port.
self.addEventListener('message', (event) => {
  const message = event.data || {};
  const answer = (async () => {
    await loaded;
    if (message.type === 'hello') {
      event.waitUntil(keepShell());
      if (typeof message.budget === 'number' && message.budget >= 0 && database) {
        budgetBytes = message.budget;
        store('settings').put(budgetBytes, 'budget');
        await serially(() => evict(budgetBytes));
      }
    }
    return summary();
  })();
  event.waitUntil(answer.then((s) => event.ports[0] && event.ports[0].postMessage(s)));
});
