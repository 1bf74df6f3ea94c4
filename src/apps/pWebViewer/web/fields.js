// The MOOS string grammars the page reads: `key=value,key=value` postings (braces protect
// commas inside `pts={x,y:x,y}`), point lists, and the AppCast item format of
// include/moos/appcast.hpp. Pure functions, no DOM.

/** Splits `text` at `sep` outside braces. */
function splitOutsideBraces(text, sep) {
  const parts = [];
  let depth = 0;
  let start = 0;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (c === '{') depth++;
    else if (c === '}') depth = Math.max(0, depth - 1);
    else if (c === sep && depth === 0) {
      parts.push(text.slice(start, i));
      start = i + 1;
    }
  }
  parts.push(text.slice(start));
  return parts;
}

/** `key=value,...` to a Map with lower-case keys and trimmed values (first '=' splits). */
export function parseFields(text) {
  const out = new Map();
  for (const part of splitOutsideBraces(String(text), ',')) {
    const eq = part.indexOf('=');
    if (eq < 0) continue;
    const key = part.slice(0, eq).trim().toLowerCase();
    if (key) out.set(key, part.slice(eq + 1).trim());
  }
  return out;
}

/** A finite number or undefined. */
export function num(fields, key) {
  const v = fields.get(key);
  if (v === undefined || v === '') return undefined;
  const n = Number(v);
  return Number.isFinite(n) ? n : undefined;
}

/** `{x1,y1:x2,y2}` (braces optional) to a flat [x1,y1,x2,y2,...]; null when malformed. */
export function parsePoints(text) {
  if (text === undefined) return null;
  let t = text.trim();
  if (t.startsWith('{')) t = t.slice(1);
  if (t.endsWith('}')) t = t.slice(0, -1);
  const flat = [];
  for (const pair of t.split(':')) {
    if (!pair.trim()) continue;
    const xy = pair.split(',');
    const x = Number(xy[0]);
    const y = Number(xy[1]);
    if (xy.length < 2 || !Number.isFinite(x) || !Number.isFinite(y)) return null;
    flat.push(x, y);
  }
  return flat;
}

const APPCAST_OUTER = '!@#';
const APPCAST_INNER = '!@';

/** One APPCAST value to {proc, node, iter, messages[], configWarnings[], events[], runWarnings[]}. */
export function parseAppCast(text) {
  const cast = { proc: '', node: '', iter: '', messages: [], configWarnings: [], events: [],
                 runWarnings: [], runWarningTotal: 0 };
  const list = (v) => v.split(APPCAST_INNER);
  for (const item of String(text).split(APPCAST_OUTER)) {
    const eq = item.indexOf('=');
    if (eq < 0) continue;
    const key = item.slice(0, eq);
    const value = item.slice(eq + 1);
    if (key === 'proc') cast.proc = value;
    else if (key === 'node') cast.node = value;
    else if (key === 'iter') cast.iter = value;
    else if (key === 'messages') {
      // Every body line is followed by the inner separator: the last piece is empty.
      cast.messages = list(value);
      if (cast.messages.length && cast.messages[cast.messages.length - 1] === '') cast.messages.pop();
    } else if (key === 'config_warnings') cast.configWarnings = list(value);
    else if (key === 'events') cast.events = list(value);
    else if (key === 'run_warning_total') cast.runWarningTotal = Number(value) || 0;
    else if (key === 'run_warnings') cast.runWarnings = list(value);
  }
  return cast;
}

/** The AppCast as the pane shows it: header, warnings, body, events newest first. */
export function appCastText(cast) {
  const lines = [];
  lines.push(`${cast.proc} ${cast.node}  ${cast.configWarnings.length}/${cast.runWarningTotal}` +
             `(${cast.iter})`);
  lines.push('='.repeat(62));
  cast.configWarnings.forEach((w, i) =>
    lines.push(`Configuration Warning [${i + 1} of ${cast.configWarnings.length}]: ${w}`));
  if (cast.runWarnings.length) {
    lines.push(`Runtime Warnings: ${cast.runWarningTotal}`);
    for (const w of cast.runWarnings) {
      const colon = w.indexOf(':');
      lines.push(` [${w.slice(0, colon)}]: ${w.slice(colon + 1)}`);
    }
  }
  lines.push(...cast.messages);
  if (cast.events.length) {
    lines.push('='.repeat(67));
    lines.push(`Most Recent Events (${cast.events.length}):`);
    lines.push(...cast.events.slice().reverse());
  }
  return lines.join('\n');
}
