// The map's geometry: world coordinates (x east, y north, metres) and canvas pixels, and the
// world box of an object.

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
