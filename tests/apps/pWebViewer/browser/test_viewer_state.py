"""The page's state logic (pMarineViewer semantics) checked through window.viewerState():
a replay.json with known mail, the page seeked to chosen MOOS times."""

import sys
import unittest

from browser_support import (ReplayPageCase, browser_page, static_site, mail, replay_doc,
                             open_replay, state_at)

APPCAST = ("proc=uFldHazardSensor!@#iter=7!@#node=shoreside!@#iter=7!@#"
           "messages=Sensor line one!@Vehicles: 2!@!@#!@#events_total=1!@#"
           "events=[3.00]: Detection report sent!@#run_warning_total=1!@#run_warnings=1:too fast")

MAILS = [
    mail("VIEW_MARKER", "x=10,y=20,width=8,primary_color=red,type=triangle,label=a", 100.0),
    mail("VIEW_MARKER", "x=30,y=40,width=8,primary_color=light_blue,type=square,label=b", 100.0),
    # Same label replaces.
    mail("VIEW_MARKER", "x=11,y=21,width=4,primary_color=green,type=diamond,label=a", 101.0),
    # active=false removes.
    mail("VIEW_MARKER", "x=30,y=40,label=b,active=false", 102.0),
    # Unlabelled circles accumulate; a duration expires against the circle's time field.
    mail("VIEW_CIRCLE", "x=10,y=20,radius=10,vertices=12,duration=5.0,edge_color=white,"
                        "fill_color=white,time=103.00,vertex_size=0,edge_size=1,"
                        "fill_transparency=0.30", 103.0),
    mail("VIEW_CIRCLE", "x=11,y=21,radius=10,vertices=5,edge_color=red,fill_color=red,"
                        "time=104.00,vertex_size=0,edge_size=1,fill_transparency=0.30", 104.0),
    mail("VIEW_POLYGON", "pts={0,0:10,0:10,10:0,10},label=sensor_swath_jake,msg=0.90,"
                         "edge_color=green,fill_color=white,vertex_size=0,edge_size=0,"
                         "fill_transparency=0.2", 100.5),
    mail("VIEW_SEGLIST", "pts={51,26.3:51,-3.7},edge_color=gray70,vertex_size=0,edge_size=1",
         100.5),
    mail("VIEW_POINT", "x=5,y=5,vertex_size=4,vertex_color=yellow,label=p1,duration=2", 105.0),
    mail("NODE_REPORT", "NAME=jake,X=0,Y=0,SPD=1.5,HDG=90,TYPE=kayak,LENGTH=4", 100.0),
    mail("NODE_REPORT", "NAME=jake,X=1.5,Y=0,SPD=1.5,HDG=90,TYPE=kayak", 101.0),
    mail("NODE_REPORT", "NAME=jake,X=3,Y=0.5,SPD=1.5,HDG=80,TYPE=kayak", 102.0),
    mail("APPCAST", APPCAST, 103.5, src="uFldHazardSensor"),
    mail("HAZARDSET_EVAL", "vname=jake,report_name=jake,total_score=20,norm_score=86.67,"
                           "correct_hazards=5,missed_hazards=0,false_alarms=2,total_objects=7",
         106.0),
    mail("HAZARD_SEARCH_SCORE", 86.67, 106.0, src="uFldHazardMetric"),
    # Malformed postings are counted and ignored.
    mail("VIEW_CIRCLE", "x=1,radius=3", 106.0),
    mail("NODE_REPORT", "X=1,Y=2", 106.0),
]


class ViewerStateTest(ReplayPageCase):
    MAILS = MAILS

    def test_replay_spans_the_mail(self):
        s = self.page.evaluate("window.viewerState()")
        self.assertEqual(s["replay"]["start"], 100.0)
        self.assertEqual(s["replay"]["end"], 106.0)
        self.assertEqual(s["mode"], "replay")
        self.assertEqual(state_at(self.page, 104.0)["elapsed"], 4.0)

    def test_same_label_replaces(self):
        s = state_at(self.page, 101.0)
        self.assertEqual(sorted(s["markers"]), ["a", "b"])
        self.assertEqual(s["markers"].count("a"), 1)

    def test_active_false_removes(self):
        self.assertIn("b", state_at(self.page, 101.9)["markers"])
        self.assertEqual(state_at(self.page, 102.0)["markers"], ["a"])

    def test_duration_expires_against_moos_time(self):
        self.assertEqual(len(state_at(self.page, 103.0)["circles"]), 1)
        s = state_at(self.page, 104.0)
        self.assertEqual(len(s["circles"]), 2)  # unlabelled circles do not replace each other
        s = state_at(self.page, 106.0)          # 103 + 5 = 108 not reached at the log's end
        self.assertEqual(len(s["circles"]), 2)
        self.assertEqual(state_at(self.page, 105.0)["points"], ["p1"])

    def test_seeking_back_rebuilds(self):
        state_at(self.page, 106.0)
        s = state_at(self.page, 100.0)
        self.assertEqual(sorted(s["markers"]), ["a", "b"])
        self.assertEqual(s["circles"], [])
        self.assertEqual(s["vehicles"]["jake"]["trail"], 1)

    def test_trail_and_latest_pose(self):
        s = state_at(self.page, 102.5)
        jake = s["vehicles"]["jake"]
        self.assertEqual((jake["x"], jake["y"], jake["hdg"]), (3, 0.5, 80))
        self.assertEqual(jake["trail"], 3)

    def test_polygon_seglist_labels(self):
        s = state_at(self.page, 101.0)
        self.assertEqual(s["polygons"], ["sensor_swath_jake"])
        self.assertEqual(len(s["seglists"]), 1)

    def test_appcast_text(self):
        self.assertEqual(state_at(self.page, 103.0)["appcasts"], {})
        text = state_at(self.page, 104.0)["appcasts"]["shoreside/uFldHazardSensor"]
        self.assertIn("Sensor line one\nVehicles: 2", text)
        self.assertIn("[3.00]: Detection report sent", text)
        self.assertIn("[1]: too fast", text)
        # The pane shows the sensor's report (it refreshes a few times a second).
        self.page.wait_for_function(
            "document.getElementById('appcast-text').textContent.includes('Vehicles: 2')")
        self.assertIn("shoreside/uFldHazardSensor", self.page.inner_text("#appcast-list"))

    def test_score_table_and_rejects(self):
        s = state_at(self.page, 106.0)
        self.assertEqual(s["score"][0]["vname"], "jake")
        self.assertEqual(s["score"][0]["norm_score"], "86.67")
        self.assertEqual(s["rejected"], 2)
        self.page.wait_for_function("document.getElementById('counts').textContent"
                                    ".includes('2 malformed postings ignored')")
        self.assertEqual(s["vars"]["HAZARD_SEARCH_SCORE"], 86.67)  # a double stays a number
        self.page.wait_for_selector("#score-box:not([hidden])")
        self.assertIn("86.67", self.page.inner_text("#score"))

    def test_no_page_errors(self):
        state_at(self.page, 106.0)
        self.page.wait_for_timeout(300)
        self.assertEqual(self.page.errors, [])


class DurationExpiryTest(unittest.TestCase):
    """An expiry inside the log: a circle with duration 2 is gone 2 MOOS seconds later."""

    def test_circle_expires(self):
        mails = [mail("VIEW_CIRCLE", "x=0,y=0,radius=10,duration=2.0,time=10", 10.0),
                 mail("VIEW_MARKER", "x=0,y=0,label=m", 20.0)]
        with static_site(replay_doc(mails)) as url, browser_page() as page:
            open_replay(page, url)
            self.assertEqual(len(state_at(page, 11.9)["circles"]), 1)
            self.assertEqual(state_at(page, 12.0)["circles"], [])
            self.assertEqual(state_at(page, 20.0)["circles"], [])


class UnlabelledRingTest(unittest.TestCase):
    """Unlabelled postings are a ring of the newest unlabelled_ring (the hello's) per variable;
    labelled ones are not counted in it."""

    def test_oldest_unlabelled_dropped(self):
        mails = [mail("VIEW_CIRCLE", "x=0,y=0,radius=5,label=keep", 1.0)]
        mails += [mail("VIEW_CIRCLE", "x=%d,y=0,radius=5" % i, 1.0 + i) for i in range(1, 6)]
        doc = replay_doc(mails)
        doc["hello"]["unlabelled_ring"] = 3
        with static_site(doc) as url, browser_page() as page:
            open_replay(page, url)
            self.assertEqual(state_at(page, 3.0)["circles"], ["keep", "_circle_1", "_circle_2"])
            self.assertEqual(state_at(page, 6.0)["circles"],
                             ["keep", "_circle_3", "_circle_4", "_circle_5"])


class DatumTest(unittest.TestCase):
    """A NODE_REPORT with LAT/LON only is placed with the datum of the hello (metres E/N)."""

    def test_lat_lon_to_local_grid(self):
        doc = replay_doc([mail("NODE_REPORT", "NAME=gilda,LAT=43.8253,LON=-70.3304,HDG=0", 1.0),
                          mail("NODE_REPORT", "NAME=gilda,LAT=43.8263,LON=-70.3294,HDG=0", 2.0)])
        doc["hello"].update(lat_origin=43.8253, lon_origin=-70.3304)
        with static_site(doc) as url, browser_page() as page:
            open_replay(page, url)
            g = state_at(page, 1.0)["vehicles"]["gilda"]
            self.assertAlmostEqual(g["x"], 0.0, places=6)
            self.assertAlmostEqual(g["y"], 0.0, places=6)
            g = state_at(page, 2.0)["vehicles"]["gilda"]
            # 0.001 deg of latitude is 111.3 m; of longitude at 43.8 deg, 80.3 m.
            self.assertAlmostEqual(g["y"], 111.3, delta=0.2)
            self.assertAlmostEqual(g["x"], 80.3, delta=0.2)


if __name__ == "__main__":
    sys.exit(0 if unittest.main(exit=False).result.wasSuccessful() else 1)
