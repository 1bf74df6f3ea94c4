"""What the page draws and how it is driven: pixels of the canvas where a marker is, layer
switches, pan by drag, zoom by wheel and buttons, replay play/speed, the frame-stats hook."""

import sys
import unittest

from browser_support import (ReplayPageCase, browser_page, static_site, mail, replay_doc,
                             open_replay, state_at, next_frame)

MAILS = [
    mail("VIEW_MARKER", "x=0,y=0,width=20,primary_color=red,type=square,label=r", 10.0),
    mail("VIEW_CIRCLE", "x=100,y=0,radius=10,fill_color=blue,fill_transparency=1,"
                        "edge_color=blue,label=c", 10.0),
    mail("VIEW_MARKER", "x=0,y=100,width=20,primary_color=green,type=square,label=g", 10.0),
    # MOOS colour words: underscores, grayNN, hex:, invisible.
    mail("VIEW_MARKER", "x=-60,y=0,width=20,primary_color=light_blue,type=square,label=lb", 10.0),
    mail("VIEW_MARKER", "x=-60,y=40,width=20,primary_color=gray70,type=square,label=g70", 10.0),
    mail("VIEW_MARKER", "x=-60,y=80,width=20,primary_color=hex:ff8800,type=square,label=hx", 10.0),
    mail("VIEW_MARKER", "x=-60,y=120,width=20,primary_color=invisible,edge_color=invisible,"
                        "type=square,label=inv", 10.0),
    mail("NODE_REPORT", "NAME=v,X=100,Y=100,HDG=0,TYPE=kayak", 10.0),
    mail("NODE_REPORT", "NAME=v,X=100,Y=110,HDG=0,TYPE=kayak", 30.0),
]

PIXEL_AT = """([x, y]) => {
  const v = window.viewerView();
  const c = document.getElementById('map');
  const sx = Math.round((x - v.cx) * v.scale + v.w / 2), sy = Math.round(v.h / 2 - (y - v.cy) * v.scale);
  return Array.from(c.getContext('2d').getImageData(sx, sy, 1, 1).data);
}"""


class RenderTest(ReplayPageCase):
    MAILS = MAILS

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        state_at(cls.page, 10.0)
        cls.page.evaluate("window.viewerView({cx: 50, cy: 50, scale: 2})")
        next_frame(cls.page)

    def pixel(self, x, y):
        next_frame(self.page)
        return self.page.evaluate(PIXEL_AT, [x, y])

    def set_layer(self, layer, on):
        box = self.page.locator("#layers input[data-layer=%s]" % layer)
        if box.is_checked() != on:
            box.click()

    def test_markers_and_circles_are_drawn_in_their_colours(self):
        self.assertEqual(self.pixel(0, 0)[:3], [255, 0, 0])
        self.assertEqual(self.pixel(0, 100)[:3], [0, 128, 0])
        self.assertEqual(self.pixel(100, 0)[:3], [0, 0, 255])

    def test_moos_colour_words(self):
        self.assertEqual(self.pixel(-60, 0)[:3], [173, 216, 230])
        self.assertEqual(self.pixel(-60, 40)[:3], [179, 179, 179])
        self.assertEqual(self.pixel(-60, 80)[:3], [255, 136, 0])
        background = self.pixel(-60, 160)
        self.assertEqual(self.pixel(-60, 120), background)

    def test_layer_switches_hide_and_show(self):
        self.set_layer("marker", False)
        self.assertNotEqual(self.pixel(0, 0)[:3], [255, 0, 0])
        self.assertEqual(self.pixel(100, 0)[:3], [0, 0, 255])  # circles still on
        self.set_layer("marker", True)
        self.assertEqual(self.pixel(0, 0)[:3], [255, 0, 0])
        self.set_layer("circle", False)
        self.assertNotEqual(self.pixel(100, 0)[:3], [0, 0, 255])
        self.set_layer("circle", True)

    def test_drag_pans_by_the_mouse_distance(self):
        before = self.page.evaluate("window.viewerView()")
        box = self.page.locator("#map").bounding_box()
        x, y = box["x"] + 300, box["y"] + 300
        self.page.mouse.move(x, y)
        self.page.mouse.down()
        self.page.mouse.move(x + 40, y + 20, steps=4)
        self.page.mouse.up()
        after = self.page.evaluate("window.viewerView()")
        dpr = self.page.evaluate("window.devicePixelRatio")
        self.assertAlmostEqual(after["cx"], before["cx"] - 40 * dpr / before["scale"], places=6)
        self.assertAlmostEqual(after["cy"], before["cy"] + 20 * dpr / before["scale"], places=6)
        self.page.evaluate("window.viewerView({cx: 50, cy: 50, scale: 2})")

    def test_zoom_buttons_and_wheel(self):
        self.page.click("#zoom-in")
        self.assertAlmostEqual(self.page.evaluate("window.viewerView().scale"), 3.0)
        self.page.click("#zoom-out")
        self.assertAlmostEqual(self.page.evaluate("window.viewerView().scale"), 2.0)
        box = self.page.locator("#map").bounding_box()
        self.page.mouse.move(box["x"] + 200, box["y"] + 200)
        self.page.mouse.wheel(0, -200)
        self.page.wait_for_function("window.viewerView().scale > 2.0")
        self.page.evaluate("window.viewerView({cx: 50, cy: 50, scale: 2})")

    def test_frame_stats_hook(self):
        next_frame(self.page)
        stats = self.page.evaluate("window.viewerFrameStats()")
        self.assertGreater(len(stats["draw_ms"]), 0)
        self.assertTrue(all(ms >= 0 for ms in stats["draw_ms"]))
        self.assertEqual(stats["objects_drawn"], 7)


class ReplayControlsTest(unittest.TestCase):
    def test_play_advances_at_the_chosen_speed_and_stops_at_the_end(self):
        with static_site(replay_doc(MAILS)) as url, browser_page() as page:
            open_replay(page, url)
            self.assertEqual(page.evaluate("window.viewerState().replay.t"), 10.0)
            page.select_option("#speed", "50")
            page.click("#play")
            page.wait_for_function("window.viewerState().replay.playing === false", timeout=10000)
            s = page.evaluate("window.viewerState()")
            self.assertEqual(s["replay"]["t"], 30.0)
            self.assertEqual(s["vehicles"]["v"]["y"], 110)
            # The slider moves the replay back.
            page.evaluate("(() => { const s = document.getElementById('slider');"
                          " s.value = '0'; s.dispatchEvent(new Event('input')); })()")
            self.assertEqual(page.evaluate("window.viewerState().vehicles.v.y"), 100)


if __name__ == "__main__":
    sys.exit(0 if unittest.main(exit=False).result.wasSuccessful() else 1)
