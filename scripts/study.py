#!/usr/bin/env python3
"""FLIP, Pareto fronts, reference noise floors, plots and tables for a `glint study` folder
(docs/accuracy-vs-time.md).

    python3 scripts/study.py [--flip-only] [--hdr-flip] DIR [MORE_DIRS...]

DIR is what `glint study --out DIR` (and `glint study --scaling --out DIR`) wrote, on this
machine or another: the image paths inside study.json are relative to DIR. Studies split over
several runs (e.g. one per effect) are combined by naming every folder; the results go to the
first. Adds the columns `flip`, `flip_hdr`, `floor_flip` and `pareto` to each folder's study.csv
and writes DIR/<effect>.png (FLIP against time, one colour per scene, each scene's Pareto front
connected, its reference noise floor dotted), DIR/<effect>_hdr.png (the same in HDR-FLIP, where
it was computed), DIR/scaling_resolution.png and DIR/scaling_fraction.png (from the first folder
with a scaling.json) and DIR/study.md (the tables, the reference noise floors and whether each
reference is converged, the presets and the budget choice glint study made).

FLIP is NVIDIA's perceptual difference (flip-evaluator). `flip` is LDR-FLIP for every effect: of
reflection (and hybrid) radiance clamped to [0, radiance_clamp] (study.json's, 16) and
tone-mapped per channel with Reinhard x / (1 + x), and of shadow visibility clamped to [0, 1].
`flip_hdr` (--hdr-flip, reflections and hybrid only: slow at 1080p) is HDR-FLIP of the linear
radiance. The images are zeroed outside the pixels the error is measured over (mask.exr), and
FLIP is averaged over those pixels only. Where a row has a second, independent reference
(`reference2`), FLIP between the two references is the noise floor `floor_flip`.

--flip-only: FLIP, Pareto fronts and tables without matplotlib (the GPU machine); study.json
keeps the FLIP values, so a later run elsewhere draws the plots without the images.
--hdr-flip: also HDR-FLIP (flip_hdr, floor_flip_hdr) and the <effect>_hdr.png plots.
"""
import csv
import json
import math
import pathlib
import sys

import numpy as np

# Measured points of other implementations (docs/anchors/*.json), drawn beside the fronts.
ANCHORS = pathlib.Path(__file__).resolve().parents[1] / "docs" / "anchors"

# study.json's radiance_clamp where the file predates it (replay_error.h, kMaeClamp).
RADIANCE_CLAMP = 16.0

# Pixels kept around the mask when LDR-FLIP is cropped to it: LDR-FLIP at its 67 pixels per
# degree changes no error more than 7 pixels from a changed input pixel (measured with
# flip-evaluator 1.7), and LDR-FLIP has no image-wide statistic, so the masked pixels' errors are
# those of the whole image. HDR-FLIP is never cropped: it picks its exposures from the whole image.
FLIP_MARGIN = 32


def pyplot():
    """matplotlib only where plots are drawn: --flip-only runs where it is not installed."""
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    return plt


def flip_metric(clamp):
    """What `flip` means, kept in study.json (flip_metric): a study.json whose FLIP was computed
    another way (before it: HDR-FLIP for radiance, visibility read as sRGB) is computed again."""
    return (f"LDR-FLIP (flip-evaluator, inputsRGB=False) of radiance clamped to [0, {clamp:g}] and "
            f"tone-mapped with Reinhard x/(1+x), of shadow visibility clamped to [0, 1]")


def load_rgb(path):
    import flip_evaluator as flip

    if not pathlib.Path(path).exists():  # flip.load does not say what is missing
        sys.exit(f"study.py: {path} is missing: FLIP needs the study's images (study.json holds no FLIP "
                 f"of the current kind for it)")
    image = np.asarray(flip.load(str(path)), dtype=np.float32)[..., :3]
    return np.nan_to_num(image, nan=0.0, posinf=0.0, neginf=0.0)  # non-finite is reported apart


def tone_map(radiance, clamp=RADIANCE_CLAMP):
    """Display-linear values in [0, 1) from radiance: clamped to [0, clamp] (as the MAE is), then
    Reinhard x / (1 + x) per channel."""
    clamped = np.clip(np.asarray(radiance, dtype=np.float32), 0.0, clamp)
    return clamped / (1.0 + clamped)


def ldr_image(effect, image, clamp=RADIANCE_CLAMP):
    """What LDR-FLIP is given: shadow visibility as it is (clamped to [0, 1]), radiance tone-mapped.
    Both are linear values (light, not sRGB-encoded pixel values)."""
    return np.clip(image, 0.0, 1.0) if effect == "shadows" else tone_map(image, clamp)


def crop_to(mask, margin=FLIP_MARGIN):
    """The rows and columns of the mask's bounding box, widened by margin (within the image)."""
    ys, xs = np.nonzero(mask)
    return (slice(max(ys.min() - margin, 0), ys.max() + margin + 1),
            slice(max(xs.min() - margin, 0), xs.max() + margin + 1))


def masked_flip(reference, test, mask, dynamic_range="LDR"):
    """Mean FLIP of test against reference over mask; None where the mask holds no pixel."""
    import flip_evaluator as flip

    if not mask.any():
        return None
    if dynamic_range == "LDR":  # the work follows the masked area; the result is the whole image's
        box = crop_to(mask)
        reference, test, mask = reference[box], test[box], mask[box]
    # inputsRGB=False: both images hold linear values. flip-evaluator reads LDR input as
    # sRGB-encoded unless told otherwise (its default inputsRGB=True), which would treat
    # Reinhard's and visibility's linear values as display-encoded ones; HDR input is always linear.
    error, _, _ = flip.evaluate(np.ascontiguousarray(reference), np.ascontiguousarray(test), dynamic_range,
                                inputsRGB=False, applyMagma=False)
    error = np.asarray(error).reshape(mask.shape)
    return float(error[mask].mean())


def mean_flip(directory, row, test="output", dynamic_range="LDR", clamp=RADIANCE_CLAMP):
    """Mean FLIP of the row's image `test` (its output, or its second reference "reference2")
    against its reference over its mask: LDR-FLIP of ldr_image(), or HDR-FLIP of the linear
    radiance (negative values set to 0). None where the mask holds no pixel."""
    mask = load_rgb(directory / row["mask"])[..., 0] > 0.5
    if not mask.any():
        return None
    reference = load_rgb(directory / row["reference"])
    other = load_rgb(directory / row[test])
    if dynamic_range == "HDR":
        return masked_flip(np.maximum(reference, 0), np.maximum(other, 0), mask, "HDR")
    return masked_flip(ldr_image(row["effect"], reference, clamp), ldr_image(row["effect"], other, clamp), mask)


def forget_stale_flips(study, metric):
    """Drops FLIP values computed another way than `metric` names, so that they are computed again.
    A study.json from before flip_metric holds HDR-FLIP of the linear radiance under `flip` for
    reflections and hybrid: what --hdr-flip computes, so it is kept as flip_hdr."""
    for row in study["rows"]:
        if "flip_metric" not in study and "flip" in row and row["effect"] != "shadows":
            row.setdefault("flip_hdr", row["flip"])
        row.pop("flip", None)
        row.pop("floor_flip", None)
    study["flip_metric"] = metric


def parallel_map(function, arguments, workers=None):
    """[function(*a) for a in arguments], in `workers` processes (None: one per CPU; 1, or fewer
    than two calls: in this process). `function` must be importable by name (a module's own)."""
    if workers == 1 or len(arguments) < 2:
        return [function(*a) for a in arguments]
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    # spawn, not fork: a forked child can inherit a lock held by another thread of this one.
    with ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context("spawn")) as pool:
        return list(pool.map(function, *zip(*arguments)))


def add_flips(directory, study, hdr=False, workers=None):
    """flip (and flip_hdr with hdr) of every row of one folder's study.json, and the noise floors
    floor_flip (floor_flip_hdr) of the rows with a second reference, each floor computed once per
    reference. Values already in study.json are kept: absent means not computed, None (null) that
    no pixel was scored. The images are independent, so they are scored in parallel, one process
    per CPU (FLIP itself runs on one core); `workers` 1 scores them in this process."""
    clamp = study.get("radiance_clamp", RADIANCE_CLAMP)
    if study.get("flip_metric") != flip_metric(clamp):
        forget_stale_flips(study, flip_metric(clamp))
    jobs = {}  # (test image, reference, mask, dynamic range) -> the mean_flip arguments
    wanted = []  # (row, field, job key)
    for row in study["rows"]:
        radiance = row["effect"] != "shadows"  # HDR-FLIP is for radiance only
        fields = [("flip", "output", "LDR")]
        if hdr and radiance:
            fields.append(("flip_hdr", "output", "HDR"))
        if row.get("reference2"):  # the floor: one per reference, shared by the scene's rows
            fields.append(("floor_flip", "reference2", "LDR"))
            if hdr and radiance:
                fields.append(("floor_flip_hdr", "reference2", "HDR"))
        for field, test, dynamic_range in fields:
            if field in row:
                continue
            key = (row[test], row["reference"], row["mask"], dynamic_range)
            jobs.setdefault(key, (row, test, dynamic_range))
            wanted.append((row, field, key))
    values = parallel_map(mean_flip, [(directory, row, test, dynamic_range, clamp)
                                      for row, test, dynamic_range in jobs.values()], workers)
    results = dict(zip(jobs, values))
    for row, field, key in wanted:
        row[field] = results[key]


def dominated(row, rivals, key="flip"):
    """Whether another point is at least as fast and as accurate as row, and strictly better in one."""
    return any(r is not row and r["time_us"] <= row["time_us"] and r[key] <= row[key]
               and (r["time_us"] < row["time_us"] or r[key] < row[key]) for r in rivals)


def front(points, key="flip"):
    """The points of one scene and effect that no other dominates in time and `key`, fastest first.
    A point without a value (no pixel scored, not computed) is on no front and competes with none."""
    scored_points = [p for p in points if p.get(key) is not None]
    return sorted((p for p in scored_points if not dominated(p, scored_points, key)),
                  key=lambda p: (p["time_us"], p[key]))


def mark_pareto(rows):
    """pareto = 1 where no other point of the same scene and effect is as fast and as accurate.
    A point without a FLIP (no pixel scored) is on no front and competes with none."""
    for row in rows:
        row["pareto"] = 0
    for scene, effect in {(r["scene"], r["effect"]) for r in rows}:
        for row in front([r for r in rows if (r["scene"], r["effect"]) == (scene, effect)]):
            row["pareto"] = 1


def smallest_step(points, key):
    """The smallest non-zero difference in `key` between consecutive points (None: there is none)."""
    values = [p.get(key) for p in points]
    steps = [abs(b - a) for a, b in zip(values, values[1:]) if a is not None and b is not None]
    return min((s for s in steps if s > 0), default=None)


def spp_to_converge(spp, floor, step):
    """The reference spp at which the floor would fall below a quarter of step, if the floor falls
    like 1/sqrt(spp) (Monte Carlo noise; FLIP's floor only roughly does): spp (4 floor / step)^2,
    rounded up to a power of two; None where there is nothing to estimate."""
    if not spp or floor is None or not step or floor < step / 4:
        return None
    needed = spp * (4 * floor / step) ** 2
    return 1 << max(0, math.ceil(math.log2(needed)))


def resolved_steps(points, key, floor):
    """(steps between consecutive front points at least 4 floor apart, all non-zero steps)."""
    values = [p.get(key) for p in points]
    steps = [abs(b - a) for a, b in zip(values, values[1:]) if a is not None and b is not None]
    steps = [s for s in steps if s > 0]
    return (None if floor is None else sum(s > 4 * floor for s in steps)), len(steps)


def converged(floor, step):
    """floor below a quarter of the smallest step; True with no step (nothing for the reference to
    resolve), None without a floor."""
    if floor is None:
        return None
    return True if step is None else floor < step / 4


def convergence(rows):
    """Per (scene, effect): the reference's noise floor (FLIP, MAE, mean error between the two
    independent references), the smallest steps between consecutive points of the scene's Pareto
    front by time (in FLIP, and in MAE between the same points), and whether the reference is
    converged by the rule of docs/accuracy-vs-time.md: its floor below a quarter of the smallest
    step, for FLIP and for MAE separately (None where there is no floor)."""
    result = {}
    for scene, effect in sorted({(r["scene"], r["effect"]) for r in rows}):
        group = [r for r in rows if (r["scene"], r["effect"]) == (scene, effect)]
        points = front(group)
        floor = next((r["floor"] for r in group if r.get("floor")), {})
        floor_flip = next((r["floor_flip"] for r in group if r.get("floor_flip") is not None), None)
        steps = {key: smallest_step(points, key) for key in ("flip", "mae")}
        result[(scene, effect)] = {
            "reference_spp": next((r["reference_spp"] for r in group if r.get("reference_spp")), None),
            "floor_flip": floor_flip, "floor_mae": floor.get("mae"), "floor_error_mean": floor.get("error_mean"),
            "front_points": len(points),
            "smallest_flip_step": steps["flip"], "smallest_mae_step": steps["mae"],
            "converged_flip": converged(floor_flip, steps["flip"]),
            "converged_mae": converged(floor.get("mae"), steps["mae"])}
        spp = result[(scene, effect)]["reference_spp"]
        needed = [spp_to_converge(spp, f, steps[k]) for k, f in (("flip", floor_flip), ("mae", floor.get("mae")))]
        result[(scene, effect)]["spp_to_converge"] = max((n for n in needed if n), default=None)
        result[(scene, effect)]["resolved_flip_steps"] = resolved_steps(points, "flip", floor_flip)
    return result


def convergence_warnings(verdicts):
    """One line per scene and effect whose reference is not converged, with what to do about it."""
    lines = []
    for (scene, effect), v in verdicts.items():
        failed = [f"{name} floor {v[f'floor_{key}']:.4g} is not below a quarter of the smallest front step "
                  f"{v[f'smallest_{key}_step']:.4g}" for key, name in (("flip", "FLIP"), ("mae", "MAE"))
                  if v[f"converged_{key}"] is False]
        if failed:
            spp = f"{v['reference_spp']} spp" if v["reference_spp"] else "its spp"
            needed = v.get("spp_to_converge")
            hint = f"glint study --spp {needed} would converge it, if the floor falls like 1/sqrt(spp)" if needed else \
                "run glint study again with a larger --spp"
            lines.append(f"study.py: warning: {scene} {effect}: the reference ({spp}) is not converged: "
                         f"{'; '.join(failed)}; {hint}")
    return lines


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


def drawn_anchors(anchors, effect, kind):
    """The anchors of effect whose FLIP is of `kind` ("LDR" or "HDR", the anchor's flip_kind): a
    FLIP of another or an unstated kind is not comparable with the plot's, so it is not drawn."""
    return [a for a in anchors if a["effect"] == effect and a.get("flip") is not None and a.get("flip_kind") == kind]


def plot_effect(rows, effect, title, path, anchors=(), key="flip"):
    """FLIP (key "flip", LDR) or HDR-FLIP (key "flip_hdr") against time for one effect: one colour
    per scene, its Pareto front in that metric connected, its reference noise floor dotted, and the
    anchors whose FLIP is of the same kind."""
    plt = pyplot()
    hdr = key == "flip_hdr"
    figure, axes = plt.subplots(figsize=(8, 5.5))
    scenes = sorted({r["scene"] for r in rows if r["effect"] == effect})
    floor_shown = False
    for colour, scene in zip(plt.cm.tab10.colors, scenes):
        points = sorted((r for r in rows if (r["effect"], r["scene"]) == (effect, scene) and r.get(key) is not None),
                        key=lambda r: r["time_us"])
        axes.scatter([p["time_us"] for p in points], [p[key] for p in points], color=colour, label=scene)
        line = front(points, key)
        axes.plot([p["time_us"] for p in line], [p[key] for p in line], color=colour, linewidth=1)
        for p in points:
            axes.annotate(p["label"], (p["time_us"], p[key]), fontsize=6, xytext=(3, 2), textcoords="offset points")
        floor = next((r["floor_" + key] for r in rows if (r["effect"], r["scene"]) == (effect, scene)
                      and r.get("floor_" + key) is not None), None)
        if floor is not None:  # an error near it is the reference's noise, not the point's
            axes.axhline(floor, color=colour, linestyle=":", linewidth=1,
                         label=None if floor_shown else "reference noise floor (dotted)")
            floor_shown = True
    drawn = drawn_anchors(anchors, effect, "HDR" if hdr else "LDR")
    for a in drawn:
        axes.scatter([a["time_us"]], [a["flip"]], marker="*", s=90, color="black")
        axes.annotate(f"{a['label']} ({a['scene']})", (a["time_us"], a["flip"]), fontsize=6, xytext=(-4, -9),
                      textcoords="offset points", ha="right")
    if drawn:  # where and when: the time and the error of an anchor come from different runs
        sources = ", ".join(sorted({a["source"] for a in drawn}))
        figure.text(0.01, 0.005, f"★ measured points of other implementations; their time and error conditions "
                    f"are in study.md and docs/anchors/{sources}", fontsize=6)
    metric = ("mean HDR-FLIP of the radiance" if hdr else
              "mean LDR-FLIP of the visibility" if effect == "shadows" else "mean LDR-FLIP of the tone-mapped radiance")
    axes.set(xlabel="GPU time of the effect (µs, median)", ylabel=f"{metric} over the measured pixels",
             title=f"{effect}{' (HDR-FLIP)' if hdr else ''}: {title}")
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


def metric(row, key, form="{:.4f}"):
    """A row's metric: "-" where it was not computed (absent: an older study.json, HDR-FLIP
    without --hdr-flip), else scored()."""
    return "-" if key not in row else scored(row[key], form)


def metric_lines(clamp=RADIANCE_CLAMP):
    """What the tables' metrics are, for the head of study.md."""
    return [f"Metrics, each over the mask (reflections and hybrid: the glossy pixels below the largest "
            f"roughness threshold swept; shadows: the receivers): **FLIP** is LDR-FLIP (flip-evaluator, "
            f"67 pixels per degree) of the radiance clamped to [0, {clamp:g}] and tone-mapped per channel "
            f"with Reinhard x/(1+x), and for shadows of the visibility in [0, 1], both given to FLIP as "
            f"linear values; **HDR-FLIP** is HDR-FLIP of the linear radiance (`study.py --hdr-flip` only, "
            f"\"-\" where not computed); **MAE** and **RMSE** are of the colour channels clamped to "
            f"[0, {clamp:g}] (\"-\" in a study from before them); **mean error** is glint's relative "
            f"error (reflections: luminance of |out − ref| / max(luminance(ref), 0.05); shadows: "
            f"|out − ref|), unclamped. The Pareto fronts are in FLIP against time.", ""]


def study_tables(rows):
    lines = []
    for effect in sorted({r["effect"] for r in rows}):
        shadows = effect == "shadows"  # the penumbra error is where a shadow denoiser shows
        hybrid = effect == "hybrid"  # its cost follows the fraction of rays it ray traces
        lines += [f"### {effect}", "",
                  "| scene | point | settings | time (µs) |" + (" RT rays |" if hybrid else "")
                  + " FLIP |" + ("" if shadows else " HDR-FLIP |") + " MAE | RMSE | mean error |"
                  + (" penumbra | moving edge |" if shadows else "") + " non-finite | Pareto |",
                  "|---|---|---|---|" + ("---|" if hybrid else "") + "---|" + ("" if shadows else "---|")
                  + "---|---|---|" + ("---|---|" if shadows else "") + "---|---|"]
        for r in (r for r in rows if r["effect"] == effect):
            # glint writes -1 where no pixel of the mask is in penumbra
            # moving edge: null where no receiver moved, absent in a study from before it
            penumbra = (f" {scored(r['penumbra'] if r['penumbra'] >= 0 else None)} | {metric(r, 'moving_edge')} |"
                        if shadows else "")
            fraction = r.get("traced_fraction", "")  # the share of rays ray traced
            traced = (f" {100 * float(fraction):.1f} % |" if fraction != "" else " - |") if hybrid else ""
            hdr = "" if shadows else f" {metric(r, 'flip_hdr')} |"
            lines.append(f"| {r['scene']} | {r['label']} | `{' '.join(r['settings']) or '-'}` | {r['time_us']:.1f} |"
                         f"{traced} {scored(r['flip'])} |{hdr} {metric(r, 'mae')} | {metric(r, 'rmse_clamped')} | "
                         f"{metric(r, 'error_mean')} |{penumbra} {r['non_finite']:g} | "
                         f"{'**yes**' if r['pareto'] else ''} |")
        lines.append("")
    return lines


def floor_tables(verdicts):
    """The reference noise floors, the smallest front steps and whether each reference is converged."""
    if not any(v["floor_flip"] is not None or v["floor_mae"] is not None for v in verdicts.values()):
        return ["### reference noise floors", "",
                "None measured: the study has no second references (glint study --no-floor, or older).", ""]
    lines = ["### reference noise floors", "",
             "The floor is the difference between two independent references of the same frame (different seeds) "
             "over the same mask, in the tables' metrics. A reference is converged when its floor is below a "
             "quarter of the smallest error difference the study reports: the smallest non-zero step between "
             "consecutive points of the scene's Pareto front (by time), in FLIP, and in MAE between the same "
             "points, each metric on its own. A front of one point has no step. A front step smaller than 4× the "
             "floor is within the references' noise: the two points it separates are a tie at this spp. The spp "
             "to converge assumes the floor falls like 1/sqrt(spp).", "",
             "| scene | effect | reference spp | floor FLIP | floor MAE | floor mean error | smallest FLIP step "
             "| smallest MAE step | converged (FLIP) | converged (MAE) | FLIP front steps above 4× floor "
             "| spp to converge (estimate) |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def value(x):
        return "-" if x is None else f"{x:.4g}"

    def verdict(x):
        return "-" if x is None else "yes" if x else "**no**"

    def resolved(v):
        above, steps = v.get("resolved_flip_steps", (None, 0))
        return "-" if above is None else f"{above} of {steps}"

    for (scene, effect), v in verdicts.items():
        nothing = "one point" if v["front_points"] < 2 else "no step"
        steps = [nothing if v[f"smallest_{k}_step"] is None else value(v[f"smallest_{k}_step"]) for k in ("flip", "mae")]
        lines.append(f"| {scene} | {effect} | {v['reference_spp'] or '-'} | {value(v['floor_flip'])} | "
                     f"{value(v['floor_mae'])} | {value(v['floor_error_mean'])} | {steps[0]} | {steps[1]} | "
                     f"{verdict(v['converged_flip'])} | {verdict(v['converged_mae'])} | {resolved(v)} | "
                     f"{v.get('spp_to_converge') or '-'} |")
    return lines + [""]


def anchor_tables(anchors):
    lines = ["### anchors (docs/anchors)", "",
             "Drawn on the plots only when the study ran on the device and at the size of the point's time, and "
             "only on the plot of the FLIP kind the anchor states (LDR: the FLIP plot; HDR: the HDR-FLIP plot); an "
             "anchor whose kind is unstated is listed here only.", "",
             "| effect | scene | point | time (µs) | time measured | FLIP | FLIP kind | MAE | error measured |",
             "|---|---|---|---|---|---|---|---|---|"]
    for a in anchors:
        lines.append(f"| {a['effect']} | {a['scene']} | {a['label']} | {a['time_us']:.1f} | {a['time_measured']} "
                     f"| {scored(a.get('flip'))} | {a.get('flip_kind', 'unstated')} | {scored(a.get('mae'))} "
                     f"| {a['error_measured']} |")
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


# The columns study.py adds to study.csv, after glint's.
ADDED_COLUMNS = ["flip", "flip_hdr", "floor_flip", "pareto"]


def add_columns(directory, rows):
    """study.csv keeps the C++ columns (same rows, same order) and gains ADDED_COLUMNS: a value,
    "no pixels scored", or empty where not computed (flip_hdr without --hdr-flip, floor_flip
    without a second reference). A folder brought back with study.json alone has nothing to add to."""
    if not (directory / "study.csv").exists():
        return
    with open(directory / "study.csv", newline="") as file:
        table = list(csv.DictReader(file))
    for line, row in zip(table, rows, strict=True):
        for column in ADDED_COLUMNS[:-1]:
            line[column] = scored(row[column], "{:.6g}") if column in row else ""
        line["pareto"] = row["pareto"]
    with open(directory / "study.csv", "w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=[c for c in table[0] if c not in ADDED_COLUMNS] + ADDED_COLUMNS)
        writer.writeheader()
        writer.writerows(table)


def borrow_times(rows, timed):
    """The rows with each one's time taken from the row of `timed` (another study's study.json) with
    the same scene, effect and label; a row `timed` lacks is left out. For points whose error and
    time are measured under different conditions, as the anchors' are (error at a small size on
    any device, time on the GPU at full size): the plots then put both kinds of point on one axis."""
    times = {(r["scene"], r["effect"], r["label"]): r["time_us"] for r in timed["rows"]}
    return [dict(r, time_us=times[(r["scene"], r["effect"], r["label"])], time_us_own=r["time_us"])
            for r in rows if (r["scene"], r["effect"], r["label"]) in times]


def main(directories, plots=True, hdr=False, times_from=None):
    directories = [pathlib.Path(d) for d in directories]
    out = directories[0]
    studies = [json.loads((d / "study.json").read_text()) for d in directories]
    rows = []
    for directory, study in zip(directories, studies):
        add_flips(directory, study, hdr)  # kept in study.json, so that plots need no images
        (directory / "study.json").write_text(json.dumps(study, indent=1))
        rows += study["rows"]
    timed = json.loads((pathlib.Path(times_from) / "study.json").read_text()) if times_from else None
    if timed:
        rows = borrow_times(rows, timed)
    mark_pareto(rows)
    for directory, study in zip(directories, studies):
        add_columns(directory, study["rows"])
    verdicts = convergence(rows)
    for line in convergence_warnings(verdicts):
        print(line, file=sys.stderr)

    study = studies[0]
    device = study["device"]["name"]
    clamp = study.get("radiance_clamp", RADIANCE_CLAMP)
    if any(s["device"]["name"] != device or (s["width"], s["height"]) != (study["width"], study["height"])
           for s in studies):
        print("study.py: warning: the folders were measured on different devices or sizes", file=sys.stderr)
    if any(s.get("radiance_clamp", RADIANCE_CLAMP) != clamp for s in studies):
        print("study.py: warning: the folders clamp radiance differently: FLIP and MAE are not comparable "
              "between them", file=sys.stderr)
    title = f"{device}, {study['width']}×{study['height']}, frame {study['frames']}"
    markdown = [f"Device: {device} ({study['device']['driver']}, subgroup {study['device']['subgroupSize']}); "
                f"{study['width']}×{study['height']}; error on frame {study['frames']} of {study['frames']}; "
                f"time: median of {study['runs']} runs.", ""] + metric_lines(clamp)
    if timed:  # the time axis is the other study's: anchors measured there are comparable
        title = (f"error: {title}\ntime: {timed['device']['name']}, {timed['width']}×{timed['height']} "
                 f"(--times-from)")
        markdown += [f"The times are those of the same points in {times_from} ({timed['device']['name']}, "
                     f"{timed['width']}×{timed['height']}, median of {timed['runs']} runs): errors and times "
                     "were measured under different conditions, as the anchors' are. Points it lacks are left "
                     "out.", ""]
        study = dict(study, device=timed["device"], width=timed["width"], height=timed["height"])
    anchors = load_anchors()
    comparable = [a for a in anchors if comparable_anchor(a, study)]
    for effect in sorted({r["effect"] for r in rows}) if plots else []:
        plot_effect(rows, effect, title, out / f"{effect}.png", comparable)
        if any(r.get("flip_hdr") is not None for r in rows if r["effect"] == effect):
            plot_effect(rows, effect, title, out / f"{effect}_hdr.png", comparable, key="flip_hdr")
    markdown += study_tables(rows)
    markdown += floor_tables(verdicts)
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
    print(f"wrote {out / 'study.md'}, the plots and the {', '.join(ADDED_COLUMNS)} columns of study.csv")


OPTIONS = ("--flip-only", "--hdr-flip")

if __name__ == "__main__":
    arguments = [a for a in sys.argv[1:] if a not in OPTIONS]
    times_from = None
    if "--times-from" in arguments[:-1]:
        index = arguments.index("--times-from")
        times_from = arguments[index + 1]
        del arguments[index:index + 2]
    if not arguments or any(a.startswith("--") for a in arguments):
        sys.exit("usage: study.py [--flip-only] [--hdr-flip] [--times-from TIMED_DIR] DIR [MORE_DIRS...] "
                 "(folders written by glint study --out DIR)")
    # --flip-only: FLIP, Pareto and tables without matplotlib (the GPU machine); study.json keeps
    # the FLIP values, so a later run elsewhere draws the plots without the images.
    # --hdr-flip: HDR-FLIP too; it evaluates FLIP at several exposures over the whole image, so it
    # is opt-in (docs/accuracy-vs-time.md says where it did not finish).
    # --times-from TIMED_DIR: plot each point at the time of the same point in TIMED_DIR's study
    # (borrow_times), so that anchors timed there are drawn beside points scored here.
    main(arguments, plots="--flip-only" not in sys.argv, hdr="--hdr-flip" in sys.argv, times_from=times_from)
