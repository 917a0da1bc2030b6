// The page in headless Chromium (WebGL 2 on SwiftShader): it starts, draws a track opened through
// the file input in its colour, shows a broken file's error and keeps what is open, and a link
// with the command line's options draws what `trailray render` draws with the same options.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { after, before, test } from 'node:test';

import {
  canvasPixels, config, framesDrawn, launchBrowser, openPage, pixelsOfColor, run, screenshotPixels, staticServer,
} from './harness.mjs';

const MAGENTA = [255, 0, 255];
// No network in the tests: no online terrain (its default), so every picture is the same anywhere.
const OFFLINE = 'terrain=none&imagery=none';
let browser, server, base;
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'trailray-page-'));

before(async () => {
  ({ server, url: base } = await staticServer(config.webRoot, { '/examples/': path.join(config.sourceDir, 'examples') }));
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close();
  server?.close();
  fs.rmSync(scratch, { recursive: true, force: true });
});

async function status(page) {
  return JSON.parse(await page.evaluate(() => window.trailray.api.status()));
}

// Opens `file` through the page's file input and waits for the frame that shows the result.
async function pick(page, file) {
  const drawn = (await status(page)).frames_drawn;
  const count = () => page.evaluate(() => [window.trailray.openedFiles, window.trailray.messages.length]);
  const [opened, messages] = await count();
  const input = await page.$('#file-input');
  await input.uploadFile(file);
  await page.waitForFunction((n) => window.trailray.openedFiles + window.trailray.messages.length > n, {},
    opened + messages);
  if ((await count())[0] > opened) await framesDrawn(page, drawn + 1);  // a file that failed changes nothing
}

test('the page starts and draws the neutral ground', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}`);
  await framesDrawn(page);
  const image = await canvasPixels(page);
  assert.equal(image.width, 640);
  let sum = 0;
  for (let i = 0; i < image.data.length; i += 4) sum += image.data[i] + image.data[i + 1] + image.data[i + 2];
  const mean = sum / (image.data.length / 4) / 3;
  assert.ok(mean > 40 && mean < 250, `the picture is lit ground, not black or blank (mean ${mean})`);
  assert.equal(pixelsOfColor(image, MAGENTA).count, 0);
  await page.close();
});

test('a GPX given through the file input draws its track in its colour, framed', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&color=%23ff00ff`);
  await framesDrawn(page);
  assert.equal(pixelsOfColor(await canvasPixels(page), MAGENTA).count, 0, 'no track before one is opened');
  await pick(page, path.join(config.sourceDir, 'examples', 'hike.gpx'));
  const s = await status(page);
  assert.equal(s.tracks.length, 1);
  assert.equal(s.tracks[0].points, 860);
  assert.equal(s.tracks[0].color, '#ff00ff');
  const image = await canvasPixels(page);
  const track = pixelsOfColor(image, MAGENTA, 60);
  assert.ok(track.count > 400, `the track's pixels (${track.count})`);
  // Framed: the track's pixels gather around the middle of the picture.
  assert.ok(Math.abs(track.x - image.width / 2) < image.width * 0.2, `centred across (${track.x})`);
  assert.ok(Math.abs(track.y - image.height / 2) < image.height * 0.25, `centred down (${track.y})`);
  assert.match(s.tracks[0].name, /Harder slope hike/);
  await page.close();
});

test('a broken file shows its error (file and line) and what is open stays', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&color=%23ff00ff&track=examples/hike.gpx`);
  await framesDrawn(page);
  const before = pixelsOfColor(await canvasPixels(page), MAGENTA, 60).count;
  assert.ok(before > 400);
  const broken = path.join(scratch, 'broken.gpx');
  fs.writeFileSync(broken, '<?xml version="1.0"?>\n<gpx version="1.1">\n<trk><trkseg></trk>\n</gpx>\n');
  await pick(page, broken);
  const messages = await page.evaluate(() => window.trailray.messages);
  assert.equal(messages.length, 1, messages.join('\n'));
  assert.match(messages[0], /broken\.gpx/);
  assert.match(messages[0], /:3\b|line 3/, 'the position of the error');
  assert.match(await page.$eval('#messages', (m) => m.textContent), /broken\.gpx/, 'shown in the page');
  assert.equal((await status(page)).tracks.length, 1);
  assert.ok(pixelsOfColor(await canvasPixels(page), MAGENTA, 60).count > before * 0.9, 'the open track is still drawn');
  await page.close();
});

test('a bad option in the link is reported and the rest still applies', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&width=huge&color=%23ff00ff&track=examples/hike.gpx`);
  await framesDrawn(page);
  const messages = await page.evaluate(() => window.trailray.messages);
  assert.equal(messages.length, 1);
  assert.match(messages[0], /^width=huge/);
  assert.ok(pixelsOfColor(await canvasPixels(page), MAGENTA, 60).count > 400);
  await page.close();
});

// The same options as a link and on the command line. The two pictures come from the same
// renderer on two rasterizers (SwiftShader in Chromium, llvmpipe natively): they differ at edges
// by a pixel and in the last bits of shading, so the comparison is of the picture, not of bits:
// the track covers the same pixels (its magenta pixels overlap by 90 %) and the mean difference
// over all pixels is small (under 6 of 255; a view moved by a few degrees gives well over 10).
test('a link with ?track= and view options draws what `trailray render` draws', async (t) => {
  const view = 'terrain=none&imagery=none&look-at=46.6975,7.8625,800&distance=2600&heading=20&pitch=-35' +
    '&time=2024-06-18T12:00:00Z';
  // no-panels: the picture alone (`render` draws no panels).
  const page = await openPage(browser, `${base}?track=examples/hike.gpx&color=%23ff00ff&no-panels&${view}`);
  await framesDrawn(page);
  const web = await canvasPixels(page);
  await page.close();

  const native = path.join(scratch, 'native.png');
  const args = ['render', '--size', `${web.width}x${web.height}`,
    '--legend', 'off', '--color', '#ff00ff', '-o', native];
  for (const [name, value] of new URLSearchParams(view)) args.push(`--${name}`, value);
  args.push(path.join(config.sourceDir, 'examples', 'hike.gpx'));
  const rendered = await run(config.nativeBinary, args);
  assert.equal(rendered.code, 0, rendered.output);
  const reference = await pngPixels(native);
  assert.equal(reference.width, web.width);

  const a = pixelsOfColor(web, MAGENTA, 60), b = pixelsOfColor(reference, MAGENTA, 60);
  assert.ok(b.count > 300, `the native picture has the track (${b.count})`);
  assert.ok(Math.abs(a.count - b.count) < 0.1 * b.count, `track pixels: page ${a.count}, native ${b.count}`);
  assert.ok(Math.hypot(a.x - b.x, a.y - b.y) < 3, `track centroids ${a.x},${a.y} and ${b.x},${b.y}`);
  let difference = 0;
  for (let i = 0; i < web.data.length; i += 4)
    for (let c = 0; c < 3; ++c) difference += Math.abs(web.data[i + c] - reference.data[i + c]);
  const mean = difference / (web.data.length / 4) / 3;
  t.diagnostic(`page vs native: track pixels ${a.count} vs ${b.count}, mean difference ${mean.toFixed(2)} of 255`);
  assert.ok(mean < 6, `mean difference ${mean.toFixed(2)} of 255`);
});

// A PNG's pixels, decoded by the browser.
async function pngPixels(file) {
  const page = await browser.newPage();
  const encoded = fs.readFileSync(file).toString('base64');
  const result = await page.evaluate(async (data) => {
    const image = new Image();
    image.src = `data:image/png;base64,${data}`;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    return { width: image.width, height: image.height, data: Array.from(context.getImageData(0, 0, image.width, image.height).data) };
  }, encoded);
  await page.close();
  return { width: result.width, height: result.height, data: Uint8Array.from(result.data) };
}

test('the view kept in the address reproduces the picture after a drag', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&track=examples/hike.gpx&color=%23ff00ff`);
  await framesDrawn(page);
  const first = await status(page);
  await page.mouse.move(320, 200);
  await page.mouse.down();
  await page.mouse.move(380, 230, { steps: 5 });
  await page.mouse.up();
  await framesDrawn(page, first.frames_drawn + 1);
  const moved = await canvasPixels(page);
  const address = page.url();
  assert.match(address, /#look-at=[-0-9.]+,[-0-9.]+,[-0-9.]+&distance=[0-9.]+&heading=[-0-9.]+&pitch=[-0-9.]+.*color=/);
  await page.close();

  const again = await openPage(browser, address);
  await framesDrawn(again);
  const restored = await canvasPixels(again);
  await again.close();
  const a = pixelsOfColor(moved, MAGENTA, 60), b = pixelsOfColor(restored, MAGENTA, 60);
  assert.ok(a.count > 300);
  // The fragment rounds the view (1e-6 degrees, 0.1 m, 0.01 degrees): the same picture within a pixel.
  assert.ok(Math.hypot(a.x - b.x, a.y - b.y) < 1.5, `centroids ${a.x},${a.y} and ${b.x},${b.y}`);
  assert.ok(Math.abs(a.count - b.count) < 0.05 * a.count);
});

test('the legend over the page is the one `trailray render` draws into its picture', async (t) => {
  const view = 'terrain=none&imagery=none&look-at=46.70,7.85,1500&distance=9000&heading=0&pitch=-40' +
    '&time=2024-07-14T12:00:00Z&color-by=vspeed';
  const page = await openPage(browser, `${base}?track=examples/paraglider_flight.igc&${view}`);
  await framesDrawn(page);
  const legend = (await status(page)).legend;
  assert.ok(legend.width > 50 && legend.height > 20, `a colour bar (${JSON.stringify(legend)})`);
  const web = await canvasPixels(page, { withLegend: true });
  await page.close();

  const native = path.join(scratch, 'legend.png');
  const args = ['render', '--size', `${web.width}x${web.height}`, '-o', native];
  for (const [name, value] of new URLSearchParams(view)) args.push(`--${name}`, value);
  args.push(path.join(config.sourceDir, 'examples', 'paraglider_flight.igc'));
  const rendered = await run(config.nativeBinary, args);
  assert.equal(rendered.code, 0, rendered.output);
  const reference = await pngPixels(native);
  // Within the legend's panel: the same panel, text and colour bar (mean difference of a few
  // levels for the picture showing through its translucent back; a missing legend gives ~100).
  let difference = 0;
  for (let y = legend.y; y < legend.y + legend.height; ++y)
    for (let x = legend.x; x < legend.x + legend.width; ++x)
      for (let c = 0; c < 3; ++c) {
        const i = (y * web.width + x) * 4 + c;
        difference += Math.abs(web.data[i] - reference.data[i]);
      }
  const mean = difference / (legend.width * legend.height * 3);
  t.diagnostic(`legend panel: mean difference ${mean.toFixed(2)} of 255`);
  assert.ok(mean < 6, `mean difference in the legend ${mean.toFixed(2)}`);
});

// The viewer's interface in the page (ui/: the same panels and overlays as `trailray view`), at
// 960x540 where the panels open at fixed places (ui/panel_layout: the track list at the top left
// under the menu bar, its first row's visibility box at 28,70; the compass at the right, 36 px in
// from the edge, 241 px down).
const WIDE = [960, 540];

// Waits until the page has drawn the interface after an input (a few animation frames).
const settle = (page) => page.evaluate(() => new Promise((r) => {
  let n = 0;
  const step = () => (++n >= 8 ? r() : requestAnimationFrame(step));
  requestAnimationFrame(step);
}));

// The share of the canvas the interface covers: pixels where the canvas (picture and panels)
// differs from the picture alone (the screenshot's) by more than 30 levels.
async function interfaceShare(page) {
  const canvas = await canvasPixels(page, { withLegend: true });
  const picture = await screenshotPixels(page);
  await settle(page);  // the interface comes back after the picture
  return changedPixels(canvas, picture) / (canvas.width * canvas.height);
}

// On a small window (here a laptop's 1280x720) the 3D view comes first: the track list opens, the
// other panels folded to their title bars; a large one (1600x900) opens them all as before.
test('the panels open folded on a small window, the 3D view first, and open on a large one', async (t) => {
  const url = `${base}?${OFFLINE}&track=examples/paraglider_flight.igc`;
  const small = await openPage(browser, url, 1280, 720);
  await framesDrawn(small);
  await settle(small);
  const folded = (await status(small)).panels;
  const smallShare = await interfaceShare(small);
  if (process.env.TRAILRAY_SCREENSHOT) await small.screenshot({ path: `${process.env.TRAILRAY_SCREENSHOT}-1280x720.png` });
  await small.close();
  const large = await openPage(browser, url, 1600, 900);
  await framesDrawn(large);
  await settle(large);
  const opened = (await status(large)).panels;
  const largeShare = await interfaceShare(large);
  if (process.env.TRAILRAY_SCREENSHOT) await large.screenshot({ path: `${process.env.TRAILRAY_SCREENSHOT}-1600x900.png` });
  await large.close();
  t.diagnostic(`the interface covers ${(100 * smallShare).toFixed(1)} % of 1280x720, ${(100 * largeShare).toFixed(1)} % of 1600x900`);
  const names = ['Tracks', 'Statistics', 'Profile', 'Replay'];
  assert.deepEqual(names.map((n) => folded[n]?.collapsed), [false, true, true, true], JSON.stringify(folded));
  for (const n of names)  // the folded ones' title bars inside the window
    assert.ok(folded[n].x >= 0 && folded[n].y >= 0 && folded[n].x + folded[n].width <= 1280 && folded[n].y + 19 <= 720,
      `${n} at ${JSON.stringify(folded[n])}`);
  assert.ok(smallShare < 0.2, `the panels leave the 3D view free (${(100 * smallShare).toFixed(1)} % covered)`);
  assert.deepEqual(names.map((n) => opened[n]?.collapsed), [false, false, false, false], JSON.stringify(opened));
  assert.ok(largeShare > 0.3, `a large window opens the panels (${(100 * largeShare).toFixed(1)} % covered)`);
});

// A range dragged across the Profile's chart: its statistics (seven lines under the chart) show in
// full, the panel inside the window; on a small window the Profile opens folded at the bottom
// and, unfolded, comes up into the window.
test('a range dragged across the profile shows its statistics in full, inside the window', async (t) => {
  for (const [width, height] of [[1280, 720], [960, 540], [1600, 900]]) {
    const page = await openPage(browser, `${base}?${OFFLINE}&track=examples/paraglider_flight.igc`, width, height);
    await framesDrawn(page);
    await settle(page);
    let p = (await status(page)).panels.Profile;
    const inside = (q) => q.x >= 0 && q.y >= 0 && q.x + q.width <= width && q.y + q.height <= height;
    if (p.collapsed) {
      await page.mouse.click(p.x + 10, p.y + 9);  // its title bar's arrow
      await settle(page);
      p = (await status(page)).panels.Profile;
      assert.equal(p.collapsed, false, 'unfolded by its arrow');
    }
    assert.ok(inside(p), `${width}x${height}: the Profile inside the window (${JSON.stringify(p)})`);
    // The plot: under the title bar and the axis buttons, right of the altitude labels.
    const y = p.y + 19 + 8 + 23 + 34;
    const left = p.x + 8 + 48, plot = p.width - 16 - 48;
    await page.mouse.move(left + plot * 0.3, y);
    await page.mouse.down();
    await page.mouse.move(left + plot * 0.7, y, { steps: 8 });
    await page.mouse.up();
    await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).selection.length > 0, { timeout: 20000 });
    await settle(page);
    const s = await status(page);
    p = s.panels.Profile;
    t.diagnostic(`${width}x${height}: ${JSON.stringify(p)}; ${s.selection.join('; ')}`);
    if (process.env.TRAILRAY_SCREENSHOT) await page.screenshot({ path: `${process.env.TRAILRAY_SCREENSHOT}-${width}x${height}.png` });
    await page.close();
    assert.equal(s.selection.length, 7);
    assert.match(s.selection[0], /^points: \d+, segments: 1$/);
    assert.equal(p.collapsed, false);
    assert.ok(inside(p), `${width}x${height}: the Profile inside the window (${JSON.stringify(p)})`);
    assert.equal(p.scroll_max, 0, `${width}x${height}: every line of the panel in sight (${p.scroll_max} px scrolled out)`);
  }
});

test('hover over the track shows its tooltip (the point\'s numbers) over the picture', async (t) => {
  const page = await openPage(browser, `${base}?${OFFLINE}&color=%23ff00ff&track=examples/hike.gpx`, ...WIDE);
  await framesDrawn(page);
  await settle(page);
  const before = await canvasPixels(page);
  // A pixel of the track: the magenta pixel nearest the track's centroid.
  const track = pixelsOfColor(before, MAGENTA, 60);
  assert.ok(track.count > 400, `the track is drawn (${track.count})`);
  let best = null;
  for (let y = 0; y < before.height; ++y)
    for (let x = 0; x < before.width; ++x) {
      const i = (y * before.width + x) * 4;
      const d = Math.abs(before.data[i] - 255) + before.data[i + 1] + Math.abs(before.data[i + 2] - 255);
      if (d < 60) {
        const r = Math.hypot(x - track.x, y - track.y);
        if (!best || r < best.r) best = { x, y, r };
      }
    }
  await page.mouse.move(best.x, best.y);
  await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).hover.track === 0, { timeout: 20000 });
  await settle(page);
  const hover = (await status(page)).hover;
  t.diagnostic(`hovered ${best.x},${best.y}: ${hover.lines.join('; ')}`);
  assert.match(hover.lines[0], /^time: 20\d\d-\d\d-\d\d \d\d:\d\d:\d\d UTC$/);
  assert.ok(hover.lines.some((l) => /^altitude: \d+ m$/.test(l)), hover.lines.join('; '));
  // The tooltip: a dark box right of and below the cursor that was not there before.
  const after = await canvasPixels(page);
  let changed = 0, dark = 0;
  for (let y = best.y + 12; y < Math.min(after.height, best.y + 140); ++y)
    for (let x = best.x + 12; x < Math.min(after.width, best.x + 220); ++x) {
      const i = (y * after.width + x) * 4;
      if (Math.abs(after.data[i] - before.data[i]) + Math.abs(after.data[i + 1] - before.data[i + 1]) > 60) ++changed;
      if (after.data[i] + after.data[i + 1] + after.data[i + 2] < 120) ++dark;
    }
  assert.ok(changed > 5000 && dark > 5000, `the tooltip's box (${changed} pixels changed, ${dark} dark)`);
  // Away from the track: no tooltip, the picture as before.
  await page.mouse.move(5, before.height - 5);
  await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).hover.track === -1, { timeout: 20000 });
  await page.close();
});

// The part of a 960x540 picture that no panel covers (right of the track list, above the chart,
// below the menu bar): the panels themselves show the track's colour (its swatch, its profile).
function pictureArea(image) {
  const [left, top, right, bottom] = [270, 60, 900, 360];
  const data = new Uint8Array((right - left) * (bottom - top) * 4);
  for (let y = top; y < bottom; ++y)
    data.set(image.data.subarray((y * image.width + left) * 4, (y * image.width + right) * 4), (y - top) * (right - left) * 4);
  return { width: right - left, height: bottom - top, data };
}

test('the Tracks panel hides and shows a track; the scene is drawn again for it', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&color=%23ff00ff&track=examples/hike.gpx`, ...WIDE);
  await framesDrawn(page);
  await settle(page);
  const shown = pixelsOfColor(pictureArea(await canvasPixels(page)), MAGENTA, 60).count;
  assert.ok(shown > 400, `the track is drawn (${shown})`);
  const drawn = (await status(page)).frames_drawn;
  await page.mouse.click(28, 70);
  await framesDrawn(page, drawn + 1);
  await settle(page);
  const hidden = pixelsOfColor(pictureArea(await canvasPixels(page)), MAGENTA, 60).count;
  assert.ok(hidden < shown * 0.05, `hidden: ${hidden} magenta pixels of ${shown}`);
  await page.mouse.click(28, 70);
  await framesDrawn(page, drawn + 2);
  await settle(page);
  const again = pixelsOfColor(pictureArea(await canvasPixels(page)), MAGENTA, 60).count;
  assert.ok(Math.abs(again - shown) < shown * 0.05, `shown again: ${again} of ${shown}`);
  // Hovering a panel draws the interface, not the scene.
  const frames = (await status(page)).frames_drawn;
  await page.mouse.move(120, 100);
  await settle(page);
  assert.equal((await status(page)).frames_drawn, frames);
  await page.close();
});

test('the compass turns the view north up', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&track=examples/hike.gpx&heading=70`, ...WIDE);
  await framesDrawn(page);
  await settle(page);
  const heading = async () => Number(/heading=([-0-9.]+)/.exec(await page.evaluate(() => window.trailray.api.viewState()))[1]);
  assert.ok(Math.abs((await heading()) - 70) < 0.5, `starts at the given heading (${await heading()})`);
  await page.mouse.click(WIDE[0] - 36, 241);
  await page.waitForFunction(() => / heading=0\.00|&heading=-?0\.00/.test(`&${window.trailray.api.viewState()}`),
    { timeout: 30000 });
  await page.close();
});

// Pixels that differ by more than 30 levels (in any channel) between two pictures of one size.
function changedPixels(a, b) {
  let n = 0;
  for (let i = 0; i < a.data.length; i += 4)
    if (Math.max(...[0, 1, 2].map((c) => Math.abs(a.data[i + c] - b.data[i + c]))) > 30) ++n;
  return n;
}

test('an edit in the panels goes into the address like the option it stands for', async (t) => {
  const page = await openPage(browser, `${base}?${OFFLINE}&color=%23ff00ff&track=examples/hike.gpx`, ...WIDE);
  await framesDrawn(page);
  await settle(page);
  assert.doesNotMatch(page.url(), /curtain/);
  const before = pictureArea(await canvasPixels(page));
  // The Tracks panel's "curtain" box (a solid track: its fourth row, the third box).
  const drawn = (await status(page)).frames_drawn;
  await page.mouse.click(176, 149);
  await framesDrawn(page, drawn + 1);
  await page.waitForFunction(() => /[#&]curtain=1/.test(location.hash), { timeout: 20000 });
  await settle(page);
  const curtained = pictureArea(await canvasPixels(page));
  const curtain = changedPixels(before, curtained);
  assert.ok(curtain > 1000, `the curtain under the track (${curtain} pixels changed)`);
  // The address reproduces it.
  const again = await openPage(browser, page.url(), ...WIDE);
  await page.close();
  await framesDrawn(again);
  await settle(again);
  const restored = changedPixels(curtained, pictureArea(await canvasPixels(again)));
  t.diagnostic(`curtain: ${curtain} pixels changed; reopened from the address: ${restored} differ`);
  assert.ok(restored < curtain * 0.05, `reopened: ${restored} pixels differ from the edited picture`);
  await again.close();
});

// Mean absolute difference of two pictures of one size, per channel, in levels of 255.
function meanDifference(a, b) {
  let sum = 0;
  for (let i = 0; i < a.data.length; i += 4)
    for (let c = 0; c < 3; ++c) sum += Math.abs(a.data[i + c] - b.data[i + c]);
  return sum / (a.data.length / 4) / 3;
}

test('the screenshot is the picture without the panels, with the legend', async (t) => {
  const view = `${OFFLINE}&track=examples/paraglider_flight.igc&color-by=vspeed&look-at=46.70,7.85,1500` +
    '&distance=9000&heading=0&pitch=-40&time=2024-07-14T12:00:00Z';
  const page = await openPage(browser, `${base}?${view}`, ...WIDE);
  await framesDrawn(page);
  await settle(page);
  const withPanels = await canvasPixels(page, { withLegend: true });
  const shot = await screenshotPixels(page);
  await settle(page);
  const after = await canvasPixels(page, { withLegend: true });
  await page.close();
  const bare = await openPage(browser, `${base}?${view}&no-panels`, ...WIDE);
  await framesDrawn(bare);
  await settle(bare);
  const picture = await canvasPixels(bare, { withLegend: true });
  await bare.close();
  const [toPicture, toPanels, back] = [meanDifference(shot, picture), meanDifference(shot, withPanels),
    meanDifference(after, withPanels)];
  t.diagnostic(`screenshot vs the bare picture ${toPicture.toFixed(2)}, vs the canvas with panels ${toPanels.toFixed(2)}`);
  assert.equal(shot.width, WIDE[0]);
  assert.ok(toPicture < 1, `the screenshot is the picture (mean difference ${toPicture.toFixed(2)})`);
  assert.ok(toPanels > 5, `the panels are not in it (${toPanels.toFixed(2)} from the canvas with them)`);
  assert.ok(back < 1, `the panels come back after it (${back.toFixed(2)})`);
});

test('the keys are the desktop viewer\'s: E turns the view, N turns it north up', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&track=examples/hike.gpx&heading=0`, ...WIDE);
  await framesDrawn(page);
  await page.focus('#canvas');
  const heading = async () => Number(/heading=([-0-9.]+)/.exec(await page.evaluate(() => window.trailray.api.viewState()))[1]);
  await page.keyboard.down('KeyE');
  await new Promise((r) => setTimeout(r, 800));
  await page.keyboard.up('KeyE');
  const turned = await heading();
  assert.ok(Math.abs(turned) > 5, `E held turns the view (heading ${turned})`);
  await page.keyboard.press('KeyN');
  await page.waitForFunction(() => /&heading=-?0\.00&/.test(`&${window.trailray.api.viewState()}&`), { timeout: 30000 });
  await page.close();
});

test('the shading panel\'s time of day moves the sun, live while dragged, and goes into the address', async (t) => {
  const page = await openPage(browser, `${base}?${OFFLINE}&track=examples/hike.gpx&time=2024-07-13T10:00:00Z`, ...WIDE);
  await framesDrawn(page);
  await settle(page);
  const before = pictureArea(await canvasPixels(page));
  // Windows menu (top left) -> Shading (its fifth entry); the panel opens with the time slider
  // in its first row (x 277..517 for 0..24 h at this size).
  await page.mouse.click(40, 10);
  await settle(page);
  await page.mouse.click(37, 112);
  await settle(page);
  const drawn = (await status(page)).frames_drawn;
  await page.mouse.move(377, 70);
  await page.mouse.down();
  await page.mouse.move(437, 70, { steps: 4 });
  await settle(page);
  assert.ok((await status(page)).frames_drawn > drawn, 'the scene is drawn again while the slider is dragged');
  await page.mouse.up();
  await page.waitForFunction(() => /[#&]time=2024-07-13T1[5-7]:\d\d:\d\dZ/.test(location.hash), { timeout: 20000 });
  await settle(page);
  const moved = changedPixels(before, pictureArea(await canvasPixels(page)));
  t.diagnostic(`${/time=[^&]*/.exec(new URL(page.url()).hash)[0]}: ${moved} pixels changed (the shadows moved)`);
  assert.ok(moved > 1000, `the sun moved the shadows (${moved} pixels changed)`);
  await page.close();
});

// A Terrarium height tile (PNG, 256 x 256, RGB) of z/x/y: rolling hills of +-300 m about 800 m,
// waves 3 and 4 km long in Web Mercator metres, so neighbouring tiles of any zoom meet and the
// ground is relief, lit and shadowed, not the flat neutral plane.
function hillTile(z, x, y) {
  const size = 256;
  const world = 40075016.686;
  const rows = Buffer.alloc(size * (1 + size * 3));
  for (let j = 0; j < size; ++j) {
    rows[j * (1 + size * 3)] = 0;  // filter: none
    const my = world / 2 - ((y * size + j + 0.5) / (size * 2 ** z)) * world;
    for (let i = 0; i < size; ++i) {
      const mx = ((x * size + i + 0.5) / (size * 2 ** z)) * world - world / 2;
      const height = 800 + 300 * Math.sin((2 * Math.PI * mx) / 3000) * Math.cos((2 * Math.PI * my) / 4000);
      const v = Math.round((height + 32768) * 256);
      rows.set([(v >> 16) & 255, (v >> 8) & 255, v & 255], j * (1 + size * 3) + 1 + i * 3);
    }
  }
  const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (bytes) => {
    let c = 0xffffffff;
    for (const b of bytes) c = crcTable[(c ^ b) & 255] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type, data) => {
    const length = Buffer.alloc(4);
    length.writeUInt32BE(data.length);
    const body = Buffer.concat([Buffer.from(type, 'ascii'), data]);
    const sum = Buffer.alloc(4);
    sum.writeUInt32BE(crc(body));
    return Buffer.concat([length, body, sum]);
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(size, 0);
  header.writeUInt32BE(size, 4);
  header.set([8, 2, 0, 0, 0], 8);  // 8 bits, RGB
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', header),
    chunk('IDAT', zlib.deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]);
}

// A tile server of another origin (so it sends CORS headers, as the page's note says it must)
// that answers /NAME/z/x/y.png with the hills and records what was asked.
async function hillTileServer() {
  const asked = [];
  const server = http.createServer((request, response) => {
    asked.push(request.url);
    const zxy = /\/(\d+)\/(\d+)\/(\d+)\.png/.exec(request.url);
    if (!zxy) { response.writeHead(404, { 'Access-Control-Allow-Origin': '*' }).end(); return; }
    response.writeHead(200, { 'Content-Type': 'image/png', 'Access-Control-Allow-Origin': '*' })
      .end(hillTile(...zxy.slice(1).map(Number)));
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  return { server, asked, url: `http://127.0.0.1:${server.address().port}/` };
}

// Every tile the view wants has come (none left on its way).
const allTilesIn = (page) => page.waitForFunction(() => {
  const s = JSON.parse(window.trailray.api.status());
  return s.tiles.wanted > 0 && s.tiles.loaded + s.tiles.no_data + s.tiles.failed === s.tiles.wanted;
}, { timeout: 120000, polling: 250 });

test('a terrain template typed into "Terrain & imagery" draws its tiles, and the address keeps it', async (t) => {
  const tiles = await hillTileServer();
  try {
    const page = await openPage(browser, `${base}?${OFFLINE}&no-panels&color=%23ff00ff&track=examples/hike.gpx`);
    await framesDrawn(page);
    const flat = await canvasPixels(page);
    await page.click('#sources-button');
    assert.equal(await page.$eval('#sources', (f) => f.hidden), false, 'the form opens');
    assert.equal(await page.$eval('#sources [name=terrain]', (i) => i.value), 'none', 'it shows the source in use');

    // A wrong template is refused with its reason; the form stays open, the source unchanged.
    await page.$eval('#sources [name=terrain]', (i) => { i.value = ''; });
    await page.type('#sources [name=terrain]', 'ftp://tiles.example/{z}/{x}/{y}.png');
    await page.click('#sources button[type=submit]');
    assert.match((await page.evaluate(() => window.trailray.messages)).join('\n'), /^terrain=ftp:.*expected none or a URL template/m);
    assert.equal(await page.$eval('#sources', (f) => f.hidden), false);
    assert.equal((await status(page)).sources.terrain, 'none');

    // A template whose own query has two parameters: '&' must survive the address.
    const template = `${tiles.url}hills/{z}/{x}/{y}.png?a=1&b=2`;
    await page.$eval('#sources [name=terrain]', (i) => { i.value = ''; });
    await page.type('#sources [name=terrain]', template);
    await page.click('#sources button[type=submit]');
    assert.equal(await page.$eval('#sources', (f) => f.hidden), true, 'applied, the form closes');
    const s = await status(page);
    assert.equal(s.sources.terrain, template);
    assert.equal(s.sources.terrain_encoding, 'terrarium');
    await allTilesIn(page);
    await settle(page);
    assert.deepEqual((await status(page)).tile_failures, []);
    assert.ok(tiles.asked.length > 0 && tiles.asked.every((u) => /^\/hills\/\d+\/\d+\/\d+\.png\?a=1&b=2$/.test(u)),
      tiles.asked.slice(0, 3).join(' '));
    const hills = await canvasPixels(page);
    const changed = meanDifference(flat, hills);
    t.diagnostic(`${tiles.asked.length} tiles asked; hills vs no terrain: mean difference ${changed.toFixed(1)} of 255`);
    assert.ok(changed > 8, `the terrain is drawn (mean difference ${changed.toFixed(1)})`);
    assert.match(new URL(page.url()).hash, /[#&]terrain=http:\/\/127\.0\.0\.1:\d+\/hills\/\{z\}\/\{x\}\/\{y\}\.png\?a=1%26b=2(&|$)/);

    // The copied address opens the same source and the same picture.
    const again = await openPage(browser, page.url());
    assert.equal((await status(again)).sources.terrain, template);
    await allTilesIn(again);
    await settle(again);
    const reopened = meanDifference(hills, await canvasPixels(again));
    t.diagnostic(`reopened from the address: mean difference ${reopened.toFixed(2)}`);
    assert.ok(reopened < 1, `reopened: mean difference ${reopened.toFixed(2)}`);
    await again.close();
    await page.close();
  } finally {
    tiles.server.close();
  }
});

// Tiles asked for by a view the camera has left arrive all the same; they are never taken (the
// view wants others) and must not pile up over a long session: what the page keeps of them is
// bounded, while the view moves across many places, and the tiles of the view it rests on come.
test('fetched tiles the view no longer wants are kept within a bound while the view moves far', async (t) => {
  const tiles = await hillTileServer();
  try {
    const template = encodeURIComponent(`${tiles.url}hills/{z}/{x}/{y}.png`);
    const page = await openPage(browser,
      `${base}?imagery=none&terrain=${template}&no-panels&look-at=46.0,6.0,800&distance=4000&pitch=-35`);
    await framesDrawn(page);
    let mostKept = 0;
    // Twelve places a degree or more apart: each wants its own tiles (all but the coarsest).
    for (let i = 1; i <= 12; ++i) {
      const drawn = (await status(page)).frames_drawn;
      await page.evaluate((v) => window.trailray.api.setOption('look-at', v), `${46 + (i % 4) * 0.9},${6 + i * 1.1},800`);
      await framesDrawn(page, drawn + 2);
      mostKept = Math.max(mostKept, (await status(page)).tiles.kept);
    }
    await allTilesIn(page);
    await new Promise((r) => setTimeout(r, 1500));  // the last answers of earlier views come in
    const s = await status(page);
    mostKept = Math.max(mostKept, s.tiles.kept);
    t.diagnostic(`${tiles.asked.length} tiles asked; kept unused at most ${mostKept}, now ${s.tiles.kept} ` +
      `(${(s.tiles.kept_bytes / 1e6).toFixed(1)} MB); ${s.tiles.dropped} dropped`);
    assert.ok(tiles.asked.length > 150, `the view asked for many tiles (${tiles.asked.length})`);
    assert.ok(mostKept <= 64, `tiles kept unused: at most ${mostKept} (bound 64)`);
    assert.ok(s.tiles.dropped > 0, 'more than the bound arrived unwanted, and the oldest were let go');
    // The view it rests on still got every tile it wants.
    assert.equal(s.tiles.loaded + s.tiles.no_data, s.tiles.wanted);
    assert.deepEqual(s.tile_failures, []);
    await page.close();
  } finally {
    tiles.server.close();
  }
});

// The view's numbers as the fragment has them.
async function viewOf(page) {
  const state = new URLSearchParams(await page.evaluate(() => window.trailray.api.viewState()));
  return { target: state.get('look-at'), distance: Number(state.get('distance')), heading: Number(state.get('heading')) };
}

test('touch: one finger orbits, two fingers pan, a pinch zooms', async () => {
  const page = await openPage(browser, `${base}?${OFFLINE}&no-panels&track=examples/hike.gpx&heading=0`, 640, 400,
    { hasTouch: true });
  await framesDrawn(page);
  const cdp = await page.createCDPSession();
  // Touch points in CSS pixels; each move is one event with every finger's place.
  const gesture = async (from, to, steps = 6) => {
    const at = (k) => from.map(([x, y], i) => ({ id: i, x: x + ((to[i][0] - x) * k) / steps, y: y + ((to[i][1] - y) * k) / steps }));
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
    for (let k = 1; k <= steps; ++k) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k) });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await settle(page);
  };
  const start = await viewOf(page);

  await gesture([[320, 200]], [[420, 200]]);
  const orbited = await viewOf(page);
  assert.ok(Math.abs(orbited.heading - start.heading) > 5, `one finger turns the view (heading ${orbited.heading})`);
  assert.equal(orbited.target, start.target, 'about the same point');

  await gesture([[300, 200], [340, 200]], [[220, 200], [420, 200]]);
  const pinched = await viewOf(page);
  assert.ok(pinched.distance < orbited.distance * 0.6,
    `spreading two fingers zooms in (distance ${orbited.distance} -> ${pinched.distance})`);
  assert.ok(Math.abs(pinched.heading - orbited.heading) < 1, 'and does not turn the view');

  await gesture([[280, 150], [360, 150]], [[280, 300], [360, 300]]);
  const panned = await viewOf(page);
  assert.notEqual(panned.target, pinched.target, 'two fingers moved together pan the view');
  assert.ok(Math.abs(panned.distance / pinched.distance - 1) < 0.1,
    `without zooming (distance ${pinched.distance} -> ${panned.distance})`);
  await page.close();
});

test('at device pixel ratio 2 the canvas has twice the pixels and the same picture', async (t) => {
  const url = `${base}?${OFFLINE}&no-panels&color=%23ff00ff&track=examples/hike.gpx`;
  const one = await openPage(browser, url);
  await framesDrawn(one);
  const sharp = await openPage(browser, url, 640, 400, { deviceScaleFactor: 2 });
  await framesDrawn(sharp);
  const [a, b] = [await canvasPixels(one), await canvasPixels(sharp)];
  await one.close();
  await sharp.close();
  assert.deepEqual([b.width, b.height], [1280, 800]);
  const [ta, tb] = [pixelsOfColor(a, MAGENTA, 60), pixelsOfColor(b, MAGENTA, 60)];
  t.diagnostic(`track pixels ${ta.count} at ratio 1, ${tb.count} at ratio 2 (${(tb.count / ta.count).toFixed(2)}x)`);
  // The same view: the track where it was, relative to the picture.
  assert.ok(Math.abs(ta.x / a.width - tb.x / b.width) < 0.02 && Math.abs(ta.y / a.height - tb.y / b.height) < 0.02,
    `the track in the same place (${ta.x / a.width}, ${ta.y / a.height} vs ${tb.x / b.width}, ${tb.y / b.height})`);
  // The track's width is in CSS pixels: twice as long and twice as wide, about four times the
  // pixels (a width left in device pixels would give about two).
  assert.ok(tb.count > 3 * ta.count && tb.count < 5 * ta.count, `${tb.count} vs ${ta.count}`);
});
