"""Meshes the command line exports, checked by a mesh library nobody here wrote (trimesh):
every exported body closed (watertight after merging vertices), consistently wound, facing
outwards (positive volume), and one body where one is meant."""

import os
import subprocess
import tempfile
import unittest

import trimesh

SEASHELLS = os.environ.get("SEASHELLS", "target/release/seashells")

# One preset of each form that is one closed body.
ONE_BODY = ["turbinate", "oliva-porphyria", "kawaguchi-shell", "kawaguchi-horn", "implicit-whorl"]


def export(preset, extension, *options):
    """Writes `preset` with `seashells mesh` and returns the file's path."""
    folder = tempfile.mkdtemp(prefix="seashells-files-")
    path = os.path.join(folder, f"{preset}.{extension}")
    subprocess.run(
        [SEASHELLS, "mesh", "--preset", preset, "--out", path, *options],
        check=True,
        capture_output=True,
    )
    return path


class Solids(unittest.TestCase):
    def test_one_closed_outward_body(self):
        for preset in ONE_BODY:
            with self.subTest(preset=preset):
                mesh = trimesh.load(export(preset, "stl"), force="mesh")
                self.assertTrue(mesh.is_watertight, f"{preset} is not watertight")
                self.assertTrue(mesh.is_winding_consistent, f"{preset} is wound inconsistently")
                self.assertGreater(mesh.volume, 0, f"{preset} faces inwards")
                bodies = mesh.split(only_watertight=False)
                self.assertEqual(len(bodies), 1, f"{preset} falls apart into {len(bodies)} bodies")


if __name__ == "__main__":
    unittest.main()
