// `trailray serve` and the page together in headless Chromium: the served page shows the given
// track with the given options, on the given DEM's terrain (Terrarium tiles the page fetches).
import assert from 'node:assert/strict';
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';

import {
  canvasPixels, config, framesDrawn, launchBrowser, openPage, pixelsOfColor, run, screenshotPixels,
} from './harness.mjs';

const MAGENTA = [255, 0, 255];
let browser;
const servers = [];

before(async () => { browser = await launchBrowser(); });
after(async () => {
  await browser?.close();
  for (const s of servers) s.kill('SIGTERM');
});

// Starts `trailray serve ARGS` on a free port; resolves to its address once it listens.
function serve(args) {
  const child = spawn(config.nativeBinary, ['serve', '--port', '0', '--web-root', config.webRoot, ...args]);
  servers.push(child);
  return new Promise((resolve, reject) => {
    let output = '';
    child.stdout.on('data', (d) => {
      output += d;
      const m = output.match(/serving on (http:\/\/\S+)/);
      if (m) resolve(m[1]);
    });
    child.stderr.on('data', (d) => { output += d; });
    child.on('exit', (code) => reject(new Error(`serve exited with ${code}: ${output}`)));
  });
}

async function status(page) {
  return JSON.parse(await page.evaluate(() => window.trailray.api.status()));
}

test('serve --terrain none --color shows the given track in that colour', async () => {
  const url = await serve(['--terrain', 'none', '--imagery', 'none', '--color', '#ff00ff',
    path.join(config.sourceDir, 'examples', 'paraglider_flight.igc')]);
  const page = await openPage(browser, url);
  await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).tracks.length === 1, { timeout: 60000 });
  await framesDrawn(page);
  const s = await status(page);
  assert.equal(s.tracks[0].color, '#ff00ff');
  assert.equal(s.tiles.wanted, 0, 'no terrain was asked for');
  assert.ok(pixelsOfColor(await canvasPixels(page), MAGENTA, 60).count > 400);
  assert.deepEqual(await page.evaluate(() => window.trailray.messages), []);
  await page.close();
});

test('serve --terrain DEM: the page draws the served terrain under the track', async (t) => {
  const dem = path.join(config.sharedData || '', 'dem', 'interlaken_dhm25_wgs84.tif');
  const flight = path.join(config.sharedData || '', 'igc', 'goigc_0100_interlaken.igc');
  if (!config.sharedData || !fs.existsSync(dem) || !fs.existsSync(flight)) {
    t.skip(`needs ${dem} and ${flight} (../shared/data is absent)`);
    return;
  }
  const url = await serve(['--terrain', dem, '--imagery', 'none', '--color', '#ff00ff', flight]);
  const started = Date.now();
  const page = await openPage(browser, url);
  // Every tile the view wants has come (from the DEM, or "no data" beyond it), none failed.
  await page.waitForFunction(() => {
    const s = JSON.parse(window.trailray.api.status());
    return s.tracks.length === 1 && s.tiles.wanted > 0 && s.tiles.loaded + s.tiles.no_data + s.tiles.failed === s.tiles.wanted;
  }, { timeout: 180000, polling: 500 });
  // The status is that of the last frame drawn: the one with every tile. Let the canvas show it.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const s = await status(page);
  t.diagnostic(`tiles: ${JSON.stringify(s.tiles)} in ${((Date.now() - started) / 1000).toFixed(1)} s`);
  assert.deepEqual(s.tile_failures, []);
  assert.ok(s.tiles.loaded > 0, 'height tiles from the DEM');
  const image = await canvasPixels(page);
  assert.ok(pixelsOfColor(image, MAGENTA, 60).count > 200, 'the track');
  // The same view without the terrain (the fragment's option comes last) is another picture: the
  // relief, lit and shadowed, instead of the flat neutral ground.
  const view = await page.evaluate(() => window.trailray.api.viewState());
  const flat = await openPage(browser, `${url}#${view}&terrain=none`);
  await framesDrawn(flat);
  const neutral = await canvasPixels(flat);
  await flat.close();
  let difference = 0;
  for (let i = 0; i < image.data.length; i += 4)
    for (let c = 0; c < 3; ++c) difference += Math.abs(image.data[i + c] - neutral.data[i + c]);
  const mean = difference / (image.data.length / 4) / 3;
  t.diagnostic(`terrain vs neutral ground: mean difference ${mean.toFixed(1)} of 255`);
  assert.ok(mean > 8, `the terrain changes the picture (mean difference ${mean.toFixed(1)})`);
  if (process.env.TRAILRAY_SCREENSHOT) await page.screenshot({ path: process.env.TRAILRAY_SCREENSHOT });
  await page.close();
});

test('serve --overlay HEATMAP: the page draws the heatmap on the terrain with its colour bar', async (t) => {
  const dem = path.join(config.sharedData || '', 'dem', 'interlaken_dhm25_wgs84.tif');
  const flight = path.join(config.sharedData || '', 'igc', 'goigc_0100_interlaken.igc');
  if (!config.sharedData || !fs.existsSync(dem) || !fs.existsSync(flight)) {
    t.skip(`needs ${dem} and ${flight} (../shared/data is absent)`);
    return;
  }
  const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'trailray-serve-overlay-'));
  const heat = path.join(scratch, 'heat.mbtiles');
  const made = spawnSync(config.nativeBinary, ['heatmap', flight, '-o', heat, '--cell', '100']);
  assert.equal(made.status, 0, String(made.stderr));
  const shown = async (args) => {
    const url = await serve(['--terrain', dem, '--imagery', 'none', '--legend', 'on', ...args]);
    const page = await openPage(browser, url);
    await page.waitForFunction(() => {
      const s = JSON.parse(window.trailray.api.status());
      return s.tiles.wanted > 0 && s.tiles.loaded + s.tiles.no_data + s.tiles.failed === s.tiles.wanted;
    }, { timeout: 180000, polling: 500 });
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const s = await status(page);
    const pixels = await canvasPixels(page);
    const messages = await page.evaluate(() => window.trailray.messages);
    await page.close();
    return { s, pixels, messages };
  };
  // No track: only the heatmap could make a legend or change the ground's colours.
  const plain = await shown(['--look-at', '46.71,7.84,1200', '--distance', '7000', '--pitch', '-60']);
  const over = await shown(['--overlay', heat, '--look-at', '46.71,7.84,1200', '--distance', '7000', '--pitch', '-60']);
  assert.deepEqual(over.s.tile_failures, []);
  assert.deepEqual(over.messages, []);
  assert.ok(!(plain.s.legend && plain.s.legend.width), 'no legend without the overlay');
  assert.ok(over.s.legend.width > 50 && over.s.legend.height > 20, `its colour bar (${JSON.stringify(over.s.legend)})`);
  let changed = 0;
  for (let i = 0; i < over.pixels.data.length; i += 4) {
    let d = 0;
    for (let c = 0; c < 3; ++c) d += Math.abs(over.pixels.data[i + c] - plain.pixels.data[i + c]);
    if (d > 30) ++changed;
  }
  t.diagnostic(`pixels the heatmap changed: ${changed}`);
  assert.ok(changed > 300, `the heatmap on the ground (${changed} pixels changed)`);
  fs.rmSync(scratch, { recursive: true, force: true });
});

// The Statistics panel (ui/'s, as the desktop viewer draws it) describes a served flight with the
// figures `trailray stats --json` gives for the same file: its lines are in the status as the
// panel draws them.
test('serve: the Statistics panel says what `trailray stats` says of the served flight', async (t) => {
  const flights = [path.join(config.sourceDir, 'examples', 'paraglider_flight.igc')];
  const real = path.join(config.sharedData || '', 'igc', 'goigc_0100_interlaken.igc');
  if (config.sharedData && fs.existsSync(real)) flights.push(real);
  else t.diagnostic(`${real} is absent: the example flight only`);
  for (const flight of flights) {
    const stats = await run(config.nativeBinary, ['stats', '--json', flight]);
    assert.equal(stats.code, 0, stats.output);
    const clean = JSON.parse(stats.output).files[0].tracks[0].clean;
    const url = await serve(['--terrain', 'none', '--imagery', 'none', flight]);
    const page = await openPage(browser, url, 1600, 900);
    await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).tracks.length === 1, { timeout: 60000 });
    await framesDrawn(page);
    const lines = (await status(page)).statistics.lines;
    t.diagnostic(`${path.basename(flight)}: ${lines.join('; ')}`);
    if (process.env.TRAILRAY_SCREENSHOT) await page.screenshot({ path: `${process.env.TRAILRAY_SCREENSHOT}-${path.basename(flight)}.png` });
    await page.close();
    const hms = (seconds) => {
      const s = Math.round(seconds);
      return `${Math.floor(s / 3600)}:${String(Math.floor(s / 60) % 60).padStart(2, '0')}:${String(s % 60).padStart(2, '0')}`;
    };
    assert.equal(lines[0], `points: ${clean.points}, segments: ${clean.segments}`);
    assert.ok(clean.points > 1000, `a real flight (${clean.points} points)`);
    assert.equal(lines[1], `distance: ${(clean.distance_2d_m / 1000).toFixed(3)} km`);
    assert.equal(lines[2], `duration: ${hms(clean.duration_s)}, moving: ${hms(clean.moving_time_s)}`);
    assert.equal(lines[3], `climb: +${Math.round(clean.elevation_gain_m)} m, descent: -${Math.round(clean.elevation_loss_m)} m`);
    assert.equal(lines[4], `altitude: ${Math.round(clean.min_elevation_m)} m to ${Math.round(clean.max_elevation_m)} m`);
    assert.ok(lines.every((l) => !l.includes('\u2014')), `no figure missing: ${lines.join('; ')}`);
  }
});

// "Loading terrain: N/M tiles" (bottom left) is drawn while tiles are on their way; once every
// tile the resting view wants is in, it goes away without the view moving (the interface is
// drawn again with the last figures, not left with those of the frame before).
test('serve --terrain DEM: once every tile is in and the view rests, "Loading terrain" goes away', async (t) => {
  const dem = path.join(config.sharedData || '', 'dem', 'interlaken_dhm25_wgs84.tif');
  const flight = path.join(config.sharedData || '', 'igc', 'goigc_0100_interlaken.igc');
  if (!config.sharedData || !fs.existsSync(dem) || !fs.existsSync(flight)) {
    t.skip(`needs ${dem} and ${flight} (../shared/data is absent)`);
    return;
  }
  const url = await serve(['--terrain', dem, '--imagery', 'none', flight]);
  const page = await openPage(browser, url);
  const loadingSeen = page.waitForFunction(() => {
    const s = JSON.parse(window.trailray.api.status()).interface.tiles_shown;
    return s.wanted > s.loaded + s.no_data + s.failed;
  }, { timeout: 180000, polling: 50 }).then(() => true, () => false);
  await page.waitForFunction(() => {
    const s = JSON.parse(window.trailray.api.status());
    return s.tracks.length === 1 && s.tiles.wanted > 0 && s.tiles.loaded + s.tiles.no_data + s.tiles.failed === s.tiles.wanted;
  }, { timeout: 180000, polling: 250 });
  assert.ok(await loadingSeen, 'the interface said "Loading terrain" while tiles came');
  // The view rests: nothing moves it, nothing more arrives. Within a second the line is gone.
  await new Promise((r) => setTimeout(r, 1500));
  const s = await status(page);
  const shown = s.interface.tiles_shown;
  t.diagnostic(`tiles ${JSON.stringify(s.tiles)}; the interface shows ${JSON.stringify(shown)}`);
  assert.equal(shown.wanted - shown.loaded - shown.no_data - shown.failed, 0,
    `the interface still says "Loading terrain: ${shown.loaded + shown.no_data + shown.failed}/${shown.wanted} tiles"`);
  // And the canvas shows no line there: its bottom left is the picture without the interface.
  const canvas = await canvasPixels(page);
  const picture = await screenshotPixels(page);
  let difference = 0, n = 0;
  for (let y = canvas.height - 30; y < canvas.height; ++y)
    for (let x = 0; x < 230; ++x, ++n)
      for (let c = 0; c < 3; ++c) difference += Math.abs(canvas.data[(y * canvas.width + x) * 4 + c] - picture.data[(y * canvas.width + x) * 4 + c]);
  const mean = difference / n / 3;
  t.diagnostic(`bottom left, canvas vs the picture without the interface: mean difference ${mean.toFixed(2)}`);
  if (process.env.TRAILRAY_SCREENSHOT) await page.screenshot({ path: `${process.env.TRAILRAY_SCREENSHOT}-rest.png` });
  assert.ok(mean < 1, `no text drawn at the bottom left (mean difference ${mean.toFixed(2)})`);
  await page.close();
});

test('serve --photos --places: the photo\'s thumbnail above its point on the track, the places\' labels', async () => {
  const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'trailray-serve-photos-'));
  // A walk east along 46.6° N at 2000 m, a point every 0.0005° and 10 s.
  let gpx = '<gpx version="1.1"><trk><name>Walk</name><trkseg>\n';
  for (let i = 0; i <= 40; ++i) {
    const time = new Date(Date.UTC(2024, 6, 1, 9, 0, i * 10)).toISOString().replace('.000', '');
    gpx += `<trkpt lat="46.6" lon="${(8 + i * 0.0005).toFixed(4)}"><ele>2000</ele><time>${time}</time></trkpt>\n`;
  }
  fs.writeFileSync(path.join(scratch, 'walk.gpx'), `${gpx}</trkseg></trk></gpx>\n`);
  // A flat red photo (made by the browser's canvas) taken at the walk's middle point (exiv2 writes its GPS).
  const maker = await browser.newPage();
  const jpeg = await maker.evaluate(() => {
    const c = document.createElement('canvas');
    c.width = 400; c.height = 300;
    const g = c.getContext('2d');
    g.fillStyle = '#ff0000';
    g.fillRect(0, 0, 400, 300);
    return c.toDataURL('image/jpeg', 0.95).split(',')[1];
  });
  await maker.close();
  const photo = path.join(scratch, 'red.jpg');
  fs.writeFileSync(photo, Buffer.from(jpeg, 'base64'));
  const exiv2 = spawnSync('exiv2', ['-M', 'set Exif.GPSInfo.GPSLatitude 46/1 36/1 0/1', '-M', 'set Exif.GPSInfo.GPSLatitudeRef N',
    '-M', 'set Exif.GPSInfo.GPSLongitude 8/1 0/1 36/1', '-M', 'set Exif.GPSInfo.GPSLongitudeRef E', photo]);
  assert.equal(exiv2.status, 0, `exiv2: ${exiv2.stderr}`);
  // A peak north of the walk and a village without an elevation, as OpenStreetMap XML.
  fs.writeFileSync(path.join(scratch, 'places.osm'), `<?xml version="1.0" encoding="UTF-8"?>
<osm version="0.6">
 <node id="1" lat="46.604" lon="8.01" version="1"><tag k="natural" v="peak"/><tag k="name" v="Testhorn"/><tag k="ele" v="2500"/></node>
 <node id="2" lat="46.596" lon="8.005" version="1"><tag k="place" v="village"/><tag k="name" v="Testdorf"/></node>
</osm>
`);
  const url = await serve(['--terrain', 'none', '--imagery', 'none', '--color', '#0000ff', '--photos', photo,
    '--places', path.join(scratch, 'places.osm'), path.join(scratch, 'walk.gpx')]);
  const page = await openPage(browser, `${url}?no-panels`);
  await page.waitForFunction(() => window.trailray.photosLoaded, { timeout: 60000 });
  await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).photos.thumbnails === 1, { timeout: 60000 });
  await framesDrawn(page);
  const s = await status(page);
  assert.deepEqual(s.photos.names, ['red.jpg']);
  assert.equal(s.places.count, 2);
  assert.deepEqual([...s.places.names].sort(), ['Testdorf', 'Testhorn 2500 m']);
  const image = await canvasPixels(page);
  const red = pixelsOfColor(image, [255, 0, 0], 60);
  const track = pixelsOfColor(image, [0, 0, 255], 60);
  // The thumbnail (72 px on its long side: 72 x 54) stands above the middle of the track.
  assert.ok(track.count > 200, `the track (${track.count} blue pixels)`);
  assert.ok(red.count > 1500 && red.count < 8000, `the thumbnail: ${red.count} red pixels`);
  assert.ok(Math.abs(red.x - track.x) < 40, `above the track's middle (x ${red.x.toFixed(0)} vs ${track.x.toFixed(0)})`);
  assert.ok(red.y < track.y - 20, `above the track (y ${red.y.toFixed(0)} vs ${track.y.toFixed(0)})`);
  assert.deepEqual(await page.evaluate(() => window.trailray.messages), []);
  if (process.env.TRAILRAY_SCREENSHOT) await page.screenshot({ path: `${process.env.TRAILRAY_SCREENSHOT}-photos.png` });
  // A click on the photo's pin (its ball stands on the track's line, just above it) shows it
  // larger, from the larger picture the page fetches then.
  await page.mouse.click(red.x, track.y - 12);
  await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).photos.enlarged === 0, { timeout: 30000 });
  await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).photos.wanted === null, { timeout: 30000 });
  await new Promise((r) => setTimeout(r, 3000));  // the flight to it
  await framesDrawn(page);
  const enlarged = pixelsOfColor(await canvasPixels(page), [255, 0, 0], 60);
  assert.ok(enlarged.count > 4 * red.count, `shown larger: ${enlarged.count} red pixels, ${red.count} before`);
  if (process.env.TRAILRAY_SCREENSHOT) await page.screenshot({ path: `${process.env.TRAILRAY_SCREENSHOT}-photo-enlarged.png` });
  await page.close();
  fs.rmSync(scratch, { recursive: true, force: true });
});
