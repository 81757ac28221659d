#!/usr/bin/env python3
"""Value tests of scripts/study.py: the Pareto selection against hand-made points whose fronts
follow from the definition (a point is on the front when no other point of its scene and effect
is at least as fast and as accurate, and strictly better in one), and FLIP of image pairs whose
answer is known without FLIP's code: identical images score 0, a difference outside the mask
scores 0, a larger uniform difference scores more, and an empty mask scores no pixels.

Run by tests/cli/study_python.cmake with the venv's interpreter (scripts/python_env.sh)."""
import pathlib
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import study  # noqa: E402


def point(scene, time_us, flip, effect="reflections"):
    return {"scene": scene, "effect": effect, "time_us": time_us, "flip": flip}


class ParetoTest(unittest.TestCase):
    def test_fronts_per_scene_and_effect(self):
        rows = [
            point("room", 1.0, 0.5),  # fastest: on the front
            point("room", 2.0, 0.3),  # most accurate: on the front
            point("room", 3.0, 0.3),  # as accurate as (2, 0.3) and slower: dominated
            point("room", 2.5, 0.6),  # slower and worse than (1, 0.5): dominated
            point("room", 1.0, 0.5),  # equal to the first: neither is strictly better, both stay
            point("hall", 10.0, 0.9),  # alone in its scene, although room's points beat it
            point("room", 100.0, 0.9, effect="shadows"),  # alone in its effect
        ]
        study.mark_pareto(rows)
        self.assertEqual([r["pareto"] for r in rows], [1, 1, 0, 0, 1, 1, 1])

    def test_unscored_points_are_on_no_front_and_beat_none(self):
        rows = [point("room", 1.0, None), point("room", 2.0, 0.4), point("room", 3.0, 0.2)]
        study.mark_pareto(rows)
        self.assertEqual([r["pareto"] for r in rows], [0, 1, 1])
        self.assertEqual(study.scored(None), "no pixels scored")
        self.assertEqual(study.scored(0.12345), "0.1235")


class ChoiceTableTest(unittest.TestCase):
    def test_presets_and_budget_are_listed_as_study_json_holds_them(self):
        point = {"point": "no_denoiser", "settings": ["denoise=false"], "time_us": 412.3, "error": 1.5}
        study_json = {"presets": {"reflections": {"ultra": dict(point, point="spq_4"), "low": point}},
                      "budget": {"budget_us": 500.0, "choices": {"reflections": point, "shadows": None}}}
        lines = study.choice_tables(study_json)
        self.assertIn("| reflections | low | no_denoiser | `denoise=false` | 412.3 | 1.5000 |", lines)
        rows = [line for line in lines if line.startswith("| reflections |")]
        self.assertEqual([row.split(" | ")[1] for row in rows], ["low", "ultra"])  # cheapest first
        self.assertIn("### budget 500 µs", lines)
        self.assertIn("- reflections: no_denoiser (`denoise=false`), 412.3 µs, error 1.5000 × the defaults'", lines)
        self.assertIn("- shadows: no measured point fits", lines)
        self.assertEqual(study.choice_tables({}), [])  # a study from before the presets


class FlipTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.folder.name)
        ramp = np.linspace(0.1, 0.6, 48, dtype=np.float32)
        self.reference = np.repeat(np.tile(ramp, (32, 1))[..., None], 3, axis=2)
        self.left = np.zeros((32, 48), dtype=bool)
        self.left[:, :24] = True

    def tearDown(self):
        self.folder.cleanup()

    def save(self, name, image):
        import matplotlib.pyplot as plt

        plt.imsave(self.dir / name, np.clip(image, 0.0, 1.0))
        return name

    def flip(self, output, mask, effect="shadows"):
        row = {"effect": effect, "reference": self.save("reference.png", self.reference),
               "output": self.save("output.png", output),
               "mask": self.save("mask.png", np.repeat(mask.astype(np.float32)[..., None], 3, axis=2))}
        return study.mean_flip(self.dir, row)

    def test_identical_images_score_zero(self):
        everywhere = np.ones((32, 48), dtype=bool)
        self.assertEqual(self.flip(self.reference.copy(), everywhere), 0.0)
        self.assertEqual(self.flip(self.reference.copy(), everywhere, effect="reflections"), 0.0)

    def test_only_masked_pixels_count(self):
        output = self.reference.copy()
        output[:, 40:] += 0.3  # far from the left half, beyond FLIP's filter reach at this size
        self.assertEqual(self.flip(output, self.left), 0.0)
        self.assertGreater(self.flip(output, ~self.left), 0.0)

    def test_larger_difference_scores_more(self):
        everywhere = np.ones((32, 48), dtype=bool)
        small = self.flip(self.reference + 0.05, everywhere)
        large = self.flip(self.reference + 0.3, everywhere)
        self.assertGreater(small, 0.0)
        self.assertGreater(large, small)
        self.assertLessEqual(large, 1.0)  # FLIP's range

    def test_empty_mask_is_not_scored(self):
        self.assertIsNone(self.flip(self.reference + 0.3, np.zeros((32, 48), dtype=bool)))


class AnchorTest(unittest.TestCase):
    def test_bundled_anchors_load_with_their_conditions(self):
        anchors = study.load_anchors()
        denoised = [a for a in anchors if a["label"] == "FidelityFX SDK 1.1.4, denoised"]
        self.assertEqual(len(denoised), 1)
        # The figures of docs/anchors/fidelityfx-sdk-1.1.4.json, each with where it was measured.
        self.assertEqual((denoised[0]["time_us"], denoised[0]["flip"]), (298.6, 0.421))
        for a in anchors:
            self.assertTrue(a["time_measured"] and a["error_measured"] and a["source"].endswith(".json"))

    def test_plot_and_table_carry_the_anchor(self):
        anchors = [{"effect": "reflections", "scene": "room", "label": "other", "time_us": 5.0, "flip": 0.2,
                    "device": "GPU X", "width": 1920, "height": 1080,
                    "mae": None, "time_measured": "GPU X, 1080p", "error_measured": "CPU Y, 360p",
                    "source": "other.json"}]
        rows = [dict(point("room", 1.0, 0.5), label="a"), dict(point("room", 2.0, 0.3), label="b")]
        study.mark_pareto(rows)
        with tempfile.TemporaryDirectory() as folder:
            path = pathlib.Path(folder) / "reflections.png"
            study.plot_effect(rows, "reflections", "test", path, anchors)
            self.assertGreater(path.stat().st_size, 0)
        table = "\n".join(study.anchor_tables(anchors))
        self.assertIn("| reflections | room | other | 5.0 | GPU X, 1080p | 0.2000 | no pixels scored | CPU Y, 360p |", table)

    def test_anchors_are_drawn_only_on_their_device_and_size(self):
        anchor = {"device": "NVIDIA H200", "width": 1920, "height": 1080}
        def run(name, width, height):
            return {"device": {"name": name}, "width": width, "height": height}
        self.assertTrue(study.comparable_anchor(anchor, run("NVIDIA H200", 1920, 1080)))
        self.assertFalse(study.comparable_anchor(anchor, run("llvmpipe (LLVM 15.0.6, 256 bits)", 1920, 1080)))
        self.assertFalse(study.comparable_anchor(anchor, run("NVIDIA H200", 640, 360)))


if __name__ == "__main__":
    unittest.main()
