// What the browser tests share: Debian's Chromium headless with WebGL 2 on SwiftShader (the CPU,
// like llvmpipe natively), a static server for the built page and the test files, and reading
// the canvas's pixels back.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import puppeteer from 'puppeteer-core';

export const config = {
  webRoot: process.env.TRAILRAY_WEB_ROOT,       // build-web/web
  sourceDir: process.env.TRAILRAY_SOURCE_DIR,   // the repository (examples/)
  nativeBinary: process.env.TRAILRAY_BINARY,    // the native trailray (render, serve)
  sharedData: process.env.TRAILRAY_SHARED_DATA, // ../shared/data (may be absent)
  chromium: process.env.TRAILRAY_CHROMIUM || '/usr/lib/chromium/chromium',
};

const types = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.wasm': 'application/wasm' };

// Serves `root` at / and each of `extra` (URL prefix -> folder) beside it; resolves to the
// server and its base URL.
export function staticServer(root, extra = {}) {
  const server = http.createServer((request, response) => {
    const url = new URL(request.url, 'http://localhost');
    let folder = root;
    let rest = decodeURIComponent(url.pathname);
    for (const [prefix, dir] of Object.entries(extra)) {
      if (rest.startsWith(prefix)) { folder = dir; rest = rest.slice(prefix.length - 1); }
    }
    const file = path.join(folder, rest === '/' ? 'index.html' : rest);
    if (!file.startsWith(folder) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      response.writeHead(404).end('not found');
      return;
    }
    response.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(response);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => {
    resolve({ server, url: `http://127.0.0.1:${server.address().port}/` });
  }));
}

export async function launchBrowser() {
  return puppeteer.launch({
    executablePath: config.chromium,
    headless: true,
    args: ['--headless=new', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
      '--disable-dev-shm-usage', '--window-size=800,600'],
  });
}

// A page of the given CSS size at device pixel ratio 1, opened at `url`, once the viewer runs;
// `viewport` overrides puppeteer's viewport fields (deviceScaleFactor, hasTouch).
export async function openPage(browser, url, width = 640, height = 400, viewport = {}) {
  const page = await browser.newPage();
  await page.setViewport({ width, height, deviceScaleFactor: 1, ...viewport });
  const logs = [];
  page.on('console', (m) => logs.push(m.text()));
  page.on('pageerror', (e) => logs.push(String(e)));
  await page.goto(url);
  try {
    await page.waitForFunction(() => window.trailray && (window.trailray.started || window.trailray.failed),
      { timeout: 90000 });
  } catch (e) {
    throw new Error(`the page did not start: ${logs.join('\n')}`);
  }
  const failed = await page.evaluate(() => window.trailray.failed);
  if (failed) throw new Error(`the page failed: ${failed}\n${logs.join('\n')}`);
  page.logs = logs;
  return page;
}

// Waits until the viewer has drawn at least `count` frames in all.
export async function framesDrawn(page, count = 1) {
  await page.waitForFunction((n) => JSON.parse(window.trailray.api.status()).frames_drawn >= n, { timeout: 90000 }, count);
  // One more animation frame so the canvas shows it.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

// The canvas's pixels (RGBA, top-down) and size; `withLegend`: with the legend over them.
export async function canvasPixels(page, { withLegend = false } = {}) {
  const { width, height, data } = await page.evaluate((legendToo) => {
    const canvas = document.getElementById('canvas');
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    const legend = window.trailray.legend;
    if (legendToo && legend && legend.width) context.drawImage(document.getElementById('legend'), legend.x, legend.y);
    const image = context.getImageData(0, 0, copy.width, copy.height);
    return { width: copy.width, height: copy.height, data: Array.from(image.data) };
  }, withLegend);
  return { width, height, data: Uint8Array.from(data) };
}

// The picture as the Screenshot button saves it (the scene without the panels, the legend over it).
export async function screenshotPixels(page) {
  const { width, height, data } = await page.evaluate(() => {
    const picture = window.trailray.picture();
    const image = picture.getContext('2d').getImageData(0, 0, picture.width, picture.height);
    return { width: picture.width, height: picture.height, data: Array.from(image.data) };
  });
  return { width, height, data: Uint8Array.from(data) };
}

// Pixels close to an sRGB colour (each channel within `tolerance`): their count and centroid.
export function pixelsOfColor(image, rgb, tolerance = 40) {
  let count = 0, sx = 0, sy = 0;
  for (let y = 0; y < image.height; ++y) {
    for (let x = 0; x < image.width; ++x) {
      const i = (y * image.width + x) * 4;
      if (Math.abs(image.data[i] - rgb[0]) <= tolerance && Math.abs(image.data[i + 1] - rgb[1]) <= tolerance &&
          Math.abs(image.data[i + 2] - rgb[2]) <= tolerance) {
        ++count; sx += x; sy += y;
      }
    }
  }
  return { count, x: count ? sx / count : NaN, y: count ? sy / count : NaN };
}

// Runs a program to its end; resolves to its exit code and output.
export function run(program, args) {
  return new Promise((resolve) => {
    const child = spawn(program, args);
    let output = '';
    child.stdout.on('data', (d) => { output += d; });
    child.stderr.on('data', (d) => { output += d; });
    child.on('close', (code) => resolve({ code, output }));
  });
}
