#!/usr/bin/env python3
"""Value tests of scripts/run_flip.py (LDR-FLIP per frame of a `glint run` folder): run folders
written here with known images, the FLIP values and summary.json fields checked.

    build/venv/bin/python tests/cli/run_flip_test.py -v
"""
import json
import pathlib
import struct
import sys
import tempfile
import unittest
import zlib

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import run_flip  # noqa: E402
import study  # noqa: E402

WIDTH, HEIGHT = 48, 40


def write_exr(path, image, zip_compression=True):
    """A scanline OpenEXR file of FLOAT channels as glint writes it: an H x W x 3 image as R, G, B,
    an H x W (or H x W x 1) one as Y; ZIP (16 lines a block) or no compression."""
    image = np.asarray(image, dtype=np.float32)
    if image.ndim == 2:
        image = image[..., None]
    height, width, count = image.shape
    names = ["R", "G", "B"] if count == 3 else ["Y"]
    order = sorted(range(count), key=lambda c: names[c])  # channels are stored by name

    def attribute(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value

    chlist = b"".join(names[c].encode() + b"\0" + struct.pack("<iB3xii", 2, 0, 1, 1) for c in order) + b"\0"
    header = (b"\x76\x2f\x31\x01" + struct.pack("<i", 2)
              + attribute("channels", "chlist", chlist)
              + attribute("compression", "compression", bytes([3 if zip_compression else 0]))
              + attribute("dataWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1))
              + attribute("displayWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1))
              + attribute("lineOrder", "lineOrder", b"\0")
              + attribute("pixelAspectRatio", "float", struct.pack("<f", 1.0))
              + attribute("screenWindowCenter", "v2f", struct.pack("<2f", 0.0, 0.0))
              + attribute("screenWindowWidth", "float", struct.pack("<f", 1.0)) + b"\0")
    lines = 16 if zip_compression else 1
    chunks = []
    for y in range(0, height, lines):
        raw = b"".join(image[row, :, c].astype("<f4").tobytes() for row in range(y, min(y + lines, height))
                       for c in order)
        if zip_compression:  # OpenEXR's ZIP: halves of even and odd bytes, delta-coded, deflated
            data = np.frombuffer(raw, dtype=np.uint8)
            split = np.concatenate([data[0::2], data[1::2]]).astype(np.int64)
            coded = split.copy()
            coded[1:] = (split[1:] - split[:-1] + 128) & 0xFF
            packed = zlib.compress(coded.astype(np.uint8).tobytes())
            raw = packed if len(packed) < len(raw) else raw
        chunks.append(struct.pack("<ii", y, len(raw)) + raw)
    offsets, at = [], len(header) + 8 * len(chunks)
    for chunk in chunks:
        offsets.append(at)
        at += len(chunk)
    pathlib.Path(path).write_bytes(header + struct.pack(f"<{len(chunks)}Q", *offsets) + b"".join(chunks))


def square_mask():
    mask = np.zeros((HEIGHT, WIDTH), dtype=np.float32)
    mask[10:30, 12:36] = 1.0
    return mask


def radiance(seed, scale=1.0):
    """A smooth-ish HDR radiance image (0 to about 4)."""
    rng = np.random.default_rng(seed)
    return (scale * rng.uniform(0.0, 4.0, (HEIGHT, WIDTH, 3))).astype(np.float32)


class RunFolder:
    """A run folder as glint run writes it: summary.json and one folder per frame."""

    def __init__(self, root):
        self.root = pathlib.Path(root)
        self.frames = []

    def frame(self, effect, reference, output=None, noisy=None, mask=None, reference2=None, denoised=True):
        index = len(self.frames)
        folder = self.root / f"frame_{index:04d}"
        folder.mkdir(parents=True, exist_ok=True)
        write_exr(folder / f"{effect}_reference.exr", reference)
        write_exr(folder / f"{effect}_mask.exr", square_mask() if mask is None else mask)
        if denoised:
            write_exr(folder / f"{effect}_denoised.exr", reference if output is None else output)
        if noisy is not None:
            write_exr(folder / f"{effect}_noisy.exr", noisy)
        record = {"frame": index, "number": index, "folder": folder.name, "images": [],
                  "errors": {effect: {"image": f"{effect}/{'denoised' if denoised else 'noisy'}", "mean": 0.5}}}
        if reference2 is not None:
            write_exr(folder / f"{effect}_reference2.exr", reference2)
            record["referenceNoise"] = {effect: {"mean": 0.1}}
        self.frames.append(record)
        return folder

    def write(self):
        errors = {}
        for record in self.frames:
            for effect in record["errors"]:
                errors[effect] = {"first": 0.5, "last": 0.5, "noisyLast": -1.0}
        summary = {"capture": "test", "effects": sorted(errors), "frames": self.frames, "error": errors}
        (self.root / "summary.json").write_text(json.dumps(summary, indent=2))
        return self.root

    def summary(self):
        return json.loads((self.root / "summary.json").read_text())


class ExrReading(unittest.TestCase):
    def test_reads_what_flip_evaluator_reads(self):
        import flip_evaluator as flip

        image = radiance(1)
        with tempfile.TemporaryDirectory() as tmp:
            for zipped in (True, False):
                path = pathlib.Path(tmp) / f"image_{zipped}.exr"
                write_exr(path, image, zip_compression=zipped)
                np.testing.assert_array_equal(np.asarray(flip.load(str(path)))[..., :3], image)
                np.testing.assert_array_equal(run_flip.read_exr(path)[..., ::-1], image)  # stored B, G, R
                np.testing.assert_array_equal(run_flip.load(path), image)

    def test_one_channel_images_are_repeated_as_grey(self):
        grey = np.linspace(0.0, 1.0, WIDTH * HEIGHT, dtype=np.float32).reshape(HEIGHT, WIDTH)
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / "visibility.exr"
            write_exr(path, grey)
            image = run_flip.load(path)
            self.assertEqual(image.shape, (HEIGHT, WIDTH, 3))
            for c in range(3):
                np.testing.assert_array_equal(image[..., c], grey)

    def test_non_finite_values_read_as_zero(self):
        image = radiance(2)
        image[5, 5, 0] = np.nan
        image[6, 6, 1] = np.inf
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / "bad.exr"
            write_exr(path, image[..., 0])  # one channel: read here, not by flip-evaluator
            loaded = run_flip.load(path)
            self.assertTrue(np.isfinite(loaded).all())
            self.assertEqual(loaded[5, 5, 0], 0.0)


class RunFlip(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.addCleanup(self.tmp.cleanup)
        self.run = RunFolder(pathlib.Path(self.tmp.name) / "run")

    def test_identical_output_and_reference_score_zero(self):
        reference = radiance(3)
        self.run.frame("reflections", reference, output=reference.copy(), noisy=reference.copy())
        run_flip.add_flips([self.run.write()], workers=1)
        error = self.run.summary()["frames"][0]["errors"]["reflections"]
        self.assertEqual(error["flip"], 0.0)
        self.assertEqual(error["noisyFlip"], 0.0)

    def test_brighter_output_scores_above_zero_and_noisier_more(self):
        reference = radiance(4, 0.5)
        self.run.frame("reflections", reference, output=reference * 1.5, noisy=reference * 4.0)
        run_flip.add_flips([self.run.write()], workers=1)
        error = self.run.summary()["frames"][0]["errors"]["reflections"]
        self.assertGreater(error["flip"], 0.0)
        self.assertGreater(error["noisyFlip"], error["flip"])

    def test_the_value_is_study_pys_ldr_flip_over_the_mask(self):
        reference, output = radiance(5), radiance(6)
        mask = square_mask() > 0.5
        self.run.frame("reflections", reference, output=output)
        run_flip.add_flips([self.run.write()], workers=1)
        expected = study.masked_flip(study.ldr_image("reflections", reference) * mask[..., None],
                                     study.ldr_image("reflections", output) * mask[..., None], mask)
        self.assertAlmostEqual(self.run.summary()["frames"][0]["errors"]["reflections"]["flip"], expected, places=6)

    def test_differences_outside_the_mask_do_not_count(self):
        reference = radiance(7)
        output = reference.copy()
        output[square_mask() < 0.5] += 3.0
        self.run.frame("reflections", reference, output=output)
        run_flip.add_flips([self.run.write()], workers=1)
        self.assertEqual(self.run.summary()["frames"][0]["errors"]["reflections"]["flip"], 0.0)

    def test_an_empty_mask_scores_none(self):
        reference = radiance(8)
        self.run.frame("reflections", reference, output=reference * 2, noisy=reference * 3,
                       mask=np.zeros((HEIGHT, WIDTH)), reference2=reference * 0.5)
        run_flip.add_flips([self.run.write()], workers=1)
        summary = self.run.summary()
        self.assertIsNone(summary["frames"][0]["errors"]["reflections"]["flip"])
        self.assertIsNone(summary["frames"][0]["errors"]["reflections"]["noisyFlip"])
        self.assertIsNone(summary["frames"][0]["referenceNoise"]["reflections"]["flip"])
        self.assertIsNone(summary["error"]["reflections"]["flipLast"])
        self.assertIn('"flipLast": null', (self.run.root / "summary.json").read_text())

    def test_shadow_visibility_of_one_channel(self):
        visibility = np.full((HEIGHT, WIDTH), 0.5, dtype=np.float32)
        noisy = (np.random.default_rng(9).uniform(size=(HEIGHT, WIDTH)) < 0.5).astype(np.float32)
        self.run.frame("shadows", visibility, output=visibility.copy(), noisy=noisy)
        run_flip.add_flips([self.run.write()], workers=1)
        error = self.run.summary()["frames"][0]["errors"]["shadows"]
        self.assertEqual(error["flip"], 0.0)
        self.assertGreater(error["noisyFlip"], 0.05)

    def test_summary_fields(self):
        reference = radiance(10)
        self.run.frame("reflections", reference, output=reference * 1.2, noisy=reference * 2, reference2=reference)
        self.run.frame("reflections", reference, output=reference * 1.1, noisy=reference * 2,
                       reference2=reference * 1.3)
        run_flip.add_flips([self.run.write()], workers=1)
        summary = self.run.summary()
        self.assertEqual(summary["flip"]["clamp"], study.RADIANCE_CLAMP)
        self.assertIn("LDR-FLIP", summary["flip"]["metric"])
        self.assertIn("Reinhard", summary["flip"]["metric"])
        first, last = (f["errors"]["reflections"] for f in summary["frames"][:2])
        for error in (first, last):
            self.assertGreater(error["flip"], 0.0)
            self.assertGreater(error["noisyFlip"], error["flip"])
        self.assertEqual(summary["frames"][0]["referenceNoise"]["reflections"]["flip"], 0.0)
        self.assertGreater(summary["frames"][1]["referenceNoise"]["reflections"]["flip"], 0.0)
        self.assertEqual(summary["frames"][0]["referenceNoise"]["reflections"]["mean"], 0.1)  # kept
        totals = summary["error"]["reflections"]
        self.assertEqual(totals["flipLast"], last["flip"])
        self.assertEqual(totals["noisyFlipLast"], last["noisyFlip"])
        self.assertEqual(totals["referenceNoiseFlipLast"], summary["frames"][1]["referenceNoise"]["reflections"]["flip"])

    def test_an_output_that_is_not_denoised_has_no_noisy_flip(self):
        self.run.frame("shadows", np.full((HEIGHT, WIDTH), 0.25), noisy=np.ones((HEIGHT, WIDTH)), denoised=False)
        run_flip.add_flips([self.run.write()], workers=1)
        summary = self.run.summary()
        shadows = summary["frames"][0]["errors"]["shadows"]
        self.assertGreater(shadows["flip"], 0.0)
        self.assertNotIn("noisyFlip", shadows)
        self.assertEqual(summary["error"]["shadows"]["flipLast"], shadows["flip"])
        self.assertNotIn("noisyFlipLast", summary["error"]["shadows"])

    def test_idempotent(self):
        reference = radiance(11)
        self.run.frame("reflections", reference, output=reference * 1.2, noisy=reference * 2, reference2=reference)
        run = self.run.write()
        run_flip.add_flips([run], workers=1)
        once = (run / "summary.json").read_bytes()
        modified = (run / "summary.json").stat().st_mtime_ns
        run_flip.add_flips([run], workers=1)
        self.assertEqual((run / "summary.json").read_bytes(), once)
        self.assertEqual((run / "summary.json").stat().st_mtime_ns, modified)  # nothing to compute or write

    def test_values_of_another_metric_are_computed_again(self):
        reference = radiance(12)
        self.run.frame("reflections", reference, output=reference.copy())
        run = self.run.write()
        summary = self.run.summary()
        summary["frames"][0]["errors"]["reflections"]["flip"] = 123.0
        summary["flip"] = {"metric": "another metric", "clamp": 16}
        (run / "summary.json").write_text(json.dumps(summary))
        run_flip.add_flips([run], workers=1)
        self.assertEqual(self.run.summary()["frames"][0]["errors"]["reflections"]["flip"], 0.0)

    def test_frames_scored_in_processes_equal_those_scored_here(self):
        other = RunFolder(pathlib.Path(self.tmp.name) / "other")
        for folder in (self.run, other):
            for seed in range(3):
                reference = radiance(20 + seed)
                folder.frame("reflections", reference, output=radiance(30 + seed), noisy=radiance(40 + seed))
            folder.write()
        run_flip.add_flips([self.run.root], workers=1)
        run_flip.add_flips([other.root], workers=2)
        self.assertEqual(self.run.summary()["frames"], other.summary()["frames"])

    def test_a_missing_mask_is_named(self):
        reference = radiance(13)
        folder = self.run.frame("reflections", reference)
        (folder / "reflections_mask.exr").unlink()
        with self.assertRaisesRegex(FileNotFoundError, "reflections_mask.exr is missing"):
            run_flip.add_flips([self.run.write()], workers=1)


if __name__ == "__main__":
    unittest.main()
