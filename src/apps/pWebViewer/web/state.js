// The viewer's state and the ONE function that changes it: applyMail(state, mail). Live (SSE)
// and replay (an .alog's mail) both feed mail objects through it in time order, then call
// expire(state, t), so the state at MOOS time t is the same either way. pMarineViewer
// semantics: a posting with the same label replaces the earlier one, active=false removes it,
// duration=D expires it D MOOS seconds after its time (the `time` field, else the mail's time).
// A mail's time moves the state's clock forward at most to state.clockLimit (live: the server's
// clock, so that one posting stamped far in the future by a skewed clock expires nothing early).
import { parseFields, num, parsePoints, parseAppCast, appCastText } from './fields.js';

/** VIEW_* variable -> object kind. */
export const KIND_OF_VAR = {
  VIEW_MARKER: 'marker', VIEW_POLYGON: 'polygon', VIEW_CIRCLE: 'circle',
  VIEW_SEGLIST: 'seglist', VIEW_POINT: 'point',
};
export const KINDS = ['polygon', 'circle', 'seglist', 'marker', 'point'];
const NODE_REPORT_VARS = new Set(['NODE_REPORT', 'NODE_REPORT_LOCAL']);
/** uFldHazardMetric's verdict per report (docs/mission-logic.md): the score table's rows. */
const SCORE_VAR = 'HAZARDSET_EVAL';
/** Bounds: unlabelled postings per kind (a ring of the newest), default trail length. */
export const MAX_UNLABELLED = 2000;  // pWebViewer's unlabelled_ring default
export const DEFAULT_TRAIL_LENGTH = 200;
const MAX_APPCASTS = 500;
const MAX_VARS = 500;

export function newState(options = {}) {
  const kinds = {};
  for (const k of KINDS) kinds[k] = new Map();
  return {
    time: 0, warp: 1, mode: options.mode || 'live', community: '',
    clockLimit: Infinity,  // the latest time a mail may move the clock to
    firstTime: Infinity,  // the earliest MOOS time seen: the page shows time since then
    trailLength: options.trailLength || DEFAULT_TRAIL_LENGTH,
    unlabelledRing: options.unlabelledRing || MAX_UNLABELLED,
    vehicles: new Map(), kinds, unlabelledSeq: 0, unlabelledCount: {}, unlabelledQueue: {},
    kindChanges: Object.fromEntries(KINDS.map((k) => [k, 0])),  // lets a renderer cache per kind
    expiring: new Set(), nextExpiry: Infinity, appcasts: new Map(), scores: new Map(), vars: new Map(),
    datum: options.datum || null,   // {lat, lon} from hello's lat_origin/lon_origin
    version: 0, mailCount: 0, rejected: 0,
  };
}

/** A fresh state for a server's hello (live) or a log's (replay): its bounds and datum. */
export function stateForHello(hello, mode) {
  const state = newState({
    mode, trailLength: hello.trail_length, unlabelledRing: hello.unlabelled_ring,
    datum: Number.isFinite(hello.lat_origin) && Number.isFinite(hello.lon_origin)
      ? { lat: hello.lat_origin, lon: hello.lon_origin } : null,
  });
  state.community = hello.community || '';
  state.warp = hello.warp ?? 1;
  if (Number.isFinite(hello.time)) state.time = state.firstTime = hello.time;
  return state;
}

/** Advances the state's clock (never backwards) and drops what has expired by then. */
export function expire(state, time) {
  if (Number.isFinite(time) && time > state.time) state.time = Math.min(time, state.clockLimit);
  // Scans only when the soonest expiry has come, so a mail costs O(1) between expiries.
  if (state.time < state.nextExpiry) return;
  let next = Infinity;
  for (const obj of state.expiring) {
    if (obj.expiry <= state.time) {
      removeObject(state, state.kinds[obj.kind], obj.key);
      state.version++;
    } else {
      next = Math.min(next, obj.expiry);
    }
  }
  state.nextExpiry = next;
}

/** Applies one mail object {type:'mail', var, val, src, time} (other types are ignored). */
export function applyMail(state, mail) {
  if (!mail || mail.type !== 'mail' || typeof mail.var !== 'string') return;
  state.mailCount++;
  if (Number.isFinite(mail.time)) {
    if (mail.time > state.time) state.time = Math.max(state.time, Math.min(mail.time, state.clockLimit));
    if (mail.time < state.firstTime) state.firstTime = mail.time;
  }
  const kind = KIND_OF_VAR[mail.var];
  if (kind) applyView(state, kind, String(mail.val), mail.time);
  else if (NODE_REPORT_VARS.has(mail.var)) applyNodeReport(state, String(mail.val), mail.time);
  else if (mail.var === 'APPCAST') applyAppCast(state, String(mail.val), mail.time);
  else {
    if (mail.var === SCORE_VAR) applyScore(state, String(mail.val));
    if (state.vars.size < MAX_VARS || state.vars.has(mail.var)) state.vars.set(mail.var, mail.val);
  }
  expire(state, mail.time);
  state.version++;
}

function color(f, key) {
  const v = f.get(key);
  return v === undefined || v === '' ? undefined : v;
}

/** The drawable fields every VIEW_* object shares. */
function commonFields(f) {
  return {
    label: f.get('label') || '', msg: f.get('msg') || '',
    labelColor: color(f, 'label_color'), edgeColor: color(f, 'edge_color'),
    vertexColor: color(f, 'vertex_color'), fillColor: color(f, 'fill_color'),
    alpha: num(f, 'fill_transparency'), edgeSize: num(f, 'edge_size'),
    vertexSize: num(f, 'vertex_size'),
  };
}

function buildObject(kind, f) {
  const o = commonFields(f);
  o.kind = kind;
  if (kind === 'polygon' || kind === 'seglist') {
    o.pts = parsePoints(f.get('pts'));
    if (!o.pts) return null;
  } else {
    o.x = num(f, 'x');
    o.y = num(f, 'y');
    if (o.x === undefined || o.y === undefined) return null;
  }
  if (kind === 'circle') {
    o.radius = num(f, 'radius');
    if (o.radius === undefined || o.radius < 0) return null;
    o.vertices = Math.round(num(f, 'vertices') || 0);
  } else if (kind === 'marker') {
    o.shape = (f.get('type') || 'circle').toLowerCase();
    o.width = Math.max(0, num(f, 'width') ?? 1);
    o.scale = num(f, 'scale') ?? 1;
    o.fillColor = color(f, 'primary_color') || color(f, 'color') || o.fillColor;
    o.secondaryColor = color(f, 'secondary_color');
  }
  return o;
}

function applyView(state, kind, text, mailTime) {
  const f = parseFields(text);
  const map = state.kinds[kind];
  const label = f.get('label') || '';
  const active = (f.get('active') || 'true').toLowerCase();
  if (active === 'false') {
    if (label) removeObject(state, map, label);
    return;
  }
  const obj = buildObject(kind, f);
  if (!obj) { state.rejected++; return; }
  if (label) {
    obj.key = label;
    removeObject(state, map, label);
  } else {
    obj.key = `_${kind}_${++state.unlabelledSeq}`;
    obj.unlabelled = true;
  }
  const duration = num(f, 'duration');
  if (duration !== undefined && duration > 0) {
    obj.expiry = (num(f, 'time') ?? mailTime ?? state.time) + duration;
    state.expiring.add(obj);
    state.nextExpiry = Math.min(state.nextExpiry, obj.expiry);
  }
  map.set(obj.key, obj);
  state.kindChanges[kind]++;
  if (obj.unlabelled) trimUnlabelled(state, kind, map, obj.key);
}

function removeObject(state, map, key) {
  const old = map.get(key);
  if (!old) return;
  map.delete(key);
  state.kindChanges[old.kind]++;
  state.expiring.delete(old);
  if (old.unlabelled) state.unlabelledCount[old.kind]--;
}

/**
 * Counts a new unlabelled object of `kind` (key) and keeps at most state.unlabelledRing of them,
 * dropping the oldest: a queue of their keys, oldest first (keys of objects that have expired
 * meanwhile are skipped), so a posting costs O(1) however many labelled objects there are.
 */
function trimUnlabelled(state, kind, map, key) {
  const queue = state.unlabelledQueue[kind] || (state.unlabelledQueue[kind] = { keys: [], head: 0 });
  queue.keys.push(key);
  state.unlabelledCount[kind] = (state.unlabelledCount[kind] || 0) + 1;
  while (state.unlabelledCount[kind] > state.unlabelledRing && queue.head < queue.keys.length) {
    removeObject(state, map, queue.keys[queue.head++]);
  }
  if (queue.head > 1024 && queue.head * 2 > queue.keys.length) {
    queue.keys = queue.keys.slice(queue.head);
    queue.head = 0;
  }
}

function applyNodeReport(state, text, mailTime) {
  const f = parseFields(text);
  const name = f.get('name');
  let x = num(f, 'x');
  let y = num(f, 'y');
  if ((x === undefined || y === undefined) && state.datum) [x, y] = localXY(state.datum, f);
  if (!name || x === undefined || y === undefined) { state.rejected++; return; }
  let v = state.vehicles.get(name);
  if (!v) {
    v = { name, trail: [] };
    state.vehicles.set(name, v);
  }
  v.x = x; v.y = y;
  v.hdg = num(f, 'hdg') ?? v.hdg ?? 0;
  v.length = num(f, 'length') ?? v.length;
  v.color = color(f, 'color') || v.color;
  v.type = (f.get('type') || v.type || 'ship').toLowerCase();
  v.time = mailTime;
  v.trail.push(x, y);
  const excess = v.trail.length - 2 * state.trailLength;
  if (excess > 0) v.trail.splice(0, excess);
}

/**
 * LAT/LON to the mission's local x/y (metres east/north of the datum the server's hello names):
 * a local tangent-plane approximation, good to well under a metre within a few km of the datum.
 */
const EARTH_RADIUS_M = 6378137;
function localXY(datum, f) {
  const lat = num(f, 'lat');
  const lon = num(f, 'lon');
  if (lat === undefined || lon === undefined) return [undefined, undefined];
  const rad = Math.PI / 180;
  return [(lon - datum.lon) * rad * EARTH_RADIUS_M * Math.cos(datum.lat * rad),
          (lat - datum.lat) * rad * EARTH_RADIUS_M];
}

function applyAppCast(state, text, mailTime) {
  const cast = parseAppCast(text);
  if (!cast.proc) { state.rejected++; return; }
  const key = `${cast.node}/${cast.proc}`;
  if (!state.appcasts.has(key) && state.appcasts.size >= MAX_APPCASTS) return;
  state.appcasts.set(key, { key, cast, text: appCastText(cast), time: mailTime });
}

/** HAZARDSET_EVAL keys kept per row, with the score table's headings. */
export const SCORE_COLUMNS = ['vname', 'total_score', 'norm_score', 'correct_hazards',
                              'missed_hazards', 'false_alarms', 'total_objects', 'total_time'];
export const SCORE_HEADINGS = ['vehicle', 'score', 'norm', 'correct', 'missed', 'false alarms',
                               'objects', 'time'];

function applyScore(state, text) {
  const f = parseFields(text);
  const vname = f.get('vname');
  if (!vname) { state.rejected++; return; }
  const row = {};
  for (const c of SCORE_COLUMNS) row[c] = f.get(c) ?? '';
  state.scores.set(vname, row);
}

/** The plain JSON summary of the contract's test hook window.viewerState(). */
export function summary(state) {
  const labels = (kind) => Array.from(state.kinds[kind].keys());
  const vehicles = {};
  for (const [name, v] of state.vehicles) {
    vehicles[name] = { x: v.x, y: v.y, hdg: v.hdg, trail: v.trail.length / 2 };
  }
  const appcasts = {};
  for (const [key, a] of state.appcasts) appcasts[key] = a.text;
  return {
    time: state.time, elapsed: Number.isFinite(state.firstTime) ? state.time - state.firstTime : 0,
    warp: state.warp, mode: state.mode, vehicles,
    markers: labels('marker'), circles: labels('circle'), polygons: labels('polygon'),
    seglists: labels('seglist'), points: labels('point'), appcasts,
    score: state.scores.size ? Array.from(state.scores.values()) : null,
    vars: Object.fromEntries(state.vars),   // the latest value of every other variable
    mail: state.mailCount, rejected: state.rejected,
  };
}
