// The pixel layer: objects a few pixels across are written straight into one ImageData and
// composited with a single drawImage, far cheaper than a path per object.
import { rgbBytes } from './colors.js';

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
    const w = this.image.width, h = this.image.height, words = this.words;
    const left = Math.round(sx - size / 2), top = Math.round(sy - size / 2);
    const x0 = left < 0 ? 0 : left, x1 = left + size > w ? w : left + size;
    const y0 = top < 0 ? 0 : top, y1 = top + size > h ? h : top + size;
    // A plain loop: the squares are a few pixels, too small for fill()'s call to pay off.
    for (let y = y0; y < y1; y++) {
      const row = y * w;
      for (let x = x0; x < x1; x++) words[row + x] = word;
    }
    this.used = true;
  }
  draw(ctx) {
    if (!this.used) return;
    this.canvas.getContext('2d').putImageData(this.image, 0, 0);
    ctx.drawImage(this.canvas, 0, 0);
  }
}

const wordCache = new Map();
export function pixelWord(css, alpha) {
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
