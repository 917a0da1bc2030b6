// Benchmark: the page in headless Chromium (WebGL 2 on SwiftShader): load to the first frame,
// and the median of 7 frames while the camera moves, each timed around trailray_frame with a
// 1-pixel read-back (which waits for the GPU), and of 7 frames of the interface alone (the pointer
// over a panel: the scene's picture is kept). Prints one line per track; never fails a build.
//   node bench/page_frame.mjs TRACK...     (after scripts/web.sh and `npm ci --prefix tests/web`)
// Compare with `trailray render --terrain none --imagery none --size 960x540 --legend off
// --profile --frames 7 TRACK` in the same run (README, "Speed").
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const { staticServer, launchBrowser, openPage, framesDrawn } = await import(path.join(root, 'tests/web/harness.mjs'));

const tracks = process.argv.slice(2);
if (!tracks.length) {
  console.error('usage: node bench/page_frame.mjs TRACK...');
  process.exit(2);
}
const folder = path.dirname(path.resolve(tracks[0]));
const { server, url } = await staticServer(path.join(root, 'build-web/web'), { '/data/': `${folder}/` });
const browser = await launchBrowser();
try {
  for (const track of tracks) {
    const t0 = Date.now();
    const name = encodeURIComponent(path.basename(track));
    const page = await openPage(browser, `${url}?terrain=none&imagery=none&track=data/${name}`, 960, 540);
    await framesDrawn(page, 1);
    const first = (Date.now() - t0) / 1000;
    const times = await page.evaluate(() => {
      const api = window.trailray.api;
      const canvas = document.getElementById('canvas');
      const gl = canvas.getContext('webgl2');
      const pixel = new Uint8Array(4);
      const out = [];
      for (let i = 0; i < 7; ++i) {
        api.orbit(0.5, 0);
        const t = performance.now();
        api.frame(canvas.width, canvas.height, 1, 0.016);
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        out.push(performance.now() - t);
      }
      // Frames of the interface alone: the pointer over a panel, the scene's picture kept.
      const ui = [];
      for (let i = 0; i < 7; ++i) {
        api.pointer(100 + i, 100, 0);
        const t = performance.now();
        api.frame(canvas.width, canvas.height, 1, 0.016);
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        ui.push(performance.now() - t);
      }
      return { scene: out.sort((a, b) => a - b), ui: ui.sort((a, b) => a - b) };
    });
    const s = JSON.parse(await page.evaluate(() => window.trailray.api.status()));
    console.log(`${path.basename(track)}: ${s.tracks.map((t) => t.points).join('+')} points drawn; load to first frame ` +
      `${first.toFixed(1)} s; frame median ${times.scene[3].toFixed(0)} ms (min ${times.scene[0].toFixed(0)}, ` +
      `max ${times.scene[6].toFixed(0)}); interface-only frame median ${times.ui[3].toFixed(1)} ms`);
    await page.close();
  }
} finally {
  await browser.close();
  server.close();
}
