"""Running the command line that writes the files the tests read back."""

import os
import subprocess
import tempfile

SEASHELLS = os.environ.get("SEASHELLS", "target/release/seashells")


def run(args, extension):
    """Runs `seashells ARGS --out FILE.EXTENSION` in a fresh folder; returns the finished
    process and the file's path."""
    folder = tempfile.mkdtemp(prefix="seashells-files-")
    path = os.path.join(folder, f"out.{extension}")
    result = subprocess.run([SEASHELLS, *args, "--out", path], capture_output=True, text=True)
    return result, path


def export(preset, extension, *options, command="mesh"):
    """Writes `preset` with `seashells COMMAND` (mesh or pattern) and returns the file's path."""
    result, path = run([command, "--preset", preset, *options], extension)
    if result.returncode != 0:
        raise AssertionError(f"seashells {command} {preset}: {result.stderr}")
    return path
