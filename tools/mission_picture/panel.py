"""The right-hand panel: score table, summary lines and legend, in the most detailed layout
that fits the frame."""

from xml.sax.saxutils import escape

from .colours import name_outline
from .layout import DETAIL_MAX_OBJECTS, MAP_BACKGROUND, MAP_Y, PANEL_BOTTOM, PANEL_W, PANEL_X
from .legend import LEGEND_ROW_PX, legend_entries, legend_rows
from .rows import Row, heading_row, text_row
from .text_fit import fit_text, svg_text, text_width_px


def setting_text(ack):
    """A vehicle's acknowledged sensor setting (UHZ_CONFIG_ACK fields), "?" for a missing one."""
    return "swath %s m, pd %s, pfa %s, pclass %s" % (
        ack.get("width", "?"), ack.get("pd", "?"), ack.get("pfa", "?"), ack.get("pclass", "?"))


def score_rows_full(run, colour, vehicles_shown):
    """Four lines per vehicle: score, sensor setting, found/missed/false alarms, penalty split."""
    rows = []
    for vname in vehicles_shown:
        e = run.evals[vname]

        def score_line(y, vname=vname, e=e):
            name, name_size = fit_text(vname, PANEL_W * 0.6, 15, 11, bold=True)
            rest = ": %s / 100" % e.get("norm_score", "?")
            fitted, size = fit_text(rest, PANEL_W - text_width_px(name, name_size, bold=True),
                                    15, 12)
            col = colour.get(vname, "#222")
            return ['<text class="score" data-vehicle="%s" x="%d" y="%d" font-size="15" '
                    'fill="#222"><tspan font-weight="bold" font-size="%g" fill="%s"%s>%s</tspan>'
                    '<tspan font-size="%g">%s</tspan></text>'
                    % (escape(vname), PANEL_X, y + 14, name_size, col, name_outline(col),
                       escape(name), size, escape(fitted))]
        rows.append(Row(20, score_line))
        ack = run.acks.get(vname)
        if ack:
            rows.append(text_row("sensor: " + setting_text(ack), 12, "#444", 16, indent=10))
        rows.append(text_row("found %s, missed %s, false alarms %s" % (
            e.get("correct_hazards", "?"), e.get("missed_hazards", "?"),
            e.get("false_alarms", "?")), 12, "#444", 16, indent=10))
        rows.append(text_row("penalty %s (missed %s, FA %s, time %s)" % (
            e.get("total_score", "?"), e.get("score_missed_hazards", "?"),
            e.get("score_false_alarms", "?"), e.get("score_time_overage", "?")),
            12, "#444", 22, indent=10))
    return rows


SCORE_COLUMNS = [("vehicle", 0), ("score", 118), ("found", 178), ("missed", 228), ("FA", 284)]
SCORE_ROW_PX = 18
MAX_SETTING_ROWS = 3        # distinct sensor settings listed; more are counted in one line
MAX_NAMES_LISTED = 3        # a setting used by more vehicles names their count instead
MAX_HANDOVER_ROWS = 4       # hand-overs listed one per line; more are summed up in one line


def vehicle_swatch(x, y, col):
    """The vehicle's colour as a short bar on a dark plate: readable for any colour."""
    return ('<rect x="%.1f" y="%.1f" width="18" height="10" rx="2" fill="%s"/>'
            '<rect x="%.1f" y="%.1f" width="14" height="4" fill="%s"/>'
            % (x, y, MAP_BACKGROUND, x + 2, y + 3, col))


def setting_rows(run, vehicles):
    """One line per distinct sensor setting (UHZ_CONFIG_ACK) with the vehicles that used it."""
    settings = {}
    for vname in vehicles:
        ack = run.acks.get(vname)
        if ack:
            settings.setdefault(setting_text(ack), []).append(vname)
    if len(settings) > MAX_SETTING_ROWS:
        return [text_row("sensor: %d different settings" % len(settings), 12, "#444", 16)]
    rows = []
    for key, names in settings.items():
        if len(names) == len(vehicles) and len(names) > 1:
            who = "all"
        elif len(names) > MAX_NAMES_LISTED:
            who = "%d vehicles" % len(names)
        else:
            who = ", ".join(names)
        rows.append(text_row("sensor (%s): %s" % (who, key), 12, "#444", 16))
    return rows


def score_rows_compact(run, colour, vehicles_shown, hidden=0):
    """A table: one row per vehicle (name in its colour, score, found, missed, false alarms), a
    row for the `hidden` vehicles that did not fit, then one line per distinct sensor setting."""
    def header(y):
        return ['<text x="%d" y="%d" font-size="11" fill="#666">%s</text>'
                % (PANEL_X + dx, y + 11, name) for name, dx in SCORE_COLUMNS]
    rows = [Row(16, header)]
    for vname in vehicles_shown:
        e = run.evals[vname]

        def line(y, vname=vname, e=e):
            col = colour.get(vname, "#222")
            name, size = fit_text(vname, SCORE_COLUMNS[1][1] - 28, 14, 10, bold=True)
            parts = [vehicle_swatch(PANEL_X, y + 4, col),
                     '<text class="score" data-vehicle="%s" x="%d" y="%d" font-size="%g" '
                     'font-weight="bold" fill="%s"%s>%s</text>'
                     % (escape(vname), PANEL_X + 22, y + 13, size, col, name_outline(col),
                        escape(name))]
            cells = [e.get(k, "?") for k in
                     ("norm_score", "correct_hazards", "missed_hazards", "false_alarms")]
            edges = [dx for _name, dx in SCORE_COLUMNS[2:]] + [PANEL_W]
            for (label, dx), right, cell in zip(SCORE_COLUMNS[1:], edges, cells):
                bold = label == "score"
                fitted, cell_size = fit_text(cell, right - dx - 4, 13 if bold else 12, 9, bold)
                parts.append('<text x="%d" y="%d" font-size="%g" fill="#222"%s>%s</text>'
                             % (PANEL_X + dx, y + 13, cell_size,
                                ' font-weight="bold"' if bold else "", escape(fitted)))
            return parts
        rows.append(Row(SCORE_ROW_PX, line))
    if hidden:
        rows.append(text_row("+%d more vehicles (see summary.json)" % hidden, 12, "#444", 16))
    rows += setting_rows(run, sorted(run.evals))
    rows[-1].height += 6
    return rows


def summary_rows(run, final, objects, detail):
    hazards = sum(1 for o in objects if o["hazard"])
    rows = [text_row("truth: %d hazards, %d benign" % (hazards, len(objects) - hazards),
                     12, "#444", 18)]
    if len(run.handovers) <= MAX_HANDOVER_ROWS:
        for (source, dest, count) in run.handovers:
            rows.append(text_row("hand-over: %s gave %s %d objects" % (source, dest, count),
                                 12, "#444", 18, cls="handover"))
    else:
        rows.append(text_row("hand-overs: %d, %d objects in all" % (
            len(run.handovers), sum(c for _s, _d, c in run.handovers)), 12, "#444", 18,
            cls="handover"))
    if final:
        rows.append(text_row("last report: %s, %d objects" % (final[0], len(final[1])),
                             12, "#444", 18))
    if detail.field:
        rows.append(text_row("field view: {:,} objects, no labels (more than {:,})".format(
                             len(objects), DETAIL_MAX_OBJECTS)
                             if detail.auto else "field view: no labels",
                             12, "#444", 18, cls="detail-note"))
    return rows


def unscored_rows(vehicles, colour, run):
    """Vehicles with a track but no score still need their colour explained: three a row."""
    unscored = [v for v in vehicles if v not in run.evals]
    per_row, column_px = 3, PANEL_W // 3
    rows = []
    for start in range(0, min(len(unscored), 2 * per_row), per_row):
        def line(y, names=unscored[start:start + per_row]):
            return [vehicle_swatch(PANEL_X + column_px * i, y + 4, colour[v]) +
                    svg_text(PANEL_X + column_px * i + 22, y + 13, v, 12, colour[v],
                             column_px - 26, bold=True, extra=name_outline(colour[v]))
                    for i, v in enumerate(names)]
        rows.append(Row(18, line))
    if len(unscored) > 2 * per_row:
        rows.append(text_row("+%d more tracked vehicles" % (len(unscored) - 2 * per_row),
                             12, "#444", 16))
    return rows


def panel_layouts(run, final, objects, vehicles, colour, opts, detail):
    """Panel layouts from the most to the least detailed; the first one that fits is drawn.

    The full score block and per-vehicle legend rows (the Jake picture) come first; then the
    legend folds the vehicles into one row (the score names them in their colours); then the
    score becomes a table of one row per vehicle; then the legend rows tighten; last, the table
    shows as many vehicles as fit and counts the others."""
    scored = sorted(run.evals)
    score = [heading_row("Score")]
    if not scored:
        score.append(text_row("no HAZARDSET_EVAL in the log", 13, "#666", 24))
    summary = summary_rows(run, final, objects, detail)
    unscored = unscored_rows(vehicles, colour, run)
    gap = [Row(20, lambda y: [])]
    per_vehicle = legend_entries(vehicles, colour, opts, detail, True)
    folded = legend_entries(vehicles, colour, opts, detail, False)
    full = score + score_rows_full(run, colour, scored)
    yield full + summary + gap + legend_rows(per_vehicle, LEGEND_ROW_PX[0])
    yield full + unscored + summary + gap + legend_rows(folded, LEGEND_ROW_PX[0])
    for row_px in LEGEND_ROW_PX:
        table = score_rows_compact(run, colour, scored) if scored else []
        yield score + table + unscored + summary + gap + legend_rows(folded, row_px)
    rest = unscored + summary + gap + legend_rows(folded, LEGEND_ROW_PX[-1])
    for shown in range(len(scored) - 1, 0, -1):
        table = score_rows_compact(run, colour, scored[:shown], len(scored) - shown)
        if panel_height(score + table + rest) <= PANEL_BOTTOM - MAP_Y:
            break
    else:
        table = [text_row("%d vehicles scored (see summary.json)" % len(scored), 12, "#444", 18)]
    yield score + table + rest


def panel_height(rows):
    return sum(r.height for r in rows)


def draw_panel(w, run, final, objects, vehicles, colour, opts, detail):
    chosen = None
    for rows in panel_layouts(run, final, objects, vehicles, colour, opts, detail):
        chosen = rows
        if panel_height(rows) <= PANEL_BOTTOM - MAP_Y:
            break
    y = MAP_Y
    w('<g class="panel">')
    for row in chosen:
        if y + row.height > PANEL_BOTTOM + 8:   # a row that cannot fit is left out, never drawn
            break                               # outside the frame (the +8: trailing spacing)
        for part in row.draw(y):
            w(part)
        y += row.height
    w('</g>')
