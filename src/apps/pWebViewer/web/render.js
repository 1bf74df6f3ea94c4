// Draws the state on a 2D canvas. Every object is culled against the view, then added to the
// batch of its style (one Path2D per colour/size/alpha), so a frame costs a few fill/stroke
// calls however many objects there are. Objects smaller than a few pixels go to a pixel layer
// (one putImageData) instead of a path. Nothing here changes the state.
import { cssColor } from './colors.js';
import { KINDS } from './state.js';
import { toScreenX, toScreenY, toWorld, bbox } from './view.js';
import { pixelWord } from './pixel_layer.js';
import { forEachInView } from './cull_grid.js';
import {
  MAX_SPRITE_PX, markerSprite, circleSprite, stamp, addShape, circlePoints,
} from './sprites.js';

const MIN_MARKER_PX = 3;
const PIXEL_LAYER_PX = 5;       // markers drawn smaller than this go to the pixel layer
const MIN_VEHICLE_PX = 22;
const LABEL_LIMIT = 500;        // no labels when more labelled objects than this are in view
const DEFAULT_TEXT = '#e8e8e8';

// Skia rasterises one path of thousands of small overlapping contours far slower than the same
// contours split over several paths, so a batch is drawn in chunks of CHUNK shapes.
const CHUNK = 256;

class Batches {
  constructor() { this.map = new Map(); this.done = []; }
  get(key, fill, stroke, lineWidth, alpha) {
    let b = this.map.get(key);
    if (b && b.count >= CHUNK) { this.done.push(b); b = undefined; }
    if (!b) {
      b = { fill, stroke, lineWidth, alpha, path: new Path2D(), count: 0 };
      this.map.set(key, b);
    }
    b.count++;
    return b;
  }
  draw(ctx) {
    for (const b of this.done) drawBatch(ctx, b);
    for (const b of this.map.values()) drawBatch(ctx, b);
    ctx.globalAlpha = 1;
    this.map.clear();
    this.done = [];
  }
}

function drawBatch(ctx, b) {
  ctx.globalAlpha = b.alpha ?? 1;
  if (b.fill) { ctx.fillStyle = b.fill; ctx.fill(b.path); }
  if (b.stroke) { ctx.strokeStyle = b.stroke; ctx.lineWidth = b.lineWidth; ctx.stroke(b.path); }
}

function addPolyline(path, v, pts, closed) {
  for (let i = 0; i < pts.length; i += 2) {
    const sx = toScreenX(v, pts[i]), sy = toScreenY(v, pts[i + 1]);
    if (i === 0) path.moveTo(sx, sy); else path.lineTo(sx, sy);
  }
  if (closed) path.closePath();
}

/**
 * The resolved drawing style of an object, computed once (objects never change in place): CSS
 * colours, batch keys and the pixel-layer word, so a frame does no string work per object.
 */
const DEFAULT_EDGE = { circle: 'white', polygon: 'white', seglist: 'yellow', marker: 'black' };
function styleOf(o) {
  if (o.style) return o.style;
  const st = {};
  const closed = o.kind === 'polygon' || o.kind === 'circle';
  if (o.kind === 'marker') {
    st.fill = cssColor(o.fillColor, 'red');
    st.alpha = Math.max(0, Math.min(1, o.alpha ?? 1));
  } else if (o.kind === 'point') {
    st.fill = cssColor(o.vertexColor || o.fillColor, 'yellow');
    st.alpha = 1;
  } else if (closed) {
    st.fill = cssColor(o.fillColor, undefined);
    st.alpha = Math.max(0, Math.min(1, o.alpha ?? 0.1));
    if (st.alpha === 0) st.fill = null;
  }
  if (st.fill) st.fillKey = `f|${st.fill}|${st.alpha}`;
  st.edgeWidth = o.kind === 'marker' ? 1 : o.edgeSize ?? 1;
  st.edge = st.edgeWidth > 0 ? cssColor(o.edgeColor, DEFAULT_EDGE[o.kind]) : null;
  if (st.edge) st.edgeKey = `e|${st.edge}|${st.edgeWidth}`;
  st.vertexSize = o.kind === 'point' ? Math.max(2, o.vertexSize ?? 3) : o.vertexSize;
  st.vertex = st.vertexSize > 0 && o.kind !== 'point' ? cssColor(o.vertexColor, 'red') : null;
  if (st.vertex) st.vertexKey = `v|${st.vertex}|${st.vertexSize}`;
  // Far out, a shape is a square of its fill (at least 0.3 opaque to stay visible), else edge.
  const tiny = st.fill || st.edge;
  if (tiny) st.tinyWord = pixelWord(tiny, st.fill && o.kind !== 'marker' ? Math.max(0.3, st.alpha) : st.alpha ?? 1);
  o.style = st;
  return st;
}

function addVertices(batches, v, st, pts) {
  const s = st.vertexSize;
  const path = batches.get(st.vertexKey, st.vertex, null, 0, 1).path;
  for (let i = 0; i < pts.length; i += 2) {
    path.rect(toScreenX(v, pts[i]) - s / 2, toScreenY(v, pts[i + 1]) - s / 2, s, s);
  }
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
    forEachInView(state, kind, { x0: wx0, y0: wy0, x1: wx1, y1: wy1 }, (o) => {
      if (!visible(bbox(o))) return;
      drawn++;
      const st = styleOf(o);
      if (kind === 'marker') addMarker(ctx, batches, pixels, v, o, st);
      else if (kind === 'point') addPoint(batches, v, o, st);
      else if (isTiny(o.bbox, v)) addTiny(pixels, v, o.bbox, st);
      else if (kind === 'circle' && o.radius * v.scale * 2 <= MAX_SPRITE_PX) {
        stamp(ctx, circleSprite(st, o.vertices, o.radius * v.scale), toScreenX(v, o.x), toScreenY(v, o.y));
      }
      else {
        const pts = kind === 'circle' ? circlePoints(o) : o.pts;
        const closed = kind !== 'seglist';
        if (closed && st.fill && pts.length >= 6) {
          addPolyline(batches.get(st.fillKey, st.fill, null, 0, st.alpha).path, v, pts, true);
        }
        if (st.edge) addPolyline(batches.get(st.edgeKey, null, st.edge, st.edgeWidth, 1).path, v, pts, closed);
        if (st.vertex) addVertices(batches, v, st, pts);
      }
      if (labels.length <= LABEL_LIMIT) {
        const text = shownText(o);
        if (text) labels.push([o, text]);
      }
    });
    batches.draw(ctx);
  }
  pixels.draw(ctx);
  if (layers.trails) drawTrails(ctx, state, v);
  if (layers.vehicles) drawVehicles(ctx, state, v);
  if (layers.labels && labels.length <= LABEL_LIMIT) drawLabels(ctx, v, labels);
  drawScaleBar(ctx, v);
  return drawn;
}

/** Shapes under TINY_PX on screen are a pixel-layer square: the view is too coarse to tell more. */
const TINY_PX = 6;
function isTiny(b, v) {
  return (b.x1 - b.x0) * v.scale < TINY_PX && (b.y1 - b.y0) * v.scale < TINY_PX;
}

function addTiny(pixels, v, b, st) {
  if (st.tinyWord === undefined) return;
  const size = Math.max(1, Math.round(Math.max(b.x1 - b.x0, b.y1 - b.y0) * v.scale));
  pixels.square(toScreenX(v, (b.x0 + b.x1) / 2), toScreenY(v, (b.y0 + b.y1) / 2), size, st.tinyWord);
}

function addMarker(ctx, batches, pixels, v, o, st) {
  const size = Math.max(MIN_MARKER_PX, o.width * o.scale * v.scale);
  const sx = toScreenX(v, o.x), sy = toScreenY(v, o.y);
  if (size < PIXEL_LAYER_PX) {
    if (st.fill) pixels.square(sx, sy, Math.round(size), st.tinyWord);
    return;
  }
  if (size <= MAX_SPRITE_PX) {
    stamp(ctx, markerSprite(st, o.shape, size), sx, sy);
    return;
  }
  if (st.fill) addShape(batches.get(st.fillKey, st.fill, null, 0, st.alpha).path, o.shape, sx, sy, size);
  if (st.edge) addShape(batches.get(st.edgeKey, null, st.edge, 1, 1).path, o.shape, sx, sy, size);
}

function addPoint(batches, v, o, st) {
  if (!st.fill) return;
  const s = st.vertexSize;
  batches.get(st.fillKey, st.fill, null, 0, 1).path
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
