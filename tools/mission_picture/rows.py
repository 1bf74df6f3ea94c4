"""Panel rows: a height and a function that draws the row with its top at y."""

from xml.sax.saxutils import escape

from .layout import PANEL_W, PANEL_X
from .text_fit import svg_text


class Row:
    """One panel row: its height and a function that draws it with its top at y."""

    def __init__(self, height, draw):
        self.height = height
        self.draw = draw


def text_row(text, font_px, fill, height, indent=0, bold=False, cls=""):
    extra = ' class="%s"' % cls if cls else ""
    return Row(height, lambda y: [svg_text(PANEL_X + indent, y + font_px, text, font_px, fill,
                                           PANEL_W - indent, bold=bold, extra=extra)])


def heading_row(text):
    return Row(30, lambda y: ['<text x="%d" y="%d" font-size="18" font-weight="bold" fill="#222">'
                              '%s</text>' % (PANEL_X, y + 16, escape(text))])
