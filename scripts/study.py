#!/usr/bin/env python3
"""FLIP, Pareto fronts, plots and tables for a `glint study` folder (docs/accuracy-vs-time.md).

    python3 scripts/study.py DIR [MORE_DIRS...]

DIR is what `glint study --out DIR` (and `glint study --scaling --out DIR`) wrote, on this
machine or another: the image paths inside study.json are relative to DIR. Studies split over
several runs (e.g. one per effect) are combined by naming every folder; the results go to the
first. Adds the columns `flip` and `pareto` to each folder's study.csv and writes
DIR/<effect>.png (error against time, one colour per scene, each scene's Pareto front
connected), DIR/scaling_resolution.png and DIR/scaling_fraction.png (from the first folder
with a scaling.json) and DIR/study.md (the tables, with the presets and the budget choice
glint study made).

FLIP is NVIDIA's perceptual difference (flip-evaluator): HDR-FLIP for reflection radiance,
LDR-FLIP for shadow visibility shown as a grey image. The images are zeroed outside the pixels
the error is measured over (mask.exr), and FLIP is averaged over those pixels only.
"""
import csv
import json
import pathlib
import sys

import numpy as np

# Measured points of other implementations (docs/anchors/*.json), drawn beside the fronts.
ANCHORS = pathlib.Path(__file__).resolve().parents[1] / "docs" / "anchors"


def pyplot():
    """matplotlib only where plots are drawn: --flip-only runs where it is not installed."""
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    return plt


def load_rgb(path):
    import flip_evaluator as flip

    image = np.asarray(flip.load(str(path)), dtype=np.float32)[..., :3]
    return np.nan_to_num(image, nan=0.0, posinf=0.0, neginf=0.0)  # non-finite is reported apart


def mean_flip(directory, row):
    import flip_evaluator as flip

    reference = load_rgb(directory / row["reference"])
    output = load_rgb(directory / row["output"])
    mask = load_rgb(directory / row["mask"])[..., 0] > 0.5
    if row["effect"] != "shadows":  # reflections and hybrid are HDR radiance
        error, _, _ = flip.evaluate(np.maximum(reference, 0), np.maximum(output, 0), "HDR", applyMagma=False)
    else:
        error, _, _ = flip.evaluate(np.clip(reference, 0, 1), np.clip(output, 0, 1), "LDR", applyMagma=False)
    error = np.asarray(error).reshape(mask.shape)
    return float(error[mask].mean()) if mask.any() else None  # None: no pixel scored


def mark_pareto(rows):
    """pareto = 1 where no other point of the same scene and effect is as fast and as accurate.
    A point without a FLIP (no pixel scored) is on no front and competes with none."""
    scored = [r for r in rows if r["flip"] is not None]
    for row in rows:
        if row["flip"] is None:
            row["pareto"] = 0
            continue
        rivals = [r for r in scored if (r["scene"], r["effect"]) == (row["scene"], row["effect"]) and r is not row]
        row["pareto"] = int(not any(
            r["time_us"] <= row["time_us"] and r["flip"] <= row["flip"]
            and (r["time_us"] < row["time_us"] or r["flip"] < row["flip"]) for r in rivals))


def load_anchors(folder=ANCHORS):
    """Every point of every docs/anchors/*.json, with the file it came from."""
    points = []
    for file in sorted(pathlib.Path(folder).glob("*.json")):
        for point in json.loads(file.read_text())["points"]:
            points.append(dict(point, source=file.name))
    return points


def comparable_anchor(anchor, study):
    """An anchor's time is comparable when it was measured on this study's device and size."""
    return (anchor["device"] in study["device"]["name"]
            and (anchor["width"], anchor["height"]) == (study["width"], study["height"]))


def plot_effect(rows, effect, title, path, anchors=()):
    plt = pyplot()
    figure, axes = plt.subplots(figsize=(8, 5.5))
    scenes = sorted({r["scene"] for r in rows if r["effect"] == effect})
    for colour, scene in zip(plt.cm.tab10.colors, scenes):
        points = sorted((r for r in rows if (r["effect"], r["scene"]) == (effect, scene) and r["flip"] is not None),
                        key=lambda r: r["time_us"])
        axes.scatter([p["time_us"] for p in points], [p["flip"] for p in points], color=colour, label=scene)
        front = [p for p in points if p["pareto"]]
        axes.plot([p["time_us"] for p in front], [p["flip"] for p in front], color=colour, linewidth=1)
        for p in points:
            axes.annotate(p["label"], (p["time_us"], p["flip"]), fontsize=6, xytext=(3, 2), textcoords="offset points")
    drawn = [a for a in anchors if a["effect"] == effect and a.get("flip") is not None]
    for a in drawn:
        axes.scatter([a["time_us"]], [a["flip"]], marker="*", s=90, color="black")
        axes.annotate(f"{a['label']} ({a['scene']})", (a["time_us"], a["flip"]), fontsize=6, xytext=(-4, -9),
                      textcoords="offset points", ha="right")
    if drawn:  # where and when: the time and the error of an anchor come from different runs
        sources = ", ".join(sorted({a["source"] for a in drawn}))
        figure.text(0.01, 0.005, f"★ measured points of other implementations; their time and error conditions "
                    f"are in study.md and docs/anchors/{sources}", fontsize=6)
    axes.set(xlabel="GPU time of the effect (µs, median)", ylabel="mean FLIP over the measured pixels",
             title=f"{effect}: {title}")
    axes.legend(fontsize=8)
    axes.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(path, dpi=130)
    plt.close(figure)


def plot_scaling(rows, sweep, x_of, xlabel, title, path):
    plt = pyplot()
    """One panel per effect: every pass and the total, so that it shows which passes follow the work."""
    effects = sorted({r["effect"] for r in rows})
    figure, panels = plt.subplots(1, len(effects), figsize=(6 * len(effects), 4.5), squeeze=False)
    for axes, effect in zip(panels[0], effects):
        points = sorted((r for r in rows if (r["effect"], r["sweep"]) == (effect, sweep)), key=x_of)
        xs = [x_of(p) for p in points]
        axes.plot(xs, [p["time_us"] for p in points], marker="o", linewidth=2.5, color="black", label="total")
        for name in [p["pass"] for p in points[0]["passes"]]:
            times = [next((q["medianUs"] for q in p["passes"] if q["pass"] == name), 0.0) for p in points]
            axes.plot(xs, times, marker=".", linewidth=1, label=name.split("/")[-1])
        axes.set(xlabel=xlabel.get(effect, "") if isinstance(xlabel, dict) else xlabel,
                 ylabel="GPU time (µs, median)", title=effect)
        axes.set_ylim(bottom=0)
        axes.legend(fontsize=7)
        axes.grid(alpha=0.3)
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(path, dpi=130)
    plt.close(figure)


def scored(value, form="{:.4f}"):
    """A metric, or "no pixels scored" where no pixel was scored (never a number for nothing)."""
    return "no pixels scored" if value is None else form.format(value)


def study_tables(rows):
    lines = []
    for effect in sorted({r["effect"] for r in rows}):
        shadows = effect == "shadows"  # the penumbra error is where a shadow denoiser shows
        hybrid = effect == "hybrid"  # its cost follows the fraction of rays it ray traces
        lines += [f"### {effect}", "",
                  "| scene | point | settings | time (µs) |" + (" RT rays |" if hybrid else "")
                  + " FLIP | mean error | RMSE |" + (" penumbra |" if shadows else "") + " non-finite | Pareto |",
                  "|---|---|---|---|" + ("---|" if hybrid else "") + "---|---|---|" + ("---|" if shadows else "")
                  + "---|---|"]
        for r in (r for r in rows if r["effect"] == effect):
            penumbra = f" {r['penumbra']:.4f} |" if shadows else ""
            fraction = r.get("traced_fraction", "")  # the share of rays ray traced
            traced = (f" {100 * float(fraction):.1f} % |" if fraction != "" else " - |") if hybrid else ""
            lines.append(f"| {r['scene']} | {r['label']} | `{' '.join(r['settings']) or '-'}` | {r['time_us']:.1f} |"
                         f"{traced} {scored(r['flip'])} | {r['error_mean']:.4f} | {r['rmse']:.4f} |{penumbra} "
                         f"{r['non_finite']:g} | {'**yes**' if r['pareto'] else ''} |")
        lines.append("")
    return lines


def anchor_tables(anchors):
    lines = ["### anchors (docs/anchors)", "",
             "Drawn on the plots only when the study ran on the device and at the size of the point's time.", "",
             "| effect | scene | point | time (µs) | time measured | FLIP | MAE | error measured |",
             "|---|---|---|---|---|---|---|---|"]
    for a in anchors:
        lines.append(f"| {a['effect']} | {a['scene']} | {a['label']} | {a['time_us']:.1f} | {a['time_measured']} "
                     f"| {scored(a.get('flip'))} | {scored(a.get('mae'))} | {a['error_measured']} |")
    return lines + [""]


def choice_tables(study):
    """The presets and the budget choice glint study made from its points (study.json's
    "presets" and "budget"; the rule is cli_presets.h's, docs/accuracy-vs-time.md "Presets")."""
    presets = study.get("presets", {})
    if not presets:
        return []
    lines = ["### presets (presets.toml)", "",
             "Each point's time on its slowest scene and its mean error relative to the defaults point's.", "",
             "| effect | preset | point | settings | time (µs) | error (× defaults) |", "|---|---|---|---|---|---|"]
    order = ["low", "medium", "high", "ultra"]  # study.json's objects come back sorted by name
    for effect, chosen in presets.items():
        for name, p in sorted(chosen.items(), key=lambda item: order.index(item[0]) if item[0] in order else 4):
            lines.append(f"| {effect} | {name} | {p['point']} | `{' '.join(p['settings']) or '-'}` | "
                         f"{p['time_us']:.1f} | {scored(p['error'])} |")
    lines.append("")
    budget = study.get("budget")
    if budget:
        lines += [f"### budget {budget['budget_us']:g} µs", ""]
        for effect, p in budget["choices"].items():
            lines.append(f"- {effect}: no measured point fits" if p is None else
                         f"- {effect}: {p['point']} (`{' '.join(p['settings']) or '-'}`), {p['time_us']:.1f} µs, "
                         f"error {scored(p['error'])} × the defaults'")
        lines.append("")
    return lines


def scaling_tables(rows):
    lines = ["| effect | sweep | size | fraction | time (µs) | traced fraction / filtered tiles |", "|---|---|---|---|---|---|"]
    for r in rows:
        counters = r.get("counters", {})
        work = counters.get("reflections/traced_fraction", counters.get("shadows/filtered_tiles", ""))
        fraction = "scene" if r["fraction"] < 0 else f"{100 * r['fraction']:.0f} %"
        lines.append(f"| {r['effect']} | {r['sweep']} | {r['width']}×{r['height']} | {fraction} "
                     f"| {r['time_us']:.1f} | {work if work == '' else f'{work:.4g}'} |")
    return lines + [""]


def add_columns(directory, rows):
    """study.csv keeps the C++ columns (same rows, same order) and gains flip and pareto."""
    with open(directory / "study.csv", newline="") as file:
        table = list(csv.DictReader(file))
    for line, row in zip(table, rows, strict=True):
        line["flip"], line["pareto"] = scored(row["flip"], "{:.6g}"), row["pareto"]
    with open(directory / "study.csv", "w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=list(table[0].keys()))
        writer.writeheader()
        writer.writerows(table)


def main(directories, plots=True):
    directories = [pathlib.Path(d) for d in directories]
    out = directories[0]
    studies = [json.loads((d / "study.json").read_text()) for d in directories]
    rows = []
    for directory, study in zip(directories, studies):
        for row in study["rows"]:
            if "flip" not in row:  # kept in study.json, so that plots need no images
                row["flip"] = mean_flip(directory, row)
        (directory / "study.json").write_text(json.dumps(study, indent=1))
        rows += study["rows"]
    mark_pareto(rows)
    for directory, study in zip(directories, studies):
        add_columns(directory, study["rows"])

    study = studies[0]
    device = study["device"]["name"]
    if any(s["device"]["name"] != device or (s["width"], s["height"]) != (study["width"], study["height"])
           for s in studies):
        print("study.py: warning: the folders were measured on different devices or sizes", file=sys.stderr)
    title = f"{device}, {study['width']}×{study['height']}, frame {study['frames']}"
    markdown = [f"Device: {device} ({study['device']['driver']}, subgroup {study['device']['subgroupSize']}); "
                f"{study['width']}×{study['height']}; error on frame {study['frames']} of {study['frames']}; "
                f"time: median of {study['runs']} runs.", ""]
    anchors = load_anchors()
    comparable = [a for a in anchors if comparable_anchor(a, study)]
    for effect in sorted({r["effect"] for r in rows}) if plots else []:
        plot_effect(rows, effect, title, out / f"{effect}.png", comparable)
    markdown += study_tables(rows)
    for other in studies:  # each folder's own presets: a split study chose them per effect
        markdown += choice_tables(other)
    if anchors:
        markdown += anchor_tables(anchors)

    scaling_files = [d / "scaling.json" for d in directories if (d / "scaling.json").exists()]
    if scaling_files:
        scaling = json.loads(scaling_files[0].read_text())["rows"]
    if scaling_files and plots:
        plot_scaling(scaling, "resolution", lambda r: r["width"] * r["height"] / 1e6, "megapixels",
                     f"time against resolution ({device})", out / "scaling_resolution.png")
        plot_scaling(scaling, "fraction", lambda r: 100 * r["fraction"],
                     {"reflections": "% of rows glossy", "shadows": "% of rows in penumbra"},
                     f"time against affected pixels ({device})", out / "scaling_fraction.png")
    if scaling_files:
        markdown += ["### scaling", ""] + scaling_tables(scaling)
    (out / "study.md").write_text("\n".join(markdown))
    print(f"wrote {out / 'study.md'}, the plots and the flip and pareto columns of study.csv")


if __name__ == "__main__":
    arguments = [a for a in sys.argv[1:] if a != "--flip-only"]
    if not arguments:
        sys.exit("usage: study.py [--flip-only] DIR [MORE_DIRS...] (folders written by glint study --out DIR)")
    # --flip-only: FLIP, Pareto and tables without matplotlib (the GPU machine); study.json keeps
    # the FLIP values, so a later run elsewhere draws the plots without the images.
    main(arguments, plots="--flip-only" not in sys.argv)
