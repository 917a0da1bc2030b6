// The page: opens tracks (file picker, drag and drop, ?track=URL, `trailray serve`'s tracks),
// applies the command line's options from the URL (and from serve's configuration), passes the
// gestures to the viewer (trailray.wasm, page_api.cpp) and asks it for a frame each animation
// frame. The view is kept in the address's fragment, so a copied address reproduces it.
'use strict';

const page = {
  api: null,
  ready: null,       // resolves once the viewer runs
  started: false,    // (tests wait on these two)
  failed: null,      // why the viewer cannot run
  messages: [],      // every error and note shown, for tests
  openedFiles: 0,
  photosLoaded: false,  // serve's photo thumbnails fetched (tests wait on it)
};
window.trailray = page;

let resolveReady;
page.ready = new Promise((resolve) => { resolveReady = resolve; });

var Module = {
  canvas: document.getElementById('canvas'),
  onRuntimeInitialized: () => {
    start().catch((e) => {
      showMessage(String(e));
      page.failed = String(e);
    });
  },
  printErr: (text) => console.warn(text),
};

function showMessage(text, kind) {
  page.messages.push(text);
  const box = document.createElement('div');
  box.textContent = text;
  if (kind === 'note') box.className = 'note';
  document.getElementById('messages').appendChild(box);
  setTimeout(() => box.remove(), kind === 'note' ? 6000 : 20000);
}

function bindApi() {
  const c = (name, ret, args) => Module.cwrap(name, ret, args);
  return {
    start: c('trailray_start', 'string', []),
    openTrack: c('trailray_open_track', 'string', ['string', 'number', 'number']),
    setOption: c('trailray_set_option', 'string', ['string', 'string']),
    orbit: c('trailray_orbit', null, ['number', 'number']),
    pan: c('trailray_pan', null, ['number', 'number', 'number', 'number']),
    zoom: c('trailray_zoom', null, ['number', 'number', 'number']),
    frame: c('trailray_frame', 'number', ['number', 'number', 'number', 'number']),
    error: c('trailray_error', 'string', []),
    viewState: c('trailray_view_state', 'string', []),
    status: c('trailray_status', 'string', []),
    legendPixels: c('trailray_legend_pixels', 'number', []),
    pointer: c('trailray_pointer', 'number', ['number', 'number', 'number']),
    wheel: c('trailray_wheel', 'number', ['number', 'number']),
    key: c('trailray_key', 'number', ['number', 'number', 'number']),
    char: c('trailray_char', null, ['number']),
    picture: c('trailray_picture', 'number', []),
    setServedPins: c('trailray_set_served_pins', 'string', ['string']),
    photoPicture: c('trailray_photo_picture', 'string', ['number', 'number', 'number', 'number']),
    // The desktop's `view --script` commands on the viewer (the tests run one script in both).
    runScript: c('trailray_run_script', 'string', ['string']),
  };
}

// A file's bytes into the viewer: "" or the reader's error (naming the file and the position).
function openBytes(name, bytes) {
  const pointer = Module._malloc(Math.max(bytes.length, 1));
  Module.HEAPU8.set(bytes, pointer);
  let error;
  try {
    error = page.api.openTrack(name, pointer, bytes.length);
  } finally {
    Module._free(pointer);
  }
  if (error) {
    showMessage(error);
  } else {
    page.openedFiles += 1;
    updateTrackList();
  }
  return error;
}

// A photo's picture (serve's JPEG) into the viewer for its pin: the thumbnail, or the larger one
// of the photo shown enlarged.
async function loadPhotoPicture(index, url, large) {
  try {
    const response = await fetch(url);
    if (!response.ok) throw new Error(`${response.status} ${response.statusText}`);
    const bytes = new Uint8Array(await response.arrayBuffer());
    const pointer = Module._malloc(Math.max(bytes.length, 1));
    Module.HEAPU8.set(bytes, pointer);
    let error;
    try {
      error = page.api.photoPicture(index, large ? 1 : 0, pointer, bytes.length);
    } finally {
      Module._free(pointer);
    }
    if (error) showMessage(error, 'note');
  } catch (e) {
    showMessage(`${url}: cannot be loaded (${e.message})`, 'note');
  }
}

// serve's photos (pins, plain until their thumbnails come) and places (labels).
async function openServedPins(served) {
  const error = page.api.setServedPins(JSON.stringify({ photos: served.photos || [], places: served.places || [] }));
  if (error) { showMessage(error); return; }
  const thumbnails = (served.photos || []).map((p, i) => (p.thumbnail ? loadPhotoPicture(i, new URL(p.thumbnail, location.href).href, false) : null));
  await Promise.all(thumbnails.filter(Boolean));
  page.photosLoaded = true;
}

// The larger picture of the photo shown enlarged, asked for once.
const largePhotosAsked = new Set();
function loadWantedPhoto(status) {
  const wanted = status.photos && status.photos.wanted;
  if (!wanted || largePhotosAsked.has(wanted.index)) return;
  largePhotosAsked.add(wanted.index);
  loadPhotoPicture(wanted.index, new URL(wanted.url, location.href).href, true);
}

async function openFiles(files) {
  for (const file of files) openBytes(file.name, new Uint8Array(await file.arrayBuffer()));
}

async function openUrl(url) {
  const name = decodeURIComponent(new URL(url, location.href).pathname.split('/').pop() || 'track');
  setProgress(`loading ${name}`);
  try {
    const response = await fetch(url);
    if (!response.ok) throw new Error(`${response.status} ${response.statusText}`);
    openBytes(name, new Uint8Array(await response.arrayBuffer()));
  } catch (e) {
    showMessage(`${url}: cannot be loaded (${e.message})`);
  } finally {
    setProgress('');
  }
}

function setProgress(text) { document.getElementById('progress').textContent = text; }

function setOption(name, value) {
  const error = page.api.setOption(name, value);
  if (error) showMessage(error);
  return error;
}

// The tracks are listed in the viewer's own Tracks panel; the page only hides its drop hint.
function updateTrackList() {
  const status = JSON.parse(page.api.status());
  document.body.classList.toggle('has-tracks', status.tracks.length > 0);
  for (const w of status.warnings) showMessage(w, 'note');
}

// The options of a query string or fragment, in order (`track` apart).
function optionsOf(text) {
  const options = [];
  const tracks = [];
  for (const [name, value] of new URLSearchParams(text)) {
    if (name === 'track') tracks.push(value);
    else if (!window.trailrayTileCache?.options.includes(name)) options.push([name, value]);  // tile_cache.js's
  }
  return { options, tracks };
}

// `trailray serve` describes its tracks and options at api/config.json; elsewhere there is none.
async function servedConfig() {
  try {
    const response = await fetch('api/config.json');
    if (!response.ok) return null;
    return await response.json();
  } catch (e) {
    return null;
  }
}

// serve's terrain and imagery (its own tiles: relative URLs, made absolute), or none.
function applyServedLayers(served) {
  for (const layer of ['terrain', 'imagery']) {
    if (!(layer in served)) continue;
    const source = served[layer];
    if (!source) { setOption(layer, 'none'); continue; }
    setOption(layer, new URL(source.url, location.href).href.replace(/%7B/g, '{').replace(/%7D/g, '}'));
    if (layer === 'terrain' && source.encoding) setOption('terrain-encoding', source.encoding);
    if (source.max_zoom !== undefined) setOption(`${layer}-max-zoom`, String(source.max_zoom));
    // A heatmap serve drew into its imagery (--overlay): its colour bar.
    if (layer === 'imagery' && source.legend) setOption('overlay-legend', JSON.stringify(source.legend));
  }
}

// The pointer, wheel and keys go to the viewer's panels first (page_api.cpp): what they want
// (a panel under the pointer, a text field with the focus) does not move the camera.
function installGestures(canvas) {
  const pointers = new Map();
  const ratio = () => window.devicePixelRatio || 1;
  const css = (e) => { const r = canvas.getBoundingClientRect(); return [e.clientX - r.left, e.clientY - r.top]; };
  const at = (e) => css(e).map((v) => v * ratio());
  const toPanels = (e) => { const [x, y] = css(e); return page.api.pointer(x, y, e.buttons) === 1; };
  let pinch = null;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('pointerdown', (e) => {
    canvas.setPointerCapture(e.pointerId);
    canvas.focus();
    const panels = toPanels(e);
    pointers.set(e.pointerId, { xy: at(e), button: e.button, shift: e.shiftKey, panels });
    pinch = null;
  });
  const release = (e) => { toPanels(e); pointers.delete(e.pointerId); pinch = null; };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('pointerleave', () => { if (!pointers.size) page.api.pointer(NaN, NaN, 0); });
  canvas.addEventListener('pointermove', (e) => {
    toPanels(e);
    const p = pointers.get(e.pointerId);
    if (!p || p.panels) return;
    const xy = at(e);
    if (pointers.size === 1) {
      if (p.button === 2 || p.shift) page.api.pan(p.xy[0], p.xy[1], xy[0], xy[1]);
      else page.api.orbit((xy[0] - p.xy[0]) / ratio(), (xy[1] - p.xy[1]) / ratio());
      p.xy = xy;
      return;
    }
    p.xy = xy;
    // Two fingers: the midpoint pans, the spread zooms about it.
    const [a, b] = [...pointers.values()];
    const mid = [(a.xy[0] + b.xy[0]) / 2, (a.xy[1] + b.xy[1]) / 2];
    const spread = Math.hypot(a.xy[0] - b.xy[0], a.xy[1] - b.xy[1]);
    if (pinch) {
      page.api.pan(pinch.mid[0], pinch.mid[1], mid[0], mid[1]);
      if (pinch.spread > 0 && spread > 0) page.api.zoom(Math.log(spread / pinch.spread) / Math.log(1 / 0.8), mid[0], mid[1]);
    }
    pinch = { mid, spread };
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const xy = at(e);
    const lines = e.deltaMode === 1 ? e.deltaY / 3 : e.deltaY / 100;
    if (page.api.wheel(-lines, 0) === 1) return;  // a panel scrolls
    page.api.zoom(-lines, xy[0], xy[1]);
  }, { passive: false });
  const modifiers = (e) => (e.ctrlKey ? 1 : 0) | (e.shiftKey ? 2 : 0) | (e.altKey ? 4 : 0) | (e.metaKey ? 8 : 0);
  canvas.addEventListener('keyup', (e) => page.api.key(e.keyCode, 0, modifiers(e)));
  canvas.addEventListener('keydown', (e) => {
    const panels = page.api.key(e.keyCode, 1, modifiers(e)) === 1;
    if (e.key.length === 1 && !e.ctrlKey && !e.metaKey) page.api.char(e.key.codePointAt(0));
    if (panels) { if (e.key === 'Tab' || e.key === ' ') e.preventDefault(); return; }
    // The camera keys are the viewer's (as on the desktop: WASD or arrows move, Q/E turn, Page
    // Up/Down tilt, +/- zoom, N north up, F fly to the track, space plays the replay); P saves
    // the picture as the Screenshot button does.
    if (e.key === 'p' || e.key === 'P') document.getElementById('screenshot').click();
    if (e.key.startsWith('Arrow') || e.key.startsWith('Page') || e.key === ' ') e.preventDefault();
  });
}

function installFileOpening() {
  document.getElementById('file-input').addEventListener('change', (e) => {
    openFiles([...e.target.files]);
    e.target.value = '';
  });
  window.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dragging'); });
  window.addEventListener('dragleave', () => document.body.classList.remove('dragging'));
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    document.body.classList.remove('dragging');
    openFiles([...e.dataTransfer.files]);
  });
}

// The picture as "Screenshot" saves it, at the canvas's size: the scene without the panels (drawn
// for it; the next frame puts them back), the legend over it.
page.picture = () => {
  const canvas = document.getElementById('canvas');
  page.api.picture();
  const picture = document.createElement('canvas');
  picture.width = canvas.width;
  picture.height = canvas.height;
  const context = picture.getContext('2d');
  context.drawImage(canvas, 0, 0);
  if (page.legend && page.legend.width) context.drawImage(document.getElementById('legend'), page.legend.x, page.legend.y);
  return picture;
};

function installButtons() {
  document.getElementById('share').addEventListener('click', async () => {
    try {
      await navigator.clipboard.writeText(location.href);
      showMessage('a link to this view is on the clipboard', 'note');
    } catch (e) {
      showMessage(`copy this link: ${location.href}`, 'note');
    }
  });
  document.getElementById('screenshot').addEventListener('click', () => {
    page.picture().toBlob((blob) => {
      const link = document.createElement('a');
      link.href = URL.createObjectURL(blob);
      link.download = 'trailray.png';
      link.click();
      setTimeout(() => URL.revokeObjectURL(link.href), 1000);
    }, 'image/png');
  });
}

// "Terrain & imagery": the sources in use, as URL templates, changed in the page (the `terrain`,
// `terrain-encoding` and `imagery` options, so the address keeps them like any other).
function installSourcesForm() {
  const form = document.getElementById('sources');
  const button = document.getElementById('sources-button');
  const encoding = form.elements['terrain-encoding'];
  let encodingChosen = false;  // else the terrain option's guess from its URL stands
  const fill = (sources) => {
    form.elements.terrain.value = sources.terrain;
    encoding.value = sources.terrain_encoding;
    form.elements.imagery.value = sources.imagery;
  };
  const show = (open) => {
    form.hidden = !open;
    button.setAttribute('aria-expanded', String(open));
    if (!open) { document.getElementById('canvas').focus(); return; }
    fill(JSON.parse(page.api.status()).sources);
    encodingChosen = false;
    form.elements.terrain.focus();
  };
  button.addEventListener('click', () => show(form.hidden));
  form.elements.cancel.addEventListener('click', () => show(false));
  form.elements.defaults.addEventListener('click', () => {
    fill(JSON.parse(page.api.status()).default_sources);
    encodingChosen = true;
  });
  encoding.addEventListener('change', () => { encodingChosen = true; });
  form.addEventListener('keydown', (e) => { if (e.key === 'Escape') show(false); });
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    const now = JSON.parse(page.api.status()).sources;
    const terrain = form.elements.terrain.value.trim() || 'none';
    const imagery = form.elements.imagery.value.trim() || 'none';
    let failed = false;
    // Only what changed: setting a source again would drop what serve gave with it (max zoom).
    if (terrain !== now.terrain) failed ||= Boolean(setOption('terrain', terrain));
    if (!failed && terrain !== 'none' && encodingChosen && encoding.value !== now.terrain_encoding)
      failed ||= Boolean(setOption('terrain-encoding', encoding.value));
    if (!failed && imagery !== now.imagery) failed ||= Boolean(setOption('imagery', imagery));
    tileFailureShown = false;  // the new sources' first failure is news
    if (!failed) show(false);
  });
}

// "terrain: 12 of 25 tiles" while tiles are on their way; the first failure once, as a note.
let tileFailureShown = false;
function showTileProgress(status) {
  const t = status.tiles;
  const pending = t.wanted - t.loaded - t.no_data - t.failed;
  setProgress(pending > 0 ? `terrain: ${t.loaded + t.no_data} of ${t.wanted} tiles` : '');
  if (status.tile_failures.length && !tileFailureShown) {
    tileFailureShown = true;
    showMessage(`${status.tile_failures[0]} (and ${status.tile_failures.length - 1} more)`, 'note');
  }
}

// The legend the viewer drew with the frame, in its canvas over the picture (redrawn only when
// its version changes).
let legendVersion = -1;
function showLegend(legend, ratio) {
  if (legend.version === legendVersion) return;
  legendVersion = legend.version;
  const overlay = document.getElementById('legend');
  const pointer = page.api.legendPixels();
  if (!legend.width || !pointer) { overlay.width = overlay.height = 0; return; }
  overlay.width = legend.width;
  overlay.height = legend.height;
  Object.assign(overlay.style, { left: `${legend.x / ratio}px`, top: `${legend.y / ratio}px`,
    width: `${legend.width / ratio}px`, height: `${legend.height / ratio}px` });
  const bytes = Module.HEAPU8.slice(pointer, pointer + legend.width * legend.height * 4);
  overlay.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(bytes.buffer), legend.width), 0, 0);
  page.legend = legend;
}

function runFrames(canvas) {
  let last = performance.now();
  let lastState = '';
  const step = (now) => {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(canvas.clientHeight * ratio));
    if (canvas.width !== width || canvas.height !== height) { canvas.width = width; canvas.height = height; }
    const drew = page.api.frame(width, height, ratio, (now - last) / 1000);
    last = now;
    if (drew < 0) showMessage(`drawing failed: ${page.api.error()}`);
    if (drew > 0) {
      const status = JSON.parse(page.api.status());
      showTileProgress(status);
      showLegend(status.legend, ratio);
      loadWantedPhoto(status);
      const state = page.api.viewState();
      if (state !== lastState) {
        lastState = state;
        history.replaceState(null, '', `${location.pathname}${location.search}#${state}`);
      }
    }
    requestAnimationFrame(step);
  };
  requestAnimationFrame(step);
}

async function start() {
  page.api = bindApi();
  const canvas = document.getElementById('canvas');
  const failure = page.api.start();
  if (failure) {
    showMessage(failure);
    page.failed = failure;
    return;
  }
  installGestures(canvas);
  installFileOpening();
  installButtons();
  installSourcesForm();
  await window.trailrayTileCache?.ready;  // what follows is fetched through the tile cache

  // Served options first, then the query's, then the fragment's (the view last seen).
  const served = await servedConfig();
  const query = optionsOf(location.search.slice(1));
  const fragment = optionsOf(location.hash.slice(1));
  if (served) applyServedLayers(served);
  if (served && served.options) for (const [name, value] of Object.entries(served.options)) setOption(name, String(value));
  for (const [name, value] of query.options) setOption(name, value);
  for (const url of (served && served.tracks ? served.tracks.map((t) => t.url) : [])) await openUrl(url);
  for (const url of query.tracks) await openUrl(url);
  if (served && ((served.photos && served.photos.length) || (served.places && served.places.length))) {
    await openServedPins(served);
  }
  for (const [name, value] of fragment.options) setOption(name, value);
  runFrames(canvas);
  page.started = true;
  resolveReady();
}
