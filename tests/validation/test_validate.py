#!/usr/bin/env python3
"""bench/validation/validate.py: the statistics against values computed by hand, the manual's
model, and the tables made from recorded pass_bench results (recorded/: the result files of one
control run and one scene run of each program, of 2026-11-27, with the sensor paths shortened)."""

import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "bench", "validation"))   # the module under test
import validate  # noqa: E402

RECORDED = os.path.join(HERE, "recorded")


def recorded(name):
    return validate.read_runs([os.path.join(RECORDED, name)])


class Statistics(unittest.TestCase):
    def test_wilson_interval_of_8_in_10(self):
        # centre (p + z^2/2n) / (1 + z^2/n), half-width z sqrt(p(1-p)/n + z^2/4n^2) / (1 + z^2/n)
        lo, hi = validate.wilson(8, 10)
        self.assertAlmostEqual(lo, 0.4902, places=4)
        self.assertAlmostEqual(hi, 0.9433, places=4)

    def test_wilson_interval_of_none_in_100_reaches_z2_over_n_plus_z2(self):
        lo, hi = validate.wilson(0, 100)
        self.assertAlmostEqual(lo, 0.0, places=12)
        self.assertAlmostEqual(hi, 1.959963984540054 ** 2 / (100 + 1.959963984540054 ** 2))

    def test_wilson_interval_without_trials_is_everything(self):
        self.assertEqual(validate.wilson(0, 0), (0.0, 1.0))

    def test_two_proportion_test_of_50_and_40_in_100(self):
        # pooled 0.45, se sqrt(0.45 * 0.55 * 2/100) = 0.070356, z = 1.4213
        self.assertAlmostEqual(validate.two_proportion_p(50, 100, 40, 100), 0.1552, places=4)

    def test_two_proportion_test_cannot_tell_two_certainties_apart(self):
        self.assertEqual(validate.two_proportion_p(100, 100, 30, 30), 1.0)
        self.assertEqual(validate.two_proportion_p(0, 100, 0, 30), 1.0)

    def test_one_proportion_test_of_50_in_100_against_40_percent(self):
        # z = 0.1 / sqrt(0.4 * 0.6 / 100) = 2.0412
        self.assertAlmostEqual(validate.one_proportion_p(50, 100, 0.4), 0.0412, places=4)

    def test_one_proportion_test_against_a_certainty_is_all_or_nothing(self):
        self.assertEqual(validate.one_proportion_p(0, 100, 0.0), 1.0)
        self.assertEqual(validate.one_proportion_p(1, 100, 0.0), 0.0)
        self.assertEqual(validate.one_proportion_p(30, 30, 1.0), 1.0)

    def test_holm_multiplies_by_the_remaining_count_and_keeps_the_order(self):
        adjusted = validate.holm([0.01, 0.04, 0.03])
        for got, want in zip(adjusted, [0.03, 0.06, 0.06]):
            self.assertAlmostEqual(got, want)
        self.assertEqual(validate.holm([0.6, 0.9]), [1.0, 1.0])

    def test_tost_of_equal_halves(self):
        # se sqrt(2 * 0.25 / n); p = 1 - Phi(0.03 / se)
        self.assertAlmostEqual(validate.tost_p(500, 1000, 500, 1000, 0.03), 0.0899, places=4)
        self.assertAlmostEqual(validate.tost_p(2500, 5000, 2500, 5000, 0.03), 0.00135, places=5)

    def test_tost_rejects_a_difference_beyond_the_margin(self):
        self.assertGreater(validate.tost_p(5500, 10000, 5000, 10000, 0.03), 0.5)

    def test_tost_of_two_exact_figures_compares_them_with_the_margin(self):
        self.assertEqual(validate.tost_p(0, 100, 0, 50, 0.03), 0.0)
        self.assertEqual(validate.tost_p(100, 100, 0, 50, 0.03), 1.0)


class Model(unittest.TestCase):
    def test_detection_follows_the_manual(self):
        pd, exp, hr = 0.8, 4, 0.5
        self.assertAlmostEqual(validate.model_detection("H", pd, exp, hr), 0.8)
        self.assertAlmostEqual(validate.model_detection("B", pd, exp, hr), 0.4096)
        self.assertAlmostEqual(validate.model_detection("B0", pd, exp, hr), 0.2048)
        self.assertAlmostEqual(validate.model_detection("Bh", pd, exp, hr), 0.4548)

    def test_classification_follows_the_manual(self):
        self.assertAlmostEqual(validate.model_classification("H", 0.8, 0.5), 0.8)
        self.assertAlmostEqual(validate.model_classification("B", 0.8, 0.5), 0.8)
        self.assertAlmostEqual(validate.model_classification("B0", 0.8, 0.5), 1.0)
        self.assertAlmostEqual(validate.model_classification("Bh", 0.8, 0.5), 0.9)


class Tables(unittest.TestCase):
    def test_a_result_file_is_read_with_its_header(self):
        run = recorded("scene-ours.csv")[0]
        self.assertEqual(run.header["seed"], "1")
        self.assertEqual(run.rows[("inside", "H")]["passes"], 5000)

    def test_runs_with_other_parameters_are_refused(self):
        ours = recorded("scene-ours.csv")
        control = recorded("control-ours.csv")
        with self.assertRaisesRegex(ValueError, "disagree on pd"):
            validate.scene_figures(ours, control)

    def test_scene_figures_pool_the_runs_and_carry_the_model(self):
        ours, original = recorded("scene-ours.csv"), recorded("scene-original.csv")
        figures = validate.scene_figures(ours + ours, original)
        self.assertEqual(len(figures), 9)
        self.assertEqual(figures[0].name, "detection, hazard")
        self.assertAlmostEqual(figures[0].model, 0.8)
        self.assertEqual(figures[0].ours[1], 10000)   # two copies of 5,000 passes
        self.assertEqual(figures[0].original, (3936, 5000))
        self.assertEqual(figures[-1].name, "detected outside the swath")
        self.assertEqual(figures[-1].ours[0], 0)

    def test_scene_table_has_a_line_per_figure(self):
        ours, original = recorded("scene-ours.csv"), recorded("scene-original.csv")
        table = validate.scene_table(validate.scene_figures(ours, original), 0.03)
        lines = table.splitlines()
        self.assertEqual(len(lines), 2 + 9)
        self.assertIn("equivalent within ±3 points", lines[0])
        # Recorded: ours 3965 of 5000 hazards detected, the original 3936; nothing outside.
        self.assertEqual(lines[2], "| detection, hazard | 80.00 % "
                         "| 3965 / 5000 = 79.30 % [78.15, 80.40] "
                         "| 3936 / 5000 = 78.72 % [77.56, 79.83] "
                         "| 1.000 | yes (0.0015) | 1.000 / 0.426 |")
        self.assertEqual(lines[10], "| detected outside the swath | 0.00 % "
                         "| 0 / 10000 = 0.00 % [0.00, 0.04] | 0 / 10000 = 0.00 % [0.00, 0.04] "
                         "| 1.000 | yes (0) | 1.000 / 1.000 |")

    def test_runs_table_counts_the_passes_the_control_vehicle_sensed(self):
        ours, original = recorded("scene-ours.csv"), recorded("scene-original.csv")
        self.assertEqual(validate.events_seen(ours), (9992, 10000))
        table = validate.runs_table([("ours", ours[0]), ("original", original[0]),
                                     ("ours", ours[0])])
        lines = table.splitlines()
        self.assertEqual(len(lines), 2 + 3 + 2)   # three runs, then one pooled line per program
        self.assertEqual(lines[2], "| ours | 1 | 25 | 79.30 % | 40.06 % | 19.72 % | 45.54 % "
                         "| 9992 / 10000 | 0 |")
        self.assertTrue(lines[5].startswith("| ours, all runs | - | 50 | 79.30 % |"), lines[5])
        self.assertTrue(lines[5].endswith("| 19984 / 20000 | 0 |"), lines[5])
        self.assertTrue(lines[6].startswith("| original, all runs | time | 25 | 78.72 % |"))

    def test_control_table_shows_the_swath_length_of_each_program(self):
        table = validate.control_table(recorded("control-ours.csv"),
                                       recorded("control-original.csv"))
        self.assertIn("| hazards inside the swath | 800 / 800 | 800 / 800 |", table)
        self.assertIn("| every object outside the swath | 0 / 1600 | 0 / 1600 |", table)
        self.assertIn("| hazards 7 m beyond a lane end | 0 / 15 | 15 / 15 |", table)

    def test_the_command_line_prints_the_tables(self):
        import contextlib
        import io
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            status = validate.main(["scene", "--ours", os.path.join(RECORDED, "scene-ours.csv"),
                                    "--original", os.path.join(RECORDED, "scene-original.csv")])
        self.assertEqual(status, 0)
        self.assertIn("| ours | 1 | 25 |", out.getvalue())

    def test_a_file_that_is_not_a_result_is_refused_with_its_name(self):
        import tempfile
        with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
            f.write("group,kind,objects,passes\ninside,H,two,3\n")
        try:
            with self.assertRaisesRegex(ValueError, "not a pass_bench result file"):
                validate.read_runs([f.name])
        finally:
            os.unlink(f.name)

    def test_the_command_line_names_a_missing_file(self):
        import contextlib
        import io
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            status = validate.main(["control", "--ours", "no-such.csv", "--original", "x.csv"])
        self.assertEqual(status, 1)
        self.assertIn("no-such.csv", err.getvalue())


if __name__ == "__main__":
    unittest.main(verbosity=2)
