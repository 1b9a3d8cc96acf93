"""Meshes the command line exports, checked by a mesh library nobody here wrote (trimesh):
every exported body closed (watertight after merging vertices), consistently wound, facing
outwards (positive volume), and as many bodies as are meant: one for a shell, one per branch
(the stem counted as one) for Kawaguchi's branching forms."""

import glob
import json
import os
import subprocess
import tempfile
import unittest

import trimesh

SEASHELLS = os.environ.get("SEASHELLS", "target/release/seashells")
SPECIES = os.path.join(os.path.dirname(__file__), "..", "..", "species")

# One preset of each form that is one closed body.
ONE_BODY = ["turbinate", "oliva-porphyria", "kawaguchi-shell", "kawaguchi-horn", "implicit-whorl"]

# The bodies of each branching preset: its stem and its branches, each one closed tube, as its
# tree grows them (tests/branching.rs checks that the mesh has one body per branch of the tree).
BRANCHES = {
    "kawaguchi-spiral-plant": 61,
    "kawaguchi-tendril": 17,
    "kawaguchi-leaves": 171,
    "kawaguchi-coral": 467,
    "kawaguchi-tentacles": 9,
}


def presets_of_kind(kind):
    """The ids of the presets in species/ whose form is of `kind`."""
    ids = []
    for path in sorted(glob.glob(os.path.join(SPECIES, "*.json"))):
        with open(path, encoding="utf-8") as f:
            if json.load(f)["spec"]["form"]["kind"] == kind:
                ids.append(os.path.basename(path)[: -len(".json")])
    return ids


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
    def assert_closed_outward_bodies(self, preset, bodies):
        """The export of `preset` is watertight, consistently wound and faces outwards, and
        falls apart into `bodies` bodies, each of them closed and outward too."""
        mesh = trimesh.load(export(preset, "stl"), force="mesh")
        self.assertTrue(mesh.is_watertight, f"{preset} is not watertight")
        self.assertTrue(mesh.is_winding_consistent, f"{preset} is wound inconsistently")
        self.assertGreater(mesh.volume, 0, f"{preset} faces inwards")
        parts = mesh.split(only_watertight=False)
        self.assertEqual(len(parts), bodies, f"{preset} falls apart into {len(parts)} bodies")
        for part in parts:
            self.assertTrue(part.is_watertight, f"a body of {preset} is open")
            self.assertGreater(part.volume, 0, f"a body of {preset} faces inwards")

    def test_one_closed_outward_body(self):
        for preset in ONE_BODY:
            with self.subTest(preset=preset):
                self.assert_closed_outward_bodies(preset, 1)

    def test_every_chamber_preset_is_one_closed_outward_body(self):
        presets = presets_of_kind("chambers")
        self.assertGreaterEqual(len(presets), 6)
        for preset in presets:
            with self.subTest(preset=preset):
                self.assert_closed_outward_bodies(preset, 1)

    def test_every_branching_preset_is_a_closed_outward_body_per_branch(self):
        presets = presets_of_kind("branching")
        self.assertEqual(sorted(presets), sorted(BRANCHES), "a branching preset without its count")
        for preset in presets:
            with self.subTest(preset=preset):
                self.assert_closed_outward_bodies(preset, BRANCHES[preset])


if __name__ == "__main__":
    unittest.main()
