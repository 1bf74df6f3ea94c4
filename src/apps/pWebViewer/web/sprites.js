// Sprites: a marker or circle of one style and pixel size is drawn once on a small canvas, then
// stamped with drawImage, which costs far less than rasterising its path again. Also the two
// shape builders the sprites and the direct paths share.

/** Markers and circles up to this many pixels across are sprites; larger ones are paths. */
export const MAX_SPRITE_PX = 64;
const MAX_SPRITES = 1000;
const sprites = new Map();

function sprite(key, sizePx, draw) {
  let c = sprites.get(key);
  if (!c) {
    if (sprites.size >= MAX_SPRITES) sprites.clear();
    c = document.createElement('canvas');
    c.width = c.height = Math.ceil(sizePx) + 4;  // room for the edge's anti-aliasing
    draw(c.getContext('2d'), c.width / 2);
    sprites.set(key, c);
  }
  return c;
}

export function markerSprite(st, shape, size) {
  const px = Math.round(size);
  return sprite(`m|${st.fillKey}|${st.edgeKey}|${shape}|${px}`, px, (g, mid) => {
    const path = new Path2D();
    addShape(path, shape, mid, mid, px);
    if (st.fill) { g.globalAlpha = st.alpha; g.fillStyle = st.fill; g.fill(path); }
    if (st.edge) { g.globalAlpha = 1; g.strokeStyle = st.edge; g.lineWidth = 1; g.stroke(path); }
  });
}

export function circleSprite(st, vertices, radiusPx) {
  const r = Math.round(radiusPx);
  const key = `c|${st.fillKey}|${st.edgeKey}|${st.vertexKey}|${vertices}|${r}`;
  return sprite(key, 2 * r + 2 * (st.vertexSize || 0), (g, mid) => {
    const pts = circlePoints({ x: mid, y: mid, radius: r, vertices });
    const path = new Path2D();
    for (let i = 0; i < pts.length; i += 2) {
      if (i === 0) path.moveTo(pts[i], pts[i + 1]); else path.lineTo(pts[i], pts[i + 1]);
    }
    path.closePath();
    if (st.fill) { g.globalAlpha = st.alpha; g.fillStyle = st.fill; g.fill(path); }
    if (st.edge) { g.globalAlpha = 1; g.strokeStyle = st.edge; g.lineWidth = st.edgeWidth; g.stroke(path); }
    if (st.vertex) {
      g.fillStyle = st.vertex;
      const vs = st.vertexSize;
      for (let i = 0; i < pts.length; i += 2) g.fillRect(pts[i] - vs / 2, pts[i + 1] - vs / 2, vs, vs);
    }
  });
}

export function stamp(ctx, image, sx, sy) {
  ctx.drawImage(image, Math.round(sx - image.width / 2), Math.round(sy - image.height / 2));
}

export function addShape(path, shape, sx, sy, size) {
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

export function circlePoints(o) {
  if (o.circlePts) return o.circlePts;
  // A regular polygon with a vertex at angle 0 is symmetric about the x axis, so callers in
  // screen space (y down, the sprites) get the same shape.
  const n = o.vertices >= 3 ? o.vertices : 36;
  const pts = [];
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n;
    pts.push(o.x + o.radius * Math.cos(a), o.y + o.radius * Math.sin(a));
  }
  o.circlePts = pts;
  return pts;
}
