#!/usr/bin/env python3
"""Value tests of scripts/study.py: the Pareto selection against hand-made points whose fronts
follow from the definition (a point is on the front when no other point of its scene and effect
is at least as fast and as accurate, and strictly better in one); FLIP of image pairs whose
answer is known without FLIP's code: identical images score 0, a difference outside the mask
scores 0, a larger uniform difference scores more, a difference above the radiance clamp scores
0, and an empty mask scores no pixels; the tone mapping at values worked out by hand; the
reference noise floors and the convergence rule on hand-made fronts; the tables and columns.
The images are written as uncompressed OpenEXR (write_exr), which glint writes and FLIP reads,
so that radiance above 1 survives.

Run by tests/cli/study_python.cmake with the venv's interpreter (scripts/python_env.sh)."""
import contextlib
import csv
import io
import json
import pathlib
import struct
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import study  # noqa: E402


def point(scene, time_us, flip, effect="reflections"):
    return {"scene": scene, "effect": effect, "time_us": time_us, "flip": flip}


def write_exr(path, image):
    """An uncompressed scanline OpenEXR file of an H x W x 3 image, 32-bit float channels B, G, R
    (the file format's alphabetical order), from the OpenEXR file layout: magic number and
    version, the required header attributes, the offset of each scanline, then the scanlines."""
    image = np.asarray(image, dtype=np.float32)
    height, width = image.shape[:2]
    float_channel = struct.pack("<iB3xii", 2, 0, 1, 1)  # FLOAT, not perceptually linear, no subsampling

    def attribute(name, kind, value):
        return name + b"\0" + kind + b"\0" + struct.pack("<i", len(value)) + value

    window = struct.pack("<iiii", 0, 0, width - 1, height - 1)
    header = (struct.pack("<ii", 20000630, 2)
              + attribute(b"channels", b"chlist", b"B\0" + float_channel + b"G\0" + float_channel
                          + b"R\0" + float_channel + b"\0")
              + attribute(b"compression", b"compression", b"\0")  # none
              + attribute(b"dataWindow", b"box2i", window)
              + attribute(b"displayWindow", b"box2i", window)
              + attribute(b"lineOrder", b"lineOrder", b"\0")  # increasing y
              + attribute(b"pixelAspectRatio", b"float", struct.pack("<f", 1.0))
              + attribute(b"screenWindowCenter", b"v2f", struct.pack("<ff", 0.0, 0.0))
              + attribute(b"screenWindowWidth", b"float", struct.pack("<f", 1.0)) + b"\0")
    line_bytes = width * 3 * 4
    first = len(header) + 8 * height
    offsets = struct.pack(f"<{height}Q", *(first + y * (8 + line_bytes) for y in range(height)))
    lines = b"".join(struct.pack("<ii", y, line_bytes) + image[y, :, ::-1].T.astype("<f4").tobytes()
                     for y in range(height))
    pathlib.Path(path).write_bytes(header + offsets + lines)


def srgb_encode(linear):
    """The sRGB transfer function (IEC 61966-2-1), linear [0, 1] to encoded [0, 1]."""
    return np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * np.power(linear, 1 / 2.4) - 0.055).astype(np.float32)


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
        self.everywhere = np.ones((32, 48), dtype=bool)

    def tearDown(self):
        self.folder.cleanup()

    def save(self, name, image):
        write_exr(self.dir / name, image)
        return name

    def row(self, output, mask, effect="shadows", reference=None):
        return {"effect": effect, "reference": self.save("reference.exr", self.reference if reference is None else reference),
                "output": self.save("output.exr", output),
                "mask": self.save("mask.exr", np.repeat(mask.astype(np.float32)[..., None], 3, axis=2))}

    def flip(self, output, mask, effect="shadows", reference=None, dynamic_range="LDR"):
        return study.mean_flip(self.dir, self.row(output, mask, effect, reference), dynamic_range=dynamic_range)

    def test_identical_images_score_zero(self):
        self.assertEqual(self.flip(self.reference.copy(), self.everywhere), 0.0)
        self.assertEqual(self.flip(self.reference.copy(), self.everywhere, effect="reflections"), 0.0)
        self.assertEqual(self.flip(self.reference.copy(), self.everywhere, "reflections", dynamic_range="HDR"), 0.0)

    def test_only_masked_pixels_count(self):
        output = self.reference.copy()
        output[:, 40:] += 0.3  # far from the left half, beyond FLIP's filter reach at this size
        self.assertEqual(self.flip(output, self.left), 0.0)
        self.assertGreater(self.flip(output, ~self.left), 0.0)

    def test_larger_difference_scores_more(self):
        small = self.flip(self.reference + 0.05, self.everywhere)
        large = self.flip(self.reference + 0.3, self.everywhere)
        self.assertGreater(small, 0.0)
        self.assertGreater(large, small)
        self.assertLessEqual(large, 1.0)  # FLIP's range

    def test_empty_mask_is_not_scored(self):
        self.assertIsNone(self.flip(self.reference + 0.3, np.zeros((32, 48), dtype=bool)))

    def test_reflections_are_scored_on_tone_mapped_radiance(self):
        radiance = self.reference * 10  # 1 to 6: beyond LDR's [0, 1], inside the clamp
        self.assertEqual(self.flip(radiance.copy(), self.everywhere, "reflections", radiance), 0.0)
        brighter = self.flip(radiance * 2, self.everywhere, "reflections", radiance)
        self.assertGreater(brighter, 0.0)
        self.assertLessEqual(brighter, 1.0)
        # Radiance 20 and 40 both clamp to 16: the same tone-mapped image, nothing for FLIP to see.
        self.assertEqual(self.flip(np.full_like(radiance, 40.0), self.everywhere, "reflections",
                                   np.full_like(radiance, 20.0)), 0.0)

    def test_ldr_flip_is_given_linear_values(self):
        """FLIP of the tone-mapped radiance as linear input equals flip-evaluator's FLIP of the same
        values sRGB-encoded by hand (its default reading of LDR input); reading the linear values as
        sRGB-encoded would give another number."""
        import flip_evaluator as flip

        radiance = self.reference * 10
        output = radiance * 1.5
        got = self.flip(output, self.everywhere, "reflections", radiance)
        def mapped(x):
            return srgb_encode(np.minimum(x, 16) / (1 + np.minimum(x, 16)))  # by hand: Reinhard, then sRGB
        expected = float(np.mean(flip.evaluate(mapped(radiance), mapped(output), "LDR", applyMagma=False)[0]))
        self.assertAlmostEqual(got, expected, places=5)
        misread = float(np.mean(flip.evaluate(np.minimum(radiance, 16) / (1 + np.minimum(radiance, 16)),
                                              np.minimum(output, 16) / (1 + np.minimum(output, 16)),
                                              "LDR", applyMagma=False)[0]))
        self.assertGreater(abs(got - misread), 1e-3)

    def test_cropping_to_the_mask_changes_no_masked_error(self):
        import flip_evaluator as flip

        rng = np.random.default_rng(7)
        reference = rng.random((120, 160, 3), dtype=np.float32)
        test = np.clip(reference + 0.1 * rng.standard_normal(reference.shape).astype(np.float32), 0, 1)
        mask = np.zeros((120, 160), dtype=bool)
        mask[70:100, 90:130] = True  # 40 or more pixels from every edge: the crop is smaller than the image
        whole = flip.evaluate(reference, test, "LDR", inputsRGB=False, applyMagma=False)[0].reshape(mask.shape)
        self.assertAlmostEqual(study.masked_flip(reference, test, mask), float(whole[mask].mean()), places=6)


class ToneMapTest(unittest.TestCase):
    def test_known_values(self):
        # Reinhard x / (1 + x) after the clamp to [0, 16]: 0 -> 0, 1 -> 1/2, 100 -> 16 -> 16/17,
        # -3 -> 0 -> 0 (no negative light), 3 -> 3/4.
        mapped = study.tone_map(np.array([0.0, 1.0, 100.0, -3.0, 3.0]))
        np.testing.assert_allclose(mapped, [0.0, 0.5, 16 / 17, 0.0, 0.75], rtol=1e-6)
        np.testing.assert_allclose(study.tone_map(np.array([100.0]), clamp=4.0), [0.8], rtol=1e-6)

    def test_shadow_visibility_is_not_tone_mapped(self):
        np.testing.assert_allclose(study.ldr_image("shadows", np.array([-0.5, 0.25, 1.5])), [0.0, 0.25, 1.0])
        np.testing.assert_allclose(study.ldr_image("hybrid", np.array([1.0])), [0.5])


def study_row(scene, time_us, flip, mae=None, floor_flip=None, floor_mae=None, effect="reflections", label=None):
    """A hand-made row as study.py holds it after FLIP: floor_* given only where there is a floor."""
    row = dict(point(scene, time_us, flip, effect), label=label or f"t{time_us:g}", reference_spp=64)
    if mae is not None:
        row["mae"] = mae
    if floor_flip is not None:
        row["floor_flip"] = floor_flip
    if floor_mae is not None:
        row["floor"] = {"error_mean": 0.01, "mae": floor_mae, "rmse_clamped": 0.02, "penumbra": -1}
    return row


class BorrowTimesTest(unittest.TestCase):
    def test_each_point_takes_the_time_of_the_same_point_in_the_timed_study(self):
        scored = [{"scene": "room", "effect": "reflections", "label": "defaults", "time_us": 85.0, "flip_hdr": 0.23},
                  {"scene": "room", "effect": "reflections", "label": "spq_4", "time_us": 84.0, "flip_hdr": 0.22},
                  {"scene": "hall", "effect": "reflections", "label": "defaults", "time_us": 9.0, "flip_hdr": 0.5}]
        timed = {"rows": [{"scene": "room", "effect": "reflections", "label": "defaults", "time_us": 191.6},
                          {"scene": "room", "effect": "reflections", "label": "spq_4", "time_us": 234.8},
                          {"scene": "room", "effect": "shadows", "label": "defaults", "time_us": 59.0}]}
        rows = study.borrow_times(scored, timed)
        self.assertEqual([(r["label"], r["time_us"], r["time_us_own"], r["flip_hdr"]) for r in rows],
                         [("defaults", 191.6, 85.0, 0.23), ("spq_4", 234.8, 84.0, 0.22)])  # hall: not timed


class ConvergenceTest(unittest.TestCase):
    def scene(self, floor_flip, floor_mae=0.01, scene="room"):
        # Front by time: FLIP 0.30, 0.20, 0.18 (steps 0.10 and 0.02), MAE 0.50, 0.30, 0.25 (steps
        # 0.20 and 0.05). The point at 4 µs is dominated by the one at 3 µs: it is no step of the
        # front, although its FLIP 0.19 is 0.01 from it.
        return [study_row(scene, t, f, m, floor_flip, floor_mae)
                for t, f, m in ((1.0, 0.30, 0.50), (2.0, 0.20, 0.30), (3.0, 0.18, 0.25), (4.0, 0.19, 0.26))]

    def test_floor_below_a_quarter_of_the_smallest_step_is_converged(self):
        verdict = study.convergence(self.scene(0.004))[("room", "reflections")]
        self.assertAlmostEqual(verdict["smallest_flip_step"], 0.02)
        self.assertAlmostEqual(verdict["smallest_mae_step"], 0.05)
        self.assertEqual((verdict["converged_flip"], verdict["converged_mae"]), (True, True))  # 0.01 < 0.0125
        self.assertEqual((verdict["floor_flip"], verdict["floor_mae"], verdict["reference_spp"]), (0.004, 0.01, 64))

    def test_floor_above_a_quarter_of_the_smallest_step_is_not(self):
        verdict = study.convergence(self.scene(0.006, floor_mae=0.0126))[("room", "reflections")]
        self.assertEqual((verdict["converged_flip"], verdict["converged_mae"]), (False, False))
        warnings = study.convergence_warnings({("room", "reflections"): verdict})
        self.assertEqual(len(warnings), 1)  # one line per scene and effect
        self.assertIn("room reflections", warnings[0])
        self.assertIn("0.006", warnings[0])
        self.assertIn("0.02", warnings[0])
        self.assertIn("--spp 128 would converge it", warnings[0])  # both metrics need 65-92 spp
        self.assertEqual(study.convergence_warnings(study.convergence(self.scene(0.004))), [])

    def test_one_point_front_is_converged_trivially(self):
        rows = [study_row("hall", 1.0, 0.5, 0.4, floor_flip=0.3, floor_mae=0.3),
                study_row("hall", 2.0, 0.6, 0.5, floor_flip=0.3, floor_mae=0.3)]  # dominated
        verdict = study.convergence(rows)[("hall", "reflections")]
        self.assertEqual(verdict["front_points"], 1)
        self.assertIsNone(verdict["smallest_flip_step"])
        self.assertEqual((verdict["converged_flip"], verdict["converged_mae"]), (True, True))
        table = "\n".join(study.floor_tables({("hall", "reflections"): verdict}))
        self.assertIn("| hall | reflections | 64 | 0.3 | 0.3 | 0.01 | one point | one point | yes | yes | 0 of 0 | - |",
                      table)

    def test_rows_without_a_floor_are_not_judged(self):
        rows = [study_row("room", t, f, m) for t, f, m in ((1.0, 0.3, 0.5), (2.0, 0.2, 0.3))]
        verdict = study.convergence(rows)[("room", "reflections")]
        self.assertEqual((verdict["converged_flip"], verdict["converged_mae"]), (None, None))
        self.assertEqual(study.convergence_warnings({("room", "reflections"): verdict}), [])
        self.assertIn("None measured", "\n".join(study.floor_tables({("room", "reflections"): verdict})))

    def test_scenes_and_effects_are_judged_apart(self):
        rows = self.scene(0.004) + [dict(r, effect="hybrid") for r in self.scene(0.006)]
        verdicts = study.convergence(rows)
        self.assertEqual(verdicts[("room", "reflections")]["converged_flip"], True)
        self.assertEqual(verdicts[("room", "hybrid")]["converged_flip"], False)
        table = "\n".join(study.floor_tables(verdicts))
        # FLIP steps 0.10 and 0.02 against 4 x 0.006 = 0.024: one resolved. Converging the 0.02 step
        # needs 64 (4 x 0.006 / 0.02)^2 = 92.2 spp, so 128; MAE is converged already.
        self.assertIn("| room | hybrid | 64 | 0.006 | 0.01 | 0.01 | 0.02 | 0.05 | **no** | yes | 1 of 2 | 128 |", table)

    def test_spp_to_converge_follows_one_over_the_square_root_of_spp(self):
        self.assertEqual(study.spp_to_converge(64, 0.01, 0.01), 1024)  # floor 4x too high: 16x the spp
        self.assertEqual(study.spp_to_converge(64, 0.01, 0.02), 256)  # 2x too high: 4x
        self.assertIsNone(study.spp_to_converge(64, 0.001, 0.1))  # converged already
        self.assertIsNone(study.spp_to_converge(None, 0.01, 0.01))  # spp unknown
        self.assertIsNone(study.spp_to_converge(64, 0.01, None))  # no step to resolve


class FloorTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.dir = pathlib.Path(self.folder.name)
        ramp = np.linspace(0.5, 8.0, 48, dtype=np.float32)
        self.reference = np.repeat(np.tile(ramp, (32, 1))[..., None], 3, axis=2)
        write_exr(self.dir / "reference.exr", self.reference)
        write_exr(self.dir / "mask.exr", np.ones((32, 48, 3), dtype=np.float32))
        write_exr(self.dir / "output_a.exr", self.reference * 1.5)
        write_exr(self.dir / "output_b.exr", self.reference * 1.5)
        write_exr(self.dir / "reference2.exr", self.reference * 1.1)

    def tearDown(self):
        self.folder.cleanup()

    def rows(self, reference2="reference2.exr", effect="reflections"):
        return [{"scene": "room", "effect": effect, "label": label, "reference": "reference.exr",
                 "output": f"output_{label}.exr", "mask": "mask.exr", "reference2": reference2} for label in ("a", "b")]

    def test_identical_references_have_no_floor(self):
        write_exr(self.dir / "reference2.exr", self.reference)
        data = {"rows": self.rows()}
        study.add_flips(self.dir, data, hdr=True)
        for row in data["rows"]:
            self.assertEqual((row["floor_flip"], row["floor_flip_hdr"]), (0.0, 0.0))
            self.assertGreater(row["flip"], 0.0)
            self.assertGreater(row["flip_hdr"], 0.0)

    def test_floor_is_computed_once_per_reference(self):
        calls = []
        original = study.mean_flip

        def counting(directory, row, test="output", *arguments, **keywords):
            calls.append(test)
            return original(directory, row, test, *arguments, **keywords)

        study.mean_flip = counting
        try:
            data = {"rows": self.rows()}
            study.add_flips(self.dir, data, workers=1)  # counted in this process; no --hdr-flip: no HDR-FLIP at all
        finally:
            study.mean_flip = original
        self.assertEqual(calls.count("reference2"), 1)
        self.assertEqual(calls.count("output"), 2)
        self.assertGreater(data["rows"][0]["floor_flip"], 0.0)
        self.assertEqual(data["rows"][0]["floor_flip"], data["rows"][1]["floor_flip"])
        self.assertNotIn("flip_hdr", data["rows"][0])
        self.assertNotIn("floor_flip_hdr", data["rows"][0])

    def test_no_second_reference_no_floor(self):
        rows = self.rows()
        for row in rows:
            del row["reference2"]
        study.add_flips(self.dir, {"rows": rows})
        self.assertNotIn("floor_flip", rows[0])

    def test_flip_of_an_older_study_json_is_kept_as_hdr_flip_and_computed_again(self):
        # Before flip_metric, study.py wrote HDR-FLIP of the radiance under "flip".
        rows = self.rows()
        rows[0]["flip"], rows[1]["flip"] = 0.25, None
        data = {"rows": rows}
        study.add_flips(self.dir, data)
        self.assertEqual((rows[0]["flip_hdr"], rows[1]["flip_hdr"]), (0.25, None))
        self.assertGreater(rows[0]["flip"], 0.0)
        self.assertEqual(data["flip_metric"], study.flip_metric(16.0))
        rows[0]["flip"] = 0.5  # a value of the current kind is kept
        study.add_flips(self.dir, data)
        self.assertEqual(rows[0]["flip"], 0.5)


class TableTest(unittest.TestCase):
    def test_point_table(self):
        rows = [dict(study_row("room", 1.0, None), settings=[], error_mean=0.5, non_finite=0, penumbra=-1),
                dict(study_row("room", 2.0, 0.25, mae=0.125), settings=["denoise=false"], error_mean=0.75,
                     rmse_clamped=0.5, flip_hdr=0.375, non_finite=0, penumbra=-1)]
        study.mark_pareto(rows)
        lines = study.study_tables(rows)
        self.assertIn("| scene | point | settings | time (µs) | FLIP | HDR-FLIP | MAE | RMSE | mean error "
                      "| non-finite | Pareto |", lines)
        self.assertIn("| room | t1 | `-` | 1.0 | no pixels scored | - | - | - | 0.5000 | 0 |  |", lines)
        self.assertIn("| room | t2 | `denoise=false` | 2.0 | 0.2500 | 0.3750 | 0.1250 | 0.5000 | 0.7500 | 0 "
                      "| **yes** |", lines)

    def test_shadow_table_has_penumbra_moving_edges_and_no_hdr_flip(self):
        # Moving edges: a value, null (no receiver moved) and absent (a study from before them).
        rows = [dict(study_row("yard", 1.0, 0.25, mae=0.125, effect="shadows"), settings=[], error_mean=0.5,
                     rmse_clamped=0.5, non_finite=0, penumbra=0.0625, moving_edge=0.375),
                dict(study_row("lawn", 1.0, 0.25, effect="shadows"), settings=[], error_mean=0.5, non_finite=0,
                     penumbra=-1, moving_edge=None),
                dict(study_row("park", 1.0, 0.25, effect="shadows"), settings=[], error_mean=0.5, non_finite=0,
                     penumbra=-1)]
        study.mark_pareto(rows)
        lines = study.study_tables(rows)
        self.assertIn("| scene | point | settings | time (µs) | FLIP | MAE | RMSE | mean error | penumbra | moving edge "
                      "| non-finite | Pareto |", lines)
        self.assertIn("| yard | t1 | `-` | 1.0 | 0.2500 | 0.1250 | 0.5000 | 0.5000 | 0.0625 | 0.3750 | 0 | **yes** |",
                      lines)
        self.assertIn("| lawn | t1 | `-` | 1.0 | 0.2500 | - | - | 0.5000 | no pixels scored | no pixels scored | 0 "
                      "| **yes** |", lines)
        self.assertIn("| park | t1 | `-` | 1.0 | 0.2500 | - | - | 0.5000 | no pixels scored | - | 0 | **yes** |", lines)

    def test_metric_lines_state_the_clamp(self):
        text = " ".join(study.metric_lines(16.0))
        self.assertIn("[0, 16]", text)
        self.assertIn("Reinhard", text)

    def test_csv_gains_the_columns(self):
        with tempfile.TemporaryDirectory() as folder:
            path = pathlib.Path(folder) / "study.csv"
            path.write_text("scene,effect,label\nroom,reflections,a\nroom,shadows,b\n")
            rows = [{"flip": 0.25, "flip_hdr": None, "floor_flip": 0.125, "pareto": 1}, {"flip": None, "pareto": 0}]
            study.add_columns(pathlib.Path(folder), rows)
            study.add_columns(pathlib.Path(folder), rows)  # again: the same columns, not twice
            with open(path, newline="") as file:
                table = list(csv.reader(file))
        self.assertEqual(table[0], ["scene", "effect", "label", "flip", "flip_hdr", "floor_flip", "pareto"])
        self.assertEqual(table[1], ["room", "reflections", "a", "0.25", "no pixels scored", "0.125", "1"])
        self.assertEqual(table[2], ["room", "shadows", "b", "no pixels scored", "", "", "0"])


class MainTest(unittest.TestCase):
    """study.py on two hand-made folders (a study split by effect), each with its images."""

    def make_folder(self, root, effect, scale):
        folder = pathlib.Path(root) / effect
        images = folder / "images"
        images.mkdir(parents=True)
        ramp = np.linspace(0.1, 0.9, 48, dtype=np.float32) * scale
        reference = np.repeat(np.tile(ramp, (32, 1))[..., None], 3, axis=2)
        write_exr(images / "reference.exr", reference)
        write_exr(images / "reference2.exr", reference * 1.02)
        write_exr(images / "mask.exr", np.ones((32, 48, 3), dtype=np.float32))
        rows = []
        for label, time_us, error in (("fast", 1.0, 0.3), ("slow", 2.0, 0.05)):
            write_exr(images / f"{label}.exr", reference * (1 + error))
            rows.append({"scene": "room", "effect": effect, "label": label, "settings": [], "time_us": time_us,
                         "error_mean": error, "rmse": error, "mae": error * scale / 2, "rmse_clamped": error,
                         "penumbra": -1, "non_finite": 0, "pixels": 48 * 32, "traced_fraction": "",
                         "reference_spp": 64, "output": f"images/{label}.exr", "reference": "images/reference.exr",
                         "reference2": "images/reference2.exr", "mask": "images/mask.exr",
                         "floor": {"error_mean": 0.02, "mae": 0.01 * scale, "rmse_clamped": 0.02, "penumbra": -1}})
        data = {"device": {"name": "GPU X", "driver": "1", "subgroupSize": 32}, "width": 48, "height": 32,
                "frames": 3, "runs": 5, "radiance_clamp": 16, "rows": rows}
        (folder / "study.json").write_text(json.dumps(data))
        (folder / "study.csv").write_text("scene,effect,label\n" + "".join(f"room,{effect},{r['label']}\n" for r in rows))
        return folder

    def test_split_study_with_hdr_flip(self):
        with tempfile.TemporaryDirectory() as root:
            folders = [self.make_folder(root, "reflections", 4.0), self.make_folder(root, "shadows", 1.0)]
            errors = io.StringIO()
            with contextlib.redirect_stderr(errors), contextlib.redirect_stdout(io.StringIO()):
                study.main(folders, plots=True, hdr=True)
            for name in ("study.md", "reflections.png", "reflections_hdr.png", "shadows.png"):
                self.assertTrue((folders[0] / name).exists(), name)
            self.assertFalse((folders[0] / "shadows_hdr.png").exists())  # no HDR-FLIP of visibility
            markdown = (folders[0] / "study.md").read_text()
            self.assertIn("### reference noise floors", markdown)
            self.assertIn("| room | shadows | 64 |", markdown)
            saved = json.loads((folders[1] / "study.json").read_text())
            self.assertNotIn("flip_hdr", saved["rows"][0])
            self.assertGreater(saved["rows"][0]["floor_flip"], 0.0)
            self.assertNotIn("Traceback", errors.getvalue())

    def test_flip_only_draws_nothing(self):
        with tempfile.TemporaryDirectory() as root:
            folder = self.make_folder(root, "reflections", 4.0)
            with contextlib.redirect_stderr(io.StringIO()), contextlib.redirect_stdout(io.StringIO()):
                study.main([folder], plots=False)
            self.assertTrue((folder / "study.md").exists())
            self.assertEqual(list(folder.glob("*.png")), [])
            self.assertIn("| room | fast |", (folder / "study.md").read_text())


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
                    "flip_kind": "LDR", "device": "GPU X", "width": 1920, "height": 1080,
                    "mae": None, "time_measured": "GPU X, 1080p", "error_measured": "CPU Y, 360p",
                    "source": "other.json"}]
        rows = [dict(point("room", 1.0, 0.5), label="a"), dict(point("room", 2.0, 0.3), label="b")]
        study.mark_pareto(rows)
        with tempfile.TemporaryDirectory() as folder:
            path = pathlib.Path(folder) / "reflections.png"
            study.plot_effect(rows, "reflections", "test", path, anchors)
            self.assertGreater(path.stat().st_size, 0)
        table = "\n".join(study.anchor_tables(anchors + [dict(anchors[0], label="unsure", flip_kind=None)]))
        self.assertIn("| reflections | room | other | 5.0 | GPU X, 1080p | 0.2000 | LDR | no pixels scored "
                      "| CPU Y, 360p |", table)
        del anchors[0]["flip_kind"]
        table = "\n".join(study.anchor_tables(anchors))
        self.assertIn("| reflections | room | other | 5.0 | GPU X, 1080p | 0.2000 | unstated | no pixels scored "
                      "| CPU Y, 360p |", table)

    def test_anchors_are_drawn_only_beside_their_flip_kind(self):
        anchor = {"effect": "reflections", "flip": 0.4}
        ldr, hdr, unstated = dict(anchor, flip_kind="LDR"), dict(anchor, flip_kind="HDR"), dict(anchor)
        anchors = [ldr, hdr, unstated, dict(ldr, effect="shadows"), dict(ldr, flip=None)]
        self.assertEqual(study.drawn_anchors(anchors, "reflections", "LDR"), [ldr])
        self.assertEqual(study.drawn_anchors(anchors, "reflections", "HDR"), [hdr])

    def test_anchors_are_drawn_only_on_their_device_and_size(self):
        anchor = {"device": "NVIDIA H200", "width": 1920, "height": 1080}
        def run(name, width, height):
            return {"device": {"name": name}, "width": width, "height": height}
        self.assertTrue(study.comparable_anchor(anchor, run("NVIDIA H200", 1920, 1080)))
        self.assertFalse(study.comparable_anchor(anchor, run("llvmpipe (LLVM 15.0.6, 256 bits)", 1920, 1080)))
        self.assertFalse(study.comparable_anchor(anchor, run("NVIDIA H200", 640, 360)))


if __name__ == "__main__":
    unittest.main()
