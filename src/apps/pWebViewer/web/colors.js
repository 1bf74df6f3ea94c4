// MOOS colour words (pMarineViewer's ColorParse vocabulary as our apps post it) to CSS colours:
// `light_blue` -> lightblue, `gray70` -> 70 % grey, `hex:ff8800` / `hex:ff,88,00`; `invisible`
// and `empty` mean "do not draw" (null). Unknown words fall back to the caller's default.
const cache = new Map();
let probe = null;

function probeContext() {
  if (!probe) probe = document.createElement('canvas').getContext('2d', { willReadFrequently: true });
  return probe;
}

/** True when the browser accepts `css` as a colour. */
function isCssColor(css) {
  const ctx = probeContext();
  ctx.fillStyle = '#010203';
  ctx.fillStyle = css;
  return ctx.fillStyle !== '#010203';
}

function translate(word) {
  const w = word.trim().toLowerCase();
  if (w === 'invisible' || w === 'empty' || w === 'off') return null;
  const grey = /^gr[ae]y(\d{1,3})$/.exec(w);
  if (grey) {
    const level = Math.round(Math.min(100, Number(grey[1])) * 2.55);
    return `rgb(${level},${level},${level})`;
  }
  if (w.startsWith('hex:')) {
    const hex = w.slice(4).replace(/,/g, '');
    return /^[0-9a-f]{6}$/.test(hex) ? `#${hex}` : undefined;
  }
  const css = w.replace(/_/g, '');
  return isCssColor(css) ? css : undefined;
}

/** CSS colour for a MOOS colour word; `fallback` when absent or unknown; null = invisible. */
export function cssColor(word, fallback) {
  if (word === undefined || word === '') return fallback;
  if (!cache.has(word)) cache.set(word, translate(word));
  const css = cache.get(word);
  return css === undefined ? fallback : css;
}

const rgbaCache = new Map();

/** [r, g, b] bytes of a CSS colour (for the pixel layer of tiny objects). */
export function rgbBytes(css) {
  let rgb = rgbaCache.get(css);
  if (!rgb) {
    const ctx = probeContext();
    ctx.clearRect(0, 0, 1, 1);
    ctx.fillStyle = css;
    ctx.fillRect(0, 0, 1, 1);
    const d = ctx.getImageData(0, 0, 1, 1).data;
    rgb = [d[0], d[1], d[2]];
    rgbaCache.set(css, rgb);
  }
  return rgb;
}
