#!/usr/bin/env python3
"""LDR-FLIP per frame for the folders `glint run` wrote (docs/replay.md, "FLIP of a run").

    python3 scripts/run_flip.py RUN_DIR [MORE_RUN_DIRS...]

For every frame of RUN_DIR/summary.json and every effect scored there (errors.<effect>), the
metric is scripts/study.py's LDR-FLIP: flip-evaluator given linear values, of radiance clamped
to [0, 16] and tone-mapped per channel with Reinhard x/(1+x), of shadow visibility clamped to
[0, 1]; both images are zeroed outside the frame's error mask (<effect>_mask.exr, which glint run
writes) and FLIP is averaged over the mask's pixels. It adds to summary.json:

    frames[i].errors.<effect>.flip           the output's (the image errors.<effect>.image names)
    frames[i].errors.<effect>.noisyFlip      its noisy input's, where the output is denoised
    frames[i].referenceNoise.<effect>.flip   the reference against the second reference
                                             (<effect>_reference2.exr, glint run --second-reference)
    error.<effect>.flipLast, noisyFlipLast, referenceNoiseFlipLast   the last frame's
    flip: {"metric": words, "clamp": 16}

null where the mask holds no pixel. Values already there for the same metric are kept, so a
second call changes nothing; `glint run` rewrites summary.json without them. The frames are
scored in parallel, one process per CPU. Needs numpy and flip-evaluator (scripts/python_env.sh
makes build/venv with them).
"""
import json
import pathlib
import struct
import sys
import zlib

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import study  # noqa: E402  (scripts/study.py: the metric's definition)


def metric(clamp):
    """What `flip` means in summary.json: study.py's LDR-FLIP, over the error mask."""
    return (study.flip_metric(clamp) + "; both images zeroed outside the error mask (<effect>_mask.exr) "
            "and FLIP averaged over the mask's pixels")


# OpenEXR scanline files as glint writes them (report_image.cpp: FLOAT channels, ZIP). flip-evaluator
# reads only RGB(A) EXR and ends the process on any other, and glint writes shadow visibility and
# the masks as one channel (Y), so those are read here.
EXR_MAGIC = b"\x76\x2f\x31\x01"
EXR_TYPES = {0: np.dtype("<u4"), 1: np.dtype("<f2"), 2: np.dtype("<f4")}  # UINT, HALF, FLOAT
EXR_LINES_PER_BLOCK = {0: 1, 2: 1, 3: 16}  # NO_COMPRESSION, ZIPS_COMPRESSION, ZIP_COMPRESSION


def exr_header(data, path):
    """(channels [(name, numpy type)] in file order, compression, data window) of an EXR file's
    bytes, and the position just after its header."""
    if data[:4] != EXR_MAGIC:
        raise ValueError(f"{path}: not an OpenEXR file")
    if data[5] & 0x1A:  # the version's flags: tiled (bit 9), deep (11), multi-part (12); long names are fine
        raise ValueError(f"{path}: a tiled, deep or multi-part OpenEXR file (glint writes single-part scanlines)")
    position, channels, compression, window = 8, [], None, None
    while data[position] != 0:
        name_end = data.index(b"\0", position)
        type_end = data.index(b"\0", name_end + 1)
        name = data[position:name_end].decode()
        (size,) = struct.unpack_from("<i", data, type_end + 1)
        value = data[type_end + 5:type_end + 5 + size]
        position = type_end + 5 + size
        if name == "channels":
            at = 0
            while value[at] != 0:
                end = value.index(b"\0", at)
                pixel_type, _, x_sampling, y_sampling = struct.unpack_from("<iB3xii", value, end + 1)
                if pixel_type not in EXR_TYPES or (x_sampling, y_sampling) != (1, 1):
                    raise ValueError(f"{path}: channel {value[at:end].decode()} is of a type or sampling "
                                     f"run_flip.py does not read")
                channels.append((value[at:end].decode(), EXR_TYPES[pixel_type]))
                at = end + 17
        elif name == "compression":
            compression = value[0]
        elif name == "dataWindow":
            window = struct.unpack("<4i", value)
    if compression not in EXR_LINES_PER_BLOCK:
        raise ValueError(f"{path}: OpenEXR compression {compression} (run_flip.py reads none, ZIPS and ZIP)")
    if not channels or window is None:
        raise ValueError(f"{path}: no channels or no data window")
    return channels, compression, window, position + 1


def unzip_block(block):
    """OpenEXR's ZIP block: deflate, over bytes delta-coded and split into even and odd halves."""
    coded = np.frombuffer(zlib.decompress(block), dtype=np.uint8).astype(np.int64)
    coded[1:] -= 128
    interleaved = (np.cumsum(coded) & 0xFF).astype(np.uint8)
    raw = np.empty_like(interleaved)
    half = (len(raw) + 1) // 2
    raw[0::2], raw[1::2] = interleaved[:half], interleaved[half:]
    return raw.tobytes()


def read_exr(path, data=None):
    """The channels of a scanline OpenEXR file (its bytes `data`, else read from path) as float32,
    height x width x channels (in the file's channel order, which is by name)."""
    data = pathlib.Path(path).read_bytes() if data is None else data
    channels, compression, (x0, y0, x1, y1), position = exr_header(data, path)
    width, height = x1 - x0 + 1, y1 - y0 + 1
    lines_per_block = EXR_LINES_PER_BLOCK[compression]
    blocks = -(-height // lines_per_block)
    offsets = struct.unpack_from(f"<{blocks}Q", data, position)
    line_bytes = width * sum(kind.itemsize for _, kind in channels)
    image = np.zeros((height, width, len(channels)), dtype=np.float32)
    for offset in offsets:
        y, size = struct.unpack_from("<ii", data, offset)
        lines = min(lines_per_block, y1 + 1 - y)
        block = data[offset + 8:offset + 8 + size]
        if size < lines * line_bytes:  # stored as is where compressing would not shrink it
            block = unzip_block(block)
        at = 0
        for line in range(y - y0, y - y0 + lines):
            for c, (_, kind) in enumerate(channels):
                image[line, :, c] = np.frombuffer(block, dtype=kind, count=width, offset=at)
                at += width * kind.itemsize
    return image


def load(path):
    """An image glint run wrote as RGB float32 (one channel repeated), non-finite values 0:
    study.load_rgb (flip-evaluator's reader) for RGB(A), read_exr for fewer channels."""
    path = pathlib.Path(path)
    if not path.exists():
        raise FileNotFoundError(f"{path} is missing")
    data = path.read_bytes()
    if not data.startswith(EXR_MAGIC) or len(exr_header(data, path)[0]) >= 3:
        return study.load_rgb(path)
    image = read_exr(path, data)
    image = np.repeat(image[..., :1], 3, axis=2) if image.shape[2] == 1 else \
        np.concatenate([image, image[..., -1:]], axis=2)  # two channels: X, Y, Y
    return np.nan_to_num(image, nan=0.0, posinf=0.0, neginf=0.0)


def frame_flips(folder, effect, images, clamp=study.RADIANCE_CLAMP):
    """{key: FLIP of folder/<file> against folder/<effect>_reference.exr} for images {key: file},
    over folder/<effect>_mask.exr; every value None where the mask holds no pixel."""
    folder = pathlib.Path(folder)
    mask = load(folder / f"{effect}_mask.exr")[..., 0] > 0.5
    if not mask.any():
        return {key: None for key in images}

    def ldr(name):  # zero outside the mask, as study.py's images are
        return study.ldr_image(effect, load(folder / name), clamp) * mask[..., None]

    reference = ldr(f"{effect}_reference.exr")
    return {key: study.masked_flip(reference, ldr(name), mask) for key, name in images.items()}


def frame_images(folder, effect, error):
    """{summary key: image file} to score for one frame's errors.<effect>: the output's `flip`, the
    noisy input's `noisyFlip` where the output is denoised, the second reference's `floor`."""
    output = error.get("image") or (f"{effect}/denoised" if (folder / f"{effect}_denoised.exr").exists()
                                    else f"{effect}/noisy")
    images = {"flip": output.replace("/", "_") + ".exr"}
    if output != f"{effect}/noisy" and (folder / f"{effect}_noisy.exr").exists():
        images["noisyFlip"] = f"{effect}_noisy.exr"
    if (folder / f"{effect}_reference2.exr").exists():
        images["floor"] = f"{effect}_reference2.exr"
    return images


def forget(summary):
    """Drops every FLIP value of summary (computed for another metric)."""
    for record in summary.get("frames", []):
        for error in record.get("errors", {}).values():
            error.pop("flip", None)
            error.pop("noisyFlip", None)
        for noise in record.get("referenceNoise", {}).values():
            noise.pop("flip", None)
    for error in summary.get("error", {}).values():
        for key in ("flipLast", "noisyFlipLast", "referenceNoiseFlipLast"):
            error.pop(key, None)
    summary.pop("flip", None)


def plan(run, summary):
    """The (frame folder, effect, images) still to score in one run, and where each result goes."""
    jobs = []
    for record in summary.get("frames", []):
        folder = run / record.get("folder", f"frame_{record['frame']:04d}")
        for effect, error in record.get("errors", {}).items():
            images = frame_images(folder, effect, error)
            noise = record.get("referenceNoise", {}).get(effect, {})
            done = {"flip": "flip" in error, "noisyFlip": "noisyFlip" in error, "floor": "flip" in noise}
            images = {key: name for key, name in images.items() if not done[key]}
            if images:
                jobs.append((record, effect, folder, images))
    return jobs


def store(record, effect, values):
    error = record["errors"][effect]
    for key in ("flip", "noisyFlip"):
        if key in values:
            error[key] = values[key]
    if "floor" in values:
        record.setdefault("referenceNoise", {}).setdefault(effect, {})["flip"] = values["floor"]


def summarize(summary, clamp):
    """error.<effect>.flipLast (noisyFlipLast, referenceNoiseFlipLast) from the last frame, and the
    metric's name."""
    frames = summary.get("frames", [])
    if frames:
        last = frames[-1]
        for effect, error in last.get("errors", {}).items():
            totals = summary.setdefault("error", {}).setdefault(effect, {})
            for key, last_key in (("flip", "flipLast"), ("noisyFlip", "noisyFlipLast")):
                if key in error:
                    totals[last_key] = error[key]
            noise = last.get("referenceNoise", {}).get(effect, {})
            if "flip" in noise:
                totals["referenceNoiseFlipLast"] = noise["flip"]
    summary["flip"] = {"metric": metric(clamp), "clamp": clamp}


def add_flips(runs, workers=None, clamp=study.RADIANCE_CLAMP):
    """Adds the FLIP values to every run's summary.json (the module's comment says which) and
    returns the summaries. `workers` 1 scores in this process; None, one process per CPU."""
    runs = [pathlib.Path(run) for run in runs]
    summaries, jobs = [], []
    for run in runs:
        path = run / "summary.json"
        if not path.exists():
            raise FileNotFoundError(f"{path} is missing (run glint run first)")
        summary = json.loads(path.read_text())
        if summary.get("flip", {}).get("metric") != metric(clamp):
            forget(summary)
        summaries.append(summary)
        jobs += plan(run, summary)
    for _, effect, folder, _ in jobs:  # every missing file named before any work
        if not (folder / f"{effect}_mask.exr").exists():
            raise FileNotFoundError(f"{folder / (effect + '_mask.exr')} is missing: glint run writes the error "
                                    f"mask since run_flip.py exists; run glint run again")
    results = study.parallel_map(frame_flips, [(folder, effect, images, clamp)
                                               for _, effect, folder, images in jobs], workers)
    for (record, effect, _, _), values in zip(jobs, results):
        store(record, effect, values)
    for run, summary in zip(runs, summaries):
        before = (run / "summary.json").read_text()
        summarize(summary, clamp)
        after = json.dumps(summary, indent=2, sort_keys=True, allow_nan=False) + "\n"
        if after != before:
            (run / "summary.json").write_text(after)
    return summaries


def shown(value):
    return "no pixels scored" if value is None else f"{value:.4f}"


def report_line(run, summary):
    """One line per run: the last frame's FLIP per effect."""
    parts = []
    for effect, error in sorted(summary.get("error", {}).items()):
        if "flipLast" not in error:
            continue
        text = f"{effect} {shown(error['flipLast'])}"
        extra = [f"noisy input {shown(error['noisyFlipLast'])}"] if "noisyFlipLast" in error else []
        if "referenceNoiseFlipLast" in error:
            extra.append(f"reference noise floor {shown(error['referenceNoiseFlipLast'])}")
        parts.append(text + (f" ({', '.join(extra)})" if extra else ""))
    frames = len(summary.get("frames", []))
    return f"{run}: LDR-FLIP of {frames} frame(s); last frame: {'; '.join(parts) or 'nothing scored'}"


def main(runs):
    try:
        summaries = add_flips(runs)
    except (FileNotFoundError, ValueError) as error:
        sys.exit(f"run_flip.py: {error}")
    for run, summary in zip(runs, summaries):
        print(report_line(run, summary))


if __name__ == "__main__":
    arguments = sys.argv[1:]
    if not arguments or any(a.startswith("-") for a in arguments):
        sys.exit("usage: run_flip.py RUN_DIR [MORE_RUN_DIRS...] (folders written by glint run --out RUN_DIR)")
    main(arguments)
