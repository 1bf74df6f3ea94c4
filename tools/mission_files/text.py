"""The base text grammar of include/base/text.hpp, for the Python tools.

Contract (the same as the C++ base layer):
- Trimming removes blanks, tabs, CR and LF from both ends (nothing else).
- A number is [+-]digits[.digits][(e|E)[+-]digits] with at least one mantissa digit, blanks
  trimmed; anything else, and anything non-finite after conversion (nan, inf, 1e999), is None.
- Booleans: true/yes/on and false/no/off in any case.
- `key=value` lists split on commas, each piece at its first '=', both sides trimmed, empty
  pieces skipped; with braces respected, commas inside {...} do not split.
"""

import math
import re

TRIMMED = " \t\r\n"
NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
WHOLE_NUMBER = re.compile(r"[+-]?[0-9]+")
TRUE_WORDS, FALSE_WORDS = ("true", "yes", "on"), ("false", "no", "off")
EXCERPT_CHARS = 160
ASCII_LOWER = str.maketrans("ABCDEFGHIJKLMNOPQRSTUVWXYZ", "abcdefghijklmnopqrstuvwxyz")


def trim(text):
    return text.strip(TRIMMED)


def to_lower(text):
    """ASCII lower case (as base::to_lower: other letters are kept as written)."""
    return text.lower() if text.isascii() else text.translate(ASCII_LOWER)


def parse_number(text):
    """A finite float for a number of the grammar above, else None (never raises)."""
    try:
        value = float(text)   # reads every number of the grammar, and more (below)
    except (TypeError, ValueError):
        return None
    if not math.isfinite(value):
        return None
    # On printable ASCII without '_', float() reads the grammar and only the words nan and
    # inf, refused above; other text (other blanks, digits of other scripts) takes the pattern.
    if text.isascii() and text.isprintable() and "_" not in text:
        return value
    return value if NUMBER.fullmatch(text.strip(TRIMMED)) else None


def json_number(text):
    """parse_number, kept an int when the text is a whole number (summary.json writes `25`, not
    `25.0`), else None."""
    value = parse_number(text)
    if value is not None and WHOLE_NUMBER.fullmatch(text.strip(TRIMMED)):
        return int(text.strip(TRIMMED))
    return value


def escape_for_log(text):
    """base::escape_for_log: every control byte (below 0x20, and 0x7F) and every backslash as
    \\xHH, so outside text can neither end a line nor forge one."""
    return "".join("\\x%02X" % ord(c) if ord(c) < 0x20 or c in "\x7f\\" else c for c in text)


def log_excerpt(text):
    """base::log_excerpt: excerpt(), then escape_for_log()."""
    return escape_for_log(excerpt(text))


def parse_bool(text):
    word = to_lower(trim(text))
    if word in TRUE_WORDS:
        return True
    if word in FALSE_WORDS:
        return False
    return None


def excerpt(text, max_chars=EXCERPT_CHARS):
    """For messages: the text cut to max_chars, with its length in bytes when cut."""
    if len(text) <= max_chars:
        return text
    return "%s ... (%d bytes)" % (text[:max_chars], len(text.encode("utf-8")))


def split_outside_braces(text, separator=","):
    """Pieces of text split at `separator`, except inside {...} (an unmatched '}' is ignored)."""
    pieces = text.split(separator)   # at C speed; pieces inside braces are joined back
    if "{" not in text:
        return pieces
    parts, pending, depth = [], None, 0
    for piece in pieces:
        pending = piece if pending is None else pending + separator + piece
        depth = brace_depth_after(piece, depth)
        if depth == 0:
            parts.append(pending)
            pending = None
    if pending is not None:
        parts.append(pending)
    return parts


def brace_depth_after(piece, depth):
    """The brace depth after reading piece from `depth`; a '}' at depth 0 is ignored."""
    if "}" not in piece:
        return depth + piece.count("{")
    if "{" not in piece:
        return max(0, depth - piece.count("}"))
    for c in piece:
        if c == "{":
            depth += 1
        elif c == "}" and depth > 0:
            depth -= 1
    return depth


def split_key_values(text, separator=",", respect_braces=False):
    """[(key, value, has_equals)] of a `key=value` list (base::split_key_values); a piece without
    '=' is (piece, "", False)."""
    pieces = split_outside_braces(text, separator) if respect_braces else text.split(separator)
    out = []
    for piece in pieces:
        piece = piece.strip(TRIMMED)
        if not piece:
            continue
        key, equals, value = piece.partition("=")
        out.append((key.strip(TRIMMED), value.strip(TRIMMED), bool(equals)))
    return out


def key_values(text):
    """`a=1, B={x,y}` -> {'a': '1', 'b': '{x,y}'}: keys in lower case, braces respected, pieces
    without '=' left out, the later of a repeated key kept."""
    out = {}
    if text.isascii() and text.isprintable():
        # The hot path (every drawn posting): the only blank is the space, so str.strip and
        # str.lower are base::trim and base::to_lower, at C speed.
        for piece in split_outside_braces(text):
            key, equals, value = piece.partition("=")
            if equals:
                out[key.strip().lower()] = value.strip()
        return out
    for key, value, has_equals in split_key_values(text, respect_braces=True):
        if has_equals:
            out[to_lower(key)] = value
    return out


def parse_point_list(body):
    """`x1,y1:x2,y2` -> [(x, y), ...] (more coordinates of a vertex are ignored), or None when
    a vertex is not two numbers."""
    points = []
    for vertex in body.split(":"):
        coords = vertex.split(",")
        if len(coords) < 2:
            return None
        x, y = parse_number(coords[0]), parse_number(coords[1])
        if x is None or y is None:
            return None
        points.append((x, y))
    return points or None


def parse_points(text):
    """`pts={x1,y1:x2,y2}` (anywhere in text) or `x1,y1:x2,y2` -> [(x, y), ...] or None."""
    start = text.find("pts")
    if start >= 0:
        open_brace = text.find("{", start)
        close_brace = text.find("}", open_brace + 1)
        if open_brace >= 0 and close_brace > open_brace and \
                text[start + 3:open_brace].strip() in ("=", ""):
            return parse_point_list(text[open_brace + 1:close_brace])
    return parse_point_list(text)
