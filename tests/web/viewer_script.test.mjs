// One viewer, two front ends: the same script of inputs run by the desktop's `trailray view
// --script` (in a window under Xvfb) and by the page (trailray_run_script, in headless Chromium),
// and what they show compared line for line: the session's state (ui/session_state.hpp: tracks,
// the Statistics panel's lines, the hover and its tooltip, the camera, warnings) after each
// step, print-hover and print-camera.
import assert from 'node:assert/strict';
import path from 'node:path';
import { after, before, test } from 'node:test';

import { config, framesDrawn, launchBrowser, openPage, run, staticServer } from './harness.mjs';

const WIDTH = 800, HEIGHT = 600;
// No network, and a view given (the first camera the same whatever each lays out around it).
const VIEW = [['terrain', 'none'], ['imagery', 'none'], ['look-at', '46.6975,7.8625,800'], ['distance', '2600'],
  ['heading', '20'], ['pitch', '-35']];
const TRACK = 'hike.gpx';
let browser, server, base;

before(async () => {
  ({ server, url: base } = await staticServer(config.webRoot, { '/examples/': path.join(config.sourceDir, 'examples') }));
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close();
  server?.close();
});

// The page with the track open and its first frame drawn (the camera placed for the canvas).
async function pageWithTrack() {
  const query = new URLSearchParams([['track', `examples/${TRACK}`], ...VIEW, ['no-panels', '']]);
  const page = await openPage(browser, `${base}?${query}`, WIDTH, HEIGHT);
  await page.waitForFunction(() => JSON.parse(window.trailray.api.status()).tracks.length > 0, { timeout: 60000 });
  await framesDrawn(page);
  return page;
}

async function pageRun(page, script) {
  const result = JSON.parse(await page.evaluate((s) => window.trailray.api.runScript(s), script));
  assert.equal(result.error, null, `the page ran the script: ${result.error}`);
  return result.output;
}

async function desktopRun(script) {
  const file = path.join(process.env.TMPDIR || '/tmp', `trailray-script-${process.pid}.txt`);
  (await import('node:fs')).writeFileSync(file, script);
  const args = ['-a', '-s', '-screen 0 1280x720x24', config.nativeBinary, 'view', '--size', `${WIDTH}x${HEIGHT}`];
  for (const [name, value] of VIEW) args.push(`--${name}`, value);
  args.push('--script', file, path.join(config.sourceDir, 'examples', TRACK));
  const r = await run('xvfb-run', args);
  assert.equal(r.code, 0, r.output);
  return r.output;
}

// What both print: the state's JSON lines, the hover with its tooltip, the camera.
function shown(output) {
  return output.split('\n').filter((l) => l.startsWith('{') || l.startsWith('hover:') || l.startsWith('  ') ||
    l.startsWith('camera:') || l.startsWith('marker:'));
}

test('one script of inputs: the desktop viewer and the page show the same', async (t) => {
  const page = await pageWithTrack();
  // A pixel on the track: where the replay's marker stands after a while.
  const marker = /marker: track 0 point \d+ at ([0-9.]+) ([0-9.]+)/.exec(
    await pageRun(page, 'speed 200\nplay 5\nprint-marker\n'));
  assert.ok(marker, 'the marker is in the picture');
  await page.close();
  const [x, y] = [Number(marker[1]), Number(marker[2])];
  const script = [
    'hide-panels', 'print-state',
    `hover ${x} ${y}`, 'print-hover', 'print-state',
    'orbit 60 -10', 'print-camera', 'print-state',
    'zoom 2', 'print-camera',
    'select 0', 'print-camera', 'print-state',
    'hover 3 3', 'print-hover',
  ].join('\n') + '\n';

  const web = shown(await pageRun(await pageWithTrack(), script));
  const desktop = shown(await desktopRun(script));
  t.diagnostic(`desktop: ${desktop.filter((l) => !l.startsWith('{')).join(' | ')}`);
  // Each viewer says something of every step: four states, the hover's tooltip, four cameras.
  assert.equal(web.filter((l) => l.startsWith('{')).length, 4);
  assert.ok(web.some((l) => /^hover: track 0 '.*' point \d+$/.test(l)), `the page hovers the track: ${web.join('\n')}`);
  assert.ok(web.includes('hover: none'), 'a corner hovers nothing');
  const state = JSON.parse(web[0]);
  assert.equal(state.tracks.length, 1);
  assert.ok(state.statistics.length > 3, 'the Statistics panel has its lines');
  assert.deepEqual(web, desktop);
});
