# Script mode: glint report on a hand-written run folder (summary.json as glint run writes it,
# docs/replay.md) and the FidelityFX anchors file: the page names the metric (mask, threshold,
# clamp range, reference samples and seeds), draws one error-against-frame plot with the noisy
# input, the output and the reference noise floor, and lists the glossy room's anchor points
# with their conditions in a table, never on the plot. A malformed anchors file is one line
# naming it.
file(REMOVE_RECURSE "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/run_glint.cmake")
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
  "error": {"reflections": {"first": 0.5, "last": 0.3, "noisyLast": 0.8, "referenceNoiseLast": 0.0625}}
}
]=])
run_glint(0 report "${OUT}/glossy_room" --out "${OUT}/report.html" --anchors "${ANCHORS}")
file(READ "${OUT}/report.html" html)

# References too noisy for the difference reported: a floor of 0.2 against |0.3 - 0.8| = 0.5.
file(READ "${OUT}/glossy_room/summary.json" noisy_summary)
string(REPLACE "\"mean\": 0.0625" "\"mean\": 0.2" noisy_summary "${noisy_summary}")
file(MAKE_DIRECTORY "${OUT}/noisy_references/frame_0000" "${OUT}/noisy_references/frame_0001")
file(WRITE "${OUT}/noisy_references/summary.json" "${noisy_summary}")
run_glint(0 report "${OUT}/noisy_references" --out "${OUT}/report_noisy.html")
file(READ "${OUT}/report_noisy.html" noisy_html)
if(NOT noisy_html MATCHES "<td>no: floor 0.2000 is not below a quarter of 0.5000</td>")
  message(FATAL_ERROR "report_noisy.html does not say the references are not converged")
endif()
foreach(expected
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
  if(NOT html MATCHES "${expected}")
    message(FATAL_ERROR "report.html lacks '${expected}'")
  endif()
endforeach()
# Three series, each one unbroken line over both frames; no anchor marker on the axis.
string(REGEX MATCHALL "<polyline" lines "${html}")
list(LENGTH lines count)
if(NOT count EQUAL 3)
  message(FATAL_ERROR "expected 3 plotted lines (noisy, output, noise floor), found ${count}")
endif()
if(html MATCHES "<circle")
  message(FATAL_ERROR "an anchor was drawn on a plot it was not measured on")
endif()

file(WRITE "${OUT}/bad_anchors.json" "{\"points\": 3}")
run_glint(2 report "${OUT}/glossy_room" --out "${OUT}/report_bad.html" --anchors "${OUT}/bad_anchors.json")
if(NOT run_err MATCHES "^glint: report: [^\n]*bad_anchors.json: no \"points\" array\n?$")
  message(FATAL_ERROR "expected one line naming bad_anchors.json, got: ${run_err}")
endif()
