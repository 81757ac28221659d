# Script mode: glint report on a hand-written run folder (summary.json as glint run writes it,
# docs/replay.md) and the FidelityFX anchors file: the page names the metric (mask, threshold,
# clamp range, reference samples and seeds), draws one error-against-frame plot with the noisy
# input, the output and the reference noise floor, and lists the glossy room's anchor points
# with their conditions in a table, never on the plot; its FLIP columns show "-" without FLIP
# values, and the values scripts/run_flip.py adds (with a FLIP plot) when the summary has them;
# a shadows run's moving-edge columns and plot. A malformed anchors file is one line naming it.
file(REMOVE_RECURSE "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/run_glint.cmake")

# Writes `summary` as the summary.json of the run folder OUT/<name>, with the frame folders
# named after it, renders its report to OUT/report_<name>.html and returns the page in `page`.
function(report_of name summary page)
  foreach(frame ${ARGN})
    file(MAKE_DIRECTORY "${OUT}/${name}/${frame}")
  endforeach()
  file(WRITE "${OUT}/${name}/summary.json" "${summary}")
  run_glint(0 report "${OUT}/${name}" --out "${OUT}/report_${name}.html")
  file(READ "${OUT}/report_${name}.html" html)
  set(${page} "${html}" PARENT_SCOPE)
endfunction()

# Fails unless the page `text` (read from `name`) matches every pattern after the first two.
function(expect_all text name)
  foreach(expected IN LISTS ARGN)
    if(NOT text MATCHES "${expected}")
      message(FATAL_ERROR "${name} lacks '${expected}'")
    endif()
  endforeach()
endfunction()

# Fails unless the page draws exactly `expected` polylines (`what` names them).
function(expect_polylines text expected what)
  string(REGEX MATCHALL "<polyline" lines "${text}")
  list(LENGTH lines count)
  if(NOT count EQUAL expected)
    message(FATAL_ERROR "expected ${expected} plotted lines (${what}), found ${count}")
  endif()
endfunction()
file(MAKE_DIRECTORY "${OUT}/glossy_room/frame_0000" "${OUT}/glossy_room/frame_0001")
file(WRITE "${OUT}/glossy_room/summary.json" [=[
{
  "capture": "captures/glossy_room",
  "device": {"name": "test device", "driver": "test driver", "subgroupSize": 8},
  "effects": ["reflections"],
  "settings": ["denoise=true", "roughnessThreshold=0.3"],
  "width": 480, "height": 270,
  "simulation": {"scene": "harness/scenes/glossy_room.toml", "width": 480, "height": 270, "frames": 2,
                 "referenceSpp": 48, "seed": 1},
  "secondReference": {"scene": "harness/scenes/glossy_room.toml", "width": 480, "height": 270, "frames": 2,
                      "referenceSpp": 48, "seed": 2},
  "frames": [
    {"frame": 0, "folder": "frame_0000", "images": [],
     "errors": {"reflections": {"image": "reflections/denoised", "pixels": 10, "mean": 0.5, "rmse": 0.7,
                                "penumbra": -1, "nonFinite": 0, "maeClamped": 0.25, "noisyMean": 0.9}},
     "referenceNoise": {"reflections": {"mean": 0.05, "rmse": 0.06, "maeClamped": 0.01}}},
    {"frame": 1, "folder": "frame_0001", "images": [],
     "errors": {"reflections": {"image": "reflections/denoised", "pixels": 10, "mean": 0.3, "rmse": 0.4,
                                "penumbra": -1, "nonFinite": 0, "maeClamped": 0.125, "rmseClamped": 0.35,
                                "noisyMean": 0.8}},
     "referenceNoise": {"reflections": {"mean": 0.0625, "rmse": 0.07, "maeClamped": 0.02}}}
  ],
  "error": {"reflections": {"first": 0.5, "last": 0.3, "noisyLast": 0.8, "referenceNoiseLast": 0.0625,
                            "maskThreshold": 0.3}}
}
]=])
run_glint(0 report "${OUT}/glossy_room" --out "${OUT}/report.html" --anchors "${ANCHORS}")
file(READ "${OUT}/report.html" html)

# References too noisy for the difference reported: a floor of 0.2 against |0.3 - 0.8| = 0.5.
file(READ "${OUT}/glossy_room/summary.json" noisy_summary)
string(REPLACE "\"mean\": 0.0625" "\"mean\": 0.2" noisy_summary "${noisy_summary}")
report_of(noisy_references "${noisy_summary}" noisy_html frame_0000 frame_0001)
if(NOT noisy_html MATCHES "<td>no: floor 0.2000 is not below a quarter of 0.5000</td>")
  message(FATAL_ERROR "report_noisy_references.html does not say the references are not converged")
endif()
expect_all("${html}" report.html
    "GGX alpha below roughnessThreshold = 0.30"
    "radiance clamped to \\[0, 16\\]"
    "48 samples per pixel \\(seed 1\\)"
    "independent seed 2"
    "480x270, 2 frame"
    "<svg"
    "noisy input"
    "output \\(denoised\\)"
    "reference noise floor"
    "<td>0.0625 \\(clamped MAE 0.0200\\)</td><td>yes</td><td>0.1250</td><td>0.3500</td>"
    "FidelityFX SDK 1.1.4, denoised"
    "640x360, frame 15 of a 16-frame sequence")
# Three series, each one unbroken line over both frames; no anchor marker on the axis.
expect_polylines("${html}" 3 "noisy, output, noise floor")
if(html MATCHES "<circle")
  message(FATAL_ERROR "an anchor was drawn on a plot it was not measured on")
endif()

# A summary from before FLIP: the FLIP columns show "-" and the page says FLIP was not computed.
if(NOT html MATCHES "<td>0.1250</td><td>0.3500</td><td>-</td><td>-</td></tr>"
   OR NOT html MATCHES "FLIP was not computed for this run")
  message(FATAL_ERROR "report.html of a summary without FLIP does not show \"-\" in its FLIP columns")
endif()

# The same run after scripts/run_flip.py: per-frame FLIP of the output, its noisy input and the
# reference noise floor; the table's FLIP columns and the floor cell show them, the page names
# the metric and plots FLIP against frame beside the error (three more lines).
file(READ "${OUT}/glossy_room/summary.json" flip_summary)
string(REPLACE "\"noisyMean\": 0.9}" "\"noisyMean\": 0.9, \"flip\": 0.2, \"noisyFlip\": 0.4}"
       flip_summary "${flip_summary}")
string(REPLACE "\"noisyMean\": 0.8}" "\"noisyMean\": 0.8, \"flip\": 0.125, \"noisyFlip\": 0.375}"
       flip_summary "${flip_summary}")
string(REPLACE "\"maeClamped\": 0.01}" "\"maeClamped\": 0.01, \"flip\": 0.05}" flip_summary "${flip_summary}")
string(REPLACE "\"maeClamped\": 0.02}" "\"maeClamped\": 0.02, \"flip\": 0.0625}" flip_summary "${flip_summary}")
string(REPLACE "\"referenceNoiseLast\": 0.0625}"
       "\"referenceNoiseLast\": 0.0625, \"flipLast\": 0.125, \"noisyFlipLast\": 0.375, \"referenceNoiseFlipLast\": 0.0625}"
       flip_summary "${flip_summary}")
string(REPLACE "\"frames\": [" "\"flip\": {\"metric\": \"LDR-FLIP of the test\", \"clamp\": 16},\n  \"frames\": ["
       flip_summary "${flip_summary}")
report_of(with_flip "${flip_summary}" flip_html frame_0000 frame_0001)
expect_all("${flip_html}" report_with_flip.html
    "<th>FLIP, last frame</th><th>its noisy input&#39;s FLIP, last frame</th>"
    "<td>0.0625 \\(clamped MAE 0.0200, FLIP 0.0625\\)</td><td>yes</td><td>0.1250</td><td>0.3500</td><td>0.1250</td><td>0.3750</td></tr>"
    "LDR-FLIP as scripts/study.py defines it"
    "radiance clamped to \\[0, 16\\] and tone-mapped per channel with Reinhard x/\\(1\\+x\\)"
    "shadow visibility clamped to \\[0, 1\\]"
    "reflections: LDR-FLIP against the reference"
    "mean LDR-FLIP")
expect_polylines("${flip_html}" 6 "error and FLIP: noisy, output, noise floor")
# A null FLIP (the frame's mask held no pixel) is "no pixels scored", never a number.
string(REPLACE "\"noisyFlip\": 0.375" "\"noisyFlip\": null" null_summary "${flip_summary}")
report_of(null_flip "${null_summary}" null_html frame_0000 frame_0001)
if(NOT null_html MATCHES "<td>0.1250</td><td>no pixels scored</td></tr>")
  message(FATAL_ERROR "report_null_flip.html does not show a null FLIP as \"no pixels scored\"")
endif()

# A reflections run has no moving edges: "-" in both of their columns.
if(NOT html MATCHES "<td>0.8000</td><td>-</td><td>-</td><td>0.0625 ")
  message(FATAL_ERROR "report.html of a reflections run does not show \"-\" for the moving edges")
endif()

# A shadows run with moving edges (docs/replay.md): none on frame 0 (null), then 12 and 8
# pixels. The table shows the last frame's with its pixel count, the metric sentence says what
# they are, and a plot draws them against frame with a marker on every value: the error plot's
# two lines over the three frames, the moving-edge plot's two over frames 1-2 and four markers.
file(MAKE_DIRECTORY "${OUT}/walker/frame_0002")
file(WRITE "${OUT}/walker/summary.json" [=[
{
  "capture": "captures/walker",
  "device": {"name": "test device", "driver": "test driver", "subgroupSize": 8},
  "effects": ["shadows"],
  "settings": [],
  "width": 160, "height": 90,
  "frames": [
    {"frame": 0, "folder": "frame_0000", "images": [],
     "errors": {"shadows": {"image": "shadows/denoised", "pixels": 100, "mean": 0.01, "penumbra": 0.1,
                            "noisyMean": 0.02, "movingEdgePixels": 0, "movingEdge": null, "noisyMovingEdge": null}}},
    {"frame": 1, "folder": "frame_0001", "images": [],
     "errors": {"shadows": {"image": "shadows/denoised", "pixels": 100, "mean": 0.01, "penumbra": 0.1,
                            "noisyMean": 0.02, "movingEdgePixels": 12, "movingEdge": 0.25, "noisyMovingEdge": 0.5}}},
    {"frame": 2, "folder": "frame_0002", "images": [],
     "errors": {"shadows": {"image": "shadows/denoised", "pixels": 100, "mean": 0.01, "penumbra": 0.1,
                            "noisyMean": 0.02, "movingEdgePixels": 8, "movingEdge": 0.125, "noisyMovingEdge": 0.375}}}
  ],
  "error": {"shadows": {"first": 0.01, "last": 0.01, "noisyLast": 0.02}}
}
]=])
run_glint(0 report "${OUT}/walker" --out "${OUT}/report_walker.html")
file(READ "${OUT}/report_walker.html" walker_html)
expect_all("${walker_html}" report_walker.html
    "<th>error over moving edges, last frame</th><th>its noisy input&#39;s, over the same moving edges</th>"
    "<td>0.0200</td><td>0.1250 \\(8 pixels\\)</td><td>0.3750 \\(8 pixels\\)</td>"
    "changed by more than 0.25 since the previous frame at the same pixel"
    "shadows: error over moving edges")
expect_polylines("${walker_html}" 4 "error: noisy, output; moving edges: noisy, output")
string(REGEX MATCHALL "<circle" markers "${walker_html}")
list(LENGTH markers marker_count)
if(NOT marker_count EQUAL 4)
  message(FATAL_ERROR "expected a marker on each of the 4 moving-edge values, found ${marker_count}")
endif()
# No receiver moved on the last frame: "no pixels scored", never 0.
file(READ "${OUT}/walker/summary.json" still_summary)
string(REPLACE "\"movingEdgePixels\": 8, \"movingEdge\": 0.125, \"noisyMovingEdge\": 0.375"
       "\"movingEdgePixels\": 0, \"movingEdge\": null, \"noisyMovingEdge\": null" still_summary "${still_summary}")
report_of(still "${still_summary}" still_html frame_0002)
if(NOT still_html MATCHES "<td>0.0200</td><td>no pixels scored</td><td>no pixels scored</td>")
  message(FATAL_ERROR "report_still.html does not show the last frame's empty moving edges as \"no pixels scored\"")
endif()

# The summary over several runs (docs/replay.md, "glint report"): one row per run and effect.
# The glossy room's second reference says the difference is -0.45 where the first says -0.5:
# they agree (apart by 0.05, less than a quarter of 0.5). A shadows run whose output is its noisy
# input (equal errors) has no difference to resolve: its floor must be below a quarter of the
# error itself, met at 0.0002 (< 0.00025) and not at 0.0003.
string(REPLACE "\"maeClamped\": 0.02}" "\"maeClamped\": 0.02, \"differenceAgainstSecond\": -0.45}"
       paired_summary "${noisy_summary}")
string(REPLACE "\"mean\": 0.2" "\"mean\": 0.0625" paired_summary "${paired_summary}")
file(MAKE_DIRECTORY "${OUT}/paired/frame_0000" "${OUT}/paired/frame_0001")
file(WRITE "${OUT}/paired/summary.json" "${paired_summary}")
set(hard_summary [=[
{
  "capture": "captures/hard", "device": {"name": "test device", "driver": "test driver", "subgroupSize": 8},
  "effects": ["shadows"], "settings": [], "width": 160, "height": 90,
  "simulation": {"referenceSpp": 8, "referenceSamples": [8, 16, 24]},
  "frames": [{"frame": 2, "folder": "frame_0002", "images": [],
              "errors": {"shadows": {"image": "shadows/denoised", "pixels": 100, "mean": 0.001, "noisyMean": 0.001}}}],
  "error": {"shadows": {"first": 0.001, "last": 0.001, "noisyLast": 0.001, "referenceNoiseLast": FLOOR}}
}
]=])
string(REPLACE "FLOOR" "0.0002" hard_resolved "${hard_summary}")
string(REPLACE "FLOOR" "0.0003" hard_unresolved "${hard_summary}")
foreach(name hard_resolved hard_unresolved)
  file(MAKE_DIRECTORY "${OUT}/${name}/frame_0002")
  file(WRITE "${OUT}/${name}/summary.json" "${${name}}")
endforeach()
run_glint(0 report "${OUT}/paired" "${OUT}/hard_resolved" "${OUT}/hard_unresolved" --out "${OUT}/summary.html")
file(READ "${OUT}/summary.html" summary_html)
expect_all("${summary_html}" summary.html
    "<h2>Summary: the last frame of every run</h2>"
    "<table class=\"compact\">"
    "<td>paired</td><td>reflections</td><td>0.8000</td><td>0.3000</td><td>0.0625</td><td>yes</td><td>-0.5000 / -0.4500</td><td>yes</td><td>-</td><td>-</td><td>-</td><td>48</td>"
    "<td>hard_resolved</td><td>shadows</td><td>0.0010</td><td>0.0010</td><td>0.0002</td><td>yes \\(output = input\\)</td><td>0.0000 / -</td><td>-</td>"
    "<td>24</td>"
    "<td>hard_unresolved</td><td>shadows</td><td>0.0010</td><td>0.0010</td><td>0.0003</td><td>no</td>")
# One run: no summary.
if(html MATCHES "Summary: the last frame")
  message(FATAL_ERROR "report.html of one run has a summary table")
endif()

file(WRITE "${OUT}/bad_anchors.json" "{\"points\": 3}")
run_glint(2 report "${OUT}/glossy_room" --out "${OUT}/report_bad.html" --anchors "${OUT}/bad_anchors.json")
if(NOT run_err MATCHES "^glint: report: [^\n]*bad_anchors.json: no \"points\" array\n?$")
  message(FATAL_ERROR "expected one line naming bad_anchors.json, got: ${run_err}")
endif()
