#!/usr/bin/env python3
"""cmake --install into a temporary prefix, and the product used from there alone.

Usage: test_install.py --build-dir B --source-dir S --version V --cmake C --cpack P
"""
import gzip
import json
import os
import pathlib
import re
import shutil
import tempfile
import unittest

from install_support import cache_option, checked, parse_arguments, programs, run, system_path

ARGS = parse_arguments()
SOURCE = pathlib.Path(ARGS.source_dir)
# Programs with the MOOS-IvP information switches --example and --interface.
MOOS_APPS = {"uFldHazardSensor", "uFldHazardMetric", "pHazardMgr", "uSimSurveyVehicle",
             "pLogLite", "pWebViewer"}


class Installed(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = pathlib.Path(tempfile.mkdtemp(prefix="hazardsensor-install-"))
        cls.prefix = cls.scratch / "prefix"
        checked([ARGS.cmake, "--install", ARGS.build_dir, "--prefix", cls.prefix])
        cls.programs = programs(ARGS.build_dir)
        cls.env = dict(os.environ, PATH=f"{cls.prefix / 'bin'}{os.pathsep}{system_path()}")

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.scratch, ignore_errors=True)

    def test_every_program_answers_version_with_its_name_and_the_release(self):
        for name in self.programs:
            with self.subTest(program=name):
                result = run([name, "--version"], env=self.env)
                self.assertEqual(result.returncode, 0, result.stderr)
                self.assertEqual(result.stdout, f"{name} {ARGS.version} (HazardSensor)\n")

    def test_every_program_answers_help(self):
        for name in self.programs:
            with self.subTest(program=name):
                result = run([name, "--help"], env=self.env)
                self.assertEqual(result.returncode, 0, result.stderr)
                self.assertIn(name, result.stdout)
                self.assertGreater(len(result.stdout.splitlines()), 5)

    def test_every_program_allocates_through_mimalloc(self):
        if not cache_option(ARGS.build_dir, "HAZARD_MIMALLOC"):
            self.skipTest("built with -DHAZARD_MIMALLOC=OFF")
        for name in self.programs:
            with self.subTest(program=name):
                path = self.prefix / "bin" / name
                needed = re.findall(r"\(NEEDED\).*\[(.+)\]", checked(["readelf", "-d", path]))
                self.assertIn("libmimalloc.so.2", needed)
                # The dynamic linker binds the program's and libstdc++'s malloc and operator
                # new to mimalloc, not to the C library's.
                result = run([path, "--version"], env=dict(self.env, LD_DEBUG="bindings"))
                self.assertEqual(result.returncode, 0, result.stderr[-2000:])
                for symbol in ("malloc", "_Znwm"):
                    bound = re.findall(rf"binding file (\S+) .* to (\S+) .*symbol `{symbol}'",
                                       result.stderr)
                    self.assertTrue(bound, f"no binding of {symbol}")
                    self.assertEqual({os.path.basename(to) for _, to in bound},
                                     {"libmimalloc.so.2"}, bound)

    def test_every_program_has_a_man_page_made_from_its_own_texts(self):
        for name in self.programs:
            with self.subTest(program=name):
                page = self.prefix / "share/man/man1" / f"{name}.1.gz"
                self.assertTrue(page.is_file(), page)
                text = gzip.decompress(page.read_bytes()).decode()
                self.assertRegex(text, rf'(?m)^\.TH {re.escape(name.upper())} "1"')
                self.assertIn(ARGS.version, text)
                # A switch the program's --help prints appears in the page.
                self.assertIn("help", text)
                if name in MOOS_APPS:
                    self.assertIn(".SH EXAMPLE", text)
                    self.assertIn(".SH INTERFACE", text)

    def test_the_engine_headers_libraries_and_packages_are_installed(self):
        include = self.prefix / "include/hazardsensor"
        for header in ("hazard/driver.hpp", "hazard/engine.hpp", "base/text.hpp"):
            self.assertTrue((include / header).is_file(), header)
        libs = {p.name for p in self.prefix.rglob("libhazardsensor-*.a")}
        self.assertEqual(libs, {"libhazardsensor-base.a", "libhazardsensor-hazard.a"})
        configs = {p.name for p in self.prefix.rglob("HazardSensor*.cmake")}
        self.assertTrue({"HazardSensorConfig.cmake", "HazardSensorConfigVersion.cmake",
                         "HazardSensorTargets.cmake"} <= configs, configs)
        (pc,) = list(self.prefix.rglob("hazardsensor.pc"))
        env = dict(os.environ, PKG_CONFIG_PATH=str(pc.parent))
        self.assertEqual(checked(["pkg-config", "--modversion", "hazardsensor"], env=env).strip(),
                         ARGS.version)
        flags = checked(["pkg-config", "--cflags", "--libs", "hazardsensor"], env=env).split()
        # The .pc file finds the prefix from its own place: any prefix works.
        include_dirs = {os.path.realpath(f[2:]) for f in flags if f.startswith("-I")}
        self.assertIn(os.path.realpath(include), include_dirs)
        self.assertIn("-lhazardsensor-hazard", flags)

    def test_docs_missions_and_their_launcher_are_installed(self):
        doc = self.prefix / "share/doc/hazardsensor"
        for name in ("README.md", "CHANGELOG.md", "copyright", "changelog.gz",
                     "docs/uFldHazardSensor.md"):
            self.assertTrue((doc / name).is_file(), name)
        data = self.prefix / "share/hazardsensor"
        for launcher in ("missions/jake/launch.sh", "missions/hazard_field_large/launch.sh"):
            self.assertTrue(os.access(data / launcher, os.X_OK), launcher)
        self.assertTrue((data / "tools/render_mission.py").is_file())
        self.assertEqual(list(data.rglob("__pycache__")), [])

    def test_the_embedding_example_builds_and_runs_against_the_prefix_alone(self):
        build = self.scratch / "embed-cmake"
        checked([ARGS.cmake, "-S", SOURCE / "examples/embed_engine", "-B", build, "-G", "Ninja",
                 f"-DCMAKE_PREFIX_PATH={self.prefix}", "-DCMAKE_BUILD_TYPE=Release"])
        checked([ARGS.cmake, "--build", build])
        out = checked([build / "embed_engine"])
        self.assertIn(f"HazardSensor engine {ARGS.version}", out)
        detections = re.search(r"^(\d+) detections of 11 objects$", out, re.MULTILINE)
        self.assertIsNotNone(detections, out)
        self.assertGreater(int(detections.group(1)), 0)
        self.assertEqual(out.count("UHZ_DETECTION_REPORT"), int(detections.group(1)))

    def test_the_embedding_example_builds_with_pkg_config(self):
        (pc,) = list(self.prefix.rglob("hazardsensor.pc"))
        env = dict(os.environ, PKG_CONFIG_PATH=str(pc.parent))
        flags = checked(["pkg-config", "--cflags", "--libs", "hazardsensor"], env=env).split()
        program = self.scratch / "embed-pkg-config"
        checked(["c++", "-std=c++17", "-O1", SOURCE / "examples/embed_engine/main.cpp", "-o",
                 program, *flags])
        self.assertRegex(checked([program]), r"(?m)^[1-9]\d* detections of 11 objects$")

    def test_the_jake_mission_runs_from_the_installed_launcher_by_program_names(self):
        """pAntler's convention: `Run = uFldHazardSensor` in the mission file, found on PATH."""
        launcher = self.prefix / "share/hazardsensor/missions/jake/launch.sh"
        mission = (launcher.parent / "jake.moos").read_text()
        self.assertRegex(mission, r"(?m)^\s*Run = uFldHazardSensor\s+@")
        work = self.scratch / "elsewhere"
        work.mkdir()
        result = run([launcher, "--quiet", "--no-view"], timeout=400, cwd=work, env=self.env)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        (run_dir,) = list((work / "runs").iterdir())
        summary = json.loads((run_dir / "summary.json").read_text())
        self.assertIn("betty", json.dumps(summary))
        self.assertIn("Mission score (betty's report):", result.stdout)
        found = dict(line.split(" ", 1) for line in
                     (run_dir / "programs.txt").read_text().splitlines())
        self.assertEqual(found["uFldHazardSensor"], str(self.prefix / "bin/uFldHazardSensor"))
        self.assertEqual(found["pHazardMgr_betty"], str(self.prefix / "bin/pHazardMgr"))
        self.assertEqual(found["moosdb-lite"], str(self.prefix / "bin/moosdb-lite"))

    def test_the_installed_launcher_names_what_is_missing_from_path(self):
        launcher = self.prefix / "share/hazardsensor/missions/jake/launch.sh"
        env = dict(os.environ, PATH=system_path())
        result = run([launcher, "--quiet"], cwd=self.scratch, env=env)
        self.assertEqual(result.returncode, 2)
        self.assertIn("missing programs:", result.stderr)
        self.assertIn("uFldHazardSensor", result.stderr)


class OneVersion(unittest.TestCase):
    def test_the_changelogs_first_entries_are_this_release(self):
        changelog = (SOURCE / "CHANGELOG.md").read_text()
        first = re.search(r"(?m)^## \[?(\d+\.\d+\.\d+)", changelog)
        self.assertIsNotNone(first, "CHANGELOG.md has no release heading")
        self.assertEqual(first.group(1), ARGS.version)
        debian = (SOURCE / "packaging/changelog").read_text().splitlines()[0]
        self.assertRegex(debian, rf"^hazardsensor \({re.escape(ARGS.version)}\) ")


if __name__ == "__main__":
    unittest.main(verbosity=2)
