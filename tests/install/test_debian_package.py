#!/usr/bin/env python3
"""The Debian package: built by CPack from the build, its contents, its Depends, lintian, and
the programs run from the unpacked package.

Usage: test_debian_package.py --build-dir B --source-dir S --version V --cmake C --cpack P
"""
import pathlib
import shutil
import tempfile
import unittest

from install_support import cache_option, checked, parse_arguments, programs, run

ARGS = parse_arguments()


def debian_architecture():
    return checked(["dpkg", "--print-architecture"]).strip()


class DebianPackage(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = pathlib.Path(tempfile.mkdtemp(prefix="hazardsensor-deb-"))
        checked([ARGS.cpack, "--config", pathlib.Path(ARGS.build_dir) / "CPackConfig.cmake",
                 "-B", cls.scratch], timeout=900)
        cls.deb = cls.scratch / f"hazardsensor_{ARGS.version}_{debian_architecture()}.deb"
        cls.programs = programs(ARGS.build_dir)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.scratch, ignore_errors=True)

    def field(self, name):
        return checked(["dpkg-deb", "--field", self.deb, name]).strip()

    def test_the_package_is_named_for_its_version_and_architecture(self):
        self.assertTrue(self.deb.is_file(), sorted(p.name for p in self.scratch.iterdir()))
        self.assertEqual(self.field("Package"), "hazardsensor")
        self.assertEqual(self.field("Version"), ARGS.version)
        self.assertTrue(self.field("Description").startswith("simulated side-looking sonar"))

    def test_it_installs_every_program_under_usr(self):
        listing = checked(["dpkg-deb", "--contents", self.deb])
        paths = {line.split()[-1] for line in listing.splitlines()}
        for name in self.programs:
            with self.subTest(program=name):
                self.assertIn(f"./usr/bin/{name}", paths)
                self.assertIn(f"./usr/share/man/man1/{name}.1.gz", paths)
        self.assertIn("./usr/share/doc/hazardsensor/copyright", paths)
        self.assertIn("./usr/share/doc/hazardsensor/changelog.gz", paths)
        self.assertIn("./usr/share/hazardsensor/missions/jake/launch.sh", paths)
        self.assertEqual([p for p in paths if not p.startswith("./usr/") and p != "./"], [])

    def test_depends_names_the_shared_libraries_it_links_and_no_moos(self):
        depends = self.field("Depends")
        for package in ("libc6", "libstdc++6", "libgeographiclib", "python3"):
            self.assertIn(package, depends)
        self.assertNotIn("moos", depends.lower())
        if cache_option(ARGS.build_dir, "HAZARD_MIMALLOC"):
            self.assertIn("libmimalloc2.0", depends)
        # pWebViewer's HTTP server is Boost.Beast, header-only: no HTTP or Boost library to install.
        self.assertNotIn("httplib", depends)
        self.assertNotIn("libboost", depends)

    def test_lintian_reports_no_error(self):
        result = run(["lintian", "--no-tag-display-limit", self.deb], timeout=600)
        errors = [line for line in result.stdout.splitlines() if line.startswith("E:")]
        self.assertEqual(errors, [], result.stdout)
        self.assertNotIn("E:", result.stderr)

    def test_the_unpacked_programs_run(self):
        root = self.scratch / "unpacked"
        checked(["dpkg", "-x", self.deb, root])
        for name in self.programs:
            with self.subTest(program=name):
                out = checked([root / "usr/bin" / name, "--version"])
                self.assertEqual(out, f"{name} {ARGS.version} (HazardSensor)\n")


if __name__ == "__main__":
    unittest.main(verbosity=2)
