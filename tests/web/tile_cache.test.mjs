// The browser's tile cache (src/web/page/tile_cache_worker.js) in headless Chromium: tiles seen
// through `trailray serve` are drawn again after a reload with the server stopped (no network at
// all: the shell, the served configuration, the track and the tiles all come from the cache),
// and a small budget keeps the cache within it while the page still works.
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';

import http from 'node:http';

import { canvasPixels, config, framesDrawn, launchBrowser, openPage, staticServer } from './harness.mjs';

const dem = path.join(config.sharedData || '', 'dem', 'interlaken_dhm25_wgs84.tif');
const flight = path.join(config.sharedData || '', 'igc', 'goigc_0100_interlaken.igc');
const haveData = config.sharedData && fs.existsSync(dem) && fs.existsSync(flight);
const TILE_CACHE = 'trailray-tiles-v1';
let browser;
const servers = [];

before(async () => { browser = await launchBrowser(); });
after(async () => {
  await browser?.close();
  for (const s of servers) s.kill('SIGTERM');
});

// `trailray serve` with the Interlaken DEM and flight on a free port (each test its own port, so
// its own origin: a cache of its own); resolves to its address and process once it listens.
function serve(args = ['--terrain', dem, flight]) {
  const child = spawn(config.nativeBinary, ['serve', '--port', '0', '--web-root', config.webRoot, '--imagery', 'none',
    '--color', '#ff00ff', ...args]);
  servers.push(child);
  return new Promise((resolve, reject) => {
    let output = '';
    child.stdout.on('data', (d) => {
      output += d;
      const m = output.match(/serving on (http:\/\/\S+)/);
      if (m) resolve({ url: m[1], child });
    });
    child.stderr.on('data', (d) => { output += d; });
    child.on('exit', (code) => reject(new Error(`serve exited with ${code}: ${output}`)));
  });
}

async function stop(child) {
  const exited = new Promise((resolve) => child.once('exit', resolve));
  child.kill('SIGTERM');
  await exited;
}

const status = async (page) => JSON.parse(await page.evaluate(() => window.trailray.api.status()));
const cacheStatus = (page) => page.evaluate(() => window.trailrayTileCache.status());

// Every tile the view wants has come (tiles, "no data" or failures); then the frame that shows
// them on the canvas.
async function allTiles(page, tracks = 1) {
  await page.waitForFunction((n) => {
    const s = JSON.parse(window.trailray.api.status());
    return s.tracks.length === n && s.tiles.wanted > 0 && s.tiles.loaded + s.tiles.no_data + s.tiles.failed === s.tiles.wanted;
  }, { timeout: 180000, polling: 200 }, tracks);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

// Waits until the worker has stored at least `count` tiles (it stores them after handing them on).
async function tilesKept(page, count) {
  await page.waitForFunction(async (n) => (await window.trailrayTileCache.status()).tiles >= n, { timeout: 30000, polling: 200 }, count);
  return cacheStatus(page);
}

function meanDifference(a, b) {
  assert.equal(a.data.length, b.data.length);
  let sum = 0;
  for (let i = 0; i < a.data.length; i += 4)
    for (let c = 0; c < 3; ++c) sum += Math.abs(a.data[i + c] - b.data[i + c]);
  return sum / (a.data.length / 4) / 3;
}

test('a reload with the server stopped starts the page and draws the terrain seen before', async (t) => {
  if (!haveData) { t.skip(`needs ${dem} and ${flight} (../shared/data is absent)`); return; }
  const { url, child } = await serve();
  const opened = Date.now();
  const page = await openPage(browser, url);
  assert.ok(await page.evaluate(() => window.trailrayTileCache.ready), 'the worker controls the page');
  await allTiles(page);
  t.diagnostic(`first visit: every tile drawn ${Date.now() - opened} ms`);
  const before = await status(page);
  assert.deepEqual(before.tile_failures, []);
  assert.ok(before.tiles.loaded > 0, 'height tiles from the DEM');
  // The first visit's tiles too: the page waited for the worker before it fetched any.
  const kept = await tilesKept(page, before.tiles.loaded + before.tiles.no_data);
  t.diagnostic(`kept after the first visit: ${kept.tiles} tiles, ${kept.entries} entries, ${(kept.bytes / 1048576).toFixed(2)} MB ` +
    `(view: ${JSON.stringify(before.tiles)})`);
  const image = await canvasPixels(page);
  const view = await page.evaluate(() => window.trailray.api.viewState());

  // The server stopped, not puppeteer's setOfflineMode: that cuts the page's requests but not
  // the worker's own fetches (with nothing kept, a reload in offline mode still got every tile
  // from serve), so a broken cache would pass.
  await stop(child);
  await assert.rejects(fetch(url), 'the server is gone');
  const started = Date.now();
  await page.reload();
  await page.waitForFunction(() => window.trailray && (window.trailray.started || window.trailray.failed), { timeout: 30000 });
  assert.equal(await page.evaluate(() => window.trailray.failed), null);
  const startedMs = Date.now() - started;
  await framesDrawn(page);
  const firstFrameMs = Date.now() - started;
  await allTiles(page);
  const allMs = Date.now() - started;
  t.diagnostic(`offline reload: started ${startedMs} ms, first frame ${firstFrameMs} ms, every tile drawn ${allMs} ms`);
  const after = await status(page);
  assert.equal(after.tracks.length, 1, 'the served track, from the cache');
  assert.deepEqual(after.tile_failures, []);
  // The tiles the view has; not `kept`/`dropped`, the fetched tiles waiting for the loader at that
  // moment (those that arrive after the view moved on wait there, bounded), which depend on
  // when the answers came: from the cache, faster than from serve.
  const drawn = ({ wanted, loaded, no_data, failed }) => ({ wanted, loaded, no_data, failed });
  assert.deepEqual(drawn(after.tiles), drawn(before.tiles), 'the same tiles, every one from the cache');
  const again = await canvasPixels(page);
  // The same tiles, view and renderer (SwiftShader is deterministic): the same picture, up to
  // rounding in the blending of the frame (well under 1 of 255 on average).
  const same = meanDifference(image, again);
  // Offline still, the same view without terrain: the neutral ground, another picture.
  const flat = await openPage(browser, `${url}#${view}&terrain=none`);
  await framesDrawn(flat);
  const neutral = meanDifference(again, await canvasPixels(flat));
  await flat.close();
  t.diagnostic(`offline picture vs online: mean difference ${same.toFixed(2)}; vs neutral ground ${neutral.toFixed(1)} (of 255)`);
  assert.ok(same < 1, `the offline picture is the online one (mean difference ${same.toFixed(2)})`);
  assert.ok(neutral > 8, `the offline picture has the terrain (mean difference to none ${neutral.toFixed(1)})`);
  assert.deepEqual(await page.evaluate(() => window.trailray.messages), []);
  await page.close();
});

// The bytes the Cache API really holds for the page's tiles and files (bodies read), and how many.
function cacheContents(page) {
  return page.evaluate(async (name) => {
    const cache = await caches.open(name);
    let bytes = 0;
    const keys = await cache.keys();
    for (const key of keys) bytes += (await (await cache.match(key)).arrayBuffer()).byteLength;
    return { entries: keys.length, bytes, tiles: keys.filter((k) => k.url.includes('/tiles/terrain/')).length };
  }, TILE_CACHE);
}

test('a small cache-max-size-mb keeps the cache within it, and 0 keeps nothing; the page works', async (t) => {
  if (!haveData) { t.skip(`needs ${dem} and ${flight} (../shared/data is absent)`); return; }
  const { url } = await serve();
  // The view's 12 height tiles are about 260 kB (Terrarium PNG from serve, 13 "no data" answers
  // beside them): 50 kB holds a few.
  const budget = Math.round(0.05 * 1048576);
  const page = await openPage(browser, `${url}?cache-max-size-mb=0.05`);
  await allTiles(page);
  const s = await status(page);
  assert.deepEqual(s.tile_failures, []);
  assert.ok(s.tiles.loaded > 0);
  await page.waitForFunction(async (n) => (await window.trailrayTileCache.status()).stored >= n, { timeout: 30000 },
    s.tiles.loaded + s.tiles.no_data);
  const kept = await cacheStatus(page);
  const real = await cacheContents(page);
  t.diagnostic(`budget ${budget} B: kept ${JSON.stringify(kept)}; in the Cache API: ${JSON.stringify(real)}`);
  assert.equal(kept.budget, budget);
  assert.ok(kept.evicted > 0, 'tiles were evicted');
  assert.ok(kept.bytes <= budget, `the account is within the budget (${kept.bytes} B)`);
  assert.ok(real.bytes <= budget, `the bodies in the Cache API are within the budget (${real.bytes} B)`);
  assert.equal(real.entries, kept.entries, 'the index knows every entry');
  assert.ok(real.tiles > 0, 'the most recent tiles are kept');
  assert.deepEqual(await page.evaluate(() => window.trailray.messages), []);

  // 0: nothing kept, and the budget stays for the next visit that gives none.
  await page.goto(`${url}?cache-max-size-mb=0`);
  await page.waitForFunction(() => window.trailray && window.trailray.started, { timeout: 30000 });
  await allTiles(page);
  assert.deepEqual((await status(page)).tile_failures, []);
  await page.goto(url);
  await page.waitForFunction(() => window.trailray && window.trailray.started, { timeout: 30000 });
  await allTiles(page);
  const off = await cacheStatus(page);
  assert.equal(off.budget, 0);
  assert.equal(off.enabled, false);
  assert.deepEqual(await cacheContents(page), { entries: 0, bytes: 0, tiles: 0 });
  await page.close();
});

test('a bad cache-max-size-mb is shown as an error, and the page still starts', async () => {
  const { url } = await serve(['--terrain', 'none']);
  const page = await openPage(browser, `${url}?cache-max-size-mb=lots`);
  await page.waitForFunction(() => window.trailray.messages.length > 0, { timeout: 10000 });
  assert.deepEqual(await page.evaluate(() => window.trailray.messages),
    ['cache-max-size-mb=lots: expected a size in MB (0: no tile cache)']);
  await page.close();
});

// A tile server on another origin in front of serve's tiles that answers some tiles badly, by a
// rule on the tile's numbers: as serve does (a whole PNG, or 404 "no data"), 503 (with the PNG:
// some servers send a placeholder image with their error), an HTML page
// with 200 (a captive portal), a PNG cut short with a Content-Length that agrees (a broken
// server), or serve's tile without CORS headers. Counts the requests for each path.
const KINDS = ['as-served', 'as-served', 'error', 'html', 'cut-short', 'no-cors'];
function badTileServer(upstream) {
  const requests = new Map();
  const kinds = new Map();
  const server = http.createServer(async (request, response) => {
    const m = request.url.match(/^\/tiles\/terrain\/(\d+)\/(\d+)\/(\d+)\.png$/);
    if (!m) { response.writeHead(404).end(); return; }
    const [z, x, y] = m.slice(1).map(Number);
    const kind = KINDS[(x * 7 + y * 13 + z) % KINDS.length];
    requests.set(request.url, (requests.get(request.url) || 0) + 1);
    const answer = await fetch(new URL(request.url, upstream));
    const body = Buffer.from(await answer.arrayBuffer());
    kinds.set(request.url, kind === 'as-served' ? (answer.status === 200 ? 'tile' : 'no-data') : kind);
    const cors = { 'Access-Control-Allow-Origin': '*' };
    if (kind === 'as-served') response.writeHead(answer.status, { ...cors, 'Content-Type': answer.headers.get('content-type') }).end(body);
    else if (kind === 'error') response.writeHead(503, { ...cors, 'Content-Type': 'image/png' }).end(body);  // a whole image, but an error
    else if (kind === 'html') response.writeHead(200, { ...cors, 'Content-Type': 'text/html' }).end('<html><body>log in first</body></html>');
    else if (kind === 'cut-short') response.writeHead(200, { ...cors, 'Content-Type': 'image/png' }).end(body.subarray(0, body.length >> 1));
    else response.writeHead(200, { 'Content-Type': 'image/png' }).end(body);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => {
    servers.push({ kill: () => server.close() });
    resolve({ url: `http://127.0.0.1:${server.address().port}/`, requests, kinds });
  }));
}

test('only whole, readable tiles are kept (and "no data"): not errors, HTML, cut-short or non-CORS answers', async (t) => {
  if (!haveData) { t.skip(`needs ${dem} and ${flight} (../shared/data is absent)`); return; }
  const { url: upstream } = await serve();
  const tiles = await badTileServer(upstream);
  const { server, url: base } = await staticServer(config.webRoot);
  servers.push({ kill: () => server.close() });
  const address = `${base}?terrain=${tiles.url}tiles/terrain/{z}/{x}/{y}.png&imagery=none` +
    '&look-at=46.69,7.86,600&distance=6000&heading=0&pitch=-89';
  const page = await openPage(browser, address);
  await allTiles(page, 0);
  const s = await status(page);
  const byKind = {};
  for (const kind of tiles.kinds.values()) byKind[kind] = (byKind[kind] || 0) + 1;
  t.diagnostic(`tiles answered: ${JSON.stringify(byKind)}; the viewer: ${JSON.stringify(s.tiles)}`);
  for (const kind of ['tile', 'no-data', 'error', 'html', 'cut-short', 'no-cors'])
    assert.ok(byKind[kind] > 0, `the view asks for at least one tile answered "${kind}"`);
  assert.ok(s.tiles.failed > 0 && s.tiles.loaded > 0);
  const good = [...tiles.kinds].filter(([, kind]) => kind === 'tile' || kind === 'no-data').map(([p]) => p);
  await page.waitForFunction(async (n) => (await window.trailrayTileCache.status()).stored >= n, { timeout: 30000 }, good.length);
  const kept = await page.evaluate(async (name) => (await (await caches.open(name)).keys()).map((k) => new URL(k.url).pathname),
    TILE_CACHE);
  assert.deepEqual(kept.filter((p) => p.startsWith('/tiles/')).sort(), good.sort(), 'exactly the good answers are kept');
  const refused = (await cacheStatus(page)).refused;
  assert.ok(refused >= byKind.html + byKind['cut-short'], `the HTML and cut-short answers were refused (${refused})`);

  // A reload asks the network only for what was not kept.
  const before = new Map(tiles.requests);
  await page.reload();
  await page.waitForFunction(() => window.trailray && window.trailray.started, { timeout: 30000 });
  await allTiles(page, 0);
  for (const p of good) assert.equal(tiles.requests.get(p), before.get(p), `${p} came from the cache`);
  const asked = [...tiles.kinds].filter(([, kind]) => kind === 'error').map(([p]) => p);
  assert.ok(asked.some((p) => tiles.requests.get(p) > before.get(p)), 'the failed tiles are asked for again');
  await page.close();
});

test('the least recently used tiles are evicted first, not the first stored', async (t) => {
  if (!haveData) { t.skip(`needs ${dem} and ${flight} (../shared/data is absent)`); return; }
  const { url } = await serve();
  // The page fetches no tiles itself (terrain=none): the test asks for them, as the viewer would:
  // tiles over the DEM, the first (about 37 kB) asked for again after each of the others (12, 20,
  // 6, 12 kB, then smaller ones). 80 kB holds it and a few of them: under LRU the first stays
  // and the second goes; first in, first out would have evicted the first.
  const page = await openPage(browser, `${url}?terrain=none&cache-max-size-mb=0.08`);
  const tiles = ['11/1068/722', '12/2136/1445', '12/2138/1445', '11/1069/722', '10/534/361', '9/267/180', '8/133/90',
    '7/66/45', '6/33/22', '5/16/11', '4/8/5'].map((zxy) => `tiles/terrain/${zxy}.png`);
  const result = await page.evaluate(async (urls) => {
    const status = () => window.trailrayTileCache.status();
    const stored = async (count) => { while ((await status()).stored < count) await new Promise((r) => setTimeout(r, 20)); };
    const answers = [];
    const before = (await status()).stored;
    for (const [i, u] of urls.entries()) {
      answers.push((await fetch(u)).status);
      await stored(before + i + 1);  // stored in turn (the worker stores after it answers)
      if (i > 0) await (await fetch(urls[0])).arrayBuffer();
    }
    const kept = new Set((await (await caches.open('trailray-tiles-v1')).keys()).map((k) => new URL(k.url).pathname.slice(1)));
    return { answers, kept: urls.map((u) => kept.has(u)), summary: await status() };
  }, tiles);
  t.diagnostic(JSON.stringify(result));
  assert.ok(result.answers.every((s) => s === 200), 'whole tiles from the DEM');
  assert.ok(result.summary.evicted > 0, 'tiles were evicted');
  assert.ok(result.summary.hits >= tiles.length - 1, 'the first tile came from the cache each time');
  assert.ok(result.summary.bytes <= result.summary.budget);
  assert.equal(result.kept[0], true, 'the first tile, used after every other, is kept');
  assert.equal(result.kept[1], false, 'the second, never used again, is gone');
  assert.equal(result.kept.at(-1), true, 'the last stored is kept');
  await page.close();
});
