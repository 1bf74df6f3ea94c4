"""Panel and title texts fitted to a width: a never-short estimate of the rendered width
from the DejaVu Sans metrics, a smaller font, then an ellipsis."""

from xml.sax.saxutils import escape

# Text widths: the advance widths of DejaVu Sans and DejaVu Sans Bold (the SVG's first font;
# Debian fonts-dejavu-core 2.37, hmtx table) for the characters 32 (space) to 126 (~), in
# hundredths of an em, rounded up. Any other character counts as one em (bold 1.12), at least
# its width in these fonts. An estimate is therefore never short (the tests read the installed
# fonts to check it), and a fitted text stays inside the panel.
DEJAVU_SANS_CEM = (
    32, 41, 46, 84, 64, 96, 78, 28, 40, 40, 50, 84, 32, 37, 32, 34,
    64, 64, 64, 64, 64, 64, 64, 64, 64, 64, 34, 34, 84, 84, 84, 54,
    100, 69, 69, 70, 78, 64, 58, 78, 76, 30, 30, 66, 56, 87, 75, 79,
    61, 79, 70, 64, 62, 74, 69, 99, 69, 62, 69, 40, 34, 40, 84, 50,
    50, 62, 64, 55, 64, 62, 36, 64, 64, 28, 28, 58, 28, 98, 64, 62,
    64, 64, 42, 53, 40, 64, 60, 82, 60, 60, 53, 64, 34, 64, 84)


DEJAVU_SANS_BOLD_CEM = (
    35, 46, 53, 84, 70, 101, 88, 31, 46, 46, 53, 84, 38, 42, 38, 37,
    70, 70, 70, 70, 70, 70, 70, 70, 70, 70, 40, 40, 84, 84, 84, 59,
    100, 78, 77, 74, 84, 69, 69, 83, 84, 38, 38, 78, 64, 100, 84, 86,
    74, 86, 78, 73, 69, 82, 78, 111, 78, 73, 73, 46, 37, 46, 84, 50,
    50, 68, 72, 60, 72, 68, 44, 72, 72, 35, 35, 67, 35, 105, 72, 69,
    72, 72, 50, 60, 48, 72, 66, 93, 65, 66, 59, 72, 37, 72, 84)
FIRST_TABLE_CHAR = 32
OTHER_CHAR_EM, OTHER_CHAR_BOLD_EM = 1.0, 1.12


def text_width_px(text, font_px, bold=False):
    """An upper estimate of the rendered width of text (see DEJAVU_SANS_CEM)."""
    table = DEJAVU_SANS_BOLD_CEM if bold else DEJAVU_SANS_CEM
    other_cem = 100 * (OTHER_CHAR_BOLD_EM if bold else OTHER_CHAR_EM)
    cem = 0.0
    for c in text:
        code = ord(c) - FIRST_TABLE_CHAR
        cem += table[code] if 0 <= code < len(table) else other_cem
    return cem / 100.0 * font_px


def fit_text(text, max_width_px, font_px, min_font_px, bold=False):
    """(text, font_px) that fits max_width_px: a smaller font first, then an ellipsis."""
    size = float(font_px)
    while size > min_font_px and text_width_px(text, size, bold) > max_width_px:
        size = max(float(min_font_px), size - 0.5)
    if text_width_px(text, size, bold) <= max_width_px:
        return text, size
    while len(text) > 1 and text_width_px(text + "\u2026", size, bold) > max_width_px:
        text = text[:-1]
    return text.rstrip() + "\u2026", size


def svg_text(x, y, text, font_px, fill, max_width_px, min_font_px=None, bold=False, extra=""):
    """A <text> element fitted to max_width_px (font shrinks to min_font_px, then an ellipsis)."""
    fitted, size = fit_text(text, max_width_px, font_px, min_font_px or font_px * 0.8, bold)
    return ('<text x="%.1f" y="%.1f" font-size="%g" fill="%s"%s%s>%s</text>'
            % (x, y, size, fill, ' font-weight="bold"' if bold else "", extra, escape(fitted)))
