// Culling: which objects of a kind may be in view, without walking every object each frame.
import { bbox } from './view.js';

/**
 * A uniform grid over one kind's objects, rebuilt only when that kind changed, so a frame visits
 * the cells in view instead of every object. Kinds with few objects are walked directly.
 */
const GRID_MIN_OBJECTS = 2000;
const GRID_CELLS_PER_SIDE = 128;
const grids = new Map();

function gridFor(state, kind) {
  const map = state.kinds[kind];
  let g = grids.get(kind);
  if (g && g.map === map && g.changes === state.kindChanges[kind]) return g;
  const all = { x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity };
  for (const o of map.values()) {
    const b = bbox(o);
    all.x0 = Math.min(all.x0, b.x0); all.y0 = Math.min(all.y0, b.y0);
    all.x1 = Math.max(all.x1, b.x1); all.y1 = Math.max(all.y1, b.y1);
  }
  const cell = Math.max((all.x1 - all.x0) / GRID_CELLS_PER_SIDE, (all.y1 - all.y0) / GRID_CELLS_PER_SIDE, 1e-6);
  g = { map, changes: state.kindChanges[kind], all, cell, cells: new Map(), big: [] };
  for (const o of map.values()) {
    const b = o.bbox;
    const i0 = Math.floor((b.x0 - all.x0) / cell), i1 = Math.floor((b.x1 - all.x0) / cell);
    const j0 = Math.floor((b.y0 - all.y0) / cell), j1 = Math.floor((b.y1 - all.y0) / cell);
    if ((i1 - i0 + 1) * (j1 - j0 + 1) > 16) { g.big.push(o); continue; }  // spans many cells
    for (let i = i0; i <= i1; i++) {
      for (let j = j0; j <= j1; j++) {
        const key = i * 65536 + j;
        let list = g.cells.get(key);
        if (!list) g.cells.set(key, (list = []));
        list.push(o);
      }
    }
  }
  grids.set(kind, g);
  return g;
}

let frameNo = 0;

/** Calls visit(o) once for every object of `kind` whose box may meet the world box w. */
export function forEachInView(state, kind, w, visit) {
  const map = state.kinds[kind];
  if (map.size < GRID_MIN_OBJECTS) { for (const o of map.values()) visit(o); return; }
  const g = gridFor(state, kind);
  const n = GRID_CELLS_PER_SIDE;
  const i0 = Math.max(0, Math.floor((w.x0 - g.all.x0) / g.cell));
  const i1 = Math.min(n, Math.floor((w.x1 - g.all.x0) / g.cell));
  const j0 = Math.max(0, Math.floor((w.y0 - g.all.y0) / g.cell));
  const j1 = Math.min(n, Math.floor((w.y1 - g.all.y0) / g.cell));
  // Walking most of the grid costs more than the plain walk in insertion order (measured).
  if ((i1 - i0 + 1) * (j1 - j0 + 1) > (n * n) / 4) { for (const o of map.values()) visit(o); return; }
  const stamp = ++frameNo;  // an object in several cells is visited once
  for (let i = i0; i <= i1; i++) {
    for (let j = j0; j <= j1; j++) {
      const list = g.cells.get(i * 65536 + j);
      if (!list) continue;
      for (const o of list) if (o.seen !== stamp) { o.seen = stamp; visit(o); }
    }
  }
  for (const o of g.big) visit(o);
}
