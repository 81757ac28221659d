# Script mode: scripts/run_flip.py's value tests (tests/cli/run_flip_test.py: FLIP of known image
# pairs, empty masks, the summary.json fields, idempotence), then run_flip.py on two small glint
# runs (the glossy room's reflections with --second-reference, the courtyard's one-channel shadow
# visibility) and glint report on them: every frame gets its FLIP values, the report's error table
# shows them and the page plots FLIP against frame. Python as in python_env_check.cmake: skipped
# without the venv, failed instead where skips are forbidden.
include("${CMAKE_CURRENT_LIST_DIR}/python_env_check.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/run_glint.cmake")
require_python(flip_evaluator numpy)
execute_process(COMMAND "${PYTHON}" "${VALUE_TESTS}" -v RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "run_flip.py's value tests failed (exit ${status})")
endif()

file(REMOVE_RECURSE "${OUT}")
run_glint(0 simulate "${SCENES}/glossy_room.toml" --size 48x27 --frame-count 2 --spp 4 --out "${OUT}/glossy")
run_glint(0 simulate "${SCENES}/glossy_room.toml" --size 48x27 --frame-count 2 --spp 4 --seed 2 --out "${OUT}/glossy2")
run_glint(0 run "${OUT}/glossy" --set denoise=true --second-reference "${OUT}/glossy2" --out "${OUT}/runs/glossy_room")
run_glint(0 simulate "${SCENES}/courtyard_penumbra.toml" --size 48x27 --frame-count 2 --spp 4 --out "${OUT}/courtyard")
run_glint(0 run "${OUT}/courtyard" --out "${OUT}/runs/courtyard_penumbra")
set(runs "${OUT}/runs/glossy_room" "${OUT}/runs/courtyard_penumbra")
foreach(pass first second)  # the second changes nothing
  execute_process(COMMAND "${PYTHON}" "${SCRIPT}" ${runs} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "run_flip.py (${pass}): exit ${status}\n${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "run_flip.py exited ${status}")
  endif()
  if(NOT out MATCHES "glossy_room: LDR-FLIP of 2 frame\\(s\\); last frame: reflections 0\\.[0-9]+ \\(noisy input 0\\.[0-9]+, reference noise floor 0\\.[0-9]+\\)"
     OR NOT out MATCHES "courtyard_penumbra: LDR-FLIP of 2 frame\\(s\\); last frame: shadows 0\\.[0-9]+ \\(noisy input 0\\.[0-9]+\\)")
    message(FATAL_ERROR "run_flip.py did not print each run's last-frame FLIP")
  endif()
  file(READ "${OUT}/runs/glossy_room/summary.json" summary_${pass})
endforeach()
if(NOT summary_first STREQUAL summary_second)
  message(FATAL_ERROR "a second run_flip.py changed summary.json")
endif()

# FLIP lies in [0, 1]. (Not compared with the noisy input's: at 48x27 after 2 frames the glossy
# room's denoised output has a higher LDR-FLIP than its noisy input, 0.354 against 0.307 on
# lavapipe, though a lower relative error and clamped MAE.)
function(summary_value run variable)
  file(READ "${OUT}/runs/${run}/summary.json" json)
  string(JSON value GET "${json}" ${ARGN})
  if(NOT value MATCHES "^[0-9.e+-]+$" OR value LESS 0 OR value GREATER 1)
    message(FATAL_ERROR "${run}/summary.json: ${ARGN} is '${value}', not a FLIP in [0, 1]")
  endif()
  set(${variable} "${value}" PARENT_SCOPE)
endfunction()
summary_value(glossy_room flip error reflections flipLast)
summary_value(glossy_room noisy_flip error reflections noisyFlipLast)
summary_value(glossy_room floor_flip error reflections referenceNoiseFlipLast)
summary_value(glossy_room first_flip frames 0 errors reflections flip)
summary_value(glossy_room first_floor frames 0 referenceNoise reflections flip)
summary_value(courtyard_penumbra shadow_flip error shadows flipLast)
summary_value(courtyard_penumbra shadow_noisy_flip error shadows noisyFlipLast)
if(flip EQUAL noisy_flip OR shadow_flip EQUAL shadow_noisy_flip OR NOT floor_flip GREATER 0)
  message(FATAL_ERROR "FLIP of the output equals its noisy input's (reflections ${flip} and ${noisy_flip}, "
                      "shadows ${shadow_flip} and ${shadow_noisy_flip}), or the floor ${floor_flip} is not above 0")
endif()
# run_flip.py scores what glint scored: its mask holds the pixels glint counted, and the clamped
# MAE of the images it reads over that mask is glint's.
execute_process(COMMAND "${PYTHON}" -c [=[
import json, pathlib, sys
import numpy as np
sys.path.insert(0, sys.argv[1])
import run_flip
for run in sys.argv[2:]:
    summary = json.loads((pathlib.Path(run) / "summary.json").read_text())
    for record in summary["frames"]:
        folder = pathlib.Path(run) / record["folder"]
        for effect, error in record["errors"].items():
            mask = run_flip.load(folder / f"{effect}_mask.exr")[..., 0] > 0.5
            out, ref = (np.clip(run_flip.load(folder / name), 0, 16)
                        for name in (error["image"].replace("/", "_") + ".exr", f"{effect}_reference.exr"))
            mae = float(np.abs(out - ref)[mask].mean())
            assert mask.sum() == error["pixels"], (folder, effect, mask.sum(), error["pixels"])
            assert abs(mae - error["maeClamped"]) < 1e-5, (folder, effect, mae, error["maeClamped"])
]=] "${SCRIPTS}" ${runs} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "run_flip.py's masks or images are not the ones glint run scored")
endif()
file(READ "${OUT}/runs/glossy_room/summary.json" json)
string(JSON clamp GET "${json}" flip clamp)
string(JSON metric GET "${json}" flip metric)
if(NOT clamp EQUAL 16 OR NOT metric MATCHES "LDR-FLIP.*Reinhard.*mask")
  message(FATAL_ERROR "summary.json's flip is {clamp ${clamp}, metric '${metric}'}")
endif()

run_glint(0 report ${runs} --out "${OUT}/report.html")
file(READ "${OUT}/report.html" html)
foreach(expected
    "<th>FLIP, last frame</th><th>its noisy input&#39;s FLIP, last frame</th>"
    "LDR-FLIP as scripts/study.py defines it"
    "reflections: LDR-FLIP against the reference"
    "shadows: LDR-FLIP against the reference"
    "FLIP 0\\.[0-9][0-9][0-9][0-9]\\)</td>"
    "<td>0\\.[0-9][0-9][0-9][0-9]</td><td>0\\.[0-9][0-9][0-9][0-9]</td></tr>")
  if(NOT html MATCHES "${expected}")
    message(FATAL_ERROR "report.html lacks '${expected}'")
  endif()
endforeach()
