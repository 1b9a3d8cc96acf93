"""Exports in the shell's colours, read back by tools nobody here wrote: the Khronos glTF
Validator passes a GLB of one preset of each form with no errors, and trimesh loads them with
their texture; the Oliva PLY's vertex colours are many, and they are the GLB's texture sampled
at the same vertices' texture coordinates; the GLB's texture is the planar pattern the page
draws and `seashells pattern` writes."""

import json
import os
import subprocess
import unittest

import numpy as np
import trimesh
from PIL import Image

from cli import export

# One preset of each form, and whether it has a pattern.
# Each form's preset and how its GLB carries colour: the pattern as a texture, colours per
# vertex (the Murex's four parts textured apart and blended by field, Galbraith et al. §3.4),
# or the material's colour alone.
FORMS = {
    "sweep": ("oliva-porphyria", "texture"),
    "chambers": ("kawaguchi-painted", "texture"),
    "branching": ("kawaguchi-coral", None),
    "implicit": ("murex-cabritii", "vertex"),
}


def validate(path):
    """The Khronos glTF Validator's report on `path` (see validate_gltf.mjs)."""
    script = os.path.join(os.path.dirname(__file__), "validate_gltf.mjs")
    out = subprocess.run(["node", script, path], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def to_linear(srgb):
    c = np.asarray(srgb, dtype=np.float64) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def to_srgb(linear):
    c = np.clip(linear, 0.0, 1.0)
    s = np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)
    return np.floor(s * 255.0 + 0.5).astype(int)


def sample(image, uv):
    """What a glTF viewer shows at texture coordinates `uv` (glTF's, v downwards) of an sRGB
    base colour texture with linear filtering and clamped edges: bilinear in linear light."""
    texels = to_linear(np.asarray(image.convert("RGB")))
    h, w = texels.shape[:2]
    x = np.clip(uv[:, 0] * w - 0.5, 0, w - 1)
    y = np.clip(uv[:, 1] * h - 0.5, 0, h - 1)
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    x1, y1 = np.minimum(x0 + 1, w - 1), np.minimum(y0 + 1, h - 1)
    fx, fy = (x - x0)[:, None], (y - y0)[:, None]
    top = texels[y0, x0] * (1 - fx) + texels[y0, x1] * fx
    bottom = texels[y1, x0] * (1 - fx) + texels[y1, x1] * fx
    return to_srgb(top * (1 - fy) + bottom * fy)


def glb_json(path):
    """The JSON chunk of the GLB at `path` (glTF 2.0 §4.4: a 12-byte header, then the chunk's
    length and type)."""
    with open(path, "rb") as f:
        data = f.read()
    length = int.from_bytes(data[12:16], "little")
    assert data[16:20] == b"JSON"
    return json.loads(data[20:20 + length])


def parts(path):
    """The GLB's primitives by material name, as trimesh loads them."""
    scene = trimesh.load(path)
    return {g.visual.material.name: g for g in scene.geometry.values()}


class Glb(unittest.TestCase):
    def test_one_preset_of_each_form_passes_the_validator_and_loads(self):
        for form, (preset, colours) in FORMS.items():
            patterned = colours == "texture"
            with self.subTest(form=form):
                path = export(preset, "glb")
                report = validate(path)
                errors = [m for m in report["messages"] if m["severity"] == 0]
                print(f"\n{form} ({preset}): {os.path.getsize(path)} bytes, validator "
                      f"{report['numErrors']} errors, {report['numWarnings']} warnings, "
                      f"{report['numInfos']} infos, {report['info']['totalTriangleCount']} triangles")
                self.assertEqual(report["numErrors"], 0, errors)
                self.assertEqual(report["info"]["hasTextures"], patterned)
                loaded = parts(path)
                self.assertIn("shell", loaded)
                shell = loaded["shell"]
                self.assertGreater(len(shell.faces), 1000)
                if patterned:
                    self.assertIsNotNone(shell.visual.material.baseColorTexture)
                    self.assertEqual(shell.visual.uv.shape, (len(shell.vertices), 2))
                if colours == "vertex":
                    document = glb_json(path)
                    attributes = [p["attributes"] for m in document["meshes"] for p in m["primitives"]]
                    self.assertTrue(any("COLOR_0" in a for a in attributes), attributes)

    def test_the_texture_is_the_planar_pattern(self):
        glb = parts(export("oliva-porphyria", "glb"))
        texture = glb["shell"].visual.material.baseColorTexture
        pattern = export("oliva-porphyria", "png", command="pattern")
        planar = Image.open(pattern).convert("RGB")
        self.assertEqual(texture.size, (400, 2900))
        self.assertTrue(np.array_equal(np.asarray(texture.convert("RGB")), np.asarray(planar)))

    def test_the_size_is_the_largest_side_in_metres_or_the_side_named(self):
        # glTF's up is y and its depth z; the options name a printer's sides (z up, y deep).
        for options, axis, metres in [([], None, 0.08),
                                      (["--size", "120"], None, 0.12),
                                      (["--size", "120", "--size-axis", "z"], 1, 0.12),
                                      (["--size", "50", "--size-axis", "y"], 2, 0.05),
                                      (["--size", "50", "--size-axis", "x"], 0, 0.05)]:
            with self.subTest(options=options):
                scene = trimesh.load(export("kawaguchi-shell", "glb", *options))
                low, high = scene.bounds
                side = max(high - low) if axis is None else high[axis] - low[axis]
                self.assertAlmostEqual(side, metres, places=6)
                self.assertAlmostEqual(low[1], 0.0, places=6)


class Ply(unittest.TestCase):
    def test_the_oliva_has_many_colours_and_they_are_the_glb_texture_at_its_vertices(self):
        ply = trimesh.load(export("oliva-porphyria", "ply"), process=False)
        colours = ply.visual.vertex_colors[:, :3].astype(int)
        distinct = len(np.unique(colours, axis=0))
        self.assertGreater(distinct, 1000, f"only {distinct} colours")
        by_position = {tuple(p): c for p, c in zip(ply.vertices.astype(np.float32).tolist(), colours)}

        shell = parts(export("oliva-porphyria", "glb"))["shell"]
        uv = shell.visual.uv.copy()
        uv[:, 1] = 1.0 - uv[:, 1]  # trimesh turns glTF's v upwards
        sampled = sample(shell.visual.material.baseColorTexture, uv)
        # The GLB keeps copies where the pattern's x wraps; the PLY welds them into one vertex,
        # which takes the colour of one of them.
        agree = {}
        for p, c in zip(shell.vertices.astype(np.float32).tolist(), sampled):
            key = tuple(p)
            ply_colour = by_position[key]
            agree[key] = agree.get(key, False) or np.abs(ply_colour - c).max() <= 1
        wrong = [k for k, ok in agree.items() if not ok]
        print(f"\nOliva PLY: {len(colours)} vertices, {distinct} colours; {len(agree)} positions "
              f"of the GLB's outer surface compared, {len(wrong)} differ")
        self.assertGreater(len(agree), 50_000)
        self.assertEqual(wrong, [])


if __name__ == "__main__":
    unittest.main()
