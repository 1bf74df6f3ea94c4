"""What the install tests share: their command line and running a program."""
import argparse
import os
import pathlib
import subprocess
import sys


def parse_arguments():
    """--build-dir, --source-dir, --version, --cmake, --cpack; the rest is unittest's."""
    parser = argparse.ArgumentParser()
    for name in ("build-dir", "source-dir", "version", "cmake", "cpack"):
        parser.add_argument("--" + name, required=True)
    args, rest = parser.parse_known_args()
    sys.argv[1:] = rest
    return args


def programs(build_dir):
    """The installed programs' names (the build's programs.txt: "name path" a line)."""
    lines = (pathlib.Path(build_dir) / "programs.txt").read_text().splitlines()
    names = [line.split(" ", 1)[0] for line in lines if line.strip()]
    if len(names) < 10:
        raise AssertionError(f"programs.txt lists {len(names)} programs: {names}")
    return names


def cache_option(build_dir, name):
    """A boolean option of the build's CMakeCache.txt (ON, TRUE, 1, YES: true)."""
    cache = (pathlib.Path(build_dir) / "CMakeCache.txt").read_text()
    for line in cache.splitlines():
        if line.startswith(name + ":"):
            return line.split("=", 1)[1].strip().upper() in ("ON", "TRUE", "1", "YES")
    raise AssertionError(f"{name} is not in {build_dir}/CMakeCache.txt")


def run(command, timeout=120, **kwargs):
    """Runs a command; its CompletedProcess (text, both streams captured)."""
    return subprocess.run([str(c) for c in command], capture_output=True, text=True,
                          timeout=timeout, stdin=subprocess.DEVNULL, **kwargs)


def checked(command, timeout=600, **kwargs):
    """Runs a command that must succeed; its standard output."""
    result = run(command, timeout=timeout, **kwargs)
    if result.returncode != 0:
        raise AssertionError(f"{' '.join(map(str, command))} exited {result.returncode}\n"
                             f"stdout:\n{result.stdout[-4000:]}\nstderr:\n{result.stderr[-4000:]}")
    return result.stdout


def system_path():
    """The system's programs only: no build tree, no user folder."""
    return os.pathsep.join(p for p in ("/usr/bin", "/bin") if os.path.isdir(p))
