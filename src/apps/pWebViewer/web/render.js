// Draws the state on a 2D canvas. Every object is culled against the view, then added to the
// batch of its style (one Path2D per colour/size/alpha), so a frame costs a few fill/stroke
// calls however many objects there are. Objects smaller than a few pixels go to a pixel layer
// (one putImageData) instead of a path. Nothing here changes the state.
import { cssColor, rgbBytes } from './colors.js';
import { KINDS } from './state.js';

const MIN_MARKER_PX = 3;
const PIXEL_LAYER_PX = 5;       // markers drawn smaller than this go to the pixel layer
const MIN_VEHICLE_PX = 16;
const LABEL_LIMIT = 1500;       // no labels when more labelled objects than this are in view
const DEFAULT_TEXT = '#e8e8e8';

/** World (x east, y north, metres) <-> canvas pixels. */
export function makeView(cx = 0, cy = 0, scale = 1) { return { cx, cy, scale, w: 1, h: 1 }; }
export function toScreenX(v, x) { return (x - v.cx) * v.scale + v.w / 2; }
export function toScreenY(v, y) { return v.h / 2 - (y - v.cy) * v.scale; }
export function toWorld(v, sx, sy) {
  return [v.cx + (sx - v.w / 2) / v.scale, v.cy - (sy - v.h / 2) / v.scale];
}

/** The world box {x0,y0,x1,y1} of an object, cached on it (objects never change in place). */
export function bbox(o) {
  if (o.bbox) return o.bbox;
  let b;
  if (o.pts) {
    b = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity };
    for (let i = 0; i < o.pts.length; i += 2) {
      b.x0 = Math.min(b.x0, o.pts[i]); b.x1 = Math.max(b.x1, o.pts[i]);
      b.y0 = Math.min(b.y0, o.pts[i + 1]); b.y1 = Math.max(b.y1, o.pts[i + 1]);
    }
  } else {
    const r = o.radius ?? (o.width ?? 0) * (o.scale ?? 1) / 2;
    b = { x0: o.x - r, y0: o.y - r, x1: o.x + r, y1: o.y + r };
  }
  o.bbox = b;
  return b;
}

class Batches {
  constructor() { this.map = new Map(); }
  get(key, make) {
    let b = this.map.get(key);
    if (!b) { b = make(); b.path = new Path2D(); this.map.set(key, b); }
    return b;
  }
  draw(ctx) {
    for (const b of this.map.values()) {
      ctx.globalAlpha = b.alpha ?? 1;
      if (b.fill) { ctx.fillStyle = b.fill; ctx.fill(b.path); }
      if (b.stroke) { ctx.strokeStyle = b.stroke; ctx.lineWidth = b.lineWidth; ctx.stroke(b.path); }
    }
    ctx.globalAlpha = 1;
    this.map.clear();
  }
}

/** The pixel layer: tiny objects written straight into an ImageData. */
export class PixelLayer {
  constructor() { this.canvas = document.createElement('canvas'); this.used = false; }
  begin(w, h) {
    if (!this.image || this.image.width !== w || this.image.height !== h) {
      this.canvas.width = w; this.canvas.height = h;
      this.image = this.canvas.getContext('2d').createImageData(w, h);
      this.words = new Uint32Array(this.image.data.buffer);
    } else if (this.used) {
      this.words.fill(0);
    }
    this.used = false;
  }
  square(sx, sy, size, word) {
    const w = this.image.width, h = this.image.height;
    const x0 = Math.max(0, Math.round(sx - size / 2)), x1 = Math.min(w, x0 + size);
    const y0 = Math.max(0, Math.round(sy - size / 2)), y1 = Math.min(h, y0 + size);
    for (let y = y0; y < y1; y++) this.words.fill(word, y * w + x0, y * w + x1);
    this.used = true;
  }
  draw(ctx) {
    if (!this.used) return;
    this.canvas.getContext('2d').putImageData(this.image, 0, 0);
    ctx.drawImage(this.canvas, 0, 0);
  }
}

const wordCache = new Map();
function pixelWord(css, alpha) {
  const key = `${css}|${alpha}`;
  let word = wordCache.get(key);
  if (word === undefined) {
    const [r, g, b] = rgbBytes(css);
    const a = Math.round(255 * Math.max(0, Math.min(1, alpha)));
    // ImageData is non-premultiplied RGBA; a little-endian Uint32 reads it as ABGR.
    word = ((a << 24) | (b << 16) | (g << 8) | r) >>> 0;
    wordCache.set(key, word);
  }
  return word;
}

function addShape(path, shape, sx, sy, size) {
  const r = size / 2;
  switch (shape) {
    case 'square': path.rect(sx - r, sy - r, size, size); break;
    case 'diamond':
      path.moveTo(sx, sy - r); path.lineTo(sx + r, sy); path.lineTo(sx, sy + r);
      path.lineTo(sx - r, sy); path.closePath(); break;
    case 'triangle':
      path.moveTo(sx, sy - r); path.lineTo(sx + r, sy + r); path.lineTo(sx - r, sy + r);
      path.closePath(); break;
    default:  // circle, and pMarineViewer's efield/gateway/kelp drawn as a disc
      path.moveTo(sx + r, sy); path.arc(sx, sy, r, 0, 2 * Math.PI); break;
  }
}

function addPolyline(path, v, pts, closed) {
  for (let i = 0; i < pts.length; i += 2) {
    const sx = toScreenX(v, pts[i]), sy = toScreenY(v, pts[i + 1]);
    if (i === 0) path.moveTo(sx, sy); else path.lineTo(sx, sy);
  }
  if (closed) path.closePath();
}

function addVertices(batches, v, o, pts) {
  if (!(o.vertexSize > 0)) return;
  const color = cssColor(o.vertexColor, 'red');
  if (!color) return;
  const b = batches.get(`v|${color}|${o.vertexSize}`, () => ({ fill: color }));
  for (let i = 0; i < pts.length; i += 2) {
    const s = o.vertexSize;
    b.path.rect(toScreenX(v, pts[i]) - s / 2, toScreenY(v, pts[i + 1]) - s / 2, s, s);
  }
}

function addEdge(batches, v, o, pts, closed, defaultColor) {
  const width = o.edgeSize ?? 1;
  const color = cssColor(o.edgeColor, defaultColor);
  if (!(width > 0) || !color) return;
  addPolyline(batches.get(`e|${color}|${width}`, () => ({ stroke: color, lineWidth: width })).path,
              v, pts, closed);
}

function addFill(batches, v, o, pts) {
  const color = cssColor(o.fillColor, undefined);
  if (!color || pts.length < 6) return;
  const alpha = Math.max(0, Math.min(1, o.alpha ?? 0.1));
  if (alpha === 0) return;
  addPolyline(batches.get(`f|${color}|${alpha}`, () => ({ fill: color, alpha })).path, v, pts, true);
}

function circlePoints(o) {
  if (o.circlePts) return o.circlePts;
  const n = o.vertices >= 3 ? o.vertices : 36;
  const pts = [];
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n;
    pts.push(o.x + o.radius * Math.cos(a), o.y + o.radius * Math.sin(a));
  }
  o.circlePts = pts;
  return pts;
}

function shownText(o) {
  const text = o.msg || o.label;
  return !text || text === '_null_' || o.unlabelled && !o.msg ? '' : text;
}

/** Draws the state. `layers` maps kind/'trails'/'vehicles'/'labels' to booleans. */
export function render(ctx, state, v, layers, pixels) {
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = '#18283a';
  ctx.fillRect(0, 0, v.w, v.h);
  const [wx0, wy1] = toWorld(v, 0, 0);
  const [wx1, wy0] = toWorld(v, v.w, v.h);
  const visible = (b) => b.x1 >= wx0 && b.x0 <= wx1 && b.y1 >= wy0 && b.y0 <= wy1;
  const batches = new Batches();
  const labels = [];
  pixels.begin(v.w, v.h);
  let drawn = 0;
  for (const kind of KINDS) {
    if (!layers[kind]) continue;
    for (const o of state.kinds[kind].values()) {
      if (!visible(bbox(o))) continue;
      drawn++;
      if (kind === 'marker') addMarker(batches, pixels, v, o);
      else if (kind === 'point') addPoint(batches, v, o);
      else {
        const pts = kind === 'circle' ? circlePoints(o) : o.pts;
        const closed = kind !== 'seglist';
        if (closed) addFill(batches, v, o, pts);
        addEdge(batches, v, o, pts, closed, kind === 'seglist' ? 'yellow' : 'white');
        addVertices(batches, v, o, pts);
      }
      if (labels.length <= LABEL_LIMIT) {
        const text = shownText(o);
        if (text) labels.push([o, text]);
      }
    }
    batches.draw(ctx);
  }
  pixels.draw(ctx);
  if (layers.trails) drawTrails(ctx, state, v);
  if (layers.vehicles) drawVehicles(ctx, state, v);
  if (layers.labels && labels.length <= LABEL_LIMIT) drawLabels(ctx, v, labels);
  drawScaleBar(ctx, v);
  return drawn;
}

function addMarker(batches, pixels, v, o) {
  const size = Math.max(MIN_MARKER_PX, o.width * o.scale * v.scale);
  const fill = cssColor(o.fillColor, 'red');
  const sx = toScreenX(v, o.x), sy = toScreenY(v, o.y);
  const alpha = o.alpha ?? 1;
  if (size < PIXEL_LAYER_PX) {
    if (fill) pixels.square(sx, sy, Math.round(size), pixelWord(fill, alpha));
    return;
  }
  if (fill) addShape(batches.get(`m|${fill}|${alpha}`, () => ({ fill, alpha })).path, o.shape, sx, sy, size);
  const edge = cssColor(o.edgeColor, 'black');
  if (edge) {
    addShape(batches.get(`me|${edge}`, () => ({ stroke: edge, lineWidth: 1 })).path, o.shape, sx, sy, size);
  }
}

function addPoint(batches, v, o) {
  const color = cssColor(o.vertexColor || o.fillColor, 'yellow');
  if (!color) return;
  const s = Math.max(2, o.vertexSize ?? 3);
  batches.get(`p|${color}`, () => ({ fill: color })).path
    .rect(toScreenX(v, o.x) - s / 2, toScreenY(v, o.y) - s / 2, s, s);
}

function drawTrails(ctx, state, v) {
  ctx.lineWidth = 1;
  ctx.globalAlpha = 0.7;
  for (const veh of state.vehicles.values()) {
    const color = cssColor(veh.color, 'yellow');
    if (!color || veh.trail.length < 4) continue;
    const path = new Path2D();
    addPolyline(path, v, veh.trail, false);
    ctx.strokeStyle = color;
    ctx.stroke(path);
  }
  ctx.globalAlpha = 1;
}

// Hull outlines in body units (length 1, bow at +y), by NODE_REPORT TYPE.
const HULLS = {
  auv: [0, 0.5, 0.12, 0.35, 0.12, -0.45, -0.12, -0.45, -0.12, 0.35],
  kayak: [0, 0.5, 0.15, 0.1, 0.1, -0.5, -0.1, -0.5, -0.15, 0.1],
  ship: [0, 0.5, 0.3, 0.2, 0.3, -0.5, -0.3, -0.5, -0.3, 0.2],
};
HULLS.uuv = HULLS.auv; HULLS.glider = HULLS.auv; HULLS.heron = HULLS.kayak;

function drawVehicles(ctx, state, v) {
  ctx.font = '12px sans-serif';
  for (const veh of state.vehicles.values()) {
    const sx = toScreenX(v, veh.x), sy = toScreenY(v, veh.y);
    if (sx < -50 || sy < -50 || sx > v.w + 50 || sy > v.h + 50) continue;
    const size = Math.max(MIN_VEHICLE_PX, (veh.length ?? 4) * v.scale);
    const hull = HULLS[veh.type] || HULLS.ship;
    const a = (veh.hdg * Math.PI) / 180;  // heading: clockwise from north
    const cos = Math.cos(a), sin = Math.sin(a);
    ctx.beginPath();
    for (let i = 0; i < hull.length; i += 2) {
      const bx = hull[i] * size, by = hull[i + 1] * size;
      const px = sx + bx * cos + by * sin, py = sy - (-bx * sin + by * cos);
      if (i === 0) ctx.moveTo(px, py); else ctx.lineTo(px, py);
    }
    ctx.closePath();
    ctx.fillStyle = cssColor(veh.color, 'yellow') || 'yellow';
    ctx.fill();
    ctx.strokeStyle = 'black';
    ctx.lineWidth = 1;
    ctx.stroke();
    ctx.fillStyle = DEFAULT_TEXT;
    ctx.fillText(veh.name, sx + size / 2 + 4, sy - 4);
  }
}

function drawLabels(ctx, v, labels) {
  ctx.font = '11px sans-serif';
  for (const [o, text] of labels) {
    const color = cssColor(o.labelColor, DEFAULT_TEXT);
    if (!color) continue;
    const b = bbox(o);
    ctx.fillStyle = color;
    ctx.fillText(text, toScreenX(v, b.x1) + 3, toScreenY(v, b.y1) + 3);
  }
}

/** A bar of a round length (1, 2 or 5 x 10^n m) about 120 px long, bottom left. */
export function scaleBarLength_m(pxPerM) {
  const target = 120 / pxPerM;
  const pow = 10 ** Math.floor(Math.log10(target));
  for (const m of [5, 2, 1]) if (m * pow <= target) return m * pow;
  return pow;
}

function drawScaleBar(ctx, v) {
  const len = scaleBarLength_m(v.scale);
  const px = len * v.scale;
  const x = 16, y = v.h - 20;
  ctx.strokeStyle = 'white'; ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x, y - 5); ctx.lineTo(x, y); ctx.lineTo(x + px, y); ctx.lineTo(x + px, y - 5);
  ctx.stroke();
  ctx.fillStyle = 'white'; ctx.font = '12px sans-serif';
  ctx.fillText(len >= 1000 ? `${len / 1000} km` : `${len} m`, x + px / 2 - 14, y - 8);
}
