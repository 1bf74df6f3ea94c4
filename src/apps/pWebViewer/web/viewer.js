// The page: picks its data source (an inlined replay, ?replay=URL of its own origin, or the
// server's /events, whose hello says live or replay), owns the map view and the side pane, and
// exposes the test hooks window.viewerState() and window.viewerFrameStats(). All state changes
// go through state.js's applyMail/expire. Text from the mail reaches the DOM only as textContent.
// A button press carries the run's token from the page's own URL (?token=, printed by
// pWebViewer at start-up) in a header, which no other site's page can send (docs/viewer.md,
// "Trust model").
import { newState, stateForHello, applyMail, expire, summary, SCORE_COLUMNS,
         SCORE_HEADINGS } from './state.js';
import { Replay } from './replay.js';
import { render } from './render.js';
import { makeView, toWorld, bbox } from './view.js';
import { PixelLayer } from './pixel_layer.js';

const $ = (id) => document.getElementById(id);
const canvas = $('map');
const ctx = canvas.getContext('2d');
const view = makeView(0, 0, 1);
const pixels = new PixelLayer();
const params = new URLSearchParams(location.search);
const FLUSH_FOR_STATS = params.get('flush') === '1';  // bench: include rasterisation in draw_ms
const TOKEN = params.get('token') || '';
/** Real seconds a live mail may run ahead of the server's last clock event (its delivery). */
const CLOCK_SLACK_S = 2;

const LAYERS = [
  ['marker', 'hazards (markers)'], ['polygon', 'swaths (polygons)'],
  ['circle', 'detections (circles)'], ['seglist', 'seglists'], ['point', 'points'],
  ['trails', 'trails'], ['vehicles', 'vehicles'], ['labels', 'labels'],
];
const layers = Object.fromEntries(LAYERS.map(([k]) => [k, true]));

let state = newState();
let replay = null;
let viewTouched = false;   // until the user pans or zooms, the view follows the content
let dirty = true;
let drawnVersion = -1;
let drawnState = null;
let lastFrame = 0;
let lastDrawn = 0;
let objectsDrawn = 0;
const frameStats = { draw_ms: [], interval_ms: [] };
const MAX_STATS = 600;

// ---------------------------------------------------------------------------------- data sources

function startReplay(data) {
  replay = new Replay(data);
  replay.seek(replay.start);
  state = replay.state;
  $('replay').hidden = false;
  $('mode').textContent = 'replay';
  showButtons([]);  // a replay posts nothing
  resize();
}

/** The server's clock as its last hello or clock event told it, and when that came. */
const serverClock = { time: 0, warp: 1, at: 0 };

function heardClock(msg) {
  if (!Number.isFinite(msg.time)) return;
  serverClock.time = msg.time;
  serverClock.at = performance.now();
  if (Number.isFinite(msg.warp) && msg.warp > 0) serverClock.warp = msg.warp;
}

/** The latest MOOS time a live mail may move the page's clock to: the server's clock now. */
function liveClockLimit() {
  const elapsed = (performance.now() - serverClock.at) / 1000;
  return serverClock.time + (elapsed + CLOCK_SLACK_S) * serverClock.warp;
}

function startLive() {
  $('mode').textContent = 'live';
  const source = new EventSource('events');
  source.onmessage = (event) => {
    let msg;
    try { msg = JSON.parse(event.data); } catch { return; }
    if (msg.type === 'hello' && msg.mode === 'replay') {
      source.close();
      loadReplay('replay.json');
    } else if (msg.type === 'hello') {
      // A (re)connection: the server sends its retained state again after the hello.
      heardClock(msg);
      state = stateForHello(msg, 'live');
      showButtons(msg.buttons);
    } else if (msg.type === 'mail') {
      state.clockLimit = liveClockLimit();
      applyMail(state, msg);
    } else if (msg.type === 'clock') {
      heardClock(msg);
      if (Number.isFinite(msg.warp)) state.warp = msg.warp;
      state.clockLimit = liveClockLimit();
      expire(state, msg.time);
      state.version++;
    }
  };
  source.onerror = () => { $('mode').textContent = 'live (reconnecting)'; };
  source.onopen = () => { $('mode').textContent = 'live'; };
}

/**
 * Inlined replay (an exported HTML file), else ?replay=URL, else the server's /events: its hello
 * says whether it is live or replaying a log (then the mail comes from replay.json).
 */
async function chooseSource() {
  if (window.VIEWER_REPLAY) return startReplay(window.VIEWER_REPLAY);
  if (params.get('replay')) return loadReplay(params.get('replay'));
  startLive();
}

/** `text` as a URL of the page's own origin, else null: a link to the page must not make it
 * show a mission served from elsewhere. */
function ownOriginUrl(text) {
  let url;
  try { url = new URL(text, location.href); } catch { return null; }
  return location.origin !== 'null' && url.origin === location.origin ? url : null;
}

async function loadReplay(text) {
  const url = ownOriginUrl(text);
  if (!url) {
    $('mode').textContent = 'replay refused: not from this server';
    return;
  }
  const reply = await fetch(url, { cache: 'no-store', redirect: 'error' });
  if (!reply.ok) throw new Error(`${url}: HTTP ${reply.status}`);
  startReplay(await reply.json());
}

function showButtons(buttons) {
  const box = $('buttons');
  box.textContent = '';
  for (const b of buttons || []) {
    const el = document.createElement('button');
    el.textContent = b.label;
    el.disabled = !TOKEN;
    if (!TOKEN) el.title = 'open the URL pWebViewer printed at start-up (with its ?token=) to press';
    el.onclick = () => fetch(`button/${b.index}`, { method: 'POST', headers: { 'X-Viewer-Token': TOKEN } });
    box.appendChild(el);
  }
}

// ---------------------------------------------------------------------------------- view

function resize() {
  const r = canvas.getBoundingClientRect();
  const dpr = window.devicePixelRatio || 1;
  canvas.width = Math.max(1, Math.round(r.width * dpr));
  canvas.height = Math.max(1, Math.round(r.height * dpr));
  view.w = canvas.width; view.h = canvas.height;
  dirty = true;
}

function contentBox() {
  const box = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity };
  const grow = (b) => {
    box.x0 = Math.min(box.x0, b.x0); box.y0 = Math.min(box.y0, b.y0);
    box.x1 = Math.max(box.x1, b.x1); box.y1 = Math.max(box.y1, b.y1);
  };
  for (const map of Object.values(state.kinds)) for (const o of map.values()) grow(bbox(o));
  for (const v of state.vehicles.values()) grow({ x0: v.x, y0: v.y, x1: v.x, y1: v.y });
  return Number.isFinite(box.x0) ? box : null;
}

function fit() {
  const b = contentBox();
  if (!b) return;
  const margin = 40;
  view.cx = (b.x0 + b.x1) / 2; view.cy = (b.y0 + b.y1) / 2;
  view.scale = Math.min((view.w - 2 * margin) / Math.max(b.x1 - b.x0, 10),
                        (view.h - 2 * margin) / Math.max(b.y1 - b.y0, 10));
  dirty = true;
}

function zoomAt(factor, sx, sy) {
  const [wx, wy] = toWorld(view, sx, sy);
  view.scale = Math.max(1e-4, Math.min(1e4, view.scale * factor));
  const [wx2, wy2] = toWorld(view, sx, sy);
  view.cx += wx - wx2; view.cy += wy - wy2;
  viewTouched = true; dirty = true;
}

function setupInteraction() {
  let drag = null;
  const dpr = () => window.devicePixelRatio || 1;
  canvas.addEventListener('pointerdown', (e) => {
    drag = { x: e.clientX, y: e.clientY };
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    const r = canvas.getBoundingClientRect();
    const [wx, wy] = toWorld(view, (e.clientX - r.left) * dpr(), (e.clientY - r.top) * dpr());
    $('cursor').textContent = `x=${wx.toFixed(1)} y=${wy.toFixed(1)}`;
    if (!drag) return;
    view.cx -= ((e.clientX - drag.x) * dpr()) / view.scale;
    view.cy += ((e.clientY - drag.y) * dpr()) / view.scale;
    drag = { x: e.clientX, y: e.clientY };
    viewTouched = true; dirty = true;
  });
  const end = () => { drag = null; };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const r = canvas.getBoundingClientRect();
    zoomAt(Math.exp(-e.deltaY * 0.0015), (e.clientX - r.left) * dpr(), (e.clientY - r.top) * dpr());
  }, { passive: false });
  $('zoom-in').onclick = () => zoomAt(1.5, view.w / 2, view.h / 2);
  $('zoom-out').onclick = () => zoomAt(1 / 1.5, view.w / 2, view.h / 2);
  $('zoom-fit').onclick = () => { fit(); viewTouched = true; };
  window.addEventListener('resize', resize);
  const box = $('layers');
  for (const [key, text] of LAYERS) {
    const label = document.createElement('label');
    const input = document.createElement('input');
    input.type = 'checkbox'; input.checked = true; input.dataset.layer = key;
    input.onchange = () => { layers[key] = input.checked; dirty = true; };
    label.append(input, ` ${text}`);
    box.appendChild(label);
  }
  $('play').onclick = () => {
    if (!replay) return;
    if (replay.t >= replay.end) replay.seek(replay.start);
    replay.playing = !replay.playing;
  };
  $('speed').onchange = () => { if (replay) replay.speed = Number($('speed').value); };
  $('slider').oninput = () => {
    if (!replay) return;
    replay.seek(replay.start + (replay.end - replay.start) * Number($('slider').value) / 1000);
    state = replay.state;
  };
}

// ---------------------------------------------------------------------------------- side pane

let selectedCast = null;
let castPicked = false;    // until the user picks an AppCast, the sensor's is shown
let paneVersion = -1;
let paneState = null;

function updatePane() {
  // Elapsed MOOS seconds since the earliest time seen (as pMarineViewer shows it); the absolute
  // MOOS time (warped, so far from the epoch at warp > 1) is in the tooltip.
  const first = state.firstTime;
  $('time').textContent = Number.isFinite(first) ? (state.time - first).toFixed(1) : '-';
  $('time').title = `MOOS time ${state.time.toFixed(2)}`;
  $('warp').textContent = String(state.warp);
  const k = state.kinds;
  $('counts').textContent = `${state.vehicles.size} vehicles, ${k.marker.size} markers, ` +
    `${k.circle.size} circles, ${k.polygon.size} polygons` +
    (state.rejected ? `, ${state.rejected} malformed postings ignored` : '');
  if (replay) {
    $('play').textContent = replay.playing ? 'pause' : 'play';
    const span = replay.end - replay.start;
    if (span > 0) $('slider').value = String(Math.round(1000 * (replay.t - replay.start) / span));
    $('replay-time').textContent = `${(replay.t - replay.start).toFixed(1)} / ${span.toFixed(1)} s`;
  }
  if (paneVersion === state.version && paneState === state) return;
  paneVersion = state.version;
  paneState = state;
  updateScore();
  updateAppCasts();
}

function updateScore() {
  const rows = Array.from(state.scores.values());
  $('score-box').hidden = rows.length === 0;
  const table = $('score');
  table.textContent = '';
  if (!rows.length) return;
  const head = table.insertRow();
  for (const c of SCORE_HEADINGS) head.appendChild(document.createElement('th')).textContent = c;
  for (const r of rows) {
    const tr = table.insertRow();
    for (const c of SCORE_COLUMNS) tr.insertCell().textContent = r[c];
  }
}

function updateAppCasts() {
  const keys = Array.from(state.appcasts.keys()).sort();
  if (!castPicked || !keys.includes(selectedCast)) {
    selectedCast = keys.find((k) => k.endsWith('/uFldHazardSensor')) || keys[0] || null;
  }
  const list = $('appcast-list');
  list.textContent = '';
  for (const key of keys) {
    const li = document.createElement('li');
    const cast = state.appcasts.get(key).cast;
    li.textContent = `${key}  ${cast.configWarnings.length}/${cast.runWarningTotal}`;
    if (key === selectedCast) li.className = 'selected';
    li.onclick = () => { selectedCast = key; castPicked = true; paneVersion = -1; };
    list.appendChild(li);
  }
  $('appcast-text').textContent = selectedCast ? state.appcasts.get(selectedCast).text : '';
}

// ---------------------------------------------------------------------------------- frames

function pushStat(list, value) {
  list.push(value);
  if (list.length > MAX_STATS) list.shift();
}

let lastPane = 0;
function frame(now) {
  if (replay) {
    replay.tick(lastFrame ? (now - lastFrame) / 1000 : 0);
    state = replay.state;
  }
  if (!viewTouched && state.version !== drawnVersion) fitIfOutside();
  // A seek back or a reconnection brings a new state object, whose version may repeat.
  if (dirty || state !== drawnState || state.version !== drawnVersion) {
    const t0 = performance.now();
    objectsDrawn = render(ctx, state, view, layers, pixels);
    if (FLUSH_FOR_STATS) ctx.getImageData(0, 0, 1, 1);  // wait for the rasteriser
    pushStat(frameStats.draw_ms, performance.now() - t0);
    if (lastDrawn) pushStat(frameStats.interval_ms, now - lastDrawn);
    lastDrawn = now;
    dirty = false;
    drawnVersion = state.version;
    drawnState = state;
  }
  if (now - lastPane > 250) { updatePane(); lastPane = now; }
  lastFrame = now;
  requestAnimationFrame(frame);
}

/**
 * While the user has not moved the view, keep everything in it: fit as soon as there is
 * content, then look again every 50 state changes (the content box walks every object).
 */
let fittedVersion = -1;
let fitted = false;
function fitIfOutside() {
  if (fitted && state.version - fittedVersion < 50 && state.version >= fittedVersion) return;
  fittedVersion = state.version;
  const b = contentBox();
  if (!b) return;
  const [x0, y1] = toWorld(view, 0, 0);
  const [x1, y0] = toWorld(view, view.w, view.h);
  if (!fitted || b.x0 < x0 || b.x1 > x1 || b.y0 < y0 || b.y1 > y1) fit();
  fitted = true;
}

// ---------------------------------------------------------------------------------- hooks

window.viewerState = () => {
  const s = summary(state);
  if (replay) s.replay = { start: replay.start, end: replay.end, t: replay.t, playing: replay.playing };
  return s;
};
window.viewerFrameStats = () => ({ draw_ms: frameStats.draw_ms.slice(),
                                   interval_ms: frameStats.interval_ms.slice(),
                                   objects_drawn: objectsDrawn });
/** For tests and the benchmark: set or read the view (world centre, pixels per metre). */
window.viewerView = (next) => {
  if (next) { Object.assign(view, next); viewTouched = true; dirty = true; }
  return { cx: view.cx, cy: view.cy, scale: view.scale, w: view.w, h: view.h };
};
/** For tests: move the replay to MOOS time t. */
window.viewerSeek = (t) => { if (replay) { replay.playing = false; replay.seek(t); state = replay.state; } };

setupInteraction();
resize();
chooseSource();
requestAnimationFrame(frame);
